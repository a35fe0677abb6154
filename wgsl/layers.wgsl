// brdf: the glTF extension lobes, the twins of the Rust module `layers` (sheen, clearcoat,
// specular and IOR, anisotropy). Needs common.wgsl, ggx.wgsl and fresnel.wgsl. The sheen
// albedo table (`layers::sheen::albedo`) and the layered material have no twin here: a shader
// samples the table as a texture and composes the lobes itself.

// The smallest sheen alpha (layers::sheen::ALPHA_MIN): keeps D_charlie's exponent 1 / (2 alpha)
// at 5e3 and its peak near 1.6e3.
const BRDF_SHEEN_ALPHA_MIN: f32 = 1e-4;

// 0 unless both cosines are above the horizon (domain::above_horizon; diffuse.wgsl has its own
// copy, and no family may define a name another defines).
fn brdf_layers_above_both(n_dot_v: f32, n_dot_l: f32, value: f32) -> f32 {
    return select(0.0, value, (n_dot_v > 0.0) & (n_dot_l > 0.0));
}

// The Charlie sheen NDF (Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF",
// eq. 2): D = (2 + 1/alpha) (sin^2)^(1 / (2 alpha)) / (2 pi), sin^2 = (1 - c)(1 + c) for
// c = n_dot_h clamped to [0, 1]; alpha floored at BRDF_SHEEN_ALPHA_MIN; 0 for n_dot_h <= 0.
fn layers_sheen_d_charlie(n_dot_h: f32, alpha: f32) -> f32 {
    let inv = 1.0 / max(alpha, BRDF_SHEEN_ALPHA_MIN);
    let c = saturate(n_dot_h);
    let s2 = (1.0 - c) * (1.0 + c);
    let d = (2.0 + inv) * brdf_sheen_pow(s2, 0.5 * inv) * (0.5 * BRDF_FRAC_1_PI);
    return brdf_above(n_dot_h, d);
}

// x^y for x >= 0 and y > 0, 0 at x = 0 as the Rust kernels' pow gives: WGSL's pow is
// exp2(y log2(x)), and log2(0) leaves what the accuracy table promises.
fn brdf_sheen_pow(x: f32, y: f32) -> f32 {
    let zero = x <= 0.0;
    return select(pow(select(x, 1.0, zero), y), 0.0, zero);
}

// at_one + (at_zero - at_one) t: a coefficient of the Lambda fit between its alpha = 1 and
// alpha = 0 values.
fn brdf_sheen_mix(at_one: f32, at_zero: f32, t: f32) -> f32 {
    return at_one + (at_zero - at_one) * t;
}

// The fit's exponent L(x) = a / (1 + b x^c) + d x + e, the coefficients interpolated with
// t = (1 - alpha)^2 (Estevez and Kulla 2017, section 3, Table 1).
fn brdf_sheen_lambda_exponent(x: f32, alpha: f32) -> f32 {
    let t = (1.0 - alpha) * (1.0 - alpha);
    let a = brdf_sheen_mix(21.5473, 25.3245, t);
    let b = brdf_sheen_mix(3.82987, 3.32435, t);
    let c = brdf_sheen_mix(0.19823, 0.16801, t);
    let d = brdf_sheen_mix(-1.97760, -1.27393, t);
    let e = brdf_sheen_mix(-4.32054, -4.85967, t);
    return a / (b * brdf_sheen_pow(x, c) + 1.0) + (d * x + e);
}

// The Charlie sheen's fitted Smith Lambda: exp(L(c)) below c = 1/2, exp(2 L(1/2) - L(1 - c))
// above, c = |n_dot_v| clamped to 1 (Estevez and Kulla 2017, section 3).
fn layers_sheen_lambda_charlie(n_dot_v: f32, alpha: f32) -> f32 {
    let a = max(alpha, BRDF_SHEEN_ALPHA_MIN);
    let c = min(abs(n_dot_v), 1.0);
    let low = c < 0.5;
    let l = brdf_sheen_lambda_exponent(select(1.0 - c, c, low), a);
    let mid = brdf_sheen_lambda_exponent(0.5, a);
    return exp(select(2.0 * mid - l, l, low));
}

