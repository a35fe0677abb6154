// brdf: Beckmann microfacet terms, the twins of the Rust module `beckmann` (D, the fast D,
// Smith's a, the exact Lambda and G1 without erf, Walter's rational Lambda, the Blinn-Phong
// exponent conversions, and the anisotropic `Beckmann`'s methods). Needs common.wgsl.

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

// The fast form of the same D (the Rust `beckmann::d_fast`'s earlier form, E in working precision,
// its error growing as about 4 E ULP): one division r = 1 / (c alpha)^2,
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

// The exact Smith terms of the Beckmann distribution. WGSL has no erf: Lambda is written, as in
// the Rust kernels, without erfc's cancellation (Heitz 2014, "Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 83):
//   Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 = P / (a (a + K)),
//   P = exp(-a^2) K / (2 sqrt(pi)),  K(a) = 1 / (sqrt(pi) erfcx(a)) - a in (0, 1 / sqrt(pi)],
// a product and quotient of positive factors. K is a degree-15 polynomial in x = a / 2 - 1 on
// [0, 4] (a Chebyshev fit in 40-digit arithmetic, within 2.3e-10 of K; its coefficients'
// rounding to f32 moves it by at most 7.3e-8 relative, about 1.2 ULP), evaluated by Horner
// with |x| <= 1 and coefficients below 0.21, so each step's error stays at the size of one
// rounding; above 4 the continued fraction sqrt(pi) erfcx(a) = 1 / (a + (1/2) / (a + 1 / (a +
// (3/2) / (a + ...)))) (Abramowitz and Stegun 7.1.14), 8 levels started from its fixed point,
// as the Rust kernel's f32 path does.

// K(a) for a in [0, 1e4].
fn brdf_beckmann_k(a: f32) -> f32 {
    let x = min(a, 4.0) * 0.5 - 1.0;
    let h0 = -1.7618787606947663e-5;
    let h1 = fma(h0, x, 3.2510434001680699e-5);
    let h2 = fma(h1, x, 2.8504603673479296e-5);
    let h3 = fma(h2, x, -0.00011370732086018473);
    let h4 = fma(h3, x, 0.00016126122490431933);
    let h5 = fma(h4, x, -0.00028629777460812713);
    let h6 = fma(h5, x, 0.00044788188782794665);
    let h7 = fma(h6, x, -0.00025290396370533276);
    let h8 = fma(h7, x, -0.0010006086079963436);
    let h9 = fma(h8, x, 0.0046428758126935384);
    let h10 = fma(h9, x, -0.012989564928699139);
    let h11 = fma(h10, x, 0.029295398577905273);
    let h12 = fma(h11, x, -0.05713210767271882);
    let h13 = fma(h12, x, 0.098790736221138972);
    let h14 = fma(h13, x, -0.15249831630463021);
    let fit = fma(h14, x, 0.20908040278325627);
    // The continued fraction's tail from its fixed point (k / 2) / (a + t) = t at k = 9, then
    // levels 8 down to 2 (level k is (k / 2) / (a + t)), then K = (1/2) / (a + t).
    let ac = max(a, 4.0);
    let t9 = 9.0 / (ac + sqrt(fma(ac, ac, 18.0)));
    let t8 = 4.0 / (ac + t9);
    let t7 = 3.5 / (ac + t8);
    let t6 = 3.0 / (ac + t7);
    let t5 = 2.5 / (ac + t6);
    let t4 = 2.0 / (ac + t5);
    let t3 = 1.5 / (ac + t4);
    let t2 = 1.0 / (ac + t3);
    let cf = 0.5 / (ac + t2);
    return select(cf, fit, a < 4.0);
}

// The Smith argument a = |z| / r (r = alpha(phi) sin(theta)), capped at 1e4 (where
// exp(-a^2) is 0 in f32): the divisor max(r, 1e-4 |z|) is r wherever a < 1e4, and keeps the
// quotient finite at the normal (r = 0).
fn brdf_beckmann_a(z: f32, r: f32) -> f32 {
    return min(z / max(r, 1e-4 * z), 1e4);
}

