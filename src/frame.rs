//! Shading frames and the local-frame trigonometry every lobe uses.
//!
//! In a local shading frame the normal is +z, so `cos(theta) = w.z`; the helpers below name
//! these quantities (after pbrt-v4's `CosTheta`, `Tan2Theta`, `CosPhi`) so kernels never
//! redo ad-hoc trigonometry. All of them are generic over [`Real`] and take [`V3`], so they
//! serve `f32`, `f64` and lanes alike; `glam` vectors convert with `V3::from` and back with
//! `into()` (see [`crate::vec3`] for lanes).
//!
//! ```
//! use brdf::V3;
//! use brdf::frame::{self, Frame};
//! use brdf::glam::Vec3;
//!
//! let n = Vec3::new(0.0, 0.6, 0.8);
//! let f = Frame::from_normal(V3::from(n));
//! let light = V3::from(Vec3::new(0.0, 0.0, 1.0));
//! let local = f.to_local(light);
//! assert!((frame::cos_theta(local) - 0.8).abs() < 1e-6);
//! let back: Vec3 = f.to_world(local).into();
//! assert!((back - Vec3::Z).length() < 1e-6);
//! ```

use crate::domain::{finite_or_nan, nan_unless};
use crate::real::Real;
use crate::vec3::V3;

/// An orthonormal basis `(t, b, n)`: tangent, bitangent, normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<T> {
    /// Tangent (local +x).
    pub t: V3<T>,
    /// Bitangent (local +y), `n x t`.
    pub b: V3<T>,
    /// Normal (local +z).
    pub n: V3<T>,
}

impl<T: Real> Frame<T> {
    /// A right-handed orthonormal basis whose third axis is the unit normal `n`.
    ///
    /// Formula (s = sign(n.z) with sign(+-0) = +-1, a = -1 / (s + n.z), c = n.x n.y a):
    /// t = (1 + s n.x^2 a, s c, -s n.x), b = (c, s + n.y^2 a, -n.y).
    ///
    /// Branch-free and continuous except across the plane n.z = 0, where it stays
    /// orthonormal to rounding (the Frisvad 2012 construction it improves on loses
    /// orthogonality near n = (0, 0, -1)). Domain: unit `n`; the error of the basis grows with
    /// `| |n| - 1 |`. A NaN or infinite component of `n` gives a frame of NaN axes.
    ///
    /// Source: Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin 2017, "Building an
    /// Orthonormal Basis, Revisited", JCGT 6(1).
    #[inline]
    #[must_use]
    pub fn from_normal(n: V3<T>) -> Self {
        let s = T::ONE.copysign(n.z);
        let a = -(s + n.z).recip();
        let c = n.x * n.y * a;
        let t = V3::new(T::ONE + s * n.x * n.x * a, s * c, -s * n.x);
        let b = V3::new(c, s + n.y * n.y * a, -n.y);
        // Some axes skip a component (b.z = -n.y whatever n.x is; copysign turns a NaN n.z into
        // a sign): a NaN anywhere in n gives an all-NaN frame, never a plausible axis.
        let bad = crate::vec3::any_nonfinite3(n);
        let nan = |v: V3<T>| V3::select(bad, V3::splat(T::splat(f64::NAN)), v);
        Self {
            t: nan(t),
            b: nan(b),
            n: nan(n),
        }
    }

    /// A frame from three given orthonormal axes (for example an anisotropic material's
    /// tangent, bitangent and normal). The axes are not checked.
    #[inline]
    #[must_use]
    pub const fn from_axes(t: V3<T>, b: V3<T>, n: V3<T>) -> Self {
        Self { t, b, n }
    }

    /// World-space `v` in this frame: `(v.t, v.b, v.n)`.
    #[inline]
    #[must_use]
    pub fn to_local(&self, v: V3<T>) -> V3<T> {
        V3::new(v.dot(self.t), v.dot(self.b), v.dot(self.n))
    }

