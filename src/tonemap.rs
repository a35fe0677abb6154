//! Tonemapping operators: scene-referred linear RGB in, display-referred linear RGB in [0, 1]
//! out (apply [`crate::color::srgb_oetf`] to encode for an 8-bit sRGB target).
//!
//! Three entry points for every operator: generic functions on one channel (`T: Real`) or on
//! an RGB [`V3`], and the [`Operator`] enum with `apply` (generic), `apply_vec3` and
//! `apply_vec3a` (glam).
//!
//! # Bad input
//! Every operator first maps its input through [`sanitize`]: negative -> 0 and values above
//! [`MAX_INPUT`] (including +inf) -> `MAX_INPUT`, documented input clamps; outputs are clamped
//! to [0, 1]. A NaN is not a value to clamp: a NaN channel gives NaN in every output channel
//! it reaches (its own for per-channel operators, all three for those that mix channels
//! through luminance or a matrix), identically on scalar and lane paths, so a reference
//! renderer sees the bug instead of a black pixel. Invalid parameters reaching a free
//! function (exposure or white point <= 0 or not finite, a hand-built parameter struct
//! outside its constructor's domain) give NaN. Each operator's `f(+inf)` is its value at
//! `MAX_INPUT`: 1 for all of them except AgX (0.9970, its curve's top; the golden look tints
//! it).
//!
//! # Channel coupling
//! Per-channel operators are monotonic in each channel. Operators that use luminance or the
//! channel extremes (Reinhard on luminance, Reinhard-Jodie, ACES Hill, PBR Neutral, AgX) are
//! monotonic along every grey ramp and in each channel's own input, but raising one channel
//! can lower another's output (that is what desaturation and luminance preservation do).
//! Three designs bend even that, by amounts `tests/tonemap_properties.rs` measures and bounds:
//! PBR Neutral's darkest-channel offset lets that channel's own output fall by up to 2e-7
//! while another channel is compressed; AgX's outset matrix (negative off-diagonals) lowers a
//! channel that has reached the top of the log encoding by up to 2e-5 as its input grows; and
//! the punchy and golden looks (saturation > 1) dip a grey ramp by up to 1e-5 where the
//! channels reach that top at slightly different inputs, and a channel's own output by up to
//! 6e-5.

use crate::color::{self, ACES_HILL_INPUT, ACES_HILL_OUTPUT, AGX_INSET, AGX_OUTSET, luminance};
use crate::domain::{any_nan3, nan_unless, nan_where};
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;
use glam::{Vec3, Vec3A};

/// Largest input an operator evaluates; larger values (and +inf) are clamped to it. 1e9 is
/// about 30 stops above mid grey, beyond any scene, and keeps every operator's intermediate
/// terms (ACES' x^2, Lottes' x^1.6) far from f32 overflow.
pub const MAX_INPUT: f64 = 1e9;

/// The operators' input clamp: negative (and -inf) -> 0, above [`MAX_INPUT`] (and +inf) ->
/// `MAX_INPUT`; NaN stays NaN.
#[inline]
#[must_use]
pub fn sanitize<T: Real>(x: T) -> T {
    color::non_negative(x).min(T::splat(MAX_INPUT))
}

#[inline]
fn sanitize_rgb<T: Real>(c: V3<T>) -> V3<T> {
    V3::new(sanitize(c.x), sanitize(c.y), sanitize(c.z))
}

#[inline]
fn saturate_rgb<T: Real>(c: V3<T>) -> V3<T> {
    // Clamped to [0, 1]; a NaN (from a NaN input) stays NaN.
    V3::new(c.x.saturate(), c.y.saturate(), c.z.saturate())
}

#[inline]
fn per_channel<T: Real>(c: V3<T>, f: impl Fn(T) -> T) -> V3<T> {
    V3::new(f(c.x), f(c.y), f(c.z))
}

/// Camera exposure: the factor scene luminance is multiplied by before tonemapping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Exposure(pub f64);

impl Exposure {
    /// Exposure of a photometric EV100: 1 / (1.2 * 2^EV100), the saturation-based sensor model
    /// with q = 0.65 and K = 12.5 (78 / (100 q) = 1.2) of Lagarde and de Rousiers 2014, "Moving
    /// Frostbite to Physically Based Rendering", section 4.2. EV100 must be finite.
    pub fn from_ev100(ev100: f64) -> Result<Self, ParamError> {
        require::<f64>(ev100.is_finite(), "ev100", "finite")?;
        Ok(Self(1.0 / (1.2 * libm::exp2(ev100))))
    }

