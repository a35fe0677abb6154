//! Display transfer functions, luminance, and the colour matrices the tonemapping operators use.
//!
//! RGB travels as [`V3`] (x = red, y = green, z = blue), linear Rec.709 / sRGB primaries unless
//! a function says otherwise.

use crate::domain::{finite_or_nan, nan_unless};
use crate::real::Real;
use crate::vec3::V3;

/// Rec.709 / sRGB luminance weights (ITU-R BT.709-6, item 3.2): Y = 0.2126 R + 0.7152 G +
/// 0.0722 B.
pub const REC709_LUMA: [f64; 3] = [0.2126, 0.7152, 0.0722];

/// Relative luminance of a linear Rec.709 colour, with [`REC709_LUMA`]. Any finite
/// components (negative ones included: luminance is linear); a NaN component gives NaN; a
/// sum beyond the type's range for finite input is capped at +-MAX. Within 2 ulps of the
/// exact weighted sum of the rounded weights where the components share a sign.
#[inline]
#[must_use]
pub fn luminance<T: Real>(c: V3<T>) -> T {
    let y = c.x.mul_add(
        T::splat(REC709_LUMA[0]),
        c.y.mul_add(T::splat(REC709_LUMA[1]), c.z * T::splat(REC709_LUMA[2])),
    );
    let finite = c.x.is_finite() & c.y.is_finite() & c.z.is_finite();
    T::select(finite, y.clamp(-T::MAX, T::MAX), y)
}

/// A 3 x 3 matrix in row-major order, applied as `out_i = sum_j m[i][j] in_j`.
pub type Mat3 = [[f64; 3]; 3];

/// `m * c`. NaN in a component gives NaN in every output that weights it (NaN * 0 is NaN);
/// finite where each |m_ij c_j| sum stays below MAX.
#[inline]
#[must_use]
pub fn mul<T: Real>(m: &Mat3, c: V3<T>) -> V3<T> {
    let row = |r: [f64; 3]| {
        c.x.mul_add(
            T::splat(r[0]),
            c.y.mul_add(T::splat(r[1]), c.z * T::splat(r[2])),
        )
    };
    V3::new(row(m[0]), row(m[1]), row(m[2]))
}

/// sRGB inverse EOTF ("OETF", linear to encoded), IEC 61966-2-1:1999 section 5.2:
/// 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055, each piece exactly as the
/// standard defines it. The threshold is applied to the input's exact value (the f64 nearest
/// 0.0031308 lies below it, and no f64 lies between the two, so comparing the input widened
/// to f64 against it decides every f32 and f64 input as the real threshold would).
///
/// The standard's pieces do not meet: at 0.0031308 the power piece is 2.85e-8 below the
/// linear one (0.0404499075 against 0.040449936; the IEC constants were rounded from an
/// exact-tangent design), so the curve as specified steps down by that much there, about
/// 1/500 of a 16-bit code. It is followed as specified; each piece is monotone.
///
/// Evaluated per lane in f64 ([`Real::map_f64`]; the `pow` it needs is per lane anyway): one
/// `pow`, then one Newton step against the power piece of the EOTF evaluated with a two-word
/// base. Against the standard's formula in 300-bit arithmetic (mpmath; 2,300 points per type:
/// uniform on [0, 1] and [0, 0.05], log-uniform down to 1e-26, 40 neighbours of each
/// breakpoint, 0, subnormals, 1, 2, 100): within 1 ulp in f32 and f32x8 (every point
/// correctly rounded or 1 ulp off), and within 2.8 ulps in f64 and f64x4 (the MPFR oracle's
/// deep search over 10^5 fresh points and a hill-climb: max 2.57). OETF(EOTF(x)) is within 1 ulp
/// of x in f32 and 2 in f64 over [0, 1] outside the seam's interval (0.040449936, 0.04045],
/// and every 8- and 16-bit code round-trips exactly (`cargo test --test tonemap color_transfer:: --
/// --nocapture`). [`srgb_oetf_fast`] is the plain single-`pow` form in the input's own precision.
///
/// Domain: every finite value. Negative input is clamped to 0 (a documented input clamp: so
/// one slightly negative pixel from a filter encodes as black); NaN and +-inf give NaN (crate
/// docs, "Bad input", rule 5: an infinite radiance is an overflow upstream). Above 1 the
/// power curve continues (clamp before quantizing).
#[inline]
#[must_use]
pub fn srgb_oetf<T: Real>(x: T) -> T {
    display_input(x).map_f64(srgb_oetf_f64)
}

