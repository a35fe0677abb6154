//! Importance sampling: the cosine-weighted hemisphere, and for GGX and Beckmann the
//! distribution of normals D(m) cos(theta_m) and the distribution of visible normals
//! D_wo(m) = G1(wo) max(0, wo.m) D(m) / |wo.z|, each with its pdf.
//!
//! Directions live in the local shading frame (normal = +z; [`crate::frame::Frame`] takes
//! world-space vectors there and back), and both `wo` and the sampled `wi` point away from
//! the surface: wi = 2 (wo.m) m - wo, which is [`crate::vec3::V3::mirror`], the negative of
//! glam's and GLSL's `reflect` of an incident direction.
//!
//! Every sampler maps two uniform numbers `u1, u2` in [0, 1) to a unit local-frame direction
//! and returns it with its pdf (with respect to solid angle), so a caller never pairs a
//! sampler with the wrong pdf. u = 1 is clamped to the largest float below 1 (where a mapping
//! would reach an infinite slope). Samplers are generic over [`Real`] and branch-free on lane
//! values: a lane's output equals the scalar output for that lane's inputs.
//!
//! Which uniform drives which angle differs between samplers: u2 is the azimuth of
//! `cosine_hemisphere`'s direction and the disk angle of `ggx_vndf`, the angle of the D cos
//! samplers' slope (their normal's azimuth is 2 pi u2 + pi), u1 the cap azimuth of
//! `ggx_vndf_spherical_cap`, and `beckmann_vndf` has no angle (u1 and u2 are its two slopes).
//! Each sampler's doc gives its mapping; `tests/sampling/windows.rs` checks them at normal
//! incidence.
//!
//! Each sampler draws its pdf for every wo, with no approximate special case (for example at
//! normal incidence), and for fixed u its sample is continuous in wo above the horizon,
//! except at wo = +z for the samplers that build a frame around wo's azimuth (`ggx_vndf`,
//! `beckmann_vndf` and `beckmann_reflection`), where that azimuth is undefined
//! (`tests/sampling/windows.rs` checks both, on both sides of every internal switch).
//!
//! Bad input: a NaN in `u1`, `u2` or any component of `wo` gives a NaN direction (all three
//! components) and a NaN pdf, never a plausible normal. alpha is clamped to [ALPHA_MIN,
//! ALPHA_MAX] (`crate::microfacet`), so every finite alpha the constructors accept samples
//! unit normals with finite pdfs (`tests/microfacet/domains.rs`).
//!
//! The pdf of the reflected direction wi = reflect(wo, m) is pdf_m / (4 |wo.m|) ([`reflect_pdf`];
//! Walter et al. 2007, eq. 14).
//!
//! The Cook-Torrance reflection lobe in one call: `ggx_reflection` and `beckmann_reflection`
//! (and their `_rgb` forms, each behind its model's feature) draw a visible normal, reflect
//! wo about it and return (wi, pdf, weight) with weight = f cos / pdf = F G2 / G1 for a
//! Fresnel closure of the caller's; `ggx_reflection_pdf` and `beckmann_reflection_pdf` give
//! the same pdf for any (wo, wi), for multiple importance sampling.

use crate::domain::nan_where;
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

#[cfg(feature = "beckmann")]
use crate::beckmann::Beckmann;
#[cfg(feature = "ggx")]
use crate::ggx::Ggx;
#[cfg(any(feature = "ggx", feature = "beckmann"))]
use crate::microfacet::Microfacet;

/// Clamps a uniform sample into [0, 1 - epsilon/2]: the largest float below 1 for u >= 1,
/// so mappings with a pole at u = 1 stay finite. NaN propagates.
#[inline]
fn clamp_u<T: Real>(u: T) -> T {
    u.clamp(T::ZERO, T::ONE - T::EPSILON * T::HALF)
}

/// The sample, or a NaN direction (all three components) and a NaN pdf where `bad` holds: the
/// normalizations with a fallback direction would otherwise turn NaN input into a plausible
/// unit vector.
#[inline]
fn nan_sample<T: Real>(bad: T::Mask, m: V3<T>, pdf: T) -> (V3<T>, T) {
    let nan = T::splat(f64::NAN);
    (V3::select(bad, V3::splat(nan), m), T::select(bad, nan, pdf))
}

/// A direction on the cosine-weighted upper hemisphere (Malley's method: a uniform point on the
/// unit disk, r = sqrt(u1), phi = 2 pi u2, lifted to z = sqrt(1 - r^2)), and its pdf
/// cos(theta) / pi. Source: Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed.,
/// section A.5.3.
#[inline]
#[must_use]
pub fn cosine_hemisphere<T: Real>(u1: T, u2: T) -> (V3<T>, T) {
    let (u1, u2) = (clamp_u(u1), clamp_u(u2));
    let r = u1.sqrt();
    let phi = T::TWO * T::PI * u2;
    let z = (T::ONE - u1).sqrt_nonneg();
    let w = V3::new(r * phi.cos(), r * phi.sin(), z);
    nan_sample(u1.is_nan() | u2.is_nan(), w, z * T::FRAC_1_PI)
}

