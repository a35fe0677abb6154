//! AgX, in the three forms renderers ship: Wrensch's minimal Rec.709 form, three.js's
//! Rec.2020 form, and Filament's Rec.2020 form with its own curve fit and looks.
//!
//! All three share Troy Sobotka's design (Sobotka 2022, "AgX"): an inset matrix, a log2
//! encoding over [-12.47393, 4.026069] EV (mid grey 0.18 sits 10 stops above the bottom and
//! 6.5 below the top), a polynomial fit of the sigmoid contrast curve, an optional look, an
//! outset matrix and a 2.2 power back to display-linear values. They differ in the working
//! primaries, the matrices, the polynomial and the looks, by up to 0.3 on saturated colours,
//! so each function is named for the source it reproduces.
//!
//! Each is evaluated lane by lane in f64 (the log encoding, the polynomial and the outset
//! cancel too much for f32 arithmetic to meet the crate's accuracy promise), so the f32 and
//! f32x8 results are the f64 result rounded once; f64 and f64x4 lanes carry the same pipeline
//! in double words (every published decimal constant to twice f64's precision, a double-word
//! log and exp for the powers), rounded once. Against the correctly rounded value of the
//! published definition: within 0.7 ULP on f32 and 0.8 on f64 (1.0 for [`agx_threejs`]), max
//! 0.50 and 0.78 found over the AgX functions and looks (`docs/accuracy.md`; the 0.78, three.js's
//! variant at (0.00174, 0.0965, 0), came from a run's fresh points after the deep search had
//! found 0.52); where one rounding of a colour channel
//! moves the result by more than 8 ULPs, within that rounding's effect.

use super::{sanitize_rgb, saturate_rgb};
use crate::color::{
    AGX_INSET, AGX_INSET_REC2020, AGX_OUTSET, AGX_OUTSET_REC2020, Mat3, REC709_LUMA,
    REC709_TO_REC2020, REC2020_TO_REC709,
};
use crate::dw::Dw;
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

/// An AgX look: an ASC CDL slope and power per channel, then a saturation around Rec.709
/// luma, applied to the encoded (post-curve) values. As Wrensch 2023 and Filament define it,
/// with the luma taken before the CDL: v' = pow(v * slope, power), out = luma(v) + sat (v' -
/// luma(v)). Built through [`AgxLook::new`] or the constants, so it is always valid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AgxLook {
    slope: [f64; 3],
    power: [f64; 3],
    saturation: f64,
}

impl AgxLook {
    /// No grade: the base curve.
    pub const BASE: Self = Self {
        slope: [1.0; 3],
        power: [1.0; 3],
        saturation: 1.0,
    };
    /// "Golden" as Wrensch 2023 publishes it: slope (1, 0.9, 0.5), power 0.8, saturation 0.8.
    pub const GOLDEN: Self = Self {
        slope: [1.0, 0.9, 0.5],
        power: [0.8; 3],
        saturation: 0.8,
    };
    /// "Golden" as Filament ships it (`ToneMapper.cpp`, `AgxLook::GOLDEN`): Wrensch's slope and
    /// power with saturation 1.3.
    pub const GOLDEN_FILAMENT: Self = Self {
        slope: [1.0, 0.9, 0.5],
        power: [0.8; 3],
        saturation: 1.3,
    };
    /// "Punchy", the same in Wrensch 2023 and Filament: power 1.35, saturation 1.4.
    pub const PUNCHY: Self = Self {
        slope: [1.0; 3],
        power: [1.35; 3],
        saturation: 1.4,
    };

    /// A validated look: slopes finite and >= 0, powers finite and > 0, saturation finite and
    /// >= 0.
    pub fn new(slope: [f64; 3], power: [f64; 3], saturation: f64) -> Result<Self, ParamError> {
        for s in slope {
            require::<f64>(s >= 0.0 && s.is_finite(), "slope", "finite and >= 0")?;
        }
        for p in power {
            require::<f64>(p > 0.0 && p.is_finite(), "power", "finite and > 0")?;
        }
        require::<f64>(
            saturation >= 0.0 && saturation.is_finite(),
            "saturation",
            "finite and >= 0",
        )?;
        Ok(Self {
            slope,
            power,
            saturation,
        })
    }

    /// The per-channel CDL slope.
    #[must_use]
    pub fn slope(&self) -> [f64; 3] {
        self.slope
    }

    /// The per-channel CDL power.
    #[must_use]
    pub fn power(&self) -> [f64; 3] {
        self.power
    }

