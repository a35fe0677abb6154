// brdf: tonemapping curves and display transfer functions, the twins of the Rust modules
// `tonemap` (sanitize, Reinhard and its extended, luminance and Jodie forms, Narkowicz's ACES
// fit) and `color` (sRGB and Rec.709 transfer, gamma, luminance). Needs common.wgsl. The Rust
// transfer functions are correctly rounded through f64; these round each operation, and `pow`
// carries the accuracy WGSL gives exp2(y log2(x)). Also the exposure curve, Hill's ACES fit,
// Khronos PBR Neutral, Hable's, Lottes' and Uchimura's curves from their parameters, AgX
// (minimal, three.js's, Filament's, with the looks), the operator table `Operator::apply`, and
// color::mul, a colour matrix times a colour.

// tonemap::MAX_INPUT: HDR input is clamped to [0, 1e9].
const BRDF_TONEMAP_MAX_INPUT: f32 = 1e9;
// color::SRGB_OETF_BREAK and SRGB_EOTF_BREAK (IEC 61966-2-1).
const BRDF_SRGB_OETF_BREAK: f32 = 0.0031308;
const BRDF_SRGB_EOTF_BREAK: f32 = 0.04045;

// An HDR input clamped to [0, MAX_INPUT] (negative -> 0).
fn tonemap_sanitize(x: f32) -> f32 {
    return clamp(x, 0.0, BRDF_TONEMAP_MAX_INPUT);
}

// Reinhard's curve c / (1 + c) (Reinhard et al. 2002, "Photographic Tone Reproduction for
// Digital Images", eq. 3).
fn tonemap_reinhard(c: f32) -> f32 {
    let x = tonemap_sanitize(c);
    return saturate(x / (1.0 + x));
}

// Reinhard's extended curve c (1 + c / w^2) / (1 + c) with white point w (Reinhard et al. 2002,
// eq. 4), c / w^2 formed as (c / w) / w so that w^2 cannot overflow.
fn tonemap_reinhard_extended(c: f32, white: f32) -> f32 {
    let x = tonemap_sanitize(c);
    let num = 1.0 + x / white / white;
    return saturate(x * num / (1.0 + x));
}

// Narkowicz's fit of the ACES filmic curve, x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14)
// (Narkowicz 2015, "ACES Filmic Tone Mapping Curve"), clamped to [0, 1].
fn tonemap_aces_narkowicz(c: f32) -> f32 {
    let x = tonemap_sanitize(c);
    let num = fma(2.51, x, 0.03) * x;
    let den = fma(fma(2.43, x, 0.59), x, 0.14);
    return saturate(num / den);
}

// 1 + L for the sanitized channels, L = 0.2126 r + 0.7152 g + 0.0722 b summed in that order
// (tonemap's luminance_dw).
fn brdf_tonemap_one_plus_luminance(r: f32, g: f32, b: f32) -> f32 {
    return 0.2126 * r + 0.7152 * g + 0.0722 * b + 1.0;
}

// Reinhard on luminance, each channel c / (1 + L) (Reinhard et al. 2002, eq. 3 applied with
// the luminance), clamped to [0, 1].
fn tonemap_reinhard_luminance(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    let r = tonemap_sanitize(c_r);
    let g = tonemap_sanitize(c_g);
    let b = tonemap_sanitize(c_b);
    let d = brdf_tonemap_one_plus_luminance(r, g, b);
    return vec3<f32>(saturate(r / d), saturate(g / d), saturate(b / d));
}

// Extended Reinhard on luminance, each channel c (1 + L / w^2) / (1 + L) (Reinhard et al.
// 2002, eq. 4), L / w^2 as (L / w) / w and capped at the largest finite f32.
fn tonemap_reinhard_extended_luminance(c_r: f32, c_g: f32, c_b: f32, white: f32) -> vec3<f32> {
    let r = tonemap_sanitize(c_r);
    let g = tonemap_sanitize(c_g);
    let b = tonemap_sanitize(c_b);
    let l = color_luminance(r, g, b);
    let num = min(1.0 + l / white / white, BRDF_F32_MAX);
    let den = 1.0 + l;
    return vec3<f32>(saturate(r * num / den), saturate(g * num / den), saturate(b * num / den));
}

