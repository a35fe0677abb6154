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

/// three.js's anisotropic lobe (WebGPU node materials), transcribed in f32:
/// - `D_GGX_Anisotropic` and `V_GGX_SmithCorrelated_Anisotropic`,
///   `src/nodes/functions/BSDF/*.js` at commit 011d3c8d632cbe7c61f094f8daf35af4761521ae;
/// - `BRDF_GGX.js` (commit 343d19d7cdffa8341881d107b9bbcf10771ae42f) passes alphaB = alpha =
///   roughness^2 and the tangent's alphaT;
/// - `src/materials/nodes/MeshPhysicalNodeMaterial.js` (commit
///   2121d08351df31cb74606fe6b2802287e1d72a88) sets alphaT = mix(roughness^2, 1,
///   anisotropy^2), the strength saturated.
mod threejs {
    const RECIPROCAL_PI: f32 = 1.0 / core::f32::consts::PI;
    const EPSILON: f32 = 1e-6;

    pub fn alpha_t(roughness: f32, anisotropy: f32) -> f32 {
        let a = roughness * roughness;
        let s = anisotropy.clamp(0.0, 1.0);
        let t = s * s;
        a * (1.0 - t) + t
    }

    pub fn d(alpha_t: f32, alpha_b: f32, nh: f32, th: f32, bh: f32) -> f32 {
        let a2 = alpha_t * alpha_b;
        let (x, y, z) = (alpha_b * th, alpha_t * bh, a2 * nh);
        let v2 = x * x + y * y + z * z;
        let w2 = a2 / v2;
        RECIPROCAL_PI * (a2 * (w2 * w2))
    }

    #[allow(clippy::too_many_arguments)]
    pub fn v(at: f32, ab: f32, tv: f32, bv: f32, tl: f32, bl: f32, nv: f32, nl: f32) -> f32 {
        let len = |x: f32, y: f32, z: f32| (x * x + y * y + z * z).sqrt();
        let gv = nl * len(at * tv, ab * bv, nv);
        let gl = nv * len(at * tl, ab * bl, nl);
        0.5 / (gv + gl).max(EPSILON)
    }
}

/// The stretched lobe against three.js: alpha_t is the same mix, and D and V of the crate's
/// anisotropic GGX agree with three.js's to its f32 rounding over random directions, roughness
/// and strength (three.js's D forms |v|^2 from squares that do not cancel, so no n.h = 1 loss).
#[test]
fn threejs_anisotropic_lobe_agrees_to_f32_rounding() {
    let mut rng = Rng(77);
    let (mut wa, mut wd, mut wv, mut n) = (0.0f64, 0.0f64, 0.0f64, 0usize);
    let rel = |a: f32, b: f32| (f64::from(a) - f64::from(b)).abs() / f64::from(b).abs();
    let dir = |rng: &mut Rng| {
        let z = 0.02 + 0.98 * rng.next_f64();
        let phi = core::f64::consts::TAU * rng.next_f64();
        let s = (1.0 - z * z).sqrt();
        V3::new((s * phi.cos()) as f32, (s * phi.sin()) as f32, z as f32).normalize()
    };
    for _ in 0..20_000 {
        let r = (0.05 + 0.95 * rng.next_f64()) as f32;
        let s = rng.next_f64() as f32;
        let ours_at = alpha_t(r * r, s);
        let theirs_at = threejs::alpha_t(r, s);
        wa = wa.max(rel(ours_at, theirs_at));
        let (v, l) = (dir(&mut rng), dir(&mut rng));
        let h = (v + l).normalize();
        let lobe = Ggx::new(theirs_at, r * r).unwrap();
        // The lobe's frame is (t, b, n) = (x, y, z): each dot product is a component.
        let d_theirs = threejs::d(theirs_at, r * r, h.z, h.x, h.y);
        let v_theirs = threejs::v(theirs_at, r * r, v.x, v.y, l.x, l.y, v.z, l.z);
        if d_theirs > 1e-30 {
            wd = wd.max(rel(lobe.d(h), d_theirs));
        }
        wv = wv.max(rel(lobe.v_correlated(v, l), v_theirs));
        n += 1;
    }
    println!(
        "three.js anisotropy over {n} pairs: alpha_t max rel {wa:.2e}, D max rel {wd:.2e}, \
         V max rel {wv:.2e}"
    );
    // alpha_t: the same mix, summed in another order (a few f32 roundings).
    assert!(wa < 1e-6, "{wa}");
    // D: a handful of f32 roundings on three.js's side (a2 / v2 squared: about 10 ULP).
    assert!(wd < 2e-6, "{wd}");
    // V: two f32 square roots and sums on three.js's side.
    assert!(wv < 2e-6, "{wv}");
}