    /// The saturation around Rec.709 luma.
    #[must_use]
    pub fn saturation(&self) -> f64 {
        self.saturation
    }

    /// v' = max(v slope, 0)^power, luma(v) + sat (v' - luma(v)). The sources raise v slope to
    /// the power without the max; v is negative only at the bottom of Wrensch's curve (-0.00232),
    /// where their `pow` is undefined (NaN in C++, unspecified in GLSL), and 0 is its limit.
    fn apply(&self, v: [f64; 3]) -> [f64; 3] {
        if *self == Self::BASE {
            return v;
        }
        let luma = dot(&REC709_LUMA, v);
        let mut out = [0.0; 3];
        for k in 0..3 {
            let graded = libm::pow((v[k] * self.slope[k]).max(0.0), self.power[k]);
            out[k] = self.saturation.mul_add(graded - luma, luma);
        }
        out
    }
}

/// Bottom and top of the log2 encoding: log2(0.18 * 2^-10) and log2(0.18 * 2^6.5), to the
/// 7 significant digits every source publishes.
const MIN_EV: f64 = -12.47393;
const MAX_EV: f64 = 4.026069;

/// Wrensch's 6th-order fit of the default contrast sigmoid, 15.5 x^6 - 40.14 x^5 + 31.96 x^4 -
/// 6.868 x^3 + 0.4298 x^2 + 0.1191 x - 0.00232, as the exact coefficients of its expansion in
/// t = x - 1/2 (constant term first): Horner in x adds terms of +-40 that cancel to about 1
/// near the top; in t no term exceeds 1.
const CURVE_WRENSCH: [f64; 7] = [0.291_492_5, 1.7404, 2.424_05, -4.548, -10.265, 6.36, 15.5];

/// Filament's 7th-order fit, -17.86 x^7 + 78.01 x^6 - 126.7 x^5 + 92.06 x^4 - 28.72 x^3 +
/// 4.361 x^2 - 0.1718 x + 0.002857, expanded exactly in t = x - 1/2 (constant term first).
const CURVE_FILAMENT: [f64; 8] = [
    0.290_957,
    1.758_887_5,
    2.409_75,
    -5.393_75,
    -10.29,
    13.565,
    15.5,
    -17.86,
];

/// three.js's `LINEAR_REC2020_TO_LINEAR_SRGB`: ITU-R BT.2407's matrix to its 4 published
/// decimals, which three.js uses as is.
const THREEJS_REC2020_TO_SRGB: Mat3 = [
    [1.6605, -0.5876, -0.0728],
    [-0.1246, 1.1329, -0.0083],
    [-0.0182, -0.1006, 1.1187],
];

/// three.js's `LINEAR_SRGB_TO_LINEAR_REC2020` (r162 and later): ITU-R BT.2087's matrix to its 4
/// published decimals, as three.js writes it. It is not the inverse of
/// [`THREEJS_REC2020_TO_SRGB`] (white maps to 1.0000, 0.9999, 1.0000).
const THREEJS_SRGB_TO_REC2020: Mat3 = [
    [0.6274, 0.3293, 0.0433],
    [0.0691, 0.9195, 0.0113],
    [0.0164, 0.0880, 0.8956],
];

/// three.js's explicit `AgXOutsetMatrix` (r162 and later), the inverse of Blender's outset
/// inverse written to 17 digits (the last digit differs from [`AGX_OUTSET_REC2020`]'s).
const THREEJS_AGX_OUTSET: Mat3 = [
    [
        1.127_100_581_814_436_8,
        -0.110_606_643_096_603_23,
        -0.016_493_938_717_834_573,
    ],
    [
        -0.141_329_763_498_438_3,
        1.157_823_702_216_272,
        -0.016_493_938_717_834_257,
    ],
    [
        -0.141_329_763_498_438_26,
        -0.110_606_643_096_602_94,
        1.251_936_406_595_040_5,
    ],
];

#[inline]
fn dot(r: &[f64; 3], v: [f64; 3]) -> f64 {
    r[0].mul_add(v[0], r[1].mul_add(v[1], r[2] * v[2]))
}

#[inline]
fn mat(m: &Mat3, v: [f64; 3]) -> [f64; 3] {
    [dot(&m[0], v), dot(&m[1], v), dot(&m[2], v)]
}

