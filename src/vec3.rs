//! [`V3`]: a 3-vector of [`Real`]s, the structure-of-arrays direction and colour type of the
//! SIMD path.
//!
//! `V3<f32>` and `V3<f64>` are plain vectors. `V3<f32x8>` holds eight vectors as three `f32x8`
//! (the x, y and z of each lane); `V3<f64x4>` holds four as three `f64x4`.
//!
//! # Getting vectors in and out
//! | you have | you want | write |
//! |---|---|---|
//! | `Vec3`, `Vec3A`, `[f32; 3]` | `V3<f32>` | `V3::from(v)` or `v.into()` |
//! | `DVec3`, `[f64; 3]` | `V3<f64>` | `V3::from(v)` or `v.into()` |
//! | one `Vec3` / `Vec3A` for every lane | `V3<f32x8>` | `V3::<f32x8>::broadcast(v)` |
//! | one `DVec3` for every lane | `V3<f64x4>` | `V3::<f64x4>::broadcast(v)` |
//! | eight `Vec3` (or `Vec3A`, `V3<f32>`, `[f32; 3]`) | `V3<f32x8>` | [`V3::from_lanes`] |
//! | four `DVec3` (or `V3<f64>`, `[f64; 3]`) | `V3<f64x4>` | [`V3::from_lanes`] |
//! | `V3<f32>` / `V3<f64>` | `Vec3`, `Vec3A`, `DVec3`, `[T; 3]` | `v.into()` |
//! | `V3<f32x8>` / `V3<f64x4>` | one glam vector per lane | `v.to_lanes()` or [`V3::lane`] |
//!
//! Two constructors put one value everywhere and are easy to confuse: [`V3::splat`]`(t)` is the
//! vector `(t, t, t)` (a grey colour, for instance), while [`V3::broadcast`]`(v)` copies one
//! three-component vector `v` into every lane.
//!
//! There is deliberately no `From<Vec3> for V3<f32x8>`: with it, the everyday
//! `V3::from(v).dot(n)` on a `Vec3` would no longer know which `V3` to build and would need
//! a type annotation. `From` means the scalar `V3` of the same precision; lanes say so.
//!
//! ```
//! use brdf::V3;
//! use brdf::glam::{DVec3, Vec3};
//! use brdf::wide::{f32x8, f64x4};
//!
//! let n = Vec3::new(0.0, 0.6, 0.8);
//! // One direction in every lane, two equivalent spellings.
//! let a = V3::<f32x8>::broadcast(n);
//! let c = V3::from_lanes([n; 8]);
//! assert_eq!(a, c);
//! assert_eq!(a.lane(5), V3::from(n));
//! // Eight different directions, and back.
//! let dirs: [Vec3; 8] = core::array::from_fn(|i| Vec3::new(i as f32, 0.0, 1.0));
//! assert_eq!(V3::from_lanes(dirs).to_lanes(), dirs);
//! // f64 lanes likewise.
//! let d = V3::from_lanes([DVec3::Z; 4]);
//! assert_eq!(d.z, f64x4::splat(1.0));
//! ```

use crate::real::Real;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use glam::{DVec3, Vec3, Vec3A};
use wide::{f32x8, f64x4};

/// A 3-vector whose components are [`Real`]s (scalars or lanes): a direction, a normal or an
/// RGB colour.
///
/// Arithmetic is component-wise: `+`, `-`, `*` and `/` between two vectors, `*` and `/` by a
/// component value `T` (`v * s`, `v / s`; `s * v` too for the concrete types `f32`, `f64`,
/// `f32x8` and `f64x4`, but not in code generic over `T: Real`, where Rust's orphan rule
/// allows no `impl Mul<V3<T>> for T`: write `v * s` there), and the assigning
/// forms `+=`, `-=`, `*=`, `/=`. Each component is rounded once per operation, exactly as the
/// scalar expression would be, so lanes equal scalars bit for bit.
///
/// ```
/// use brdf::V3;
/// use brdf::glam::Vec3;
///
/// let albedo = V3::new(0.8_f32, 0.5, 0.2);
/// let light = V3::from(Vec3::new(1.0, 1.0, 0.5));
/// let lit = albedo * light * 2.0 / 4.0;
/// assert_eq!(Vec3::from(lit), Vec3::new(0.4, 0.25, 0.05));
/// assert_eq!(0.5 * albedo, albedo / 2.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3<T> {
    /// x component (first tangent axis in a shading frame; red in a colour).
    pub x: T,
    /// y component (second tangent axis in a shading frame; green in a colour).
    pub y: T,
    /// z component (the normal in a shading frame; blue in a colour).
    pub z: T,
}

