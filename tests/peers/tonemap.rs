//! Tonemapping operators as other engines and their authors ship them, transcribed to f32 Rust
//! from each peer's own source (never from this crate), so tests and the report can measure how
//! far `brdf::tonemap` is from each one under a stated mapping.
//!
//! Conventions of the transcription:
//! - f32 throughout, unfused (`a * b + c`, never `mul_add`), in the source's operation order,
//!   as a GPU without fast-math contraction would evaluate it.
//! - Colours are `[r, g, b]`. Matrices are stored row-major (`m[row][col]`); sources written
//!   with GLSL `mat3(...)` or Filament's `mat3f{...}` list their 9 scalars COLUMN by column
//!   (GLSL spec 5.4.2; Filament `libs/math/include/math/mat3.h`, "construct from 9 elements in
//!   column-major form"), so those are entered through [`cols`], which transposes.
//! - Where a source calls a function that is undefined for some inputs (GLSL `pow` of a
//!   negative base, `0 / 0`), the transcription computes what IEEE f32 gives (NaN) and says so;
//!   callers skip and count such points.
//! - No clamp is added that the source lacks.
//!
//! This module depends on nothing but `core`/`std`, so it can be read against the sources line
//! by line.

// Not every consumer uses every peer; literals keep every digit the sources print.
#![allow(dead_code, clippy::excessive_precision)]

/// An RGB triple.
pub type Rgb = [f32; 3];
/// A 3 x 3 matrix, row-major.
pub type M3 = [[f32; 3]; 3];

/// A matrix from 9 scalars listed column by column (GLSL `mat3(a, ..., i)`, Filament
/// `mat3f{a, ..., i}`): the first three are the first column.
pub const fn cols(v: [f32; 9]) -> M3 {
    [[v[0], v[3], v[6]], [v[1], v[4], v[7]], [v[2], v[5], v[8]]]
}

/// A matrix from 9 scalars listed row by row.
pub const fn rows(v: [f32; 9]) -> M3 {
    [[v[0], v[1], v[2]], [v[3], v[4], v[5]], [v[6], v[7], v[8]]]
}

/// `m * v` in f32: out_i = (m_i0 v_0 + m_i1 v_1) + m_i2 v_2.
pub fn mul(m: &M3, v: Rgb) -> Rgb {
    let r = |i: usize| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    [r(0), r(1), r(2)]
}

