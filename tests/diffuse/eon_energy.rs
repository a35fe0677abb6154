//! EON is energy-preserving: with rho = 1 its directional albedo, integrated numerically, is 1
//! for every roughness sigma in [0, 1] and every view angle up to 89 degrees. The exact form
//! meets this to the integrator's accuracy; the fitted form (`eon_approx`) to the accuracy of
//! the paper's fit of the FON albedo.
#![cfg(all(feature = "diffuse", feature = "integrate"))]

use brdf::V3;
use brdf::diffuse::{eon, eon_approx};
use brdf::integrate::directional_albedo;

use crate::common::dot;

const SIGMAS: [f64; 7] = [0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0];
const THETAS_DEG: [f64; 9] = [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 88.0, 89.0];

fn wo(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin(), 0.0, t.cos())
}

/// Max |albedo - 1| over the grid for one kernel, with the integrator's largest error estimate.
fn furnace(name: &str, f: fn(f64, f64, f64, f64, f64) -> f64) -> (f64, f64) {
    use std::fmt::Write;
    let (mut worst, mut worst_est) = (0.0f64, 0.0f64);
    // One string, printed at once: the two tests run in parallel.
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{name}: directional albedo - 1 at rho = 1 (rows sigma, columns theta_o in degrees)"
    );
    let _ = write!(out, "  sigma ");
    for t in THETAS_DEG {
        let _ = write!(out, "{t:>10}");
    }
    let _ = writeln!(out);
    for sigma in SIGMAS {
        let _ = write!(out, "  {sigma:5.2} ");
        for t in THETAS_DEG {
            let o = wo(t);
            let e = directional_albedo(o, |a, b| f(a.z, b.z, dot(a, b), 1.0, sigma));
            let dev = e.value - 1.0;
            let _ = write!(out, "{dev:>10.2e}");
            worst = worst.max(dev.abs());
            worst_est = worst_est.max(e.error);
        }
        let _ = writeln!(out);
    }
    let _ = writeln!(
        out,
        "  max |albedo - 1| = {worst:.2e} (integrator's largest error estimate {worst_est:.1e})"
    );
    print!("{out}");
    (worst, worst_est)
}

#[test]
fn eon_exact_white_furnace_is_one() {
    let (worst, est) = furnace("eon", eon);
    // Exact in theory: what remains is the integrator's error (it targets 1e-7 relative, and
    // the kinks of the integrand, the s = 0 plane and theta_i = theta_o, lie on rectangle edges
    // here). Measured 5.1e-10; 1e-8 leaves room for rounding and fails for any formula error
    // (c1 - c2 off by 1e-6 moves the albedo by 8e-7).
    assert!(est < 1e-6, "integrator did not converge: {est}");
    assert!(worst < 1e-8, "white furnace off by {worst}");
}

#[test]
fn eon_approx_white_furnace_is_one_within_fit_error() {
    let (worst, _) = furnace("eon_approx", eon_approx);
    // The fitted E enters the compensation lobe twice (1 - E_o and the integral of 1 - E_i);
    // its error of up to 4.7e-4 (measured 5.3e-4 on the albedo) bounds it. 1e-3 is well under
    // the 1e-2 target and fails if a coefficient of the fit is wrong in its third digit.
    assert!(worst < 1e-3, "fitted white furnace off by {worst}");
    // ...and is not exact: a tighter bound here would mean the test no longer sees the fit.
    assert!(worst > 1e-5, "fit error suspiciously small: {worst}");
}
