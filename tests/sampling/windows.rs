//! Every sampler of `brdf::sampling` draws the distribution of the pdf it returns at the
//! configurations where its code changes behaviour, and on both sides of each switch: near
//! normal incidence (theta_o = 0, 0.1, 0.79, 0.82 and 1 degree at alpha = 1: the stretched
//! view crosses 0.81 degrees, below which `beckmann_vndf` once drew D cos normals instead of
//! visible ones), near grazing (89, 89.9 degrees), alpha at the floor `ALPHA_MIN`, at 1, at 10
//! and at the ceiling `ALPHA_MAX`, and anisotropic. Each configuration gets two checks:
//!
//! - chi-square goodness of fit against the sampler's pdf function (`tests/common`);
//! - the first moments E[x], E[y], E[z] of the samples against the integrals of x pdf, y pdf
//!   and z pdf by `brdf::integrate::hemisphere`, within a bound in standard errors.
//!
//! And for every sampler that reads wo, for fixed uniforms the sample moves continuously as
//! theta_o sweeps across each of those windows.
//!
//! Test space. An alpha = 1e-4 lobe is narrower than a chi-square bin and than the
//! integrator's finest grading (1e-3 rad), and at alpha = 1e4 every normal hugs the horizon.
//! So each sampled normal m is taken to the unit-roughness configuration,
//! m_u = normalize(m.x / alpha_x, m.y / alpha_y, m.z), where every alpha spreads its samples
//! over the hemisphere (the inverse of the stretch m = normalize(alpha_x u.x, alpha_y u.y, u.z)
//! with which the samplers build m; Heitz 2018, "Sampling the GGX Distribution of Visible
//! Normals", section 2), and its pdf is multiplied by the Jacobian of that map,
//! dm / dm_u = alpha_x alpha_y / |S m_u|^3 with S = diag(alpha_x, alpha_y, 1). A reflection
//! sampler's wi is first taken to its half vector h = normalize(wo + wi), with the Jacobian
//! dwi / dh = 4 wo.h (Walter et al. 2007, eq. 14). The maps are bijections, so a sampler that
//! draws the wrong distribution of m or wi draws the wrong distribution of m_u; at alpha = 1
//! the normal map is the identity.
//!
//! `cargo test --test sampling windows:: -- --nocapture` prints every figure.
#![cfg(all(
    feature = "sampling",
    feature = "ggx",
    feature = "beckmann",
    feature = "integrate"
))]

use crate::common;

use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::integrate::{Config, hemisphere};
use brdf::microfacet::{ALPHA_MAX, ALPHA_MIN};
use brdf::sampling as sm;
use brdf::{Real, V3};
use common::{Rng, assert_fits, chi_square_with};
use glam::DVec3;

/// The view at polar angle `theta_deg`, azimuth 53.13 degrees: off both tangent axes, so an
/// anisotropic lobe, and a sampler that ignored wo's azimuth, both show.
fn wo_at(theta_deg: f64) -> DVec3 {
    let t = theta_deg.to_radians();
    DVec3::new(0.6 * t.sin(), 0.8 * t.sin(), t.cos())
}

/// The map between a lobe of widths (alpha_x, alpha_y) and the unit configuration.
#[derive(Clone, Copy, Debug)]
struct Stretch {
    ax: f64,
    ay: f64,
}

impl Stretch {
    const UNIT: Self = Self { ax: 1.0, ay: 1.0 };

    fn unstretch(self, m: DVec3) -> DVec3 {
        DVec3::new(m.x / self.ax, m.y / self.ay, m.z).normalize()
    }

    fn stretch(self, u: DVec3) -> DVec3 {
        DVec3::new(self.ax * u.x, self.ay * u.y, u.z).normalize()
    }

    /// dm / dm_u in solid angle: |det S| / |S u|^3 for the map u -> S u / |S u|.
    fn jacobian(self, u: DVec3) -> f64 {
        let s = DVec3::new(self.ax * u.x, self.ay * u.y, u.z).length();
        self.ax * self.ay / (s * s * s)
    }

    /// The view as the unit configuration sees it (where its visible normals peak).
    fn view(self, wo: DVec3) -> DVec3 {
        DVec3::new(self.ax * wo.x, self.ay * wo.y, wo.z).normalize()
    }

    /// The stretched view's polar angle in degrees: the quantity the samplers' windows are
    /// defined on.
    fn theta_deg(self, wo: DVec3) -> f64 {
        let v = self.view(wo);
        v.x.hypot(v.y).atan2(v.z).to_degrees()
    }
}

