// brdf: samplers and the densities a shader needs to weight its samples, the twins of the
// Rust module `sampling` (the cosine-hemisphere sampler and pdf, the half-vector-to-reflection
// Jacobian, GGX's and Beckmann's D cos and visible-normal samplers, the D cos and
// visible-normal pdfs, GGX's and Beckmann's reflection samplers with their weights and pdfs,
// and erf^-1 with the erf and erfc it polishes with). Needs common.wgsl, ggx.wgsl and
// beckmann.wgsl.
//
// Angles: cos(2 pi u) and sin(2 pi u) through brdf_cos_sin_2pi (common.wgsl).

// The pdf max(0, w.z) / pi of cosine-weighted hemisphere sampling (Pharr, Jakob, Humphreys,
// "Physically Based Rendering", 4th ed., A.5.3).
fn sampling_cosine_hemisphere_pdf(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return max(w_z, 0.0) * BRDF_FRAC_1_PI;
}

// The pdf of the reflected direction from the pdf of the microfacet normal,
// pdf_m / (4 |v.h|) (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 14), capped at the largest finite f32; 0 where v.h = 0.
fn sampling_reflect_pdf(pdf_m: f32, v_dot_h: f32) -> f32 {
    let den = 4.0 * abs(v_dot_h);
    return select(0.0, min(pdf_m / den, BRDF_F32_MAX), den > 0.0);
}

// v / |v|, or (0, 0, 1) for the zero vector (vec3::V3::normalize_or with the normal as the
// fallback); |v|^2 in the order of the Rust V3::dot.
fn brdf_normalize_or_z(v: vec3<f32>) -> vec3<f32> {
    let len2 = fma(v.x, v.x, fma(v.y, v.y, v.z * v.z));
    let ok = len2 > 0.0;
    let inv = select(0.0, 1.0 / sqrt(len2), ok);
    return vec3<f32>(select(0.0, v.x * inv, ok), select(0.0, v.y * inv, ok),
        select(1.0, v.z * inv, ok));
}

// Cosine-weighted hemisphere sampling (Malley's method; Pharr, Jakob, Humphreys, "Physically
// Based Rendering", 4th ed., A.5.3): the direction (sqrt(u1) cos(2 pi u2), sqrt(u1)
// sin(2 pi u2), sqrt(1 - u1)) and its pdf z / pi.
fn sampling_cosine_hemisphere(u1: f32, u2: f32) -> vec4<f32> {
    let uc1 = brdf_clamp_u(u1);
    let r = sqrt(uc1);
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let z = sqrt(1.0 - uc1);
    return vec4<f32>(r * cs.x, r * cs.y, z, z * BRDF_FRAC_1_PI);
}

// The pdf D_wo(m) of visible-normal sampling (Heitz 2014, eq. 38) for the model `model`
// (0 = GGX, 1 = Beckmann), wo taken in the upper hemisphere (|wo.z|).
fn sampling_visible_normal_pdf(
    model: u32, alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32,
    m_x: f32, m_y: f32, m_z: f32,
) -> f32 {
    let z = abs(wo_z);
    return select(ggx_Ggx_d_visible(alpha_x, alpha_y, wo_x, wo_y, z, m_x, m_y, m_z),
        beckmann_Beckmann_d_visible(alpha_x, alpha_y, wo_x, wo_y, z, m_x, m_y, m_z),
        model == 1u);
}

// The view stretched to the unit-roughness configuration, normalize(alpha_x x, alpha_y y, |z|).
fn brdf_stretch(wo: vec3<f32>, ax: f32, ay: f32) -> vec3<f32> {
    return brdf_normalize_or_z(vec3<f32>(ax * wo.x, ay * wo.y, abs(wo.z)));
}

// The microfacet normal from a visible normal of the stretched configuration.
fn brdf_unstretch(h: vec3<f32>, ax: f32, ay: f32) -> vec3<f32> {
    return brdf_normalize_or_z(vec3<f32>(ax * h.x, ay * h.y, max(h.z, 0.0)));
}

// GGX visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of Visible Normals",
// JCGT 7(4)): a uniform disk point squashed onto the half the stretched view sees, lifted to
// the hemisphere, unstretched; with its pdf D_wo(m).
fn sampling_ggx_vndf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let m = brdf_ggx_vndf_normal(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z), u1, u2);
    let pdf = ggx_Ggx_d_visible(alpha_x, alpha_y, wo_x, wo_y, abs(wo_z), m.x, m.y, m.z);
    return vec4<f32>(m, pdf);
}

