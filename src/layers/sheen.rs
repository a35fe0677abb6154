//! `KHR_materials_sheen`: the "Charlie" sheen lobe of Estevez and Kulla, its fitted Smith
//! Lambda, the cheaper Neubelt-Pettineo visibility, Ashikhmin's velvet NDF, the sheen's
//! directional albedo E and the albedo scaling the extension applies to the layer below.
//!
//! # The lobe
//! With alpha = sheenRoughness^2 (glTF's `sheenRoughnessFactor` is perceptual, as the base
//! roughness is), floored at [`ALPHA_MIN`], and sin^2 = (1 - n.h)(1 + n.h):
//!
//! ```text
//! D_charlie = (2 + 1/alpha) sin^(1/alpha) / (2 pi)                     d_charlie
//! Lambda    = exp(L(c))                 for c < 1/2                   lambda_charlie
//!           = exp(2 L(1/2) - L(1 - c))  for c >= 1/2
//! L(x)      = a / (1 + b x^c') + d x + e, (a, b, c', d, e) interpolated between the
//!             paper's fits at alpha = 0 and alpha = 1 with the weight (1 - alpha)^2
//! V_charlie = 1 / ((1 + Lambda(n.v) + Lambda(n.l)) 4 n.v n.l)           v_charlie
//! V_neubelt = 1 / (4 (n.l + n.v - n.l n.v))                             v_neubelt
//! f_sheen   = sheenColor D_charlie V_charlie                            charlie
//! ```
//!
//! The Lambda fit is the paper's (its Table 1, interpolated as its section 3 says); the
//! "terminator softening" the paper adds for light directions (Lambda^(1 + 2 (1 - c)^8)) is
//! not part of the glTF lobe and not applied here. The fit's Lambda stays finite at the
//! horizon (exp(a + e) = 2.9e7 at alpha = 1, 7.7e8 at alpha = 0) where the exact Smith
//! Lambda grows like 1 / n.v, so V_charlie grows like 1 / (4 Lambda(0) n.v n.l) towards
//! grazing views, and the lobe's albedo passes 1 there for smooth sheens ([`ALBEDO_TABLE`]).
//! The Khronos sample viewer clamps V to [0, 1], which changes it wherever
//! (1 + Lambda_v + Lambda_l) 4 n.v n.l < 1 (both cosines below about 0.2 at alpha = 1). The
//! crate does not clamp: the value is the formula's, capped at the largest finite float.
//!
//! # Albedo and albedo scaling
//! E(mu, alpha) = integral of f_sheen(wo, wi) cos(theta_i) dwi with sheenColor = 1 is the
//! light the sheen reflects; the extension scales the layer below by
//!
//! ```text
//! sheen_albedo_scaling = min(1 - max_rgb(sheenColor) E(n.v), 1 - max_rgb(sheenColor) E(n.l))
//! ```
//!
//! ([`albedo_scaling`]), or by the view-only form 1 - max_rgb(sheenColor) E(n.v) which it
//! offers "to trade a bit of accuracy for more performance": that one is computed once per
//! shading point and applies to every light and to the environment alike (pass e_l = e_v).
//! The min form is symmetric in the two directions, so it keeps the layered BRDF reciprocal;
//! the view-only form does not.
//!
//! E is tabulated by the crate's own integrators ([`albedo_estimate`], adaptive cubature of
//! [`crate::integrate`]) into a caller's buffer ([`albedo_table`]) or read from the built-in
//! [`ALBEDO_TABLE`] ([`albedo`], 16 x 16, the V_charlie lobe the extension specifies). Two
//! published analytic fits are offered for the Neubelt-visibility lobe engines ship
//! ([`albedo_fit_materialx`], [`albedo_fit_threejs`]); their measured error is in their docs.
//!
//! Sources: Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF" (SIGGRAPH
//! course "Physically Based Shading in Theory and Practice"); Neubelt and Pettineo 2013,
//! "Crafting a Next-Gen Material Pipeline for The Order: 1886"; Ashikhmin and Premoze 2007,
//! "Distribution-based BRDFs"; Conty and Kulla 2017, "Revisiting Physically Based Shading at
//! Imageworks" (albedo scaling); The Khronos Group, "KHR_materials_sheen" (ratified),
//! sections "Sheen BRDF" and "Albedo-scaling technique".

