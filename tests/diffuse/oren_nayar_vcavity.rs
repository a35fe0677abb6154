//! The full Oren-Nayar model's direct term L1 against the paper's own definition, evaluated
//! numerically: Oren and Nayar 1994 define the rough surface as V-cavities of Lambertian
//! facets with a Gaussian distribution of facet slope angles theta_a (standard deviation
//! sigma, isotropic in azimuth) and the direct radiance as
//!
//! ```text
//! L1 = integral over facet normals a of P(a) (rho / pi) E0 <s,a> <v,a> / (<a,n> <v,n>) GAF dw_a
//! GAF = min(1, 2 <a,n> <s,n> / <s,a>, 2 <a,n> <v,n> / <v,a>)   (V-groove masking-shadowing)
//! P(a) proportional to exp(-theta_a^2 / (2 sigma^2)), normalized over the hemisphere
//! ```
//!
//! (facet radiance times its projected area towards v over the macro surface's; the V-groove
//! shadowed and masked parts both start at the groove bottom, hence the min). The full model
//! is the paper's closed-form fit to this integral, so the two must agree to the fit's
//! accuracy; this test measures that accuracy and pins it. L1 is extracted from
//! `oren_nayar_full` as 4 f(rho = 1/2) - f(rho = 1) (f = rho L1 / pi + rho^2 L2 / pi). The
//! qualitative model's distance from the same integral is printed for comparison.
//!
//! What this does not check: the interreflection term L2 (the paper derives it separately,
//! by an approximation for which no independent definition is evaluated here).
//!
//! `cargo test --no-default-features --features diffuse,integrate --test diffuse
//! oren_nayar_vcavity:: -- --nocapture` prints the table.
#![cfg(all(feature = "diffuse", feature = "integrate"))]

use brdf::V3;
use brdf::diffuse::{oren_nayar, oren_nayar_full};
use brdf::integrate::{Config, hemisphere};
use core::f64::consts::PI;

use crate::common::dot;

fn cfg() -> Config {
    Config {
        abs_tol: 1e-9,
        rel_tol: 1e-6,
        max_evals: 300_000,
    }
}

/// The V-cavity direct term as a BRDF (rho = 1): L1 / (E0 cos(theta_i)).
fn vcavity_l1(v: V3<f64>, l: V3<f64>, sigma: f64) -> (f64, f64) {
    let p = |a: V3<f64>| {
        let t = a.z.clamp(-1.0, 1.0).acos();
        (-t * t / (2.0 * sigma * sigma)).exp()
    };
    let norm = hemisphere(p, &[], &cfg());
    let radiance = hemisphere(
        |a| {
            let (sa, va) = (dot(l, a), dot(v, a));
            if sa <= 0.0 || va <= 0.0 {
                return 0.0;
            }
            let gaf = 1f64.min(2.0 * a.z * l.z / sa).min(2.0 * a.z * v.z / va);
            p(a) * sa * va / (a.z * v.z) * gaf / PI
        },
        &[l, v],
        &cfg(),
    );
    let value = radiance.value / norm.value / l.z;
    (value, radiance.error / norm.value / l.z)
}

/// Bound on the deviation for phi in {0, 90} deg (measured maximum plus ~20 %).
const BACK_BOUND: f64 = 0.09;

fn dir(theta_deg: f64, phi_deg: f64) -> V3<f64> {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    V3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

#[test]
fn full_model_l1_fits_the_v_cavity_integral() {
    let thetas = [0.0, 30.0, 60.0, 75.0];
    let phis = [0.0, 90.0, 180.0];
    let (mut worst_full, mut worst_back) = (0.0f64, 0.0f64);
    println!(
        "sigma  max pi |L1_full - V|   max pi |qualitative - V|   (V: V-cavity integral, rho = 1)"
    );
    for sigma in [0.1, 0.2, 0.3, 0.4] {
        let (mut ef, mut eq, mut est, mut eb) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        let mut at = (0.0, 0.0, 0.0);
        for &ti in &thetas {
            for &to in &thetas {
                for &ph in &phis {
                    let (v, l) = (dir(to, 0.0), dir(ti, ph));
                    let (reference, err) = vcavity_l1(v, l, sigma);
                    est = est.max(err / reference);
                    let k = |rho| oren_nayar_full(v.z, l.z, dot(v, l), rho, sigma);
                    let full_l1 = 4.0 * k(0.5) - k(1.0);
                    let q = oren_nayar(v.z, l.z, dot(v, l), 1.0, sigma);
                    // In units of the Lambertian value 1/pi: the relative error is meaningless
                    // where forward-grazing shadowing drives the integral towards 0.
                    let e = (full_l1 - reference).abs() * PI;
                    if ph < 180.0 {
                        eb = eb.max(e);
                    }
                    if e > ef {
                        ef = e;
                        at = (ti, to, ph);
                    }
                    eq = eq.max((q - reference).abs() * PI);
                }
            }
        }
        println!(
            "{sigma:>5}  {ef:>8.4} at (theta_i, theta_o, phi) = {at:?}; {eb:.4} for phi < 180   {eq:>8.4}   integrator err est {est:.1e}"
        );
        worst_full = worst_full.max(ef);
        worst_back = worst_back.max(eb);
    }
    println!(
        "worst full-model L1 deviation from the V-cavity integral: {worst_full:.4} / pi \
         (phi < 180 deg: {worst_back:.4} / pi)"
    );
    // The fit's accuracy as measured, with ~20 % headroom: 0.163 / pi overall (forward
    // scattering, theta_i = theta_o = 75 deg, where shadowing and masking dominate and the
    // fit is weakest), and the phi < 180 deg bound below. A wrong coefficient or a dropped
    // term shows up well beyond these (the qualitative model, which drops C3 and simplifies
    // C2, is off by 0.53 / pi).
    assert!(worst_full < 0.2, "{worst_full}");
    assert!(worst_back < BACK_BOUND, "{worst_back}");
}
