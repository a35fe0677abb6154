//! The working-precision rough conductor (`ggx_conductor_rgb_fast`) against the exact tier
//! (`ggx_conductor_rgb`) on the same inputs: within its documented relative bound per channel
//! on f32 and f64 where F is well conditioned (k >= 0.1 or eta >= 1: no critical angle), lanes
//! equal to scalars bit for bit, the exact tier's edges and bad input unchanged.
#![cfg(all(feature = "ggx", feature = "cook-torrance"))]

use brdf::cook_torrance;
use brdf::fresnel::ComplexIor;
use brdf::microfacet::Alpha;
use brdf::wide::{f32x8, f64x4};
use brdf::{Cosines, Real, V3};

use crate::common::Rng;
use crate::fast_check::{random_dir, within_bound};

/// The relative bounds `ggx_conductor_rgb_fast`'s docs state (f32, f64).
const BOUND_REL: [f64; 2] = [1.5e-6, 2.6e-15];

/// Random cosines (n.v, n.l from 1e-6 to 1, log-uniform half the time, n.h and v.h of the
/// same directions), alpha from ALPHA_MIN to 1, and (eta, k) per channel: measured metals
/// half the time, log-uniform over [1e-3, 1e3] otherwise, kept where k >= 0.1 or eta >= 1.
fn inputs(n: usize) -> Vec<([f64; 5], [[f64; 3]; 2])> {
    let mut rng = Rng(0xc0d0_c7a5);
    const METALS: [([f64; 3], [f64; 3]); 3] = [
        ([0.18, 0.42, 1.37], [3.42, 2.35, 1.77]), // gold
        ([2.76, 2.54, 2.27], [3.84, 3.43, 3.04]), // iron
        ([1.66, 0.88, 0.52], [9.22, 6.27, 4.84]), // aluminium
    ];
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (v, l) = (random_dir(&mut rng), random_dir(&mut rng));
        let h = (v + l).normalize();
        let alpha = libm::pow(10.0, -4.0 * rng.next_f64());
        let ior = if rng.next_f64() < 0.5 {
            let m = METALS[(rng.next_f64() * 3.0) as usize % 3];
            [m.0, m.1]
        } else {
            let mut e = [0.0; 3];
            let mut k = [0.0; 3];
            for i in 0..3 {
                e[i] = libm::pow(10.0, 6.0 * rng.next_f64() - 3.0);
                k[i] = libm::pow(10.0, 6.0 * rng.next_f64() - 3.0);
            }
            [e, k]
        };
        if (0..3).all(|i| ior[1][i] >= 0.1 || ior[0][i] >= 1.0) {
            out.push(([v.z, l.z, h.z, v.dot(h), alpha], ior));
        }
    }
    out
}

fn eval<T: Real>(x: [f64; 5], ior: [[f64; 3]; 2], fast: bool) -> V3<T> {
    let s = T::splat;
    let c = Cosines {
        n_dot_v: s(x[0]),
        n_dot_l: s(x[1]),
        n_dot_h: s(x[2]),
        v_dot_h: s(x[3]),
    };
    let ior = ComplexIor {
        eta: V3::new(s(ior[0][0]), s(ior[0][1]), s(ior[0][2])),
        k: V3::new(s(ior[1][0]), s(ior[1][1]), s(ior[1][2])),
    };
    if fast {
        cook_torrance::ggx_conductor_rgb_fast(c, Alpha(s(x[4])), ior)
    } else {
        cook_torrance::ggx_conductor_rgb(c, Alpha(s(x[4])), ior)
    }
}

#[test]
fn fast_tier_within_its_bound_of_the_exact_tier() {
    within_bound(
        "rough conductor",
        "",
        BOUND_REL,
        inputs,
        |&(x, ior), worst| {
            let (a, b) = (eval::<f32>(x, ior, true), eval::<f32>(x, ior, false));
            for (p, q) in a.to_array().into_iter().zip(b.to_array()) {
                assert!(p.is_finite() && q.is_finite(), "{x:?} {ior:?}");
                worst.f32(p, q);
            }
            let (a, b) = (eval::<f64>(x, ior, true), eval::<f64>(x, ior, false));
            for (p, q) in a.to_array().into_iter().zip(b.to_array()) {
                worst.f64(p, q);
            }
        },
    );
}

