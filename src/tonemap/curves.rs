//! The tone curves: exposure, the Reinhard family, the ACES fits, Hable, Lottes, Uchimura and
//! Khronos PBR Neutral.

use super::{per_channel, sanitize, sanitize_rgb, saturate_rgb};
use crate::color::{self, ACES_HILL_INPUT, ACES_HILL_OUTPUT, luminance};
use crate::domain::{nan_unless, nan_where};
use crate::dw::{Dw, two_prod};
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nan3;

/// True for f32 and its lanes (a 24-bit significand), where f64 arithmetic is exact enough.
#[inline]
fn single<T: Real>() -> bool {
    let eps: f64 = T::EPSILON.lane(0).into();
    eps > 1e-10
}

/// e^y - 1 without the cancellation of `exp(y) - 1` near y = 0: Kahan's trick (Kahan 2004,
/// "A Logarithm Too Clever by Half"; Higham 2002, "Accuracy and Stability of Numerical
/// Algorithms", 1.14.1): with u = fl(e^y), (u - 1) y / ln u, which divides out the rounding
/// error of u (u - 1 is exact near 1); y itself where u rounds to 1, -1 where u - 1 rounds
/// to -1 (u below half an ulp of 1, or 0), +inf where u overflows. NaN gives NaN.
#[inline]
fn expm1<T: Real>(y: T) -> T {
    let u = y.exp();
    let um1 = u - T::ONE;
    let ratio = um1 * y / u.ln();
    let v = T::select(um1.simd_eq(-T::ONE), -T::ONE, ratio);
    let v = T::select(u.simd_eq(T::INFINITY), T::INFINITY, v);
    T::select(u.simd_eq(T::ONE), y, v)
}

/// The exponential exposure curve T(c) = 1 - exp(-c * exposure). T(0) = 0, T(inf) = 1.
/// `exposure` in (0, MAX] ([`super::Exposure`] builds one); 0, negative, +inf and NaN give NaN.
/// Evaluated as -expm1(-c exposure), so a small c keeps its relative accuracy instead of
/// losing it to the cancellation in 1 - exp(-c exposure): on f32 and f32x8 in f64 (the product
/// of two f32 values is exact there, Kahan's expm1 adds a few units of 2^-53) and rounded
/// once; on f64 and f64x4 with the product's rounding error carried as a double word
/// (expm1(p + e) = expm1(p) + e (1 + expm1(p)) to first order) and the C library's expm1
/// lane by lane.
///
/// Peers: none of three.js, Filament and bevy ships 1 - exp(-e c) as an operator (three.js's
/// `LinearToneMapping` is saturate(e c); bevy uses 1 - exp(-x) only inside its
/// `SomewhatBoringDisplayTransform`, which also desaturates).
#[inline]
#[must_use]
pub fn exposure_curve<T: Real>(c: T, exposure: T) -> T {
    let ok = exposure.simd_gt(T::ZERO) & exposure.simd_le(T::MAX);
    let c = sanitize(c);
    let t = T::via_f64(
        [c, exposure],
        ExposureCurve,
        crate::real::sealed::Token::NEW,
    );
    nan_unless(ok, nan_where(c.is_nan(), t.saturate()))
}

/// 1 - exp(-c e) for the sanitized c and any e (the caller maps an invalid e to NaN).
#[derive(Clone, Copy)]
struct ExposureCurve;

impl crate::real::sealed::Widened<2> for ExposureCurve {
    /// c e, and with it the result, can lie below f32's smallest normal number.
    const TINY: bool = true;

    #[inline]
    fn native<T: Real>(self, [c, e]: [T; 2]) -> T {
        // c e = p + err exactly (while p is finite and above 2^-969, where a smaller p's lost
        // bits lie far below the result's last place). Where p >= 40 the result rounds to 1
        // and err is dropped (it may be NaN once c e overflows). An exposure above 2^960 is
        // moved by 2^-64 to c (c <= 1e9, both scalings exact), whose Veltkamp split without
        // FMA overflows near the largest finite value.
        let big = e.simd_gt(T::splat(9.745_314_011_4e288));
        let c = c * T::select(big, T::splat(18_446_744_073_709_551_616.0), T::ONE);
        let e = e * T::select(big, T::splat(5.421_010_862_427_522e-20), T::ONE);
        let (p, err) = two_prod(c, e);
        let m = T::from_fn(|i| {
            let x: f64 = (-p).lane(i).into();
            <T::Scalar as Real>::splat(libm::expm1(x))
        });
        let err = T::select(p.simd_lt(T::splat(40.0)), err, T::ZERO);
        // 1 - exp(-p - err) = -m + err exp(-p) = -m + err (1 + m).
        err.mul_add(T::ONE + m, -m)
    }

    #[inline]
    fn wide<W: Real<Scalar = f64>>(self, [c, e]: [W; 2]) -> W {
        // c and e are f32 values: their product has at most 48 significant bits and lies
        // within f64's range, so it is exact.
        -expm1(-(c * e))
    }
}

/// Reinhard, Stark, Shirley, Ferwerda 2002, "Photographic Tone Reproduction for Digital
/// Images", eq. 3 per channel: c / (1 + c).
///
/// Peers: three.js `ReinhardToneMapping` at `toneMappingExposure` e is `reinhard(e * c)` per
/// channel; bevy `Tonemapping::Reinhard` is `reinhard` per channel. Filament ships none.
#[inline]
#[must_use]
pub fn reinhard<T: Real>(c: T) -> T {
    let c = sanitize(c);
    (c / (T::ONE + c)).saturate()
}

