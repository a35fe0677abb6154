// brdf: samplers and the densities a shader needs to weight its samples, the twins of the
// Rust module `sampling` (the cosine-hemisphere sampler and pdf, the half-vector-to-reflection
// Jacobian, GGX's D cos and visible-normal samplers, the D cos and visible-normal pdfs, GGX's
// and Beckmann's reflection pdfs, and GGX's reflection samplers with their weights). Needs
// common.wgsl, ggx.wgsl and beckmann.wgsl. The Beckmann samplers (which need erf_inv) have no
// twin yet.
//
// Angles: cos(2 pi u) and sin(2 pi u) through brdf_cos_sin_2pi (common.wgsl).

// The pdf max(0, w.z) / pi of cosine-weighted hemisphere sampling (Pharr, Jakob, Humphreys,
// "Physically Based Rendering", 4th ed., A.5.3).
fn sampling_cosine_hemisphere_pdf(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return max(w_z, 0.0) * BRDF_FRAC_1_PI;
}

// The pdf of the reflected direction from the pdf of the microfacet normal,
// pdf_m / (4 |v.h|) (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 14), capped at the largest finite f32; 0 where v.h = 0.
fn sampling_reflect_pdf(pdf_m: f32, v_dot_h: f32) -> f32 {
    let den = 4.0 * abs(v_dot_h);
    return select(0.0, min(pdf_m / den, BRDF_F32_MAX), den > 0.0);
}

// v / |v|, or (0, 0, 1) for the zero vector (vec3::V3::normalize_or with the normal as the
// fallback); |v|^2 in the order of the Rust V3::dot.
fn brdf_normalize_or_z(v: vec3<f32>) -> vec3<f32> {
    let len2 = fma(v.x, v.x, fma(v.y, v.y, v.z * v.z));
    let ok = len2 > 0.0;
    let inv = select(0.0, 1.0 / sqrt(len2), ok);
    return vec3<f32>(select(0.0, v.x * inv, ok), select(0.0, v.y * inv, ok),
        select(1.0, v.z * inv, ok));
}

// Cosine-weighted hemisphere sampling (Malley's method; Pharr, Jakob, Humphreys, "Physically
// Based Rendering", 4th ed., A.5.3): the direction (sqrt(u1) cos(2 pi u2), sqrt(u1)
// sin(2 pi u2), sqrt(1 - u1)) and its pdf z / pi.
fn sampling_cosine_hemisphere(u1: f32, u2: f32) -> vec4<f32> {
    let uc1 = brdf_clamp_u(u1);
    let r = sqrt(uc1);
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let z = sqrt(1.0 - uc1);
    return vec4<f32>(r * cs.x, r * cs.y, z, z * BRDF_FRAC_1_PI);
}

// The pdf D_wo(m) of visible-normal sampling (Heitz 2014, eq. 38) for the model `model`
// (0 = GGX, 1 = Beckmann), wo taken in the upper hemisphere (|wo.z|).
fn sampling_visible_normal_pdf(
    model: u32, alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32,
    m_x: f32, m_y: f32, m_z: f32,
) -> f32 {
    let z = abs(wo_z);
    return select(ggx_Ggx_d_visible(alpha_x, alpha_y, wo_x, wo_y, z, m_x, m_y, m_z),
        beckmann_Beckmann_d_visible(alpha_x, alpha_y, wo_x, wo_y, z, m_x, m_y, m_z),
        model == 1u);
}

// The view stretched to the unit-roughness configuration, normalize(alpha_x x, alpha_y y, |z|).
fn brdf_stretch(wo: vec3<f32>, ax: f32, ay: f32) -> vec3<f32> {
    return brdf_normalize_or_z(vec3<f32>(ax * wo.x, ay * wo.y, abs(wo.z)));
}

// The microfacet normal from a visible normal of the stretched configuration.
fn brdf_unstretch(h: vec3<f32>, ax: f32, ay: f32) -> vec3<f32> {
    return brdf_normalize_or_z(vec3<f32>(ax * h.x, ay * h.y, max(h.z, 0.0)));
}

// GGX visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of Visible Normals",
// JCGT 7(4)): a uniform disk point squashed onto the half the stretched view sees, lifted to
// the hemisphere, unstretched; with its pdf D_wo(m).
fn sampling_ggx_vndf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let m = brdf_ggx_vndf_normal(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z), u1, u2);
    let pdf = ggx_Ggx_d_visible(alpha_x, alpha_y, wo_x, wo_y, abs(wo_z), m.x, m.y, m.z);
    return vec4<f32>(m, pdf);
}

