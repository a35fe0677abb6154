//! The working-precision tier of the material (`metallic_roughness_fast`, `gltf_fast`,
//! `MetallicRoughness::eval_fast`) against the exact tier on the same inputs: within the
//! documented 12 ULP (relative 7e-7 in f32, 1.4e-15 in f64) per channel on f32 and f64, lanes equal to scalars bit for bit, and the
//! exact tier's edges and bad input (horizon zeros, NaN parameters) unchanged.
#![cfg(feature = "material")]

use brdf::Cosines;
use brdf::material::{self, DiffuseCoupling, MetallicRoughness};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

use crate::common::Rng;

/// The bounds the docs of `metallic_roughness_fast` state: in ULP of the exact tier's result,
/// and relative (f32, f64).
const BOUND_ULP: f64 = 12.0;
const BOUND_REL: [f64; 2] = [7e-7, 1.4e-15];

const COUPLINGS: [DiffuseCoupling; 3] = [
    DiffuseCoupling::Gltf,
    DiffuseCoupling::OneMinusF,
    DiffuseCoupling::Additive,
];

/// Distance in ULP of `x` from `r` for the float type with `mantissa` bits, in units of the
/// spacing at |r| (the smallest normal's spacing below it).
fn ulp(x: f64, r: f64, mantissa: i32, min_exp: i32) -> f64 {
    if x == r {
        return 0.0;
    }
    let e = if r == 0.0 {
        min_exp
    } else {
        (libm::log2(r.abs()).floor() as i32).max(min_exp)
    };
    (x - r).abs() / libm::exp2(f64::from(e - mantissa + 1))
}

/// |x - r| / |r| (0 where both are 0).
fn rel(x: f64, r: f64) -> f64 {
    if x == r { 0.0 } else { (x - r).abs() / r.abs() }
}

/// Cosines of a view and a light direction: n.v, n.l, n.h, v.h (the half vector's in f64).
fn cosines_of(v: V3<f64>, l: V3<f64>) -> [f64; 4] {
    let h = (v + l).normalize();
    [v.z, l.z, h.z, v.dot(h)]
}

/// Inputs: random directions (n.v and n.l from 1e-6 to 1, log-uniform half the time),
/// base colours, metallic and roughness including 0 and 1, and F0 including 0 and 1.
fn inputs(n: usize) -> Vec<([f64; 4], [f64; 6])> {
    let mut rng = Rng(0xfa57_7135);
    let dir = crate::common::random_dir;
    let pick = |rng: &mut Rng| match (rng.next_f64() * 8.0) as u32 {
        0 => 0.0,
        1 => 1.0,
        _ => rng.next_f64(),
    };
    (0..n)
        .map(|_| {
            let (v, l) = (dir(&mut rng), dir(&mut rng));
            let p = [
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
            ];
            (cosines_of(v, l), p)
        })
        .collect()
}

fn eval<T: Real>(c: [f64; 4], p: [f64; 6], k: DiffuseCoupling, fast: bool) -> V3<T> {
    let s = T::splat;
    let cos = Cosines {
        n_dot_v: s(c[0]),
        n_dot_l: s(c[1]),
        n_dot_h: s(c[2]),
        v_dot_h: s(c[3]),
    };
    let base = V3::new(s(p[0]), s(p[1]), s(p[2]));
    if fast {
        material::metallic_roughness_fast(cos, base, s(p[3]), s(p[4]), s(p[5]), k)
    } else {
        material::metallic_roughness(cos, base, s(p[3]), s(p[4]), s(p[5]), k)
    }
}