    /// Exposure from camera settings: EV100 = log2(N^2 / t * 100 / S) for aperture N
    /// (f-number), shutter time t (seconds) and ISO S (Lagarde and de Rousiers 2014, eq. 12),
    /// then [`Exposure::from_ev100`]. Each must be finite and > 0. Sunny 16 (N = 16, t = 1/100,
    /// S = 100) gives EV100 = 14.64.
    pub fn from_camera(aperture: f64, shutter_s: f64, iso: f64) -> Result<Self, ParamError> {
        const DOMAIN: &str = "finite and > 0";
        require::<f64>(aperture > 0.0 && aperture.is_finite(), "aperture", DOMAIN)?;
        require::<f64>(
            shutter_s > 0.0 && shutter_s.is_finite(),
            "shutter_s",
            DOMAIN,
        )?;
        require::<f64>(iso > 0.0 && iso.is_finite(), "iso", DOMAIN)?;
        Self::from_ev100(ev100_from_camera(aperture, shutter_s, iso))
    }
}

/// EV100 = log2(N^2 / t * 100 / S) (Lagarde and de Rousiers 2014, eq. 12), for f-number N,
/// shutter time t in seconds and sensitivity S (ISO).
///
/// Domain: each argument finite and > 0 (subnormals included); anything else, NaN included,
/// gives NaN. Evaluated as 2 log2 N - log2 t + log2(100 / S) term by term, so no product
/// overflows or underflows: the result is finite over the whole domain (within +-2200).
#[inline]
#[must_use]
pub fn ev100_from_camera(aperture: f64, shutter_s: f64, iso: f64) -> f64 {
    let ok = |v: f64| v > 0.0 && v.is_finite();
    if !(ok(aperture) && ok(shutter_s) && ok(iso)) {
        return f64::NAN;
    }
    2.0 * libm::log2(aperture) - libm::log2(shutter_s) + (libm::log2(100.0) - libm::log2(iso))
}

/// The exponential exposure curve T(c) = 1 - exp(-c * exposure). T(0) = 0, T(inf) = 1.
/// `exposure` in (0, MAX] ([`Exposure`] builds one); 0, negative, +inf and NaN give NaN.
#[inline]
#[must_use]
pub fn exposure_curve<T: Real>(c: T, exposure: T) -> T {
    let ok = exposure.simd_gt(T::ZERO) & exposure.simd_le(T::MAX);
    nan_unless(ok, (T::ONE - (-sanitize(c) * exposure).exp()).saturate())
}

/// Reinhard, Stark, Shirley, Ferwerda 2002, "Photographic Tone Reproduction for Digital
/// Images", eq. 3 per channel: c / (1 + c).
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
#[inline]
#[must_use]
pub fn reinhard_extended<T: Real>(c: T, white: T) -> T {
    let c = sanitize(c);
    let ok = white.simd_gt(T::ZERO) & white.simd_le(T::MAX);
    let v = (c * (T::ONE + c / white / white) / (T::ONE + c)).saturate();
    nan_unless(ok, v)
}

/// Reinhard on luminance: L' = L / (1 + L), colour scaled by L' / L, i.e. c / (1 + L)
/// (Reinhard et al. 2002, applied to luminance as the paper does). Keeps hue; channels are
/// clamped to 1 (a saturated colour can exceed it).
#[inline]
#[must_use]
pub fn reinhard_luminance<T: Real>(c: V3<T>) -> V3<T> {
    let c = sanitize_rgb(c);
    let scale = (T::ONE + luminance(c)).recip();
    saturate_rgb(c * scale)
}

/// Reinhard-Jodie: per-channel Reinhard blended toward luminance Reinhard by the per-channel
/// result itself, lerp(c / (1 + L), c / (1 + c), c / (1 + c)) (the variant popularised by
/// user Jodie on Shadertoy, 2019; see Reinhard et al. 2002 for both parts).
#[inline]
#[must_use]
pub fn reinhard_jodie<T: Real>(c: V3<T>) -> V3<T> {
    let c = sanitize_rgb(c);
    let by_lum = c * (T::ONE + luminance(c)).recip();
    let lerp = |l: T, t: T| l.mul_add(T::ONE - t, t * t);
    let tv = per_channel(c, |x| x / (T::ONE + x));
    saturate_rgb(V3::new(
        lerp(by_lum.x, tv.x),
        lerp(by_lum.y, tv.y),
        lerp(by_lum.z, tv.z),
    ))
}

