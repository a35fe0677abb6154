//! The Phong family: classic Phong turned into a BRDF, the modified (reciprocal) and normalized
//! (energy-conserving) Phong of Lewis and of Lafortune and Willems, and Blinn-Phong with its
//! exact BRDF normalization, the common approximation of it and the microfacet (NDF)
//! normalization.
//!
//! | model | f (without the cosine n.l) | reciprocal | albedo <= 1 |
//! |---|---|---|---|
//! | [`classic`] | ks (r.l)^n / (n.l) | no | no (2 pi ks at n = 0) |
//! | [`modified`] | ks (r.l)^n | yes | for ks <= (n + 2) / (2 pi) (its albedo is at most ks 2 pi / (n + 2)) |
//! | [`normalized`] | ks (n + 2) / (2 pi) (r.l)^n | yes | yes (ks at normal incidence) |
//! | [`diffuse_specular`] | kd / pi + ks (n + 2) / (2 pi) (r.l)^n | yes | yes for kd + ks <= 1 |
//! | [`blinn_phong`] | ks (n.h)^n | yes | for ks <= c(n) (albedo ks / c(n) at normal incidence) |
//! | [`blinn_phong_normalized`] | ks c(n) (n.h)^n, c exact | yes | ks at normal incidence |
//! | [`blinn_phong_normalized_approx`] | ks (n + 8) / (8 pi) (n.h)^n | yes | up to 1.075 ks (n = 8.76) |
//! | [`blinn_phong_ndf`] | D = (n + 2) / (2 pi) (n.h)^n, a microfacet distribution | | |
//!
//! Here n is the exponent (the "shininess"), r the mirror direction of the view direction v
//! about the normal (r.l = 2 (n.v)(n.l) - v.l, which equals the mirror of l dotted with v),
//! and h = (v + l) / |v + l| the half vector.
//!
//! Conventions shared by every lobe here:
//! - Dot-product entry points take the cosines first (`n_dot_v`, `n_dot_l`, then `r_dot_l` or
//!   `n_dot_h`) and the parameters after; they return the BRDF f (without the cosine n.l).
//!   They validate nothing: a parameter outside its documented domain gives NaN (also below
//!   the horizon), a NaN input gives NaN, and a direction at or below the horizon gives 0.
//! - Each lobe also has a parameter type whose constructor validates (returning
//!   [`ParamError`]), with `eval(wo, wi)` on local-frame unit vectors (normal = +z).
//! - The exponent n is finite and >= 0, up to `T::MAX`: no normalization overflows there (every
//!   product is ordered so that the largest intermediate is about n) and n = 0 gives the limit
//!   n -> 0+ of the lobe, a step: 1 where the cosine is > 0, 0 where it is <= 0 (so 0^0 is
//!   never evaluated as 1 outside the lobe). n = +inf is outside the domain (NaN): its
//!   normalized lobes are a delta, not a function.
//! - The lobe cosine is clamped to 1 (a unit-vector dot product can round above 1; (1 + e)^n
//!   would overflow for large n). `pow` is `libm` per lane, so lanes equal scalars bit for bit
//!   and exponents of 10^4 keep full accuracy.
//!
//! Accuracy: lanes (`f32x8`, `f64x4`) equal scalars bit for bit. f32 against f64 on the same
//! inputs: within 4 f32 epsilon relative (measured worst 3.0, exact Blinn-Phong) wherever the
//! lobe max(0, c)^n is a normal f32; where it underflows into subnormals the error is absolute,
//! at most 2^-149 (f / c^n + 1).
//!
//! Albedo at a glance (ks = 1, `tests/phong/energy.rs`): normalized Phong gives 1 at normal
//! incidence and about cos(theta_o) for tight lobes (0.087 at 85 degrees, n >= 1000); exact
//! Blinn-Phong gives 1 at normal incidence and about cos^2(theta_o) for tight lobes; classic
//! Phong gives 2 pi at n = 0, still 1.07 at n = 2 and 89 degrees.
//!
//! ```
//! use brdf::V3;
//! use brdf::phong::{self, NormalizedPhong};
//!
//! let lobe = NormalizedPhong::new(0.8_f32, 50.0).unwrap();
//! let wo = V3::new(0.6, 0.0, 0.8);
//! // The mirror direction of wo: the peak, ks (n + 2) / (2 pi).
//! let wi = V3::new(-0.6, 0.0, 0.8);
//! let peak = 0.8 * phong::phong_normalization(50.0_f32);
//! assert!((lobe.eval(wo, wi) / peak - 1.0).abs() < 1e-6);
//! // The same through the dot-product entry point, with r.l = 2 (n.v)(n.l) - v.l = 1.
//! // (`normalized` rounds once where `peak` here rounds twice.)
//! assert!((phong::normalized(0.8, 0.8, 1.0, 0.8, 50.0) / peak - 1.0).abs() < 1e-6);
//! ```
//!
//! Figures quoted here and on each item come from `cargo test --no-default-features --features
//! phong,integrate --test phong -- --nocapture` (its modules `energy`, `reciprocity`,
//! `normalization` and `stability`).