/// Extended Reinhard (Reinhard et al. 2002, eq. 4) per channel with white point w:
/// c (1 + c / w^2) / (1 + c), which reaches 1 at c = w (clamped beyond). w in (0, MAX]; 0,
/// negative, +inf and NaN give NaN. c / w^2 is formed as (c / w) / w, so a subnormal w
/// neither overflows w^2 to 0 nor forms 0 / 0 at c = 0.
///
/// Evaluated in double words of the lane type (about 48 bits for f32 lanes, 106 for f64) and
/// rounded once (plain arithmetic, six roundings, reached 3.3 ulps). Where 1 + c / w^2
/// exceeds 2^64 (a white point far below c, where the result all but saturates) the plain
/// form is used, so no double word overflows.
///
/// Peers: none of three.js, Filament and bevy ships it. The paper applies eq. 4 to
/// luminance: that is [`reinhard_extended_luminance`].
#[inline]
#[must_use]
pub fn reinhard_extended<T: Real>(c: T, white: T) -> T {
    let c = sanitize(c);
    let ok = white.simd_gt(T::ZERO) & white.simd_le(T::MAX);
    let num = T::ONE + c / white / white;
    let plain = c * num / (T::ONE + c);
    // Below 2^64 the double words stay far inside f32's range (c <= MAX_INPUT = 1e9); above
    // it the plain lanes are selected, whatever the double words gave there.
    let precise = num.simd_lt(T::splat(18_446_744_073_709_551_616.0));
    // Above w = 2^64, c / w^2 < 1e9 / 2^128 is far below an ulp of 1 and num is 1: the double
    // words would otherwise split w itself, which overflows near MAX.
    let (cd, wd) = (
        Dw::exact(c),
        Dw::exact(T::select(huge(white), T::ONE, white)),
    );
    let num_dw = Dw::select(
        huge(white),
        Dw::exact(T::ONE),
        cd.div(wd).div(wd).add_t(T::ONE),
    );
    let v = cd.mul(num_dw).div(Dw::sum(T::ONE, c)).value();
    nan_unless(ok, T::select(precise, v, plain).saturate())
}

/// Whether a white point is above 2^64, where L / w^2 (L <= 3 MAX_INPUT) is below 2^-98.
#[inline]
fn huge<T: Real>(white: T) -> T::Mask {
    white.simd_gt(T::splat(18_446_744_073_709_551_616.0))
}

/// Reinhard on luminance: L' = L / (1 + L), colour scaled by L' / L, i.e. c / (1 + L)
/// (Reinhard et al. 2002, applied to luminance as the paper does). Keeps hue; channels are
/// clamped to 1 (a saturated colour can exceed it). 1 + L, with L from the BT.709 decimal
/// weights, and the quotient are evaluated in double words of the lane type and rounded once
/// (plain arithmetic reached 3.6 ulps).
///
/// Peers: bevy `Tonemapping::ReinhardLuminance` is `reinhard_luminance(c)` (bevy divides
/// 0 / 0 at black, which gives 0 here). three.js and Filament ship none.
#[inline]
#[must_use]
pub fn reinhard_luminance<T: Real>(c: V3<T>) -> V3<T> {
    let c = sanitize_rgb(c);
    let d = luminance_dw(c).add_t(T::ONE);
    saturate_rgb(per_channel(c, |x| Dw::exact(x).div(d).value()))
}

/// Extended Reinhard on luminance (Reinhard et al. 2002, eq. 4, applied to luminance):
/// L' = L (1 + L / w^2) / (1 + L), colour scaled by L' / L = (1 + L / w^2) / (1 + L) (so a
/// black colour stays black), channels clamped to [0, 1]. Keeps hue; a grey reaches 1 at
/// L = w. w in (0, MAX]; 0, negative, +inf and NaN give NaN (in every channel), as does a NaN
/// channel. L / w^2 is formed as (L / w) / w, as in [`reinhard_extended`], and 1 + L / w^2
/// is capped at the largest finite value, so a tiny white point keeps a zero channel at 0.
///
/// The scale (1 + L / w^2) / (1 + L) and its product with each channel are evaluated in
/// double words of the lane type (about 48 bits for f32 lanes, 106 for f64), with L from the
/// BT.709 decimal weights carried to that precision, and rounded once (plain arithmetic, about
/// nine roundings, reached 5.1 ulps). Where 1 + L / w^2 exceeds 2^64 (a white point far below
/// the luminance, whose channels then all but saturate) the plain form is used, so no double
/// word overflows.
///
/// Peers: none of three.js, Filament and bevy ships it.
#[inline]
#[must_use]
pub fn reinhard_extended_luminance<T: Real>(c: V3<T>, white: T) -> V3<T> {
    let c = sanitize_rgb(c);
    let ok = white.simd_gt(T::ZERO) & white.simd_le(T::MAX);
    let l = luminance(c);
    // Capped: for a tiny white point L / w / w overflows to +inf, and a zero channel would
    // then give 0 * inf = NaN. Capped at MAX, a bright lane's channels still saturate to 1
    // (its L / w^2 exceeds MAX, so every nonzero channel's x * num / den does) and a zero
    // channel stays 0; below the cap nothing changes.
    let num = (T::ONE + l / white / white).min(T::MAX);
    let den = T::ONE + l;
    // Below 2^64 every double-word product stays far inside the range of f32 (channels are at
    // most MAX_INPUT = 1e9); above it the plain form's lanes are selected, whatever the
    // double words gave there.
    let precise = num.simd_lt(T::splat(18_446_744_073_709_551_616.0));
    let ld = luminance_dw(c);
    // As in `reinhard_extended`: above w = 2^64 the term L / w^2 is negligible beside 1.
    let wd = Dw::exact(T::select(huge(white), T::ONE, white));
    let num_dw = Dw::select(
        huge(white),
        Dw::exact(T::ONE),
        ld.div(wd).div(wd).add_t(T::ONE),
    );
    let scale = num_dw.div(ld.add_t(T::ONE));
    per_channel(c, |x| {
        let v = T::select(precise, Dw::exact(x).mul(scale).value(), x * num / den);
        nan_unless(ok, v.saturate())
    })
}

/// Reinhard-Jodie: per-channel Reinhard blended toward luminance Reinhard by the per-channel
/// result itself, lerp(c / (1 + L), c / (1 + c), c / (1 + c)) (the variant popularised by
/// user Jodie on Shadertoy, 2019; see Reinhard et al. 2002 for both parts).
///
/// With t = c / (1 + c) and 1 - t = 1 / (1 + c) the lerp is one fraction,
/// c (c (1 + L) + 1 + c) / ((1 + L) (1 + c)^2), all of whose terms are positive (no
/// cancellation, and no 1 - t for a bright channel); it is evaluated in double words of the
/// lane type (about 48 bits for f32 lanes, 106 for f64), with L from the BT.709 decimal
/// weights carried to that precision, and rounded once (the plain lerp reached 4.6 ulps).
///
/// Peers: none of three.js, Filament and bevy ships it.
#[inline]
#[must_use]
pub fn reinhard_jodie<T: Real>(c: V3<T>) -> V3<T> {
    let c = sanitize_rgb(c);
    let d = luminance_dw(c).add_t(T::ONE);
    let f = |x: T| {
        let xd = Dw::exact(x);
        let x1 = Dw::sum(T::ONE, x);
        let num = xd.mul(xd.mul(d).add(x1));
        let den = d.mul(x1.sq());
        num.div(den).value()
    };
    saturate_rgb(per_channel(c, f))
}

