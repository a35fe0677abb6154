// brdf: the Cook-Torrance specular assembly, the twins of the Rust module `cook_torrance`
// (the half vector and its cosines, the forms over a microfacet model on local-frame
// directions, and the isotropic GGX and Beckmann lobes from dot products: constant F, Schlick
// RGB, exact dielectric, exact conductor). Needs common.wgsl, ggx.wgsl, fresnel.wgsl and
// beckmann.wgsl.

// n.h = s.z / |s| and v.h = |s| / 2 (capped at 1) for s = wo + wi, without forming the half
// vector (Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces",
// eq. 13); n.h = 1 where s = 0. Local-frame directions (the normal is z).
fn cook_torrance_half_cosines(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> vec2<f32> {
    let sx = wo_x + wi_x;
    let sy = wo_y + wi_y;
    let sz = wo_z + wi_z;
    // |s|^2 in the order of the Rust V3::dot: z^2 first.
    let len = sqrt(fma(sx, sx, fma(sy, sy, sz * sz)));
    let n_dot_h = select(sz / len, 1.0, len == 0.0);
    return vec2<f32>(n_dot_h, min(0.5 * len, 1.0));
}

// D V F capped at the largest finite f32, 0 where n.v or n.l is <= 0 (domain::above_horizon).
fn brdf_cook_torrance_assemble(dv: f32, n_dot_v: f32, n_dot_l: f32, fresnel: f32) -> f32 {
    let value = min(min(dv, BRDF_F32_MAX) * fresnel, BRDF_F32_MAX);
    return select(0.0, value, (n_dot_v > 0.0) & (n_dot_l > 0.0));
}

// Isotropic GGX Cook-Torrance from dot products (Cook and Torrance 1982, "A Reflectance Model
// for Computer Graphics"; Walter et al. 2007; Heitz 2014, eq. 99):
// f = D(n.h) V(n.v, n.l) F with the height-correlated V = G2 / (4 n.l n.v) and a constant F.
fn cook_torrance_ggx(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32, fresnel: f32,
) -> f32 {
    let dv = ggx_d(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha);
    return brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, fresnel);
}

// GGX with Schlick's Fresnel of an RGB F0 at v.h (clamped to [0, 1]), per channel: the
// specular lobe of glTF, Filament and Unreal Engine 4 (Schlick 1994; Karis 2013).
fn cook_torrance_ggx_schlick_rgb(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32,
    f0_r: f32, f0_g: f32, f0_b: f32,
) -> vec3<f32> {
    let f = fresnel_schlick_rgb(f0_r, f0_g, f0_b, saturate(v_dot_h));
    let dv = ggx_d(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha);
    return vec3<f32>(
        brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f.x),
        brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f.y),
        brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f.z),
    );
}

// Rough dielectric reflection: isotropic GGX with the exact dielectric Fresnel at v.h (clamped
// to [0, 1]) (Walter et al. 2007; Born and Wolf 1.5.2).
fn cook_torrance_ggx_dielectric(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32, eta: f32,
) -> f32 {
    let f = fresnel_dielectric(saturate(v_dot_h), eta);
    let dv = ggx_d(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha);
    return brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f);
}

// The working-precision tier of cook_torrance_ggx_dielectric (cook_torrance::
// ggx_dielectric_fast): D from ggx_d_fast, V from ggx_v_correlated, F from
// fresnel_dielectric_fast at v.h clamped to [0, 1] (Walter et al. 2007; Born and Wolf 1.5.2).
fn cook_torrance_ggx_dielectric_fast(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32, eta: f32,
) -> f32 {
    let f = fresnel_dielectric_fast(saturate(v_dot_h), eta);
    let dv = ggx_d_fast(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha);
    return brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f);
}

