//! The prefilter sample set integrates a smooth environment to the GGX-prefiltered value of
//! Karis 2013 computed by an independent route: the adaptive cubature of
//! `brdf::integrate::hemisphere` applied to the estimator's limit
//! L_pre = integral L(l) (n.l) D(h) / 4 dl / integral (n.l) D(h) / 4 dl over n.l > 0,
//! with h = normalize(l + n) and D = `ggx::d` (the samples themselves never enter it).
#![cfg(all(feature = "ibl", feature = "integrate"))]

use brdf::V3;
use brdf::frame::Frame;
use brdf::ggx;
use brdf::ibl::prefilter;
use brdf::integrate::{Config, hemisphere};

use crate::common::normalize;

/// A smooth, positive, non-symmetric environment (world space): a degree-2 polynomial.
fn env(l: V3<f64>) -> f64 {
    1.0 + 0.5 * l.x + 0.3 * l.y + 0.8 * l.z * l.z + 0.4 * l.x * l.z
}

/// Karis's weighted estimator with n samples around the world direction r.
fn estimate(r: V3<f64>, n: u32, alpha: f64) -> f64 {
    let frame = Frame::from_normal(r);
    let (mut num, mut den) = (0.0, 0.0);
    for s in prefilter::samples(n, alpha) {
        num += env(frame.to_world(s.dir)) * s.weight;
        den += s.weight;
    }
    num / den
}

/// The same limit by cubature over the hemisphere around r.
fn reference(r: V3<f64>, alpha: f64) -> f64 {
    let frame = Frame::from_normal(r);
    let cfg = Config {
        abs_tol: 1e-12,
        rel_tol: 1e-10,
        max_evals: 4_000_000,
    };
    let kernel = |w: V3<f64>| {
        let hz = (0.5 * (1.0 + w.z)).sqrt();
        w.z * ggx::d(hz, alpha) / 4.0
    };
    let num = hemisphere(
        |w| env(frame.to_world(w)) * kernel(w),
        &[V3::unit_z()],
        &cfg,
    );
    let den = hemisphere(kernel, &[V3::unit_z()], &cfg);
    assert!(num.error < 1e-8 * num.value && den.error < 1e-8 * den.value);
    num.value / den.value
}

#[test]
fn prefilter_samples_converge_to_the_ggx_prefiltered_environment() {
    let dirs = [
        V3::unit_z(),
        V3::new(0.6, 0.0, 0.8),
        V3::new(-0.48, 0.64, 0.6),
        V3::new(0.0, 0.8, -0.6),
    ];
    // Bounds at 1.25x the measured worst error of each row (printed below), rounded up: the
    // Hammersley set's error decays like log(N) / N, and a lost Jacobian, a wrong weight or a
    // swapped u would move these estimates by 1e-2 or more.
    let rows = [
        (0.05, 256, 1.4e-3),
        (0.25, 256, 5.0e-4),
        (0.5, 256, 1.3e-3),
        (1.0, 256, 4.5e-3),
        (0.05, 4096, 3.8e-6),
        (0.25, 4096, 2.5e-5),
        (0.5, 4096, 6.6e-5),
        (1.0, 4096, 2.1e-4),
    ];
    println!("| alpha | N | max relative error | bound |");
    println!("|---|---|---|---|");
    for (alpha, n, bound) in rows {
        let mut worst = 0.0_f64;
        for r in dirs {
            let r = normalize(r);
            let (e, want) = (estimate(r, n, alpha), reference(r, alpha));
            worst = worst.max((e - want).abs() / want);
        }
        println!("| {alpha} | {n} | {worst:.2e} | {bound:.1e} |");
        assert!(
            worst < bound,
            "alpha {alpha}, N {n}: {worst:e} >= {bound:e}"
        );
    }
}
