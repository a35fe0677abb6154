//! The DFG table is within 1e-4 of the exact split-sum integrals on every cell of a 64 x 64
//! grid at `dfg::DEFAULT_SAMPLES`, measured against two routes that share no code with the
//! visible-normal quadrature of `dfg::dfg`:
//!
//! - every cell: a deterministic product rule over the half vector in the coordinates of the
//!   GGX D cos distribution (u in [0, 1] with tan^2 theta_h = alpha^2 u / (1 - u), phi), with
//!   the horizon NoL = 0 solved in closed form for each phi so the u integral stops there:
//!   Gauss-Legendre in u on [0, u*(phi)] (smooth), trapezoid in phi on [0, pi] (even and
//!   periodic: spectral). The weight is 4 V F NoL v.h / n.h with `ggx::v_correlated`.
//! - a subset of cells: `integrate::directional_albedo_with` of D V F NoL, the BRDF itself,
//!   by adaptive cubature.
//!
//! Also: A, B >= 0, E <= 1, E -> 1 as alpha -> 0, the white-furnace values at alpha = 1, and
//! the table builder's layout and errors. `cargo test --test ibl dfg_accuracy:: -- --nocapture`
//! prints the figures.
#![cfg(all(feature = "ibl", feature = "integrate"))]

use brdf::V3;
use brdf::ggx;
use brdf::ibl::dfg;
use brdf::integrate::{Config, directional_albedo_with};

use crate::common::{dot, normalize};

const N: usize = 64;
/// Gauss-Legendre nodes per u panel and phi intervals of the reference rule.
const REF_GL: usize = 16;
const REF_PHI: usize = 96;

/// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from Chebyshev guesses).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (core::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 0.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// [A, B, E] by the product rule in D-cos coordinates (module docs). In s = 1 - u the
/// integrand varies on the scale of s near the horizon at grazing views, so [s*, 1] is cut
/// into panels growing by 4x from s* = 1 - u*, each with Gauss-Legendre.
fn reference(n_dot_v: f64, alpha: f64, gl: &[(f64, f64)], n_phi: usize) -> [f64; 3] {
    let cv = n_dot_v;
    let sv = ((1.0 - cv) * (1.0 + cv)).sqrt();
    // The kernels clamp alpha to ALPHA_MIN; D (which cancels) must use the same width.
    let alpha = alpha.max(brdf::microfacet::ALPHA_MIN);
    let a2 = alpha * alpha;
    let mut acc = [0.0; 2];
    for k in 0..=n_phi {
        let phi = core::f64::consts::PI * k as f64 / n_phi as f64;
        let trap = if k == 0 || k == n_phi { 0.5 } else { 1.0 };
        let cp = phi.cos();
        // NoL = 2 (v.h) cos(theta_h) - cv = 0 at tan(2 theta*) = -cv / (sv cos(phi)).
        let t = (0.5 * cv.atan2(-sv * cp)).tan();
        let mut lo = a2 / (a2 + t * t);
        let mut row = [0.0; 2];
        while lo < 1.0 {
            let hi = if lo * 4.0 > 0.5 { 1.0 } else { lo * 4.0 };
            for &(x, w) in gl {
                let s = lo + 0.5 * (hi - lo) * (x + 1.0);
                let u = 1.0 - s;
                let den = s + a2 * u;
                let ch = (s / den).sqrt();
                let sh = (a2 * u / den).sqrt();
                let vh = sv * sh * cp + cv * ch;
                let nl = 2.0 * vh * ch - cv;
                if nl <= 0.0 || vh <= 0.0 {
                    continue;
                }
                // f cos / pdf with pdf = D cos(theta_h) / (4 v.h): D cancels.
                let g = 4.0 * ggx::v_correlated(cv, nl, alpha) * nl * vh / ch;
                let fc = (1.0 - vh).powi(5);
                let ww = w * 0.5 * (hi - lo);
                row[0] += ww * g * (1.0 - fc);
                row[1] += ww * g * fc;
            }
            lo = hi;
        }
        acc[0] += trap * row[0];
        acc[1] += trap * row[1];
    }
    // (u, phi) has density 1 / (2 pi); phi in [0, pi] counts twice by symmetry.
    let (a, b) = (acc[0] / n_phi as f64, acc[1] / n_phi as f64);
    [a, b, a + b]
}

fn cell(i: usize, j: usize) -> (f64, f64) {
    let n_dot_v = (i as f64 + 0.5) / N as f64;
    let r = (j as f64 + 0.5) / N as f64;
    (n_dot_v, r * r)
}