// The half vector h = normalize(wo + wi) (the normal (0, 0, 1) where wo + wi = 0) and
// v.h = wo.h clamped to [0, 1] (Walter et al. 2007, eq. 13); |s|^2 and the dot products in the
// order of the Rust V3::dot (z's product first).
fn cook_torrance_half_vector(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> vec4<f32> {
    let s = vec3<f32>(wo_x + wi_x, wo_y + wi_y, wo_z + wi_z);
    let len2 = fma(s.x, s.x, fma(s.y, s.y, s.z * s.z));
    let ok = len2 > 0.0;
    let inv = select(0.0, 1.0 / sqrt(len2), ok);
    let h = vec3<f32>(select(0.0, s.x * inv, ok), select(0.0, s.y * inv, ok),
        select(1.0, s.z * inv, ok));
    let v_dot_h = saturate(fma(wo_x, h.x, fma(wo_y, h.y, wo_z * h.z)));
    return vec4<f32>(h, v_dot_h);
}

// D(h) V(wo, wi) of the model (0 = GGX, 1 = Beckmann) with widths (alpha_x, alpha_y), capped at
// the largest finite f32, 0 below the horizon; and v.h.
fn brdf_cook_torrance_masked_dv(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> vec2<f32> {
    let hv = cook_torrance_half_vector(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    let beckmann = model == 1u;
    let d = select(ggx_Ggx_d(alpha_x, alpha_y, hv.x, hv.y, hv.z),
        beckmann_Beckmann_d(alpha_x, alpha_y, hv.x, hv.y, hv.z), beckmann);
    let v = select(
        ggx_Ggx_v_correlated(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi_x, wi_y, wi_z),
        beckmann_Beckmann_v_correlated(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi_x, wi_y, wi_z),
        beckmann);
    let dv = select(0.0, min(d * v, BRDF_F32_MAX), (wo_z > 0.0) & (wi_z > 0.0));
    return vec2<f32>(dv, hv.w);
}

// Cook-Torrance f = D(h) V(wo, wi) F on local-frame directions (Cook and Torrance 1982; Heitz
// 2014, eq. 99) for the microfacet model `model` (0 = GGX, 1 = Beckmann) and a constant F,
// capped at the largest finite f32.
fn cook_torrance_eval(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, fresnel: f32,
) -> f32 {
    let dv = brdf_cook_torrance_masked_dv(model, alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z);
    return min(dv.x * fresnel, BRDF_F32_MAX);
}

// cook_torrance_eval with the exact dielectric Fresnel at v.h (Born and Wolf 1.5.2).
fn cook_torrance_dielectric(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32,
) -> f32 {
    let dv = brdf_cook_torrance_masked_dv(model, alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z);
    return min(dv.x * fresnel_dielectric(dv.y, eta), BRDF_F32_MAX);
}

// cook_torrance_eval with the exact conductor Fresnel of eta + i k at v.h (Born and Wolf 14.2).
fn cook_torrance_conductor(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32, k: f32,
) -> f32 {
    let dv = brdf_cook_torrance_masked_dv(model, alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z);
    return min(dv.x * fresnel_conductor(dv.y, eta, k), BRDF_F32_MAX);
}

// cook_torrance_eval with a constant RGB F, per channel.
fn cook_torrance_eval_rgb(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
    fresnel_r: f32, fresnel_g: f32, fresnel_b: f32,
) -> vec3<f32> {
    let dv = brdf_cook_torrance_masked_dv(model, alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z);
    return vec3<f32>(min(dv.x * fresnel_r, BRDF_F32_MAX), min(dv.x * fresnel_g, BRDF_F32_MAX),
        min(dv.x * fresnel_b, BRDF_F32_MAX));
}

// D V of the isotropic Beckmann from dot products: D(n.h) and the height-correlated V of the
// directions (sin, 0, cos) with the two cosines clamped to [0, 1].
fn brdf_cook_torrance_beckmann_dv(n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, alpha: f32) -> f32 {
    let cv = saturate(n_dot_v);
    let cl = saturate(n_dot_l);
    let v = beckmann_Beckmann_v_correlated(alpha, alpha, sqrt(brdf_one_minus_sq(cv)), 0.0, cv,
        sqrt(brdf_one_minus_sq(cl)), 0.0, cl);
    return beckmann_d(n_dot_h, alpha) * v;
}

// Beckmann Cook-Torrance from dot products (Walter et al. 2007; Heitz 2014, eq. 99):
// f = D(n.h) G2 / (4 n.l n.v) F with the height-correlated G2 and a constant F.
fn cook_torrance_beckmann(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32, fresnel: f32,
) -> f32 {
    let dv = brdf_cook_torrance_beckmann_dv(n_dot_v, n_dot_l, n_dot_h, alpha);
    return brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, fresnel);
}

// D V times an RGB F, per channel, assembled as brdf_cook_torrance_assemble.
fn brdf_cook_torrance_assemble_rgb(dv: f32, n_dot_v: f32, n_dot_l: f32, f: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f.x),
        brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f.y),
        brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f.z),
    );
}

// Rough conductor: isotropic GGX with the exact conductor Fresnel of RGB eta + i k at v.h
// (clamped to [0, 1]) (Cook and Torrance 1982; Born and Wolf 14.2).
fn cook_torrance_ggx_conductor_rgb(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32,
    eta_r: f32, eta_g: f32, eta_b: f32, k_r: f32, k_g: f32, k_b: f32,
) -> vec3<f32> {
    let f = fresnel_conductor_rgb(saturate(v_dot_h), eta_r, eta_g, eta_b, k_r, k_g, k_b);
    let dv = ggx_d(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha);
    return brdf_cook_torrance_assemble_rgb(dv, n_dot_v, n_dot_l, f);
}

