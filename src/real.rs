//! The float/lane abstraction every kernel is written against.
//!
//! [`Real`] is implemented for `f32`, `f64`, [`f32x8`] and [`f64x4`] (eight `f32` and four
//! `f64` lanes, from the [`wide`] crate, re-exported as `brdf::wide`). A kernel written once
//! as `fn d<T: Real>(n_dot_h: T, alpha: T) -> T` runs on one value or on eight lanes at a
//! time. Branches on lane values become [`Real::select`] on a [`Mask`] (`bool` for scalars,
//! an all-ones/all-zeros lane mask for SIMD types). The trait is sealed: those four types are
//! its only implementations (the kernels rely on crate-internal operations of each).
//!
//! [`f32x8`]: https://docs.rs/wide/1/wide/struct.f32x8.html
//! [`f64x4`]: https://docs.rs/wide/1/wide/struct.f64x4.html
//! [`wide`]: https://docs.rs/wide/1/wide/
//!
//! # Making lane values: wide's methods and two `splat`s
//! Three of `wide`'s own methods are all a user of this crate needs from it:
//! - `f32x8::new([f32; 8])` / `f64x4::new([f64; 4])`: one value per lane;
//! - `f32x8::splat(x: f32)` / `f64x4::splat(x: f64)`: `x` in every lane, `x` of the lane
//!   type;
//! - `v.to_array()`: the lanes back as an array (or [`Real::lane`] for one of them).
//!
//! `Real` has a `splat` of its own, [`Real::splat`]`(x: f64)`, which takes an `f64` on every
//! implementing type and rounds it to the lane type, so that generic code can write literals
//! and constants once. The two share a name, and on a concrete lane type `f32x8::splat(x)`
//! resolves to `wide`'s (inherent methods win over trait methods), which takes an `f32`:
//!
//! | you write | in | meaning |
//! |---|---|---|
//! | `T::splat(0.5)` | generic code, `T: Real` | [`Real::splat`]: `0.5_f64` rounded to `T`'s lanes |
//! | `f32x8::splat(0.5)` | concrete code | `wide`'s: `0.5_f32` in every lane |
//! | `f32x8::from_f64(alpha)` | concrete code, `alpha: f64` | [`Real::from_f64`]: the same as `Real::splat` under a name `wide` does not use |
//! | `T::from_scalar(x)` | generic code, `x: T::Scalar` | [`Real::from_scalar`]: `x` in every lane, no rounding |
//!
//! ```
//! use brdf::Real;
//! use brdf::wide::f32x8;
//!
//! fn half<T: Real>() -> T {
//!     T::splat(0.5) // Real::splat: takes f64 on every T
//! }
//! let alpha: f64 = 0.25;
//! let a = f32x8::from_f64(alpha); // f64 into f32 lanes (Real)
//! let b = f32x8::splat(0.25); // f32 literal (wide)
//! assert_eq!(a, b);
//! assert_eq!(half::<f32x8>(), f32x8::splat(0.5));
//! assert_eq!(f32x8::new([1.0; 8]).to_array(), [1.0; 8]);
//! ```
//!
//! # Semantics shared by every implementation
//! - `min`/`max`: `a.max(b)` is `b` where `a < b` and `a` otherwise, so a NaN in `self`
//!   propagates and a NaN in the argument is ignored. `clamp(x, lo, hi)` therefore returns
//!   NaN for a NaN `x` on every path (the lane instructions `minps`/`maxps` and `libm::fmin`
//!   disagree on NaN; this definition is the same everywhere).
//! - `recip` is the correctly rounded `1 / x` (not the 12-bit `rcpps` estimate).
//! - `mul_add(a, b)` is `self * a + b`, fused when the target has FMA (`target_feature =
//!   "fma"` on x86, NEON on aarch64) and two roundings otherwise, identically for scalar and
//!   lane types on one target. On scalars it compiles to the fused instruction inline (through
//!   `wide`'s 128-bit types, not `libm::fmaf`, which is a call that picks its implementation at
//!   run time), and `sqrt` to `sqrtss` / `sqrtsd`: a build with `-C target-cpu=native` is never
//!   slower on scalars than the default build.
//!
//! # Accuracy of the lane paths
//! Scalar paths call `libm` (correctly rounded or within 1 ULP for the functions used). Lane
//! paths use `wide`'s polynomials where they are accurate and fall back to `libm` per lane
//! where they are not. The bound of each lane function against the scalar one, over its whole
//! domain including 0, subnormals, huge values and infinities, is listed on the method and
//! enforced by `tests/lanes/vs_scalar.rs`:
//!
//! | function | f32x8 vs f32 | f64x4 vs f64 | lane implementation |
//! |---|---|---|---|
//! | `sqrt`, `recip`, `abs`, `floor`, `min`, `max`, `copysign`, `mul_add` | 0 ULP | 0 ULP | IEEE instructions |
//! | `exp` | 1 ULP | 2 ULP | `wide` polynomial (f32: the same operations, bit-identical, without its data-dependent branches) |
//! | `exp_ftz` | 1 ULP | 2 ULP | `exp` with results below `MIN_POSITIVE` flushed to 0 (f32: no subnormal intermediate for normal inputs; `tests/lanes/exp.rs` checks the definition bit for bit and reads the x86 flags) |
//! | `exp2` | 1 ULP | 0 ULP | `wide` polynomial (f32), `libm` per lane (f64: `wide` is 1901 ULP off) |
//! | `ln` | 1 ULP | 1 ULP | `wide` polynomial, subnormals rescaled, negatives give NaN |
//! | `sin`, `cos` | 1 ULP | 1 ULP | `wide` polynomial for \|x\| <= 1e3, `libm` per lane beyond |
//! | `atan` | 3 ULP | 1 ULP | `wide` polynomial |
//! | `atan2` | 3 ULP | 2 ULP | `wide` polynomial |
//! | `acos` | 1 ULP | 2 ULP | `wide` polynomial |
//! | `asin` | 2 ULP | 2 ULP | `wide` polynomial |
//! | `pow`, `erf`, `erfc`, `tan` | 0 ULP | 0 ULP | `libm` per lane |
//!
//! Measured over about 2.2 million inputs per type (every 4099th f32 bit pattern, every
//! (2^43 + 1)th f64 one, the specials and a dense sweep of [-10, 10]):
//! `cargo test --test lanes vs_scalar:: -- --nocapture`.
//!
//! `pow` maps to `libm` per lane because an `exp(y ln x)` polynomial loses `|y ln x|` ULP,
//! which is thousands of ULP for the Phong exponents (10^4) this crate feeds it.

use core::fmt::Debug;
use core::ops::{
    Add, AddAssign, BitAnd, BitOr, Div, DivAssign, Mul, MulAssign, Neg, Not, Sub, SubAssign,
};
use wide::{f32x8, f64x4};

/// A lane mask: the result of a comparison, consumed by [`Real::select`].
///
/// `bool` for scalar types; for SIMD types, a vector whose lanes are all ones (true) or all
/// zeros (false).
pub trait Mask:
    Copy + Debug + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self>
{
    /// True when at least one lane is set.
    fn any(self) -> bool;
    /// True when every lane is set.
    fn all(self) -> bool;
}

