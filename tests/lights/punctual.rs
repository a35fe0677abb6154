//! Punctual lights: the two strength conventions agree, the inverse square law and the cosine
//! law match a small spherical emitter integrated over the hemisphere, each falloff has its
//! documented value at its edges (distance 0 and MAX, radius 0 and MAX) and never NaN there,
//! bad input gives NaN (an infinite distance or radius included: crate docs, "Bad input",
//! rule 5), and lanes reproduce scalars.
#![cfg(all(feature = "lights", feature = "integrate"))]

use crate::common;
use brdf::frame::Frame;
use brdf::integrate::{Config, hemisphere};
use brdf::lights::{self, Attenuation, SpotCone};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};
use proptest::prelude::*;

#[test]
fn white_lambert_lit_head_on_shows_the_light_colour() {
    for c in [0.0, 0.25, 1.0, 7.5, 1e6] {
        let lo = lights::radiance_pi(core::f64::consts::FRAC_1_PI, c, 1.0);
        // pi x (1/pi) rounds to within one ulp of 1.
        assert!((lo - c).abs() <= 2.0 * f64::EPSILON * c, "{lo} vs {c}");
        let lo32 = lights::radiance_pi(core::f32::consts::FRAC_1_PI, c as f32, 1.0);
        assert!((lo32 - c as f32).abs() <= 2.0 * f32::EPSILON * c as f32);
    }
    let rgb = lights::radiance_pi_rgb(
        V3::splat(core::f64::consts::FRAC_1_PI),
        V3::new(1.0, 0.5, 0.25),
        0.5,
    );
    assert!((rgb.x - 0.5).abs() < 1e-15 && (rgb.y - 0.25).abs() < 1e-15);
}

#[test]
fn radiance_is_capped_at_the_largest_float_instead_of_overflowing() {
    assert_eq!(lights::radiance(1e30_f32, 1e30, 0.5), f32::MAX);
    assert_eq!(lights::radiance(f64::MAX, f64::MAX, 1.0), f64::MAX);
    assert_eq!(lights::radiance(f64::MAX, 0.0, 1.0), 0.0);
}

#[test]
fn real_time_and_radiometric_conventions_agree_when_c_light_is_e_over_pi() {
    for (f, e, nl) in [(0.3, 2.0, 0.7), (1e-3, 1e4, 1.0), (5.0, 0.1, 1e-6)] {
        let a = lights::radiance_pi(f, e / core::f64::consts::PI, nl);
        let b = lights::radiance(f, e, nl);
        assert!((a - b).abs() <= 4.0 * f64::EPSILON * b, "{a} vs {b}");
    }
}

/// Irradiance from a sphere of radius `r` and uniform radiance `le`, centred at distance `d`
/// in direction `c` (unit, local frame), by integrating le max(0, n.w) over the cone it
/// subtends. The integral runs in a frame whose pole is `c`, so the cone's edge is a line of
/// constant polar angle; a peak on that line makes it an edge of the initial partition, so the
/// jump never falls inside a cubature rectangle. Its intensity seen
/// from afar is le pi r^2, so the inverse square and cosine laws predict
/// le pi r^2 / d^2 * c.z, exactly for a sphere whose cone clears the horizon (the cone's
/// projected solid angle is pi sin^2(half-angle) c.z).
fn sphere_irradiance(r: f64, d: f64, c: V3<f64>, le: f64) -> (f64, f64) {
    let cos_half = (1.0 - (r / d) * (r / d)).sqrt();
    let frame = Frame::from_normal(c);
    let cfg = Config {
        abs_tol: 1e-13,
        rel_tol: 1e-10,
        max_evals: 4_000_000,
    };
    let e = hemisphere(
        |w| {
            if w.z >= cos_half {
                let world = frame.to_world(w);
                le * world.z.max(0.0)
            } else {
                0.0
            }
        },
        &[V3::new(r / d, 0.0, cos_half)],
        &cfg,
    );
    (e.value, e.error)
}