// The Charlie visibility 1 / ((1 + Lambda(n.v) + Lambda(n.l)) 4 n.v n.l), cosines capped at 1;
// 0 where either is <= 0; capped at the largest finite f32.
fn layers_sheen_v_charlie(n_dot_v: f32, n_dot_l: f32, alpha: f32) -> f32 {
    let cv = min(n_dot_v, 1.0);
    let cl = min(n_dot_l, 1.0);
    let g = 1.0 + layers_sheen_lambda_charlie(cv, alpha) + layers_sheen_lambda_charlie(cl, alpha);
    let above = (n_dot_v > 0.0) & (n_dot_l > 0.0);
    // Below the horizon the divisor may be 0; the value is discarded there.
    let den = select(1.0, 4.0 * cv * cl * g, above);
    return brdf_layers_above_both(n_dot_v, n_dot_l, min(1.0 / den, BRDF_F32_MAX));
}

// Neubelt and Pettineo's cloth visibility (2013, "Crafting a Next-Gen Material Pipeline for
// The Order: 1886"): 1 / (4 (n.v + n.l (1 - n.v))), cosines capped at 1; 0 where either is <= 0.
fn layers_sheen_v_neubelt(n_dot_v: f32, n_dot_l: f32) -> f32 {
    let cv = min(n_dot_v, 1.0);
    let cl = min(n_dot_l, 1.0);
    let above = (n_dot_v > 0.0) & (n_dot_l > 0.0);
    let den = select(1.0, 4.0 * (cl * (1.0 - cv) + cv), above);
    return brdf_layers_above_both(n_dot_v, n_dot_l, min(1.0 / den, BRDF_F32_MAX));
}

// Ashikhmin's velvet NDF (Ashikhmin and Premoze 2007, "Distribution-based BRDFs"):
// (1 + 4 exp(-cot^2 / alpha^2) / sin^4) / (pi (1 + 4 alpha^2)); the exponential term dropped
// where cot^2 / alpha^2 > 200 (below 1e-80 of the constant; without it 0 / 0 near n.h = 1).
fn layers_sheen_d_ashikhmin(n_dot_h: f32, alpha: f32) -> f32 {
    let a = max(alpha, BRDF_SHEEN_ALPHA_MIN);
    let a2 = a * a;
    let c = saturate(n_dot_h);
    let s2 = (1.0 - c) * (1.0 + c);
    // cot^2 / alpha^2 = c^2 / (alpha^2 sin^2), computed only where sin^2 leaves room for it.
    let keep = c * c <= 200.0 * a2 * s2;
    let safe_s2 = select(1.0, s2, keep);
    let t = (c * c) / (a2 * safe_s2);
    let term = select(0.0, 4.0 * exp(-t) / (safe_s2 * safe_s2), keep);
    let d = (1.0 + term) * BRDF_FRAC_1_PI / (4.0 * a2 + 1.0);
    return brdf_above(n_dot_h, d);
}

// The glTF sheen lobe sheenColor D_charlie V_charlie per channel (KHR_materials_sheen, "Sheen
// BRDF"), v.h unused.
fn layers_sheen_charlie(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32,
    sheen_color_r: f32, sheen_color_g: f32, sheen_color_b: f32, alpha: f32,
) -> vec3<f32> {
    let dv = min(
        layers_sheen_d_charlie(n_dot_h, alpha) * layers_sheen_v_charlie(n_dot_v, n_dot_l, alpha),
        BRDF_F32_MAX,
    );
    return vec3<f32>(sheen_color_r * dv, sheen_color_g * dv, sheen_color_b * dv);
}

// MaterialX's rational fit of the Imageworks sheen albedo (D_charlie V_neubelt), P / Q with
// P, Q quadratics in mu and alpha, clamped to [0, 1] (MaterialX, mx_microfacet_sheen.glsl,
// mx_imageworks_sheen_dir_albedo_analytic).
fn layers_sheen_albedo_fit_materialx(n_dot_v: f32, alpha: f32) -> f32 {
    let mu = saturate(n_dot_v);
    let a = alpha;
    let p = 13.67300 + -68.78018 * mu + 799.08825 * a + -905.00061 * mu * a
        + 60.28956 * mu * mu + 1086.96473 * a * a;
    let q = 1.0 + 61.57746 * mu + 442.78211 * a + 2597.49308 * mu * a
        + 121.81241 * mu * mu + 3045.55075 * a * a;
    return saturate(p / q);
}