/// The log2 encoding: (clamp(log2 v, MIN_EV, MAX_EV) - MIN_EV) / (MAX_EV - MIN_EV), with
/// v <= 0 at the bottom (the sources floor v at 1e-10, 33 EV below MIN_EV).
#[inline]
fn encode(v: f64) -> f64 {
    let ev = libm::log2(v.max(f64::MIN_POSITIVE));
    (ev.clamp(MIN_EV, MAX_EV) - MIN_EV) / (MAX_EV - MIN_EV)
}

/// Horner in t = x - 1/2.
#[inline]
fn curve(coeffs: &[f64], x: f64) -> f64 {
    let t = x - 0.5;
    coeffs.iter().rev().fold(0.0, |acc, &c| acc.mul_add(t, c))
}

/// Inset, encoding, curve, look, outset, max(0) and the 2.2 power: the AgX pipeline every
/// variant shares, on one RGB triple in f64. Unclamped above; NaN in any channel gives NaN in
/// all three.
fn pipeline(c: [f64; 3], inset: &Mat3, outset: &Mat3, coeffs: &[f64], look: &AgxLook) -> [f64; 3] {
    let v = mat(inset, c).map(|x| curve(coeffs, encode(x)));
    mat(outset, look.apply(v)).map(|x| libm::pow(x.max(0.0), 2.2))
}

/// `f` on each lane of `c`, widened to f64, and the result rounded back to the lane type; a
/// lane with a NaN channel gives NaN in all three (f64's `max` would drop it).
#[inline]
fn per_lane<T: Real>(c: V3<T>, f: impl Fn([f64; 3]) -> [f64; 3]) -> V3<T> {
    // No lane type has more than 8 lanes.
    let mut out = [[0.0; 3]; 8];
    for (i, o) in out.iter_mut().enumerate().take(T::LANES) {
        let v: [f64; 3] = [c.x.lane(i).into(), c.y.lane(i).into(), c.z.lane(i).into()];
        *o = if v.iter().any(|x| x.is_nan()) {
            [f64::NAN; 3]
        } else {
            f(v)
        };
    }
    let ch = |k: usize| T::from_fn(|i| <T::Scalar as Real>::splat(out[i][k]));
    V3::new(ch(0), ch(1), ch(2))
}

/// Minimal AgX exactly as Wrensch 2023 ("Minimal AgX Implementation") publishes it, on
/// linear Rec.709 (sRGB primaries) in and out: [`AGX_INSET`], the log2 encoding over
/// [-12.47393, 4.026069] EV, the 6th-order contrast polynomial 15.5 x^6 - 40.14 x^5 +
/// 31.96 x^4 - 6.868 x^3 + 0.4298 x^2 + 0.1191 x - 0.00232, the `look` ([`AgxLook::GOLDEN`] and
/// [`AgxLook::PUNCHY`] are Wrensch's), [`AGX_OUTSET`], then max(0) and the 2.2 power that
/// returns display-linear values. Output clamped to [0, 1]; the source does not clamp (a
/// saturated primary's outset reaches 1.19) and its `pow` of the curve's negative toe is
/// undefined: 0 here. f(0) = 0; greys reach 0.99698 at [`super::MAX_INPUT`] and +inf.
///
/// Input: linear RGB, clamped by [`super::sanitize`]. A NaN in any channel gives NaN in all
/// three. A look cannot be invalid (its fields are private).
///
/// Peers: Wrensch's Shadertoy (cd3XWr) and three.js's unused `agx()` / `agxEotf()` are this
/// function: within 2.2e-5 of the shader evaluated in f32, all of it the shader's own f32
/// rounding of the monomial polynomial (terms up to 40 cancel), and within 6.6e-7 with that
/// polynomial summed in f64 (`tests/tonemap/against_peers.rs`). Where the shader raises the curve's
/// negative toe to a power (channels below about 2e-4 under a look), it returns NaN.
/// bevy's `Tonemapping::AgX` samples a LUT and is not this curve. Evaluated in f64 lane by lane
/// (in double words on f64 lanes; see the module docs).
#[inline]
#[must_use]
pub fn agx_minimal<T: Real>(c: V3<T>, look: &AgxLook) -> V3<T> {
    Variant::Minimal.apply(c, look)
}