impl Mask for bool {
    #[inline]
    fn any(self) -> bool {
        self
    }
    #[inline]
    fn all(self) -> bool {
        self
    }
}

impl Mask for f32x8 {
    #[inline]
    fn any(self) -> bool {
        f32x8::any(self)
    }
    #[inline]
    fn all(self) -> bool {
        f32x8::all(self)
    }
}

impl Mask for f64x4 {
    #[inline]
    fn any(self) -> bool {
        f64x4::any(self)
    }
    #[inline]
    fn all(self) -> bool {
        f64x4::all(self)
    }
}

/// A real number type, scalar (`f32`, `f64`) or a SIMD vector of lanes (`f32x8`, `f64x4`).
///
/// Every kernel in this crate is generic over `Real`. See the [module docs](self) for the
/// shared NaN semantics and the accuracy table of the lane paths.
///
/// Implemented for `f32`, `f64`, `wide::f32x8` and `wide::f64x4` (all foreign types, so
/// rustdoc's "Implementors" list below stays empty); a kernel generic over `T: Real` accepts
/// exactly these four.
///
/// On a concrete `f32` or `f64` the inherent methods of the same name win over this trait's:
/// `a.min(b)` on two `f32`s is `f32::min`, which ignores a NaN on either side, while
/// `Real::min` (what generic code calls) propagates a NaN in `self`. Write
/// `Real::min(a, b)` in concrete code that must behave as the kernels do; the same holds for
/// `max`, `clamp`, `mul_add` (std's is always fused) and `splat` (see the module docs).
///
/// On a concrete `f32x8` the same shadowing changes accuracy: `wide`'s inherent `recip` is
/// the 12-bit `rcpps` estimate on AVX (relative error up to 3.7e-4), and its `exp`, `ln` and
/// `powf` are its own polynomials. `s.length().recip()` in a closure over `f32x8` lanes is
/// that estimate, and a half vector normalized with it put a rough conductor 1e5 ULP off
/// (about 1%); write `Real::recip(x)` (or `T::ONE / x`), `Real::exp(x)` and so on there.
pub trait Real:
    sealed::Sealed
    + Copy
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + 'static
{
    /// The type of one lane: `f32` for `f32` and `f32x8`, `f64` for `f64` and `f64x4`.
    type Scalar: Real<Scalar = Self::Scalar, Mask = bool> + PartialOrd + Into<f64>;
    /// The result of a comparison.
    type Mask: Mask;

    /// Number of lanes (1 for scalars).
    const LANES: usize;
    /// The value zero, `0`, in every lane.
    const ZERO: Self;
    /// The value one, `1`, in every lane.
    const ONE: Self;
    /// The value one half, `1/2`, in every lane.
    const HALF: Self;
    /// The value two, `2`, in every lane.
    const TWO: Self;
    /// The value pi in every lane, rounded to the lane type.
    const PI: Self;
    /// The value `1/pi` in every lane, rounded to the lane type.
    const FRAC_1_PI: Self;
    /// Machine epsilon of the lane type (2^-23 for f32, 2^-52 for f64).
    const EPSILON: Self;
    /// Smallest positive normal value of the lane type.
    const MIN_POSITIVE: Self;
    /// Largest finite value of the lane type.
    const MAX: Self;
    /// Positive infinity.
    const INFINITY: Self;

    /// Every lane set to `v`, rounded to the lane type: the way to write a literal or a
    /// constant once in generic code (`T::splat(0.5)`).
    ///
    /// Takes an `f64` on every type. On a concrete `f32x8` or `f64x4`, `f32x8::splat(x)`
    /// names `wide`'s inherent `splat`, which takes the lane type (`f32`) instead; there,
    /// write [`Real::from_f64`] for an `f64` (see the [module docs](self)).
    fn splat(v: f64) -> Self;
    /// Every lane set to `v`, rounded to the lane type: [`Real::splat`] under a name that
    /// `wide`'s SIMD types do not shadow, so `f32x8::from_f64(alpha)` needs no
    /// `<f32x8 as Real>::` qualification.
    #[inline]
    #[must_use]
    fn from_f64(v: f64) -> Self {
        Self::splat(v)
    }
    /// Every lane set to `v`, exactly (no rounding: `v` is already of the lane type).
    fn from_scalar(v: Self::Scalar) -> Self;
    /// Builds a value lane by lane: lane `i` is `f(i)`.
    fn from_fn(f: impl FnMut(usize) -> Self::Scalar) -> Self;
    /// Lane `i` (`i < LANES`; lane 0 for out-of-range indices on scalars).
    fn lane(self, i: usize) -> Self::Scalar;

    /// Lane-wise `self < o` (false where either is NaN).
    fn simd_lt(self, o: Self) -> Self::Mask;
    /// Lane-wise `self <= o` (false where either is NaN).
    fn simd_le(self, o: Self) -> Self::Mask;
    /// Lane-wise `self > o` (false where either is NaN).
    fn simd_gt(self, o: Self) -> Self::Mask;
    /// Lane-wise `self >= o` (false where either is NaN).
    fn simd_ge(self, o: Self) -> Self::Mask;
    /// Lane-wise `self == o` (false where either is NaN).
    fn simd_eq(self, o: Self) -> Self::Mask;
    /// Lane-wise NaN test.
    fn is_nan(self) -> Self::Mask;
    /// Lane-wise test for a finite value (not NaN, not infinite).
    fn is_finite(self) -> Self::Mask;
    /// Lane-wise `if m { t } else { f }`.
    fn select(m: Self::Mask, t: Self, f: Self) -> Self;

    /// `o` where `self > o`, else `self`: NaN in `self` propagates, NaN in `o` is ignored.
    fn min(self, o: Self) -> Self;
    /// `o` where `self < o`, else `self`: NaN in `self` propagates, NaN in `o` is ignored.
    fn max(self, o: Self) -> Self;
    /// `self.max(lo).min(hi)`; NaN propagates. Requires `lo <= hi`.
    #[inline]
    fn clamp(self, lo: Self, hi: Self) -> Self {
        self.max(lo).min(hi)
    }
    /// `clamp(self, 0, 1)`; NaN propagates.
    #[inline]
    fn saturate(self) -> Self {
        self.clamp(Self::ZERO, Self::ONE)
    }
    /// `self * a + b`, fused when the target has FMA (one instruction, inline; see the module
    /// docs).
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// Square root, correctly rounded; NaN for negative input.
    fn sqrt(self) -> Self;
    /// `sqrt(max(self, 0))`: the square root of a quantity that is non-negative in exact
    /// arithmetic but may round slightly below zero. NaN propagates.
    #[inline]
    fn sqrt_nonneg(self) -> Self {
        self.max(Self::ZERO).sqrt()
    }
    /// `1 / self`, correctly rounded.
    fn recip(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// `|self|` with the sign bit of `sign`.
    fn copysign(self, sign: Self) -> Self;
    /// Largest integer not above `self`.
    fn floor(self) -> Self;
    /// e^self. Lanes: within 1 ULP (f32x8) / 2 ULP (f64x4) of the scalar path.
    fn exp(self) -> Self;
    /// e^self with every result below the smallest normal number ([`Real::MIN_POSITIVE`])
    /// flushed to 0, and otherwise equal to [`Real::exp`] bit for bit.
    ///
    /// For kernels whose arguments run far into the tail (a Beckmann lobe at grazing angles):
    /// on f32x8, for normal inputs and 0, no lane ever meets a subnormal number, which on x86
    /// costs a microcode assist of about a hundred cycles per instruction
    /// (`tests/lanes/exp.rs` reads the x86 flags that record one). Inputs: any; NaN gives NaN,
    /// +inf gives +inf, -inf gives 0. Error of the flush: results in (0, MIN_POSITIVE) become
    /// 0, an absolute error below 1.2e-38 (f32) / 2.3e-308 (f64).
    fn exp_ftz(self) -> Self;
    /// 2^self. Lanes: within 1 ULP (f32x8) / 0 ULP (f64x4) of the scalar path.
    fn exp2(self) -> Self;
    /// Natural logarithm; -inf at 0, NaN below 0. Lanes: within 1 ULP of the scalar path.
    fn ln(self) -> Self;
    /// `self^e` with C99 `pow` semantics. Lanes: `libm` per lane, identical to scalar.
    fn pow(self, e: Self) -> Self;
    /// The error function. Lanes: `libm` per lane, identical to scalar.
    fn erf(self) -> Self;
    /// The complementary error function 1 - erf(x), accurate where erf(x) is near 1. Lanes:
    /// `libm` per lane, identical to scalar.
    fn erfc(self) -> Self;
    /// Sine. Lanes: within 1 ULP of the scalar path for every input.
    fn sin(self) -> Self;
    /// Cosine. Lanes: within 1 ULP of the scalar path for every input.
    fn cos(self) -> Self;
    /// Tangent. Lanes: `libm` per lane, identical to scalar.
    fn tan(self) -> Self;
    /// Arc tangent, in [-pi/2, pi/2]. Lanes: within 3 ULP (f32x8) / 1 ULP (f64x4).
    fn atan(self) -> Self;
    /// Four-quadrant arc tangent of `self / x`, in [-pi, pi]. Lanes: within 3 ULP (f32x8) / 2 ULP (f64x4).
    fn atan2(self, x: Self) -> Self;
    /// Arc cosine, in [0, pi]; NaN outside [-1, 1]. Lanes: within 1 ULP (f32x8) / 2 ULP (f64x4).
    fn acos(self) -> Self;
    /// Arc sine, in [-pi/2, pi/2]; NaN outside [-1, 1]. Lanes: within 2 ULP.
    fn asin(self) -> Self;

    /// Applies an f64 function lane by lane (each lane widened to f64, the result rounded back):
    /// for the few functions whose accuracy needs f64 arithmetic and that are scalar per lane
    /// anyway (they call `libm::pow`), such as the sRGB transfer pair.
    fn map_f64(self, f: fn(f64) -> f64) -> Self;

    /// `self^n` for a small non-negative integer `n` by repeated squaring: exact-ish and far
    /// cheaper than [`Real::pow`] (Schlick's `(1 - c)^5` uses it).
    #[inline]
    fn powi(self, n: u32) -> Self {
        let mut base = self;
        let mut acc = Self::ONE;
        let mut k = n;
        while k > 0 {
            if k & 1 == 1 {
                acc *= base;
            }
            base *= base;
            k >>= 1;
        }
        acc
    }
    /// `self * self`.
    #[inline]
    fn sq(self) -> Self {
        self * self
    }
}

// Scalar fused multiply-add and square root as single instructions. `libm::fmaf` is a call
// (on x86_64 one that picks its implementation at run time through a function pointer), and
// `libm::sqrtf` a call that is not inlined across crates; `wide`'s 128-bit types wrap the
// instructions in safe, always-inlined functions, and LLVM narrows a splat, one lane
// operation and the extraction of lane 0 to the scalar instruction (`vfmadd213ss`, `sqrtss`).
// Without FMA the multiply-add is `a * b + c`, two roundings, exactly as before and as the
// lanes do on such targets (`tests/lanes/vs_scalar.rs`); `tests/lanes/scalar_instructions.rs`
// checks both against their definitions.

/// a b + c, fused where the target has FMA (x86 with `fma`, aarch64 with NEON).
#[inline(always)]
fn fma_f32(a: f32, b: f32, c: f32) -> f32 {
    #[cfg(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    ))]
    {
        use wide::f32x4;
        f32x4::splat(a)
            .mul_add(f32x4::splat(b), f32x4::splat(c))
            .to_array()[0]
    }
    #[cfg(not(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    )))]
    {
        a * b + c
    }
}

/// a b + c on f64, as [`fma_f32`].
#[inline(always)]
fn fma_f64(a: f64, b: f64, c: f64) -> f64 {
    #[cfg(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    ))]
    {
        use wide::f64x2;
        f64x2::splat(a)
            .mul_add(f64x2::splat(b), f64x2::splat(c))
            .to_array()[0]
    }
    #[cfg(not(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    )))]
    {
        a * b + c
    }
}

/// The correctly rounded square root as one instruction where the target has one in `wide`
/// (SSE, NEON); `libm::sqrtf` elsewhere.
#[inline(always)]
fn sqrt_f32(x: f32) -> f32 {
    #[cfg(any(
        target_feature = "sse",
        all(target_arch = "aarch64", target_feature = "neon")
    ))]
    {
        wide::f32x4::splat(x).sqrt().to_array()[0]
    }
    #[cfg(not(any(
        target_feature = "sse",
        all(target_arch = "aarch64", target_feature = "neon")
    )))]
    {
        libm::sqrtf(x)
    }
}