#[test]
fn fast_tier_within_its_bound_of_the_exact_tier() {
    let n = std::env::var("BRDF_FAST_TIER_POINTS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200_000);
    let pts = inputs(n);
    let (mut worst32, mut worst64, mut rel32, mut rel64) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (c, p) in &pts {
        for k in COUPLINGS {
            let (e32, f32_) = (eval::<f32>(*c, *p, k, false), eval::<f32>(*c, *p, k, true));
            let (e64, f64_) = (eval::<f64>(*c, *p, k, false), eval::<f64>(*c, *p, k, true));
            for (x, r) in f32_.to_array().into_iter().zip(e32.to_array()) {
                assert!(x.is_finite() && r.is_finite(), "{c:?} {p:?} {k:?}");
                worst32 = worst32.max(ulp(f64::from(x), f64::from(r), 24, -126));
                rel32 = rel32.max(rel(f64::from(x), f64::from(r)));
            }
            for (x, r) in f64_.to_array().into_iter().zip(e64.to_array()) {
                worst64 = worst64.max(ulp(x, r, 53, -1022));
                rel64 = rel64.max(rel(x, r));
            }
        }
    }
    println!(
        "fast tier against the exact tier over {n} points x 3 couplings: f32 {worst32:.2} ULP \
         (relative {rel32:.2e}), f64 {worst64:.2} ULP (relative {rel64:.2e})"
    );
    assert!(
        worst32 <= BOUND_ULP && rel32 <= BOUND_REL[0],
        "f32: {worst32} ULP, {rel32:e}"
    );
    assert!(
        worst64 <= BOUND_ULP && rel64 <= BOUND_REL[1],
        "f64: {worst64} ULP, {rel64:e}"
    );
}

#[test]
fn gltf_fast_is_metallic_roughness_fast_with_gltfs_parameters() {
    for (c, p) in inputs(2_000) {
        let cos = Cosines {
            n_dot_v: c[0],
            n_dot_l: c[1],
            n_dot_h: c[2],
            v_dot_h: c[3],
        };
        let base = V3::new(p[0], p[1], p[2]);
        let a = material::gltf_fast(cos, base, p[3], p[4]);
        let b = material::metallic_roughness_fast(
            cos,
            base,
            p[3],
            p[4],
            material::GLTF_DIELECTRIC_F0,
            DiffuseCoupling::Gltf,
        );
        assert_eq!(
            a.to_array().map(f64::to_bits),
            b.to_array().map(f64::to_bits)
        );
    }
}

#[test]
fn lanes_equal_scalars_bit_for_bit() {
    let pts = inputs(4_000);
    for chunk in pts.chunks_exact(8) {
        for k in COUPLINGS {
            let cos8 = Cosines {
                n_dot_v: f32x8::new(core::array::from_fn(|i| chunk[i].0[0] as f32)),
                n_dot_l: f32x8::new(core::array::from_fn(|i| chunk[i].0[1] as f32)),
                n_dot_h: f32x8::new(core::array::from_fn(|i| chunk[i].0[2] as f32)),
                v_dot_h: f32x8::new(core::array::from_fn(|i| chunk[i].0[3] as f32)),
            };
            let par8 = |j: usize| f32x8::new(core::array::from_fn(|i| chunk[i].1[j] as f32));
            let out8 = material::metallic_roughness_fast(
                cos8,
                V3::new(par8(0), par8(1), par8(2)),
                par8(3),
                par8(4),
                par8(5),
                k,
            );
            for (i, (c, p)) in chunk.iter().enumerate() {
                let s = eval::<f32>(*c, *p, k, true);
                assert_eq!(
                    out8.lane(i).to_array().map(f32::to_bits),
                    s.to_array().map(f32::to_bits),
                    "f32x8 lane {i}: {c:?} {p:?} {k:?}"
                );
            }
        }
    }
    for chunk in pts.chunks_exact(4) {
        for k in COUPLINGS {
            let cos4 = |j: usize| f64x4::new(core::array::from_fn(|i| chunk[i].0[j]));
            let par4 = |j: usize| f64x4::new(core::array::from_fn(|i| chunk[i].1[j]));
            let out4 = material::metallic_roughness_fast(
                Cosines {
                    n_dot_v: cos4(0),
                    n_dot_l: cos4(1),
                    n_dot_h: cos4(2),
                    v_dot_h: cos4(3),
                },
                V3::new(par4(0), par4(1), par4(2)),
                par4(3),
                par4(4),
                par4(5),
                k,
            );
            for (i, (c, p)) in chunk.iter().enumerate() {
                let s = eval::<f64>(*c, *p, k, true);
                assert_eq!(
                    out4.lane(i).to_array().map(f64::to_bits),
                    s.to_array().map(f64::to_bits),
                    "f64x4 lane {i}: {c:?} {p:?} {k:?}"
                );
            }
        }
    }
}

#[test]
fn eval_fast_keeps_the_exact_tiers_edges_and_bound() {
    let m = MetallicRoughness::new(V3::new(0.9f32, 0.6, 0.3), 0.5, 0.5).unwrap();
    let up = V3::new(0.0f32, 0.6, 0.8);
    // Below either horizon: 0, as the exact tier.
    let below = V3::new(0.0f32, 0.6, -0.8);
    assert_eq!(m.eval_fast(up, below).to_array(), [0.0; 3]);
    assert_eq!(m.eval_fast(below, up).to_array(), [0.0; 3]);
    // NaN or infinite directions: NaN, as the exact tier.
    for bad in [
        V3::new(f32::NAN, 0.0, 1.0),
        V3::new(0.0, f32::INFINITY, 1.0),
    ] {
        assert!(m.eval_fast(bad, up).to_array().iter().all(|x| x.is_nan()));
        assert!(m.eval(bad, up).to_array().iter().all(|x| x.is_nan()));
    }
    // Against eval on a ring of light directions.
    let mut worst = 0.0f64;
    for i in 0..2000 {
        let t = 1.5 * i as f32 / 2000.0;
        let wi = V3::new(t.sin() * 0.8, -t.sin() * 0.6, t.cos());
        let (a, b) = (m.eval_fast(up, wi), m.eval(up, wi));
        for (x, r) in a.to_array().into_iter().zip(b.to_array()) {
            worst = worst.max(ulp(f64::from(x), f64::from(r), 24, -126));
        }
    }
    assert!(worst <= BOUND_ULP, "{worst} ULP");
    // NaN parameters reaching the free function give NaN.
    let c = Cosines {
        n_dot_v: 0.5f32,
        n_dot_l: 0.5,
        n_dot_h: 0.9,
        v_dot_h: 0.8,
    };
    let f = material::gltf_fast(c, V3::splat(0.5), f32::NAN, 0.5);
    assert!(f.to_array().iter().all(|x| x.is_nan()));
    let f = material::gltf_fast(c, V3::splat(0.5), 0.5, 1.5);
    assert!(f.to_array().iter().all(|x| x.is_nan()));
}
