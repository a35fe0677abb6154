//! Generalized reciprocity of the rough dielectric BTDF: f_t(wo, wi) / n_wo^2 =
//! f_t(wi, wo) / n_wi^2 in radiance transport, checked over direction pairs with
//! `integrate::reciprocity`'s directions; the importance form is the radiance form's adjoint.

use brdf::V3;
use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::microfacet::Microfacet;
use brdf::rough_dielectric::{Transport, eval};

/// The index of the medium a direction lies in: 1 outside, eta inside.
fn n_of(w: V3<f64>, eta: f64) -> f64 {
    if w.z >= 0.0 { 1.0 } else { eta }
}

/// Directions over the whole sphere: a Fibonacci spiral, plus near-normal and near-grazing
/// ones on both sides.
fn directions() -> Vec<V3<f64>> {
    let n = 200;
    let mut out: Vec<V3<f64>> = (0..n)
        .map(|i| {
            let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - z * z).sqrt();
            let p = 2.399_963_229_728_653 * i as f64;
            V3::new(r * p.cos(), r * p.sin(), z)
        })
        .collect();
    for z in [0.999_999_f64, 1e-3, -1e-3, -0.999_999] {
        let r = (1.0 - z * z).sqrt();
        out.push(V3::new(r * 0.6, r * 0.8, z));
    }
    out
}

/// Max relative asymmetry |f(a, b) / n_a^2 - f(b, a) / n_b^2| / max over all ordered pairs.
fn worst<M: Microfacet<f64>>(m: &M, eta: f64) -> f64 {
    let scaled =
        |a: V3<f64>, b: V3<f64>| eval(m, a, b, eta, Transport::Radiance) / n_of(a, eta).powi(2);
    let dirs = directions();
    let mut worst: f64 = 0.0;
    let mut live = 0;
    for &a in &dirs {
        for &b in &dirs {
            let (x, y) = (scaled(a, b), scaled(b, a));
            // Below 1e-280 D has underflowed towards the subnormals, where no relative
            // accuracy is left (Beckmann's exp(-tan^2 / alpha^2) far from its peak).
            if x.max(y) > 1e-280 {
                live += (a.z * b.z < 0.0) as usize;
                worst = worst.max((x - y).abs() / x.max(y));
            }
        }
    }
    assert!(
        live > 100,
        "too few transmission pairs with a value: {live}"
    );
    worst
}

#[test]
fn btdf_obeys_generalized_reciprocity() {
    for eta in [1.5, 1.0 / 1.33, 1.05, 4.0] {
        for (ax, ay) in [(0.1, 0.1), (0.5, 0.5), (0.2, 0.7)] {
            let g = worst(&Ggx::new(ax, ay).unwrap(), eta);
            let b = worst(&Beckmann::new(ax, ay).unwrap(), eta);
            println!("eta {eta} alpha ({ax}, {ay}): ggx {g:.2e} beckmann {b:.2e}");
            // The two orders form h and F from different roundings; next to the critical
            // angle 1 - F has a square-root slope in the cosine, so one rounding of wi.h moves
            // it by about sqrt(eps) = 1.5e-8 relative (measured worst: 8.8e-9, printed).
            assert!(
                g < 1e-7 && b < 1e-7,
                "eta {eta} alpha ({ax}, {ay}): {g} {b}"
            );
        }
    }
}

/// Without the n^2 factors the BTDF is not symmetric (a test of the test: the check above
/// would catch a missing or inverted factor).
#[test]
fn plain_swap_is_not_symmetric_across_the_interface() {
    let g = Ggx::isotropic(0.3).unwrap();
    let (a, b) = (
        V3::new(0.0, 0.6, 0.8),
        V3::new(0.0, -0.3, -(0.91_f64).sqrt()),
    );
    let ab = eval(&g, a, b, 1.5, Transport::Radiance);
    let ba = eval(&g, b, a, 1.5, Transport::Radiance);
    assert!(ab > 0.0 && ba > 0.0);
    assert!(((ab / ba) - 1.0 / 2.25).abs() < 1e-12, "{ab} {ba}");
}

#[test]
fn importance_is_the_adjoint_of_radiance() {
    let g = Ggx::new(0.2, 0.5).unwrap();
    let mut rng = crate::common::Rng(5);
    for _ in 0..10_000 {
        let mut d = || {
            let z = 2.0 * rng.next_f64() - 1.0;
            let p = core::f64::consts::TAU * rng.next_f64();
            let r = (1.0 - z * z).sqrt();
            V3::new(r * p.cos(), r * p.sin(), z)
        };
        let (a, b) = (d(), d());
        for eta in [1.5, 0.7] {
            let imp = eval(&g, a, b, eta, Transport::Importance);
            let rad = eval(&g, b, a, eta, Transport::Radiance);
            // sqrt(eps) conditioning of 1 - F near the critical angle, as above.
            assert!(
                (imp - rad).abs() <= 1e-7 * imp.max(rad),
                "{a:?} {b:?} {eta}: {imp} {rad}"
            );
        }
    }
}