/// pdf of [`cosine_hemisphere`]: max(0, w.z) / pi.
#[inline]
#[must_use]
pub fn cosine_hemisphere_pdf<T: Real>(w: V3<T>) -> T {
    nan_where(any_nonfinite3(w), w.z.max(T::ZERO) * T::FRAC_1_PI)
}

/// pdf of a reflected direction whose half vector m was drawn with pdf `pdf_m`:
/// pdf_m / (4 |v.h|) (the Jacobian of wi = 2 (wo.m) m - wo; Walter et al. 2007, eq. 14).
/// Domain: pdf_m in [0, +inf), v_dot_h in [-1, 1]. 0 where v.h = 0; capped at the largest
/// finite value; NaN for NaN input or a negative pdf_m.
#[inline]
#[must_use]
pub fn reflect_pdf<T: Real>(pdf_m: T, v_dot_h: T) -> T {
    // v.h is a cosine: +-inf counts as +-1 (rules 3 and 5), not as a 0 pdf.
    let v_dot_h = crate::domain::unit_if_inf(v_dot_h);
    let den = T::splat(4.0) * v_dot_h.abs();
    let v = T::select(den.simd_gt(T::ZERO), (pdf_m / den).min(T::MAX), T::ZERO);
    let pdf_ok = pdf_m.simd_ge(T::ZERO) & pdf_m.simd_lt(T::INFINITY);
    nan_where(!pdf_ok | v_dot_h.is_nan(), v)
}

/// Microfacet normal from a slope (sx, sy) of the unit-roughness distribution, stretched by
/// (alpha_x, alpha_y): m = normalize(-alpha_x sx, -alpha_y sy, 1) (Heitz 2014, section 5.2:
/// stretching slopes turns the alpha = 1 distribution into the anisotropic one).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn normal_from_slope<T: Real>(sx: T, sy: T, ax: T, ay: T) -> V3<T> {
    V3::new(-ax * sx, -ay * sy, T::ONE).normalize_or(V3::unit_z())
}

/// A GGX microfacet normal with pdf D(m) cos(theta_m) (the classic NDF sampling: every normal,
/// visible or not). The slope of the unit GGX, radius r = sqrt(u1 / (1 - u1)) at angle
/// phi = 2 pi u2, stretched by alpha: m = normalize(-alpha_x r cos phi, -alpha_y r sin phi, 1)
/// (Walter et al. 2007 eq. 35-36; anisotropic by Heitz 2014 section 5.2). A slope points
/// down the facet and its normal up it, so for an isotropic alpha the normal's azimuth is
/// phi + pi = 2 pi u2 + pi, not 2 pi u2.
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_d_cos<T: Real>(ggx: &Ggx<T>, u1: T, u2: T) -> (V3<T>, T) {
    let (u1, u2) = (clamp_u(u1), clamp_u(u2));
    let (ax, ay) = ggx.clamped_alphas();
    let r = (u1 / (T::ONE - u1)).sqrt();
    let phi = T::TWO * T::PI * u2;
    let m = normal_from_slope(r * phi.cos(), r * phi.sin(), ax, ay);
    nan_sample(
        u1.is_nan() | u2.is_nan() | ax.is_nan() | ay.is_nan(),
        m,
        d_cos_pdf(ggx, m),
    )
}

/// A Beckmann microfacet normal with pdf D(m) cos(theta_m): the slope of the unit Beckmann (a
/// 2D Gaussian of variance 1/2), radius r = sqrt(-ln(1 - u1)) at angle phi = 2 pi u2, stretched
/// by alpha: m = normalize(-alpha_x r cos phi, -alpha_y r sin phi, 1) (Walter et al. 2007
/// eq. 28-29). As for [`ggx_d_cos`], an isotropic normal's azimuth is 2 pi u2 + pi.
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_d_cos<T: Real>(beckmann: &Beckmann<T>, u1: T, u2: T) -> (V3<T>, T) {
    let (u1, u2) = (clamp_u(u1), clamp_u(u2));
    let (ax, ay) = beckmann.clamped_alphas();
    let r = (-(T::ONE - u1).ln()).sqrt_nonneg();
    let phi = T::TWO * T::PI * u2;
    let m = normal_from_slope(r * phi.cos(), r * phi.sin(), ax, ay);
    let bad = u1.is_nan() | u2.is_nan() | ax.is_nan() | ay.is_nan();
    nan_sample(bad, m, d_cos_pdf(beckmann, m))
}

/// pdf D(m) max(0, m.z) of `ggx_d_cos` and `beckmann_d_cos` (each behind its feature).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
#[must_use]
pub fn d_cos_pdf<T: Real, M: Microfacet<T> + ?Sized>(dist: &M, m: V3<T>) -> T {
    dist.d(m) * m.z.max(T::ZERO)
}