/// `a * b` for matrices in f32 (Filament's `constexpr` products of `mat3f`).
pub fn mat_mul(a: &M3, b: &M3) -> M3 {
    let mut m = [[0.0; 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    m
}

/// The inverse by cofactors, in f32 (what GLSL `inverse` and Filament's `constexpr inverse` of
/// a `mat3f` compute; their exact operation order is unpublished, so the last bit may differ).
pub fn inverse(m: &M3) -> M3 {
    let c =
        |r0: usize, c0: usize, r1: usize, c1: usize| m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
    let cof = [
        [c(1, 1, 2, 2), -c(1, 0, 2, 2), c(1, 0, 2, 1)],
        [-c(0, 1, 2, 2), c(0, 0, 2, 2), -c(0, 0, 2, 1)],
        [c(0, 1, 1, 2), -c(0, 0, 1, 2), c(0, 0, 1, 1)],
    ];
    let det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
    let inv = 1.0 / det;
    // The inverse is the transposed cofactor matrix over the determinant.
    let mut out = [[0.0; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = cof[j][i] * inv;
        }
    }
    out
}

fn map(c: Rgb, f: impl Fn(f32) -> f32) -> Rgb {
    [f(c[0]), f(c[1]), f(c[2])]
}

/// GLSL `clamp(x, 0, 1)`; a NaN stays NaN.
pub fn saturate(x: f32) -> f32 {
    if x.is_nan() { x } else { x.clamp(0.0, 1.0) }
}

fn saturate3(c: Rgb) -> Rgb {
    map(c, saturate)
}

fn dot(a: Rgb, b: Rgb) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// GLSL `mix(a, b, t)` = a (1 - t) + b t.
fn mix(a: f32, b: f32, t: f32) -> f32 {
    a * (1.0 - t) + b * t
}

/// GLSL `smoothstep(e0, e1, x)`.
fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

// ------------------------------------------------------------------------------------------
// three.js
// ------------------------------------------------------------------------------------------

/// three.js `LinearToneMapping`: saturate(exposure c).
///
/// Source: mrdoob/three.js, `src/renderers/shaders/ShaderChunk/tonemapping_pars_fragment.glsl.js`,
/// commit adb06d747b64ed48b639bc446db395cf1406b581 (r162 or later: it has `NeutralToneMapping`;
/// the stored copies hold no r187 tag to compare against). `exposure` is the
/// `toneMappingExposure` uniform.
pub fn threejs_linear(c: Rgb, exposure: f32) -> Rgb {
    saturate3(map(c, |x| exposure * x))
}

/// three.js `ReinhardToneMapping`: c *= exposure, then saturate(c / (1 + c)) per channel.
///
/// Source: mrdoob/three.js, `tonemapping_pars_fragment.glsl.js` at commit adb06d74 (see
/// [`threejs_linear`]).
pub fn threejs_reinhard(c: Rgb, exposure: f32) -> Rgb {
    saturate3(map(c, |x| {
        let x = x * exposure;
        x / (1.0 + x)
    }))
}

/// three.js `RRTAndODTFit` (Stephen Hill's rational fit), per channel.
fn threejs_rrt_and_odt_fit(v: f32) -> f32 {
    let a = v * (v + 0.024_578_6) - 0.000_090_537;
    let b = v * (0.983_729 * v + 0.432_951) + 0.238_081;
    a / b
}

/// three.js `ACESFilmicToneMapping`: c *= exposure / 0.6 (three.js's brightening, "the scale
/// factor of 1/0.6 is subjective"), `ACESInputMat`, `RRTAndODTFit`, `ACESOutputMat`, saturate.
/// The two matrices are written as `mat3(vec3, vec3, vec3)` columns, "transposed from source".
///
/// Source: mrdoob/three.js, `tonemapping_pars_fragment.glsl.js` at commit adb06d74 (identical
/// in commit 0ac1f6ab583e183ba7ed865b092b033be85dc790).
pub fn threejs_aces_filmic(c: Rgb, exposure: f32) -> Rgb {
    const INPUT: M3 = cols([
        0.59719, 0.07600, 0.02840, //
        0.35458, 0.90834, 0.13383, //
        0.04823, 0.01566, 0.83777,
    ]);
    const OUTPUT: M3 = cols([
        1.60475, -0.10208, -0.00327, //
        -0.53108, 1.10813, -0.07276, //
        -0.07367, -0.00605, 1.07602,
    ]);
    let s = exposure / 0.6;
    let c = map(c, |x| x * s);
    let c = mul(&INPUT, c);
    let c = map(c, threejs_rrt_and_odt_fit);
    saturate3(mul(&OUTPUT, c))
}

thread_local! {
    /// When set (on the calling thread only), the AgX polynomials are summed in f64 and rounded
    /// once, not in f32 as the shaders do: isolates the shaders' own polynomial rounding from
    /// every other difference.
    pub static AGX_POLY_IN_F64: core::cell::Cell<bool> = const { core::cell::Cell::new(false) };
}

fn poly_in_f64() -> bool {
    AGX_POLY_IN_F64.with(core::cell::Cell::get)
}

/// Wrensch's 6th-order fit of the AgX contrast curve as three.js (and Wrensch) write it:
/// 15.5 x^6 - 40.14 x^5 + 31.96 x^4 - 6.868 x^3 + 0.4298 x^2 + 0.1191 x - 0.00232, summed left
/// to right from the powers x2 = x x, x4 = x2 x2 (in f64 under [`AGX_POLY_IN_F64`]).
pub fn agx_contrast_6th(x: f32) -> f32 {
    if poly_in_f64() {
        let x = f64::from(x);
        let x2 = x * x;
        let x4 = x2 * x2;
        return (15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x
            + 0.4298 * x2
            + 0.1191 * x
            - 0.00232) as f32;
    }
    let x2 = x * x;
    let x4 = x2 * x2;
    15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x
        - 0.00232
}

/// Blender's AgX inset for Rec.2020 (Eary Chow's `AgXBaseRec2020.py`), as three.js and Filament
/// list it, column by column.
pub const AGX_INSET_REC2020: M3 = cols([
    0.856_627_153_315_983,
    0.137_318_972_929_847,
    0.111_898_212_999_95,
    0.095_121_240_538_158_8,
    0.761_241_990_602_591,
    0.076_799_418_603_190_3,
    0.048_251_606_145_858_3,
    0.101_439_036_467_562,
    0.811_302_368_396_859,
]);

/// Blender's outset inverse for Rec.2020 (Filament `AgXOutsetMatrixInv`, three.js
/// `AgXOutsetMatrixInv` at 0ac1f6ab), column by column. The engines invert it.
pub const AGX_OUTSET_INV_REC2020: M3 = cols([
    0.899_796_955_911_611,
    0.111_420_988_957_48,
    0.111_420_988_957_48,
    0.087_199_619_202_835_1,
    0.875_575_586_156_966,
    0.087_199_619_202_834_9,
    0.013_003_424_885_555,
    0.013_003_424_885_554_8,
    0.801_379_391_839_686,
]);

/// The bottom and top of AgX's log2 encoding, log2(0.18 2^-10) and log2(0.18 2^6.5), as every
/// source writes them.
pub const AGX_MIN_EV: f32 = -12.47393;
/// See [`AGX_MIN_EV`].
pub const AGX_MAX_EV: f32 = 4.026069;

/// three.js `AgXToneMapping` at commit adb06d74 (see [`threejs_linear`]): c *= exposure;
/// `LINEAR_SRGB_TO_LINEAR_REC2020` (an explicit 4-decimal matrix, ITU-R BT.2087's; NOT the
/// inverse of the Rec.2020-to-sRGB one); `AgXInsetMatrix`; max(c, 1e-10); log2; (c - min_ev) /
/// (max_ev - min_ev); clamp to [0, 1]; the 6th-order curve; `AgXOutsetMatrix` (explicit, 17
/// digits, "generated from Filament's AgXOutsetMatrixInv"); pow(max(0, c), 2.2);
/// `LINEAR_REC2020_TO_LINEAR_SRGB` (BT.2407's 4-decimal matrix); clamp to [0, 1].
pub fn threejs_agx(c: Rgb, exposure: f32) -> Rgb {
    const REC2020_TO_SRGB: M3 = cols([
        1.6605, -0.1246, -0.0182, //
        -0.5876, 1.1329, -0.1006, //
        -0.0728, -0.0083, 1.1187,
    ]);
    const SRGB_TO_REC2020: M3 = cols([
        0.6274, 0.0691, 0.0164, //
        0.3293, 0.9195, 0.0880, //
        0.0433, 0.0113, 0.8956,
    ]);
    const OUTSET: M3 = cols([
        1.1271005818144368,
        -0.1413297634984383,
        -0.14132976349843826,
        -0.11060664309660323,
        1.157823702216272,
        -0.11060664309660294,
        -0.016493938717834573,
        -0.016493938717834257,
        1.2519364065950405,
    ]);
    let c = map(c, |x| x * exposure);
    let c = mul(&SRGB_TO_REC2020, c);
    let c = mul(&AGX_INSET_REC2020, c);
    let c = map(c, |x| {
        let l = x.max(1e-10).log2();
        let e = ((l - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV)).clamp(0.0, 1.0);
        agx_contrast_6th(e)
    });
    let c = mul(&OUTSET, c);
    let c = map(c, |x| 0f32.max(x).powf(2.2));
    saturate3(mul(&REC2020_TO_SRGB, c))
}

/// three.js `AgXToneMapping` as first shipped (commit 0ac1f6ab583e183ba7ed865b092b033be85dc790,
/// r160/r161: no `NeutralToneMapping` yet): `LINEAR_SRGB_TO_LINEAR_REC2020 =
/// inverse(LINEAR_REC2020_TO_LINEAR_SRGB)` and `AgXOutsetMatrix = inverse(AgXOutsetMatrixInv)`,
/// both GLSL `inverse` (computed here in f32); max(0) after the Rec.2020 conversion, then the
/// exposure; no final clamp. Otherwise as [`threejs_agx`].
pub fn threejs_agx_0ac1f6ab(c: Rgb, exposure: f32) -> Rgb {
    // `transpose(mat3(vec3 rows...))`: the BT.2407 rows as written.
    const REC2020_TO_SRGB: M3 = rows([
        1.6605, -0.5876, -0.0728, //
        -0.1246, 1.1329, -0.0083, //
        -0.0182, -0.1006, 1.1187,
    ]);
    let srgb_to_rec2020 = inverse(&REC2020_TO_SRGB);
    let outset = inverse(&AGX_OUTSET_INV_REC2020);
    let v = mul(&srgb_to_rec2020, c);
    let v = map(v, |x| 0f32.max(x) * exposure);
    let v = mul(&AGX_INSET_REC2020, v);
    let v = map(v, |x| {
        let l = x.max(1e-10).log2();
        let e = ((l - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV)).clamp(0.0, 1.0);
        agx_contrast_6th(e)
    });
    let v = mul(&outset, v);
    let v = map(v, |x| 0f32.max(x).powf(2.2));
    mul(&REC2020_TO_SRGB, v)
}

/// three.js `NeutralToneMapping` (Khronos PBR Neutral): c *= exposure; offset the darkest
/// channel (x - 6.25 x^2 below 0.08, else 0.04); return if the peak is below 0.76; else
/// compress the peak to 1 - d^2 / (peak + d - 0.76), d = 0.24, scale, and mix toward
/// newPeak (1, 1, 1) by g = 1 - 1 / (0.15 (peak - newPeak) + 1). No clamp.
///
/// Source: mrdoob/three.js, `tonemapping_pars_fragment.glsl.js` at commit adb06d74.
pub fn threejs_neutral(c: Rgb, exposure: f32) -> Rgb {
    khronos_neutral_body(map(c, |x| x * exposure), true)
}

/// The PBR Neutral body shared by three.js, bevy and the Khronos reference; `to_new_peak`
/// false gives the variant that mixes toward (1, 1, 1) instead (Khronos's first commit and
/// Filament at 0916f5bb).
fn khronos_neutral_body(c: Rgb, to_new_peak: bool) -> Rgb {
    let start_compression: f32 = 0.8 - 0.04;
    let desaturation: f32 = 0.15;
    let x = c[0].min(c[1].min(c[2]));
    let offset = if x < 0.08 { x - 6.25 * x * x } else { 0.04 };
    let c = map(c, |v| v - offset);
    let peak = c[0].max(c[1].max(c[2]));
    if peak < start_compression {
        return c;
    }
    let d = 1.0 - start_compression;
    let new_peak = 1.0 - d * d / (peak + d - start_compression);
    let c = map(c, |v| v * (new_peak / peak));
    let g = 1.0 - 1.0 / (desaturation * (peak - new_peak) + 1.0);
    let target = if to_new_peak { new_peak } else { 1.0 };
    map(c, |v| mix(v, target, g))
}

// ------------------------------------------------------------------------------------------
// Filament (operators act on linear Rec.2020; see `filament_grade`)
// ------------------------------------------------------------------------------------------

/// Filament `sRGB_to_XYZ` (`filament/src/ColorSpaceUtils.h`, commit
/// 082da86ca889c905cfdc8928fb8fbeff1c50b091), column by column.
pub const FILAMENT_SRGB_TO_XYZ: M3 = cols([
    0.4124560, 0.2126730, 0.0193339, //
    0.3575760, 0.7151520, 0.1191920, //
    0.1804380, 0.0721750, 0.9503040,
]);
/// Filament `XYZ_to_sRGB` (same file).
pub const FILAMENT_XYZ_TO_SRGB: M3 = cols([
    3.2404542, -0.9692660, 0.0556434, //
    -1.5371385, 1.8760108, -0.2040259, //
    -0.4985314, 0.0415560, 1.0572252,
]);
/// Filament `Rec2020_to_XYZ` (same file).
pub const FILAMENT_REC2020_TO_XYZ: M3 = cols([
    0.6369530, 0.2626983, 0.0000000, //
    0.1446169, 0.6780088, 0.0280731, //
    0.1688558, 0.0592929, 1.0608272,
]);
/// Filament `XYZ_to_Rec2020` (same file).
pub const FILAMENT_XYZ_TO_REC2020: M3 = cols([
    1.7166634, -0.6666738, 0.0176425, //
    -0.3556733, 1.6164557, -0.0427770, //
    -0.2533681, 0.0157683, 0.9422433,
]);

/// Filament's `sRGB_to_Rec2020 = XYZ_to_Rec2020 * sRGB_to_XYZ` (a `constexpr mat3f` product,
/// in f32).
pub fn filament_srgb_to_rec2020() -> M3 {
    mat_mul(&FILAMENT_XYZ_TO_REC2020, &FILAMENT_SRGB_TO_XYZ)
}

/// Filament's `Rec2020_to_sRGB = XYZ_to_sRGB * Rec2020_to_XYZ` (f32).
pub fn filament_rec2020_to_srgb() -> M3 {
    mat_mul(&FILAMENT_XYZ_TO_SRGB, &FILAMENT_REC2020_TO_XYZ)
}

/// Filament's colour grading around a tone mapper, without adjustments (exposure 0 EV, no
/// white balance, no LUT quantisation): `colorGradingIn` (sRGB_to_Rec2020), the tone mapper,
/// `colorGradingOut` (Rec2020_to_sRGB), saturate. Source: google/filament,
/// `filament/src/details/ColorGrading.cpp` (commit 1e3a258bf12047b681fad3be1d9bec60512c783f),
/// `hdrColorAt`. Filament bakes this into a 3D LUT indexed in LogC; the LUT's sampling error
/// is not modelled.
pub fn filament_grade(c: Rgb, tone_mapper: impl Fn(Rgb) -> Rgb) -> Rgb {
    let v = mul(&filament_srgb_to_rec2020(), c);
    let v = tone_mapper(v);
    saturate3(mul(&filament_rec2020_to_srgb(), v))
}

/// Filament's deprecated `ToneMapping::FILMIC` path: `colorGradingIn` and `colorGradingOut` are
/// identity (`selectColorGradingTransformIn/Out` in ColorGrading.cpp), so the tone mapper sees
/// linear sRGB; then saturate.
pub fn filament_grade_legacy_filmic(c: Rgb) -> Rgb {
    saturate3(filament_filmic(c))
}

/// Filament `LinearToneMapper`: saturate(c). Source: google/filament,
/// `filament/src/ToneMapper.cpp`, commit 0916f5bbbdeb3bfa553ce6ad2276652e570d4712.
pub fn filament_linear(c: Rgb) -> Rgb {
    saturate3(c)
}

/// Filament `FilmicToneMapper` (Narkowicz 2015): x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14)
/// per channel, no clamp, no 0.6. Source: `filament/src/ToneMapper.cpp` at 0916f5bb.
pub fn filament_filmic(c: Rgb) -> Rgb {
    map(c, |x| {
        let (a, b, cc, d, e) = (2.51f32, 0.03f32, 2.43f32, 0.59f32, 0.14f32);
        (x * (a * x + b)) / (x * (cc * x + d) + e)
    })
}

/// Filament `PBRNeutralToneMapper` at commit 0916f5bb: the Khronos body but the final mix goes
/// toward (1, 1, 1), not toward newPeak (as Khronos's first commit 8b9b3929 did; Khronos's
/// current reference, three.js and bevy mix toward newPeak, and a later Filament revision
/// found in the index, with `GT7ToneMapper`, does too). No clamp.
pub fn filament_pbr_neutral(c: Rgb) -> Rgb {
    khronos_neutral_body(c, false)
}

/// Filament's AgX look enum (`ToneMapper.h`, `AgxToneMapper::AgxLook`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilamentAgxLook {
    /// Base contrast.
    None,
    /// power 1.35, sat 1.4.
    Punchy,
    /// slope (1, 0.9, 0.5), power 0.8, sat 1.3.
    Golden,
}

/// Filament's 7th-order fit: -17.86 x^7 + 78.01 x^6 - 126.7 x^5 + 92.06 x^4 - 28.72 x^3 +
/// 4.361 x^2 - 0.1718 x + 0.002857 (not Wrensch's 6th-order one), summed left to right (in
/// f64 under [`AGX_POLY_IN_F64`]).
pub fn filament_agx_contrast(x: f32) -> f32 {
    if poly_in_f64() {
        let x = f64::from(x);
        let x2 = x * x;
        let x4 = x2 * x2;
        let x6 = x4 * x2;
        return (-17.86 * x6 * x + 78.01 * x6 - 126.7 * x4 * x + 92.06 * x4 - 28.72 * x2 * x
            + 4.361 * x2
            - 0.1718 * x
            + 0.002857) as f32;
    }
    let x2 = x * x;
    let x4 = x2 * x2;
    let x6 = x4 * x2;
    -17.86 * x6 * x + 78.01 * x6 - 126.7 * x4 * x + 92.06 * x4 - 28.72 * x2 * x + 4.361 * x2
        - 0.1718 * x
        + 0.002857
}

/// Filament `AgxToneMapper::operator()` (linear Rec.2020 in and out): max(0); `AgXInsetMatrix`;
/// max(v, 1e-10); log2; (v - min_ev) / (max_ev - min_ev); clamp [0, 1]; the 7th-order curve;
/// `agxLook` (luma = dot(v, (0.2126, 0.7152, 0.0722)) BEFORE the CDL, v = pow(v slope, power),
/// luma + sat (v - luma)); `AgXOutsetMatrix = inverse(AgXOutsetMatrixInv)` (a `constexpr mat3f`
/// inverse, computed here in f32); pow(max(0, v), 2.2). No clamp.
///
/// Source: google/filament, `filament/src/ToneMapper.cpp`, commit
/// 0916f5bbbdeb3bfa553ce6ad2276652e570d4712 (a later revision with NEON paths has the same
/// scalar code).
pub fn filament_agx(c: Rgb, look: FilamentAgxLook) -> Rgb {
    let outset = inverse(&AGX_OUTSET_INV_REC2020);
    let v = map(c, |x| 0f32.max(x));
    let v = mul(&AGX_INSET_REC2020, v);
    let v = map(v, |x| {
        let l = x.max(1e-10).log2();
        let e = ((l - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV)).clamp(0.0, 1.0);
        filament_agx_contrast(e)
    });
    let v = match look {
        FilamentAgxLook::None => v,
        FilamentAgxLook::Golden => cdl_look(v, [1.0, 0.9, 0.5], 0.8, 1.3),
        FilamentAgxLook::Punchy => cdl_look(v, [1.0; 3], 1.35, 1.4),
    };
    let v = mul(&outset, v);
    map(v, |x| 0f32.max(x).powf(2.2))
}

/// The ASC CDL look of Wrensch 2023 and Filament: luma of the input, then pow(v slope + 0,
/// power), then luma + sat (v - luma). `powf` of a negative base is NaN (GLSL: undefined).
fn cdl_look(v: Rgb, slope: Rgb, power: f32, sat: f32) -> Rgb {
    let luma = dot(v, [0.2126, 0.7152, 0.0722]);
    let g = [
        (v[0] * slope[0] + 0.0).powf(power),
        (v[1] * slope[1] + 0.0).powf(power),
        (v[2] * slope[2] + 0.0).powf(power),
    ];
    map(g, |x| luma + sat * (x - luma))
}

/// Filament `GenericToneMapper(contrast, midGrayIn, midGrayOut, hdrMax)`: x^contrast
/// outputScale / (x^contrast + inputScale) per channel, with a = midGrayIn^contrast,
/// b = hdrMax^contrast, c = a - midGrayOut b, inputScale = a b (midGrayOut - 1) / c,
/// outputScale = midGrayOut (a - b) / c, after Filament's parameter clamps (contrast >= 1e-5,
/// mid greys in [1e-5, 1], hdrMax >= 1). No output clamp (it exceeds 1 above hdrMax).
/// Defaults (`ToneMapper.h`): 1.55, 0.18, 0.215, 10.
///
/// Source: `filament/src/ToneMapper.cpp` at 0916f5bb, `GenericToneMapper::Options`.
pub fn filament_generic(c: Rgb, contrast: f32, mid_in: f32, mid_out: f32, hdr_max: f32) -> Rgb {
    let contrast = contrast.max(1e-5);
    let mid_in = mid_in.clamp(1e-5, 1.0);
    let mid_out = mid_out.clamp(1e-5, 1.0);
    let hdr_max = hdr_max.max(1.0);
    let a = mid_in.powf(contrast);
    let b = hdr_max.powf(contrast);
    let cc = a - mid_out * b;
    let input_scale = (a * b * (mid_out - 1.0)) / cc;
    let output_scale = mid_out * (a - b) / cc;
    map(c, |x| {
        let x = x.powf(contrast);
        output_scale * x / (x + input_scale)
    })
}

// ------------------------------------------------------------------------------------------
// bevy
// ------------------------------------------------------------------------------------------

/// bevy `tonemapping_reinhard`: c / (1 + c) per channel, no clamp.
///
/// Source: bevyengine/bevy, `crates/bevy_core_pipeline/src/tonemapping.wesl`, at mirror HEAD
/// 4805ca792c3e94eef07afd6fa9a2712f388c9a67 (file last changed in
/// b70463f072a3380ebb37c8803f1c4941357e64fa; bevy 0.20.0-dev). bevy's `tone_mapping` first
/// takes max(c, 0) and multiplies by 2^`ColorGrading::exposure`; the camera's exposure
/// (`Exposure::exposure()` = exp2(-ev100) / 1.2, `crates/bevy_camera/src/camera.rs`) scales the
/// lighting in the PBR shader before that. bevy's AgX, TonyMcMapface and BlenderFilmic sample
/// 3D LUTs (not transcribed).
pub fn bevy_reinhard(c: Rgb) -> Rgb {
    map(c, |x| x / (1.0 + x))
}

/// bevy `tonemapping_reinhard_luminance`: l_old = dot(c, (0.2126, 0.7152, 0.0722)),
/// l_new = l_old / (1 + l_old), c (l_new / l_old). Black gives 0 / 0 (NaN in IEEE; WGSL leaves
/// it indeterminate). Source: as [`bevy_reinhard`].
pub fn bevy_reinhard_luminance(c: Rgb) -> Rgb {
    let l_old = dot(c, [0.2126, 0.7152, 0.0722]);
    let l_new = l_old / (1.0 + l_old);
    let s = l_new / l_old;
    map(c, |x| x * s)
}

/// bevy `ACESFitted` (Stephen Hill's fit, "same base implementation that Godot 4.0 uses"):
/// `color *= rgb_to_rrt` with WGSL `mat3x3(vec3 columns)`: a row vector times the matrix, so
/// out_i = dot(c, column_i), and the columns are written as Hill's rows; `RRTAndODTFit`;
/// `*= odt_to_rgb` likewise; saturate. Source: as [`bevy_reinhard`].
pub fn bevy_aces_fitted(c: Rgb) -> Rgb {
    // Each row here is a `vec3` of bevy's source, which is a column of the WGSL matrix;
    // `v * M` dots v with it.
    const RGB_TO_RRT: M3 = rows([
        0.59719, 0.35458, 0.04823, //
        0.07600, 0.90834, 0.01566, //
        0.02840, 0.13383, 0.83777,
    ]);
    const ODT_TO_RGB: M3 = rows([
        1.60475, -0.53108, -0.07367, //
        -0.10208, 1.10813, -0.00605, //
        -0.00327, -0.07276, 1.07602,
    ]);
    let v = [
        dot(c, RGB_TO_RRT[0]),
        dot(c, RGB_TO_RRT[1]),
        dot(c, RGB_TO_RRT[2]),
    ];
    let v = map(v, threejs_rrt_and_odt_fit);
    let v = [
        dot(v, ODT_TO_RGB[0]),
        dot(v, ODT_TO_RGB[1]),
        dot(v, ODT_TO_RGB[2]),
    ];
    saturate3(v)
}

/// bevy `tonemapping_pbr_neutral` (Khronos PBR Neutral, mixing toward new_max_channel), no
/// clamp. Source: as [`bevy_reinhard`].
pub fn bevy_pbr_neutral(c: Rgb) -> Rgb {
    khronos_neutral_body(c, true)
}

/// bevy's camera `Exposure::exposure()`: exp2(-ev100) / 1.2 (f32). Source: bevyengine/bevy,
/// `crates/bevy_camera/src/camera.rs` at mirror HEAD 4805ca79.
pub fn bevy_camera_exposure(ev100: f32) -> f32 {
    (-ev100).exp2() / 1.2
}

// ------------------------------------------------------------------------------------------
// Authors' reference code
// ------------------------------------------------------------------------------------------

/// Wrensch's looks ("Minimal AgX Implementation", `agxLook`): golden slope (1, 0.9, 0.5),
/// power 0.8, sat 0.8; punchy power 1.35, sat 1.4.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WrenschLook {
    /// No look.
    Default,
    /// slope (1, 0.9, 0.5), power 0.8, sat 0.8.
    Golden,
    /// power 1.35, sat 1.4.
    Punchy,
}