/// three.js's `AgXToneMapping` (three.js r162 and later, `tonemapping_pars_fragment.glsl.js`)
/// at `toneMappingExposure` 1, on linear sRGB in and out: BT.2087's 4-decimal sRGB-to-Rec.2020
/// matrix (0.6274, 0.3293, 0.0433; 0.0691, 0.9195, 0.0113; 0.0164, 0.0880, 0.8956),
/// [`crate::color::AGX_INSET_REC2020`], the log2 encoding over [-12.47393, 4.026069] EV,
/// Wrensch's 6th-order polynomial (see [`agx_minimal`]), no look, three.js's explicit outset
/// (Blender's outset inverse inverted, to 17 digits), max(0), the 2.2 power, then BT.2407's
/// 4-decimal Rec.2020-to-sRGB matrix (1.6605, -0.5876, -0.0728; -0.1246, 1.1329, -0.0083;
/// -0.0182, -0.1006, 1.1187) and the clamp to [0, 1] that three.js applies.
///
/// Mapping: three.js with exposure e renders `agx_threejs(e * c)`, to 2.2e-5: three.js's own
/// f32 rounding of the polynomial, as for [`agx_minimal`] (7.2e-7 with it summed in f64). three.js r160 and r161
/// took the sRGB-to-Rec.2020 matrix as the inverse of the Rec.2020-to-sRGB one; that version
/// differs from this one by up to 1.5e-4.
///
/// Input: linear RGB, clamped by [`super::sanitize`]. A NaN in any channel gives NaN in all
/// three. Evaluated in f64 lane by lane (in double words on f64 lanes).
#[inline]
#[must_use]
pub fn agx_threejs<T: Real>(c: V3<T>) -> V3<T> {
    Variant::Threejs.apply(c, &AgxLook::BASE)
}

/// Filament's `AgxToneMapper` (`filament/src/ToneMapper.cpp`) with its looks, on Filament's
/// working space, linear Rec.2020, in and out: max(0), [`crate::color::AGX_INSET_REC2020`],
/// the log2 encoding over [-12.47393, 4.026069] EV, Filament's 7th-order contrast polynomial
/// -17.86 x^7 + 78.01 x^6 - 126.7 x^5 + 92.06 x^4 - 28.72 x^3 + 4.361 x^2 - 0.1718 x + 0.002857,
/// the `look` ([`AgxLook::GOLDEN_FILAMENT`] and [`AgxLook::PUNCHY`] are Filament's),
/// [`crate::color::AGX_OUTSET_REC2020`], max(0) and the 2.2 power. Output clamped to [0, 1].
///
/// Mapping: Filament's `AgxToneMapper(look)` applied to a Rec.2020 colour c gives
/// `agx_filament(c, look)`; from linear sRGB, Filament's colour grading converts to Rec.2020
/// first and back after, which [`super::Operator::AgxFilament`] does with
/// [`crate::color::REC709_TO_REC2020`] and [`crate::color::REC2020_TO_REC709`]. Agreement
/// with Filament's f32 code: 7.5e-5, all of it Filament's f32 sum of its 7th-order
/// polynomial (terms up to 127 cancel; 6.6e-7 with the sum in f64); through the colour
/// grading, 2.2e-4 (Filament's 7-digit XYZ matrices map sRGB white to (1.000089, 0.999971,
/// 0.999934) in Rec.2020).
///
/// Input: linear Rec.2020, clamped by [`super::sanitize`]. A NaN in any channel gives NaN in
/// all three. Evaluated in f64 lane by lane (in double words on f64 lanes).
#[inline]
#[must_use]
pub fn agx_filament<T: Real>(c: V3<T>, look: &AgxLook) -> V3<T> {
    Variant::Filament.apply(c, look)
}

/// [`agx_filament`] seen from linear sRGB: [`crate::color::REC709_TO_REC2020`], Filament's
/// AgX, [`crate::color::REC2020_TO_REC709`], clamped to [0, 1].
#[inline]
pub(crate) fn agx_filament_srgb<T: Real>(c: V3<T>, look: &AgxLook) -> V3<T> {
    Variant::FilamentSrgb.apply(c, look)
}

// ---------------------------------------------------------------------------------------
// The f64 lanes: the same pipeline carried in double words, so that f64 results meet the
// crate's accuracy promise. Every decimal constant of the sources is held as its nearest f64
// plus the remainder (computed exactly from the published decimals), every matrix product,
// the log2 encoding and the polynomial are carried in double words, and the two powers are
// corrected to first order for their argument's low part.
// ---------------------------------------------------------------------------------------

type Dd = Dw<f64>;
type DwMat = [[(f64, f64); 3]; 3];

