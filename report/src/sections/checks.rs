//! The report's checks of the crate's tools: the integrators on known integrals, the lanes
//! against scalar, NDF normalization, Smith's weak furnace, the tonemapping table, the
//! accuracy table, and the sphere renders.

use brdf::ggx::Ggx;
use brdf::integrate::{self, Config, Estimate};
use brdf::microfacet::Microfacet;
use brdf::tonemap::{AgxLook, Operator};
use brdf::wide::f32x8;
use brdf::{Real, V3, beckmann};
use core::f64::consts::PI;

/// `a . b` summed as glam's `DVec3::dot` sums it (three rounded products, two rounded sums);
/// `V3::dot` fuses them, which can move the last bit of the Phong rows below.
fn dot(a: V3<f64>, b: V3<f64>) -> f64 {
    a.x * b.x + a.y * b.y + a.z * b.z
}

fn row(name: &str, e: Estimate, exact: f64) {
    outln!(
        "| {name:<34} | {:>15.12} | {:>15.12} | {:>9.2e} | {:>9.2e} | {:>7} |",
        e.value,
        exact,
        (e.value - exact).abs(),
        e.error,
        e.evaluations
    );
}

pub fn integrator_checks() {
    outln!("## Integrators on known integrals (default budget)\n");
    outln!("| integrand | estimate | exact | actual err | reported | evals |");
    outln!("|---|---|---|---|---|---|");
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
        let wo = V3::new(0.6, 0.0, 0.8);
        row(
            &format!("Lambert albedo, rho = {rho}"),
            integrate::directional_albedo(wo, |_, _| rho / PI),
            rho,
        );
    }
    let n = 10_000.0;
    let wo = V3::new(0.6, 0.0, 0.8);
    let r = V3::new(-wo.x, -wo.y, wo.z);
    row(
        "Phong n=1e4 about mirror, 37 deg",
        integrate::directional_albedo(wo, |_, wi| {
            (n + 2.0) / (2.0 * PI) * dot(r, wi).max(0.0).powf(n)
        }),
        wo.z,
    );
    let classic = integrate::reciprocity(|a, b| {
        let r = V3::new(-a.x, -a.y, a.z);
        dot(r, b).max(0.0).powi(4) / b.z
    });
    outln!(
        "\nreciprocity of classic Phong (1 / n.l factor): max relative asymmetry {:.3} over {} pairs",
        classic.max_rel,
        classic.pairs
    );
}

pub fn lane_checks() {
    outln!("\n## Lanes against scalar (f32x8 vs f32, 100 000 points in [-10, 10])\n");
    outln!("| function | max ULP |");
    outln!("|---|---|");
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
        outln!("| {name} | {worst} |");
    }
}

pub fn microfacet_checks() {
    outln!("\n## NDF normalization: integral of D(m) cos(theta_m) dm (should be 1)\n");
    outln!("| alpha_x x alpha_y | GGX | Beckmann |");
    outln!("|---|---|---|");
    for (ax, ay) in [
        (0.01, 0.01),
        (0.1, 0.1),
        (0.5, 0.5),
        (1.0, 1.0),
        (1.0, 0.01),
        (0.5, 0.05),
    ] {
        let g = Ggx::new(ax, ay).expect("valid alpha");
        let b = beckmann::Beckmann::new(ax, ay).expect("valid alpha");
        let eg = integrate::ndf_projected_area(|m| g.d(m));
        let eb = integrate::ndf_projected_area(|m| b.d(m));
        outln!("| {ax} x {ay} | {:.9} | {:.9} |", eg.value, eb.value);
    }
    outln!("\n## Smith weak white furnace (should be 1)\n");
    outln!("| alpha | theta_o | GGX | Beckmann |");
    outln!("|---|---|---|---|");
    for alpha in [0.01, 0.2, 1.0] {
        let g = Ggx::new(alpha, alpha).expect("valid alpha");
        let b = beckmann::Beckmann::new(alpha, alpha).expect("valid alpha");
        for deg in [0.0f64, 60.0, 89.0, 89.9] {
            let t = deg.to_radians();
            let wo = V3::new(t.sin(), 0.0, t.cos());
            let (g1g, g1b) = (g.g1(wo), b.g1(wo));
            let eg = integrate::smith_weak_furnace(wo, |m| g.d(m), |_, _| g1g);
            let eb = integrate::smith_weak_furnace(wo, |m| b.d(m), |_, _| g1b);
            outln!("| {alpha} | {deg} | {:.7} | {:.7} |", eg.value, eb.value);
        }
    }
}

pub fn tonemap_table() {
    outln!("\n## Tonemapping operators on grey input (display-linear output)\n");
    let inputs = [0.0, 0.18, 1.0, 4.0, 16.0, 1e3, f64::INFINITY];
    out!("| operator |");
    for x in inputs {
        out!(" {x} |");
    }
    outln!();
    outln!("|---|{}", "---|".repeat(inputs.len()));
    for op in Operator::all() {
        out!("| {} |", op_name(&op));
        for x in inputs {
            out!(" {:.4} |", op.apply(V3::splat(x)).y);
        }
        outln!();
    }
}

pub fn op_name(op: &Operator) -> String {
    match op {
        Operator::AgxMinimal(look) | Operator::AgxFilament(look) if *look != AgxLook::BASE => {
            let which = if matches!(op, Operator::AgxMinimal(_)) {
                "AgxMinimal"
            } else {
                "AgxFilament"
            };
            let name = if *look == AgxLook::PUNCHY {
                "punchy"
            } else {
                "golden"
            };
            format!("{which} {name}")
        }
        _ => format!("{op:?}")
            .split('(')
            .next()
            .unwrap_or("?")
            .to_string(),
    }
}

/// The per-function ULP table against the correctly rounded MPFR oracle. Measuring it needs
/// GMP and MPFR (the `brdf-oracle` workspace member); `.ci/run` re-measures it on every run
/// and fails if this committed copy differs, so what the report prints is current.
pub fn accuracy_table() {
    outln!("\n## Exact functions against the correctly rounded oracle (max ULP)\n");
    out!("{}", include_str!("../../../docs/accuracy.md"));
}