/// Wrensch 2023, "Minimal AgX Implementation" (iolite-engine.com blog; Shadertoy cd3XWr):
/// `agx` (Rec.709 inset `agx_mat`, log2, clamp to [min_ev, max_ev], normalise, 6th-order
/// curve), `agxLook` (luma before the CDL), `agxEotf` (`agx_mat_inv`, pow(v, 2.2) with NO
/// max(0)). Linear sRGB in and out, no clamp.
///
/// Text: `agx()` and `agxEotf()` as three.js quotes them verbatim at commit
/// 0ac1f6ab583e183ba7ed865b092b033be85dc790 (`tonemapping_pars_fragment.glsl.js`, with the
/// blog's and Shadertoy's URLs); `agxLook()` as public copies of the Shadertoy quote it (golden
/// sat 0.8, which Filament changed to 1.3). Where Wrensch's `pow` gets a negative base (the
/// curve is -0.00232 at the bottom, so black and inputs below about 2e-4 reach it) the result
/// is NaN here, undefined in GLSL.
pub fn wrensch_agx(c: Rgb, look: WrenschLook) -> Rgb {
    const AGX_MAT: M3 = cols([
        0.842_479_062_253_094,
        0.042_328_242_261_012_3,
        0.042_375_654_905_705_1,
        0.078_433_599_999_999_2,
        0.878_468_636_469_772,
        0.078_433_6,
        0.079_223_745_147_764_3,
        0.079_166_127_460_543_4,
        0.879_142_973_793_104,
    ]);
    const AGX_MAT_INV: M3 = cols([
        1.196_879_005_120_17,
        -0.052_896_851_757_456_2,
        -0.052_971_635_514_443_8,
        -0.098_020_881_140_136_8,
        1.151_903_129_904_17,
        -0.098_043_450_117_124_1,
        -0.099_029_744_079_720_5,
        -0.098_961_176_844_843_3,
        1.151_073_672_641_16,
    ]);
    let v = mul(&AGX_MAT, c);
    let v = map(v, |x| {
        let l = x.log2().clamp(AGX_MIN_EV, AGX_MAX_EV);
        agx_contrast_6th((l - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV))
    });
    let v = match look {
        WrenschLook::Default => v,
        WrenschLook::Golden => cdl_look(v, [1.0, 0.9, 0.5], 0.8, 0.8),
        WrenschLook::Punchy => cdl_look(v, [1.0; 3], 1.35, 1.4),
    };
    let v = mul(&AGX_MAT_INV, v);
    map(v, |x| x.powf(2.2))
}