use crate::domain::{above_horizon, finite_dirs, in_unit, nan_unless, unit_if_inf};
use crate::dw::Dw;
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

/// 1 / (2 pi).
const FRAC_1_2PI: f64 = 0.159_154_943_091_895_35;
/// 1 / (8 pi).
const FRAC_1_8PI: f64 = 0.039_788_735_772_973_836;
/// 1 / (8 pi) - `FRAC_1_8PI`: the tail of 1 / pi (-1.9678676675182486e-17) divided by 8.
const FRAC_1_8PI_TAIL: f64 = -2.459_834_584_397_810_8e-18;

/// Mask of a valid exponent: finite and >= 0 (false for NaN).
#[inline]
fn exponent_ok<T: Real>(exponent: T) -> T::Mask {
    exponent.simd_ge(T::ZERO) & exponent.is_finite()
}

/// The lobe max(0, c)^n with c clamped to 1: 0 for c <= 0 (also at n = 0, the limit n -> 0+),
/// NaN for NaN c. Without the explicit NaN case, C99 `pow(NaN, 0) = 1` and the `c > 0` select
/// would both turn a NaN cosine into a plausible value. The BRDF kernels also test the lobe
/// cosine for NaN outside their horizon guard, so a NaN gives NaN below the horizon too.
#[inline]
fn lobe<T: Real>(c: T, exponent: T) -> T {
    let v = T::select(c.simd_gt(T::ZERO), c.min(T::ONE).pow(exponent), T::ZERO);
    T::select(c.is_nan(), T::splat(f64::NAN), v)
}

/// The Phong lobe normalization (n + 2) / (2 pi): the integral of (n + 2) / (2 pi) cos^n(a)
/// cos(a) over the hemisphere around the lobe axis is 1 (Lafortune and Willems 1994, "Using
/// the modified Phong reflectance model for physically based rendering", Tech. Report CW 197,
/// KU Leuven). The same factor normalizes the Blinn-Phong NDF ([`blinn_phong_ndf`]).
///
/// Domain: n finite and >= 0 (NaN otherwise); 1 / pi at n = 0, about n / (2 pi) for large n,
/// finite up to n = `T::MAX` (5.4e37 in f32). It exceeds 1 for n > 2 pi - 2 = 4.28.
#[inline]
#[must_use]
pub fn phong_normalization<T: Real>(exponent: T) -> T {
    nan_unless(
        exponent_ok(exponent),
        (exponent + T::TWO) * T::splat(FRAC_1_2PI),
    )
}

