// brdf: glTF volume attenuation, the twins of the Rust module `transmission`
// (`transmission::Volume`'s methods, taking the constructor's thickness, attenuation colour and
// attenuation distance first), the thin-walled BTDF and the dielectric BSDF. Needs common.wgsl,
// ggx.wgsl, fresnel.wgsl, beckmann.wgsl and rough_dielectric.wgsl.

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

// normalize(x, y, z), or (0, 0, 1) for the zero vector (V3::normalize_or(unit_z)); the floor
// keeps the unused branch of the select finite there.
fn brdf_transmission_normalize_or_z(x: f32, y: f32, z: f32) -> vec3<f32> {
    let len2 = x * x + y * y + z * z;
    let s = 1.0 / sqrt(max(len2, 1e-30));
    let ok = len2 > 0.0;
    return vec3<f32>(select(0.0, x * s, ok), select(0.0, y * s, ok), select(1.0, z * s, ok));
}

// The glTF dielectric BSDF with KHR_materials_transmission (and KHR_materials_volume's reading
// of the BTDF) per RGB channel, taking the transmission factor and the volume's constructor
// arguments (thickness, attenuation colour, attenuation distance) after ior:
// - wi on wo's side: F D V + (1 - F)(1 - t) base_color / pi, h = normalize(wo + wi), D V the
//   GGX lobe with the height-correlated V;
// - wi through the surface: (1 - F) t base_color btdf, btdf = transmission_thin_walled_btdf
//   where the thickness is 0, else Walter et al. 2007's refraction lobe into ior in radiance
//   transport (rough_dielectric.wgsl), F then read at that lobe's half vector;
// F = fresnel_schlick(f0_from_ior(ior), |wo.h|) (glTF's fresnel_mix). 0 for wo at or below
// the horizon and for wi on it; capped at the largest finite f32. The attenuation colour and
// distance do not enter the BSDF (the volume attenuates along the path, not at the surface).
// Needs ggx.wgsl, fresnel.wgsl, beckmann.wgsl and rough_dielectric.wgsl.
fn transmission_dielectric_bsdf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
    base_color_r: f32, base_color_g: f32, base_color_b: f32, ior: f32, factor: f32,
    thickness: f32, attenuation_color_r: f32, attenuation_color_g: f32,
    attenuation_color_b: f32, attenuation_distance: f32,
) -> vec3<f32> {
    let f0 = fresnel_f0_from_ior(ior);
    let same = wo_z * wi_z > 0.0;
    // Reflection side.
    let h_r = brdf_transmission_normalize_or_z(wo_x + wi_x, wo_y + wi_y, wo_z + wi_z);
    let f_r = fresnel_schlick(f0, min(abs(wo_x * h_r.x + wo_y * h_r.y + wo_z * h_r.z), 1.0));
    let spec = min(ggx_Ggx_d(alpha_x, alpha_y, h_r.x, h_r.y, h_r.z)
        * ggx_Ggx_v_correlated(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi_x, wi_y, wi_z),
        BRDF_F32_MAX);
    let diffuse_w = (1.0 - f_r) * (1.0 - factor) * BRDF_FRAC_1_PI;
    // Transmission side: thin-walled or volumetric.
    let h_thin = brdf_transmission_normalize_or_z(wo_x + wi_x, wo_y + wi_y, wo_z - wi_z);
    let thin = transmission_thin_walled_btdf(alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z);
    let vol = brdf_rough_dielectric_btdf_ggx(alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z, ior);
    let is_thin = thickness == 0.0;
    let btdf = select(vol.x, thin, is_thin);
    let c_t = min(abs(select(vol.y, wo_x * h_thin.x + wo_y * h_thin.y + wo_z * h_thin.z,
        is_thin)), 1.0);
    let f_t = fresnel_schlick(f0, c_t);
    let trans_w = min((1.0 - f_t) * factor * btdf, BRDF_F32_MAX);
    let above = (wo_z > 0.0) & (wi_z != 0.0);
    let refl = min(f_r * spec, BRDF_F32_MAX);
    let c = vec3<f32>(base_color_r, base_color_g, base_color_b);
    return vec3<f32>(
        select(0.0, select(min(trans_w * c.x, BRDF_F32_MAX), refl + diffuse_w * c.x, same), above),
        select(0.0, select(min(trans_w * c.y, BRDF_F32_MAX), refl + diffuse_w * c.y, same), above),
        select(0.0, select(min(trans_w * c.z, BRDF_F32_MAX), refl + diffuse_w * c.z, same), above),
    );
}