/// pdf of the visible-normal samplers: D_wo(m) (`Microfacet::d_visible`), with wo mirrored into
/// the upper hemisphere as the samplers do. 0 for wo at the horizon or of zero length (a
/// visible-normal sampler given the zero vector returns a finite normal with this pdf, 0);
/// NaN for a NaN or infinite component of wo.
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
#[must_use]
pub fn visible_normal_pdf<T: Real, M: Microfacet<T> + ?Sized>(dist: &M, wo: V3<T>, m: V3<T>) -> T {
    dist.d_visible(V3::new(wo.x, wo.y, wo.z.abs()), m)
}

/// `wo` flipped into the upper hemisphere and stretched to the unit-roughness configuration:
/// normalize(alpha_x wo.x, alpha_y wo.y, |wo.z|).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn stretch<T: Real>(wo: V3<T>, ax: T, ay: T) -> V3<T> {
    V3::new(ax * wo.x, ay * wo.y, wo.z.abs()).normalize_or(V3::unit_z())
}

/// A GGX visible normal (pdf D_wo(m)) by Heitz 2018, "Sampling the GGX Distribution of Visible
/// Normals" (JCGT 7(4)): stretch wo to the unit hemisphere configuration, v, sample the
/// projected hemisphere seen from it (a disk whose far half is squashed by (1 + v.z) / 2),
/// lift, and unstretch. wo below the horizon is mirrored (the visible normals of |wo.z|).
///
/// The disk point is sqrt(u1) (cos phi, sin phi) with phi = 2 pi u2, in the basis
/// t1 = (-v.y, v.x, 0) / |(v.x, v.y)| (across wo's azimuth), t2 = v x t1; at normal incidence,
/// where that azimuth is undefined, t1 = +x, t2 = +y, so an isotropic normal's azimuth is
/// 2 pi u2 there. The sample is continuous in wo everywhere else.
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_vndf<T: Real>(ggx: &Ggx<T>, wo: V3<T>, u1: T, u2: T) -> (V3<T>, T) {
    let (u1, u2) = (clamp_u(u1), clamp_u(u2));
    let (ax, ay) = ggx.clamped_alphas();
    let vh = stretch(wo, ax, ay);
    // Orthonormal basis around vh; at vh = +z (normal view) any tangent works.
    let len2 = vh.x.mul_add(vh.x, vh.y * vh.y);
    let has_tangent = len2.simd_gt(T::ZERO);
    let inv_len = T::select(has_tangent, len2.sqrt().recip(), T::ZERO);
    let t1 = V3::new(
        T::select(has_tangent, -vh.y * inv_len, T::ONE),
        vh.x * inv_len,
        T::ZERO,
    );
    let t2 = vh.cross(t1);
    // Uniform disk point, then the squash of the half the view cannot see.
    let r = u1.sqrt();
    let phi = T::TWO * T::PI * u2;
    let p1 = r * phi.cos();
    let s = T::HALF * (T::ONE + vh.z);
    let p2 = (T::ONE - s) * (T::ONE - p1 * p1).sqrt_nonneg() + s * (r * phi.sin());
    let lift = (T::ONE - p1 * p1 - p2 * p2).sqrt_nonneg();
    let nh = t1 * p1 + t2 * p2 + vh * lift;
    let m = V3::new(ax * nh.x, ay * nh.y, nh.z.max(T::ZERO)).normalize_or(V3::unit_z());
    let bad = any_nonfinite3(wo) | u1.is_nan() | u2.is_nan() | ax.is_nan() | ay.is_nan();
    nan_sample(bad, m, visible_normal_pdf(ggx, wo, m))
}

/// A GGX visible normal (pdf D_wo(m)) by the spherical-cap method of Dupuy and Benyoub 2023,
/// "Sampling Visible GGX Normals with Spherical Caps" (HPG): in the unit configuration the
/// visible normals are the half vectors between the stretched view and uniform directions on
/// the spherical cap z >= -v.z; one uniform cap sample, one add, one unstretch. Same
/// distribution as [`ggx_vndf`], fewer operations and no basis.
///
/// The cap point has azimuth phi = 2 pi u1 and height z = (1 - u2)(1 + v.z) - v.z (u1 is the
/// angle here, not u2), so at normal incidence an isotropic normal's azimuth is 2 pi u1. With
/// no basis the sample is continuous in wo everywhere, normal incidence included.
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_vndf_spherical_cap<T: Real>(ggx: &Ggx<T>, wo: V3<T>, u1: T, u2: T) -> (V3<T>, T) {
    let (u1, u2) = (clamp_u(u1), clamp_u(u2));
    let (ax, ay) = ggx.clamped_alphas();
    let v = stretch(wo, ax, ay);
    let phi = T::TWO * T::PI * u1;
    let z = (T::ONE - u2).mul_add(T::ONE + v.z, -v.z);
    let sin_theta = (T::ONE - z * z).sqrt_nonneg();
    let c = V3::new(sin_theta * phi.cos(), sin_theta * phi.sin(), z);
    let h = c + v;
    let m = V3::new(ax * h.x, ay * h.y, h.z.max(T::ZERO)).normalize_or(V3::unit_z());
    let bad = any_nonfinite3(wo) | u1.is_nan() | u2.is_nan() | ax.is_nan() | ay.is_nan();
    nan_sample(bad, m, visible_normal_pdf(ggx, wo, m))
}

