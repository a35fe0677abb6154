//! EON: the energy-preserving Oren-Nayar model, its directional albedo and its importance
//! sampling (Portsmouth, Kutz, Hill 2025, "EON: A Practical Energy-Preserving Rough Diffuse
//! BRDF", JCGT 14(1); the diffuse lobe of the OpenPBR Surface specification, whose
//! `diffuse_roughness` is sigma below).
//!
//! EON is Fujii's Oren-Nayar (FON) single-scattering lobe plus a separable multiple-scattering
//! lobe that returns exactly the energy FON loses:
//!
//! ```text
//! f = f_FON + f_ms
//! f_FON = rho/pi * A (1 + sigma s/t)                  A = 1 / (1 + c1 sigma)
//!   s = v.l - (n.v)(n.l),  t = max(n.v, n.l) where s > 0, else t = 1
//! f_ms  = rho_ms/pi * (1 - E(n.v)) (1 - E(n.l)) / (1 - E_avg)
//! E(mu)  = A (1 + sigma G(mu)/pi)                     FON directional albedo at rho = 1
//! E_avg  = A (1 + c2 sigma)                           its cosine-weighted average
//! rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg))        multiple-scattering albedo
//! c1 = 1/2 - 2/(3 pi),  c2 = 2/3 - 28/(15 pi)
//! ```
//!
//! The directional albedo is then rho E + rho_ms (1 - E) in closed form, 1 when rho = 1. The
//! compensation lobe has the separable form of Kelemen and Szirmay-Kalos 2001, "A Microfacet
//! Based Coupled Specular-Matte BRDF Model with Importance Sampling".
//!
//! Two variants differ only in how E(mu) is computed: [`eon`] uses the exact E, so its
//! white-furnace albedo is 1 to rounding; [`eon_approx`] uses the quartic fit the paper ships
//! for shaders (no `acos`), whose albedo error is the fit's (see [`eon_fon_albedo_approx`]).
//!
//! # Implementation notes
//! With u = 1 - E the compensation term is written without the quotient of small numbers the
//! paper's listing guards with `max(1e-7, ...)`: 1 - E(mu) = sigma (c1 - G(mu)/pi) A and
//! 1 - E_avg = sigma (c1 - c2) A, so (1 - E_o)(1 - E_i)/(1 - E_avg) =
//! sigma A (c1 - g_o)(c1 - g_i)/(c1 - c2), which is exactly 0 at sigma = 0 (EON is then
//! Lambert exactly, where the listing adds rho^2 1e-7 / pi). With the fit, each factor c1 - g is
//! clamped at 0: the fit overshoots c1 by 4.6e-4 at grazing, where the exact value is 0. The
//! exact c1 - G/pi is not formed as a difference at all (it cancels towards grazing): it is
//! computed as S asin(mu) + (1 - S)(...) with nothing left to cancel (see `pi_loss_exact`).
//!
//! As everywhere in this crate, a parameter outside its domain gives NaN for every pair of
//! directions, those below the horizon included, and a NaN input gives NaN.

use crate::domain::{above_horizon, checked_unit, in_unit, nan_unless, nan_where, unit_if_inf};
use crate::dw::Dw;
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

/// c1 = 1/2 - 2/(3 pi) = G(0)/pi: Fujii's normalization A = 1/(1 + c1 sigma) makes the FON
/// albedo exactly 1 at grazing incidence and below 1 elsewhere.
const C1: f64 = 0.287_793_409_210_806_2;
/// c1 - `C1`, the rest of c1 beyond f64.
const C1_TAIL: f64 = 1.311_911_778_345_499_2e-17;
/// c2 = 2/3 - 28/(15 pi) = 2 integral_0^1 (G(mu)/pi) mu dmu: the average albedo's slope.
const C2: f64 = 0.072_488_212_456_924_08;
/// c2 - `C2`.
const C2_TAIL: f64 = 1.576_467_347_210_685_2e-18;
/// c1 - c2, the factor of sigma A in 1 - E_avg.
const C1_MINUS_C2: f64 = 0.215_305_196_753_882_13;
/// (c1 - c2) - `C1_MINUS_C2`.
const C1_MINUS_C2_TAIL: f64 = 1.154_265_043_624_430_6e-17;
/// 1 / (pi^3 (c1 - c2)): the constant of the compensation lobe written in pi c1 - G (below).
const MS_SCALE: f64 = 0.149_794_500_641_183_27;
/// `MS_SCALE`'s rest beyond f64.
const MS_SCALE_TAIL: f64 = 4.333_174_584_654_001e-18;
/// pi c1 = pi/2 - 2/3 = pi (1 - E(1)) / (sigma A): E's deficit at normal incidence.
const PI_C1: f64 = 0.904_129_660_128_229_9;
/// `PI_C1`'s rest beyond f64.
const PI_C1_TAIL: f64 = 2.422_490_580_319_577_5e-17;
/// The paper's fit of G(mu)/pi as a quartic in 1 - mu (coefficients of (1-mu)^1..(1-mu)^4).
const G_FIT: [f64; 4] = [
    0.057_108_528_9,
    0.491_881_867,
    -0.332_181_442,
    0.071_442_995_3,
];

/// Fujii's A = 1 / (1 + c1 sigma).
#[inline]
fn fon_a<T: Real>(sigma: T) -> T {
    T::splat(C1).mul_add(sigma, T::ONE).recip()
}

