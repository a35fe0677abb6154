//! The Oren-Nayar family never returns NaN, inf or a negative value for finite inputs in its
//! documented domain (rho in [0, 1]; sigma >= 0 and finite for the qualitative and full
//! models, sweeping up to f32::MAX and f64::MAX; Fujii's sigma in [0, 1]), including grazing
//! and polar directions, subnormal cosines and cosines just above 1; it is 0 below the
//! horizon; and with sigma = 0 all three forms are Lambert exactly.
#![cfg(feature = "diffuse")]

use crate::common;
use brdf::Real;
use brdf::diffuse::{lambert, oren_nayar, oren_nayar_fujii, oren_nayar_full};
use brdf::wide::{f32x8, f64x4};
use proptest::prelude::*;

fn all3<T: Real>(cv: T, cl: T, vl: T, rho: T, sigma: T, fujii_sigma: T) -> [T; 3] {
    [
        oren_nayar(cv, cl, vl, rho, sigma),
        oren_nayar_full(cv, cl, vl, rho, sigma),
        oren_nayar_fujii(cv, cl, vl, rho, fujii_sigma),
    ]
}

/// v.l for directions with cosines cv, cl (clamped into [-1, 1] for the sines) and azimuth
/// difference with cosine cos_phi.
fn v_dot_l(cv: f64, cl: f64, cos_phi: f64) -> f64 {
    let s = |c: f64| (1.0 - c.clamp(-1.0, 1.0).powi(2)).sqrt();
    cv * cl + s(cv) * s(cl) * cos_phi
}

fn sweep<T: Real>(sigmas: &[f64], cosines: &[f64]) -> usize {
    let mut n = 0;
    for &sigma in sigmas {
        for &fs in &[0.0, 1e-30, 0.5, 1.0] {
            for &cv in cosines {
                for &cl in cosines {
                    for &cp in &[-1.0, -0.3, 0.0, 0.3, 1.0] {
                        for &rho in &[0.0, 0.5, 1.0] {
                            let vl = v_dot_l(cv, cl, cp);
                            let out = all3(
                                T::splat(cv),
                                T::splat(cl),
                                T::splat(vl),
                                T::splat(rho),
                                T::splat(sigma),
                                T::splat(fs),
                            );
                            for (k, f) in out.iter().enumerate() {
                                let x: f64 = f.lane(0).into();
                                assert!(
                                    x.is_finite() && x >= 0.0,
                                    "form {k}: f = {x} at sigma {sigma}, fujii {fs}, cv {cv}, cl {cl}, cos_phi {cp}, rho {rho}"
                                );
                                if cv <= 0.0 || cl <= 0.0 {
                                    assert_eq!(x, 0.0, "below the horizon");
                                }
                                n += 1;
                            }
                        }
                    }
                }
            }
        }
    }
    n
}

#[test]
fn extremes_are_finite_and_non_negative_f64() {
    let sigmas = [
        0.0,
        5e-324,
        1e-300,
        1e-20,
        1e-3,
        0.3,
        0.7,
        1.0,
        10.0,
        1e10,
        1e154,
        1.4e154,
        1e200,
        f64::MAX,
    ];
    let cosines = [
        -0.5,
        -1e-300,
        0.0,
        5e-324,
        1e-310,
        f64::MIN_POSITIVE,
        1e-300,
        1e-16,
        1e-8,
        0.01,
        0.5,
        1.0 - 1e-12,
        1.0,
        1.0 + 1e-12,
        1.0 + 1e-6,
    ];
    let n = sweep::<f64>(&sigmas, &cosines);
    println!("f64: {n} evaluations finite and >= 0");
}

#[test]
fn extremes_are_finite_and_non_negative_f32() {
    let sigmas = [
        0.0,
        1e-45,
        1e-38,
        1e-20,
        1e-3,
        0.3,
        0.7,
        1.0,
        10.0,
        1e10,
        1.8e19,
        1e30,
        f32::MAX as f64,
    ];
    let cosines = [
        -0.5,
        -1e-30,
        0.0,
        1e-45,
        1e-40,
        f32::MIN_POSITIVE as f64,
        1e-30,
        1e-8,
        0.01,
        0.5,
        1.0 - 1e-7,
        1.0,
        1.0 + 1.2e-7,
        1.0 + 1e-5,
    ];
    let n = sweep::<f32>(&sigmas, &cosines);
    let n8 = sweep::<f32x8>(&sigmas[..4], &cosines);
    let n4 = sweep::<f64x4>(&[0.0, 0.5, f64::MAX], &cosines);
    println!("f32: {n}, f32x8: {n8}, f64x4: {n4} evaluations finite and >= 0");
}

#[test]
fn zero_sigma_is_lambert_exactly() {
    for i in 1..=100 {
        for j in 1..=100 {
            let (cv, cl) = (i as f64 / 100.0, j as f64 / 100.0);
            for cp in [-1.0, 0.0, 0.5, 1.0] {
                let vl = v_dot_l(cv, cl, cp);
                for rho in [0.0, 0.3, 1.0] {
                    let l = lambert(cv, cl, rho);
                    for f in all3(cv, cl, vl, rho, 0.0, 0.0) {
                        assert_eq!(f.to_bits(), l.to_bits(), "{f} vs Lambert {l}");
                    }
                    let l32 = lambert(cv as f32, cl as f32, rho as f32);
                    for f in all3(cv as f32, cl as f32, vl as f32, rho as f32, 0.0, 0.0) {
                        assert_eq!(f.to_bits(), l32.to_bits(), "{f} vs Lambert {l32}");
                    }
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(common::proptest_config())]
    /// Finite and non-negative over the whole continuous domain, sigma log-uniform over every
    /// magnitude a double can hold.
    #[test]
    fn finite_and_non_negative_everywhere(
        cv in -0.2f64..1.0 + 1e-9, cl in -0.2f64..1.0 + 1e-9, cp in -1.0f64..=1.0,
        rho in 0.0f64..=1.0, log_sigma in -320.0f64..308.2, fs in 0.0f64..=1.0,
    ) {
        let sigma = 10f64.powf(log_sigma).min(f64::MAX);
        let vl = v_dot_l(cv, cl, cp);
        for f in all3(cv, cl, vl, rho, sigma, fs) {
            prop_assert!(f.is_finite() && f >= 0.0, "{f}");
        }
        let sigma32 = (sigma as f32).min(f32::MAX);
        for f in all3(cv as f32, cl as f32, vl as f32, rho as f32, sigma32, fs as f32) {
            prop_assert!(f.is_finite() && f >= 0.0, "{f}");
        }
    }
}
