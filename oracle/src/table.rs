//! Rendering of the measurements: the detailed rows the tests print, and the Markdown table
//! of `docs/accuracy.md`.

use crate::bounds::{self, Bound};
use crate::cases;
use crate::harness::{Case, Measurement, Options, Stats, measure};

/// The command that regenerates `docs/accuracy.md`.
pub const BLESS_COMMAND: &str = "BLESS=1 cargo test -p brdf-oracle --release --test accuracy_table";

/// Where `docs/accuracy.md` lives.
#[must_use]
pub fn doc_path() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/accuracy.md")
}

/// A max ULP figure: two decimals, `inf` for a NaN or inf result, failures counted.
fn figure(s: &Stats) -> String {
    let v = if s.max_ulp.is_finite() {
        format!("{:.2}", s.max_ulp)
    } else {
        "inf".to_string()
    };
    if s.failures > 0 {
        format!("{v} ({} fail)", s.failures)
    } else {
        v
    }
}

/// The header of [`detail_row`].
#[must_use]
pub fn detail_header() -> String {
    format!(
        "{:<36} {:>14} {:>14} {:>14} {:>14}  {:>11} {:>13} {:>9}  bound f32/f64/f32x8/f64x4; worst f32 / f64 args",
        "function", "f32", "f64", "f32x8", "f64x4", "points", "tiny f32/f64", "overflow"
    )
}

/// One measured row with its bound and worst points.
#[must_use]
pub fn detail_row(case: &Case, m: &Measurement, b: &Bound) -> String {
    format!(
        "{:<36} {:>14} {:>14} {:>14} {:>14}  {:>5}/{:<5} {:>6}/{:<6} {:>4}/{:<4}  {}/{}/{}/{}; {:?} / {:?}",
        case.name,
        figure(&m.f32),
        figure(&m.f64),
        figure(&m.f32x8),
        figure(&m.f64x4),
        m.f32.points,
        m.f64.points,
        m.f32.tiny,
        m.f64.tiny,
        m.f32.overflow,
        m.f64.overflow,
        b.f32,
        b.f64,
        b.f32x8,
        b.f64x4,
        m.f32.worst,
        m.f64.worst,
    )
}

/// Measures every case (in parallel over the machine's cores) and returns them in table order.
#[must_use]
pub fn measure_all(opts: Options) -> Vec<(Case, Measurement)> {
    let all = cases::all();
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(vec![None; all.len()]);
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(case) = all.get(i) else { break };
                    let m = measure(case, opts);
                    results.lock().expect("no panic while holding the lock")[i] = Some(m);
                }
            });
        }
    });
    let results = results
        .into_inner()
        .expect("no panic while holding the lock");
    all.into_iter()
        .zip(results)
        .map(|(c, m)| (c, m.expect("every case measured")))
        .collect()
}

/// The Markdown of `docs/accuracy.md` for these measurements.
#[must_use]
pub fn markdown(rows: &[(Case, Measurement)]) -> String {
    let mut s = String::new();
    s.push_str(
        "Max error in ULPs of the correctly rounded result (MPFR at 256 bits and more, from each function's published definition) over the stated points per type, counting results >= 1e-30 (f32) and >= 1e-300 (f64).\n",
    );
    s.push_str(&format!("Regenerate with `{BLESS_COMMAND}`.\n\n"));
    s.push_str("| function | f32 | f64 | f32x8 | f64x4 | points f32 / f64 | reference |\n");
    s.push_str("|---|---:|---:|---:|---:|---:|---|\n");
    for (case, m) in rows {
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} / {} | {} |\n",
            case.name,
            figure(&m.f32),
            figure(&m.f64),
            figure(&m.f32x8),
            figure(&m.f64x4),
            m.f32.points,
            m.f64.points,
            case.source
        ));
    }
    s
}

/// The bound an exact max ULP figure suggests: rounded up to the next 0.5, at least 0.5.
#[must_use]
pub fn suggested_bound(max_ulp: f64) -> f64 {
    ((max_ulp * 2.0).ceil() / 2.0).max(0.5)
}

/// The [`bounds::BOUNDS`] rows these measurements suggest, as Rust source (printed by the
/// table test so retuning is a paste).
#[must_use]
pub fn suggested_bounds(rows: &[(Case, Measurement)]) -> String {
    let mut s = String::new();
    for (case, m) in rows {
        let cur = bounds::bound(case.name);
        s.push_str(&format!(
            "    b(\"{}\", {:.1}, {:.1}, {:.1}, {:.1}),{}\n",
            case.name,
            suggested_bound(m.f32.max_ulp),
            suggested_bound(m.f64.max_ulp),
            suggested_bound(m.f32x8.max_ulp),
            suggested_bound(m.f64x4.max_ulp),
            if cur.why.is_empty() {
                String::new()
            } else {
                format!(" // {}", cur.why)
            }
        ));
    }
    s
}
