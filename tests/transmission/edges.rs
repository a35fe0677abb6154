//! Edges of the rough dielectric: eta = 1 is a pass-through, total internal reflection sends
//! everything back, the extreme grid (alpha 0 and 1 and beyond, eta next to 1 on both sides
//! and at the ends of its domain, grazing directions) gives finite non-negative values, and
//! lanes equal scalars there; NaN in any input gives NaN.

use crate::dir;
use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::rough_dielectric::{self as rd, Transport};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

#[test]
fn eta_one_is_a_pass_through() {
    let g = Ggx::new(0.3, 0.6).unwrap();
    for theta in [0.0, 40.0, 89.0, 180.0, 120.0, 91.0] {
        let wo = dir(theta, 70.0);
        for t in [Transport::Radiance, Transport::Importance] {
            for u in [0.0, 0.3, 0.999] {
                let (wi, p, w) = rd::ggx_sample(&g, wo, 1.0, u, 0.4, 0.8, t);
                assert_eq!((wi.x, wi.y, wi.z), (-wo.x, -wo.y, -wo.z));
                assert_eq!((p, w), (f64::MAX, 1.0));
            }
            // And the Dirac has no density: eval and pdf are 0 everywhere, -wo included.
            for wi in [-wo, dir(150.0, 10.0), dir(20.0, 200.0)] {
                assert_eq!(rd::eval(&g, wo, wi, 1.0, t), 0.0);
                assert_eq!(rd::pdf(&g, wo, wi, 1.0), 0.0);
            }
        }
    }
    // Next to 1 the interface is nearly invisible: almost no reflection, refraction nearly
    // straight through.
    let (wi, p, w) = rd::ggx_sample(
        &g,
        dir(30.0, 0.0),
        1.0 + 1e-6,
        0.5,
        0.4,
        0.8,
        Transport::Radiance,
    );
    assert!(
        wi.z < 0.0 && p > 0.0 && w > 0.0 && (wi + dir(30.0, 0.0)).length() < 1e-5,
        "{wi:?}"
    );
}

#[test]
fn total_internal_reflection_sends_everything_back() {
    // From inside glass at 60 degrees with a nearly smooth Beckmann surface (no facet steeper
    // than a few alpha: GGX's long tail would still refract a little) every facet is beyond
    // the critical angle: each sample reflects with weight <= 1, and eval has no transmission.
    let g = Beckmann::isotropic(0.01).unwrap();
    let wo = dir(120.0, 0.0);
    let mut rng = crate::common::Rng(3);
    for _ in 0..1000 {
        let (wi, p, w) = rd::beckmann_sample(
            &g,
            wo,
            1.5,
            rng.next_f64(),
            rng.next_f64(),
            rng.next_f64(),
            Transport::Radiance,
        );
        assert!(
            wi.z < 0.0 && p > 0.0 && w > 0.0 && w <= 1.0,
            "{wi:?} {p} {w}"
        );
    }
    for theta in [0.0, 20.0, 60.0, 89.0] {
        assert_eq!(
            rd::eval(&g, wo, dir(theta, 180.0), 1.5, Transport::Radiance),
            0.0
        );
    }
    // The same view from outside transmits.
    assert!(
        rd::eval(
            &g,
            dir(60.0, 0.0),
            crate::refracted(dir(60.0, 0.0), 1.5).unwrap(),
            1.5,
            Transport::Radiance
        ) > 0.0
    );
}

fn grid_dirs() -> Vec<V3<f64>> {
    let mut out = vec![V3::new(0.0, 0.0, 0.0)];
    for theta in [
        0.0,
        1e-4,
        30.0,
        89.9,
        90.0 - 1e-7,
        90.0,
        90.0 + 1e-7,
        90.1,
        150.0,
        180.0,
    ] {
        for phi in [0.0, 135.0] {
            out.push(dir(theta, phi));
        }
    }
    out
}

const ALPHAS: [f64; 5] = [0.0, 1e-4, 0.5, 1.0, 1e4];
const ETAS: [f64; 9] = [
    1e-30,
    0.5,
    1.0 - 1e-6,
    1.0 - 1e-12,
    1.0,
    1.0 + 1e-12,
    1.0 + 1e-6,
    1.5,
    1e30,
];
const US: [f64; 3] = [0.0, 0.5, 1.0];

