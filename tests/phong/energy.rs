//! Energy of the Phong family, by numerical integration of the directional albedo
//! rho(wo) = integral f(wo, wi) cos(theta_i) dwi (`brdf::integrate::directional_albedo`):
//! - classic Phong exceeds 1 (Lewis 1994): where, and by how much;
//! - normalized, diffuse + specular and the exactly normalized Blinn-Phong stay <= 1 over an
//!   (exponent, theta_o) grid with exponents 0 to 10^4; modified Phong stays <= its
//!   normal-incidence albedo 2 pi ks / (n + 2), above 1 for n < 2 pi - 2;
//! - closed forms at normal incidence: normalized Phong gives ks, modified 2 pi ks / (n + 2),
//!   classic 2 pi ks / (n + 1), exact Blinn-Phong 1, the approximate one (n + 8) / (8 pi c(n)),
//!   and the Blinn-Phong NDF has projected area 1.
#![cfg(all(feature = "phong", feature = "integrate"))]

use brdf::V3;
use brdf::integrate::{Estimate, directional_albedo, ndf_projected_area};
use brdf::phong;
use core::f64::consts::PI;

use crate::common::{dot, normalize};

const EXPONENTS: [f64; 12] = [
    0.0, 0.5, 1.0, 2.0, 5.0, 10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0, 10000.0,
];
const THETAS_DEG: [f64; 8] = [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0];

/// Relative accuracy demanded of the integrator against closed forms. The integrator's own
/// tests (tests/integrate/accuracy.rs) show cos^10000 lobes to 1e-3 relative at worst; the
/// Phong lobes here come out far better (the errors printed are below 1e-6), so 1e-4 leaves
/// room without hiding a wrong normalization (the smallest model error caught here, the
/// (n + 8) / (8 pi) factor, is 2e-4 at n = 10^4).
const REL_TOL: f64 = 1e-4;

fn wo(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin(), 0.0, t.cos())
}

/// r.l from local vectors, the mirror of wo about +z dotted with wi.
fn r_dot_l(wo: V3<f64>, wi: V3<f64>) -> f64 {
    dot(V3::new(-wo.x, -wo.y, wo.z), wi)
}

fn n_dot_h(wo: V3<f64>, wi: V3<f64>) -> f64 {
    normalize(wo + wi).z
}

fn albedo(theta_deg: f64, f: impl Fn(V3<f64>, V3<f64>) -> f64) -> Estimate {
    let e = directional_albedo(wo(theta_deg), f);
    assert!(e.value.is_finite() && e.error.is_finite(), "{e:?}");
    e
}

/// Albedo table of `f(n)` over EXPONENTS x THETAS_DEG, printed in one piece (tests run in
/// parallel). Returns the largest (albedo - error estimate) over `allowance(n)`, with where it
/// occurs.
fn table(
    name: &str,
    allowance: impl Fn(f64) -> f64,
    f: impl Fn(f64, V3<f64>, V3<f64>) -> f64,
) -> (f64, f64, f64) {
    use core::fmt::Write;
    let mut out = String::new();
    writeln!(
        out,
        "{name}: directional albedo, rows exponent n, columns theta_o (degrees)"
    )
    .unwrap();
    write!(out, "{:>8}", "n").unwrap();
    for t in THETAS_DEG {
        write!(out, "{t:>9}").unwrap();
    }
    writeln!(out).unwrap();
    let mut worst = (f64::NEG_INFINITY, 0.0, 0.0);
    let mut max_err: f64 = 0.0;
    for n in EXPONENTS {
        write!(out, "{n:>8}").unwrap();
        for t in THETAS_DEG {
            let e = albedo(t, |o, i| f(n, o, i));
            write!(out, "{:>9.6}", e.value).unwrap();
            max_err = max_err.max(e.error);
            let excess = (e.value - e.error) / allowance(n);
            if excess > worst.0 {
                worst = (excess, n, t);
            }
        }
        writeln!(out).unwrap();
    }
    writeln!(
        out,
        "{name}: max (albedo - error estimate) / allowance {:.9} at n = {}, theta_o = {} deg; largest error estimate {max_err:.1e}",
        worst.0, worst.1, worst.2
    )
    .unwrap();
    println!("{out}");
    worst
}

#[test]
fn classic_phong_albedo_exceeds_one() {
    let ks = 1.0;
    let (worst, n, t) = table(
        "classic Phong (ks = 1)",
        |_| 1.0,
        |n, o, i| phong::classic(o.z, i.z, r_dot_l(o, i), ks, n),
    );
    // Lewis 1994: at normal incidence the albedo is 2 pi ks / (n + 1), 2 pi at n = 0.
    assert!(
        worst > 6.0,
        "classic Phong should reach 2 pi at n = 0: {worst}"
    );
    assert_eq!((n, t), (0.0, 0.0));
    // The exponent below which classic Phong breaks energy at normal incidence: 2 pi - 1.
    let n_cross = 2.0 * PI - 1.0;
    for (n, above) in [(n_cross - 0.05, true), (n_cross + 0.05, false)] {
        let e = albedo(0.0, |o, i| phong::classic(o.z, i.z, r_dot_l(o, i), ks, n));
        println!(
            "classic Phong n = {n:.4}, theta_o = 0: albedo {:.6} (closed form {:.6})",
            e.value,
            2.0 * PI / (n + 1.0)
        );
        assert_eq!(e.value > 1.0, above, "n = {n}: {}", e.value);
    }
}