// three.js's fit of the sheen's environment term (IBLSheenBRDF in
// lights_physical_pars_fragment.glsl.js), read as the albedo: saturate(exp(a n.v + b) + k),
// a and b quadratics in the perceptual roughness r, split at r = 1/4.
fn layers_sheen_albedo_fit_threejs(n_dot_v: f32, roughness: f32) -> f32 {
    let mu = saturate(n_dot_v);
    let r = roughness;
    let r2 = r * r;
    let smooth_ = r < 0.25;
    let a = select(-8.48 * r2 + 14.3 * r + -9.95, -339.2 * r2 + 161.4 * r + -25.9, smooth_);
    let b = select(1.97 * r2 + -3.27 * r + 0.72, 44.0 * r2 + -23.7 * r + 3.26, smooth_);
    let k = select(0.1 * (r - 0.25), 0.0, smooth_);
    return saturate(exp(a * mu + b) + k);
}

// The sheen albedo E(mu, alpha) of the glTF lobe (layers::sheen::ALBEDO_TABLE, bit for bit):
// entry 16 i + j is E at mu_j = (j + 1/2) / 16 and alpha_i = ((i + 1/2) / 16)^2, the adaptive
// cubature of D_charlie V_charlie cos rounded to f32. A shader may as well bind it as a 16 x 16
// texture with linear filtering and clamp-to-edge.
const BRDF_SHEEN_ALBEDO_TABLE: array<f32, 256> = array<f32, 256>(
    1.6336572e0f, 1.0216756e-1f, 3.6620144e-3f, 5.9458387e-5f, 3.771664e-7f, 8.1564694e-10f, 5.045271e-13f, 7.824237e-17f,
    2.9398514e-21f, 1.4597238e-26f, 5.184346e-33f, 6.2848e-41f, 0e0f, 0e0f, 0e0f, 0e0f,
    1.4023854e0f, 5.5475646e-1f, 2.2799633e-1f, 9.036512e-2f, 3.3441372e-2f, 1.1290542e-2f, 3.401858e-3f, 8.924634e-4f,
    1.9784989e-4f, 3.566953e-5f, 4.9437967e-6f, 4.847868e-7f, 2.9439468e-8f, 8.558086e-10f, 7.355044e-12f, 3.4970016e-15f,
    1.0835003e0f, 5.9697247e-1f, 3.4867945e-1f, 2.0512225e-1f, 1.1904894e-1f, 6.730542e-2f, 3.668223e-2f, 1.9070901e-2f,
    9.348924e-3f, 4.2665396e-3f, 1.7725755e-3f, 6.4904004e-4f, 1.9910524e-4f, 4.6766767e-5f, 6.9172484e-6f, 3.339754e-7f,
    9.085049e-1f, 5.786904e-1f, 3.9018586e-1f, 2.6736474e-1f, 1.8313263e-1f, 1.2420451e-1f, 8.282022e-2f, 5.394022e-2f,
    3.4096766e-2f, 2.0815693e-2f, 1.21156145e-2f, 6.6007124e-3f, 3.2741306e-3f, 1.4094089e-3f, 4.757733e-4f, 9.1335285e-5f,
    8.111899e-1f, 5.613416e-1f, 4.0971053e-1f, 3.046904e-1f, 2.2758834e-1f, 1.6939126e-1f, 1.24921724e-1f, 9.084004e-2f,
    6.487047e-2f, 4.543437e-2f, 3.0934216e-2f, 2.0220326e-2f, 1.2462671e-2f, 7.0284284e-3f, 3.4128486e-3f, 1.1995024e-3f,
    7.589488e-1f, 5.541627e-1f, 4.253719e-1f, 3.3295506e-1f, 2.6233894e-1f, 2.0659702e-1f, 1.6183731e-1f, 1.256053e-1f,
    9.631271e-2f, 7.301842e-2f, 5.436718e-2f, 3.938509e-2f, 2.7405683e-2f, 1.7947357e-2f, 1.0641514e-2f, 5.188837e-3f,
    7.355207e-1f, 5.5741405e-1f, 4.4289994e-1f, 3.5893592e-1f, 2.9315022e-1f, 2.3971805e-1f, 1.9542608e-1f, 1.5829377e-1f,
    1.2712902e-1f, 1.014364e-1f, 7.997771e-2f, 6.185107e-2f, 4.6467587e-2f, 3.3429377e-2f, 2.2456354e-2f, 1.3339513e-2f,
    7.3190665e-1f, 5.696704e-1f, 4.6393684e-1f, 3.8538298e-1f, 3.2283676e-1f, 2.710696e-1f, 2.2723609e-1f, 1.8961509e-1f,
    1.5724936e-1f, 1.2996635e-1f, 1.0657319e-1f, 8.6178586e-2f, 6.821297e-2f, 5.230635e-2f, 3.8214266e-2f, 2.5769532e-2f,
    7.424639e-1f, 5.8918387e-1f, 4.88524e-1f, 4.1316205e-1f, 3.5253683e-1f, 3.0172706e-1f, 2.5808194e-1f, 2.200211e-1f,
    1.8672994e-1f, 1.582763e-1f, 1.3347557e-1f, 1.1141897e-1f, 9.152939e-2f, 7.343767e-2f, 5.690744e-2f, 4.1786637e-2f,
    7.630696e-1f, 6.140621e-1f, 5.158962e-1f, 4.4211087e-1f, 3.823781e-1f, 3.3190516e-1f, 2.8813198e-1f, 2.4954963e-1f,
    2.1543041e-1f, 1.8602203e-1f, 1.6012965e-1f, 1.368175e-1f, 1.1549256e-1f, 9.577814e-2f, 7.7437446e-2f, 6.032602e-2f,
    7.901597e-1f, 6.422015e-1f, 5.4474837e-1f, 4.714016e-1f, 4.1181487e-1f, 3.6120883e-1f, 3.1704938e-1f, 2.7785683e-1f,
    2.4295472e-1f, 2.1272303e-1f, 1.8594825e-1f, 1.6166702e-1f, 1.3927054e-1f, 1.1837479e-1f, 9.874261e-2f, 8.023838e-2f,
    8.2018477e-1f, 6.7119884e-1f, 5.733378e-1f, 4.997199e-1f, 4.3982068e-1f, 3.8880348e-1f, 3.4412104e-1f, 3.0429748e-1f,
    2.6868424e-1f, 2.3775567e-1f, 2.1027714e-1f, 1.852611e-1f, 1.620861e-1f, 1.4036337e-1f, 1.19857624e-1f, 1.0044463e-1f,
    8.493076e-1f, 6.983017e-1f, 5.995474e-1f, 5.253798e-1f, 4.650208e-1f, 4.135436e-1f, 3.683691e-1f, 3.2801268e-1f,
    2.9183957e-1f, 2.6038992e-1f, 2.3241007e-1f, 2.0689347e-1f, 1.8320975e-1f, 1.6096798e-1f, 1.3993642e-1f, 1.2000332e-1f,
    8.732815e-1f, 7.2041965e-1f, 6.2095505e-1f, 5.464202e-1f, 4.8579693e-1f, 4.3407393e-1f, 3.8864154e-1f, 3.4800535e-1f,
    3.115391e-1f, 2.7983063e-1f, 2.5161335e-1f, 2.2586799e-1f, 2.0195915e-1f, 1.7949575e-1f, 1.5825044e-1f, 1.3812388e-1f,
    8.87503e-1f, 7.3420596e-1f, 6.3492495e-1f, 5.6069577e-1f, 5.0037205e-1f, 4.4890475e-1f, 4.0367526e-1f, 3.631905e-1f,
    3.2683614e-1f, 2.9524136e-1f, 2.6713666e-1f, 2.4149778e-1f, 2.1768823e-1f, 1.9531879e-1f, 1.7416716e-1f, 1.5414622e-1f,
    8.872505e-1f, 7.362162e-1f, 6.387257e-1f, 5.659669e-1f, 5.068782e-1f, 4.5646042e-1f, 4.121285e-1f, 3.7241367e-1f,
    3.367258e-1f, 3.0574048e-1f, 2.7819982e-1f, 2.5308356e-1f, 2.2975862e-1f, 2.0783998e-1f, 1.8711157e-1f, 1.6749877e-1f,
);

