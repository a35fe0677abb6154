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
    let (h, v_dot_h) = half_vector(wo, wi);
    let value = m.d(h) * m.v_correlated(wo, wi) * fresnel(v_dot_h);
    let above = wo.z.simd_gt(T::ZERO) & wi.z.simd_gt(T::ZERO);
    T::select(above, value, T::ZERO)
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
    let (h, v_dot_h) = half_vector(wo, wi);
    let dv = m.d(h) * m.v_correlated(wo, wi);
    let above = wo.z.simd_gt(T::ZERO) & wi.z.simd_gt(T::ZERO);
    fresnel(v_dot_h) * T::select(above, dv, T::ZERO)
}
