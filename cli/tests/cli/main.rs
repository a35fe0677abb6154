//! The reference CLI's tests, one binary (so the crate links once):
//!
//! | module | property |
//! |---|---|
//! | `eval` | every kernel through the `brdf-ref` binary equals a hand-written direct call, bit for bit |
//! | `lanes` | `f32x8` and `f64x4` entries equal the scalar entries lane by lane |
//! | `drift` | the table's argument names and order are the functions' parameters (parsed with `syn`) |
//! | `malformed` | bad rows are reported by row and column and skipped; the exit status says so |
//! | `diff` | `diff` finds a planted 3-ULP error and reports 0 ULP on the crate's own output |
//! | `stability` | every output is a number in its range at the extremes of every domain |

mod diff;
mod direct;
mod drift;
mod eval;
mod lanes;
mod malformed;
mod stability;

use std::io::Write;
use std::process::{Command, Stdio};

/// Runs the `brdf-ref` binary with `args` and `stdin`: (exit status, stdout, stderr).
pub fn run(args: &[&str], stdin: &str) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_brdf-ref"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the brdf-ref binary runs");
    let mut input = child.stdin.take().expect("stdin");
    let text = stdin.to_string();
    let writer = std::thread::spawn(move || input.write_all(text.as_bytes()));
    let out = child.wait_with_output().expect("brdf-ref finishes");
    writer.join().expect("writer").expect("stdin written");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).expect("utf-8 stdout"),
        String::from_utf8(out.stderr).expect("utf-8 stderr"),
    )
}

/// The test points of a kernel in `ty`: the extremes of its domains (at most `cap` rows) and
/// `random` seeded random rows inside them.
pub fn points(
    k: &brdf_ref::Kernel,
    ty: brdf_ref::Float,
    cap: usize,
    random: usize,
) -> Vec<Vec<f64>> {
    let mut rows = brdf_ref::points::extreme_rows(k, ty, cap);
    rows.extend(brdf_ref::points::random_rows(k, ty, random, 0x5EED));
    rows
}

/// Equal bits, or both NaN (lanes and scalars may differ in a NaN's payload).
pub fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}