type Draw = Box<dyn Fn(f64, f64) -> DVec3>;
type Density = Box<dyn Fn(DVec3) -> f64>;

/// One sampler at one configuration, seen in test space.
struct Case {
    label: String,
    /// (u1, u2) -> the sample in test space.
    draw: Draw,
    /// The sampler's pdf function, carried to test space.
    pdf: Density,
    /// Where the test-space density peaks, for the integrator's initial partition.
    peaks: Vec<DVec3>,
}

/// A normal sampler: `sample` returns (m, pdf), `pdf` is its pdf function of m. Each draw
/// checks that the returned pdf is the pdf function at m, bit for bit (the samplers call it);
/// the chi-square then needs only the function, carried to test space.
fn normal_case(
    label: String,
    s: Stretch,
    wo: DVec3,
    sample: impl Fn(f64, f64) -> (V3<f64>, f64) + 'static,
    pdf: impl Fn(DVec3) -> f64 + 'static,
) -> Case {
    let pdf = std::rc::Rc::new(pdf);
    let name = label.clone();
    Case {
        label,
        draw: Box::new({
            let pdf = pdf.clone();
            move |u1, u2| {
                let (m, p) = sample(u1, u2);
                let q = pdf(m.into());
                assert_eq!(
                    p.to_bits(),
                    q.to_bits(),
                    "{name}: returned pdf {p} vs function {q}"
                );
                s.unstretch(m.into())
            }
        }),
        pdf: Box::new(move |mu| pdf(s.stretch(mu)) * s.jacobian(mu)),
        peaks: vec![DVec3::Z, s.view(wo)],
    }
}

/// A reflection sampler: `sample` returns (wi, pdf), `pdf` is its pdf function of (wo, wi);
/// the returned pdf is checked as in [`normal_case`]. The density of h = normalize(wo + wi)
/// is pdf(wi) dwi / dh = pdf(wi) 4 wo.h.
fn reflection_case(
    label: String,
    s: Stretch,
    wo: DVec3,
    sample: impl Fn(V3<f64>, f64, f64) -> (V3<f64>, f64) + 'static,
    pdf: impl Fn(V3<f64>, V3<f64>) -> f64 + 'static,
) -> Case {
    let pdf = std::rc::Rc::new(pdf);
    let name = label.clone();
    Case {
        label,
        draw: Box::new({
            let pdf = pdf.clone();
            move |u1, u2| {
                let (wi, p) = sample(wo.into(), u1, u2);
                let q = pdf(wo.into(), wi);
                assert_eq!(
                    p.to_bits(),
                    q.to_bits(),
                    "{name}: returned pdf {p} vs function {q}"
                );
                s.unstretch((wo + DVec3::from(wi)).normalize())
            }
        }),
        pdf: Box::new(move |hu| {
            let h = s.stretch(hu);
            let wi = 2.0 * wo.dot(h) * h - wo;
            (pdf(wo.into(), wi.into()) * 4.0 * wo.dot(h)).max(0.0) * s.jacobian(hu)
        }),
        peaks: vec![DVec3::Z, s.view(wo)],
    }
}

/// Replicates of the stratified moment estimate, and the cells per side of each replicate's
/// grid.
const REPLICATES: usize = 32;
const GRID: usize = 32;

/// E[x], E[y], E[z] of the test-space samples, and their standard errors: `REPLICATES`
/// independent estimates, each from one uniform pair per cell of a `GRID` x `GRID` grid
/// (jittered stratification: unbiased, and far less noisy than as many independent draws,
/// which is what lets a 0.8 degree view's shift of E[x] by 4e-3 show at many sigma with
/// 3e4 samples). The standard error comes from the spread of the replicates.
fn moments(draw: &dyn Fn(f64, f64) -> DVec3) -> ([f64; 3], [f64; 3]) {
    let mut rng = Rng(0x3a11);
    let mut reps = [[0.0; 3]; REPLICATES];
    for rep in &mut reps {
        for i in 0..GRID {
            for j in 0..GRID {
                let u1 = (i as f64 + rng.next_f64()) / GRID as f64;
                let u2 = (j as f64 + rng.next_f64()) / GRID as f64;
                let w = draw(u1, u2);
                for (r, c) in rep.iter_mut().zip(w.to_array()) {
                    *r += c / (GRID * GRID) as f64;
                }
            }
        }
    }
    let mut mean = [0.0; 3];
    let mut se = [0.0; 3];
    for k in 0..3 {
        let m = reps.iter().map(|r| r[k]).sum::<f64>() / REPLICATES as f64;
        let var =
            reps.iter().map(|r| (r[k] - m) * (r[k] - m)).sum::<f64>() / (REPLICATES - 1) as f64;
        mean[k] = m;
        se[k] = (var / REPLICATES as f64).sqrt();
    }
    (mean, se)
}

