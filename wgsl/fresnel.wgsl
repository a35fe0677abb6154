// brdf: Fresnel reflectance, the twins of the Rust module `fresnel`. Needs common.wgsl.

// (1 - c)^5 for c = cos_theta clamped to [0, 1], with the rounding of 1 - c fed back as a
// first-order correction 5 (1 - c)^4 e, e = (1 - (1 - c)) - c (fresnel::one_minus_pow5). An
// implementation that reassociates may fold e to 0; the bound of the tests allows for it.
fn brdf_one_minus_pow5(cos_theta: f32) -> f32 {
    let c = saturate(cos_theta);
    let y = 1.0 - c;
    let e = (1.0 - y) - c;
    let y2 = y * y;
    let y4 = y2 * y2;
    return y4 * y + y4 * (5.0 * e);
}

// a (1 - w) + w b in one fused step where the implementation fuses (fresnel::lerp_exact): exact
// at w = 0 and w = 1.
fn brdf_lerp(a: f32, b: f32, w: f32) -> f32 {
    return fma(a, 1.0 - w, w * b);
}

// Normal-incidence reflectance F0 = ((eta - 1) / (eta + 1))^2 (Fresnel's equations at normal
// incidence; Born and Wolf, "Principles of Optics", 1.5.2). eta > 0, capped at 2^40, above
// which F0 rounds to 1 - 4 / eta in f32 anyway.
fn fresnel_f0_from_ior(eta: f32) -> f32 {
    let e = min(eta, 1099511627776.0);
    let r = (e - 1.0) / (e + 1.0);
    return r * r;
}

// The IOR of a normal-incidence reflectance, (1 + sqrt(F0)) / (1 - sqrt(F0)), F0 clamped to
// [0, 1], capped at the largest finite f32 (at F0 = 1).
fn fresnel_ior_from_f0(f0: f32) -> f32 {
    let s = sqrt(saturate(f0));
    let den = 1.0 - s;
    return min(select(BRDF_F32_MAX, (1.0 + s) / den, den > 0.0), BRDF_F32_MAX);
}

// Schlick's approximation F = F0 + (1 - F0)(1 - c)^5 (Schlick 1994, "An Inexpensive BRDF Model
// for Physically-based Rendering", eq. 15), c = v_dot_h clamped to [0, 1].
fn fresnel_schlick(f0: f32, v_dot_h: f32) -> f32 {
    return brdf_lerp(f0, 1.0, brdf_one_minus_pow5(v_dot_h));
}

// Schlick with a grazing value F90 (Burley 2012, "Physically-Based Shading at Disney"):
// F = F0 + (F90 - F0)(1 - c)^5.
fn fresnel_schlick_f90(f0: f32, f90: f32, v_dot_h: f32) -> f32 {
    return brdf_lerp(f0, f90, brdf_one_minus_pow5(v_dot_h));
}

// fresnel_schlick per channel of an RGB F0.
fn fresnel_schlick_rgb(f0_r: f32, f0_g: f32, f0_b: f32, v_dot_h: f32) -> vec3<f32> {
    let w = brdf_one_minus_pow5(v_dot_h);
    return vec3<f32>(brdf_lerp(f0_r, 1.0, w), brdf_lerp(f0_g, 1.0, w), brdf_lerp(f0_b, 1.0, w));
}

// fresnel_schlick_f90 per channel of RGB F0 and F90.
fn fresnel_schlick_f90_rgb(
    f0_r: f32, f0_g: f32, f0_b: f32, f90_r: f32, f90_g: f32, f90_b: f32, v_dot_h: f32,
) -> vec3<f32> {
    let w = brdf_one_minus_pow5(v_dot_h);
    return vec3<f32>(brdf_lerp(f0_r, f90_r, w), brdf_lerp(f0_g, f90_g, w), brdf_lerp(f0_b, f90_b, w));
}

// Schlick with the spherical-Gaussian power (Karis 2013, "Real Shading in Unreal Engine 4"):
// (1 - c)^5 replaced by 2^((-5.55473 c - 6.98316) c).
fn fresnel_schlick_sg(f0: f32, v_dot_h: f32) -> f32 {
    let c = saturate(v_dot_h);
    let w = exp2(fma(c, -5.55473, -6.98316) * c);
    return brdf_lerp(f0, 1.0, w);
}