// (P, Q, K) of a: P = exp(-a^2) K / (2 sqrt(pi)), Q = a (a + K); Lambda = P / Q, G1 = Q / (Q + P).
fn brdf_beckmann_pq(a: f32) -> vec3<f32> {
    let k = brdf_beckmann_k(a);
    // 1 / (2 sqrt(pi)).
    let p = exp(-(a * a)) * (k * 0.28209479177387814);
    return vec3<f32>(p, a * (a + k), k);
}

// Lambda = P / Q, the pole at a = 0 (the horizon) capped at the largest finite f32.
fn brdf_beckmann_lambda_of_a(a: f32) -> f32 {
    let pq = brdf_beckmann_pq(a);
    return select(BRDF_F32_MAX, min(pq.x / pq.y, BRDF_F32_MAX), a > 0.0);
}

// G1 = 1 / (1 + Lambda) = Q / (Q + P): 0 at the horizon (Q = 0), 1 at the normal (P = 0).
fn brdf_beckmann_g1_of_a(a: f32) -> f32 {
    let pq = brdf_beckmann_pq(a);
    return pq.y / (pq.y + pq.x);
}

// a of the isotropic Beckmann from c = |n_dot_v| clamped to 1: c / (alpha sqrt(1 - c^2)).
fn brdf_beckmann_a_iso(n_dot_v: f32, alpha: f32) -> f32 {
    let c = min(abs(n_dot_v), 1.0);
    return brdf_beckmann_a(c, brdf_clamp_alpha(alpha) * sqrt(brdf_one_minus_sq(c)));
}

// The exact Smith Lambda of the isotropic Beckmann (Heitz 2014, eq. 83; Walter et al. 2007,
// eq. 27's exact form) in the cancellation-free form above, a = 1 / (alpha tan(theta)) from
// c = |n_dot_v| clamped to 1; capped at the largest finite f32 at the horizon, 0 at the normal.
fn beckmann_lambda(n_dot_v: f32, alpha: f32) -> f32 {
    return brdf_beckmann_lambda_of_a(brdf_beckmann_a_iso(n_dot_v, alpha));
}

// Smith's G1 = 1 / (1 + Lambda) of the isotropic Beckmann as Q / (Q + P): 0 at the horizon,
// 1 at the normal.
fn beckmann_g1(n_dot_v: f32, alpha: f32) -> f32 {
    return brdf_beckmann_g1_of_a(brdf_beckmann_a_iso(n_dot_v, alpha));
}

// exp(-e) / pden, exp's argument shifted by 64 ln 2 where e > 64 and the quotient scaled by
// 2^-64, so that exp(-e) is not subnormal (which WGSL may flush) while the result is normal.
fn brdf_beckmann_exp_over(e: f32, pden: f32) -> f32 {
    let big = e > 64.0;
    // 64 ln 2, and 2^-64.
    let x = exp(-(e - select(0.0, 44.3614195558365, big)));
    let scale = select(1.0, 5.421010862427522e-20, big);
    return x * (scale / max(pden, 1.17549435e-38));
}

// The anisotropic distribution `beckmann::Beckmann` as functions of its constructor's
// arguments (alpha_x, alpha_y) and local-frame directions (the normal is z). A zero direction
// takes the horizon's values, as in the Rust methods.

// (|z|, r, a) of a direction: r = sqrt((alpha_x x)^2 + (alpha_y y)^2) = alpha(phi) sin(theta),
// a = |z| / r.
fn brdf_beckmann_smith(alpha_x: f32, alpha_y: f32, w: vec3<f32>) -> vec3<f32> {
    let v = brdf_horizon_if_zero(w);
    let px = brdf_clamp_alpha(alpha_x) * v.x;
    let py = brdf_clamp_alpha(alpha_y) * v.y;
    let z = abs(v.z);
    let r = sqrt(px * px + py * py);
    return vec3<f32>(z, r, brdf_beckmann_a(z, r));
}

// D(m) = exp(-((x / ax)^2 + (y / ay)^2) / z^2) / (pi ax ay z^4) for m.z > 0, else 0 (Walter et
// al. 2007, eq. 25; Heitz 2014, eq. 80).
fn beckmann_Beckmann_d(alpha_x: f32, alpha_y: f32, m_x: f32, m_y: f32, m_z: f32) -> f32 {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let u = m_x / ax;
    let v = m_y / ay;
    let z2 = m_z * m_z;
    let e = (u * u + v * v) / z2;
    return brdf_above(m_z, brdf_beckmann_exp_over(e, ax * ay * z2 * z2 * BRDF_PI));
}

