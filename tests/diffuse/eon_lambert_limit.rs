//! At sigma = 0 EON is Lambert exactly: the BRDF equals rho/pi bit for bit, the albedo is rho,
//! and the sampler is cosine sampling (pdf cos(theta_i)/pi).
#![cfg(feature = "diffuse")]

use crate::common;

use brdf::diffuse::{eon, eon_albedo, eon_albedo_approx, eon_approx, eon_pdf, eon_sample, lambert};
use brdf::{Real, V3};
use common::Rng;

fn unit(rng: &mut Rng) -> [f64; 3] {
    let z = rng.next_f64();
    let phi = std::f64::consts::TAU * rng.next_f64();
    let r = (1.0 - z * z).sqrt();
    [r * phi.cos(), r * phi.sin(), z]
}

fn check<T: Real + PartialEq>(label: &str) {
    let mut rng = Rng(7);
    let mut n = 0;
    for _ in 0..20_000 {
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        let rho = rng.next_f64();
        let wo = V3::new(T::splat(a[0]), T::splat(a[1]), T::splat(a[2]));
        let wi = V3::new(T::splat(b[0]), T::splat(b[1]), T::splat(b[2]));
        let (r, z) = (T::splat(rho), T::ZERO);
        let want = lambert(wo.z, wi.z, r);
        assert_eq!(eon(wo.z, wi.z, wo.dot(wi), r, z), want, "{label} eon");
        assert_eq!(
            eon_approx(wo.z, wi.z, wo.dot(wi), r, z),
            want,
            "{label} eon_approx"
        );
        assert_eq!(eon_albedo(wo.z, r, z), r, "{label} eon_albedo");
        assert_eq!(
            eon_albedo_approx(wo.z, r, z),
            r,
            "{label} eon_albedo_approx"
        );
        n += 1;
    }
    println!(
        "{label}: eon, eon_approx == lambert and albedo == rho bitwise at sigma = 0 on {n} random pairs"
    );
}

#[test]
fn eon_at_zero_roughness_is_lambert_bitwise() {
    check::<f32>("f32");
    check::<f64>("f64");
}

#[test]
fn eon_sampling_at_zero_roughness_is_cosine_sampling() {
    let mut rng = Rng(11);
    let mut worst = 0.0f64;
    for _ in 0..20_000 {
        let a = unit(&mut rng);
        let wo = V3::new(a[0], a[1], a[2]);
        let (wi, pdf) = eon_sample(wo, 0.0, rng.next_f64(), rng.next_f64());
        let cos = wi.z / std::f64::consts::PI;
        worst = worst.max((pdf - cos).abs() / cos);
        worst = worst.max((eon_pdf(wo, wi, 0.0) - cos).abs() / cos);
    }
    println!("sigma = 0: max relative |pdf - cos/pi| = {worst:.2e}");
    // M = I and P_u = 0 exactly at sigma = 0; the pdf is z/pi up to the rounding of |M wh|^4
    // and the normalization of wi: a few ULP.
    assert!(worst < 1e-14, "{worst}");
}
