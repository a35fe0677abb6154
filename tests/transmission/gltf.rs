//! glTF `KHR_materials_transmission` and `KHR_materials_volume` (`brdf::transmission`):
//! Beer-Lambert's laws, the thin-walled BTDF as the mirrored reflection lobe (by the
//! integrators), the dielectric BSDF's energy over the sphere in both readings, its
//! opaque limit (t = 0) against the metallic-roughness material, and its volumetric lobe
//! against `rough_dielectric`.

use crate::common::Rng;
use crate::{dir, refracted};
use brdf::ggx::Ggx;
use brdf::integrate::{Config, directional_albedo_sphere, hemisphere};
use brdf::microfacet::Microfacet;
use brdf::rough_dielectric::{self as rd, Transport};
use brdf::transmission::{Transmission, Volume, dielectric_bsdf, thin_walled_btdf};
use brdf::{V3, fresnel};

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

#[test]
fn beer_lambert_laws() {
    let c = V3::new(0.9, 0.5, 0.02);
    let v = Volume::new(0.0, c, 0.7).unwrap();
    // T(d) = c: the definition of the attenuation colour.
    let at_d = v.transmittance(0.7);
    for (a, b) in [(at_d.x, c.x), (at_d.y, c.y), (at_d.z, c.z)] {
        assert!(rel(a, b) < 4.0 * f64::EPSILON, "{a} {b}");
    }
    let one = v.transmittance(0.0);
    assert_eq!((one.x, one.y, one.z), (1.0, 1.0, 1.0));
    let sigma = v.attenuation_coefficient();
    let mut rng = Rng(8);
    for _ in 0..1000 {
        let (a, b) = (5.0 * rng.next_f64(), 5.0 * rng.next_f64());
        let (ta, tb, tab) = (
            v.transmittance(a),
            v.transmittance(b),
            v.transmittance(a + b),
        );
        // Multiplicative in the path length, and exp(-sigma x).
        assert!(rel(tab.x, ta.x * tb.x) < 1e-13 && rel(tab.z, ta.z * tb.z) < 1e-12);
        assert!(rel(ta.y, (-sigma.y * a).exp()) < 1e-13);
    }
    // Edges: colour 1 never attenuates, colour 0 absorbs everything, the largest distance and
    // the largest path stay finite.
    let e = Volume::new(0.0, V3::new(1.0, 0.0, 0.5), f64::MAX).unwrap();
    let t = e.transmittance(f64::MAX);
    assert_eq!((t.x, t.y), (1.0, 0.0));
    assert!(t.z > 0.0 && t.z < 1.0);
    assert_eq!(e.transmittance(1.0).x, 1.0);
    assert!(e.transmittance(f64::NAN).x.is_nan() && e.transmittance(-1.0).y.is_nan());
    // Construction validates every field.
    assert!(Volume::new(-1.0, c, 1.0).is_err());
    assert!(Volume::new(0.0, V3::new(1.1, 0.0, 0.0), 1.0).is_err());
    assert!(Volume::new(0.0, c, 0.0).is_err());
    assert!(Volume::new(0.0, c, f64::INFINITY).is_err());
    assert!(Transmission::new(1.5).is_err() && Transmission::new(f64::NAN).is_err());
}

/// The thin-walled BTDF transmits exactly what the separable-G reflection lobe reflects, by a
/// change of variables (wi -> its mirror through the plane): both integrals by quadrature.
#[test]
fn thin_walled_btdf_is_the_mirrored_reflection_lobe() {
    let cfg = Config::default();
    for (ax, ay) in [(0.1, 0.1), (0.4, 0.4), (0.2, 0.6)] {
        let g = Ggx::new(ax, ay).unwrap();
        for theta in [0.0, 45.0, 80.0] {
            let wo = dir(theta, 20.0);
            let below = hemisphere(
                |w| thin_walled_btdf(&g, wo, V3::new(w.x, w.y, -w.z)) * w.z,
                &[V3::new(-wo.x, -wo.y, wo.z), wo],
                &cfg,
            );
            let reflect = hemisphere(
                |wi| {
                    let h = (wo + wi).normalize();
                    g.d(h) * g.g2_separable(wo, wi) / (4.0 * wo.z * wi.z) * wi.z
                },
                &[wo],
                &cfg,
            );
            println!(
                "({ax}, {ay}) theta {theta}: transmitted {:.6} reflected {:.6}",
                below.value, reflect.value
            );
            assert!((below.value - reflect.value).abs() < 1e-6 + below.error + reflect.error);
        }
    }
}

