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
//! `MAX_INPUT`: 1 for all of them except AgX, whose curve fits top out below 1 (Wrensch's, in
//! [`agx_minimal`] and [`agx_threejs`], at 0.9970; Filament's at 0.9610, 0.9424 under punchy;
//! the golden looks tint it).
//!
//! # Channel coupling
//! Per-channel operators are monotonic in each channel. Operators that use luminance or the
//! channel extremes (Reinhard on luminance, Reinhard-Jodie, ACES Hill, PBR Neutral, AgX) are
//! monotonic along every grey ramp and in each channel's own input, but raising one channel
//! can lower another's output (that is what desaturation and luminance preservation do).
//! Two designs bend even that, by amounts `tests/tonemap/properties.rs` measures and bounds:
//! PBR Neutral's darkest-channel offset lets that channel's own output fall by up to 2e-7
//! while another channel is compressed. AgX's outset matrices (negative off-diagonals) lower a
//! channel that has reached the top of the log encoding by up to 3.5e-5 as its input grows
//! (up to 1e-4 under Filament's punchy look); the looks with saturation > 1 dip a grey ramp by
//! up to 3e-6 where the channels reach that top at slightly different inputs; and Filament's
//! curve fit itself dips by 2e-8 near black (it starts at 0.002857 with a negative slope), so
//! Filament's AgX maps black to 2.5e-6 rather than 0.
//!
//! # Matching an engine
//! Engines differ in where they apply exposure, whether a pre-exposure or a gamma is part of
//! the operator, per-channel versus luminance forms, and the working colour space. Each
//! operator's documentation states the expression that reproduces three.js, Filament and bevy
//! where they ship the same curve; `cargo test --test tonemap against_peers:: -- --nocapture`
//! checks every such mapping against transcriptions of the engines' own shader code on about 13,000
//! colours (greys from 0 to 1e4, saturated colours, random colours), to 4.8e-7 (four f32 ULPs
//! of 1) for the rational curves and to the engines' own f32 rounding for AgX, and the
//! report prints the table. The traps: three.js's `ACESFilmicToneMapping` at exposure e is
//! [`aces_hill`]`(c * e / 0.6)` (0.28 apart without the 1/0.6); Hable's post pre-exposes by 16
//! and encodes with a 1/2.2 power, neither part of [`hable`]; three.js multiplies by
//! `toneMappingExposure` inside each operator, bevy by 2^exposure before it; Filament runs its
//! tone mappers on Rec.2020 values.
//!
//! # Which AgX
//! Three functions, each true to one published source, because the sources differ by up to
//! 0.3 on saturated colours: [`agx_minimal`] is Wrensch 2023's minimal AgX on Rec.709 (with
//! his looks), [`agx_threejs`] is three.js's `AgXToneMapping` (Rec.2020 matrices from
//! Blender, Wrensch's curve, sRGB in and out), and [`agx_filament`] is Filament's
//! `AgxToneMapper` (the same Rec.2020 matrices, its own 7th-order curve fit, its looks, on
//! Rec.2020 in and out). bevy's AgX samples a 3D LUT baked from Sobotka's configuration; no
//! analytic form here reproduces it.

mod agx;
mod curves;

pub use agx::*;
pub use curves::*;

use crate::color;
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
pub(crate) fn sanitize_rgb<T: Real>(c: V3<T>) -> V3<T> {
    V3::new(sanitize(c.x), sanitize(c.y), sanitize(c.z))
}

#[inline]
pub(crate) fn saturate_rgb<T: Real>(c: V3<T>) -> V3<T> {
    // Clamped to [0, 1]; a NaN (from a NaN input) stays NaN.
    V3::new(c.x.saturate(), c.y.saturate(), c.z.saturate())
}

#[inline]
pub(crate) fn per_channel<T: Real>(c: V3<T>, f: impl Fn(T) -> T) -> V3<T> {
    V3::new(f(c.x), f(c.y), f(c.z))
}

