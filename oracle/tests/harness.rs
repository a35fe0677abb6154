//! The oracle itself is sound: its references are computed with precision to spare, and its
//! bounds are tight enough that one extra rounding in any kernel breaks them (every run
//! measures the committed hardest inputs, where each bound's figure was reached). Run with
//! `cargo test -p brdf-oracle --release --test harness -- --nocapture` to see the figures.

use brdf_oracle::bounds::{self, BOUNDS};
use brdf_oracle::cases;
use brdf_oracle::harness::Options;
use brdf_oracle::table;

/// Every case has a bound and every bound a case, in the same order.
#[test]
fn bounds_table_matches_cases() {
    let names: Vec<&str> = cases::all().iter().map(|c| c.name).collect();
    let bound_names: Vec<&str> = BOUNDS.iter().map(|b| b.name).collect();
    assert_eq!(names, bound_names);
    for b in BOUNDS {
        let above = [b.f32, b.f64, b.f32x8, b.f64x4]
            .into_iter()
            .chain(b.with_fma.into_iter().flatten())
            .any(|v| v > bounds::TARGET);
        assert!(
            !above || !b.why.is_empty(),
            "{}: a bound above {} needs a reason",
            b.name,
            bounds::TARGET
        );
    }
}

/// The references (256 bits plus each point's exponent span) agree with the same definitions
/// at 256 more bits to within 1e-6 of
/// an f64 ULP at every measured point: the working precision leaves no trace in the figures.
#[test]
fn references_are_precise_to_a_millionth_ulp() {
    let opts = Options {
        check_reference: true,
        scalars_only: true,
        ..Options::default()
    };
    let rows = table::measure_all(opts);
    let mut worst = (0.0, "");
    for (case, m) in &rows {
        println!("{:<36} drift {:.3e} f64 ulp", case.name, m.reference_drift);
        if m.reference_drift > worst.0 {
            worst = (m.reference_drift, case.name);
        }
    }
    assert!(
        worst.0 < 1e-6,
        "{}: reference drift {} ulp",
        worst.1,
        worst.0
    );
}

/// Perturbing every result by one rounding (a relative 2^-24 in f32, 2^-53 in f64, either
/// sign) pushes every function's max error past its bound: the bounds are tight enough to
/// catch a formula that rounds once more.
#[test]
fn one_extra_rounding_exceeds_every_bound() {
    let mut loose = Vec::new();
    let runs: Vec<_> = [1.0, -1.0]
        .into_iter()
        .map(|s| {
            let opts = Options {
                perturb: (s * 2f64.powi(-24), s * 2f64.powi(-53)),
                scalars_only: true,
                ..Options::default()
            };
            table::measure_all(opts)
        })
        .collect();
    println!(
        "{:<36} {:>10} {:>10} {:>6} {:>6}",
        "function", "f32 +-1r", "f64 +-1r", "bound", "bound"
    );
    for (i, (case, up)) in runs[0].iter().enumerate() {
        let down = &runs[1][i].1;
        let b = bounds::bound(case.name);
        let f32 = up.f32.max_ulp.max(down.f32.max_ulp);
        let f64 = up.f64.max_ulp.max(down.f64.max_ulp);
        println!(
            "{:<36} {:>10.3} {:>10.3} {:>6} {:>6}",
            case.name, f32, f64, b.f32, b.f64
        );
        if f32 <= b.f32 {
            loose.push(format!(
                "{} f32: perturbed {f32:.3} <= bound {}",
                case.name, b.f32
            ));
        }
        if f64 <= b.f64 {
            loose.push(format!(
                "{} f64: perturbed {f64:.3} <= bound {}",
                case.name, b.f64
            ));
        }
    }
    assert!(loose.is_empty(), "bounds too loose:\n{}", loose.join("\n"));
}
