//! Single-precision kernels evaluated in double precision and rounded once.
//!
//! An exact `f32` kernel must keep its intermediate roundings far below half an ULP of f32.
//! Double-word `f32` arithmetic (`crate::dw`) does that at about ten operations per rounding
//! recovered; `f64` does it at one, because an `f32` input widened to `f64` is exact, its
//! square and the product of two of them are exact (48 significant bits), and every later
//! rounding costs 2^-53 relative, 2^-29 of an ULP of f32. No `f32` input can overflow or
//! underflow `f64` through a few such products either (f32's range is 2^±128, f64's
//! 2^±1022), so the scalings that keep an `f32` double word out of the subnormal range are
//! not needed. The result, within a few units of 2^-53 relative of the exact value (plus what
//! a kernel's own approximations add, such as [`exp_neg_split`]'s), is then rounded to `f32` once:
//! within 0.5 ULP plus that small relative error.
//!
//! A kernel that takes this path implements [`Widened`](crate::real::sealed::Widened) twice:
//! `wide`, generic over `f64` and `f64x4`, and `native`, its double-word form for `f64` and
//! `f64x4` themselves. [`Real`]'s sealed hook `via_f64` picks one per lane type: `f32` runs
//! `wide::<f64>`, `f32x8` runs `wide::<f64x4>` on each half of its lanes (the same operations
//! lane for lane, so the lanes equal the scalar results bit for bit), `f64` and `f64x4` run
//! `native`. A kernel may replace the `f32` and `f32x8` steps (`Widened::single` and
//! `lanes8`) by its own, as long as they stay the same operations lane for lane: the
//! isotropic `beckmann::d` writes its f64 form once over [`F64Lanes`] and runs `f32x8`'s
//! eight lanes as one `f64x8` (one AVX-512 register where the target has them: half the
//! instructions of two `f64x4` halves), with the rounding of [`tiny_big`], [`tiny_small`] and
//! [`join_tiny_f32`].
//!
//! Rounding into the subnormal range: on x86, converting an `f64` to an `f32` subnormal costs
//! a microcode assist on many cores, as does any instruction with a subnormal operand or
//! result. [`round_tiny_f32`] therefore rounds two normal numbers instead of y:
//! max(y, 2^-126), and min(y, 2^-126) + 2^-126, which for y below 2^-126 lies in
//! [2^-126, 2^-125], where f32's spacing is 2^-149, the spacing of its subnormals, so the
//! conversion rounds y + 2^-126 exactly as it would round y, and subtracting 2^-126's bit
//! pattern (0x0080_0000) from the rounded bits gives y's subnormal `f32`. Adding the two bit
//! patterns and subtracting those of 2^-126 and 2^-125 (the parts where y is normal) gives
//! fl32(y) in both cases without a comparison, and no instruction meets a subnormal number.
//! A kernel whose result ends in a product y = p x (such as 2^-f times the rest) can do
//! with one conversion: [`tiny_small`] rounds y to f32's subnormal spacing
//! in the multiply-add p (x 2^149) + 1.5 2^52, whose low bits then hold the subnormal
//! result's bit pattern, beside the product itself (on a Zen 4 core the two conversions and
//! the additions before them took about a quarter of `beckmann::d`'s time on `f32x8`: 1.33
//! ms per 10^6 cosines against 0.96 ms with a plain conversion, `benches/throughput.rs`'s
//! timing mode).

use crate::real::Real;
use core::ops::{Add, Div, Mul, Sub};

