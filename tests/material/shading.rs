//! The shading point's geometry (`brdf::shading`): `Cosines` from world-space and local
//! directions against an f64 reference, their symmetry and edges, and the world-space entry
//! points of the material against the dot-product form through an independent route (the
//! cosines from world-space dot products, not the frame's rotation).
#![cfg(feature = "material")]

use brdf::material::{self, MetallicRoughness};
use brdf::wide::f32x8;
use brdf::{Cosines, Real, ShadingPoint, V3};

/// A deterministic stream of unit vectors (splitmix64, uniform on the sphere).
struct Dirs(u64);

impl Dirs {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn dir(&mut self) -> [f64; 3] {
        let z = 2.0 * self.unit() - 1.0;
        let phi = core::f64::consts::TAU * self.unit();
        let r = (1.0 - z * z).sqrt();
        [r * phi.cos(), r * phi.sin(), z]
    }

    /// A unit vector rounded to f32, renormalized in f64 and rounded again (so its length is
    /// within an f32 rounding of 1).
    fn dir32(&mut self) -> V3<f32> {
        let d = self.dir();
        V3::new(d[0] as f32, d[1] as f32, d[2] as f32)
    }
}

fn f64_of(v: V3<f32>) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The four cosines in f64 from the same f32 vectors, with h = normalize(v + l).
fn reference(n: V3<f32>, v: V3<f32>, l: V3<f32>) -> [f64; 4] {
    let (n, v, l) = (f64_of(n), f64_of(v), f64_of(l));
    let s = [v[0] + l[0], v[1] + l[1], v[2] + l[2]];
    let len = dot(s, s).sqrt();
    let h = [s[0] / len, s[1] / len, s[2] / len];
    // v.h as the crate defines it: |v + l| / 2, the mean of v.h and l.h for any lengths.
    [dot(n, v), dot(n, l), dot(n, h), (len / 2.0).min(1.0)]
}

#[test]
fn cosines_from_world_match_an_f64_reference_within_4_eps_absolute() {
    let mut rng = Dirs(7);
    let mut worst = [0.0f64; 4];
    for _ in 0..200_000 {
        let (n, v, l) = (rng.dir32(), rng.dir32(), rng.dir32());
        let c = Cosines::from_world(n, v, l);
        let got = [c.n_dot_v, c.n_dot_l, c.n_dot_h, c.v_dot_h].map(f64::from);
        let want = reference(n, v, l);
        // v + l shorter than 1e-3: h is ill-conditioned (each component's rounding turns it).
        if (2.0 * want[3]) < 1e-3 {
            continue;
        }
        for i in 0..4 {
            worst[i] = worst[i].max((got[i] - want[i]).abs() / f64::from(f32::EPSILON));
        }
    }
    println!("Cosines::from_world f32, max abs error in eps (n.v, n.l, n.h, v.h): {worst:.2?}");
    for (i, w) in worst.iter().enumerate() {
        assert!(*w <= 4.0, "cosine {i}: {w} eps");
    }
}

#[test]
fn cosines_from_local_equal_from_world_about_z_and_are_symmetric_bit_for_bit() {
    let mut rng = Dirs(11);
    let z = V3::unit_z();
    for _ in 0..100_000 {
        let (wo, wi) = (rng.dir32(), rng.dir32());
        let a = Cosines::from_local(wo, wi);
        let b = Cosines::from_world(z, wo, wi);
        let swapped = Cosines::from_local(wi, wo);
        let bits = |c: Cosines<f32>| [c.n_dot_v, c.n_dot_l, c.n_dot_h, c.v_dot_h].map(f32::to_bits);
        assert_eq!(bits(a), bits(b), "{wo:?} {wi:?}");
        assert_eq!(
            (a.n_dot_h.to_bits(), a.v_dot_h.to_bits()),
            (swapped.n_dot_h.to_bits(), swapped.v_dot_h.to_bits())
        );
        assert_eq!((a.n_dot_v, a.n_dot_l), (swapped.n_dot_l, swapped.n_dot_v));
    }
}

type Triple = (V3<f32>, V3<f32>, V3<f32>);

#[test]
fn lanes_equal_scalars_bit_for_bit() {
    let mut rng = Dirs(13);
    for _ in 0..10_000 {
        let triples: Vec<_> = (0..8)
            .map(|_| (rng.dir32(), rng.dir32(), rng.dir32()))
            .collect();
        let lanes = |f: fn(&Triple) -> V3<f32>| {
            let w: Vec<V3<f32>> = triples.iter().map(f).collect();
            V3::new(
                f32x8::from(core::array::from_fn::<f32, 8, _>(|i| w[i].x)),
                f32x8::from(core::array::from_fn::<f32, 8, _>(|i| w[i].y)),
                f32x8::from(core::array::from_fn::<f32, 8, _>(|i| w[i].z)),
            )
        };
        let c8 = Cosines::from_world(lanes(|t| t.0), lanes(|t| t.1), lanes(|t| t.2));
        for (i, t) in triples.iter().enumerate() {
            let c = Cosines::from_world(t.0, t.1, t.2);
            assert_eq!(c.n_dot_v.to_bits(), c8.n_dot_v.lane(i).to_bits());
            assert_eq!(c.n_dot_l.to_bits(), c8.n_dot_l.lane(i).to_bits());
            assert_eq!(c.n_dot_h.to_bits(), c8.n_dot_h.lane(i).to_bits());
            assert_eq!(c.v_dot_h.to_bits(), c8.v_dot_h.lane(i).to_bits());
        }
    }
}