/// Every finite in-domain input of the grid gives finite non-negative f, pdf and weight, on
/// f32 and f64, and the lanes (f32x8, f64x4) equal the scalars bit for bit (the kernel is
/// arithmetic, sqrt and the lanes' own exact Fresnel and Lambda, which are lane-exact for
/// these models except the Beckmann erf/exp terms, bounded below).
#[test]
fn extreme_grid_is_finite_and_lanes_equal_scalars() {
    let dirs = grid_dirs();
    let mut max_ulps_beckmann = 0u64;
    for alpha in ALPHAS {
        for eta in ETAS {
            for (i, &wo) in dirs.iter().enumerate() {
                for &wi in dirs.iter().skip(i % 3) {
                    for t in [Transport::Radiance, Transport::Importance] {
                        grid_point::<f64>(alpha, eta, wo, wi, t);
                        grid_point::<f32>(alpha, eta, wo, wi, t);
                    }
                }
                for u in US {
                    let g = Ggx::isotropic(alpha).unwrap();
                    let (w, p, x) =
                        rd::ggx_sample(&g, wo, eta, u, 1.0 - u, 0.3, Transport::Radiance);
                    assert!(
                        w.x.is_finite() && p >= 0.0 && p.is_finite() && x >= 0.0 && x.is_finite(),
                        "{alpha} {eta} {wo:?} {u}: {w:?} {p} {x}"
                    );
                    let b = Beckmann::isotropic(alpha).unwrap();
                    let (w, p, x) =
                        rd::beckmann_sample(&b, wo, eta, u, 1.0 - u, 0.3, Transport::Importance);
                    assert!(
                        w.x.is_finite() && p >= 0.0 && p.is_finite() && x >= 0.0 && x.is_finite(),
                        "{alpha} {eta} {wo:?} {u}: {w:?} {p} {x}"
                    );
                    // Lanes of the samplers.
                    let g4 = Ggx::isotropic(f64x4::splat(alpha)).unwrap();
                    let s = |x: f64| f64x4::splat(x);
                    let (w4, p4, x4) = rd::ggx_sample(
                        &g4,
                        V3::new(s(wo.x), s(wo.y), s(wo.z)),
                        s(eta),
                        s(u),
                        s(1.0 - u),
                        s(0.3),
                        Transport::Radiance,
                    );
                    let (w1, p1, x1) =
                        rd::ggx_sample(&g, wo, eta, u, 1.0 - u, 0.3, Transport::Radiance);
                    assert_eq!(
                        (
                            w4.x.lane(2),
                            w4.y.lane(2),
                            w4.z.lane(2),
                            p4.lane(1),
                            x4.lane(3)
                        ),
                        (w1.x, w1.y, w1.z, p1, x1)
                    );
                    let b4 = Beckmann::isotropic(f64x4::splat(alpha)).unwrap();
                    let (_, p4, _) = rd::beckmann_sample(
                        &b4,
                        V3::new(s(wo.x), s(wo.y), s(wo.z)),
                        s(eta),
                        s(u),
                        s(1.0 - u),
                        s(0.3),
                        Transport::Radiance,
                    );
                    let (_, p1, _) =
                        rd::beckmann_sample(&b, wo, eta, u, 1.0 - u, 0.3, Transport::Radiance);
                    max_ulps_beckmann = max_ulps_beckmann.max(ulps(p4.lane(0), p1));
                }
            }
        }
    }
    println!("beckmann sampler pdf, f64x4 lane vs scalar: max {max_ulps_beckmann} ulps");
    // The Beckmann visible-normal sampler's lanes use polynomial erf/exp (crate docs); its
    // 7 Newton steps amplify them, and a near-singular pdf amplifies the normal's error.
    assert!(max_ulps_beckmann < 1 << 40 || max_ulps_beckmann == u64::MAX);
}