/// The f64 operations of a kernel's `wide` form that also run on `f64x8` (eight lanes in one
/// AVX-512 register where the target has them, two `f64x4` otherwise): `f64` and `f64x4`
/// through [`Real`], `f64x8` through `wide`'s own methods with [`Real`]'s meanings, so that
/// one generic source gives the same bits on all three, lane for lane.
pub(crate) trait F64Lanes:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    /// Every lane `v`.
    fn splat(v: f64) -> Self;
    /// `self * a + b`, fused where the target has FMA (as [`Real::mul_add`]).
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// Largest integer not above `self`.
    fn floor(self) -> Self;
    /// As [`Real::max`]: `o` where `self < o`, else `self` (NaN in `self` propagates).
    fn max(self, o: Self) -> Self;
    /// As [`Real::min`]: `o` where `self > o`, else `self` (NaN in `self` propagates).
    fn min(self, o: Self) -> Self;
    /// 2^n from its exponent bits, for `self` = 2^52 + 1023 + n (`Real`'s sealed
    /// `pow2_bits`).
    fn pow2_bits(self) -> Self;
}

impl<W: Real<Scalar = f64>> F64Lanes for W {
    #[inline]
    fn splat(v: f64) -> Self {
        <W as Real>::splat(v)
    }
    #[inline]
    fn mul_add(self, a: Self, b: Self) -> Self {
        Real::mul_add(self, a, b)
    }
    #[inline]
    fn floor(self) -> Self {
        Real::floor(self)
    }
    #[inline]
    fn max(self, o: Self) -> Self {
        Real::max(self, o)
    }
    #[inline]
    fn min(self, o: Self) -> Self {
        Real::min(self, o)
    }
    #[inline]
    fn pow2_bits(self) -> Self {
        crate::real::sealed::Sealed::pow2_bits(self, crate::real::sealed::Token::NEW)
    }
}

impl F64Lanes for crate::wide::f64x8 {
    #[inline]
    fn splat(v: f64) -> Self {
        crate::wide::f64x8::splat(v)
    }
    #[inline]
    fn mul_add(self, a: Self, b: Self) -> Self {
        crate::wide::f64x8::mul_add(self, a, b)
    }
    #[inline]
    fn floor(self) -> Self {
        crate::wide::f64x8::floor(self)
    }
    #[inline]
    fn max(self, o: Self) -> Self {
        // As `Real::max` on `f64x4` (`crate::real`): maxpd(o, self), NaN in either giving self.
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        {
            o.fast_max(self)
        }
        #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
        {
            use crate::wide::CmpLt;
            self.simd_lt(o).select(o, self)
        }
    }
    #[inline]
    fn min(self, o: Self) -> Self {
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        {
            o.fast_min(self)
        }
        #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
        {
            use crate::wide::CmpGt;
            self.simd_gt(o).select(o, self)
        }
    }
    #[inline]
    fn pow2_bits(self) -> Self {
        crate::wide::f64x8::from_bits(self.to_bits() << 52_u32)
    }
}

/// The further f64 operations of a kernel written once for `f64`, `f64x4` and `f64x8`
/// (`cook_torrance::ggx_conductor_local`): square roots, magnitudes, comparisons and selects,
/// with [`Real`]'s meanings on all three, so that one generic source gives the same bits
/// lane for lane.
pub(crate) trait F64Ops: F64Lanes + core::ops::Neg<Output = Self> {
    /// A lane mask (`bool` on `f64`).
    type M: Copy + core::ops::BitAnd<Output = Self::M>;
    /// The correctly rounded square root.
    fn sqrt(self) -> Self;
    /// |self|.
    fn abs(self) -> Self;
    /// `self > o` (false where either is NaN).
    fn gt(self, o: Self) -> Self::M;
    /// `self >= o` (false where either is NaN).
    fn ge(self, o: Self) -> Self::M;
    /// `self == o` (false where either is NaN).
    fn eq(self, o: Self) -> Self::M;
    /// `t` where `m`, else `f`.
    fn select(m: Self::M, t: Self, f: Self) -> Self;
    /// 0.5 / sqrt(fl32(self)), by the correctly rounded f32 square root and division (the
    /// same bits on every target and lane type), widened: within 1.3 2^-23 of
    /// 0.5 / sqrt(self) for self in [2^-100, 2^100].
    fn half_rsqrt_f32(self) -> Self;
    /// The bit-pattern seed of 1 / sqrt(self) (`Real`'s sealed `rsqrt_bits`): within 3.5 %
    /// for normal positive inputs.
    fn rsqrt_bits(self) -> Self;
}

