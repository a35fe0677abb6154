// brdf: the layered glTF material, the twins of `layers::layered::Layered`'s `eval`,
// `lobe_probabilities`, `pdf` and `sample` (the metallic-roughness base with
// KHR_materials_sheen, _clearcoat, _anisotropy, _iridescence, _transmission and _volume, each
// off at its glTF default), composed from the lobes' own twins in the Rust order. Needs
// common.wgsl, ggx.wgsl, fresnel.wgsl, beckmann.wgsl, sampling.wgsl, rough_dielectric.wgsl,
// transmission.wgsl, layers.wgsl and iridescence.wgsl.
//
// Each twin takes the material as the reference CLI builds it (`Layered::new(base_color,
// metallic, roughness)` then `with_sheen`, `with_clearcoat`, `with_anisotropy`,
// `with_iridescence(factor, ThinFilm::new(thickness, ior))`, `with_transmission`, `with_volume`),
// 22 arguments, then the local-frame directions (normal +z, tangent +x). The coat normal is the
// shading normal and the multiple-scattering compensation is off (the constructor's defaults);
// the volume's attenuation colour and distance act along the path, not at the surface, and are
// not read.

// mu* = 1 - 21^(-1/5), where Schlick's weight is its hemispherical average 1/21.
const BRDF_LAYERED_AVERAGE_COS: f32 = 0.456053555;

// (1 - t) a + t b (material::lerp).
fn brdf_layered_lerp(a: f32, b: f32, t: f32) -> f32 {
    return (1.0 - t) * a + t * b;
}

// One channel of the thin film's Rec.709 reflectance over a base of normal-incidence
// reflectance f0 (the Rust `film_rgb`): the base index (1 + sqrt(F0)) / (1 - sqrt(F0)) capped at
// the largest finite f32, the film's XYZ by iridescence_dielectric under air, the row of
// XYZ_TO_REC709 divided by its sum (the conversion of the equal-energy white), clamped to
// [0, 1]. 1 - sqrt(F0) is formed as (1 - F0) / (1 + sqrt(F0)), its value without the
// cancellation near F0 = 1 (exactly 0 at F0 = 1, where the Rust kernel's floor at the smallest
// normal takes over alike).
fn brdf_layered_film_channel(
    thickness: f32, ior: f32, f0: f32, m0: f32, m1: f32, m2: f32, cos_theta: f32,
) -> f32 {
    let s = saturate(f0);
    let r = sqrt(s);
    let den = max((1.0 - s) / (1.0 + r), 1.17549435e-38);
    let base_ior = min((1.0 + r) / den, BRDF_F32_MAX);
    let xyz = iridescence_dielectric(thickness, ior, 1.0, base_ior, cos_theta);
    return saturate(m0 * xyz.x + m1 * xyz.y + m2 * xyz.z);
}

// The film's reflectance in linear Rec.709 RGB over a base of per-channel F0.
fn brdf_layered_film_rgb(thickness: f32, ior: f32, f0: vec3<f32>, cos_theta: f32) -> vec3<f32> {
    return vec3<f32>(
        brdf_layered_film_channel(thickness, ior, f0.x, 2.68965507f, -1.27586198f,
            -0.413793087f, cos_theta),
        brdf_layered_film_channel(thickness, ior, f0.y, -1.0221082f, 1.97828662f,
            0.0438215397f, cos_theta),
        brdf_layered_film_channel(thickness, ior, f0.z, 0.0612244569f, -0.224489778f,
            1.16326535f, cos_theta),
    );
}

// One channel's (F, 1 - F, 1 - F_dielectric) of the base (material::fresnel_and_kd_film with
// the glTF dielectric F0 = 0.04, F90 = 1): the dielectric's and the metal's Schlick terms and
// their complements from the weights (w, 1 - w), each mixed towards the film's by k unless k
// is 0, then mixed by metallic.
fn brdf_layered_channel(
    base: f32, film_d: f32, film_m: f32, metallic: f32, w: f32, one_minus_w: f32, k: f32,
) -> vec3<f32> {
    let off = k == 0.0;
    let f_d0 = fma(0.04, one_minus_w, w);
    let f_m0 = fma(base, one_minus_w, w);
    let g_d0 = 0.96 * one_minus_w;
    let g_m0 = (1.0 - base) * one_minus_w;
    let f_d = select(brdf_layered_lerp(f_d0, film_d, k), f_d0, off);
    let g_d = select(brdf_layered_lerp(g_d0, 1.0 - film_d, k), g_d0, off);
    let f_m = select(brdf_layered_lerp(f_m0, film_m, k), f_m0, off);
    let g_m = select(brdf_layered_lerp(g_m0, 1.0 - film_m, k), g_m0, off);
    return vec3<f32>(brdf_layered_lerp(f_d, f_m, metallic), brdf_layered_lerp(g_d, g_m, metallic),
        g_d);
}