// One channel of Reinhard-Jodie: c (c d + 1 + c) / (d (1 + c)^2), the blend of per-channel
// and luminance Reinhard by the per-channel curve, d = 1 + L.
fn brdf_tonemap_jodie(x: f32, d: f32) -> f32 {
    let x1 = 1.0 + x;
    return saturate(x * fma(x, d, x1) / (d * (x1 * x1)));
}

// Reinhard-Jodie: per-channel Reinhard blended toward luminance Reinhard by the per-channel
// result, lerp(c / (1 + L), c / (1 + c), c / (1 + c)) (user Jodie on Shadertoy, 2019; both
// parts from Reinhard et al. 2002), as one fraction of positive terms, clamped to [0, 1].
fn tonemap_reinhard_jodie(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    let r = tonemap_sanitize(c_r);
    let g = tonemap_sanitize(c_g);
    let b = tonemap_sanitize(c_b);
    let d = brdf_tonemap_one_plus_luminance(r, g, b);
    return vec3<f32>(brdf_tonemap_jodie(r, d), brdf_tonemap_jodie(g, d), brdf_tonemap_jodie(b, d));
}

// Rec. 709 luminance 0.2126 r + 0.7152 g + 0.0722 b (ITU-R BT.709-6, item 3.2), in the Rust
// kernel's order (blue's product first).
fn color_luminance(c_r: f32, c_g: f32, c_b: f32) -> f32 {
    return fma(c_r, 0.2126, fma(c_g, 0.7152, c_b * 0.0722));
}

// The sRGB encoding (IEC 61966-2-1): 12.92 x up to 0.0031308, 1.055 x^(1/2.4) - 0.055 above;
// negative input counts as 0.
fn color_srgb_oetf(x: f32) -> f32 {
    let v = max(x, 0.0);
    let curve = fma(1.055, pow(v, 1.0 / 2.4), -0.055);
    return select(curve, v * 12.92, v <= BRDF_SRGB_OETF_BREAK);
}

// The same curve as the Rust `srgb_oetf_fast` evaluates it (one pow, no refinement); the
// WGSL forms of the two are the same.
fn color_srgb_oetf_fast(x: f32) -> f32 {
    return color_srgb_oetf(x);
}

// The sRGB decoding (IEC 61966-2-1): x / 12.92 up to 0.04045, ((x + 0.055) / 1.055)^2.4 above;
// negative input counts as 0; capped at the largest finite f32.
fn color_srgb_eotf(x: f32) -> f32 {
    let v = max(x, 0.0);
    let curve = pow((v + 0.055) / 1.055, 2.4);
    return min(select(curve, v / 12.92, v <= BRDF_SRGB_EOTF_BREAK), BRDF_F32_MAX);
}

// The Rec. 709 encoding (ITU-R BT.709-6, item 1.2): 4.5 L up to 0.018,
// 1.099 L^0.45 - 0.099 above; negative input counts as 0.
fn color_rec709_oetf(l: f32) -> f32 {
    let v = max(l, 0.0);
    return select(fma(1.099, pow(v, 0.45), -0.099), 4.5 * v, v <= 0.018);
}

// A pure power encoding x^(1 / gamma) (negative x counts as 0), capped at the largest finite
// f32. 0 is selected explicitly: WGSL's pow(0, y) (exp2(y log2(0))) has no accuracy.
fn color_gamma_encode(x: f32, gamma: f32) -> f32 {
    let v = max(x, 0.0);
    return min(select(pow(v, 1.0 / gamma), 0.0, v == 0.0), BRDF_F32_MAX);
}

// A pure power decoding x^gamma (negative x counts as 0), capped at the largest finite f32;
// 0 selected explicitly as in color_gamma_encode.
fn color_gamma_decode(x: f32, gamma: f32) -> f32 {
    let v = max(x, 0.0);
    return min(select(pow(v, gamma), 0.0, v == 0.0), BRDF_F32_MAX);
}

// color_srgb_oetf per channel.
fn color_srgb_oetf_rgb(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    return vec3<f32>(color_srgb_oetf(c_r), color_srgb_oetf(c_g), color_srgb_oetf(c_b));
}

// color_srgb_eotf per channel.
fn color_srgb_eotf_rgb(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    return vec3<f32>(color_srgb_eotf(c_r), color_srgb_eotf(c_g), color_srgb_eotf(c_b));
}

