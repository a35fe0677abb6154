//! Display transfer functions, luminance, and the colour matrices the tonemapping operators use.
//!
//! RGB travels as [`V3`] (x = red, y = green, z = blue), linear Rec.709 / sRGB primaries unless
//! a function says otherwise.

use crate::real::Real;
use crate::vec3::V3;

/// Rec.709 / sRGB luminance weights (ITU-R BT.709-6, item 3.2): Y = 0.2126 R + 0.7152 G +
/// 0.0722 B.
pub const REC709_LUMA: [f64; 3] = [0.2126, 0.7152, 0.0722];

/// Relative luminance of a linear Rec.709 colour, with [`REC709_LUMA`].
#[inline]
#[must_use]
pub fn luminance<T: Real>(c: V3<T>) -> T {
    c.x.mul_add(
        T::splat(REC709_LUMA[0]),
        c.y.mul_add(T::splat(REC709_LUMA[1]), c.z * T::splat(REC709_LUMA[2])),
    )
}

/// A 3 x 3 matrix in row-major order, applied as `out_i = sum_j m[i][j] in_j`.
pub type Mat3 = [[f64; 3]; 3];

/// `m * c`.
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

/// sRGB inverse EOTF ("OETF", linear to encoded), piecewise form of IEC 61966-2-1:1999:
/// 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055.
///
/// Evaluated per lane in f64 ([`Real::map_f64`]; the `pow` it needs is per lane anyway): one
/// `pow`, then one Newton step against the two-word [`srgb_eotf`], so that it inverts the EOTF
/// as implemented, not only the ideal curve. OETF(EOTF(x)) is within 1 ulp of x over [0, 1]
/// in f32 and f32x8, and within 2 ulps in f64 (410 points in a million, where EOTF(x) sits at
/// the bottom of its binade and libm's pow rounding shows); every 8- and 16-bit code
/// round-trips exactly (`cargo test --test color_transfer -- --nocapture`). [`srgb_oetf_fast`] is the plain
/// single-`pow` form in the input's own precision, for hot paths.
///
/// Domain [0, 1]; negative input and NaN give 0 (so one bad pixel cannot poison an 8-bit
/// image); above 1 the curve continues (clamp before quantizing).
#[inline]
#[must_use]
pub fn srgb_oetf<T: Real>(x: T) -> T {
    non_negative(x).map_f64(srgb_oetf_f64)
}

/// [`srgb_oetf`] in the input's own precision without the refinement: one `pow`; its round
/// trip with [`srgb_eotf`] is within 5 ulps in f32 and f64 (the rounding of the exponent 1/2.4
/// and of 1.055 x^(1/2.4) - 0.055).
#[inline]
#[must_use]
pub fn srgb_oetf_fast<T: Real>(x: T) -> T {
    let x = non_negative(x);
    let lin = x * T::splat(12.92);
    let pow = T::splat(1.055).mul_add(x.pow(T::splat(1.0 / 2.4)), T::splat(-0.055));
    T::select(x.simd_le(T::splat(0.003_130_8)), lin, pow)
}

/// The EOTF's breakpoint: the image 12.92 * 0.0031308 = 0.040449936 of the OETF's, not the
/// standard's rounded 0.04045. Between the two the standard's pieces differ by under 1e-9
/// (its constants leave that seam); placing the breakpoint at the exact image makes each
/// piece of the EOTF the exact inverse of the matching piece of the OETF, so round trips do
/// not cross pieces (`tests/color_transfer.rs`).
pub const SRGB_EOTF_BREAK: f64 = 12.92 * 0.003_130_8;

/// sRGB EOTF (encoded to linear), piecewise form of IEC 61966-2-1:1999: x / 12.92 for
/// x <= [`SRGB_EOTF_BREAK`], else ((x + 0.055) / 1.055)^2.4. Negative and NaN give 0.
///
/// Evaluated per lane in f64 with the base (x + 0.055) / 1.055 carried as two words (its
/// rounding would otherwise cost up to 2.4 ulps: the base lies in a binade up to twice as
/// coarse as x) and folded back into the power to first order. See [`srgb_oetf`] for the
/// round-trip accuracy this buys.
#[inline]
#[must_use]
pub fn srgb_eotf<T: Real>(x: T) -> T {
    non_negative(x).map_f64(srgb_eotf_f64)
}

/// (s, e) with s = fl(a + b) and s + e = a + b exactly (Knuth's TwoSum).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn srgb_eotf_f64(x: f64) -> f64 {
    if x <= SRGB_EOTF_BREAK {
        return x / 12.92;
    }
    let (s, s_err) = two_sum(x, 0.055);
    let b = s / 1.055;
    // The division's exact remainder by a fused multiply-add (libm's `fma` is exact in
    // software where the target has no FMA instruction), plus the addition's error.
    let rem = libm::fma(-b, 1.055, s) + s_err;
    let b_lo = rem / 1.055;
    let p = libm::pow(b, 2.4);
    // (b + b_lo)^2.4 = b^2.4 (1 + 2.4 b_lo / b) to first order; b_lo / b < 2^-52.
    p + p * (2.4 * b_lo / b)
}

fn srgb_oetf_f64(x: f64) -> f64 {
    if x <= 0.003_130_8 {
        return x * 12.92;
    }
    let y = 1.055 * libm::pow(x, 1.0 / 2.4) - 0.055;
    // Newton on EOTF(y) = x: EOTF'(y) = 2.4 EOTF(y) / (y + 0.055) on the power piece.
    let e = srgb_eotf_f64(y);
    let step = (e - x) * (y + 0.055) / (2.4 * e);
    if step.is_finite() { y - step } else { y }
}

/// Rec.709 OETF (ITU-R BT.709-6, item 1.2): 4.5 L for L < 0.018, else 1.099 L^0.45 - 0.099.
/// Negative and NaN give 0.
#[inline]
#[must_use]
pub fn rec709_oetf<T: Real>(l: T) -> T {
    let l = non_negative(l);
    let lin = l * T::splat(4.5);
    let pow = T::splat(1.099).mul_add(l.pow(T::splat(0.45)), T::splat(-0.099));
    T::select(l.simd_lt(T::splat(0.018)), lin, pow)
}

/// Plain gamma encoding x^(1 / gamma) (the classic display gamma correction; 2.2 approximates sRGB).
/// Negative and NaN give 0; gamma must be positive.
#[inline]
#[must_use]
pub fn gamma_encode<T: Real>(x: T, gamma: T) -> T {
    non_negative(x).pow(gamma.recip())
}

/// Plain gamma decoding x^gamma, the inverse of [`gamma_encode`]. Negative and NaN give 0.
#[inline]
#[must_use]
pub fn gamma_decode<T: Real>(x: T, gamma: T) -> T {
    non_negative(x).pow(gamma)
}

/// `max(x, 0)` with NaN mapped to 0: the input guard of every display function.
#[inline]
pub(crate) fn non_negative<T: Real>(x: T) -> T {
    T::select(x.simd_gt(T::ZERO), x, T::ZERO)
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

/// AgX inset: linear Rec.709 into the AgX log-encoding space (Troy Sobotka's AgX, as
/// published in the minimal implementation of Wrensch 2023, "Minimal AgX Implementation").
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

/// AgX outset: the inverse of [`AGX_INSET`], back to Rec.709.
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