#[test]
fn inverse_square_and_cosine_laws_match_a_small_spherical_emitter() {
    let (r, le) = (0.05, 3.0);
    let intensity = le * core::f64::consts::PI * r * r;
    println!("sphere light r = {r}: integrated irradiance against I cos / d^2");
    let mut worst: f64 = 0.0;
    for (d, theta_deg) in [(1.0, 0.0), (1.0, 45.0), (2.0, 70.0), (0.5, 30.0)] {
        let t: f64 = f64::to_radians(theta_deg);
        let c = V3::new(t.sin(), 0.0, t.cos());
        let (e_num, err) = sphere_irradiance(r, d, c, le);
        let e_perp = intensity * lights::inverse_square(d, 1e-3);
        let e = lights::irradiance(e_perp, c.z);
        let rel = (e_num - e).abs() / e;
        println!(
            "  d = {d}, theta = {theta_deg} deg: {e_num:.9} vs {e:.9} (rel {rel:.1e}, est {err:.1e})"
        );
        worst = worst.max(rel);
        // The reflected radiance of a white Lambertian surface is the same integral times 1/pi.
        let lo = lights::radiance(core::f64::consts::FRAC_1_PI, e_perp, c.z);
        assert!((lo - e / core::f64::consts::PI).abs() <= 1e-14 * lo);
    }
    // The closed form is exact and the integrand smooth on every rectangle: 1e-9 is the
    // integrator's accuracy on smooth integrands with room to spare.
    assert!(worst < 1e-9, "worst relative error {worst:e}");
}

#[test]
fn inverse_square_is_clamped_at_its_minimum_distance_and_vanishes_far_away() {
    assert_eq!(
        lights::inverse_square(0.0, 0.01),
        1e4_f64.next_up().min(1.0 / (0.01 * 0.01))
    );
    assert_eq!(
        lights::inverse_square(0.005, 0.01),
        lights::inverse_square(0.01, 0.01)
    );
    assert_eq!(lights::inverse_square(2.0, 0.01), 0.25);
    assert_eq!(lights::inverse_square(f64::MAX, 0.01), 0.0);
    assert_eq!(lights::inverse_square(f32::MAX, 0.01), 0.0);
    // An infinite distance is an overflow upstream (crate docs, "Bad input", rule 5).
    assert!(lights::inverse_square(f64::INFINITY, 0.01).is_nan());
    assert!(lights::inverse_square(f32::INFINITY, 0.01).is_nan());
}

/// An independent f64 evaluation of Karis's window, written from the formula.
fn karis(d: f64, r: f64) -> f64 {
    let x = 1.0 - (d / r).powi(4);
    x.clamp(0.0, 1.0).powi(2) / (d * d + 1.0)
}

#[test]
fn windowed_falloff_has_its_documented_edges() {
    let w = lights::windowed::<f64>;
    assert_eq!(w(0.0, 5.0), 1.0);
    assert_eq!(w(5.0, 5.0), 0.0);
    assert_eq!(w(7.0, 5.0), 0.0);
    assert_eq!(w(0.0, 0.0), 0.0, "radius 0 lights nothing, also at d = 0");
    assert_eq!(w(1.0, 0.0), 0.0);
    assert_eq!(w(3.0, f64::MAX), 1.0 / 10.0, "no window at radius MAX");
    assert_eq!(w(f64::MAX, 5.0), 0.0);
    assert_eq!(w(f64::MAX, f64::MAX), 0.0);
    assert_eq!(lights::windowed::<f32>(f32::MAX, f32::MAX), 0.0);
    // Infinite distances and radii are out of the domain (rule 5).
    assert!(w(3.0, f64::INFINITY).is_nan());
    assert!(w(f64::INFINITY, 5.0).is_nan());
    assert!(w(f64::INFINITY, f64::INFINITY).is_nan());
    assert!(lights::windowed::<f32>(f32::MAX, f32::INFINITY).is_nan());
    // Matches the formula in the interior and is non-increasing in d.
    let mut prev = f64::INFINITY;
    for i in 0..=1000 {
        let d = 6.0 * i as f64 / 1000.0;
        let v = w(d, 5.0);
        assert!((v - karis(d, 5.0)).abs() <= 1e-15, "d = {d}");
        assert!(v <= prev, "not monotone at d = {d}");
        prev = v;
    }
    // Zero slope at the radius: the one-sided difference quotient vanishes like (r - d)^1.
    let h = 1e-4;
    let slope = (w(5.0 - h, 5.0) - w(5.0, 5.0)) / h;
    assert!(slope.abs() < 1e-5, "slope at r: {slope:e}");
}