/// [`srgb_oetf`] in the input's own precision without the refinement: one `pow`, the same
/// pieces and threshold (compared in the input's precision: the f32 nearest 0.0031308 lies
/// 9e-11 above it, so that one f32 input takes the linear piece here and the power piece in
/// [`srgb_oetf`]). Within 5 ulps of the standard on [0, 1] in f32 and f64 (the rounding of
/// the exponent 1/2.4 and of 1.055 x^(1/2.4) - 0.055; f32: 3.08 ulps over every input,
/// `oracle/tests/exhaustive_f32.rs`). Above 1 the exponent's rounding is multiplied by ln x:
/// up to 16.6 ulps in f32 (at 1.7e38, same sweep; about 3.5 at 1e9) and, by the same
/// estimate, about 120 in f64 near its largest value. Negative input gives 0, NaN and +-inf
/// give NaN.
#[inline]
#[must_use]
pub fn srgb_oetf_fast<T: Real>(x: T) -> T {
    let x = display_input(x);
    let lin = x * T::splat(12.92);
    let pow = T::splat(1.055).mul_add(x.pow(T::splat(1.0 / 2.4)), T::splat(-0.055));
    T::select(x.simd_le(T::splat(SRGB_OETF_BREAK)), lin, pow)
}

/// The OETF's breakpoint, 0.0031308, as IEC 61966-2-1 specifies it (the f64 nearest; no f64
/// lies between it and the real 0.0031308, so `x <= SRGB_OETF_BREAK` decides every f64 as the
/// standard does).
pub const SRGB_OETF_BREAK: f64 = 0.003_130_8;

/// The EOTF's breakpoint, 0.04045, as IEC 61966-2-1 specifies it (the f64 nearest, which lies
/// below the real 0.04045 with no f64 in between). It is not the image 12.92 * 0.0031308 =
/// 0.040449936 of the OETF's breakpoint: the standard rounded it. At 0.04045 the EOTF's power
/// piece lies 2.33e-9 above its linear one (0.0031308073 against 0.0031308050), so the EOTF is
/// monotone; between 0.040449936 and 0.04045 an encoded value decodes on the linear piece and
/// re-encodes on the power piece, 2.85e-8 lower (the OETF's step, see [`srgb_oetf`]).
pub const SRGB_EOTF_BREAK: f64 = 0.040_45;

/// sRGB EOTF (encoded to linear), IEC 61966-2-1:1999 section 5.2: x / 12.92 for
/// x <= [`SRGB_EOTF_BREAK`] (0.04045), else ((x + 0.055) / 1.055)^2.4.
///
/// Evaluated per lane in f64 with the base (x + 0.055) / 1.055 carried as two words (its
/// rounding would otherwise cost up to 2.4 ulps: the base lies in a binade up to twice as
/// coarse as x) and folded back into the power to first order, with the rounding of the
/// exponent 2.4 in f64 (a factor b^(2.4 - fl(2.4)), up to 1.9 ulps near the breakpoint).
/// Against the standard's formula in 300-bit arithmetic (mpmath, the points of
/// [`srgb_oetf`]): within 1 ulp in f32 and f32x8; within 2.5 ulps in f64 and f64x4 (the MPFR
/// oracle's deep search: max 2.27; libm's `pow`).
///
/// Domain: every finite value. Negative input is clamped to 0, NaN and +-inf give NaN (rule
/// 5); above 1 the curve continues, and results beyond the type's range (f32 inputs above
/// about 1e16, f64 above 1e128) are capped at MAX.
#[inline]
#[must_use]
pub fn srgb_eotf<T: Real>(x: T) -> T {
    cap_finite(x, display_input(x).map_f64(srgb_eotf_f64))
}

/// `y` with values above MAX lowered to MAX where the input `x` is finite (a power of a
/// finite input overflowing), unchanged (+inf, NaN) otherwise.
#[inline]
fn cap_finite<T: Real>(x: T, y: T) -> T {
    T::select(x.is_finite(), y.min(T::MAX), y)
}