// The normal of sampling_ggx_vndf without its pdf (for the samplers that weigh their sample by
// another density).
fn brdf_ggx_vndf_normal(alpha_x: f32, alpha_y: f32, wo: vec3<f32>, u1: f32, u2: f32) -> vec3<f32> {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let vh = brdf_stretch(wo, ax, ay);
    let len2 = fma(vh.x, vh.x, vh.y * vh.y);
    let has_tangent = len2 > 0.0;
    let inv_len = select(0.0, 1.0 / sqrt(len2), has_tangent);
    let t1 = vec3<f32>(select(1.0, -vh.y * inv_len, has_tangent), vh.x * inv_len, 0.0);
    // vh x t1 with t1.z = 0.
    let t2 = vec3<f32>(-vh.z * t1.y, vh.z * t1.x, vh.x * t1.y - vh.y * t1.x);
    let r = sqrt(brdf_clamp_u(u1));
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let p1 = r * cs.x;
    let s = 0.5 * (1.0 + vh.z);
    let p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * (r * cs.y);
    let lift = sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0));
    let nh = vec3<f32>(t1.x * p1 + t2.x * p2 + vh.x * lift, t1.y * p1 + t2.y * p2 + vh.y * lift,
        t1.z * p1 + t2.z * p2 + vh.z * lift);
    return brdf_unstretch(nh, ax, ay);
}

// The normal of sampling_ggx_vndf_spherical_cap without its pdf (for the samplers that weigh
// their sample by another density).
fn brdf_ggx_vndf_spherical_cap_normal(
    alpha_x: f32, alpha_y: f32, wo: vec3<f32>, u1: f32, u2: f32,
) -> vec3<f32> {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let v = brdf_stretch(wo, ax, ay);
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u1));
    let z = fma(1.0 - brdf_clamp_u(u2), 1.0 + v.z, -v.z);
    let sin_theta = sqrt(max(1.0 - z * z, 0.0));
    let h = vec3<f32>(sin_theta * cs.x + v.x, sin_theta * cs.y + v.y, z + v.z);
    return brdf_unstretch(h, ax, ay);
}

// GGX visible-normal sampling by spherical caps (Dupuy and Benyoub 2023, "Sampling Visible GGX
// Normals with Spherical Caps"): a uniform direction on the cap z >= -v.z around the
// stretched view, plus the view, unstretched; with its pdf D_wo(m).
fn sampling_ggx_vndf_spherical_cap(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let m = brdf_ggx_vndf_spherical_cap_normal(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z),
        u1, u2);
    let pdf = ggx_Ggx_d_visible(alpha_x, alpha_y, wo_x, wo_y, abs(wo_z), m.x, m.y, m.z);
    return vec4<f32>(m, pdf);
}

// The pdf of the reflected direction wi under GGX visible-normal sampling: D(h) / (4 (wo.z +
// wo.z Lambda(wo))) with h = normalize(wo + wi) (Heitz 2018, eq. 17 with Walter et al. 2007's
// Jacobian), capped at the largest finite f32; 0 where wo is at or below the horizon, wo.h <= 0
// or wi = 0.
fn sampling_ggx_reflection_pdf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let h = brdf_normalize_or_z(vec3<f32>(wo_x + wi_x, wo_y + wi_y, wo_z + wi_z));
    let c = wo_z;
    let inv = min(1.0 / (4.0 * (c + ggx_Ggx_cos_lambda(alpha_x, alpha_y, wo_x, wo_y, wo_z))),
        BRDF_F32_MAX);
    let wi_zero = (wi_x == 0.0) & (wi_y == 0.0) & (wi_z == 0.0);
    let wo_dot_h = fma(wo_x, h.x, fma(wo_y, h.y, wo_z * h.z));
    let visible = (c > 0.0) & (wo_dot_h > 0.0) & !wi_zero;
    let d = ggx_Ggx_d(alpha_x, alpha_y, h.x, h.y, h.z);
    return select(0.0, min(inv * d, BRDF_F32_MAX), visible);
}

// The pdf of the reflected direction wi under Beckmann visible-normal sampling: D(h) / (4 (wo.z
// + wo.z Lambda(wo))) with h = normalize(wo + wi) (Heitz and d'Eon 2014; Walter et al. 2007,
// eq. 14), capped at the largest finite f32; 0 where wo is at or below the horizon, wo.h <= 0
// or wi = 0. The same form as sampling_ggx_reflection_pdf.
fn sampling_beckmann_reflection_pdf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let h = brdf_normalize_or_z(vec3<f32>(wo_x + wi_x, wo_y + wi_y, wo_z + wi_z));
    let c = wo_z;
    let inv = min(1.0 / (4.0 * (c + beckmann_Beckmann_cos_lambda(alpha_x, alpha_y, wo_x, wo_y,
        wo_z))), BRDF_F32_MAX);
    let wi_zero = (wi_x == 0.0) & (wi_y == 0.0) & (wi_z == 0.0);
    let wo_dot_h = fma(wo_x, h.x, fma(wo_y, h.y, wo_z * h.z));
    let visible = (c > 0.0) & (wo_dot_h > 0.0) & !wi_zero;
    let d = beckmann_Beckmann_d(alpha_x, alpha_y, h.x, h.y, h.z);
    return select(0.0, min(inv * d, BRDF_F32_MAX), visible);
}