use crate::domain::{above, above_horizon, in_unit, nan_unless, nan_where};
use crate::error::ParamError;
use crate::real::Real;
use crate::shading::Cosines;
use crate::vec3::V3;

/// Smallest sheen alpha the kernels use. Why 1e-4 (sheenRoughness 0.01): D_charlie's peak
/// (2 + 1/alpha) / (2 pi) stays near 1.6e3 and its exponent 1/(2 alpha) at 5e3, where
/// sin^(1/alpha) is still representable in f32 for every sin^2 above 0.98; the Lambda fit's
/// weight (1 - alpha)^2 differs from its alpha = 0 value by 2e-4.
pub const ALPHA_MIN: f64 = 1e-4;

/// alpha in [0, 1] (false for NaN).
#[inline]
fn alpha_ok<T: Real>(alpha: T) -> T::Mask {
    in_unit(alpha)
}

/// alpha floored at [`ALPHA_MIN`] (a NaN alpha may come out finite: every caller checks alpha
/// with `alpha_ok` and puts the NaN back).
#[inline]
fn floor_alpha<T: Real>(alpha: T) -> T {
    alpha.max(T::splat(ALPHA_MIN))
}

/// sin^2 = (1 - c)(1 + c) for a cosine c clamped to [0, 1]: no cancellation near c = 1.
#[inline]
fn sin2<T: Real>(c: T) -> T {
    let c = c.saturate();
    (T::ONE - c) * (T::ONE + c)
}

/// The Charlie sheen NDF D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi), evaluated as
/// (2 + 1/alpha) (sin^2)^(1/(2 alpha)) / (2 pi) with sin^2 = (1 - c)(1 + c). Normalized:
/// integral of D cos(theta_h) over the hemisphere is 1 for every alpha.
///
/// Domain: n_dot_h a cosine in [-1, 1] (above 1 counts as 1, n.h <= 0 gives 0, the crate's
/// microfacet convention); alpha in [0, 1], alpha = sheenRoughness^2, floored at
/// [`ALPHA_MIN`]; NaN for NaN input or alpha outside [0, 1]. D = 0 at n.h = 1 (the lobe is a
/// ring of grazing fibres) and reaches (2 + 1/alpha) / (2 pi) towards n.h = 0.
///
/// Source: Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF", eq. 2; the
/// Khronos glTF sample viewer's `D_Charlie` (`source/Renderer/shaders/brdf.glsl`).
#[inline]
#[must_use]
pub fn d_charlie<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a = floor_alpha(alpha);
    let inv = a.recip();
    let d =
        (T::TWO + inv) * sin2(n_dot_h).pow(T::HALF * inv) * T::splat(0.5 / core::f64::consts::PI);
    nan_unless(alpha_ok(alpha), above(n_dot_h, d))
}

/// The paper's fitted exponent L(x) = a / (1 + b x^c) + d x + e, with each coefficient
/// interpolated between its alpha = 0 and alpha = 1 values by t = (1 - alpha)^2
/// (`mix(at_one, at_zero, t)`).
#[inline]
fn lambda_exponent<T: Real>(x: T, alpha: T) -> T {
    let one_minus = T::ONE - alpha;
    let t = one_minus * one_minus;
    let mix = |at_one: f64, at_zero: f64| T::splat(at_one) + (T::splat(at_zero - at_one)) * t;
    let a = mix(21.5473, 25.3245);
    let b = mix(3.82987, 3.32435);
    let c = mix(0.19823, 0.16801);
    let d = mix(-1.97760, -1.27393);
    let e = mix(-4.32054, -4.85967);
    a / b.mul_add(x.pow(c), T::ONE) + d.mul_add(x, e)
}