/// Bound on |mean - integral| in standard errors. The replicate means are independent and
/// unbiased, so (mean - integral) / se follows Student's t with 31 degrees of freedom:
/// P(|t| > 6) = 1.1e-6 per moment, 3.4e-4 over the 312 moments checked here (the largest
/// measured is 1.9). The D cos draws that `beckmann_vndf` once made below 0.81 degrees
/// score t = -17 and -21 at 0.79 degrees (`d_cos_normals_fail_as_visible_normals`).
const T_BOUND: f64 = 6.0;

/// Draws per chi-square fit: half the shared `common::SAMPLES`, so that the 104 fits here
/// (`beckmann_vndf` costs about 1.7 us a draw) keep each test to a few seconds. The fits
/// catch errors of shape, which move many bins at once (D cos normals judged as a 45 degree
/// view's visible normals score 1.8e6 against a critical 384); the moments catch the small
/// shifts.
const DRAWS: usize = 100_000;

/// Midpoints per side of each chi-square bin for the expected counts: the test-space densities
/// vary over many bins (none is narrower than a unit-roughness lobe), where 16 x 16 gives
/// the statistic of the shared rule's 64 x 64 to within 1.1 (measured on all 104 fits here:
/// statistics of 156 to 529 against critical values of 245 to 630) at a sixteenth of its
/// cost.
const SUB: usize = 16;

/// Largest |integral of the test-space pdf - 1|: measured 6.1e-6 where the kink of
/// max(0, wo.m) crosses the integrator's rectangles near the horizon (a GGX lobe at a
/// stretched view of 0.79 degrees, whose D stays large there; the known flaw in
/// `brdf::integrate`'s docs). A wrong Jacobian is off by O(1).
const MASS_BOUND: f64 = 1e-4;

/// What [`check`] compares for one case.
struct Measured {
    /// Chi-square statistic and degrees of freedom.
    fit: (f64, usize),
    /// Integral of the test-space pdf, and the integrator's error estimate.
    mass: (f64, f64),
    /// Per axis: the samples' mean, its standard error, the pdf's moment and the
    /// integrator's error estimate.
    moments: [(f64, f64, f64, f64); 3],
}

impl Measured {
    /// The moments' t values, (mean - integral) / se.
    fn t(&self) -> [f64; 3] {
        self.moments
            .map(|(mean, se, integral, _)| (mean - integral) / se)
    }
}

fn measure(case: &Case) -> Measured {
    // The chi-square's own check of the returned pdf against the function is the draw's
    // bitwise one above; here it compares the carried function with itself.
    let fit = chi_square_with(
        DRAWS,
        SUB,
        |u1, u2| {
            let w = (case.draw)(u1, u2);
            (w, (case.pdf)(w))
        },
        &case.pdf,
    );
    // The integrator's directions are `V3`s; the test space is glam's, like the chi-square's.
    let pdf = |w: V3<f64>| (case.pdf)(w.into());
    let peaks: Vec<V3<f64>> = case.peaks.iter().map(|&p| p.into()).collect();
    let cfg = Config::default();
    let total = hemisphere(pdf, &peaks, &cfg);
    let (mean, se) = moments(&case.draw);
    let moments = core::array::from_fn(|k| {
        let e = hemisphere(|w| w.to_array()[k] * pdf(w), &peaks, &cfg);
        (mean[k], se[k], e.value, e.error)
    });
    Measured {
        fit,
        mass: (total.value, total.error),
        moments,
    }
}

fn check(case: &Case) {
    let r = measure(case);
    assert_fits(&case.label, r.fit);
    // The carried pdf integrates to 1, so the Jacobians are right and the moments compare
    // distributions of equal mass.
    let missed = (r.mass.0 - 1.0).abs();
    assert!(
        missed <= MASS_BOUND,
        "{}: the test-space pdf integrates to {} (error {:.1e})",
        case.label,
        r.mass.0,
        r.mass.1
    );
    let mut line = format!(" mass 1 {:+.1e};", r.mass.0 - 1.0);
    for (k, ((mean, se, integral, error), t)) in r.moments.iter().zip(r.t()).enumerate() {
        let axis = ["x", "y", "z"][k];
        line += &format!(" E[{axis}] {mean:+.5} vs {integral:+.5} ({t:+.1} se)");
        // The mass the integrator missed bounds what it missed of a moment (|x| <= 1).
        assert!(
            (mean - integral).abs() <= T_BOUND * se + error + missed,
            "{}: E[{axis}] of the samples {mean} vs the pdf's {integral} (se {se:.1e}, \
             t = {t:.1}, integration error {error:.1e})",
            case.label,
        );
    }
    println!("{}:{line}", case.label);
}

