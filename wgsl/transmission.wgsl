// brdf: glTF volume attenuation, the twins of the Rust module `transmission`
// (`transmission::Volume`'s methods, taking the constructor's thickness, attenuation colour and
// attenuation distance first), and the thin-walled BTDF. Needs common.wgsl and ggx.wgsl.

// The largest path-length ratio x / d used: ratio * ln c stays finite for every c >= 2^-149
// (|ln c| < 104, 1e36 * 104 < f32's largest value), and exp of anything below -104 is 0 in
// f32, so capping changes no result.
const BRDF_RATIO_MAX: f32 = 1e36;

// One channel of the Beer-Lambert transmittance c^ratio = exp(ratio ln c); the ends the Rust
// kernel selects (x = 0 or c = 1 give 1, c = 0 with x > 0 gives 0) are selected here too, since
// ln 0 has no WGSL value.
fn brdf_beer_lambert(c: f32, ratio: f32, path_length: f32) -> f32 {
    let v = exp(min(ratio, BRDF_RATIO_MAX) * log(max(c, 1.17549435e-38)));
    let one = select(v, 1.0, (path_length == 0.0) | (c == 1.0));
    return select(one, 0.0, (c == 0.0) & (path_length > 0.0));
}

// Beer-Lambert transmittance T(x) = c^(x / d) = exp(-sigma x) per channel
// (KHR_materials_volume, "Attenuation"), c the attenuation colour, d the attenuation distance.
// path_length in [0, MAX].
fn transmission_Volume_transmittance(
    thickness: f32, attenuation_color_r: f32, attenuation_color_g: f32,
    attenuation_color_b: f32, attenuation_distance: f32, path_length: f32,
) -> vec3<f32> {
    let ratio = path_length / attenuation_distance;
    return vec3<f32>(
        brdf_beer_lambert(attenuation_color_r, ratio, path_length),
        brdf_beer_lambert(attenuation_color_g, ratio, path_length),
        brdf_beer_lambert(attenuation_color_b, ratio, path_length),
    );
}

// One channel of sigma = -ln(c) / d, in [0, MAX]; c = 0 (ln 0 = -inf, no WGSL value) gives MAX
// as the Rust kernel's cap does.
fn brdf_attenuation(c: f32, d: f32) -> f32 {
    let s = max(min(-log(max(c, 1.17549435e-38)) / d, BRDF_F32_MAX), 0.0);
    return select(s, BRDF_F32_MAX, c == 0.0);
}

// The attenuation coefficient sigma = -ln(c) / d per channel (KHR_materials_volume,
// "Attenuation"), capped at the largest finite f32.
fn transmission_Volume_attenuation_coefficient(
    thickness: f32, attenuation_color_r: f32, attenuation_color_g: f32,
    attenuation_color_b: f32, attenuation_distance: f32,
) -> vec3<f32> {
    return vec3<f32>(
        brdf_attenuation(attenuation_color_r, attenuation_distance),
        brdf_attenuation(attenuation_color_g, attenuation_distance),
        brdf_attenuation(attenuation_color_b, attenuation_distance),
    );
}

// The thin-walled BTDF of KHR_materials_transmission (its implementation notes): the GGX lobe
// at the mirrored direction wi' = (wi.x, wi.y, -wi.z), h_T = normalize(wo + wi'),
// f = D(h_T) G1(wo) G1(wi) / (4 |wo.z| |wi.z|), with the steps h_T.wi' > 0, h_T.wo > 0, wo
// above and wi below the surface (the Rust kernel's doc says why the steps read wi'). Needs
// ggx.wgsl.
fn transmission_thin_walled_btdf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let x = wo_x + wi_x;
    let y = wo_y + wi_y;
    let z = wo_z - wi_z;
    let len2 = x * x + y * y + z * z;
    // The floor keeps the unused branch of the select finite where the sum is zero.
    let s = 1.0 / sqrt(max(len2, 1e-30));
    let live_h = len2 > 0.0;
    let h_x = select(0.0, x * s, live_h);
    let h_y = select(0.0, y * s, live_h);
    let h_z = select(1.0, z * s, live_h);
    let steps = (h_x * wi_x + h_y * wi_y - h_z * wi_z > 0.0)
        & (h_x * wo_x + h_y * wo_y + h_z * wo_z > 0.0);
    let live = steps & (wo_z > 0.0) & (wi_z < 0.0);
    let g = ggx_Ggx_g1(alpha_x, alpha_y, wo_x, wo_y, wo_z)
        * ggx_Ggx_g1(alpha_x, alpha_y, wi_x, wi_y, wi_z);
    // 1 / p capped at the largest f32, as the Rust kernel caps it; the floor keeps the unused
    // branch of the select within the divisions WGSL promises an accuracy for.
    let p = 4.0 * abs(wo_z) * abs(wi_z);
    let inv = select(BRDF_F32_MAX, min(1.0 / max(p, 1.17549435e-38), BRDF_F32_MAX), p >= 1.17549435e-38);
    let f = min(min(ggx_Ggx_d(alpha_x, alpha_y, h_x, h_y, h_z) * g, BRDF_F32_MAX) * inv, BRDF_F32_MAX);
    return select(0.0, f, live);
}
