//! `KHR_materials_clearcoat`: a GGX coat with its own roughness and normal over the base
//! material, F0 = 0.04 (IOR 1.5), and the layering that attenuates the base by the light the
//! coat reflects.
//!
//! ```text
//! F_coat(c)  = 0.04 + 0.96 (1 - c)^5                               fresnel
//! coat       = F_coat(v.h) D(n_c.h) V(n_c.v, n_c.l)                 coat (exact Smith V)
//!            = F_coat(v.h) D(n_c.h) / (4 (l.h)^2)                   coat_kelemen
//! f          = clearcoat coat + (1 - clearcoat F_coat(c)) base      layer
//! ```
//!
//! The cosines n_c.* are taken about the coat's own normal; alpha = clearcoatRoughness^2.
//!
//! # Which Fresnel argument attenuates the base
//! The extension's text composes `mix(material, clearcoat_brdf, clearcoat * F_coat(n.v))`:
//! the base is attenuated by F_coat at the view cosine n_c.v, and its discussion says why
//! (one value per shading point, energy kept when the coat is smooth, where n.v ~ v.h). The
//! Khronos sample viewer attenuates the base by F_coat(n_c.v) as well, but evaluates the coat
//! lobe itself with F_coat(v.h) (Appendix B's specular term). Filament and three.js do the
//! same as the viewer; three.js's Fresnel there is Karis's spherical-Gaussian fit
//! 2^((-5.55473 c - 6.98316) c) of (1 - c)^5, up to 6.9% from Schlick's at F0 = 0.04. [`layer`] takes the attenuating Fresnel value from the caller, so both
//! are one call: `layer(base, coat, clearcoat, fresnel(n_dot_v))` (the extension and the
//! engines) or `fresnel(v_dot_h)` (a per-light attenuation that keeps the layer reciprocal
//! when the base is). With F_coat(n.v) the layered BRDF is not reciprocal; the coat lobe is.
//!
//! # Kelemen's visibility
//! V_kelemen = 1 / (4 (l.h)^2) replaces the Smith visibility G2 / (4 n.v n.l) by its value
//! for G2 = n.v n.l / (l.h)^2: cheap, and meant for smooth coats near normal view. Against
//! the exact height-correlated Smith V (in the plane of incidence, cosines from 0.05 to 1):
//! up to 1.50x (or 1/1.50x) for alpha <= 0.1 and both cosines >= 0.5, and up to 20x at grazing
//! angles (measured: `cargo test --test layers clearcoat:: -- --nocapture`).
//!
//! # Energy
//! The extension's layering over a white Lambertian base reflects up to 1.0009 (alpha 0.05,
//! 60 degrees): the coat reflects with F(v.h), the base is attenuated by F(n.v), and the two
//! differ off the mirror direction (`clearcoat::coat_over_white_lambert`).
//!
//! Sources: The Khronos Group, "KHR_materials_clearcoat" (ratified), sections "Clearcoat
//! BRDF", "Layering" and "Discussion"; Kelemen and Szirmay-Kalos 2001, "A Microfacet Based
//! Coupled Specular-Matte BRDF Model with Importance Sampling"; Guy and Agopian, "Physically
//! Based Rendering in Filament", section 4.9 (clear coat, `V_Kelemen`).

use crate::domain::{above, in_unit, nan_unless, nan_where};
use crate::ggx;
use crate::real::Real;
use crate::shading::Cosines;
use crate::vec3::V3;

/// F0 of the coat: ((1.5 - 1) / (1.5 + 1))^2 = 0.04, the extension's fixed IOR 1.5.
pub const F0: f64 = 0.04;

/// The coat's Schlick Fresnel F = 0.04 + 0.96 (1 - c)^5 ([`crate::fresnel::schlick`] with F0
/// = [`F0`]): pass n_c.v for the extension's base attenuation, v.h inside the coat lobe.
///
/// Domain: `cos_theta` a cosine in [-1, 1], clamped to [0, 1] (so F = 1 at or below the
/// horizon, Schlick's grazing value); NaN for NaN. Output in [0.04, 1].
///
/// Source: KHR_materials_clearcoat, "Layering" (`fresnel_coat`); Schlick 1994.
#[inline]
#[must_use]
pub fn fresnel<T: Real>(cos_theta: T) -> T {
    crate::fresnel::schlick(T::splat(F0), cos_theta)
}

