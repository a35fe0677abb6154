//! The image-based-lighting bug every engine once had, against the split-sum path that fixes
//! it, both measured against brute-force integration of the BRDF over a procedural sky with a
//! sun:
//!
//! - the bug: one radiance sample along the normal passed off as diffuse irradiance, and a
//!   lerp from the mirror sample toward that normal sample passed off as roughness, both
//!   added at full weight (the normal sample counted twice, no energy split);
//! - the fix: diffuse = kD base / pi E(n) with the cosine-convolved irradiance E (quadrature,
//!   and SH9), kD = (1 - F)(1 - metallic); specular = GGX-prefiltered radiance along r (n = v
//!   = r) times the split-sum DFG terms, F0 A + B (Karis 2013).
//!
//! The reference is the reflectance integral itself, L_o(v) = integral f(v, l) L(l) n.l dl,
//! with the crate's metallic-roughness BRDF (kd = (1 - metallic)(1 - F(v.h)) per channel,
//! `DiffuseCoupling::OneMinusF`) on a fine midpoint grid in (n.l, phi).
//!
//! `cargo test --test ibl seed_s0:: -- --nocapture` prints every figure.
#![cfg(all(feature = "ibl", feature = "material"))]

#[path = "../scenes/s0.rs"]
mod s0;

use brdf::V3;
use s0::{Surface, env, paths, reference, rel, surfaces, white};

/// The fixed path matches the reflectance integral; the bug does not, by the printed factors.
///
/// Measured relative errors of the split-sum path (max over RGB of |split - exact| / max
/// exact), with quadrature / SH9 irradiance: rough dielectric 1.5% / 3.7%, glossy dielectric
/// 0.9% / 2.3%, matte white 2.7% / 5.1%, rough gold 14.3% / 14.3%. The gold's error is the
/// split sum's own: its prefiltered lobe is centred on r with n = v = r, while the true lobe
/// of a rough surface seen off-normal leans toward n and stretches, and the sun sits in
/// the tail where the two differ (Lagarde and de Rousiers 2014's dominant-direction
/// correction, tried here with either roughness convention, trades it for an error on the
/// glossy dielectric: it is not a fix). SH9 adds its band truncation of the sun on the
/// diffuse surfaces. Each bound is the measured figure rounded up. The single-sample path is
/// 65% to 90% off on every surface.
#[test]
fn the_split_sum_path_matches_brute_force_and_the_single_sample_path_does_not() {
    let mut worst_fixed: f64 = 0.0;
    let mut worst_sh9: f64 = 0.0;
    let mut least_bug = f64::INFINITY;
    for s in surfaces() {
        let want = reference(&s, env, 1500);
        let p = paths(&s, env);
        let (ef, es, eb) = (rel(p.fixed, want), rel(p.fixed_sh9, want), rel(p.bug, want));
        println!(
            "{:28} reference {:?}\n{:28} split sum {:?} ({:.2}%), with SH9 {:.2}%, single sample {:?} ({:.0}%)",
            s.name,
            want.to_array(),
            "",
            p.fixed.to_array(),
            100.0 * ef,
            100.0 * es,
            p.bug.to_array(),
            100.0 * eb
        );
        worst_fixed = worst_fixed.max(ef);
        worst_sh9 = worst_sh9.max(es);
        least_bug = least_bug.min(eb);
        assert!(ef <= s.bounds.0, "{}: split sum {ef}", s.name);
        assert!(es <= s.bounds.1, "{}: split sum with SH9 {es}", s.name);
    }
    println!(
        "max relative error: split sum {:.2}%, with SH9 {:.2}%; single-sample path at least {:.0}% off",
        100.0 * worst_fixed,
        100.0 * worst_sh9,
        100.0 * least_bug
    );
    assert!(
        least_bug >= 0.5,
        "the single-sample path is too close: {least_bug}"
    );
}

/// In a white furnace (L = 1 everywhere) a white material reflects at most what arrives: the
/// split-sum path's kD = (1 - F)(1 - metallic) gives exactly 1 for a white dielectric (no
/// sample counted twice), while the single-sample path reflects 1 + F0 (the normal sample
/// used by both terms).
#[test]
fn no_sample_is_counted_twice_in_a_white_furnace() {
    for s in surfaces() {
        let s = Surface {
            base: V3::splat(1.0),
            ..s
        };
        let p = paths(&s, white);
        let want = reference(&s, white, 400);
        println!(
            "{:28} furnace: split sum {:.6}, single sample {:.4}, reflectance integral {:.4}",
            s.name, p.fixed.y, p.bug.y, want.y
        );
        if s.metallic == 0.0 {
            assert!((p.fixed.y - 1.0).abs() < 1e-9, "{}: {}", s.name, p.fixed.y);
        }
        assert!(p.fixed.max_element() <= 1.0 + 1e-9, "{}", s.name);
        assert!(p.bug.min_element() >= 1.0 + 0.04 - 1e-9, "{}", s.name);
    }
}
