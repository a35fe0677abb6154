//! The Cook-Torrance microfacet specular BRDF, f = D(h) G2(wo, wi) F(wo.h) / (4 |n.wo| |n.wi|),
//! evaluated as D V F with the visibility V = G2 / (4 |n.wo| |n.wi|) of
//! [`Microfacet::v_correlated`], so nothing divides by a vanishing cosine.
//!
//! Sources: Cook and Torrance 1982, "A Reflectance Model for Computer Graphics"; Walter,
//! Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through Rough Surfaces",
//! eq. 20 (the 1/4 Jacobian); Heitz 2014, "Understanding the Masking-Shadowing Function",
//! eq. 99 (height-correlated G2).
//!
//! Directions are local-frame unit vectors pointing away from the surface. The BRDF is 0 when
//! either direction is at or below the horizon (reflection only). Energy: with F = 1 the
//! directional albedo is below 1 and falls with roughness, since single scattering drops the
//! light that bounces more than once between microfacets (`tests/cook_torrance_energy.rs`
//! prints the loss).

use crate::domain::{above_horizon, any_nan3, nan_where};
use crate::fresnel;
use crate::microfacet::Microfacet;
use crate::real::Real;
use crate::vec3::V3;

/// The half vector h = normalize(wo + wi) and v.h, with the guard for wo = -wi (h undefined):
/// h falls back to the normal there, which only happens below the horizon, where `eval`
/// returns 0 anyway.
#[inline]
#[must_use]
pub fn half_vector<T: Real>(wo: V3<T>, wi: V3<T>) -> (V3<T>, T) {
    let h = (wo + wi).normalize_or(V3::unit_z());
    (h, wo.dot(h).saturate())
}

/// D(h) V(wo, wi) capped at MAX (0 where either direction is at or below the horizon, NaN
/// where any component is NaN) and v.h: the part of the BRDF every Fresnel form multiplies.
///
/// Why the cap: V is itself capped at MAX where both cosines are tiny, and D > 1 would then
/// overflow the product to inf (and inf times a zero Fresnel to NaN).
#[inline]
fn masked_dv<T: Real, M: Microfacet<T> + ?Sized>(m: &M, wo: V3<T>, wi: V3<T>) -> (T, T) {
    let (h, v_dot_h) = half_vector(wo, wi);
    let dv = (m.d(h) * m.v_correlated(wo, wi)).min(T::MAX);
    let dv = above_horizon(wo.z, wi.z, dv);
    (nan_where(any_nan3(wo) | any_nan3(wi), dv), v_dot_h)
}

/// f = D(h) V(wo, wi) F, with F given by the caller as a function of v.h (any Fresnel form of
/// [`crate::fresnel`], or a constant). 0 where wo.z <= 0 or wi.z <= 0.
///
/// Reciprocal (f(wo, wi) = f(wi, wo)) because h, v.h = l.h and V are symmetric in the two
/// directions.
#[inline]
#[must_use]
pub fn eval<T: Real, M: Microfacet<T> + ?Sized>(
    m: &M,
    wo: V3<T>,
    wi: V3<T>,
    fresnel: impl Fn(T) -> T,
) -> T {
    let (dv, v_dot_h) = masked_dv(m, wo, wi);
    (dv * fresnel(v_dot_h)).min(T::MAX)
}

/// Cook-Torrance with the exact dielectric Fresnel term of relative IOR `eta`
/// ([`fresnel::dielectric`]).
#[inline]
#[must_use]
pub fn dielectric<T: Real, M: Microfacet<T> + ?Sized>(m: &M, wo: V3<T>, wi: V3<T>, eta: T) -> T {
    eval(m, wo, wi, |c| fresnel::dielectric(c, eta))
}

/// Cook-Torrance with the exact conductor Fresnel term of complex IOR eta + i k
/// ([`fresnel::conductor`]), one channel.
#[inline]
#[must_use]
pub fn conductor<T: Real, M: Microfacet<T> + ?Sized>(
    m: &M,
    wo: V3<T>,
    wi: V3<T>,
    eta: T,
    k: T,
) -> T {
    eval(m, wo, wi, |c| fresnel::conductor(c, eta, k))
}