/// The checks have teeth, and the moments see what the chi-square cannot: D cos normals (what
/// `beckmann_vndf` once drew below a stretched view angle of 0.81 degrees) judged as the
/// visible normals of a view 0.79 degrees from normal pass the chi-square but miss E[x] and
/// E[y] by many standard errors; judged as those of a 45 degree view they fail both.
#[test]
fn d_cos_normals_fail_as_visible_normals() {
    let b = Beckmann::isotropic(1.0).unwrap();
    for (theta, chi_square_sees_it) in [(0.79, false), (45.0, true)] {
        let wo = wo_at(theta);
        let r = measure(&Case {
            label: String::new(),
            draw: Box::new(move |u1, u2| sm::beckmann_d_cos(&b, u1, u2).0.into()),
            pdf: Box::new(move |m| sm::visible_normal_pdf(&b, wo.into(), m.into())),
            peaks: vec![DVec3::Z, wo],
        });
        let t = r.t();
        println!(
            "D cos as visible normals at theta_o {theta} deg: chi^2 {:.1} (dof {}, critical \
             {:.1}), t = {:+.1} {:+.1} {:+.1}",
            r.fit.0,
            r.fit.1,
            common::critical(r.fit.1),
            t[0],
            t[1],
            t[2]
        );
        assert!(t[0].abs().max(t[1].abs()) > 2.0 * T_BOUND, "{t:?}");
        assert_eq!(r.fit.0 > common::critical(r.fit.1), chi_square_sees_it);
    }
}

/// (alpha_x, alpha_y, theta_o in degrees) where the visible-normal samplers are checked, in
/// three groups (one test each for the costly `beckmann_vndf`). The switch that matters is
/// the stretched view angle 0.81 degrees, below which `beckmann_vndf` once drew D cos
/// normals: theta_o = 0.81 degrees / alpha for small angles, 89.6 degrees at ALPHA_MIN,
/// 8.1e-5 degrees at ALPHA_MAX. For each alpha: views on both sides of it, exactly normal
/// (where the samplers' azimuth frames fall back to the tangent frame), and near grazing
/// (where `beckmann_vndf`'s Newton iteration works hardest).
type Views = &'static [(f64, f64, f64)];

/// alpha = 1: normal incidence, both sides of the switch and past it, and grazing.
const VIEWS_ALPHA_1: Views = &[
    (1.0, 1.0, 0.0),
    (1.0, 1.0, 0.1),
    (1.0, 1.0, 0.79),
    (1.0, 1.0, 0.82),
    (1.0, 1.0, 1.0),
    (1.0, 1.0, 89.0),
    (1.0, 1.0, 89.9),
];

/// alpha at its floor, where every view short of 89.6 degrees is within 0.81 degrees of
/// normal once stretched, and alpha = 10.
const VIEWS_ALPHA_MIN_AND_10: Views = &[
    (ALPHA_MIN, ALPHA_MIN, 0.0),
    (ALPHA_MIN, ALPHA_MIN, 89.5),
    (ALPHA_MIN, ALPHA_MIN, 89.7),
    (ALPHA_MIN, ALPHA_MIN, 89.9),
    (10.0, 10.0, 0.079),
    (10.0, 10.0, 0.082),
    (10.0, 10.0, 89.9),
];

/// alpha at its ceiling, where every view past 8.1e-5 degrees is grazing once stretched, and
/// anisotropic lobes (whose stretched angle depends on wo's azimuth too).
const VIEWS_ALPHA_MAX_AND_ANISOTROPIC: Views = &[
    (ALPHA_MAX, ALPHA_MAX, 0.0),
    (ALPHA_MAX, ALPHA_MAX, 7.9e-5),
    (ALPHA_MAX, ALPHA_MAX, 8.2e-5),
    (ALPHA_MAX, ALPHA_MAX, 89.9),
    (0.3, 1.0, 0.95),
    (0.3, 1.0, 1.05),
    (0.3, 1.0, 60.0),
    (0.3, 1.0, 89.9),
    (ALPHA_MIN, ALPHA_MAX, 45.0),
];

const VIEWS: [Views; 3] = [
    VIEWS_ALPHA_1,
    VIEWS_ALPHA_MIN_AND_10,
    VIEWS_ALPHA_MAX_AND_ANISOTROPIC,
];