// The base's mixed Fresnel (F.r, F.g, F.b) and glTF's diffuse weight
// kd = (1 - metallic) min_rgb(1 - F_dielectric) for the Schlick weights (w, 1 - w), the film
// read at cos_theta (its factor 0 where its thickness is 0, the Sample Viewer's rule).
fn brdf_layered_fresnel_kd_weights(
    base: vec3<f32>, metallic: f32, factor: f32, thickness: f32, ior: f32, w: f32,
    one_minus_w: f32, cos_theta: f32,
) -> vec4<f32> {
    let film_d = brdf_layered_film_rgb(thickness, ior, vec3<f32>(0.04), cos_theta);
    let film_m = brdf_layered_film_rgb(thickness, ior, base, cos_theta);
    let k = select(factor, 0.0, thickness == 0.0);
    let r = brdf_layered_channel(base.x, film_d.x, film_m.x, metallic, w, one_minus_w, k);
    let g = brdf_layered_channel(base.y, film_d.y, film_m.y, metallic, w, one_minus_w, k);
    let b = brdf_layered_channel(base.z, film_d.z, film_m.z, metallic, w, one_minus_w, k);
    return vec4<f32>(r.x, g.x, b.x, (1.0 - metallic) * min(min(r.z, g.z), b.z));
}

// brdf_layered_fresnel_kd_weights at the Schlick weights of cos_theta clamped to [0, 1]:
// w = (1 - c)^5 and 1 - w = c (1 + s (1 + s (1 + s (1 + s)))), s = 1 - c (no cancellation).
fn brdf_layered_fresnel_kd(
    base: vec3<f32>, metallic: f32, factor: f32, thickness: f32, ior: f32, cos_theta: f32,
) -> vec4<f32> {
    let c = saturate(cos_theta);
    let s = 1.0 - c;
    let s2 = s * s;
    let w = s2 * s2 * s;
    let one_minus_w = c * fma(s, fma(s, fma(s, s + 1.0, 1.0), 1.0), 1.0);
    return brdf_layered_fresnel_kd_weights(base, metallic, factor, thickness, ior, w,
        one_minus_w, cos_theta);
}

// w in the anisotropy frame (the tangent rotated by the direction (c, s)).
fn brdf_layered_aniso_local(w: vec3<f32>, c: f32, s: f32) -> vec3<f32> {
    return vec3<f32>(c * w.x + s * w.y, c * w.y - s * w.x, w.z);
}

// a . b in the order of the Rust V3::dot.
fn brdf_layered_dot(a: vec3<f32>, b: vec3<f32>) -> f32 {
    return fma(a.x, b.x, fma(a.y, b.y, a.z * b.z));
}

// The anisotropic base GGX's tangent width max(mix(min(alpha, 1), 1, strength^2), alpha).
fn brdf_layered_alpha_t(alpha: f32, strength: f32) -> f32 {
    return max(layers_anisotropy_alpha_t(min(alpha, 1.0), strength), alpha);
}

// The volumetric reading's relative index eta = (1 + r) / (1 - r), r = sqrt(mean F0_d) (the
// glTF dielectric's 0.04 per channel, summed in f32 as the Rust `volume_eta` sums it), and 1
// where the lobe is the thin-walled one (the volume's thickness 0, or eta within 1e-4 of 1),
// else 0.
fn brdf_layered_volume_eta(volume_thickness: f32) -> vec2<f32> {
    let f0: f32 = 0.04;
    let r = sqrt(clamp((f0 + f0 + f0) * 0.333333343, 0.0, 1.0));
    let eta = min((1.0 + r) / max(1.0 - r, 1.17549435e-38), BRDF_F32_MAX);
    let thin = (volume_thickness <= 0.0) | (eta <= 1.00010002);
    return vec2<f32>(eta, select(0.0, 1.0, thin));
}