/// Exact normalization c(n) of the Blinn-Phong BRDF c (n.h)^n, the one that makes its
/// directional albedo exactly 1 at normal incidence:
///
/// c(n) = (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)).
///
/// Derivation: at v = normal, n.h = cos(theta_l / 2); with x = cos(theta_l / 2) the albedo
/// integral 2 pi c int_0^(pi/2) cos^n(theta/2) cos(theta) sin(theta) d theta becomes
/// 8 pi c int_(1/sqrt 2)^1 (2 x^(n+3) - x^(n+1)) dx = 8 pi c (n + 2^(-n/2)) / ((n + 2)(n + 4)).
/// Checked by numerical integration for n from 0 to 10^4 (`tests/phong/energy.rs`). Same
/// result as Giesen 2009, "Derivation of the normalization factor for Blinn-Phong".
///
/// Domain: n finite and >= 0 (NaN otherwise). c(0) = 1 / pi (a Lambertian lobe: (n.h)^0 = 1);
/// c(n) -> (n + 6) / (8 pi) for large n. Evaluated as
/// (n + 2) / (8 pi) * (n + 4) / (n + 2^(-n/2)) in double-word arithmetic (Dekker 1971), so
/// only the power 2^(-n/2) and the final result are rounded, (n + 2)(n + 4) never overflows
/// (it would in f32 from n = 1.8e19) and the underflow of 2^(-n/2) is harmless (n itself
/// dominates the sum there); finite up to n = `T::MAX` (1.4e37 in f32). Within 1.0 ULP of the
/// correctly rounded value for n in [0, `T::MAX`] on every lane type, max 0.81 found (MPFR
/// oracle, `cargo test -p brdf-oracle --release --test lobes -- --nocapture`).
#[inline]
#[must_use]
pub fn blinn_phong_normalization_exact<T: Real>(exponent: T) -> T {
    let (c, scale) = normalization_exact_dw(exponent);
    nan_unless(exponent_ok(exponent), c.value() * scale)
}

/// c(n) = (n + 2) / (8 pi) (n + 4) / (n + 2^(-n/2)) in double words, as (c s^-1, s) with s a
/// power of two: 1 up to n = 2^64 (f32) or 2^512 (f64), where c is carried whole; above, c is
/// n / (8 pi) to far below one ULP (the rest is 6 / n relative) and is carried scaled by
/// s^-1 = 2^-64 (2^-512), which keeps Dekker's splits of n and of the products finite. Only
/// the power 2^(-n/2) is rounded before the end (one `pow`, weighted by 2^(-n/2) / n).
#[inline]
fn normalization_exact_dw<T: Real>(n: T) -> (Dw<T>, T) {
    let eps: f64 = T::EPSILON.lane(0).into();
    // (2^64, 2^-64) for f32, (2^512, 2^-512) for f64.
    let (up, down) = if eps > 1e-10 {
        (1.844_674_407_370_955_2e19, 5.421_010_862_427_522e-20)
    } else {
        (1.340_780_792_994_259_7e154, 7.458_340_731_200_207e-155)
    };
    let big = n.simd_gt(T::splat(up));
    let k8 = Dw::constant(FRAC_1_8PI, FRAC_1_8PI_TAIL);
    // The small path on big lanes sees 0, so it stays finite there.
    let m = T::select(big, T::ZERO, n);
    // 2^(-n/2) as 0.5^(n/2) through `pow`, which is libm per lane, so lanes equal scalars (the
    // lane `exp2` is a polynomial within 1 ulp, not bit-identical).
    let p = T::HALF.pow(T::HALF * m);
    let ratio = Dw::sum(m, T::splat(4.0)).div(Dw::sum(m, p));
    let small = Dw::sum(m, T::TWO).mul(k8).mul(ratio);
    let large = Dw::exact(n * T::splat(down)).mul(k8);
    (
        Dw::select(big, large, small),
        T::select(big, T::splat(up), T::ONE),
    )
}

