//! The split-sum helpers keep the crate's rule 4 at the edges of their domains: finite
//! in-domain input gives finite output, never +-inf or NaN. Each case is a reproducer the
//! reference CLI's stability sweep found (`cli/tests/cli/stability.rs`).
#![cfg(feature = "ibl")]

use brdf::V3;
use brdf::ibl::energy::{Albedo, Reflectance};
use brdf::ibl::{dfg, energy};
use brdf::wide::{f32x8, f64x4};

#[test]
fn dfg_specular_is_capped_on_the_negative_side_too() {
    // A fit's B < 0 times a large radiance: F0 A + F90 B = -1e30, times 1e30 gave -inf.
    let l = V3::new(1e30_f32, 1e30, 1e30);
    let out = dfg::specular(l, V3::new(0.0, 0.0, 0.0), 1.0, 0.0, -1e30);
    assert_eq!([out.x, out.y, out.z], [-f32::MAX; 3]);
    // The positive side, as before.
    let out = dfg::specular(l, V3::new(1.0, 1.0, 1.0), 1.0, 1e30, 0.0);
    assert_eq!([out.x, out.y, out.z], [f32::MAX; 3]);
    let m = f64::MAX;
    let out = dfg::specular(V3::new(m, m, m), V3::new(0.5, 0.5, 0.5), 1.0, 0.5, -m);
    assert_eq!(out.x, -m);
}

#[test]
fn dfg_specular_zero_radiance_with_overflowing_f0_a_plus_f90_b_is_zero() {
    // a, b near MAX: F0 A + F90 B overflows to inf, and a zero radiance gave 0 * inf = NaN.
    let m = f32::MAX;
    let out = dfg::specular(
        V3::new(0.0_f32, 1.0, 0.0),
        V3::new(1.0, 1.0, 1.0),
        1.0,
        m,
        m,
    );
    assert_eq!([out.x, out.y, out.z], [0.0, m, 0.0]);
    let z = f32x8::splat(0.0);
    let one = f32x8::splat(1.0);
    let out = dfg::specular(
        V3::new(z, z, z),
        V3::new(one, one, one),
        one,
        f32x8::splat(m),
        f32x8::splat(m),
    );
    assert_eq!(out.x.to_array(), [0.0; 8]);
    let m = f64::MAX;
    let z = f64x4::splat(0.0);
    let one = f64x4::splat(1.0);
    let out = dfg::specular(
        V3::new(z, z, z),
        V3::new(one, one, one),
        one,
        f64x4::splat(m),
        f64x4::splat(-m),
    );
    assert_eq!(out.x.to_array(), [0.0; 4]);
}

#[test]
fn dfg_specular_ordinary_values_and_nan_are_unchanged() {
    let out = dfg::specular(
        V3::new(2.0_f64, 1.0, 0.5),
        V3::new(0.04, 0.5, 1.0),
        1.0,
        0.5,
        0.25,
    );
    assert_eq!(
        [out.x, out.y, out.z],
        [
            2.0 * 0.04_f64.mul_add(0.5, 0.25),
            0.5_f64.mul_add(0.5, 0.25),
            0.5 * 1.0_f64.mul_add(0.5, 0.25),
        ]
    );
    let out = dfg::specular(
        V3::new(1.0_f32, 1.0, 1.0),
        V3::new(0.5, 0.5, 0.5),
        1.0,
        f32::NAN,
        0.0,
    );
    assert!(out.x.is_nan() && out.y.is_nan() && out.z.is_nan());
}

#[test]
fn turquin_scale_is_one_at_f_zero_for_every_e() {
    // For e below 1 / MAX, (1 - e) / e overflowed and f = 0 gave 0 * inf = NaN.
    for e in [
        f32::from_bits(1),
        1e-38,
        2.9e-39,
        f32::MIN_POSITIVE,
        1e-6,
        0.5,
        1.0,
    ] {
        assert_eq!(
            energy::turquin_scale(Albedo(e), Reflectance(0.0_f32)),
            1.0,
            "e = {e:e}"
        );
        let v = energy::turquin_scale(Albedo(e), Reflectance(1.0_f32));
        assert!(v.is_finite() && v >= 1.0, "e = {e:e}: {v}");
    }
    for e in [5e-324, 1e-310] {
        assert_eq!(
            energy::turquin_scale(Albedo(e), Reflectance(0.0_f64)),
            1.0,
            "e = {e:e}"
        );
        assert_eq!(
            energy::turquin_scale(Albedo(e), Reflectance(1.0_f64)),
            f64::MAX,
            "e = {e:e}"
        );
    }
    let lanes = energy::turquin_scale(
        Albedo(f32x8::splat(f32::from_bits(1))),
        Reflectance(f32x8::splat(0.0)),
    );
    assert_eq!(lanes.to_array(), [1.0; 8]);
    let lanes = energy::turquin_scale(Albedo(f64x4::splat(5e-324)), Reflectance(f64x4::splat(0.0)));
    assert_eq!(lanes.to_array(), [1.0; 4]);
    // Ordinary values are unchanged: 1 + 0.5 (1 - 0.25) / 0.25 = 2.5.
    assert_eq!(
        energy::turquin_scale(Albedo(0.25_f64), Reflectance(0.5)),
        2.5
    );
    assert!(energy::turquin_scale(Albedo(f32::NAN), Reflectance(0.0)).is_nan());
}
