//! GGX / Trowbridge-Reitz: the NDF, its exact Smith Lambda, the height-correlated visibility,
//! and the real-time approximations of Smith G that engines ship, each with its measured error.
//!
//! Sources: Trowbridge and Reitz 1975, "Average irregularity representation of a rough surface
//! for ray reflection"; Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction
//! through Rough Surfaces" (EGSR); Heitz 2014, "Understanding the Masking-Shadowing Function in
//! Microfacet-Based BRDFs" (JCGT 3(2)).
//!
//! Two entry points for every term: free functions of dot products (`d(n_dot_h, alpha)`), and
//! the [`Ggx`] type implementing [`Microfacet`] on local-frame vectors (isotropic and
//! anisotropic). Cosines passed to the free functions are clamped to [0, 1] (a cosine just
//! above 1 from an unnormalized input becomes 1; a negative one, from a back-facing direction,
//! becomes 0). alpha is floored at [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN).
//!
//! Precision near the pole: every form here uses sin^2 = (1 - c)(1 + c) (exact 1 - c for
//! c >= 1/2) or, on vectors, x^2 + y^2, never 1 - c^2; and D's denominator is
//! sin^2 + cos^2 alpha^2, a sum of non-negative terms, not 1 + c^2 (alpha^2 - 1), whose
//! rewrite (1 - c^2) + c^2 alpha^2 by GPU compilers cancels for c near 1.
//!
//! f32 against f64 on the same inputs (`cargo test --test stability -- --nocapture`): `d`
//! within 5 ulps (it squares the error of its denominator), `lambda` 4, `g1` and
//! `v_correlated` 2, over alpha in [2e-4, 1] and cosines down to 1e-7 and up to the last
//! 64 floats below 1.

use crate::error::ParamError;
use crate::microfacet::{Microfacet, floor_alpha, validate_alphas};
use crate::real::Real;
use crate::vec3::V3;

/// `(1 - c)(1 + c)` for c in [0, 1]: sin^2 without the cancellation of `1 - c*c`.
#[inline]
fn sin2_from_cos<T: Real>(c: T) -> T {
    (T::ONE - c) * (T::ONE + c)
}

/// The GGX (Trowbridge-Reitz) distribution with roughness alpha_x along the local x axis and
/// alpha_y along y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ggx<T> {
    /// Roughness along the tangent (local x).
    pub alpha_x: T,
    /// Roughness along the bitangent (local y).
    pub alpha_y: T,
}

impl<T: Real> Ggx<T> {
    /// An anisotropic GGX. Both alphas must be finite and >= 0 in every lane, else
    /// [`ParamError`]; values below [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN) (including 0)
    /// are stored as given and clamped when evaluated.
    pub fn new(alpha_x: T, alpha_y: T) -> Result<Self, ParamError> {
        validate_alphas(alpha_x, alpha_y)?;
        Ok(Self { alpha_x, alpha_y })
    }

    /// An isotropic GGX, `alpha_x = alpha_y = alpha`; same validation as [`Ggx::new`].
    pub fn isotropic(alpha: T) -> Result<Self, ParamError> {
        Self::new(alpha, alpha)
    }

    /// `alpha_x^2 x^2 + alpha_y^2 y^2` = alpha^2 tan^2(theta) cos^2(theta) of `w`.
    #[inline]
    fn projected_roughness2(&self, w: V3<T>) -> T {
        let (ax, ay) = (floor_alpha(self.alpha_x), floor_alpha(self.alpha_y));
        (ax * w.x).mul_add(ax * w.x, (ay * w.y) * (ay * w.y))
    }
}

impl<T: Real> Microfacet<T> for Ggx<T> {
    /// D(m) = 1 / (pi ax ay (x^2/ax^2 + y^2/ay^2 + z^2)^2) for m.z > 0, else 0 (Walter et al.
    /// 2007 eq. 33 in the anisotropic form of Heitz 2014 eq. 85, without tan or cos^4).
    #[inline]
    fn d(&self, m: V3<T>) -> T {
        let (ax, ay) = (floor_alpha(self.alpha_x), floor_alpha(self.alpha_y));
        let (u, v) = (m.x / ax, m.y / ay);
        let t = u.mul_add(u, v.mul_add(v, m.z * m.z));
        let d = (T::PI * ax * ay * t * t).recip();
        T::select(m.z.simd_gt(T::ZERO), d, T::ZERO)
    }