/// Views for the reflection samplers: each side of their visible-normal sampler's old
/// switch, then views that reflect part of the lobe below the horizon (grazing, rough),
/// where the weight is 0 and the pdf is not, and an anisotropic lobe.
const REFLECTION_VIEWS_NEAR_NORMAL: Views = &[
    (1.0, 1.0, 0.0),
    (1.0, 1.0, 0.79),
    (1.0, 1.0, 0.82),
    (ALPHA_MIN, ALPHA_MIN, 89.5),
    (ALPHA_MIN, ALPHA_MIN, 89.7),
    (10.0, 10.0, 0.079),
];

const REFLECTION_VIEWS_GRAZING: Views = &[
    (1.0, 1.0, 89.9),
    (10.0, 10.0, 45.0),
    (ALPHA_MAX, ALPHA_MAX, 0.0),
    (ALPHA_MAX, ALPHA_MAX, 89.0),
    (0.3, 1.0, 60.0),
];

fn label(name: &str, ax: f64, ay: f64, theta: f64) -> String {
    let s = Stretch { ax, ay };
    format!(
        "{name}, alpha {ax:e} x {ay:e}, theta_o {theta} deg (stretched {:.4} deg)",
        s.theta_deg(wo_at(theta))
    )
}

#[test]
fn cosine_hemisphere_fits_its_pdf_and_moments() {
    check(&normal_case(
        "cosine_hemisphere".into(),
        Stretch::UNIT,
        DVec3::Z,
        sm::cosine_hemisphere,
        |w| sm::cosine_hemisphere_pdf(w.into()),
    ));
}

#[test]
fn d_cos_samplers_fit_their_pdf_and_moments_from_alpha_min_to_alpha_max() {
    for (ax, ay) in [
        (ALPHA_MIN, ALPHA_MIN),
        (1.0, 1.0),
        (10.0, 10.0),
        (ALPHA_MAX, ALPHA_MAX),
        (0.3, 1.0),
        (ALPHA_MIN, ALPHA_MAX),
    ] {
        let s = Stretch { ax, ay };
        let g = Ggx::new(ax, ay).unwrap();
        check(&normal_case(
            format!("ggx_d_cos, alpha {ax:e} x {ay:e}"),
            s,
            DVec3::Z,
            move |u1, u2| sm::ggx_d_cos(&g, u1, u2),
            move |m| sm::d_cos_pdf(&g, m.into()),
        ));
        let b = Beckmann::new(ax, ay).unwrap();
        check(&normal_case(
            format!("beckmann_d_cos, alpha {ax:e} x {ay:e}"),
            s,
            DVec3::Z,
            move |u1, u2| sm::beckmann_d_cos(&b, u1, u2),
            move |m| sm::d_cos_pdf(&b, m.into()),
        ));
    }
}

#[test]
fn ggx_visible_normal_sampler_fits_its_pdf_and_moments_in_every_window() {
    for &(ax, ay, theta) in VIEWS.concat().iter() {
        let (s, wo) = (Stretch { ax, ay }, wo_at(theta));
        let g = Ggx::new(ax, ay).unwrap();
        check(&normal_case(
            label("ggx_vndf", ax, ay, theta),
            s,
            wo,
            move |u1, u2| sm::ggx_vndf(&g, wo.into(), u1, u2),
            move |m| sm::visible_normal_pdf(&g, wo.into(), m.into()),
        ));
    }
}

#[test]
fn ggx_spherical_cap_sampler_fits_its_pdf_and_moments_in_every_window() {
    for &(ax, ay, theta) in VIEWS.concat().iter() {
        let (s, wo) = (Stretch { ax, ay }, wo_at(theta));
        let g = Ggx::new(ax, ay).unwrap();
        check(&normal_case(
            label("ggx_vndf_spherical_cap", ax, ay, theta),
            s,
            wo,
            move |u1, u2| sm::ggx_vndf_spherical_cap(&g, wo.into(), u1, u2),
            move |m| sm::visible_normal_pdf(&g, wo.into(), m.into()),
        ));
    }
}

fn beckmann_vndf_views(views: Views) {
    for &(ax, ay, theta) in views {
        let (s, wo) = (Stretch { ax, ay }, wo_at(theta));
        let b = Beckmann::new(ax, ay).unwrap();
        check(&normal_case(
            label("beckmann_vndf", ax, ay, theta),
            s,
            wo,
            move |u1, u2| sm::beckmann_vndf(&b, wo.into(), u1, u2),
            move |m| sm::visible_normal_pdf(&b, wo.into(), m.into()),
        ));
    }
}