/// Hable 2010, "Filmic Tonemapping Operators" (filmicworlds.com), the Uncharted 2 shader:
/// texColor *= 16 (the post's hard-coded exposure), ExposureBias = 2,
/// curr = U(ExposureBias texColor), whiteScale = 1 / U(W), W = 11.2, color = curr whiteScale,
/// pow(color, 1/2.2); U(x) = ((x (A x + C B) + D E) / (x (A x + B) + D F)) - E / F with
/// A..F = 0.15, 0.50, 0.10, 0.20, 0.02, 0.30. Returns the gamma-encoded value; no clamp.
pub fn hable_2010(c: Rgb) -> Rgb {
    let u = |x: f32| {
        let (a, b, cc, d, e, f) = (0.15f32, 0.50f32, 0.10f32, 0.20f32, 0.02f32, 0.30f32);
        ((x * (a * x + cc * b) + d * e) / (x * (a * x + b) + d * f)) - e / f
    };
    let w = 11.2f32;
    map(c, |x| {
        let tex = x * 16.0;
        let curr = u(2.0 * tex);
        let white_scale = 1.0 / u(w);
        (curr * white_scale).powf(1.0 / 2.2)
    })
}

/// Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (knarkowicz.wordpress.com), `ACESFilm`:
/// saturate((x (2.51 x + 0.03)) / (x (2.43 x + 0.59) + 0.14)). The post: "for the original
/// ACES curve just multiply input (x) by 0.6" (the fit is pre-exposed so 1 maps to about 0.8).
pub fn narkowicz_2015(c: Rgb) -> Rgb {
    saturate3(map(c, |x| {
        let (a, b, cc, d, e) = (2.51f32, 0.03f32, 2.43f32, 0.59f32, 0.14f32);
        (x * (a * x + b)) / (x * (cc * x + d) + e)
    }))
}