/// [`sqrt_f32`] on f64 (SSE2, NEON).
#[inline(always)]
fn sqrt_f64(x: f64) -> f64 {
    #[cfg(any(
        target_feature = "sse2",
        all(target_arch = "aarch64", target_feature = "neon")
    ))]
    {
        wide::f64x2::splat(x).sqrt().to_array()[0]
    }
    #[cfg(not(any(
        target_feature = "sse2",
        all(target_arch = "aarch64", target_feature = "neon")
    )))]
    {
        libm::sqrt(x)
    }
}

macro_rules! impl_real_scalar {
    ($t:ident, $bits:literal, $exp:path, $exp2:path, $ln:path, $pow:path, $erf:path, $sin:path,
     $cos:path, $tan:path, $atan:path, $atan2:path, $acos:path, $asin:path, $sqrt:path,
     $fma:path, $copysign:path, $floor:path, $erfc:path) => {
        impl Real for $t {
            type Scalar = $t;
            type Mask = bool;
            const LANES: usize = 1;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const HALF: Self = 0.5;
            const TWO: Self = 2.0;
            const PI: Self = core::$t::consts::PI;
            const FRAC_1_PI: Self = core::$t::consts::FRAC_1_PI;
            const EPSILON: Self = $t::EPSILON;
            const MIN_POSITIVE: Self = $t::MIN_POSITIVE;
            const MAX: Self = $t::MAX;
            const INFINITY: Self = $t::INFINITY;

            #[inline]
            fn splat(v: f64) -> Self {
                v as $t
            }
            #[inline]
            fn from_scalar(v: Self) -> Self {
                v
            }
            #[inline]
            fn from_fn(mut f: impl FnMut(usize) -> Self) -> Self {
                f(0)
            }
            #[inline]
            fn lane(self, _i: usize) -> Self {
                self
            }
            #[inline]
            fn map_f64(self, f: fn(f64) -> f64) -> Self {
                f(self as f64) as $t
            }
            #[inline]
            fn simd_lt(self, o: Self) -> bool {
                self < o
            }
            #[inline]
            fn simd_le(self, o: Self) -> bool {
                self <= o
            }
            #[inline]
            fn simd_gt(self, o: Self) -> bool {
                self > o
            }
            #[inline]
            fn simd_ge(self, o: Self) -> bool {
                self >= o
            }
            #[inline]
            fn simd_eq(self, o: Self) -> bool {
                self == o
            }
            #[inline]
            fn is_nan(self) -> bool {
                $t::is_nan(self)
            }
            #[inline]
            fn is_finite(self) -> bool {
                $t::is_finite(self)
            }
            #[inline]
            fn select(m: bool, t: Self, f: Self) -> Self {
                if m { t } else { f }
            }
            #[inline]
            fn min(self, o: Self) -> Self {
                if self > o { o } else { self }
            }
            #[inline]
            fn max(self, o: Self) -> Self {
                if self < o { o } else { self }
            }
            #[inline]
            fn mul_add(self, a: Self, b: Self) -> Self {
                $fma(self, a, b)
            }
            #[inline]
            fn sqrt(self) -> Self {
                $sqrt(self)
            }
            #[inline]
            fn recip(self) -> Self {
                1.0 / self
            }
            #[inline]
            fn abs(self) -> Self {
                $t::from_bits(self.to_bits() & !(1 << ($bits - 1)))
            }
            #[inline]
            fn copysign(self, sign: Self) -> Self {
                $copysign(self, sign)
            }
            #[inline]
            fn floor(self) -> Self {
                $floor(self)
            }
            #[inline]
            fn exp(self) -> Self {
                $exp(self)
            }
            #[inline]
            fn exp_ftz(self) -> Self {
                let e = $exp(self);
                if e < $t::MIN_POSITIVE { 0.0 } else { e }
            }
            #[inline]
            fn exp2(self) -> Self {
                $exp2(self)
            }
            #[inline]
            fn ln(self) -> Self {
                $ln(self)
            }
            #[inline]
            fn pow(self, e: Self) -> Self {
                $pow(self, e)
            }
            #[inline]
            fn erf(self) -> Self {
                $erf(self)
            }
            #[inline]
            fn erfc(self) -> Self {
                $erfc(self)
            }
            #[inline]
            fn sin(self) -> Self {
                $sin(self)
            }
            #[inline]
            fn cos(self) -> Self {
                $cos(self)
            }
            #[inline]
            fn tan(self) -> Self {
                $tan(self)
            }
            #[inline]
            fn atan(self) -> Self {
                $atan(self)
            }
            #[inline]
            fn atan2(self, x: Self) -> Self {
                $atan2(self, x)
            }
            #[inline]
            fn acos(self) -> Self {
                $acos(self)
            }
            #[inline]
            fn asin(self) -> Self {
                $asin(self)
            }
        }
    };
}

