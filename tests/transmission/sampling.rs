//! `rough_dielectric::ggx_sample` and `beckmann_sample` draw the density `rough_dielectric::pdf`
//! says, over the whole sphere: chi-square on (cos theta in [-1, 1], phi) bins, both lobes,
//! from outside and inside, grazing, near total internal reflection, anisotropic, with the
//! samples the sampler kills (pdf 0) counted in a bin of their own whose expected count is the
//! mass the pdf misses. And the returned pdf is the pdf function's, the weight f |wi.z| / pdf.

use crate::common::{Rng, critical, sphere};
use crate::dir;
use brdf::V3;
use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::rough_dielectric::{self as rd, Transport};
use core::f64::consts::TAU;

type Sampler<'a> = &'a dyn Fn(V3<f64>, f64, f64, f64) -> (V3<f64>, f64, f64);
type Pdf<'a> = &'a dyn Fn(V3<f64>, V3<f64>) -> f64;

/// (statistic, degrees of freedom) of the sampler's directions against the pdf
/// ([`sphere::chi_square`]); each live sample is a unit vector whose returned pdf is the pdf
/// function's.
fn chi_square(wo: V3<f64>, sample: Sampler, pdf: Pdf) -> (f64, usize) {
    let fit = sphere::chi_square(
        |rng| {
            let (w, p, _) = sample(wo, rng.next_f64(), rng.next_f64(), rng.next_f64());
            if p > 0.0 {
                assert!((w.length() - 1.0).abs() < 1e-9, "not unit: {w:?}");
                assert_eq!(p, pdf(wo, w), "returned pdf vs pdf function at {w:?}");
            }
            (w, p)
        },
        |w| pdf(wo, w),
    );
    // Pooled bins that expect almost nothing must receive almost nothing.
    assert!(
        fit.stray < 20.0,
        "{} samples where the pdf expects {}",
        fit.stray,
        fit.stray_expected
    );
    (fit.stat, fit.dof)
}

fn check(name: &str, wo: V3<f64>, sample: Sampler, pdf: Pdf) {
    let (stat, dof) = chi_square(wo, sample, pdf);
    let c = critical(dof);
    println!("{name}: chi^2 = {stat:.1}, dof = {dof}, critical = {c:.1}");
    assert!(dof > 30, "{name}: too few populated bins ({dof})");
    assert!(stat < c, "{name}: chi^2 = {stat} >= {c} (dof {dof})");
}

/// (label, theta_o, eta, alpha_x, alpha_y): both lobes from outside and inside, grazing views,
/// views from inside just below and above glass's critical angle (41.8 degrees from -z),
/// anisotropic roughness, and a rough interface near eta = 1.
const CASES: &[(&str, f64, f64, f64, f64)] = &[
    ("outside normal", 0.0, 1.5, 0.3, 0.3),
    ("outside oblique", 50.0, 1.5, 0.5, 0.5),
    ("outside grazing", 88.0, 1.5, 0.4, 0.4),
    ("inside normal", 180.0, 1.5, 0.3, 0.3),
    ("inside near critical (40 deg)", 140.0, 1.5, 0.3, 0.3),
    ("inside past critical (45 deg)", 135.0, 1.5, 0.3, 0.3),
    ("inside grazing", 92.0, 1.5, 0.5, 0.5),
    ("outside anisotropic", 60.0, 1.5, 0.15, 0.6),
    ("inside anisotropic", 120.0, 1.33, 0.6, 0.15),
    ("less dense inside", 30.0, 0.75, 0.4, 0.4),
    ("eta near 1", 40.0, 1.1, 1.0, 1.0),
];

#[test]
fn ggx_sampler_matches_its_pdf_over_the_sphere() {
    for &(label, theta, eta, ax, ay) in CASES {
        let m = Ggx::new(ax, ay).unwrap();
        let s = |wo, a, b, c| rd::ggx_sample(&m, wo, eta, a, b, c, Transport::Radiance);
        let p = |wo, wi| rd::pdf(&m, wo, wi, eta);
        check(&format!("ggx {label}"), dir(theta, 25.0), &s, &p);
    }
}

#[test]
fn beckmann_sampler_matches_its_pdf_over_the_sphere() {
    for &(label, theta, eta, ax, ay) in CASES {
        let m = Beckmann::new(ax, ay).unwrap();
        let s = |wo, a, b, c| rd::beckmann_sample(&m, wo, eta, a, b, c, Transport::Radiance);
        let p = |wo, wi| rd::pdf(&m, wo, wi, eta);
        check(&format!("beckmann {label}"), dir(theta, 25.0), &s, &p);
    }
}

/// A pdf missing the refraction Jacobian's eta'^2 fails (a test of the test).
#[test]
fn a_wrong_pdf_is_rejected() {
    let m = Ggx::isotropic(0.3).unwrap();
    let wo = dir(30.0, 0.0);
    let s = |wo, a, b, c| rd::ggx_sample(&m, wo, 1.5, a, b, c, Transport::Radiance);
    let wrong = |wo: V3<f64>, wi: V3<f64>| {
        let p = rd::pdf(&m, wo, wi, 1.5);
        if wi.z < 0.0 { p * 1.2 } else { p }
    };
    // The sampler's pdf no longer equals the function's: compare shapes only.
    let shape = |wo: V3<f64>, a, b, c| {
        let (w, p, x) = s(wo, a, b, c);
        (w, if p > 0.0 { wrong(wo, w) } else { 0.0 }, x)
    };
    let (stat, dof) = chi_square(wo, &shape, &wrong);
    assert!(stat > 10.0 * critical(dof), "{stat} {dof}");
}

/// weight = f |wi.z| / pdf for every live sample, in both transport modes.
#[test]
fn weight_is_f_cos_over_pdf() {
    let mut rng = Rng(99);
    let g = Ggx::new(0.2, 0.45).unwrap();
    let b = Beckmann::new(0.35, 0.2).unwrap();
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let z = 2.0 * rng.next_f64() - 1.0;
        let phi = TAU * rng.next_f64();
        let r = (1.0 - z * z).sqrt();
        let wo = V3::new(r * phi.cos(), r * phi.sin(), z);
        let u = [rng.next_f64(), rng.next_f64(), rng.next_f64()];
        for eta in [1.5, 0.8] {
            for t in [Transport::Radiance, Transport::Importance] {
                for (wi, p, w, f) in [
                    {
                        let (wi, p, w) = rd::ggx_sample(&g, wo, eta, u[0], u[1], u[2], t);
                        (wi, p, w, rd::eval(&g, wo, wi, eta, t))
                    },
                    {
                        let (wi, p, w) = rd::beckmann_sample(&b, wo, eta, u[0], u[1], u[2], t);
                        (wi, p, w, rd::eval(&b, wo, wi, eta, t))
                    },
                ] {
                    if p > 1e-6 {
                        let direct = f * wi.z.abs() / p;
                        worst = worst.max((direct - w).abs() / w.max(1e-300));
                    } else if p == 0.0 {
                        assert_eq!(w, 0.0);
                    }
                }
            }
        }
    }
    println!("max relative |f cos / pdf - weight|: {worst:.2e}");
    // The weight is G2 / G1 from the sampled normal, f / pdf from the half vector
    // recomputed from wi: they differ by the rounding of that recomputation.
    assert!(worst < 1e-6, "{worst}");
}