/// Narkowicz's fit of the ACES filmic curve (Narkowicz 2015, "ACES Filmic Tone Mapping
/// Curve"): x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), clamped to [0, 1]. It includes the
/// RRT+ODT's brightening; Narkowicz scales input by 0.6 to match ACES' exposure (not applied
/// here). f(0) = 0, f(1) = 0.8038.
#[inline]
#[must_use]
pub fn aces_narkowicz<T: Real>(c: T) -> T {
    let x = sanitize(c);
    let num = x * x.mul_add(T::splat(2.51), T::splat(0.03));
    let den = x.mul_add(x.mul_add(T::splat(2.43), T::splat(0.59)), T::splat(0.14));
    (num / den).saturate()
}

/// Hill's rational fit of the ACES RRT + ODT tone curve in the fit's working space:
/// (v (v + 0.0245786) - 0.000090537) / (v (0.983729 v + 0.4329510) + 0.238081).
#[inline]
fn rrt_odt_fit<T: Real>(v: T) -> T {
    let a = v.mul_add(v + T::splat(0.024_578_6), T::splat(-0.000_090_537));
    let b = v.mul_add(
        v.mul_add(T::splat(0.983_729), T::splat(0.432_951)),
        T::splat(0.238_081),
    );
    a / b
}

/// ACES RRT + sRGB ODT as fitted by Stephen Hill (2016, `ACESFitted.hlsl`, used in MJP's
/// BakingLab): [`ACES_HILL_INPUT`], the rational tone curve per channel, [`ACES_HILL_OUTPUT`],
/// clamped to [0, 1]. Toe: the curve is -0.00038 at 0, so black stays black after the clamp.
#[inline]
#[must_use]
pub fn aces_hill<T: Real>(c: V3<T>) -> V3<T> {
    let v = color::mul(&ACES_HILL_INPUT, sanitize_rgb(c));
    saturate_rgb(color::mul(&ACES_HILL_OUTPUT, per_channel(v, rrt_odt_fit)))
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

    /// Validated parameters: all finite and > 0 (the curve then rises from F(0) = 0).
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
        Ok(Self {
            a,
            b,
            c,
            d,
            e,
            f,
            white,
            exposure_bias,
        })
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

    #[inline]
    fn curve<T: Real>(&self, x: T) -> T {
        let s = |v: f64| T::splat(v);
        let num = x.mul_add(x.mul_add(s(self.a), s(self.c * self.b)), s(self.d * self.e));
        let den = x.mul_add(x.mul_add(s(self.a), s(self.b)), s(self.d * self.f));
        num / den - s(self.e / self.f)
    }
}

/// Hable's filmic curve ("Uncharted 2"; Hable 2010, "Filmic Tonemapping Operators") per
/// channel: F(bias c) / F(W), clamped to [0, 1]. F(0) = 0. Parameters outside
/// [`HableParams::new`]'s domain (a struct built by hand) give NaN.
#[inline]
#[must_use]
pub fn hable<T: Real>(c: T, p: &HableParams) -> T {
    if !p.is_valid() {
        return T::splat(f64::NAN);
    }
    let x = sanitize(c) * T::splat(p.exposure_bias);
    (p.curve(x) / p.curve(T::splat(p.white))).saturate()
}

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

    /// Validated parameters: all finite and > 0, mid_in < hdr_max, mid_out < 1.
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
        Ok(Self::derive(contrast, shoulder, hdr_max, mid_in, mid_out))
    }

    /// True when the public fields are in [`LottesParams::new`]'s domain and b, c are finite.
    fn is_valid(&self) -> bool {
        let pos = |v: f64| v > 0.0 && v.is_finite();
        pos(self.contrast)
            && pos(self.shoulder)
            && pos(self.hdr_max)
            && pos(self.mid_in)
            && pos(self.mid_out)
            && self.mid_in < self.hdr_max
            && self.mid_out < 1.0
            && self.b.is_finite()
            && self.c.is_finite()
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

/// Lottes' curve (Lottes 2016, "Advanced Techniques and Optimization of HDR Color Pipelines",
/// GDC) per channel: x^a / (x^(a d) b + c), clamped to [0, 1]. Passes through
/// (mid_in, mid_out) and (hdr_max, 1). Parameters outside [`LottesParams::new`]'s domain (a
/// public field changed by hand) give NaN.
#[inline]
#[must_use]
pub fn lottes<T: Real>(c: T, p: &LottesParams) -> T {
    if !p.is_valid() {
        return T::splat(f64::NAN);
    }
    let x = sanitize(c);
    let xa = x.pow(T::splat(p.contrast));
    let xad = x.pow(T::splat(p.contrast * p.shoulder));
    (xa / xad.mul_add(T::splat(p.b), T::splat(p.c))).saturate()
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
    /// divides by P - S1 <= 0; the names are those of Uchimura 2017).
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
        let s1 = m + a * ((pm - m) * l / a);
        all_finite && pm > 0.0 && a > 0.0 && m > 0.0 && l >= 0.0 && self.black > 0.0 && s1 < pm
    }
}

