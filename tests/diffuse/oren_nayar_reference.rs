//! The dot-product forms of the Oren-Nayar family equal their published angle forms: each
//! kernel against an explicit f64 evaluation in (theta, phi) (acos, atan2, sin, tan, the
//! paper's max/min of angles) on random directions, including near-polar and near-grazing
//! ones. Also the structural identities between the forms that hold exactly.
//!
//! `cargo test --no-default-features --features diffuse,integrate --test diffuse
//! oren_nayar_reference:: -- --nocapture` prints the errors.
#![cfg(feature = "diffuse")]

use crate::common;

use brdf::diffuse::{
    OrenNayar, OrenNayarFujii, OrenNayarFull, oren_nayar, oren_nayar_a, oren_nayar_fujii,
    oren_nayar_full,
};
use brdf::glam::DVec3;
use common::Rng;
use core::f64::consts::{FRAC_1_PI, PI};

struct Angles {
    theta_i: f64,
    theta_o: f64,
    cos_phi: f64,
}

fn angles(v: DVec3, l: DVec3) -> Angles {
    let (phi_o, phi_i) = (v.y.atan2(v.x), l.y.atan2(l.x));
    Angles {
        theta_i: l.z.acos(),
        theta_o: v.z.acos(),
        cos_phi: (phi_i - phi_o).cos(),
    }
}

/// Oren and Nayar 1994, qualitative model, as printed.
fn qualitative_angles(v: DVec3, l: DVec3, rho: f64, sigma: f64) -> f64 {
    let g = angles(v, l);
    let s2 = sigma * sigma;
    let a = 1.0 - 0.5 * s2 / (s2 + 0.33);
    let b = 0.45 * s2 / (s2 + 0.09);
    let (alpha, beta) = (g.theta_i.max(g.theta_o), g.theta_i.min(g.theta_o));
    rho / PI * (a + b * g.cos_phi.max(0.0) * alpha.sin() * beta.tan())
}

/// Oren and Nayar 1994, full model (L1 + L2), as printed, with L1 clamped at 0 as documented.
fn full_angles(v: DVec3, l: DVec3, rho: f64, sigma: f64) -> f64 {
    let g = angles(v, l);
    let s2 = sigma * sigma;
    let (alpha, beta) = (g.theta_i.max(g.theta_o), g.theta_i.min(g.theta_o));
    let c1 = 1.0 - 0.5 * s2 / (s2 + 0.33);
    let c2 = if g.cos_phi >= 0.0 {
        0.45 * s2 / (s2 + 0.09) * alpha.sin()
    } else {
        0.45 * s2 / (s2 + 0.09) * (alpha.sin() - (2.0 * beta / PI).powi(3))
    };
    let c3 = 0.125 * s2 / (s2 + 0.09) * (4.0 * alpha * beta / (PI * PI)).powi(2);
    let l1 = c1
        + g.cos_phi * c2 * beta.tan()
        + (1.0 - g.cos_phi.abs()) * c3 * ((alpha + beta) / 2.0).tan();
    let l2 = 0.17 * rho * s2 / (s2 + 0.13) * (1.0 - g.cos_phi * (2.0 * beta / PI).powi(2));
    rho / PI * (l1.max(0.0) + l2)
}

/// Fujii 2012 in his own notation: f = rho (A' + B' s / t), A' = 1 / (pi + (pi/2 - 2/3)
/// sigma), B' = sigma A', s = cos(phi) sin(theta_i) sin(theta_o).
fn fujii_angles(v: DVec3, l: DVec3, rho: f64, sigma: f64) -> f64 {
    let g = angles(v, l);
    let a = 1.0 / (PI + (PI / 2.0 - 2.0 / 3.0) * sigma);
    let b = sigma * a;
    let s = g.cos_phi * g.theta_i.sin() * g.theta_o.sin();
    let t = if s > 0.0 {
        g.theta_i.cos().max(g.theta_o.cos())
    } else {
        1.0
    };
    rho * (a + b * s / t)
}

