// brdf: the Cook-Torrance specular assembly, the twins of the Rust module `cook_torrance`
// (the half-vector cosines and the isotropic GGX lobes from dot products: constant F, Schlick
// RGB, exact dielectric). Needs common.wgsl, ggx.wgsl and fresnel.wgsl. The generic forms over
// a microfacet model, the conductor lobes and the Beckmann lobes have no twin yet.

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