// The exposure curve 1 - exp(-c exposure), exposure in (0, MAX]. 1 - exp(-y) cancels for small
// y: below y = 1/4 it is the Taylor series y (1 - y/2 (1 - y/3 (1 - ... (1 - y/7)))) (terms
// beyond y^7 are below 1.5e-9 of it there), above it the difference loses at most 2 bits.
// exp's argument is capped at 104, where exp(-y) is 0 in f32.
fn tonemap_exposure_curve(c: f32, exposure: f32) -> f32 {
    let y = tonemap_sanitize(c) * exposure;
    let s6 = 1.0 - y * 0.14285714285714285;
    let s5 = 1.0 - y * 0.16666666666666666 * s6;
    let s4 = 1.0 - y * 0.2 * s5;
    let s3 = 1.0 - y * 0.25 * s4;
    let s2 = 1.0 - y * 0.3333333333333333 * s3;
    let series = y * (1.0 - y * 0.5 * s2);
    return saturate(select(1.0 - exp(-min(y, 104.0)), series, y < 0.25));
}

// Hill's fit of the ACES RRT and sRGB ODT's tone curve, (v (v + 0.0245786) - 0.000090537) /
// (v (0.983729 v + 0.432951) + 0.238081).
fn brdf_aces_hill_fit(v: f32) -> f32 {
    return (v * (v + 0.0245786) - 0.000090537) / (v * fma(0.983729, v, 0.432951) + 0.238081);
}

// Stephen Hill's ACES fit (ACESFitted.hlsl, 2016, from the BakingLab project): the input
// matrix (sRGB to the RRT's space, with its saturation), the rational tone curve per channel,
// the output matrix (back to sRGB), clamped to [0, 1].
fn tonemap_aces_hill(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    let r = tonemap_sanitize(c_r);
    let g = tonemap_sanitize(c_g);
    let b = tonemap_sanitize(c_b);
    let v0 = brdf_aces_hill_fit(0.59719 * r + 0.35458 * g + 0.04823 * b);
    let v1 = brdf_aces_hill_fit(0.07600 * r + 0.90834 * g + 0.01566 * b);
    let v2 = brdf_aces_hill_fit(0.02840 * r + 0.13383 * g + 0.83777 * b);
    return vec3<f32>(
        saturate(1.60475 * v0 - 0.53108 * v1 - 0.07367 * v2),
        saturate(-0.10208 * v0 + 1.10813 * v1 - 0.00605 * v2),
        saturate(-0.00327 * v0 - 0.07276 * v1 + 1.07602 * v2),
    );
}

// Khronos PBR Neutral (Khronos Group 2024, "PBR Neutral Specification"): the offset
// x - 6.25 x^2 below x = min(r, g, b) = 0.08, else 0.04, subtracted from each channel; above
// the peak p = max(channel) = 0.76 the channels compressed towards the new peak
// 1 - 0.0576 / (p - 0.52). Written as the Rust kernel does, without the mix's cancellation:
// with e = p - 0.76, t = e + 0.24 and h = 0.15 e^2 / t (= desaturation (p - new peak)), each
// channel is (c + h p) new_peak / (p (1 + h)). Clamped to [0, 1].
fn tonemap_pbr_neutral(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    let c = vec3<f32>(tonemap_sanitize(c_r), tonemap_sanitize(c_g), tonemap_sanitize(c_b));
    let x = min(min(c.x, c.y), c.z);
    let low = x < 0.08;
    let x2 = 6.25 * (x * x);
    let cx = select(c.x - 0.04, c.x - x + x2, low);
    let cy = select(c.y - 0.04, c.y - x + x2, low);
    let cz = select(c.z - 0.04, c.z - x + x2, low);
    let peak = max(max(cx, cy), cz);
    let e = peak - 0.76;
    let t = e + 0.24;
    let new_peak = 1.0 - 0.0576 / t;
    let h = 0.15 * (e * e / t);
    let factor = new_peak / (peak * (h + 1.0));
    let hp = h * peak;
    let compress = e >= 0.0;
    return vec3<f32>(
        saturate(select(cx, (cx + hp) * factor, compress)),
        saturate(select(cy, (cy + hp) * factor, compress)),
        saturate(select(cz, (cz + hp) * factor, compress)),
    );
}

// Hable's filmic curve F(x) = ((x (A x + C B) + D E) / (x (A x + B) + D F)) - E / F with the
// constant folded in: F(x) = x (P x + Q) / ((R x + S) x + T), P = (F - E) A, Q = B (F C - E),
// R = F A, S = F B, T = D F^2 (no cancellation in x).
fn brdf_hable_curve(y: f32, p: f32, q: f32, r: f32, s: f32, t: f32) -> f32 {
    return y * fma(p, y, q) / fma(fma(r, y, s), y, t);
}