/// Khronos PBR Neutral reference (`PBR_Neutral/pbrNeutral.glsl`, KhronosGroup/ToneMapping,
/// commit f5dc101149fc5c85c0f9852fe2ba438853e8a7d1): the body of [`threejs_neutral`] without
/// the exposure. Its first commit (8b9b392972bd304c3e328ef65d75ddb015207385) mixed toward
/// (1, 1, 1) and multiplied by a `toneMappingExposure` it did not declare.
pub fn khronos_pbr_neutral(c: Rgb) -> Rgb {
    khronos_neutral_body(c, true)
}

/// Reinhard, Stark, Shirley, Ferwerda 2002, "Photographic Tone Reproduction for Digital
/// Images", eq. 3: L_d = L / (1 + L), on the (key-scaled) luminance L.
pub fn reinhard_2002_eq3(l: f32) -> f32 {
    l / (1.0 + l)
}

/// Reinhard et al. 2002, eq. 4: L_d = L (1 + L / L_white^2) / (1 + L).
pub fn reinhard_2002_eq4(l: f32, l_white: f32) -> f32 {
    l * (1.0 + l / (l_white * l_white)) / (1.0 + l)
}

/// Lottes 2016, "Advanced Techniques and Optimization of HDR Color Pipelines" (GDC), the
/// generic curve x^a / (x^(a d) b + c) with b, c solved so that midIn maps to midOut and hdrMax
/// to 1; defaults a = 1.6, d = 0.977, hdrMax = 8, midIn = 0.18, midOut = 0.267. No clamp.
///
/// Text: dmnsgn/glsl-tone-map `lottes.glsl`, commit 31b41d1d49c9683bfc73bed494b2a2d3d291926b
/// (the talk's formula as a shader), b and c in f32.
pub fn lottes_2016(x: f32, a: f32, d: f32, hdr_max: f32, mid_in: f32, mid_out: f32) -> f32 {
    let den = (hdr_max.powf(a * d) - mid_in.powf(a * d)) * mid_out;
    let b = (-mid_in.powf(a) + hdr_max.powf(a) * mid_out) / den;
    let c = (hdr_max.powf(a * d) * mid_in.powf(a) - hdr_max.powf(a) * mid_in.powf(a * d) * mid_out)
        / den;
    x.powf(a) / (x.powf(a * d) * b + c)
}

