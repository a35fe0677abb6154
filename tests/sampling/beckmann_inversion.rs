//! `sampling::beckmann_vndf` inverts the slope marginal's CDF: for the returned normal m, the
//! slope x it was built from (recovered by undoing the stretch by alpha and the rotation by
//! wo's azimuth, as the sampler applies them) satisfies CDF(x) = u1 to within the rounding of
//! the float type, on f32, f64, f32x8 and f64x4, over views from normal incidence to 89.99
//! degrees, alpha from ALPHA_MIN to ALPHA_MAX (isotropic and anisotropic), and u1 from 0 to the
//! largest float below 1.
//!
//! The CDF of the unit configuration seen from theta (Heitz and d'Eon 2014) is
//! C(x) = norm (1 + erf(x) + tan(theta) exp(-x^2) / sqrt(pi)) for x <= cot(theta), and it is
//! evaluated here in f64 without cancellation on either side: the head with erfc for x < 0,
//! the tail 1 - C(x) = norm integral_x^cot 2 / sqrt(pi) exp(-t^2) (1 - t tan) dt in closed
//! form where x tan <= 1/2 and by Gauss-Legendre quadrature of its positive integrand above.
//!
//! The bound is a backward error: |C(x) - u1| within K times the change in C that rounding
//! the output can explain: eps (one unit of u1's scale), the erf-space step eps of the solve
//! (norm |1 - x tan| eps in C), and moving x by eps (1 + |x| + |y|) (the normal's rounding,
//! seen through the unstretch and the unrotation) and tan(theta) by a relative eps.
#![cfg(all(feature = "sampling", feature = "beckmann"))]

use brdf::beckmann::Beckmann;
use brdf::microfacet::{ALPHA_MAX, ALPHA_MIN};
use brdf::sampling::beckmann_vndf;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

use crate::common;
use common::Rng;

const FRAC_1_SQRT_PI: f64 = 0.564_189_583_547_756_3;

/// 8-point Gauss-Legendre nodes and weights on [-1, 1].
const GL8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// (C(x), 1 - C(x)) for the unit configuration with tan(theta) = `tan`, each to f64 precision
/// relative to itself.
fn cdf(x: f64, tan: f64) -> (f64, f64) {
    let cot = if tan > 0.0 {
        tan.recip()
    } else {
        f64::INFINITY
    };
    let tail_cot = if tan > 0.0 {
        tan * FRAC_1_SQRT_PI * (-cot * cot).exp()
    } else {
        0.0
    };
    let norm = (1.0 + libm::erf(cot) + tail_cot).recip();
    if x >= cot {
        return (1.0, 0.0);
    }
    let gauss = (-x * x).exp();
    let head = if x < 0.0 {
        libm::erfc(-x)
    } else {
        1.0 + libm::erf(x)
    } + tan * FRAC_1_SQRT_PI * gauss;
    let tail = if x * tan <= 0.5 {
        // erfc(x) - erfc(cot) - tan / sqrt(pi) (exp(-x^2) - exp(-cot^2)): at most a factor 4
        // of cancellation for x <= cot / 2 (the integrand 1 - t tan stays above 1/2 on the
        // part of [x, cot] below cot / 2, which holds most of the Gaussian's weight).
        let gauss_diff = if tan > 0.0 {
            -gauss * libm::expm1(x * x - cot * cot)
        } else {
            0.0
        };
        // erf(cot) - erf(x) as erfc(x) - erfc(cot) where both erfc are below 1/2, so that
        // neither difference cancels (x <= cot / 2).
        let erf_diff = if x > 0.5 {
            libm::erfc(x) - libm::erfc(cot)
        } else {
            libm::erf(cot) - libm::erf(x)
        };
        erf_diff - tan * FRAC_1_SQRT_PI * gauss_diff
    } else {
        // 2 tan / sqrt(pi) integral_0^d s exp(-(cot - s)^2) ds, d = cot - x: positive
        // integrand, increasing in s; beyond 20 / x below d it is below exp(-40) of its peak.
        let d = cot - x;
        let lo = (d - 20.0 / x).max(0.0);
        let panels = 64;
        let h = (d - lo) / panels as f64;
        let mut sum = 0.0;
        for p in 0..panels {
            let mid = lo + (p as f64 + 0.5) * h;
            for &(node, weight) in &GL8 {
                for s in [mid - node * h / 2.0, mid + node * h / 2.0] {
                    sum += weight * s * (-(cot - s) * (cot - s)).exp();
                }
            }
        }
        2.0 * tan * FRAC_1_SQRT_PI * sum * h / 2.0
    };
    (norm * head, norm * tail)
}