/// pi c1 - G(mu) = pi (1 - E(mu)) / (sigma A) for mu in [0, 1] (the FON albedo integral;
/// Portsmouth et al. 2025, `E_FON_exact`) as a double word. G as printed,
/// S (acos(mu) - S mu) + (2/3)((S/mu)(1 - S^3) - S) with S = sqrt(1 - mu^2), tends to pi c1
/// at grazing, so c1 - G/pi cancels: 13 ULP lost at mu = 0.15 in f64, and in f32 all of them
/// below mu = 1e-7, where c1 - G/pi, about mu/pi, is below an ULP of c1. With
/// acos = pi/2 - asin and (S/mu)(1 - S^3) = S mu (1 + S + S^2)/(1 + S) (from
/// 1 - S = mu^2/(1 + S)), the constant and the O(mu) terms cancel symbolically:
/// pi c1 - G = S asin(mu) + (1 - S) (pi c1 - S mu (2 + S) / (3 (1 + S))),
/// two terms >= 0, the subtraction taking at most 0.3 of pi c1. 1 - S is formed as
/// mu^2/(1 + S) where it would cancel (S > 1/2); pi c1, the products and the sum are carried in
/// double words, so the roundings left are those of S, `asin` and the bracket's small term.
#[inline]
fn pi_loss_exact<T: Real>(mu: T) -> Dw<T> {
    let si = ((T::ONE - mu) * (T::ONE + mu)).sqrt_nonneg();
    let one_plus_si = T::ONE + si;
    let one_minus_si = T::select(si.simd_gt(T::HALF), mu * mu / one_plus_si, T::ONE - si);
    let bracket = Dw::constant(PI_C1, PI_C1_TAIL)
        .add_t(-(si * mu * (si + T::TWO) / (T::splat(3.0) * one_plus_si)));
    Dw::product(si, mu.asin()).add(bracket.mul(Dw::exact(one_minus_si)))
}

/// c1 - G(mu)/pi from [`pi_loss_exact`], rounded once.
#[inline]
fn loss_exact<T: Real>(mu: T) -> T {
    Dw::frac_1_pi().mul(pi_loss_exact(mu)).value()
}

/// The paper's fit of G(mu)/pi: sum of G_FIT[k] (1 - mu)^(k+1), Horner form.
#[inline]
fn g_fit<T: Real>(mu: T) -> T {
    let m = T::ONE - mu;
    let p = T::splat(G_FIT[3]).mul_add(m, T::splat(G_FIT[2]));
    let p = p.mul_add(m, T::splat(G_FIT[1]));
    let p = p.mul_add(m, T::splat(G_FIT[0]));
    p * m
}

/// c1 - G(mu)/pi from the fit, clamped at 0 (see the module notes); NaN propagates.
#[inline]
fn loss_fit<T: Real>(mu: T) -> T {
    (T::splat(C1) - g_fit(mu)).max(T::ZERO)
}

/// pi c1 - G(mu) from the fit (as [`pi_loss_exact`]).
#[inline]
fn pi_loss_fit<T: Real>(mu: T) -> Dw<T> {
    Dw::exact(T::PI * loss_fit(mu))
}

/// rho_ms for an already checked rho and sigma, given A.
#[inline]
fn rho_ms_with<T: Real>(rho: T, sigma: T, a: T) -> T {
    let e_avg = T::splat(C2).mul_add(sigma, T::ONE) * a;
    // 1 - rho (1 - E_avg) >= E_avg >= 0.83 on the domain: no division by zero.
    let one_minus_e_avg = sigma * T::splat(C1_MINUS_C2) * a;
    let q = rho * rho * e_avg / (-rho).mul_add(one_minus_e_avg, T::ONE);
    // rho_ms <= rho on the domain (rho^2 E_avg <= rho (1 - rho (1 - E_avg)) is rho <= 1), and
    // rho_ms = 1 at rho = 1, but E_avg and 1 - E_avg are rounded separately, so the quotient
    // can land an ulp off (1 + 2^-23 in f32 at rho = 1, sigma = 1e-6; 1 - 2^-24 at sigma =
    // 3e-3): capped at rho, and exactly 1 at rho = 1 (a NaN sigma's NaN E_avg kept there).
    // NaN propagates (`min` keeps a NaN in self; a NaN rho makes the quotient NaN).
    let one = T::select(e_avg.is_nan(), e_avg, T::ONE);
    T::select(rho.simd_eq(T::ONE), one, q.min(rho))
}