// The sheen albedo E(n.v, alpha) (layers::sheen::albedo): ALBEDO_TABLE read bilinearly in
// (mu, sqrt(alpha)) between texel centres and constant beyond them (a texture's clamp-to-edge),
// clamped to 1 (the table passes 1 at grazing views of the smoothest sheens). n.v clamped to
// [0, 1]; alpha in [0, 1]. The Rust kernel interpolates in f64 and rounds once; this one
// rounds each step.
fn layers_sheen_albedo(n_dot_v: f32, alpha: f32) -> f32 {
    let x = clamp(saturate(n_dot_v) * 16.0 - 0.5, 0.0, 15.0);
    let y = clamp(sqrt(saturate(alpha)) * 16.0 - 0.5, 0.0, 15.0);
    let j = min(u32(x), 14u);
    let i = min(u32(y), 14u);
    let fx = x - f32(j);
    let fy = y - f32(i);
    let k = i * 16u + j;
    let a = BRDF_SHEEN_ALBEDO_TABLE[k];
    let b = BRDF_SHEEN_ALBEDO_TABLE[k + 1u];
    let c = BRDF_SHEEN_ALBEDO_TABLE[k + 16u];
    let d = BRDF_SHEEN_ALBEDO_TABLE[k + 17u];
    let lo = a + fx * (b - a);
    let hi = c + fx * (d - c);
    return min(lo + fy * (hi - lo), 1.0);
}