/// The Charlie sheen's fitted Smith Lambda: Lambda(c) = exp(L(c)) for c < 1/2 and
/// exp(2 L(1/2) - L(1 - c)) for c >= 1/2, with the paper's five-parameter L interpolated in
/// alpha (module docs). Continuous at c = 1/2; about 2e-8 at c = 1 and exp(a + e) (2.9e7 to
/// 7.7e8) at c = 0.
///
/// Domain: n_dot_v a cosine in [-1, 1], used as |c| clamped to [0, 1] (as `crate::ggx`'s
/// Lambda); alpha in [0, 1], floored at [`ALPHA_MIN`]; NaN for NaN input or alpha outside
/// [0, 1].
///
/// Source: Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF", section 3 and
/// Table 1; the Khronos glTF sample viewer's `lambdaSheen`.
#[inline]
#[must_use]
pub fn lambda_charlie<T: Real>(n_dot_v: T, alpha: T) -> T {
    let a = floor_alpha(alpha);
    let c = n_dot_v.abs().min(T::ONE);
    let low = c.simd_lt(T::HALF);
    let x = T::select(low, c, T::ONE - c);
    let l = lambda_exponent(x, a);
    let mid = lambda_exponent(T::HALF, a);
    let lambda = T::select(low, l, T::TWO * mid - l).exp();
    nan_unless(alpha_ok(alpha), nan_where(n_dot_v.is_nan(), lambda))
}

/// The Charlie sheen's visibility V = G2 / (4 n.v n.l) = 1 / ((1 + Lambda(n.v) + Lambda(n.l))
/// 4 n.v n.l) with [`lambda_charlie`] (height-correlated Smith form).
///
/// Domain: cosines in [-1, 1] (above 1 counts as 1); 0 where n.v <= 0 or n.l <= 0; alpha in
/// [0, 1], floored at [`ALPHA_MIN`]; NaN for NaN input or alpha outside [0, 1]. Capped at the
/// largest finite float where both cosines are tiny. Not clamped to 1 as the Khronos sample
/// viewer's `V_Sheen` is (module docs).
///
/// Source: Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF", section 3;
/// KHR_materials_sheen, "Sheen visibility".
#[inline]
#[must_use]
pub fn v_charlie<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let cv = n_dot_v.min(T::ONE);
    let cl = n_dot_l.min(T::ONE);
    let g = T::ONE + lambda_charlie(cv, alpha) + lambda_charlie(cl, alpha);
    let v = (T::splat(4.0) * cv * cl * g).recip().min(T::MAX);
    nan_unless(alpha_ok(alpha), above_horizon(n_dot_v, n_dot_l, v))
}

/// Neubelt and Pettineo's cloth visibility V = 1 / (4 (n.l + n.v - n.l n.v)), evaluated as
/// 1 / (4 (n.v + n.l (1 - n.v))), a sum of non-negative terms. Cheap, and not derived from
/// the Charlie NDF: Filament and three.js pair it with D_charlie.
///
/// Domain: cosines in [-1, 1] (above 1 counts as 1); 0 where n.v <= 0 or n.l <= 0; NaN for
/// NaN input. At most 1/4 divided by the larger cosine; capped at the largest finite float.
///
/// Source: Neubelt and Pettineo 2013, "Crafting a Next-Gen Material Pipeline for The Order:
/// 1886" (SIGGRAPH course notes); Filament's `V_Neubelt` (`shaders/src/surface_brdf.fs`).
#[inline]
#[must_use]
pub fn v_neubelt<T: Real>(n_dot_v: T, n_dot_l: T) -> T {
    let cv = n_dot_v.min(T::ONE);
    let cl = n_dot_l.min(T::ONE);
    let v = (T::splat(4.0) * cl.mul_add(T::ONE - cv, cv))
        .recip()
        .min(T::MAX);
    above_horizon(n_dot_v, n_dot_l, v)
}