/// Every energy-conserving model of the family stays <= 1 over the grid.
fn assert_bounded(name: &str, f: impl Fn(f64, V3<f64>, V3<f64>) -> f64) {
    let (worst, n, t) = table(name, |_| 1.0, f);
    assert!(
        worst <= 1.0,
        "{name}: albedo {worst} > 1 at n = {n}, theta_o = {t}"
    );
}

/// Modified Phong is bounded by its normal-incidence albedo 2 pi ks / (n + 2), which exceeds 1
/// for n < 2 pi - 2 (Lewis 1994): energy conserving only from there on.
#[test]
fn modified_phong_albedo_is_at_most_its_normal_incidence_value() {
    let allowance = |n: f64| 2.0 * PI / (n + 2.0);
    let (worst, n, t) = table(
        "modified Phong (ks = 1), bound 2 pi / (n + 2)",
        allowance,
        |n, o, i| phong::modified(o.z, i.z, r_dot_l(o, i), 1.0, n),
    );
    assert!(worst <= 1.0, "n = {n}, theta_o = {t}: {worst}");
    for n in EXPONENTS {
        let e = albedo(0.0, |o, i| phong::modified(o.z, i.z, r_dot_l(o, i), 1.0, n));
        println!(
            "modified Phong (ks = 1) n = {n}: normal-incidence albedo {:.6}",
            e.value
        );
        assert_eq!(e.value > 1.0, n < 2.0 * PI - 2.0, "n = {n}: {}", e.value);
    }
}

#[test]
fn normalized_phong_albedo_is_at_most_ks() {
    assert_bounded("normalized Phong (ks = 1)", |n, o, i| {
        phong::normalized(o.z, i.z, r_dot_l(o, i), 1.0, n)
    });
}

#[test]
fn diffuse_plus_normalized_phong_albedo_is_at_most_kd_plus_ks() {
    assert_bounded(
        "kd/pi + normalized Phong (kd = 0.4, ks = 0.6)",
        |n, o, i| phong::diffuse_specular(o.z, i.z, r_dot_l(o, i), 0.4, 0.6, n),
    );
}

#[test]
fn exactly_normalized_blinn_phong_albedo_is_at_most_one() {
    assert_bounded("Blinn-Phong, exact normalization (ks = 1)", |n, o, i| {
        phong::blinn_phong_normalized(o.z, i.z, n_dot_h(o, i), 1.0, n)
    });
}

fn assert_close(label: &str, e: Estimate, expected: f64) {
    let rel = (e.value - expected).abs() / expected;
    println!(
        "{label}: albedo {:.9} expected {expected:.9} rel err {rel:.1e} (estimate {:.1e}, {} evals)",
        e.value, e.error, e.evaluations
    );
    assert!(rel <= REL_TOL, "{label}: {} vs {expected}", e.value);
}

#[test]
fn normal_incidence_albedos_match_closed_forms() {
    for n in EXPONENTS {
        let ks = 0.8;
        assert_close(
            &format!("normalized Phong ks = {ks}, n = {n}"),
            albedo(0.0, |o, i| {
                phong::normalized(o.z, i.z, r_dot_l(o, i), ks, n)
            }),
            ks,
        );
        assert_close(
            &format!("modified Phong ks = {ks}, n = {n}"),
            albedo(0.0, |o, i| phong::modified(o.z, i.z, r_dot_l(o, i), ks, n)),
            ks * 2.0 * PI / (n + 2.0),
        );
        assert_close(
            &format!("classic Phong ks = {ks}, n = {n}"),
            albedo(0.0, |o, i| phong::classic(o.z, i.z, r_dot_l(o, i), ks, n)),
            ks * 2.0 * PI / (n + 1.0),
        );
        assert_close(
            &format!("Blinn-Phong exact normalization, n = {n}"),
            albedo(0.0, |o, i| {
                phong::blinn_phong_normalized(o.z, i.z, n_dot_h(o, i), 1.0, n)
            }),
            1.0,
        );
        let c = phong::blinn_phong_normalization_exact(n);
        assert_close(
            &format!("Blinn-Phong unnormalized, n = {n}"),
            albedo(0.0, |o, i| {
                phong::blinn_phong(o.z, i.z, n_dot_h(o, i), 1.0, n)
            }),
            1.0 / c,
        );
        assert_close(
            &format!("Blinn-Phong (n + 8) / (8 pi), n = {n}"),
            albedo(0.0, |o, i| {
                phong::blinn_phong_normalized_approx(o.z, i.z, n_dot_h(o, i), 1.0, n)
            }),
            phong::blinn_phong_normalization_approx(n) / c,
        );
        assert_close(
            &format!("Blinn-Phong NDF used as a BRDF, n = {n}"),
            albedo(0.0, |o, i| phong::blinn_phong_ndf(n_dot_h(o, i), n)),
            phong::phong_normalization(n) / c,
        );
    }
}

#[test]
fn blinn_phong_ndf_projected_area_is_one() {
    for n in EXPONENTS {
        let e = ndf_projected_area(|m| phong::blinn_phong_ndf(m.z, n));
        println!(
            "Blinn-Phong NDF n = {n}: integral D cos = {:.9} (+- {:.1e})",
            e.value, e.error
        );
        assert!((e.value - 1.0).abs() <= REL_TOL, "n = {n}: {}", e.value);
    }
}