// Schlick with an F82 tint for metals (Hoffman 2019, "Fresnel Equations Considered Harmful";
// Kutz et al. 2021, "Novel aspects of the Adobe Standard Material"):
// F = max(Schlick(F0, c) - b c (1 - c)^6, 0), b = Schlick(F0, 1/7) (1 - tint) / (1/7 (6/7)^6).
fn fresnel_schlick_f82(f0: f32, f82_tint: f32, cos_theta: f32) -> f32 {
    // 1/7 (1 - 1/7)^6, rounded to f32 from its f64 value as in the Rust kernel.
    let denom = 0.0566527795148523;
    let b = fresnel_schlick(f0, 0.14285714285714285) * (1.0 - f82_tint) / denom;
    let mu = saturate(cos_theta);
    let y = 1.0 - mu;
    let y2 = y * y;
    let y4 = y2 * y2;
    let dip = b * mu * (y2 * y4);
    return max(fresnel_schlick(f0, mu) - dip, 0.0);
}

// fresnel_schlick_f82 per channel.
fn fresnel_schlick_f82_rgb(
    f0_r: f32, f0_g: f32, f0_b: f32, f82_tint_r: f32, f82_tint_g: f32, f82_tint_b: f32,
    cos_theta: f32,
) -> vec3<f32> {
    return vec3<f32>(
        fresnel_schlick_f82(f0_r, f82_tint_r, cos_theta),
        fresnel_schlick_f82(f0_g, f82_tint_g, cos_theta),
        fresnel_schlick_f82(f0_b, f82_tint_b, cos_theta),
    );
}

// Kulla and Conty's rational fit of the dielectric Fresnel average (Kulla and Conty 2017,
// "Revisiting Physically Based Shading at Imageworks"): (eta - 1) / (4.08567 + 1.00071 eta)
// for eta >= 1 (divided through by eta so a large eta does not overflow), a cubic below.
fn fresnel_average_dielectric_fit(eta: f32) -> f32 {
    let inv = 1.0 / eta;
    let above = (1.0 - inv) / fma(inv, 4.08567, 1.00071);
    let below = fma(eta, fma(eta, fma(eta, -0.130607, -0.965241), 0.1014), 0.997118);
    return select(below, above, eta >= 1.0);
}

// Exact dielectric reflectances (Rs, Rp) for s- and p-polarized light (Fresnel 1823; Born and
// Wolf, "Principles of Optics", 1.5.2), cos_theta_i in [-1, 1] (negative: from inside, the
// relative IOR then taken as 1 / eta), eta > 0. In the Rust kernel's cancellation-free form:
// with a = c (m = eta^2 - 1) from outside and a = eta c (m = 1 - eta^2) from inside,
// g^2 = a^2 + m, Rs = (m / (a + g)^2)^2 and Rp from x = eta^2 a (resp. eta^2 g), y = g (resp. a)
// as ((eta^2 - 1) W f / (x + y)^2)^2, W = (eta^2 + 1) c^2 - f, f = 1 (resp. eta^2), so the
// Brewster zero is W's; 1 and 1 under total internal reflection (g^2 < 0). The Rust kernel's
// second path for eta beyond [1/256, 256] has no twin: there eta^2 leaves f32's range first
// (beyond 2^64 or below 2^-64), where WGSL promises nothing.
fn fresnel_dielectric_polarized(cos_theta_i: f32, eta: f32) -> vec2<f32> {
    let inside = cos_theta_i < 0.0;
    let c = min(abs(cos_theta_i), 1.0);
    let n2 = eta * eta;
    let n2m1 = n2 - 1.0;
    let cc = c * c;
    let n2cc = n2 * cc;
    let a = select(c, eta * c, inside);
    let a2 = select(cc, n2cc, inside);
    let m = select(n2m1, -n2m1, inside);
    let g2 = a2 + m;
    let g = sqrt(max(g2, 0.0));
    // (a + g)^2 as a (a + 2 g) + g^2: a = 0 gives exactly g^2 = m and Rs = 1.
    let d_perp = a * (a + 2.0 * g) + g2;
    let f = select(1.0, n2, inside);
    let w = n2cc + cc - f;
    let x = n2 * select(a, g, inside);
    let y = select(g, a, inside);
    let y2 = select(g2, a2, inside);
    let d_par = x * (x + 2.0 * y) + y2;
    let r_perp = select(-m / d_perp, 0.0, d_perp == 0.0);
    let r_par = select(n2m1 * w * f / d_par, 0.0, d_par == 0.0);
    let tir = g2 < 0.0;
    let rs = select(min(r_perp * r_perp, 1.0), 1.0, tir);
    let rp = select(min(r_par * r_par, 1.0), 1.0, tir);
    return vec2<f32>(rs, rp);
}

// The unpolarized dielectric reflectance (Rs + Rp) / 2 (Born and Wolf 1.5.2).
fn fresnel_dielectric(cos_theta_i: f32, eta: f32) -> f32 {
    let r = fresnel_dielectric_polarized(cos_theta_i, eta);
    return 0.5 * (r.x + r.y);
}
