//! The albedo tables of `ibl::energy`: the built-in E(mu, alpha) and E_avg(alpha) tables are
//! what their builders produce, the builder agrees with the adaptive cubature of
//! `integrate::directional_albedo` applied to the crate's GGX Cook-Torrance with F = 1 (an
//! independent route: cubature of D V against QMC over visible normals of G2 / G1), and the
//! bilinear lookups stay within their documented error.
#![cfg(all(feature = "ibl", feature = "integrate", feature = "cook-torrance"))]

use brdf::V3;
use brdf::cook_torrance;
use brdf::ggx::Ggx;
use brdf::ibl::energy::{
    E_AVG_GGX_TABLE, E_GGX_TABLE, E_TABLE_SIZE, e_avg_ggx, e_avg_ggx_estimate, e_avg_table, e_ggx,
    e_ggx_estimate, e_table,
};
use brdf::integrate::directional_albedo;
use brdf::microfacet::ALPHA_MIN;

/// Samples the built-in tables were baked with (module docs of `ibl::energy`).
const BAKED_SAMPLES: u32 = 65536;

#[test]
fn built_in_tables_are_what_the_builders_produce() {
    let n = E_TABLE_SIZE;
    let mut e = vec![0f32; n * n];
    e_table(&mut e, n, n, BAKED_SAMPLES).unwrap();
    let mut avg = vec![0f32; n];
    e_avg_table(&mut avg, BAKED_SAMPLES).unwrap();
    // The builder is deterministic f64 arithmetic rounded to f32; an FMA or libm difference on
    // another target may move the last bit, never more than 1e-6.
    let max_e = e
        .iter()
        .zip(E_GGX_TABLE.iter())
        .map(|(a, b)| (a - b).abs())
        .fold(0f32, f32::max);
    let max_avg = avg
        .iter()
        .zip(E_AVG_GGX_TABLE.iter())
        .map(|(a, b)| (a - b).abs())
        .fold(0f32, f32::max);
    println!("regenerated E table: max abs difference {max_e:e}; E_avg: {max_avg:e}");
    assert!(max_e <= 1e-6 && max_avg <= 1e-6);
    // The grid's corners: E = 1 at grazing (mu = 0), 1 - ln 2 at alpha = 1, mu = 1.
    assert_eq!(E_GGX_TABLE[0], 1.0);
    let corner = f64::from(E_GGX_TABLE[n * n - 1]);
    assert!(
        (corner - (1.0 - core::f64::consts::LN_2)).abs() < 2e-5,
        "{corner}"
    );
}

fn albedo_by_cubature(mu: f64, alpha: f64) -> (f64, f64) {
    let g = Ggx::isotropic(alpha).unwrap();
    let wo = V3::new(((1.0 - mu) * (1.0 + mu)).sqrt(), 0.0, mu);
    let r = directional_albedo(wo, |o, i| cook_torrance::eval(&g, o, i, |_| 1.0));
    (r.value, r.error)
}

#[test]
fn builder_matches_cubature_of_the_cook_torrance_brdf() {
    println!("E(mu, alpha): QMC ({BAKED_SAMPLES} samples, as baked) minus cubature");
    println!(
        "{:>7} {:>6} {:>10} {:>10}",
        "alpha", "theta", "cubature", "qmc-cub"
    );
    let mut worst = 0f64;
    for alpha in [ALPHA_MIN, 0.01, 0.05, 0.25, 0.5, 1.0] {
        for theta in [0.0f64, 30.0, 60.0, 75.0, 85.0, 89.0] {
            let mu = theta.to_radians().cos();
            let (cub, err) = albedo_by_cubature(mu, alpha);
            let qmc = e_ggx_estimate(mu, alpha, BAKED_SAMPLES);
            println!("{alpha:>7} {theta:>6} {cub:>10.7} {:>10.2e}", qmc - cub);
            assert!(err < 1e-6, "cubature error {err}");
            worst = worst.max((qmc - cub).abs());
        }
    }
    println!("max |QMC - cubature| = {worst:.2e}");
    // QMC converges as about 0.5 / samples (8e-6 here) on wide lobes and a few times slower
    // on the narrowest; 5e-5 is the documented bound of the baked table and still fails for
    // any wrong weight (a separable G2 moves E by 1e-2).
    assert!(worst < 5e-5);
}

#[test]
fn lookups_stay_within_their_documented_error() {
    // Off-grid points (sqrt-spaced like the table, offset from its nodes) against the builder.
    let (mut all, mut to85) = ((0f64, 0.0, 0.0), (0f64, 0.0, 0.0));
    for a in 0..40 {
        for m in 0..40 {
            let alpha = ((f64::from(a) + 0.37) / 40.0).powi(2).max(ALPHA_MIN);
            let mu = ((f64::from(m) + 0.61) / 40.0).powi(2);
            let d = (e_ggx(mu, alpha) - e_ggx_estimate(mu, alpha, 4096)).abs();
            if d > all.0 {
                all = (d, mu, alpha);
            }
            if mu >= 85f64.to_radians().cos() && d > to85.0 {
                to85 = (d, mu, alpha);
            }
        }
    }
    println!(
        "e_ggx lookup: max abs error {:.4} (at mu {:.2e}, alpha {:.2e}); theta_o <= 85 deg: {:.4} (mu {:.3}, alpha {:.3})",
        all.0, all.1, all.2, to85.0, to85.1, to85.2
    );
    // The documented bounds (module docs): 0.06 overall, 0.0016 up to 85 degrees. 4096
    // samples add 1.2e-4 of QMC error.
    assert!(all.0 < 0.07 && to85.0 < 0.002);
    let mut worst_avg = 0f64;
    for a in 0..10 {
        let alpha = ((f64::from(a) + 0.5) / 10.0).powi(2);
        let d = (e_avg_ggx(alpha) - e_avg_ggx_estimate(alpha, 4096)).abs();
        worst_avg = worst_avg.max(d);
    }
    println!("e_avg_ggx lookup: max abs error {worst_avg:.2e} between nodes");
    assert!(worst_avg < 2e-3);
}

#[test]
fn builders_reject_bad_buffers() {
    let mut small = [0f32; 3];
    assert!(e_table(&mut small, 2, 2, 16).is_err());
    assert!(e_table(&mut small, 3, 1, 16).is_err());
    assert!(e_table(&mut [0f32; 4], 2, 2, 0).is_err());
    assert!(e_avg_table(&mut [0f32; 1], 16).is_err());
    assert!(e_avg_table(&mut [0f32; 4], 0).is_err());
    assert!(e_ggx_estimate(0.5, -1.0, 16).is_nan());
    assert!(e_ggx_estimate(f64::NAN, 0.5, 16).is_nan());
    assert!(e_ggx_estimate(0.5, 0.5, 0).is_nan());
}
