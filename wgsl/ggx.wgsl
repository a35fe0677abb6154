// brdf: GGX (Trowbridge-Reitz) microfacet terms, the twins of the Rust module `ggx`.
// Needs common.wgsl. Every alpha is the width (alpha = r^2 for a perceptual roughness r),
// clamped to [BRDF_ALPHA_MIN, BRDF_ALPHA_MAX].

// Isotropic GGX NDF (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 33): D = alpha^2 / (pi t^2), t = (1 - c)(1 + c) + c^2 alpha^2 for
// c = n_dot_h in (0, 1], 0 for c <= 0. t is the cancellation-free rewrite of
// 1 + c^2 (alpha^2 - 1): at alpha = 7e-3 near c = 1 the textbook form loses every digit of
// alpha^2 in f32. Rust's `ggx::d` is correctly rounded; this twin rounds each operation.
fn ggx_d(n_dot_h: f32, alpha: f32) -> f32 {
    let a = brdf_clamp_alpha(alpha);
    let c = min(n_dot_h, 1.0);
    let a2 = a * a;
    let t = brdf_one_minus_sq(c) + (c * c) * a2;
    let d = min(a2 / (t * t * BRDF_PI), BRDF_F32_MAX);
    return brdf_above(n_dot_h, d);
}

// The fast form of the same NDF (Guy and Agopian 2018, "Physically Based Rendering in
// Filament", D_GGX): k = alpha / ((1 - c^2) + (c alpha)^2), D = k^2 / pi.
fn ggx_d_fast(n_dot_h: f32, alpha: f32) -> f32 {
    let a = brdf_clamp_alpha(alpha);
    let c = min(n_dot_h, 1.0);
    let ca = c * a;
    let k = a / (ca * ca + brdf_sin2(c));
    let d = min(k * k * BRDF_FRAC_1_PI, BRDF_F32_MAX);
    return brdf_above(n_dot_h, d);
}

// Anisotropic GGX NDF from the half vector's shading-frame components (Heitz 2014,
// "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 85):
// D = 1 / (pi ax ay ((t.h / ax)^2 + (b.h / ay)^2 + (n.h)^2)^2), 0 for n_dot_h <= 0.
fn ggx_d_aniso(n_dot_h: f32, t_dot_h: f32, b_dot_h: f32, alpha_x: f32, alpha_y: f32) -> f32 {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let u = t_dot_h / ax;
    let v = b_dot_h / ay;
    let t = u * u + v * v + n_dot_h * n_dot_h;
    let d = min(1.0 / (ax * ay * (t * t) * BRDF_PI), BRDF_F32_MAX);
    return brdf_above(n_dot_h, d);
}

// Smith Lambda of isotropic GGX (Heitz 2014, eq. 86), (sqrt(1 + alpha^2 tan^2) - 1) / 2 without
// cancellation: q / (2 c (sqrt(c^2 + q) + c)), q = alpha^2 (1 - c)(1 + c), c = |n_dot_v|
// clamped to 1. The pole at c = 0 is capped at the largest finite f32.
fn ggx_lambda(n_dot_v: f32, alpha: f32) -> f32 {
    let c = min(abs(n_dot_v), 1.0);
    let a = brdf_clamp_alpha(alpha);
    let q = (a * a) * brdf_one_minus_sq(c);
    let den = 2.0 * c * (sqrt(c * c + q) + c);
    return select(BRDF_F32_MAX, min(q / den, BRDF_F32_MAX), den > 0.0);
}

// Smith masking of isotropic GGX (Walter et al. 2007, eq. 34): G1 = 2c / (c + sqrt(c^2 + q)),
// q as in ggx_lambda; 1 at c = 1, 0 at c = 0.
fn ggx_g1(n_dot_v: f32, alpha: f32) -> f32 {
    let c = min(abs(n_dot_v), 1.0);
    let a = brdf_clamp_alpha(alpha);
    let q = (a * a) * brdf_one_minus_sq(c);
    return (2.0 * c) / (sqrt(c * c + q) + c);
}

