//! The [`Microfacet`] trait: the verbs every microfacet distribution offers (after pbrt-v4's
//! `TrowbridgeReitzDistribution`): D, Lambda, G1, the two G2 forms, the visibility V and the
//! distribution of visible normals, all on local-frame vectors (normal = +z).
//!
//! Implemented by `ggx::Ggx` and `beckmann::Beckmann` (each behind its feature). The provided
//! methods are written once here from `d`, `lambda` and `cos_lambda`, so both models share one
//! height-correlated G2 and one guarded visibility.
//!
//! # Roughness conventions
//! Every `alpha` parameter in this crate is the distribution's width alpha (Walter et al. 2007's
//! alpha_g for GGX, the RMS slope for Beckmann), never the artist's perceptual roughness:
//!
//! | quantity | relation | names elsewhere |
//! |---|---|---|
//! | perceptual roughness r | the slider, in [0, 1] | glTF 2.0 `roughnessFactor`; Unreal Engine 4 material `Roughness`; Filament `perceptualRoughness`; Disney's `roughness` |
//! | alpha | r^2 ([`alpha_from_perceptual`]) | this crate's `alpha`; Filament's shader argument `roughness` (`D_GGX`, `V_SmithGGXCorrelated`); pbrt-v4's `alpha_x`, `alpha_y` |
//! | alpha^2 | r^4 | Unreal Engine 4's `a2` (`D_GGX(a2, NoH)`, `Vis_SmithJoint(a2, NoV, NoL)` in `BRDF.ush`); pbrt-v4's material `roughness` when `remaproughness` is on (its `RoughnessToAlpha` takes the square root) |
//!
//! So a shader's `roughness` may be either of the first two rows: Filament's shading code receives
//! alpha (it squares the material's perceptual roughness beforehand), while others (LearnOpenGL's
//! `DistributionGGX`, Unreal Engine 4 before its `a2` form) take the perceptual value and square it
//! inside the function. Read the function body, not the argument's name. Convert a perceptual value
//! with [`alpha_from_perceptual`] (and back with [`perceptual_from_alpha`]); pass alpha * alpha
//! where an engine's formula wants `a2`. The mapping r -> r^2 is Burley 2012 ("Physically-Based
//! Shading at Disney") and Karis 2013 ("Real Shading in Unreal Engine 4").
//! `cargo run --release --example shader_port` ports Filament's and Unreal Engine 4's GGX to
//! this crate and checks the conventions numerically.

use crate::domain::{nan_unless, nan_where};
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

/// The smallest alpha the kernels evaluate with; smaller (including 0) is clamped up to it. As a
/// perceptual roughness ([`alpha_from_perceptual`]): r = 0.01. Filament clamps higher, at r = 0.045
/// (alpha 0.002025) on desktop and r = 0.089 on mobile: to reproduce its values, clamp r first.
///
/// Why 1e-4: the GGX peak D = 1 / (pi alpha^2) is then 3.2e7 and Beckmann's 1 / (pi alpha^2)
/// likewise, and D V F stays below 1e15, far inside f32's range (3.4e38);
/// alpha^2 = 1e-8 is a normal f32. The lobe is then 1e-4 rad wide: narrower than a pixel's
/// footprint in any renderer, so the clamp changes no image, and its directional albedo is
/// that of a mirror.
pub const ALPHA_MIN: f64 = 1e-4;

/// The largest alpha the kernels evaluate with; larger finite values are clamped down to it. As a
/// perceptual roughness ([`alpha_from_perceptual`]): r = 100.
///
/// Why 1e4 (the mirror image of [`ALPHA_MIN`]): every intermediate of every kernel stays a
/// normal f32 up to it. The GGX D of a unit normal m has the denominator
/// pi alpha_x alpha_y (x^2/alpha_x^2 + y^2/alpha_y^2 + z^2)^2 >= pi / alpha^2, which
/// underflows f32 near alpha = 1e10 (where D turned into inf and NaN); alpha^4 = 1e16, the
/// square of the peak denominator alpha^2 cos^2, overflows f32 only above 4e9; and the
/// stretched view direction of the visible-normal samplers, (alpha x, alpha y, z), has a
/// length^2 that overflows at 1.8e19. Physically alpha = 1e4 is an RMS slope of 89.994
/// degrees: the surface is already at the alpha -> inf limit (every normal at the horizon),
/// so the clamp changes no value a renderer can see.
pub const ALPHA_MAX: f64 = 1e4;