/// [`AGX_INSET`] as double words.
const DD_INSET: DwMat = [
    [
        (0.842479062253094, 9.0248831329518e-18),
        (0.0784335999999992, -1.1799676561167872e-18),
        (0.0792237451477643, 1.0094552265400126e-18),
    ],
    [
        (0.0423282422610123, 2.857080819285329e-18),
        (0.878468636469772, -2.4000235433049967e-17),
        (0.0791661274605434, 2.113183691926679e-18),
    ],
    [
        (0.0423756549057051, 9.3689903997074e-20),
        (0.0784336, -6.091660509355279e-18),
        (0.879142973793104, -2.1140720760740806e-17),
    ],
];

/// [`AGX_OUTSET`] as double words.
const DD_OUTSET: DwMat = [
    [
        (1.19687900512017, -9.191367833409459e-17),
        (-0.0980208811401368, -4.79347000400594e-18),
        (-0.0990297440797205, -3.025760448053916e-18),
    ],
    [
        (-0.0528968517574562, -3.3367903756243323e-18),
        (1.15190312990417, 1.3269733171910048e-17),
        (-0.0989611768448433, 4.3454670610117316e-18),
    ],
    [
        (-0.0529716355144438, 3.0833065056413033e-18),
        (-0.0980434501171241, 6.291122132006421e-18),
        (1.15107367264116, 1.0486415718332865e-16),
    ],
];

/// [`AGX_INSET_REC2020`] as double words.
const DD_INSET_REC2020: DwMat = [
    [
        (0.856627153315983, -4.7576764874975196e-17),
        (0.0951212405381588, -4.977975080419128e-18),
        (0.0482516061458583, -1.0092593056469923e-19),
    ],
    [
        (0.137318972929847, 1.1448994107013277e-17),
        (0.761241990602591, -1.2127220437832875e-17),
        (0.101439036467562, 6.782263308195979e-19),
    ],
    [
        (0.11189821299995, 5.2940495265829664e-18),
        (0.0767994186031903, 2.439121281258849e-18),
        (0.811302368396859, 1.3911795198509936e-17),
    ],
];

/// [`AGX_OUTSET_REC2020`] as double words (the exact inverse of Blender's outset-inverse).
const DD_OUTSET_REC2020: DwMat = [
    [
        (1.1271005818144366, 2.3781424876850925e-17),
        (-0.11060664309660322, 4.412141571610032e-18),
        (-0.01649393871783457, 1.0598287354067852e-18),
    ],
    [
        (-0.14132976349843826, -5.6495384104714944e-18),
        (1.1578237022162718, -8.15457175158715e-17),
        (-0.016493938717834253, 8.468405747060329e-19),
    ],
    [
        (-0.14132976349843826, 1.2277157661259599e-17),
        (-0.11060664309660292, 6.7023412902297965e-18),
        (1.2519364065950402, 4.1915360369921816e-17),
    ],
];

/// [`REC709_TO_REC2020`] as double words.
const DD_REC709_TO_REC2020: DwMat = [
    [
        (0.627403895934699, 4.911338361689377e-17),
        (0.3292830383778837, -2.7537977215024243e-18),
        (0.043313065687417225, 2.212671431959248e-18),
    ],
    [
        (0.06909728935823208, 2.2582015884232995e-18),
        (0.9195403950754587, 4.0144988998589853e-17),
        (0.011362315566309178, -7.698271635697803e-19),
    ],
    [
        (0.01639143887515028, -4.957025887249013e-19),
        (0.08801330787722575, 5.999563454512251e-18),
        (0.895595253247624, -4.713722428923072e-17),
    ],
];

/// [`REC2020_TO_REC709`] as double words.
const DD_REC2020_TO_REC709: DwMat = [
    [
        (1.6604910021084345, -7.249683297775641e-17),
        (-0.5876411387885495, -1.611255643433138e-17),
        (-0.07284986331988488, 5.342662565201053e-18),
    ],
    [
        (-0.12455047452159074, -3.173879556354377e-18),
        (1.1328998971259603, -6.954243827404853e-17),
        (-0.008349422604369477, -1.420681606229842e-19),
    ],
    [
        (-0.018150763354905303, -2.1865139808741887e-19),
        (-0.10057889800800739, 6.6489335114747876e-18),
        (1.1187296613629127, -5.847198639269158e-17),
    ],
];

/// [`THREEJS_REC2020_TO_SRGB`] as double words.
const DD_THREEJS_REC2020_TO_SRGB: DwMat = [
    [
        (1.6605, -8.704148513061228e-17),
        (-0.5876, 1.1191048088221578e-17),
        (-0.0728, 3.597122599785507e-18),
    ],
    [
        (-0.1246, 2.4202861936828413e-18),
        (1.1329, -1.8118839761882556e-17),
        (-0.0083, 8.604228440844963e-20),
    ],
    [
        (-0.0182, 8.992806499463767e-19),
        (-0.1006, -5.018208071305707e-18),
        (1.1187, -2.7711166694643906e-17),
    ],
];