// The normal of sampling_ggx_vndf without its pdf (for the samplers that weigh their sample by
// another density).
fn brdf_ggx_vndf_normal(alpha_x: f32, alpha_y: f32, wo: vec3<f32>, u1: f32, u2: f32) -> vec3<f32> {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let vh = brdf_stretch(wo, ax, ay);
    let len2 = fma(vh.x, vh.x, vh.y * vh.y);
    let has_tangent = len2 > 0.0;
    let inv_len = select(0.0, 1.0 / sqrt(len2), has_tangent);
    let t1 = vec3<f32>(select(1.0, -vh.y * inv_len, has_tangent), vh.x * inv_len, 0.0);
    // vh x t1 with t1.z = 0.
    let t2 = vec3<f32>(-vh.z * t1.y, vh.z * t1.x, vh.x * t1.y - vh.y * t1.x);
    let r = sqrt(brdf_clamp_u(u1));
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let p1 = r * cs.x;
    let s = 0.5 * (1.0 + vh.z);
    let p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * (r * cs.y);
    let lift = sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0));
    let nh = vec3<f32>(t1.x * p1 + t2.x * p2 + vh.x * lift, t1.y * p1 + t2.y * p2 + vh.y * lift,
        t1.z * p1 + t2.z * p2 + vh.z * lift);
    return brdf_unstretch(nh, ax, ay);
}

// The normal of sampling_ggx_vndf_spherical_cap without its pdf (for the samplers that weigh
// their sample by another density).
fn brdf_ggx_vndf_spherical_cap_normal(
    alpha_x: f32, alpha_y: f32, wo: vec3<f32>, u1: f32, u2: f32,
) -> vec3<f32> {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let v = brdf_stretch(wo, ax, ay);
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u1));
    let z = fma(1.0 - brdf_clamp_u(u2), 1.0 + v.z, -v.z);
    let sin_theta = sqrt(max(1.0 - z * z, 0.0));
    let h = vec3<f32>(sin_theta * cs.x + v.x, sin_theta * cs.y + v.y, z + v.z);
    return brdf_unstretch(h, ax, ay);
}

// GGX visible-normal sampling by spherical caps (Dupuy and Benyoub 2023, "Sampling Visible GGX
// Normals with Spherical Caps"): a uniform direction on the cap z >= -v.z around the
// stretched view, plus the view, unstretched; with its pdf D_wo(m).
fn sampling_ggx_vndf_spherical_cap(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let m = brdf_ggx_vndf_spherical_cap_normal(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z),
        u1, u2);
    let pdf = ggx_Ggx_d_visible(alpha_x, alpha_y, wo_x, wo_y, abs(wo_z), m.x, m.y, m.z);
    return vec4<f32>(m, pdf);
}

// The pdf of the reflected direction wi under GGX visible-normal sampling: D(h) / (4 (wo.z +
// wo.z Lambda(wo))) with h = normalize(wo + wi) (Heitz 2018, eq. 17 with Walter et al. 2007's
// Jacobian), capped at the largest finite f32; 0 where wo is at or below the horizon, wo.h <= 0
// or wi = 0.
fn sampling_ggx_reflection_pdf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let h = brdf_normalize_or_z(vec3<f32>(wo_x + wi_x, wo_y + wi_y, wo_z + wi_z));
    let c = wo_z;
    let inv = min(1.0 / (4.0 * (c + ggx_Ggx_cos_lambda(alpha_x, alpha_y, wo_x, wo_y, wo_z))),
        BRDF_F32_MAX);
    let wi_zero = (wi_x == 0.0) & (wi_y == 0.0) & (wi_z == 0.0);
    let wo_dot_h = fma(wo_x, h.x, fma(wo_y, h.y, wo_z * h.z));
    let visible = (c > 0.0) & (wo_dot_h > 0.0) & !wi_zero;
    let d = ggx_Ggx_d(alpha_x, alpha_y, h.x, h.y, h.z);
    return select(0.0, min(inv * d, BRDF_F32_MAX), visible);
}