#[test]
fn windowed_inverse_square_is_window_times_the_inverse_square() {
    for (d, r) in [(0.0, 2.0), (0.5, 2.0), (1.9, 2.0), (2.0, 2.0), (3.0, 2.0)] {
        let v = lights::windowed_inverse_square(d, r, 0.01);
        let expected = (1.0 - (d / r).powi(4)).clamp(0.0, 1.0).powi(2) / f64::max(d, 0.01).powi(2);
        assert!(
            (v - expected).abs() <= 1e-12 * expected.max(1.0),
            "{d} {r}: {v} {expected}"
        );
    }
    assert_eq!(
        lights::windowed_inverse_square(3.0, f64::MAX, 0.01),
        1.0 / 9.0
    );
    assert_eq!(lights::windowed_inverse_square(3.0, 0.0, 0.01), 0.0);
    assert_eq!(
        lights::windowed_inverse_square(f64::MAX, f64::MAX, 0.01),
        0.0
    );
    assert!(lights::windowed_inverse_square(3.0, f64::INFINITY, 0.01).is_nan());
    assert!(lights::windowed_inverse_square(f64::INFINITY, f64::INFINITY, 0.01).is_nan());
}

#[test]
fn polynomial_attenuation_has_its_documented_edges() {
    let p = lights::polynomial::<f64>;
    assert_eq!(p(0.0, 2.0, 1.0, 1.0), 0.5);
    assert_eq!(p(3.0, 1.0, 0.0, 1.0), 0.1);
    assert_eq!(p(3.0, 1.0, 2.0, 0.5), 1.0 / (1.0 + 6.0 + 4.5));
    assert!(p(f64::MAX, 1.0, 0.5, 0.0) <= 2.0 / f64::MAX);
    assert_eq!(p(f64::MAX, 2.0, 0.0, 0.0), 0.5, "constant only: no 0 x inf");
    assert_eq!(p(f64::MAX, 1.0, 0.0, 1.0), 0.0);
    assert_eq!(lights::polynomial::<f32>(f32::MAX, 1.0, 0.0, 0.0), 1.0);
    assert!(p(f64::INFINITY, 1.0, 0.5, 0.0).is_nan());
    assert!(p(f64::INFINITY, 2.0, 0.0, 0.0).is_nan());
}

#[test]
fn spot_cone_is_one_inside_zero_outside_and_hard_when_the_cones_meet() {
    let (outer, inner) = (0.8_f64, 0.9_f64);
    assert_eq!(lights::spot_cone(1.0, outer, inner), 1.0);
    assert_eq!(lights::spot_cone(0.9, outer, inner), 1.0);
    assert_eq!(lights::spot_cone(0.8, outer, inner), 0.0);
    assert_eq!(lights::spot_cone(-1.0, outer, inner), 0.0);
    assert!((lights::spot_cone(0.85, outer, inner) - 0.25).abs() < 1e-12);
    let mut prev = 0.0;
    for i in 0..=200 {
        let c = 0.7 + 0.3 * i as f64 / 200.0;
        let v = lights::spot_cone(c, outer, inner);
        assert!(v >= prev && (0.0..=1.0).contains(&v));
        prev = v;
    }
    assert_eq!(
        lights::spot_cone(0.5, 0.5, 0.5),
        1.0,
        "hard edge: lit on the cone"
    );
    assert_eq!(lights::spot_cone(0.4999, 0.5, 0.5), 0.0);
    let cone = SpotCone::new(0.1_f64, 0.3).unwrap();
    assert_eq!(cone.eval(1.0), 1.0);
    assert_eq!(
        cone.eval(0.2_f64.cos()),
        lights::spot_cone(0.2_f64.cos(), 0.3_f64.cos(), 0.1_f64.cos())
    );
    assert_eq!(cone.eval(0.31_f64.cos()), 0.0);
    assert_eq!(
        SpotCone::new(0.2_f64, 0.2).unwrap().eval(0.2_f64.cos()),
        1.0
    );
}