/// [`THREEJS_SRGB_TO_REC2020`] as double words.
const DD_THREEJS_SRGB_TO_REC2020: DwMat = [
    [
        (0.6274, 4.2277292777725964e-17),
        (0.3293, 1.8385293287792592e-17),
        (0.0433, 1.787459069646502e-18),
    ],
    [
        (0.0691, 5.240252676230739e-18),
        (0.9195, 1.5987211554602253e-17),
        (0.0113, 7.188694084447888e-19),
    ],
    [
        (0.0164, -1.3822276656583198e-18),
        (0.088, 5.10702591327572e-18),
        (0.8956, 4.831690603168681e-17),
    ],
];

/// [`THREEJS_AGX_OUTSET`] as double words.
const DD_THREEJS_AGX_OUTSET: DwMat = [
    [
        (1.1271005818144368, -4.155453865969321e-17),
        (-0.11060664309660323, -9.674801411165391e-20),
        (-0.016493938717834573, -3.119076350440082e-19),
    ],
    [
        (-0.1413297634984383, -1.2216812338738236e-17),
        (1.157823702216272, -6.59679280288401e-17),
        (-0.016493938717834257, -3.1580262822899386e-20),
    ],
    [
        (-0.14132976349843826, 2.761204563284991e-20),
        (-0.11060664309660294, -1.5302919782152457e-18),
        (1.2519364065950405, 3.70254337467486e-17),
    ],
];

/// [`CURVE_WRENSCH`] as double words.
const DD_CURVE_WRENSCH: [(f64, f64); 7] = [
    (0.2914925, 1.2274625760255731e-17),
    (1.7404, 5.2935433814127464e-17),
    (2.42405, 1.8403056856186594e-16),
    (-4.548, 4.263256414560601e-17),
    (-10.265, 5.684341886080802e-16),
    (6.36, -3.1974423109204507e-16),
    (15.5, 0.0),
];

/// [`CURVE_FILAMENT`] as double words.
const DD_CURVE_FILAMENT: [(f64, f64); 8] = [
    (0.290957, -2.1167068098293384e-17),
    (1.7588875, 6.288303211476887e-17),
    (2.40975, 1.6342482922482304e-16),
    (-5.39375, -1.7763568394002506e-16),
    (-10.29, -8.526512829121202e-16),
    (13.565, 4.973799150320702e-16),
    (15.5, 0.0),
    (-17.86, -5.684341886080802e-16),
];

/// Rec.709 luma weights (0.2126, 0.7152, 0.0722) as double words.
const DD_LUMA: [(f64, f64); 3] = [
    (0.2126, -1.1191048088221578e-17),
    (0.7152, 5.311306949806749e-17),
    (0.0722, -2.886579864025407e-19),
];

/// -MIN_EV = 12.47393 as a double word.
const DD_NEG_MIN_EV: (f64, f64) = (12.47393, 7.037215254968032e-16);

/// MAX_EV - MIN_EV = 16.499999 as a double word.
const DD_RANGE: (f64, f64) = (16.499999, 1.0279563866788521e-15);

#[inline]
fn dd(c: (f64, f64)) -> Dd {
    Dd::constant(c.0, c.1)
}

#[inline]
fn mat_dd(m: &DwMat, v: [Dd; 3]) -> [Dd; 3] {
    let row = |r: &[(f64, f64); 3]| {
        dd(r[0])
            .mul(v[0])
            .add(dd(r[1]).mul(v[1]))
            .add(dd(r[2]).mul(v[2]))
    };
    [row(&m[0]), row(&m[1]), row(&m[2])]
}

/// ln 2 and log2(e) as double words.
const DD_LN_2: (f64, f64) = (core::f64::consts::LN_2, 2.319_046_813_846_299_6e-17);
const DD_LOG2_E: (f64, f64) = (core::f64::consts::LOG2_E, 2.035_527_374_093_103_3e-17);
/// The sources' 2.2 display power as a double word.
const DD_GAMMA: (f64, f64) = (2.2, -1.776_356_839_400_250_6e-16);

