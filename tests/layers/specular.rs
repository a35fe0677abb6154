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