/// Ashikhmin's velvet NDF D = (1 + 4 exp(-cot^2(theta_h) / alpha^2) / sin^4(theta_h)) /
/// (pi (1 + 4 alpha^2)), the older cloth reference (an inverted Gaussian plus a constant
/// floor). The exponential term is dropped where cot^2 / alpha^2 > 200 (it is then below
/// 1e-80 of the constant); without that guard exp underflows to 0 while sin^4 does too, and
/// 0 / 0 is NaN at n.h near 1.
///
/// Domain: n_dot_h a cosine in [-1, 1] (above 1 counts as 1, n.h <= 0 gives 0); alpha in
/// [0, 1], floored at [`ALPHA_MIN`]; NaN for NaN input or alpha outside [0, 1]. Equals
/// 1 / (pi (1 + 4 alpha^2)) at n.h = 1.
///
/// Source: Ashikhmin and Premoze 2007, "Distribution-based BRDFs" (technical report);
/// Filament's `D_Ashikhmin` (`shaders/src/surface_brdf.fs`).
#[inline]
#[must_use]
pub fn d_ashikhmin<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a = floor_alpha(alpha);
    let a2 = a * a;
    let c = n_dot_h.saturate();
    let s2 = sin2(n_dot_h);
    // cot^2 / alpha^2 = c^2 / (alpha^2 sin^2), +inf at sin = 0 (then the term is dropped).
    let t = (c * c) / (a2 * s2);
    let keep = t.simd_le(T::splat(200.0));
    let safe_s2 = T::select(keep, s2, T::ONE);
    let term = T::select(
        keep,
        T::splat(4.0) * (-t).exp() / (safe_s2 * safe_s2),
        T::ZERO,
    );
    let d = (T::ONE + term) * T::FRAC_1_PI / T::splat(4.0).mul_add(a2, T::ONE);
    nan_unless(alpha_ok(alpha), above(n_dot_h, d))
}

/// The glTF sheen lobe f_sheen = sheenColor D_charlie V_charlie per RGB channel
/// ([`d_charlie`], [`v_charlie`]), not multiplied by the cosine: the extension's `sheen_brdf`
/// times `sheenColor`.
///
/// Arguments: the shading point's [`Cosines`] (v.h is not used); `sheen_color` with each
/// channel in [0, 1] (glTF's `sheenColorFactor`); `alpha` = sheenRoughness^2 in [0, 1].
/// Edges: 0 where n.v <= 0 or n.l <= 0; NaN for NaN input or a parameter outside its domain;
/// capped at the largest finite float.
///
/// Source: KHR_materials_sheen, "Sheen BRDF"; Estevez and Kulla 2017.
#[inline]
#[must_use]
pub fn charlie<T: Real>(c: Cosines<T>, sheen_color: V3<T>, alpha: T) -> V3<T> {
    let dv = (d_charlie(c.n_dot_h, alpha) * v_charlie(c.n_dot_v, c.n_dot_l, alpha)).min(T::MAX);
    let nan = c.v_dot_h.is_nan();
    let ch = |s: T| nan_unless(in_unit(s), nan_where(nan, s * dv));
    V3::new(ch(sheen_color.x), ch(sheen_color.y), ch(sheen_color.z))
}

/// The directional albedo of the sheen lobe with sheenColor = 1 for the view cosine `mu` and
/// the sheen alpha, by the crate's adaptive cubature ([`crate::integrate::directional_albedo`]):
/// integral of D_charlie V f cos(theta_i) dwi, with V = [`v_charlie`] or, when `neubelt`, V =
/// [`v_neubelt`]. f64 only; `mu` in (0, 1], alpha in [0, 1] (NaN outside).
///
/// Measured: E <= 0.65 for mu >= 0.15 with either visibility (`cargo test --test layers
/// sheen::charlie_albedo -- --nocapture`); at grazing views of smooth sheens both pass 1
/// (1.02 with V_charlie and 1.75 with V_neubelt at mu = 0.05, sheen roughness 0.05).
#[must_use]
pub fn albedo_estimate(mu: f64, alpha: f64, neubelt: bool) -> f64 {
    if !(mu > 0.0 && mu <= 1.0 && (0.0..=1.0).contains(&alpha)) {
        return f64::NAN;
    }
    let s = libm::sqrt((1.0 - mu) * (1.0 + mu));
    let wo = V3::new(s, 0.0, mu);
    crate::integrate::directional_albedo(wo, |o, i| {
        let c = Cosines::from_local(o, i);
        let v = if neubelt {
            v_neubelt(c.n_dot_v, c.n_dot_l)
        } else {
            v_charlie(c.n_dot_v, c.n_dot_l, alpha)
        };
        d_charlie(c.n_dot_h, alpha) * v
    })
    .value
}

/// Side of the built-in [`ALBEDO_TABLE`].
pub const ALBEDO_TABLE_SIZE: usize = 16;

