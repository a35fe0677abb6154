//! Beckmann: the NDF, its exact Smith Lambda (with erf), Walter et al.'s rational
//! approximation of it, and the Blinn-Phong exponent conversion.
//!
//! Sources: Beckmann and Spizzichino 1963, "The Scattering of Electromagnetic Waves from Rough
//! Surfaces"; Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through
//! Rough Surfaces" (EGSR), eqs. 25-27; Heitz 2014, "Understanding the Masking-Shadowing Function
//! in Microfacet-Based BRDFs" (JCGT 3(2)), eqs. 80-83.
//!
//! Same conventions as the `ggx` module: free functions of dot products with cosines clamped to
//! [0, 1], the [`Beckmann`] type on local-frame vectors, alpha floored at
//! [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN), sin^2 as (1 - c)(1 + c) or x^2 + y^2.
//!
//! f32 against f64 on the same inputs (`cargo test --test stability -- --nocapture`): `g1`
//! within 4 ulps; `d` within 4 + 3 E ulps (E = tan^2 / alpha^2, the exponent: exp turns the
//! rounding of E into a relative error E times larger) while exp(-E) is a normal f32
//! (E < 87); `lambda` within 16 + 4 a^4 ulps (a = 1 / (alpha tan), the same conditioning
//! plus the cancellation of its two terms, which agree to 1 / (4 a^2)). Lambda's error is
//! large only where Lambda < 1e-7, which G1 = 1 / (1 + Lambda) does not see.

use crate::error::ParamError;
use crate::microfacet::{Microfacet, floor_alpha, validate_alphas};
use crate::real::Real;
use crate::vec3::V3;

/// 1 / sqrt(pi).
const FRAC_1_SQRT_PI: f64 = 0.564_189_583_547_756_3;

/// The Beckmann distribution with roughness alpha_x along local x and alpha_y along y (alpha is
/// the RMS slope).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Beckmann<T> {
    /// RMS slope along the tangent (local x).
    pub alpha_x: T,
    /// RMS slope along the bitangent (local y).
    pub alpha_y: T,
}

impl<T: Real> Beckmann<T> {
    /// An anisotropic Beckmann. Both alphas must be finite and >= 0 in every lane, else
    /// [`ParamError`]; values below the floor are clamped when evaluated.
    pub fn new(alpha_x: T, alpha_y: T) -> Result<Self, ParamError> {
        validate_alphas(alpha_x, alpha_y)?;
        Ok(Self { alpha_x, alpha_y })
    }

    /// An isotropic Beckmann; same validation as [`Beckmann::new`].
    pub fn isotropic(alpha: T) -> Result<Self, ParamError> {
        Self::new(alpha, alpha)
    }

    /// sqrt(ax^2 x^2 + ay^2 y^2) = alpha(phi) sin(theta) of `w`.
    #[inline]
    fn projected_roughness(&self, w: V3<T>) -> T {
        let (ax, ay) = (floor_alpha(self.alpha_x), floor_alpha(self.alpha_y));
        (ax * w.x).mul_add(ax * w.x, (ay * w.y) * (ay * w.y)).sqrt()
    }
}

/// Lambda of the Beckmann distribution from a = 1 / (alpha tan(theta)) (Walter et al. 2007
/// eq. 27 rewritten): Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, with erfc instead of
/// erf - 1 so large a does not cancel to the rounding error of erf near 1.
#[inline]
fn lambda_of_a<T: Real>(a: T) -> T {
    let l = T::HALF * ((-a * a).exp() * T::splat(FRAC_1_SQRT_PI) / a - a.erfc());
    // Past a ~ 4 the two terms agree to every digit and their difference rounds to a few ulps
    // of 1e-9 or less, of either sign; Lambda is >= 0, and G1 = 1 / (1 + Lambda) is 1 there.
    l.max(T::ZERO)
}

impl<T: Real> Microfacet<T> for Beckmann<T> {
    /// D(m) = exp(-(x^2/ax^2 + y^2/ay^2) / z^2) / (pi ax ay z^4) for m.z > 0, else 0 (Walter
    /// et al. 2007 eq. 25, anisotropic as Heitz 2014 eq. 80). The exponent is
    /// tan^2(theta) / alpha^2, not the h.h some course notes print.
    #[inline]
    fn d(&self, m: V3<T>) -> T {
        let (ax, ay) = (floor_alpha(self.alpha_x), floor_alpha(self.alpha_y));
        let (u, v) = (m.x / ax, m.y / ay);
        let z2 = m.z * m.z;
        let e = u.mul_add(u, v * v) / z2;
        // z^4 underflows only for z < 1e-10 (f32), where exp(-e) is already exactly 0 for any
        // unit m; the max turns 0 / 0 into 0 / MIN_POSITIVE = 0.
        let den = (T::PI * ax * ay * z2 * z2).max(T::MIN_POSITIVE);
        T::select(m.z.simd_gt(T::ZERO), (-e).exp() / den, T::ZERO)
    }

    /// Exact Lambda: (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 with a = |z| / (alpha(phi)
    /// sin(theta)) (Heitz 2014 eq. 83). +inf at the horizon, 0 at the normal.
    #[inline]
    fn lambda(&self, w: V3<T>) -> T {
        lambda_of_a(w.z.abs() / self.projected_roughness(w))
    }