/// One case's outcome: the residual C(x) - u1, its ratio to the rounding bound, and for
/// u1 > 1/2 the relative error of the tail, (1 - C(x)) / (1 - u1) - 1.
#[derive(Clone, Copy, Default)]
struct Case {
    resid: f64,
    score: f64,
    tail_rel: f64,
}

struct Worst {
    resid: (f64, String),
    score: (f64, String),
    tail_rel: (f64, String),
    /// Worst tail relative error by decade of 1 - u1: index k for 1 - u1 in (1e-(k+1), 1e-k].
    tail_by_decade: [f64; 17],
    cases: usize,
}

impl Worst {
    fn new() -> Self {
        let z = || (0.0, String::new());
        Self {
            resid: z(),
            score: z(),
            tail_rel: z(),
            tail_by_decade: [0.0; 17],
            cases: 0,
        }
    }
    fn add(&mut self, c: Case, eps: f64, u1: f64, at: impl Fn() -> String) {
        self.cases += 1;
        if u1 > 0.5 {
            let k = ((-(1.0 - u1).log10()).floor() as usize).min(16);
            self.tail_by_decade[k] = self.tail_by_decade[k].max(c.tail_rel.abs());
        }
        let r = c.resid.abs() / eps;
        if r.is_nan() || r > self.resid.0 {
            self.resid = (r, at());
        }
        if c.score.is_nan() || c.score > self.score.0 {
            self.score = (c.score, at());
        }
        if c.tail_rel.is_nan() || c.tail_rel.abs() > self.tail_rel.0 {
            self.tail_rel = (c.tail_rel.abs(), at());
        }
    }
}

/// The residual of one returned normal `m` (f64 copies of one lane), for the stretched view
/// `v` and the alphas the sampler used, and u1, u2 as the sampler clamps them.
fn measure(m: [f64; 3], v: [f64; 3], ax: f64, ay: f64, u1: f64, eps: f64) -> (Case, f64, f64) {
    let sin_t = v[0].mul_add(v[0], v[1] * v[1]).sqrt();
    let tan = sin_t / v[2];
    let (cos_p, sin_p) = if sin_t > 0.0 {
        (v[0] / sin_t, v[1] / sin_t)
    } else {
        (1.0, 0.0)
    };
    // m = normalize(-ax rx, -ay ry, 1): undo the stretch, then the rotation.
    let rx = -m[0] / (m[2] * ax);
    let ry = -m[1] / (m[2] * ay);
    let x = cos_p * rx + sin_p * ry;
    let y = -sin_p * rx + cos_p * ry;
    let upper = u1 > 0.5;
    let (c, t) = cdf(x, tan);
    let resid = if upper { (1.0 - u1) - t } else { c - u1 };
    let tail_rel = if upper { t / (1.0 - u1) - 1.0 } else { 0.0 };
    // Rounding bound: see the module doc.
    let cot = if tan > 0.0 {
        tan.recip()
    } else {
        f64::INFINITY
    };
    let norm = cdf(f64::NEG_INFINITY, tan).1.recip();
    let delta = eps * (1.0 + x.abs() + y.abs());
    let mut band = eps * (1.0 + norm * (1.0 - x.min(cot) * tan).abs());
    for xs in [x - delta, x, x + delta] {
        for ts in [tan * (1.0 - eps), tan, tan * (1.0 + eps)] {
            let (c2, t2) = cdf(xs, ts);
            let change = if upper { t2 - t } else { c2 - c };
            band = band.max(change.abs() + eps);
        }
    }
    let score = resid.abs() / band;
    (
        Case {
            resid,
            score,
            tail_rel,
        },
        x,
        tan.atan().to_degrees(),
    )
}

