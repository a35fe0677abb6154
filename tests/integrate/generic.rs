//! The `_f32` integrators (f32 kernels over `V3<f32>`) give the estimates of their f64 /
//! `V3<f64>` twins up to the kernel's own f32 rounding, and both match the closed forms: one
//! kernel, written once over `V3<T>`, integrated through both entry points.
#![cfg(feature = "integrate")]

use brdf::integrate::{self, Config, Estimate};
use brdf::{Real, V3};
use core::f64::consts::PI;

/// A deliberately non-reciprocal, direction-asymmetric BRDF with a closed-form albedo:
/// f(wo, wi) = (1 + wo.x / 2) 5 / (2 pi) max(0, wi.z)^3, so
/// rho(wo) = (1 + wo.x / 2) 5 / (2 pi) integral cos^4 dw = 1 + wo.x / 2.
/// Swapping wo and wi, or dropping the cosine, changes the integral.
fn tilted<T: Real>(wo: V3<T>, wi: V3<T>) -> T {
    let k = (T::ONE + T::HALF * wo.x) * T::splat(5.0 / (2.0 * PI));
    let c = wi.z.max(T::ZERO);
    k * c * c * c
}

/// GGX NDF, written in the cancellation-free form alpha^2 / (pi (alpha^2 z^2 + x^2 + y^2)^2)
/// so that f32 keeps full relative accuracy at the peak.
fn ggx_d<T: Real>(m: V3<T>, alpha: T) -> T {
    let a2 = alpha * alpha;
    let t = a2 * m.z * m.z + m.x * m.x + m.y * m.y;
    a2 * T::FRAC_1_PI / (t * t)
}

/// Smith G1 for GGX: 2 / (1 + sqrt(1 + alpha^2 tan^2)), and 0 where wo.m <= 0.
fn ggx_g1<T: Real>(wo: V3<T>, m: V3<T>, alpha: T) -> T {
    let tan2 = (wo.x * wo.x + wo.y * wo.y) / (wo.z * wo.z);
    let g = T::TWO / (T::ONE + (T::ONE + alpha * alpha * tan2).sqrt());
    T::select(wo.dot(m).simd_gt(T::ZERO), g, T::ZERO)
}

fn report(name: &str, e64: Estimate, e32: Estimate, exact: f64) -> f64 {
    let rel = (e32.value - e64.value).abs() / e64.value.abs();
    println!(
        "{name:<34} f64 {:.10} (err est {:.1e}, {} evals)  f32 {:.10} ({} evals)  exact {exact:.10}  |f32-f64|/f64 = {rel:.2e}",
        e64.value, e64.error, e64.evaluations, e32.value, e32.evaluations
    );
    rel
}

// The f32 kernels here are a handful of roundings deep (relative error a few 1e-7 per
// evaluation, unbiased in sign), so the integrals agree to ~1e-6; 1e-5 leaves a margin of
// ten. The closed forms are met to the integrator's documented accuracy (1e-5 absolute on
// smooth integrands, 1e-3 relative on peaked lobes).
const F32_ROUNDING: f64 = 1e-5;

#[test]
fn f32_directional_albedo_matches_f64_and_the_closed_form() {
    for theta_o in [0.0_f64, 0.4, 0.9, 1.3, 1.55] {
        let (s, c) = theta_o.sin_cos();
        let wo = V3::new(0.8 * s, 0.6 * s, c);
        let e64 = integrate::directional_albedo(wo, tilted);
        let e32 = integrate::directional_albedo_f32(wo.map(|x| x as f32), tilted);
        let exact = 1.0 + 0.5 * wo.x;
        let rel = report(&format!("albedo theta_o = {theta_o}"), e64, e32, exact);
        assert!(rel <= F32_ROUNDING, "f32 albedo off f64 by {rel:.2e}");
        assert!(
            (e64.value - exact).abs() <= 1e-5,
            "f64 albedo {}",
            e64.value
        );
        assert!(
            (e32.value - exact).abs() <= 1e-5,
            "f32 albedo {}",
            e32.value
        );
    }
    // The explicit-Config form delegates the same way.
    let cfg = Config {
        rel_tol: 1e-4,
        ..Config::default()
    };
    let wo = V3::new(0.6, 0.0, 0.8);
    let e = integrate::directional_albedo_with_f32(wo, tilted, &cfg);
    assert!((e.value - 1.3).abs() <= 1e-3, "albedo with cfg {}", e.value);
}

