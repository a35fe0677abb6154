//! KHR_materials_ior and KHR_materials_specular: the special IOR 0, validation, and the
//! dielectric F0 against the metallic-roughness material's own `with_ior`/`with_specular`.
#![cfg(feature = "specular")]

use brdf::V3;
use brdf::layers::specular::{Ior, Specular, f0_from_ior};

#[test]
fn ior_edges_and_special_value() {
    assert_eq!(f0_from_ior(0.0_f64), 1.0);
    assert_eq!(f0_from_ior(1.0_f64), 0.0);
    assert!((f0_from_ior(1.5_f64) - 0.04).abs() < 1e-17);
    for bad in [0.5, -1.0, f64::INFINITY, f64::NAN] {
        assert!(f0_from_ior(bad).is_nan(), "{bad}");
        assert!(Ior::new(bad).is_err(), "{bad}");
    }
    assert!(Ior::new(0.0_f32).is_ok());
    assert!(Specular::new(1.1_f32, V3::splat(1.0)).is_err());
    assert!(Specular::new(0.5_f32, V3::new(1.0, -0.1, 1.0)).is_err());
    assert!(Specular::new(0.5_f32, V3::new(1.0, 4.0, 1.0)).is_ok());
}

#[cfg(feature = "material")]
#[test]
fn dielectric_f0_matches_the_metallic_roughness_material() {
    use brdf::layers::specular::dielectric_f0;
    use brdf::material::MetallicRoughness;
    for ior in [1.0, 1.33, 1.5, 2.4, 5.0] {
        for (s, col) in [
            (1.0, [1.0, 1.0, 1.0]),
            (0.5, [2.0, 1.0, 0.3]),
            (0.0, [9.0, 0.0, 1.0]),
        ] {
            let col = V3::new(col[0], col[1], col[2]);
            let m = MetallicRoughness::new(V3::splat(0.5), 0.0, 0.5)
                .and_then(|m| m.with_ior(ior))
                .and_then(|m| m.with_specular(s, col))
                .unwrap();
            let spec = Specular::new(s, col).unwrap();
            let ours = spec.dielectric_f0(&Ior::new(ior).unwrap());
            assert_eq!(ours, m.dielectric_f0(), "ior {ior} specular {s}");
            assert_eq!(spec.dielectric_f90(), m.dielectric_f90());
            assert_eq!(ours, dielectric_f0(f0_from_ior(ior), s, col));
        }
    }
}

/// three.js's dielectric F0 and F90 (`setupSpecular` in
/// `src/materials/nodes/MeshPhysicalNodeMaterial.js` at commit
/// 2121d08351df31cb74606fe6b2802287e1d72a88), transcribed in f32 for metalness 0:
/// specularColor = min(((ior - 1) / (ior + 1))^2 specularColorFactor, 1) specularIntensity and
/// specularF90 = mix(specularIntensity, 1, metalness) = specularIntensity.
fn threejs_specular(ior: f32, intensity: f32, color: [f32; 3]) -> ([f32; 3], f32) {
    let f0 = ((ior - 1.0) / (ior + 1.0)).powi(2);
    (color.map(|c| (f0 * c).min(1.0) * intensity), intensity)
}

/// The extensions' F0 and F90 rule against three.js's: the same formula, so the values agree
/// to the f32 rounding of F0_ior (three.js divides then squares; the crate's `f0_from_ior` is
/// within its documented ULP of the exact value).
#[test]
fn dielectric_f0_and_f90_agree_with_threejs() {
    let mut worst = 0.0f64;
    for ior in [1.0f32, 1.01, 1.33, 1.5, 1.8, 2.4, 3.0, 5.0] {
        for s in [0.0f32, 0.25, 0.5, 1.0] {
            for col in [[1.0f32, 1.0, 1.0], [2.0, 1.0, 0.3], [9.0, 0.0, 0.5]] {
                let spec = Specular::new(s, V3::new(col[0], col[1], col[2])).unwrap();
                let ours = spec.dielectric_f0(&Ior::new(ior).unwrap());
                let (theirs, f90) = threejs_specular(ior, s, col);
                assert_eq!(spec.dielectric_f90(), f90, "F90 is the specular factor");
                for (o, t) in [
                    (ours.x, theirs[0]),
                    (ours.y, theirs[1]),
                    (ours.z, theirs[2]),
                ] {
                    if t > 0.0 {
                        worst = worst.max((f64::from(o) - f64::from(t)).abs() / f64::from(t));
                    } else {
                        assert_eq!(o, 0.0);
                    }
                }
            }
        }
    }
    println!("three.js specular F0: max rel {worst:.2e}");
    assert!(worst < 1e-6, "{worst}");
}
