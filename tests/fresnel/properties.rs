//! The exact Fresnel equations satisfy the identities issue 3 names: eta = 1 reflects nothing,
//! normal incidence equals F0, the critical angle is continuous, a conductor with k = 0 is a
//! dielectric, Schlick is exact at 0 and 90 degrees; plus polarization and reversibility.
#![cfg(feature = "fresnel")]

use crate::common;
use brdf::Real;
use brdf::fresnel::{
    self, average_dielectric, conductor, dielectric, dielectric_polarized, schlick,
};
use brdf::wide::f32x8;
use proptest::prelude::*;

fn cosines() -> impl Iterator<Item = f64> {
    (0..=1000).map(|i| i as f64 / 1000.0)
}

#[test]
fn dielectric_at_eta_one_is_exactly_zero() {
    for c in cosines() {
        assert_eq!(dielectric(c, 1.0), 0.0, "cos {c}");
        assert_eq!(dielectric(-c, 1.0), 0.0, "cos {c} from inside");
        assert_eq!(dielectric(c as f32, 1.0f32), 0.0);
    }
}

#[test]
fn normal_incidence_equals_f0_formula() {
    for eta in [0.5, 0.9, 1.0 + 1e-6, 1.33, 1.5, 2.4, 10.0] {
        let f0: f64 = fresnel::f0_from_ior(eta);
        // 4 ulps: a handful of roundings on either side.
        assert!(
            (dielectric(1.0, eta) - f0).abs() <= 4.0 * f64::EPSILON * f0.max(1e-300),
            "eta {eta}"
        );
        assert!(
            (fresnel::ior_from_f0(fresnel::f0_from_ior(eta.max(1.0 / eta))) - eta.max(1.0 / eta))
                .abs()
                < 1e-9 * eta
        );
    }
}

#[test]
fn near_one_eta_keeps_its_digits() {
    // eta = 1 + 1e-6: F ~ ((eta - 1)/(eta + 1))^2 = 2.5e-13 at normal incidence. The
    // textbook ratio loses ~6 digits to cancellation in f64 (all of them in f32).
    let eta = 1.0 + 1e-6;
    let f0 = fresnel::f0_from_ior(eta);
    let f32_value = dielectric(1.0_f32, eta as f32) as f64;
    let f0_32 = fresnel::f0_from_ior(eta as f32 as f64);
    assert!((dielectric(1.0, eta) - f0).abs() <= 1e-12 * f0);
    assert!(
        (f32_value - f0_32).abs() <= 1e-5 * f0_32,
        "{f32_value} vs {f0_32}"
    );
}

#[test]
fn critical_angle_is_continuous_and_total_reflection_gives_one() {
    let eta: f64 = 1.0 / 1.5; // glass to air
    let c_crit = (1.0 - eta * eta).sqrt();
    // Below the critical cosine: exactly 1.
    for i in 0..100 {
        assert_eq!(dielectric(c_crit * i as f64 / 100.0, eta), 1.0);
    }
    // Approaching from above, 1 - F vanishes like sqrt(c - c_crit) (the transmitted cosine
    // does): continuous, with an infinite slope. The constant is ~11 for glass; 20 bounds it.
    for k in 0..=24 {
        let delta = 10f64.powf(-3.0 - 0.5 * k as f64);
        let f = dielectric(c_crit + delta, eta);
        assert!(
            f <= 1.0 && 1.0 - f <= 20.0 * delta.sqrt(),
            "delta {delta:e}: F = {f}"
        );
    }
    // From inside: the same interface seen with a negative cosine and eta = 1.5.
    assert_eq!(dielectric(-0.1, 1.5), 1.0);
    // (Within an ulp: from inside, 1.5 is used as given; `eta` is 1 / 1.5 rounded.)
    let (inside, outside) = (dielectric(-0.9, 1.5), dielectric(0.9, eta));
    assert!((inside - outside).abs() <= 2.0 * f64::EPSILON * outside);
}