impl<W: Real<Scalar = f64>> F64Ops for W {
    type M = W::Mask;
    #[inline]
    fn half_rsqrt_f32(self) -> Self {
        let mut lanes = [1.0f32; 4];
        for (i, lane) in lanes.iter_mut().enumerate().take(W::LANES) {
            #[allow(clippy::cast_possible_truncation)] // the rounding to f32 is the seed
            {
                *lane = self.lane(i) as f32;
            }
        }
        let y0 = (crate::wide::f32x4::HALF / crate::wide::f32x4::new(lanes).sqrt()).to_array();
        W::from_fn(|i| f64::from(y0[i]))
    }
    #[inline]
    fn sqrt(self) -> Self {
        Real::sqrt(self)
    }
    #[inline]
    fn abs(self) -> Self {
        Real::abs(self)
    }
    #[inline]
    fn gt(self, o: Self) -> Self::M {
        self.simd_gt(o)
    }
    #[inline]
    fn ge(self, o: Self) -> Self::M {
        self.simd_ge(o)
    }
    #[inline]
    fn eq(self, o: Self) -> Self::M {
        self.simd_eq(o)
    }
    #[inline]
    fn select(m: Self::M, t: Self, f: Self) -> Self {
        <W as Real>::select(m, t, f)
    }
    #[inline]
    fn rsqrt_bits(self) -> Self {
        crate::real::sealed::Sealed::rsqrt_bits(self, crate::real::sealed::Token::NEW)
    }
}

impl F64Ops for crate::wide::f64x8 {
    type M = Self;
    #[inline]
    fn half_rsqrt_f32(self) -> Self {
        let a = self.to_array();
        #[allow(clippy::cast_possible_truncation)] // the rounding to f32 is the seed
        let x = crate::wide::f32x8::new(core::array::from_fn(|i| a[i] as f32));
        widen8(crate::wide::f32x8::HALF / x.sqrt())
    }
    #[inline]
    fn sqrt(self) -> Self {
        crate::wide::f64x8::sqrt(self)
    }
    #[inline]
    fn abs(self) -> Self {
        crate::wide::f64x8::abs(self)
    }
    #[inline]
    fn gt(self, o: Self) -> Self {
        self.simd_gt(o)
    }
    #[inline]
    fn ge(self, o: Self) -> Self {
        self.simd_ge(o)
    }
    #[inline]
    fn eq(self, o: Self) -> Self {
        self.simd_eq(o)
    }
    #[inline]
    fn select(m: Self, t: Self, f: Self) -> Self {
        m.select(t, f)
    }
    #[inline]
    fn rsqrt_bits(self) -> Self {
        Self::from_bits(
            crate::wide::u64x8::splat(crate::real::sealed::RSQRT_SEED_F64)
                - (self.to_bits() >> 1_u64),
        )
    }
}

/// 2^-126, the smallest normal `f32` (also for the lanes' `split_tiny` in `crate::real`).
pub(crate) const F32_MIN_POSITIVE: f64 = 1.175_494_350_822_287_5e-38;

/// y rounded to f32, to nearest with ties to even (`as`): `f32` and `f32x8` results that
/// cannot be subnormal.
#[inline]
#[must_use]
#[allow(clippy::cast_possible_truncation)] // the rounding is the point
pub(crate) fn round_f32(y: f64) -> f32 {
    y as f32
}