    /// Lambda(w) = (sqrt(1 + alpha^2 tan^2) - 1) / 2 (Heitz 2014 eq. 86), evaluated as
    /// q / (2 |z| (sqrt(z^2 + q) + |z|)) with q = ax^2 x^2 + ay^2 y^2: no cancellation for
    /// small alpha tan, and +inf (q / 0) at the horizon.
    #[inline]
    fn lambda(&self, w: V3<T>) -> T {
        let c = w.z.abs();
        let q = self.projected_roughness2(w);
        q / (T::TWO * c * (c.mul_add(c, q).sqrt() + c))
    }

    /// |z| Lambda = q / (2 (sqrt(z^2 + q) + |z|)): alpha sin(theta) / 2 at the horizon.
    #[inline]
    fn cos_lambda(&self, w: V3<T>) -> T {
        let c = w.z.abs();
        let q = self.projected_roughness2(w);
        q / (T::TWO * (c.mul_add(c, q).sqrt() + c))
    }
}

/// Isotropic GGX NDF of the cosine between normal and half vector:
/// D = alpha^2 / (pi ((1 - c)(1 + c) + c^2 alpha^2)^2) for c = n_dot_h in (0, 1], 0 for
/// c <= 0 (Walter et al. 2007 eq. 33; the denominator is the cancellation-free rewrite of
/// (1 + c^2 (alpha^2 - 1))^2). Peak 1 / (pi alpha^2) at c = 1.
#[inline]
#[must_use]
pub fn d<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a = floor_alpha(alpha);
    let a2 = a * a;
    let c = n_dot_h.min(T::ONE);
    let t = sin2_from_cos(c) + c * c * a2;
    let d = a2 / (T::PI * t * t);
    T::select(n_dot_h.simd_gt(T::ZERO), d, T::ZERO)
}

/// Anisotropic GGX NDF from the half vector's components in the shading frame:
/// D = 1 / (pi ax ay ((t.h/ax)^2 + (b.h/ay)^2 + (n.h)^2)^2), 0 for n_dot_h <= 0 (Heitz 2014
/// eq. 85; Burley 2012). `t_dot_h`, `b_dot_h`: the half vector against tangent and bitangent.
#[inline]
#[must_use]
pub fn d_aniso<T: Real>(n_dot_h: T, t_dot_h: T, b_dot_h: T, alpha_x: T, alpha_y: T) -> T {
    Ggx { alpha_x, alpha_y }.d(V3::new(t_dot_h, b_dot_h, n_dot_h))
}

/// Smith Lambda of the isotropic GGX for a direction at cosine `n_dot_v`:
/// Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2, evaluated without cancellation as
/// q / (2 c (sqrt(c^2 + q) + c)), q = alpha^2 (1 - c)(1 + c) (Heitz 2014 eq. 86).
/// |n_dot_v| is used (Lambda is symmetric) and clamped to 1; +inf at c = 0.
#[inline]
#[must_use]
pub fn lambda<T: Real>(n_dot_v: T, alpha: T) -> T {
    let c = n_dot_v.abs().min(T::ONE);
    let a = floor_alpha(alpha);
    let q = a * a * sin2_from_cos(c);
    q / (T::TWO * c * (c.mul_add(c, q).sqrt() + c))
}

/// Smith masking G1 = 1 / (1 + Lambda) = 2c / (c + sqrt(c^2 + alpha^2 (1 - c^2))) of the
/// isotropic GGX (Walter et al. 2007 eq. 34). 1 at c = 1, 0 at c = 0; uses |n_dot_v|.
#[inline]
#[must_use]
pub fn g1<T: Real>(n_dot_v: T, alpha: T) -> T {
    let c = n_dot_v.abs().min(T::ONE);
    let a = floor_alpha(alpha);
    let q = a * a * sin2_from_cos(c);
    T::TWO * c / (c + c.mul_add(c, q).sqrt())
}

/// Height-correlated Smith visibility of the isotropic GGX,
/// V = G2 / (4 NoL NoV) = 0.5 / (NoL sqrt(NoV^2 + alpha^2 (1 - NoV^2)) + NoV sqrt(NoL^2 +
/// alpha^2 (1 - NoL^2))) (Heitz 2014 eq. 99 with eq. 86; the form of Lagarde and de Rousiers
/// 2014, "Moving Frostbite to PBR", with the cancellation-free 1 - c^2).
///
/// Cosines clamped to [0, 1]. Finite when either cosine is positive (at NoL = 0 it is
/// 0.5 / (NoV alpha)); 0 when both are 0; capped at the largest finite value.
#[inline]
#[must_use]
pub fn v_correlated<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let a = floor_alpha(alpha);
    let a2 = a * a;
    let gv = cl * (a2 * sin2_from_cos(cv)).mul_add(T::ONE, cv * cv).sqrt();
    let gl = cv * (a2 * sin2_from_cos(cl)).mul_add(T::ONE, cl * cl).sqrt();
    guarded_half_over(gv + gl)
}

