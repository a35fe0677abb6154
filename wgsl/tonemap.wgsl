// brdf: tonemapping curves and display transfer functions, the twins of the Rust modules
// `tonemap` (sanitize, Reinhard and its extended, luminance and Jodie forms, Narkowicz's ACES
// fit) and `color` (sRGB and Rec.709 transfer, gamma, luminance). Needs common.wgsl. The Rust
// transfer functions are correctly rounded through f64; these round each operation, and `pow`
// carries the accuracy WGSL gives exp2(y log2(x)). Also the exposure curve, Hill's ACES fit,
// Khronos PBR Neutral, and Hable's, Lottes' and Uchimura's curves from their parameters. AgX
// and the operator table have no twin yet. Also color::mul, a colour matrix times a colour.

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
