//! [`V3`]: a 3-vector of [`Real`]s, the structure-of-arrays direction type of the SIMD path.
//!
//! `V3<f32>` and `V3<f64>` are plain vectors and convert to and from `glam::Vec3` /
//! `glam::DVec3`. `V3<f32x8>` holds eight directions as three `f32x8` (x, y and z of each
//! lane), built from `[Vec3; 8]` with [`V3::from_lanes`]; `V3<f64x4>` likewise from
//! `[DVec3; 4]`.

use crate::real::Real;
use core::ops::{Add, Mul, Neg, Sub};
use glam::{DVec3, Vec3};
use wide::{f32x8, f64x4};

/// A 3-vector whose components are [`Real`]s (scalars or lanes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3<T> {
    /// x component (first tangent axis in a shading frame).
    pub x: T,
    /// y component (second tangent axis in a shading frame).
    pub y: T,
    /// z component (the normal in a shading frame).
    pub z: T,
}

impl<T: Real> V3<T> {
    /// The vector `(x, y, z)`.
    #[inline]
    #[must_use]
    pub const fn new(x: T, y: T, z: T) -> Self {
        Self { x, y, z }
    }

    /// The vector `(v, v, v)`.
    #[inline]
    #[must_use]
    pub fn splat(v: T) -> Self {
        Self::new(v, v, v)
    }

    /// `(0, 0, 1)`: the normal of a local shading frame.
    #[inline]
    #[must_use]
    pub fn unit_z() -> Self {
        Self::new(T::ZERO, T::ZERO, T::ONE)
    }

    /// Dot product `x1 x2 + y1 y2 + z1 z2`.
    #[inline]
    #[must_use]
    pub fn dot(self, o: Self) -> T {
        self.x.mul_add(o.x, self.y.mul_add(o.y, self.z * o.z))
    }

    /// Cross product.
    #[inline]
    #[must_use]
    pub fn cross(self, o: Self) -> Self {
        Self::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// Squared length.
    #[inline]
    #[must_use]
    pub fn length_squared(self) -> T {
        self.dot(self)
    }

    /// Euclidean length.
    #[inline]
    #[must_use]
    pub fn length(self) -> T {
        self.length_squared().sqrt()
    }

    /// `self / |self|`; where `|self|` is 0 or infinite the lane is `fallback`, so a degenerate
    /// half vector (wo = -wi) cannot poison a kernel with a 0 / 0. A NaN component gives NaN in
    /// all three (the crate's rule: a NaN input is never replaced by a plausible direction).
    #[inline]
    #[must_use]
    pub fn normalize_or(self, fallback: Self) -> Self {
        let len2 = self.length_squared();
        let ok = len2.simd_gt(T::ZERO) & len2.is_finite();
        let inv = T::select(ok, len2.sqrt().recip(), T::ZERO);
        let n = self * inv;
        // len2 is NaN exactly where a component is: the sum of squares of the others cannot be.
        let pick = |v: T, f: T| crate::domain::nan_where(len2.is_nan(), T::select(ok, v, f));
        Self::new(
            pick(n.x, fallback.x),
            pick(n.y, fallback.y),
            pick(n.z, fallback.z),
        )
    }

    /// Mirror reflection of `self` about the unit normal `n`: `2 (self . n) n - self`.
    /// Both point away from the surface.
    #[inline]
    #[must_use]
    pub fn reflect(self, n: Self) -> Self {
        n * (T::TWO * self.dot(n)) - self
    }

    /// Lane-wise select between two vectors.
    #[inline]
    #[must_use]
    pub fn select(m: T::Mask, t: Self, f: Self) -> Self {
        Self::new(
            T::select(m, t.x, f.x),
            T::select(m, t.y, f.y),
            T::select(m, t.z, f.z),
        )
    }

    /// Lane `i` as a scalar vector.
    #[inline]
    #[must_use]
    pub fn lane(self, i: usize) -> V3<T::Scalar> {
        V3::new(self.x.lane(i), self.y.lane(i), self.z.lane(i))
    }
}

impl<T: Real> Add for V3<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<T: Real> Sub for V3<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<T: Real> Neg for V3<T> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<T: Real> Mul<T> for V3<T> {
    type Output = Self;
    #[inline]
    fn mul(self, s: T) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

impl From<Vec3> for V3<f32> {
    #[inline]
    fn from(v: Vec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<V3<f32>> for Vec3 {
    #[inline]
    fn from(v: V3<f32>) -> Self {
        Vec3::new(v.x, v.y, v.z)
    }
}

impl From<DVec3> for V3<f64> {
    #[inline]
    fn from(v: DVec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<V3<f64>> for DVec3 {
    #[inline]
    fn from(v: V3<f64>) -> Self {
        DVec3::new(v.x, v.y, v.z)
    }
}

impl V3<f32x8> {
    /// Transposes eight `Vec3` (array of structures) into one `V3<f32x8>` (structure of
    /// arrays): lane `i` of the result is `v[i]`.
    #[inline]
    #[must_use]
    pub fn from_lanes(v: [Vec3; 8]) -> Self {
        Self::new(
            f32x8::new(v.map(|p| p.x)),
            f32x8::new(v.map(|p| p.y)),
            f32x8::new(v.map(|p| p.z)),
        )
    }

    /// The inverse of [`V3::<f32x8>::from_lanes`].
    #[inline]
    #[must_use]
    pub fn to_lanes(self) -> [Vec3; 8] {
        let (x, y, z) = (self.x.to_array(), self.y.to_array(), self.z.to_array());
        core::array::from_fn(|i| Vec3::new(x[i], y[i], z[i]))
    }
}

impl V3<f64x4> {
    /// Transposes four `DVec3` into one `V3<f64x4>`: lane `i` of the result is `v[i]`.
    #[inline]
    #[must_use]
    pub fn from_lanes(v: [DVec3; 4]) -> Self {
        Self::new(
            f64x4::new(v.map(|p| p.x)),
            f64x4::new(v.map(|p| p.y)),
            f64x4::new(v.map(|p| p.z)),
        )
    }

    /// The inverse of [`V3::<f64x4>::from_lanes`].
    #[inline]
    #[must_use]
    pub fn to_lanes(self) -> [DVec3; 4] {
        let (x, y, z) = (self.x.to_array(), self.y.to_array(), self.z.to_array());
        core::array::from_fn(|i| DVec3::new(x[i], y[i], z[i]))
    }
}