#[test]
fn conductor_with_zero_k_equals_dielectric() {
    for eta in [1.1, 1.5, 2.5, 10.0] {
        for c in cosines() {
            let (a, b) = (conductor(c, eta, 0.0), dielectric(c, eta));
            assert!((a - b).abs() <= 1e-14, "eta {eta} cos {c}: {a} vs {b}");
        }
    }
}

#[test]
fn schlick_is_exact_at_normal_and_grazing_incidence() {
    for eta in [1.2, 1.5, 2.0] {
        let f0 = fresnel::f0_from_ior(eta);
        assert!((schlick(f0, 1.0) - dielectric(1.0, eta)).abs() < 1e-15);
        assert_eq!(schlick(f0, 0.0), 1.0);
        assert_eq!(dielectric(0.0, eta), 1.0);
    }
}

#[test]
fn rgb_forms_equal_their_scalar_channels() {
    let f0 = brdf::V3::new(0.9, 0.6, 0.2);
    let f90 = brdf::V3::new(1.0, 0.8, 0.5);
    for c in cosines() {
        let rgb = fresnel::schlick_rgb(f0, c);
        let rgb90 = fresnel::schlick_f90_rgb(f0, f90, c);
        assert_eq!(
            [rgb.x, rgb.y, rgb.z],
            [schlick(0.9, c), schlick(0.6, c), schlick(0.2, c)]
        );
        assert_eq!(rgb90.y, fresnel::schlick_f90(0.6, 0.8, c));
    }
    // Exact at both ends: F0 at normal incidence, F90 at grazing.
    assert_eq!(fresnel::schlick_f90_rgb(f0, f90, 0.0), f90);
    assert_eq!(fresnel::schlick_f90_rgb(f0, f90, 1.0), f0);
}

#[test]
fn polarized_reflectances_average_to_the_unpolarized_one_and_vanish_at_brewster() {
    let eta: f64 = 1.5;
    for c in cosines() {
        let (rs, rp) = dielectric_polarized(c, eta);
        assert!((0.0..=1.0).contains(&rs) && (0.0..=1.0).contains(&rp));
        assert!(rs >= rp - 1e-15, "Rs >= Rp for external reflection");
        assert_eq!(0.5 * (rs + rp), dielectric(c, eta));
    }
    // Brewster's angle: tan(theta_B) = eta, where Rp = 0.
    let c_b = eta.atan().cos();
    assert!(dielectric_polarized(c_b, eta).1 < 1e-30);
}

#[test]
fn reflectance_is_the_same_from_both_sides_of_the_interface() {
    // Stokes relations: R(theta_i, eta) = R(theta_t, 1/eta) for the refracted angle theta_t.
    let eta: f64 = 1.5;
    for c in cosines().skip(1) {
        // cos_t = sqrt(eta^2 - sin^2_i) / eta, without the cancellation of 1 - sin^2_t.
        let ct = (eta * eta - (1.0 - c) * (1.0 + c)).sqrt() / eta;
        let (a, b) = (dielectric(c, eta), dielectric(-ct, eta));
        // Going back from inside, k = eta^-2 - 1 + cos_t^2 = c^2 / eta^2 is a difference of
        // O(1) numbers: the rounding of cos_t (1e-16) becomes 1e-16 / c^2 relative in k. That
        // conditioning of the round trip, not the function, sets the tolerance.
        assert!(
            (a - b).abs() < 1e-13 + 1e-15 / (c * c),
            "cos {c}: {a} vs {b}"
        );
    }
}

#[test]
fn conductor_is_stable_for_huge_k() {
    for k in [1.0, 10.0, 100.0, 1e3] {
        for c in cosines() {
            let f = conductor(c, 0.2, k);
            let f32v = conductor(c as f32, 0.2, k as f32);
            assert!(
                f.is_finite() && (0.0..=1.0).contains(&f),
                "k {k} cos {c}: {f}"
            );
            assert!(
                f32v.is_finite() && (f32v as f64 - f).abs() < 1e-5,
                "k {k} cos {c}: {f32v} vs {f}"
            );
        }
    }
    // Silver-like metal reflects most light at normal incidence: ((n-1)^2 + k^2)/((n+1)^2 + k^2).
    let (n, k) = (0.155, 3.48);
    let f0 = ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
    assert!((conductor(1.0, n, k) - f0).abs() < 1e-14);
}