/// The EON kernel with a given pi c1 - G (exact or fitted).
#[inline]
fn eon_with<T: Real>(
    n_dot_v: T,
    n_dot_l: T,
    v_dot_l: T,
    rho: T,
    sigma: T,
    pi_loss: impl Fn(T) -> Dw<T>,
) -> T {
    // An infinite v.l counts as +-1 (rules 3 and 5) before the shape forms inf * 0.
    let v_dot_l = unit_if_inf(v_dot_l);
    let rho = checked_unit(rho);
    let sigma = checked_unit(sigma);
    let mu_o = n_dot_v.clamp(T::ZERO, T::ONE);
    let mu_i = n_dot_l.clamp(T::ZERO, T::ONE);
    // Oren-Nayar's s = sin_i sin_o cos(phi_i - phi_o), in [-1, 1] for unit vectors. Clamped
    // there (in `fujii_shape`): cosines that no pair of unit vectors has (or rounding at
    // grazing) could otherwise push 1 + sigma s below 0 at sigma = 1, or s/t past the
    // largest float.
    // t = max(mu_i, mu_o) where s > 0. s/t grows like 1/t when both directions graze on the
    // same side (the model's backscattering peak); flooring t at the smallest normal keeps it
    // finite (below 1/MIN_POSITIVE) instead of inf for subnormal cosines. The shape
    // 1 + sigma s/t cancels towards 0 for opposite grazing directions: it is carried in
    // double words, with the single-scattering term rho A (1 + sigma s/t) / pi.
    let (shape, t) = super::fujii_shape(mu_o, mu_i, v_dot_l, sigma);
    let den = Dw::constant(C1, C1_TAIL)
        .mul(Dw::exact(sigma))
        .add_t(T::ONE);
    let single = Dw::frac_1_pi().mul(Dw::exact(rho)).mul(shape).div(den);
    // Divided by t last (exact where t = 1): s / t can be too large for Dekker's split.
    let single = Dw {
        hi: single.hi / t,
        lo: single.lo / t,
    };
    // f_ms = rho_ms/pi sigma A (c1 - g_o)(c1 - g_i)/(c1 - c2) with A cancelled from rho_ms =
    // rho^2 (1 + c2 sigma) / (1 + c1 sigma - rho sigma (c1 - c2)) and c1 - g = L/pi,
    // L = pi c1 - G: rho^2 sigma (1 + c2 sigma) L_o L_i / ((1 + c1 sigma) (1 + c1 sigma -
    // rho sigma (c1 - c2)) pi^3 (c1 - c2)), one quotient of sums that do not cancel. Carried
    // in double words: this lobe is up to about a third of f (both directions grazing on
    // opposite sides, where 1 + sigma s/t cancels, or both near the normal), and its ten
    // roundings in working precision cost up to 3 ULP of f in the oracle's search.
    let rho_sigma = Dw::product(rho, sigma);
    let ms_den = den.mul(
        den.add(
            rho_sigma
                .mul(Dw::constant(C1_MINUS_C2, C1_MINUS_C2_TAIL))
                .neg(),
        ),
    );
    let ms_num = rho_sigma
        .mul(Dw::exact(rho))
        .mul(
            Dw::constant(C2, C2_TAIL)
                .mul(Dw::exact(sigma))
                .add_t(T::ONE),
        )
        .mul(Dw::constant(MS_SCALE, MS_SCALE_TAIL))
        .mul(pi_loss(mu_o))
        .mul(pi_loss(mu_i));
    let value = single.add(ms_num.div(ms_den)).value();
    // The domain check wraps the horizon guard: a bad parameter (or a NaN v.l) is NaN below
    // the horizon too.
    nan_unless(
        in_unit(rho) & in_unit(sigma) & !v_dot_l.is_nan(),
        above_horizon(n_dot_v, n_dot_l, value),
    )
}

/// The EON BRDF f = f_FON + f_ms with the exact FON albedo (formulas in the docs of
/// [`brdf::diffuse`](crate::diffuse) under EON); the reference form, energy-preserving to rounding: at rho = 1 its directional
/// albedo is 1 for every sigma and view angle (within 5.1e-10 by numerical integration, up to
/// theta_o = 89 degrees: `cargo test --test diffuse eon_energy:: -- --nocapture`).
///
/// Arguments: the cosines n.v, n.l and v.l of unit vectors, the single-scattering albedo rho
/// and the roughness sigma (OpenPBR's `diffuse_roughness`).
///
/// Domain: rho in [0, 1] and sigma in [0, 1] (NaN outside, and for NaN). sigma above 1 is not
/// a rougher surface: 1 + sigma s/t turns negative for s < -1/sigma (directions grazing on
/// opposite sides), and the paper's fits are made on [0, 1]. Cosines beyond [-1, 1] are
/// clamped into it. Edges: sigma = 0 is Lambert rho/pi exactly; 0 where n.v <= 0 or n.l <= 0;
/// when both directions graze on the same side f grows like sigma/(pi max(n.v, n.l)) (the
/// backscattering peak), finite for every finite input.
///
/// Accuracy against the paper's definition evaluated in MPFR: within 1.4 ULP (f32), 1.3 (f64),
/// 1.5 (f32x8) and 1.4 (f64x4) of the correctly rounded value, max 1.15, 1.14, 1.25 and 1.16
/// found by the oracle's deep search (10^5 fresh points per type plus a longer hill-climb,
/// `BRDF_ORACLE_DEEP=1 BRDF_ORACLE_RECORD=1 cargo test -p brdf-oracle --release --test
/// accuracy_table -- --nocapture`; `docs/accuracy.md`).
/// The single-scattering shape 1 + sigma s/t, which cancels for opposite grazing directions,
/// and the compensation lobe, up to about a third of f, are carried in double words; E's
/// deficit 1 - E(mu), which cancels towards grazing as printed, is computed in a form without
/// cancellation. Lanes differ from scalars in the last bits where the lane `asin` (a
/// polynomial, not libm's) enters it.
///
/// Source: Portsmouth, Kutz, Hill 2025, "EON: A Practical Energy-Preserving Rough Diffuse
/// BRDF", JCGT 14(1), the `f_EON` listing with `exact = true`; Fujii 2012, "A tiny improvement
/// of Oren-Nayar reflectance model".
#[inline]
#[must_use]
pub fn eon<T: Real>(n_dot_v: T, n_dot_l: T, v_dot_l: T, rho: T, sigma: T) -> T {
    eon_with(n_dot_v, n_dot_l, v_dot_l, rho, sigma, pi_loss_exact)
}