#[test]
fn constructors_reject_parameters_outside_their_domain() {
    assert!(Attenuation::inverse_square(0.0_f64).is_err());
    assert!(Attenuation::inverse_square(f64::INFINITY).is_err());
    assert!(Attenuation::inverse_square(f64::NAN).is_err());
    assert!(Attenuation::windowed(-1.0_f64).is_err());
    assert!(Attenuation::windowed(f64::NAN).is_err());
    assert!(Attenuation::windowed(f64::MAX).is_ok());
    assert!(Attenuation::windowed(f64::INFINITY).is_err());
    assert!(Attenuation::windowed_inverse_square(f64::INFINITY, 0.01).is_err());
    assert!(Attenuation::windowed_inverse_square(1.0_f64, 0.0).is_err());
    assert!(Attenuation::polynomial(0.0_f64, 1.0, 1.0).is_err());
    assert!(Attenuation::polynomial(1.0_f64, -1.0, 1.0).is_err());
    assert!(Attenuation::polynomial(1.0_f64, 0.0, f64::INFINITY).is_err());
    let e = Attenuation::polynomial(1.0_f64, 0.0, f64::NAN).unwrap_err();
    assert_eq!(e.param, "quadratic");
    assert!(SpotCone::new(0.3_f64, 0.2).is_err(), "inner beyond outer");
    assert!(SpotCone::new(-0.1_f64, 0.2).is_err());
    assert!(SpotCone::new(0.1_f64, 4.0).is_err());
    assert!(SpotCone::new(f64::NAN, 0.2).is_err());
    let lanes = f32x8::from([0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, -1.0]);
    assert!(
        Attenuation::windowed(lanes).is_err(),
        "one bad lane rejects"
    );
    // The validated forms equal the kernels.
    let a = Attenuation::windowed_inverse_square(4.0_f64, 0.01).unwrap();
    assert_eq!(a.eval(1.5), lights::windowed_inverse_square(1.5, 4.0, 0.01));
    let a = Attenuation::polynomial(1.0_f64, 0.2, 0.1).unwrap();
    assert_eq!(a.eval(1.5), lights::polynomial(1.5, 1.0, 0.2, 0.1));
    let a = Attenuation::inverse_square(0.01_f64).unwrap();
    assert_eq!(a.eval(2.0), 0.25);
    assert_eq!(Attenuation::windowed(2.0_f64).unwrap().eval(0.0), 1.0);
}