/// Writes the sheen albedo E into `out` (row-major, `out[i * n + j]`, n = sqrt(out.len())) at
/// texel centres, as a GPU lookup texture samples it: mu_j = (j + 1/2) / n and perceptual
/// sheen roughness r_i = (i + 1/2) / n, alpha_i = r_i^2; each entry is
/// [`albedo_estimate`]`(mu_j, alpha_i, neubelt)` rounded to f32. `albedo_table(out, false)`
/// with 256 entries reproduces [`ALBEDO_TABLE`]. Deterministic.
///
/// Errors ([`ParamError`], `out` untouched): `out.len()` not a square of at least 4.
/// Cost: one adaptive cubature per entry (about 0.1 s for 16 x 16 on one core).
pub fn albedo_table(out: &mut [f32], neubelt: bool) -> Result<(), ParamError> {
    let n = (libm::sqrt(out.len() as f64) + 0.5) as usize;
    if n < 2 || n * n != out.len() {
        return Err(ParamError {
            param: "out",
            expected: "a square length n * n with n >= 2",
        });
    }
    for (i, row) in out.chunks_exact_mut(n).enumerate() {
        let r = (i as f64 + 0.5) / n as f64;
        for (j, e) in row.iter_mut().enumerate() {
            let mu = (j as f64 + 0.5) / n as f64;
            *e = albedo_estimate(mu, r * r, neubelt) as f32;
        }
    }
    Ok(())
}

/// Bilinear lookup of [`ALBEDO_TABLE`] at (mu, perceptual roughness sqrt(alpha)) in f64,
/// clamped to the texel centres (a texture's clamp-to-edge).
fn lookup(mu: f64, alpha: f64) -> f64 {
    const N: usize = ALBEDO_TABLE_SIZE;
    let coord = |x: f64| (x * N as f64 - 0.5).clamp(0.0, (N - 1) as f64);
    let x = coord(mu.clamp(0.0, 1.0));
    let y = coord(libm::sqrt(alpha.clamp(0.0, 1.0)));
    // NaN casts to 0: a valid index whose value the caller discards.
    let j = (x as usize).min(N - 2);
    let i = (y as usize).min(N - 2);
    let (fx, fy) = (x - j as f64, y - i as f64);
    let at = |i: usize, j: usize| f64::from(ALBEDO_TABLE[i * N + j]);
    let lo = at(i, j) + fx * (at(i, j + 1) - at(i, j));
    let hi = at(i + 1, j) + fx * (at(i + 1, j + 1) - at(i + 1, j));
    lo + fy * (hi - lo)
}

/// The sheen albedo E(mu, alpha) of the glTF lobe ([`charlie`] with sheenColor = 1) from the
/// built-in [`ALBEDO_TABLE`], bilinear in (mu, sqrt(alpha)) between texel centres and
/// constant beyond them. The lookup runs in f64 per lane and is rounded once, so lanes equal
/// scalars bit for bit. What [`albedo_scaling`] takes, once per shading point.
///
/// Domain: n_dot_v a cosine in [-1, 1], clamped to [0, 1]; alpha in [0, 1]; NaN for NaN input
/// or alpha outside [0, 1]. Output in [0, 1]: the table exceeds 1 at grazing views of the
/// smoothest sheens (the Lambda fit's flaw, [`ALBEDO_TABLE`]), clamped to 1 here. Error
/// against [`albedo_estimate`]: max abs 0.0096 over mu and sheen roughness in [0.1, 1]
/// (`cargo test --test layers sheen_albedo:: -- --nocapture`); up to 0.17 below sheen
/// roughness 0.1, whose rows fall by 10^3 within one texel.
#[inline]
#[must_use]
pub fn albedo<T: Real>(n_dot_v: T, alpha: T) -> T {
    let v = T::from_fn(|i| {
        let (m, a): (f64, f64) = (n_dot_v.lane(i).into(), alpha.lane(i).into());
        <T::Scalar as Real>::splat(lookup(m, a).min(1.0))
    });
    nan_unless(alpha_ok(alpha), nan_where(n_dot_v.is_nan(), v))
}

