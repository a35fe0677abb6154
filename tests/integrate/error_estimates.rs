//! The public integrators' reported error bounds the actual error, checked against closed
//! forms; all but two rows played no part in choosing [`KINK_SAFETY`]:
//!
//! 1. the Beckmann weak white furnace, alpha from ALPHA_MIN to 1, view angles up to 89 degrees,
//!    and the two hardest cases of the sweep [`KINK_SAFETY`] is read off (the last, ignored,
//!    test here);
//! 2. kinks off the rectangle edges: a tilted great circle (through [`smith_weak_furnace`]) and
//!    a ring (through [`hemisphere`], with and without a `peaks` direction on it);
//! 3. anisotropic NDFs (alpha_x / alpha_y = 1/100, 1/10, 10, 100): normalization, signed
//!    projected area and the weak furnace.
//!
//! Each case prints value, actual error, estimate and estimate / actual:
//! `cargo test --release --test integrate error_estimates:: -- --nocapture`.
#![cfg(all(feature = "integrate", feature = "ggx", feature = "beckmann"))]

use brdf::V3;
use brdf::beckmann::{self, Beckmann};
use brdf::ggx::Ggx;
use brdf::integrate::{
    Config, Estimate, KINK_SAFETY, hemisphere, ndf_projected_area, smith_weak_furnace,
};
use brdf::microfacet::{ALPHA_MIN, Microfacet};
use core::f64::consts::{FRAC_PI_2, PI};

use crate::common::dot;

/// Below this the actual error is the rounding of summing up to 4096 rectangles of terms
/// <= |exact| (a few hundred ULP at worst), not the rule's: no estimate is asked to cover it,
/// and no ratio is computed.
fn rounding_floor(exact: f64) -> f64 {
    1e-13 * exact.abs().max(1.0)
}

/// How the integrator scaled its raw estimate: 1 for [`hemisphere`] and
/// [`ndf_projected_area`], [`KINK_SAFETY`] for [`smith_weak_furnace`].
#[derive(Clone, Copy)]
enum Scale {
    Raw,
    Kink,
}

struct Row {
    case: String,
    exact: f64,
    est: Estimate,
    scale: Scale,
}

impl Row {
    fn new(case: String, exact: f64, est: Estimate, scale: Scale) -> Self {
        Self {
            case,
            exact,
            est,
            scale,
        }
    }
    fn actual(&self) -> f64 {
        (self.est.value - self.exact).abs()
    }
    /// estimate / actual, or None where the actual error is within rounding.
    fn ratio(&self) -> Option<f64> {
        let a = self.actual();
        (a > rounding_floor(self.exact)).then(|| self.est.error / a)
    }
    fn is_bound(&self) -> bool {
        self.actual() <= self.est.error + rounding_floor(self.exact)
    }
    /// Not absurdly loose: within 1e4 of the actual error, or within 100 of what the stopping
    /// rule asks for (`rel_tol` of the value, times the integrator's scale). Refinement stops
    /// as soon as the estimate meets `rel_tol`, so on an integral it resolves to 1e-12 the
    /// estimate sits near `rel_tol` whatever the actual error: that is the tolerance, not a
    /// loose estimate.
    fn is_not_loose(&self) -> bool {
        let factor = match self.scale {
            Scale::Raw => 1.0,
            Scale::Kink => KINK_SAFETY,
        };
        let requested = Config::default().rel_tol * factor * self.exact.abs();
        self.est.error <= 1e4 * self.actual() || self.est.error <= 100.0 * requested
    }
}

/// Prints the table (`-- --nocapture`) and returns its smallest estimate / actual.
fn table(title: &str, rows: &[Row]) -> f64 {
    println!("\n{title}");
    println!(
        "{:<46} {:>16} {:>9} {:>9} {:>9} {:>7}",
        "case", "value", "actual", "estimate", "est/act", "evals"
    );
    let mut min_ratio = f64::INFINITY;
    for r in rows {
        let ratio = r.ratio();
        let shown = ratio.map_or_else(|| "rounding".to_string(), |q| format!("{q:.2e}"));
        println!(
            "{:<46} {:>16.12} {:>9.2e} {:>9.2e} {:>9} {:>7}",
            r.case,
            r.est.value,
            r.actual(),
            r.est.error,
            shown,
            r.est.evaluations
        );
        if let Some(q) = ratio {
            min_ratio = min_ratio.min(q);
        }
    }
    println!("smallest estimate / actual: {min_ratio:.2e}");
    min_ratio
}

