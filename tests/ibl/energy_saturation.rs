//! Kulla and Conty's Fresnel term saturates coloured metals: F_ms / F_avg falls as F_avg
//! falls, so the compensated albedo of a gold-like F0 has a larger max/min channel ratio than
//! the single-scattering one. Prints the figures.
#![cfg(all(feature = "ibl", feature = "integrate", feature = "cook-torrance"))]

use brdf::V3;
use brdf::cook_torrance;
use brdf::fresnel;
use brdf::ggx::Ggx;
use brdf::ibl::energy::{AverageAlbedo, Reflectance};
use brdf::ibl::energy::{e_avg_ggx, fresnel_avg_schlick, kulla_conty_fresnel, kulla_conty_ggx};
use brdf::integrate::directional_albedo;

/// A gold-like F0 (linear Rec.709), as in glTF sample materials.
const GOLD: [f64; 3] = [1.0, 0.78, 0.34];

#[test]
fn fms_over_favg_falls_with_favg() {
    let e_avg: f64 = e_avg_ggx(1.0);
    println!("alpha = 1 (E_avg = {e_avg:.4}): F_ms / F_avg against F_avg");
    let mut prev = f64::INFINITY;
    for k in (0..=10).rev() {
        let f_avg = f64::from(k) / 10.0;
        let ratio = if f_avg > 0.0 {
            kulla_conty_fresnel(Reflectance(f_avg), AverageAlbedo(e_avg)) / f_avg
        } else {
            0.0
        };
        println!(
            "  F_avg {f_avg:.1}: F_ms {:.4}, F_ms / F_avg {ratio:.4}",
            kulla_conty_fresnel(Reflectance(f_avg), AverageAlbedo(e_avg))
        );
        // Strictly falling: F_avg E_avg / (1 - F_avg (1 - E_avg)) is increasing in F_avg.
        assert!(ratio < prev, "{f_avg}: {ratio} >= {prev}");
        prev = ratio;
    }
}

#[test]
fn compensation_saturates_a_gold_like_metal() {
    println!("gold-like F0 {GOLD:?} (Schlick), albedo per channel r g b and max/min");
    for alpha in [0.25, 0.5, 1.0] {
        let g = Ggx::isotropic(alpha).unwrap();
        for theta in [0.0f64, 60.0] {
            let t = theta.to_radians();
            let wo = V3::new(t.sin(), 0.0, t.cos());
            let mut ss = [0.0; 3];
            let mut ms = [0.0; 3];
            for c in 0..3 {
                let f0 = GOLD[c];
                let f_avg = fresnel_avg_schlick(f0, 1.0);
                let single = |o: V3<f64>, i: V3<f64>| {
                    cook_torrance::eval(&g, o, i, |vh| fresnel::schlick(f0, vh))
                };
                ss[c] = directional_albedo(wo, single).value;
                ms[c] = directional_albedo(wo, |o, i| {
                    single(o, i) + kulla_conty_ggx(o.z, i.z, alpha, f_avg)
                })
                .value;
            }
            let ratio = |a: [f64; 3]| a[0] / a[2];
            println!(
                "  alpha {alpha} theta {theta:>2}: single {:.4} {:.4} {:.4} (r/b {:.4}) -> compensated {:.4} {:.4} {:.4} (r/b {:.4})",
                ss[0],
                ss[1],
                ss[2],
                ratio(ss),
                ms[0],
                ms[1],
                ms[2],
                ratio(ms)
            );
            // More saturated: the added light is F_ms-coloured, F_ms / F_avg falling with F_avg.
            assert!(ratio(ms) > ratio(ss), "alpha {alpha} theta {theta}");
            // And brighter in every channel (the lobe only adds).
            assert!((0..3).all(|c| ms[c] > ss[c]));
        }
    }
}