/// The common approximation (n + 8) / (8 pi) of [`blinn_phong_normalization_exact`]
/// (Akenine-Moller, Haines, Hoffman 2008, "Real-Time Rendering", 3rd ed.; it integrates the
/// albedo with the n.l factor approximated, and is exact at n = 0).
///
/// Error against the exact factor, measured over n in [0, 10^4] (`tests/phong/normalization.rs`):
/// it is never below the exact one, by at most 7.52% (relative), at n = 8.76; the excess is
/// 2 / (n + 6) for large n (0.02% at n = 10^4). Since the exact factor gives albedo 1 at normal
/// incidence, the approximation gives up to 1.075 there.
///
/// Domain: n finite and >= 0 (NaN otherwise); finite up to n = `T::MAX`.
#[inline]
#[must_use]
pub fn blinn_phong_normalization_approx<T: Real>(exponent: T) -> T {
    nan_unless(
        exponent_ok(exponent),
        (exponent + T::splat(8.0)) * T::splat(FRAC_1_8PI),
    )
}

/// Classic Phong as a BRDF: f = ks max(0, r.l)^n / (n.l).
///
/// Phong's shading model I = ks (r.v)^n I_light (Phong 1975, "Illumination for Computer
/// Generated Pictures", CACM 18(6)) multiplies the light by the lobe without the cosine n.l,
/// so the BRDF that reproduces it divides by n.l. Kept for comparison: it is neither
/// reciprocal (f(v, l) / f(l, v) = (n.v) / (n.l)) nor energy conserving (its albedo at normal
/// incidence is ks 2 pi / (n + 1), above ks for n < 2 pi - 1; 2 pi ks at n = 0) (Lewis 1994,
/// "Making Shaders More Physically Plausible", Computer Graphics Forum 13(2)).
///
/// `r_dot_l`: the mirror of v about the normal dotted with l, 2 (n.v)(n.l) - v.l.
///
/// Domain: ks in [0, 1], exponent finite and >= 0 (NaN otherwise, also below the horizon);
/// 0 where `n_dot_v <= 0` or `n_dot_l <= 0` or `r_dot_l <= 0`.
///
/// Edge n.l -> 0+: f grows as 1 / (n.l) (a grazing light and a grazing viewer can share the
/// mirror direction), while f (n.l) = ks (r.l)^n, the shading model itself, stays bounded.
/// The divisor is floored at `T::MIN_POSITIVE` (so only subnormal cosines are affected):
/// f <= ks / MIN_POSITIVE (8.5e37 in f32, 4.5e307 in f64), never inf.
#[inline]
#[must_use]
pub fn classic<T: Real>(n_dot_v: T, n_dot_l: T, r_dot_l: T, ks: T, exponent: T) -> T {
    // An infinite n.l counts as 1 (rules 3 and 5): ks / inf would be a plausible 0.
    let n_dot_l = unit_if_inf(n_dot_l);
    // ks / n.l first (at most 1 / MIN_POSITIVE, finite), then the lobe: a subnormal lobe is
    // then rounded once more at most, not scaled up after a subnormal product.
    let f = ks / n_dot_l.max(T::MIN_POSITIVE) * lobe(r_dot_l, exponent);
    nan_unless(
        in_unit(ks) & exponent_ok(exponent) & !r_dot_l.is_nan(),
        above_horizon(n_dot_v, n_dot_l, f),
    )
}

/// Modified Phong: f = ks max(0, r.l)^n (Lewis 1994, "Making Shaders More Physically
/// Plausible", Computer Graphics Forum 13(2)). Reciprocal (r.l is symmetric in v and l), but
/// energy conserving only for ks <= (n + 2) / (2 pi): its albedo peaks at normal incidence at
/// ks 2 pi / (n + 2), which exceeds 1 with ks = 1 for n < 2 pi - 2 = 4.28 (pi at n = 0).
/// [`normalized`] divides that out.
///
/// Domain: ks in [0, 1], exponent finite and >= 0 (NaN otherwise, also below the horizon);
/// 0 where `n_dot_v <= 0`, `n_dot_l <= 0` or `r_dot_l <= 0`; at most ks.
///
/// Accuracy: within 1.7 ULP of the correctly rounded value on every lane type, max 1.48 (f32)
/// and 1.45 (f64) found (MPFR oracle, `cargo test -p brdf-oracle --release --test lobes --
/// --nocapture`): the inputs are exact, so the condition number n ln(r.l) of the
/// power costs nothing; only `pow` and one product round.
#[inline]
#[must_use]
pub fn modified<T: Real>(n_dot_v: T, n_dot_l: T, r_dot_l: T, ks: T, exponent: T) -> T {
    nan_unless(
        in_unit(ks) & exponent_ok(exponent) & !r_dot_l.is_nan(),
        above_horizon(n_dot_v, n_dot_l, ks * lobe(r_dot_l, exponent)),
    )
}

