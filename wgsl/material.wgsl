// brdf: the glTF 2.0 metallic-roughness material, the twins of the Rust module `material`
// (F0 from Filament's reflectance, the BRDF from dot products with its three diffuse
// couplings, and glTF's own composition, in the crate's precise and working-precision tiers;
// `MetallicRoughness` on local-frame directions, its lobe-selection probability, its one-sample
// MIS sampler and pdf). Needs common.wgsl, ggx.wgsl and, for the direction forms,
// cook_torrance.wgsl (with fresnel.wgsl and beckmann.wgsl) and sampling.wgsl.

// F0 = 0.16 reflectance^2 (Guy and Agopian 2018, "Physically Based Rendering in Filament",
// 4.8.3.2).
fn material_f0_from_reflectance(reflectance: f32) -> f32 {
    return 0.16 * reflectance * reflectance;
}

// a (1 - w) + b w with both weights given (material::mix2).
fn brdf_material_mix2(a: f32, b: f32, w: f32, one_minus_w: f32) -> f32 {
    return fma(a, one_minus_w, b * w);
}

// (1 - t) a + t b.
fn brdf_material_lerp(a: f32, b: f32, t: f32) -> f32 {
    return (1.0 - t) * a + t * b;
}

// One channel: D V F + kd base / pi above the horizon, capped at the largest finite f32.
fn brdf_material_channel(n_dot_v: f32, n_dot_l: f32, f: f32, dv: f32, diffuse: f32) -> f32 {
    let value = min(fma(f, dv, diffuse), BRDF_F32_MAX);
    return select(0.0, value, (n_dot_v > 0.0) & (n_dot_l > 0.0));
}

// The metallic-roughness BRDF from dot products, per channel (Khronos, "glTF 2.0
// Specification", Appendix B; Karis 2013; Guy and Agopian 2018): F D V + kd base / pi with
// alpha = roughness^2, the GGX D and height-correlated V, Schlick's F mixed between a
// dielectric F0 (and F90 = 1) and the base colour by `metallic`. Schlick's weights are
// w = (1 - c)^5 and 1 - w = c (1 + s (1 + s (1 + s (1 + s)))), s = 1 - c, c = v.h clamped to
// [0, 1], so that 1 - w does not cancel. `coupling` picks the diffuse weight kd: 0 = glTF's
// (1 - metallic)(1 - max_rgb F_dielectric), 1 = (1 - metallic)(1 - F) per channel,
// 2 = 1 - metallic.
fn material_metallic_roughness(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32,
    base_color_r: f32, base_color_g: f32, base_color_b: f32,
    metallic: f32, roughness: f32, dielectric_f0: f32, coupling: u32,
) -> vec3<f32> {
    let alpha = microfacet_alpha_from_perceptual(roughness);
    let dv = min(ggx_d(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha), BRDF_F32_MAX);
    return brdf_material_with_dv(n_dot_v, n_dot_l, v_dot_h, base_color_r, base_color_g,
        base_color_b, metallic, dielectric_f0, coupling, dv);
}

// The material from D V (capped) and the other cosines: the Fresnel mix and the diffuse
// coupling per channel.
fn brdf_material_with_dv(
    n_dot_v: f32, n_dot_l: f32, v_dot_h: f32,
    base_color_r: f32, base_color_g: f32, base_color_b: f32,
    metallic: f32, dielectric_f0: f32, coupling: u32, dv: f32,
) -> vec3<f32> {
    let c = saturate(v_dot_h);
    let s = 1.0 - c;
    let s2 = s * s;
    let w = s2 * s2 * s;
    let one_minus_w = c * fma(s, fma(s, fma(s, s + 1.0, 1.0), 1.0), 1.0);
    let one_minus_m = 1.0 - metallic;
    let f_dielectric = brdf_material_mix2(dielectric_f0, 1.0, w, one_minus_w);
    let g_dielectric = brdf_material_mix2(1.0 - dielectric_f0, 0.0, w, one_minus_w);
    let base = vec3<f32>(base_color_r, base_color_g, base_color_b);
    return vec3<f32>(
        brdf_material_lobe(n_dot_v, n_dot_l, base.x, metallic, one_minus_m, w, one_minus_w,
            f_dielectric, g_dielectric, dv, coupling),
        brdf_material_lobe(n_dot_v, n_dot_l, base.y, metallic, one_minus_m, w, one_minus_w,
            f_dielectric, g_dielectric, dv, coupling),
        brdf_material_lobe(n_dot_v, n_dot_l, base.z, metallic, one_minus_m, w, one_minus_w,
            f_dielectric, g_dielectric, dv, coupling),
    );
}