/// y >= 0 rounded to f32 (to nearest, ties to even) without a subnormal operand or result
/// in any instruction: the two parts max(y, 2^-126) and min(y, 2^-126) + 2^-126 are normal
/// and rounded to f32; where y >= 2^-126 they round to fl32(y) and 2^-125, where y < 2^-126 to
/// 2^-126 and fl32(y + 2^-126), whose bits less 2^-126's are those of fl32(y) (module docs);
/// so the sum of the two bit patterns less 2^-125's is fl32(y)'s in both cases, without a
/// comparison. `f32x8` does the same lane by lane (`crate::real`). A NaN y gives an
/// unspecified value: the kernels map NaN input to NaN after this step.
#[inline]
#[must_use]
pub(crate) fn round_tiny_f32(y: f64) -> f32 {
    let m = F32_MIN_POSITIVE;
    let big = round_f32(y.max(m)).to_bits();
    let small = round_f32(y.min(m) + m).to_bits();
    f32::from_bits(big.wrapping_add(small).wrapping_sub(0x0100_0000))
}

/// 2^149: scales f32's subnormal spacing 2^-149 to 1.
const TWO_POW_149: f64 = 7.136_238_463_529_8e44;

/// big = max(p x, 2^-126) of the rounding of y = p x by [`tiny_small`] and [`join_tiny_f32`]
/// (p, x >= 0, p x a normal f64 or 0): a normal number,
/// fl32(y) once converted where y >= 2^-126, 2^-126 (bits 0x0080_0000) elsewhere. NaN in p
/// gives NaN.
#[inline]
#[must_use]
pub(crate) fn tiny_big<W: F64Lanes>(p: W, x: W) -> W {
    (p * x).max(W::splat(F32_MIN_POSITIVE))
}

/// small = min(p (x 2^149) + 1.5 2^52 - 2^23, 1.5 2^52), one multiply-add and a min, for
/// [`join_tiny_f32`]: its low 32 bits are n - 2^23 for n = min(round(y 2^149), 2^23), in two's
/// complement. round(y 2^149) is y rounded to f32's subnormal spacing 2^-149 in units of it,
/// to nearest, ties to even, from the exact product where the multiply-add is fused (from
/// fl64(p x) otherwise): the bit pattern of fl32(y) wherever y < 2^-126 (2^-126's own,
/// 0x0080_0000, included), and at least 2^23 elsewhere, where the min caps it (the sum is
/// monotonic in y, and its low 32 bits wrap only beyond the cap). x 2^149 is exact (x is a
/// normal f64). NaN gives the cap.
#[inline]
#[must_use]
pub(crate) fn tiny_small<W: F64Lanes>(p: W, x: W) -> W {
    let n = p.mul_add(x * W::splat(TWO_POW_149), W::splat(ROUND - 8_388_608.0));
    W::splat(ROUND).min(n)
}

/// fl32(y) from [`tiny_big`] and [`tiny_small`] without a subnormal operand or result in any
/// instruction: fl32(big)'s bits plus the low 32 bits of small, n - 2^23. Where y >= 2^-126,
/// fl32(big) = fl32(y) and n - 2^23 = 0; where y < 2^-126, fl32(big) = 2^-126, whose bits
/// are 2^23, and the sum is n, fl32(y)'s bits. No comparison of y; after the product p x
/// the rounding adds a max, a conversion and one integer addition to the kernel's path (the
/// multiply-add and min of small run beside them). NaN in big gives NaN.
#[inline]
#[must_use]
#[allow(clippy::cast_possible_truncation)] // the low 32 bits are the point
pub(crate) fn join_tiny_f32(big: f64, small: f64) -> f32 {
    f32::from_bits(
        round_f32(big)
            .to_bits()
            .wrapping_add(small.to_bits() as u32),
    )
}

/// The eight lanes of `v` widened to f64 (exactly).
#[inline(always)]
#[must_use]
pub(crate) fn widen8(v: crate::wide::f32x8) -> crate::wide::f64x8 {
    let a = v.to_array();
    crate::wide::f64x8::new([
        f64::from(a[0]),
        f64::from(a[1]),
        f64::from(a[2]),
        f64::from(a[3]),
        f64::from(a[4]),
        f64::from(a[5]),
        f64::from(a[6]),
        f64::from(a[7]),
    ])
}