/// With t = 1 (no diffuse lobe) the glTF dielectric with transmission scatters at most all
/// the light (white base colour), thin-walled and volumetric, for views from normal to
/// grazing; its albedo is linear in t, so below t = 1 it exceeds 1 exactly where the opaque
/// glTF dielectric does (its diffuse weight 1 - F(v.h) ignores the energy the specular lobe
/// takes: `tests/material/energy.rs`).
#[test]
fn dielectric_bsdf_furnace_is_at_most_one_without_diffuse() {
    let white = V3::new(1.0, 1.0, 1.0);
    println!(
        "{:>5} {:>7} {:>10} {:>10} {:>10} {:>10}",
        "alpha", "theta_o", "thin t=1", "vol t=1", "t=0", "t=1/2"
    );
    for alpha in [0.05, 0.3, 1.0] {
        let g = Ggx::isotropic(alpha).unwrap();
        for theta in [0.0, 50.0, 85.0] {
            let wo = dir(theta, 0.0);
            let rho = |t: f64, thick: f64| {
                let tr = Transmission::new(t).unwrap();
                let vol = Volume::new(thick, white, f64::MAX).unwrap();
                let peaks: Vec<V3<f64>> = refracted(wo, 1.5).into_iter().chain([-wo]).collect();
                directional_albedo_sphere(
                    wo,
                    |o, i| dielectric_bsdf(&g, o, i, white, 1.5, &tr, &vol).x,
                    &peaks,
                )
            };
            let (thin, vol) = (rho(1.0, 0.0), rho(1.0, 1.0));
            let (opaque, half) = (rho(0.0, 1.0), rho(0.5, 1.0));
            println!(
                "{alpha:>5} {theta:>7} {:>10.5} {:>10.5} {:>10.5} {:>10.5}",
                thin.value, vol.value, opaque.value, half.value
            );
            for e in [thin, vol] {
                assert!(
                    e.value <= 1.0 + e.error + 1e-6,
                    "alpha {alpha} theta {theta}: {e:?}"
                );
            }
            let mid = 0.5 * (opaque.value + vol.value);
            assert!((half.value - mid).abs() < 1e-6 + half.error + opaque.error + vol.error);
        }
    }
}

/// With t = 0 the BSDF is the opaque glTF dielectric: the metallic-roughness material with
/// metallic 0 (ior 1.5, F0 = 0.04), and nothing below the surface.
#[cfg(feature = "material")]
#[test]
fn opaque_limit_is_the_metallic_roughness_material() {
    use brdf::material::MetallicRoughness;
    let base = V3::new(0.8, 0.4, 0.1);
    let opaque = Transmission::new(0.0).unwrap();
    let thin = Volume::new(0.0, V3::new(1.0, 1.0, 1.0), 1.0).unwrap();
    let mut rng = Rng(21);
    let mut worst: f64 = 0.0;
    for _ in 0..5000 {
        let r = 0.2 + 0.8 * rng.next_f64();
        let g = Ggx::isotropic(r * r).unwrap();
        let mat = MetallicRoughness::new(base, 0.0, r).unwrap();
        let wo = dir(89.0 * rng.next_f64(), 360.0 * rng.next_f64());
        let wi = dir(89.0 * rng.next_f64(), 360.0 * rng.next_f64());
        let a = dielectric_bsdf(&g, wo, wi, base, 1.5, &opaque, &thin);
        let b = mat.eval(wo, wi);
        worst = worst.max(rel(a.x, b.x)).max(rel(a.z, b.z));
        let below = dielectric_bsdf(
            &g,
            wo,
            V3::new(wi.x, wi.y, -wi.z),
            base,
            1.5,
            &opaque,
            &thin,
        );
        assert_eq!((below.x, below.y, below.z), (0.0, 0.0, 0.0));
    }
    println!("t = 0 against MetallicRoughness::eval: max relative difference {worst:.2e}");
    assert!(worst < 1e-12, "{worst}");
}

/// The volumetric reading's transmission lobe is `rough_dielectric`'s (radiance) with its
/// exact Fresnel factor 1 - F replaced by the glTF Schlick factor.
#[test]
fn volumetric_lobe_is_the_rough_dielectric_with_schlick() {
    let g = Ggx::new(0.25, 0.4).unwrap();
    let base = V3::new(1.0, 0.5, 0.25);
    let tr = Transmission::new(0.8).unwrap();
    let vol = Volume::new(2.0, V3::new(1.0, 1.0, 1.0), 1.0).unwrap();
    let mut rng = Rng(4);
    let mut checked = 0;
    for _ in 0..20_000 {
        let wo = dir(85.0 * rng.next_f64(), 360.0 * rng.next_f64());
        let wi = dir(95.0 + 85.0 * rng.next_f64(), 360.0 * rng.next_f64());
        let f = dielectric_bsdf(&g, wo, wi, base, 1.5, &tr, &vol);
        let walter = rd::eval(&g, wo, wi, 1.5, Transport::Radiance);
        let h = rd::half_vector(wo, wi, 1.5);
        let c = wo.dot(h);
        let exact_t = 1.0 - fresnel::dielectric(c, 1.5);
        let schlick_t = 1.0 - fresnel::schlick(fresnel::f0_from_ior(1.5), c.abs());
        if walter > 1e-6 && exact_t > 0.1 {
            let want = walter / exact_t * schlick_t * 0.8;
            assert!(
                rel(f.x, want) < 1e-9 && rel(f.y, 0.5 * want) < 1e-9,
                "{wo:?} {wi:?}: {f:?} {want}"
            );
            checked += 1;
        }
    }
    assert!(checked > 1000, "{checked}");
}
