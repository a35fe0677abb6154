// brdf: diffuse lobes, the twins of the Rust module `diffuse` (Lambert, the qualitative
// Oren-Nayar model and its A and B, Burley and its renormalized form, the diffuse-Fresnel
// couplings, and the parameter types' `eval` on local-frame directions). Needs common.wgsl and
// fresnel.wgsl. Also the full and Fujii's Oren-Nayar and EON (exact and fitted) with its
// albedos and its importance sampling (the CLTC sampler, the mixture, their pdfs).

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

// Fujii's shape (t + sigma s, t) of the improved Oren-Nayar lobe and EON's single scattering
// (Fujii 2012, "A tiny improvement of Oren-Nayar reflectance model"): s = v.l - n.v n.l formed
// with one rounding (fma) and clamped to [-1, 1], its range for unit vectors; t = max(n.v, n.l)
// floored at the smallest normal where s > 0 and sigma > 0, else 1. The sum t + sigma s is one
// fused step: for s < 0 it cancels towards 0 (opposite grazing directions at sigma = 1), so
// sigma s is not rounded first where the implementation fuses.
fn brdf_fujii_shape(n_dot_v: f32, n_dot_l: f32, v_dot_l: f32, sigma: f32) -> vec2<f32> {
    let s = clamp(fma(-n_dot_v, n_dot_l, v_dot_l), -1.0, 1.0);
    let t = select(1.0, max(max(n_dot_v, n_dot_l), 1.17549435e-38), (s > 0.0) & (sigma > 0.0));
    return vec2<f32>(fma(s, sigma, t), t);
}

// Fujii's c1 = 1/2 - 2/(3 pi) = G(0)/pi and EON's c2 = 2/3 - 28/(15 pi), c1 - c2, pi c1 and
// 1 / (pi^3 (c1 - c2)) (Portsmouth, Kutz, Hill 2025, "EON: A Practical Energy-Preserving Rough
// Diffuse BRDF", JCGT 14(1)).
const BRDF_EON_C1: f32 = 0.2877934092108062;
const BRDF_EON_C2: f32 = 0.07248821245692408;
const BRDF_EON_C1_MINUS_C2: f32 = 0.21530519675388213;
const BRDF_EON_PI_C1: f32 = 0.9041296601282299;
const BRDF_EON_MS_SCALE: f32 = 0.14979450064118327;

// Fujii's improved Oren-Nayar lobe (Fujii 2012): rho / pi (1 + sigma s / t) / (1 + c1 sigma),
// rho and sigma in [0, 1]; 0 below the horizon.
fn diffuse_oren_nayar_fujii(
    n_dot_v: f32, n_dot_l: f32, v_dot_l: f32, rho: f32, sigma: f32,
) -> f32 {
    let st = brdf_fujii_shape(n_dot_v, n_dot_l, v_dot_l, sigma);
    let den = fma(BRDF_EON_C1, sigma, 1.0);
    let f = (rho * BRDF_FRAC_1_PI) * st.x / den;
    return brdf_above_horizon(n_dot_v, n_dot_l, f / st.y);
}

