//! Energy: the Kulla-Conty compensated GGX never reflects more than it receives for Fresnel
//! terms with F <= 1: directional albedo <= 1 + the lookup error over a (alpha, theta_o) grid,
//! for Schlick F0 (dielectric and coloured) and the exact conductor Fresnel with its F_avg.
#![cfg(all(feature = "ibl", feature = "integrate", feature = "cook-torrance"))]

use brdf::V3;
use brdf::cook_torrance;
use brdf::fresnel;
use brdf::ggx::Ggx;
use brdf::ibl::energy::{fresnel_avg_conductor, fresnel_avg_schlick, kulla_conty_ggx};
use brdf::integrate::directional_albedo;
use brdf::microfacet::ALPHA_MIN;

/// A Fresnel term of v.h.
type Fresnel = Box<dyn Fn(f64) -> f64>;

#[test]
fn compensated_albedo_never_exceeds_one() {
    // (name, Fresnel of v.h, its F_avg)
    let cases: [(&str, Fresnel, f64); 4] = [
        (
            "schlick F0 = 1",
            Box::new(|c| fresnel::schlick(1.0, c)),
            fresnel_avg_schlick(1.0, 1.0),
        ),
        (
            "schlick F0 = 0.04",
            Box::new(|c| fresnel::schlick(0.04, c)),
            fresnel_avg_schlick(0.04, 1.0),
        ),
        (
            "schlick F0 = 0.34",
            Box::new(|c| fresnel::schlick(0.34, c)),
            fresnel_avg_schlick(0.34, 1.0),
        ),
        (
            "conductor eta 0.18 k 3.42",
            Box::new(|c| fresnel::conductor(c, 0.18, 3.42)),
            fresnel_avg_conductor(0.18, 3.42),
        ),
    ];
    for (name, f, f_avg) in &cases {
        let mut hi = 0f64;
        for alpha in [ALPHA_MIN, 0.05, 0.2, 0.5, 0.8, 1.0] {
            let g = Ggx::isotropic(alpha).unwrap();
            for theta in [0.0f64, 45.0, 70.0, 85.0, 89.0] {
                let t = theta.to_radians();
                let wo = V3::new(t.sin(), 0.0, t.cos());
                let r = directional_albedo(wo, |o, i| {
                    cook_torrance::eval(&g, o, i, f) + kulla_conty_ggx(o.z, i.z, alpha, *f_avg)
                });
                hi = hi.max(r.value);
                // 0.002: the table's lookup error (tests/ibl/energy_tables.rs), which is all
                // that can lift F = 1 above 1; a smaller F only lowers the albedo.
                assert!(
                    r.value <= 1.002 + r.error,
                    "{name} alpha {alpha} theta {theta}: {}",
                    r.value
                );
            }
        }
        println!("{name} (F_avg {f_avg:.4}): max albedo {hi:.5}");
    }
}

#[test]
fn conductor_average_matches_its_definition() {
    // F_avg of the exact conductor by quadrature against an independent midpoint sum.
    for (eta, k) in [(0.18, 3.42), (1.5, 0.0), (0.27, 2.78)] {
        let n = 200_000;
        let mid: f64 = (0..n)
            .map(|i| {
                let mu = (f64::from(i) + 0.5) / f64::from(n);
                2.0 * fresnel::conductor(mu, eta, k) * mu
            })
            .sum::<f64>()
            / f64::from(n);
        let q = fresnel_avg_conductor(eta, k);
        println!(
            "conductor eta {eta} k {k}: F_avg {q:.10} (midpoint {mid:.10}); schlick with F0 = F(1): {:.6}",
            fresnel_avg_schlick(fresnel::conductor(1.0, eta, k), 1.0)
        );
        // Midpoint error ~ h^2 / 24 max |f''| with h = 5e-6: below 1e-9.
        assert!((q - mid).abs() < 1e-9);
    }
}
