//! Stability on stiff and extreme inputs (issue 3): alpha in {0, 1e-7, 1e-4, 1}, cosines in
//! {0, 1e-7, 1 - 1e-7, 1, just above 1, negative}, eta in {1, 1 +- 1e-6, 0.5, 10}, k up to
//! 1e3, in f32, f64 and f32x8 lanes. Never NaN, never inf except where documented (Lambda at
//! the horizon), the documented value at each edge, lanes equal to scalars, and every exact
//! f32 function within its stated ULP bound of its f64 twin over a dense sweep.
#![cfg(all(feature = "ggx", feature = "beckmann", feature = "fresnel"))]

use crate::common;
use brdf::beckmann::{self, Beckmann};
use brdf::fresnel;
use brdf::ggx::{self, Ggx};
use brdf::microfacet::{ALPHA_MIN, Microfacet};
use brdf::wide::f32x8;
use brdf::{Real, V3};
use proptest::prelude::*;

const ALPHAS: [f64; 4] = [0.0, 1e-7, 1e-4, 1.0];
const COSINES: [f64; 8] = [0.0, 1e-7, 1.0 - 1e-7, 1.0, 1.0 + 1e-6, -1e-7, -0.5, 0.5];
const ETAS: [f64; 6] = [1.0, 1.0 + 1e-6, 1.0 - 1e-6, 0.5, 10.0, 1.5];
const KS: [f64; 4] = [0.0, 1.0, 100.0, 1e3];

/// A unit local direction with the given cosine (clamped into [-1, 1] for the vector; the
/// free functions get the raw cosine).
fn dir<T: Real>(c: f64) -> V3<T> {
    let c = c.clamp(-1.0, 1.0);
    let s = ((1.0 - c) * (1.0 + c)).sqrt();
    V3::new(T::splat(0.6 * s), T::splat(0.8 * s), T::splat(c))
}