/// Every row's estimate bounds its actual error and is not absurdly loose.
fn assert_honest(title: &str, rows: &[Row]) {
    table(title, rows);
    let under: Vec<_> = rows.iter().filter(|r| !r.is_bound()).collect();
    let loose: Vec<_> = rows.iter().filter(|r| !r.is_not_loose()).collect();
    for r in &under {
        println!(
            "NOT A BOUND: {}: actual {:.3e} > estimate {:.3e}",
            r.case,
            r.actual(),
            r.est.error
        );
    }
    for r in &loose {
        println!(
            "LOOSE: {}: estimate {:.3e}, actual {:.3e}",
            r.case,
            r.est.error,
            r.actual()
        );
    }
    assert!(under.is_empty(), "{title}: an estimate under-reports");
    assert!(loose.is_empty(), "{title}: an estimate is absurdly loose");
}

/// A direction at `theta_deg` from the normal and azimuth `phi` (radians).
fn dir_at(theta_deg: f64, phi: f64) -> V3<f64> {
    let (s, c) = theta_deg.to_radians().sin_cos();
    V3::new(s * phi.cos(), s * phi.sin(), c)
}

/// The azimuth the crate's other integrator tests use, off both tangent axes (where the
/// initial partition has its edges), so nothing lines up by accident.
const PHI: f64 = 0.643_501_108_793_284_4; // atan2(0.6, 0.8)

/// Case 1. Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based
/// BRDFs", eq. 18 and section 5 (the weak white furnace): with G1 the Smith masking of D,
/// integral of G1(wo, m) max(0, wo.m) D(m) dm / cos(theta_o) = 1 for every wo. Here the
/// crate's isotropic Beckmann free functions `beckmann::d` and `beckmann::g1`; G1 is within
/// 2.3 ULP of exact (its docs), so the closed form 1 holds to 1e-15, far below any estimate.
///
/// The last two rows are the worst cases of a sweep (theta_o in 0.02 degree steps over 73 to
/// 76.5, 85.5 to 87 and 88.6 to 89.9 degrees, six azimuths, alpha 0.15 to 1, GGX and
/// Beckmann: 34 020 integrals), where the raw estimate under-reports by 990x and 1110x. At
/// 74.66 degrees the top of the kink circle wo.m = 0 (theta = 90 - theta_o) lies at
/// 0.267 rad, just past the initial partition's edge at 0.256 rad and in front of every
/// sample point of the rectangle behind it; at 89.8 degrees the circle passes 0.0035 rad from
/// the pole, where the polar grid is most distorted.
#[test]
fn beckmann_weak_furnace_estimate_bounds_the_actual_error() {
    let mut rows = Vec::new();
    for alpha in [ALPHA_MIN, 1e-3, 0.1, 0.5, 1.0] {
        for theta in [0.0, 45.0, 80.0, 85.0, 89.0] {
            let wo = dir_at(theta, PHI);
            let g1 = beckmann::g1(wo.z, alpha);
            let e = smith_weak_furnace(wo, |m| beckmann::d(m.z, alpha), |_, _| g1);
            let case = format!("beckmann furnace a={alpha} @ {theta} deg");
            rows.push(Row::new(case, 1.0, e, Scale::Kink));
        }
    }
    for (alpha, theta, phi) in [(0.25, 74.66, 0.0), (1.0, 89.8, 1.3)] {
        let wo = dir_at(theta, phi);
        let g1 = beckmann::g1(wo.z, alpha);
        let e = smith_weak_furnace(wo, |m| beckmann::d(m.z, alpha), |_, _| g1);
        let case = format!("beckmann furnace a={alpha} @ {theta} deg, phi {phi}");
        rows.push(Row::new(case, 1.0, e, Scale::Kink));
    }
    assert_honest("case 1: Beckmann weak furnace (x KINK_SAFETY)", &rows);
}