/// Uchimura 2017, "HDR Theory and Practice" (CEDEC), the Gran Turismo curve: toe
/// T = m (x / m)^c + b, linear L = m + a (x - m), shoulder S = P - (P - S1) exp(CP (x - S0)),
/// blended by w0 = 1 - smoothstep(0, m, x), w2 = step(m + l0, x), w1 = 1 - w0 - w2, with
/// l0 = (P - m) l / a, S0 = m + l0, S1 = m + a l0, C2 = a P / (P - S1), CP = -C2 / P. Defaults
/// P = 1, a = 1, m = 0.22, l = 0.4, c = 1.33, b = 0. No clamp.
///
/// Text: dmnsgn/glsl-tone-map `uchimura.glsl`, commit
/// 31b41d1d49c9683bfc73bed494b2a2d3d291926b (the slides' curve as a shader; also Shadertoy
/// WdjSW3).
pub fn uchimura_2017(x: f32, p: f32, a: f32, m: f32, l: f32, c: f32, b: f32) -> f32 {
    let l0 = ((p - m) * l) / a;
    let s0 = m + l0;
    let s1 = m + a * l0;
    let c2 = (a * p) / (p - s1);
    let cp = -c2 / p;
    let w0 = 1.0 - smoothstep(0.0, m, x);
    let w2 = if x < m + l0 { 0.0 } else { 1.0 };
    let w1 = 1.0 - w0 - w2;
    let t = m * (x / m).powf(c) + b;
    let s = p - (p - s1) * (cp * (x - s0)).exp();
    let lin = m + a * (x - m);
    t * w0 + lin * w1 + s * w2
}