/// BT.709 luminance 0.2126 R + 0.7152 G + 0.0722 B in double words of the lane type, each
/// decimal weight carried to that precision (as the nearest f64 plus the rest). For the
/// operators' non-negative channels no term cancels; a NaN channel gives NaN.
#[inline]
fn luminance_dw<T: Real>(c: V3<T>) -> Dw<T> {
    let k = |hi: f64, tail: f64| Dw::<T>::constant(hi, tail);
    k(0.2126, -1.119_104_808_822_157_8e-17)
        .mul(Dw::exact(c.x))
        .add(k(0.7152, 5.311_306_949_806_749e-17).mul(Dw::exact(c.y)))
        .add(k(0.0722, -2.886_579_864_025_407e-19).mul(Dw::exact(c.z)))
}

/// Narkowicz's fit of the ACES filmic curve (Narkowicz 2015, "ACES Filmic Tone Mapping
/// Curve"): x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), clamped to [0, 1]. It includes the
/// RRT+ODT's brightening; Narkowicz scales input by 0.6 to match ACES' exposure (not applied
/// here). f(0) = 0, f(1) = 0.8038.
///
/// Evaluated in double words of the lane type (about 48 bits for f32 lanes, 106 for f64),
/// with each decimal constant carried to that precision: numerator and denominator by
/// Horner, their quotient, then one rounding, so the result is within a few hundredths of
/// an ulp of correctly rounded (plain Horner and a division reached 3.8 ulps).
///
/// Peers: Narkowicz's `ACESFilm(x)` is `aces_narkowicz(x)`, his ACES-exposure form
/// `aces_narkowicz(0.6 * x)`. Filament's `FilmicToneMapper` is the same curve without the
/// clamp: on linear sRGB (Filament's legacy `ToneMapping::FILMIC` path) it is
/// `aces_narkowicz` per channel; through `ColorGrading` Filament applies it to Rec.2020 values
/// and clamps only after converting back, which differs by up to 0.013 where a Rec.2020 channel
/// passes 7.24 (the curve rises to 1.033 there). three.js and bevy do not ship it.
#[inline]
#[must_use]
pub fn aces_narkowicz<T: Real>(c: T) -> T {
    let x = Dw::exact(sanitize(c));
    // Each decimal as its nearest f64 plus the rest (exact decimal minus that f64).
    let k = |hi: f64, tail: f64| Dw::<T>::constant(hi, tail);
    let num = k(2.51, 2.131_628_207_280_300_5e-16)
        .mul(x)
        .add(k(0.03, 1.110_223_024_625_156_6e-18))
        .mul(x);
    let den = k(2.43, -1.598_721_155_460_225_4e-16)
        .mul(x)
        .add(k(0.59, 3.108_624_468_950_438_4e-17))
        .mul(x)
        .add(k(0.14, -1.332_267_629_550_187_8e-17));
    // The denominator is at least 0.14; a NaN input gives NaN through every part.
    num.div(den).value().saturate()
}

/// The tails (exact decimal minus its nearest f64) of [`ACES_HILL_INPUT`]'s entries.
const HILL_INPUT_TAIL: [[f64; 3]; 3] = [
    [
        1.385_558_334_732_195_3e-18,
        -6.288_303_211_476_887e-18,
        -2.036_149_027_162_537e-18,
    ],
    [
        1.887_379_141_862_766_3e-18,
        -3.627_320_666_055_311_6e-17,
        -3.086_420_008_457_935e-19,
    ],
    [
        -1.632_027_846_198_98e-18,
        -4.511_946_372_076_636_5e-18,
        -1.467_270_749_344_607e-17,
    ],
];

/// The tails of [`ACES_HILL_OUTPUT`]'s entries.
const HILL_OUTPUT_TAIL: [[f64; 3]; 3] = [
    [
        1.012_523_398_458_142_8e-16,
        -3.481_659_405_224_491e-18,
        -6.261_657_858_885_883e-19,
    ],
    [
        4.067_857_162_226_573_4e-18,
        -5.940_137_270_954_437e-17,
        -1.776_356_839_400_250_5e-19,
    ],
    [
        -9.672_818_102_046_676e-20,
        5.226_929_999_935_237e-18,
        2.351_896_455_365_931_6e-17,
    ],
];

/// A decimal matrix (nearest f64 plus tail) times a double-word colour, in double words.
#[inline]
fn mul_dw<T: Real>(m: &color::Mat3, tail: &[[f64; 3]; 3], c: [Dw<T>; 3]) -> [Dw<T>; 3] {
    core::array::from_fn(|i| {
        let k = |j: usize| Dw::<T>::constant(m[i][j], tail[i][j]);
        k(0).mul(c[0]).add(k(1).mul(c[1])).add(k(2).mul(c[2]))
    })
}

/// Hill's rational fit of the ACES RRT + ODT tone curve in the fit's working space:
/// (v (v + 0.0245786) - 0.000090537) / (v (0.983729 v + 0.4329510) + 0.238081), in double
/// words with the decimal constants to twice the working precision.
#[inline]
fn rrt_odt_fit<T: Real>(v: Dw<T>) -> Dw<T> {
    let k = |hi: f64, tail: f64| Dw::<T>::constant(hi, tail);
    let a = v
        .mul(v.add(k(0.024_578_6, 9.404_921_286_204_626e-19)))
        .add(k(-9.0537e-5, 4.084_309_279_672_737e-21));
    let b = v
        .mul(
            k(0.983_729, 3.543_476_623_235_62e-17)
                .mul(v)
                .add(k(0.432_951, 2.524_558_340_155_636e-17)),
        )
        .add(k(0.238_081, 1.291_766_693_611_862_1e-17));
    a.div(b)
}