fn random_dir(rng: &mut Rng) -> DVec3 {
    // A mix of uniform cosines and cosines crowded at the pole and the horizon.
    let u = rng.next_f64();
    let z = match (rng.next_f64() * 4.0) as u32 {
        0 => 1.0 - 1e-6 * u,
        1 => 1e-3 + 1e-2 * u,
        _ => 1e-3 + (1.0 - 1e-3) * u,
    };
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * rng.next_f64();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

#[test]
fn dot_product_forms_equal_angle_forms() {
    let mut rng = Rng(0x0e4e_9a7a);
    let (mut eq, mut ef, mut ej) = (0.0f64, 0.0f64, 0.0f64);
    let mut worst_full = (DVec3::ZERO, DVec3::ZERO, 0.0);
    for _ in 0..200_000 {
        let (v, l) = (random_dir(&mut rng), random_dir(&mut rng));
        let rho = rng.next_f64();
        let sigma = 1.5 * rng.next_f64();
        let sf = rng.next_f64();
        let (cv, cl, vl) = (v.z, l.z, v.dot(l));
        eq = eq.max(rel(
            oren_nayar(cv, cl, vl, rho, sigma),
            qualitative_angles(v, l, rho, sigma),
        ));
        let e = rel(
            oren_nayar_full(cv, cl, vl, rho, sigma),
            full_angles(v, l, rho, sigma),
        );
        if e > ef {
            ef = e;
            worst_full = (v, l, sigma);
        }
        ej = ej.max(rel(
            oren_nayar_fujii(cv, cl, vl, rho, sf),
            fujii_angles(v, l, rho, sf),
        ));
    }
    println!("max relative difference, dot-product form vs angle form (f64, 200k pairs):");
    println!(
        "  qualitative {eq:.2e}\n  full        {ef:.2e} (worst at {worst_full:?})\n  Fujii       {ej:.2e}"
    );
    // The two routes round differently (atan2 / cos versus one fused s); the angle form's
    // own error near the horizon, where tan(beta) ~ 1 / cos amplifies the rounding of acos,
    // dominates: 1e-11 is ~15x the worst measured (6.3e-13) and catches any wrong term (those differ by
    // percent).
    assert!(eq < 1e-11, "qualitative {eq}");
    assert!(ef < 1e-11, "full {ef}");
    assert!(ej < 1e-11, "Fujii {ej}");
}

#[test]
fn eval_equals_free_function_bit_for_bit() {
    let mut rng = Rng(7);
    for _ in 0..20_000 {
        let (v, l) = (random_dir(&mut rng), random_dir(&mut rng));
        let (rho, sigma) = (rng.next_f64(), rng.next_f64());
        let (wo, wi) = (v.into(), l.into());
        let vl = brdf::V3::from(v).dot(brdf::V3::from(l));
        let q = OrenNayar::new(rho, sigma).unwrap();
        let f = OrenNayarFull::new(rho, sigma).unwrap();
        let j = OrenNayarFujii::new(rho, sigma).unwrap();
        assert_eq!(
            q.eval(wo, wi).to_bits(),
            oren_nayar(v.z, l.z, vl, rho, sigma).to_bits()
        );
        assert_eq!(
            f.eval(wo, wi).to_bits(),
            oren_nayar_full(v.z, l.z, vl, rho, sigma).to_bits()
        );
        assert_eq!(
            j.eval(wo, wi).to_bits(),
            oren_nayar_fujii(v.z, l.z, vl, rho, sigma).to_bits()
        );
    }
}

/// The qualitative model is the full model without C3 and L2 and with C2 = B sin(alpha) for
/// every phi: where cos(phi) = 1 those terms vanish or coincide, so full - qualitative is
/// exactly rho/pi * L2 = rho^2 / pi * 0.17 sigma^2 / (sigma^2 + 0.13) (1 - (2 beta / pi)^2).
/// Where one direction is the normal (beta = 0), full = rho / pi (C1 + 0.17 rho ...).
#[test]
fn full_model_reduces_to_qualitative_plus_interreflection_in_plane() {
    let mut worst = 0.0f64;
    for i in 0..90 {
        for j in 0..90 {
            for &sigma in &[0.1, 0.3, 0.7, 1.5] {
                let (ti, to) = ((i as f64 + 0.5).to_radians(), (j as f64 + 0.5).to_radians());
                // Same azimuth: cos(phi) = 1.
                let v = DVec3::new(to.sin(), 0.0, to.cos());
                let l = DVec3::new(ti.sin(), 0.0, ti.cos());
                let rho = 0.8;
                let s2: f64 = sigma * sigma;
                let beta = ti.min(to);
                let l2 = 0.17 * rho * s2 / (s2 + 0.13) * (1.0 - (2.0 * beta / PI).powi(2));
                let full = oren_nayar_full(v.z, l.z, v.dot(l), rho, sigma);
                let q = oren_nayar(v.z, l.z, v.dot(l), rho, sigma);
                worst = worst.max(rel(full, q + rho * FRAC_1_PI * l2));
            }
        }
    }
    println!("in-plane full vs qualitative + L2: max relative difference {worst:.2e}");
    // Same terms by two roundings (one acos-based, one s-based): 1e-13 is ~60x the measured.
    assert!(worst < 1e-13, "{worst}");

    // One direction along the normal.
    for &sigma in &[0.0, 0.2, 1.0] {
        let rho = 0.6;
        let s2: f64 = sigma * sigma;
        let expect = rho / PI * (oren_nayar_a(sigma) + 0.17 * rho * s2 / (s2 + 0.13));
        for c in [0.01, 0.5, 0.99] {
            let full = oren_nayar_full(1.0, c, c, rho, sigma);
            assert!(rel(full, expect) < 1e-14, "{full} vs {expect}");
        }
    }
}