/// A microfacet normal distribution with its Smith masking function.
///
/// Directions are unit vectors in the local shading frame. Method names follow the terms of
/// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs"
/// (JCGT 3(2)), whose equations the provided methods implement. The roughness lives in the
/// implementing type, given to its constructor as alpha, the width (not perceptual roughness:
/// see the [roughness conventions](crate::microfacet#roughness-conventions) and
/// [`alpha_from_perceptual`]).
///
/// Bad input (crate docs, "Bad input"): a NaN or infinite component of any direction gives NaN
/// in every method; a zero-length direction has cosine 0 and takes the horizon's values
/// (G1 = 0, Lambda capped at MAX, D_wo = 0), never the 0 / 0 of its components.
pub trait Microfacet<T: Real> {
    /// NDF D(m); 0 for m.z <= 0. Normalized: integral of D(m) m.z dm = 1. Domain: m a unit
    /// vector; a NaN or infinite component gives NaN.
    fn d(&self, m: V3<T>) -> T;

    /// Smith Lambda(w) >= 0, a function of |w.z| (symmetric under w -> -w); its pole at the
    /// horizon (w.z = 0) is capped at the largest finite value; 0 at the normal. NaN in any
    /// component gives NaN.
    fn lambda(&self, w: V3<T>) -> T;

    /// |w.z| Lambda(w), computed so that it stays finite at the horizon (where Lambda has its
    /// pole and |w.z| = 0): the visibility term needs this product, not Lambda itself. NaN in
    /// any component gives NaN.
    fn cos_lambda(&self, w: V3<T>) -> T;

    /// Smith masking G1(w) = 1 / (1 + Lambda(w)) (Heitz 2014, eq. 43): 1 at the normal, 0 at
    /// the horizon (where Lambda is capped at MAX); NaN for NaN input. Within
    /// 1 ULP of 1 / (1 + Lambda) computed exactly from the model's Lambda.
    #[inline]
    #[must_use]
    fn g1(&self, w: V3<T>) -> T {
        let l = self.lambda(w);
        // At the capped pole 1 / (1 + MAX) would be a subnormal, not the limit 0.
        T::select(l.simd_eq(T::MAX), T::ZERO, (T::ONE + l).recip())
    }

    /// Height-correlated masking-shadowing G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014,
    /// eq. 99). 0 when either direction is at the horizon; NaN for NaN input.
    #[inline]
    #[must_use]
    fn g2_correlated(&self, wo: V3<T>, wi: V3<T>) -> T {
        // Each Lambda is capped at MAX; the sum may still overflow to inf, whose reciprocal is
        // the right limit 0.
        (T::ONE + self.lambda(wo) + self.lambda(wi)).recip()
    }

    /// Separable masking-shadowing G2 = G1(wo) G1(wi) (Heitz 2014, eq. 98). Never above the
    /// correlated form, since (1 + Lo)(1 + Li) = 1 + Lo + Li + Lo Li: it counts the shadowing
    /// of points already masked twice, so a BRDF using it is slightly darker.
    #[inline]
    #[must_use]
    fn g2_separable(&self, wo: V3<T>, wi: V3<T>) -> T {
        self.g1(wo) * self.g1(wi)
    }

    /// Visibility V = G2 / (4 |wo.z| |wi.z|) with the height-correlated G2, evaluated as
    /// 1 / (4 (|o.z| |i.z| + |i.z| |o.z| Lambda(o) + |o.z| |i.z| Lambda(i))), i.e. through
    /// [`Microfacet::cos_lambda`], so no 0 x inf or 0 / 0 occurs.
    ///
    /// Domain: unit vectors. Edges: finite whenever one of the cosines is non-zero; 0 when both
    /// are 0 (the limit along any path is unbounded, and the BRDF is then multiplied by a zero
    /// cosine anyway); capped at the largest finite value instead of overflowing to inf. NaN
    /// in any component of either vector gives NaN.
    #[inline]
    #[must_use]
    fn v_correlated(&self, wo: V3<T>, wi: V3<T>) -> T {
        let (co, ci) = (wo.z.abs(), wi.z.abs());
        let den = co * ci + ci * self.cos_lambda(wo) + co * self.cos_lambda(wi);
        let den4 = T::splat(4.0) * den;
        let v = T::select(den4.simd_gt(T::ZERO), den4.recip().min(T::MAX), T::ZERO);
        nan_where(any_nonfinite3(wo) | any_nonfinite3(wi) | den.is_nan(), v)
    }