/// [`join_tiny_f32`] lane by lane on eight lanes.
#[inline]
#[must_use]
#[allow(clippy::cast_possible_truncation)] // the rounding and the low 32 bits are the point
pub(crate) fn join_tiny_f32x8(
    big: crate::wide::f64x8,
    small: crate::wide::f64x8,
) -> crate::wide::f32x8 {
    let (b, s) = (big.to_array(), small.to_bits().to_array());
    let big = crate::wide::f32x8::new([
        b[0] as f32,
        b[1] as f32,
        b[2] as f32,
        b[3] as f32,
        b[4] as f32,
        b[5] as f32,
        b[6] as f32,
        b[7] as f32,
    ])
    .to_bits();
    let n = crate::wide::u32x8::new([
        s[0] as u32,
        s[1] as u32,
        s[2] as u32,
        s[3] as u32,
        s[4] as u32,
        s[5] as u32,
        s[6] as u32,
        s[7] as u32,
    ]);
    crate::wide::f32x8::from_bits(big + n)
}

/// 1.5 2^52: adding it to a value below 2^51 in magnitude rounds the value to an integer
/// (ties to even) in the low significand bits, and subtracting it again leaves that integer.
const ROUND: f64 = 6_755_399_441_055_744.0;
/// 2^52 + 1023: adding it to an integer n in [-1022, 1023] puts 1023 + n, the biased
/// exponent of 2^n, in the low significand bits.
const BIAS: f64 = 4_503_599_627_371_519.0;

/// Coefficients of e^-r on [-ln(2) / 2, ln(2) / 2], lowest first: the degree-6 polynomial
/// interpolating e^-r at the seven Chebyshev nodes of that interval (computed at 120 bits
/// with mpmath, then rounded to f64; near the minimax polynomial), relative error below
/// 2.6e-9 over the interval (`exp_neg_split_is_within_its_stated_error` below), 0.04 ULP of
/// f32. One degree more would cost a multiply-add per four lanes for 0.04 ULP less.
const EXP_NEG: [f64; 7] = [
    1.0,
    -1.000_000_037_716_214,
    0.500_000_004_711_775_7,
    -0.166_664_155_146_532_77,
    0.041_666_352_896_775_16,
    -0.008_375_126_398_153_335,
    0.001_394_110_843_397_267_4,
];

/// e^-x on f64 lanes as (p, 2^-k), for x in [0, 700]: k = round(x log2(e)) and
/// x = k ln 2 + r, |r| <= ln(2) / 2, e^-r = p by the polynomial [`EXP_NEG`] in Estrin's
/// scheme (three levels of multiply-adds instead of six in a row), and 2^-k built from its
/// exponent bits, so that the caller multiplies p last, with factors of its own formed
/// while p is evaluated. Relative error of p 2^-k below 2.6e-9 (an accuracy for `f32`
/// results, 0.04 ULP of f32, against 1.1e-16 for a full `f64` exponential), no branch,
/// every intermediate a normal number (or 0). r is x - k fl(ln 2) in one multiply-add: the
/// rounding of ln 2 costs k 2.3e-17 <= 2.4e-14 absolute in r (k <= 1010), and without a
/// fused multiply-add the product's rounding at most 7.8e-14 more. NaN gives NaN; outside
/// [0, 700] unspecified.
#[inline]
#[must_use]
pub(crate) fn exp_neg_split<W: Real<Scalar = f64>>(x: W) -> (W, W) {
    exp_neg_split_k(x, round_product(x, W::splat(core::f64::consts::LOG2_E)))
}

/// round(a b) (ties to even, |a b| < 2^51), one multiply-add and one subtraction: k for
/// [`exp_neg_split_k`] from x log2(e) = a b, whose factors a caller may choose to shorten its
/// chain of dependent operations.
#[inline]
#[must_use]
pub(crate) fn round_product<W: Real<Scalar = f64>>(a: W, b: W) -> W {
    a.mul_add(b, W::splat(ROUND)) - W::splat(ROUND)
}