impl<T: Real> V3<T> {
    /// The vector `(x, y, z)`.
    #[inline]
    #[must_use]
    pub const fn new(x: T, y: T, z: T) -> Self {
        Self { x, y, z }
    }

    /// The vector `(t, t, t)`: all three components equal to `t` (a grey colour, for
    /// instance).
    ///
    /// Not a lane broadcast: to copy one glam vector into every lane of a `V3<f32x8>` use
    /// [`V3::broadcast`].
    ///
    /// ```
    /// use brdf::V3;
    /// assert_eq!(V3::splat(0.5_f32), V3::new(0.5, 0.5, 0.5));
    /// ```
    #[inline]
    #[must_use]
    pub fn splat(t: T) -> Self {
        Self::new(t, t, t)
    }

    /// `(0, 0, 1)`: the normal of a local shading frame.
    #[inline]
    #[must_use]
    pub fn unit_z() -> Self {
        Self::new(T::ZERO, T::ZERO, T::ONE)
    }

    /// One scalar vector `v` in every lane: lane `i` of the result is `v` for every `i`.
    ///
    /// `v` is anything that converts to the lane's scalar vector `V3<T::Scalar>`: a glam
    /// `Vec3` or `Vec3A` (or `[f32; 3]`) for `V3<f32x8>`, a `DVec3` (or `[f64; 3]`) for
    /// `V3<f64x4>`. On scalar `T` it is the plain conversion.
    ///
    /// Not [`V3::splat`], which sets the three components of one vector to one value.
    ///
    /// ```
    /// use brdf::V3;
    /// use brdf::glam::{DVec3, Vec3};
    /// use brdf::wide::{f32x8, f64x4};
    ///
    /// let wo = V3::<f32x8>::broadcast(Vec3::new(0.0, 0.6, 0.8));
    /// assert_eq!(wo.y, f32x8::splat(0.6));
    /// let n = V3::<f64x4>::broadcast(DVec3::Z);
    /// assert_eq!(n, V3::unit_z());
    /// ```
    #[inline]
    #[must_use]
    pub fn broadcast(v: impl Into<V3<T::Scalar>>) -> Self {
        let v = v.into();
        Self::new(
            T::from_scalar(v.x),
            T::from_scalar(v.y),
            T::from_scalar(v.z),
        )
    }