// One channel of material_metallic_roughness for the base colour `base`.
fn brdf_material_lobe(
    n_dot_v: f32, n_dot_l: f32, base: f32, metallic: f32, one_minus_m: f32, w: f32,
    one_minus_w: f32, f_dielectric: f32, g_dielectric: f32, dv: f32, coupling: u32,
) -> f32 {
    let f_metal = brdf_material_mix2(base, 1.0, w, one_minus_w);
    let g_metal = (1.0 - base) * one_minus_w;
    let f = brdf_material_lerp(f_dielectric, f_metal, metallic);
    let g = brdf_material_lerp(g_dielectric, g_metal, metallic);
    // The dielectric F0 is grey: max_rgb of its Fresnel is any channel's.
    let kd = select(select(one_minus_m, g * one_minus_m, coupling == 1u),
        one_minus_m * g_dielectric, coupling == 0u);
    let diffuse = kd * base * BRDF_FRAC_1_PI;
    return brdf_material_channel(n_dot_v, n_dot_l, f, dv, diffuse);
}

// glTF 2.0's own composition (Appendix B): material_metallic_roughness with the dielectric
// F0 = 0.04 and glTF's diffuse coupling.
fn material_gltf(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32,
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
) -> vec3<f32> {
    return material_metallic_roughness(n_dot_v, n_dot_l, n_dot_h, v_dot_h,
        base_color_r, base_color_g, base_color_b, metallic, roughness, 0.04, 0u);
}

// material_metallic_roughness in the working-precision tier: Filament's D_GGX (ggx_d_fast)
// in place of the precise D.
fn material_metallic_roughness_fast(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32,
    base_color_r: f32, base_color_g: f32, base_color_b: f32,
    metallic: f32, roughness: f32, dielectric_f0: f32, coupling: u32,
) -> vec3<f32> {
    let alpha = microfacet_alpha_from_perceptual(roughness);
    let dv = min(ggx_d_fast(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha),
        BRDF_F32_MAX);
    return brdf_material_with_dv(n_dot_v, n_dot_l, v_dot_h, base_color_r, base_color_g,
        base_color_b, metallic, dielectric_f0, coupling, dv);
}

// material_gltf in the working-precision tier.
fn material_gltf_fast(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32,
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
) -> vec3<f32> {
    return material_metallic_roughness_fast(n_dot_v, n_dot_l, n_dot_h, v_dot_h,
        base_color_r, base_color_g, base_color_b, metallic, roughness, 0.04, 0u);
}