// Height-correlated Smith visibility (Heitz 2014, eq. 99; Lagarde and de Rousiers 2014,
// "Moving Frostbite to PBR"): V = 0.5 / (NoL s_v + NoV s_l), s = sqrt(c^2 + alpha^2 (1 - c^2)),
// cosines clamped to [0, 1]; 0 when both are 0, capped at the largest finite f32.
fn ggx_v_correlated(n_dot_v: f32, n_dot_l: f32, alpha: f32) -> f32 {
    let cv = saturate(n_dot_v);
    let cl = saturate(n_dot_l);
    let a2 = brdf_clamp_alpha(alpha) * brdf_clamp_alpha(alpha);
    let sv = sqrt(cv * cv + a2 * brdf_one_minus_sq(cv));
    let sl = sqrt(cl * cl + a2 * brdf_one_minus_sq(cl));
    let den = sv * cl + sl * cv;
    return select(0.0, min(0.5 / den, BRDF_F32_MAX), den > 0.0);
}

// 0.5 / den for den > 0 (capped), 0 otherwise: the guard shared by the fast V forms.
fn brdf_ggx_half_over(den: f32) -> f32 {
    return select(0.0, min(0.5 / den, BRDF_F32_MAX), den > 0.0);
}

// Hammon's approximation of the correlated visibility (Hammon 2017, "PBR Diffuse Lighting for
// GGX+Smith Microsurfaces"): V = 0.5 / lerp(2 NoL NoV, NoL + NoV, alpha).
fn ggx_v_correlated_hammon(n_dot_v: f32, n_dot_l: f32, alpha: f32) -> f32 {
    let cv = saturate(n_dot_v);
    let cl = saturate(n_dot_l);
    let a = brdf_clamp_alpha(alpha);
    let two_lv = 2.0 * cl * cv;
    return brdf_ggx_half_over(two_lv + a * (cl + cv - two_lv));
}

// Filament's fast visibility (Guy and Agopian 2018, V_SmithGGXCorrelated_Fast):
// V = 0.5 / (NoL (NoV (1 - alpha) + alpha) + NoV (NoL (1 - alpha) + alpha)).
fn ggx_v_correlated_fast(n_dot_v: f32, n_dot_l: f32, alpha: f32) -> f32 {
    let cv = saturate(n_dot_v);
    let cl = saturate(n_dot_l);
    let a = brdf_clamp_alpha(alpha);
    let one_minus_a = 1.0 - a;
    return brdf_ggx_half_over(cl * fma(cv, one_minus_a, a) + cv * fma(cl, one_minus_a, a));
}

// Schlick's G1 (Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering";
// Karis 2013, "Real Shading in Unreal Engine 4"): c / (c + k (1 - c)), a sum of non-negative
// terms (the printed c (1 - k) + k cancels for large k). k > 0.
fn ggx_g1_schlick(n_dot_v: f32, k: f32) -> f32 {
    let c = saturate(n_dot_v);
    return c / fma(k, 1.0 - c, c);
}

// k = alpha / 2 (Karis 2013, for image-based lighting).
fn ggx_schlick_k_ibl(alpha: f32) -> f32 {
    return brdf_clamp_alpha(alpha) * 0.5;
}

// k = (r + 1)^2 / 8 from the perceptual roughness r, clamped to 100 (Karis 2013, analytic
// lights).
fn ggx_schlick_k_analytic(perceptual_roughness: f32) -> f32 {
    let r1 = min(perceptual_roughness, 100.0) + 1.0;
    return r1 * r1 * 0.125;
}

// Separable Schlick-GGX visibility 1 / (4 (NoV + k (1 - NoV)) (NoL + k (1 - NoL))), cosines
// clamped to [0, 1], capped at the largest finite f32.
fn ggx_v_schlick(n_dot_v: f32, n_dot_l: f32, k: f32) -> f32 {
    let cv = saturate(n_dot_v);
    let cl = saturate(n_dot_l);
    let den = 4.0 * fma(k, 1.0 - cv, cv) * fma(k, 1.0 - cl, cl);
    return select(0.0, min(1.0 / den, BRDF_F32_MAX), den > 0.0);
}

// The anisotropic distribution `ggx::Ggx` as functions of its constructor's arguments
// (alpha_x, alpha_y) and local-frame directions (the normal is z). A zero direction takes the
// horizon's values, as in the Rust methods.