#[test]
fn lanes_equal_scalars_bit_for_bit() {
    let pts = inputs(4_000);
    for chunk in pts.chunks_exact(8) {
        let c8 = |j: usize| f32x8::new(core::array::from_fn(|i| chunk[i].0[j] as f32));
        let i8 =
            |a: usize, ch: usize| f32x8::new(core::array::from_fn(|i| chunk[i].1[a][ch] as f32));
        let out = cook_torrance::ggx_conductor_rgb_fast(
            Cosines {
                n_dot_v: c8(0),
                n_dot_l: c8(1),
                n_dot_h: c8(2),
                v_dot_h: c8(3),
            },
            Alpha(c8(4)),
            ComplexIor {
                eta: V3::new(i8(0, 0), i8(0, 1), i8(0, 2)),
                k: V3::new(i8(1, 0), i8(1, 1), i8(1, 2)),
            },
        );
        for (i, &(x, ior)) in chunk.iter().enumerate() {
            assert_eq!(
                out.lane(i).to_array().map(f32::to_bits),
                eval::<f32>(x, ior, true).to_array().map(f32::to_bits)
            );
        }
    }
    for chunk in pts.chunks_exact(4) {
        let c4 = |j: usize| f64x4::new(core::array::from_fn(|i| chunk[i].0[j]));
        let i4 = |a: usize, ch: usize| f64x4::new(core::array::from_fn(|i| chunk[i].1[a][ch]));
        let out = cook_torrance::ggx_conductor_rgb_fast(
            Cosines {
                n_dot_v: c4(0),
                n_dot_l: c4(1),
                n_dot_h: c4(2),
                v_dot_h: c4(3),
            },
            Alpha(c4(4)),
            ComplexIor {
                eta: V3::new(i4(0, 0), i4(0, 1), i4(0, 2)),
                k: V3::new(i4(1, 0), i4(1, 1), i4(1, 2)),
            },
        );
        for (i, &(x, ior)) in chunk.iter().enumerate() {
            assert_eq!(
                out.lane(i).to_array().map(f64::to_bits),
                eval::<f64>(x, ior, true).to_array().map(f64::to_bits)
            );
        }
    }
}

#[test]
fn edges_and_bad_input_as_the_exact_tier() {
    let gold = ComplexIor {
        eta: V3::new(0.18f32, 0.42, 1.37),
        k: V3::new(3.42, 2.35, 1.77),
    };
    let c = Cosines {
        n_dot_v: 0.8f32,
        n_dot_l: 0.7,
        n_dot_h: 0.95,
        v_dot_h: 0.9,
    };
    let f = |c: Cosines<f32>, a: f32, ior: ComplexIor<V3<f32>>| {
        (
            cook_torrance::ggx_conductor_rgb_fast(c, Alpha(a), ior).to_array(),
            cook_torrance::ggx_conductor_rgb(c, Alpha(a), ior).to_array(),
        )
    };
    // Below the horizon: 0.
    let (a, b) = f(Cosines { n_dot_l: -0.1, ..c }, 0.3, gold);
    assert_eq!(a, [0.0; 3]);
    assert_eq!(b, [0.0; 3]);
    // NaN anywhere: NaN in every channel (cosines, alpha) or in its own channel (eta, k).
    for bad in [
        Cosines {
            n_dot_v: f32::NAN,
            ..c
        },
        Cosines {
            n_dot_h: f32::NAN,
            ..c
        },
        Cosines {
            v_dot_h: f32::NAN,
            ..c
        },
    ] {
        let (a, b) = f(bad, 0.3, gold);
        assert!(
            a.iter().all(|x| x.is_nan()) && b.iter().all(|x| x.is_nan()),
            "{bad:?}"
        );
    }
    for alpha in [f32::NAN, -0.1, f32::INFINITY] {
        let (a, b) = f(c, alpha, gold);
        assert!(
            a.iter().all(|x| x.is_nan()) && b.iter().all(|x| x.is_nan()),
            "{alpha}"
        );
    }
    let bad_k = ComplexIor {
        k: V3::new(f32::NAN, 2.35, 1.77),
        ..gold
    };
    let (a, b) = f(c, 0.3, bad_k);
    assert!(a[0].is_nan() && b[0].is_nan() && a[1].is_finite() && b[1].is_finite());
    // Grazing cosines at alpha's floor: finite, capped.
    let g = Cosines {
        n_dot_v: 1e-38f32,
        n_dot_l: 1e-38,
        n_dot_h: 1.0,
        v_dot_h: 1.0,
    };
    let (a, _) = f(g, 0.0, gold);
    assert!(a.iter().all(|x| x.is_finite()));
}
