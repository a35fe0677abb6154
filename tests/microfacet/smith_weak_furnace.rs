//! Smith's weak white furnace: integral of G1(wo) max(0, wo.m) D(m) dm / cos(theta_o) = 1
//! for every wo (Heitz 2014, "Understanding the Masking-Shadowing Function", section 5), so
//! the distribution of visible normals integrates to 1. Both models, isotropic and
//! anisotropic, theta_o up to 89.9 degrees.
#![cfg(all(feature = "integrate", feature = "ggx", feature = "beckmann"))]

use brdf::V3;
use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::integrate::{Config, hemisphere, smith_weak_furnace};
use brdf::microfacet::Microfacet;

/// Issue 3's bound.
const TOL: f64 = 1e-3;
const THETAS_DEG: [f64; 7] = [0.0, 30.0, 60.0, 80.0, 85.0, 89.0, 89.9];
const ALPHAS: [(f64, f64); 6] = [
    (0.01, 0.01),
    (0.1, 0.1),
    (0.5, 0.5),
    (1.0, 1.0),
    (1.0, 0.01),
    (0.3, 0.05),
];

fn wo(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    // An azimuth off both tangent axes, so anisotropy matters.
    V3::new(t.sin() * 0.8, t.sin() * 0.6, t.cos())
}

fn check(name: &str, m: &impl Microfacet<f64>) {
    for theta in THETAS_DEG {
        let o = wo(theta);
        let g1 = m.g1(o);
        let e = smith_weak_furnace(o, |h| m.d(h), |_, _| g1);
        assert!(
            (e.value - 1.0).abs() <= TOL,
            "{name} at {theta} deg: {} (+- {:.1e})",
            e.value,
            e.error
        );
    }
}

#[test]
fn ggx_weak_furnace_is_one() {
    for (ax, ay) in ALPHAS {
        check(&format!("ggx {ax}x{ay}"), &Ggx::new(ax, ay).unwrap());
    }
}

#[test]
fn beckmann_weak_furnace_is_one() {
    for (ax, ay) in ALPHAS {
        check(
            &format!("beckmann {ax}x{ay}"),
            &Beckmann::new(ax, ay).unwrap(),
        );
    }
}

/// The provided `d_visible` is the furnace integrand itself: it must integrate to 1 too.
#[test]
fn visible_normal_distribution_integrates_to_one() {
    let g = Ggx::new(0.4, 0.1).unwrap();
    let b = Beckmann::isotropic(0.3).unwrap();
    for theta in [0.0, 45.0, 85.0] {
        let o = wo(theta);
        let cfg = Config::default();
        let eg = hemisphere(|h| g.d_visible(o, h), &[o], &cfg);
        let eb = hemisphere(|h| b.d_visible(o, h), &[o], &cfg);
        assert!(
            (eg.value - 1.0).abs() <= TOL,
            "ggx D_wo at {theta}: {}",
            eg.value
        );
        assert!(
            (eb.value - 1.0).abs() <= TOL,
            "beckmann D_wo at {theta}: {}",
            eb.value
        );
    }
}

/// A wrong Lambda breaks the furnace: the separable-looking but wrong GGX G1 with 1 + a^2
/// where 1 - a^2 belongs (one seed's typo) is caught.
#[test]
fn a_wrong_lambda_fails_the_furnace() {
    let alpha: f64 = 0.5;
    let g = Ggx::isotropic(alpha).unwrap();
    let o = wo(80.0);
    let c = o.z;
    let wrong_g1 = 2.0 * c / (c + (alpha * alpha + (1.0 + alpha * alpha) * c * c).sqrt());
    let e = smith_weak_furnace(o, |h| g.d(h), |_, _| wrong_g1);
    assert!(
        (e.value - 1.0).abs() > 10.0 * TOL,
        "the typo should be visible: {}",
        e.value
    );
}
