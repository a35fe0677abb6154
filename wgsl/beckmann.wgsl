// brdf: Beckmann microfacet terms, the twins of the Rust module `beckmann` (D, the fast D,
// Smith's a, Walter's rational Lambda, the Blinn-Phong exponent conversions). Needs
// common.wgsl. The exact Lambda and G1 (through erfc) have no twin yet.

// Isotropic Beckmann NDF (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 25): D = exp(-E) / (pi alpha^2 c^4), E = (1 - c)(1 + c) / (c^2 alpha^2) for
// c = n_dot_h in (0, 1], 0 for c <= 0. Where E > 64, exp's argument is shifted by 64 ln 2 and
// the quotient scaled by 2^-64, as in the Rust kernel, so exp(-E) does not fall into the
// subnormal range (which WGSL may flush to 0) while D is a normal number.
fn beckmann_d(n_dot_h: f32, alpha: f32) -> f32 {
    let a = brdf_clamp_alpha(alpha);
    let c = min(n_dot_h, 1.0);
    let c2 = c * c;
    let a2 = a * a;
    let e = brdf_one_minus_sq(c) / (c2 * a2);
    let big = e > 64.0;
    // 64 ln 2, and 2^-64.
    let x = exp(-(e - select(0.0, 44.3614195558365, big)));
    let scale = select(1.0, 5.421010862427522e-20, big);
    let pden = max(a2 * c2 * c2 * BRDF_PI, 1.17549435e-38);
    return brdf_above(n_dot_h, x * (scale / pden));
}

// The fast form of the same D (as the Rust `beckmann::d_fast`): one division r = 1 / (c alpha)^2,
// D = y^2 with y = 2^-t r alpha / sqrt(pi), t = (1 - c^2) r / (2 ln 2), so that neither 2^-t nor
// y is subnormal while D is normal; cosines below 2^-40 (c <= 0 included) give 0 through the
// cap on t.
fn beckmann_d_fast(n_dot_h: f32, alpha: f32) -> f32 {
    let a = brdf_clamp_alpha(alpha);
    // 2^-40: below it E > 2^53 and D = 0; c alpha, c^2 and (c alpha)^2 stay normal.
    let c = clamp(n_dot_h, 9.094947017729282e-13, 1.0);
    let ca = c * a;
    // 2^-63 floors (c alpha)^2 so that r stays finite.
    let r = 1.0 / max(ca * ca, 1.0842021724855044e-19);
    // log2(e) / 2.
    let t = brdf_sin2(c) * (r * 0.7213475204444817);
    // 1 / sqrt(pi).
    let y = exp2(-min(t, 108.2)) * (r * (a * 0.5641895835477563));
    let zero = (t >= 108.2) | (y < 1.0842021724855044e-19);
    let yz = select(y, 0.0, zero);
    return yz * yz;
}

// Smith's a = c / (alpha sqrt(1 - c^2)) = 1 / (alpha tan(theta)) of the isotropic Beckmann
// (Walter et al. 2007, eq. 27), c = |n_dot_v| clamped to 1; capped at the largest finite f32
// (at c = 1, where a is infinite).
fn beckmann_a_of(n_dot_v: f32, alpha: f32) -> f32 {
    let c = min(abs(n_dot_v), 1.0);
    let a = brdf_clamp_alpha(alpha);
    let den = a * sqrt(brdf_one_minus_sq(c));
    return select(BRDF_F32_MAX, min(c / den, BRDF_F32_MAX), den > 0.0);
}

// Walter et al.'s rational approximation of the Beckmann Lambda (2007, eq. 27):
// (1 - 1.259 a + 0.396 a^2) / (3.535 a + 2.181 a^2) for a < 1.6, else 0; the pole at a = 0 (the
// horizon) capped at the largest finite f32.
fn beckmann_lambda_walter(n_dot_v: f32, alpha: f32) -> f32 {
    let a = beckmann_a_of(n_dot_v, alpha);
    let num = fma(a, fma(a, 0.396, -1.259), 1.0);
    let den = a * fma(a, 2.181, 3.535);
    let ratio = select(BRDF_F32_MAX, max(num / den, 0.0), den > 0.0);
    return min(select(0.0, ratio, a < 1.6), BRDF_F32_MAX);
}

// The Beckmann width matching a Blinn-Phong exponent, alpha = sqrt(2 / (n + 2)) (Walter et al.
// 2007, section 5.2). n >= 0.
fn beckmann_alpha_from_blinn_phong(exponent: f32) -> f32 {
    return sqrt(2.0 / (exponent + 2.0));
}

// The Blinn-Phong exponent matching a Beckmann width, n = 2 / alpha^2 - 2 (Walter et al. 2007,
// section 5.2), alpha clamped to [ALPHA_MIN, ALPHA_MAX], 0 at and above alpha = 1.
fn beckmann_blinn_phong_from_alpha(alpha: f32) -> f32 {
    let a = brdf_clamp_alpha(alpha);
    return max(2.0 / (a * a) - 2.0, 0.0);
}