/// (s, e) with s = fl(a + b) and s + e = a + b exactly (Knuth's TwoSum).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// The EOTF's power piece ((x + 0.055) / 1.055)^2.4 for any x > -0.055.
fn srgb_eotf_pow_f64(x: f64) -> f64 {
    let (s, s_err) = two_sum(x, 0.055);
    let b = s / 1.055;
    // The division's exact remainder by a fused multiply-add (libm's `fma` is exact in
    // software where the target has no FMA instruction), plus the addition's error.
    let rem = libm::fma(-b, 1.055, s) + s_err;
    let b_lo = rem / 1.055;
    let p = libm::pow(b, 2.4);
    // (b + b_lo)^2.4 = b^2.4 (1 + 2.4 b_lo / b) to first order; b_lo / b < 2^-52. The f64
    // exponent is 2.4 - EXPONENT_2_4_TAIL: the power it gives is off by the factor
    // b^tail = 1 + tail ln b (up to 1.9 ulps near the breakpoint, where ln b = -2.3), restored
    // to first order too.
    p + p * (2.4 * b_lo / b + EXPONENT_2_4_TAIL * libm::log(b))
}

/// 12/5 - fl(2.4): the rounding of the EOTF's exponent in f64.
const EXPONENT_2_4_TAIL: f64 = 8.881_784_197_001_253e-17;

fn srgb_eotf_f64(x: f64) -> f64 {
    if x <= SRGB_EOTF_BREAK {
        return x / 12.92;
    }
    let p = srgb_eotf_pow_f64(x);
    // A power that overflows (x above about 1e128) stays +inf, capped by the caller (the
    // first-order correction would form inf * 0).
    if p.is_finite() { p } else { libm::pow(x, 2.4) }
}

fn srgb_oetf_f64(x: f64) -> f64 {
    if x <= SRGB_OETF_BREAK {
        return x * 12.92;
    }
    let y = 1.055 * libm::pow(x, 1.0 / 2.4) - 0.055;
    // Newton on the power piece's inverse, EOTF_pow(y) = x, with
    // EOTF_pow'(y) = 2.4 EOTF_pow(y) / (y + 0.055). Always against the power piece: the
    // OETF's power piece is the exact inverse of the EOTF's, whatever side of 0.04045 y is.
    let e = srgb_eotf_pow_f64(y);
    let step = (e - x) * (y + 0.055) / (2.4 * e);
    if step.is_finite() { y - step } else { y }
}

/// The Rec.709 OETF's breakpoint 0.018 (ITU-R BT.709-6, item 1.2), as the f64 nearest it;
/// that f64 lies 1.4e-18 below 0.018, so [`rec709_oetf`] tests `L <= REC709_BREAK` to decide
/// every f32 and f64 input as the standard's `L < 0.018` does.
pub const REC709_BREAK: f64 = 0.018;

/// Rec.709 OETF (ITU-R BT.709-6, item 1.2): 4.5 L for L < 0.018, else 1.099 L^0.45 - 0.099.
///
/// The threshold follows the standard for the input's exact value: evaluated per lane in
/// f64, so the f32 nearest 0.018 (7.7e-10 below it) takes the linear piece, 4.5 L = 0.081,
/// and the f64 nearest 0.018 (also below) too. The pieces do not meet: at 0.018 the power
/// piece gives 0.0812479, 2.5e-4 above 4.5 * 0.018 = 0.081 (BT.709's rounded constants), so
/// the curve steps up there. Against the formula evaluated in MPFR (the oracle's deep search,
/// `docs/accuracy.md`): within 0.7 ulp in f32 and f32x8, 3.7 ulps in f64 and f64x4, max 3.48
/// found (the 1.099 L^0.45 - 0.099 subtraction loses up to 1.2 bits near the breakpoint).
///
/// Domain: every finite value. Negative input is clamped to 0, NaN and +-inf give NaN (rule
/// 5); above 1 the power curve continues.
#[inline]
#[must_use]
pub fn rec709_oetf<T: Real>(l: T) -> T {
    display_input(l).map_f64(rec709_oetf_f64)
}

