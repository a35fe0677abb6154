//! KHR_materials_anisotropy: strength 0 is the isotropic lobe bit for bit, the direction
//! rotation, and the bent reflection vector against a transcription of the Khronos sample
//! viewer.
#![cfg(feature = "anisotropy")]

use brdf::ggx::Ggx;
use brdf::layers::anisotropy::{alpha_t, bent_reflection, direction};
use brdf::microfacet::Microfacet;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

use crate::common::Rng;

#[test]
fn strength_zero_is_the_isotropic_lobe_bit_for_bit() {
    fn check<T: Real>(x: impl Fn(f64) -> T) {
        let mut rng = Rng(3);
        for _ in 0..500 {
            let a = x(rng.next_f64());
            let at = alpha_t(a, T::ZERO);
            let m = V3::new(x(0.3), x(-0.2), x(rng.next_f64() + 0.1)).normalize();
            let aniso = Ggx::new(at, a).unwrap().d(m);
            let iso = Ggx::isotropic(a).unwrap().d(m);
            for k in 0..T::LANES {
                let (p, q): (f64, f64) = (aniso.lane(k).into(), iso.lane(k).into());
                assert_eq!(p.to_bits(), q.to_bits());
            }
        }
        let one: f64 = alpha_t(x(0.3), T::ONE).lane(0).into();
        assert_eq!(one, 1.0, "strength 1 stretches to alpha 1");
    }
    check(|v| v as f32);
    check(|v| v);
    check(|v| f32x8::splat(v as f32));
    check(f64x4::splat);
}

#[test]
fn direction_rotates_counter_clockwise_from_the_tangent() {
    let d = direction(1.0_f64, 0.0, core::f64::consts::FRAC_PI_2);
    assert!(d.x.abs() < 1e-16 && (d.y - 1.0).abs() < 1e-16 && d.z == 0.0);
    let d = direction(3.0_f64, 4.0, 0.0);
    assert!((d.x - 0.6).abs() < 1e-16 && (d.y - 0.8).abs() < 1e-16);
    // A zero texel vector is the default direction, the tangent.
    assert_eq!(direction(0.0_f64, 0.0, 0.0), V3::new(1.0, 0.0, 0.0));
    assert!(direction(f64::INFINITY, 0.0, 0.0).x.is_nan());
}

/// The Khronos glTF Sample Viewer, `source/Renderer/shaders/ibl.glsl`,
/// `getIBLRadianceAnisotropy` (as at commit 2c3c5a5dc2ae71af6fc2a5498c7ff83312ab5c73),
/// transcribed in f32 with glam: the bent normal and `normalize(reflect(-v, bentNormal))`.
fn viewer(n: glam::Vec3, v: glam::Vec3, b: glam::Vec3, aniso: f32, rough: f32) -> glam::Vec3 {
    let t = b.cross(v);
    let an = t.cross(b);
    let bend = 1.0 - aniso * (1.0 - rough);
    let k = bend * bend * bend * bend;
    let bent = (an * (1.0 - k) + n * k).normalize();
    let i = -v;
    (i - 2.0 * bent.dot(i) * bent).normalize()
}

#[test]
fn bent_reflection_matches_the_sample_viewer() {
    let mut rng = Rng(11);
    let mut worst = 0.0f32;
    for _ in 0..5000 {
        let n = glam::Vec3::Z;
        let phi = (rng.next_f64() * core::f64::consts::TAU) as f32;
        let ct = (rng.next_f64() * 0.95 + 0.05) as f32;
        let st = (1.0 - ct * ct).sqrt();
        let v = glam::Vec3::new(st * phi.cos(), st * phi.sin(), ct);
        let rot = (rng.next_f64() * core::f64::consts::TAU) as f32;
        let b = glam::Vec3::new(-rot.sin(), rot.cos(), 0.0);
        let (s, r) = (rng.next_f64() as f32, rng.next_f64() as f32);
        let ours: glam::Vec3 = bent_reflection(n.into(), v.into(), b.into(), s, r).into();
        let theirs = viewer(n, v, b, s, r);
        worst = worst.max((ours - theirs).length());
        // Strength 0: the mirror direction.
        let mirror: glam::Vec3 = bent_reflection(n.into(), v.into(), b.into(), 0.0, r).into();
        let m = glam::Vec3::new(-v.x, -v.y, v.z);
        assert!((mirror - m).length() < 4e-7, "{mirror} vs {m}");
    }
    println!("bent reflection vs sample viewer: max distance {worst:.2e}");
    assert!(worst < 2e-6, "{worst}");
}