/// (name, value, may be +inf, allowed range).
type Output<T> = (&'static str, T, bool, Option<(f64, f64)>);

/// Every scalar quantity the kernels produce for one input combination, with whether it may
/// be +inf (Lambda at the horizon) and its range.
fn kernels<T: Real>(a: f64, cv: f64, cl: f64, eta: f64, k: f64) -> Vec<Output<T>> {
    let (at, v, l) = (T::splat(a), T::splat(cv), T::splat(cl));
    let unit = Some((0.0, 1.0));
    let g = Ggx::isotropic(at).unwrap();
    let ga = Ggx::new(at, T::splat(1.0)).unwrap();
    let b = Beckmann::isotropic(at).unwrap();
    let (wv, wl) = (dir::<T>(cv), dir::<T>(cl));
    let h = (wv + wl).normalize_or(V3::unit_z());
    vec![
        ("ggx::d", ggx::d(v, at), false, None),
        ("ggx::lambda", ggx::lambda(v, at), true, None),
        ("ggx::g1", ggx::g1(v, at), false, unit),
        (
            "ggx::v_correlated",
            ggx::v_correlated(v, l, at),
            false,
            None,
        ),
        (
            "ggx::v_correlated_hammon",
            ggx::v_correlated_hammon(v, l, at),
            false,
            None,
        ),
        (
            "ggx::v_correlated_fast",
            ggx::v_correlated_fast(v, l, at),
            false,
            None,
        ),
        (
            "ggx::g1_schlick",
            ggx::g1_schlick(v, ggx::schlick_k_ibl(at)),
            false,
            unit,
        ),
        (
            "ggx::v_schlick",
            ggx::v_schlick(v, l, ggx::schlick_k_analytic(at)),
            false,
            None,
        ),
        ("Ggx.d", g.d(h), false, None),
        ("Ggx(aniso).d", ga.d(h), false, None),
        ("Ggx.lambda", g.lambda(wv), true, None),
        ("Ggx.cos_lambda", g.cos_lambda(wv), false, None),
        ("Ggx.g2_correlated", g.g2_correlated(wv, wl), false, unit),
        ("Ggx.v_correlated", g.v_correlated(wv, wl), false, None),
        ("Ggx.d_visible", g.d_visible(wv, h), false, None),
        ("beckmann::d", beckmann::d(v, at), false, None),
        ("beckmann::lambda", beckmann::lambda(v, at), true, None),
        ("beckmann::g1", beckmann::g1(v, at), false, unit),
        (
            "beckmann::lambda_walter",
            beckmann::lambda_walter(v, at),
            true,
            None,
        ),
        ("Beckmann.d", b.d(h), false, None),
        ("Beckmann.cos_lambda", b.cos_lambda(wv), false, None),
        ("Beckmann.v_correlated", b.v_correlated(wv, wl), false, None),
        ("Beckmann.d_visible", b.d_visible(wv, h), false, None),
        (
            "fresnel::dielectric",
            fresnel::dielectric(v, T::splat(eta)),
            false,
            unit,
        ),
        (
            "fresnel::conductor",
            fresnel::conductor(v, T::splat(eta), T::splat(k)),
            false,
            unit,
        ),
        (
            "fresnel::schlick",
            fresnel::schlick(fresnel::f0_from_ior(T::splat(eta)), v),
            false,
            unit,
        ),
        (
            "fresnel::schlick_sg",
            fresnel::schlick_sg(T::splat(0.04), v),
            false,
            unit,
        ),
        (
            "fresnel::schlick_f82",
            fresnel::schlick_f82(T::splat(0.9), T::splat(0.5), v),
            false,
            unit,
        ),
    ]
}

fn for_each_input(mut f: impl FnMut(f64, f64, f64, f64, f64)) {
    for a in ALPHAS {
        for cv in COSINES {
            for cl in COSINES {
                for (i, eta) in ETAS.iter().enumerate() {
                    f(a, cv, cl, *eta, KS[i % KS.len()]);
                }
            }
        }
    }
}

fn check_values<T: Real>(label: &str) {
    for_each_input(|a, cv, cl, eta, k| {
        for (name, value, may_be_inf, range) in kernels::<T>(a, cv, cl, eta, k) {
            for i in 0..T::LANES {
                let x: f64 = value.lane(i).into();
                let ctx =
                    format!("{label} {name} alpha {a} cos_v {cv} cos_l {cl} eta {eta} k {k}: {x}");
                assert!(!x.is_nan(), "NaN: {ctx}");
                assert!(x >= 0.0, "negative: {ctx}");
                if !(may_be_inf && x == f64::INFINITY) {
                    assert!(x.is_finite(), "inf: {ctx}");
                }
                if let Some((lo, hi)) = range {
                    assert!((lo..=hi).contains(&x), "out of [{lo}, {hi}]: {ctx}");
                }
            }
        }
    });
}

#[test]
fn no_nan_or_unexpected_inf_in_f32() {
    check_values::<f32>("f32");
}

#[test]
fn no_nan_or_unexpected_inf_in_f64() {
    check_values::<f64>("f64");
}

#[test]
fn no_nan_or_unexpected_inf_in_lanes() {
    check_values::<f32x8>("f32x8");
}

#[test]
fn lanes_equal_scalars_on_the_extreme_grid() {
    for_each_input(|a, cv, cl, eta, k| {
        let s = kernels::<f32>(a, cv, cl, eta, k);
        let l = kernels::<f32x8>(a, cv, cl, eta, k);
        for ((name, x, ..), (_, y, ..)) in s.iter().zip(&l) {
            for i in 0..8 {
                let y = y.lane(i);
                // Lanes share every operation with the scalar path except exp/exp2 (1 ulp,
                // src/real.rs), used by Beckmann and the SG Fresnel; 2 ulps covers one exp
                // feeding a product.
                let tol = 2.0 * f32::EPSILON * x.abs();
                assert!(
                    x == &y || (x - y).abs() <= tol,
                    "{name}: scalar {x} lane {y} (alpha {a}, {cv}, {cl}, eta {eta})"
                );
            }
        }
    });
}

#[test]
fn documented_edge_values() {
    let amin = ALPHA_MIN;
    // alpha = 0 is clamped to ALPHA_MIN: the peak of D is 1 / (pi ALPHA_MIN^2), finite.
    assert_eq!(ggx::d(1.0, 0.0), ggx::d(1.0, amin));
    assert!((ggx::d(1.0, 0.0) - 1.0 / (core::f64::consts::PI * amin * amin)).abs() < 1e-6);
    assert_eq!(beckmann::d(1.0, 0.0), beckmann::d(1.0, amin));
    // Lambda's pole at the horizon is capped at MAX, so G1 and the correlated G2 are 0 there.
    assert_eq!(ggx::lambda(0.0, 0.5), f64::MAX);
    assert_eq!(beckmann::lambda(0.0, 0.5), f64::MAX);
    assert_eq!(ggx::g1(0.0, 0.5), 0.0);
    assert_eq!(beckmann::g1(0.0, 0.5), 0.0);
    // At the normal: Lambda = 0, G1 = 1.
    assert_eq!(ggx::lambda(1.0, 0.5), 0.0);
    assert_eq!(beckmann::lambda(1.0, 0.5), 0.0);
    assert_eq!(ggx::g1(1.0, 0.5), 1.0);
    // Cosines just above 1 are 1; negative cosines give D = 0.
    assert_eq!(ggx::d(1.0 + 1e-6, 0.3), ggx::d(1.0, 0.3));
    assert_eq!(ggx::d(-0.5, 0.3), 0.0);
    // V: finite with one grazing cosine (0.5 / (NoV alpha)), 0 with both.
    assert!((ggx::v_correlated(0.5, 0.0, 0.3) - 0.5 / (0.5 * 0.3)).abs() < 1e-12);
    assert_eq!(ggx::v_correlated(0.0, 0.0, 0.3), 0.0);
    let g = Ggx::isotropic(0.3).unwrap();
    assert_eq!(
        g.v_correlated(V3::new(1.0, 0.0, 0.0), V3::new(0.0, 1.0, 0.0)),
        0.0
    );
    // Fresnel: eta = 1 reflects nothing; grazing reflects everything; huge k is a mirror.
    assert_eq!(fresnel::dielectric(0.3, 1.0), 0.0);
    assert_eq!(fresnel::dielectric(0.0, 1.5), 1.0);
    assert!(fresnel::conductor(1.0, 1.0, 1e3) > 0.999_99);
    // Constructors reject what the kernels cannot take.
    assert!(Ggx::new(-0.1, 0.2).is_err());
    assert!(Ggx::isotropic(f64::NAN).is_err());
    assert!(Beckmann::new(0.1, f64::INFINITY).is_err());
    assert_eq!(Ggx::isotropic(-1.0f32).unwrap_err().param, "alpha_x");
}

/// Distance in f32 ulps between an f32 result and the f64 result rounded to f32.
fn ulps(x32: f32, x64: f64) -> u64 {
    let r = x64 as f32;
    if x32 == r || (x32.is_nan() && r.is_nan()) {
        return 0;
    }
    if !x32.is_finite() || !r.is_finite() {
        return u64::MAX;
    }
    let key = |x: f32| {
        let i = x.to_bits() as i32;
        (if i < 0 { i32::MIN - i } else { i }) as i64
    };
    (key(x32) - key(r)).unsigned_abs()
}

/// Cosines for the sweep: uniform, plus the last 64 f32 values below 1 and the first above 0,
/// where cancellation would show.
fn sweep_cosines() -> Vec<f32> {
    let mut v: Vec<f32> = (1..=400).map(|i| i as f32 / 400.0).collect();
    let mut c = 1.0f32;
    for _ in 0..64 {
        c = f32::from_bits(c.to_bits() - 1);
        v.push(c);
    }
    v.extend([1e-7, 1e-5, 1e-3]);
    v
}

const SWEEP_ALPHAS: [f32; 9] = [2e-4, 1e-3, 0.01, 0.05, 0.1, 0.3, 0.5, 0.8, 1.0];

fn worst_ulps(f32f: impl Fn(f32, f32) -> f32, f64f: impl Fn(f64, f64) -> f64) -> (u64, f32, f32) {
    let mut worst = (0, 0.0, 0.0);
    for a in SWEEP_ALPHAS {
        for c in sweep_cosines() {
            let u = ulps(f32f(c, a), f64f(c as f64, a as f64));
            if u > worst.0 {
                worst = (u, c, a);
            }
        }
    }
    worst
}

/// f32 twins of the parameters built from the sweep's alpha, so both precisions see the same
/// input values (eta = 1 + alpha rounded in f32, not in f64).
fn eta_above(a: f32) -> f32 {
    1.0 + a
}
fn eta_below(a: f32) -> f32 {
    1.0 / (1.0 + a)
}

#[test]
fn f32_kernels_stay_within_their_ulp_bound_of_f64() {
    // (name, bound, f32 version, f64 version on the same inputs). 4 ulps is issue 3's target;
    // the looser bounds are the measured maxima with their reason:
    // - ggx::d, fresnel::schlick: 5. D = alpha^2 / (pi t^2) squares the ~1.5-ulp error of
    //   t = sin^2 + cos^2 alpha^2; Schlick's (1 - c)^5 multiplies the rounding of 1 - c
    //   (for c < 1/2) by 5.
    // - fresnel::conductor: 16 (measured 13). The scaled complex square root and the two
    //   ratios of sums of squares round about a dozen times; against a 300-bit reference the
    //   f32 conductor alone is within 8.3 ulps (src/fresnel.rs, "Accuracy").
    // - fresnel::dielectric with eta < 1: 49, at the critical cosine, where F has an infinite
    //   slope in k = c^2 + eta^2 - 1 and the rounding of that sum is amplified (eta > 1 has
    //   no critical angle: 5).
    // - Beckmann: see beckmann_f32_error_is_bounded_by_its_exponent below.
    type Pair = (&'static str, u64, fn(f32, f32) -> f32, fn(f64, f64) -> f64);
    let cases: [Pair; 10] = [
        ("ggx::d", 5, |c, a| ggx::d(c, a), |c, a| ggx::d(c, a)),
        (
            "ggx::lambda",
            4,
            |c, a| ggx::lambda(c, a),
            |c, a| ggx::lambda(c, a),
        ),
        ("ggx::g1", 4, |c, a| ggx::g1(c, a), |c, a| ggx::g1(c, a)),
        (
            "ggx::v_correlated (NoL = NoV)",
            4,
            |c, a| ggx::v_correlated(c, c, a),
            |c, a| ggx::v_correlated(c, c, a),
        ),
        (
            "ggx::v_correlated (NoL = 0.5)",
            4,
            |c, a| ggx::v_correlated(c, 0.5, a),
            |c, a| ggx::v_correlated(c, 0.5, a),
        ),
        (
            "beckmann::g1",
            4,
            |c, a| beckmann::g1(c, a),
            |c, a| beckmann::g1(c, a),
        ),
        (
            "fresnel::dielectric (eta = 1 + alpha)",
            5,
            |c, a| fresnel::dielectric(c, eta_above(a)),
            |c, a| fresnel::dielectric(c, eta_above(a as f32) as f64),
        ),
        (
            "fresnel::dielectric (eta = 1 / (1 + alpha))",
            49,
            |c, a| fresnel::dielectric(c, eta_below(a)),
            |c, a| fresnel::dielectric(c, eta_below(a as f32) as f64),
        ),
        (
            "fresnel::conductor (k = 10 alpha)",
            16,
            |c, a| fresnel::conductor(c, 0.5, 10.0 * a),
            |c, a| fresnel::conductor(c, 0.5, (10.0 * a as f32) as f64),
        ),
        (
            "fresnel::schlick",
            5,
            |c, a| fresnel::schlick(a, c),
            |c, a| fresnel::schlick(a, c),
        ),
    ];
    let mut failed = Vec::new();
    for (name, bound, f, g) in cases {
        let (u, c, a) = worst_ulps(f, g);
        println!("{name}: max {u} ulp (cos {c:e}, alpha {a})");
        if u > bound {
            failed.push(format!("{name}: {u} > {bound}"));
        }
    }
    assert!(failed.is_empty(), "{failed:?}");
}

/// Beckmann's D and Lambda contain exp(-E) with E = tan^2 / alpha^2 (D) or a^2 = 1 / (alpha
/// tan)^2 (Lambda). The f32 rounding of E (a few ulps relative) becomes an absolute error of
/// E times that in the exponent, so the relative error of the result grows like E ulps: the
/// conditioning of exp, not the implementation. Lambda also subtracts two terms that agree to
/// 1 / (4 a^2), which costs another factor of a^2 (and for small a, where Lambda is small next
/// to each term, a constant). Measured bounds: D within 4 + 3 E ulps while exp(-E) is a normal
/// f32 (E < 87; beyond, D < 1e-30 and keeps only subnormal bits), Lambda within 16 + 4 a^4
/// ulps, for results in f32's normal range. G1 = 1 / (1 + Lambda) stays within 4 ulps because
/// Lambda is below 1e-7 wherever its own error is large.
#[test]
fn beckmann_f32_error_is_bounded_by_its_exponent() {
    let mut worst_d: (f64, f32, f32) = (0.0, 0.0, 0.0);
    let mut worst_l: (f64, f32, f32) = (0.0, 0.0, 0.0);
    for a in SWEEP_ALPHAS {
        for c in sweep_cosines() {
            let (c64, a64) = (c as f64, a as f64);
            let d64 = beckmann::d(c64, a64);
            let e = (1.0 - c64) * (1.0 + c64) / (c64 * c64 * a64 * a64);
            if d64 >= f32::MIN_POSITIVE as f64 && e < 87.0 {
                let ratio = ulps(beckmann::d(c, a), d64) as f64 / (4.0 + 3.0 * e);
                if ratio > worst_d.0 {
                    worst_d = (ratio, c, a);
                }
            }
            let l64 = beckmann::lambda(c64, a64);
            if l64 >= f32::MIN_POSITIVE as f64 && l64.is_finite() {
                let aa = beckmann::a_of(c64, a64);
                let ratio = ulps(beckmann::lambda(c, a), l64) as f64 / (16.0 + 4.0 * aa.powi(4));
                if ratio > worst_l.0 {
                    worst_l = (ratio, c, a);
                }
            }
        }
    }
    println!("beckmann::d: worst error / (4 + 3E) = {worst_d:?}");
    println!("beckmann::lambda: worst error / (16 + 4 a^4) = {worst_l:?}");
    assert!(worst_d.0 <= 1.0, "{worst_d:?}");
    assert!(worst_l.0 <= 1.0, "{worst_l:?}");
}

proptest! {
    #![proptest_config(common::proptest_config())]
    /// Positivity and finiteness over the whole continuous domain, not only the grid.
    #[test]
    fn microfacet_terms_are_finite_and_non_negative(
        a in 0.0f64..2.0, ax in 0.0f64..1.0, cv in -1.2f64..1.2, cl in -1.2f64..1.2,
        phi in 0.0f64..6.3,
    ) {
        let g = Ggx::new(a, ax).unwrap();
        let b = Beckmann::new(a, ax).unwrap();
        let v = dir::<f64>(cv);
        let l = V3::new(phi.cos() * (1.0 - cl.clamp(-1.0, 1.0).powi(2)).sqrt(), phi.sin() * (1.0 - cl.clamp(-1.0, 1.0).powi(2)).sqrt(), cl.clamp(-1.0, 1.0));
        let h = (v + l).normalize_or(V3::unit_z());
        for x in [
            g.d(h), g.g1(v), g.g2_correlated(v, l), g.v_correlated(v, l), g.d_visible(v, h), g.cos_lambda(v),
            b.d(h), b.g1(v), b.g2_correlated(v, l), b.v_correlated(v, l), b.d_visible(v, h), b.cos_lambda(v),
            ggx::d(cv, a), ggx::v_correlated(cv, cl, a), beckmann::d(cv, a), beckmann::g1(cv, a),
        ] {
            prop_assert!(x.is_finite() && x >= 0.0, "{x}");
        }
        prop_assert!(g.lambda(v) >= 0.0 && b.lambda(v) >= 0.0);
    }
}