// |z|, q = (alpha_x x)^2 + (alpha_y y)^2 and s = sqrt(z^2 + q) of a direction.
fn brdf_ggx_smith(alpha_x: f32, alpha_y: f32, w: vec3<f32>) -> vec3<f32> {
    let v = brdf_horizon_if_zero(w);
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let c = abs(v.z);
    let px = ax * v.x;
    let py = ay * v.y;
    let q = px * px + py * py;
    return vec3<f32>(c, q, sqrt(c * c + q));
}

// D(m) = 1 / (pi ax ay ((x / ax)^2 + (y / ay)^2 + z^2)^2) for m.z > 0, else 0 (Heitz 2014,
// eq. 85).
fn ggx_Ggx_d(alpha_x: f32, alpha_y: f32, m_x: f32, m_y: f32, m_z: f32) -> f32 {
    return ggx_d_aniso(m_z, m_x, m_y, alpha_x, alpha_y);
}

// Lambda(w) = q / (2 |z| (s + |z|)) (Heitz 2014, eq. 86 on vectors), the pole at the horizon
// capped at the largest finite f32.
fn ggx_Ggx_lambda(alpha_x: f32, alpha_y: f32, w_x: f32, w_y: f32, w_z: f32) -> f32 {
    let m = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(w_x, w_y, w_z));
    let den = (m.z + m.x) * (2.0 * m.x);
    return select(BRDF_F32_MAX, min(m.y / den, BRDF_F32_MAX), den > 0.0);
}

// |z| Lambda = q / (2 (sqrt(z^2 + q) + |z|)): alpha sin(theta) / 2 at the horizon.
fn ggx_Ggx_cos_lambda(alpha_x: f32, alpha_y: f32, w_x: f32, w_y: f32, w_z: f32) -> f32 {
    let m = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(w_x, w_y, w_z));
    return m.y / (2.0 * (m.z + m.x));
}

// G1(w) = 2 |z| / (|z| + s) (Walter et al. 2007, eq. 34 on vectors).
fn ggx_Ggx_g1(alpha_x: f32, alpha_y: f32, w_x: f32, w_y: f32, w_z: f32) -> f32 {
    let m = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(w_x, w_y, w_z));
    return (2.0 * m.x) / (m.x + m.z);
}

// The separable G2 = G1(wo) G1(wi) (Heitz 2014, eq. 98).
fn ggx_Ggx_g2_separable(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return ggx_Ggx_g1(alpha_x, alpha_y, wo_x, wo_y, wo_z)
        * ggx_Ggx_g1(alpha_x, alpha_y, wi_x, wi_y, wi_z);
}

// The height-correlated G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014, eq. 99) as
// 2 |o.z| |i.z| / (|i.z| s_o + |o.z| s_i), capped at 1; 0 where both are at the horizon.
fn ggx_Ggx_g2_correlated(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let o = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let i = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(wi_x, wi_y, wi_z));
    let den = o.z * i.x + i.z * o.x;
    return select(0.0, min(2.0 * o.x * i.x / den, 1.0), den > 0.0);
}

// V = G2 / (4 |o.z| |i.z|) = 0.5 / (|i.z| s_o + |o.z| s_i), capped at the largest finite f32;
// 0 where both are at the horizon.
fn ggx_Ggx_v_correlated(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let o = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let i = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(wi_x, wi_y, wi_z));
    return brdf_ggx_half_over(o.z * i.x + i.z * o.x);
}

// The distribution of visible normals D_wo(m) = G1(wo) max(0, wo.m) D(m) / |wo.z| (Heitz 2014,
// eq. 38), G1 / |wo.z| = 1 / (|wo.z| + |wo.z| Lambda) finite at the horizon (0 there).
fn ggx_Ggx_d_visible(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, m_x: f32, m_y: f32, m_z: f32,
) -> f32 {
    let c = abs(wo_z);
    let cl = ggx_Ggx_cos_lambda(alpha_x, alpha_y, wo_x, wo_y, wo_z);
    let g1_over_cos = select(0.0, 1.0 / (c + cl), c > 0.0);
    let cos_om = max(fma(wo_x, m_x, fma(wo_y, m_y, wo_z * m_z)), 0.0);
    let d = ggx_Ggx_d(alpha_x, alpha_y, m_x, m_y, m_z);
    return min(min(g1_over_cos * cos_om, BRDF_F32_MAX) * d, BRDF_F32_MAX);
}
