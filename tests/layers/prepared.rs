//! The layered material prepared per shading point (`Layered::at_view`): its min-form eval is
//! the direct eval bit for bit (f64 and lanes), and its view-only form equals the min form
//! exactly where the light's sheen albedo is at most the view's, and dims the base less
//! elsewhere, the sheen lobe and coat unchanged.
#![cfg(feature = "layered")]

use brdf::layers::layered::Layered;
use brdf::layers::sheen;
use brdf::wide::f32x8;
use brdf::{Real, V3};

use crate::common::Rng;

fn random_dir(rng: &mut Rng) -> V3<f64> {
    let z = rng.next_f64();
    let phi = rng.next_f64() * core::f64::consts::TAU;
    let r = (1.0 - z * z).sqrt();
    V3::new(r * phi.cos(), r * phi.sin(), z)
}

/// A plain base, a sheen alone, and every layer with compensation, at sheen roughness r.
fn materials<T: Real>(r: f64) -> Vec<Layered<T>> {
    let s = T::splat;
    let plain = Layered::new(V3::new(s(0.9), s(0.6), s(0.3)), s(0.2), s(0.5)).unwrap();
    let sheen = plain
        .with_sheen(V3::new(s(0.8), s(0.4), s(0.2)), s(r))
        .unwrap();
    let all = sheen
        .with_clearcoat(s(0.8), s(0.2))
        .and_then(|m| m.with_clearcoat_normal(V3::new(s(0.0), s(0.6), s(0.8))))
        .and_then(|m| m.with_anisotropy(s(0.7), s(0.4)))
        .unwrap()
        .with_compensation(true);
    vec![plain, sheen, all]
}

const SHEEN_ROUGHNESS: [f64; 4] = [0.0, 0.3, 0.7, 1.0];

#[test]
fn prepared_eval_is_the_direct_eval_bit_for_bit() {
    let mut rng = Rng(24);
    for r in SHEEN_ROUGHNESS {
        for m in materials::<f64>(r) {
            for _ in 0..200 {
                let wo = random_dir(&mut rng);
                let at = m.at_view(wo);
                for _ in 0..5 {
                    let wi = random_dir(&mut rng);
                    let (a, b) = (at.eval(wi), m.eval(wo, wi));
                    for (x, y) in [(a.x, b.x), (a.y, b.y), (a.z, b.z)] {
                        assert_eq!(x.to_bits(), y.to_bits(), "r {r} wo {wo:?} wi {wi:?}");
                    }
                }
            }
            // Below the horizon and NaN, as the direct form.
            let at = m.at_view(V3::new(0.0, 0.0, 1.0));
            assert_eq!(at.eval(V3::new(0.0, 0.6, -0.8)), V3::splat(0.0));
            assert!(at.eval(V3::new(f64::NAN, 0.0, 1.0)).x.is_nan());
            assert!(
                m.at_view(V3::new(0.0, f64::NAN, 1.0))
                    .eval(V3::new(0.0, 0.0, 1.0))
                    .y
                    .is_nan()
            );
        }
    }
}

#[test]
fn prepared_lanes_follow_the_direct_lanes() {
    let mut rng = Rng(7);
    for r in SHEEN_ROUGHNESS {
        for m in materials::<f32x8>(r) {
            for _ in 0..50 {
                let dir = |rng: &mut Rng| {
                    let d: [V3<f64>; 8] = core::array::from_fn(|_| random_dir(rng));
                    V3::new(
                        f32x8::from_fn(|i| d[i].x as f32),
                        f32x8::from_fn(|i| d[i].y as f32),
                        f32x8::from_fn(|i| d[i].z as f32),
                    )
                };
                let (wo, wi) = (dir(&mut rng), dir(&mut rng));
                let (a, b) = (m.at_view(wo).eval(wi), m.eval(wo, wi));
                for (x, y) in [(a.x, b.x), (a.y, b.y), (a.z, b.z)] {
                    for i in 0..8 {
                        assert_eq!(x.lane(i).to_bits(), y.lane(i).to_bits());
                    }
                }
            }
        }
    }
}

#[test]
fn view_only_scaling_is_the_min_form_where_the_light_albedo_is_lower() {
    // min(1 - m E_v, 1 - m E_l) = 1 - m max(E_v, E_l): the view-only 1 - m E_v is the same
    // number where E_l <= E_v, and larger (the base dimmed less) where E_l > E_v.
    let mut rng = Rng(3);
    let (mut equal, mut brighter) = (0, 0);
    for r in SHEEN_ROUGHNESS {
        let alpha = r * r;
        for m in materials::<f64>(r).into_iter().skip(1) {
            for _ in 0..400 {
                let (wo, wi) = (random_dir(&mut rng), random_dir(&mut rng));
                let at = m.at_view(wo);
                let (min_form, view_only) = (at.eval(wi), at.eval_view_only(wi));
                let (e_v, e_l) = (sheen::albedo(wo.z, alpha), sheen::albedo(wi.z, alpha));
                let pairs = [
                    (min_form.x, view_only.x),
                    (min_form.y, view_only.y),
                    (min_form.z, view_only.z),
                ];
                if e_l <= e_v {
                    equal += 1;
                    for (a, b) in pairs {
                        assert_eq!(a.to_bits(), b.to_bits(), "E_l {e_l} <= E_v {e_v}");
                    }
                } else {
                    brighter += 1;
                    for (a, b) in pairs {
                        assert!(
                            b >= a,
                            "view-only {b} below min form {a} (E_l {e_l} > E_v {e_v})"
                        );
                    }
                    // The red channel's base is non-zero and the sheen colour's max is 0.8:
                    // a gap in E must show in the result.
                    if e_l - e_v > 1e-3 {
                        assert!(pairs[0].1 > pairs[0].0);
                    }
                }
            }
        }
    }
    assert!(
        equal > 100 && brighter > 100,
        "both cases sampled: {equal} {brighter}"
    );
}

#[test]
fn view_only_is_the_min_form_for_a_black_sheen() {
    let mut rng = Rng(11);
    // The plain base: its sheen colour is black.
    let m = materials::<f64>(0.5)[0];
    for _ in 0..200 {
        let (wo, wi) = (random_dir(&mut rng), random_dir(&mut rng));
        let at = m.at_view(wo);
        assert_eq!(at.eval(wi), at.eval_view_only(wi));
    }
}