/// Uchimura's "GT" curve (Uchimura 2017, "HDR Theory and Practice", CEDEC): a power toe
/// m (x/m)^c + b, a linear section m + a (x - m), and an exponential shoulder
/// P - (P - S1) exp(-a P / (P - S1) (x - S0) / P), blended by smoothstep(0, m, x) and a step at
/// S0 = m + l0, where l0 = (P - m) l / a is the linear section's length in x and
/// S1 = m + a l0 its end value (the talk's notation). Per channel, clamped to [0, 1].
/// f(0) = b. Parameters: every field finite, P, a, m, c > 0, l >= 0 and m + a l0 < P (the Gran
/// Turismo values qualify); others give NaN.
#[inline]
#[must_use]
pub fn uchimura<T: Real>(c: T, p: &UchimuraParams) -> T {
    if !p.is_valid() {
        return T::splat(f64::NAN);
    }
    let x = sanitize(c);
    let (pm, a, m, l, cc, b) = (
        p.max_brightness,
        p.contrast,
        p.linear_start,
        p.linear_length,
        p.black,
        p.pedestal,
    );
    let l0 = (pm - m) * l / a;
    let s0 = m + l0;
    let s1 = m + a * l0;
    let c2 = a * pm / (pm - s1);
    let cp = -c2 / pm;
    let s = |v: f64| T::splat(v);
    let t = (x / s(m)).saturate();
    let w0 = T::ONE - t * t * (s(3.0) - T::TWO * t);
    let w2 = T::select(x.simd_ge(s(s0)), T::ONE, T::ZERO);
    let w1 = T::ONE - w0 - w2;
    let toe = s(m).mul_add((x / s(m)).pow(s(cc)), s(b));
    let shoulder = s(pm) - s(pm - s1) * (s(cp) * (x - s(s0))).exp();
    let linear = s(a).mul_add(x - s(m), s(m));
    (toe * w0 + linear * w1 + shoulder * w2).saturate()
}

/// Khronos PBR Neutral (Khronos Group 2024, "PBR Neutral Tone Mapper" specification): an
/// offset f of the darkest channel (x - x^2 / 0.16 below 0.08, else 0.04), identity below
/// the compression start Ks = 0.76, then a peak compression p_n = 1 - (1 - Ks)^2 / (p + 1 -
/// 2 Ks) with desaturation g = 1 / (0.15 (p - p_n) + 1) toward white. Keeps base colours up to
/// 0.76 exact (minus the offset), which is its purpose for product rendering.
#[inline]
#[must_use]
pub fn pbr_neutral<T: Real>(c: V3<T>) -> V3<T> {
    let c = sanitize_rgb(c);
    let s = |v: f64| T::splat(v);
    let ks = 0.8 - 0.04;
    let x = c.x.min(c.y).min(c.z);
    let offset = T::select(x.simd_lt(s(0.08)), x - s(6.25) * x * x, s(0.04));
    let c = c - V3::splat(offset);
    let peak = c.x.max(c.y).max(c.z);
    let d = 1.0 - ks;
    let new_peak = T::ONE - s(d * d) / (peak + s(d - ks));
    let g = (s(0.15) * (peak - new_peak) + T::ONE).recip();
    let safe_peak = T::select(peak.simd_gt(T::ZERO), peak, T::ONE);
    let scaled = c * (new_peak / safe_peak * g) + V3::splat(new_peak * (T::ONE - g));
    let compress = peak.simd_ge(s(ks));
    let out = saturate_rgb(V3::select(compress, scaled, c));
    // The offset and the peak mix the channels, but `min`/`max` ignore a NaN argument: without
    // this a NaN in one channel would leave the other two plausible.
    let bad = any_nan3(c);
    V3::new(
        nan_where(bad, out.x),
        nan_where(bad, out.y),
        nan_where(bad, out.z),
    )
}