    /// Distribution of visible normals D_wo(m) = G1(wo) max(0, wo.m) D(m) / |wo.z| (Heitz
    /// 2014, eq. 38). It integrates to 1 over m for every wo with wo.z != 0; 0 when wo.z = 0;
    /// capped at the largest finite value; NaN for a NaN or infinite component of either vector.
    #[inline]
    #[must_use]
    fn d_visible(&self, wo: V3<T>, m: V3<T>) -> T {
        let c = wo.z.abs();
        // G1 / |wo.z| = 1 / (|wo.z| + |wo.z| Lambda): finite at the horizon.
        let cl = self.cos_lambda(wo);
        let g1_over_cos = (c + cl).recip();
        let v = T::select(c.simd_gt(T::ZERO), g1_over_cos, T::ZERO);
        // Each factor is finite; the product of a large 1 / |wo.z| and a large D may not be.
        let value = (v * wo.dot(m).max(T::ZERO)).min(T::MAX) * self.d(m);
        nan_where(any_nonfinite3(wo) | cl.is_nan(), value.min(T::MAX))
    }
}

/// The constructor check shared by every distribution: both alphas finite and >= 0 in every
/// lane (comparisons are false for NaN, so NaN is rejected too).
#[cfg_attr(not(any(feature = "ggx", feature = "beckmann")), allow(dead_code))]
pub(crate) fn validate_alphas<T: Real>(alpha_x: T, alpha_y: T) -> Result<(), ParamError> {
    const DOMAIN: &str = "finite and >= 0";
    require::<T>(
        alpha_x.simd_ge(T::ZERO) & alpha_x.is_finite(),
        "alpha_x",
        DOMAIN,
    )?;
    require::<T>(
        alpha_y.simd_ge(T::ZERO) & alpha_y.is_finite(),
        "alpha_y",
        DOMAIN,
    )
}

/// True where alpha is in the documented domain [0, +inf) (false for NaN, negatives, +inf).
#[inline]
pub(crate) fn alpha_ok<T: Real>(alpha: T) -> T::Mask {
    alpha.simd_ge(T::ZERO) & alpha.simd_lt(T::INFINITY)
}

/// sin^2 = 1 - c^2 from a cosine c in [0, 1] in working precision, for the `_fast` kernels:
/// one fused multiply-add (a single rounding, so within 0.5 ULP for every c) where the target
/// fuses them (x86 with `fma`, aarch64 with NEON, as `Real::mul_add`), otherwise 1 - c c below
/// c = 1/2 (nothing cancels) and (1 - c)(1 + c) above (1 - c exact there), within 1 ULP.
#[cfg(feature = "ggx")]
#[inline]
pub(crate) fn sin2_working<T: Real>(c: T) -> T {
    #[cfg(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    ))]
    {
        (-c).mul_add(c, T::ONE)
    }
    #[cfg(not(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    )))]
    {
        T::select(
            c.simd_lt(T::HALF),
            (-c).mul_add(c, T::ONE),
            (T::ONE - c) * (T::ONE + c),
        )
    }
}

/// alpha clamped to [`ALPHA_MIN`], [`ALPHA_MAX`]; NaN for alpha < 0, NaN or +inf (a parameter
/// outside its domain is never replaced by another parameter's value).
#[inline]
pub(crate) fn clamp_alpha<T: Real>(alpha: T) -> T {
    nan_unless(
        alpha_ok(alpha),
        alpha.clamp(T::splat(ALPHA_MIN), T::splat(ALPHA_MAX)),
    )
}

