//! Normalization factors of the Phong family against independent routes:
//! - the exact Blinn-Phong factor c(n) = (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) against a 1-D
//!   quadrature of its defining integral (albedo 1 at normal incidence);
//! - the "Real-Time Rendering" approximation (n + 8) / (8 pi) against c(n) over n in [0, 10^4]:
//!   its maximum relative error, where it occurs, and its sign;
//! - the NDF normalization (n + 2) / (2 pi) beside the BRDF one, so the two are not confused;
//! - normalized Phong against classic Phong at the peak: dimmer for wide lobes, brighter for
//!   tight ones, crossing at n = 2 pi - 2.
#![cfg(feature = "phong")]

use brdf::phong;
use core::f64::consts::PI;

/// The albedo at normal incidence of the unnormalized lobe cos^n(theta_h), by composite
/// Simpson over theta_l in [0, pi/2]: 2 pi int cos^n(theta / 2) cos(theta) sin(theta) d theta.
/// 2^17 intervals put 3600 samples across the half-width sqrt(8 / n) = 0.028 rad of the
/// narrowest lobe (n = 10^4); Simpson's error there is below 1e-12 relative.
fn blinn_phong_albedo_unnormalized(n: f64) -> f64 {
    let m = 1 << 17;
    let h = (PI / 2.0) / m as f64;
    let g = |t: f64| (t / 2.0).cos().powf(n) * t.cos() * t.sin();
    let mut s = g(0.0) + g(PI / 2.0);
    for i in 1..m {
        s += g(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    2.0 * PI * s * h / 3.0
}

#[test]
fn exact_blinn_phong_normalization_matches_its_defining_integral() {
    let mut worst: f64 = 0.0;
    for n in [
        0.0, 0.25, 1.0, 2.17, 3.0, 8.76, 16.0, 64.0, 333.3, 1000.0, 4096.0, 10000.0,
    ] {
        let by_quadrature = 1.0 / blinn_phong_albedo_unnormalized(n);
        let closed = phong::blinn_phong_normalization_exact(n);
        let rel = (closed / by_quadrature - 1.0).abs();
        worst = worst.max(rel);
        println!(
            "n = {n:>8}: c(n) = {closed:.12e}, quadrature {by_quadrature:.12e}, rel {rel:.1e}"
        );
        // Simpson at this resolution is good to ~1e-12; 1e-9 separates that from any error
        // in the formula (a wrong power of 2 or a missing factor is O(1)).
        assert!(rel < 1e-9, "n = {n}: {closed} vs {by_quadrature}");
    }
    println!(
        "exact Blinn-Phong normalization vs quadrature: worst relative difference {worst:.1e}"
    );
}

/// Dense sweep of [0, 10^4]: step 1e-4 up to 20 (the maximum lies there), then geometric.
fn sweep() -> impl Iterator<Item = f64> {
    let fine = (0..=200_000).map(|i| i as f64 * 1e-4);
    let coarse = (1..=100_000).map(|i| 20.0 * (500.0_f64).powf(i as f64 / 100_000.0));
    fine.chain(coarse)
}

#[test]
fn approximate_blinn_phong_normalization_error_is_measured() {
    let (mut max_rel, mut at, mut min_rel) = (f64::NEG_INFINITY, 0.0, f64::INFINITY);
    for n in sweep() {
        let rel = phong::blinn_phong_normalization_approx(n)
            / phong::blinn_phong_normalization_exact(n)
            - 1.0;
        if rel > max_rel {
            (max_rel, at) = (rel, n);
        }
        min_rel = min_rel.min(rel);
    }
    let end = phong::blinn_phong_normalization_approx(1e4_f64)
        / phong::blinn_phong_normalization_exact(1e4)
        - 1.0;
    println!(
        "(n + 8) / (8 pi) vs exact over n in [0, 1e4]: max relative error {:.4}% at n = {at:.4}; \
         min {min_rel:.1e} (never below exact); {:.4}% at n = 1e4 (2 / (n + 6) = {:.4}%)",
        max_rel * 100.0,
        end * 100.0,
        2.0 / (1e4 + 6.0) * 100.0
    );
    // The values the docs quote: 7.52% at n = 8.76, never below the exact factor (so the
    // approximation always adds energy), 0.02% at n = 10^4.
    assert!((max_rel - 0.0752).abs() < 5e-5, "{max_rel}");
    assert!((at - 8.76).abs() < 0.01, "{at}");
    assert!(min_rel >= -1e-15, "{min_rel}");
    assert!((end - 2.0 / (1e4 + 6.0)).abs() < 1e-7, "{end}");
}

#[test]
fn ndf_and_brdf_normalizations_differ() {
    println!(
        "{:>8} {:>14} {:>14} {:>14} {:>12}",
        "n", "c exact", "(n+8)/(8pi)", "(n+2)/(2pi)", "ndf/c exact"
    );
    let mut last = 0.0;
    for n in [0.0, 1.0, 4.0, 10.0, 100.0, 1000.0, 10000.0] {
        let (c, a, d) = (
            phong::blinn_phong_normalization_exact(n),
            phong::blinn_phong_normalization_approx(n),
            phong::phong_normalization(n),
        );
        println!("{n:>8} {c:>14.6} {a:>14.6} {d:>14.6} {:>12.6}", d / c);
        // The NDF factor makes D(m) cos(theta_m) integrate to 1; used as a BRDF factor it
        // gives albedo d / c at normal incidence: 1 at n = 0 (both are 1 / pi), rising to 4
        // (the 4 of the half-vector Jacobian 1 / (4 v.h)).
        assert!(d / c >= 1.0 && d / c < 4.0, "n = {n}");
        assert!(d / c > last, "n = {n}: not increasing");
        last = d / c;
    }
    let large = 1e4_f64;
    let ratio = phong::phong_normalization(large) / phong::blinn_phong_normalization_exact(large);
    assert!(ratio > 3.99, "{ratio}");
}

#[test]
fn wide_normalized_lobe_is_dimmer_and_tight_one_brighter_than_classic_at_its_peak() {
    let ks = 0.9;
    // The peak: viewer and light along the normal, so n.v = n.l = r.l = 1.
    let peak = |n: f64| {
        (
            phong::normalized(1.0, 1.0, 1.0, ks, n),
            phong::classic(1.0, 1.0, 1.0, ks, n),
        )
    };
    for n in [0.0, 1.0, 2.0, 4.0, 4.28, 4.29, 5.0, 10.0, 100.0, 10000.0] {
        let (p, c) = peak(n);
        println!(
            "n = {n:>7}: normalized peak {p:.6}, classic peak {c:.6}, ratio {:.4}",
            p / c
        );
        assert_eq!(p < c, n < 2.0 * PI - 2.0, "n = {n}: {p} vs {c}");
    }
    // Bisection for the crossover; the factor (n + 2) / (2 pi) is 1 at n = 2 pi - 2.
    let (mut lo, mut hi) = (0.0, 100.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        let (p, c) = peak(mid);
        if p < c {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    println!(
        "crossover at n = {lo:.12} (2 pi - 2 = {:.12})",
        2.0 * PI - 2.0
    );
    assert!((lo - (2.0 * PI - 2.0)).abs() < 1e-12, "{lo}");
}