impl_real_scalar!(
    f32,
    32,
    libm::expf,
    libm::exp2f,
    libm::logf,
    libm::powf,
    libm::erff,
    libm::sinf,
    libm::cosf,
    libm::tanf,
    libm::atanf,
    libm::atan2f,
    libm::acosf,
    libm::asinf,
    sqrt_f32,
    fma_f32,
    libm::copysignf,
    libm::floorf,
    libm::erfcf
);
impl_real_scalar!(
    f64,
    64,
    libm::exp,
    libm::exp2,
    libm::log,
    libm::pow,
    libm::erf,
    libm::sin,
    libm::cos,
    libm::tan,
    libm::atan,
    libm::atan2,
    libm::acos,
    libm::asin,
    sqrt_f64,
    fma_f64,
    libm::copysign,
    libm::floor,
    libm::erfc
);

macro_rules! impl_real_lanes {
    ($v:ident, $s:ident, $n:literal, $subnormal_scale_log2:literal) => {
        impl Real for $v {
            type Scalar = $s;
            type Mask = $v;
            const LANES: usize = $n;
            const ZERO: Self = $v::splat(0.0);
            const ONE: Self = $v::splat(1.0);
            const HALF: Self = $v::splat(0.5);
            const TWO: Self = $v::splat(2.0);
            const PI: Self = $v::splat(core::$s::consts::PI);
            const FRAC_1_PI: Self = $v::splat(core::$s::consts::FRAC_1_PI);
            const EPSILON: Self = $v::splat($s::EPSILON);
            const MIN_POSITIVE: Self = $v::splat($s::MIN_POSITIVE);
            const MAX: Self = $v::splat($s::MAX);
            const INFINITY: Self = $v::splat($s::INFINITY);

            #[inline]
            fn splat(v: f64) -> Self {
                $v::splat(v as $s)
            }
            #[inline]
            fn from_scalar(v: $s) -> Self {
                $v::splat(v)
            }
            #[inline]
            fn from_fn(f: impl FnMut(usize) -> $s) -> Self {
                $v::new(core::array::from_fn(f))
            }
            #[inline]
            fn lane(self, i: usize) -> $s {
                self.to_array()[i]
            }
            #[inline]
            fn map_f64(self, f: fn(f64) -> f64) -> Self {
                $v::new(self.to_array().map(|x| f(x as f64) as $s))
            }
            #[inline]
            fn simd_lt(self, o: Self) -> Self {
                $v::simd_lt(self, o)
            }
            #[inline]
            fn simd_le(self, o: Self) -> Self {
                $v::simd_le(self, o)
            }
            #[inline]
            fn simd_gt(self, o: Self) -> Self {
                $v::simd_gt(self, o)
            }
            #[inline]
            fn simd_ge(self, o: Self) -> Self {
                $v::simd_ge(self, o)
            }
            #[inline]
            fn simd_eq(self, o: Self) -> Self {
                $v::simd_eq(self, o)
            }
            #[inline]
            fn is_nan(self) -> Self {
                $v::is_nan(self)
            }
            #[inline]
            fn is_finite(self) -> Self {
                $v::is_finite(self)
            }
            #[inline]
            fn select(m: Self, t: Self, f: Self) -> Self {
                m.select(t, f)
            }
            #[inline]
            fn min(self, o: Self) -> Self {
                // x86's minps(a, b) is `a < b ? a : b`, NaN in either giving b: with a = o,
                // b = self, exactly this method's definition in one instruction (and the
                // same on `wide`'s portable fallback). Elsewhere (NEON's fmin returns NaN for
                // a NaN in either) a compare and a select.
                #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
                {
                    o.fast_min(self)
                }
                #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
                {
                    $v::simd_gt(self, o).select(o, self)
                }
            }
            #[inline]
            fn max(self, o: Self) -> Self {
                // maxps(o, self) = `o > self ? o : self`, NaN in either giving self.
                #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
                {
                    o.fast_max(self)
                }
                #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
                {
                    $v::simd_lt(self, o).select(o, self)
                }
            }
            #[inline]
            fn mul_add(self, a: Self, b: Self) -> Self {
                $v::mul_add(self, a, b)
            }
            #[inline]
            fn sqrt(self) -> Self {
                $v::sqrt(self)
            }
            #[inline]
            fn recip(self) -> Self {
                // Not `wide::recip`: on AVX that is the 12-bit `rcpps` estimate.
                Self::ONE / self
            }
            #[inline]
            fn abs(self) -> Self {
                $v::abs(self)
            }
            #[inline]
            fn copysign(self, sign: Self) -> Self {
                let mag = $v::abs(self);
                sign.is_sign_negative().select(-mag, mag)
            }
            #[inline]
            fn floor(self) -> Self {
                $v::floor(self)
            }
            #[inline]
            fn exp(self) -> Self {
                exp_lanes(self)
            }
            #[inline]
            fn exp_ftz(self) -> Self {
                self.exp_ftz_lanes()
            }
            #[inline]
            fn exp2(self) -> Self {
                exp2_lanes(self)
            }
            #[inline]
            fn ln(self) -> Self {
                // `wide::ln` treats subnormal input as zero (-inf). Rescale those lanes into
                // the normal range first and subtract the scale's logarithm.
                let scale = $v::splat((2.0 as $s).powi($subnormal_scale_log2));
                let tiny = self.simd_gt(Self::ZERO) & self.simd_lt(Self::MIN_POSITIVE);
                let x = tiny.select(self * scale, self);
                let ln_x = $v::ln(x);
                let correction = $v::splat(($subnormal_scale_log2 as $s) * core::$s::consts::LN_2);
                // `wide::ln` also returns -inf for negative subnormals, where C99 says NaN.
                let negative = self.simd_lt(Self::ZERO);
                negative.select(
                    <Self as Real>::splat(f64::NAN),
                    tiny.select(ln_x - correction, ln_x),
                )
            }
            #[inline]
            fn pow(self, e: Self) -> Self {
                {
                    let (a, b) = (self.to_array(), e.to_array());
                    $v::new(core::array::from_fn(|i| <$s as Real>::pow(a[i], b[i])))
                }
            }
            #[inline]
            fn erf(self) -> Self {
                $v::new(self.to_array().map(<$s as Real>::erf))
            }
            #[inline]
            fn erfc(self) -> Self {
                $v::new(self.to_array().map(<$s as Real>::erfc))
            }
            #[inline]
            fn sin(self) -> Self {
                // `wide`'s range reduction is within 1 ULP up to |x| = 1e3 and loses every
                // digit past ~1e7; the rare lanes beyond 1e3 take libm's exact reduction.
                let far = !self.abs().simd_le($v::splat(1e3)) & self.is_finite();
                let near = $v::sin(self);
                if far.any() {
                    let (x, n, m) = (self.to_array(), near.to_array(), far.to_array());
                    $v::new(core::array::from_fn(|i| {
                        if m[i] != 0.0 {
                            <$s as Real>::sin(x[i])
                        } else {
                            n[i]
                        }
                    }))
                } else {
                    near
                }
            }
            #[inline]
            fn cos(self) -> Self {
                // See `sin`.
                let far = !self.abs().simd_le($v::splat(1e3)) & self.is_finite();
                let near = $v::cos(self);
                if far.any() {
                    let (x, n, m) = (self.to_array(), near.to_array(), far.to_array());
                    $v::new(core::array::from_fn(|i| {
                        if m[i] != 0.0 {
                            <$s as Real>::cos(x[i])
                        } else {
                            n[i]
                        }
                    }))
                } else {
                    near
                }
            }
            #[inline]
            fn tan(self) -> Self {
                $v::new(self.to_array().map(<$s as Real>::tan))
            }
            #[inline]
            fn atan(self) -> Self {
                $v::atan(self)
            }
            #[inline]
            fn atan2(self, x: Self) -> Self {
                $v::atan2(self, x)
            }
            #[inline]
            fn acos(self) -> Self {
                $v::acos(self)
            }
            #[inline]
            fn asin(self) -> Self {
                $v::asin(self)
            }
        }
    };
}

