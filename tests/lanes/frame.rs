//! Shading frames are orthonormal and right-handed for every unit normal, round-trip vectors,
//! and agree between scalar and lane paths; the local trigonometry helpers are exact at the
//! pole and the horizon.

use crate::common;
use brdf::frame::{self, Frame};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};
use glam::{DVec3, Vec3};
use proptest::prelude::*;

fn unit(theta: f64, phi: f64) -> V3<f64> {
    frame::spherical_direction(theta, phi)
}

fn check_orthonormal(n: V3<f64>, tol: f64) {
    let f = Frame::from_normal(n);
    for (name, v) in [("t", f.t), ("b", f.b), ("n", f.n)] {
        assert!(
            (v.length() - 1.0).abs() <= tol,
            "|{name}| = {} for n = {n:?}",
            v.length()
        );
    }
    assert!(f.t.dot(f.b).abs() <= tol, "t.b for {n:?}");
    assert!(f.t.dot(f.n).abs() <= tol, "t.n for {n:?}");
    assert!(f.b.dot(f.n).abs() <= tol, "b.n for {n:?}");
    // Right-handed: t x b = n.
    assert!(
        (f.t.cross(f.b) - f.n).length() <= tol,
        "handedness for {n:?}"
    );
}

#[test]
fn frame_is_orthonormal_at_the_poles_and_the_equator() {
    // Duff et al.'s construction is accurate to a few ulps everywhere, including n = -z where
    // Frisvad's original loses orthogonality; 1e-15 is about 5 f64 ulps.
    for n in [
        V3::new(0.0, 0.0, 1.0),
        V3::new(0.0, 0.0, -1.0),
        V3::new(-0.0, -0.0, -1.0),
        V3::new(1.0, 0.0, 0.0),
        V3::new(0.0, -1.0, 0.0),
        V3::new(1e-9, 0.0, -1.0).normalize_or(V3::unit_z()),
        V3::new(0.0, 1e-9, -1.0).normalize_or(V3::unit_z()),
        V3::new(1.0, 0.0, -1e-12).normalize_or(V3::unit_z()),
    ] {
        check_orthonormal(n, 1e-15);
    }
}

proptest! {
    #![proptest_config(common::proptest_config())]
    #[test]
    fn frame_is_orthonormal_for_any_unit_normal(theta in 0.0..core::f64::consts::PI, phi in 0.0..core::f64::consts::TAU) {
        check_orthonormal(unit(theta, phi), 1e-15);
    }

    #[test]
    fn world_to_local_round_trips(theta in 0.0..core::f64::consts::PI, phi in 0.0..core::f64::consts::TAU,
                                  x in -2.0..2.0, y in -2.0..2.0, z in -2.0..2.0) {
        let f = Frame::from_normal(unit(theta, phi));
        let v = V3::new(x, y, z);
        let back = f.to_world(f.to_local(v));
        prop_assert!((back - v).length() <= 1e-14 * (1.0 + v.length()));
        // The normal maps to +z.
        let nz = f.to_local(f.n);
        prop_assert!((nz - V3::unit_z()).length() <= 1e-15);
    }

    #[test]
    fn lanes_build_the_same_frame_as_scalars(theta in 0.0..core::f64::consts::PI, phi in 0.0..core::f64::consts::TAU) {
        let n64 = unit(theta, phi);
        let n32 = V3::new(n64.x as f32, n64.y as f32, n64.z as f32);
        let s = Frame::from_normal(n32);
        let l = Frame::from_normal(V3::new(f32x8::splat(n32.x), f32x8::splat(n32.y), f32x8::splat(n32.z)));
        for i in 0..8 {
            prop_assert_eq!(l.t.lane(i), s.t);
            prop_assert_eq!(l.b.lane(i), s.b);
        }
        let s = Frame::from_normal(n64);
        let l = Frame::from_normal(V3::new(f64x4::splat(n64.x), f64x4::splat(n64.y), f64x4::splat(n64.z)));
        prop_assert_eq!(l.t.lane(3), s.t);
        prop_assert_eq!(l.b.lane(3), s.b);
    }
}

