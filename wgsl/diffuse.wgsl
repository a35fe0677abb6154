// brdf: diffuse lobes, the twins of the Rust module `diffuse` (Lambert, the qualitative
// Oren-Nayar model and its A and B, Burley and its renormalized form). Needs common.wgsl.
// The full and Fujii Oren-Nayar forms, EON, its albedos and samplers and the diffuse-Fresnel
// couplings have no twin yet.

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

// Burley's diffuse (Burley 2012, "Physically-Based Shading at Disney"): rho / pi
// (1 + (F_D90 - 1)(1 - n.l)^5)(1 + (F_D90 - 1)(1 - n.v)^5), F_D90 = 1/2 + 2 r (l.h)^2 for the
// perceptual roughness r, l.h clamped to [0, 1]; 0 below the horizon.
fn diffuse_burley(n_dot_v: f32, n_dot_l: f32, l_dot_h: f32, rho: f32, roughness: f32) -> f32 {
    let lh = saturate(l_dot_h);
    let fd90_minus_1 = fma(lh * lh, 2.0 * roughness, -0.5);
    let f = BRDF_FRAC_1_PI * rho * brdf_burley_factor(fd90_minus_1, n_dot_l)
        * brdf_burley_factor(fd90_minus_1, n_dot_v);
    return brdf_above_horizon(n_dot_v, n_dot_l, f);
}

// Burley's diffuse renormalized for energy with the GGX specular (Lagarde and de Rousiers
// 2014, "Moving Frostbite to PBR", listing 1): F_D90 = r (1/2 + 2 (l.h)^2) - 1 + 1, times
// energyFactor = 1 - r (1 - 1 / 1.51).
fn diffuse_burley_renormalized(
    n_dot_v: f32, n_dot_l: f32, l_dot_h: f32, rho: f32, roughness: f32,
) -> f32 {
    let lh = saturate(l_dot_h);
    let fd90_minus_1 = fma(fma(2.0 * lh, lh, 0.5), roughness, -1.0);
    // 1 - 1 / 1.51.
    let k = fma(0.33774834437086093, -roughness, 1.0);
    let f = BRDF_FRAC_1_PI * rho * k * brdf_burley_factor(fd90_minus_1, n_dot_l)
        * brdf_burley_factor(fd90_minus_1, n_dot_v);
    return brdf_above_horizon(n_dot_v, n_dot_l, f);
}