    /// Transposes one scalar vector per lane (array of structures) into one `V3` of lanes
    /// (structure of arrays): lane `i` of the result is `lanes[i]`.
    ///
    /// Accepts `[Vec3; 8]`, `[Vec3A; 8]`, `[V3<f32>; 8]` or `[[f32; 3]; 8]` (giving
    /// `V3<f32x8>`) and `[DVec3; 4]`, `[V3<f64>; 4]` or `[[f64; 3]; 4]` (giving `V3<f64x4>`);
    /// see [`LaneArray`]. The lane type follows from the array, so `V3::from_lanes([v; 8])`
    /// needs no annotation. The inverse is `to_lanes` (below) or [`V3::lane`].
    ///
    /// ```
    /// use brdf::V3;
    /// use brdf::glam::Vec3;
    ///
    /// let dirs: [Vec3; 8] = core::array::from_fn(|i| Vec3::new(0.0, 0.1 * i as f32, 1.0));
    /// let v = V3::from_lanes(dirs);
    /// assert_eq!(Vec3::from(v.lane(3)), dirs[3]);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_lanes(lanes: impl LaneArray<T>) -> Self {
        lanes.into()
    }

    /// `[x, y, z]`.
    #[inline]
    #[must_use]
    pub fn to_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }

    /// Applies `f` to each component: `(f(x), f(y), f(z))`.
    ///
    /// ```
    /// use brdf::{Real, V3};
    /// let c = V3::new(0.25_f64, 1.0, 4.0).map(Real::sqrt);
    /// assert_eq!(c, V3::new(0.5, 1.0, 2.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn map<U>(self, mut f: impl FnMut(T) -> U) -> V3<U> {
        V3 {
            x: f(self.x),
            y: f(self.y),
            z: f(self.z),
        }
    }

    /// Applies `f` to the matching components of `self` and `o`:
    /// `(f(x, o.x), f(y, o.y), f(z, o.z))`.
    ///
    /// ```
    /// use brdf::{Real, V3};
    /// let base = V3::new(2.0_f32, 3.0, 4.0);
    /// let p = base.zip_map(V3::new(2.0, 1.0, 0.5), Real::pow);
    /// assert_eq!(p, V3::new(4.0, 3.0, 2.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn zip_map<U, R>(self, o: V3<U>, mut f: impl FnMut(T, U) -> R) -> V3<R> {
        V3 {
            x: f(self.x, o.x),
            y: f(self.y, o.y),
            z: f(self.z, o.z),
        }
    }

    /// Component-wise minimum with [`Real::min`]'s NaN rule: a NaN component of `self`
    /// propagates, a NaN component of `o` is ignored.
    ///
    /// ```
    /// use brdf::V3;
    /// let v = V3::new(1.0_f32, 5.0, -2.0).min(V3::splat(0.0));
    /// assert_eq!(v, V3::new(0.0, 0.0, -2.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn min(self, o: Self) -> Self {
        self.zip_map(o, T::min)
    }

    /// Component-wise maximum with [`Real::max`]'s NaN rule: a NaN component of `self`
    /// propagates, a NaN component of `o` is ignored.
    ///
    /// ```
    /// use brdf::V3;
    /// let v = V3::new(1.0_f32, 5.0, -2.0).max(V3::splat(0.0));
    /// assert_eq!(v, V3::new(1.0, 5.0, 0.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn max(self, o: Self) -> Self {
        self.zip_map(o, T::max)
    }

    /// The smallest component; NaN if any component is NaN (a reduction has no argument to
    /// ignore, so unlike [`V3::min`] no NaN is skipped).
    ///
    /// ```
    /// use brdf::V3;
    /// assert_eq!(V3::new(1.0_f32, 5.0, -2.0).min_element(), -2.0);
    /// assert!(V3::new(1.0_f32, f32::NAN, -2.0).min_element().is_nan());
    /// ```
    #[inline]
    #[must_use]
    pub fn min_element(self) -> T {
        crate::domain::nan_where(any_nan3(self), self.x.min(self.y).min(self.z))
    }

    /// The largest component (the peak of a colour); NaN if any component is NaN.
    ///
    /// ```
    /// use brdf::V3;
    /// assert_eq!(V3::new(1.0_f32, 5.0, -2.0).max_element(), 5.0);
    /// assert!(V3::new(1.0_f32, 5.0, f32::NAN).max_element().is_nan());
    /// ```
    #[inline]
    #[must_use]
    pub fn max_element(self) -> T {
        crate::domain::nan_where(any_nan3(self), self.x.max(self.y).max(self.z))
    }

    /// Component-wise absolute value.
    #[inline]
    #[must_use]
    pub fn abs(self) -> Self {
        self.map(T::abs)
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

    /// The unit vector `self / |self|` for any finite non-zero `self`, from subnormal components
    /// to the largest finite ones: the vector is first divided by its largest component
    /// magnitude m = max(|x|, |y|, |z|) (exact for m a power of two, one rounding otherwise),
    /// so |self|^2 can neither overflow nor underflow (`normalize_or` forms it directly, and
    /// takes its fallback where it overflows, above about 1.8e19 in `f32`). Five roundings,
    /// each at most 2^-24 (2^-53) relative, bound each component's error by 5 ULP of its own
    /// binade and 2.5 eps absolute; measured: 2.7 ULP and 1.2 eps over 4e5 `f32` vectors across
    /// the whole exponent range (`cargo test --test lanes vec3_ergonomics::normalize --
    /// --nocapture`).
    ///
    /// The zero vector has no direction and gives the zero vector (finite input, finite
    /// output); a NaN component gives NaN in all three, and so does an infinite one (inf / inf,
    /// as IEEE arithmetic has it: `V3`'s helpers are arithmetic, not kernels).
    ///
    /// ```
    /// use brdf::V3;
    /// let huge = 2f32.powi(100); // |v|^2 = 25 * 2^200 overflows f32
    /// let v = V3::new(3.0 * huge, 4.0 * huge, 0.0);
    /// assert_eq!(v.normalize(), V3::new(0.6, 0.8, 0.0));
    /// assert_eq!(v.normalize_or(V3::unit_z()), V3::unit_z()); // normalize_or's fallback
    /// assert_eq!(V3::new(0.0_f32, 0.0, 0.0).normalize(), V3::splat(0.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn normalize(self) -> Self {
        let m = self.abs().max_element();
        let s = self / m;
        let u = s / s.length();
        Self::select(m.simd_eq(T::ZERO), Self::splat(T::ZERO), u)
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

    /// The mirror direction of `self` about the unit normal `n`, both pointing away from the
    /// surface (the microfacet convention of this crate and of pbrt-v4's `Reflect`):
    /// `2 (self . n) n - self`.
    ///
    /// Not glam's or GLSL's `reflect`, which takes an incident direction pointing *towards*
    /// the surface and returns `i - 2 (i . n) n`: `v.mirror(n)` equals glam's
    /// `(-v).reflect(n)` and `-(v.reflect(n))`.
    ///
    /// ```
    /// use brdf::V3;
    /// use brdf::glam::Vec3;
    ///
    /// let (wo, n) = (Vec3::new(0.6, 0.0, 0.8), Vec3::Z);
    /// let wi = V3::from(wo).mirror(V3::from(n));
    /// assert_eq!(Vec3::from(wi), Vec3::new(-0.6, 0.0, 0.8));
    /// assert_eq!(Vec3::from(wi), (-wo).reflect(n));
    /// ```
    #[inline]
    #[must_use]
    pub fn mirror(self, n: Self) -> Self {
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

    /// Lane `i` as a scalar vector (`i < T::LANES`; scalars return themselves for any `i`).
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

/// Component-wise product (the Hadamard product: a colour times a colour).
impl<T: Real> Mul for V3<T> {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        Self::new(self.x * o.x, self.y * o.y, self.z * o.z)
    }
}

/// Every component times `s`.
impl<T: Real> Mul<T> for V3<T> {
    type Output = Self;
    #[inline]
    fn mul(self, s: T) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

/// Component-wise quotient.
impl<T: Real> Div for V3<T> {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        Self::new(self.x / o.x, self.y / o.y, self.z / o.z)
    }
}

/// Every component divided by `s` (a true division per component, not a multiplication by a
/// rounded `1 / s`).
impl<T: Real> Div<T> for V3<T> {
    type Output = Self;
    #[inline]
    fn div(self, s: T) -> Self {
        Self::new(self.x / s, self.y / s, self.z / s)
    }
}

impl<T: Real> AddAssign for V3<T> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl<T: Real> SubAssign for V3<T> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}