// `wide`'s f32x8 exp2 is within 1 ULP of libm; its f64x4 exp2 is 1901 ULP off near 0.5
// (measured by tests/lanes/vs_scalar.rs), so f64 lanes call libm per lane.
#[inline]
fn exp2_lanes<V: Exp2Lanes>(v: V) -> V {
    v.exp2_lanes()
}
trait Exp2Lanes {
    fn exp2_lanes(self) -> Self;
}
impl Exp2Lanes for f32x8 {
    #[inline]
    fn exp2_lanes(self) -> Self {
        f32x8::exp2(self)
    }
}
impl Exp2Lanes for f64x4 {
    #[inline]
    fn exp2_lanes(self) -> Self {
        f64x4::new(self.to_array().map(libm::exp2))
    }
}

// `wide`'s f32x8 exp branches twice on lane data (an early return when every lane underflows,
// and a subnormal-result path taken when any lane's 2^n is below 2^-126). Inputs that mix
// ordinary and far-negative arguments (the tail of a Beckmann D) make both branches
// unpredictable. `exp_f32x8` is the same algorithm, operation for operation, with 2^n built
// branch-free; its results are bit-identical to `f32x8::exp` on every f32 input.
#[inline]
fn exp_lanes<V: ExpLanes>(v: V) -> V {
    v.exp_lanes()
}
trait ExpLanes {
    fn exp_lanes(self) -> Self;
    fn exp_ftz_lanes(self) -> Self;
}
impl ExpLanes for f32x8 {
    #[inline]
    fn exp_lanes(self) -> Self {
        exp_f32x8(self)
    }
    #[inline]
    fn exp_ftz_lanes(self) -> Self {
        exp_ftz_f32x8(self)
    }
}
impl ExpLanes for f64x4 {
    #[inline]
    fn exp_lanes(self) -> Self {
        f64x4::exp(self)
    }
    #[inline]
    fn exp_ftz_lanes(self) -> Self {
        let e = f64x4::exp(self);
        e.simd_lt(f64x4::splat(f64::MIN_POSITIVE))
            .select(f64x4::ZERO, e)
    }
}

/// The core of the f32 lane exp: r = round(x log2 e) and z = e^y for y = x - r ln 2 (Cody-Waite,
/// ln 2 split in two f32 parts), e^y = 1 + y + y^2 P(y) with the degree-5 Taylor P; e^x is
/// z 2^r. The same operations as `wide::f32x8::exp`.
#[inline]
fn exp_reduced(xs: f32x8) -> (f32x8, f32x8) {
    let r = (xs * f32x8::LOG2_E).round_ties_even();
    let y = r.mul_neg_add(f32x8::splat(0.693_359_4), xs);
    let y = r.mul_neg_add(f32x8::splat(-2.121_944_4e-4), y);
    // Below |y| = 2^-26 the polynomial's powers of y would reach the subnormal range (each
    // subnormal costs a microcode assist on x86) while y^2 P(y) is below half an ULP of y, so
    // it cannot change the sum: they are formed from 0 there, with the same bits as a result.
    let ys = y
        .abs()
        .simd_lt(f32x8::splat(1.490_116_1e-8))
        .select(f32x8::ZERO, y);
    let y2 = ys * ys;
    let y4 = y2 * y2;
    let p = f32x8::splat(1.0 / 120.0)
        .mul_add(ys, f32x8::splat(1.0 / 24.0))
        .mul_add(
            y2,
            f32x8::splat(1.0 / 5040.0)
                .mul_add(ys, f32x8::splat(1.0 / 720.0))
                .mul_add(y4, f32x8::splat(1.0 / 6.0).mul_add(ys, f32x8::splat(0.5))),
        );
    let z = p.mul_add(y2, y) + f32x8::ONE;
    (r, z)
}