/// ACES RRT + sRGB ODT as fitted by Stephen Hill (2016, `ACESFitted.hlsl`, used in MJP's
/// BakingLab): [`ACES_HILL_INPUT`], the rational tone curve per channel, [`ACES_HILL_OUTPUT`],
/// clamped to [0, 1]. Toe: the curve is -0.00038 at 0, so black stays black after the clamp.
///
/// The fit's numerator has a root (v = 0.00337) and the output matrix has negative entries, so
/// dark colours cancel twice; the whole chain runs in double words (about twice the lane
/// type's precision) with the published decimal constants to that precision, and is rounded
/// once at the end (f32 lanes: in f64, then rounded once).
///
/// Peers: three.js `ACESFilmicToneMapping` at exposure e is `aces_hill(c * e / 0.6)` (three.js
/// brightens by 1/0.6; without it the two differ by up to 0.28); bevy `Tonemapping::AcesFitted`
/// is `aces_hill(c)`. Filament's `ACESToneMapper` and `ACESLegacyToneMapper` run the full
/// RRT + ODT, a different curve.
#[inline]
#[must_use]
pub fn aces_hill<T: Real>(c: V3<T>) -> V3<T> {
    let c = sanitize_rgb(c);
    if single::<T>() {
        // f32 lanes: plain f64 is twice their precision and cheaper than double words.
        return per_lane_rgb(c, |v| {
            let v = color::mul(&ACES_HILL_INPUT, v);
            let fit = |v: f64| {
                (v * (v + 0.024_578_6) - 0.000_090_537)
                    / (v * (0.983_729 * v + 0.432_951) + 0.238_081)
            };
            saturate_rgb(color::mul(&ACES_HILL_OUTPUT, per_channel(v, fit)))
        });
    }
    let v = mul_dw(
        &ACES_HILL_INPUT,
        &HILL_INPUT_TAIL,
        [Dw::exact(c.x), Dw::exact(c.y), Dw::exact(c.z)],
    );
    let f = v.map(rrt_odt_fit);
    let o = mul_dw(&ACES_HILL_OUTPUT, &HILL_OUTPUT_TAIL, f);
    saturate_rgb(V3::new(o[0].value(), o[1].value(), o[2].value()))
}

/// Parameters of Hable's filmic curve F(x) = (x (A x + C B) + D E) / (x (A x + B) + D F) - E / F,
/// applied as F(bias x) / F(W).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HableParams {
    /// Shoulder strength A.
    pub a: f64,
    /// Linear strength B.
    pub b: f64,
    /// Linear angle C.
    pub c: f64,
    /// Toe strength D.
    pub d: f64,
    /// Toe numerator E.
    pub e: f64,
    /// Toe denominator F.
    pub f: f64,
    /// Linear white point W.
    pub white: f64,
    /// Exposure bias applied to the input.
    pub exposure_bias: f64,
}

impl HableParams {
    /// The Uncharted 2 values (Hable 2010, "Filmic Tonemapping Operators"): A = 0.15,
    /// B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30, W = 11.2, exposure bias 2.
    pub const UNCHARTED2: Self = Self {
        a: 0.15,
        b: 0.50,
        c: 0.10,
        d: 0.20,
        e: 0.02,
        f: 0.30,
        white: 11.2,
        exposure_bias: 2.0,
    };

    /// Validated parameters: all finite and > 0, with
    /// - F(W) > 0, i.e. (F - E) A W + B (F C - E) > 0 (rejected as `e`): [`hable`] divides by
    ///   F(W), and where it is <= 0 the curve never reaches 1 (E = F with C = 1 makes F zero
    ///   everywhere, 0 / 0);
    /// - the curve's coefficients (products of up to five parameters, formed in f64) finite
    ///   and F(W) not underflowing to 0 (rejected as `white`): every parameter in
    ///   [1e-45, 1e61] suffices, far beyond any curve's (Hable's are 0.02 to 11.2).
    ///
    /// The curve then starts at F(0) = 0 and reaches 1 at input W / bias; it rises
    /// monotonically between when E < F, E < F C and C <= 1 (Hable's values qualify);
    /// otherwise it can dip below 0 near black or fall past a peak (both clamped to [0, 1]).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        a: f64,
        b: f64,
        c: f64,
        d: f64,
        e: f64,
        f: f64,
        white: f64,
        exposure_bias: f64,
    ) -> Result<Self, ParamError> {
        for (name, v) in [
            ("a", a),
            ("b", b),
            ("c", c),
            ("d", d),
            ("e", e),
            ("f", f),
            ("white", white),
            ("exposure_bias", exposure_bias),
        ] {
            require::<f64>(v > 0.0 && v.is_finite(), name, "finite and > 0")?;
        }
        let p = Self {
            a,
            b,
            c,
            d,
            e,
            f,
            white,
            exposure_bias,
        };
        require::<f64>(
            (f - e) * a * white + b * (f * c - e) > 0.0,
            "e",
            "with the other parameters, F(W) > 0: (F - E) A W + B (F C - E) > 0",
        )?;
        require::<f64>(
            p.folded().is_some(),
            "white",
            "with the other parameters, the curve's coefficients finite in f64 and F(W) not \
             underflowing to 0 (every parameter in [1e-45, 1e61] suffices)",
        )?;
        Ok(p)
    }

    /// True when every field is finite and > 0, the domain [`HableParams::new`] enforces.
    fn is_valid(&self) -> bool {
        [
            self.a,
            self.b,
            self.c,
            self.d,
            self.e,
            self.f,
            self.white,
            self.exposure_bias,
        ]
        .iter()
        .all(|v| *v > 0.0 && v.is_finite())
    }

    /// The coefficients [P b^2, Q b, R b^2 K, S b K, T K] of F(b x) / K, K = F(W) (see
    /// [`coefficients`](Self::coefficients)), each as an f64 and its tail (the double word
    /// rounded to f64 plus the rest), scaled by one power of two so the largest magnitude lies
    /// in [0.5, 1). The scaling is exact and cancels in the quotient, so it changes no result,
    /// but keeps x^2 times a coefficient finite in f32 for parameters far from 1. `None`
    /// where a coefficient is not finite or K is not > 0 (the domain [`HableParams::new`]
    /// enforces).
    fn folded(&self) -> Option<[(f64, f64); 5]> {
        let k = self.curve_dw(Dw::exact(self.white));
        let bias = Dw::exact(self.exposure_bias);
        let [cp, cq, cr, cs, ct] = self.coefficients();
        let b2 = bias.sq();
        let coef = [
            cp.mul(b2),
            cq.mul(bias),
            cr.mul(b2).mul(k),
            cs.mul(bias).mul(k),
            ct.mul(k),
        ]
        .map(|c| {
            let hi = c.value();
            (hi, (c.hi - hi) + c.lo)
        });
        let k = k.value();
        let big = coef.iter().fold(0.0_f64, |m, v| m.max(v.0.abs()));
        // `!(k > 0)` also rejects a NaN K.
        if !(k > 0.0 && k.is_finite() && big.is_finite())
            || coef.iter().any(|v| v.0.is_nan() || v.1.is_nan())
        {
            return None;
        }
        let (_, exp) = libm::frexp(big);
        Some(coef.map(|(hi, lo)| (libm::scalbn(hi, -exp), libm::scalbn(lo, -exp))))
    }

    /// F(x) in double-word f64 arithmetic, as one fraction (see [`hable`]).
    fn curve_dw(&self, x: Dw<f64>) -> Dw<f64> {
        let [p, q, r, s, t] = self.coefficients();
        let num = x.mul(p.mul(x).add(q));
        let den = r.mul(x).add(s).mul(x).add(t);
        num.div(den)
    }

    /// The one-fraction coefficients of F(x) = x (P x + Q) / (R x^2 + S x + T): P = (F - E) A,
    /// Q = B (F C - E), R = F A, S = F B, T = D F^2, in double words.
    fn coefficients(&self) -> [Dw<f64>; 5] {
        let k = Dw::exact;
        let (a, b, c, d, e, f) = (
            k(self.a),
            k(self.b),
            k(self.c),
            k(self.d),
            k(self.e),
            k(self.f),
        );
        [
            f.add(e.neg()).mul(a),
            b.mul(f.mul(c).add(e.neg())),
            f.mul(a),
            f.mul(b),
            d.mul(f).mul(f),
        ]
    }
}