/// MaterialX's rational fit of the directional albedo of the Imageworks sheen lobe with the
/// Neubelt-Pettineo visibility (D_charlie V_neubelt, [`albedo_estimate`] with `neubelt`):
/// E = P(mu, alpha) / Q(mu, alpha), P and Q quadratics in mu and alpha with MaterialX's
/// coefficients, clamped to [0, 1] as MaterialX clamps it. MaterialX's `roughness` is the
/// Charlie width itself, this crate's alpha.
///
/// Domain: n_dot_v a cosine, clamped to [0, 1]; alpha in [0, 1]; NaN for NaN input or alpha
/// outside [0, 1]. Measured error against [`albedo_estimate`]`(mu, alpha, true)`: max abs
/// 0.05 over mu in [0.1, 1] and alpha in [0.05, 1] (`cargo test --test layers sheen_albedo::
/// -- --nocapture` prints it); below mu = 0.1 the smoothest lobes' albedo passes 1 and the fit
/// is clamped.
///
/// Source: MaterialX, `libraries/pbrlib/genglsl/lib/mx_microfacet_sheen.glsl`,
/// `mx_imageworks_sheen_dir_albedo_analytic` ("rational quadratic fit to Monte Carlo data").
#[inline]
#[must_use]
pub fn albedo_fit_materialx<T: Real>(n_dot_v: T, alpha: T) -> T {
    let mu = n_dot_v.saturate();
    let a = alpha;
    let poly = |c0: f64, cm: f64, ca: f64, cma: f64, cmm: f64, caa: f64| {
        T::splat(c0)
            + T::splat(cm) * mu
            + T::splat(ca) * a
            + T::splat(cma) * mu * a
            + T::splat(cmm) * mu * mu
            + T::splat(caa) * a * a
    };
    let p = poly(
        13.67300, -68.78018, 799.08825, -905.00061, 60.28956, 1086.96473,
    );
    let q = poly(1.0, 61.57746, 442.78211, 2597.49308, 121.81241, 3045.55075);
    nan_unless(alpha_ok(alpha), (p / q).saturate())
}

/// three.js's fit of the sheen's environment term (its `IBLSheenBRDF`, two exponentials in n.v
/// split at roughness 1/4), read as the albedo of its D_charlie (alpha = r^2) V_neubelt lobe:
/// with the perceptual sheen roughness r, E = saturate(exp(a n.v + b) + k), a, b quadratics
/// in r and k = 0.1 (r - 1/4) above r = 1/4, 0 below. (three.js's function returns this DG
/// divided by pi.) A coarse fit: measured max abs error 0.54 over mu in [0.1, 1] and
/// roughness in [0.05, 1], at grazing views of the smoothest sheens.
///
/// Domain: n_dot_v a cosine, clamped to [0, 1]; `roughness` (perceptual) in [0, 1]; NaN for
/// NaN input or roughness outside [0, 1]. Measured error against
/// [`albedo_estimate`]`(mu, r^2, true)`: printed by `cargo test --test layers sheen_albedo::
/// -- --nocapture` and bounded there (0.55).
///
/// Source: three.js, `src/renderers/shaders/ShaderChunk/lights_physical_pars_fragment.glsl.js`,
/// `IBLSheenBRDF` (the same fit from r130 on; read at commit
/// 12f550e0f44f68e5b6c946dd242ee08e42d209e4).
#[inline]
#[must_use]
pub fn albedo_fit_threejs<T: Real>(n_dot_v: T, roughness: T) -> T {
    let mu = n_dot_v.saturate();
    let r = roughness;
    let r2 = r * r;
    let smooth = r.simd_lt(T::splat(0.25));
    let quad = |c2: f64, c1: f64, c0: f64| T::splat(c2) * r2 + T::splat(c1) * r + T::splat(c0);
    let a = T::select(smooth, quad(-339.2, 161.4, -25.9), quad(-8.48, 14.3, -9.95));
    let b = T::select(smooth, quad(44.0, -23.7, 3.26), quad(1.97, -3.27, 0.72));
    let k = T::select(smooth, T::ZERO, T::splat(0.1) * (r - T::splat(0.25)));
    let dg = a.mul_add(mu, b).exp() + k;
    nan_unless(in_unit(roughness), dg.saturate())
}