/// e^x on f32 lanes: Cody-Waite reduction x = r ln2 + y (r = round(x log2 e), ln 2 split in two
/// f32 parts), e^y = 1 + y + y^2 P(y) with the degree-5 Taylor P, then times 2^r as
/// (1 + ...) 2^(r - k) 2^k, k = 1 for r = 128, -64 for r < -126, else 0: the first product is
/// exact, the second rounds once (into the subnormal range where the result is subnormal).
/// The same operations as `wide::f32x8::exp`, so the same bits on every input.
#[inline]
fn exp_f32x8(x: f32x8) -> f32x8 {
    let zero = f32x8::ZERO;
    let max_x = f32x8::splat(88.723);
    let min_x = f32x8::splat(-103.63);
    // Lanes whose result is fixed (NaN, overflow to inf, underflow to 0) compute e^0 instead:
    // their garbage would otherwise reach subnormal operands, which cost a microcode assist
    // per instruction on many x86 cores.
    let fixed = !(x.simd_ge(min_x) & x.simd_le(max_x));
    let xs = fixed.select(zero, x);
    // r in [-150, 128].
    let (r, z) = exp_reduced(xs);
    let big = r.simd_gt(f32x8::splat(127.0));
    let sub = r.simd_lt(f32x8::splat(-126.0));
    let k = big.select(f32x8::ONE, sub.select(f32x8::splat(-64.0), zero));
    let two_k = big.select(
        f32x8::TWO,
        sub.select(f32x8::splat(5.421_011e-20), f32x8::ONE),
    );
    // 2^(r - k) from its exponent bits: r - k is in [-86, 127].
    let biased = (r - k) + f32x8::splat(127.0 + 8_388_608.0);
    let z = z * f32x8::from_bits(biased.to_bits() << 23_u32) * two_k;
    // 2^-150 rounds to 0 in `wide`'s construction.
    let z = r.simd_lt(f32x8::splat(-149.0)).select(zero, z);
    let special = x.simd_gt(max_x).select(
        f32x8::INFINITY,
        x.simd_lt(min_x)
            .select(zero, f32x8::from_bits(wide::u32x8::splat(0x7FC0_0101))),
    );
    fixed.select(special, z)
}

/// [`exp_f32x8`] with results below 2^-126 flushed to 0, built so that for normal inputs no
/// lane ever holds a subnormal number: the argument clamped, the same reduction and polynomial (the same bits
/// wherever the result is normal), then 2^r applied as 2^(r - k) 2^k with k = 1 for r > 0 and -1 otherwise, so that
/// 2^(r - k) is normal for every r in [-126, 128], and the lanes whose product
/// z 2^(r - k) < 2^-125 would round into the subnormal range by the final halving are zeroed
/// before it.
#[inline]
fn exp_ftz_f32x8(x: f32x8) -> f32x8 {
    let zero = f32x8::ZERO;
    // Clamped (NaN kept: maxps / minps return their second operand for a NaN) to
    // [-87.5, 88.723]: below -87.5, e^x < 2^-126 and the clamped lane is flushed by the test
    // below; above 88.723 the clamped value overflows to +inf as e^x does. In between nothing
    // changes, so r is in [-126, 128].
    let xs = f32x8::splat(88.723).fast_min(f32x8::splat(-87.5).fast_max(x));
    let (r, z) = exp_reduced(xs);
    let up = r.simd_gt(zero);
    let k = up.select(f32x8::ONE, f32x8::splat(-1.0));
    // 2^(r - k) from its exponent bits: r - k is in [-125, 127].
    let biased = (r - k) + f32x8::splat(127.0 + 8_388_608.0);
    let w = z * f32x8::from_bits(biased.to_bits() << 23_u32);
    // w >= 2^-125 (normal) wherever k = -1 leaves a normal result; below, 0 before halving.
    let w = (!up & w.simd_lt(f32x8::splat(2.350_988_7e-38))).select(zero, w);
    w * up.select(f32x8::TWO, f32x8::HALF)
}

/// Crate-internal operations of the four lane types: a supertrait of [`Real`] in a private
/// module, so that outside the crate it can be neither named, implemented nor called, and
/// `Real` is implemented for `f32`, `f64`, `f32x8` and `f64x4` only.
pub(crate) mod sealed {
    /// R of [`Sealed::rsqrt_bits`] for f32 types (Lomont 2003).
    pub(crate) const RSQRT_SEED_F32: u32 = 0x5f37_59df;
    /// R of [`Sealed::rsqrt_bits`] for f64 types (Lomont 2003).
    pub(crate) const RSQRT_SEED_F64: u64 = 0x5fe6_eb50_c7b5_37a9;

    /// See the module docs.
    /// A value only this crate can make: the argument that keeps [`Sealed`]'s methods, which
    /// are reachable through any `T: Real` bound, uncallable from outside.
    #[derive(Clone, Copy, Debug)]
    pub struct Token(());
    impl Token {
        /// The token.
        #[cfg_attr(not(feature = "beckmann"), allow(dead_code))]
        pub(crate) const NEW: Self = Self(());
    }
    pub trait Sealed: Sized {
        /// 2^-(b x) s for b x in [0, 120] (f32 types) / [0, 1000] (f64 types) and s > 0 with
        /// 2^-ceil(b x) s a normal number, with the rounding of the product b x recovered: the
        /// result is that of the exact product, to within the exponential's own error, where
        /// 2^-fl(b x) would carry fl's absolute rounding (up to 2^-18 at b x = 108, 1e-5
        /// relative in the result). NaN gives NaN; outside that range unspecified. `f32` and
        /// `f32x8`: `exp2_neg_prod_single`, the same operations on both (lanes equal
        /// scalars bit for bit), no branch, no subnormal intermediate where b x is 0 or at
        /// least 2^-100; `f64` and `f64x4`: libm's exp2 of fl(b x) times 1 - e ln 2 for the
        /// product's error e (`crate::dw::two_prod`), lane by lane. For the `_fast` Beckmann D.
        fn exp2_neg_prod(self, x: Self, s: Self, token: Token) -> Self;
        /// 2^n from its exponent bits, for `self` = 2^52 + 1023 + n (f64 types) or
        /// 2^23 + 127 + n (f32 types), n an integer with 2^n a normal number: the biased
        /// exponent sits in the low significand bits and is shifted into place. Outside that
        /// range unspecified (no panic).
        fn pow2_bits(self, token: Token) -> Self;
        /// The seed of a reciprocal square root from the bits of `self` >= 0: the bit pattern
        /// `R - (bits >> 1)` (halving and negating the exponent, the significand's linear
        /// part absorbed by R: [`RSQRT_SEED_F32`] for f32 types, [`RSQRT_SEED_F64`] for f64 types;
        /// Lomont 2003, "Fast Inverse Square Root"), within 3.5 % of 1 / sqrt(self) for
        /// every positive normal `self`; integer operations only, the same bits on every
        /// target. 0 gives a finite value (about 2^63 / 2^511); subnormal, infinite and NaN
        /// input give an unspecified value (no panic).
        fn rsqrt_bits(self, token: Token) -> Self;
        /// The kernel `k` on `x`: on `f32` and `f32x8` its f64 evaluation rounded to f32 once
        /// (`Widened::single`, `Widened::lanes8`; by default its `wide` form on `f64`, resp.
        /// two `f64x4` halves; `crate::widen`); on `f64` and `f64x4` its `native` form.
        fn via_f64<K: Widened<N>, const N: usize>(x: [Self; N], k: K, token: Token) -> Self;
    }

