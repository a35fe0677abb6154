//! Helmholtz reciprocity of the metallic-roughness material, f(wo, wi) = f(wi, wo), per RGB
//! channel, by the public reciprocity check: every coupling is reciprocal (kd and F depend on
//! v.h = l.h, D on n.h and V symmetrically on n.v and n.l), with and without
//! KHR_materials_specular, for dielectrics, metals and their mixes.
#![cfg(all(feature = "material", feature = "integrate"))]

use brdf::V3;
use brdf::integrate::reciprocity;
use brdf::material::{DiffuseCoupling, MetallicRoughness};

#[test]
fn every_coupling_is_reciprocal() {
    let mut worst: f64 = 0.0;
    for coupling in [
        DiffuseCoupling::Gltf,
        DiffuseCoupling::OneMinusF,
        DiffuseCoupling::Additive,
    ] {
        for (metallic, roughness) in [(0.0, 0.05), (0.0, 0.5), (0.5, 0.3), (1.0, 0.25), (1.0, 1.0)]
        {
            let m = MetallicRoughness::new(V3::new(0.9, 0.5, 0.1), metallic, roughness)
                .unwrap()
                .with_coupling(coupling);
            // A coloured KHR_materials_specular dielectric (max_value in the glTF weight).
            let spec = m
                .with_ior(1.8)
                .unwrap()
                .with_specular(0.7, V3::new(2.0, 1.0, 0.3))
                .unwrap();
            for (variant, mat) in [("plain", m), ("KHR_materials_specular", spec)] {
                for c in 0..3 {
                    let r = reciprocity(|o, i| {
                        let f = mat.eval(o, i);
                        [f.x, f.y, f.z][c]
                    });
                    worst = worst.max(r.max_rel);
                    assert!(
                        r.max_rel <= 1e-12,
                        "{coupling:?} {variant} metallic {metallic} roughness {roughness} channel {c}: {r:?}"
                    );
                }
            }
        }
    }
    println!("max relative asymmetry over every coupling, material and channel: {worst:.1e}");
}

/// The check has teeth: a diffuse weight taken from the Fresnel factor at n.v alone, the
/// classic non-reciprocal coupling, fails it by orders of magnitude.
#[test]
fn a_one_sided_fresnel_weight_is_caught() {
    let m = MetallicRoughness::new(V3::splat(0.8), 0.0, 0.4).unwrap();
    let r = reciprocity(|o, i| {
        let f = m.eval(o, i).x;
        let w = (1.0 - o.z).powi(5);
        f * (1.0 - (0.04 + 0.96 * w))
    });
    println!(
        "one-sided (1 - F(n.v)) weight: max relative asymmetry {:.2}",
        r.max_rel
    );
    assert!(r.max_rel > 0.1, "{r:?}");
}