/// Cook-Torrance with an RGB Fresnel term (for example [`fresnel::schlick_rgb`] or
/// [`fresnel::conductor_rgb`]): D V is computed once and scaled per channel.
#[inline]
#[must_use]
pub fn eval_rgb<T: Real, M: Microfacet<T> + ?Sized>(
    m: &M,
    wo: V3<T>,
    wi: V3<T>,
    fresnel: impl Fn(T) -> V3<T>,
) -> V3<T> {
    let (dv, v_dot_h) = masked_dv(m, wo, wi);
    let f = fresnel(v_dot_h) * dv;
    V3::new(f.x.min(T::MAX), f.y.min(T::MAX), f.z.min(T::MAX))
}

/// Dot-product entry point of isotropic GGX Cook-Torrance: f = D(n.h) V(n.v, n.l) F, with
/// [`crate::ggx::d`] and [`crate::ggx::v_correlated`], F given by the caller (the shader
/// form: `D_GGX * V_SmithGGXCorrelated * F`).
///
/// Domain: cosines in [-1, 1] (clamped to [0, 1]; 0 where n.l <= 0 or n.v <= 0), alpha in
/// [0, +inf) finite (clamped to [ALPHA_MIN, ALPHA_MAX]), F >= 0. NaN for NaN in any input,
/// alpha < 0 or +inf, F < 0. Never inf: D V and D V F are capped at the largest finite value
/// (reached only when both cosines are near 0, where the BRDF is multiplied by n.l anyway).
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx<T: Real>(n_dot_h: T, n_dot_v: T, n_dot_l: T, alpha: T, fresnel: T) -> T {
    let dv = crate::ggx::d(n_dot_h, alpha) * crate::ggx::v_correlated(n_dot_v, n_dot_l, alpha);
    assemble(dv, n_dot_h, n_dot_v, n_dot_l, alpha, fresnel)
}

/// (D V capped at MAX) F capped at MAX, 0 below the horizon, NaN for NaN input, alpha outside
/// [0, +inf) or F < 0: the shared tail of the dot-product entry points. Capping D V before the
/// multiplication by F keeps a zero F from meeting an infinite D V (0 inf = NaN).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn assemble<T: Real>(dv: T, n_dot_h: T, n_dot_v: T, n_dot_l: T, alpha: T, fresnel: T) -> T {
    let value = (dv.min(T::MAX) * fresnel).min(T::MAX);
    let value = above_horizon(n_dot_v, n_dot_l, value);
    let ok = crate::microfacet::alpha_ok(alpha) & fresnel.simd_ge(T::ZERO);
    crate::domain::nan_unless(ok, nan_where(n_dot_h.is_nan(), value))
}

/// Dot-product entry point of isotropic Beckmann Cook-Torrance with the height-correlated
/// Smith G2 = 1 / (1 + Lambda(v) + Lambda(l)): f = D G2 F / (4 n.l n.v), evaluated as
/// D F / (4 (n.l n.v + n.l n.v Lambda(v) + n.v n.l Lambda(l))) so that grazing cosines give
/// 0 instead of 0 / 0. Domain, edges and caps as [`ggx`].
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann<T: Real>(n_dot_h: T, n_dot_v: T, n_dot_l: T, alpha: T, fresnel: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let dist = crate::beckmann::Beckmann::new_unchecked(alpha, alpha);
    let (wv, wl) = (cosine_direction(cv), cosine_direction(cl));
    let dv = crate::beckmann::d(n_dot_h, alpha) * dist.v_correlated(wv, wl);
    assemble(dv, n_dot_h, n_dot_v, n_dot_l, alpha, fresnel)
}

/// A unit direction with cos(theta) = c in the xz plane (isotropic terms depend on c only).
#[cfg(feature = "beckmann")]
#[inline]
fn cosine_direction<T: Real>(c: T) -> V3<T> {
    V3::new(((T::ONE - c) * (T::ONE + c)).sqrt_nonneg(), T::ZERO, c)
}