// `material::MetallicRoughness` (as its constructor builds it: glTF's dielectric F0 = 0.04,
// F90 = 1, glTF's coupling) on local-frame directions: the half vector h = normalize(wo + wi)
// gives n.h = h.z and v.h = wo.h.
fn material_MetallicRoughness_eval(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> vec3<f32> {
    let hv = cook_torrance_half_vector(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return material_gltf(wo_z, wi_z, hv.z, hv.w, base_color_r, base_color_g, base_color_b,
        metallic, roughness);
}

// MetallicRoughness::eval in the working-precision tier.
fn material_MetallicRoughness_eval_fast(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> vec3<f32> {
    let hv = cook_torrance_half_vector(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return material_gltf_fast(wo_z, wi_z, hv.z, hv.w, base_color_r, base_color_g, base_color_b,
        metallic, roughness);
}

// One channel's (F, kd) of the glTF material for Schlick weights (w, 1 - w).
fn brdf_material_f_kd(base: f32, metallic: f32, w: f32, one_minus_w: f32) -> vec2<f32> {
    let f_dielectric = brdf_material_mix2(0.04, 1.0, w, one_minus_w);
    let g_dielectric = brdf_material_mix2(0.96, 0.0, w, one_minus_w);
    let f_metal = brdf_material_mix2(base, 1.0, w, one_minus_w);
    return vec2<f32>(brdf_material_lerp(f_dielectric, f_metal, metallic),
        (1.0 - metallic) * g_dielectric);
}

// The probability of choosing the specular lobe in the material's one-sample MIS sampler:
// S / (S + D), S the mean over channels of F at n.wo = wo.z, D the mean of kd base with kd
// at Schlick's cosine-weighted average weight 1/21, clamped to [1/16, 15/16]; 1 where D = 0.
fn material_MetallicRoughness_specular_probability(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    wo_x: f32, wo_y: f32, wo_z: f32,
) -> f32 {
    let c = saturate(wo_z);
    let t = 1.0 - c;
    let t2 = t * t;
    let w = t2 * t2 * t;
    let one_minus_w = c * fma(t, fma(t, fma(t, t + 1.0, 1.0), 1.0), 1.0);
    let fr = brdf_material_f_kd(base_color_r, metallic, w, one_minus_w);
    let fg = brdf_material_f_kd(base_color_g, metallic, w, one_minus_w);
    let fb = brdf_material_f_kd(base_color_b, metallic, w, one_minus_w);
    // 1/21 and 20/21.
    let kr = brdf_material_f_kd(base_color_r, metallic, 0.047619047619047616, 0.9523809523809523);
    let kg = brdf_material_f_kd(base_color_g, metallic, 0.047619047619047616, 0.9523809523809523);
    let kb = brdf_material_f_kd(base_color_b, metallic, 0.047619047619047616, 0.9523809523809523);
    let s = (fr.x + fg.x + fb.x) * 0.3333333333333333;
    let d = (kr.y * base_color_r + kg.y * base_color_g + kb.y * base_color_b) * 0.3333333333333333;
    let p = clamp(s / (s + d), 0.0625, 0.9375);
    return select(p, 1.0, d == 0.0);
}

// The one-sample MIS pdf (solid angle) of material_MetallicRoughness_sample
// (material::MetallicRoughness::pdf): P p_spec + (1 - P) p_diff with
// P = material_MetallicRoughness_specular_probability, p_spec = D_wo(h) / (4 |wo.h|) for
// h = normalize(wo + wi) (GGX visible normals, Heitz 2018; Walter et al. 2007, eq. 14) and
// p_diff = max(0, wi.z) / pi; 0 where wo or wi is the zero vector.
fn material_MetallicRoughness_pdf(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let p = material_MetallicRoughness_specular_probability(base_color_r, base_color_g,
        base_color_b, metallic, roughness, wo_x, wo_y, wo_z);
    let h = brdf_normalize_or_z(vec3<f32>(wo_x + wi_x, wo_y + wi_y, wo_z + wi_z));
    let alpha = microfacet_alpha_from_perceptual(roughness);
    let wo_dot_h = fma(wo_x, h.x, fma(wo_y, h.y, wo_z * h.z));
    // D_wo(h) of sampling_visible_normal_pdf for GGX (wo taken in the upper hemisphere).
    let p_spec = sampling_reflect_pdf(
        ggx_Ggx_d_visible(alpha, alpha, wo_x, wo_y, abs(wo_z), h.x, h.y, h.z), wo_dot_h);
    let p_diff = sampling_cosine_hemisphere_pdf(wi_x, wi_y, wi_z);
    let zero = ((wo_x == 0.0) & (wo_y == 0.0) & (wo_z == 0.0))
        | ((wi_x == 0.0) & (wi_y == 0.0) & (wi_z == 0.0));
    return select(brdf_material_lerp(p_diff, p_spec, p), 0.0, zero);
}

// Draws wi for the view wo by one-sample lobe selection (material::MetallicRoughness::sample):
// (wi.x, wi.y, wi.z, pdf) with pdf = material_MetallicRoughness_pdf(wo, wi). u1 (clamped into
// [0, 1)) picks the lobe and is reused: u1 < P takes the specular lobe with u1 / P, the
// reflection of wo about a GGX visible normal (sampling_ggx_vndf; Heitz 2018), otherwise
// (u1 - P) / (1 - P) goes to sampling_cosine_hemisphere. A specular wi below the horizon is
// returned as drawn, with its pdf.
fn material_MetallicRoughness_sample(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let p = material_MetallicRoughness_specular_probability(base_color_r, base_color_g,
        base_color_b, metallic, roughness, wo_x, wo_y, wo_z);
    let uc1 = brdf_clamp_u(u1);
    let specular = uc1 < p;
    // P is 1 or at most 15/16: the floor only keeps the unused branch finite at P = 1.
    let u = select((uc1 - p) / max(1.0 - p, 0.0625), uc1 / p, specular);
    let alpha = microfacet_alpha_from_perceptual(roughness);
    let m = brdf_ggx_vndf_normal(alpha, alpha, vec3<f32>(wo_x, wo_y, wo_z), u, u2);
    let k = 2.0 * fma(wo_x, m.x, fma(wo_y, m.y, wo_z * m.z));
    let wr = vec3<f32>(m.x * k - wo_x, m.y * k - wo_y, m.z * k - wo_z);
    let wd = sampling_cosine_hemisphere(u, u2);
    let wi = select(vec3<f32>(wd.x, wd.y, wd.z), wr, specular);
    let pdf = material_MetallicRoughness_pdf(base_color_r, base_color_g, base_color_b, metallic,
        roughness, wo_x, wo_y, wo_z, wi.x, wi.y, wi.z);
    return vec4<f32>(wi, pdf);
}

// material_MetallicRoughness_sample with the Monte Carlo weight
// (material::MetallicRoughness::sample_weighted): (wi.x, wi.y, wi.z, pdf, w_r, w_g, w_b),
// w = f(wo, wi) max(wi.z, 0) / pdf per channel (material_MetallicRoughness_eval), 0 where the
// pdf is 0.
fn material_MetallicRoughness_sample_weighted(
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> array<f32, 7> {
    let s = material_MetallicRoughness_sample(base_color_r, base_color_g, base_color_b, metallic,
        roughness, wo_x, wo_y, wo_z, u1, u2);
    let f = material_MetallicRoughness_eval(base_color_r, base_color_g, base_color_b, metallic,
        roughness, wo_x, wo_y, wo_z, s.x, s.y, s.z);
    // The floor keeps the unused branch finite where the pdf is 0 (below f32's smallest normal
    // WGSL's x / y promises nothing anyway).
    let scale = select(0.0, max(s.z, 0.0) / max(s.w, 1.17549435e-38), s.w > 0.0);
    return array<f32, 7>(s.x, s.y, s.z, s.w, f.x * scale, f.y * scale, f.z * scale);
}