// `diffuse::OrenNayarFujii` on local-frame directions, v.l = wo.wi.
fn diffuse_OrenNayarFujii_eval(
    rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let v_dot_l = brdf_diffuse_dot(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return diffuse_oren_nayar_fujii(wo_z, wi_z, v_dot_l, rho, sigma);
}

// pi c1 - G(mu) = pi (1 - E(mu)) / (sigma A), the FON albedo's deficit (Portsmouth et al.
// 2025, `E_FON_exact`), in the Rust kernel's form without cancellation: with S = sqrt(1 - mu^2),
//   pi c1 - G = S asin(mu) + (1 - S) (pi c1 - S mu (2 + S) / (3 (1 + S))),
// two non-negative terms (G as printed tends to pi c1 at grazing and c1 - G/pi cancels there),
// 1 - S as mu^2 / (1 + S) where S > 1/2.
fn brdf_eon_pi_loss_exact(mu: f32) -> f32 {
    let si = sqrt((1.0 - mu) * (1.0 + mu));
    let one_plus_si = 1.0 + si;
    let one_minus_si = select(1.0 - si, mu * mu / one_plus_si, si > 0.5);
    let bracket = BRDF_EON_PI_C1 - si * mu * (si + 2.0) / (3.0 * one_plus_si);
    return si * asin(mu) + bracket * one_minus_si;
}

// c1 - g(mu) from the paper's quartic fit of G(mu)/pi in m = 1 - mu, clamped at 0 (the fit
// overshoots c1 by 4.6e-4 at grazing, where the exact value is 0).
fn brdf_eon_loss_fit(mu: f32) -> f32 {
    let m = 1.0 - mu;
    let p = fma(fma(fma(0.0714429953, m, -0.332181442), m, 0.491881867), m, 0.0571085289);
    return max(BRDF_EON_C1 - p * m, 0.0);
}

// EON with the given pi c1 - G of each direction (exact or fitted): f = f_FON + f_ms,
// f_FON = rho / pi (t + sigma s) / ((1 + c1 sigma) t), f_ms = rho^2 sigma (1 + c2 sigma) L_o L_i
// / ((1 + c1 sigma)(1 + c1 sigma - rho sigma (c1 - c2)) pi^3 (c1 - c2)), L = pi c1 - G: the
// paper's (1 - E_o)(1 - E_i) / (1 - E_avg) with A cancelled, exactly 0 at sigma = 0.
fn brdf_eon_with(
    n_dot_v: f32, n_dot_l: f32, v_dot_l: f32, rho: f32, sigma: f32, loss_o: f32, loss_i: f32,
) -> f32 {
    let mu_o = saturate(n_dot_v);
    let mu_i = saturate(n_dot_l);
    let st = brdf_fujii_shape(mu_o, mu_i, v_dot_l, sigma);
    let den = fma(BRDF_EON_C1, sigma, 1.0);
    let single = (rho * BRDF_FRAC_1_PI) * st.x / den / st.y;
    let rho_sigma = rho * sigma;
    let ms_den = den * (den - rho_sigma * BRDF_EON_C1_MINUS_C2);
    let ms_num = rho_sigma * rho * fma(BRDF_EON_C2, sigma, 1.0) * BRDF_EON_MS_SCALE * loss_o
        * loss_i;
    return brdf_above_horizon(n_dot_v, n_dot_l, single + ms_num / ms_den);
}

// The EON BRDF with the exact FON albedo (Portsmouth, Kutz, Hill 2025, the `f_EON` listing
// with `exact = true`): rho, sigma in [0, 1]; Lambert rho / pi at sigma = 0; 0 below the
// horizon.
fn diffuse_eon(n_dot_v: f32, n_dot_l: f32, v_dot_l: f32, rho: f32, sigma: f32) -> f32 {
    let lo = brdf_eon_pi_loss_exact(saturate(n_dot_v));
    let li = brdf_eon_pi_loss_exact(saturate(n_dot_l));
    return brdf_eon_with(n_dot_v, n_dot_l, v_dot_l, rho, sigma, lo, li);
}

// EON with the FON albedo from the paper's quartic fit (the `f_EON` listing with
// `exact = false`): no `asin`.
fn diffuse_eon_approx(n_dot_v: f32, n_dot_l: f32, v_dot_l: f32, rho: f32, sigma: f32) -> f32 {
    let lo = BRDF_PI * brdf_eon_loss_fit(saturate(n_dot_v));
    let li = BRDF_PI * brdf_eon_loss_fit(saturate(n_dot_l));
    return brdf_eon_with(n_dot_v, n_dot_l, v_dot_l, rho, sigma, lo, li);
}

// 1 - E(mu) = sigma A (c1 - G(mu)/pi), A = 1 / (1 + c1 sigma), from c1 - G/pi.
fn brdf_eon_one_minus_e(sigma: f32, loss: f32) -> f32 {
    return sigma * (1.0 / fma(BRDF_EON_C1, sigma, 1.0)) * loss;
}

// The FON directional albedo at rho = 1, E(mu) = A (1 + sigma G(mu)/pi) as 1 - sigma A (c1 -
// G/pi) with the exact G (Portsmouth et al. 2025, `E_FON_exact`); mu = n.v clamped to 1, 0 for
// mu <= 0.
fn diffuse_eon_fon_albedo(n_dot_v: f32, sigma: f32) -> f32 {
    let loss = brdf_eon_pi_loss_exact(saturate(n_dot_v)) * BRDF_FRAC_1_PI;
    return brdf_above(n_dot_v, 1.0 - brdf_eon_one_minus_e(sigma, loss));
}

// The FON directional albedo from the paper's quartic fit (`E_FON_approx`), capped at 1.
fn diffuse_eon_fon_albedo_approx(n_dot_v: f32, sigma: f32) -> f32 {
    let loss = brdf_eon_loss_fit(saturate(n_dot_v));
    return brdf_above(n_dot_v, 1.0 - brdf_eon_one_minus_e(sigma, loss));
}

// The FON albedo's cosine-weighted average E_avg = (1 + c2 sigma) / (1 + c1 sigma).
fn diffuse_eon_fon_average_albedo(sigma: f32) -> f32 {
    return fma(BRDF_EON_C2, sigma, 1.0) * (1.0 / fma(BRDF_EON_C1, sigma, 1.0));
}

// rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg)), capped at rho, exactly 1 at rho = 1.
fn brdf_eon_rho_ms(rho: f32, sigma: f32) -> f32 {
    let a = 1.0 / fma(BRDF_EON_C1, sigma, 1.0);
    let e_avg = fma(BRDF_EON_C2, sigma, 1.0) * a;
    let one_minus_e_avg = sigma * BRDF_EON_C1_MINUS_C2 * a;
    let q = rho * rho * e_avg / fma(-rho, one_minus_e_avg, 1.0);
    return select(min(q, rho), 1.0, rho == 1.0);
}

// EON's multiple-scattering albedo rho_ms (Portsmouth et al. 2025, `rho_ms`).
fn diffuse_eon_multiscatter_albedo(rho: f32, sigma: f32) -> f32 {
    return brdf_eon_rho_ms(rho, sigma);
}

// EON's directional albedo rho E + rho_ms (1 - E) = rho + (rho_ms - rho)(1 - E) with the exact E
// (Portsmouth et al. 2025, `E_EON`); 0 for n.v <= 0.
fn diffuse_eon_albedo(n_dot_v: f32, rho: f32, sigma: f32) -> f32 {
    let loss = brdf_eon_pi_loss_exact(saturate(n_dot_v)) * BRDF_FRAC_1_PI;
    let value = fma(brdf_eon_rho_ms(rho, sigma) - rho, brdf_eon_one_minus_e(sigma, loss), rho);
    return brdf_above(n_dot_v, value);
}

// EON's directional albedo with E from the fit (`E_EON` with `exact = false`).
fn diffuse_eon_albedo_approx(n_dot_v: f32, rho: f32, sigma: f32) -> f32 {
    let loss = brdf_eon_loss_fit(saturate(n_dot_v));
    let value = fma(brdf_eon_rho_ms(rho, sigma) - rho, brdf_eon_one_minus_e(sigma, loss), rho);
    return brdf_above(n_dot_v, value);
}

// `diffuse::Eon` on local-frame directions: diffuse_eon with v.l = wo.wi.
fn diffuse_Eon_eval(
    rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let v_dot_l = brdf_diffuse_dot(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return diffuse_eon(wo_z, wi_z, v_dot_l, rho, sigma);
}

// `diffuse::Eon::eval_approx` on local-frame directions.
fn diffuse_Eon_eval_approx(
    rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let v_dot_l = brdf_diffuse_dot(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return diffuse_eon_approx(wo_z, wi_z, v_dot_l, rho, sigma);
}

// `diffuse::Eon::albedo`: diffuse_eon_albedo(wo.z, rho, sigma).
fn diffuse_Eon_albedo(rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32) -> f32 {
    return diffuse_eon_albedo(wo_z, rho, sigma);
}

// `diffuse::Eon::albedo_approx`: diffuse_eon_albedo_approx(wo.z, rho, sigma).
fn diffuse_Eon_albedo_approx(rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32) -> f32 {
    return diffuse_eon_albedo_approx(wo_z, rho, sigma);
}

// The angle theta = acos(c) as a fraction of a right angle, 2 theta / pi, for c in [0, 1]: as
// 1 - (2 / pi) asin(c) below c = 1/2 and 2 (2 / pi) asin(sqrt((1 - c) / 2)) above (acos's
// half-angle form, without the cancellation of pi/2 - asin(c) near c = 1).
fn brdf_angle_over_right_angle(c: f32) -> f32 {
    let near_right = c < 0.5;
    let y = asin(select(sqrt(0.5 * (1.0 - c)), c, near_right));
    // 2 / pi.
    let scaled = 0.6366197723675814 * y;
    return select(2.0 * scaled, 1.0 - scaled, near_right);
}

// The full Oren-Nayar model (Oren and Nayar 1994, "Generalization of Lambert's Reflectance
// Model", eqs. 27-30 with the interreflection term L2; the crate's `diffuse::oren_nayar_full`):
// rho / pi (L1 + L2), L1 = C1 + cos(phi) C2 tan(beta) + (1 - |cos(phi)|) C3 tan((alpha +
// beta) / 2), L2 = 0.17 rho sigma^2 / (sigma^2 + 0.13) (1 - cos(phi) (2 beta / pi)^2), alpha
// and beta the larger and smaller polar angle, C1 = A, C2 = 0.45 sigma^2 / (sigma^2 + 0.09)
// (sin(alpha), or sin(alpha) - (2 beta / pi)^3 where cos(phi) < 0), C3 = 0.125 sigma^2 /
// (sigma^2 + 0.09) (4 alpha beta / pi^2)^2. In the Rust kernel's forms: 1 - |cos(phi)| as
// G / (P (P + |s|)) with the Gram determinant G = (1 - n.v^2)(1 - n.l^2) - s^2 (as 1 - |s / P|
// it cancels for opposite grazing directions), C2's difference near grazing as
// x (3 - 3 x + x^2) - cos^2(alpha) / (1 + sin(alpha)), x = 1 - 2 beta / pi, the tangents'
// denominators floored at the smallest normal, L1 floored at 0; cos(phi) = 0 at a pole.
// rho in [0, 1], sigma >= 0 (radians); 0 below the horizon.
fn diffuse_oren_nayar_full(
    n_dot_v: f32, n_dot_l: f32, v_dot_l: f32, rho: f32, sigma: f32,
) -> f32 {
    let cv = min(n_dot_v, 1.0);
    let cl = min(n_dot_l, 1.0);
    let sin2_v = fma(-cv, cv, 1.0);
    let sin2_l = fma(-cl, cl, 1.0);
    let sin_v = sqrt(sin2_v);
    let sin_l = sqrt(sin2_l);
    let v_is_alpha = cv <= cl;
    let cos_alpha = min(cv, cl);
    let cos_beta = max(cv, cl);
    let sin_alpha = select(sin_l, sin_v, v_is_alpha);
    let sin_beta = select(sin_v, sin_l, v_is_alpha);
    let a = brdf_angle_over_right_angle(saturate(cos_alpha));
    let b = brdf_angle_over_right_angle(saturate(cos_beta));
    let s = fma(-n_dot_v, n_dot_l, v_dot_l);
    let p = sin_v * sin_l;
    let at_pole = !(p > 0.0);
    let safe_p = select(p, 1.0, at_pole);
    let cos_phi = clamp(select(s / safe_p, 0.0, at_pole), -1.0, 1.0);
    let gram = max(sin2_v * sin2_l - s * s, 0.0);
    let one_minus_abs_cos_phi = clamp(select(gram / (safe_p * (safe_p + abs(s))), 1.0, at_pole),
        0.0, 1.0);
    let tan_beta = sin_beta / max(cos_beta, 1.17549435e-38);
    let tan_half = (sin_alpha + sin_beta) / max(cos_alpha + cos_beta, 1.17549435e-38);
    let x = 1.0 - b;
    let cubic = x * (3.0 + x * (x - 3.0));
    let grazing_difference = cubic - cos_alpha * cos_alpha / (1.0 + sin_alpha);
    let difference = select(sin_alpha - b * b * b, grazing_difference, cos_beta < 0.5);
    let k = brdf_oren_nayar_rational(sigma, 0.09);
    let c2 = 0.45 * k * select(difference, sin_alpha, cos_phi >= 0.0);
    let ab = a * b;
    let c3 = 0.125 * k * (ab * ab);
    let l1 = max(diffuse_oren_nayar_a(sigma) + cos_phi * c2 * tan_beta
        + one_minus_abs_cos_phi * c3 * tan_half, 0.0);
    let l2 = rho * (0.17 * brdf_oren_nayar_rational(sigma, 0.13)) * (1.0 - cos_phi * (b * b));
    return brdf_above_horizon(n_dot_v, n_dot_l, BRDF_FRAC_1_PI * rho * (l1 + l2));
}

// `diffuse::OrenNayarFull` on local-frame directions, v.l = wo.wi.
fn diffuse_OrenNayarFull_eval(
    rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let v_dot_l = brdf_diffuse_dot(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return diffuse_oren_nayar_full(wo_z, wi_z, v_dot_l, rho, sigma);
}

// EON's importance sampling (Portsmouth, Kutz and Hill 2025, "EON: A practical energy-preserving
// rough diffuse BRDF", the cltc_sample, cltc_pdf, sample_EON and pdf_EON listings).

// The clipped linearly transformed cosine for one (wo, sigma) (the Rust kernel's Cltc::new; the
// paper's ltc_terms fits, mu = wo.z clamped into [0, 1]): the matrix M = [[a, 0, b], [0, c, 0],
// [d, 0, 1]] (d capped at 0), the kept fraction s = (1 + v) / 2 with v = 1 / sqrt(1 + d^2),
// 1 - v = d^2 / (k (k + 1)) (k = sqrt(1 + d^2)), k^2, det M and wo's unit azimuth (fx, fy)
// ((1, 0) at the pole): (a, b, c, d, s, v, 1 - v, k^2, det, fx, fy).
fn brdf_eon_cltc(wo: vec3<f32>, sigma: f32) -> array<f32, 11> {
    let mu = clamp(wo.z, 0.0, 1.0);
    let r = sigma;
    let a = 1.0 + r * (fma(fma(0.111709, mu, -0.518982), mu, 0.303392)
        + fma(0.335918, mu, -0.276266) * r);
    let b = r * (fma(1.15859, mu, -1.16407) + fma(-0.150105, mu, 0.150815) * r)
        / fma(mu * mu, mu, -1.43545);
    let c = 1.0 + fma(fma(0.261777, mu, -0.506373), mu, 0.20013) * r;
    // The fit of d rounds up to +0.0035 sigma within 1e-4 of mu = 1: capped at 0, as the clip
    // assumes.
    let d = min(fma(fma(0.475392, mu, -1.01625), mu, 0.540852) * r
        / fma(mu + 0.0725628, mu, -1.0743), 0.0);
    let k2 = fma(d, d, 1.0);
    let k = sqrt(k2);
    let v = 1.0 / k;
    let one_minus_v = d * d / (k * (k + 1.0));
    let clip = 0.5 * (1.0 + v);
    let det = c * fma(-b, d, a);
    let len2 = fma(wo.x, wo.x, wo.y * wo.y);
    let ok = len2 > 1.17549435e-38;
    let inv = select(1.0, 1.0 / sqrt(len2), ok);
    return array<f32, 11>(a, b, c, d, clip, v, one_minus_v, k2, det, select(1.0, wo.x * inv, ok),
        select(0.0, wo.y * inv, ok));
}

// A direction of the clipped lobe from the disk point at radius sqrt(u1) and angle phi, with
// its pdf (the Rust kernel's Cltc::sample_disk): the disk squeezed onto the region the clip
// keeps, x' = v h - s (h + x), z^2 = ((1 - v) h + s (h + x)) s (h - x) with h^2 = 1 - u1
// sin^2 phi, written in h + x and h - x (whose product is 1 - u1) so that nothing cancels at
// the rim; wi = M wh / |M wh| rotated to wo's azimuth, pdf = z |M wh|^3 / (pi s det M).
fn brdf_eon_sample_disk(t: array<f32, 11>, u1: f32, cos_phi: f32, sin_phi: f32) -> vec4<f32> {
    let q = 1.0 - u1;
    let r = sqrt(u1);
    let x = r * cos_phi;
    let y = r * sin_phi;
    let h = sqrt(fma(u1, cos_phi * cos_phi, q));
    let pos = x > 0.0;
    let direct = h + abs(x);
    let other = q / direct;
    let hp = select(other, direct, pos);
    let hm = select(direct, other, pos);
    let s = t[4];
    let xs = fma(t[5], h, -s * hp);
    let z = sqrt(max(fma(t[6], h, s * hp) * s * hm, 0.0));
    let n = s * hp * t[7] * fma(2.0 * t[5], h, -s * hp);
    let wz = select(fma(t[3], xs, z), n / fma(-t[3], xs, z), xs > 0.0);
    let w = vec3<f32>(fma(t[0], xs, t[1] * z), t[2] * y, wz);
    let len = sqrt(fma(w.x, w.x, fma(w.y, w.y, w.z * w.z)));
    let pdf = z * len * len * len / (BRDF_PI * s * t[8]);
    let inv = 1.0 / len;
    let u = vec3<f32>(w.x * inv, w.y * inv, w.z * inv);
    return vec4<f32>(fma(t[9], u.x, -t[10] * u.y), fma(t[10], u.x, t[9] * u.y), u.z, pdf);
}

// The density of brdf_eon_sample_disk at wi (the Rust kernel's Cltc::pdf):
// det^2 / |adj(M) w|^4 max(0, (adj(M) w).z) / (pi s), w = wi in wo's azimuthal frame.
fn brdf_eon_cltc_density(t: array<f32, 11>, wi: vec3<f32>) -> f32 {
    let wx = fma(t[9], wi.x, t[10] * wi.y);
    let wy = fma(t[9], wi.y, -t[10] * wi.x);
    let hx = t[2] * fma(-t[1], wi.z, wx);
    let hy = fma(-t[1], t[3], t[0]) * wy;
    let hz = t[2] * fma(t[0], wi.z, -t[3] * wx);
    let len2 = fma(hx, hx, fma(hy, hy, hz * hz));
    let q = t[8] / len2;
    return q * q * max(hz, 0.0) / (BRDF_PI * t[4]);
}

// The CLTC sampler alone (diffuse::eon_cltc_sample): (wi.x, wi.y, wi.z, pdf) for view wo and
// roughness sigma in [0, 1], u1 and u2 clamped into [0, 1); pdf 0 where wo.z <= 0 or wi.z <= 0.
fn diffuse_eon_cltc_sample(
    wo_x: f32, wo_y: f32, wo_z: f32, sigma: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let t = brdf_eon_cltc(vec3<f32>(wo_x, wo_y, wo_z), sigma);
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let s = brdf_eon_sample_disk(t, brdf_clamp_u(u1), cs.x, cs.y);
    return vec4<f32>(s.x, s.y, s.z, brdf_above_horizon(wo_z, s.z, s.w));
}

// The pdf of diffuse_eon_cltc_sample at wi (diffuse::eon_cltc_pdf), 0 where wo.z <= 0 or
// wi.z <= 0.
fn diffuse_eon_cltc_pdf(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, sigma: f32,
) -> f32 {
    let t = brdf_eon_cltc(vec3<f32>(wo_x, wo_y, wo_z), sigma);
    return brdf_above_horizon(wo_z, wi_z,
        brdf_eon_cltc_density(t, vec3<f32>(wi_x, wi_y, wi_z)));
}

// The uniform lobe's probability P_u = sigma^0.1 (0.162925 - 0.372058 mu + 0.538233 mu^2 -
// 0.290822 mu^3), mu = wo.z clamped into [0, 1]; 0 at sigma = 0 (where pow promises nothing).
fn brdf_eon_uniform_weight(wo_z: f32, sigma: f32) -> f32 {
    let mu = clamp(wo_z, 0.0, 1.0);
    let poly = fma(fma(fma(-0.290822, mu, 0.538233), mu, -0.372058), mu, 0.162925);
    return select(pow(sigma, 0.1), 0.0, sigma == 0.0) * poly;
}

// The mixture's pdf P_u / (2 pi) + (1 - P_u) pdf_CLTC(wi), 0 where wo.z <= 0 or wi.z <= 0.
fn brdf_eon_mixture_pdf(t: array<f32, 11>, p_u: f32, wo_z: f32, wi: vec3<f32>) -> f32 {
    let pdf_c = brdf_eon_cltc_density(t, wi);
    return brdf_above_horizon(wo_z, wi.z, fma(p_u, 0.5 * BRDF_FRAC_1_PI - pdf_c, pdf_c));
}

// EON's importance sampling (diffuse::eon_sample): with probability P_u a uniform hemisphere
// direction (z = 1 - u1 / P_u), otherwise the CLTC direction from (u1 - P_u) / (1 - P_u); u2 is
// the azimuth of both. (wi.x, wi.y, wi.z, pdf), pdf = diffuse_eon_pdf(wo, wi, sigma).
fn diffuse_eon_sample(wo_x: f32, wo_y: f32, wo_z: f32, sigma: f32, u1: f32, u2: f32) -> vec4<f32> {
    let t = brdf_eon_cltc(vec3<f32>(wo_x, wo_y, wo_z), sigma);
    let p_u = brdf_eon_uniform_weight(wo_z, sigma);
    let uc1 = brdf_clamp_u(u1);
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    // Strict <: at sigma = 0 (P_u = 0) every u1 takes the CLTC lobe. The floor keeps the unused
    // quotient finite there (P_u > 0 is at least 0.038 sigma^0.1, a normal number, elsewhere).
    let uniform = uc1 < p_u;
    let z = 1.0 - brdf_clamp_u(uc1 / max(p_u, 1.17549435e-38));
    let sin_theta = sqrt(max((1.0 - z) * (1.0 + z), 0.0));
    let wu = vec3<f32>(sin_theta * cs.x, sin_theta * cs.y, z);
    let wc = brdf_eon_sample_disk(t, brdf_clamp_u((uc1 - p_u) / (1.0 - p_u)), cs.x, cs.y);
    let wi = select(vec3<f32>(wc.x, wc.y, wc.z), wu, uniform);
    return vec4<f32>(wi, brdf_eon_mixture_pdf(t, p_u, wo_z, wi));
}

// The pdf of diffuse_eon_sample at wi (diffuse::eon_pdf).
fn diffuse_eon_pdf(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, sigma: f32,
) -> f32 {
    let t = brdf_eon_cltc(vec3<f32>(wo_x, wo_y, wo_z), sigma);
    return brdf_eon_mixture_pdf(t, brdf_eon_uniform_weight(wo_z, sigma), wo_z,
        vec3<f32>(wi_x, wi_y, wi_z));
}

// diffuse::Eon::sample: diffuse_eon_sample with the lobe's sigma (rho does not enter).
fn diffuse_Eon_sample(
    rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    return diffuse_eon_sample(wo_x, wo_y, wo_z, sigma, u1, u2);
}

// diffuse::Eon::pdf: diffuse_eon_pdf with the lobe's sigma.
fn diffuse_Eon_pdf(
    rho: f32, sigma: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return diffuse_eon_pdf(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z, sigma);
}