// The transmission lobe for wi below the surface (the Rust `with_transmitted`): its BTDF and
// the half vector whose wo.h feeds its diffuse weight, thin-walled (transmission_thin_walled_btdf,
// h_T = normalize(wo + wi mirrored)) where the volume's thickness is 0 or the base's index eta
// is within 1e-4 of 1, else Walter et al. 2007's refraction lobe into eta (radiance transport,
// no Fresnel; h = -normalize(wo + eta wi)), eta of brdf_layered_volume_eta. Returns
// (btdf, h).
fn brdf_layered_btdf_and_half(
    alpha_t: f32, alpha: f32, c: f32, s: f32, volume_thickness: f32,
    wo: vec3<f32>, wi: vec3<f32>,
) -> vec4<f32> {
    let eta_thin = brdf_layered_volume_eta(volume_thickness);
    let eta = eta_thin.x;
    let thin = eta_thin.y > 0.0;
    let wo_a = brdf_layered_aniso_local(wo, c, s);
    let wi_a = brdf_layered_aniso_local(wi, c, s);
    let f_thin = transmission_thin_walled_btdf(alpha_t, alpha, wo_a.x, wo_a.y, wo_a.z,
        wi_a.x, wi_a.y, wi_a.z);
    let f_vol = brdf_rough_dielectric_btdf_ggx(alpha_t, alpha, wo_a.x, wo_a.y, wo_a.z,
        wi_a.x, wi_a.y, wi_a.z, eta).x;
    let h_thin = brdf_rough_dielectric_normalize_or(wo + vec3<f32>(wi.x, wi.y, -wi.z),
        vec3<f32>(0.0, 0.0, 1.0));
    let h_vol = -brdf_rough_dielectric_normalize_or(wo + wi * eta, vec3<f32>(0.0, 0.0, -1.0));
    let h = select(h_vol, h_thin, thin);
    return vec4<f32>(select(f_vol, f_thin, thin), h.x, h.y, h.z);
}