/// Hable's filmic curve ("Uncharted 2"; Hable 2010, "Filmic Tonemapping Operators") per
/// channel: F(bias c) / F(W), clamped to [0, 1], with
/// F(x) = (x (A x + C B) + D E) / (x (A x + B) + D F) - E / F. F(0) = 0. Parameters outside
/// [`HableParams::new`]'s domain (a struct built by hand; F(W) <= 0 among them) give NaN.
///
/// F's two terms cancel for small x (F(x) is about x B (F C - E) / (D F^2) there, while
/// each term is about E / F); over one denominator the cancellation is exact:
/// F(x) = x ((F - E) A x + B (F C - E)) / (F (x (A x + B) + D F)). The coefficients of
/// F(bias c) / F(W), with the bias and 1 / F(W) folded in, are formed once per call in
/// double-word f64; numerator, denominator and quotient are then evaluated in double words
/// of the lane type (about 48 bits for f32 lanes, 106 for f64) and rounded once, so the
/// result is within a few hundredths of an ulp of correctly rounded (plain Horner and a
/// division, about nine roundings, reached 4.4 ulps near F = 1).
///
/// Peers: Hable's post's shader (`texColor *= 16`, ExposureBias 2, W = 11.2, then
/// pow(1/2.2)) is `gamma_encode(hable(16 * c, &HableParams::UNCHARTED2), 2.2)`: the 16 is a
/// pre-exposure for the post's image and the 1/2.2 a display encoding, neither part of the
/// curve. None of three.js, Filament and bevy ships it.
#[inline]
#[must_use]
pub fn hable<T: Real>(c: T, p: &HableParams) -> T {
    // F(b x) / K = x (P b^2 x + Q b) / (K (R b^2 x^2 + S b x + T)).
    let folded = if p.is_valid() { p.folded() } else { None };
    let Some([np, nq, dr, ds, dt]) = folded.map(|k| k.map(|(hi, lo)| Dw::<T>::constant(hi, lo)))
    else {
        return T::splat(f64::NAN);
    };
    let x = sanitize(c);
    let xd = Dw::exact(x);
    let num = np.mul(xd).add(nq).mul(xd);
    let den = dr.mul(xd).add(ds).mul(xd).add(dt);
    // The denominator's coefficients are > 0 but can round to 0 on the lane type where they
    // are tiny beside the numerator's (parameters far from 1): a zero denominator is the
    // curve's limit, 1 for a positive numerator (num / 0 = inf, saturated) and 0 at x = 0,
    // where num / den would be 0 / 0. A NaN x still gives NaN (the comparisons fail).
    let ok = den.hi.simd_gt(T::ZERO);
    let safe = Dw::select(ok, den, Dw::exact(T::ONE));
    // Where the quotient overflows (a denominator far below the numerator, from extreme
    // parameters) the double-word division forms inf - inf; the plain quotient is inf there,
    // which saturates to 1 like the curve.
    let q = num.div(safe).value();
    let q = T::select(q.is_nan(), num.hi / safe.hi, q);
    let v = T::select(ok, q, T::select(num.hi.simd_gt(T::ZERO), T::ONE, T::ZERO));
    nan_where(x.is_nan(), v.saturate())
}

/// The largest contrast [`LottesParams::new`] accepts: x^contrast is the curve's numerator,
/// and [`super::MAX_INPUT`]^34 = 1e306 is finite in f64 (1e9^34.3 is not), so the numerator never
/// overflows to meet an infinite denominator (inf / inf = NaN). Lottes' own value is 1.6.
pub const LOTTES_CONTRAST_MAX: f64 = 34.0;

/// Parameters of Lottes' curve x^a / (x^(a d) b + c) (b and c derived).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LottesParams {
    /// Contrast a (the toe's power).
    pub contrast: f64,
    /// Shoulder d.
    pub shoulder: f64,
    /// Input mapped to white.
    pub hdr_max: f64,
    /// Mid-grey input.
    pub mid_in: f64,
    /// Mid-grey output.
    pub mid_out: f64,
    b: f64,
    c: f64,
}