    /// |z| Lambda = (r exp(-a^2) / sqrt(pi) - |z| erfc(a)) / 2 with r = alpha(phi) sin(theta):
    /// r / (2 sqrt(pi)) at the horizon.
    #[inline]
    fn cos_lambda(&self, w: V3<T>) -> T {
        let c = w.z.abs();
        let r = self.projected_roughness(w);
        let a = c / r;
        let v = T::HALF * (r * (-a * a).exp() * T::splat(FRAC_1_SQRT_PI) - c * a.erfc());
        // At the normal r = 0 and a = inf: 0 * 0 - 1 * 0 = 0, but guard the 0 * inf of
        // r * exp(-inf) regardless of how libm orders it.
        T::select(r.simd_gt(T::ZERO), v.max(T::ZERO), T::ZERO)
    }
}

/// Isotropic Beckmann NDF of n_dot_h: D = exp(-tan^2 / alpha^2) / (pi alpha^2 c^4), with
/// tan^2 = (1 - c)(1 + c) / c^2; 0 for c <= 0 (Walter et al. 2007 eq. 25). Peak
/// 1 / (pi alpha^2) at c = 1.
#[inline]
#[must_use]
pub fn d<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a = floor_alpha(alpha);
    let c = n_dot_h.min(T::ONE);
    let c2 = c * c;
    let e = (T::ONE - c) * (T::ONE + c) / (c2 * a * a);
    let den = (T::PI * a * a * c2 * c2).max(T::MIN_POSITIVE);
    T::select(n_dot_h.simd_gt(T::ZERO), (-e).exp() / den, T::ZERO)
}

/// a = c / (alpha sqrt(1 - c^2)) = 1 / (alpha tan(theta)): the argument of every Beckmann
/// Smith term. +inf at c = 1, 0 at c = 0; uses |c| clamped to 1.
#[inline]
#[must_use]
pub fn a_of<T: Real>(n_dot_v: T, alpha: T) -> T {
    let c = n_dot_v.abs().min(T::ONE);
    c / (floor_alpha(alpha) * ((T::ONE - c) * (T::ONE + c)).sqrt())
}

/// Exact Smith Lambda of the isotropic Beckmann distribution (Walter et al. 2007 eq. 27;
/// Heitz 2014 eq. 83): (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = [`a_of`]`(n_dot_v,
/// alpha)`. +inf at n_dot_v = 0, 0 at 1.
#[inline]
#[must_use]
pub fn lambda<T: Real>(n_dot_v: T, alpha: T) -> T {
    lambda_of_a(a_of(n_dot_v, alpha))
}

/// Smith G1 = 1 / (1 + [`lambda`]) of the isotropic Beckmann distribution.
#[inline]
#[must_use]
pub fn g1<T: Real>(n_dot_v: T, alpha: T) -> T {
    (T::ONE + lambda(n_dot_v, alpha)).recip()
}

/// Walter et al.'s rational approximation of the Beckmann Lambda (Walter et al. 2007 eq. 27,
/// the G1 fit (3.535 a + 2.181 a^2) / (1 + 2.276 a + 2.577 a^2) written as Lambda = 1/G1 - 1):
/// Lambda ~ (1 - 1.259 a + 0.396 a^2) / (3.535 a + 2.181 a^2) for a < 1.6, 0 beyond.
/// Approximation: the resulting G1 is within 0.31% (relative) of the exact one for alpha and
/// NoV in [0.01, 1] (`cargo test --test smith_approximations -- --nocapture`). Clamped at 0 (the numerator crosses zero
/// just below a = 1.6).
#[inline]
#[must_use]
pub fn lambda_walter<T: Real>(n_dot_v: T, alpha: T) -> T {
    let a = a_of(n_dot_v, alpha);
    let num = a.mul_add(a.mul_add(T::splat(0.396), T::splat(-1.259)), T::ONE);
    let den = a * a.mul_add(T::splat(2.181), T::splat(3.535));
    T::select(a.simd_lt(T::splat(1.6)), (num / den).max(T::ZERO), T::ZERO)
}

/// Blinn-Phong exponent n to the Beckmann alpha with the same lobe shape near the peak:
/// alpha = sqrt(2 / (n + 2)) (Walter et al. 2007, section 5.2). Domain n >= 0 (n = 0 gives
/// alpha = 1); n = inf gives 0.
#[inline]
#[must_use]
pub fn alpha_from_blinn_phong<T: Real>(exponent: T) -> T {
    (T::TWO / (exponent.max(T::ZERO) + T::TWO)).sqrt()
}

/// Beckmann alpha to the Blinn-Phong exponent n = 2 / alpha^2 - 2 (the inverse of
/// [`alpha_from_blinn_phong`]). alpha floored at the crate's ALPHA_MIN (n <= 2e8); alpha > 1
/// gives a negative n, which no Blinn-Phong lobe has: it is clamped to 0.
#[inline]
#[must_use]
pub fn blinn_phong_from_alpha<T: Real>(alpha: T) -> T {
    let a = floor_alpha(alpha);
    (T::TWO / (a * a) - T::TWO).max(T::ZERO)
}