// The layered material's BRDF f(wo, wi) in RGB, not multiplied by the cosine (module docs of
// layers::layered): with h = normalize(wo + wi) and (F, kd) the base's mixed Fresnel and
// diffuse weight at v.h,
//   base    = F D V + kd baseColor / pi (1 - transmission)   D V isotropic GGX where the
//                                                            anisotropy strength is 0, else
//                                                            the anisotropic GGX in the
//                                                            rotated tangent frame
//   sheened = f_sheen + base s                               s the sheen's albedo scaling
//   f       = clearcoat coat + (1 - clearcoat F_coat(n.v)) sheened,
// 0 where wo.z <= 0 or wi.z <= 0; below the surface (wo above, transmission > 0) the
// transmission lobe kd(h_T) baseColor t btdf (1 - clearcoat F_coat(n.v))(1 - max(sheenColor)
// E(n.v)). wo and wi unit vectors.
fn layers_layered_Layered_eval(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    sheen_color_r: f32, sheen_color_g: f32, sheen_color_b: f32, sheen_roughness: f32,
    clearcoat: f32, clearcoat_roughness: f32, anisotropy_strength: f32,
    anisotropy_rotation: f32, iridescence_factor: f32, iridescence_thickness: f32,
    iridescence_ior: f32, transmission: f32, volume_thickness: f32,
    volume_attenuation_color_r: f32, volume_attenuation_color_g: f32,
    volume_attenuation_color_b: f32, volume_attenuation_distance: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> vec3<f32> {
    let base = vec3<f32>(base_color_r, base_color_g, base_color_b);
    let alpha = microfacet_alpha_from_perceptual(roughness);
    let sheen_alpha = sheen_roughness * sheen_roughness;
    let coat_alpha = microfacet_alpha_from_perceptual(clearcoat_roughness);
    let dir = layers_anisotropy_direction(1.0, 0.0, anisotropy_rotation);
    let wo = vec3<f32>(wo_x, wo_y, wo_z);
    let wi = vec3<f32>(wi_x, wi_y, wi_z);
    let e_v = layers_sheen_albedo(wo_z, sheen_alpha);
    let e_l = layers_sheen_albedo(wi_z, sheen_alpha);
    let f_coat = layers_clearcoat_fresnel(wo_z);
    let h = brdf_rough_dielectric_normalize_or(wo + wi, vec3<f32>(0.0, 0.0, 1.0));
    let v_dot_h = brdf_layered_dot(wo, h);
    let fk = brdf_layered_fresnel_kd(base, metallic, iridescence_factor, iridescence_thickness,
        iridescence_ior, v_dot_h);
    let iso = ggx_d(h.z, alpha) * ggx_v_correlated(wo_z, wi_z, alpha);
    let alpha_t = brdf_layered_alpha_t(alpha, anisotropy_strength);
    let h_a = brdf_layered_aniso_local(h, dir.x, dir.y);
    let wo_a = brdf_layered_aniso_local(wo, dir.x, dir.y);
    let wi_a = brdf_layered_aniso_local(wi, dir.x, dir.y);
    let aniso = ggx_Ggx_d(alpha_t, alpha, h_a.x, h_a.y, h_a.z)
        * ggx_Ggx_v_correlated(alpha_t, alpha, wo_a.x, wo_a.y, wo_a.z, wi_a.x, wi_a.y, wi_a.z);
    let dv = min(select(aniso, iso, anisotropy_strength == 0.0), BRDF_F32_MAX);
    let keep = 1.0 - transmission;
    let above = (wo_z > 0.0) & (wi_z > 0.0);
    let base_f = vec3<f32>(
        select(0.0, min(fma(fk.x, dv, fk.w * base.x * BRDF_FRAC_1_PI * keep), BRDF_F32_MAX), above),
        select(0.0, min(fma(fk.y, dv, fk.w * base.y * BRDF_FRAC_1_PI * keep), BRDF_F32_MAX), above),
        select(0.0, min(fma(fk.z, dv, fk.w * base.z * BRDF_FRAC_1_PI * keep), BRDF_F32_MAX), above),
    );
    let s = layers_sheen_albedo_scaling(sheen_color_r, sheen_color_g, sheen_color_b, e_v, e_l);
    let f_sheen = layers_sheen_charlie(wo_z, wi_z, h.z, v_dot_h, sheen_color_r, sheen_color_g,
        sheen_color_b, sheen_alpha);
    let sheened = vec3<f32>(fma(base_f.x, s, f_sheen.x), fma(base_f.y, s, f_sheen.y),
        fma(base_f.z, s, f_sheen.z));
    let coat = layers_clearcoat_coat(wo_z, wi_z, h.z, v_dot_h, coat_alpha);
    let layered = layers_clearcoat_layer(sheened.x, sheened.y, sheened.z, coat, clearcoat, f_coat);
    let reflected = vec3<f32>(select(0.0, layered.x, above), select(0.0, layered.y, above),
        select(0.0, layered.z, above));
    // The transmission lobe, below the surface.
    let bh = brdf_layered_btdf_and_half(alpha_t, alpha, dir.x, dir.y, volume_thickness, wo, wi);
    let h_t = vec3<f32>(bh.y, bh.z, bh.w);
    let kd_t = brdf_layered_fresnel_kd(base, metallic, iridescence_factor, iridescence_thickness,
        iridescence_ior, clamp(brdf_layered_dot(wo, h_t), 0.0, 1.0)).w;
    let m = max(max(sheen_color_r, sheen_color_g), sheen_color_b);
    let through = (1.0 - clearcoat * f_coat) * (1.0 - m * e_v) * transmission * bh.x;
    let live = (transmission > 0.0) & (wo_z > 0.0) & (wi_z < 0.0);
    return vec3<f32>(
        select(reflected.x, min(kd_t * base.x * through, BRDF_F32_MAX), live),
        select(reflected.y, min(kd_t * base.y * through, BRDF_F32_MAX), live),
        select(reflected.z, min(kd_t * base.z * through, BRDF_F32_MAX), live),
    );
}

// (c.x + c.y + c.z) / 3.
fn brdf_layered_mean(c: vec3<f32>) -> f32 {
    return (c.x + c.y + c.z) * 0.333333343;
}

// A lobe's estimated weight w over their sum, raised to material::LOBE_PROBABILITY_MIN = 1/16
// where w > 0, 0 where w = 0.
fn brdf_layered_floor(w: f32, safe: f32) -> f32 {
    return select(0.0, max(w / safe, 0.0625), w > 0.0);
}

// The lobe-selection probabilities at wo (coat, base specular, cosine lobes, transmission) of
// the one-sample sampler (module docs of layers::layered, "Sampling"; the Rust `lobe_weights`):
// the estimated albedos
//   coat    clearcoat F_coat(n.v)
//   spec    (1 - coat)(1 - max(sheenColor) E(n.v)) mean(F(n.v))
//   cosine  (1 - coat)(max(sheenColor) E(n.v) + (1 - max(sheenColor) E(n.v)) mean(kd baseColor)
//           (1 - transmission)), kd at Schlick's average weight 1/21 (the film at mu*)
//   trans   (1 - coat)(1 - max(sheenColor) E(n.v)) mean(kd baseColor) transmission,
// each over their sum floored at 1/16 unless 0, renormalized; (0, 0, 1, 0) where all are 0.
fn brdf_layered_lobe_weights(
    base: vec3<f32>, metallic: f32, sheen_color: vec3<f32>, sheen_alpha: f32, clearcoat: f32,
    iridescence_factor: f32, iridescence_thickness: f32, iridescence_ior: f32,
    transmission: f32, wo_z: f32,
) -> vec4<f32> {
    let f = brdf_layered_fresnel_kd(base, metallic, iridescence_factor, iridescence_thickness,
        iridescence_ior, wo_z);
    let kd = brdf_layered_fresnel_kd_weights(base, metallic, iridescence_factor,
        iridescence_thickness, iridescence_ior, 0.0476190485, 0.952380955,
        BRDF_LAYERED_AVERAGE_COS).w;
    let w_coat = clearcoat * layers_clearcoat_fresnel(wo_z);
    let through = 1.0 - w_coat;
    let m = max(max(sheen_color.x, sheen_color.y), sheen_color.z);
    let e_v = layers_sheen_albedo(wo_z, sheen_alpha);
    let s_v = 1.0 - m * e_v;
    let w_spec = through * s_v * brdf_layered_mean(vec3<f32>(f.x, f.y, f.z));
    let diffuse = brdf_layered_mean(vec3<f32>(kd * base.x, kd * base.y, kd * base.z));
    let w_cos = through * (m * e_v + s_v * (diffuse * (1.0 - transmission)));
    let w_trans = through * s_v * diffuse * transmission;
    let sum = w_coat + w_spec + w_cos + w_trans;
    let empty = sum <= 0.0;
    let safe = select(sum, 1.0, empty);
    let p_coat = brdf_layered_floor(w_coat, safe);
    let p_spec = brdf_layered_floor(w_spec, safe);
    let p_cos = brdf_layered_floor(w_cos, safe);
    let p_trans = brdf_layered_floor(w_trans, safe);
    let total = select(p_coat + p_spec + p_cos + p_trans, 1.0, empty);
    return vec4<f32>(select(p_coat / total, 0.0, empty), select(p_spec / total, 0.0, empty),
        select(p_cos / total, 1.0, empty), select(p_trans / total, 0.0, empty));
}

// The lobe-selection probabilities at wo (coat, base specular, cosine lobes) of
// brdf_layered_lobe_weights; the transmission lobe's is 1 minus their sum. wo a unit vector.
fn layers_layered_Layered_lobe_probabilities(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    sheen_color_r: f32, sheen_color_g: f32, sheen_color_b: f32, sheen_roughness: f32,
    clearcoat: f32, clearcoat_roughness: f32, anisotropy_strength: f32,
    anisotropy_rotation: f32, iridescence_factor: f32, iridescence_thickness: f32,
    iridescence_ior: f32, transmission: f32, volume_thickness: f32,
    volume_attenuation_color_r: f32, volume_attenuation_color_g: f32,
    volume_attenuation_color_b: f32, volume_attenuation_distance: f32,
    wo_x: f32, wo_y: f32, wo_z: f32,
) -> vec3<f32> {
    let p = brdf_layered_lobe_weights(vec3<f32>(base_color_r, base_color_g, base_color_b),
        metallic, vec3<f32>(sheen_color_r, sheen_color_g, sheen_color_b),
        sheen_roughness * sheen_roughness, clearcoat, iridescence_factor, iridescence_thickness,
        iridescence_ior, transmission, wo_z);
    return vec3<f32>(p.x, p.y, p.z);
}

// The transmission lobe's density at wi (the Rust `transmission_pdf`): thin-walled, the base
// specular's reflection density at wi mirrored through the surface plane; volumetric, the
// visible-normal density of h = -normalize(wo + eta wi) times the refraction Jacobian
// eta^2 |wi.h| / (wo.h + eta wi.h)^2 (Walter et al. 2007 eq. 17), 0 unless wo.h > 0 > wi.h.
fn brdf_layered_transmission_pdf(
    alpha_t: f32, alpha: f32, c: f32, s: f32, volume_thickness: f32,
    wo: vec3<f32>, wi: vec3<f32>,
) -> f32 {
    let eta_thin = brdf_layered_volume_eta(volume_thickness);
    let eta = eta_thin.x;
    let thin = eta_thin.y > 0.0;
    let wo_a = brdf_layered_aniso_local(wo, c, s);
    let h_thin = brdf_rough_dielectric_normalize_or(wo + vec3<f32>(wi.x, wi.y, -wi.z),
        vec3<f32>(0.0, 0.0, 1.0));
    let ht_a = brdf_layered_aniso_local(h_thin, c, s);
    let p_thin = sampling_reflect_pdf(sampling_visible_normal_pdf(0u, alpha_t, alpha,
        wo_a.x, wo_a.y, wo_a.z, ht_a.x, ht_a.y, ht_a.z), brdf_layered_dot(wo, h_thin));
    let h = -brdf_rough_dielectric_normalize_or(wo + wi * eta, vec3<f32>(0.0, 0.0, -1.0));
    let o_h = brdf_layered_dot(wo, h);
    let i_h = brdf_layered_dot(wi, h);
    let pair = (o_h > 0.0) & (i_h < 0.0);
    let denom = fma(eta, i_h, o_h);
    let jacobian = min(eta * eta * abs(i_h) / (denom * denom), BRDF_F32_MAX);
    let h_a = brdf_layered_aniso_local(h, c, s);
    let p_vol = min(sampling_visible_normal_pdf(0u, alpha_t, alpha, wo_a.x, wo_a.y, wo_a.z,
        h_a.x, h_a.y, h_a.z) * jacobian, BRDF_F32_MAX);
    return select(select(0.0, p_vol, pair), p_thin, thin);
}

// The one-sample mixture pdf (solid angle) of the layered material's sampler: P_coat p_coat +
// P_spec p_spec + P_cos max(0, wi.z) / pi (+ P_trans p_trans), P of brdf_layered_lobe_weights,
// p_coat the coat GGX's visible-normal reflection density, p_spec the anisotropic base's in
// the rotated tangent frame, p_trans brdf_layered_transmission_pdf; h = normalize(wo + wi).
// wo and wi unit vectors.
fn layers_layered_Layered_pdf(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    sheen_color_r: f32, sheen_color_g: f32, sheen_color_b: f32, sheen_roughness: f32,
    clearcoat: f32, clearcoat_roughness: f32, anisotropy_strength: f32,
    anisotropy_rotation: f32, iridescence_factor: f32, iridescence_thickness: f32,
    iridescence_ior: f32, transmission: f32, volume_thickness: f32,
    volume_attenuation_color_r: f32, volume_attenuation_color_g: f32,
    volume_attenuation_color_b: f32, volume_attenuation_distance: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let p = brdf_layered_lobe_weights(vec3<f32>(base_color_r, base_color_g, base_color_b),
        metallic, vec3<f32>(sheen_color_r, sheen_color_g, sheen_color_b),
        sheen_roughness * sheen_roughness, clearcoat, iridescence_factor, iridescence_thickness,
        iridescence_ior, transmission, wo_z);
    let alpha = microfacet_alpha_from_perceptual(roughness);
    let alpha_t = brdf_layered_alpha_t(alpha, anisotropy_strength);
    let coat_alpha = microfacet_alpha_from_perceptual(clearcoat_roughness);
    let dir = layers_anisotropy_direction(1.0, 0.0, anisotropy_rotation);
    let wo = vec3<f32>(wo_x, wo_y, wo_z);
    let wi = vec3<f32>(wi_x, wi_y, wi_z);
    let h = brdf_rough_dielectric_normalize_or(wo + wi, vec3<f32>(0.0, 0.0, 1.0));
    let wo_dot_h = brdf_layered_dot(wo, h);
    let wo_a = brdf_layered_aniso_local(wo, dir.x, dir.y);
    let h_a = brdf_layered_aniso_local(h, dir.x, dir.y);
    let spec = sampling_reflect_pdf(sampling_visible_normal_pdf(0u, alpha_t, alpha,
        wo_a.x, wo_a.y, wo_a.z, h_a.x, h_a.y, h_a.z), wo_dot_h);
    let coat = sampling_reflect_pdf(sampling_visible_normal_pdf(0u, coat_alpha, coat_alpha,
        wo_x, wo_y, wo_z, h.x, h.y, h.z), wo_dot_h);
    let cos = sampling_cosine_hemisphere_pdf(wi_x, wi_y, wi_z);
    let mixture = p.x * coat + p.y * spec + p.z * cos;
    let trans = brdf_layered_transmission_pdf(alpha_t, alpha, dir.x, dir.y, volume_thickness,
        wo, wi);
    return select(mixture, fma(p.w, trans, mixture), p.w > 0.0);
}

// w from the anisotropy frame back to the local frame.
fn brdf_layered_aniso_world(w: vec3<f32>, c: f32, s: f32) -> vec3<f32> {
    return vec3<f32>(c * w.x - s * w.y, s * w.x + c * w.y, w.z);
}

// v reflected about the unit n: n (2 v.n) - v (V3::mirror).
fn brdf_layered_mirror(v: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let k = 2.0 * brdf_layered_dot(v, n);
    return vec3<f32>(n.x * k - v.x, n.y * k - v.y, n.z * k - v.z);
}

// u clamped to [0, 1 - 2^-24].
fn brdf_layered_below1(u: f32) -> f32 {
    return clamp(u, 0.0, 0.99999994);
}

// (u - lo) / p rescaled into the lobe of probability p, below 1; 0 for a lobe of probability 0
// (never drawn: the guard keeps its unused division finite).
fn brdf_layered_rescale(u: f32, lo: f32, p: f32) -> f32 {
    let live = p > 0.0;
    return select(0.0, brdf_layered_below1((u - lo) / select(1.0, p, live)), live);
}

// A transmission-lobe direction in the local frame for wo_a (the anisotropy frame; the Rust
// `sample_transmission`): a visible normal m of the base GGX, then the reflection about m
// mirrored through the surface plane (thin-walled), or the refraction through m into eta
// (Walter et al. 2007 eq. 40: normalize((c - eta cos_t) m - wo), c = wo.m clamped to [0, 1],
// eta cos_t = sqrt(eta^2 - 1 + c^2); eta >= 1, no total internal reflection).
fn brdf_layered_sample_transmission(
    alpha_t: f32, alpha: f32, c_rot: f32, s_rot: f32, volume_thickness: f32, wo_a: vec3<f32>,
    u1: f32, u2: f32,
) -> vec3<f32> {
    let eta_thin = brdf_layered_volume_eta(volume_thickness);
    let eta = eta_thin.x;
    let m = brdf_ggx_vndf_normal(alpha_t, alpha, wo_a, u1, u2);
    let r = brdf_layered_mirror(wo_a, m);
    let thin_a = vec3<f32>(r.x, r.y, -r.z);
    let c = clamp(brdf_layered_dot(wo_a, m), 0.0, 1.0);
    let eta_cos_t = min(sqrt(max(fma(eta, eta, -1.0) + c * c, 0.0)), BRDF_F32_MAX);
    let k = c - eta_cos_t;
    let vol_a = brdf_rough_dielectric_normalize_or(
        vec3<f32>(m.x * k - wo_a.x, m.y * k - wo_a.y, m.z * k - wo_a.z),
        vec3<f32>(0.0, 0.0, -1.0));
    return brdf_layered_aniso_world(select(vol_a, thin_a, eta_thin.y > 0.0), c_rot, s_rot);
}

// Draws wi for the view wo by one-sample lobe selection (layers::layered::Layered::sample):
// u1, clamped below 1, picks the coat, the base specular, the cosine lobes or the
// transmission lobe by brdf_layered_lobe_weights (a lobe of probability 0 never; the specular
// lobe where the cosine and transmission lobes are both absent, the cosine lobes where the
// transmission lobe is) and is rescaled into it; u2 is passed on. The coat reflects wo about
// a GGX visible normal (Heitz 2018) of the coat, the base about one of the anisotropic base
// GGX in the rotated tangent frame, the cosine lobes draw the cosine hemisphere, the
// transmission lobe brdf_layered_sample_transmission. Returns (wi, layers_layered_Layered_pdf
// at wi); a reflected sample can fall below the horizon.
fn layers_layered_Layered_sample(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    sheen_color_r: f32, sheen_color_g: f32, sheen_color_b: f32, sheen_roughness: f32,
    clearcoat: f32, clearcoat_roughness: f32, anisotropy_strength: f32,
    anisotropy_rotation: f32, iridescence_factor: f32, iridescence_thickness: f32,
    iridescence_ior: f32, transmission: f32, volume_thickness: f32,
    volume_attenuation_color_r: f32, volume_attenuation_color_g: f32,
    volume_attenuation_color_b: f32, volume_attenuation_distance: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let p = brdf_layered_lobe_weights(vec3<f32>(base_color_r, base_color_g, base_color_b),
        metallic, vec3<f32>(sheen_color_r, sheen_color_g, sheen_color_b),
        sheen_roughness * sheen_roughness, clearcoat, iridescence_factor, iridescence_thickness,
        iridescence_ior, transmission, wo_z);
    let u = brdf_layered_below1(u1);
    let c1 = p.x;
    let c2 = p.x + p.y;
    let c3 = c2 + p.z;
    let no_trans = p.w <= 0.0;
    let is_coat = u < c1;
    let is_spec = !is_coat & ((u < c2) | ((p.z <= 0.0) & no_trans));
    let is_cos = !is_coat & !is_spec & ((u < c3) | no_trans);
    let alpha = microfacet_alpha_from_perceptual(roughness);
    let alpha_t = brdf_layered_alpha_t(alpha, anisotropy_strength);
    let coat_alpha = microfacet_alpha_from_perceptual(clearcoat_roughness);
    let dir = layers_anisotropy_direction(1.0, 0.0, anisotropy_rotation);
    let wo = vec3<f32>(wo_x, wo_y, wo_z);
    let m_c = brdf_ggx_vndf_normal(coat_alpha, coat_alpha, wo,
        brdf_layered_rescale(u, 0.0, p.x), u2);
    let wi_coat = brdf_layered_mirror(wo, m_c);
    let wo_a = brdf_layered_aniso_local(wo, dir.x, dir.y);
    let m_a = brdf_ggx_vndf_normal(alpha_t, alpha, wo_a, brdf_layered_rescale(u, c1, p.y), u2);
    let wi_spec = brdf_layered_aniso_world(brdf_layered_mirror(wo_a, m_a), dir.x, dir.y);
    let cosine = sampling_cosine_hemisphere(brdf_layered_rescale(u, c2, p.z), u2);
    let wi_cos = vec3<f32>(cosine.x, cosine.y, cosine.z);
    let wi_trans = brdf_layered_sample_transmission(alpha_t, alpha, dir.x, dir.y,
        volume_thickness, wo_a, brdf_layered_rescale(u, c3, p.w), u2);
    let wi = select(select(select(wi_trans, wi_cos, is_cos), wi_spec, is_spec), wi_coat, is_coat);
    let pdf = layers_layered_Layered_pdf(base_color_r, base_color_g, base_color_b, metallic,
        roughness, sheen_color_r, sheen_color_g, sheen_color_b, sheen_roughness, clearcoat,
        clearcoat_roughness, anisotropy_strength, anisotropy_rotation, iridescence_factor,
        iridescence_thickness, iridescence_ior, transmission, volume_thickness,
        volume_attenuation_color_r, volume_attenuation_color_g, volume_attenuation_color_b,
        volume_attenuation_distance, wo_x, wo_y, wo_z, wi.x, wi.y, wi.z);
    return vec4<f32>(wi, pdf);
}