/// An AgX look: a CDL-style slope / power / saturation grade applied in AgX's encoded space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AgxLook {
    /// Per-channel slope (multiplier).
    pub slope: [f64; 3],
    /// Per-channel power.
    pub power: [f64; 3],
    /// Saturation around Rec.709 luminance.
    pub saturation: f64,
}

impl AgxLook {
    /// No grade: base AgX.
    pub const BASE: Self = Self {
        slope: [1.0; 3],
        power: [1.0; 3],
        saturation: 1.0,
    };
    /// "Golden": slope (1, 0.9, 0.5), power 0.8, saturation 1.3 (Wrensch 2023).
    pub const GOLDEN: Self = Self {
        slope: [1.0, 0.9, 0.5],
        power: [0.8; 3],
        saturation: 1.3,
    };
    /// "Punchy": power 1.35, saturation 1.4 (Wrensch 2023).
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
}

/// The AgX contrast curve's 6th-order polynomial fit on [0, 1] (Wrensch 2023, "Minimal AgX
/// Implementation", fit of Sobotka's default contrast LUT):
/// 15.5 x^6 - 40.14 x^5 + 31.96 x^4 - 6.868 x^3 + 0.4298 x^2 + 0.1191 x - 0.00232,
/// clamped at 0 (it is -0.00232 at 0).
///
/// Evaluated in t = x - 1/2 with the exactly re-expanded coefficients (0.2914925, 1.7404,
/// 2.42405, -4.548, -10.265, 6.36, 15.5): in x, Horner's terms reach +-40 and cancel to about
/// 1 near the top, leaving 5e-6 of f32 rounding noise that made the curve wiggle; in t every
/// term stays below 1.
#[inline]
fn agx_contrast<T: Real>(x: T) -> T {
    let s = |v: f64| T::splat(v);
    let t = x - T::HALF;
    let p = t.mul_add(s(15.5), s(6.36));
    let p = t.mul_add(p, s(-10.265));
    let p = t.mul_add(p, s(-4.548));
    let p = t.mul_add(p, s(2.42405));
    let p = t.mul_add(p, s(1.7404));
    let p = t.mul_add(p, s(0.291_492_5));
    p.max(T::ZERO)
}

/// AgX (Sobotka 2022, "AgX", as in Blender 4; minimal analytic form of Wrensch 2023):
/// [`AGX_INSET`], log2 encoding over [-12.47393, 4.026069] EV, the contrast polynomial, the
/// `look`, [`AGX_OUTSET`], then the 2.2 power the reference uses to return linear values.
/// Output clamped to [0, 1]; f(0) = 0 (the polynomial's -0.00232 toe is clamped); its top, at
/// [`MAX_INPUT`] and +inf, is 0.9970. A look outside [`AgxLook::new`]'s domain (built by
/// hand) gives NaN.
#[inline]
#[must_use]
pub fn agx<T: Real>(c: V3<T>, look: &AgxLook) -> V3<T> {
    if AgxLook::new(look.slope, look.power, look.saturation).is_err() {
        return V3::splat(T::splat(f64::NAN));
    }
    const MIN_EV: f64 = -12.47393;
    const MAX_EV: f64 = 4.026069;
    let v = color::mul(&AGX_INSET, sanitize_rgb(c));
    let encode = |x: T| {
        // log2 of 0 is -inf, clamped to MIN_EV like every value below it.
        let ev = (x.max(T::MIN_POSITIVE).ln() * T::splat(core::f64::consts::LOG2_E))
            .clamp(T::splat(MIN_EV), T::splat(MAX_EV));
        agx_contrast((ev - T::splat(MIN_EV)) * T::splat(1.0 / (MAX_EV - MIN_EV)))
    };
    let v = per_channel(v, encode);
    let graded = if *look == AgxLook::BASE {
        v
    } else {
        let s = &look.slope;
        let p = &look.power;
        // The graded value is clamped at 0 before the power, so a look built by hand with a
        // negative slope darkens to black instead of producing NaN.
        let grade = |x: T, k: usize| color::non_negative(x * T::splat(s[k])).pow(T::splat(p[k]));
        let g = V3::new(grade(v.x, 0), grade(v.y, 1), grade(v.z, 2));
        let l = luminance(g);
        let sat = T::splat(look.saturation);
        V3::new(
            sat.mul_add(g.x - l, l),
            sat.mul_add(g.y - l, l),
            sat.mul_add(g.z - l, l),
        )
    };
    let out = color::mul(&AGX_OUTSET, graded);
    let lin = per_channel(out, |x| color::non_negative(x).pow(T::splat(2.2)));
    saturate_rgb(lin)
}