    /// A kernel with an f64 evaluation for single-precision inputs (`crate::widen`).
    pub trait Widened<const N: usize>: Copy {
        /// Whether a result may lie below f32's smallest normal number, so that the rounding
        /// to f32 must avoid the subnormal range (`crate::widen::round_tiny_f32`).
        const TINY: bool;
        /// The kernel in the lane type's own arithmetic (taken by `f64` and `f64x4`).
        fn native<T: super::Real>(self, x: [T; N]) -> T;
        /// The kernel in f64 on inputs that are f32 values widened exactly, to within a
        /// small relative error of the exact result (taken by `f32` and `f32x8`).
        fn wide<W: super::Real<Scalar = f64>>(self, x: [W; N]) -> W;
        /// The kernel on `f32` (taken by `f32`): by default `wide::<f64>`, rounded to f32
        /// once (`crate::widen::round_tiny_f32` where `TINY`). A kernel that rounds its
        /// own way overrides this and [`lanes8`](Widened::lanes8) together, with the same
        /// operations lane for lane.
        #[inline]
        fn single(self, x: [f32; N]) -> f32 {
            let y = self.wide::<f64>(x.map(f64::from));
            if Self::TINY {
                crate::widen::round_tiny_f32(y)
            } else {
                crate::widen::round_f32(y)
            }
        }
        /// The kernel on `f32x8` (taken by `f32x8`): by default `wide::<f64x4>` on each
        /// half of the lanes, rounded as [`single`](Widened::single) rounds, lane for lane.
        #[inline]
        fn lanes8(self, x: [super::f32x8; N]) -> super::f32x8 {
            super::via_halves(self, x)
        }
    }
    impl Sealed for f32 {
        #[inline]
        fn exp2_neg_prod(self, x: Self, s: Self, _: Token) -> Self {
            super::exp2_neg_prod_single(self, x, s)
        }
        #[inline]
        fn pow2_bits(self, _: Token) -> Self {
            f32::from_bits(self.to_bits() << 23)
        }
        #[inline]
        fn rsqrt_bits(self, _: Token) -> Self {
            f32::from_bits(RSQRT_SEED_F32.wrapping_sub(self.to_bits() >> 1))
        }
        #[inline]
        fn via_f64<K: Widened<N>, const N: usize>(x: [Self; N], k: K, _: Token) -> Self {
            k.single(x)
        }
    }
    impl Sealed for f64 {
        #[inline]
        fn exp2_neg_prod(self, x: Self, s: Self, _: Token) -> Self {
            super::exp2_neg_prod_f64(self, x, s)
        }
        #[inline]
        fn pow2_bits(self, _: Token) -> Self {
            f64::from_bits(self.to_bits() << 52)
        }
        #[inline]
        fn rsqrt_bits(self, _: Token) -> Self {
            f64::from_bits(RSQRT_SEED_F64.wrapping_sub(self.to_bits() >> 1))
        }
        #[inline]
        fn via_f64<K: Widened<N>, const N: usize>(x: [Self; N], k: K, _: Token) -> Self {
            k.native(x)
        }
    }
    impl Sealed for super::f32x8 {
        #[inline]
        fn exp2_neg_prod(self, x: Self, s: Self, _: Token) -> Self {
            super::exp2_neg_prod_single(self, x, s)
        }
        #[inline]
        fn pow2_bits(self, _: Token) -> Self {
            Self::from_bits(self.to_bits() << 23_u32)
        }
        #[inline]
        fn rsqrt_bits(self, _: Token) -> Self {
            Self::from_bits(wide::u32x8::splat(RSQRT_SEED_F32) - (self.to_bits() >> 1_u32))
        }
        #[inline]
        fn via_f64<K: Widened<N>, const N: usize>(x: [Self; N], k: K, _: Token) -> Self {
            k.lanes8(x)
        }
    }
    impl Sealed for super::f64x4 {
        #[inline]
        fn exp2_neg_prod(self, x: Self, s: Self, _: Token) -> Self {
            let (b, x, s) = (self.to_array(), x.to_array(), s.to_array());
            super::f64x4::new(core::array::from_fn(|i| {
                super::exp2_neg_prod_f64(b[i], x[i], s[i])
            }))
        }
        #[inline]
        fn pow2_bits(self, _: Token) -> Self {
            Self::from_bits(self.to_bits() << 52_u64)
        }
        #[inline]
        fn rsqrt_bits(self, _: Token) -> Self {
            Self::from_bits(wide::u64x4::splat(RSQRT_SEED_F64) - (self.to_bits() >> 1_u64))
        }
        #[inline]
        fn via_f64<K: Widened<N>, const N: usize>(x: [Self; N], k: K, _: Token) -> Self {
            k.native(x)
        }
    }
}

/// Coefficients c1..c5 of p(f) = 1 + c1 f + ... + c5 f^5, within 9.2e-8 (relative, 1.5 units
/// of 2^-24) of 2^f on [-1/2, 1/2] (and 2^-16 beyond each end): a minimax fit with p(0) = 1
/// exactly (Lawson's iteratively reweighted least squares on 4001 Chebyshev points, in f64),
/// each coefficient then rounded to f32. Evaluated in f32, within 2 ULP of
/// 2^f (`exp2_neg_prod_within_two_ulp` below). Degree 6 would be 1 ULP, at one multiply-add
/// more per lane (5 % of `beckmann::d_fast`'s time on f32x8).
#[allow(clippy::approx_constant)] // c1 is fitted: one f32 ULP below ln 2, not ln 2
const EXP2_POLY: [f32; 5] = [
    0.693_147,
    0.240_222_42,
    0.055_507_34,
    0.009_671_516,
    0.001_326_472_3,
];