/// 1 / sqrt(pi).
#[cfg(feature = "beckmann")]
const FRAC_1_SQRT_PI: f64 = 0.564_189_583_547_756_3;

/// Inverse error function erf^-1(y) for y in (-1, 1): Giles' single-precision polynomial
/// (Giles 2010, "Approximating the erfinv function", GPU Computing Gems Jade, about 4e-7
/// relative), polished by two Newton steps: on erf(x) - y for |y| <= 1/2, on
/// ln(erfc(|x|) / (1 - |y|)) beyond, so that the tails are relative to 1 - |y|. erfc(x) is
/// 1 - |y| within 0.52 (1 + 2 x^2) eps (the rounding of x) for 1 - |y| down to 2^-30 in f64
/// and over all of f32; below 2^-30 the polynomial (fit for f32's range) starts too far off
/// for two steps, and erfc(x) / (1 - |y|) - 1 reaches 1.9e-3 at 2^-53
/// (`tests/sampling/beckmann_inversion.rs`). +-inf at +-1; NaN outside [-1, 1].
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn erf_inv<T: Real>(y: T) -> T {
    let w = -((T::ONE - y) * (T::ONE + y)).ln();
    let central = {
        let w = w - T::splat(2.5);
        let mut p = T::splat(2.810_226_36e-08);
        for c in [
            3.432_739_39e-07,
            -3.523_387_7e-06,
            -4.391_506_54e-06,
            0.000_218_580_87,
            -0.001_253_725_03,
            -0.004_177_681_64,
            0.246_640_727,
            1.501_409_41,
        ] {
            p = p.mul_add(w, T::splat(c));
        }
        p
    };
    let tail = {
        let w = w.sqrt_nonneg() - T::splat(3.0);
        let mut p = T::splat(-0.000_200_214_257);
        for c in [
            0.000_100_950_558,
            0.001_349_343_22,
            -0.003_673_428_44,
            0.005_739_507_73,
            -0.007_622_461_3,
            0.009_438_870_47,
            1.001_674_06,
            2.832_976_82,
        ] {
            p = p.mul_add(w, T::splat(c));
        }
        p
    };
    let mut x = T::select(w.simd_lt(T::splat(5.0)), central, tail) * y;
    // Newton on f(x) = erf(x) - y, f'(x) = 2 / sqrt(pi) exp(-x^2), for |y| <= 1/2. In the
    // tails, on ln(erfc(|x|) / q) with q = 1 - |y| (exact there, Sterbenz): erf(x) - y has
    // an absolute error of eps there, all of q for q near eps, and erfc is exponential, so
    // plain Newton crawled (erf_inv(1 - 2^-51) gave 5.41 for 5.84); the log form is nearly
    // quadratic in x and is relative to q. Skipped (by select) where the derivative
    // underflows, i.e. |x| > 9, where the polynomial is already exact to f64.
    let q = T::ONE - y.abs();
    let in_tail = q.simd_lt(T::HALF);
    for _ in 0..2 {
        let deriv = T::TWO * T::splat(FRAC_1_SQRT_PI) * (-x * x).exp();
        let ec = x.abs().erfc();
        let tail_step = -(ec / q).ln() * ec * T::ONE.copysign(y);
        let step = T::select(in_tail, tail_step, x.erf() - y) / deriv;
        x = T::select(deriv.simd_gt(T::ZERO) & step.is_finite(), x - step, x);
    }
    let edge = y.abs().simd_eq(T::ONE);
    T::select(edge, T::INFINITY.copysign(y), x)
}