/// Normalized modified Phong: f = ks (n + 2) / (2 pi) max(0, r.l)^n (Lewis 1994; Lafortune
/// and Willems 1994, "Using the modified Phong reflectance model for physically based
/// rendering").
///
/// Its directional albedo is exactly ks at normal incidence (the lobe then lies whole in the
/// hemisphere) and less elsewhere, where the horizon clips the lobe: energy conserving for
/// ks <= 1 (measured over n in [0, 10^4] in `tests/phong/energy.rs`). A wide lobe is dimmer
/// and a tight one brighter than [`classic`] at its peak: the factor (n + 2) / (2 pi) is below
/// 1 for n < 2 pi - 2 = 4.28.
///
/// Domain: ks in [0, 1], exponent finite and >= 0 (NaN otherwise, also below the horizon);
/// 0 where `n_dot_v <= 0`, `n_dot_l <= 0` or `r_dot_l <= 0`. n = 0 gives ks / pi where
/// r.l > 0. Peak ks (n + 2) / (2 pi), finite up to n = `T::MAX` ([`phong_normalization`]).
#[inline]
#[must_use]
pub fn normalized<T: Real>(n_dot_v: T, n_dot_l: T, r_dot_l: T, ks: T, exponent: T) -> T {
    let l = lobe(r_dot_l, exponent);
    // (n + 2), 1 / (2 pi), ks and l carried in double words (Dekker 1971) and rounded once,
    // so only `pow` and the last product round (four plain roundings reached 4.07 ulps in
    // f64). Above n = 2^64 the plain product: there the lobe is 0 unless r.l = 1, and the
    // double words' splits of n would overflow near MAX.
    let big = exponent.simd_gt(T::splat(1.844_674_407_370_955_2e19));
    let m = T::select(big, T::ZERO, exponent);
    let small = Dw::sum(m, T::TWO)
        .mul(Dw::frac_1_pi().scale(T::HALF))
        .mul(Dw::exact(ks))
        // The lobe last: where it is subnormal, only the final product rounds there.
        .mul(Dw::exact(l))
        .value();
    let large = ks * phong_normalization(exponent) * l;
    nan_unless(
        in_unit(ks) & exponent_ok(exponent) & !r_dot_l.is_nan(),
        above_horizon(n_dot_v, n_dot_l, T::select(big, large, small)),
    )
}

/// Lafortune and Willems' diffuse plus normalized Phong BRDF: f = kd / pi + ks (n + 2) / (2 pi)
/// max(0, r.l)^n (Lafortune and Willems 1994, "Using the modified Phong reflectance model for
/// physically based rendering"). Reciprocal; its albedo is at most kd + ks (reached at normal
/// incidence), so energy conserving for kd + ks <= 1.
///
/// Domain: kd and ks in [0, 1] with kd + ks <= 1 + `T::EPSILON` (one rounding of the sum is
/// tolerated, so kd = 1 - ks computed in the lane type passes), exponent finite and >= 0 (NaN
/// otherwise, also below the horizon); 0 where `n_dot_v <= 0` or `n_dot_l <= 0`.
#[inline]
#[must_use]
pub fn diffuse_specular<T: Real>(
    n_dot_v: T,
    n_dot_l: T,
    r_dot_l: T,
    kd: T,
    ks: T,
    exponent: T,
) -> T {
    let f = kd.mul_add(
        T::FRAC_1_PI,
        ks * phong_normalization(exponent) * lobe(r_dot_l, exponent),
    );
    nan_unless(
        sum_ok(kd, ks) & exponent_ok(exponent) & !r_dot_l.is_nan(),
        above_horizon(n_dot_v, n_dot_l, f),
    )
}