#[test]
fn beckmann_visible_normal_sampler_fits_its_pdf_and_moments_at_alpha_1() {
    beckmann_vndf_views(VIEWS_ALPHA_1);
}

#[test]
fn beckmann_visible_normal_sampler_fits_its_pdf_and_moments_at_alpha_min_and_10() {
    beckmann_vndf_views(VIEWS_ALPHA_MIN_AND_10);
}

#[test]
fn beckmann_visible_normal_sampler_fits_its_pdf_and_moments_at_alpha_max_and_anisotropic() {
    beckmann_vndf_views(VIEWS_ALPHA_MAX_AND_ANISOTROPIC);
}

/// The `_rgb` form of a reflection sampler draws the same direction with the same pdf, bit for
/// bit (checked on 1000 draws; the fits above then hold for it too).
fn rgb_form_draws_the_same(
    wo: DVec3,
    both: impl Fn(V3<f64>, f64, f64) -> (V3<f64>, f64, V3<f64>, f64),
) {
    let mut rng = Rng(0x5c);
    for _ in 0..1000 {
        let (u1, u2) = (rng.next_f64(), rng.next_f64());
        let (wi, p, wi3, p3) = both(wo.into(), u1, u2);
        assert!(
            wi == wi3 && p.to_bits() == p3.to_bits(),
            "u = ({u1}, {u2}): {wi:?} {p} vs {wi3:?} {p3}"
        );
    }
}

#[test]
fn ggx_reflection_samplers_fit_their_pdf_and_moments_in_every_window() {
    let views = [REFLECTION_VIEWS_NEAR_NORMAL, REFLECTION_VIEWS_GRAZING].concat();
    for &(ax, ay, theta) in &views {
        let (s, wo) = (Stretch { ax, ay }, wo_at(theta));
        let g = Ggx::new(ax, ay).unwrap();
        check(&reflection_case(
            label("ggx_reflection", ax, ay, theta),
            s,
            wo,
            move |wo, u1, u2| {
                let (wi, p, _) = sm::ggx_reflection(&g, wo, u1, u2, |_| 1.0);
                (wi, p)
            },
            move |wo, wi| sm::ggx_reflection_pdf(&g, wo, wi),
        ));
        rgb_form_draws_the_same(wo, |wo, u1, u2| {
            let (wi, p, _) = sm::ggx_reflection(&g, wo, u1, u2, |_| 1.0);
            let (wi3, p3, _) = sm::ggx_reflection_rgb(&g, wo, u1, u2, |_| V3::splat(1.0));
            (wi, p, wi3, p3)
        });
    }
}

fn beckmann_reflection_views(views: Views) {
    for &(ax, ay, theta) in views {
        let (s, wo) = (Stretch { ax, ay }, wo_at(theta));
        let b = Beckmann::new(ax, ay).unwrap();
        check(&reflection_case(
            label("beckmann_reflection", ax, ay, theta),
            s,
            wo,
            move |wo, u1, u2| {
                let (wi, p, _) = sm::beckmann_reflection(&b, wo, u1, u2, |_| 1.0);
                (wi, p)
            },
            move |wo, wi| sm::beckmann_reflection_pdf(&b, wo, wi),
        ));
        rgb_form_draws_the_same(wo, |wo, u1, u2| {
            let (wi, p, _) = sm::beckmann_reflection(&b, wo, u1, u2, |_| 1.0);
            let (wi3, p3, _) = sm::beckmann_reflection_rgb(&b, wo, u1, u2, |_| V3::splat(1.0));
            (wi, p, wi3, p3)
        });
    }
}

#[test]
fn beckmann_reflection_samplers_fit_their_pdf_and_moments_near_normal_incidence() {
    beckmann_reflection_views(REFLECTION_VIEWS_NEAR_NORMAL);
}

#[test]
fn beckmann_reflection_samplers_fit_their_pdf_and_moments_near_grazing_and_rough() {
    beckmann_reflection_views(REFLECTION_VIEWS_GRAZING);
}

/// A sampler that reads wo, on any float type: (distribution, wo, u1, u2) -> the direction.
type Sampler<T, D> = fn(&D, V3<T>, T, T) -> V3<T>;

/// Sweeps of theta_o: (alpha_x, alpha_y, from, to) in degrees. The first five cross the
/// stretched angle 0.81 degrees (the old `beckmann_vndf` switch) for their alpha; the last
/// two cover the oblique and grazing range, where that sampler's Newton iteration works
/// hardest.
const SWEEPS: &[(f64, f64, f64, f64)] = &[
    (1.0, 1.0, 0.70, 0.92),
    (ALPHA_MIN, ALPHA_MIN, 89.55, 89.64),
    (10.0, 10.0, 0.070, 0.092),
    (ALPHA_MAX, ALPHA_MAX, 7.0e-5, 9.2e-5),
    (0.3, 1.0, 0.85, 1.15),
    (1.0, 1.0, 1.0, 89.0),
    (1.0, 1.0, 89.0, 89.99),
];