/// Case 2a. A kink on the tilted great circle a.m = 0: integral over the upper hemisphere of
/// max(0, a.m) dm = pi (1 + cos(theta_a)) / 2, the irradiance a plane of normal a receives
/// from a uniform upper sky of unit radiance (the sky view factor (1 + cos(beta)) / 2 of a
/// plane tilted by beta; Howell, Siegel and Menguc, "Thermal Radiation Heat Transfer",
/// appendix C). Checks: pi at theta_a = 0, pi / 2 at grazing (half the clamped cosine's pi).
/// Through [`smith_weak_furnace`] with D = 1 / pi and G1 = 1, whose integrand is exactly this
/// with a = wo: (1 + cos(theta_o)) / (2 cos(theta_o)).
///
/// Case 2b. A kink on the ring theta = theta_k = theta0 + pi / 2: integral over the hemisphere
/// of max(0, cos(theta - theta0)), theta0 < 0. In polar coordinates
/// 2 pi integral_0^theta_k cos(t - t0) sin(t) dt; cos(t - t0) sin(t) = (sin(2t - t0) + sin(t0)) / 2
/// integrates to (cos(t0) - cos(2 tk - t0)) / 4 + tk sin(t0) / 2, and 2 tk - t0 = t0 + pi, so
/// the integral is pi (cos(t0) + tk sin(t0)) (at t0 = 0: pi, the integral of cos(theta)).
/// [`hemisphere`] does not scale its estimate; with a `peaks` direction on the ring (the
/// module docs' advice) the ring is a rectangle edge and the estimate is a bound.
#[test]
fn kink_off_the_rectangle_edges_estimate_bounds_the_actual_error() {
    let mut rows = Vec::new();
    for theta in [10.0, 45.0, 70.0, 74.66, 85.0, 89.0, 89.8] {
        for phi in [PHI, 0.0] {
            let wo = dir_at(theta, phi);
            let e = smith_weak_furnace(wo, |_| 1.0 / PI, |_, _| 1.0);
            let case = format!("furnace D=1/pi G1=1 @ {theta} deg, phi {phi:.2}");
            rows.push(Row::new(case, (1.0 + wo.z) / (2.0 * wo.z), e, Scale::Kink));
        }
    }
    for theta0 in [-0.1_f64, -0.3, -0.6, -1.0, -1.3] {
        let theta_k = theta0 + FRAC_PI_2;
        let exact = PI * (theta0.cos() + theta_k * theta0.sin());
        let on_ring = dir_at(theta_k.to_degrees(), PHI);
        let e = hemisphere(
            |w| libm::cos(libm::acos(w.z) - theta0).max(0.0),
            &[on_ring],
            &Config::default(),
        );
        let case = format!("ring max(0,cos(t-({theta0}))), peak on ring");
        rows.push(Row::new(case, exact, e, Scale::Raw));
    }
    assert_honest("case 2: kinks off the rectangle edges", &rows);
}

/// The known flaw the module docs state, pinned: without a `peaks` direction on it, a ring
/// kink just past a rectangle edge (theta_k = 0.271 rad, edge at 0.256) lies in front of every
/// sample point of its rectangle, which reports zero error for the lobe's rim it never sees.
/// If this starts to fail the integrator got better: update the module docs.
#[test]
fn hemisphere_raw_estimate_misses_a_ring_kink_just_past_an_edge() {
    let theta0: f64 = -1.3;
    let exact = PI * (theta0.cos() + (theta0 + FRAC_PI_2) * theta0.sin());
    let e = hemisphere(
        |w| libm::cos(libm::acos(w.z) - theta0).max(0.0),
        &[],
        &Config::default(),
    );
    let row = Row::new("ring, no peak".into(), exact, e, Scale::Raw);
    table("known flaw: ring kink without a peak (raw)", &[row]);
    let actual = (e.value - exact).abs();
    assert!(
        actual > 1e-5 && actual > 1e4 * e.error,
        "actual {actual:.2e}, estimate {:.2e}",
        e.error
    );
}