// KHR_materials_sheen's albedo scaling min(1 - max_rgb(sheenColor) e_v,
// 1 - max_rgb(sheenColor) e_l); pass e_l = e_v for the view-only form, once per shading point.
fn layers_sheen_albedo_scaling(
    sheen_color_r: f32, sheen_color_g: f32, sheen_color_b: f32, e_v: f32, e_l: f32,
) -> f32 {
    let m = max(max(sheen_color_r, sheen_color_g), sheen_color_b);
    return min(1.0 - m * e_v, 1.0 - m * e_l);
}

// The clearcoat's Schlick Fresnel with F0 = 0.04 (IOR 1.5; KHR_materials_clearcoat).
fn layers_clearcoat_fresnel(cos_theta: f32) -> f32 {
    return fresnel_schlick(0.04, cos_theta);
}

// Kelemen's visibility 1 / (4 v.h^2) (Kelemen and Szirmay-Kalos 2001, "A Microfacet Based
// Coupled Specular-Matte BRDF Model with Importance Sampling"), v.h capped at 1; 0 for v.h <= 0.
fn layers_clearcoat_v_kelemen(v_dot_h: f32) -> f32 {
    let c = min(v_dot_h, 1.0);
    let den = select(1.0, 4.0 * c * c, v_dot_h > 0.0);
    return brdf_above(v_dot_h, min(1.0 / den, BRDF_F32_MAX));
}

// The clearcoat lobe F(v.h) D V with GGX D and the height-correlated Smith V
// (KHR_materials_clearcoat).
fn layers_clearcoat_coat(n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32) -> f32 {
    let dv = min(ggx_d(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha), BRDF_F32_MAX);
    return min(layers_clearcoat_fresnel(v_dot_h) * dv, BRDF_F32_MAX);
}

// The clearcoat lobe with Kelemen's visibility (Guy and Agopian 2018, "Physically Based
// Rendering in Filament", section 4.9); 0 unless both cosines are above the horizon.
fn layers_clearcoat_coat_kelemen(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32,
) -> f32 {
    let dv = min(ggx_d(n_dot_h, alpha) * layers_clearcoat_v_kelemen(v_dot_h), BRDF_F32_MAX);
    let f = min(layers_clearcoat_fresnel(v_dot_h) * dv, BRDF_F32_MAX);
    return brdf_layers_above_both(n_dot_v, n_dot_l, f);
}