// Hable's filmic curve (Hable 2010, "Filmic Tonemapping Operators", Uncharted 2) on the
// parameters of tonemap::HableParams: F(bias c) / F(white), clamped to [0, 1].
fn tonemap_hable(
    c: f32, p_a: f32, p_b: f32, p_c: f32, p_d: f32, p_e: f32, p_f: f32, p_white: f32,
    p_exposure_bias: f32,
) -> f32 {
    let p = (p_f - p_e) * p_a;
    let q = p_b * (p_f * p_c - p_e);
    let r = p_f * p_a;
    let s = p_f * p_b;
    let t = p_d * p_f * p_f;
    let k = brdf_hable_curve(p_white, p, q, r, s, t);
    let y = p_exposure_bias * tonemap_sanitize(c);
    return saturate(brdf_hable_curve(y, p, q, r, s, t) / k);
}

// x^y for x >= 0 with 0 selected explicitly (WGSL's pow(0, y), exp2(y log2(0)), has no
// accuracy).
fn brdf_pow0(x: f32, y: f32) -> f32 {
    return select(pow(x, y), 0.0, x == 0.0);
}

// Lottes' curve x^a / (x^(a d) b + c) (Lottes 2016, "Advanced Techniques and Optimization of
// HDR Color Pipelines"), b and c derived from the parameters of tonemap::LottesParams so that
// mid_in maps to mid_out and hdr_max to 1; clamped to [0, 1].
fn tonemap_lottes(
    c: f32, contrast: f32, shoulder: f32, hdr_max: f32, mid_in: f32, mid_out: f32,
) -> f32 {
    let a = contrast;
    let ad = contrast * shoulder;
    let mi_a = pow(mid_in, a);
    let mi_ad = pow(mid_in, ad);
    let hm_a = pow(hdr_max, a);
    let hm_ad = pow(hdr_max, ad);
    let den = (hm_ad - mi_ad) * mid_out;
    let b = (hm_a * mid_out - mi_a) / den;
    let cc = (hm_ad * mi_a - hm_a * mi_ad * mid_out) / den;
    let x = tonemap_sanitize(c);
    return saturate(brdf_pow0(x, a) / fma(brdf_pow0(x, ad), b, cc));
}

// Uchimura's curve (Uchimura 2017, "HDR theory and practice", the Gran Turismo Sport tone
// mapper) on the parameters of tonemap::UchimuraParams: a toe m (x / m)^black + pedestal, a
// linear section a (x - m) + m and an exponential shoulder P - (P - S1) exp(CP (x - S0)),
// blended by smoothstep(0, m, x) and the step at S0; clamped to [0, 1]. The toe is evaluated
// at min(x, m) (its weight is 0 beyond), the shoulder's exponent at 0 below S0 (its weight is
// 0 there), so neither overflows where it does not count.
fn tonemap_uchimura(
    c: f32, max_brightness: f32, contrast: f32, linear_start: f32, linear_length: f32,
    black: f32, pedestal: f32,
) -> f32 {
    let pm = max_brightness;
    let a = contrast;
    let m = linear_start;
    let l0 = (pm - m) * linear_length / a;
    let s0 = m + l0;
    let s1 = m + a * l0;
    let cp = -(a * pm / (pm - s1)) / pm;
    let x = tonemap_sanitize(c);
    let t = saturate(x / m);
    let smoothed = t * t * (3.0 - 2.0 * t);
    let w0 = 1.0 - smoothed;
    let past_s0 = x >= s0;
    let w2 = select(0.0, 1.0, past_s0);
    let w1 = smoothed - w2;
    let toe = m * brdf_pow0(min(x, m) / m, black) + pedestal;
    let shoulder = pm - (pm - s1) * exp(select(0.0, cp * (x - s0), past_s0));
    let linear = a * (x - m) + m;
    return saturate(toe * w0 + linear * w1 + shoulder * w2);
}

