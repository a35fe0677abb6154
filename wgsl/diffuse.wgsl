// brdf: diffuse lobes, the twins of the Rust module `diffuse` (Lambert, the qualitative
// Oren-Nayar model and its A and B, Burley and its renormalized form, the diffuse-Fresnel
// couplings, and the parameter types' `eval` on local-frame directions). Needs common.wgsl and
// fresnel.wgsl. The full and Fujii Oren-Nayar forms and EON with its albedos and samplers have
// no twin yet.

// 0 unless both cosines are above the horizon (domain::above_horizon).
fn brdf_above_horizon(n_dot_v: f32, n_dot_l: f32, value: f32) -> f32 {
    return select(0.0, value, (n_dot_v > 0.0) & (n_dot_l > 0.0));
}

// Lambert's lobe rho / pi above the horizon (Lambert 1760, "Photometria").
fn diffuse_lambert(n_dot_v: f32, n_dot_l: f32, rho: f32) -> f32 {
    return brdf_above_horizon(n_dot_v, n_dot_l, rho * BRDF_FRAC_1_PI);
}

// s^2 / (s^2 + c) for the roughness sigma (radians) capped at 2^40, above which it rounds to 1.
fn brdf_oren_nayar_rational(sigma: f32, c: f32) -> f32 {
    let s = min(sigma, 1099511627776.0);
    let s2 = s * s;
    return s2 / (s2 + c);
}

// Oren and Nayar's A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33) (Oren and Nayar 1994, "Generalization
// of Lambert's Reflectance Model", the qualitative model).
fn diffuse_oren_nayar_a(sigma: f32) -> f32 {
    return 1.0 - 0.5 * brdf_oren_nayar_rational(sigma, 0.33);
}

// Oren and Nayar's B = 0.45 sigma^2 / (sigma^2 + 0.09) (Oren and Nayar 1994).
fn diffuse_oren_nayar_b(sigma: f32) -> f32 {
    return brdf_oren_nayar_rational(sigma, 0.09) * 0.45;
}

// The qualitative Oren-Nayar lobe (Oren and Nayar 1994): rho / pi (A + B max(0, s) / cos_beta),
// s = v.l - n.v n.l = cos(phi) sin(theta_i) sin(theta_o), cos_beta = max(n.v, n.l); s is taken
// as 0 at a pole (a cosine of 1), where phi is undefined.
fn diffuse_oren_nayar(n_dot_v: f32, n_dot_l: f32, v_dot_l: f32, rho: f32, sigma: f32) -> f32 {
    let a = diffuse_oren_nayar_a(sigma);
    let b = diffuse_oren_nayar_b(sigma);
    let cos_beta = max(n_dot_v, n_dot_l);
    let s0 = fma(-n_dot_v, n_dot_l, v_dot_l);
    let s = select(0.0, s0, (s0 > 0.0) & (cos_beta < 1.0));
    // The smallest normal f32 keeps the quotient finite at grazing cos_beta.
    let lobe = s / max(cos_beta, 1.17549435e-38);
    return brdf_above_horizon(n_dot_v, n_dot_l, BRDF_FRAC_1_PI * rho * fma(b, lobe, a));
}

// 1 + (F_D90 - 1)(1 - c)^5 for c clamped to [0, 1]: one of Burley's two Fresnel factors.
fn brdf_burley_factor(fd90_minus_1: f32, c: f32) -> f32 {
    let y = 1.0 - saturate(c);
    let y2 = y * y;
    return fma(fd90_minus_1, y2 * y2 * y, 1.0);
}

// Burley's diffuse from cos^2(theta_d) (the half angle's, (l.h)^2): the shared core of
// diffuse_burley and diffuse_Burley_eval.
fn brdf_burley_core(n_dot_v: f32, n_dot_l: f32, cos2_d: f32, rho: f32, roughness: f32) -> f32 {
    let fd90_minus_1 = fma(cos2_d, 2.0 * roughness, -0.5);
    let f = BRDF_FRAC_1_PI * rho * brdf_burley_factor(fd90_minus_1, n_dot_l)
        * brdf_burley_factor(fd90_minus_1, n_dot_v);
    return brdf_above_horizon(n_dot_v, n_dot_l, f);
}