/// 2^-(b x) s on `f32` and `f32x8` for b x in [0, 120] (`Sealed::exp2_neg_prod`):
/// m = 2^23 + 127 - b x rounded once to an integer (a multiply-add), whose low significand
/// bits hold 127 - n for n = round(b x), the biased exponent of 2^-n; the remainder
/// f = n - b x of the exact product (`crate::dw::sub_prod`: exact but for one rounding below
/// 2^-26), |f| <= 1/2; 2^f = p(f) by [`EXP2_POLY`] in Horner's scheme (Estrin's, shallower, measured slower in
/// `beckmann::d_fast`); times 2^-n s, 2^-n
/// from m's bits, formed while p is evaluated.
///
/// No subnormal intermediate where b x is 0 or at least 2^-100: f is then 0 or, for n >= 1, a
/// multiple of 2^-49 (the grid of the exact b x >= 1/2), for n = 0 at least 2^-100, so each of
/// Horner's products (coefficients above 2^-10) is normal.
#[inline]
pub(crate) fn exp2_neg_prod_single<T: Real>(b: T, x: T, s: T) -> T {
    let big = T::splat(8_388_735.0);
    let m = (-b).mul_add(x, big);
    let n = big - m;
    let f = crate::dw::sub_prod(n, b, x);
    let c = |k: usize| T::splat(f64::from(EXP2_POLY[k]));
    let p = c(4).mul_add(f, c(3)).mul_add(f, c(2)).mul_add(f, c(1));
    let p = p.mul_add(f, c(0)).mul_add(f, T::ONE);
    p * (m.pow2_bits(sealed::Token::NEW) * s)
}

/// 2^-(b x) s on `f64` for b x in [0, 1000] (`Sealed::exp2_neg_prod`): libm's exp2 of
/// fl(b x), times s (1 - e ln 2) for the product's exact error e (first order: |e| <= 2^-43).
#[inline]
fn exp2_neg_prod_f64(b: f64, x: f64, s: f64) -> f64 {
    let (p, e) = crate::dw::two_prod(b, x);
    let r = libm::exp2(-p);
    // The correction scales s, not r: r e alone would be subnormal near r = 2^-1000.
    r * (s - s * (core::f64::consts::LN_2 * e))
}

/// `Widened::lanes8`'s default: `wide` on each half of the lanes, rounded to f32 once
/// (with `split_tiny` where `TINY`).
#[inline(always)]
fn via_halves<K: sealed::Widened<N>, const N: usize>(k: K, x: [f32x8; N]) -> f32x8 {
    let lo = k.wide(x.map(|v| widen_half(v, 0)));
    let hi = k.wide(x.map(|v| widen_half(v, 4)));
    if K::TINY {
        let ((big_lo, small_lo), (big_hi, small_hi)) = (split_tiny(lo), split_tiny(hi));
        let big = narrow(big_lo, big_hi).to_bits();
        let small = narrow(small_lo, small_hi).to_bits();
        // `crate::widen::round_tiny_f32`'s join, lane by lane.
        f32x8::from_bits((big + small) - wide::u32x8::splat(0x0100_0000))
    } else {
        narrow(lo, hi)
    }
}

/// Lanes `at..at + 4` of `v` widened to f64 (exactly).
#[inline(always)]
pub(crate) fn widen_half(v: f32x8, at: usize) -> f64x4 {
    let a = v.to_array();
    f64x4::new([
        f64::from(a[at]),
        f64::from(a[at + 1]),
        f64::from(a[at + 2]),
        f64::from(a[at + 3]),
    ])
}

/// The two normal parts of y >= 0 that `crate::widen::round_tiny_f32` rounds to f32 and
/// joins: (max(y, 2^-126), min(y, 2^-126) + 2^-126), by `vmaxpd` / `vminpd` (NaN lanes give
/// an unspecified value, which the kernels replace), as `f64::max` / `f64::min` on the scalar
/// path.
#[inline(always)]
fn split_tiny(y: f64x4) -> (f64x4, f64x4) {
    let m = f64x4::splat(crate::widen::F32_MIN_POSITIVE);
    (y.fast_max(m), y.fast_min(m) + m)
}

/// The eight lanes of `lo` and `hi` rounded to f32 (to nearest, ties to even).
#[inline(always)]
#[allow(clippy::cast_possible_truncation)] // the rounding is the point
pub(crate) fn narrow(lo: f64x4, hi: f64x4) -> f32x8 {
    let (l, h) = (lo.to_array(), hi.to_array());
    f32x8::new([
        l[0] as f32,
        l[1] as f32,
        l[2] as f32,
        l[3] as f32,
        h[0] as f32,
        h[1] as f32,
        h[2] as f32,
        h[3] as f32,
    ])
}

impl_real_lanes!(f32x8, f32, 8, 32);
impl_real_lanes!(f64x4, f64, 4, 64);

#[cfg(test)]
mod tests {
    use super::sealed::{Sealed, Token};
    use super::*;

    /// The f32 2^-(b x) against libm's f64 exp2 of the exact product, for b from 2^-29 to 64
    /// and x over a dense grid (b x in [0, 120]), every f32 in [0.49, 0.51] as x with b = 1
    /// (the polynomial's error peaks at |f| = 1/2): within 2.5 ULP with fused multiply-adds
    /// (2.02 found by the fit's own check), 3 without; always normal; f32x8 lanes equal the
    /// scalar function bit for bit; NaN gives NaN.
    #[test]
    fn exp2_neg_prod_within_two_ulp() {
        let mut worst = 0.0f64;
        let mut check = |b: f32, xs: [f32; 8]| {
            let lanes = f32x8::splat(b)
                .exp2_neg_prod(f32x8::new(xs), f32x8::ONE, Token::NEW)
                .to_array();
            for (x, g) in xs.iter().zip(lanes) {
                let want = libm::exp2(-(f64::from(b) * f64::from(*x)));
                let s = b.exp2_neg_prod(*x, 1.0, Token::NEW);
                let ulp = (f64::from(g) - want).abs() / f64::from(ulp_f32(want as f32));
                assert!(
                    g.is_normal() && g.to_bits() == s.to_bits(),
                    "2^-({b:e} {x:e}): lane {g:e}, scalar {s:e}"
                );
                worst = worst.max(ulp);
            }
        };
        for (b, step) in [
            (1.0f32, 1.0 / 4096.0),
            (0.180_336_88, 1.0 / 1024.0),
            (3.0e-3, 1.0 / 16.0),
            (1.862_645_1e-9, 1.0e5),
            (64.0, 1.0 / 65536.0),
        ] {
            let mut x = 0.0f32;
            while b * x <= 120.0 {
                check(b, core::array::from_fn(|k| x + k as f32 * step * 0.37));
                x += step * 8.0 * 0.37;
            }
        }
        let mut bits = 0.49f32.to_bits();
        while bits <= 0.51f32.to_bits() {
            check(
                1.0,
                core::array::from_fn(|k| f32::from_bits(bits + k as u32)),
            );
            bits += 8;
        }
        assert!(
            f32x8::splat(1.0)
                .exp2_neg_prod(f32x8::splat(f32::NAN), f32x8::ONE, Token::NEW)
                .to_array()[0]
                .is_nan()
        );
        assert!(1.0f32.exp2_neg_prod(f32::NAN, 1.0, Token::NEW).is_nan());
        let fused = cfg!(any(
            target_feature = "fma",
            all(target_arch = "aarch64", target_feature = "neon")
        ));
        assert!(worst <= if fused { 2.5 } else { 3.0 }, "{worst} ULP");
    }

    /// One unit in the last place of a positive normal f32.
    fn ulp_f32(x: f32) -> f32 {
        f32::from_bits(x.to_bits() + 1) - x
    }
}