/// KHR_materials_sheen's albedo scaling of the layer below the sheen:
/// s = min(1 - max_rgb(sheenColor) e_v, 1 - max_rgb(sheenColor) e_l), with e_v = E(n.v) and
/// e_l = E(n.l) the sheen albedo ([`albedo`] or a caller's table). The view-only form the
/// extension allows, 1 - max_rgb(sheenColor) E(n.v), is `albedo_scaling(color, e_v, e_v)`:
/// one value per shading point, for every light and the environment. The min form is
/// symmetric in v and l (reciprocal); the view-only form is not.
///
/// Domain: `sheen_color` each channel in [0, 1]; `e_v`, `e_l` in [0, 1]; NaN for NaN input or
/// a value outside its domain. Output in [0, 1]; exactly 1 for a black sheen colour.
///
/// Source: KHR_materials_sheen, "Albedo-scaling technique"; Conty and Kulla 2017, "Revisiting
/// Physically Based Shading at Imageworks".
#[inline]
#[must_use]
pub fn albedo_scaling<T: Real>(sheen_color: V3<T>, e_v: T, e_l: T) -> T {
    let m = sheen_color.x.max(sheen_color.y).max(sheen_color.z);
    let s = (T::ONE - m * e_v).min(T::ONE - m * e_l);
    let ok = in_unit(sheen_color.x)
        & in_unit(sheen_color.y)
        & in_unit(sheen_color.z)
        & in_unit(e_v)
        & in_unit(e_l);
    nan_unless(ok, s)
}