// A colour matrix (row-major m_i_j) times a colour, each row as c_r m_i0 + (c_g m_i1 + c_b m_i2)
// in the Rust kernel's order.
fn color_mul(
    m_0_0: f32, m_0_1: f32, m_0_2: f32, m_1_0: f32, m_1_1: f32, m_1_2: f32,
    m_2_0: f32, m_2_1: f32, m_2_2: f32, c_r: f32, c_g: f32, c_b: f32,
) -> vec3<f32> {
    return vec3<f32>(
        fma(c_r, m_0_0, fma(c_g, m_0_1, c_b * m_0_2)),
        fma(c_r, m_1_0, fma(c_g, m_1_1, c_b * m_1_2)),
        fma(c_r, m_2_0, fma(c_g, m_2_1, c_b * m_2_2)),
    );
}

// AgX (Sobotka 2022, "AgX"; the minimal form of Wrensch 2023, "Minimal AgX implementation";
// three.js r162's AgXToneMapping; Filament's AgxToneMapper): an inset matrix, the log2
// encoding of each channel over [MIN_EV, MAX_EV] = [-12.47393, 4.026069], a polynomial
// sigmoid in x - 1/2, a look (slope, power, saturation about the Rec. 709 luminance), the
// outset matrix and the power 2.2, clamped to [0, 1]. The matrices as the Rust module
// `tonemap` (and `color`) holds them, rounded to f32; each row r.v as r0 v0 + (r1 v1 + r2 v2)
// in the Rust order.

// r0 v.x + (r1 v.y + r2 v.z).
fn brdf_agx_row(r0: f32, r1: f32, r2: f32, v: vec3<f32>) -> f32 {
    return fma(r0, v.x, fma(r1, v.y, r2 * v.z));
}

// AgX's inset on Rec. 709 (color::AGX_INSET).
fn brdf_agx_inset(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(0.842479062253094, 0.0784335999999992, 0.0792237451477643, v),
        brdf_agx_row(0.0423282422610123, 0.878468636469772, 0.0791661274605434, v),
        brdf_agx_row(0.0423756549057051, 0.0784336, 0.879142973793104, v),
    );
}

// AgX's outset on Rec. 709 (color::AGX_OUTSET).
fn brdf_agx_outset(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(1.19687900512017, -0.0980208811401368, -0.0990297440797205, v),
        brdf_agx_row(-0.0528968517574562, 1.15190312990417, -0.0989611768448433, v),
        brdf_agx_row(-0.0529716355144438, -0.0980434501171241, 1.15107367264116, v),
    );
}

// AgX's inset on Rec. 2020 (color::AGX_INSET_REC2020).
fn brdf_agx_inset_rec2020(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(0.856627153315983, 0.0951212405381588, 0.0482516061458583, v),
        brdf_agx_row(0.137318972929847, 0.761241990602591, 0.101439036467562, v),
        brdf_agx_row(0.11189821299995, 0.0767994186031903, 0.811302368396859, v),
    );
}

// AgX's outset on Rec. 2020 (color::AGX_OUTSET_REC2020).
fn brdf_agx_outset_rec2020(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(1.1271005818144366, -0.11060664309660322, -0.01649393871783457, v),
        brdf_agx_row(-0.14132976349843826, 1.1578237022162718, -0.016493938717834253, v),
        brdf_agx_row(-0.14132976349843826, -0.11060664309660292, 1.2519364065950402, v),
    );
}

// Rec. 709 to Rec. 2020 primaries (color::REC709_TO_REC2020).
fn brdf_agx_rec709_to_rec2020(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(0.627403895934699, 0.3292830383778837, 0.043313065687417225, v),
        brdf_agx_row(0.06909728935823208, 0.9195403950754587, 0.011362315566309178, v),
        brdf_agx_row(0.01639143887515028, 0.08801330787722575, 0.895595253247624, v),
    );
}

// Rec. 2020 to Rec. 709 primaries (color::REC2020_TO_REC709).
fn brdf_agx_rec2020_to_rec709(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(1.6604910021084345, -0.5876411387885495, -0.07284986331988488, v),
        brdf_agx_row(-0.12455047452159074, 1.1328998971259603, -0.008349422604369477, v),
        brdf_agx_row(-0.018150763354905303, -0.10057889800800739, 1.1187296613629127, v),
    );
}

// three.js's sRGB to Rec. 2020 (four decimals, as three.js writes it).
fn brdf_agx_threejs_srgb_to_rec2020(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(0.6274, 0.3293, 0.0433, v),
        brdf_agx_row(0.0691, 0.9195, 0.0113, v),
        brdf_agx_row(0.0164, 0.088, 0.8956, v),
    );
}