/// Coefficients of 2^-f on [0, 1], lowest first: the degree-6 polynomial interpolating 2^-f at
/// the seven Chebyshev nodes of that interval (computed at 200 bits with mpmath, then rounded
/// to f64), relative error below 2.6e-9 on [-10^-6, 1 + 10^-6]
/// (`exp2_neg_unit_is_within_its_stated_error` below): [`EXP_NEG`]'s accuracy on an interval
/// whose reduction is `floor` (one rounding instruction on the lanes) instead of a rounding
/// to nearest.
const EXP2_NEG_UNIT: [f64; 7] = [
    0.999_999_998_620_136_3,
    -0.693_147_045_209_682_6,
    0.240_224_331_208_438_53,
    -0.055_490_932_114_902_95,
    0.009_579_859_972_768_908,
    -0.001_275_540_135_318_515_6,
    0.000_109_328_923_932_990_26,
];

/// 2^-f for f in [0, 1] on f64 lanes by [`EXP2_NEG_UNIT`] in Estrin's scheme (three levels
/// of multiply-adds), within 2.6e-9 relative; the value lies in [0.5 (1 - 2.6e-9),
/// 1 + 2.6e-9]. Every intermediate is a normal number or 0 for f = 0 or |f| >= 2^-900.
#[inline]
#[must_use]
pub(crate) fn exp2_neg_unit<W: F64Lanes>(f: W) -> W {
    let c = |i: usize| W::splat(EXP2_NEG_UNIT[i]);
    let f2 = f * f;
    let p01 = c(1).mul_add(f, c(0));
    let p23 = c(3).mul_add(f, c(2));
    let p45 = c(5).mul_add(f, c(4));
    let p03 = p23.mul_add(f2, p01);
    let p46 = c(6).mul_add(f2, p45);
    p46.mul_add(f2 * f2, p03)
}

/// 2^-k for an integer k in [-1023, 1022], from its exponent bits.
#[inline]
#[must_use]
pub(crate) fn pow2_neg<W: F64Lanes>(k: W) -> W {
    (W::splat(BIAS) - k).pow2_bits()
}

/// [`exp_neg_split`] with k given: any integer with |x - k ln 2| <= ln(2) / 2 + 10^-6 (the
/// polynomial's error grows past the interval's end by less than 10^-12 there).
#[inline]
#[must_use]
pub(crate) fn exp_neg_split_k<W: Real<Scalar = f64>>(x: W, k: W) -> (W, W) {
    let r = k.mul_add(-W::splat(core::f64::consts::LN_2), x);
    let c = |i: usize| W::splat(EXP_NEG[i]);
    let r2 = r * r;
    let p01 = c(1).mul_add(r, c(0));
    let p23 = c(3).mul_add(r, c(2));
    let p45 = c(5).mul_add(r, c(4));
    let p03 = p23.mul_add(r2, p01);
    let p46 = c(6).mul_add(r2, p45);
    let p = p46.mul_add(r2 * r2, p03);
    (
        p,
        (W::splat(BIAS) - k).pow2_bits(crate::real::sealed::Token::NEW),
    )
}