    /// Local `v` back to world space: `v.x t + v.y b + v.z n`.
    #[inline]
    #[must_use]
    pub fn to_world(&self, v: V3<T>) -> V3<T> {
        self.t * v.x + self.b * v.y + self.n * v.z
    }
}

/// cos(theta) of a local direction: `w.z`. Negative below the surface; NaN for a NaN or
/// infinite `w.z` (crate docs, "Bad input", rule 5).
#[inline]
#[must_use]
pub fn cos_theta<T: Real>(w: V3<T>) -> T {
    finite_or_nan(w.z)
}

/// cos^2(theta) of a local direction: `w.z^2`; NaN for a NaN or infinite `w.z`.
#[inline]
#[must_use]
pub fn cos2_theta<T: Real>(w: V3<T>) -> T {
    let z = finite_or_nan(w.z);
    z * z
}

/// |cos(theta)| of a local direction; NaN for a NaN or infinite `w.z`.
#[inline]
#[must_use]
pub fn abs_cos_theta<T: Real>(w: V3<T>) -> T {
    finite_or_nan(w.z).abs()
}

/// sin^2(theta) of a unit local direction, computed as `w.x^2 + w.y^2`; NaN for a NaN or
/// infinite `w.x` or `w.y` (so also [`sin_theta`], [`tan2_theta`], [`cos_phi`], [`sin_phi`]).
///
/// Not `1 - cos^2(theta)`: near the pole that subtraction cancels (for cos = 1 - 1e-7 in f32
/// it returns 0 or 2.4e-7 instead of 2e-7), and every grazing-free lobe evaluates there.
#[inline]
#[must_use]
pub fn sin2_theta<T: Real>(w: V3<T>) -> T {
    nan_unless(
        w.x.is_finite() & w.y.is_finite(),
        w.x.mul_add(w.x, w.y * w.y),
    )
}

/// sin(theta) of a unit local direction, `sqrt(w.x^2 + w.y^2)`.
#[inline]
#[must_use]
pub fn sin_theta<T: Real>(w: V3<T>) -> T {
    sin2_theta(w).sqrt()
}

/// tan^2(theta) = sin^2 / cos^2 of a unit local direction. +inf at the horizon (cos = 0);
/// 0 at the pole.
#[inline]
#[must_use]
pub fn tan2_theta<T: Real>(w: V3<T>) -> T {
    sin2_theta(w) / cos2_theta(w)
}

/// cos(phi) = w.x / sin(theta), clamped to [-1, 1]; 1 at the pole, where phi is undefined
/// (without the guard, 0/0 = NaN).
#[inline]
#[must_use]
pub fn cos_phi<T: Real>(w: V3<T>) -> T {
    let s = sin_theta(w);
    let pole = s.simd_eq(T::ZERO);
    T::select(
        pole,
        T::ONE,
        (w.x / T::select(pole, T::ONE, s)).clamp(-T::ONE, T::ONE),
    )
}

/// sin(phi) = w.y / sin(theta), clamped to [-1, 1]; 0 at the pole, where phi is undefined.
#[inline]
#[must_use]
pub fn sin_phi<T: Real>(w: V3<T>) -> T {
    let s = sin_theta(w);
    let pole = s.simd_eq(T::ZERO);
    T::select(
        pole,
        T::ZERO,
        (w.y / T::select(pole, T::ONE, s)).clamp(-T::ONE, T::ONE),
    )
}

/// A unit local direction from spherical angles: `(sin t cos p, sin t sin p, cos t)`.
#[inline]
#[must_use]
pub fn spherical_direction<T: Real>(theta: T, phi: T) -> V3<T> {
    let (st, ct) = (theta.sin(), theta.cos());
    V3::new(st * phi.cos(), st * phi.sin(), ct)
}

/// True where `a` and `b` lie in the same hemisphere of the local frame (`a.z b.z > 0`).
#[inline]
#[must_use]
pub fn same_hemisphere<T: Real>(a: V3<T>, b: V3<T>) -> T::Mask {
    (a.z * b.z).simd_gt(T::ZERO)
}