/// [`eon`] with the FON albedo E(mu) from the paper's quartic fit ([`eon_fon_albedo_approx`])
/// instead of the exact form: no `acos`, as in shader code. Its white-furnace albedo at rho = 1
/// deviates from 1 by at most 5.3e-4 over sigma in [0, 1] and theta_o up to 89 degrees
/// (`cargo test --test diffuse eon_energy:: -- --nocapture`).
///
/// Domain and edges as [`eon`]. Source: Portsmouth, Kutz, Hill 2025, the `f_EON` listing
/// with `exact = false`.
#[inline]
#[must_use]
pub fn eon_approx<T: Real>(n_dot_v: T, n_dot_l: T, v_dot_l: T, rho: T, sigma: T) -> T {
    eon_with(n_dot_v, n_dot_l, v_dot_l, rho, sigma, pi_loss_fit)
}

/// FON directional albedo at rho = 1, exactly: E(mu) = A (1 + sigma G(mu)/pi), with
/// A = 1/(1 + c1 sigma) and G(mu) = S (acos(mu) - S mu) + (2/3)((S/mu)(1 - S^3) - S),
/// S = sqrt(1 - mu^2), mu = n.v.
///
/// Domain: sigma in [0, 1] (NaN outside, and for NaN); mu above 1 is clamped to 1. Edges:
/// E = 1 at sigma = 0 and at grazing (mu -> 0+) for every sigma; E(1) = A, the minimum
/// (0.777 at sigma = 1); 0 for mu <= 0.
///
/// Source: Portsmouth, Kutz, Hill 2025, the `E_FON_exact` listing.
#[inline]
#[must_use]
pub fn eon_fon_albedo<T: Real>(n_dot_v: T, sigma: T) -> T {
    fon_albedo_with(n_dot_v, sigma, loss_exact)
}

/// FON directional albedo at rho = 1 from the paper's fit of G(mu)/pi:
/// E(mu) = A (1 + sigma g(mu)), g(mu) = 0.0571085289 m + 0.491881867 m^2 - 0.332181442 m^3 +
/// 0.0714429953 m^4 with m = 1 - mu, capped at 1 (the fit exceeds 1 by up to 3.6e-4 near
/// grazing, where the exact value is 1).
///
/// Accuracy against [`eon_fon_albedo`]: max |error| 4.7e-4 (at sigma = 1, mu = 0.95), measured
/// by `cargo test --test diffuse eon_albedo:: -- --nocapture`.
///
/// Domain and edges as [`eon_fon_albedo`]. Source: Portsmouth, Kutz, Hill 2025, the `E_FON_approx`
/// listing.
#[inline]
#[must_use]
pub fn eon_fon_albedo_approx<T: Real>(n_dot_v: T, sigma: T) -> T {
    fon_albedo_with(n_dot_v, sigma, loss_fit)
}

#[inline]
fn fon_albedo_with<T: Real>(n_dot_v: T, sigma: T, loss: impl Fn(T) -> T) -> T {
    let sigma = checked_unit(sigma);
    let mu = n_dot_v.clamp(T::ZERO, T::ONE);
    // 1 - E = sigma A (c1 - g): the form shared with the BRDF, so the cap at 1 is the same.
    let e = T::ONE - sigma * fon_a(sigma) * loss(mu);
    nan_unless(in_unit(sigma), above_horizon(n_dot_v, T::ONE, e))
}

/// Cosine-weighted average of the FON albedo, E_avg = 2 integral_0^1 E(mu) mu dmu =
/// (1 + c2 sigma)/(1 + c1 sigma), c1 = 1/2 - 2/(3 pi), c2 = 2/3 - 28/(15 pi).
///
/// Domain: sigma in [0, 1] (NaN outside). Edges: 1 at sigma = 0, 0.833 at sigma = 1.
///
/// Source: Portsmouth, Kutz, Hill 2025 (`avgEF` in the `f_EON` listing).
#[inline]
#[must_use]
pub fn eon_fon_average_albedo<T: Real>(sigma: T) -> T {
    let sigma = checked_unit(sigma);
    T::splat(C2).mul_add(sigma, T::ONE) * fon_a(sigma)
}

/// EON's multiple-scattering albedo rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg)), the colour
/// the compensation lobe takes: the sum of the albedo series of light that bounces more than
/// once, each bounce scaled by rho (E_avg from [`eon_fon_average_albedo`]).
///
/// Domain: rho in [0, 1] and sigma in [0, 1] (NaN outside). Range: [0, rho] (the rounded
/// quotient is capped at rho, which it never exceeds in exact arithmetic). Edges: rho_ms =
/// rho^2 at sigma = 0; rho_ms = 1 exactly at rho = 1 for every sigma (so the white furnace
/// returns 1); 0 at rho = 0.
///
/// Source: Portsmouth, Kutz, Hill 2025 (`rho_ms` in the `f_EON` listing).
#[inline]
#[must_use]
pub fn eon_multiscatter_albedo<T: Real>(rho: T, sigma: T) -> T {
    let (rho, sigma) = (checked_unit(rho), checked_unit(sigma));
    rho_ms_with(rho, sigma, fon_a(sigma))
}

/// Directional albedo of [`eon`], in closed form: rho E(mu) + rho_ms (1 - E(mu)) with the exact
/// E ([`eon_fon_albedo`]) and rho_ms ([`eon_multiscatter_albedo`]); mu = n.v. Equal to 1 at
/// rho = 1 for every sigma.
///
/// Accuracy against numerical integration of [`eon`]: max |difference| 5.5e-10 (the
/// integrator's accuracy) over rho and sigma in [0, 1], theta_o up to 89 degrees
/// (`cargo test --test diffuse eon_albedo:: -- --nocapture`).
///
/// Domain: rho and sigma in [0, 1] (NaN outside). Edges: rho at sigma = 0 (Lambert); 0 for
/// mu <= 0.
///
/// Source: Portsmouth, Kutz, Hill 2025, the `E_EON` listing.
#[inline]
#[must_use]
pub fn eon_albedo<T: Real>(n_dot_v: T, rho: T, sigma: T) -> T {
    eon_albedo_with(n_dot_v, rho, sigma, loss_exact)
}