/// Mask of kd, ks in [0, 1] with kd + ks <= 1 up to one rounding.
#[inline]
fn sum_ok<T: Real>(kd: T, ks: T) -> T::Mask {
    in_unit(kd) & in_unit(ks) & (kd + ks).simd_le(T::ONE + T::EPSILON)
}

/// Unnormalized Blinn-Phong: f = ks (n.h)^n (Blinn 1977, "Models of Light Reflection for
/// Computer Synthesized Pictures", SIGGRAPH). Reciprocal (h is symmetric in v and l); its
/// albedo at normal incidence is ks / c(n) ([`blinn_phong_normalization_exact`]), which
/// exceeds 1 with ks = 1 for n < 18.71 (pi at n = 0), as the modified Phong does below 4.28.
///
/// Domain: ks in [0, 1], exponent finite and >= 0 (NaN otherwise, also below the horizon);
/// 0 where `n_dot_v <= 0` or `n_dot_l <= 0`; n.h is clamped to 1. With both directions above
/// the horizon n.h > 0, so n = 0 gives the constant ks. Accuracy as [`modified`]: within
/// 1.7 ULP (f32, f32x8) / 1.6 ULP (f64, f64x4), max 1.48 / 1.45 found
/// (`cargo test -p brdf-oracle --release --test lobes -- --nocapture`).
#[inline]
#[must_use]
pub fn blinn_phong<T: Real>(n_dot_v: T, n_dot_l: T, n_dot_h: T, ks: T, exponent: T) -> T {
    nan_unless(
        in_unit(ks) & exponent_ok(exponent) & !n_dot_h.is_nan(),
        above_horizon(n_dot_v, n_dot_l, ks * lobe(n_dot_h, exponent)),
    )
}

/// Blinn-Phong with its exact BRDF normalization: f = ks c(n) (n.h)^n with
/// c(n) = (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) ([`blinn_phong_normalization_exact`]):
/// directional albedo exactly ks at normal incidence, reciprocal.
///
/// Away from normal incidence the albedo falls (about cos^2(theta_o) for a tight lobe, as the
/// half-vector lobe maps to a wider, horizon-clipped lobe of l); it never exceeds ks over
/// n in [0, 10^4] (`tests/phong/energy.rs`). n = 0 is Lambert: ks / pi.
///
/// Domain: ks in [0, 1], exponent finite and >= 0 (NaN otherwise, also below the horizon);
/// 0 where `n_dot_v <= 0` or `n_dot_l <= 0`. Peak ks c(n), finite up to n = `T::MAX`.
///
/// Accuracy: ks c(n) is carried in double words and multiplied by the power (n.h)^n once:
/// within 1.9 ULP of the correctly rounded value on every lane type, max 1.73 (f32) and 1.69
/// (f64) found, n up to `T::MAX` (MPFR oracle, `cargo test -p brdf-oracle --release --test
/// lobes -- --nocapture`). The inputs are exact, so the power's condition number
/// n ln(n.h) costs nothing: only `pow` (libm) and the final product round.
#[inline]
#[must_use]
pub fn blinn_phong_normalized<T: Real>(
    n_dot_v: T,
    n_dot_l: T,
    n_dot_h: T,
    ks: T,
    exponent: T,
) -> T {
    nan_unless(
        in_unit(ks) & exponent_ok(exponent) & !n_dot_h.is_nan(),
        above_horizon(n_dot_v, n_dot_l, {
            // ks c(n) (n.h)^n rounded once after the pow: the largest finite product stays
            // below MAX (c(n) <= MAX / (8 pi)), and a scaled c meets a lobe of 1 or 0 only.
            let (c, scale) = normalization_exact_dw(exponent);
            let lobe = lobe(n_dot_h, exponent);
            c.mul(Dw::exact(ks)).mul(Dw::exact(lobe)).value() * scale
        }),
    )
}