// Lambda(w) = P / Q at a = |z| / (alpha(phi) sin(theta)) (Heitz 2014, eq. 83 on vectors), the
// pole at the horizon capped at the largest finite f32.
fn beckmann_Beckmann_lambda(alpha_x: f32, alpha_y: f32, w_x: f32, w_y: f32, w_z: f32) -> f32 {
    let s = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(w_x, w_y, w_z));
    return brdf_beckmann_lambda_of_a(s.z);
}

// |z| Lambda = r P / (a + K) (|z| / Q = r / (a + K)): finite at the horizon, 0 at the normal.
fn brdf_beckmann_cos_lambda(s: vec3<f32>) -> f32 {
    let pq = brdf_beckmann_pq(s.z);
    return s.y * pq.x / (s.z + pq.z);
}

// |z| Lambda(w) = r P / (a + K): finite at the horizon (alpha(phi) / (2 sqrt(pi)) there), 0 at
// the normal.
fn beckmann_Beckmann_cos_lambda(alpha_x: f32, alpha_y: f32, w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return brdf_beckmann_cos_lambda(brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(w_x, w_y, w_z)));
}

// G1(w) = Q / (Q + P) (Heitz 2014, eqs. 43 and 83): 0 at the horizon, 1 at the normal.
fn beckmann_Beckmann_g1(alpha_x: f32, alpha_y: f32, w_x: f32, w_y: f32, w_z: f32) -> f32 {
    let s = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(w_x, w_y, w_z));
    return brdf_beckmann_g1_of_a(s.z);
}

// The height-correlated G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014, eq. 99), written
// with the finite |z| Lambda as |o.z| |i.z| / (|o.z| |i.z| + |i.z| |o.z| Lo + |o.z| |i.z| Li),
// so that the capped poles cannot overflow the sum; 0 where either direction is at the horizon.
fn beckmann_Beckmann_g2_correlated(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let o = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let i = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(wi_x, wi_y, wi_z));
    let zz = o.x * i.x;
    let den = zz + i.x * brdf_beckmann_cos_lambda(o) + o.x * brdf_beckmann_cos_lambda(i);
    return select(0.0, zz / den, zz > 0.0);
}

// The separable G2 = G1(wo) G1(wi) (Heitz 2014, eq. 98).
fn beckmann_Beckmann_g2_separable(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return beckmann_Beckmann_g1(alpha_x, alpha_y, wo_x, wo_y, wo_z)
        * beckmann_Beckmann_g1(alpha_x, alpha_y, wi_x, wi_y, wi_z);
}

// V = G2 / (4 |o.z| |i.z|) = 1 / (4 (|o.z| |i.z| + |i.z| |o.z| Lo + |o.z| |i.z| Li)) (Heitz
// 2014, eq. 99), capped at the largest finite f32; 0 where both directions are at the horizon.
fn beckmann_Beckmann_v_correlated(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let o = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let i = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(wi_x, wi_y, wi_z));
    let den = o.x * i.x + i.x * brdf_beckmann_cos_lambda(o) + o.x * brdf_beckmann_cos_lambda(i);
    return select(0.0, min(0.25 / den, BRDF_F32_MAX), den > 0.0);
}

// The distribution of visible normals D_wo(m) = G1(wo) max(0, wo.m) D(m) / |wo.z| (Heitz 2014,
// eq. 38), G1 / |wo.z| = 1 / (|wo.z| + |wo.z| Lambda) finite at the horizon (0 there).
fn beckmann_Beckmann_d_visible(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, m_x: f32, m_y: f32, m_z: f32,
) -> f32 {
    let o = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let g1_over_cos = select(0.0, 1.0 / (o.x + brdf_beckmann_cos_lambda(o)), o.x > 0.0);
    let cos_om = max(wo_x * m_x + wo_y * m_y + wo_z * m_z, 0.0);
    let d = beckmann_Beckmann_d(alpha_x, alpha_y, m_x, m_y, m_z);
    return min(min(g1_over_cos * cos_om, BRDF_F32_MAX) * d, BRDF_F32_MAX);
}