/// Directional albedo of the fitted model, rho E(mu) + rho_ms (1 - E(mu)) with E from
/// [`eon_fon_albedo_approx`]: what a shader using the fit assumes.
///
/// Accuracy against numerical integration of [`eon_approx`]: max |difference| 2.2e-4 over rho
/// and sigma in [0, 1], theta_o up to 89 degrees (the fit's error enters both the
/// formula and the lobe; `cargo test --test diffuse eon_albedo:: -- --nocapture`).
///
/// Domain and edges as [`eon_albedo`]. Source: Portsmouth, Kutz, Hill 2025, the `E_EON` listing
/// with `exact = false`.
#[inline]
#[must_use]
pub fn eon_albedo_approx<T: Real>(n_dot_v: T, rho: T, sigma: T) -> T {
    eon_albedo_with(n_dot_v, rho, sigma, loss_fit)
}

#[inline]
fn eon_albedo_with<T: Real>(n_dot_v: T, rho: T, sigma: T, loss: impl Fn(T) -> T) -> T {
    let (rho, sigma) = (checked_unit(rho), checked_unit(sigma));
    let mu = n_dot_v.clamp(T::ZERO, T::ONE);
    let a = fon_a(sigma);
    let one_minus_e = sigma * a * loss(mu);
    let rho_ms = rho_ms_with(rho, sigma, a);
    // rho E + rho_ms (1 - E) = rho + (rho_ms - rho)(1 - E).
    let value = (rho_ms - rho).mul_add(one_minus_e, rho);
    nan_unless(
        in_unit(rho) & in_unit(sigma),
        above_horizon(n_dot_v, T::ONE, value),
    )
}

// ---------------------------------------------------------------------------------------------
// Importance sampling
// ---------------------------------------------------------------------------------------------

/// Clamps a uniform sample into [0, 1 - epsilon/2], so u = 1 maps inside the domain of every
/// mapping below. NaN propagates.
#[inline]
fn clamp_u<T: Real>(u: T) -> T {
    u.clamp(T::ZERO, T::ONE - T::EPSILON * T::HALF)
}

/// The clipped linearly transformed cosine of the paper for one (wo, sigma): the matrix
/// M = [[a, 0, b], [0, c, 0], [d, 0, 1]] in the frame whose x axis is wo's azimuth, the
/// fraction `clip` of the cosine lobe that M keeps above the horizon, and det M.
struct Cltc<T> {
    a: T,
    b: T,
    c: T,
    d: T,
    clip: T,
    /// v = 1/sqrt(1 + d^2), 1 - v, and 1 + d^2 (see `sample_disk`).
    v: T,
    one_minus_v: T,
    k2: T,
    det: T,
    /// Unit azimuth of wo: the frame's x axis is (fx, fy, 0), its y axis (-fy, fx, 0).
    fx: T,
    fy: T,
}

impl<T: Real> Cltc<T> {
    /// The paper's rational fits of a, b, c, d in (mu = wo.z, sigma) (Portsmouth et al. 2025,
    /// the `ltc_terms` listing), made on mu, sigma in [0, 1]; mu is clamped into [0, 1].
    #[inline]
    fn new(wo: V3<T>, sigma: T) -> Self {
        let mu = wo.z.clamp(T::ZERO, T::ONE);
        let r = sigma;
        let k = T::splat;
        let a = T::ONE
            + r * (k(0.111709)
                .mul_add(mu, k(-0.518982))
                .mul_add(mu, k(0.303392))
                + k(0.335918).mul_add(mu, k(-0.276266)) * r);
        let b = r
            * (k(1.15859).mul_add(mu, k(-1.16407)) + k(-0.150105).mul_add(mu, k(0.150815)) * r)
            / (mu * mu).mul_add(mu, k(-1.43545));
        let c = T::ONE
            + k(0.261777)
                .mul_add(mu, k(-0.506373))
                .mul_add(mu, k(0.20013))
                * r;
        // The fit of d is meant to be <= 0 (the clip below assumes it), but rounds up to
        // +0.0035 sigma within 1e-4 of mu = 1: its numerator's root lies at mu = 0.999908.
        // Unclamped, the sampler would then emit directions up to 0.2 degrees below the horizon.
        let d = (k(0.475392)
            .mul_add(mu, k(-1.01625))
            .mul_add(mu, k(0.540852))
            * r
            / (mu + k(0.0725628)).mul_add(mu, k(-1.0743)))
        .min(T::ZERO);
        // M keeps the part of the cosine lobe above the plane d x + z = 0, whose cosine-weighted
        // fraction is s = (1 + v)/2 with v = cos(tilt) = 1/sqrt(1 + d^2). 1 - v is written
        // d^2/(k (k + 1)), k = sqrt(1 + d^2), to keep its digits when d is small.
        let k2 = d.mul_add(d, T::ONE);
        let k = k2.sqrt();
        let v = k.recip();
        let one_minus_v = d * d / (k * (k + T::ONE));
        let clip = T::HALF * (T::ONE + v);
        let det = c * (-b).mul_add(d, a);
        // wo's azimuth; at the pole (or a subnormal sin(theta_o)) any axis will do: take +x.
        // A NaN in wo.x or wo.y must stay NaN rather than take the fallback.
        let len2 = wo.x.mul_add(wo.x, wo.y * wo.y);
        let ok = len2.simd_gt(T::MIN_POSITIVE) | len2.is_nan();
        let inv = len2.sqrt().recip();
        let fx = T::select(ok, wo.x * inv, T::ONE);
        let fy = T::select(ok, wo.y * inv, T::ZERO);
        Self {
            a,
            b,
            c,
            d,
            clip,
            v,
            one_minus_v,
            k2,
            det,
            fx,
            fy,
        }
    }

