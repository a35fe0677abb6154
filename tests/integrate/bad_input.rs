//! The integrators keep the crate's bad-input rule for every argument, their `Config`
//! included (`integrate` module docs, "Bad input"): a NaN or infinite direction component or
//! a NaN or negative tolerance gives a NaN estimate and a NaN error, never a plausible value.
#![cfg(feature = "integrate")]

use brdf::V3;
use brdf::integrate::{
    Config, Estimate, directional_albedo, directional_albedo_f32, directional_albedo_with,
    directional_albedo_with_f32, hemisphere, hemisphere_f32, smith_weak_furnace,
    smith_weak_furnace_f32,
};

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

fn assert_nan(what: &str, e: Estimate) {
    assert!(
        e.value.is_nan() && e.error.is_nan() && e.evaluations == 0,
        "{what}: {e:?}, want Estimate::NAN"
    );
}

/// A cheap configuration, so each case runs in microseconds.
fn cfg() -> Config {
    Config {
        abs_tol: 1e-6,
        rel_tol: 1e-4,
        max_evals: 20_000,
    }
}

/// `w` rounded to `f32`.
fn narrow(w: V3<f64>) -> V3<f32> {
    w.map(|c| c as f32)
}

/// Every component of a valid direction replaced by each bad value in turn.
fn bad_dirs(w: V3<f64>) -> Vec<(String, V3<f64>)> {
    let mut out = Vec::new();
    for i in 0..3 {
        for b in BAD {
            let mut v = w.to_array();
            v[i] = b;
            out.push((format!("component {i} = {b}"), V3::from(v)));
        }
    }
    out
}

#[test]
fn smith_weak_furnace_with_a_bad_view_component_is_nan() {
    let wo = V3::new(0.36, 0.48, 0.8);
    let d = |m: V3<f64>| {
        if m.z > 0.0 {
            core::f64::consts::FRAC_1_PI
        } else {
            0.0
        }
    };
    // The good view integrates (a plausible value is what a NaN must not become).
    assert!((smith_weak_furnace(V3::unit_z(), d, |_, _| 1.0).value - 1.0).abs() < 1e-3);
    for (what, w) in bad_dirs(wo) {
        assert_nan(&what, smith_weak_furnace(w, d, |_, _| 1.0));
        let w32 = narrow(w);
        assert_nan(
            &format!("f32 {what}"),
            smith_weak_furnace_f32(w32, |_| core::f32::consts::FRAC_1_PI, |_, _| 1.0),
        );
    }
}

#[test]
fn directional_albedo_with_a_bad_view_component_is_nan() {
    // A Lambertian lobe ignores wo: the view's NaN must still reach the estimate.
    let lambert = |_wo: V3<f64>, _wi: V3<f64>| 0.5 * core::f64::consts::FRAC_1_PI;
    let lambert32 = |_wo: V3<f32>, _wi: V3<f32>| 0.5 * core::f32::consts::FRAC_1_PI;
    for (what, w) in bad_dirs(V3::new(0.36, 0.48, 0.8)) {
        assert_nan(&what, directional_albedo(w, lambert));
        assert_nan(&what, directional_albedo_with(w, lambert, &cfg()));
        assert_nan(&what, directional_albedo_f32(narrow(w), lambert32));
        assert_nan(
            &what,
            directional_albedo_with_f32(narrow(w), lambert32, &cfg()),
        );
    }
}

#[test]
fn a_nan_or_negative_tolerance_gives_a_nan_estimate() {
    let lambert = |_wo: V3<f64>, _wi: V3<f64>| 0.5 * core::f64::consts::FRAC_1_PI;
    let lambert32 = |_wo: V3<f32>, _wi: V3<f32>| 0.5 * core::f32::consts::FRAC_1_PI;
    for bad in [f64::NAN, -1e-6, f64::NEG_INFINITY] {
        for c in [
            Config {
                abs_tol: bad,
                ..cfg()
            },
            Config {
                rel_tol: bad,
                ..cfg()
            },
        ] {
            let what = format!("{c:?}");
            assert_nan(&what, hemisphere(|w| w.z, &[], &c));
            assert_nan(&what, hemisphere_f32(|w| w.z, &[], &c));
            assert_nan(&what, directional_albedo_with(V3::unit_z(), lambert, &c));
            assert_nan(
                &what,
                directional_albedo_with_f32(V3::unit_z(), lambert32, &c),
            );
        }
    }
}

#[test]
fn an_infinite_or_zero_tolerance_is_meaningful() {
    // +inf: the initial partition's estimate (within 1e-3 of pi); 0: refine until the budget
    // is spent (within 1e-9).
    for (tol, within) in [(f64::INFINITY, 1e-3), (0.0, 1e-9)] {
        let c = Config {
            abs_tol: tol,
            rel_tol: tol,
            ..cfg()
        };
        let e = hemisphere(|w| w.z, &[], &c);
        assert!(
            (e.value - core::f64::consts::PI).abs() < within && e.error.is_finite(),
            "{c:?}: {e:?}"
        );
    }
}

#[test]
fn a_bad_peak_gives_a_nan_estimate() {
    for (what, p) in bad_dirs(V3::new(0.6, 0.0, 0.8)) {
        assert_nan(&what, hemisphere(|w| w.z, &[V3::unit_z(), p], &cfg()));
        assert_nan(&what, hemisphere_f32(|w| w.z, &[narrow(p)], &cfg()));
    }
}