// Burley's diffuse (Burley 2012, "Physically-Based Shading at Disney"): rho / pi
// (1 + (F_D90 - 1)(1 - n.l)^5)(1 + (F_D90 - 1)(1 - n.v)^5), F_D90 = 1/2 + 2 r (l.h)^2 for the
// perceptual roughness r, l.h clamped to [0, 1]; 0 below the horizon.
fn diffuse_burley(n_dot_v: f32, n_dot_l: f32, l_dot_h: f32, rho: f32, roughness: f32) -> f32 {
    let lh = saturate(l_dot_h);
    return brdf_burley_core(n_dot_v, n_dot_l, lh * lh, rho, roughness);
}

// The renormalized core from cos^2(theta_d).
fn brdf_burley_renormalized_core(
    n_dot_v: f32, n_dot_l: f32, cos2_d: f32, rho: f32, roughness: f32,
) -> f32 {
    let fd90_minus_1 = fma(fma(2.0, cos2_d, 0.5), roughness, -1.0);
    // 1 - 1 / 1.51.
    let k = fma(0.33774834437086093, -roughness, 1.0);
    let f = BRDF_FRAC_1_PI * rho * k * brdf_burley_factor(fd90_minus_1, n_dot_l)
        * brdf_burley_factor(fd90_minus_1, n_dot_v);
    return brdf_above_horizon(n_dot_v, n_dot_l, f);
}

// Burley's diffuse renormalized for energy with the GGX specular (Lagarde and de Rousiers
// 2014, "Moving Frostbite to PBR", listing 1): F_D90 = r (1/2 + 2 (l.h)^2), times
// energyFactor = 1 - r (1 - 1 / 1.51).
fn diffuse_burley_renormalized(
    n_dot_v: f32, n_dot_l: f32, l_dot_h: f32, rho: f32, roughness: f32,
) -> f32 {
    let lh = saturate(l_dot_h);
    return brdf_burley_renormalized_core(n_dot_v, n_dot_l, lh * lh, rho, roughness);
}

// wo.wi in the order of the Rust V3::dot (z's product first).
fn brdf_diffuse_dot(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return fma(wo_x, wi_x, fma(wo_y, wi_y, wo_z * wi_z));
}

// cos^2(theta_d) = (1 + wo.wi) / 2 from the directions, clamped to [0, 1].
fn brdf_cos2_d(wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32) -> f32 {
    return saturate((1.0 + brdf_diffuse_dot(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z)) * 0.5);
}

// `diffuse::Lambert` on local-frame directions: diffuse_lambert(wo.z, wi.z, rho).
fn diffuse_Lambert_eval(
    rho: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return diffuse_lambert(wo_z, wi_z, rho);
}