#[test]
fn sin2_theta_has_no_cancellation_near_the_pole() {
    // w at 1e-4 rad from the normal: sin^2 = 1e-8. In f32, 1 - cos^2 cancels to 0 or a
    // multiple of 6e-8; the x^2 + y^2 form is accurate to 1 ulp.
    let t = 1e-4_f64;
    let w32 = V3::new(t.sin() as f32, 0.0, t.cos() as f32);
    let exact = t.sin().powi(2);
    let got = frame::sin2_theta(w32) as f64;
    assert!(
        (got - exact).abs() <= 2.0 * f32::EPSILON as f64 * exact,
        "{got} vs {exact}"
    );
    let naive = 1.0 - w32.z * w32.z;
    assert!(
        (naive as f64 - exact).abs() > 0.5 * exact,
        "the naive form should be this bad: {naive}"
    );
}

#[test]
fn phi_helpers_are_defined_at_the_pole() {
    let pole = V3::new(0.0_f32, 0.0, 1.0);
    assert_eq!(frame::cos_phi(pole), 1.0);
    assert_eq!(frame::sin_phi(pole), 0.0);
    let lanes = V3::new(f32x8::splat(0.0), f32x8::splat(0.0), f32x8::splat(1.0));
    assert_eq!(frame::cos_phi(lanes).lane(5), 1.0);
    assert_eq!(frame::sin_phi(lanes).lane(5), 0.0);
    // Away from the pole they are the usual cos/sin of phi.
    let w = unit(0.7, 2.0);
    assert!((frame::cos_phi(w) - 2.0_f64.cos()).abs() < 1e-15);
    assert!((frame::sin_phi(w) - 2.0_f64.sin()).abs() < 1e-15);
}

#[test]
fn tan2_theta_is_zero_at_the_pole_and_infinite_at_the_horizon() {
    assert_eq!(frame::tan2_theta(V3::new(0.0_f64, 0.0, 1.0)), 0.0);
    assert_eq!(frame::tan2_theta(V3::new(1.0_f64, 0.0, 0.0)), f64::INFINITY);
    let w = unit(0.5, 1.0);
    assert!((frame::tan2_theta(w) - 0.5_f64.tan().powi(2)).abs() < 1e-15);
}

#[test]
fn normalize_or_falls_back_on_zero_and_non_finite_vectors() {
    let fb = V3::unit_z();
    assert_eq!(V3::new(0.0_f32, 0.0, 0.0).normalize_or(fb), fb);
    assert_eq!(V3::new(f32::INFINITY, 0.0, 0.0).normalize_or(fb), fb);
    assert_eq!(
        V3::new(3.0_f32, 0.0, 4.0).normalize_or(fb),
        V3::new(0.6, 0.0, 0.8)
    );
}

#[test]
fn glam_conversions_round_trip_and_lanes_transpose() {
    let v = Vec3::new(1.0, 2.0, 3.0);
    assert_eq!(Vec3::from(V3::from(v)), v);
    let d = DVec3::new(-1.0, 0.5, 2.0);
    assert_eq!(DVec3::from(V3::from(d)), d);
    let eight: [Vec3; 8] =
        core::array::from_fn(|i| Vec3::new(i as f32, 2.0 * i as f32, -(i as f32)));
    let soa = V3::<f32x8>::from_lanes(eight);
    assert_eq!(soa.y.lane(3), 6.0);
    assert_eq!(soa.to_lanes(), eight);
    let four: [DVec3; 4] = core::array::from_fn(|i| DVec3::splat(i as f64));
    assert_eq!(V3::<f64x4>::from_lanes(four).to_lanes(), four);
}

#[test]
fn reflect_mirrors_about_the_normal() {
    let n = V3::unit_z();
    let w = V3::new(0.3_f64, -0.4, 0.866);
    assert_eq!(w.mirror(n), V3::new(-0.3, 0.4, 0.866));
    assert!(frame::same_hemisphere(w, w.mirror(n)));
}