/// A Beckmann visible normal (pdf D_wo(m)) by Heitz and d'Eon 2014, "Importance Sampling
/// Microfacet-Based BSDFs using the Distribution of Visible Normals" (EGSR), with Jakob's
/// improvements (Mitsuba): in the unit configuration seen from theta, draw the slope x from
/// its marginal by inverting its CDF at u1, (1 + erf(x) + tan(theta) exp(-x^2) / sqrt(pi)) /
/// norm, with a fitted initial guess and 7 safeguarded Newton-bisection steps in erf space
/// (b = erf(x)), then y from the Gaussian y = erf^-1(2 u2 - 1); rotate by the azimuth of wo,
/// stretch by alpha: m = normalize(-alpha_x sx, -alpha_y sy, 1) for the rotated slope
/// (sx, sy). For u1 > 1/2 each Newton step is taken on sqrt(1 - CDF) - sqrt(1 - u1): the CDF
/// meets 1 quadratically at x = cot(theta), where plain Newton only halves the error per
/// step (Jakob's 8 plain steps were just enough in f64, 7 left 20 times the bound below).
/// With it 6 steps meet the bound (5 leave 8 times it); 7 keep one step of margin.
///
/// Accuracy (`tests/sampling/beckmann_inversion.rs` recovers x from the returned normal and
/// evaluates the CDF in f64 without cancellation, over theta_o from 0 to 89.99 degrees,
/// alpha from ALPHA_MIN to ALPHA_MAX, isotropic and anisotropic, u1 up to the largest float
/// below 1, and random views, alphas and u1 on f32, f64, f32x8 and f64x4): |CDF(x) - u1| is
/// at most 2.0 eps in f32 and 2.25 eps in f64, and within 1.7 times the change in the CDF
/// that rounding the output (the erf-space step, x, tan(theta)) explains; the test asserts
/// 4. The solve is in erf space, whose step near b = 1 is an absolute eps, so 1 - CDF(x)
/// matches 1 - u1 only to about an eps: relative, 1.4e-2 for 1 - u1 in (1e-5, 1e-4] and 0.14
/// in (1e-6, 1e-5] in f32, up to 2.5 at 2^-24; 1.6e-3 in (1e-13, 1e-12] in f64, up to 2.2 at
/// 2^-53. The sampled density departs from the pdf only on that last eps of probability.
/// Cost: 1.8 us a sample in f32 scalar against 1.5 us before these fixes (`cargo bench -p brdf-bench
/// --bench sampling -- "beckmann vndf"`, a shared 2-core machine), mostly the erfc and ln of
/// erf^-1's tail polish, which every step needs (polishing only the last steps left f64 at 9
/// times the bound).
/// (Before: the solve could end at b = 1 where erf(cot) rounds to 1, whose slope is
/// infinite and whose normal fell back to +z, CDF 0.52 for u1 = 1 - 2^-24 in f32 at a
/// stretched theta of 4.8 degrees; and erf^-1 near 1 was off by up to 84 times 1 - b in f64.)
///
/// The two slopes are drawn separately, with no polar angle: u1 moves the normal along the
/// stretched view's azimuth (towards wo as u1 decreases), u2 across it. The same inversion
/// serves every wo: at normal incidence tan(theta) = 0 leaves the CDF (1 + erf(x)) / 2,
/// linear in erf(x), so the start is already its inverse, x = erf^-1(2 u1 - 1), in the
/// tangent frame (wo's azimuth is undefined there; elsewhere the sample is continuous in wo).
/// u1 and u2 below 1e-6 are raised to it, as in Mitsuba, which moves the slopes' lower tails
/// beyond that quantile onto it (a probability of 1e-6 each).
///
/// Lanes run the same fixed 7 steps (no data-dependent loop), so lanes equal scalars.
#[cfg(feature = "beckmann")]
#[must_use]
pub fn beckmann_vndf<T: Real>(beckmann: &Beckmann<T>, wo: V3<T>, u1: T, u2: T) -> (V3<T>, T) {
    let (u1, u2) = (clamp_u(u1), clamp_u(u2));
    let (ax, ay) = beckmann.clamped_alphas();
    let v = stretch(wo, ax, ay);
    let cos_t = v.z;
    let sin_t = v.x.mul_add(v.x, v.y * v.y).sqrt();
    // No special case near normal incidence: Gaussian slopes in polar form are D cos normals,
    // the visible ones at theta = 0 only (below 0.81 degrees they once gave E[m.x] = 0 where
    // D_wo has 4.3e-3 at alpha = 1, theta_o = 0.79 degrees, and made the sample jump where wo
    // crossed the switch). At theta = 0 (sin_t = 0) the inversion below stays finite:
    // tan_t = 0, cot_t = +inf, erf(cot_t) = 1 and tan_t exp(-cot_t^2) = 0.
    let tan_t = sin_t / cos_t;
    let cot_t = cos_t / sin_t;
    let sqrt_pi_inv = T::splat(FRAC_1_SQRT_PI);
    // Bracket [a, c] in erf space and the fitted start of Jakob's method.
    let mut lo = -T::ONE;
    let mut hi = cot_t.erf();
    let sample_x = u1.max(T::splat(1e-6));
    let theta = cos_t.acos();
    let fit =
        T::ONE + theta * (T::splat(-0.876) + theta * (T::splat(0.4265) - T::splat(0.0594) * theta));
    let mut b = hi - (T::ONE + hi) * (T::ONE - sample_x).pow(fit);
    let norm = (T::ONE + hi + sqrt_pi_inv * tan_t * (-cot_t * cot_t).exp()).recip();
    let tail_u = T::ONE - sample_x;
    let upper = sample_x.simd_gt(T::HALF);
    for _ in 0..7 {
        let inside = b.simd_ge(lo) & b.simd_le(hi);
        b = T::select(inside, b, T::HALF * (lo + hi));
        let x = erf_inv(b);
        let value = norm * (T::ONE + b + sqrt_pi_inv * tan_t * (-x * x).exp()) - sample_x;
        let deriv = norm * (T::ONE - x * tan_t);
        let above = value.simd_gt(T::ZERO);
        hi = T::select(above, b, hi);
        lo = T::select(above, lo, b);
        // Newton on sqrt(1 - C) - sqrt(1 - u1) in the upper half, where 1 - C = tail.
        let tail = tail_u - value;
        let (st, su) = (tail.max(T::ZERO).sqrt(), tail_u.sqrt());
        let upper_tail = upper & tail.simd_gt(T::ZERO);
        let gain = T::select(upper_tail, T::TWO * st / (st + su), T::ONE);
        let next = b - gain * value / deriv;
        // Bisect where the step is unusable: at b = 1 (erf(cot) rounded to 1) x = inf, the
        // derivative -inf and the step 0, which kept b there.
        let newton = next.is_finite() & deriv.simd_gt(T::ZERO);
        b = T::select(newton, next, T::HALF * (lo + hi));
    }
    let b = b.clamp(lo, hi);
    // The slope never exceeds cot(theta), where the CDF reaches 1. Where erf(cot) rounds to 1
    // (cot above 3.9 in f32, 5.9 in f64) the solve can end at b = 1, whose erf^-1 is +inf
    // and whose normal collapsed to +z (u1 = 1 - 2^-24 at theta 4.8 degrees gave x = 0, CDF
    // 0.52); cot is the top of the slopes the rounded b stands for.
    let sx = erf_inv(b).min(cot_t);
    let sy = erf_inv(T::TWO * u2.max(T::splat(1e-6)) - T::ONE);
    // Rotate from the view's azimuth frame to the tangent frame.
    let has_azimuth = sin_t.simd_gt(T::ZERO);
    let cos_p = T::select(has_azimuth, v.x / sin_t, T::ONE);
    let sin_p = T::select(has_azimuth, v.y / sin_t, T::ZERO);
    let rx = cos_p * sx - sin_p * sy;
    let ry = sin_p * sx + cos_p * sy;
    let m = normal_from_slope(rx, ry, ax, ay);
    let bad = any_nonfinite3(wo) | u1.is_nan() | u2.is_nan() | ax.is_nan() | ay.is_nan();
    nan_sample(bad, m, visible_normal_pdf(beckmann, wo, m))
}