/// The smaller grid in debug builds (`cargo test` in CI), the full one in release or with
/// BECKMANN_INVERSION_FULL set (about 3 s in debug as well).
fn small() -> bool {
    cfg!(debug_assertions) && std::env::var_os("BECKMANN_INVERSION_FULL").is_none()
}

/// Views (degrees from the normal), alphas (x, y) and the view's azimuth.
fn configs() -> Vec<(f64, f64, f64, f64)> {
    let thetas: &[f64] = if small() {
        &[0.0, 0.5, 15.0, 30.0, 60.0, 80.0, 89.0, 89.9, 89.99]
    } else {
        &[
            0.0, 1e-3, 0.5, 5.0, 15.0, 30.0, 45.0, 60.0, 70.0, 80.0, 85.0, 88.0, 89.0, 89.5, 89.9,
            89.95, 89.99,
        ]
    };
    let mut alphas: Vec<(f64, f64, f64)> = [ALPHA_MIN, 0.01, 0.1, 0.5, 1.0, 10.0, ALPHA_MAX]
        .iter()
        .map(|&a| (a, a, 0.9))
        .collect();
    for (ax, ay) in [(0.1, 1.0), (ALPHA_MAX, 0.01), (0.5, ALPHA_MIN)] {
        for phi in [0.0, 0.9, core::f64::consts::FRAC_PI_2] {
            alphas.push((ax, ay, phi));
        }
    }
    let mut out = Vec::new();
    for &t in thetas {
        for &(ax, ay, phi) in &alphas {
            out.push((t, ax, ay, phi));
        }
    }
    out
}

const U1: [f64; 20] = [
    0.0,
    1e-7,
    1e-6,
    1e-5,
    1e-3,
    0.01,
    0.1,
    0.3,
    0.5,
    0.7,
    0.9,
    0.99,
    1.0 - 1e-3,
    1.0 - 1e-5,
    1.0 - 1e-6,
    1.0 - 1e-7,
    1.0 - 1.0 / 16_777_216.0,
    1.0 - 1e-12,
    1.0 - f64::EPSILON / 2.0,
    1.0,
];
const U2: [f64; 3] = [1e-3, 0.5, 0.9];

/// One call of the sampler on `T` for one view and alpha, lane `i` drawing `u1(i)`, `u2(i)`.
#[allow(clippy::too_many_arguments)]
fn call<T: Real>(
    worst: &mut Worst,
    theta: f64,
    ax: f64,
    ay: f64,
    phi: f64,
    u1: impl Fn(usize) -> f64,
    u2: impl Fn(usize) -> f64,
) {
    let eps: f64 = T::EPSILON.lane(0).into();
    let th = theta.to_radians();
    let wo = V3::new(
        T::splat(th.sin() * phi.cos()),
        T::splat(th.sin() * phi.sin()),
        T::splat(th.cos()),
    );
    let (tax, tay) = (T::splat(ax), T::splat(ay));
    let b = Beckmann::new(tax, tay).unwrap();
    // The stretched view as the sampler computes it (`stretch`), in T.
    let v = V3::new(tax * wo.x, tay * wo.y, wo.z.abs()).normalize_or(V3::unit_z());
    let floor: f64 = T::splat(1e-6).lane(0).into();
    let top: f64 = (T::ONE - T::EPSILON * T::HALF).lane(0).into();
    let u1 = T::from_fn(|i| T::splat(u1(i)).lane(0));
    let u2 = T::from_fn(|i| T::splat(u2(i)).lane(0));
    let (m, _) = beckmann_vndf(&b, wo, u1, u2);
    for i in 0..T::LANES {
        let f = |t: T| -> f64 { t.lane(i).into() };
        let u: f64 = f(u1).clamp(floor, top);
        let (case, x, th_v) = measure(
            [f(m.x), f(m.y), f(m.z)],
            [f(v.x), f(v.y), f(v.z)],
            ax,
            ay,
            u,
            eps,
        );
        worst.add(case, eps, u, || {
            format!(
                "theta_o {theta} deg (stretched {th_v:.6} deg), alpha ({ax}, {ay}), phi_o {phi}, \
                 u1 {u:e} (1 - u1 = {:e}), u2 {}, x {x:.9}, resid {:.3e}, score {:.2}, \
                 tail rel {:.3e}",
                1.0 - u,
                f(u2),
                case.resid,
                case.score,
                case.tail_rel
            )
        });
    }
}

