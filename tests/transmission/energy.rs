//! White furnace of the rough dielectric BSDF over the whole sphere of wi, from outside and
//! inside: reflection plus transmission scatter at most all of the light (<= 1), and all of it
//! as alpha -> 0; the energy the single-scattering model loses, tabulated beside the
//! conductor's (Cook-Torrance with F = 1); and the sampler's mean weight against the integral.

use crate::common::Rng;
use crate::{dir, refracted};
use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::integrate::{Estimate, directional_albedo, directional_albedo_sphere};
use brdf::microfacet::Microfacet;
use brdf::rough_dielectric::{self as rd, Transport};
use brdf::{V3, cook_torrance};

/// Scattered fraction of light arriving along `wo`: the importance BSDF's albedo (module
/// docs of `rough_dielectric`, "Radiance and importance").
fn furnace<M: Microfacet<f64>>(m: &M, wo: V3<f64>, eta: f64) -> Estimate {
    let peaks: Vec<V3<f64>> = refracted(wo, eta).into_iter().collect();
    directional_albedo_sphere(
        wo,
        |o, i| rd::eval(m, o, i, eta, Transport::Importance),
        &peaks,
    )
}

fn conductor_albedo<M: Microfacet<f64>>(m: &M, wo: V3<f64>) -> f64 {
    directional_albedo(wo, |o, i| cook_torrance::eval(m, o, i, |_| 1.0)).value
}

/// Outside views at 0, 45, 70 and 85 degrees, inside views at the same angles from -z (45 and
/// beyond lie past glass's critical angle, 41.8 degrees, for a smooth surface).
const THETAS: [f64; 8] = [0.0, 45.0, 70.0, 85.0, 180.0, 135.0, 110.0, 95.0];

#[test]
fn furnace_is_at_most_one_on_both_sides_and_the_loss_is_tabulated() {
    println!(
        "{:>9} {:>5} {:>5} {:>7} {:>12} {:>12} {:>10}",
        "model", "eta", "alpha", "theta_o", "1 - E_diel", "1 - E_cond", "quad.err"
    );
    for (name, is_ggx) in [("ggx", true), ("beckmann", false)] {
        for eta in [1.5, 1.0 / 1.33] {
            for alpha in [0.05, 0.3, 1.0] {
                for theta in THETAS {
                    let wo = dir(theta, 30.0);
                    let (e, cond) = if is_ggx {
                        let m = Ggx::isotropic(alpha).unwrap();
                        (
                            furnace(&m, wo, eta),
                            (theta < 90.0).then(|| conductor_albedo(&m, wo)),
                        )
                    } else {
                        let m = Beckmann::isotropic(alpha).unwrap();
                        (
                            furnace(&m, wo, eta),
                            (theta < 90.0).then(|| conductor_albedo(&m, wo)),
                        )
                    };
                    let cond_loss = cond.map_or("-".to_string(), |c| format!("{:.3e}", 1.0 - c));
                    println!(
                        "{name:>9} {eta:>5.3} {alpha:>5} {theta:>7} {:>12.3e} {:>12} {:>10.1e}",
                        1.0 - e.value,
                        cond_loss,
                        e.error
                    );
                    // Energy: never above 1 beyond the quadrature's own error (the error
                    // estimate plus 1e-6 for the critical-angle kink, integrate's module docs).
                    assert!(
                        e.value <= 1.0 + e.error + 1e-6,
                        "{name} eta {eta} alpha {alpha} theta {theta}: {e:?}"
                    );
                    assert!(
                        e.value > 0.3,
                        "{name} eta {eta} alpha {alpha} theta {theta}: {e:?}"
                    );
                }
            }
        }
    }
}

/// As alpha -> 0 the interface is a smooth one, which reflects F and transmits 1 - F of the
/// light: the albedo tends to 1. The loss shrinks with alpha and is below 2e-3 at alpha
/// 0.01 for views up to 70 degrees on both sides (measured: printed).
#[test]
fn furnace_tends_to_one_as_alpha_goes_to_zero() {
    for eta in [1.5, 1.0 / 1.5] {
        for theta in [0.0, 60.0, 70.0, 180.0, 130.0, 110.0] {
            let wo = dir(theta, 10.0);
            let mut last = f64::INFINITY;
            for alpha in [0.3, 0.1, 0.03, 0.01] {
                let m = Ggx::isotropic(alpha).unwrap();
                let e = furnace(&m, wo, eta);
                let loss = 1.0 - e.value;
                println!(
                    "eta {eta:.3} theta {theta} alpha {alpha}: loss {loss:.3e} (err {:.1e})",
                    e.error
                );
                assert!(
                    loss < last + 1e-4,
                    "eta {eta} theta {theta} alpha {alpha}: {loss} after {last}"
                );
                last = loss;
            }
            assert!(
                last.abs() < 2e-3,
                "eta {eta} theta {theta}: loss {last} at alpha 0.01"
            );
        }
    }
}

/// The sampler's mean weight (importance transport) is the furnace integral: an estimator
/// from the sampler and one from `eval` by quadrature, which share only the BSDF's definition.
#[test]
fn mean_sample_weight_is_the_furnace_integral() {
    let n = 100_000;
    for (alpha_x, alpha_y) in [(0.3, 0.3), (0.15, 0.6)] {
        for eta in [1.5, 1.0 / 1.5] {
            for theta in [20.0, 75.0, 160.0, 120.0] {
                let wo = dir(theta, 40.0);
                for is_ggx in [true, false] {
                    let (int, mean, sd) = if is_ggx {
                        let m = Ggx::new(alpha_x, alpha_y).unwrap();
                        let (mean, sd) = mean_weight(n, |a, b, c| {
                            rd::ggx_sample(&m, wo, eta, a, b, c, Transport::Importance).2
                        });
                        (furnace(&m, wo, eta), mean, sd)
                    } else {
                        let m = Beckmann::new(alpha_x, alpha_y).unwrap();
                        let (mean, sd) = mean_weight(n, |a, b, c| {
                            rd::beckmann_sample(&m, wo, eta, a, b, c, Transport::Importance).2
                        });
                        (furnace(&m, wo, eta), mean, sd)
                    };
                    println!(
                        "ggx {is_ggx} a ({alpha_x}, {alpha_y}) eta {eta:.3} theta {theta}: integral {:.5} mean weight {mean:.5} +- {sd:.1e}",
                        int.value
                    );
                    // 5 standard errors (a correct estimator fails one seed in 10^6).
                    assert!((int.value - mean).abs() < 5.0 * sd + int.error + 1e-6);
                }
            }
        }
    }
}

fn mean_weight(n: usize, mut w: impl FnMut(f64, f64, f64) -> f64) -> (f64, f64) {
    let mut rng = Rng(0xd1e1);
    let (mut s, mut s2) = (0.0, 0.0);
    for _ in 0..n {
        let x = w(rng.next_f64(), rng.next_f64(), rng.next_f64());
        s += x;
        s2 += x * x;
    }
    let mean = s / n as f64;
    let var = (s2 / n as f64 - mean * mean).max(0.0);
    (mean, (var / n as f64).sqrt())
}