#[test]
fn f32_hemisphere_passes_its_peaks_to_the_partition() {
    // A Gaussian-like lobe exp(-|w - p|^2 / (2 s)) of angular width sqrt(s) = 1e-3 rad at
    // theta = 0.5: its integral is 2 pi s (1 - e^(-2/s)) = 2 pi s. Without p among the peaks
    // the initial rectangles near theta = 0.5 are ~0.25 rad wide and all 17 samples miss
    // the lobe (the estimate is 0), so this fails if the f32 entry point drops its peaks.
    // |w - p|^2 is summed from component differences: 1 - w.p would cancel in f32.
    let s = 1e-6_f64;
    let p = V3::new(0.5_f64.sin() * 0.6, 0.5_f64.sin() * 0.8, 0.5_f64.cos());
    fn lobe<T: Real>(w: V3<T>, p: V3<T>, s: T) -> T {
        let d = w - p;
        (-(d.length_squared()) / (T::TWO * s)).exp()
    }
    let cfg = Config::default();
    let e64 = integrate::hemisphere(|w| lobe(w, p, s), &[p], &cfg);
    let (p32, s32) = (p.map(|x| x as f32), s as f32);
    let e32 = integrate::hemisphere_f32(|w| lobe(w, p32, s32), &[p32], &cfg);
    let exact = 2.0 * PI * s;
    // The f32 lobe is centred on p rounded to f32 and its argument carries the directions'
    // f32 rounding (3e-8 absolute against a 1e-3 width): agreement to 1e-4 relative.
    let rel = report("hemisphere, 1e-3 rad lobe", e64, e32, exact);
    assert!(rel <= 1e-4, "f32 lobe integral off f64 by {rel:.2e}");
    for e in [e64, e32] {
        assert!(
            (e.value - exact).abs() <= 1e-3 * exact,
            "lobe integral {} vs {exact}",
            e.value
        );
    }
    // More than MAX_PEAKS peaks are accepted; the first ones shape the partition.
    let many = [p32; integrate::MAX_PEAKS + 3];
    let e = integrate::hemisphere_f32(|w| lobe(w, p32, s32), &many, &cfg);
    assert!((e.value - exact).abs() <= 1e-3 * exact);
}

#[test]
fn f32_ndf_area_and_weak_furnace_match_f64() {
    for alpha in [0.05_f64, 0.3, 1.0] {
        let e64 = integrate::ndf_projected_area(|m| ggx_d(m, alpha));
        let e32 = integrate::ndf_projected_area_f32(|m| ggx_d(m, alpha as f32));
        let rel = report(&format!("GGX area alpha = {alpha}"), e64, e32, 1.0);
        assert!(rel <= F32_ROUNDING, "f32 NDF area off f64 by {rel:.2e}");
        assert!(
            (e32.value - 1.0).abs() <= 1e-3,
            "f32 NDF area {}",
            e32.value
        );

        let wo = V3::new(1.0_f64.sin(), 0.0, 1.0_f64.cos());
        let e64 =
            integrate::smith_weak_furnace(wo, |m| ggx_d(m, alpha), |o, m| ggx_g1(o, m, alpha));
        let e32 = integrate::smith_weak_furnace_f32(
            wo.map(|x| x as f32),
            |m| ggx_d(m, alpha as f32),
            |o, m| ggx_g1(o, m, alpha as f32),
        );
        let rel = report(&format!("GGX weak furnace alpha = {alpha}"), e64, e32, 1.0);
        assert!(rel <= F32_ROUNDING, "f32 weak furnace off f64 by {rel:.2e}");
        assert!(
            (e32.value - 1.0).abs() <= 1e-3,
            "f32 weak furnace {}",
            e32.value
        );
    }
}

#[test]
fn f32_reciprocity_sees_the_same_pairs_as_f64() {
    // Symmetric in (a, b) to the last bit (a + b and a.z b.z commute exactly): both orders
    // of a pair see the same two f32 vectors, so exactly 0.
    let sym = integrate::reciprocity_f32(|a, b| {
        ggx_d((a + b).normalize_or(V3::unit_z()), 0.3) * (a.z * b.z)
    });
    assert_eq!(sym.max_rel, 0.0);
    // The asymmetric lobe: the same worst pair and the same ratio up to f32 rounding.
    let r64 = integrate::reciprocity(tilted);
    let r32 = integrate::reciprocity_f32(tilted);
    println!(
        "reciprocity of the tilted lobe: f64 {:.9}  f32 {:.9}  ({} pairs each)",
        r64.max_rel, r32.max_rel, r32.pairs
    );
    assert_eq!(r64.pairs, r32.pairs);
    assert_eq!(r64.worst, r32.worst);
    assert!((r64.max_rel - r32.max_rel).abs() <= F32_ROUNDING * r64.max_rel);
    assert!(r64.max_rel > 0.5, "the asymmetric lobe must be flagged");
}
