//! `brdf-ref diff`: it finds a 3-ULP error planted in one row (max ULP 3, that row first among
//! the worst, in the 3-4 bucket of the histogram, over `--max-ulp 2` but not 3), and reports
//! 0 ULP for every kernel on the crate's own output.

use crate::{points, run};
use brdf_ref::app::fmt;
use brdf_ref::{Float, KERNELS};

/// The crate's own `eval` output for a grid of `ggx::d` in f32, as diff input (header,
/// arguments, the crate's value).
fn ggx_grid() -> Vec<String> {
    let (code, out, err) = run(
        &[
            "eval",
            "ggx::d",
            "--grid",
            "n_dot_h=0:1:41",
            "--grid",
            "alpha=0.01:1:12",
        ],
        "",
    );
    assert_eq!(code, 0, "{err}");
    out.lines().map(str::to_string).collect()
}

#[test]
fn diff_finds_a_planted_three_ulp_error() {
    let mut lines = ggx_grid();
    // Line 300 of the file (its row number): 3 ULP above the crate's value.
    let planted = 300;
    let fields: Vec<String> = lines[planted - 1].split(',').map(str::to_string).collect();
    let d: f32 = fields[2].parse().expect("a number");
    assert!(d > 0.0, "a positive value, so +3 in its bits is 3 ULP up");
    let shifted = f32::from_bits(d.to_bits() + 3);
    lines[planted - 1] = format!("{},{},{}", fields[0], fields[1], shifted);
    let input = lines.join("\n") + "\n";
    let (code, out, err) = run(&["diff", "ggx::d", "--worst", "3"], &input);
    assert_eq!(
        code, 0,
        "a difference is not a failure without --max-ulp: {err}"
    );
    assert!(
        out.contains(&format!("ggx::d (f32): {} rows compared", lines.len() - 1)),
        "{out}"
    );
    assert!(out.contains("output d: max ULP 3, median ULP 0"), "{out}");
    assert!(
        out.contains("                3-4         1  "),
        "the histogram's 3-4 bucket holds the row:\n{out}"
    );
    let first_worst = out
        .lines()
        .skip_while(|l| !l.trim_start().starts_with("worst"))
        .nth(1)
        .expect("a worst row");
    assert!(
        first_worst.trim_start().starts_with(&format!(
            "row {planted}: d: crate {d}, shader {shifted}, 3 ULP"
        )),
        "the planted row comes first: {first_worst}\n{out}"
    );
    let (code, _, err) = run(&["diff", "ggx::d", "--max-ulp", "2"], &input);
    assert_eq!(code, 1, "--max-ulp 2 fails on 3 ULP");
    assert!(err.contains("FAIL: differences above --max-ulp 2"), "{err}");
    let (code, _, _) = run(&["diff", "ggx::d", "--max-ulp", "3"], &input);
    assert_eq!(code, 0, "--max-ulp 3 passes");
}

#[test]
fn diff_reports_nan_mismatches_separately() {
    let (code, out, _) = run(
        &["diff", "ggx::d", "--max-ulp", "1000"],
        "0.5,0.25,NaN\n0.5,0.25,0.033938915\n",
    );
    assert_eq!(code, 1, "a NaN against a number exceeds any --max-ulp");
    assert!(
        out.contains("non-finite mismatches: 1 (NaN against a number 1"),
        "{out}"
    );
    assert!(
        out.contains("row 1: d: crate 0.033938915, shader NaN, NaN mismatch"),
        "{out}"
    );
}

fn own_output_is_zero_ulp(ty: Float) {
    // Every kernel's points through eval, and eval's output (with its `kernel,...` headers)
    // straight back into diff.
    let mut input = String::new();
    for k in KERNELS {
        for row in points(k, ty, 24, 4) {
            let fields: Vec<String> = row.iter().map(|&x| fmt(x, ty)).collect();
            input.push_str(&format!("{},{}\n", k.path, fields.join(",")));
        }
    }
    let flag = format!("--{}", ty.name());
    let (code, evaluated, err) = run(&["eval", &flag], &input);
    assert_eq!(code, 0, "{err}");
    let (code, report, err) = run(&["diff", &flag, "--max-ulp", "0"], &evaluated);
    assert_eq!(
        code, 0,
        "the crate's own output is within 0 ULP: {err}\n{report}"
    );
    for k in KERNELS {
        assert!(
            report.contains(&format!("{} ({}): ", k.path, ty.name())),
            "{} is compared",
            k.path
        );
    }
    let outputs: usize = KERNELS.iter().map(|k| k.outputs.len()).sum();
    assert_eq!(
        report.matches("max ULP 0, median ULP 0").count(),
        outputs,
        "every output at 0 ULP"
    );
    assert_eq!(
        report.matches("non-finite mismatches: 0 ").count(),
        outputs,
        "and no mismatch"
    );
}

#[test]
fn diff_reports_zero_ulp_on_the_crates_own_f32_output() {
    own_output_is_zero_ulp(Float::F32);
}

#[test]
fn diff_reports_zero_ulp_on_the_crates_own_f64_output() {
    own_output_is_zero_ulp(Float::F64);
}