/// Blinn-Phong with the approximate normalization of "Real-Time Rendering", 3rd ed.:
/// f = ks (n + 8) / (8 pi) (n.h)^n ([`blinn_phong_normalization_approx`]). Reciprocal, but
/// its albedo at normal incidence exceeds ks by up to 7.52% (at n = 8.76): pick
/// [`blinn_phong_normalized`] where energy matters.
///
/// Domain: ks in [0, 1], exponent finite and >= 0 (NaN otherwise, also below the horizon);
/// 0 where `n_dot_v <= 0` or `n_dot_l <= 0`.
#[inline]
#[must_use]
pub fn blinn_phong_normalized_approx<T: Real>(
    n_dot_v: T,
    n_dot_l: T,
    n_dot_h: T,
    ks: T,
    exponent: T,
) -> T {
    nan_unless(
        in_unit(ks) & exponent_ok(exponent) & !n_dot_h.is_nan(),
        above_horizon(
            n_dot_v,
            n_dot_l,
            ks * blinn_phong_normalization_approx(exponent) * lobe(n_dot_h, exponent),
        ),
    )
}

/// The Blinn-Phong microfacet distribution: D(m) = (n + 2) / (2 pi) max(0, n.m)^n, normalized
/// so that the integral of D(m) (n.m) dm over the hemisphere is 1 (Walter et al. 2007,
/// "Microfacet Models for Refraction through Rough Surfaces", eq. 30; the Phong distribution
/// of Blinn 1977 in the microfacet normalization).
///
/// This is not a BRDF normalization: used as f = D (as some engines do) it gives albedo
/// (n + 2) / (2 pi c(n)) at normal incidence, from 1 at n = 0 (both factors are 1 / pi) to
/// 4 for large n (the 4 of the half-vector Jacobian 1 / (4 v.h)). In a microfacet BRDF,
/// D G F / (4 (n.v)(n.l)), that Jacobian is accounted for; [`blinn_phong_normalized`] is the
/// standalone lobe.
///
/// Domain: exponent finite and >= 0 (NaN otherwise); 0 for n.m <= 0; n.m clamped to 1.
/// n = 0 gives the constant 1 / pi on the upper hemisphere.
#[inline]
#[must_use]
pub fn blinn_phong_ndf<T: Real>(n_dot_h: T, exponent: T) -> T {
    phong_normalization(exponent) * lobe(n_dot_h, exponent)
}

/// r.l = wo.z wi.z - wo.x wi.x - wo.y wi.y: the mirror of `wo` about +z dotted with `wi`.
#[inline]
fn r_dot_l<T: Real>(wo: V3<T>, wi: V3<T>) -> T {
    wo.z.mul_add(wi.z, -(wo.x.mul_add(wi.x, wo.y * wi.y)))
}

/// n.h = (wo + wi).z / |wo + wi|, and 0 where wo + wi = 0 (wo = -wi, never both above the
/// horizon, so the kernel's horizon test returns 0 there anyway; without the guard the 0 / 0
/// would be a NaN from finite input). A NaN component propagates: a fallback normal, as
/// `normalize_or` gives, would hide it.
#[inline]
fn n_dot_h<T: Real>(wo: V3<T>, wi: V3<T>) -> T {
    let h = wo + wi;
    let len2 = h.length_squared();
    T::select(len2.simd_eq(T::ZERO), T::ZERO, h.z / len2.sqrt())
}

/// Validates ks in [0, 1] and the exponent (finite, >= 0) in every lane.
fn validate<T: Real>(ks: T, exponent: T) -> Result<(), ParamError> {
    require::<T>(in_unit(ks), "ks", "in [0, 1]")?;
    require::<T>(exponent_ok(exponent), "exponent", "finite and >= 0")
}