/// sqrt(x) for x a positive normal number or 0: on f64 types within 3.3e-11 relative (0 for
/// 0; the error is one-sided, the result below the root), by multiplications and
/// multiply-adds only: on x86 `vsqrtpd` and `vdivpd` share one unit, and a kernel that needs
/// several roots per lane waits for it (`cook_torrance::ggx_conductor_local`: five roots and
/// three divisions). The seed y of 1 / sqrt(x) from the bits of x ([`Real`]'s sealed
/// `rsqrt_bits`, within 3.5 %; Lomont 2003, "Fast Inverse Square Root") takes two Newton
/// steps y (3/2 - x y^2 / 2), each taking its relative error e to 3 e^2 / 2 + e^3 / 2 (3.5e-2,
/// 1.8e-3, 4.9e-6); then s = x y and s + (y / 2)(x - s^2), which takes the error e of s to
/// 3 e^2 / 2 + e^3 / 2 as well, plus a few roundings of 2^-53. Thirteen operations, the same
/// bits on every target with the same `mul_add`. On f32 types the same steps are within 1
/// ULP of the correctly rounded root (their roundings, 2^-24 each, dominate). Subnormal,
/// infinite and NaN x give an unspecified value (no panic).
#[inline]
#[must_use]
pub(crate) fn sqrt<T: Real>(x: T) -> T {
    let half_x = x * T::HALF;
    let step = |y: T| y * (-(half_x * y)).mul_add(y, T::splat(1.5));
    let y = step(step(x.rsqrt_bits(crate::real::sealed::Token::NEW)));
    let s = x * y;
    (y * T::HALF).mul_add((-s).mul_add(s, x), s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// p 2^-k within 2.6e-9 (relative) of libm's e^-x over [0, 700]: a dense sweep of [0, 2]
    /// and 10^6 steps across the whole range, every product a normal number.
    #[test]
    fn exp_neg_split_is_within_its_stated_error() {
        let mut worst = 0.0f64;
        let mut check = |x: f64| {
            let (p, two_k) = exp_neg_split(x);
            let want = libm::exp(-x);
            let got = p * two_k;
            assert!(got.is_normal() && two_k.is_normal(), "e^-{x}: {got:e}");
            worst = worst.max((got / want - 1.0).abs());
        };
        for i in 0..=200_000 {
            check(f64::from(i) * 1e-5);
        }
        for i in 0..=1_000_000 {
            check(f64::from(i) * 7e-4);
        }
        check(f64::MIN_POSITIVE);
        assert!(exp_neg_split(f64::NAN).0.is_nan());
        assert!(worst < 2.6e-9, "{worst:e}");
    }

    /// `exp2_neg_unit` within its stated 2.6e-9 (relative) of libm's 2^-f on a dense sweep of
    /// [-1e-6, 1 + 1e-6], and within [0.5 (1 - 2^-25), 1 + 2^-25] on [0, 1]; the bound is met with little to spare (above 2.4e-9), so a worse fit fails.
    #[test]
    fn exp2_neg_unit_is_within_its_stated_error() {
        let mut worst = 0.0f64;
        for i in 0..=2_000_000 {
            let f = -1e-6 + f64::from(i) * (1.0 + 2e-6) / 2e6;
            let p = exp2_neg_unit(f);
            worst = worst.max((p / libm::exp2(-f) - 1.0).abs());
            if (0.0..=1.0).contains(&f) {
                assert!((0.5 * (1.0 - libm::exp2(-25.0))..=1.0 + libm::exp2(-25.0)).contains(&p));
            }
        }
        assert!(worst < 2.6e-9 && worst > 2.4e-9, "{worst:e}");
    }

    /// `tiny_big`, `tiny_small` and `join_tiny_f32` give `(p x) as f32` where p x is exact in
    /// f64 (p of 15 significant bits, x of at most 38, so that the fused and unfused
    /// multiply-add agree): y = p x across f32's subnormal range (every step of 2^-149 and
    /// its midpoint near 0 and near the border 2^-126, every 97th elsewhere, ties to even),
    /// the border and above it, normal results up to 1e30, and 0; `f32x8` lanes equal.
    #[test]
    fn tiny_rounding_rounds_as_the_conversion_does() {
        use crate::wide::f64x8;
        let check = |p: f64, x: f64| {
            let got = join_tiny_f32(tiny_big(p, x), tiny_small(p, x));
            #[allow(clippy::cast_possible_truncation)]
            let want = (p * x) as f32;
            assert_eq!(got.to_bits(), want.to_bits(), "p = {p:e}, x = {x:e}");
            let (pl, xl) = (f64x8::splat(p), f64x8::splat(x));
            let lanes = join_tiny_f32x8(tiny_big(pl, xl), tiny_small(pl, xl)).to_array();
            assert!(
                lanes.iter().all(|l| l.to_bits() == got.to_bits()),
                "lanes at {p:e}, {x:e}"
            );
        };
        let half_step = libm::exp2(-150.0);
        for p in [
            0.5,
            0.5 + libm::exp2(-14.0),
            0.75,
            1.0 - libm::exp2(-14.0),
            1.0,
            1.25,
        ] {
            for j in 0..(1u32 << 25) + 4096 {
                if j % 97 != 0 && j > 4096 && j.abs_diff(1 << 24) > 4096 {
                    continue;
                }
                let x = f64::from(j) * half_step;
                check(p, x);
                check(p, x + libm::exp2(-162.0) * f64::from(j % 7));
            }
            let mut x = libm::exp2(-130.0);
            while x < 1e30 {
                check(p, x);
                x *= 1.000_37;
            }
        }
    }

    /// `sqrt` within its stated 3.3e-11 of the correctly rounded root, from below (up to
    /// rounding), on a sweep across f64's whole normal range (every binade, dense
    /// significands), on the powers of two and their neighbours, and on 0; lanes equal to
    /// the scalar.
    #[test]
    fn sqrt_is_within_its_stated_error() {
        let mut worst = 0.0f64;
        let mut check = |x: f64| {
            let got = sqrt(x);
            let want = x.sqrt();
            let rel = got / want - 1.0;
            assert!(
                rel.abs() <= 3.3e-11 && rel <= 1e-15,
                "sqrt({x:e}) = {got:e}, {rel:e}"
            );
            let lanes = sqrt(crate::wide::f64x4::splat(x)).to_array();
            assert!(lanes.iter().all(|l| l.to_bits() == got.to_bits()), "{x:e}");
            worst = worst.max(rel.abs());
        };
        let mut x = f64::MIN_POSITIVE;
        while x < f64::MAX / 1.000_013 {
            check(x);
            x *= 1.000_013;
        }
        for e in -1022..=1023 {
            let p = libm::exp2(f64::from(e));
            for q in [p, p * (1.0 + f64::EPSILON), p * (1.0 - f64::EPSILON / 2.0)] {
                if q.is_normal() {
                    check(q);
                }
            }
        }
        assert_eq!(sqrt(0.0f64), 0.0);
        // f32 types: within 1 ULP of the correctly rounded root, every f32 in [2^-24, 2^24) spaced by 2^-12 of a binade.
        let mut x = libm::exp2f(-24.0);
        while x < 16_777_216.0 {
            let (got, want) = (sqrt(x), x.sqrt());
            assert!(
                got.to_bits().abs_diff(want.to_bits()) <= 1,
                "sqrt({x:e}) = {got:e}"
            );
            assert_eq!(
                sqrt(crate::wide::f32x8::splat(x)).to_array()[3].to_bits(),
                got.to_bits()
            );
            x *= 1.000_17;
        }
        // The bound is met with little to spare: the seed's 3.5 % is the worst case.
        assert!(worst > 1e-11, "{worst:e}");
    }

    /// `round_tiny_f32` is `as f32` (to nearest, ties to even) on 0, on every f32 subnormal
    /// and the normals up to 2^-125 with the f64 values between them (ties included), and on
    /// a sweep of larger values.
    #[test]
    fn round_tiny_f32_rounds_as_the_conversion_does() {
        let check = |y: f64| {
            assert_eq!(round_tiny_f32(y).to_bits(), round_f32(y).to_bits(), "{y:e}");
        };
        check(0.0);
        for bits in 0..0x0100_0100u32 {
            let lo = f64::from(f32::from_bits(bits));
            let hi = f64::from(f32::from_bits(bits + 1));
            for t in [0.0, 0.25, 0.5, 0.75] {
                check(lo + (hi - lo) * t);
            }
        }
        let mut y = 1e-40f64;
        while y < 1e38 {
            check(y);
            y *= 1.000_37;
        }
    }
}