impl LottesParams {
    /// Lottes' defaults from the talk: contrast 1.6, shoulder 0.977, hdr_max 8, mid 0.18 ->
    /// 0.267.
    #[must_use]
    pub fn default_curve() -> Self {
        Self::derive(1.6, 0.977, 8.0, 0.18, 0.267)
    }

    /// Validated parameters: all finite and > 0, mid_in < hdr_max, mid_out < 1,
    /// contrast <= [`LOTTES_CONTRAST_MAX`] = 34, and derived b and c finite with c != 0
    /// (rejected as `shoulder`; then [`lottes`] gives a number in [0, 1] for every input).
    /// The last fails for parameters whose powers overflow f64 (contrast or shoulder near 0
    /// or MAX, hdr_max near MAX, subnormal mid points) and for contrast * shoulder so small
    /// that hdr_max^(a d) and mid_in^(a d) round to the same value. Where the mid point lies
    /// off what a rising curve through (hdr_max, 1) allows, b <= 0 or c < 0: the curve's
    /// denominator x^(a d) b + c changes sign (a pole), and the clamped result jumps between
    /// 0 and 1 there.
    pub fn new(
        contrast: f64,
        shoulder: f64,
        hdr_max: f64,
        mid_in: f64,
        mid_out: f64,
    ) -> Result<Self, ParamError> {
        for (name, v) in [
            ("contrast", contrast),
            ("shoulder", shoulder),
            ("hdr_max", hdr_max),
            ("mid_in", mid_in),
            ("mid_out", mid_out),
        ] {
            require::<f64>(v > 0.0 && v.is_finite(), name, "finite and > 0")?;
        }
        require::<f64>(mid_in < hdr_max, "mid_in", "below hdr_max")?;
        require::<f64>(mid_out < 1.0, "mid_out", "below 1")?;
        require::<f64>(
            contrast <= LOTTES_CONTRAST_MAX,
            "contrast",
            "at most 34 (MAX_INPUT^contrast finite in f64)",
        )?;
        let p = Self::derive(contrast, shoulder, hdr_max, mid_in, mid_out);
        // b and c fail to be finite where hdr_max^(a d) and mid_in^(a d) round to the same
        // value (their difference divides) or a power overflows f64; c != 0 keeps
        // f(0) = 0 / c a zero (c = 0 would be 0 / 0).
        require::<f64>(
            p.b.is_finite() && p.c.is_finite() && p.c != 0.0,
            "shoulder",
            "with contrast, hdr_max, mid_in and mid_out, derived b and c finite, c != 0",
        )?;
        Ok(p)
    }

    /// True when the public fields are in [`LottesParams::new`]'s domain, b and c are finite
    /// and c != 0.
    fn is_valid(&self) -> bool {
        let pos = |v: f64| v > 0.0 && v.is_finite();
        pos(self.contrast)
            && pos(self.shoulder)
            && pos(self.hdr_max)
            && pos(self.mid_in)
            && pos(self.mid_out)
            && self.mid_in < self.hdr_max
            && self.mid_out < 1.0
            && self.contrast <= LOTTES_CONTRAST_MAX
            && self.b.is_finite()
            && self.c.is_finite()
            && self.c != 0.0
    }

    /// b and c solve f(mid_in) = mid_out and f(hdr_max) = 1 (Lottes 2016, slide "Generic
    /// Tonemapper").
    fn derive(a: f64, d: f64, hdr_max: f64, mid_in: f64, mid_out: f64) -> Self {
        let ad = a * d;
        let (mi_a, mi_ad) = (libm::pow(mid_in, a), libm::pow(mid_in, ad));
        let (hm_a, hm_ad) = (libm::pow(hdr_max, a), libm::pow(hdr_max, ad));
        let den = (hm_ad - mi_ad) * mid_out;
        let b = (-mi_a + hm_a * mid_out) / den;
        let c = (hm_ad * mi_a - hm_a * mi_ad * mid_out) / den;
        Self {
            contrast: a,
            shoulder: d,
            hdr_max,
            mid_in,
            mid_out,
            b,
            c,
        }
    }
}

/// `f` applied to each lane of `x` in f64 arithmetic, rounded back to the lane type once:
/// for the curves whose every lane calls `pow` (scalar per lane on every lane type anyway),
/// so that f32 lanes see f64 exponents (a decimal exponent such as 1.33 rounded to f32 would
/// move x^1.33 by 1.33 ln(x) times its rounding, many ulps for a tiny x).
#[inline]
fn per_lane_f64<T: Real>(x: T, f: impl Fn(f64) -> f64) -> T {
    T::from_fn(|i| <T::Scalar as Real>::splat(f(x.lane(i).into())))
}

/// `f` applied to each lane's colour in f64 arithmetic, rounded back to the lane type once.
#[inline]
fn per_lane_rgb<T: Real>(c: V3<T>, f: impl Fn(V3<f64>) -> V3<f64>) -> V3<T> {
    let mut out = [V3::new(0.0, 0.0, 0.0); 8];
    // No lane type has more than 8 lanes.
    for (i, o) in out.iter_mut().enumerate().take(T::LANES) {
        *o = f(V3::new(
            c.x.lane(i).into(),
            c.y.lane(i).into(),
            c.z.lane(i).into(),
        ));
    }
    let ch = |g: fn(&V3<f64>) -> f64| T::from_fn(|i| <T::Scalar as Real>::splat(g(&out[i])));
    V3::new(ch(|v| v.x), ch(|v| v.y), ch(|v| v.z))
}