fn rec709_oetf_f64(l: f64) -> f64 {
    if l <= REC709_BREAK {
        return 4.5 * l;
    }
    libm::fma(1.099, libm::pow(l, 0.45), -0.099)
}

/// Plain gamma encoding x^(1 / gamma) (the classic display gamma correction; 2.2 approximates
/// sRGB). Domain: gamma in (0, MAX] (gamma <= 0, +inf and NaN give NaN); x any finite value,
/// negative clamped to 0, NaN and +-inf give NaN (rule 5); results that overflow for finite x (gamma < 1,
/// x > 1) are capped at MAX. The exponent 1 / gamma is rounded once, which costs up to
/// |ln x| / gamma * 0.5 ulp on top of `pow`'s ulp (f32 x = 1e-30 with gamma 2.2: 16 ulps).
#[inline]
#[must_use]
pub fn gamma_encode<T: Real>(x: T, gamma: T) -> T {
    let ok = gamma.simd_gt(T::ZERO) & gamma.simd_le(T::MAX);
    nan_unless(ok, cap_finite(x, display_input(x).pow(gamma.recip())))
}

/// Plain gamma decoding x^gamma, the inverse of [`gamma_encode`]: within `pow`'s 1 ulp.
/// Domain as [`gamma_encode`] (overflow for finite x > 1 is capped at MAX).
#[inline]
#[must_use]
pub fn gamma_decode<T: Real>(x: T, gamma: T) -> T {
    let ok = gamma.simd_gt(T::ZERO) & gamma.simd_le(T::MAX);
    nan_unless(ok, cap_finite(x, display_input(x).pow(gamma)))
}

/// `max(x, 0)` with NaN kept: the input clamp of every display function (a negative value is
/// clamped, a NaN is reported).
#[inline]
pub(crate) fn non_negative<T: Real>(x: T) -> T {
    T::select(x.simd_lt(T::ZERO), T::ZERO, x)
}

/// The input clamp of the transfer functions: [`non_negative`], with +-inf sent to NaN (crate
/// docs, "Bad input", rule 5) where the tonemap operators' own clamp ([`non_negative`] and
/// `MAX_INPUT`) keeps them as documented ends.
#[inline]
fn display_input<T: Real>(x: T) -> T {
    non_negative(finite_or_nan(x))
}

/// [`srgb_oetf`] per channel.
#[inline]
#[must_use]
pub fn srgb_oetf_rgb<T: Real>(c: V3<T>) -> V3<T> {
    V3::new(srgb_oetf(c.x), srgb_oetf(c.y), srgb_oetf(c.z))
}

/// [`srgb_eotf`] per channel.
#[inline]
#[must_use]
pub fn srgb_eotf_rgb<T: Real>(c: V3<T>) -> V3<T> {
    V3::new(srgb_eotf(c.x), srgb_eotf(c.y), srgb_eotf(c.z))
}

/// Linear sRGB to the ACES fit's working space (the product of sRGB -> XYZ -> D65-to-D60
/// -> AP1 -> RRT saturation), from Stephen Hill's fit of the ACES RRT + sRGB ODT
/// (`ACESFitted.hlsl`, 2016).
pub const ACES_HILL_INPUT: Mat3 = [
    [0.59719, 0.35458, 0.04823],
    [0.07600, 0.90834, 0.01566],
    [0.02840, 0.13383, 0.83777],
];

/// The ODT side of Hill's fit: the working space back to linear sRGB (ODT saturation, AP1 ->
/// XYZ -> D60-to-D65 -> sRGB).
pub const ACES_HILL_OUTPUT: Mat3 = [
    [1.60475, -0.53108, -0.07367],
    [-0.10208, 1.10813, -0.00605],
    [-0.00327, -0.07276, 1.07602],
];