const STEPS: usize = 400;

/// Fixed uniforms, each paired with each: the bulk and both tails, down to 1e-9 from 1 (and
/// below `beckmann_vndf`'s floor of 1e-6) in f64, where every sampler's path is smooth to
/// rounding.
const US_F64: &[f64] = &[
    1e-7,
    0.001,
    0.02,
    0.2,
    0.5,
    0.8,
    0.98,
    0.999,
    0.99999,
    1.0 - 1e-9,
];

/// In f32 the tails stop 1e-3 from 0 and 1: `beckmann_vndf` inverts its CDF in erf space,
/// where one ULP of b = erf(x) is sqrt(pi) / 2 exp(x^2) ULPs of the slope x, about 100 at
/// u1 = 0.999 (within the 64-ULP floor once it reaches the normal) but 7000 at u1 = 0.99999,
/// where the sample moves in steps of 7e-5: the resolution of f32, not a jump of the method
/// (f64 shows none at 1 - 1e-9).
const US_F32: &[f64] = &[0.001, 0.02, 0.2, 0.5, 0.8, 0.98, 0.999];

/// A smooth path moves by nearly equal amounts in neighbouring steps (ratio 1 + O(step)); a
/// jump, however small, moves by its size in one step and by O(step) in the others.
const RATIO: f64 = 4.0;

/// For fixed (u1, u2), the sample along each sweep: no step moves it by more than `RATIO`
/// times the larger of its two neighbouring steps, plus a rounding floor of 64 ULP. Normals
/// are compared in the unit configuration (where an ALPHA_MIN lobe's steps are not lost
/// below the rounding of m.z), reflected directions as they are (their half vector's
/// unstretch would amplify wi's rounding by 1 / alpha). Returns the largest ratio.
fn continuity<T: Real, D>(
    name: &str,
    us: &[f64],
    make: fn(T, T) -> D,
    sample: Sampler<T, D>,
    reflection: bool,
) -> f64 {
    let eps: f64 = T::EPSILON.lane(0).into();
    let floor = 64.0 * eps;
    let t = |x: f64| T::splat(x);
    let mut worst = 0.0f64;
    for &(ax, ay, from, to) in SWEEPS {
        let s = Stretch { ax, ay };
        let dist = make(t(ax), t(ay));
        let thetas: Vec<f64> = (0..=STEPS)
            .map(|i| from + (to - from) * i as f64 / STEPS as f64)
            .collect();
        for &u1 in us {
            for &u2 in us {
                let path: Vec<DVec3> = thetas
                    .iter()
                    .map(|&theta| {
                        let wo = wo_at(theta);
                        let wo = V3::new(t(wo.x), t(wo.y), t(wo.z));
                        let w = sample(&dist, wo, t(u1), t(u2));
                        let w =
                            DVec3::new(w.x.lane(0).into(), w.y.lane(0).into(), w.z.lane(0).into());
                        if reflection { w } else { s.unstretch(w) }
                    })
                    .collect();
                let step: Vec<f64> = path.windows(2).map(|p| (p[1] - p[0]).length()).collect();
                for i in 0..step.len() {
                    let before = if i > 0 { step[i - 1] } else { 0.0 };
                    let after = step.get(i + 1).copied().unwrap_or(0.0);
                    let ratio = step[i] / (before.max(after) + floor);
                    worst = worst.max(ratio);
                    assert!(
                        ratio <= RATIO,
                        "{name}: alpha {ax:e} x {ay:e}, u = ({u1}, {u2}): the sample jumps by \
                         {:.3e} between theta_o {} and {} deg, against {before:.3e} and \
                         {after:.3e} in the steps either side ({:?} -> {:?})",
                        step[i],
                        thetas[i],
                        thetas[i + 1],
                        path[i],
                        path[i + 1]
                    );
                }
            }
        }
    }
    println!("{name}: largest step / neighbouring step {worst:.2}");
    worst
}

