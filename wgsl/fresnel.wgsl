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

// The exact unpolarized dielectric reflectance in working precision, the twin of
// fresnel::dielectric_fast operation for operation: the cancellation-free arrangement of
// fresnel_dielectric_polarized (c = |cos_theta_i|, s2 = (1 - c)(1 + c), a = c, m = (eta - 1)
// (eta + 1) from outside; a = eta c, m = -(eta - 1)(eta + 1) from inside), with g2 taken as
// eta^2 - s2 (outside) resp. 1 - eta^2 s2 (inside) where a^2 + m would cancel and that form's
// larger term is the smaller, W = eta^2 c^2 - s2 resp. c^2 - eta^2 s2 (its one cancellation the
// Brewster zero), r_perp = -m / (a (a + 2 g) + g2), r_par = (eta^2 - 1) W f / (x (x + 2 y) + y^2);
// and beyond eta in [1/256, 256] the textbook ratios of nu (eta outside, 1 / eta inside):
// r_perp = (c / nu - cos_t) / (c / nu + cos_t), r_par = (nu c - cos_t) / (nu c + cos_t) for
// nu > 256 (nu c capped at 2^32), r_perp = (c - g) / (c + g), r_par = (nu^2 c - g) / (nu^2 c + g)
// with g = sqrt(nu^2 - s2) for nu < 1/256 (nu raised to 2^-40). F = (r_perp^2 + r_par^2) / 2
// capped at 1; 1 under total internal reflection (Born and Wolf, "Principles of Optics", 1.5.2).
// 1 / nu outside is taken as 1 / min(eta, 2^64): beyond 2^64 it only scales c / nu, which
// moves r_perp^2 by less than 2^-62 there, and keeps the divisor inside [2^-126, 2^126], where
// WGSL promises x / y; 1 / eta inside as 1 / min(eta, 2^40), the same f32 as the Rust kernel's
// max(1 / eta, 2^-40).
fn fresnel_dielectric_fast(cos_theta_i: f32, eta: f32) -> f32 {
    let inside = cos_theta_i < 0.0;
    let c = min(abs(cos_theta_i), 1.0);
    let s2 = (1.0 - c) * (1.0 + c);
    let cc = c * c;

    // The moderate path, on eta clamped into its range (the extreme rows discard it).
    let n = clamp(eta, 0.00390625, 256.0);
    let n2 = n * n;
    let n2m1 = (n - 1.0) * (n + 1.0);
    let a = select(c, n * c, inside);
    let a2 = a * a;
    let m = select(n2m1, -n2m1, inside);
    let other_form = select(n2 - s2, fma(-n2, s2, 1.0), inside);
    let other_max = select(max(n2, s2), 1.0, inside);
    let cancels = (inside & (n > 1.0)) | (!inside & (n < 1.0));
    let use_other = cancels & (max(a2, -m) > other_max);
    let g2 = select(a2 + m, other_form, use_other);
    let g = sqrt(max(g2, 0.0));
    let d_perp = fma(a, fma(2.0, g, a), g2);
    let f = select(1.0, n2, inside);
    let w = select(fma(n2, cc, -s2), fma(-n2, s2, cc), inside);
    let x = n2 * select(a, g, inside);
    let y = select(g, a, inside);
    let y2 = select(g2, a2, inside);
    let d_par = fma(x, fma(2.0, y, x), y2);
    let tir_moderate = g2 < 0.0;

    // The extreme path: nu = eta (outside) or 1 / eta (inside).
    let big_nu = (inside & !(eta > 1.0)) | (!inside & (eta > 1.0));
    let mu = select(1.0 / min(eta, 18446744073709551616.0), eta, inside);
    let nu_c = min(select(eta * c, c / eta, inside), 4294967296.0);
    let nu = select(eta, 1.0 / min(eta, 1099511627776.0), inside);
    let nu_lo = max(nu, 9.094947017729282e-13);
    let nu2 = nu_lo * nu_lo;
    let rad = select(nu2 - s2, fma(s2 * mu, -mu, 1.0), big_nu);
    let root = sqrt(max(rad, 0.0));
    let p = select(c, c * mu, big_nu);
    let q = select(nu2 * c, nu_c, big_nu);
    let tir_extreme = !big_nu & (rad < 0.0);

    let extreme = (eta > 256.0) | (eta < 0.00390625);
    let num_perp = select(-m, p - root, extreme);
    let den_perp = select(d_perp, p + root, extreme);
    let num_par = select(n2m1 * w * f, q - root, extreme);
    let den_par = select(d_par, q + root, extreme);
    // A zero denominator comes with a zero numerator (eta = 1 at c = 0, or a cosine whose
    // square underflows): the ratio is 0 there.
    let r_perp = select(num_perp / select(den_perp, 1.0, den_perp == 0.0), 0.0, den_perp == 0.0);
    let r_par = select(num_par / select(den_par, 1.0, den_par == 0.0), 0.0, den_par == 0.0);
    let tir = (extreme & tir_extreme) | (!extreme & tir_moderate);
    let reflectance = min(0.5 * (r_perp * r_perp + r_par * r_par), 1.0);
    return select(reflectance, 1.0, tir);
}