// The pdf of the reflected direction wi under Beckmann visible-normal sampling: D(h) / (4 (wo.z
// + wo.z Lambda(wo))) with h = normalize(wo + wi) (Heitz and d'Eon 2014; Walter et al. 2007,
// eq. 14), capped at the largest finite f32; 0 where wo is at or below the horizon, wo.h <= 0
// or wi = 0. The same form as sampling_ggx_reflection_pdf.
fn sampling_beckmann_reflection_pdf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let h = brdf_normalize_or_z(vec3<f32>(wo_x + wi_x, wo_y + wi_y, wo_z + wi_z));
    let c = wo_z;
    let inv = min(1.0 / (4.0 * (c + beckmann_Beckmann_cos_lambda(alpha_x, alpha_y, wo_x, wo_y,
        wo_z))), BRDF_F32_MAX);
    let wi_zero = (wi_x == 0.0) & (wi_y == 0.0) & (wi_z == 0.0);
    let wo_dot_h = fma(wo_x, h.x, fma(wo_y, h.y, wo_z * h.z));
    let visible = (c > 0.0) & (wo_dot_h > 0.0) & !wi_zero;
    let d = beckmann_Beckmann_d(alpha_x, alpha_y, h.x, h.y, h.z);
    return select(0.0, min(inv * d, BRDF_F32_MAX), visible);
}

// The pdf D(m) max(m.z, 0) of sampling the normal from D cos (Walter et al. 2007, eq. 24) for
// the model `model` (0 = GGX, 1 = Beckmann).
fn sampling_d_cos_pdf(
    model: u32, alpha_x: f32, alpha_y: f32, m_x: f32, m_y: f32, m_z: f32,
) -> f32 {
    let d = select(ggx_Ggx_d(alpha_x, alpha_y, m_x, m_y, m_z),
        beckmann_Beckmann_d(alpha_x, alpha_y, m_x, m_y, m_z), model == 1u);
    return d * max(m_z, 0.0);
}

// GGX normal sampled from D cos (Walter et al. 2007, eqs. 35-36, anisotropic through the
// slopes): slope radius sqrt(u1 / (1 - u1)) at the angle 2 pi u2, the normal
// normalize(-alpha_x s_x, -alpha_y s_y, 1); with its pdf D(m) m.z.
fn sampling_ggx_d_cos(alpha_x: f32, alpha_y: f32, u1: f32, u2: f32) -> vec4<f32> {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let uc1 = brdf_clamp_u(u1);
    let r = sqrt(uc1 / (1.0 - uc1));
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let m = brdf_normalize_or_z(vec3<f32>(-ax * (r * cs.x), -ay * (r * cs.y), 1.0));
    return vec4<f32>(m, sampling_d_cos_pdf(0u, alpha_x, alpha_y, m.x, m.y, m.z));
}