// A coat over its base: clearcoat coat + (1 - clearcoat f_coat) base per channel
// (KHR_materials_clearcoat, "Layering").
fn layers_clearcoat_layer(
    base_r: f32, base_g: f32, base_b: f32, coat: f32, clearcoat: f32, f_coat: f32,
) -> vec3<f32> {
    let att = 1.0 - clearcoat * f_coat;
    return vec3<f32>(
        fma(coat, clearcoat, att * base_r),
        fma(coat, clearcoat, att * base_g),
        fma(coat, clearcoat, att * base_b),
    );
}

// KHR_materials_ior's F0 = ((ior - 1) / (ior + 1))^2, and 1 for the special ior = 0.
fn layers_specular_f0_from_ior(ior: f32) -> f32 {
    let zero = ior == 0.0;
    return select(fresnel_f0_from_ior(select(ior, 1.0, zero)), 1.0, zero);
}

// KHR_materials_specular's dielectric F0 min(F0_ior color, 1) specular, per channel.
fn layers_specular_dielectric_f0(
    f0_ior: f32, specular: f32, specular_color_r: f32, specular_color_g: f32,
    specular_color_b: f32,
) -> vec3<f32> {
    return vec3<f32>(
        min(f0_ior * specular_color_r, 1.0) * specular,
        min(f0_ior * specular_color_g, 1.0) * specular,
        min(f0_ior * specular_color_b, 1.0) * specular,
    );
}

// KHR_materials_anisotropy's tangent width mix(alpha, 1, strength^2).
fn layers_anisotropy_alpha_t(alpha: f32, strength: f32) -> f32 {
    let s2 = strength * strength;
    return (1.0 - s2) * alpha + s2;
}

// KHR_materials_anisotropy's direction: (x, y) normalized ((1, 0) for the zero vector),
// rotated by `rotation` radians, in the tangent plane (z = 0).
fn layers_anisotropy_direction(x: f32, y: f32, rotation: f32) -> vec3<f32> {
    let len = sqrt(fma(x, x, y * y));
    let zero = len == 0.0;
    let safe = select(len, 1.0, zero);
    let ux = select(x / safe, 1.0, zero);
    let uy = select(y / safe, 0.0, zero);
    let s = sin(rotation);
    let c = cos(rotation);
    return vec3<f32>(c * ux - s * uy, s * ux + c * uy, 0.0);
}

// The cross product a x b, written out (the bound's interpreter models arithmetic, not cross).
fn brdf_layers_cross(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

// The bent reflection vector for anisotropic IBL (Khronos glTF sample viewer's
// getIBLRadianceAnisotropy; Guy and Agopian 2018, Filament section 5.3.9): the normal bent
// towards the anisotropic normal (b x v) x b by 1 - k^4, k = 1 - strength (1 - roughness),
// normalized (n where the mix vanishes), then v reflected about it.
fn layers_anisotropy_bent_reflection(
    n_x: f32, n_y: f32, n_z: f32, v_x: f32, v_y: f32, v_z: f32, b_x: f32, b_y: f32, b_z: f32,
    strength: f32, roughness: f32,
) -> vec3<f32> {
    let n = vec3<f32>(n_x, n_y, n_z);
    let v = vec3<f32>(v_x, v_y, v_z);
    let b = vec3<f32>(b_x, b_y, b_z);
    let n_a = brdf_layers_cross(brdf_layers_cross(b, v), b);
    let k = 1.0 - strength * (1.0 - roughness);
    let k2 = k * k;
    let k4 = k2 * k2;
    let m = vec3<f32>(
        n_a.x * (1.0 - k4) + n.x * k4,
        n_a.y * (1.0 - k4) + n.y * k4,
        n_a.z * (1.0 - k4) + n.z * k4,
    );
    let len2 = m.x * m.x + m.y * m.y + m.z * m.z;
    let ok = len2 > 0.0;
    let inv = select(0.0, 1.0 / sqrt(select(1.0, len2, ok)), ok);
    let nb = vec3<f32>(select(n.x, m.x * inv, ok), select(n.y, m.y * inv, ok), select(n.z, m.z * inv, ok));
    let t = 2.0 * (v.x * nb.x + v.y * nb.y + v.z * nb.z);
    return vec3<f32>(nb.x * t - v.x, nb.y * t - v.y, nb.z * t - v.z);
}