/// Every operator of this module, for code that chooses one at run time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Operator {
    /// [`exposure_curve`] with the given exposure.
    ExposureCurve(f64),
    /// [`reinhard`] per channel.
    Reinhard,
    /// [`reinhard_luminance`].
    ReinhardLuminance,
    /// [`reinhard_extended`] with the given white point.
    ReinhardExtended(f64),
    /// [`reinhard_jodie`].
    ReinhardJodie,
    /// [`aces_narkowicz`].
    AcesNarkowicz,
    /// [`aces_hill`].
    AcesHill,
    /// [`hable`].
    Hable(HableParams),
    /// [`lottes`].
    Lottes(LottesParams),
    /// [`uchimura`].
    Uchimura(UchimuraParams),
    /// [`pbr_neutral`].
    PbrNeutral,
    /// [`agx`] with a look.
    Agx(AgxLook),
}

impl Operator {
    /// The operator on an RGB [`V3`] of scalars or lanes.
    #[inline]
    #[must_use]
    pub fn apply<T: Real>(&self, c: V3<T>) -> V3<T> {
        match self {
            Self::ExposureCurve(e) => per_channel(c, |x| exposure_curve(x, T::splat(*e))),
            Self::Reinhard => per_channel(c, reinhard),
            Self::ReinhardLuminance => reinhard_luminance(c),
            Self::ReinhardExtended(w) => per_channel(c, |x| reinhard_extended(x, T::splat(*w))),
            Self::ReinhardJodie => reinhard_jodie(c),
            Self::AcesNarkowicz => per_channel(c, aces_narkowicz),
            Self::AcesHill => aces_hill(c),
            Self::Hable(p) => per_channel(c, |x| hable(x, p)),
            Self::Lottes(p) => per_channel(c, |x| lottes(x, p)),
            Self::Uchimura(p) => per_channel(c, |x| uchimura(x, p)),
            Self::PbrNeutral => pbr_neutral(c),
            Self::Agx(look) => agx(c, look),
        }
    }

    /// The operator on a glam `Vec3`.
    #[inline]
    #[must_use]
    pub fn apply_vec3(&self, c: Vec3) -> Vec3 {
        self.apply(V3::from(c)).into()
    }

    /// The operator on a glam `Vec3A`.
    #[inline]
    #[must_use]
    pub fn apply_vec3a(&self, c: Vec3A) -> Vec3A {
        Vec3A::from(self.apply_vec3(Vec3::from(c)))
    }

    /// Every operator with its default parameters (exposure 1, white point 4), from the
    /// simplest curves to the filmic ones.
    #[must_use]
    pub fn all() -> [Self; 14] {
        [
            Self::ExposureCurve(1.0),
            Self::Reinhard,
            Self::ReinhardLuminance,
            Self::ReinhardExtended(4.0),
            Self::ReinhardJodie,
            Self::AcesNarkowicz,
            Self::AcesHill,
            Self::Hable(HableParams::UNCHARTED2),
            Self::Lottes(LottesParams::default_curve()),
            Self::Uchimura(UchimuraParams::GRAN_TURISMO),
            Self::PbrNeutral,
            Self::Agx(AgxLook::BASE),
            Self::Agx(AgxLook::PUNCHY),
            Self::Agx(AgxLook::GOLDEN),
        ]
    }
}