/// ln a for a double word a > 0, to about 2^-100 relative: a = m 2^e with m in
/// [1/sqrt 2, sqrt 2), ln m = 2 atanh s = 2 s (1 + s^2/3 + s^4/5 + ...) with
/// s = (m - 1) / (m + 1) in double words (|s| <= 0.172) and the bracket's tail, at most 0.01,
/// in f64; then e ln 2 in double words.
fn ln_dd(a: Dd) -> Dd {
    let (m, e) = libm::frexp(a.hi);
    let (m, e) = if m < core::f64::consts::FRAC_1_SQRT_2 {
        (2.0 * m, e - 1)
    } else {
        (m, e)
    };
    let m = Dd::norm(m, libm::ldexp(a.lo, -e));
    let s = m.add_t(-1.0).div(m.add_t(1.0));
    let s2 = s.hi * s.hi;
    // s^2/3 + s^4/5 + ... + s^24/25: the next term is below 2^-64 of the bracket.
    let tail = (1..=12).rev().fold(0.0, |acc: f64, k: i32| {
        (acc + 1.0 / f64::from(2 * k + 1)) * s2
    });
    let two_s = s.scale2();
    let ln_m = two_s.add(two_s.mul(Dd::exact(tail)));
    let e = f64::from(e);
    Dd::product(e, DD_LN_2.0).add_t(e * DD_LN_2.1).add(ln_m)
}

/// exp y for a double word y, to about 2^-60 relative (0 below -745, no overflow check: every
/// caller's y is below 3): y = k ln 2 + r with |r| <= ln 2 / 2, e^(r / 256) - 1 by its
/// Taylor series (r / 256 + (r / 256)^2 h, h to 8 terms in f64), squared back eight times as
/// E -> 2 E + E^2 in double words, then scaled by 2^k.
fn exp_dd(y: Dd) -> Dd {
    if y.hi < -745.0 {
        return Dd::exact(0.0);
    }
    let k = libm::round(y.hi * core::f64::consts::LOG2_E);
    let r = y.add(Dd::product(-k, DD_LN_2.0)).add_t(-k * DD_LN_2.1);
    let r = r.scale(1.0 / 256.0);
    let x = r.hi;
    // h = 1/2! + x/3! + ... + x^6/8!
    let h = [
        1.0 / 40320.0,
        1.0 / 5040.0,
        1.0 / 720.0,
        1.0 / 120.0,
        1.0 / 24.0,
        1.0 / 6.0,
        0.5,
    ]
    .iter()
    .fold(0.0, |acc: f64, &c| acc.mul_add(x, c));
    let mut e = r.add(Dd::product(x, x).mul(Dd::exact(h)));
    for _ in 0..8 {
        e = e.scale2().add(e.sq());
    }
    let one_plus = e.add_t(1.0);
    // k is an integer below 1100 in magnitude.
    let k = k as i32;
    Dd {
        hi: libm::ldexp(one_plus.hi, k),
        lo: libm::ldexp(one_plus.lo, k),
    }
}

/// The log2 encoding in double words: (log2 v - MIN_EV) / RANGE with log2 v = ln v log2(e)
/// from [`ln_dd`] and both constants as double words, clamped to [0, 1].
fn encode_dd(v: Dd) -> Dd {
    if v.hi <= 0.0 {
        return Dd::exact(0.0);
    }
    let log2_v = ln_dd(v).mul(dd(DD_LOG2_E));
    let shifted = log2_v.add(dd(DD_NEG_MIN_EV));
    let range = dd(DD_RANGE);
    if shifted.hi <= 0.0 {
        Dd::exact(0.0)
    } else if shifted.hi > range.hi || (shifted.hi == range.hi && shifted.lo >= range.lo) {
        Dd::exact(1.0)
    } else {
        shifted.div(range)
    }
}

/// Horner in t = x - 1/2 in double words.
fn curve_dd(coeffs: &[(f64, f64)], x: Dd) -> Dd {
    let t = x.add_t(-0.5);
    let (last, rest) = coeffs.split_last().unwrap_or((&(0.0, 0.0), &[]));
    rest.iter()
        .rev()
        .fold(dd(*last), |acc, &c| acc.mul(t).add(dd(c)))
}

/// a^p = exp(p ln a) for a double word a > 0 (0 for a <= 0) and a double-word p.
#[inline]
fn pow_dd(a: Dd, p: Dd) -> Dd {
    if a.hi <= 0.0 {
        return Dd::exact(0.0);
    }
    exp_dd(ln_dd(a).mul(p))
}