/// Lottes' curve (Lottes 2016, "Advanced Techniques and Optimization of HDR Color Pipelines",
/// GDC) per channel: x^a / (x^(a d) b + c), clamped to [0, 1]. Passes through
/// (mid_in, mid_out) and (hdr_max, 1). Parameters outside [`LottesParams::new`]'s domain (a
/// public field changed by hand) give NaN. Evaluated in f64 on every lane type (a decimal
/// exponent such as 1.6 rounded to f32 would move x^1.6 by 1.6 ln(x) times its rounding), so
/// f32 results are rounded once.
///
/// Peers: Filament's `GenericToneMapper(contrast, midGrayIn, midGrayOut, hdrMax)` (defaults
/// 1.55, 0.18, 0.215, 10) is Lottes' curve with shoulder 1: per channel,
/// `lottes(x, &LottesParams::new(contrast, 1.0, hdrMax, midGrayIn, midGrayOut)?)` (Filament
/// applies it to Rec.2020 values and clamps only after converting back to sRGB).
/// three.js and bevy do not ship it.
#[inline]
#[must_use]
pub fn lottes<T: Real>(c: T, p: &LottesParams) -> T {
    if !p.is_valid() {
        return T::splat(f64::NAN);
    }
    let (a, ad, b, cc) = (p.contrast, p.contrast * p.shoulder, p.b, p.c);
    per_lane_f64(sanitize(c), |x| {
        // x^(a d) overflows for a large a d; b = 0 (a parameter, the same for every lane)
        // would then make inf * 0 = NaN of a term that is 0.
        let xad = if b == 0.0 { 0.0 } else { libm::pow(x, ad) };
        let xa = libm::pow(x, a);
        // The product, sum and quotient in double words, rounded once: only the two powers'
        // own errors remain. Where that is not finite (x^(a d) b overflowing for a large a d,
        // a denominator of 0 at a pole of parameters with b < 0, or one so small that the
        // quotient overflows), the plain form and its limit (+-inf, clamped).
        let plain = xa / (xad * b + cc);
        let v = Dw::exact(xa).div(Dw::product(xad, b).add_t(cc)).value();
        let v = if v.is_finite() { v } else { plain };
        Real::saturate(v)
    })
}

/// Parameters of Uchimura's curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UchimuraParams {
    /// Maximum display brightness P.
    pub max_brightness: f64,
    /// Contrast a.
    pub contrast: f64,
    /// Start of the linear section m.
    pub linear_start: f64,
    /// Length of the linear section l.
    pub linear_length: f64,
    /// Black tightness c.
    pub black: f64,
    /// Pedestal b.
    pub pedestal: f64,
}

impl UchimuraParams {
    /// The Gran Turismo Sport defaults: P = 1, a = 1, m = 0.22, l = 0.4, c = 1.33, b = 0.
    pub const GRAN_TURISMO: Self = Self {
        max_brightness: 1.0,
        contrast: 1.0,
        linear_start: 0.22,
        linear_length: 0.4,
        black: 1.33,
        pedestal: 0.0,
    };

    /// True when every field is finite, P, a, m and c are > 0, l >= 0, and the linear
    /// section ends below P (S1 = m + a l0 < P with l0 = (P - m) l / a, else the shoulder
    /// divides by P - S1 <= 0; the names are those of Uchimura 2017), with S0, S1 and P - S1
    /// finite (they overflow only for parameters near the largest f64, such as a linear
    /// section 1e300 long).
    fn is_valid(&self) -> bool {
        let all_finite = [
            self.max_brightness,
            self.contrast,
            self.linear_start,
            self.linear_length,
            self.black,
            self.pedestal,
        ]
        .iter()
        .all(|v| v.is_finite());
        let (pm, a, m, l) = (
            self.max_brightness,
            self.contrast,
            self.linear_start,
            self.linear_length,
        );
        let [s0, s1, _] = self.shoulder();
        all_finite
            && pm > 0.0
            && a > 0.0
            && m > 0.0
            && l >= 0.0
            && self.black > 0.0
            && s1 < pm
            && s0.is_finite()
            && s1.is_finite()
            && (pm - s1).is_finite()
    }

    /// The shoulder's constants [S0, S1, C] (Uchimura 2017's notation): l0 = (P - m) l / a,
    /// S0 = m + l0, S1 = m + a l0, and the exponent's factor C = -(a P / (P - S1)) / P, capped
    /// at -MAX (it overflows to -inf where P - S1 is tiny beside a; at x = S0 that would give
    /// -inf * 0 = NaN).
    fn shoulder(&self) -> [f64; 3] {
        let (pm, a, m, l) = (
            self.max_brightness,
            self.contrast,
            self.linear_start,
            self.linear_length,
        );
        let l0 = (pm - m) * l / a;
        let s1 = m + a * l0;
        let cp = -(a * pm / (pm - s1)) / pm;
        [m + l0, s1, Real::max(cp, -f64::MAX)]
    }
}

/// Where [`uchimura`] caps each of its three pieces (toe, linear section, shoulder) before
/// blending them: far outside the [0, 1] the result is clamped to, and small enough that the
/// sum of three such pieces stays finite.
const PIECE_CAP: f64 = 1e300;

