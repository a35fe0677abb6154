//! The material equals the formulas of its sources, written out here literally as each source
//! composes them: glTF 2.0 Appendix B (`mix(dielectric_brdf, metal_brdf, metallic)`),
//! KHR_materials_specular's dielectric, Filament's / UE4's sum, and the combined
//! kd = (1 - F)(1 - metallic) form. Also: the combined form equals Appendix B at metallic 0
//! and 1 only, and differs in between by exactly the closed form the module docs give.
#![cfg(all(feature = "material", feature = "ggx"))]

use brdf::Cosines;
use brdf::V3;
use brdf::ggx;
use brdf::material::{self, DiffuseCoupling, MetallicRoughness};

use crate::common;
use common::Rng;

const PI: f64 = core::f64::consts::PI;

fn mix(a: f64, b: f64, t: f64) -> f64 {
    a * (1.0 - t) + b * t
}

/// A uniformly random direction on the upper hemisphere.
fn direction(rng: &mut Rng) -> V3<f64> {
    let z = rng.next_f64().max(1e-6);
    let phi = 2.0 * PI * rng.next_f64();
    let r = (1.0 - z * z).sqrt();
    V3::new(r * phi.cos(), r * phi.sin(), z)
}

/// The cosines (n.v, n.l, n.h, v.h) of a random pair of directions.
fn cosines(rng: &mut Rng) -> (V3<f64>, V3<f64>, [f64; 4]) {
    let (wo, wi) = (direction(rng), direction(rng));
    let h = (wo + wi).normalize_or(V3::unit_z());
    (wo, wi, [wo.z, wi.z, h.z, wo.dot(h)])
}

/// The crate's alpha for perceptual roughness r: r^2 floored at ALPHA_MIN.
fn alpha(r: f64) -> f64 {
    (r * r).max(brdf::microfacet::ALPHA_MIN)
}

/// glTF 2.0 Appendix B, "Metal BRDF and Dielectric BRDF", line by line, for one channel, with
/// specular_brdf = D Vis from the crate's GGX terms.
fn appendix_b(c: [f64; 4], base: f64, metallic: f64, roughness: f64) -> f64 {
    let [nv, nl, nh, vh] = c;
    let a = alpha(roughness);
    let fresnel_w = (1.0 - vh.abs()).powi(5);
    let diffuse_brdf = (1.0 / PI) * base;
    let specular_brdf = ggx::d(nh, a) * ggx::v_correlated(nv, nl, a);
    let dielectric_f0 = 0.04;
    let dielectric_fresnel = dielectric_f0 + (1.0 - dielectric_f0) * fresnel_w;
    let dielectric_brdf = mix(diffuse_brdf, specular_brdf, dielectric_fresnel);
    let metal_fresnel = base + (1.0 - base) * fresnel_w;
    let metal_brdf = metal_fresnel * specular_brdf;
    mix(dielectric_brdf, metal_brdf, metallic)
}

/// |a - b| relative to `scale`, the size of the terms the BRDF sums (D V + base / pi): the
/// literal formulas form 1 - F by subtraction, which cancels where F is near 1, so their
/// error is relative to the terms, not to the result.
fn err(a: f64, b: f64, scale: f64) -> f64 {
    if a == b { 0.0 } else { (a - b).abs() / scale }
}

