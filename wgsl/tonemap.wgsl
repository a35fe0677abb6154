// brdf: tonemapping curves and display transfer functions, the twins of the Rust modules
// `tonemap` (sanitize, Reinhard and its extended, luminance and Jodie forms, Narkowicz's ACES
// fit) and `color` (sRGB and Rec.709 transfer, gamma, luminance). Needs common.wgsl. The Rust
// transfer functions are correctly rounded through f64; these round each operation, and `pow`
// carries the accuracy WGSL gives exp2(y log2(x)). The exposure curve, Hable, Lottes, Uchimura,
// ACES Hill, Khronos PBR Neutral and AgX have no twin yet.

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
