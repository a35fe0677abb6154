//! The [`Microfacet`] trait: the verbs every microfacet distribution offers (after pbrt-v4's
//! `TrowbridgeReitzDistribution`): D, Lambda, G1, the two G2 forms, the visibility V and the
//! distribution of visible normals, all on local-frame vectors (normal = +z).
//!
//! Implemented by `ggx::Ggx` and `beckmann::Beckmann` (each behind its feature). The provided methods
//! are written once here from `d`, `lambda` and `cos_lambda`, so both models share one
//! height-correlated G2 and one guarded visibility.

use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

/// The smallest alpha the kernels evaluate with; smaller (including 0) is clamped up to it.
///
/// Why 1e-4: the GGX peak D = 1 / (pi alpha^2) is then 3.2e7 and Beckmann's 1 / (pi alpha^2)
/// likewise, and D V F stays below 1e15, far inside f32's range (3.4e38) and f16-free paths;
/// alpha^2 = 1e-8 is a normal f32. The lobe is then 1e-4 rad wide: narrower than a pixel's
/// footprint in any renderer, so the clamp changes no image, and its directional albedo is
/// that of a mirror (the energy is right, as `tests/stability_microfacet.rs` checks).
pub const ALPHA_MIN: f64 = 1e-4;

/// A microfacet normal distribution with its Smith masking function.
///
/// Directions are unit vectors in the local shading frame. Method names follow the terms of
/// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs"
/// (JCGT 3(2)), whose equations the provided methods implement.
pub trait Microfacet<T: Real> {
    /// NDF D(m); 0 for m.z <= 0. Normalized: integral of D(m) m.z dm = 1.
    fn d(&self, m: V3<T>) -> T;

    /// Smith Lambda(w) >= 0, a function of |w.z| (symmetric under w -> -w); +inf at the
    /// horizon (w.z = 0), 0 at the normal.
    fn lambda(&self, w: V3<T>) -> T;

    /// |w.z| Lambda(w), computed so that it stays finite at the horizon (where Lambda = inf
    /// and |w.z| = 0): the visibility term needs this product, not Lambda itself.
    fn cos_lambda(&self, w: V3<T>) -> T;

    /// Smith masking G1(w) = 1 / (1 + Lambda(w)) (Heitz 2014, eq. 43): 1 at the normal, 0 at
    /// the horizon.
    #[inline]
    #[must_use]
    fn g1(&self, w: V3<T>) -> T {
        (T::ONE + self.lambda(w)).recip()
    }

    /// Height-correlated masking-shadowing G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014,
    /// eq. 99). 0 when either direction is at the horizon.
    #[inline]
    #[must_use]
    fn g2_correlated(&self, wo: V3<T>, wi: V3<T>) -> T {
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
    /// cosine anyway); capped at the largest finite value instead of overflowing to inf.
    #[inline]
    #[must_use]
    fn v_correlated(&self, wo: V3<T>, wi: V3<T>) -> T {
        let (co, ci) = (wo.z.abs(), wi.z.abs());
        let den = co * ci + ci * self.cos_lambda(wo) + co * self.cos_lambda(wi);
        let den4 = T::splat(4.0) * den;
        T::select(den4.simd_gt(T::ZERO), den4.recip().min(T::MAX), T::ZERO)
    }

    /// Distribution of visible normals D_wo(m) = G1(wo) max(0, wo.m) D(m) / |wo.z| (Heitz
    /// 2014, eq. 38). It integrates to 1 over m for every wo with wo.z != 0; 0 when wo.z = 0.
    #[inline]
    #[must_use]
    fn d_visible(&self, wo: V3<T>, m: V3<T>) -> T {
        let c = wo.z.abs();
        // G1 / |wo.z| = 1 / (|wo.z| + |wo.z| Lambda): finite at the horizon.
        let g1_over_cos = (c + self.cos_lambda(wo)).recip();
        let v = T::select(c.simd_gt(T::ZERO), g1_over_cos, T::ZERO);
        v * wo.dot(m).max(T::ZERO) * self.d(m)
    }
}

/// The constructor check shared by every distribution: both alphas finite and >= 0 in every
/// lane (comparisons are false for NaN, so NaN is rejected too).
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

/// `max(alpha, ALPHA_MIN)`; NaN propagates.
#[inline]
pub(crate) fn floor_alpha<T: Real>(alpha: T) -> T {
    alpha.max(T::splat(ALPHA_MIN))
}

/// Perceptual roughness r in [0, 1] to alpha = r^2, with alpha floored at [`ALPHA_MIN`] (so
/// r below 0.01 gives the floor). The square makes a linear roughness slider perceptually
/// even (Burley 2012, "Physically-Based Shading at Disney"; Karis 2013, "Real Shading in
/// Unreal Engine 4"). r > 1 passes through squared; NaN propagates.
#[inline]
#[must_use]
pub fn alpha_from_perceptual<T: Real>(roughness: T) -> T {
    floor_alpha(roughness * roughness)
}

/// alpha to perceptual roughness r = sqrt(alpha) (the inverse of [`alpha_from_perceptual`] above
/// the floor). Domain alpha >= 0; negative gives 0.
#[inline]
#[must_use]
pub fn perceptual_from_alpha<T: Real>(alpha: T) -> T {
    alpha.sqrt_nonneg()
}