macro_rules! phong_type {
    ($(#[$doc:meta])* $name:ident, $kernel:ident, $dot:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct $name<T> {
            ks: T,
            exponent: T,
        }

        impl<T: Real> $name<T> {
            /// A lobe with specular coefficient `ks` in [0, 1] and exponent finite and >= 0,
            /// in every lane; else [`ParamError`] naming `"ks"` or `"exponent"`.
            pub fn new(ks: T, exponent: T) -> Result<Self, ParamError> {
                validate(ks, exponent)?;
                Ok(Self { ks, exponent })
            }

            /// The specular coefficient ks.
            #[inline]
            #[must_use]
            pub fn ks(&self) -> T {
                self.ks
            }

            /// The exponent n.
            #[inline]
            #[must_use]
            pub fn exponent(&self) -> T {
                self.exponent
            }

            #[doc = concat!("f(wo, wi) by [`", stringify!($kernel), "`], on local-frame unit vectors")]
            /// (normal = +z) pointing away from the surface; 0 at or below the horizon.
            #[inline]
            #[must_use]
            pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
                let f = $kernel(wo.z, wi.z, $dot(wo, wi), self.ks, self.exponent);
                finite_dirs(wo, wi, f)
            }
        }
    };
}

phong_type!(
    /// Classic Phong as a BRDF, ks (r.l)^n / (n.l) ([`classic`]): neither reciprocal nor
    /// energy conserving, kept for comparison.
    ClassicPhong,
    classic,
    r_dot_l
);
phong_type!(
    /// Modified Phong, ks (r.l)^n ([`modified`]): reciprocal; albedo at most ks 2 pi / (n + 2).
    ModifiedPhong,
    modified,
    r_dot_l
);
phong_type!(
    /// Normalized modified Phong, ks (n + 2) / (2 pi) (r.l)^n ([`normalized`]): albedo ks at
    /// normal incidence, less elsewhere.
    NormalizedPhong,
    normalized,
    r_dot_l
);
phong_type!(
    /// Unnormalized Blinn-Phong, ks (n.h)^n ([`blinn_phong`]).
    BlinnPhong,
    blinn_phong,
    n_dot_h
);
phong_type!(
    /// Blinn-Phong with the exact BRDF normalization, ks c(n) (n.h)^n
    /// ([`blinn_phong_normalized`]): albedo ks at normal incidence.
    NormalizedBlinnPhong,
    blinn_phong_normalized,
    n_dot_h
);
phong_type!(
    /// Blinn-Phong with the "Real-Time Rendering" normalization, ks (n + 8) / (8 pi) (n.h)^n
    /// ([`blinn_phong_normalized_approx`]): albedo up to 1.075 ks at normal incidence.
    ApproxNormalizedBlinnPhong,
    blinn_phong_normalized_approx,
    n_dot_h
);

/// Diffuse plus normalized Phong, kd / pi + ks (n + 2) / (2 pi) (r.l)^n ([`diffuse_specular`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhongDiffuseSpecular<T> {
    kd: T,
    ks: T,
    exponent: T,
}

impl<T: Real> PhongDiffuseSpecular<T> {
    /// A lobe with kd and ks in [0, 1], kd + ks <= 1 + `T::EPSILON` and the exponent finite
    /// and non-negative, in every lane; else [`ParamError`] naming `"kd"`, `"ks"`,
    /// `"kd + ks"` or `"exponent"`.
    pub fn new(kd: T, ks: T, exponent: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(kd), "kd", "in [0, 1]")?;
        validate(ks, exponent)?;
        require::<T>(sum_ok(kd, ks), "kd + ks", "<= 1")?;
        Ok(Self { kd, ks, exponent })
    }

    /// The diffuse albedo kd.
    #[inline]
    #[must_use]
    pub fn kd(&self) -> T {
        self.kd
    }

    /// The specular coefficient ks.
    #[inline]
    #[must_use]
    pub fn ks(&self) -> T {
        self.ks
    }

    /// The exponent n.
    #[inline]
    #[must_use]
    pub fn exponent(&self) -> T {
        self.exponent
    }

    /// f(wo, wi) by [`diffuse_specular`], on local-frame unit vectors (normal = +z) pointing
    /// away from the surface; 0 at or below the horizon.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        let f = diffuse_specular(wo.z, wi.z, r_dot_l(wo, wi), self.kd, self.ks, self.exponent);
        finite_dirs(wo, wi, f)
    }
}