/// Every kernel, on one lane type, as (name, value).
fn kernels<T: Real>(x: [f64; 4]) -> [(&'static str, T); 8] {
    let [a, b, c, d] = x.map(T::splat);
    [
        ("radiance", lights::radiance(a, b, c)),
        ("radiance_pi", lights::radiance_pi(a, b, c)),
        ("irradiance", lights::irradiance(a, c)),
        ("inverse_square", lights::inverse_square(a, b)),
        ("windowed", lights::windowed(a, b)),
        (
            "windowed_inverse_square",
            lights::windowed_inverse_square(a, b, c),
        ),
        ("polynomial", lights::polynomial(a, b, c, d)),
        ("spot_cone", lights::spot_cone(a, b, c)),
    ]
}

/// Valid arguments for every kernel of [`kernels`] at once.
const VALID: [f64; 4] = [0.5, 0.6, 0.7, 0.3];

fn nan_in_each_argument_gives_nan_on<T: Real>()
where
    T::Scalar: Into<f64>,
{
    for (name, v) in kernels::<T>(VALID) {
        assert!(!v.lane(0).into().is_nan(), "{name} NaN on valid input");
    }
    for i in 0..4 {
        let mut x = VALID;
        x[i] = f64::NAN;
        for (name, v) in kernels::<T>(x) {
            // Kernels that do not read argument i are unaffected; those that do must say NaN.
            let uses = match name {
                "irradiance" => i == 0 || i == 2,
                "inverse_square" | "windowed" => i < 2,
                "polynomial" => true,
                _ => i < 3,
            };
            if uses {
                for l in 0..T::LANES {
                    assert!(
                        v.lane(l).into().is_nan(),
                        "{name}: NaN in argument {i}, lane {l}"
                    );
                }
            }
        }
    }
}

#[test]
fn nan_in_any_input_gives_nan_on_every_lane_type() {
    nan_in_each_argument_gives_nan_on::<f32>();
    nan_in_each_argument_gives_nan_on::<f64>();
    nan_in_each_argument_gives_nan_on::<f32x8>();
    nan_in_each_argument_gives_nan_on::<f64x4>();
}

#[test]
fn parameters_outside_the_domain_give_nan() {
    let nan = |v: f64| assert!(v.is_nan(), "{v}");
    nan(lights::radiance(-0.1, 1.0, 0.5));
    nan(lights::radiance(0.1, -1.0, 0.5));
    nan(lights::inverse_square(-1.0, 0.01));
    nan(lights::inverse_square(1.0, 0.0));
    nan(lights::inverse_square(1.0, f64::INFINITY));
    nan(lights::windowed(-1.0, 1.0));
    nan(lights::windowed(1.0, -1.0));
    nan(lights::windowed_inverse_square(1.0, -1.0, 0.01));
    nan(lights::polynomial(1.0, 0.0, 1.0, 1.0));
    nan(lights::polynomial(1.0, 1.0, -1.0, 1.0));
    nan(lights::polynomial(-1.0, 1.0, 1.0, 1.0));
    nan(lights::spot_cone(0.5, 0.9, 0.8));
    nan(lights::spot_cone(2.0, 0.5, 0.9));
    nan(lights::radiance(f64::INFINITY, 1.0, 0.5));
    nan(lights::radiance(1.0, f64::INFINITY, 0.5));
    nan(lights::radiance(1.0, 1.0, 5.0));
    nan(lights::spot_cone(0.5, -1.5, 0.8));
    // Rule 5: infinite distances and radii give NaN; an infinite cosine counts as +-1.
    nan(lights::inverse_square(f64::INFINITY, 0.01));
    nan(lights::windowed(f64::INFINITY, 1.0));
    nan(lights::windowed(1.0, f64::INFINITY));
    nan(lights::polynomial(f64::INFINITY, 1.0, 0.0, 0.0));
    assert_eq!(
        lights::radiance(1.0, 1.0, f64::INFINITY),
        lights::radiance(1.0, 1.0, 1.0)
    );
    assert_eq!(lights::radiance(1.0, 1.0, f64::NEG_INFINITY), 0.0);
    assert_eq!(lights::spot_cone(f64::INFINITY, 0.5, 0.9), 1.0);
    assert_eq!(lights::spot_cone(f64::NEG_INFINITY, 0.5, 0.9), 0.0);
}

#[test]
fn lanes_equal_scalars() {
    let inputs: [[f64; 4]; 8] = [
        VALID,
        [0.0, 0.0, 0.0, 0.0],
        [1.0, 1e-3, 1.0, 1.0],
        [1e30, 3.0, -0.5, 0.0],
        [2.5, 1e30, 0.95, 2.0],
        [1e30, 1e-3, 0.25, 1e-3],
        [0.3, 0.3, 0.3, 0.3],
        [5.0, 4.0, 1.0, 0.5],
    ];
    for x in inputs {
        let s32 = kernels::<f32>(x);
        let s64 = kernels::<f64>(x);
        let l32 = kernels::<f32x8>(x);
        let l64 = kernels::<f64x4>(x);
        for k in 0..s32.len() {
            for l in 0..8 {
                assert_eq!(
                    l32[k].1.lane(l).to_bits(),
                    s32[k].1.to_bits(),
                    "{} {x:?}",
                    s32[k].0
                );
            }
            for l in 0..4 {
                assert_eq!(
                    l64[k].1.lane(l).to_bits(),
                    s64[k].1.to_bits(),
                    "{} {x:?}",
                    s64[k].0
                );
            }
        }
    }
    // Mixed lanes: each lane equals the scalar of its own inputs.
    let d = f32x8::from([0.0, 0.5, 1.0, 2.0, 4.0, 8.0, f32::INFINITY, 1e30]);
    let r = f32x8::from([
        1.0,
        0.0,
        3.0,
        f32::MAX,
        4.0,
        9.0,
        f32::INFINITY,
        f32::INFINITY,
    ]);
    let v = lights::windowed(d, r);
    for l in 0..8 {
        assert_eq!(
            v.lane(l).to_bits(),
            lights::windowed(d.lane(l), r.lane(l)).to_bits()
        );
    }
}

proptest! {
    #![proptest_config(common::proptest_config())]
    /// Finite and non-negative over each documented domain, including distances and radii
    /// up to the largest float.
    #[test]
    fn falloffs_are_finite_and_non_negative_over_their_domains(
        d in prop_oneof![0.0f64..10.0, 0.0f64..f64::MAX, Just(f64::MAX), Just(0.0)],
        r in prop_oneof![0.0f64..10.0, 0.0f64..f64::MAX, Just(f64::MAX), Just(0.0)],
        dmin in prop_oneof![1e-3f64..1.0, Just(f64::MAX)],
        k in prop::array::uniform3(0.0f64..1e3),
        cos in -1.0f64..=1.0, lo in -1.0f64..=1.0, hi in -1.0f64..=1.0,
    ) {
        let constant = k[0] + 1e-3;
        let (outer, inner) = (lo.min(hi), lo.max(hi));
        let mut values = vec![
            lights::inverse_square(d, dmin),
            lights::windowed(d, r),
            lights::windowed_inverse_square(d, r, dmin),
            lights::polynomial(d, constant, k[1], k[2]),
            lights::spot_cone(cos, outer, inner),
        ];
        // Rounded to f32 and kept in its finite range (`as` rounds beyond it to +inf).
        let (d32, r32) = ((d as f32).min(f32::MAX), (r as f32).min(f32::MAX));
        for v in [
            lights::inverse_square(d32, (dmin as f32).min(f32::MAX)),
            lights::windowed(d32, r32),
            lights::windowed_inverse_square(d32, r32, dmin.min(1.0) as f32),
            lights::polynomial(d32, constant as f32, k[1] as f32, k[2] as f32),
            lights::spot_cone(cos as f32, outer as f32, inner as f32),
        ] {
            values.push(v.into());
        }
        for v in values {
            prop_assert!(v.is_finite() && v >= 0.0, "{v} at d {d} r {r}");
        }
    }
}

/// Non-negative finite values of `T` from 0 through subnormals to `T::MAX`.
fn magnitudes<T: Real>() -> Vec<T> {
    let max: f64 = T::MAX.lane(0).into();
    let tiny: f64 = T::MIN_POSITIVE.lane(0).into();
    [
        0.0,
        tiny * 1e-3,
        tiny,
        1e-30,
        1e-7,
        0.01,
        0.5,
        1.0,
        3.0,
        1e7,
        1e30,
        max.sqrt(),
        max,
    ]
    .into_iter()
    .map(T::splat)
    .collect()
}

/// Cosines: +-1, +-0, subnormal, 1e-7, the middle, 1 - 2^-24.
fn unit_cosines<T: Real>() -> Vec<T> {
    let tiny: f64 = T::MIN_POSITIVE.lane(0).into();
    [
        -1.0,
        -0.5,
        -0.0,
        0.0,
        tiny * 1e-3,
        tiny,
        1e-7,
        0.5,
        1.0 - 2f64.powi(-24),
        1.0,
    ]
    .into_iter()
    .map(T::splat)
    .collect()
}

fn in_range<T: Real>(name: &str, x: T, hi: f64, args: &[T]) {
    for i in 0..T::LANES {
        let v: f64 = x.lane(i).into();
        assert!(
            v.is_finite() && (0.0..=hi).contains(&v),
            "{name} = {v} outside [0, {hi}] at {args:?}"
        );
    }
}

/// Every light function over the whole of its documented domain (finite parameters up to
/// `T::MAX`, cosines in [-1, 1] including +-0 and subnormals): finite and
/// in its documented range, never inf or NaN.
fn whole_domain<T: Real>() -> usize {
    let max: f64 = T::MAX.lane(0).into();
    let mags = magnitudes::<T>();
    let cosines = unit_cosines::<T>();
    let distances = mags.clone();
    let mut n = 0;
    for &a in &mags {
        for &b in &mags {
            for &c in &cosines {
                in_range("radiance", lights::radiance(a, b, c), max, &[a, b, c]);
                in_range("radiance_pi", lights::radiance_pi(a, b, c), max, &[a, b, c]);
                n += 2;
            }
        }
        for &c in &cosines {
            in_range("irradiance", lights::irradiance(a, c), max, &[a, c]);
            n += 1;
        }
    }
    for &d in &distances {
        for &m in mags.iter().filter(|m| m.lane(0).into() > 0.0) {
            in_range("inverse_square", lights::inverse_square(d, m), max, &[d, m]);
            n += 1;
        }
        for &r in &distances {
            in_range("windowed", lights::windowed(d, r), 1.0, &[d, r]);
            for &m in mags.iter().filter(|m| m.lane(0).into() > 0.0) {
                let w = lights::windowed_inverse_square(d, r, m);
                in_range("windowed_inverse_square", w, max, &[d, r, m]);
                n += 1;
            }
        }
        for &kc in mags.iter().filter(|m| m.lane(0).into() > 0.0) {
            for &kl in &mags {
                for &kq in &mags {
                    let p = lights::polynomial(d, kc, kl, kq);
                    in_range("polynomial", p, max, &[d, kc, kl, kq]);
                    n += 1;
                }
            }
        }
    }
    for &c in &cosines {
        for &o in &cosines {
            for &i in &cosines {
                if o.lane(0).into() <= i.lane(0).into() {
                    in_range("spot_cone", lights::spot_cone(c, o, i), 1.0, &[c, o, i]);
                    n += 1;
                }
            }
        }
    }
    n
}

#[test]
fn every_function_is_finite_and_in_range_over_its_documented_domain() {
    let n = whole_domain::<f32>() + whole_domain::<f64>();
    let l = whole_domain::<f32x8>() + whole_domain::<f64x4>();
    println!("{n} scalar and {l} lane evaluations finite and in range");
}
