//! The prefilter weights are normalised: a constant environment prefilters to itself (to
//! rounding) for every alpha and sample count, and `fill`, `samples` and `sample` give the
//! same bits.
#![cfg(feature = "ibl")]

use brdf::ibl::prefilter::{self, PrefilterSample};

const ALPHAS: [f64; 6] = [0.0, 0.05, 0.25, 0.5, 1.0, 10.0];

#[test]
fn prefilter_of_a_constant_environment_is_the_constant() {
    let mut buf = vec![PrefilterSample::default(); 4096];
    let mut worst = 0.0_f64;
    for &alpha in &ALPHAS {
        for n in [1usize, 2, 7, 64, 1024, 4096] {
            let out = &mut buf[..n];
            let total = prefilter::fill(out, alpha);
            assert!(total > 0.0, "alpha {alpha} n {n}: total weight {total}");
            let l = 3.7;
            let sum: f64 = out.iter().map(|s| l * s.weight).sum();
            let rel = (sum / total - l).abs() / l;
            worst = worst.max(rel);
            // n additions of l w_i versus n additions of w_i: each rounding is 2^-53
            // relative, so 4 n ULP bounds the difference; measured far below.
            assert!(
                rel <= 4.0 * n as f64 * f64::EPSILON,
                "alpha {alpha} n {n}: {rel:e}"
            );
            for s in out.iter() {
                assert!(s.weight >= 0.0 && s.weight <= 1.0 && s.pdf >= 0.0);
                assert!((s.dir.length() - 1.0).abs() < 1e-12, "{:?}", s.dir);
                assert_eq!(s.weight, s.dir.z.max(0.0));
            }
        }
    }
    println!("constant environment: max relative error {worst:.2e}");
}

#[test]
fn fill_iterator_and_sample_agree_bit_for_bit() {
    for &alpha in &ALPHAS {
        let mut out = [PrefilterSample::default(); 300];
        let total = prefilter::fill(&mut out, alpha);
        let mut sum = 0.0;
        for (i, (a, b)) in out.iter().zip(prefilter::samples(300, alpha)).enumerate() {
            assert_eq!(*a, b);
            assert_eq!(*a, prefilter::sample(i as u32, 300, alpha));
            sum += b.weight;
        }
        assert_eq!(sum, total);
        // Sample 0 is the mirror direction with weight 1.
        assert_eq!(out[0].dir.z, 1.0);
        assert_eq!(out[0].weight, 1.0);
    }
    assert!(prefilter::sample(5, 5, 0.3_f64).dir.x.is_nan());
}

#[test]
fn below_horizon_samples_have_weight_zero_and_exist_for_rough_lobes() {
    let n = 1024;
    let below = prefilter::samples(n, 0.5_f64)
        .filter(|s| s.dir.z <= 0.0)
        .inspect(|s| assert_eq!(s.weight, 0.0))
        .count();
    // GGX puts P(theta_h > 45 deg) = alpha^2 / (1 + alpha^2) = 0.2 of its half vectors past
    // 45 degrees, and those reflect below the horizon.
    let frac = below as f64 / f64::from(n);
    println!("alpha 0.5: {frac:.4} of the samples below the horizon (expected 0.2)");
    assert!((frac - 0.2).abs() < 0.01, "{frac}");
}