// Exact unpolarized conductor Fresnel reflectance F = (|r_perp|^2 + |r_par|^2) / 2 for the
// complex relative IOR N = eta + i k (Born and Wolf, "Principles of Optics", section 14.2), in
// the Rust kernels' cancellation-free arrangement (fresnel::conductor_fast; r_perp =
// -u / (c + s)^2 as in Lagarde 2013, "Memo on Fresnel equations"):
//   F = |u|^2 A / (|c + s|^4 (A + B)),  u = N^2 - 1,  s = sqrt(N^2 - sin^2 theta_i),
//   A = c^2 |s|^2 + s2^2,  B = 2 c s2 Re(s),  |c + s|^2 = c (c + 2 Re(s)) + |s|^2,
// s2 = (1 - c)(1 + c), Re(N^2) - 1 = (eta - 1)(eta + 1) - k^2: every sum adds non-negative
// terms. N is scaled by 1 / max(eta, k) above 2^16 and raised to 2^-46 below it, z = s^2 and
// u by powers of two (exact) so that no square overflows or underflows (the scalings of the
// Rust kernel's f32 path). eta in (0, MAX], k in [0, MAX]; c = cos_theta_i clamped to [0, 1];
// 1 at c = 0 (0 for eta = 1, k = 0: no interface).
fn fresnel_conductor_fast(cos_theta_i: f32, eta: f32, k: f32) -> f32 {
    let big = max(eta, k);
    // 2^16 and 2^-46 (f32's epsilon squared).
    let large = big > 65536.0;
    let tiny = big < 1.4210854715202004e-14;
    let n_scale = select(1.0, 1.4210854715202004e-14, tiny) / select(1.0, big, large | tiny);
    let re = eta * n_scale;
    let im = k * n_scale;
    let m = select(1.0, n_scale, large);
    let sigma = select(1.0, big, large);
    let n2_re = fma(re, re, -(im * im));
    let u_re = fma(re - m, re + m, -(im * im));
    let u_im = 2.0 * re * im;
    let u_abs2 = fma(u_re, u_re, u_im * u_im);
    // |u| < 2^-40 (eta = 1, k tiny): z scaled by 2^63 and u by 2^61 before squaring; else z
    // by 2^27.
    let lifted = u_abs2 < 8.271806125530277e-25;
    let z_up = select(134217728.0, 9.223372036854776e18, lifted);
    let z_down = select(7.450580596923828e-9, 1.0842021724855044e-19, lifted);
    let t_down = select(6.103515625e-5, 2.3283064365386963e-10, lifted);
    let lift = select(1.0, 2.305843009213694e18, lifted);
    let ul_re = u_re * lift;
    let ul_im = u_im * lift;
    let ul_abs2 = fma(ul_re, ul_re, ul_im * ul_im);
    let ml = m * lift;
    let zl_down = z_down * lift;
    // |Im z| raised to 2^-60 where lifted, which keeps |c + s|^4 normal even at u = 0.
    let b = max(abs(u_im) * z_up, select(0.0, 8.673617379884035e-19, lifted));
    let no_interface = (u_re == 0.0) & (u_im == 0.0);
    let c = saturate(cos_theta_i);
    let s2 = (1.0 - c) * (1.0 + c);
    let cm = c * m;
    let cm2 = cm * cm;
    // z = u + (c m)^2 where (c m)^2 <= Re N^2, else Re N^2 - s2 m^2: the form adding the
    // smaller terms.
    let z_re = select(fma(s2, -(m * m), n2_re), fma(cm, cm, u_re), cm2 <= n2_re);
    // The principal root without cancellation (Press et al., "Numerical Recipes", 5.5):
    // t = sqrt(|z| + |Re z|) (scaled), 2 Re(s) = g t.
    let a = abs(z_re) * z_up;
    let norm = sqrt(fma(a, a, b * b));
    let sum = norm + a;
    let t = sqrt(sum);
    let g = select((b + b) * t_down / sum, 2.0 * t_down, z_re >= 0.0);
    let s_abs2 = norm * z_down;
    let pl_abs2 = (c * ml) * fma(g, t, cm) + norm * zl_down;
    // rho = c sigma capped at 2^46, where A / (A + B) rounds to 1 regardless.
    let rho = min(c * sigma, 70368744177664.0);
    let a_par = fma(rho * rho, s_abs2, s2 * s2);
    let ab = fma(rho * s2 * g, t, a_par);
    let ratio = (ul_abs2 * a_par) / (pl_abs2 * pl_abs2 * ab);
    return select(select(1.0, 0.0, no_interface), min(ratio, 1.0), c > 0.0);
}

// The exact conductor Fresnel of fresnel::conductor: the same F in the same arrangement as
// fresnel_conductor_fast (the Rust kernel evaluates it in f64 and rounds once; the twin
// computes in f32).
fn fresnel_conductor(cos_theta_i: f32, eta: f32, k: f32) -> f32 {
    return fresnel_conductor_fast(cos_theta_i, eta, k);
}

// fresnel_conductor per channel of RGB eta and k.
fn fresnel_conductor_rgb(
    cos_theta_i: f32, eta_r: f32, eta_g: f32, eta_b: f32, k_r: f32, k_g: f32, k_b: f32,
) -> vec3<f32> {
    return vec3<f32>(
        fresnel_conductor(cos_theta_i, eta_r, k_r),
        fresnel_conductor(cos_theta_i, eta_g, k_g),
        fresnel_conductor(cos_theta_i, eta_b, k_b),
    );
}