fn continuity_all<T: Real>(ty: &str, us: &[f64]) {
    continuity::<T, Beckmann<T>>(
        &format!("beckmann_vndf {ty}"),
        us,
        |a, b| Beckmann::new(a, b).unwrap(),
        |d, wo, u1, u2| sm::beckmann_vndf(d, wo, u1, u2).0,
        false,
    );
    continuity::<T, Beckmann<T>>(
        &format!("beckmann_reflection {ty}"),
        us,
        |a, b| Beckmann::new(a, b).unwrap(),
        |d, wo, u1, u2| sm::beckmann_reflection(d, wo, u1, u2, |_| T::ONE).0,
        true,
    );
    continuity::<T, Ggx<T>>(
        &format!("ggx_vndf {ty}"),
        us,
        |a, b| Ggx::new(a, b).unwrap(),
        |d, wo, u1, u2| sm::ggx_vndf(d, wo, u1, u2).0,
        false,
    );
    continuity::<T, Ggx<T>>(
        &format!("ggx_vndf_spherical_cap {ty}"),
        us,
        |a, b| Ggx::new(a, b).unwrap(),
        |d, wo, u1, u2| sm::ggx_vndf_spherical_cap(d, wo, u1, u2).0,
        false,
    );
    continuity::<T, Ggx<T>>(
        &format!("ggx_reflection {ty}"),
        us,
        |a, b| Ggx::new(a, b).unwrap(),
        |d, wo, u1, u2| sm::ggx_reflection(d, wo, u1, u2, |_| T::ONE).0,
        true,
    );
}

#[test]
fn samples_move_continuously_as_the_view_crosses_every_window_f64() {
    continuity_all::<f64>("f64", US_F64);
}

#[test]
fn samples_move_continuously_as_the_view_crosses_every_window_f32() {
    continuity_all::<f32>("f32", US_F32);
}

/// The uniforms' roles as the docs state them, at normal incidence with an isotropic lobe:
/// the cosine hemisphere's azimuth is 2 pi u2; the D cos samplers draw the slope at angle
/// 2 pi u2, so the normal, m = normalize(-alpha slope, 1), has azimuth 2 pi u2 + pi;
/// `ggx_vndf`'s disk angle 2 pi u2 is measured from t1 = +x there, so the normal's azimuth is
/// 2 pi u2; the spherical cap's azimuth is 2 pi u1; `beckmann_vndf` draws the two slopes
/// separately, x = erf^-1(2 u1 - 1) and y = erf^-1(2 u2 - 1).
#[test]
fn uniforms_map_to_the_documented_angles_and_slopes_at_normal_incidence() {
    use core::f64::consts::{PI, TAU};
    let alpha = 0.5;
    let g = Ggx::isotropic(alpha).unwrap();
    let b = Beckmann::isotropic(alpha).unwrap();
    let z = V3::new(0.0, 0.0, 1.0);
    let azimuth = |m: V3<f64>| m.y.atan2(m.x).rem_euclid(TAU);
    let same_angle = |a: f64, b: f64| {
        let d = (a - b).rem_euclid(TAU);
        d.min(TAU - d) < 1e-12
    };
    let mut rng = Rng(5);
    for _ in 0..1000 {
        let (u1, u2) = (rng.next_f64(), rng.next_f64());
        let cases = [
            (
                "cosine_hemisphere",
                sm::cosine_hemisphere(u1, u2).0,
                TAU * u2,
            ),
            ("ggx_d_cos", sm::ggx_d_cos(&g, u1, u2).0, TAU * u2 + PI),
            (
                "beckmann_d_cos",
                sm::beckmann_d_cos(&b, u1, u2).0,
                TAU * u2 + PI,
            ),
            ("ggx_vndf", sm::ggx_vndf(&g, z, u1, u2).0, TAU * u2),
            (
                "ggx_vndf_spherical_cap",
                sm::ggx_vndf_spherical_cap(&g, z, u1, u2).0,
                TAU * u1,
            ),
        ];
        for (name, m, want) in cases {
            assert!(
                same_angle(azimuth(m), want),
                "{name}: u = ({u1}, {u2}): azimuth {} vs documented {}",
                azimuth(m),
                want.rem_euclid(TAU)
            );
        }
        let (m, _) = sm::beckmann_vndf(&b, z, u1, u2);
        let (sx, sy) = (-m.x / (alpha * m.z), -m.y / (alpha * m.z));
        let (wx, wy) = (sm::erf_inv(2.0 * u1 - 1.0), sm::erf_inv(2.0 * u2 - 1.0));
        assert!(
            (sx - wx).abs() <= 1e-9 * wx.abs().max(1.0)
                && (sy - wy).abs() <= 1e-9 * wy.abs().max(1.0),
            "beckmann_vndf: u = ({u1}, {u2}): slopes ({sx}, {sy}) vs documented ({wx}, {wy})"
        );
    }
}