/// Mirror reflection of `wo` about the unit microfacet normal `m`: wi = 2 (wo.m) m - wo (both
/// pointing away from the surface).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn reflect_about<T: Real>(wo: V3<T>, m: V3<T>) -> V3<T> {
    m * (T::TWO * wo.dot(m)) - wo
}

/// pdf (solid angle) of a direction reflected off a visible normal: D_wo(h) / (4 wo.h) with
/// h = normalize(wo + wi), written G1(wo) D(h) / (4 wo.z) (wo.h cancels), and G1(wo) / wo.z
/// as 1 / (wo.z + wo.z Lambda(wo)) so that it stays finite at the horizon.
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn vndf_reflection_pdf<T: Real, M: Microfacet<T> + ?Sized>(dist: &M, wo: V3<T>, wi: V3<T>) -> T {
    let h = (wo + wi).normalize_or(V3::unit_z());
    let c = wo.z;
    let inv = (T::splat(4.0) * (c + dist.cos_lambda(wo)))
        .recip()
        .min(T::MAX);
    // wo.h = |wo + wi| / 2 >= 0 analytically; 0 only for wi = -wo, where h is undefined.
    // A zero-length wi has no reflection Jacobian: pdf 0, like wi = -wo (and wo = 0 has c = 0).
    let visible = c.simd_gt(T::ZERO) & wo.dot(h).simd_gt(T::ZERO) & !crate::vec3::is_zero3(wi);
    let p = T::select(visible, (inv * dist.d(h)).min(T::MAX), T::ZERO);
    nan_where(any_nonfinite3(wo) | any_nonfinite3(wi), p)
}

/// The sample of a reflection sampler without its Fresnel factor: (wi, pdf, G2 / G1(wo),
/// wo.m), with G2 / G1 = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)) masked to 0 where
/// wo or wi is at or below the horizon (NaN for NaN).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn reflection_parts<T: Real, M: Microfacet<T> + ?Sized>(
    dist: &M,
    wo: V3<T>,
    m: V3<T>,
) -> (V3<T>, T, T, T) {
    let wi = reflect_about(wo, m);
    let pdf = vndf_reflection_pdf(dist, wo, wi);
    // Each Lambda is capped at MAX; a sum overflowing to inf gives the right limit 0.
    let lo = T::ONE + dist.lambda(wo);
    let ratio = lo / (lo + dist.lambda(wi));
    let ratio = crate::domain::above_horizon(wo.z, wi.z, ratio);
    (wi, pdf, ratio, wo.dot(m).saturate())
}