/// [`AgxLook::apply`] in double words.
fn look_dd(look: &AgxLook, v: [Dd; 3]) -> [Dd; 3] {
    if *look == AgxLook::BASE {
        return v;
    }
    let luma = dd(DD_LUMA[0])
        .mul(v[0])
        .add(dd(DD_LUMA[1]).mul(v[1]))
        .add(dd(DD_LUMA[2]).mul(v[2]));
    let sat = Dd::exact(look.saturation);
    core::array::from_fn(|k| {
        let graded = pow_dd(v[k].mul(Dd::exact(look.slope[k])), Dd::exact(look.power[k]));
        luma.add(sat.mul(graded.add(luma.neg())))
    })
}

/// [`pipeline`] in double words.
fn pipeline_dd(
    c: [Dd; 3],
    inset: &DwMat,
    outset: &DwMat,
    coeffs: &[(f64, f64)],
    look: &AgxLook,
) -> [Dd; 3] {
    let v = mat_dd(inset, c).map(|x| curve_dd(coeffs, encode_dd(x)));
    mat_dd(outset, look_dd(look, v)).map(|x| pow_dd(x, dd(DD_GAMMA)))
}

/// The three variants' f64 kernels, on one non-negative RGB triple without NaN.
#[derive(Clone, Copy)]
enum Variant {
    Minimal,
    Threejs,
    Filament,
    FilamentSrgb,
}

impl Variant {
    /// The plain f64 pipeline (for the f32 lane types, whose result it rounds once).
    fn eval_f64(self, c: [f64; 3], look: &AgxLook) -> [f64; 3] {
        match self {
            Self::Minimal => pipeline(c, &AGX_INSET, &AGX_OUTSET, &CURVE_WRENSCH, look),
            Self::Threejs => {
                let out = pipeline(
                    mat(&THREEJS_SRGB_TO_REC2020, c),
                    &AGX_INSET_REC2020,
                    &THREEJS_AGX_OUTSET,
                    &CURVE_WRENSCH,
                    look,
                );
                mat(&THREEJS_REC2020_TO_SRGB, out)
            }
            Self::Filament => pipeline(
                c,
                &AGX_INSET_REC2020,
                &AGX_OUTSET_REC2020,
                &CURVE_FILAMENT,
                look,
            ),
            Self::FilamentSrgb => {
                let out = pipeline(
                    mat(&REC709_TO_REC2020, c),
                    &AGX_INSET_REC2020,
                    &AGX_OUTSET_REC2020,
                    &CURVE_FILAMENT,
                    look,
                );
                mat(&REC2020_TO_REC709, out)
            }
        }
    }

    /// The double-word pipeline, rounded to f64 (for the f64 lane types).
    fn eval_dd(self, c: [f64; 3], look: &AgxLook) -> [f64; 3] {
        let c = c.map(Dd::exact);
        let out = match self {
            Self::Minimal => pipeline_dd(c, &DD_INSET, &DD_OUTSET, &DD_CURVE_WRENSCH, look),
            Self::Threejs => {
                let out = pipeline_dd(
                    mat_dd(&DD_THREEJS_SRGB_TO_REC2020, c),
                    &DD_INSET_REC2020,
                    &DD_THREEJS_AGX_OUTSET,
                    &DD_CURVE_WRENSCH,
                    look,
                );
                mat_dd(&DD_THREEJS_REC2020_TO_SRGB, out)
            }
            Self::Filament => pipeline_dd(
                c,
                &DD_INSET_REC2020,
                &DD_OUTSET_REC2020,
                &DD_CURVE_FILAMENT,
                look,
            ),
            Self::FilamentSrgb => {
                let out = pipeline_dd(
                    mat_dd(&DD_REC709_TO_REC2020, c),
                    &DD_INSET_REC2020,
                    &DD_OUTSET_REC2020,
                    &DD_CURVE_FILAMENT,
                    look,
                );
                mat_dd(&DD_REC2020_TO_REC709, out)
            }
        };
        out.map(Dd::value)
    }

    /// The variant on `c` (sanitized), lane by lane, clamped to [0, 1]: f32 lanes through
    /// the f64 pipeline, f64 lanes through the double-word one.
    fn apply<T: Real>(self, c: V3<T>, look: &AgxLook) -> V3<T> {
        let wide = core::mem::size_of::<T::Scalar>() == 8;
        let c = sanitize_rgb(c);
        saturate_rgb(per_lane(c, |v| {
            if wide {
                self.eval_dd(v, look)
            } else {
                self.eval_f64(v, look)
            }
        }))
    }
}
