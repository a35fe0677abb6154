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