/// The weight F G2 / G1 of one channel: NaN where F is NaN, negative or infinite (rule 5),
/// capped at MAX.
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn weigh<T: Real>(ratio: T, f: T) -> T {
    let ok = f.simd_ge(T::ZERO) & f.simd_lt(T::INFINITY);
    crate::domain::nan_unless(ok, (ratio * f).min(T::MAX))
}

/// Samples the Cook-Torrance reflection lobe of a GGX surface and returns (wi, pdf, weight):
/// a visible normal m ([`ggx_vndf_spherical_cap`]; Heitz 2018, "Sampling the GGX
/// Distribution of Visible Normals"; Dupuy and Benyoub 2023), wi = 2 (wo.m) m - wo, its pdf
/// [`ggx_reflection_pdf`]`(ggx, wo, wi)` (the same value, bit for bit), and the Monte Carlo
/// weight f(wo, wi) wi.z / pdf of the lobe f = D G2 F / (4 wo.z wi.z) (`cook_torrance::eval`
/// with the height-correlated G2).
///
/// With visible-normal sampling the pdf is G1(wo) D(m) / (4 wo.z), so D and the cosines
/// cancel and the weight is F(wo.m) G2(wo, wi) / G1(wo) = F (1 + Lambda(wo)) / (1 +
/// Lambda(wo) + Lambda(wi)) (Heitz 2018; Heitz and d'Eon 2014): in [0, F], with no
/// division by a small pdf, which is why it is computed in this form and not as f cos / pdf.
/// `fresnel` is called once with wo.m (= wi.m, clamped to [0, 1]); any Fresnel form of
/// `brdf::fresnel` (scalar), or a constant; it must return F >= 0.
///
/// Edges: a wi reflected below the horizon (a grazing view and a steep visible normal) is
/// returned as drawn with its pdf > 0 and weight 0 (the lobe is reflection only; pbrt-v4
/// returns no sample there, the same estimator). wo at or below the horizon (finite): the
/// lobe is 0, so pdf 0 and weight 0, wi still a unit vector. u outside [0, 1) is clamped
/// into it. NaN in a component of wo, in u1 or u2 gives a NaN wi (all three components), pdf
/// and weight; a NaN or negative F gives a NaN weight.
///
/// ```
/// use brdf::{V3, ggx::Ggx, sampling};
/// let ggx = Ggx::isotropic(0.3).unwrap();
/// let wo = V3::new(0.6, 0.0, 0.8);
/// let (wi, pdf, weight) = sampling::ggx_reflection(&ggx, wo, 0.4, 0.7, |_| 1.0);
/// assert!(wi.z > 0.0 && pdf > 0.0 && weight > 0.0 && weight <= 1.0);
/// assert_eq!(pdf, sampling::ggx_reflection_pdf(&ggx, wo, wi));
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_reflection<T: Real>(
    ggx: &Ggx<T>,
    wo: V3<T>,
    u1: T,
    u2: T,
    fresnel: impl Fn(T) -> T,
) -> (V3<T>, T, T) {
    let (m, _) = ggx_vndf_spherical_cap(ggx, wo, u1, u2);
    let (wi, pdf, ratio, v_dot_h) = reflection_parts(ggx, wo, m);
    (wi, pdf, weigh(ratio, fresnel(v_dot_h)))
}

/// [`ggx_reflection`] with an RGB Fresnel term (for example `fresnel::schlick_rgb` or
/// `fresnel::conductor_rgb`): the weight is F_c G2 / G1(wo) per channel (x = r, y = g,
/// z = b), each channel NaN where its F is NaN or negative; wi and pdf as [`ggx_reflection`].
///
/// ```
/// use brdf::{V3, ggx::Ggx, sampling};
/// let ggx = Ggx::isotropic(0.3).unwrap();
/// let tint = V3::new(1.0, 0.8, 0.3);
/// let (_, _, w) = sampling::ggx_reflection_rgb(&ggx, V3::new(0.0, 0.0, 1.0), 0.2, 0.5, |_| tint);
/// assert!(w.x >= w.y && w.y >= w.z && w.z > 0.0);
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_reflection_rgb<T: Real>(
    ggx: &Ggx<T>,
    wo: V3<T>,
    u1: T,
    u2: T,
    fresnel: impl Fn(T) -> V3<T>,
) -> (V3<T>, T, V3<T>) {
    let (m, _) = ggx_vndf_spherical_cap(ggx, wo, u1, u2);
    let (wi, pdf, ratio, v_dot_h) = reflection_parts(ggx, wo, m);
    let f = fresnel(v_dot_h);
    let w = V3::new(weigh(ratio, f.x), weigh(ratio, f.y), weigh(ratio, f.z));
    (wi, pdf, w)
}