/// The microfacet roughness alpha (the NDF's width: GGX's alpha, Beckmann's RMS slope) as its
/// own type, so that a perceptual roughness cannot be passed where alpha is meant: the full
/// Cook-Torrance BRDFs (`cook_torrance::ggx`, `ggx_schlick_rgb`, ...) take `Alpha<T>`, while
/// the material entry points take the perceptual roughness (glTF's `roughnessFactor`) as a
/// plain value. Build it from alpha itself, `Alpha(a)`, or from a perceptual roughness,
/// [`Alpha::from_perceptual`] (alpha = r^2, floored at [`ALPHA_MIN`]).
///
/// A named wrapper, not a validated parameter: the kernel it reaches keeps the crate's rule
/// (alpha < 0, +inf or NaN give NaN; alpha is clamped to [[`ALPHA_MIN`], [`ALPHA_MAX`]]).
///
/// ```
/// # #[cfg(all(feature = "cook-torrance", feature = "ggx"))] {
/// use brdf::microfacet::Alpha;
/// use brdf::{Cosines, cook_torrance};
/// let c = Cosines { n_dot_v: 0.8_f64, n_dot_l: 0.7, n_dot_h: 0.95, v_dot_h: 0.9 };
/// let a = cook_torrance::ggx(c, Alpha::from_perceptual(0.5), 1.0);
/// assert_eq!(a, cook_torrance::ggx(c, Alpha(0.25), 1.0));
/// # }
/// ```
///
/// ```compile_fail
/// use brdf::{Cosines, cook_torrance};
/// let c = Cosines { n_dot_v: 0.8_f64, n_dot_l: 0.7, n_dot_h: 0.95, v_dot_h: 0.9 };
/// let roughness = 0.5;
/// let f = cook_torrance::ggx(c, roughness, 1.0); // a bare float is not an alpha
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Alpha<T>(pub T);

impl<T: Real> Alpha<T> {
    /// alpha = roughness^2 from a perceptual roughness ([`alpha_from_perceptual`], floored at
    /// [`ALPHA_MIN`]; NaN for a negative, infinite or NaN roughness).
    #[inline]
    #[must_use]
    pub fn from_perceptual(roughness: T) -> Self {
        Self(alpha_from_perceptual(roughness))
    }
}

/// Perceptual roughness r to alpha = r^2, clamped to [[`ALPHA_MIN`], [`ALPHA_MAX`]] (so r below
/// 0.01 gives ALPHA_MIN). The square makes a linear roughness slider perceptually even (Burley
/// 2012, "Physically-Based Shading at Disney"; Karis 2013, "Real Shading in Unreal Engine 4").
/// Domain: r in [0, +inf) finite (r > 1 passes through squared, up to the clamp); r < 0, NaN or
/// +inf gives NaN. Exact: one rounding of r^2.
///
/// r is glTF's `roughnessFactor`, Unreal Engine 4's material `Roughness` and Filament's
/// `perceptualRoughness`; the result is what every `alpha` parameter of the crate takes, and what
/// Filament's shader functions call `roughness` (see the
/// [roughness conventions](crate::microfacet#roughness-conventions)).
///
/// ```
/// use brdf::microfacet::{ALPHA_MIN, alpha_from_perceptual, perceptual_from_alpha};
/// let alpha = alpha_from_perceptual(0.5_f64); // a glTF roughnessFactor of 0.5
/// assert_eq!(alpha, 0.25); // for ggx::d(n_dot_h, alpha), Filament's D_GGX(roughness, ..)
/// assert_eq!(alpha * alpha, 0.0625); // for Unreal Engine 4's D_GGX(a2, NoH)
/// assert_eq!(perceptual_from_alpha(alpha), 0.5);
/// assert_eq!(alpha_from_perceptual(0.001_f64), ALPHA_MIN); // r below 0.01: the floor
/// ```
#[inline]
#[must_use]
pub fn alpha_from_perceptual<T: Real>(roughness: T) -> T {
    // r = 100 = sqrt(ALPHA_MAX) already gives the largest alpha; clamping r first keeps r^2
    // finite for every finite r.
    let r = roughness.min(T::splat(100.0));
    nan_unless(alpha_ok(roughness), clamp_alpha(r * r))
}

/// alpha to perceptual roughness r = sqrt(alpha) (the inverse of [`alpha_from_perceptual`] between
/// the clamps): the value a glTF `roughnessFactor` or a UE4 `Roughness` slider holds for a given
/// alpha. Domain alpha in [0, +inf) finite; alpha < 0, +inf or NaN gives NaN (crate docs,
/// "Bad input", rule 5). Correctly rounded (one square root).
#[inline]
#[must_use]
pub fn perceptual_from_alpha<T: Real>(alpha: T) -> T {
    nan_unless(alpha_ok(alpha), alpha.sqrt())
}