/// Camera exposure: the factor scene luminance is multiplied by before tonemapping.
/// Built only through its validating constructors, so its value is always finite and > 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Exposure(f64);

impl Exposure {
    /// An exposure factor: finite and > 0.
    pub fn new(factor: f64) -> Result<Self, ParamError> {
        require::<f64>(
            factor > 0.0 && factor.is_finite(),
            "exposure",
            "finite and > 0",
        )?;
        Ok(Self(factor))
    }

    /// The factor scene values are multiplied by. bevy's camera exposure, exp2(-EV100) / 1.2,
    /// is [`Exposure::from_ev100`]`(ev100).value()` to f32 rounding
    /// (`tests/tonemap/against_peers.rs`).
    #[inline]
    #[must_use]
    pub fn value(self) -> f64 {
        self.0
    }

    /// Exposure of a photometric EV100: 1 / (1.2 * 2^EV100), the saturation-based sensor model
    /// with q = 0.65 and K = 12.5 (78 / (100 q) = 1.2) of Lagarde and de Rousiers 2014, "Moving
    /// Frostbite to Physically Based Rendering", section 4.2. EV100 must be finite.
    pub fn from_ev100(ev100: f64) -> Result<Self, ParamError> {
        require::<f64>(ev100.is_finite(), "ev100", "finite")?;
        // exp2 overflows to inf (factor 0) or underflows (factor inf) past |EV100| ~ 1024.
        Self::new(1.0 / (1.2 * libm::exp2(ev100)))
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
    /// [`reinhard_extended_luminance`] with the given white point.
    ReinhardExtendedLuminance(f64),
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
    /// [`agx_minimal`] (Wrensch's minimal AgX, Rec.709) with a look.
    AgxMinimal(AgxLook),
    /// [`agx_threejs`] (three.js's AgX, through Rec.2020).
    AgxThreejs,
    /// Filament's AgX with a look, seen from linear sRGB: [`color::REC709_TO_REC2020`],
    /// [`agx_filament`], [`color::REC2020_TO_REC709`], clamped to [0, 1], as Filament's colour
    /// grading applies it.
    AgxFilament(AgxLook),
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
            Self::ReinhardExtendedLuminance(w) => reinhard_extended_luminance(c, T::splat(*w)),
            Self::ReinhardJodie => reinhard_jodie(c),
            Self::AcesNarkowicz => per_channel(c, aces_narkowicz),
            Self::AcesHill => aces_hill(c),
            Self::Hable(p) => per_channel(c, |x| hable(x, p)),
            Self::Lottes(p) => per_channel(c, |x| lottes(x, p)),
            Self::Uchimura(p) => per_channel(c, |x| uchimura(x, p)),
            Self::PbrNeutral => pbr_neutral(c),
            Self::AgxMinimal(look) => agx_minimal(c, look),
            Self::AgxThreejs => agx_threejs(c),
            Self::AgxFilament(look) => agx::agx_filament_srgb(c, look),
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
    pub fn all() -> [Self; 19] {
        [
            Self::ExposureCurve(1.0),
            Self::Reinhard,
            Self::ReinhardLuminance,
            Self::ReinhardExtended(4.0),
            Self::ReinhardExtendedLuminance(4.0),
            Self::ReinhardJodie,
            Self::AcesNarkowicz,
            Self::AcesHill,
            Self::Hable(HableParams::UNCHARTED2),
            Self::Lottes(LottesParams::default_curve()),
            Self::Uchimura(UchimuraParams::GRAN_TURISMO),
            Self::PbrNeutral,
            Self::AgxMinimal(AgxLook::BASE),
            Self::AgxMinimal(AgxLook::PUNCHY),
            Self::AgxMinimal(AgxLook::GOLDEN),
            Self::AgxThreejs,
            Self::AgxFilament(AgxLook::BASE),
            Self::AgxFilament(AgxLook::PUNCHY),
            Self::AgxFilament(AgxLook::GOLDEN_FILAMENT),
        ]
    }
}