// The GGX reflection sample without its Fresnel factor (the Rust kernel's reflection_parts):
// (wi, pdf, G2 / G1(wo), wo.m) for the visible normal m of sampling_ggx_vndf_spherical_cap,
// wi = 2 (wo.m) m - wo, pdf = sampling_ggx_reflection_pdf(wo, wi). G2 / G1(wo) =
// (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)) is written pole-free as
// |i.z| (|o.z| + s_o) / (|i.z| s_o + |o.z| s_i), s = sqrt(z^2 + q) of each direction
// (brdf_ggx_smith; Lambda = (s - |z|) / (2 |z|)): the Rust kernel's form with each Lambda
// capped at f32's largest value would leave f32's range in the sum. 0 unless wo and wi lie
// above the horizon.
fn brdf_sampling_ggx_reflection_parts(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> array<f32, 6> {
    let m = sampling_ggx_vndf_spherical_cap(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    let o_m = fma(wo_x, m.x, fma(wo_y, m.y, wo_z * m.z));
    let k = 2.0 * o_m;
    let wi = vec3<f32>(m.x * k - wo_x, m.y * k - wo_y, m.z * k - wo_z);
    let pdf = sampling_ggx_reflection_pdf(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi.x, wi.y, wi.z);
    let o = brdf_ggx_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let i = brdf_ggx_smith(alpha_x, alpha_y, wi);
    let den = i.x * o.z + o.x * i.z;
    let above = (wo_z > 0.0) & (wi.z > 0.0);
    // The floor keeps the unused branch finite where both cosines are 0.
    let ratio = select(0.0, i.x * (o.x + o.z) / max(den, 1.17549435e-38), above);
    return array<f32, 6>(wi.x, wi.y, wi.z, pdf, ratio, saturate(o_m));
}

// Samples the Cook-Torrance reflection lobe of a GGX surface with a constant Fresnel factor F
// (>= 0): (wi.x, wi.y, wi.z, pdf, weight) with the visible normal m of
// sampling_ggx_vndf_spherical_cap (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals"; Dupuy and Benyoub 2023), wi = 2 (wo.m) m - wo, pdf =
// sampling_ggx_reflection_pdf(wo, wi) and the weight f wi.z / pdf = F G2 / G1(wo) capped at
// the largest finite f32 (D and the cosines cancel; Heitz and d'Eon 2014). A wi reflected
// below the horizon keeps its pdf with weight 0; wo at or below the horizon gives pdf 0 and
// weight 0. u1, u2 clamped into [0, 1).
fn sampling_ggx_reflection(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
    fresnel: f32,
) -> array<f32, 5> {
    let p = brdf_sampling_ggx_reflection_parts(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    return array<f32, 5>(p[0], p[1], p[2], p[3], min(p[4] * fresnel, BRDF_F32_MAX));
}

// sampling_ggx_reflection with a constant RGB Fresnel factor: (wi.x, wi.y, wi.z, pdf,
// weight_r, weight_g, weight_b), the weight F_c G2 / G1(wo) per channel.
fn sampling_ggx_reflection_rgb(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
    fresnel_r: f32, fresnel_g: f32, fresnel_b: f32,
) -> array<f32, 7> {
    let p = brdf_sampling_ggx_reflection_parts(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    return array<f32, 7>(p[0], p[1], p[2], p[3], min(p[4] * fresnel_r, BRDF_F32_MAX),
        min(p[4] * fresnel_g, BRDF_F32_MAX), min(p[4] * fresnel_b, BRDF_F32_MAX));
}

// Beckmann's D cos sampler (Walter et al. 2007, eqs. 28-29, anisotropic through the slopes):
// slope radius sqrt(-ln(1 - u1)) (the unit Beckmann's slopes are a 2D Gaussian of variance
// 1/2) at the angle 2 pi u2, the normal normalize(-alpha_x s_x, -alpha_y s_y, 1); with its pdf
// D(m) m.z.
fn sampling_beckmann_d_cos(alpha_x: f32, alpha_y: f32, u1: f32, u2: f32) -> vec4<f32> {
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let uc1 = brdf_clamp_u(u1);
    let r = sqrt(max(-log(1.0 - uc1), 0.0));
    let cs = brdf_cos_sin_2pi(brdf_clamp_u(u2));
    let m = brdf_normalize_or_z(vec3<f32>(-ax * (r * cs.x), -ay * (r * cs.y), 1.0));
    return vec4<f32>(m, sampling_d_cos_pdf(1u, alpha_x, alpha_y, m.x, m.y, m.z));
}

// erf and erfc. WGSL has neither: these follow, range for range and coefficient for
// coefficient, the f32 error function the Rust kernels call in f32 (the `libm` crate's erff
// and erfcf, after FreeBSD's s_erff.c, Sun's fdlibm s_erf.c converted to float by Ian Lance
// Taylor): erf(x) = x + x P(x^2) / Q(x^2) below 0.84375; erfc(x) = 1 - erx - P(s) / Q(s),
// s = x - 1, up to 1.25; beyond, erfc(x) = exp(-z^2 - 0.5625) exp((z - x)(z + x) + R(1 / x^2) /
// S(1 / x^2)) / x with z a short copy of x whose square is exact, R / S fitted on [1.25,
// 1 / 0.35] and on [1 / 0.35, 28]; erf = 1 - erfc up to 6, then 1. z keeps 8 bits after the
// point (fdlibm keeps 12 significant bits by masking x's bits; WGSL's bitcast is not modelled
// by brdf-gpu's bound): either way z^2 is exact and the product of the two exponentials is the
// same function. fdlibm's branch for |x| < 2^-28 (which keeps x^2 from underflowing) is not
// needed: the polynomial in x^2 = 0 gives the same x + x P(0) / Q(0).

// P(x^2) / Q(x^2) of erf's first range.
fn brdf_erf_pq(x: f32) -> f32 {
    let z = x * x;
    let r = 1.2837916613e-01 + z * (-3.2504209876e-01 + z * (-2.8481749818e-02
        + z * (-5.7702702470e-03 + z * -2.3763017452e-05)));
    let s = 1.0 + z * (3.9791721106e-01 + z * (6.5022252500e-02 + z * (5.0813062117e-03
        + z * (1.3249473704e-04 + z * -3.9602282413e-06))));
    return r / s;
}

// erfc(a) for a in [0.84375, 28) (fdlibm's erfc1 below 1.25, erfc2 above).
fn brdf_erfc_mid(a: f32) -> f32 {
    let s1 = a - 1.0;
    let p = -2.3621185683e-03 + s1 * (4.1485610604e-01 + s1 * (-3.7220788002e-01
        + s1 * (3.1834661961e-01 + s1 * (-1.1089469492e-01 + s1 * (3.5478305072e-02
        + s1 * -2.1663755178e-03)))));
    let q = 1.0 + s1 * (1.0642088205e-01 + s1 * (5.4039794207e-01 + s1 * (7.1828655899e-02
        + s1 * (1.2617121637e-01 + s1 * (1.3637083583e-02 + s1 * 1.1984500103e-02)))));
    // 1 - erx, erx = 8.4506291151e-01.
    let near_one = 1.0 - 8.4506291151e-01 - p / q;
    let s = 1.0 / (a * a);
    let ra = -9.8649440333e-03 + s * (-6.9385856390e-01 + s * (-1.0558626175e+01
        + s * (-6.2375331879e+01 + s * (-1.6239666748e+02 + s * (-1.8460508728e+02
        + s * (-8.1287437439e+01 + s * -9.8143291473e+00))))));
    let sa = 1.0 + s * (1.9651271820e+01 + s * (1.3765776062e+02 + s * (4.3456588745e+02
        + s * (6.4538726807e+02 + s * (4.2900814819e+02 + s * (1.0863500214e+02
        + s * (6.5702495575e+00 + s * -6.0424413532e-02)))))));
    let rb = -9.8649431020e-03 + s * (-7.9928326607e-01 + s * (-1.7757955551e+01
        + s * (-1.6063638306e+02 + s * (-6.3756646729e+02 + s * (-1.0250950928e+03
        + s * -4.8351919556e+02)))));
    let sb = 1.0 + s * (3.0338060379e+01 + s * (3.2579251099e+02 + s * (1.5367296143e+03
        + s * (3.1998581543e+03 + s * (2.5530502930e+03 + s * (4.7452853394e+02
        + s * -2.2440952301e+01))))));
    // 1 / 0.35, fdlibm's switch (0x4036db6d).
    let first = a < 2.857142686843872;
    let rs = select(rb / sb, ra / sa, first);
    let z = floor(a * 256.0) * 0.00390625;
    let far = exp(-z * z - 0.5625) * exp((z - a) * (z + a) + rs) / a;
    return select(far, near_one, a < 1.25);
}

// erf(x) (libm's erff).
fn brdf_erf(x: f32) -> f32 {
    let a = abs(x);
    let small = x + x * brdf_erf_pq(x);
    let y = select(1.0, 1.0 - brdf_erfc_mid(a), a < 6.0);
    return select(select(y, -y, x < 0.0), small, a < 0.84375);
}

// erfc(x) for x >= 0 (libm's erfcf on the half erf^-1's polish uses).
fn brdf_erfc_nonneg(x: f32) -> f32 {
    let y = brdf_erf_pq(x);
    let low = select(0.5 - (x - 0.5 + x * y), 1.0 - (x + x * y), x < 0.25);
    let mid = select(0.0, brdf_erfc_mid(x), x < 28.0);
    return select(mid, low, x < 0.84375);
}

// One Newton step of erf^-1(y) from x (the Rust kernel's polish): on erf(x) - y for
// |y| <= 1/2 (q = 1 - |y| >= 1/2), on ln(erfc(|x|) / q) beyond; the derivative
// 2 / sqrt(pi) exp(-x^2) in both; x kept where the derivative underflows. The Rust kernel's
// guard on a non-finite step has no twin (WGSL has no infinity; the step is finite for every
// f32 y in (-1, 1)). brdf-gpu's bound treats a `_newton` function by its Newton-step rule.
fn brdf_erf_inv_newton(x: f32, y: f32, q: f32) -> f32 {
    let deriv = 2.0 * 0.5641895835477563 * exp(-x * x);
    let ec = brdf_erfc_nonneg(abs(x));
    let tail_step = -log(ec / q) * ec * select(-1.0, 1.0, y >= 0.0);
    let e = brdf_erf(x);
    let step = select(e - y, tail_step, q < 0.5) / deriv;
    return select(x, x - step, deriv > 0.0);
}

// The inverse error function erf^-1(y) for y in (-1, 1) (Giles 2010, "Approximating the
// erfinv function", GPU Computing Gems Jade: his single-precision polynomials in
// w = -ln((1 - y)(1 + y)), central below w = 5, in sqrt(w) beyond), polished by two Newton
// steps (brdf_erf_inv_newton), as the Rust kernel. At y = +-1, where the Rust kernel gives
// +-inf, WGSL has no infinity: (1 - y)(1 + y) is floored at f32's smallest normal there, a
// value near +-9.4 (every f32 y inside (-1, 1) leaves the floor unused).
fn sampling_erf_inv(y: f32) -> f32 {
    let w = -log(max((1.0 - y) * (1.0 + y), 1.17549435e-38));
    let wc = w - 2.5;
    let central = fma(fma(fma(fma(fma(fma(fma(fma(2.81022636e-08, wc, 3.43273939e-07), wc,
        -3.5233877e-06), wc, -4.39150654e-06), wc, 0.00021858087), wc, -0.00125372503), wc,
        -0.00417768164), wc, 0.246640727), wc, 1.50140941);
    let wt = sqrt(max(w, 0.0)) - 3.0;
    let tail = fma(fma(fma(fma(fma(fma(fma(fma(-0.000200214257, wt, 0.000100950558), wt,
        0.00134934322), wt, -0.00367342844), wt, 0.00573950773), wt, -0.0076224613), wt,
        0.00943887047), wt, 1.00167406), wt, 2.83297682);
    let x0 = select(tail, central, w < 5.0) * y;
    let q = 1.0 - abs(y);
    return brdf_erf_inv_newton(brdf_erf_inv_newton(x0, y, q), y, q);
}

// The Beckmann visible-slope inversion's residual at b in erf space (the Rust kernel's loop
// body): b bisected back into the bracket [lo, hi] if it left it, then
// (b, value, deriv, x) with value = norm (1 + b + tan_t exp(-x^2) / sqrt(pi)) - u the CDF's
// residual at x = erf^-1(b) and deriv = norm (1 - x tan_t) its derivative in b.
fn brdf_beckmann_vndf_residual(
    b_in: f32, lo: f32, hi: f32, u: f32, norm: f32, tan_t: f32,
) -> vec4<f32> {
    let inside = (b_in >= lo) & (b_in <= hi);
    let b = select(0.5 * (lo + hi), b_in, inside);
    let x = sampling_erf_inv(b);
    // 1 / sqrt(pi).
    let value = norm * (1.0 + b + 0.5641895835477563 * tan_t * exp(-x * x)) - u;
    let deriv = norm * (1.0 - x * tan_t);
    return vec4<f32>(b, value, deriv, x);
}

// The bracket after one step: b replaces hi where the residual is positive, lo elsewhere.
// `finite` is false at the horizon (cos_t = 0), where the Rust kernel's tan_t is +inf, its
// norm 0 and its residual 0 inf = NaN, so that no comparison holds: lo moves every step and
// every step bisects (towards erf(cot_t) = 0); the twin takes those branches explicitly.
fn brdf_beckmann_vndf_bracket(
    b_in: f32, lo: f32, hi: f32, u: f32, norm: f32, tan_t: f32, finite: bool,
) -> vec2<f32> {
    let r = brdf_beckmann_vndf_residual(b_in, lo, hi, u, norm, tan_t);
    let above = (r.y > 0.0) & finite;
    return vec2<f32>(select(r.x, lo, above), select(hi, r.x, above));
}

// One safeguarded Newton-bisection step of the inversion from b_in (the Rust kernel's loop
// body, its new b): the Newton step b - gain value / deriv, gain = 2 st / (st + su) on
// sqrt(1 - CDF) in the upper half (u > 1/2 and 1 - CDF = tail > 0: st = sqrt(tail),
// su = sqrt(1 - u)), or the midpoint of the updated bracket where deriv <= 0 or b = 1. The
// Rust kernel bisects where the step is not finite, which happens at b = 1 only (erf^-1 = +inf
// there); WGSL has no infinity, so b < 1 stands for it. brdf-gpu's bound treats a `_newton`
// function by its Newton-step rule (lo, hi and the rest as parameters).
fn brdf_beckmann_vndf_newton(
    b_in: f32, lo: f32, hi: f32, u: f32, norm: f32, tan_t: f32, tail_u: f32, upper: bool,
    finite: bool,
) -> f32 {
    let r = brdf_beckmann_vndf_residual(b_in, lo, hi, u, norm, tan_t);
    let br = brdf_beckmann_vndf_bracket(b_in, lo, hi, u, norm, tan_t, finite);
    let b = r.x;
    let value = r.y;
    let deriv = r.z;
    let tail = tail_u - value;
    let st = sqrt(max(tail, 0.0));
    let su = sqrt(tail_u);
    let upper_tail = upper & (tail > 0.0);
    let gain = select(1.0, 2.0 * st / (st + su), upper_tail);
    let next = b - gain * value / deriv;
    let newton = (deriv > 0.0) & (b < 1.0) & finite;
    return select(0.5 * (br.x + br.y), next, newton);
}

// One step of the inversion on the state (b, lo, hi).
fn brdf_beckmann_vndf_step(
    s: vec3<f32>, u: f32, norm: f32, tan_t: f32, tail_u: f32, upper: bool, finite: bool,
) -> vec3<f32> {
    let b = brdf_beckmann_vndf_newton(s.x, s.y, s.z, u, norm, tan_t, tail_u, upper, finite);
    let br = brdf_beckmann_vndf_bracket(s.x, s.y, s.z, u, norm, tan_t, finite);
    return vec3<f32>(b, br.x, br.y);
}

// The normal of sampling_beckmann_vndf without its pdf (for the samplers that weigh their
// sample by another density).
fn brdf_beckmann_vndf_normal(
    alpha_x: f32, alpha_y: f32, wo: vec3<f32>, u1: f32, u2: f32,
) -> vec3<f32> {
    let uc1 = brdf_clamp_u(u1);
    let uc2 = brdf_clamp_u(u2);
    let ax = brdf_clamp_alpha(alpha_x);
    let ay = brdf_clamp_alpha(alpha_y);
    let v = brdf_stretch(wo, ax, ay);
    let cos_t = v.z;
    let sin_t = sqrt(fma(v.x, v.x, v.y * v.y));
    // The Rust kernel's tan_t = 0, cot_t = +inf at normal incidence and tan_t = +inf at the
    // horizon: WGSL has no infinity, so cot_t is capped at 64 (erf(64) = 1 and
    // exp(-64^2) = 0 in f32, as at +inf; every slope erf^-1 returns is below 64) and tan_t's
    // divisor floored at f32's smallest normal.
    let has_azimuth = sin_t > 0.0;
    let tan_t = sin_t / max(cos_t, 1.17549435e-38);
    let cot_t = select(64.0, min(cos_t / sin_t, 64.0), has_azimuth);
    let hi = brdf_erf(cot_t);
    let sample_x = max(uc1, 1e-6);
    let theta = acos(cos_t);
    let fit = 1.0 + theta * (-0.876 + theta * (0.4265 - 0.0594 * theta));
    let b0 = hi - (1.0 + hi) * pow(1.0 - sample_x, fit);
    // 1 / sqrt(pi).
    let norm = 1.0 / (1.0 + hi + 0.5641895835477563 * tan_t * exp(-cot_t * cot_t));
    let tail_u = 1.0 - sample_x;
    let upper = sample_x > 0.5;
    let s0 = vec3<f32>(b0, -1.0, hi);
    let s1 = brdf_beckmann_vndf_step(s0, sample_x, norm, tan_t, tail_u, upper, cos_t > 0.0);
    let s2 = brdf_beckmann_vndf_step(s1, sample_x, norm, tan_t, tail_u, upper, cos_t > 0.0);
    let s3 = brdf_beckmann_vndf_step(s2, sample_x, norm, tan_t, tail_u, upper, cos_t > 0.0);
    let s4 = brdf_beckmann_vndf_step(s3, sample_x, norm, tan_t, tail_u, upper, cos_t > 0.0);
    let s5 = brdf_beckmann_vndf_step(s4, sample_x, norm, tan_t, tail_u, upper, cos_t > 0.0);
    let s6 = brdf_beckmann_vndf_step(s5, sample_x, norm, tan_t, tail_u, upper, cos_t > 0.0);
    let s7 = brdf_beckmann_vndf_step(s6, sample_x, norm, tan_t, tail_u, upper, cos_t > 0.0);
    let b = clamp(s7.x, s7.y, s7.z);
    // erf^-1(1) = +inf in the Rust kernel, so its min with cot_t is cot_t there.
    let sx = select(min(sampling_erf_inv(b), cot_t), cot_t, b >= 1.0);
    let sy = sampling_erf_inv(2.0 * max(uc2, 1e-6) - 1.0);
    let cos_p = select(1.0, v.x / sin_t, has_azimuth);
    let sin_p = select(0.0, v.y / sin_t, has_azimuth);
    let rx = cos_p * sx - sin_p * sy;
    let ry = sin_p * sx + cos_p * sy;
    return brdf_normalize_or_z(vec3<f32>(-ax * rx, -ay * ry, 1.0));
}

// Beckmann visible-normal sampling (Heitz and d'Eon 2014, "Importance Sampling
// Microfacet-Based BSDFs using the Distribution of Visible Normals", with Jakob's improvements
// in Mitsuba, as the Rust kernel): in the stretched configuration seen from theta, the slope x
// along the view's azimuth inverts its marginal CDF at u1 (a fitted start, 7 safeguarded
// Newton-bisection steps in erf space, brdf_beckmann_vndf_step), the slope across it is
// erf^-1(2 u2 - 1); both rotated to wo's azimuth, unstretched; with its pdf D_wo(m). u1 and u2
// below 1e-6 are raised to it.
fn sampling_beckmann_vndf(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> vec4<f32> {
    let m = brdf_beckmann_vndf_normal(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z), u1, u2);
    let pdf = beckmann_Beckmann_d_visible(alpha_x, alpha_y, wo_x, wo_y, abs(wo_z), m.x, m.y,
        m.z);
    return vec4<f32>(m, pdf);
}

// The Beckmann reflection sample without its Fresnel factor: (wi, pdf, G2 / G1(wo), wo.m) for
// the visible normal m of sampling_beckmann_vndf, wi = 2 (wo.m) m - wo, pdf =
// sampling_beckmann_reflection_pdf(wo, wi). G2 / G1(wo) = (1 + Lambda(wo)) / (1 + Lambda(wo) +
// Lambda(wi)) is written pole-free with the finite |z| Lambda (brdf_beckmann_cos_lambda) as
// |i.z| (|o.z| + |o.z| Lo) / (|o.z| |i.z| + |i.z| |o.z| Lo + |o.z| |i.z| Li), as in
// beckmann_Beckmann_g2_correlated. 0 unless wo and wi lie above the horizon.
fn brdf_sampling_beckmann_reflection_parts(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
) -> array<f32, 6> {
    let m = brdf_beckmann_vndf_normal(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z), u1, u2);
    let o_m = fma(wo_x, m.x, fma(wo_y, m.y, wo_z * m.z));
    let k = 2.0 * o_m;
    let wi = vec3<f32>(m.x * k - wo_x, m.y * k - wo_y, m.z * k - wo_z);
    let pdf = sampling_beckmann_reflection_pdf(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi.x, wi.y,
        wi.z);
    let o = brdf_beckmann_smith(alpha_x, alpha_y, vec3<f32>(wo_x, wo_y, wo_z));
    let i = brdf_beckmann_smith(alpha_x, alpha_y, wi);
    let lo = brdf_beckmann_cos_lambda(o);
    let den = o.x * i.x + i.x * lo + o.x * brdf_beckmann_cos_lambda(i);
    let above = (wo_z > 0.0) & (wi.z > 0.0);
    // The floor keeps the unused branch finite where both cosines are 0.
    let ratio = select(0.0, i.x * (o.x + lo) / max(den, 1.17549435e-38), above);
    return array<f32, 6>(wi.x, wi.y, wi.z, pdf, ratio, saturate(o_m));
}

// Samples the Cook-Torrance reflection lobe of a Beckmann surface with a constant Fresnel
// factor F (>= 0): (wi.x, wi.y, wi.z, pdf, weight) with the visible normal m of
// sampling_beckmann_vndf (Heitz and d'Eon 2014), wi = 2 (wo.m) m - wo, pdf =
// sampling_beckmann_reflection_pdf(wo, wi) and the weight F G2 / G1(wo) capped at the largest
// finite f32. Edges as sampling_ggx_reflection.
fn sampling_beckmann_reflection(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
    fresnel: f32,
) -> array<f32, 5> {
    let p = brdf_sampling_beckmann_reflection_parts(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    return array<f32, 5>(p[0], p[1], p[2], p[3], min(p[4] * fresnel, BRDF_F32_MAX));
}

// sampling_beckmann_reflection with a constant RGB Fresnel factor: (wi.x, wi.y, wi.z, pdf,
// weight_r, weight_g, weight_b), the weight F_c G2 / G1(wo) per channel.
fn sampling_beckmann_reflection_rgb(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, u1: f32, u2: f32,
    fresnel_r: f32, fresnel_g: f32, fresnel_b: f32,
) -> array<f32, 7> {
    let p = brdf_sampling_beckmann_reflection_parts(alpha_x, alpha_y, wo_x, wo_y, wo_z, u1, u2);
    return array<f32, 7>(p[0], p[1], p[2], p[3], min(p[4] * fresnel_r, BRDF_F32_MAX),
        min(p[4] * fresnel_g, BRDF_F32_MAX), min(p[4] * fresnel_b, BRDF_F32_MAX));
}
