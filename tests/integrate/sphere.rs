//! `integrate::sphere`, `sphere_f32` and `directional_albedo_sphere` on integrals with closed
//! forms, and their bad-input rule.
#![cfg(feature = "integrate")]

use brdf::V3;
use brdf::integrate::{Config, directional_albedo_sphere, sphere, sphere_f32};
use core::f64::consts::PI;

/// A lobe cos^n around a direction below the horizon: its integral is 2 pi / (n + 1); a
/// sphere integrator that skipped or mirrored the wrong half gets 0 or the wrong peak.
#[test]
fn sphere_integrates_known_integrals_on_both_halves() {
    let cfg = Config::default();
    let area = sphere(|_| 1.0, &[], &cfg);
    assert!((area.value - 4.0 * PI).abs() < 1e-9, "{area:?}");
    // z^2 over the sphere: 4 pi / 3; z^3 is odd: 0; only the lower half: -pi/2 for min(z, 0)^3...
    let z2 = sphere(|w| w.z * w.z, &[], &cfg);
    assert!((z2.value - 4.0 * PI / 3.0).abs() < 1e-9, "{z2:?}");
    let low = sphere(|w| (-w.z).max(0.0), &[], &cfg);
    assert!((low.value - PI).abs() < 1e-9, "{low:?}");
    let axis = V3::new(0.6, 0.0, -0.8);
    let n = 2000.0;
    let lobe = |w: V3<f64>| w.dot(axis).max(0.0).powf(n);
    let e = sphere(lobe, &[axis], &cfg);
    let exact = 2.0 * PI / (n + 1.0);
    println!(
        "cos^2000 below: {} vs {exact}, error {:.2e}",
        e.value, e.error
    );
    // The hemisphere integrator's documented accuracy on lobes this narrow: 1e-3 relative.
    assert!((e.value / exact - 1.0).abs() < 1e-3, "{e:?}");
    let e32 = sphere_f32(
        |w| w.dot(axis.map(|x| x as f32)).max(0.0).powf(n as f32),
        &[axis.map(|x| x as f32)],
        &cfg,
    );
    assert!((e32.value / exact - 1.0).abs() < 1e-3, "{e32:?}");
}

#[test]
fn directional_albedo_sphere_counts_both_sides() {
    // A BSDF that is constant 1 / (2 pi) on both sides: integral of |cos| / (2 pi) = 1.
    let e = directional_albedo_sphere(V3::new(0.0, 0.6, -0.8), |_, _| 0.5 / PI, &[]);
    assert!((e.value - 1.0).abs() < 1e-9, "{e:?}");
    // Transmission only: 1/2.
    let t = directional_albedo_sphere(
        V3::unit_z(),
        |_, wi| if wi.z < 0.0 { 0.5 / PI } else { 0.0 },
        &[],
    );
    assert!((t.value - 0.5).abs() < 1e-9, "{t:?}");
}

#[test]
fn sphere_bad_input_gives_nan() {
    let cfg = Config::default();
    let nan = V3::new(f64::NAN, 0.0, 1.0);
    let inf = V3::new(0.0, f64::INFINITY, -1.0);
    assert!(sphere(|_| 1.0, &[nan], &cfg).value.is_nan());
    assert!(sphere(|_| 1.0, &[inf], &cfg).value.is_nan());
    let bad_cfg = Config {
        abs_tol: f64::NAN,
        ..cfg
    };
    assert!(sphere(|_| 1.0, &[], &bad_cfg).value.is_nan());
    assert!(
        directional_albedo_sphere(nan, |_, _| 1.0, &[])
            .value
            .is_nan()
    );
    assert!(
        directional_albedo_sphere(V3::unit_z(), |_, _| 1.0, &[inf])
            .value
            .is_nan()
    );
    assert!(
        sphere_f32(|_| 1.0, &[V3::new(f32::NAN, 0.0, 1.0)], &cfg)
            .value
            .is_nan()
    );
}
