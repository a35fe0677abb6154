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
/// 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055, refined by one Newton step
/// against [`srgb_eotf`], so that it inverts the implemented EOTF rather than the ideal one.
/// OETF(EOTF(x)) is within 4 ulps of x over [0, 1] in f32 and f64 (83% exact, 99.4% within
/// 1 ulp; `cargo test --test color_transfer -- --nocapture`); the rest is the EOTF rounding its
/// base (x + 0.055) / 1.055 into a coarser binade than x, which a two-word base would remove.
/// Every 8- and 16-bit code round-trips exactly. The step costs a second `pow`;
/// [`srgb_oetf_fast`] skips it.
///
/// Domain [0, 1]; negative input and NaN give 0 (so one bad pixel cannot poison an 8-bit
/// image); above 1 the curve continues (clamp before quantizing).
#[inline]
#[must_use]
pub fn srgb_oetf<T: Real>(x: T) -> T {
    let x = non_negative(x);
    let y = srgb_oetf_fast(x);
    // Newton on EOTF(y) = x: EOTF'(y) = 2.4 EOTF(y) / (y + 0.055) on the power piece.
    let e = srgb_eotf(y);
    let step = (e - x) * (y + T::splat(0.055)) / (T::splat(2.4) * e);
    let refined = T::select(e.simd_gt(T::ZERO) & step.is_finite(), y - step, y);
    T::select(x.simd_le(T::splat(0.003_130_8)), y, refined)
}

/// [`srgb_oetf`] without the refinement step: one `pow`; its round trip with [`srgb_eotf`] is
/// within 5 ulps (the rounding of the exponent 1/2.4 and of 1.055 x^(1/2.4) - 0.055 adds to the
/// EOTF's own).
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
/// See [`srgb_oetf`] for the round-trip accuracy.
#[inline]
#[must_use]
pub fn srgb_eotf<T: Real>(x: T) -> T {
    let x = non_negative(x);
    let lin = x / T::splat(12.92);
    let pow = ((x + T::splat(0.055)) / T::splat(1.055)).pow(T::splat(2.4));
    T::select(x.simd_le(T::splat(SRGB_EOTF_BREAK)), lin, pow)
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

/// Plain gamma encoding x^(1 / gamma) (seed S1's gamma correction; 2.2 approximates sRGB).
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