#[test]
fn f82_tint_pins_the_dip_and_reduces_to_schlick() {
    let mu = fresnel::F82_MU;
    for f0 in [0.04, 0.5, 0.95] {
        for tint in [0.0, 0.3, 0.8, 1.0] {
            let f = fresnel::schlick_f82(f0, tint, mu);
            assert!(
                (f - tint * schlick(f0, mu)).abs() < 1e-14,
                "F82 at mu_bar for f0 {f0}, tint {tint}"
            );
            for c in cosines() {
                let g = fresnel::schlick_f82(f0, tint, c);
                assert!((0.0..=1.0).contains(&g));
                if tint == 1.0 {
                    assert_eq!(g, schlick(f0, c));
                }
            }
            assert_eq!(fresnel::schlick_f82(f0, tint, 0.0), 1.0);
            assert!((fresnel::schlick_f82(f0, tint, 1.0) - f0).abs() < 1e-15);
        }
    }
}

#[test]
fn hemispherical_average_matches_brute_force_integration() {
    // An independent route: a 2-million-point midpoint sum of 2 F(mu) mu over [0, 1] (error
    // about 1e-10, set by the sqrt kink at the critical angle for eta < 1) against the
    // substituted Gauss-Legendre rule of average_dielectric.
    for eta in [0.5, 0.67, 0.9, 0.99, 1.0, 1.01, 1.1, 1.5, 2.0, 3.0] {
        let n = 2_000_000;
        let sum: f64 = (0..n)
            .map(|i| (i as f64 + 0.5) / n as f64)
            .map(|mu| dielectric(mu, eta) * mu)
            .sum();
        let brute = 2.0 * sum / n as f64;
        let q = average_dielectric(eta);
        assert!(
            (brute - q).abs() < 1e-8,
            "eta {eta}: brute {brute} vs quadrature {q}"
        );
    }
    assert_eq!(average_dielectric(1.0), 0.0);
}

#[test]
fn lanes_match_scalar_bit_for_bit() {
    let etas = [0.5f32, 0.9, 1.0, 1.5, 2.4, 10.0, 1.000001, 0.999999];
    for i in 0..=200 {
        let c = -1.0 + 2.0 * i as f32 / 200.0;
        let lanes = dielectric(f32x8::splat(c), f32x8::new(etas));
        let cond = conductor(f32x8::splat(c), f32x8::new(etas), f32x8::splat(3.0));
        let sg = fresnel::schlick_sg(f32x8::splat(0.04), f32x8::splat(c));
        for (j, &eta) in etas.iter().enumerate() {
            assert_eq!(lanes.lane(j).to_bits(), dielectric(c, eta).to_bits());
            assert_eq!(cond.lane(j).to_bits(), conductor(c, eta, 3.0).to_bits());
        }
        // schlick_sg uses exp2: the lane path is within 1 ulp of the scalar exp2.
        assert!((sg.lane(0) - fresnel::schlick_sg(0.04f32, c)).abs() <= 2.0 * f32::EPSILON);
    }
}

proptest! {
    #![proptest_config(common::proptest_config())]
    #[test]
    fn every_fresnel_term_is_a_probability(c in -1.5f64..1.5, eta in 0.01f64..100.0, k in 0.0f64..2000.0, f0 in 0.0f64..1.0) {
        for f in [dielectric(c, eta), conductor(c, eta, k), schlick(f0, c), fresnel::schlick_sg(f0, c), fresnel::schlick_f82(f0, 0.5, c)] {
            prop_assert!(f.is_finite() && (0.0..=1.0).contains(&f), "{f}");
        }
        let (rs, rp) = dielectric_polarized(c, eta);
        prop_assert!((0.0..=1.0).contains(&rs) && (0.0..=1.0).contains(&rp));
    }
}