/// The term scale of [`err`] for cosines `c`, roughness `r` and one channel's base colour.
fn scale(c: [f64; 4], r: f64, base: f64) -> f64 {
    let a = alpha(r);
    ggx::d(c[2], a) * ggx::v_correlated(c[0], c[1], a) + base / PI
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

fn rgb(c: [f64; 3]) -> V3<f64> {
    V3::new(c[0], c[1], c[2])
}

fn channels(v: V3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// Random material parameters; metallic and roughness include their ends.
fn params(rng: &mut Rng, i: usize) -> ([f64; 3], f64, f64) {
    let base = [rng.next_f64(), rng.next_f64(), rng.next_f64()];
    let metallic = [0.0, 1.0, rng.next_f64()][i % 3];
    let roughness = [0.0, 1.0, 0.05, rng.next_f64()][i % 4];
    (base, metallic, roughness)
}

#[test]
fn gltf_equals_the_appendix_b_composition() {
    let mut rng = Rng(0xb5df);
    let mut worst: f64 = 0.0;
    for i in 0..20_000 {
        let (_, _, c) = cosines(&mut rng);
        let (base, metallic, roughness) = params(&mut rng, i);
        let ours = material::gltf(
            Cosines {
                n_dot_v: c[0],
                n_dot_l: c[1],
                n_dot_h: c[2],
                v_dot_h: c[3],
            },
            rgb(base),
            metallic,
            roughness,
        );
        for (k, ours) in channels(ours).into_iter().enumerate() {
            let expected = appendix_b(c, base[k], metallic, roughness);
            worst = worst.max(err(ours, expected, scale(c, roughness, base[k])));
        }
    }
    println!("gltf vs Appendix B composition: max difference {worst:.1e} of D V + base / pi");
    // A handful of roundings in either evaluation order (the composition's two mixes against
    // one mixed Fresnel and one fused multiply-add): 4e-15 is ~18 ulps; 6e-16 measured.
    assert!(worst <= 4e-15, "{worst}");
}

#[test]
fn gltf_terms_equal_the_specification_formulas() {
    // The specification's D and Vis, written as it writes them (with 1 + NoH^2 (alpha^2 - 1),
    // whose cancellation near NoH = 1 costs eps / alpha^2 relative: so roughness >= 0.1 here).
    let mut rng = Rng(0x5bec);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let (_, _, [nv, nl, nh, _]) = cosines(&mut rng);
        let r = 0.1 + 0.9 * rng.next_f64();
        let a2 = (r * r) * (r * r);
        let d = a2 / (PI * (nh * nh * (a2 - 1.0) + 1.0).powi(2));
        let vis = 0.5
            / (nv * (a2 + (1.0 - a2) * nl * nl).sqrt() + nl * (a2 + (1.0 - a2) * nv * nv).sqrt());
        worst = worst
            .max(rel(ggx::d(nh, r * r), d))
            .max(rel(ggx::v_correlated(nv, nl, r * r), vis));
    }
    println!("ggx::d, ggx::v_correlated vs the glTF formulas: max relative difference {worst:.1e}");
    // eps / alpha^2 at alpha = 0.01 is 2e-12.
    assert!(worst <= 1e-11, "{worst}");
}

#[test]
fn combined_one_minus_f_form_equals_appendix_b_only_at_metallic_0_and_1() {
    let mut rng = Rng(0xc0b1);
    let (mut worst_ends, mut worst_closed, mut largest_gap): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for i in 0..20_000 {
        let (_, _, c) = cosines(&mut rng);
        let (base, metallic, roughness) = params(&mut rng, i);
        // The combined form written out: F0 = lerp(0.04, base, metallic),
        // F = Schlick(F0, v.h), f = (1 - F)(1 - metallic) base / pi + F D V.
        let a = alpha(roughness);
        let w = (1.0 - c[3]).powi(5);
        let dv = ggx::d(c[2], a) * ggx::v_correlated(c[0], c[1], a);
        let ours = material::metallic_roughness(
            Cosines {
                n_dot_v: c[0],
                n_dot_l: c[1],
                n_dot_h: c[2],
                v_dot_h: c[3],
            },
            rgb(base),
            metallic,
            roughness,
            0.04,
            DiffuseCoupling::OneMinusF,
        );
        for (k, ours) in channels(ours).into_iter().enumerate() {
            let f0 = mix(0.04, base[k], metallic);
            let f = f0 + (1.0 - f0) * w;
            let combined = (1.0 - f) * (1.0 - metallic) * base[k] / PI + f * dv;
            let sc = scale(c, roughness, base[k]);
            assert!(err(ours, combined, sc) <= 4e-15, "{ours} vs {combined}");
            let spec = appendix_b(c, base[k], metallic, roughness);
            let gap = spec - combined;
            if metallic == 0.0 || metallic == 1.0 {
                worst_ends = worst_ends.max(err(spec, combined, sc));
            } else {
                // Appendix B minus the combined form, in closed form.
                let closed =
                    metallic * (1.0 - metallic) * (base[k] - 0.04) * (1.0 - w) * base[k] / PI;
                worst_closed = worst_closed.max(err(gap, closed, sc));
                largest_gap = largest_gap.max(gap.abs());
            }
        }
    }
    // The worst case of the closed form: base 1, metallic 1/2, v.h = 1.
    let peak = 0.25 * 0.96 / PI;
    println!(
        "combined (1 - F)(1 - metallic) vs Appendix B at metallic 0 and 1: max difference {worst_ends:.1e} of D V + base / pi"
    );
    println!(
        "in between: gap - m (1 - m)(base - 0.04)(1 - w) base / pi, max {worst_closed:.1e} of D V + base / pi"
    );
    println!(
        "largest gap seen {largest_gap:.4} (bound {peak:.4} at base 1, metallic 0.5, v.h = 1)"
    );
    assert!(worst_ends <= 4e-15, "{worst_ends}");
    assert!(worst_closed <= 4e-15, "{worst_closed}");
    assert!(largest_gap <= peak + 1e-15 && largest_gap > 0.5 * peak);
    // The gap at the worst case itself.
    let c = [1.0, 1.0, 1.0, 1.0];
    let combined = channels(material::metallic_roughness(
        Cosines {
            n_dot_v: 1.0,
            n_dot_l: 1.0,
            n_dot_h: 1.0,
            v_dot_h: 1.0,
        },
        V3::splat(1.0),
        0.5,
        0.5,
        0.04,
        DiffuseCoupling::OneMinusF,
    ))[0];
    assert!(((appendix_b(c, 1.0, 0.5, 0.5) - combined) - peak).abs() <= 1e-15);
}

#[test]
fn khr_materials_specular_equals_its_implementation_section() {
    let mut rng = Rng(0x5bec_c0de);
    let mut worst: f64 = 0.0;
    for i in 0..20_000 {
        let (wo, wi, c) = cosines(&mut rng);
        let (base, metallic, roughness) = params(&mut rng, i);
        let ior = 1.0 + 2.0 * rng.next_f64();
        let specular = [0.0, 1.0, rng.next_f64()][i % 3];
        // Colours above 1 are allowed by the extension (clamped after the product).
        let color = [3.0 * rng.next_f64(), rng.next_f64(), 30.0 * rng.next_f64()];
        let m = MetallicRoughness::new(rgb(base), metallic, roughness)
            .unwrap()
            .with_ior(ior)
            .unwrap()
            .with_specular(specular, rgb(color))
            .unwrap();
        let a = alpha(roughness);
        let w = (1.0 - c[3]).powi(5);
        let specular_brdf = ggx::d(c[2], a) * ggx::v_correlated(c[0], c[1], a);
        let f0_ior = ((ior - 1.0) / (ior + 1.0)).powi(2);
        let dielectric_fresnel: Vec<f64> = (0..3)
            .map(|k| mix((f0_ior * color[k]).min(1.0) * specular, specular, w))
            .collect();
        let max_value = dielectric_fresnel.iter().copied().fold(f64::MIN, f64::max);
        let ours = channels(m.eval(wo, wi));
        for k in 0..3 {
            let diffuse_brdf = base[k] / PI;
            let dielectric_brdf =
                dielectric_fresnel[k] * specular_brdf + (1.0 - max_value) * diffuse_brdf;
            let metal_brdf = (base[k] + (1.0 - base[k]) * w) * specular_brdf;
            let expected = mix(dielectric_brdf, metal_brdf, metallic);
            worst = worst.max(err(ours[k], expected, specular_brdf + diffuse_brdf));
        }
    }
    println!("KHR_materials_specular: max difference {worst:.1e} of D V + base / pi");
    // Both sides use the same cosines; only the order of the mixes and the literal's
    // 1 - max_value subtraction differ (~18 ulps of the terms allowed).
    assert!(worst <= 4e-15, "{worst}");
}

#[test]
fn filament_and_ue4_sum_the_lobes_without_a_fresnel_weight() {
    let mut rng = Rng(0xf11a);
    let mut worst: f64 = 0.0;
    for i in 0..20_000 {
        let (wo, wi, c) = cosines(&mut rng);
        let (base, metallic, roughness) = params(&mut rng, i);
        let reflectance = rng.next_f64();
        let m = MetallicRoughness::new(rgb(base), metallic, roughness)
            .unwrap()
            .with_reflectance(reflectance)
            .unwrap()
            .with_coupling(DiffuseCoupling::Additive);
        let a = alpha(roughness);
        let w = (1.0 - c[3]).powi(5);
        let dv = ggx::d(c[2], a) * ggx::v_correlated(c[0], c[1], a);
        let ours = channels(m.eval(wo, wi));
        for k in 0..3 {
            // Filament, section 4.8.3: diffuseColor = (1 - metallic) baseColor,
            // f0 = 0.16 reflectance^2 (1 - metallic) + baseColor metallic, f = Fd + Fr.
            let diffuse_color = (1.0 - metallic) * base[k];
            let f0 = 0.16 * reflectance * reflectance * (1.0 - metallic) + base[k] * metallic;
            let f = f0 + (1.0 - f0) * w;
            let expected = diffuse_color / PI + dv * f;
            worst = worst.max(err(ours[k], expected, dv + base[k] / PI));
        }
    }
    println!("Filament / UE4: max difference {worst:.1e} of D V + base / pi");
    assert!(worst <= 4e-15, "{worst}");
}

#[test]
fn eval_equals_the_dot_product_form() {
    let mut rng = Rng(0xe7a1);
    let mut worst: f64 = 0.0;
    for i in 0..20_000 {
        let (wo, wi, _) = cosines(&mut rng);
        let (base, metallic, roughness) = params(&mut rng, i);
        let coupling = [
            DiffuseCoupling::Gltf,
            DiffuseCoupling::OneMinusF,
            DiffuseCoupling::Additive,
        ][i % 3];
        let f0 = 0.2 * rng.next_f64();
        let m = MetallicRoughness::new(rgb(base), metallic, roughness)
            .unwrap()
            .with_dielectric_f0(f0)
            .unwrap()
            .with_coupling(coupling);
        let (h, v_dot_h) = brdf::cook_torrance::half_vector(wo, wi);
        let free = material::metallic_roughness(
            Cosines {
                n_dot_v: wo.z,
                n_dot_l: wi.z,
                n_dot_h: h.z,
                v_dot_h,
            },
            rgb(base),
            metallic,
            roughness,
            f0,
            coupling,
        );
        let vector = m.eval(wo, wi);
        for (a, b) in channels(free).into_iter().zip(channels(vector)) {
            worst = worst.max(rel(a, b));
        }
    }
    println!("eval vs metallic_roughness on the same cosines: max relative difference {worst:.1e}");
    // Same kernel, same cosines: identical.
    assert_eq!(worst, 0.0);
}