impl<T: Real> MulAssign for V3<T> {
    #[inline]
    fn mul_assign(&mut self, o: Self) {
        *self = *self * o;
    }
}

impl<T: Real> MulAssign<T> for V3<T> {
    #[inline]
    fn mul_assign(&mut self, s: T) {
        *self = *self * s;
    }
}

impl<T: Real> DivAssign for V3<T> {
    #[inline]
    fn div_assign(&mut self, o: Self) {
        *self = *self / o;
    }
}

impl<T: Real> DivAssign<T> for V3<T> {
    #[inline]
    fn div_assign(&mut self, s: T) {
        *self = *self / s;
    }
}

// `s * v` cannot be one generic impl (`impl<T> Mul<V3<T>> for T` is an orphan), so one per
// component type.
macro_rules! impl_scalar_times_v3 {
    ($($t:ty),*) => {$(
        /// `s * v`: every component of `v` times `s` (the same as `v * s`).
        impl Mul<V3<$t>> for $t {
            type Output = V3<$t>;
            #[inline]
            fn mul(self, v: V3<$t>) -> V3<$t> {
                V3::new(self * v.x, self * v.y, self * v.z)
            }
        }
    )*};
}
impl_scalar_times_v3!(f32, f64, f32x8, f64x4);

impl<T: Real> From<[T; 3]> for V3<T> {
    #[inline]
    fn from([x, y, z]: [T; 3]) -> Self {
        Self::new(x, y, z)
    }
}

impl<T: Real> From<V3<T>> for [T; 3] {
    #[inline]
    fn from(v: V3<T>) -> Self {
        v.to_array()
    }
}

// Scalar glam conversions, both ways.
macro_rules! impl_glam_scalar {
    ($t:ty, $($g:ty),*) => {$(
        impl From<$g> for V3<$t> {
            #[inline]
            fn from(v: $g) -> Self {
                Self::new(v.x, v.y, v.z)
            }
        }
        impl From<V3<$t>> for $g {
            #[inline]
            fn from(v: V3<$t>) -> Self {
                <$g>::new(v.x, v.y, v.z)
            }
        }
    )*};
}
impl_glam_scalar!(f32, Vec3, Vec3A);
impl_glam_scalar!(f64, DVec3);

