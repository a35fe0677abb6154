//! The crate's rule for bad input, as two guards every kernel can share.
//!
//! - A NaN in any input gives NaN out, never a plausible finite value.
//! - A parameter outside its documented domain, reaching a function that does not validate it,
//!   gives NaN.
//! - A finite direction below the horizon gives 0 (reflection only).
//!
//! The crate docs ("Bad input") state the rule for users; these helpers are how kernels keep it.
//! Each feature uses a subset, so unused ones are allowed (`lib.rs`).

use crate::real::Real;

/// `value` where `ok` holds, NaN elsewhere.
///
/// Build `ok` from comparisons (`simd_ge`, `simd_le`, ...), which are false for NaN, so a NaN
/// parameter fails the check without a separate test.
#[inline]
#[must_use]
pub(crate) fn nan_unless<T: Real>(ok: T::Mask, value: T) -> T {
    T::select(ok, value, T::splat(f64::NAN))
}

/// `value` where both cosines are > 0; NaN where either is NaN; 0 elsewhere (a direction at or
/// below the horizon reflects nothing).
///
/// Without the NaN case a guard written `select(c > 0, value, 0)` turns a NaN cosine into a
/// plausible 0.
#[inline]
#[must_use]
pub(crate) fn above_horizon<T: Real>(n_dot_v: T, n_dot_l: T, value: T) -> T {
    let above = n_dot_v.simd_gt(T::ZERO) & n_dot_l.simd_gt(T::ZERO);
    let nan = n_dot_v.is_nan() | n_dot_l.is_nan();
    T::select(above, value, T::select(nan, T::splat(f64::NAN), T::ZERO))
}

/// True where `x` lies in [0, 1] (false for NaN): the domain of every albedo, reflectance,
/// Fresnel value, metallic weight and unit roughness in the crate.
#[inline]
#[must_use]
pub(crate) fn in_unit<T: Real>(x: T) -> T::Mask {
    x.simd_ge(T::ZERO) & x.simd_le(T::ONE)
}

/// `x` where it lies in [0, 1], NaN elsewhere (and for NaN).
#[inline]
#[must_use]
pub(crate) fn checked_unit<T: Real>(x: T) -> T {
    nan_unless(in_unit(x), x)
}

/// `value` where `c > 0`; NaN where `c` is NaN; 0 elsewhere: the one-cosine form of
/// [`above_horizon`] (an NDF of n.h, a Schlick factor of v.h).
#[inline]
#[must_use]
pub(crate) fn above<T: Real>(c: T, value: T) -> T {
    T::select(
        c.simd_gt(T::ZERO),
        value,
        T::select(c.is_nan(), T::splat(f64::NAN), T::ZERO),
    )
}

/// NaN where `bad` holds, `value` elsewhere (the complement of [`nan_unless`], for masks built
/// from `is_nan`).
#[inline]
#[must_use]
pub(crate) fn nan_where<T: Real>(bad: T::Mask, value: T) -> T {
    T::select(bad, T::splat(f64::NAN), value)
}

/// `value` where `x` is finite; NaN where `x` is infinite or NaN. Rule 5 of the crate docs:
/// every documented domain ends at the largest finite float, so an infinite direction
/// component, parameter, colour, angle or distance is out of every domain (a clamped cosine
/// or sample is clamped instead, before any arithmetic could turn its infinity into NaN).
#[inline]
#[must_use]
pub(crate) fn nan_unless_finite<T: Real>(x: T, value: T) -> T {
    nan_unless(x.is_finite(), value)
}

/// `x` where it is finite, NaN elsewhere (the one-input form of [`nan_unless_finite`]).
#[inline]
#[must_use]
pub(crate) fn finite_or_nan<T: Real>(x: T) -> T {
    nan_unless_finite(x, x)
}

/// `value`, or NaN where a component of `wo` or `wi` is NaN or infinite: the guard of every
/// kernel that takes two directions, whatever components it reads (rules 1 and 5).
#[inline]
#[must_use]
pub(crate) fn finite_dirs<T: Real>(wo: crate::vec3::V3<T>, wi: crate::vec3::V3<T>, value: T) -> T {
    use crate::vec3::any_nonfinite3;
    nan_where(any_nonfinite3(wo) | any_nonfinite3(wi), value)
}

/// A clamped input (a cosine, a uniform sample) with +inf replaced by 1 and -inf by -1, so that
/// a kernel gives at an infinity bit for bit its value at +-1 (rules 3 and 5). Finite values
/// and NaN pass unchanged: one compare and one select, and no finite result moves. Apply it
/// before any arithmetic that would turn the infinity into NaN (inf - inf, 0 * inf, inf / inf).
#[inline]
#[must_use]
pub(crate) fn unit_if_inf<T: Real>(c: T) -> T {
    T::select(c.abs().simd_eq(T::INFINITY), T::ONE.copysign(c), c)
}