/// The grid on `T`, lane `i` of a call taking u1 = U1[(k + i) % 20] and
/// u2 = U2[(k / 20 + 2 i) % 3], so lanes mix tail and head values; then random views, alphas
/// (log-uniform over the whole domain, each axis) and u1 (uniform, or log-uniform towards 0
/// or towards 1).
fn sweep<T: Real>() -> Worst {
    let mut worst = Worst::new();
    for (theta, ax, ay, phi) in configs() {
        for k in 0..U1.len() * U2.len() {
            let u1 = |i: usize| U1[(k + i) % U1.len()];
            let u2 = |i: usize| U2[(k / U1.len() + 2 * i) % U2.len()];
            call::<T>(&mut worst, theta, ax, ay, phi, u1, u2);
        }
    }
    let mut rng = Rng(0x5eed_b3c4);
    let calls = if small() { 1_000 } else { 20_000 };
    let (lo, hi) = (ALPHA_MIN.ln(), ALPHA_MAX.ln());
    for _ in 0..calls {
        let mut r = || rng.next_f64();
        // Half the views within a degree of grazing, down to 1e-6 degrees from it.
        let theta = if r() < 0.5 {
            90.0 * r()
        } else {
            90.0 - 10f64.powf(-6.0 * r())
        };
        let ax = (lo + (hi - lo) * r()).exp();
        let ay = if r() < 0.5 {
            ax
        } else {
            (lo + (hi - lo) * r()).exp()
        };
        let phi = core::f64::consts::TAU * r();
        let us: Vec<(f64, f64)> = (0..T::LANES)
            .map(|_| {
                let pick = r();
                let u1 = if pick < 1.0 / 3.0 {
                    r()
                } else if pick < 2.0 / 3.0 {
                    1.0 - 10f64.powf(-17.0 * r())
                } else {
                    10f64.powf(-7.0 * r())
                };
                (u1, r())
            })
            .collect();
        call::<T>(&mut worst, theta, ax, ay, phi, |i| us[i].0, |i| us[i].1);
    }
    worst
}

/// Backward error bound, in units of the rounding bound of the module doc: 4 leaves room for
/// the few roundings of the erf^-1 polish and of the stretch that the bound counts once.
const K: f64 = 4.0;

#[test]
fn beckmann_vndf_inverts_the_slope_cdf_on_every_type() {
    let results = [
        ("f32", sweep::<f32>()),
        ("f64", sweep::<f64>()),
        ("f32x8", sweep::<f32x8>()),
        ("f64x4", sweep::<f64x4>()),
    ];
    let mut failed = Vec::new();
    for (name, w) in &results {
        println!("{name}: {} cases", w.cases);
        println!(
            "  worst |C(x) - u1| = {:.3e} eps at {}",
            w.resid.0, w.resid.1
        );
        println!("  worst score = {:.3} at {}", w.score.0, w.score.1);
        println!(
            "  worst tail |(1 - C) / (1 - u1) - 1| = {:.3e} at {}",
            w.tail_rel.0, w.tail_rel.1
        );
        let decades: Vec<String> = w
            .tail_by_decade
            .iter()
            .enumerate()
            .map(|(k, e)| format!("1e-{k}: {e:.1e}"))
            .collect();
        println!(
            "  worst tail relative error by 1 - u1: {}",
            decades.join(", ")
        );
        if w.score.0.is_nan() || w.score.0 > K {
            failed.push(*name);
        }
    }
    assert!(failed.is_empty(), "backward error above {K} on {failed:?}");
}