// The pdf D(m) max(m.z, 0) of sampling the normal from D cos (Walter et al. 2007, eq. 24) for
// the model `model` (0 = GGX, 1 = Beckmann).
fn sampling_d_cos_pdf(
    model: u32, alpha_x: f32, alpha_y: f32, m_x: f32, m_y: f32, m_z: f32,
) -> f32 {
    let d = select(ggx_Ggx_d(alpha_x, alpha_y, m_x, m_y, m_z),
        beckmann_Beckmann_d(alpha_x, alpha_y, m_x, m_y, m_z), model == 1u);
    return d * max(m_z, 0.0);
}

// GGX normal sampled from D cos (Walter et al. 2007, eqs. 35-36, anisotropic through the
// slopes): slope radius sqrt(u1 / (1 - u1)) at the angle 2 pi u2, the normal
// normalize(-alpha_x s_x, -alpha_y s_y, 1); with its pdf D(m) m.z.
fn sampling_ggx_d_cos(alpha_x: f32, alpha_y: f32, u1: f32, u2: f32) -> vec4<f32> {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let uc1 = brdf_clamp_u(u1);
    let r = sqrt(uc1 / (1.0 - uc1));
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let m = brdf_normalize_or_z(vec3<f32>(-ax * (r * cs.x), -ay * (r * cs.y), 1.0));
    return vec4<f32>(m, sampling_d_cos_pdf(0u, alpha_x, alpha_y, m.x, m.y, m.z));
}

// The GGX reflection sample without its Fresnel factor (the Rust kernel's reflection_parts):
// (wi, pdf, G2 / G1(wo), wo.m) for the visible normal m of sampling_ggx_vndf_spherical_cap,
// wi = 2 (wo.m) m - wo, pdf = sampling_ggx_reflection_pdf(wo, wi). G2 / G1(wo) =
// (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)) is written pole-free as
// |i.z| (|o.z| + s_o) / (|i.z| s_o + |o.z| s_i), s = sqrt(z^2 + q) of each direction
// (brdf_ggx_smith; Lambda = (s - |z|) / (2 |z|)): the Rust kernel's form with each Lambda
// capped at f32's largest value would leave f32's range in the sum. 0 unless wo and wi lie
// above the horizon.
fn brdf_sampling_ggx_reflection_parts(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> array<f32, 6> {
    let m = sampling_ggx_vndf_spherical_cap(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    let o_m = fma(wo_x, m.x, fma(wo_y, m.y, wo_z * m.z));
    let k = 2.0 * o_m;
    let wi = vec3<f32>(m.x * k - wo_x, m.y * k - wo_y, m.z * k - wo_z);
    let pdf = sampling_ggx_reflection_pdf(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi.x, wi.y, wi.z);
    let o = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let i = brdf_ggx_smith(alpha_x, alpha_y, wi);
    let den = i.x * o.z + o.x * i.z;
    let above = (wo_z > 0.0) & (wi.z > 0.0);
    // The floor keeps the unused branch finite where both cosines are 0.
    let ratio = select(0.0, i.x * (o.x + o.z) / max(den, 1.17549435e-38), above);
    return array<f32, 6>(wi.x, wi.y, wi.z, pdf, ratio, saturate(o_m));
}

// Samples the Cook-Torrance reflection lobe of a GGX surface with a constant Fresnel factor F
// (>= 0): (wi.x, wi.y, wi.z, pdf, weight) with the visible normal m of
// sampling_ggx_vndf_spherical_cap (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals"; Dupuy and Benyoub 2023), wi = 2 (wo.m) m - wo, pdf =
// sampling_ggx_reflection_pdf(wo, wi) and the weight f wi.z / pdf = F G2 / G1(wo) capped at
// the largest finite f32 (D and the cosines cancel; Heitz and d'Eon 2014). A wi reflected
// below the horizon keeps its pdf with weight 0; wo at or below the horizon gives pdf 0 and
// weight 0. u1, u2 clamped into [0, 1).
fn sampling_ggx_reflection(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
    fresnel: f32,
) -> array<f32, 5> {
    let p = brdf_sampling_ggx_reflection_parts(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    return array<f32, 5>(p[0], p[1], p[2], p[3], min(p[4] * fresnel, BRDF_F32_MAX));
}

// sampling_ggx_reflection with a constant RGB Fresnel factor: (wi.x, wi.y, wi.z, pdf,
// weight_r, weight_g, weight_b), the weight F_c G2 / G1(wo) per channel.
fn sampling_ggx_reflection_rgb(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
    fresnel_r: f32, fresnel_g: f32, fresnel_b: f32,
) -> array<f32, 7> {
    let p = brdf_sampling_ggx_reflection_parts(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    return array<f32, 7>(p[0], p[1], p[2], p[3], min(p[4] * fresnel_r, BRDF_F32_MAX),
        min(p[4] * fresnel_g, BRDF_F32_MAX), min(p[4] * fresnel_b, BRDF_F32_MAX));
}