#[test]
fn reference_rule_has_converged() {
    // The reference must be far more accurate than the 1e-4 it checks: raising both its
    // orders must move no cell by more than 2e-5.
    let (gl1, gl2) = (gauss_legendre(REF_GL), gauss_legendre(24));
    let mut worst = 0.0_f64;
    for j in (0..N).step_by(3) {
        for i in (0..N).step_by(3) {
            let (nv, a) = cell(i, j);
            let r1 = reference(nv, a, &gl1, REF_PHI);
            let r2 = reference(nv, a, &gl2, 192);
            for c in 0..3 {
                worst = worst.max((r1[c] - r2[c]).abs());
            }
        }
    }
    println!(
        "reference rule: max change from ({REF_GL} GL, {REF_PHI} phi) to (24 GL, 192 phi) \
         over a 22 x 22 subgrid: {worst:.2e}"
    );
    assert!(worst < 2e-5, "reference not converged: {worst:e}");
}

#[test]
fn table_within_1e4_of_exact_at_64x64_default_samples() {
    let mut t = vec![[0.0_f32; 3]; N * N];
    let start = std::time::Instant::now();
    dfg::table(&mut t, N, N, dfg::DEFAULT_SAMPLES).unwrap();
    let elapsed = start.elapsed();
    let gl = gauss_legendre(REF_GL);
    let mut worst = [0.0_f64; 3];
    let mut at = [(0, 0); 3];
    let mut sum2 = [0.0_f64; 3];
    for j in 0..N {
        for i in 0..N {
            let (nv, a) = cell(i, j);
            let r = reference(nv, a, &gl, REF_PHI);
            for c in 0..3 {
                let e = (f64::from(t[j * N + i][c]) - r[c]).abs();
                sum2[c] += e * e;
                if e > worst[c] {
                    worst[c] = e;
                    at[c] = (i, j);
                }
            }
        }
    }
    println!(
        "64 x 64 table, {} samples per cell, built in {:.2} s",
        dfg::DEFAULT_SAMPLES,
        elapsed.as_secs_f64()
    );
    for (c, name) in ["A", "B", "E"].iter().enumerate() {
        println!(
            "  {name}: max |error| {:.2e} at (NoV cell {}, r cell {}), RMS {:.2e}",
            worst[c],
            at[c].0,
            at[c].1,
            (sum2[c] / (N * N) as f64).sqrt()
        );
    }
    // The target.
    for w in worst {
        assert!(w <= 1e-4, "table error {w:e} above 1e-4");
    }
}

#[test]
fn dfg_error_falls_with_samples() {
    // Max error over a 16 x 16 subgrid of the 64 x 64 cells for each sample count: the
    // figure behind DEFAULT_SAMPLES.
    let gl = gauss_legendre(REF_GL);
    let refs: Vec<_> = (0..N)
        .step_by(4)
        .flat_map(|j| (0..N).step_by(4).map(move |i| (i, j)))
        .map(|(i, j)| {
            let (nv, a) = cell(i, j);
            (nv, a, reference(nv, a, &gl, REF_PHI))
        })
        .collect();
    let mut last = f64::INFINITY;
    for samples in [1024, 4096, 16384, 32768] {
        let mut worst = 0.0_f64;
        for &(nv, a, r) in &refs {
            let d = dfg::dfg(nv, a, samples);
            for c in 0..3 {
                worst = worst.max((d[c] - r[c]).abs());
            }
        }
        println!("samples {samples:5}: max |error| {worst:.2e} (16 x 16 subgrid)");
        assert!(worst < last * 1.2, "error grew with samples");
        last = worst;
    }
}

#[test]
fn dfg_agrees_with_adaptive_cubature_of_the_brdf() {
    // The BRDF D V F NoL integrated by the crate's adaptive cubature (no sampling at all).
    // Cells with alpha >= 0.01: narrower lobes need more rectangles than the integrator holds.
    let cfg = Config {
        abs_tol: 1e-8,
        rel_tol: 1e-8,
        max_evals: 3_000_000,
    };
    let mut worst = 0.0_f64;
    let mut worst_est = 0.0_f64;
    for j in [7, 15, 31, 47, 63] {
        for i in [0, 5, 21, 42, 63] {
            let (nv, alpha) = cell(i, j);
            let wo = V3::new(((1.0 - nv) * (1.0 + nv)).sqrt(), 0.0, nv);
            let term = |weight: fn(f64) -> f64| {
                directional_albedo_with(
                    wo,
                    |o, l| {
                        let h = normalize(o + l);
                        let vh = dot(o, h);
                        let fc = (1.0 - vh.clamp(0.0, 1.0)).powi(5);
                        ggx::d(h.z, alpha) * ggx::v_correlated(o.z, l.z, alpha) * weight(fc)
                    },
                    &cfg,
                )
            };
            let a = term(|fc| 1.0 - fc);
            let b = term(|fc| fc);
            let d = dfg::dfg(nv, alpha, dfg::DEFAULT_SAMPLES);
            worst = worst
                .max((d[0] - a.value).abs())
                .max((d[1] - b.value).abs());
            worst_est = worst_est.max(a.error).max(b.error);
        }
    }
    println!(
        "dfg vs adaptive cubature (25 cells, alpha >= 0.0035): max |error| {worst:.2e} \
         (cubature's own estimate <= {worst_est:.1e})"
    );
    assert!(worst < 1e-4 + worst_est, "{worst:e}");
}
