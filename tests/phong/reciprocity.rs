//! Helmholtz reciprocity f(v, l) = f(l, v) of the Phong family, by
//! `brdf::integrate::reciprocity` over its fixed set of 64 directions (4032 ordered pairs,
//! near-normal and near-grazing ones included), through the `eval(wo, wi)` of each type:
//! - classic Phong, ks (r.l)^n / (n.l), is not reciprocal: f(v, l) / f(l, v) = (n.v) / (n.l),
//!   so the asymmetry reaches 1 - 1e-5 on the pairs of a normal and a grazing direction (Lewis 1994);
//! - every other model is symmetric in v and l by construction (r.l and h are), and the
//!   measured asymmetry is rounding only, for exponents 0 to 10^4.
#![cfg(all(feature = "phong", feature = "integrate"))]

use brdf::V3;
use brdf::integrate::reciprocity;
use brdf::phong::{
    ApproxNormalizedBlinnPhong, BlinnPhong, ClassicPhong, ModifiedPhong, NormalizedBlinnPhong,
    NormalizedPhong, PhongDiffuseSpecular,
};

const EXPONENTS: [f64; 8] = [0.0, 0.5, 1.0, 5.0, 30.0, 300.0, 1000.0, 10000.0];

/// The symmetric models are symmetric bit for bit: r.l = fma(wo.z, wi.z, -fma(wo.x, wi.x,
/// wo.y wi.y)) and h = wo + wi use only commutative operations on swapped operands, so any
/// asymmetry at all is a bug.
const SYMMETRIC_TOL: f64 = 0.0;

fn check(name: &str, f: impl Fn(f64, V3<f64>, V3<f64>) -> f64) {
    let mut worst: f64 = 0.0;
    for n in EXPONENTS {
        let r = reciprocity(|a, b| f(n, a, b));
        println!(
            "{name} n = {n}: max_rel {:.2e} over {} pairs",
            r.max_rel, r.pairs
        );
        assert!(r.max_rel <= SYMMETRIC_TOL, "{name} n = {n}: {r:?}");
        worst = worst.max(r.max_rel);
    }
    println!("{name}: worst max_rel {worst:.2e}");
}

#[test]
fn classic_phong_is_not_reciprocal() {
    for n in EXPONENTS {
        let m = ClassicPhong::new(1.0, n).unwrap();
        let r = reciprocity(|a, b| m.eval(a, b));
        let (a, b) = r.worst;
        let (fab, fba) = (m.eval(a, b), m.eval(b, a));
        println!(
            "classic Phong n = {n}: max_rel {:.6} at wo = {:.6?}, wi = {:.6?} \
             (f(wo, wi) = {fab:.6e}, f(wi, wo) = {fba:.6e}, cos ratio {:.3e})",
            r.max_rel,
            a.to_array(),
            b.to_array(),
            a.z / b.z
        );
        // The asymmetry is 1 - min(n.v, n.l) / max(n.v, n.l) on a pair inside the lobe; the
        // direction set has cosines 1e-5 and 1, so it is 1 - 1e-5 wherever the lobe reaches
        // such a pair. 0.5 is a factor of 2 in f: far from rounding, and what the lobe gives
        // even at n = 10^4, where only near-mirror pairs count.
        assert!(r.max_rel > 0.5, "classic Phong n = {n}: {r:?}");
        // The worst pair's ratio is exactly the cosine ratio (Lewis 1994).
        let expected = a.z / b.z;
        assert!(
            ((fab / fba) / expected - 1.0).abs() < 1e-9,
            "{fab} / {fba} vs {expected}"
        );
    }
}

#[test]
fn modified_phong_is_reciprocal() {
    check("modified Phong", |n, a, b| {
        ModifiedPhong::new(1.0, n).unwrap().eval(a, b)
    });
}

#[test]
fn normalized_phong_is_reciprocal() {
    check("normalized Phong", |n, a, b| {
        NormalizedPhong::new(1.0, n).unwrap().eval(a, b)
    });
}

#[test]
fn diffuse_plus_normalized_phong_is_reciprocal() {
    check("kd/pi + normalized Phong", |n, a, b| {
        PhongDiffuseSpecular::new(0.3, 0.7, n).unwrap().eval(a, b)
    });
}

#[test]
fn blinn_phong_is_reciprocal_in_every_normalization() {
    check("Blinn-Phong", |n, a, b| {
        BlinnPhong::new(1.0, n).unwrap().eval(a, b)
    });
    check("Blinn-Phong exact normalization", |n, a, b| {
        NormalizedBlinnPhong::new(1.0, n).unwrap().eval(a, b)
    });
    check("Blinn-Phong (n + 8) / (8 pi)", |n, a, b| {
        ApproxNormalizedBlinnPhong::new(1.0, n).unwrap().eval(a, b)
    });
}