    /// Draws a direction from (u1, phi) (a point of the unit disk, uniform in area, at radius
    /// sqrt(u1) and angle phi), returning it in the local frame with its pdf.
    ///
    /// The paper squeezes the disk onto the region x <= v sqrt(1 - y^2) (v = 1/sqrt(1 + d^2))
    /// whose lift to the hemisphere is the clipped lobe: x' = -((1 - s) h + s x) with
    /// h = sqrt(1 - y^2) and s = (1 + v)/2 (the visible-normal trick of Heitz 2018, mirrored:
    /// the clip is on the +x side since d <= 0). Evaluated as printed, z = sqrt(1 - x'^2 - y^2)
    /// and (M wh).z = d x' + z both cancel to 0 at the disk's rim, where sqrt(u1) rounds to 1
    /// for u1 = 1 - epsilon/2, emitting a horizon direction with pdf 0. Below, everything is
    /// written in h + x and h - x, whose product is exactly 1 - u1 > 0:
    /// x' = v h - s (h + x), z^2 = ((1 - v) h + s (h + x)) s (h - x), and where x' > 0,
    /// d x' + z = (z^2 - d^2 x'^2)/(z - d x') with z^2 - d^2 x'^2 = s (h + x) (1 + d^2)
    /// (2 v h - s (h + x)).
    #[inline]
    fn sample_disk(&self, u1: T, cos_phi: T, sin_phi: T) -> (V3<T>, T) {
        let q = T::ONE - u1;
        let r = u1.sqrt();
        let (x, y) = (r * cos_phi, r * sin_phi);
        // h^2 = 1 - u1 sin^2(phi), written so that h^2 - x^2 = 1 - u1 holds to rounding.
        let h = u1.mul_add(cos_phi * cos_phi, q).sqrt();
        // h + x and h - x: the one without cancellation directly, the other as q over it.
        let pos = x.simd_gt(T::ZERO);
        let direct = h + x.abs();
        let other = q / direct;
        let hp = T::select(pos, direct, other);
        let hm = T::select(pos, other, direct);
        let (v, one_minus_v, k2) = (self.v, self.one_minus_v, self.k2);
        let s = self.clip;
        let xs = v.mul_add(h, -s * hp);
        let z = (one_minus_v.mul_add(h, s * hp) * s * hm).sqrt_nonneg();
        let n = s * hp * k2 * (T::TWO * v).mul_add(h, -s * hp);
        let wz = T::select(
            xs.simd_gt(T::ZERO),
            n / (-self.d).mul_add(xs, z),
            self.d.mul_add(xs, z),
        );
        let w = V3::new(self.a.mul_add(xs, self.b * z), self.c * y, wz);
        let len = w.length();
        // pdf_wh = z/(pi s); the Jacobian of wi = M wh/|M wh| is |M wh|^3 / det M.
        let pdf = z * len * len * len / (T::PI * s * self.det);
        let u = w * len.recip();
        let wi = V3::new(
            self.fx.mul_add(u.x, -self.fy * u.y),
            self.fy.mul_add(u.x, self.fx * u.y),
            u.z,
        );
        (wi, pdf)
    }

    /// pdf of `sample_disk` at a local unit direction wi (any hemisphere; the caller masks).
    #[inline]
    fn pdf(&self, wi: V3<T>) -> T {
        let wx = self.fx.mul_add(wi.x, self.fy * wi.y);
        let wy = self.fx.mul_add(wi.y, -self.fy * wi.x);
        let wz = wi.z;
        // adj(M) wi = det(M) M^-1 wi, so pdf = det^2 / |adj(M) wi|^4 * max(0, (adj(M) wi).z) /
        // (pi clip).
        let hx = self.c * (-self.b).mul_add(wz, wx);
        let hy = (-self.b).mul_add(self.d, self.a) * wy;
        let hz = self.c * self.a.mul_add(wz, -self.d * wx);
        let len2 = hx.mul_add(hx, hy.mul_add(hy, hz * hz));
        let q = self.det / len2;
        q * q * hz.max(T::ZERO) / (T::PI * self.clip)
    }
}