/// pdf (solid angle) of [`ggx_reflection`] and [`ggx_reflection_rgb`], for multiple
/// importance sampling: with h = normalize(wo + wi),
/// pdf = D_wo(h) / (4 wo.h) = G1(wo) D(h) / (4 wo.z)
/// (the visible-normal density, [`visible_normal_pdf`], times the reflection Jacobian
/// 1 / (4 wo.h) of [`reflect_pdf`]; Walter et al. 2007, eq. 14; Heitz 2018, eq. 17), evaluated
/// in the second form, in which wo.h has cancelled.
///
/// Domain: unit local-frame vectors. Integrates to 1 over the whole sphere of wi for every
/// wo above the horizon; where wi is below the horizon it is the density of the samples
/// reflected there (> 0), for which the weight is 0. 0 where wo.z <= 0 (the lobe is
/// reflection only and the sampler returns pdf 0 there, a zero-length wo included), where
/// wi = -wo and where wi is the zero vector. Capped at the largest finite value. NaN for a
/// NaN or infinite component of wo or wi.
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_reflection_pdf<T: Real>(ggx: &Ggx<T>, wo: V3<T>, wi: V3<T>) -> T {
    vndf_reflection_pdf(ggx, wo, wi)
}

/// `ggx_reflection` for a Beckmann surface: a visible normal m from [`beckmann_vndf`]
/// (Heitz and d'Eon 2014, "Importance Sampling Microfacet-Based BSDFs using the Distribution
/// of Visible Normals"), wi = 2 (wo.m) m - wo, pdf [`beckmann_reflection_pdf`]`(beckmann, wo,
/// wi)` and weight F(wo.m) G2 / G1(wo), the same simplification of f wi.z / pdf as for GGX
/// (it holds for every distribution sampled by its visible normals). Edges, NaN and the
/// Fresnel closure as `ggx_reflection`:
/// a wi below the horizon keeps its pdf > 0 with weight 0; wo at or below the horizon gives
/// pdf 0 and weight 0; NaN in wo, u1 or u2 gives NaN wi, pdf and weight; a NaN or negative F a
/// NaN weight.
///
/// ```
/// use brdf::{V3, beckmann::Beckmann, sampling};
/// let b = Beckmann::isotropic(0.3).unwrap();
/// let wo = V3::new(0.6, 0.0, 0.8);
/// let (wi, pdf, weight) = sampling::beckmann_reflection(&b, wo, 0.4, 0.7, |_| 1.0);
/// assert!(wi.z > 0.0 && pdf > 0.0 && weight > 0.0 && weight <= 1.0);
/// ```
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_reflection<T: Real>(
    beckmann: &Beckmann<T>,
    wo: V3<T>,
    u1: T,
    u2: T,
    fresnel: impl Fn(T) -> T,
) -> (V3<T>, T, T) {
    let (m, _) = beckmann_vndf(beckmann, wo, u1, u2);
    let (wi, pdf, ratio, v_dot_h) = reflection_parts(beckmann, wo, m);
    (wi, pdf, weigh(ratio, fresnel(v_dot_h)))
}

/// [`beckmann_reflection`] with an RGB Fresnel term: the weight is F_c G2 / G1(wo) per
/// channel, each NaN where its F is NaN or negative; wi and pdf as [`beckmann_reflection`].
///
/// ```
/// use brdf::{V3, beckmann::Beckmann, sampling};
/// let b = Beckmann::isotropic(0.3).unwrap();
/// let (_, _, w) = sampling::beckmann_reflection_rgb(&b, V3::new(0.0, 0.0, 1.0), 0.2, 0.5, |_| {
///     V3::new(1.0, 0.8, 0.3)
/// });
/// assert!(w.x >= w.y && w.y >= w.z && w.z > 0.0);
/// ```
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_reflection_rgb<T: Real>(
    beckmann: &Beckmann<T>,
    wo: V3<T>,
    u1: T,
    u2: T,
    fresnel: impl Fn(T) -> V3<T>,
) -> (V3<T>, T, V3<T>) {
    let (m, _) = beckmann_vndf(beckmann, wo, u1, u2);
    let (wi, pdf, ratio, v_dot_h) = reflection_parts(beckmann, wo, m);
    let f = fresnel(v_dot_h);
    let w = V3::new(weigh(ratio, f.x), weigh(ratio, f.y), weigh(ratio, f.z));
    (wi, pdf, w)
}

/// pdf (solid angle) of [`beckmann_reflection`] and [`beckmann_reflection_rgb`]:
/// G1(wo) D(h) / (4 wo.z) with h = normalize(wo + wi); form, domain and edges as
/// `ggx_reflection_pdf`: integrates to 1 over the sphere of wi for wo above the horizon, > 0
/// below the horizon (where the weight is 0), 0 where wo.z <= 0, wi = -wo or wi = 0, capped at the
/// largest finite value, NaN for a NaN or infinite component.
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_reflection_pdf<T: Real>(beckmann: &Beckmann<T>, wo: V3<T>, wi: V3<T>) -> T {
    vndf_reflection_pdf(beckmann, wo, wi)
}