fn ulps(a: f64, b: f64) -> u64 {
    if a == b {
        return 0;
    }
    if !a.is_finite() || !b.is_finite() {
        return u64::MAX;
    }
    (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
}

fn grid_point<T: Real + Copy>(alpha: f64, eta: f64, wo: V3<f64>, wi: V3<f64>, t: Transport)
where
    T::Scalar: Into<f64>,
{
    let c = |w: V3<f64>| V3::new(T::splat(w.x), T::splat(w.y), T::splat(w.z));
    let g = Ggx::isotropic(T::splat(alpha)).unwrap();
    let b = Beckmann::isotropic(T::splat(alpha)).unwrap();
    for (f, p) in [
        (
            rd::eval(&g, c(wo), c(wi), T::splat(eta), t),
            rd::pdf(&g, c(wo), c(wi), T::splat(eta)),
        ),
        (
            rd::eval(&b, c(wo), c(wi), T::splat(eta), t),
            rd::pdf(&b, c(wo), c(wi), T::splat(eta)),
        ),
    ] {
        for k in 0..T::LANES {
            let (f, p): (f64, f64) = (f.lane(k).into(), p.lane(k).into());
            assert!(
                f.is_finite() && f >= 0.0 && p.is_finite() && p >= 0.0,
                "alpha {alpha} eta {eta} {wo:?} {wi:?}: f {f} pdf {p}"
            );
        }
    }
    let h = rd::half_vector(c(wo), c(wi), T::splat(eta));
    assert!(h.z.lane(0).into() >= 0.0);
}

/// eval and pdf on lanes equal the scalar ones bit for bit for GGX (arithmetic, sqrt and the
/// crate's lane-exact Fresnel and Lambda) at random points.
#[test]
fn lanes_equal_scalars() {
    let mut rng = crate::common::Rng(11);
    let mut d = || {
        let z = 2.0 * rng.next_f64() - 1.0;
        let p = core::f64::consts::TAU * rng.next_f64();
        let r = (1.0 - z * z).sqrt();
        [r * p.cos(), r * p.sin(), z]
    };
    for _ in 0..2000 {
        let (a, b) = (d(), d());
        let eta = [1.5, 0.7, 1.0 + 1e-6][(a[0].abs() * 3.0) as usize % 3];
        let g = Ggx::new(0.3, 0.7).unwrap();
        let f1 = rd::eval(&g, a.into(), b.into(), eta, Transport::Radiance);
        let p1 = rd::pdf(&g, a.into(), b.into(), eta);
        let g8 = Ggx::new(f32x8::splat(0.3), f32x8::splat(0.7)).unwrap();
        let s = |x: f64| f32x8::splat(x as f32);
        let f8 = rd::eval(
            &g8,
            V3::new(s(a[0]), s(a[1]), s(a[2])),
            V3::new(s(b[0]), s(b[1]), s(b[2])),
            s(eta),
            Transport::Radiance,
        );
        let gs = Ggx::new(0.3_f32, 0.7).unwrap();
        let fs = rd::eval(
            &gs,
            V3::new(a[0] as f32, a[1] as f32, a[2] as f32),
            V3::new(b[0] as f32, b[1] as f32, b[2] as f32),
            eta as f32,
            Transport::Radiance,
        );
        assert_eq!(f8.lane(4).to_bits(), fs.to_bits(), "{a:?} {b:?} {eta}");
        let g4 = Ggx::new(f64x4::splat(0.3), f64x4::splat(0.7)).unwrap();
        let s4 = |x: f64| f64x4::splat(x);
        let p4 = rd::pdf(
            &g4,
            V3::new(s4(a[0]), s4(a[1]), s4(a[2])),
            V3::new(s4(b[0]), s4(b[1]), s4(b[2])),
            s4(eta),
        );
        let f4 = rd::eval(
            &g4,
            V3::new(s4(a[0]), s4(a[1]), s4(a[2])),
            V3::new(s4(b[0]), s4(b[1]), s4(b[2])),
            s4(eta),
            Transport::Radiance,
        );
        assert_eq!(
            (f4.lane(1).to_bits(), p4.lane(3).to_bits()),
            (f1.to_bits(), p1.to_bits()),
            "{a:?} {b:?} {eta}"
        );
    }
}

#[test]
fn nan_in_any_input_gives_nan() {
    let g = Ggx::isotropic(0.3).unwrap();
    let (wo, wi) = (dir(30.0, 0.0), dir(160.0, 180.0));
    let nan = f64::NAN;
    for k in 0..3 {
        let mut o = [wo.x, wo.y, wo.z];
        o[k] = nan;
        let mut i = [wi.x, wi.y, wi.z];
        i[k] = nan;
        assert!(rd::eval(&g, o.into(), wi, 1.5, Transport::Radiance).is_nan());
        assert!(rd::eval(&g, wo, i.into(), 1.5, Transport::Radiance).is_nan());
        assert!(rd::pdf(&g, o.into(), wi, 1.5).is_nan());
        assert!(rd::pdf(&g, wo, i.into(), 1.5).is_nan());
        assert!(rd::half_vector(o.into(), wi, 1.5).x.is_nan());
        let (w, p, x) = rd::ggx_sample(&g, o.into(), 1.5, 0.5, 0.5, 0.5, Transport::Radiance);
        assert!(w.x.is_nan() && w.y.is_nan() && w.z.is_nan() && p.is_nan() && x.is_nan());
    }
    for eta in [nan, 0.0, -1.0, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(
            rd::eval(&g, wo, wi, eta, Transport::Importance).is_nan(),
            "{eta}"
        );
        assert!(rd::pdf(&g, wo, wi, eta).is_nan(), "{eta}");
        let (w, p, x) = rd::beckmann_sample(
            &Beckmann::isotropic(0.3).unwrap(),
            wo,
            eta,
            0.5,
            0.5,
            0.5,
            Transport::Radiance,
        );
        assert!(w.x.is_nan() && p.is_nan() && x.is_nan(), "{eta}");
    }
    for u in 0..3 {
        let mut us = [0.5; 3];
        us[u] = nan;
        for eta in [1.5, 1.0] {
            let (w, p, x) = rd::ggx_sample(&g, wo, eta, us[0], us[1], us[2], Transport::Radiance);
            assert!(w.x.is_nan() && p.is_nan() && x.is_nan(), "u{u} eta {eta}");
        }
    }
}
