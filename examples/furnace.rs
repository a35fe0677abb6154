//! White furnace by Monte Carlo through the crate's samplers, checked against the deterministic
//! cubature of [`brdf::integrate::directional_albedo`]. The directional albedo
//! rho(wo) = integral of f(wo, wi) cos(theta_i) dwi is estimated two ways:
//!
//! 1. GGX Cook-Torrance with F = 1, sampled by visible normals (`sampling::ggx_vndf`, Heitz
//!    2018): m ~ D_wo(m), wi = 2 (wo.m) m - wo, weight f wi.z / pdf with
//!    pdf = D_wo(m) / (4 wo.m) (`sampling::reflect_pdf`). The weight is G2 / G1(wo) <= 1, so
//!    the estimate is below 1 by the energy that single scattering loses.
//! 2. The glTF metallic-roughness material through `MetallicRoughness::sample_weighted`
//!    (one-sample selection between its GGX and Lambert lobes), per RGB channel.
//!
//! Tolerance of each comparison: 4 standard errors of the Monte Carlo mean (estimated from the
//! same samples; a correct sampler falls outside with probability 6e-5) plus the cubature's
//! own error estimate. Every figure is printed; the run exits non-zero if one fails.
//!
//! `cargo run --release --example furnace`
use brdf::Cosines;
use brdf::integrate::{Estimate, directional_albedo};
use brdf::material::MetallicRoughness;
use brdf::microfacet::Alpha;
use brdf::{V3, cook_torrance, ggx::Ggx, sampling};
use std::process::ExitCode;

/// Samples per estimate.
const N: usize = 1 << 18;

/// SplitMix64 (Steele, Lea and Flood 2014): a deterministic stream of uniforms in [0, 1).
struct Rng(u64);

impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// Running mean and standard error of the mean.
#[derive(Default)]
struct Mean {
    sum: f64,
    sum2: f64,
    n: f64,
}

impl Mean {
    fn add(&mut self, x: f64) {
        (self.sum, self.sum2, self.n) = (self.sum + x, self.sum2 + x * x, self.n + 1.0);
    }
    fn mean(&self) -> f64 {
        self.sum / self.n
    }
    fn std_error(&self) -> f64 {
        let var = (self.sum2 / self.n - self.mean() * self.mean()).max(0.0);
        (var / (self.n - 1.0)).sqrt()
    }
}

/// A local-frame direction at `deg` degrees from the normal (+z), in the xz plane.
fn at(deg: f64) -> V3<f64> {
    let t = deg.to_radians();
    V3::new(t.sin(), 0.0, t.cos())
}

/// Prints one comparison and says whether it passed.
fn compare(label: &str, mc: &Mean, reference: Estimate) -> bool {
    let (mean, se) = (mc.mean(), mc.std_error());
    let diff = (mean - reference.value).abs();
    let tol = 4.0 * se + reference.error;
    let ok = diff <= tol;
    let (value, error) = (reference.value, reference.error);
    let verdict = if ok { "ok" } else { "FAIL" };
    print!("{label:<34} {mean:.5} +- {se:.1e}   {value:.5} +- {error:.0e}   ");
    println!(
        "{diff:.1e} <= {tol:.1e}  {:>4.1} sigma  {verdict}",
        diff / se
    );
    ok
}

/// GGX Cook-Torrance with F = 1 from the dot-product entry point.
fn ggx_f1(alpha: f64, wo: V3<f64>, wi: V3<f64>) -> f64 {
    cook_torrance::ggx(Cosines::from_local(wo, wi), Alpha(alpha), 1.0)
}

fn main() -> ExitCode {
    let mut rng = Rng(0x5eed_f00d);
    let mut all_ok = true;
    println!("White furnace: Monte Carlo ({N} samples) against cubature (directional_albedo)");
    println!(
        "{:<34} {:<20} {:<20} {:<20}",
        "case", "Monte Carlo +- se", "cubature +- err", "|diff| <= tol"
    );

    // 1. GGX, F = 1, visible-normal sampling.
    for alpha in [0.05, 0.3, 1.0] {
        let ggx = Ggx::isotropic(alpha).expect("alpha is finite and >= 0");
        for deg in [0.0, 60.0, 85.0] {
            let wo = at(deg);
            let mut mc = Mean::default();
            for _ in 0..N {
                let (m, pdf_m) = sampling::ggx_vndf(&ggx, wo, rng.uniform(), rng.uniform());
                let wi = m * (2.0 * wo.dot(m)) - wo;
                let pdf = sampling::reflect_pdf(pdf_m, wo.dot(m));
                let f = ggx_f1(alpha, wo, wi);
                mc.add(if pdf > 0.0 {
                    f * wi.z.max(0.0) / pdf
                } else {
                    0.0
                });
            }
            let reference = directional_albedo(wo, |o, i| ggx_f1(alpha, o, i));
            let label = format!("GGX F=1 alpha {alpha:<4} theta_o {deg:>2}");
            all_ok &= compare(&label, &mc, reference);
            if alpha == 1.0 && deg == 0.0 {
                // Closed form: at alpha = 1, f = 1 / (2 pi (1 + mu)) at normal view, so
                // rho = integral of mu / (1 + mu) over [0, 1] = 1 - ln 2.
                let exact = 1.0 - std::f64::consts::LN_2;
                let ok = (reference.value - exact).abs() <= reference.error + 1e-12;
                all_ok &= ok;
                println!(
                    "{:<34} cubature - (1 - ln 2) = {:.1e}  {}",
                    "  closed form",
                    reference.value - exact,
                    if ok { "ok" } else { "FAIL" }
                );
            }
        }
    }

    // 2. The metallic-roughness material, one-sample lobe selection, per channel.
    let materials = [
        ("red plastic r 0.4", V3::new(0.8, 0.05, 0.04), 0.0, 0.4),
        ("gold r 0.25", V3::new(1.0, 0.766, 0.336), 1.0, 0.25),
        ("blue half-metal r 0.7", V3::new(0.2, 0.4, 0.9), 0.5, 0.7),
    ];
    for (name, base, metallic, roughness) in materials {
        let mat = MetallicRoughness::new(base, metallic, roughness).expect("in-range parameters");
        for deg in [0.0, 70.0] {
            let wo = at(deg);
            let mut mc = [Mean::default(), Mean::default(), Mean::default()];
            for _ in 0..N {
                let (_, _, w) = mat.sample_weighted(wo, rng.uniform(), rng.uniform());
                for (acc, x) in mc.iter_mut().zip([w.x, w.y, w.z]) {
                    acc.add(x);
                }
            }
            for (c, channel) in ["R", "G", "B"].iter().enumerate() {
                let reference = directional_albedo(wo, |o, i| {
                    let f = mat.eval(o, i);
                    [f.x, f.y, f.z][c]
                });
                let label = format!("{name} theta_o {deg:>2} {channel}");
                all_ok &= compare(&label, &mc[c], reference);
            }
        }
    }

    if all_ok {
        println!("furnace: every Monte Carlo estimate agrees with the cubature");
        ExitCode::SUCCESS
    } else {
        println!("furnace: FAILED (see the FAIL lines)");
        ExitCode::FAILURE
    }
}