// three.js's Rec. 2020 to sRGB (four decimals).
fn brdf_agx_threejs_rec2020_to_srgb(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(1.6605, -0.5876, -0.0728, v),
        brdf_agx_row(-0.1246, 1.1329, -0.0083, v),
        brdf_agx_row(-0.0182, -0.1006, 1.1187, v),
    );
}

// three.js's AgX outset (its inverse of the inset, as three.js computes it).
fn brdf_agx_threejs_outset(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_agx_row(1.1271005818144368, -0.11060664309660323, -0.016493938717834573, v),
        brdf_agx_row(-0.1413297634984383, 1.157823702216272, -0.016493938717834257, v),
        brdf_agx_row(-0.14132976349843826, -0.11060664309660294, 1.2519364065950405, v),
    );
}

// The log2 encoding (log2(max(v, 2^-126)) clamped to [MIN_EV, MAX_EV] - MIN_EV) / (MAX_EV -
// MIN_EV).
fn brdf_agx_encode(v: f32) -> f32 {
    let ev = log2(max(v, 1.17549435e-38));
    return (clamp(ev, -12.47393, 4.026069) + 12.47393) / 16.499999;
}

// Wrensch's sigmoid: 15.5 t^6 + 6.36 t^5 - 10.265 t^4 - 4.548 t^3 + 2.42405 t^2 + 1.7404 t
// + 0.2914925 in t = x - 1/2 (Horner).
fn brdf_agx_curve_wrensch(x: f32) -> f32 {
    let t = x - 0.5;
    let h5 = fma(15.5, t, 6.36);
    let h4 = fma(h5, t, -10.265);
    let h3 = fma(h4, t, -4.548);
    let h2 = fma(h3, t, 2.42405);
    let h1 = fma(h2, t, 1.7404);
    return fma(h1, t, 0.2914925);
}

// Filament's sigmoid: the degree-7 polynomial of its AgxToneMapper in t = x - 1/2.
fn brdf_agx_curve_filament(x: f32) -> f32 {
    let t = x - 0.5;
    let h6 = fma(-17.86, t, 15.5);
    let h5 = fma(h6, t, 13.565);
    let h4 = fma(h5, t, -10.29);
    let h3 = fma(h4, t, -5.39375);
    let h2 = fma(h3, t, 2.40975);
    let h1 = fma(h2, t, 1.7588875);
    return fma(h1, t, 0.290957);
}

// The encoding and the sigmoid per channel; `filament` picks Filament's polynomial.
fn brdf_agx_sigmoid(v: vec3<f32>, filament: bool) -> vec3<f32> {
    let e = vec3<f32>(brdf_agx_encode(v.x), brdf_agx_encode(v.y), brdf_agx_encode(v.z));
    let w = vec3<f32>(brdf_agx_curve_wrensch(e.x), brdf_agx_curve_wrensch(e.y),
        brdf_agx_curve_wrensch(e.z));
    let f = vec3<f32>(brdf_agx_curve_filament(e.x), brdf_agx_curve_filament(e.y),
        brdf_agx_curve_filament(e.z));
    return select(w, f, filament);
}

// One channel of a look: saturation (max(v slope, 0)^power - luma) + luma.
fn brdf_agx_look_channel(v: f32, slope: f32, power: f32, saturation: f32, luma: f32) -> f32 {
    return fma(saturation, brdf_pow0(max(v * slope, 0.0), power) - luma, luma);
}

// The look of choice `look` (tonemap::AgxLook): 0 = BASE (the identity), 1 = PUNCHY (power
// 1.35, saturation 1.4), 2 = GOLDEN (slope (1, 0.9, 0.5), power 0.8, saturation 0.8), 3 =
// GOLDEN_FILAMENT (GOLDEN with saturation 1.3); luma with Rec. 709's weights.
fn brdf_agx_look(v: vec3<f32>, look: u32) -> vec3<f32> {
    let golden = look >= 2u;
    let sy = select(1.0, 0.9, golden);
    let sz = select(1.0, 0.5, golden);
    let power = select(1.35, 0.8, golden);
    let saturation = select(select(0.8, 1.3, look == 3u), 1.4, look == 1u);
    let luma = fma(0.2126, v.x, fma(0.7152, v.y, 0.0722 * v.z));
    let graded = vec3<f32>(brdf_agx_look_channel(v.x, 1.0, power, saturation, luma),
        brdf_agx_look_channel(v.y, sy, power, saturation, luma),
        brdf_agx_look_channel(v.z, sz, power, saturation, luma));
    return select(graded, v, look == 0u);
}

