//! The working-precision rough dielectric reflection (`ggx_dielectric_fast`) against the exact
//! tier (`ggx_dielectric`) on the same inputs: within its documented relative bound on f32
//! and f64 for eta >= 1 (no critical angle), finite and non-negative for eta < 1, lanes equal
//! to scalars bit for bit.
#![cfg(all(feature = "ggx", feature = "cook-torrance"))]

use brdf::cook_torrance;
use brdf::microfacet::Alpha;
use brdf::wide::{f32x8, f64x4};
use brdf::{Cosines, Real};

use crate::common::Rng;
use crate::fast_check::{random_dir, within_bound};

/// The relative bounds `ggx_dielectric_fast`'s docs state (f32, f64).
const BOUND_REL: [f64; 2] = [2.5e-6, 4e-15];

/// Random cosines (n.v, n.l from 1e-6 to 1, log-uniform half the time, n.h and v.h of the
/// same directions), alpha from 1e-4 to 1, eta log-uniform over [1e-3, 1e3] and within 1e-6
/// of 1.
fn inputs(n: usize) -> Vec<[f64; 6]> {
    let mut rng = Rng(0xd1e1_ec7c);
    (0..n)
        .map(|_| {
            let (v, l) = (random_dir(&mut rng), random_dir(&mut rng));
            let h = (v + l).normalize();
            let alpha = libm::pow(10.0, -4.0 * rng.next_f64());
            let eta = if rng.next_f64() < 0.8 {
                libm::pow(10.0, 6.0 * rng.next_f64() - 3.0)
            } else {
                1.0 + 1e-6 * (2.0 * rng.next_f64() - 1.0)
            };
            [v.z, l.z, h.z, v.dot(h), alpha, eta]
        })
        .collect()
}

fn eval<T: Real>(x: [f64; 6], fast: bool) -> T {
    let s = T::splat;
    let c = Cosines {
        n_dot_v: s(x[0]),
        n_dot_l: s(x[1]),
        n_dot_h: s(x[2]),
        v_dot_h: s(x[3]),
    };
    if fast {
        cook_torrance::ggx_dielectric_fast(c, Alpha(s(x[4])), s(x[5]))
    } else {
        cook_torrance::ggx_dielectric(c, Alpha(s(x[4])), s(x[5]))
    }
}

#[test]
fn fast_tier_within_its_bound_of_the_exact_tier() {
    within_bound(
        "rough dielectric",
        " (eta >= 1)",
        BOUND_REL,
        inputs,
        |&x, worst| {
            let (p, q) = (eval::<f32>(x, true), eval::<f32>(x, false));
            let (p64, q64) = (eval::<f64>(x, true), eval::<f64>(x, false));
            assert!(
                p.is_finite() && p >= 0.0 && p64.is_finite() && p64 >= 0.0,
                "{x:?}"
            );
            if x[5] < 1.0 && (x[5] as f32) < 1.0 {
                return;
            }
            worst.f32(p, q);
            worst.f64(p64, q64);
        },
    );
}

#[test]
fn lanes_equal_scalars_bit_for_bit() {
    let pts = inputs(4096);
    for chunk in pts.chunks(8) {
        let lane =
            |k: usize| f32x8::from(core::array::from_fn::<f32, 8, _>(|i| chunk[i][k] as f32));
        let c = Cosines {
            n_dot_v: lane(0),
            n_dot_l: lane(1),
            n_dot_h: lane(2),
            v_dot_h: lane(3),
        };
        let out = cook_torrance::ggx_dielectric_fast(c, Alpha(lane(4)), lane(5)).to_array();
        for (i, x) in chunk.iter().enumerate() {
            assert_eq!(out[i].to_bits(), eval::<f32>(*x, true).to_bits(), "{x:?}");
        }
    }
    for chunk in pts.chunks(4) {
        let lane = |k: usize| f64x4::from(core::array::from_fn::<f64, 4, _>(|i| chunk[i][k]));
        let c = Cosines {
            n_dot_v: lane(0),
            n_dot_l: lane(1),
            n_dot_h: lane(2),
            v_dot_h: lane(3),
        };
        let out = cook_torrance::ggx_dielectric_fast(c, Alpha(lane(4)), lane(5)).to_array();
        for (i, x) in chunk.iter().enumerate() {
            assert_eq!(out[i].to_bits(), eval::<f64>(*x, true).to_bits(), "{x:?}");
        }
    }
}