// `diffuse::OrenNayar` on local-frame directions: the qualitative lobe with v.l = wo.wi.
fn diffuse_OrenNayar_eval(
    rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let v_dot_l = brdf_diffuse_dot(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return diffuse_oren_nayar(wo_z, wi_z, v_dot_l, rho, sigma);
}

// `diffuse::Burley` on local-frame directions, cos^2(theta_d) = (1 + wo.wi) / 2.
fn diffuse_Burley_eval(
    rho: f32, roughness: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let cos2_d = brdf_cos2_d(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return brdf_burley_core(wo_z, wi_z, cos2_d, rho, roughness);
}

// `diffuse::BurleyRenormalized` on local-frame directions.
fn diffuse_BurleyRenormalized_eval(
    rho: f32, roughness: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let cos2_d = brdf_cos2_d(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return brdf_burley_renormalized_core(wo_z, wi_z, cos2_d, rho, roughness);
}

// The diffuse weight (1 - F(n.l)) / (1 - F0) normalized at normal incidence (Ashikhmin and
// Shirley 2000, "An Anisotropic Phong BRDF Model"; the crate's `fresnel_weight_normalized`).
fn diffuse_fresnel_weight_normalized(fresnel_l: f32, f0: f32) -> f32 {
    return (1.0 - fresnel_l) / (1.0 - f0);
}

// The symmetric diffuse weight (1 - F(n.v))(1 - F(n.l)) (reciprocal by construction).
fn diffuse_fresnel_weight_symmetric(fresnel_v: f32, fresnel_l: f32) -> f32 {
    return (1.0 - fresnel_v) * (1.0 - fresnel_l);
}

// The energy-conserving mix (1 - F) f_diffuse + F f_specular, as F (f_s - f_d) + f_d.
fn diffuse_fresnel_mix(f_diffuse: f32, f_specular: f32, fresnel: f32) -> f32 {
    return fma(fresnel, f_specular - f_diffuse, f_diffuse);
}

// diffuse_fresnel_mix with Schlick's F(F0, cos_theta) (Schlick 1994).
fn diffuse_fresnel_mix_schlick(f_diffuse: f32, f_specular: f32, f0: f32, cos_theta: f32) -> f32 {
    return diffuse_fresnel_mix(f_diffuse, f_specular, fresnel_schlick(f0, cos_theta));
}

// 1 - (1 - c)^5 for c clamped to [0, 1], (1 - c)^5 as (1 - c) ((1 - c)^2)^2.
fn brdf_diffuse_one_minus_pow5(y: f32) -> f32 {
    let y2 = y * y;
    return 1.0 - y * (y2 * y2);
}

// Shirley et al.'s coupled diffuse 21 / (20 pi) rho (1 - F0) (1 - (1 - n.l)^5)(1 - (1 - n.v)^5)
// (Shirley, Smits, Hu, Lafortune 1997, "A Practitioners' Assessment of Light Reflection
// Models").
fn diffuse_shirley_coupled(n_dot_v: f32, n_dot_l: f32, rho: f32, f0: f32) -> f32 {
    // 21 / (20 pi).
    let scale = rho * (1.0 - f0) * 0.33422538049298023;
    let f = scale * brdf_diffuse_one_minus_pow5(1.0 - saturate(n_dot_l))
        * brdf_diffuse_one_minus_pow5(1.0 - saturate(n_dot_v));
    return brdf_above_horizon(n_dot_v, n_dot_l, f);
}

// Ashikhmin and Shirley's diffuse 28 / (23 pi) rho (1 - Rs) (1 - (1 - n.l / 2)^5)
// (1 - (1 - n.v / 2)^5) (Ashikhmin and Shirley 2000, eq. 5).
fn diffuse_ashikhmin_shirley(n_dot_v: f32, n_dot_l: f32, rho: f32, rs: f32) -> f32 {
    // 28 / (23 pi).
    let scale = rho * (1.0 - rs) * 0.387507687528093;
    let f = scale * brdf_diffuse_one_minus_pow5(fma(0.5, -saturate(n_dot_l), 1.0))
        * brdf_diffuse_one_minus_pow5(fma(0.5, -saturate(n_dot_v), 1.0));
    return brdf_above_horizon(n_dot_v, n_dot_l, f);
}

// `diffuse::ShirleyCoupled` on local-frame directions.
fn diffuse_ShirleyCoupled_eval(
    rho: f32, f0: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return diffuse_shirley_coupled(wo_z, wi_z, rho, f0);
}

// `diffuse::AshikhminShirley` on local-frame directions.
fn diffuse_AshikhminShirley_eval(
    rho: f32, rs: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return diffuse_ashikhmin_shirley(wo_z, wi_z, rho, rs);
}