/// Kelemen's visibility V = 1 / (4 (v.h)^2) (v.h = l.h), the cheap stand-in for the Smith
/// visibility of a smooth coat (module docs, with its measured error).
///
/// Domain: `v_dot_h` a cosine in [-1, 1] (above 1 counts as 1); 0 where v.h <= 0; NaN for
/// NaN. Capped at the largest finite float (v.h subnormal). 1/4 at v.h = 1.
///
/// Source: Kelemen and Szirmay-Kalos 2001; Filament's `V_Kelemen`.
#[inline]
#[must_use]
pub fn v_kelemen<T: Real>(v_dot_h: T) -> T {
    let c = v_dot_h.min(T::ONE);
    above(v_dot_h, (T::splat(4.0) * c * c).recip().min(T::MAX))
}

/// The coat lobe F_coat(v.h) D V with the GGX D ([`ggx::d`]) and the exact height-correlated
/// Smith V ([`ggx::v_correlated`]), F0 = 0.04: the extension's `clearcoat_brdf` with
/// Appendix B's Fresnel, not multiplied by the cosine.
///
/// Arguments: the [`Cosines`] about the coat's normal; `alpha` = clearcoatRoughness^2, the
/// GGX width, finite and >= 0 (clamped as [`ggx::d`] clamps it). Edges: 0 where n.v <= 0 or
/// n.l <= 0; NaN for NaN input or alpha < 0 or +inf; capped at the largest finite float.
/// Reciprocal.
///
/// Source: KHR_materials_clearcoat, "Clearcoat BRDF"; glTF 2.0 Appendix B.
#[inline]
#[must_use]
pub fn coat<T: Real>(c: Cosines<T>, alpha: T) -> T {
    let dv =
        (ggx::d(c.n_dot_h, alpha) * ggx::v_correlated(c.n_dot_v, c.n_dot_l, alpha)).min(T::MAX);
    let f = fresnel(c.v_dot_h);
    nan_where(c.n_dot_h.is_nan(), (f * dv).min(T::MAX))
}

/// The coat lobe with Kelemen's visibility: F_coat(v.h) D [`v_kelemen`](v.h), the Filament
/// clear-coat lobe. Same arguments and domain as [`coat`]; 0 where n.v <= 0 or n.l <= 0.
///
/// Source: Guy and Agopian, "Physically Based Rendering in Filament", section 4.9.2.
#[inline]
#[must_use]
pub fn coat_kelemen<T: Real>(c: Cosines<T>, alpha: T) -> T {
    let dv = (ggx::d(c.n_dot_h, alpha) * v_kelemen(c.v_dot_h)).min(T::MAX);
    let f = fresnel(c.v_dot_h);
    let value = crate::domain::above_horizon(c.n_dot_v, c.n_dot_l, (f * dv).min(T::MAX));
    // The horizon select above would hide a NaN cosine or an invalid alpha: put it back.
    let bad = c.n_dot_h.is_nan() | c.v_dot_h.is_nan() | !crate::microfacet::alpha_ok(alpha);
    nan_where(bad, value)
}

/// The coat over the base: f = clearcoat coat + (1 - clearcoat f_coat) base per RGB channel,
/// evaluated as coat clearcoat + ((1 - clearcoat f_coat) base) with one fused multiply-add,
/// so `clearcoat` = 0 returns `base` bit for bit.
///
/// Arguments: `base` the base material's RGB BRDF value (finite, >= 0); `coat` the coat lobe
/// ([`coat`] or [`coat_kelemen`], or the extension's F-free `clearcoat_brdf` times
/// F_coat(n.v)); `clearcoat` the layer's weight in [0, 1] (glTF's `clearcoatFactor`);
/// `f_coat` the attenuating Fresnel value in [0, 1], [`fresnel`] of n_c.v (the extension, the
/// sample viewer, Filament, three.js) or of v.h (module docs). NaN for NaN or infinite input
/// or `clearcoat`, `f_coat` outside [0, 1].
///
/// Source: KHR_materials_clearcoat, "Layering".
#[inline]
#[must_use]
pub fn layer<T: Real>(base: V3<T>, coat: T, clearcoat: T, f_coat: T) -> V3<T> {
    let att = T::ONE - clearcoat * f_coat;
    // An infinite base or coat is an overflow upstream (crate docs, rule 5): NaN, not inf.
    let ok = in_unit(clearcoat) & in_unit(f_coat) & coat.is_finite();
    let ch = |b: T| nan_unless(ok & b.is_finite(), coat.mul_add(clearcoat, att * b));
    V3::new(ch(base.x), ch(base.y), ch(base.z))
}