/// `0.5 / den` for den > 0 (capped at MAX), 0 for den <= 0: the shared guard of every V form.
#[inline]
fn guarded_half_over<T: Real>(den: T) -> T {
    T::select(den.simd_gt(T::ZERO), (T::HALF / den).min(T::MAX), T::ZERO)
}

/// Hammon's fast approximation of the height-correlated visibility:
/// V = 0.5 / lerp(2 NoL NoV, NoL + NoV, alpha) (Hammon 2017, "PBR Diffuse Lighting for
/// GGX+Smith Microsurfaces", GDC). Approximation: max relative error 0.29 against
/// [`v_correlated`] for alpha and cosines in [0.01, 1], worst at alpha = 0.01 with both
/// cosines 0.01 (`cargo test --test smith_approximations -- --nocapture`). Cosines clamped to
/// [0, 1]; 0 when both are 0.
#[inline]
#[must_use]
pub fn v_correlated_hammon<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let a = floor_alpha(alpha);
    let two_lv = T::TWO * cl * cv;
    guarded_half_over(two_lv + a * (cl + cv - two_lv))
}

/// Filament's fast visibility: the square roots of [`v_correlated`] replaced by their linear
/// interpolation in alpha, V = 0.5 / (NoL (NoV (1 - alpha) + alpha) + NoV (NoL (1 - alpha) +
/// alpha)) (Google Filament, "Physically Based Rendering in Filament", section 4.4.2.1,
/// `V_SmithGGXCorrelated_Fast`). Expanded, its denominator is 2 NoL NoV (1 - alpha) +
/// alpha (NoL + NoV): algebraically identical to [`v_correlated_hammon`] (same 0.29 maximum
/// relative error), evaluated in a different order. Cosines clamped to [0, 1].
#[inline]
#[must_use]
pub fn v_correlated_fast<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let a = floor_alpha(alpha);
    let one_minus_a = T::ONE - a;
    guarded_half_over(cl * cv.mul_add(one_minus_a, a) + cv * cl.mul_add(one_minus_a, a))
}

/// Schlick's G1 approximation as used for GGX: G1 = c / (c (1 - k) + k) (Schlick 1994, "An
/// Inexpensive BRDF Model for Physically-based Rendering"; Karis 2013). Choose k with
/// [`schlick_k_ibl`] or [`schlick_k_analytic`]. Domain k in (0, 1]; cosine clamped to [0, 1];
/// 0 at c = 0, 1 at c = 1. With k = alpha / 2 its max abs error against [`g1`] is 0.16
/// (alpha = 0.01, NoV = 0.01; alpha and NoV in [0.01, 1]).
#[inline]
#[must_use]
pub fn g1_schlick<T: Real>(n_dot_v: T, k: T) -> T {
    let c = n_dot_v.saturate();
    let den = c.mul_add(T::ONE - k, k);
    T::select(den.simd_gt(T::ZERO), c / den, T::ZERO)
}

/// k = alpha / 2: Schlick-GGX matched to Smith-GGX (Karis 2013, "Real Shading in Unreal
/// Engine 4", used for image-based lighting).
#[inline]
#[must_use]
pub fn schlick_k_ibl<T: Real>(alpha: T) -> T {
    floor_alpha(alpha) * T::HALF
}

/// k = (r + 1)^2 / 8 from perceptual roughness r: Karis 2013's remapping for analytic lights
/// ("Real Shading in Unreal Engine 4"; it reduces the hotness of rough surfaces at grazing
/// angles, and is not an approximation of Smith-GGX).
#[inline]
#[must_use]
pub fn schlick_k_analytic<T: Real>(perceptual_roughness: T) -> T {
    let r1 = perceptual_roughness + T::ONE;
    r1 * r1 * T::splat(0.125)
}

/// Separable Schlick-GGX visibility V = G1(v) G1(l) / (4 NoV NoL)
/// = 1 / (4 (NoV (1 - k) + k)(NoL (1 - k) + k)): the NoV NoL cancel analytically, so it never
/// divides by zero for k > 0. Cosines clamped to [0, 1]. With k = alpha / 2 it is up to 0.97
/// below [`v_correlated`] (relative; alpha = 1, both cosines 0.01), like every separable G2.
#[inline]
#[must_use]
pub fn v_schlick<T: Real>(n_dot_v: T, n_dot_l: T, k: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let one_minus_k = T::ONE - k;
    let den = T::splat(4.0) * cv.mul_add(one_minus_k, k) * cl.mul_add(one_minus_k, k);
    T::select(den.simd_gt(T::ZERO), den.recip().min(T::MAX), T::ZERO)
}