/// One scalar vector per lane of `T`, in lane order: the arrays [`V3::from_lanes`] transposes.
///
/// | array | `T` |
/// |---|---|
/// | `[Vec3; 8]`, `[Vec3A; 8]`, `[V3<f32>; 8]`, `[[f32; 3]; 8]` | `f32x8` |
/// | `[DVec3; 4]`, `[V3<f64>; 4]`, `[[f64; 3]; 4]` | `f64x4` |
///
/// Each also converts with `From`/`Into` in both directions (`V3<f32x8>` into `[Vec3; 8]`
/// and so on).
pub trait LaneArray<T: Real>: Into<V3<T>> {
    // A marker: the conversion itself is the `Into` (`From`) implementation.
}

macro_rules! impl_lane_array {
    ($lanes:ident, $s:ty, $n:literal, $($g:ty),*) => {$(
        impl LaneArray<$lanes> for [$g; $n] {}
        impl From<[$g; $n]> for V3<$lanes> {
            #[inline]
            fn from(v: [$g; $n]) -> Self {
                let v = v.map(V3::<$s>::from);
                Self::new(
                    $lanes::new(v.map(|p| p.x)),
                    $lanes::new(v.map(|p| p.y)),
                    $lanes::new(v.map(|p| p.z)),
                )
            }
        }
        impl From<V3<$lanes>> for [$g; $n] {
            #[inline]
            fn from(v: V3<$lanes>) -> Self {
                let (x, y, z) = (v.x.to_array(), v.y.to_array(), v.z.to_array());
                core::array::from_fn(|i| V3::<$s>::new(x[i], y[i], z[i]).into())
            }
        }
    )*};
}
impl_lane_array!(f32x8, f32, 8, Vec3, Vec3A, V3<f32>, [f32; 3]);
impl_lane_array!(f64x4, f64, 4, DVec3, V3<f64>, [f64; 3]);

impl V3<f32x8> {
    /// The eight lanes as glam vectors (array of structures): element `i` is lane `i`. The
    /// inverse of [`V3::from_lanes`]; for `[Vec3A; 8]`, `[V3<f32>; 8]` or `[[f32; 3]; 8]`
    /// use `into()`.
    #[inline]
    #[must_use]
    pub fn to_lanes(self) -> [Vec3; 8] {
        self.into()
    }
}

impl V3<f64x4> {
    /// The four lanes as glam vectors: element `i` is lane `i`. The inverse of
    /// [`V3::from_lanes`]; for `[V3<f64>; 4]` or `[[f64; 3]; 4]` use `into()`.
    #[inline]
    #[must_use]
    pub fn to_lanes(self) -> [DVec3; 4] {
        self.into()
    }
}

/// True in lanes where any component of `v` is NaN.
#[inline]
#[must_use]
pub(crate) fn any_nan3<T: Real>(v: V3<T>) -> T::Mask {
    v.x.is_nan() | v.y.is_nan() | v.z.is_nan()
}

/// True in lanes where any component of `v` is NaN or infinite: the guard of every kernel that
/// takes a direction, a normal or a colour (crate docs, "Bad input", rules 1 and 5). A
/// direction (inf, 0, 1) has no one meaning, so it gives NaN like a NaN component; the `V3`
/// arithmetic helpers keep [`any_nan3`] and IEEE arithmetic.
#[inline]
#[must_use]
pub(crate) fn any_nonfinite3<T: Real>(v: V3<T>) -> T::Mask {
    !(v.x.is_finite() & v.y.is_finite() & v.z.is_finite())
}

/// True in lanes where `v` is the zero vector (every component +-0).
#[inline]
#[must_use]
#[allow(dead_code)] // used by the microfacet, sampling, material and IBL features
pub(crate) fn is_zero3<T: Real>(v: V3<T>) -> T::Mask {
    v.x.simd_eq(T::ZERO) & v.y.simd_eq(T::ZERO) & v.z.simd_eq(T::ZERO)
}

/// `v`, or the horizon direction +x where `v` is the zero vector. A zero-length direction has
/// cosine 0 with the normal, like a horizon direction, and the microfacet terms give it the
/// horizon's value (G1 = 0, the capped Lambda pole) instead of the 0 / 0 of its zero
/// components: finite input, finite output (crate docs, "Bad input", rule 5's last sentence).
#[inline]
#[must_use]
#[allow(dead_code)] // used by the microfacet, sampling, material and IBL features
pub(crate) fn horizon_if_zero3<T: Real>(v: V3<T>) -> V3<T> {
    V3::select(is_zero3(v), V3::new(T::ONE, T::ZERO, T::ZERO), v)
}