/// Case 3. Anisotropic lobes, alpha_x / alpha_y = 1/100, 1/10, 10 and 100, crate's GGX and
/// Beckmann:
/// - normalization, integral of D(m) m.z dm = 1 (Walter et al. 2007, "Microfacet Models for
///   Refraction through Rough Surfaces", eq. 4);
/// - signed projected area onto wo, integral of D(m) (wo.m) dm = cos(theta_o) (Heitz 2014,
///   section 2: the microsurface's signed projected area onto any direction equals the
///   geometric surface's), an integrand that changes sign smoothly across wo.m = 0;
/// - the weak furnace of case 1 with the anisotropic Smith G1 (Heitz 2014, eq. 18).
#[test]
fn anisotropic_lobe_estimate_bounds_the_actual_error() {
    let cfg = Config::default();
    let mut rows = Vec::new();
    for (ax, ay) in [(0.05, 0.5), (0.5, 0.05), (0.01, 1.0), (0.3, 0.003)] {
        let g = Ggx::new(ax, ay).unwrap();
        let b = Beckmann::new(ax, ay).unwrap();
        let dg = |m: V3<f64>| g.d(m);
        let db = |m: V3<f64>| b.d(m);
        let area = ndf_projected_area(dg);
        rows.push(Row::new(
            format!("ggx area {ax}x{ay}"),
            1.0,
            area,
            Scale::Raw,
        ));
        let area = ndf_projected_area(db);
        rows.push(Row::new(
            format!("beckmann area {ax}x{ay}"),
            1.0,
            area,
            Scale::Raw,
        ));
        for theta in [30.0, 70.0, 89.0] {
            let wo = dir_at(theta, PHI);
            let e = hemisphere(|m| dg(m) * dot(wo, m), &[wo], &cfg);
            let case = format!("ggx signed proj {ax}x{ay} @ {theta}");
            rows.push(Row::new(case, wo.z, e, Scale::Raw));
            let e = hemisphere(|m| db(m) * dot(wo, m), &[wo], &cfg);
            let case = format!("beckmann signed proj {ax}x{ay} @ {theta}");
            rows.push(Row::new(case, wo.z, e, Scale::Raw));
            let g1 = g.g1(wo);
            let e = smith_weak_furnace(wo, dg, |_, _| g1);
            let case = format!("ggx furnace {ax}x{ay} @ {theta}");
            rows.push(Row::new(case, 1.0, e, Scale::Kink));
            let g1 = b.g1(wo);
            let e = smith_weak_furnace(wo, db, |_, _| g1);
            let case = format!("beckmann furnace {ax}x{ay} @ {theta}");
            rows.push(Row::new(case, 1.0, e, Scale::Kink));
        }
    }
    assert_honest("case 3: anisotropic lobes", &rows);
}

/// The sweep [`KINK_SAFETY`] is read off (about 5 minutes, so ignored by default:
/// `cargo test --release --test integrate error_estimates:: -- --ignored --nocapture`): GGX and
/// Beckmann weak furnaces, theta_o in 0.02 degree steps over the three bands where the top of
/// the kink circle (theta = 90 - theta_o) lies just past an initial-partition edge (0.256,
/// 0.064 and 0.016 rad), six azimuths, alpha 0.15 to 1. Prints the largest raw under-report,
/// actual / (estimate / KINK_SAFETY), and requires every returned estimate to be a bound.
#[test]
#[ignore = "about 5 minutes; the evidence behind KINK_SAFETY"]
fn kink_safety_covers_the_sweep_of_ggx_and_beckmann_furnaces() {
    let mut worst = (0.0_f64, String::new());
    let (mut n, mut under) = (0, 0);
    for (lo, hi) in [(73.0, 76.5), (85.5, 87.0), (88.6, 89.9)] {
        let steps = ((hi - lo) / 0.02_f64).round() as usize;
        for phi in [0.0, 0.15, 0.3, PHI, 1.0, 1.3] {
            for alpha in [0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5, 0.7, 1.0] {
                let ggx = Ggx::isotropic(alpha).unwrap();
                let beck = Beckmann::isotropic(alpha).unwrap();
                let models: [&dyn Microfacet<f64>; 2] = [&ggx, &beck];
                for (name, m) in ["ggx", "beckmann"].into_iter().zip(models) {
                    for i in 0..steps {
                        let theta = lo + 0.02 * i as f64;
                        let wo = dir_at(theta, phi);
                        let g1 = m.g1(wo);
                        let e = smith_weak_furnace(wo, |h| m.d(h), |_, _| g1);
                        let actual = (e.value - 1.0).abs();
                        let raw_under = actual / (e.error / KINK_SAFETY);
                        n += 1;
                        if actual > e.error + rounding_floor(1.0) {
                            under += 1;
                        }
                        if raw_under > worst.0 {
                            worst = (
                                raw_under,
                                format!(
                                    "{name} a={alpha} @ {theta:.2} deg, phi {phi:.2}: \
                                     actual {actual:.2e}, estimate {:.2e}",
                                    e.error
                                ),
                            );
                        }
                    }
                }
            }
        }
    }
    println!(
        "{n} furnaces, {under} estimates below the actual error; largest raw under-report \
         {:.3e}x ({})",
        worst.0, worst.1
    );
    assert_eq!(under, 0, "KINK_SAFETY = {KINK_SAFETY} is too small");
}