/// Uchimura's "GT" curve (Uchimura 2017, "HDR Theory and Practice", CEDEC): a power toe
/// m (x/m)^c + b, a linear section m + a (x - m), and an exponential shoulder
/// P - (P - S1) exp(-a P / (P - S1) (x - S0) / P), blended by smoothstep(0, m, x) and a step at
/// S0 = m + l0, where l0 = (P - m) l / a is the linear section's length in x and
/// S1 = m + a l0 its end value (the talk's notation). Per channel, clamped to [0, 1].
/// f(0) = b. Parameters: every field finite, P, a, m, c > 0, l >= 0, m + a l0 < P, and S0,
/// S1 and P - S1 finite in f64 (they overflow only for parameters near the largest f64; the
/// Gran Turismo values qualify); others give NaN. Finite in-domain parameters give a result
/// in [0, 1] for every input: each piece is evaluated only where its weight can be nonzero
/// (the toe at min(x, m), the shoulder's exponent selected to 0 below S0, where exp would
/// overflow for a S0 / (P - S1) above ~709) and capped at +-1e300 before the blend. Evaluated in f64 on every lane type (its toe
/// raises x / m to a decimal power), so f32 results are rounded once.
///
/// Peers: the shader transcription in wide use (dmnsgn's `glsl-tone-map`) with the Gran
/// Turismo values is `uchimura(x, &UchimuraParams::GRAN_TURISMO)`. None of three.js, Filament
/// and bevy ships it (Filament's GT7 tone mapper is a different, 2025 curve).
#[inline]
#[must_use]
pub fn uchimura<T: Real>(c: T, p: &UchimuraParams) -> T {
    if !p.is_valid() {
        return T::splat(f64::NAN);
    }
    let (pm, a, m, cc, b) = (
        p.max_brightness,
        p.contrast,
        p.linear_start,
        p.black,
        p.pedestal,
    );
    let [s0, s1, cp] = p.shoulder();
    // A piece beyond +-1e300 lies far outside [0, 1] whatever its weight; capped there, the
    // three weighted pieces (weights in [-1, 1]) sum without overflow, so no inf - inf.
    let cap = |v: f64| Real::clamp(v, -PIECE_CAP, PIECE_CAP);
    per_lane_f64(sanitize(c), |x| {
        let t = Real::saturate(x / m);
        // smoothstep(0, m, x); w1 = 1 - w0 - w2 is formed as smooth - w2, which it equals,
        // without the cancellation of 1 - (1 - smooth) for small x.
        let smooth = t * t * (3.0 - 2.0 * t);
        let w0 = 1.0 - smooth;
        let past_s0 = x >= s0;
        let w2 = Real::select(past_s0, 1.0, 0.0);
        let w1 = smooth - w2;
        // The toe's weight w0 is exactly 0 from x = m on (t = 1 there), so the toe is
        // evaluated at min(x, m): (x / m)^c stays in [0, 1] instead of overflowing for a tiny
        // m and then giving 0 * inf = NaN. NaN in x propagates (`min` keeps self's NaN).
        let toe = m * libm::pow(Real::min(x, m) / m, cc) + b;
        // Likewise the shoulder's weight is 0 below S0, where its exponent is positive and
        // can overflow exp (a S0 / (P - S1) above ~709): selected to 0 there before exp.
        let shoulder = pm - (pm - s1) * libm::exp(Real::select(past_s0, cp * (x - s0), 0.0));
        let linear = a * (x - m) + m;
        Real::saturate(cap(toe) * w0 + cap(linear) * w1 + cap(shoulder) * w2)
    })
}

/// Khronos PBR Neutral (Khronos Group 2024, "PBR Neutral Tone Mapper" specification): an
/// offset f of the darkest channel (x - x^2 / 0.16 below 0.08, else 0.04), identity below
/// the compression start Ks = 0.76, then a peak compression p_n = 1 - (1 - Ks)^2 / (p + 1 -
/// 2 Ks) with desaturation g = 1 / (0.15 (p - p_n) + 1), a mix toward (p_n, p_n, p_n). Keeps base colours up to
/// 0.76 exact (minus the offset), which is its purpose for product rendering.
///
/// Evaluated without the specification's cancellations, each an identity: a channel minus
/// the offset is (c - x) + 6.25 x^2 below 0.08 (the darkest channel's own c - x is 0, its
/// result 6.25 x^2); p - p_n = (p - Ks)^2 / (p - Ks + d) with d = 1 - Ks; and the output
/// mix(c p_n / p, p_n, 1 - g) is (c + h p) p_n / (p (1 + h)) with h = 0.15 (p - p_n), so no
/// 1 - g is formed. Every step runs in double words of the lane type (about 48 bits for f32
/// lanes, 106 for f64) with the decimal constants carried to that precision, and each
/// channel is rounded once (plain arithmetic, about twelve roundings, reached 5.3 ulps).
///
/// Peers: the Khronos reference `pbrNeutral.glsl`, three.js `NeutralToneMapping` at exposure
/// e as `pbr_neutral(e * c)`, and bevy `Tonemapping::PbrNeutral` are this function. Older
/// Filament releases' `PBRNeutralToneMapper` mixes toward white instead of toward the
/// compressed peak, as the specification's first draft did: up to 5.5e-3 apart.
#[inline]
#[must_use]
pub fn pbr_neutral<T: Real>(c: V3<T>) -> V3<T> {
    let c = sanitize_rgb(c);
    let k = |hi: f64, tail: f64| Dw::<T>::constant(hi, tail);
    let x = c.x.min(c.y).min(c.z);
    let low = x.simd_lt(T::splat(0.08));
    let x2 = Dw::exact(T::splat(6.25)).mul(Dw::square(x));
    let offset_hi = k(0.04, -8.326_672_684_688_674e-19).neg();
    // Each channel minus the offset: exact c - x plus 6.25 x^2 below 0.08, c - 0.04 above.
    let off = |v: T| {
        let lo = Dw::sum(v, -x).add(x2);
        let hi = Dw::exact(v).add(offset_hi);
        Dw::select(low, lo, hi)
    };
    let (cx, cy, cz) = (off(c.x), off(c.y), off(c.z));
    let above = |a: Dw<T>, b: Dw<T>| a.hi.simd_gt(b.hi) | (a.hi.simd_eq(b.hi) & a.lo.simd_gt(b.lo));
    let max = |a: Dw<T>, b: Dw<T>| Dw::select(above(a, b), a, b);
    let peak = max(max(cx, cy), cz);
    // e = p - Ks with Ks = 0.8 - 0.04 = 0.76, t = e + d with d = 1 - Ks = 0.24.
    let e = peak.add(k(0.76, -8.881_784_197_001_253e-18).neg());
    let t = e.add(k(0.24, 8.881_784_197_001_253e-18));
    let new_peak = k(0.0576, 1.576_516_694_967_722_4e-18)
        .div(t)
        .neg()
        .add_t(T::ONE);
    let h = k(0.15, 5.551_115_123_125_783e-18).mul(e.sq().div(t));
    // Out of the compression (p < Ks) these are not used; t, p and 1 + h are > 0 within it.
    let factor = new_peak.div(peak.mul(h.add_t(T::ONE)));
    let hp = h.mul(peak);
    let scaled = |v: Dw<T>| v.add(hp).mul(factor).value();
    let compress = e.hi.simd_ge(T::ZERO);
    let channel = |v: Dw<T>| T::select(compress, scaled(v), v.value());
    let out = saturate_rgb(V3::new(channel(cx), channel(cy), channel(cz)));
    // The offset and the peak mix the channels, but `min`/`max` ignore a NaN argument: without
    // this a NaN in one channel would leave the other two plausible.
    let bad = any_nan3(c);
    V3::new(
        nan_where(bad, out.x),
        nan_where(bad, out.y),
        nan_where(bad, out.z),
    )
}