// max(x, 0)^2.2 per channel (0 selected at 0).
fn brdf_agx_gamma(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(brdf_pow0(max(v.x, 0.0), 2.2), brdf_pow0(max(v.y, 0.0), 2.2),
        brdf_pow0(max(v.z, 0.0), 2.2));
}

// Each component clamped to [0, 1].
fn brdf_saturate3(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(saturate(v.x), saturate(v.y), saturate(v.z));
}

// The sanitized input.
fn brdf_tonemap_sanitize3(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    return vec3<f32>(tonemap_sanitize(c_r), tonemap_sanitize(c_g), tonemap_sanitize(c_b));
}

// Minimal AgX on Rec. 709 (Wrensch 2023) with a look (0 = BASE, 1 = PUNCHY, 2 = GOLDEN,
// 3 = GOLDEN_FILAMENT), clamped to [0, 1].
fn tonemap_agx_minimal(c_r: f32, c_g: f32, c_b: f32, look: u32) -> vec3<f32> {
    let v = brdf_agx_sigmoid(brdf_agx_inset(brdf_tonemap_sanitize3(c_r, c_g, c_b)), false);
    return brdf_saturate3(brdf_agx_gamma(brdf_agx_outset(brdf_agx_look(v, look))));
}

// three.js's AgXToneMapping (r162): sRGB to Rec. 2020 with three.js's four-decimal matrix,
// the Rec. 2020 inset, Wrensch's sigmoid, three.js's outset, the power 2.2, back to sRGB;
// clamped to [0, 1].
fn tonemap_agx_threejs(c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    let c = brdf_agx_threejs_srgb_to_rec2020(brdf_tonemap_sanitize3(c_r, c_g, c_b));
    let v = brdf_agx_sigmoid(brdf_agx_inset_rec2020(c), false);
    let out = brdf_agx_gamma(brdf_agx_threejs_outset(v));
    return brdf_saturate3(brdf_agx_threejs_rec2020_to_srgb(out));
}

// Filament's AgxToneMapper on Rec. 2020 input: the Rec. 2020 inset, Filament's sigmoid, a look,
// the Rec. 2020 outset, the power 2.2; clamped to [0, 1].
fn tonemap_agx_filament(c_r: f32, c_g: f32, c_b: f32, look: u32) -> vec3<f32> {
    let v = brdf_agx_sigmoid(brdf_agx_inset_rec2020(brdf_tonemap_sanitize3(c_r, c_g, c_b)), true);
    return brdf_saturate3(brdf_agx_gamma(brdf_agx_outset_rec2020(brdf_agx_look(v, look))));
}

// Filament's AgX on Rec. 709 input (as tonemap::Operator applies it): converted to Rec. 2020
// and back around tonemap_agx_filament's pipeline.
fn brdf_agx_filament_srgb(c: vec3<f32>, look: u32) -> vec3<f32> {
    let v = brdf_agx_sigmoid(brdf_agx_inset_rec2020(brdf_agx_rec709_to_rec2020(c)), true);
    let out = brdf_agx_gamma(brdf_agx_outset_rec2020(brdf_agx_look(v, look)));
    return brdf_saturate3(brdf_agx_rec2020_to_rec709(out));
}

// A per-channel curve's three channels.
fn brdf_tonemap_hable3(c: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        tonemap_hable(c.x, 0.15, 0.50, 0.10, 0.20, 0.02, 0.30, 11.2, 2.0),
        tonemap_hable(c.y, 0.15, 0.50, 0.10, 0.20, 0.02, 0.30, 11.2, 2.0),
        tonemap_hable(c.z, 0.15, 0.50, 0.10, 0.20, 0.02, 0.30, 11.2, 2.0),
    );
}

fn brdf_tonemap_lottes3(c: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        tonemap_lottes(c.x, 1.6, 0.977, 8.0, 0.18, 0.267),
        tonemap_lottes(c.y, 1.6, 0.977, 8.0, 0.18, 0.267),
        tonemap_lottes(c.z, 1.6, 0.977, 8.0, 0.18, 0.267),
    );
}