/// The f64 CDF agrees with itself across the switch between its closed-form and quadrature
/// tails, and its two halves add to 1.
#[test]
fn reference_cdf_is_consistent() {
    for tan in [0.0, 1e-3, 0.3, 1.0, 5.0, 100.0, 1e4] {
        let cot = if tan > 0.0 { 1.0 / tan } else { 1e300 };
        for x in [-5.0, -1.0, 0.0, 0.3, 1.0, 2.5, 6.0] {
            let (c, t) = cdf(x.min(cot), tan);
            assert!((c + t - 1.0).abs() < 1e-14, "tan {tan} x {x}: {c} + {t}");
        }
        if tan > 0.0 {
            // Just either side of the switch at x = cot / 2.
            let (_, a) = cdf(0.5 * cot * (1.0 - 1e-15), tan);
            let (_, b) = cdf(0.5 * cot * (1.0 + 1e-15), tan);
            if a == 0.0 && b == 0.0 {
                continue; // both underflow: cot / 2 is far out in the Gaussian's tail
            }
            assert!((a / b - 1.0).abs() < 1e-13, "tan {tan}: {a} vs {b}");
        }
    }
}

/// `erf_inv` is relative to 1 - |y| in its tails (the sampler's slope at u1 near 1 is
/// erf^-1 of b near 1): erfc(x) = q = 1 - y to within the rounding of x, (1 + 2 x^2) eps
/// relative, for q = 2^-k down to 2^-30 in f64 and to f32's smallest step below 1, 2^-24.
/// Below 2^-30 Giles' polynomial (fit for f32's range) starts the two Newton steps too far
/// off for them to finish: erfc(x) / q - 1 reaches 1.9e-3 at q = 2^-53, bounded here at 4e-3.
/// Plain Newton on erf(x) - y gave erfc(x) / q - 1 = 84 at q = 2^-51.
#[test]
fn erf_inv_is_relative_in_the_tails() {
    let mut worst = (0.0_f64, 0.0_f64);
    let mut worst_far = 0.0_f64;
    for k in 2..=53 {
        let q = 0.5_f64.powi(k);
        let mut cases = vec![
            (brdf::sampling::erf_inv(1.0 - q), f64::EPSILON),
            (-brdf::sampling::erf_inv(q - 1.0), f64::EPSILON),
        ];
        if k <= 24 {
            let x = brdf::sampling::erf_inv(1.0 - q as f32);
            cases.push((f64::from(x), f64::from(f32::EPSILON)));
        }
        for (x, eps) in cases {
            let rel = (libm::erfc(x) / q - 1.0).abs();
            if k > 30 {
                worst_far = worst_far.max(rel);
                continue;
            }
            let ulps = rel / ((1.0 + 2.0 * x * x) * eps);
            if ulps > worst.0 {
                worst = (ulps, q);
            }
        }
    }
    println!(
        "erf_inv tails: worst {:.2} (1 + 2 x^2) eps at q = {:e}; below 2^-30: {worst_far:.2e}",
        worst.0, worst.1
    );
    // 4: the roundings of x (1 + 2 x^2 eps in erfc) and of erfc itself, with room.
    assert!(worst.0 <= 4.0, "{worst:?}");
    assert!(worst_far <= 4e-3, "{worst_far}");
}