#[test]
fn opposite_directions_and_nan_give_the_documented_edges() {
    let n = V3::new(0.0, 0.6, 0.8);
    let v = V3::new(0.6, 0.0, 0.8);
    let c = Cosines::from_world(n, v, -v);
    assert_eq!((c.n_dot_h, c.v_dot_h), (1.0_f64, 0.0));
    let c = Cosines::from_local(v, -v);
    assert_eq!((c.n_dot_h, c.v_dot_h), (1.0_f64, 0.0));
    for i in 0..3 {
        let mut bad = [0.0, 0.6, 0.8];
        bad[i] = f64::NAN;
        let bad = V3::from(bad);
        // A NaN normal reaches n.v, n.l and n.h (even where v = -l selects n.h = 1).
        let c = Cosines::from_world(bad, v, -v);
        assert!(c.n_dot_v.is_nan() && c.n_dot_l.is_nan() && c.n_dot_h.is_nan());
        // A NaN view direction reaches every cosine but n.l.
        let c = Cosines::from_world(n, bad, v);
        assert!(c.n_dot_v.is_nan() && c.n_dot_h.is_nan() && c.v_dot_h.is_nan());
        assert!(!c.n_dot_l.is_nan());
        // Locally n.l is wi.z: only a NaN z reaches it; any NaN reaches h.
        let c = Cosines::from_local(v, bad);
        assert!(c.n_dot_h.is_nan() && c.v_dot_h.is_nan());
        assert_eq!(c.n_dot_l.is_nan(), i == 2);
    }
}

/// The material from world space (frame rotation, then the local-frame evaluation) against
/// `material::gltf` on cosines formed by world-space dot products: two routes to one value.
#[test]
fn material_world_space_matches_the_dot_product_form() {
    let mut rng = Dirs(17);
    let mut worst = 0.0f64;
    let mut compared = 0;
    for i in 0..50_000 {
        let (n, v, l) = (rng.dir(), rng.dir(), rng.dir());
        let (n, v, l) = (V3::from(n), V3::from(v), V3::from(l));
        // Keep both cosines away from the horizon, where either route is 0 or ill-conditioned.
        if n.dot(v) < 0.05 || n.dot(l) < 0.05 {
            continue;
        }
        let base = V3::new(0.9, 0.6, 0.3);
        let (metallic, roughness) = (f64::from(i % 5) / 4.0, 0.05 + f64::from(i % 7) / 7.0);
        let m = MetallicRoughness::new(base, metallic, roughness).unwrap();
        let sp = ShadingPoint::new(n, v);
        let world = m.eval_world(&sp, l);
        let dots = material::gltf(Cosines::from_world(n, v, l), base, metallic, roughness);
        for (a, b) in [(world.x, dots.x), (world.y, dots.y), (world.z, dots.z)] {
            worst = worst.max((a - b).abs() / b.abs().max(1e-300));
        }
        compared += 1;
    }
    println!("eval_world vs gltf(Cosines::from_world) on {compared} points: max rel {worst:.2e}");
    assert!(compared > 10_000);
    // The two routes round n.h differently (a rotation against a dot product, each within a
    // few 1e-16); D's relative sensitivity to n.h is about 2 / alpha^2 near its peak, 3e5 at the
    // smallest alpha here (0.05^2): a few 1e-11 at most.
    assert!(worst < 1e-10, "{worst:e}");
}

#[test]
fn world_space_sampling_is_the_local_sample_rotated_with_its_pdf() {
    let mut rng = Dirs(19);
    let m = MetallicRoughness::new(V3::new(0.8, 0.5, 0.2), 0.3, 0.4).unwrap();
    let mut worst_pdf = 0.0f64;
    for _ in 0..20_000 {
        let (n, v) = (V3::from(rng.dir()), V3::from(rng.dir()));
        if n.dot(v) <= 0.0 {
            continue;
        }
        let sp = ShadingPoint::new(n, v);
        let (u1, u2) = (rng.unit(), rng.unit());
        let (l, pdf) = m.sample_world(&sp, u1, u2);
        let (wi, pdf_local) = m.sample(sp.wo(), u1, u2);
        assert_eq!(pdf.to_bits(), pdf_local.to_bits());
        assert!((l.length() - 1.0).abs() < 1e-14);
        assert!((n.dot(l) - wi.z).abs() < 1e-14);
        // The pdf of the world-space direction, through the frame's inverse rotation.
        let back = m.pdf_world(&sp, l);
        if pdf > 1e-6 {
            worst_pdf = worst_pdf.max((back - pdf).abs() / pdf);
        }
        let (l2, pdf2, w) = m.sample_weighted_world(&sp, u1, u2);
        assert_eq!((l2, pdf2.to_bits()), (l, pdf.to_bits()));
        let want = m.eval_world(&sp, l) * (n.dot(l).max(0.0) / pdf);
        if pdf > 0.0 {
            assert!(
                (w - want).length() <= 1e-9 * want.length().max(1e-300),
                "{w:?} {want:?}"
            );
        }
    }
    println!("pdf_world(sample_world) vs the sample's pdf: max rel {worst_pdf:.2e}");
    assert!(worst_pdf < 1e-9, "{worst_pdf:e}");
}