// The working-precision rough conductor: Filament's D_GGX (ggx_d_fast) and conductor_fast.
fn cook_torrance_ggx_conductor_rgb_fast(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32,
    eta_r: f32, eta_g: f32, eta_b: f32, k_r: f32, k_g: f32, k_b: f32,
) -> vec3<f32> {
    let c = saturate(v_dot_h);
    let f = vec3<f32>(fresnel_conductor_fast(c, eta_r, k_r), fresnel_conductor_fast(c, eta_g, k_g),
        fresnel_conductor_fast(c, eta_b, k_b));
    let dv = ggx_d_fast(n_dot_h, alpha) * ggx_v_correlated(n_dot_v, n_dot_l, alpha);
    return brdf_cook_torrance_assemble_rgb(dv, n_dot_v, n_dot_l, f);
}

// Rough conductor with the isotropic Beckmann: exact conductor Fresnel per channel.
fn cook_torrance_beckmann_conductor_rgb(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32,
    eta_r: f32, eta_g: f32, eta_b: f32, k_r: f32, k_g: f32, k_b: f32,
) -> vec3<f32> {
    let f = fresnel_conductor_rgb(saturate(v_dot_h), eta_r, eta_g, eta_b, k_r, k_g, k_b);
    let dv = brdf_cook_torrance_beckmann_dv(n_dot_v, n_dot_l, n_dot_h, alpha);
    return brdf_cook_torrance_assemble_rgb(dv, n_dot_v, n_dot_l, f);
}

// The isotropic Beckmann with Schlick's Fresnel of an RGB F0 at v.h (Schlick 1994).
fn cook_torrance_beckmann_schlick_rgb(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32,
    f0_r: f32, f0_g: f32, f0_b: f32,
) -> vec3<f32> {
    let f = fresnel_schlick_rgb(f0_r, f0_g, f0_b, saturate(v_dot_h));
    let dv = brdf_cook_torrance_beckmann_dv(n_dot_v, n_dot_l, n_dot_h, alpha);
    return brdf_cook_torrance_assemble_rgb(dv, n_dot_v, n_dot_l, f);
}

// Rough dielectric reflection with the isotropic Beckmann and the exact dielectric Fresnel.
fn cook_torrance_beckmann_dielectric(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, alpha: f32, eta: f32,
) -> f32 {
    let f = fresnel_dielectric(saturate(v_dot_h), eta);
    let dv = brdf_cook_torrance_beckmann_dv(n_dot_v, n_dot_l, n_dot_h, alpha);
    return brdf_cook_torrance_assemble(dv, n_dot_v, n_dot_l, f);
}

// The working-precision rough conductor, GGX, one channel, from local-frame directions (the
// Rust kernel's ggx_conductor_local_fast; Walter et al. 2007; Born and Wolf 14.2): with
// s = wo + wi, D V = alpha^2 |s|^4 / (2 pi (s_x^2 + s_y^2 + alpha^2 s_z^2)^2 den) in one
// division, den = n.l sqrt(alpha^2 + n.v^2 (1 - alpha^2)) + n.v sqrt(alpha^2 + n.l^2 (1 -
// alpha^2)) (the roots written alpha^2 sin^2 + cos^2, sin^2 without cancellation), the
// divisor floored at f32's smallest normal as in the Rust kernel, capped at the largest finite
// f32; times F = fresnel_conductor_fast(v.h, eta, k) with v.h = wo.s / |s|; 0 unless both
// directions lie above the horizon. alpha clamped to [ALPHA_MIN, ALPHA_MAX].
fn cook_torrance_ggx_conductor_local_fast(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, alpha: f32, eta: f32,
    k: f32,
) -> f32 {
    let a = brdf_clamp_alpha(alpha);
    let sx = wo_x + wi_x;
    let sy = wo_y + wi_y;
    let sz = wo_z + wi_z;
    let sxy = fma(sx, sx, sy * sy);
    let ss = fma(sz, sz, sxy);
    // Above the horizon s.z > 0, so |s| > 0: the select only keeps the unused branch finite.
    let len = sqrt(ss);
    let v_dot_h = saturate(select(fma(wo_x, sx, fma(wo_y, sy, wo_z * sz)) / len, 1.0,
        len == 0.0));
    let f = fresnel_conductor_fast(v_dot_h, eta, k);
    let a2 = a * a;
    let t = fma(a2, sz * sz, sxy);
    let cv = saturate(wo_z);
    let cl = saturate(wi_z);
    let rv = sqrt(fma(a2, brdf_sin2(cv), cv * cv));
    let rl = sqrt(fma(a2, brdf_sin2(cl), cl * cl));
    let den = fma(cl, rv, cv * rl);
    let dv = min((a2 * (0.5 * BRDF_FRAC_1_PI)) * (ss * ss) / max((t * t) * den, 1.17549435e-38),
        BRDF_F32_MAX);
    return select(0.0, dv * f, (wo_z > 0.0) & (wi_z > 0.0));
}
