//! The filtered-importance-sampling mip level reproduces hand-computed values of
//! max(0, 0.5 log2(Omega_s / Omega_p) + 1) (Krivanek and Colbert 2008), is finite and
//! non-negative over its whole finite domain, and agrees across f32, f64 and lanes.
#![cfg(feature = "ibl")]

use brdf::Real;
use brdf::ibl::prefilter::mip_level;
use brdf::wide::{f32x8, f64x4};
use core::f64::consts::PI;

#[test]
fn mip_level_matches_hand_computed_values() {
    // w = 256, N = 1024, pdf = 1 / pi (GGX alpha = 0.5 at h = n: D = 1 / (pi alpha^2) = 4 / pi,
    // pdf = D / 4): Omega_s = pi / 1024, Omega_p = 4 pi / (6 * 65536) = pi / 98304, ratio 96,
    // lod = 0.5 log2(96) + 1 = 0.5 (5 + log2 3) + 1 = 4.2924812503605780.
    let lod = mip_level(1.0 / PI, 1024.0, 256.0);
    let hand = 0.5 * (5.0 + 3f64.log2()) + 1.0;
    println!("mip_level(1/pi, 1024, 256) = {lod:.15} (hand {hand:.15})");
    // Three logarithms and a few additions of numbers near 8: a few ULP of 8.
    assert!((lod - hand).abs() < 1e-14, "{lod} vs {hand}");
    // Omega_s = Omega_p gives exactly the bias, 1.
    let (w, n) = (128.0, 64.0);
    let pdf_equal = 6.0 * w * w / (4.0 * PI * n);
    let one = mip_level(pdf_equal, n, w);
    println!("Omega_s = Omega_p: {one:.15}");
    assert!((one - 1.0).abs() < 1e-14);
    // Each factor 4 in pdf lowers the level by one; clamped at 0.
    assert!((mip_level(pdf_equal * 4.0, n, w) - 0.0).abs() < 1e-14);
    assert_eq!(mip_level(pdf_equal * 64.0, n, w), 0.0);
    assert!((mip_level(pdf_equal / 16.0, n, w) - 3.0).abs() < 1e-14);
    // f32 agrees with f64 to f32 rounding of the inputs and logarithms.
    let l32 = mip_level(1.0_f32 / core::f32::consts::PI, 1024.0, 256.0);
    println!("f32: {l32} (f64 {lod})");
    assert!((f64::from(l32) - lod).abs() < 4.0 * 8.0 * f64::from(f32::EPSILON));
}

#[test]
fn mip_level_is_finite_and_non_negative_over_the_finite_domain() {
    let pdfs = [0.0, 1e-300, 1e-30, 1e-3, 1.0, 1e3, 1e30, f64::MAX];
    let counts = [1.0, 2.0, 1e6, 1e30, f64::MAX];
    let sizes = [1.0, 2.0, 4096.0, 1e30, f64::MAX];
    for &p in &pdfs {
        for &n in &counts {
            for &w in &sizes {
                let l = mip_level(p, n, w);
                assert!(l.is_finite() && l >= 0.0, "f64 ({p}, {n}, {w}) -> {l}");
                // f64 values beyond f32's range become f32::MAX (still finite).
                let f = |x: f64| {
                    if x.is_finite() {
                        (x as f32).min(f32::MAX)
                    } else {
                        x as f32
                    }
                };
                let l32 = mip_level(f(p), f(n), f(w));
                assert!(
                    l32.is_finite() && l32 >= 0.0,
                    "f32 ({p}, {n}, {w}) -> {l32}"
                );
            }
        }
    }
    // pdf = 0 is an infinitely coarse level, capped at the largest finite value.
    assert_eq!(mip_level(0.0, 16.0, 64.0), f64::MAX);
    assert_eq!(mip_level(f64::MAX, 16.0, 64.0), 0.0);
}

#[test]
fn mip_level_is_nan_for_nan_or_out_of_domain_input_on_every_type() {
    let bad: [(f64, f64, f64); 9] = [
        (f64::NAN, 16.0, 64.0),
        (f64::INFINITY, 16.0, 64.0),
        (1.0, f64::NAN, 64.0),
        (1.0, 16.0, f64::NAN),
        (-1e-30, 16.0, 64.0),
        (1.0, 0.5, 64.0),
        (1.0, f64::INFINITY, 64.0),
        (1.0, 16.0, 0.5),
        (1.0, 16.0, f64::INFINITY),
    ];
    for (p, n, w) in bad {
        assert!(mip_level(p, n, w).is_nan(), "f64 ({p}, {n}, {w})");
        assert!(
            mip_level(p as f32, n as f32, w as f32).is_nan(),
            "f32 ({p}, {n}, {w})"
        );
        let l8 = mip_level(f32x8::from_f64(p), f32x8::from_f64(n), f32x8::from_f64(w));
        assert!((0..8).all(|i| l8.lane(i).is_nan()), "f32x8 ({p}, {n}, {w})");
        let l4 = mip_level(f64x4::from_f64(p), f64x4::from_f64(n), f64x4::from_f64(w));
        assert!((0..4).all(|i| l4.lane(i).is_nan()), "f64x4 ({p}, {n}, {w})");
    }
}

#[test]
fn mip_level_lanes_equal_scalars() {
    let pdfs = [0.0, 1e-6, 0.01, 0.3, 1.0, 7.0, 1e4, 1e9];
    let p8 = f32x8::from_fn(|i| pdfs[i] as f32);
    let l8 = mip_level(p8, f32x8::from_f64(256.0), f32x8::from_f64(512.0));
    for (i, &p) in pdfs.iter().enumerate() {
        assert_eq!(
            l8.lane(i),
            mip_level(p as f32, 256.0, 512.0),
            "f32x8 lane {i}"
        );
    }
    let p4 = f64x4::from_fn(|i| pdfs[i + 2]);
    let l4 = mip_level(p4, f64x4::from_f64(256.0), f64x4::from_f64(512.0));
    for i in 0..4 {
        assert_eq!(
            l4.lane(i),
            mip_level(pdfs[i + 2], 256.0, 512.0),
            "f64x4 lane {i}"
        );
    }
}