/// Linear Rec.709 (sRGB primaries) to linear Rec.2020, both with the D65 white: the exact
/// product of the two primaries' RGB-to-XYZ matrices (ITU-R BT.709-6 and BT.2020-2 primaries,
/// derived as in SMPTE RP 177), to f64 precision; ITU-R BT.2087 tabulates it to 4 decimals.
/// Every entry is positive, so it maps non-negative colours to non-negative colours.
pub const REC709_TO_REC2020: Mat3 = [
    [
        0.627_403_895_934_699,
        0.329_283_038_377_883_7,
        0.043_313_065_687_417_225,
    ],
    [
        0.069_097_289_358_232_08,
        0.919_540_395_075_458_7,
        0.011_362_315_566_309_178,
    ],
    [
        0.016_391_438_875_150_28,
        0.088_013_307_877_225_75,
        0.895_595_253_247_624,
    ],
];

/// Linear Rec.2020 to linear Rec.709 (D65), the exact inverse of [`REC709_TO_REC2020`]
/// (ITU-R BT.2407 tabulates it to 4 decimals). Colours outside the Rec.709 gamut come out
/// with negative components.
pub const REC2020_TO_REC709: Mat3 = [
    [
        1.660_491_002_108_434_5,
        -0.587_641_138_788_549_5,
        -0.072_849_863_319_884_88,
    ],
    [
        -0.124_550_474_521_590_74,
        1.132_899_897_125_960_3,
        -0.008_349_422_604_369_477,
    ],
    [
        -0.018_150_763_354_905_303,
        -0.100_578_898_008_007_39,
        1.118_729_661_362_912_7,
    ],
];

/// AgX inset for Rec.2020 input, from Blender's AgX (Eary Chow's `AgXBaseRec2020.py`), as
/// Filament's `ToneMapper.cpp` and three.js's `AgXToneMapping` ship it. Rows sum to 1, so
/// greys stay grey.
pub const AGX_INSET_REC2020: Mat3 = [
    [
        0.856_627_153_315_983,
        0.095_121_240_538_158_8,
        0.048_251_606_145_858_3,
    ],
    [
        0.137_318_972_929_847,
        0.761_241_990_602_591,
        0.101_439_036_467_562,
    ],
    [
        0.111_898_212_999_95,
        0.076_799_418_603_190_3,
        0.811_302_368_396_859,
    ],
];

/// AgX outset for Rec.2020: the exact inverse of Blender's published outset-inverse matrix
/// (Filament's `AgXOutsetMatrixInv`, rows (0.899796955911611, 0.0871996192028351,
/// 0.013003424885555), (0.11142098895748, 0.875575586156966, 0.0130034248855548),
/// (0.11142098895748, 0.0871996192028349, 0.801379391839686)), which Filament and three.js
/// invert; it is not the inverse of [`AGX_INSET_REC2020`].
pub const AGX_OUTSET_REC2020: Mat3 = [
    [
        1.127_100_581_814_436_6,
        -0.110_606_643_096_603_22,
        -0.016_493_938_717_834_57,
    ],
    [
        -0.141_329_763_498_438_26,
        1.157_823_702_216_271_8,
        -0.016_493_938_717_834_253,
    ],
    [
        -0.141_329_763_498_438_26,
        -0.110_606_643_096_602_92,
        1.251_936_406_595_040_2,
    ],
];

/// AgX inset for Rec.709 input: linear Rec.709 into the AgX log-encoding space (Troy Sobotka's
/// AgX, as published by Wrensch 2023, "Minimal AgX Implementation"). Rows sum to 1.
pub const AGX_INSET: Mat3 = [
    [
        0.842_479_062_253_094,
        0.078_433_599_999_999_2,
        0.079_223_745_147_764_3,
    ],
    [
        0.042_328_242_261_012_3,
        0.878_468_636_469_772,
        0.079_166_127_460_543_4,
    ],
    [0.042_375_654_905_705_1, 0.078_433_6, 0.879_142_973_793_104],
];

/// AgX outset for Rec.709, as Wrensch 2023 publishes it: the inverse of [`AGX_INSET`] (to
/// about 1e-15), back to Rec.709.
pub const AGX_OUTSET: Mat3 = [
    [
        1.196_879_005_120_17,
        -0.098_020_881_140_136_8,
        -0.099_029_744_079_720_5,
    ],
    [
        -0.052_896_851_757_456_2,
        1.151_903_129_904_17,
        -0.098_961_176_844_843_3,
    ],
    [
        -0.052_971_635_514_443_8,
        -0.098_043_450_117_124_1,
        1.151_073_672_641_16,
    ],
];