/// The CLTC sampler alone: a direction wi drawn from the clipped linearly transformed cosine
/// fitted to EON's lobe for view wo (local frame, normal +z) and roughness sigma, and its pdf
/// with respect to solid angle.
///
/// Method: a cosine-distributed direction wh, restricted to the half-space that the matrix
/// M = [[a, 0, b], [0, c, 0], [d, 0, 1]] maps above the horizon (drawn by squeezing the
/// projected disk onto that region), mapped to wi = M wh / |M wh| and rotated to wo's azimuth;
/// pdf = (wh.z / (pi s)) |M wh|^3 / det M with s = (1 + 1/sqrt(1 + d^2))/2 the kept fraction.
/// a, b, c, d are the paper's rational fits in (wo.z, sigma).
///
/// Domain: wo a unit vector, sigma in [0, 1] (NaN outside), u1, u2 in [0, 1] (u = 1 is clamped
/// below 1). Edges: wi.z > 0 with a positive pdf for every u1, u2 in [0, 1] (the disk's rim,
/// where the paper's listing rounds to a horizon direction, is evaluated without
/// cancellation); the pdf is 0 where wo.z <= 0 (discard the sample); at sigma = 0, M = I and
/// this is cosine sampling. NaN in any input gives NaN.
///
/// Source: Portsmouth, Kutz, Hill 2025, the `cltc_sample` and `ltc_terms` listings;
/// linearly transformed cosines: Heitz, Dupuy, Hill, Neubelt 2016, "Real-Time Polygonal-Light
/// Shading with Linearly Transformed Cosines".
#[inline]
#[must_use]
pub fn eon_cltc_sample<T: Real>(wo: V3<T>, sigma: T, u1: T, u2: T) -> (V3<T>, T) {
    let ltc = Cltc::new(wo, checked_unit(sigma));
    let phi = T::TWO * T::PI * clamp_u(u2);
    let (wi, pdf) = ltc.sample_disk(clamp_u(u1), phi.cos(), phi.sin());
    // The pdf does not depend on wo's azimuth, but a NaN there (which makes wi.x NaN) must
    // still reach it.
    let pdf = nan_unless(in_unit(sigma), above_horizon(wo.z, wi.z, pdf));
    nan_sample(any_nonfinite3(wo), (wi, pdf))
}

/// (NaN, NaN) where `bad`: a NaN in a component of wo that the sampler's formula does not
/// reach (wi.z does not depend on wo's azimuth) must still give a NaN direction and pdf.
#[inline]
fn nan_sample<T: Real>(bad: T::Mask, (wi, pdf): (V3<T>, T)) -> (V3<T>, T) {
    let n = |x: T| nan_where(bad, x);
    (V3::new(n(wi.x), n(wi.y), n(wi.z)), n(pdf))
}

/// pdf of [`eon_cltc_sample`] at wi (solid angle): det(M)^2 / |adj(M) w|^4 * max(0,
/// (adj(M) w).z) / (pi s), with w = wi in wo's azimuthal frame and adj(M) = det(M) M^-1.
///
/// Domain: wo, wi unit vectors, sigma in [0, 1] (NaN outside). 0 where wi.z <= 0 or
/// wo.z <= 0 (a zero-length wo or wi included); NaN in any input, or an infinite component of
/// wo or wi, gives NaN. Integrates to 1 over the upper hemisphere.
///
/// Source: Portsmouth, Kutz, Hill 2025, the `cltc_pdf` listing.
#[inline]
#[must_use]
pub fn eon_cltc_pdf<T: Real>(wo: V3<T>, wi: V3<T>, sigma: T) -> T {
    let ltc = Cltc::new(wo, checked_unit(sigma));
    let pdf = nan_unless(in_unit(sigma), above_horizon(wo.z, wi.z, ltc.pdf(wi)));
    // Below the horizon the guard gives 0 whatever wo.x, wo.y, wi.x, wi.y are: keep their NaN.
    nan_where(any_nonfinite3(wo) | any_nonfinite3(wi), pdf)
}

/// Probability of the uniform lobe in EON's sampling mixture, the paper's fit
/// P_u = sigma^0.1 (0.162925 - 0.372058 mu + 0.538233 mu^2 - 0.290822 mu^3), mu = wo.z
/// clamped into [0, 1]; it lies in (0, 0.163] for sigma > 0 (0.038 at sigma = 1) and is 0 at sigma = 0.
#[inline]
fn uniform_weight<T: Real>(wo_z: T, sigma: T) -> T {
    let mu = wo_z.clamp(T::ZERO, T::ONE);
    let k = T::splat;
    let poly = k(-0.290822)
        .mul_add(mu, k(0.538233))
        .mul_add(mu, k(-0.372058))
        .mul_add(mu, k(0.162925));
    sigma.pow(k(0.1)) * poly
}

/// Importance sampling of EON: a direction wi for view wo (local frame, normal +z) and
/// roughness sigma, with its pdf with respect to solid angle.
///
/// The paper's mixture: with probability P_u = sigma^0.1 (0.162925 - 0.372058 mu +
/// 0.538233 mu^2 - 0.290822 mu^3) (mu = wo.z) a uniform hemisphere direction, which covers the
/// broad multiple-scattering lobe; otherwise a CLTC direction ([`eon_cltc_sample`]), which
/// follows the single-scattering lobe. u1 picks the lobe and is rescaled to [0, 1) for it;
/// u2 is the azimuth of both. The pdf returned is the mixture's,
/// P_u / (2 pi) + (1 - P_u) pdf_CLTC(wi), equal to [`eon_pdf`] at wi. Branch-free: both lobes
/// are drawn and one selected, so lanes equal scalars.
///
/// Domain: wo a unit vector, sigma in [0, 1] (NaN outside), u1, u2 in [0, 1]. Edges: wi.z > 0
/// with a positive pdf for every u1, u2 (`tests/diffuse/eon_sampling.rs`); pdf 0 where
/// wo.z <= 0 (discard the sample); sigma = 0 is cosine sampling (P_u = 0). NaN in any input
/// gives NaN.
///
/// Source: Portsmouth, Kutz, Hill 2025, the `sample_EON` listing.
#[inline]
#[must_use]
pub fn eon_sample<T: Real>(wo: V3<T>, sigma: T, u1: T, u2: T) -> (V3<T>, T) {
    let sigma = checked_unit(sigma);
    let ltc = Cltc::new(wo, sigma);
    let p_u = uniform_weight(wo.z, sigma);
    let u1 = clamp_u(u1);
    let phi = T::TWO * T::PI * clamp_u(u2);
    let (sin_phi, cos_phi) = (phi.sin(), phi.cos());
    // Strict `<`: at sigma = 0, P_u = 0 and u1 = 0 must take the CLTC lobe (u1/P_u is 0/0).
    let uniform = u1.simd_lt(p_u);
    // Uniform lobe: z = 1 - u in (0, 1], so no sample lands on the horizon.
    let z = T::ONE - clamp_u(u1 / p_u);
    let sin_theta = ((T::ONE - z) * (T::ONE + z)).sqrt_nonneg();
    let wu = V3::new(sin_theta * cos_phi, sin_theta * sin_phi, z);
    let (wc, _) = ltc.sample_disk(clamp_u((u1 - p_u) / (T::ONE - p_u)), cos_phi, sin_phi);
    let wi = V3::select(uniform, wu, wc);
    nan_sample(any_nonfinite3(wo), (wi, mixture_pdf(&ltc, p_u, wo, wi)))
}