/// The sheen albedo E(mu, alpha) of the glTF lobe (D_charlie V_charlie, sheenColor 1) on a
/// 16 x 16 grid at texel centres: `ALBEDO_TABLE[16 i + j]` = E(mu_j, alpha_i) with
/// mu_j = (j + 1/2) / 16 and alpha_i = ((i + 1/2) / 16)^2; written by [`albedo_table`]
/// (adaptive cubature) and rounded to f32. The Lambda fit does not conserve energy at grazing
/// views of smooth sheens: E reaches 1.63 at mu = 1/32, alpha = 1/1024 (the first entry);
/// [`albedo`] clamps its result to 1.
#[rustfmt::skip]
pub static ALBEDO_TABLE: [f32; ALBEDO_TABLE_SIZE * ALBEDO_TABLE_SIZE] = [
    1.6336572e0, 1.0216756e-1, 3.6620144e-3, 5.9458387e-5, 3.771664e-7, 8.1564694e-10, 5.045271e-13, 7.824237e-17, 2.9398514e-21, 1.4597238e-26, 5.184346e-33, 6.2848e-41, 0e0, 0e0, 0e0, 0e0,
    1.4023854e0, 5.5475646e-1, 2.2799633e-1, 9.036512e-2, 3.3441372e-2, 1.1290542e-2, 3.401858e-3, 8.924634e-4, 1.9784989e-4, 3.566953e-5, 4.9437967e-6, 4.847868e-7, 2.9439468e-8, 8.558086e-10, 7.355044e-12, 3.4970016e-15,
    1.0835003e0, 5.9697247e-1, 3.4867945e-1, 2.0512225e-1, 1.1904894e-1, 6.730542e-2, 3.668223e-2, 1.9070901e-2, 9.348924e-3, 4.2665396e-3, 1.7725755e-3, 6.4904004e-4, 1.9910524e-4, 4.6766767e-5, 6.9172484e-6, 3.339754e-7,
    9.085049e-1, 5.786904e-1, 3.9018586e-1, 2.6736474e-1, 1.8313263e-1, 1.2420451e-1, 8.282022e-2, 5.394022e-2, 3.4096766e-2, 2.0815693e-2, 1.21156145e-2, 6.6007124e-3, 3.2741306e-3, 1.4094089e-3, 4.757733e-4, 9.1335285e-5,
    8.111899e-1, 5.613416e-1, 4.0971053e-1, 3.046904e-1, 2.2758834e-1, 1.6939126e-1, 1.24921724e-1, 9.084004e-2, 6.487047e-2, 4.543437e-2, 3.0934216e-2, 2.0220326e-2, 1.2462671e-2, 7.0284284e-3, 3.4128486e-3, 1.1995024e-3,
    7.589488e-1, 5.541627e-1, 4.253719e-1, 3.3295506e-1, 2.6233894e-1, 2.0659702e-1, 1.6183731e-1, 1.256053e-1, 9.631271e-2, 7.301842e-2, 5.436718e-2, 3.938509e-2, 2.7405683e-2, 1.7947357e-2, 1.0641514e-2, 5.188837e-3,
    7.355207e-1, 5.5741405e-1, 4.4289994e-1, 3.5893592e-1, 2.9315022e-1, 2.3971805e-1, 1.9542608e-1, 1.5829377e-1, 1.2712902e-1, 1.014364e-1, 7.997771e-2, 6.185107e-2, 4.6467587e-2, 3.3429377e-2, 2.2456354e-2, 1.3339513e-2,
    7.3190665e-1, 5.696704e-1, 4.6393684e-1, 3.8538298e-1, 3.2283676e-1, 2.710696e-1, 2.2723609e-1, 1.8961509e-1, 1.5724936e-1, 1.2996635e-1, 1.0657319e-1, 8.6178586e-2, 6.821297e-2, 5.230635e-2, 3.8214266e-2, 2.5769532e-2,
    7.424639e-1, 5.8918387e-1, 4.88524e-1, 4.1316205e-1, 3.5253683e-1, 3.0172706e-1, 2.5808194e-1, 2.200211e-1, 1.8672994e-1, 1.582763e-1, 1.3347557e-1, 1.1141897e-1, 9.152939e-2, 7.343767e-2, 5.690744e-2, 4.1786637e-2,
    7.630696e-1, 6.140621e-1, 5.158962e-1, 4.4211087e-1, 3.823781e-1, 3.3190516e-1, 2.8813198e-1, 2.4954963e-1, 2.1543041e-1, 1.8602203e-1, 1.6012965e-1, 1.368175e-1, 1.1549256e-1, 9.577814e-2, 7.7437446e-2, 6.032602e-2,
    7.901597e-1, 6.422015e-1, 5.4474837e-1, 4.714016e-1, 4.1181487e-1, 3.6120883e-1, 3.1704938e-1, 2.7785683e-1, 2.4295472e-1, 2.1272303e-1, 1.8594825e-1, 1.6166702e-1, 1.3927054e-1, 1.1837479e-1, 9.874261e-2, 8.023838e-2,
    8.2018477e-1, 6.7119884e-1, 5.733378e-1, 4.997199e-1, 4.3982068e-1, 3.8880348e-1, 3.4412104e-1, 3.0429748e-1, 2.6868424e-1, 2.3775567e-1, 2.1027714e-1, 1.852611e-1, 1.620861e-1, 1.4036337e-1, 1.19857624e-1, 1.0044463e-1,
    8.493076e-1, 6.983017e-1, 5.995474e-1, 5.253798e-1, 4.650208e-1, 4.135436e-1, 3.683691e-1, 3.2801268e-1, 2.9183957e-1, 2.6038992e-1, 2.3241007e-1, 2.0689347e-1, 1.8320975e-1, 1.6096798e-1, 1.3993642e-1, 1.2000332e-1,
    8.732815e-1, 7.2041965e-1, 6.2095505e-1, 5.464202e-1, 4.8579693e-1, 4.3407393e-1, 3.8864154e-1, 3.4800535e-1, 3.115391e-1, 2.7983063e-1, 2.5161335e-1, 2.2586799e-1, 2.0195915e-1, 1.7949575e-1, 1.5825044e-1, 1.3812388e-1,
    8.87503e-1, 7.3420596e-1, 6.3492495e-1, 5.6069577e-1, 5.0037205e-1, 4.4890475e-1, 4.0367526e-1, 3.631905e-1, 3.2683614e-1, 2.9524136e-1, 2.6713666e-1, 2.4149778e-1, 2.1768823e-1, 1.9531879e-1, 1.7416716e-1, 1.5414622e-1,
    8.872505e-1, 7.362162e-1, 6.387257e-1, 5.659669e-1, 5.068782e-1, 4.5646042e-1, 4.121285e-1, 3.7241367e-1, 3.367258e-1, 3.0574048e-1, 2.7819982e-1, 2.5308356e-1, 2.2975862e-1, 2.0783998e-1, 1.8711157e-1, 1.6749877e-1,
];
