//! Bad and extreme input for Burley's diffuse and its renormalized form: finite, non-negative
//! and bounded over the documented domain including its edges (roughness 0 and 1, grazing,
//! cosines just above 1), NaN for parameters outside [0, 1] and `ParamError` from the
//! constructors (also for NaN), lanes equal to scalars, f32 within a stated bound of f64. NaN
//! in each input is checked with every other kernel of the crate in `tests/kernels/bad_input.rs`.
//!
//! `cargo test --no-default-features --features diffuse --test diffuse burley_stability:: --
//! --nocapture`
#![cfg(feature = "diffuse")]

use crate::common;
use brdf::diffuse::{Burley, BurleyRenormalized, burley, burley_renormalized};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};
use proptest::prelude::*;

/// A unit direction with cosine `c` (clamped into [-1, 1]) and azimuth `phi`.
fn dir<T: Real>(c: f64, phi: f64) -> V3<T> {
    let c = c.clamp(-1.0, 1.0);
    let s = ((1.0 - c) * (1.0 + c)).sqrt();
    V3::new(
        T::splat(s * phi.cos()),
        T::splat(s * phi.sin()),
        T::splat(c),
    )
}

/// Every value the two lobes produce for one input: dot-product functions and `eval`.
fn kernels<T: Real>(v: f64, l: f64, lh: f64, rho: f64, r: f64) -> [(&'static str, T); 4] {
    let s = T::splat;
    let (wo, wi) = (dir::<T>(v, 0.3), dir::<T>(l, 0.3 + 2.0 * lh));
    let b = Burley::new(s(rho), s(r)).unwrap();
    let n = BurleyRenormalized::new(s(rho), s(r)).unwrap();
    [
        ("burley", burley(s(v), s(l), s(lh), s(rho), s(r))),
        (
            "burley_renormalized",
            burley_renormalized(s(v), s(l), s(lh), s(rho), s(r)),
        ),
        ("Burley.eval", b.eval(wo, wi)),
        ("BurleyRenormalized.eval", n.eval(wo, wi)),
    ]
}

fn lanes<T: Real>(x: T) -> Vec<f64> {
    (0..T::LANES).map(|i| x.lane(i).into()).collect()
}

/// The documented upper bound 6.25 rho / pi (both factors at F_D90 = 2.5), with slack for
/// rounding in the type (8 ulp of the value).
fn upper<T: Real>(rho: f64) -> f64 {
    let eps: f64 = T::EPSILON.lane(0).into();
    6.25 * rho / core::f64::consts::PI * (1.0 + 8.0 * eps)
}

const COS: [f64; 10] = [
    -0.5,
    -0.0,
    0.0,
    f64::MIN_POSITIVE,
    1e-7,
    0.5,
    1.0 - 1e-7,
    1.0,
    1.0 + 1e-6,
    1.0 + 1e-3,
];
const LH: [f64; 6] = [-0.1, 0.0, 0.5, 1.0, 1.0 + 1e-6, 1.5];
const RHO: [f64; 3] = [0.0, 0.5, 1.0];
const ROUGH: [f64; 5] = [0.0, 1e-7, 0.5, 1.0 - 1e-7, 1.0];

fn sweep_extremes<T: Real>(name: &str) -> usize {
    let mut n = 0;
    let mut max = 0.0_f64;
    for v in COS {
        for l in COS {
            for lh in LH {
                for rho in RHO {
                    for r in ROUGH {
                        for (k, x) in kernels::<T>(v, l, lh, rho, r) {
                            for x in lanes(x) {
                                n += 1;
                                assert!(
                                    x.is_finite() && x >= 0.0 && x <= upper::<T>(rho),
                                    "{name} {k}({v}, {l}, {lh}, {rho}, {r}) = {x}"
                                );
                                if v <= 0.0 || l <= 0.0 {
                                    assert_eq!(x, 0.0, "{k} below the horizon");
                                }
                                max = max.max(x);
                            }
                        }
                    }
                }
            }
        }
    }
    println!(
        "{name}: {n} values finite, >= 0, <= 6.25 rho / pi; max {max:.6} (6.25/pi = {:.6})",
        6.25 / core::f64::consts::PI
    );
    n
}

/// The edges of the domain: cosines 0, the smallest normal, 1e-7, 1 - 1e-7, 1 and just above
/// 1 (clamped), negative (0 out), l.h outside [0, 1] (clamped), roughness 0 and 1, rho 0 and 1.
#[test]
fn burley_is_finite_non_negative_and_bounded_at_the_domain_edges() {
    sweep_extremes::<f32>("f32");
    sweep_extremes::<f64>("f64");
    sweep_extremes::<f32x8>("f32x8");
    sweep_extremes::<f64x4>("f64x4");
    // The maximum is reached where documented: r = 1, both grazing, l.h = 1.
    let peak = burley(1e-300_f64, 1e-300, 1.0, 1.0, 1.0);
    assert!((peak - 6.25 / core::f64::consts::PI).abs() < 1e-15);
}

proptest! {
    #![proptest_config(common::proptest_config())]
    /// The continuous domain, in f64 and f32.
    #[test]
    fn burley_is_finite_and_non_negative(
        v in -0.2f64..1.001, l in -0.2f64..1.001, lh in -0.1f64..1.1,
        rho in 0.0f64..=1.0, r in 0.0f64..=1.0,
    ) {
        for (k, x) in kernels::<f64>(v, l, lh, rho, r) {
            prop_assert!(x.is_finite() && x >= 0.0 && x <= upper::<f64>(rho), "{k} = {x}");
        }
        for (k, x) in kernels::<f32>(v, l, lh, rho, r) {
            prop_assert!(x.is_finite() && x >= 0.0 && f64::from(x) <= upper::<f32>(rho), "{k} = {x}");
        }
    }
}

/// NaN through the kernels is checked with every other kernel in `tests/kernels/bad_input.rs`; here
/// the constructors refuse a NaN parameter.
fn constructors_reject_nan<T: Real>() {
    let s = T::splat;
    let nan = f64::NAN;
    assert!(Burley::new(s(nan), s(0.5)).is_err() && Burley::new(s(0.5), s(nan)).is_err());
    assert!(BurleyRenormalized::new(s(nan), s(0.5)).is_err());
    assert!(BurleyRenormalized::new(s(0.5), s(nan)).is_err());
}

#[test]
fn constructors_reject_a_nan_parameter() {
    constructors_reject_nan::<f32>();
    constructors_reject_nan::<f64>();
    constructors_reject_nan::<f32x8>();
    constructors_reject_nan::<f64x4>();
}

const BAD: [f64; 6] = [
    -1e-7,
    -0.0001,
    1.0 + 1e-6,
    2.0,
    f64::INFINITY,
    f64::NEG_INFINITY,
];

fn invalid_params<T: Real>(name: &str) {
    let s = T::splat;
    for bad in BAD {
        for (rho, r) in [(bad, 0.5), (0.5, bad)] {
            for x in [
                burley(s(0.5), s(0.5), s(0.9), s(rho), s(r)),
                burley_renormalized(s(0.5), s(0.5), s(0.9), s(rho), s(r)),
                // Below the horizon too: a bad parameter is never hidden behind a 0.
                burley(s(-0.5), s(0.5), s(0.9), s(rho), s(r)),
            ] {
                assert!(
                    lanes(x).iter().all(|x| x.is_nan()),
                    "{name}: rho {rho}, r {r} gave {x:?}"
                );
            }
            let e = Burley::new(s(rho), s(r)).unwrap_err();
            assert_eq!(e.param, if rho == bad { "rho" } else { "roughness" });
            assert!(BurleyRenormalized::new(s(rho), s(r)).is_err());
        }
    }
    // One bad lane is enough to refuse the whole vector.
    if T::LANES > 1 {
        let one_bad = T::from_fn(|i| {
            if i == 1 {
                T::Scalar::splat(1.5)
            } else {
                T::Scalar::splat(0.5)
            }
        });
        assert!(Burley::new(s(0.5), one_bad).is_err());
        assert!(BurleyRenormalized::new(one_bad, s(0.5)).is_err());
    }
}

#[test]
fn invalid_parameters_give_nan_and_param_error() {
    invalid_params::<f32>("f32");
    invalid_params::<f64>("f64");
    invalid_params::<f32x8>("f32x8");
    invalid_params::<f64x4>("f64x4");
}

/// A deterministic stream of inputs over the domain, edges included.
struct Inputs(common::Rng);
impl Inputs {
    fn next(&mut self) -> f64 {
        self.0.next_f64()
    }
    /// (n.v, n.l, l.h, rho, r) with one in eight cosines at an edge.
    fn case(&mut self) -> [f64; 5] {
        let mut c = || {
            let u = self.next();
            if u < 0.125 {
                COS[(u * 80.0) as usize]
            } else {
                (u - 0.125) / 0.875
            }
        };
        let (v, l) = (c(), c());
        [v, l, self.next() * 1.1, self.next(), self.next()]
    }
}

/// Lanes against scalars, bit for bit: the kernels use only +, *, mul_add, min/max and
/// selects, which `wide` computes per lane exactly as the scalar path does.
#[test]
fn lanes_equal_scalars() {
    let mut inputs = Inputs(common::Rng(7));
    let mut n = 0;
    for _ in 0..20_000 {
        let cases: Vec<[f64; 5]> = (0..8).map(|_| inputs.case()).collect();
        let w8 = |j: usize| f32x8::from_fn(|i| cases[i][j] as f32);
        let w4 = |j: usize| f64x4::from_fn(|i| cases[i][j]);
        let l8 = [
            burley(w8(0), w8(1), w8(2), w8(3), w8(4)),
            burley_renormalized(w8(0), w8(1), w8(2), w8(3), w8(4)),
        ];
        let l4 = [
            burley(w4(0), w4(1), w4(2), w4(3), w4(4)),
            burley_renormalized(w4(0), w4(1), w4(2), w4(3), w4(4)),
        ];
        for (i, c) in cases.iter().enumerate() {
            let f = c.map(|x| x as f32);
            let s32 = [
                burley(f[0], f[1], f[2], f[3], f[4]),
                burley_renormalized(f[0], f[1], f[2], f[3], f[4]),
            ];
            for k in 0..2 {
                assert_eq!(
                    l8[k].lane(i).to_bits(),
                    s32[k].to_bits(),
                    "f32x8 lane {i} of {c:?}"
                );
            }
            if i < 4 {
                let s64 = [
                    burley(c[0], c[1], c[2], c[3], c[4]),
                    burley_renormalized(c[0], c[1], c[2], c[3], c[4]),
                ];
                for k in 0..2 {
                    assert_eq!(
                        l4[k].lane(i).to_bits(),
                        s64[k].to_bits(),
                        "f64x4 lane {i} of {c:?}"
                    );
                }
            }
            n += 1;
        }
        // eval on lanes against eval on scalars.
        let b8 = Burley::new(w8(3), w8(4)).unwrap();
        let wo = V3::new(
            f32x8::from_fn(|i| cases[i][0] as f32),
            f32x8::splat(0.0),
            f32x8::from_fn(|i| (1.0 - cases[i][0] * cases[i][0]).max(0.0).sqrt() as f32),
        );
        let wi = V3::new(
            f32x8::from_fn(|i| -(cases[i][1] as f32)),
            f32x8::splat(0.1),
            f32x8::from_fn(|i| (0.99 - cases[i][1] * cases[i][1]).max(0.0).sqrt() as f32),
        );
        let e8 = b8.eval(wo, wi);
        for (i, c) in cases.iter().enumerate() {
            let b = Burley::new(c[3] as f32, c[4] as f32).unwrap();
            let e = b.eval(wo.lane(i), wi.lane(i));
            assert_eq!(e8.lane(i).to_bits(), e.to_bits(), "eval lane {i}");
        }
    }
    println!("{n} cases x 2 lobes: f32x8 and f64x4 lanes bit-identical to scalars");
}

/// f32 against f64 on the same (f32-representable) inputs. The error is absolute, relative to
/// the output scale rho / pi: where a factor 1 + (F_D90 - 1)(1 - c)^5 is small (the
/// renormalized form at r ~ 0 and grazing c) it is a difference of nearly equal terms, so a
/// relative bound would not hold there, and the absolute one is what a renderer sees. The
/// largest error comes from n.v or n.l near 0, where 1 - c rounds to f32 (half an ulp of 1,
/// 3e-8) and the fifth power and the factors (up to 2.5 each) amplify it. Measured
/// 2.2e-6 rho / pi; bound 4e-6 rho / pi (about twice that), as documented on [`burley`].
#[test]
fn f32_within_stated_bound_of_f64() {
    let mut inputs = Inputs(common::Rng(11));
    let (mut worst_abs, mut worst_rel) = (0.0_f64, 0.0_f64);
    let mut at = [0.0; 5];
    for _ in 0..500_000 {
        let c = inputs.case().map(|x| f64::from(x as f32));
        let f = c.map(|x| x as f32);
        if c[3] == 0.0 {
            continue;
        }
        let pairs = [
            (
                burley(f[0], f[1], f[2], f[3], f[4]),
                burley(c[0], c[1], c[2], c[3], c[4]),
            ),
            (
                burley_renormalized(f[0], f[1], f[2], f[3], f[4]),
                burley_renormalized(c[0], c[1], c[2], c[3], c[4]),
            ),
        ];
        for (x32, x64) in pairs {
            let scale = c[3] / core::f64::consts::PI;
            let abs = (f64::from(x32) - x64).abs() / scale;
            if abs > worst_abs {
                (worst_abs, at) = (abs, c);
            }
            if x64 > 0.01 * scale {
                worst_rel = worst_rel.max((f64::from(x32) - x64).abs() / x64);
            }
        }
    }
    println!(
        "max |f32 - f64| / (rho / pi) = {worst_abs:.3e} at {at:?}; max relative error where f > rho / (100 pi): {worst_rel:.3e} ({:.1} f32 ulp)",
        worst_rel / f64::from(f32::EPSILON)
    );
    assert!(worst_abs < 4e-6, "f32 error {worst_abs:e}");
}