#[inline]
fn mixture_pdf<T: Real>(ltc: &Cltc<T>, p_u: T, wo: V3<T>, wi: V3<T>) -> T {
    let pdf_c = ltc.pdf(wi);
    let pdf = p_u.mul_add(T::splat(0.5) * T::FRAC_1_PI - pdf_c, pdf_c);
    // p_u is NaN for a bad sigma, and the horizon guard ignores wo.x, wo.y, wi.x, wi.y: keep
    // their NaN below the horizon too.
    let bad = p_u.is_nan() | any_nonfinite3(wo) | any_nonfinite3(wi);
    nan_where(bad, above_horizon(wo.z, wi.z, pdf))
}

/// pdf of [`eon_sample`] at wi (solid angle): P_u / (2 pi) + (1 - P_u) pdf_CLTC(wi), with P_u
/// and pdf_CLTC as there ([`eon_cltc_pdf`]).
///
/// Domain: wo, wi unit vectors, sigma in [0, 1] (NaN outside). 0 where wi.z <= 0 or
/// wo.z <= 0 (a zero-length wo or wi included); NaN in any input, or an infinite component of
/// wo or wi, gives NaN. Integrates to 1 over the upper hemisphere.
///
/// Source: Portsmouth, Kutz, Hill 2025, the `pdf_EON` listing.
#[inline]
#[must_use]
pub fn eon_pdf<T: Real>(wo: V3<T>, wi: V3<T>, sigma: T) -> T {
    let sigma = checked_unit(sigma);
    let ltc = Cltc::new(wo, sigma);
    mixture_pdf(&ltc, uniform_weight(wo.z, sigma), wo, wi)
}

/// An EON lobe: single-scattering albedo rho in [0, 1] and roughness sigma in [0, 1] (the
/// OpenPBR Surface `base_color` and `diffuse_roughness`). See [`eon`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eon<T> {
    rho: T,
    sigma: T,
}

impl<T: Real> Eon<T> {
    /// An EON lobe; rho and sigma must lie in [0, 1] in every lane, else [`ParamError`] (sigma
    /// above 1 makes the FON term negative; see [`eon`]).
    pub fn new(rho: T, sigma: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(rho), "rho", "in [0, 1]")?;
        require::<T>(in_unit(sigma), "sigma", "in [0, 1]")?;
        Ok(Self { rho, sigma })
    }

    /// The single-scattering albedo rho.
    #[inline]
    #[must_use]
    pub fn rho(&self) -> T {
        self.rho
    }

    /// The roughness sigma.
    #[inline]
    #[must_use]
    pub fn sigma(&self) -> T {
        self.sigma
    }

    /// f(wo, wi) with the exact FON albedo ([`eon`]); local-frame unit vectors, normal +z,
    /// both pointing away from the surface.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        super::nan_if_nan_dir(wo, wi, eon(wo.z, wi.z, wo.dot(wi), self.rho, self.sigma))
    }

    /// f(wo, wi) with the fitted FON albedo ([`eon_approx`]).
    #[inline]
    #[must_use]
    pub fn eval_approx(&self, wo: V3<T>, wi: V3<T>) -> T {
        let f = eon_approx(wo.z, wi.z, wo.dot(wi), self.rho, self.sigma);
        super::nan_if_nan_dir(wo, wi, f)
    }

    /// Directional albedo at wo ([`eon_albedo`]); NaN where a component of wo is NaN or infinite.
    #[inline]
    #[must_use]
    pub fn albedo(&self, wo: V3<T>) -> T {
        nan_where(any_nonfinite3(wo), eon_albedo(wo.z, self.rho, self.sigma))
    }

    /// Directional albedo of the fitted model at wo ([`eon_albedo_approx`]); NaN where a
    /// component of wo is NaN or infinite.
    #[inline]
    #[must_use]
    pub fn albedo_approx(&self, wo: V3<T>) -> T {
        nan_where(
            any_nonfinite3(wo),
            eon_albedo_approx(wo.z, self.rho, self.sigma),
        )
    }

    /// A direction wi and its solid-angle pdf ([`eon_sample`]).
    #[inline]
    #[must_use]
    pub fn sample(&self, wo: V3<T>, u1: T, u2: T) -> (V3<T>, T) {
        eon_sample(wo, self.sigma, u1, u2)
    }

    /// pdf of [`Eon::sample`] ([`eon_pdf`]).
    #[inline]
    #[must_use]
    pub fn pdf(&self, wo: V3<T>, wi: V3<T>) -> T {
        eon_pdf(wo, wi, self.sigma)
    }
}