fn brdf_tonemap_uchimura3(c: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        tonemap_uchimura(c.x, 1.0, 1.0, 0.22, 0.4, 1.33, 0.0),
        tonemap_uchimura(c.y, 1.0, 1.0, 0.22, 0.4, 1.33, 0.0),
        tonemap_uchimura(c.z, 1.0, 1.0, 0.22, 0.4, 1.33, 0.0),
    );
}

// Every operator of tonemap::Operator::all() with its default parameters, by index: 0 the
// exposure curve (exposure 1), 1 Reinhard, 2 on luminance, 3 extended (white 4), 4 extended on
// luminance (white 4), 5 Jodie, 6 Narkowicz's ACES, 7 Hill's ACES, 8 Hable (Uncharted 2),
// 9 Lottes (his default curve), 10 Uchimura (Gran Turismo), 11 Khronos PBR Neutral, 12-14
// minimal AgX (BASE, PUNCHY, GOLDEN), 15 three.js's AgX, 16-18 Filament's AgX on Rec. 709 input
// (BASE, PUNCHY, GOLDEN_FILAMENT). Every operator is evaluated and one selected. The Rust
// kernel's argument `operator` is `operator_` here: WGSL reserves the word.
fn tonemap_Operator_apply(operator_: u32, c_r: f32, c_g: f32, c_b: f32) -> vec3<f32> {
    let c = vec3<f32>(c_r, c_g, c_b);
    let s = brdf_tonemap_sanitize3(c_r, c_g, c_b);
    let o0 = vec3<f32>(tonemap_exposure_curve(c_r, 1.0), tonemap_exposure_curve(c_g, 1.0),
        tonemap_exposure_curve(c_b, 1.0));
    let o1 = vec3<f32>(tonemap_reinhard(c_r), tonemap_reinhard(c_g), tonemap_reinhard(c_b));
    let o2 = tonemap_reinhard_luminance(c_r, c_g, c_b);
    let o3 = vec3<f32>(tonemap_reinhard_extended(c_r, 4.0), tonemap_reinhard_extended(c_g, 4.0),
        tonemap_reinhard_extended(c_b, 4.0));
    let o4 = tonemap_reinhard_extended_luminance(c_r, c_g, c_b, 4.0);
    let o5 = tonemap_reinhard_jodie(c_r, c_g, c_b);
    let o6 = vec3<f32>(tonemap_aces_narkowicz(c_r), tonemap_aces_narkowicz(c_g),
        tonemap_aces_narkowicz(c_b));
    let o7 = tonemap_aces_hill(c_r, c_g, c_b);
    let o8 = brdf_tonemap_hable3(c);
    let o9 = brdf_tonemap_lottes3(c);
    let o10 = brdf_tonemap_uchimura3(c);
    let o11 = tonemap_pbr_neutral(c_r, c_g, c_b);
    let o12 = tonemap_agx_minimal(c_r, c_g, c_b, 0u);
    let o13 = tonemap_agx_minimal(c_r, c_g, c_b, 1u);
    let o14 = tonemap_agx_minimal(c_r, c_g, c_b, 2u);
    let o15 = tonemap_agx_threejs(c_r, c_g, c_b);
    let o16 = brdf_agx_filament_srgb(s, 0u);
    let o17 = brdf_agx_filament_srgb(s, 1u);
    let o18 = brdf_agx_filament_srgb(s, 3u);
    let r1 = select(o0, o1, operator_ == 1u);
    let r2 = select(r1, o2, operator_ == 2u);
    let r3 = select(r2, o3, operator_ == 3u);
    let r4 = select(r3, o4, operator_ == 4u);
    let r5 = select(r4, o5, operator_ == 5u);
    let r6 = select(r5, o6, operator_ == 6u);
    let r7 = select(r6, o7, operator_ == 7u);
    let r8 = select(r7, o8, operator_ == 8u);
    let r9 = select(r8, o9, operator_ == 9u);
    let r10 = select(r9, o10, operator_ == 10u);
    let r11 = select(r10, o11, operator_ == 11u);
    let r12 = select(r11, o12, operator_ == 12u);
    let r13 = select(r12, o13, operator_ == 13u);
    let r14 = select(r13, o14, operator_ == 14u);
    let r15 = select(r14, o15, operator_ == 15u);
    let r16 = select(r15, o16, operator_ == 16u);
    let r17 = select(r16, o17, operator_ == 17u);
    return select(r17, o18, operator_ == 18u);
}
