//! `KHR_materials_anisotropy`: a strength and a direction stretch the GGX lobe along one
//! tangent, onto the crate's anisotropic GGX ([`crate::ggx::Ggx`], [`crate::ggx::d_aniso`]).
//!
//! ```text
//! alpha_b = alpha = roughness^2                      across the stretch
//! alpha_t = mix(alpha, 1, strength^2)                along it              alpha_t
//! dir     = R(rotation) (x, y)                       in (t, b) space       direction
//! t'      = dir.x t + dir.y b,  b' = n x t'          the lobe's frame
//! ```
//!
//! For image-based lighting a prefiltered map is isotropic, so the engines bend the normal
//! towards the plane the stretched lobe spans and reflect about it ([`bent_reflection`]).
//!
//! Sources: The Khronos Group, "KHR_materials_anisotropy" (ratified), "Anisotropy" and
//! "Implementation"; Burley 2012, "Physically-Based Shading at Disney", addendum (anisotropic
//! GGX); McAuley 2015 / Revie 2012 bent reflection as in Guy and Agopian, "Physically Based
//! Rendering in Filament", section 5.3.9 (anisotropic IBL) and the Khronos glTF sample viewer's
//! `getIBLRadianceAnisotropy` (`source/Renderer/shaders/ibl.glsl`).

use crate::domain::{in_unit, nan_unless, nan_where};
use crate::real::Real;
use crate::vec3::{V3, any_nonfinite3};

/// The tangent alpha of KHR_materials_anisotropy: alpha_t = mix(alpha, 1, strength^2) =
/// (1 - s^2) alpha + s^2, so strength 0 returns alpha bit for bit (the isotropic lobe) and
/// strength 1 gives 1. alpha_b stays alpha.
///
/// Domain: `alpha` in [0, 1] (the material's roughness squared); `strength` in [0, 1]
/// (glTF's `anisotropyStrength` times the texture's blue channel); NaN for NaN input or a
/// value outside [0, 1]. Output in [alpha, 1].
///
/// Source: KHR_materials_anisotropy, "Anisotropy".
#[inline]
#[must_use]
pub fn alpha_t<T: Real>(alpha: T, strength: T) -> T {
    let s2 = strength * strength;
    nan_unless(
        in_unit(alpha) & in_unit(strength),
        (T::ONE - s2) * alpha + s2,
    )
}

/// The anisotropy direction in tangent space: the texture's (x, y) normalized and rotated by
/// `rotation` radians counter-clockwise from the tangent, returned as (x', y', 0) in the
/// (t, b, n) basis. (x, y) = (1, 0) (no texture) gives (cos rotation, sin rotation, 0).
///
/// Domain: `x`, `y` finite, not both 0 (a zero vector has no direction: it is taken as the
/// tangent (1, 0), the extension's default texel); `rotation` finite; NaN for NaN or
/// infinite input.
///
/// Source: KHR_materials_anisotropy, "Implementation" (the `mat2` rotation of the sample
/// implementation).
#[inline]
#[must_use]
pub fn direction<T: Real>(x: T, y: T, rotation: T) -> V3<T> {
    let len = x.mul_add(x, y * y).sqrt();
    let zero = len.simd_eq(T::ZERO);
    let safe = T::select(zero, T::ONE, len);
    let (ux, uy) = (
        T::select(zero, T::ONE, x / safe),
        T::select(zero, T::ZERO, y / safe),
    );
    let (s, c) = (rotation.sin(), rotation.cos());
    let bad = !(x.is_finite() & y.is_finite() & rotation.is_finite());
    let bad: T::Mask = bad;
    V3::new(
        nan_where(bad, c * ux - s * uy),
        nan_where(bad, s * ux + c * uy),
        nan_where(bad, T::ZERO),
    )
}

/// The bent reflection vector for anisotropic image-based lighting, in the frame of its
/// arguments (world or local): with `b` the unit anisotropy bitangent (across the stretch),
/// t_a = b x v, n_a = t_a x b (the normal of the plane the stretched lobe spans, as seen
/// from v), k = (1 - strength (1 - roughness))^4 and n_b = normalize(mix(n_a, n, k)), the
/// result is reflect(-v, n_b) = 2 (v.n_b) n_b - v. strength 0 gives k = 1, the mirror
/// direction about n.
///
/// Domain: `n`, `v`, `b` unit vectors with finite components; `strength` and perceptual
/// `roughness` in [0, 1]; NaN for NaN or infinite input or a parameter outside [0, 1]. Where
/// mix(n_a, n, k) vanishes (never for unit input with k > 0) n is used.
///
/// Source: the Khronos glTF sample viewer's `getIBLRadianceAnisotropy` (the fourth power of
/// the bend factor); Guy and Agopian, "Physically Based Rendering in Filament", section 5.3.9
/// (the bent normal, there with the bend factor itself).
#[inline]
#[must_use]
pub fn bent_reflection<T: Real>(n: V3<T>, v: V3<T>, b: V3<T>, strength: T, roughness: T) -> V3<T> {
    let t_a = b.cross(v);
    let n_a = t_a.cross(b);
    let k = T::ONE - strength * (T::ONE - roughness);
    let k2 = k * k;
    let k4 = k2 * k2;
    let mixed = n_a * (T::ONE - k4) + n * k4;
    let n_b = mixed.normalize_or(n);
    let r = n_b * (T::TWO * v.dot(n_b)) - v;
    let bad = any_nonfinite3(n) | any_nonfinite3(v) | any_nonfinite3(b);
    let ok = in_unit(strength) & in_unit(roughness);
    let f = |x: T| nan_unless(ok, nan_where(bad, x));
    V3::new(f(r.x), f(r.y), f(r.z))
}
