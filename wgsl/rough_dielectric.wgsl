// brdf: the rough dielectric BSDF of Walter et al. 2007, the twins of the Rust module
// `rough_dielectric`: the generalized half vector, the BSDF (reflection and transmission, from
// either side, radiance or importance transport) and the pdf of both lobes, over a microfacet
// model given as a u32 (0 = GGX, 1 = Beckmann) with widths (alpha_x, alpha_y), and the GGX
// and Beckmann samplers. Needs
// common.wgsl, ggx.wgsl, fresnel.wgsl, beckmann.wgsl and sampling.wgsl.

// (h, |r|^2) for the raw sum r = wi + wo / eta' (eta' > 1) or wi eta' + wo (eta' <= 1), a
// positive multiple of wo + eta' wi: h = +-normalize(r) with h.z >= 0, (0, 0, 1) where r is the
// zero vector (then |r|^2 = 0, the degenerate pair of the Rust kernel).
fn brdf_rough_dielectric_half(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32,
) -> vec4<f32> {
    let etap = select(select(eta, 1.0 / eta, wo_z < 0.0), 1.0, wo_z * wi_z > 0.0);
    let big = etap > 1.0;
    let inv = 1.0 / etap;
    let x = select(wi_x * etap + wo_x, wi_x + wo_x * inv, big);
    let y = select(wi_y * etap + wo_y, wi_y + wo_y * inv, big);
    let z = select(wi_z * etap + wo_z, wi_z + wo_z * inv, big);
    let len2 = x * x + y * y + z * z;
    // A zero sum (wi = -wo at eta' = 1) has no direction: the normal, as in the Rust kernel.
    // The floor keeps the unused branch of the select finite there.
    let s = select(0.0, 1.0 / sqrt(max(len2, 1e-30)), len2 > 0.0);
    let flip = select(s, -s, z < 0.0);
    let live = len2 > 0.0;
    return vec4<f32>(select(0.0, x * flip, live), select(0.0, y * flip, live),
        select(1.0, z * flip, live), len2);
}

// The generalized half vector h = +-normalize(wo + eta' wi) with h.z >= 0 (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces", eq. 16): eta' = 1 where wo and wi
// lie on the same side, else eta for wo outside and 1 / eta for wo inside. Written, as the Rust
// kernel writes it, as wi + wo / eta' where eta' > 1 (a positive multiple), so that neither
// term overflows for any eta in (0, MAX]. Where the sum is the zero vector, h is (0, 0, 1).
fn rough_dielectric_half_vector(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32,
) -> vec3<f32> {
    let h = brdf_rough_dielectric_half(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z, eta);
    return vec3<f32>(h.x, h.y, h.z);
}

// a b for finite a, b >= 0, capped at the largest finite f32 (the Rust kernel's cap_mul): a
// later factor 0 then gives 0.
fn brdf_rough_dielectric_cap_mul(a: f32, b: f32) -> f32 {
    return min(a * b, BRDF_F32_MAX);
}

// 1 / p for p >= 0, capped at the largest finite f32. Below f32's smallest normal the cap is
// taken (1 / p there is within a factor 4 of it or beyond, and WGSL's x / y promises no
// accuracy for such a divisor); the floor keeps the unused branch within that promise.
fn brdf_rough_dielectric_recip(p: f32) -> f32 {
    return select(BRDF_F32_MAX, min(1.0 / max(p, 1.17549435e-38), BRDF_F32_MAX),
        p >= 1.17549435e-38);
}

// (d(omega_h) / d(omega_i), s): the refraction Jacobian |i.h| / (i.h + o.h / eta')^2 (Walter et
// al. 2007, eq. 17) capped at the largest finite f32, formed as |i.h| eta'^2 / (eta' i.h + o.h)^2
// where eta' < 1 so that o.h / eta' cannot overflow, 0 where the sum is 0; and the transport
// factor s = (1 / eta')^2 capped (transport 0, radiance) or 1 (transport 1, importance).
fn brdf_rough_dielectric_jacobian(o_h: f32, i_h: f32, etap: f32, transport: u32) -> vec2<f32> {
    let small = etap < 1.0;
    let sum = select(i_h + o_h / etap, fma(etap, i_h, o_h), small);
    let num = select(abs(i_h), min(abs(i_h) * (etap * etap), BRDF_F32_MAX), small);
    let ss = sum * sum;
    let q = select(BRDF_F32_MAX, min(num / max(ss, 1.17549435e-38), BRDF_F32_MAX),
        ss >= 1.17549435e-38);
    let dwh = select(q, 0.0, sum == 0.0);
    // (1 / eta')^2 capped: 1 / eta' below 2^64 squares to at most (2^64 - 2^40)^2, which rounds
    // to a finite f32; from 2^64 on the square is beyond the largest f32, so the cap.
    let r = min(1.0 / etap, BRDF_F32_MAX);
    let rc = min(r, 18446742974197923840.0);
    let radiance = select(rc * rc, BRDF_F32_MAX, r >= 18446744073709551616.0);
    return vec2<f32>(dwh, select(1.0, radiance, transport == 0u));
}

// D(h) of the model (0 = GGX, 1 = Beckmann).
fn brdf_rough_dielectric_d(model: u32, alpha_x: f32, alpha_y: f32, h: vec4<f32>) -> f32 {
    return select(ggx_Ggx_d(alpha_x, alpha_y, h.x, h.y, h.z),
        beckmann_Beckmann_d(alpha_x, alpha_y, h.x, h.y, h.z), model == 1u);
}

// The height-correlated G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) of the model (Heitz 2014,
// "Understanding the Masking-Shadowing Function", eq. 99), in the twins' pole-free forms
// (ggx_Ggx_g2_correlated, beckmann_Beckmann_g2_correlated): the Rust kernel's 1 / (1 + Lambda +
// Lambda) with Lambda capped at f32's largest value would leave f32's range in the sum.
fn brdf_rough_dielectric_g2(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    return select(
        ggx_Ggx_g2_correlated(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi_x, wi_y, wi_z),
        beckmann_Beckmann_g2_correlated(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi_x, wi_y, wi_z),
        model == 1u);
}

// (f, pdf) of both lobes at a pair, sharing one half vector (the Rust kernel's `lobes`): with
// F = fresnel_dielectric(wo.h, eta),
// f = D G2 F / (4 |wo.z| |wi.z|) on one side, s D G2 (1 - F) |wo.h| dwh / (|wo.z| |wi.z|)
// across; pdf = D_v(h) F / (4 |wo.h|) and D_v(h) dwh (1 - F), D_v the visible-normal density
// seen from sign(wo.z) wo; both 0 unless each direction sees the facet's own side, h is not
// degenerate and eta != 1.
fn brdf_rough_dielectric_lobes(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32, transport: u32,
) -> vec2<f32> {
    let h = brdf_rough_dielectric_half(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z, eta);
    let reflect = wo_z * wi_z > 0.0;
    let etap = select(select(eta, 1.0 / eta, wo_z < 0.0), 1.0, reflect);
    let o_h = wo_x * h.x + wo_y * h.y + wo_z * h.z;
    let i_h = wi_x * h.x + wi_y * h.y + wi_z * h.z;
    // Each direction must see the facet's own side; this also drops the horizon.
    let facing = (o_h * wo_z > 0.0) & (i_h * wi_z > 0.0);
    let live = facing & (h.w > 0.0) & (eta != 1.0);
    let f_r = fresnel_dielectric(o_h, eta);
    let t = 1.0 - f_r;
    let dg = brdf_rough_dielectric_d(model, alpha_x, alpha_y, h)
        * brdf_rough_dielectric_g2(model, alpha_x, alpha_y, wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    let inv_cos = brdf_rough_dielectric_recip(abs(wo_z) * abs(wi_z));
    let fr = brdf_rough_dielectric_cap_mul(brdf_rough_dielectric_cap_mul(dg, f_r),
        0.25 * inv_cos);
    let j = brdf_rough_dielectric_jacobian(o_h, i_h, etap, transport);
    let ft = brdf_rough_dielectric_cap_mul(
        brdf_rough_dielectric_cap_mul(brdf_rough_dielectric_cap_mul(dg, t),
            brdf_rough_dielectric_cap_mul(abs(o_h), inv_cos)),
        j.x);
    let f = select(0.0, select(brdf_rough_dielectric_cap_mul(ft, j.y), fr, reflect), live);
    let up = select(1.0, -1.0, wo_z < 0.0);
    let pm = select(
        ggx_Ggx_d_visible(alpha_x, alpha_y, up * wo_x, up * wo_y, up * wo_z, h.x, h.y, h.z),
        beckmann_Beckmann_d_visible(alpha_x, alpha_y, up * wo_x, up * wo_y, up * wo_z,
            h.x, h.y, h.z),
        model == 1u);
    let pr = brdf_rough_dielectric_cap_mul(
        brdf_rough_dielectric_cap_mul(pm, brdf_rough_dielectric_recip(4.0 * abs(o_h))), f_r);
    let pt = brdf_rough_dielectric_cap_mul(brdf_rough_dielectric_cap_mul(pm, j.x), t);
    let p = select(0.0, select(pt, pr, reflect), live);
    return vec2<f32>(f, p);
}

// The rough dielectric BSDF f(wo, wi) (Walter et al. 2007, eqs. 20 and 21), reflection and
// transmission together: f = D(h) G2 F / (4 |wo.z| |wi.z|) for wo, wi on the same side, and
// f = s D(h) G2 (1 - F) |wi.h| |wo.h| / (|wi.z| |wo.z| (wi.h + wo.h / eta')^2) across, with
// h = rough_dielectric_half_vector, F = fresnel_dielectric(wo.h, eta) (1 under total internal
// reflection), s = 1 / eta'^2 for transport 0 (radiance) and 1 for transport 1 (importance).
// 0 on the horizon, for a back-facing h and for eta = 1; capped at the largest finite f32.
// eta in (0, MAX]; the exact Fresnel factor's range, eta in [1/256, 256] (fresnel.wgsl).
fn rough_dielectric_eval(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32, transport: u32,
) -> f32 {
    return brdf_rough_dielectric_lobes(model, alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z, eta, transport).x;
}

// pdf (solid angle) of the rough dielectric samplers at wi, both lobes combined (Walter et al.
// 2007, eqs. 14 and 17): F D_v(h) / (4 |wo.h|) for wi on wo's side and
// (1 - F) D_v(h) |wi.h| / (wi.h + wo.h / eta')^2 across, D_v the visible-normal density of the
// facet seen from wo's side (ggx_Ggx_d_visible of sign(wo.z) wo); 0 where the BSDF is 0 by an
// edge; capped at the largest finite f32.
fn rough_dielectric_pdf(
    model: u32, alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32,
) -> f32 {
    return brdf_rough_dielectric_lobes(model, alpha_x, alpha_y, wo_x, wo_y, wo_z,
        wi_x, wi_y, wi_z, eta, 1u).y;
}

// Walter et al. 2007's BTDF without its Fresnel factor for GGX in radiance transport, and wo.h
// (the Rust kernel's btdf_without_fresnel, for transmission_dielectric_bsdf):
// (D(h) G2 |wi.h| |wo.h| / (|wi.z| |wo.z| (wi.h + wo.h / eta')^2) s, wo.h), 0 where the pair is
// no refraction pair (same side, back-facing h, degenerate h, eta = 1).
fn brdf_rough_dielectric_btdf_ggx(
    alpha_x: f32, alpha_y: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32,
) -> vec2<f32> {
    let h = brdf_rough_dielectric_half(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z, eta);
    let reflect = wo_z * wi_z > 0.0;
    let etap = select(select(eta, 1.0 / eta, wo_z < 0.0), 1.0, reflect);
    let o_h = wo_x * h.x + wo_y * h.y + wo_z * h.z;
    let i_h = wi_x * h.x + wi_y * h.y + wi_z * h.z;
    let facing = (o_h * wo_z > 0.0) & (i_h * wi_z > 0.0);
    let live = facing & (h.w > 0.0) & !reflect & (eta != 1.0);
    let j = brdf_rough_dielectric_jacobian(o_h, i_h, etap, 0u);
    let dg = ggx_Ggx_d(alpha_x, alpha_y, h.x, h.y, h.z)
        * ggx_Ggx_g2_correlated(alpha_x, alpha_y, wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    let inv_cos = brdf_rough_dielectric_recip(abs(wo_z) * abs(wi_z));
    let ft = brdf_rough_dielectric_cap_mul(
        brdf_rough_dielectric_cap_mul(dg, brdf_rough_dielectric_cap_mul(abs(o_h), inv_cos)),
        j.x);
    return vec2<f32>(select(0.0, brdf_rough_dielectric_cap_mul(ft, j.y), live), o_h);
}

// v / |v| with |v|^2 in the order of the Rust V3::dot, or `fallback` where |v|^2 is 0
// (vec3::V3::normalize_or).
fn brdf_rough_dielectric_normalize_or(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2 = fma(v.x, v.x, fma(v.y, v.y, v.z * v.z));
    let ok = len2 > 0.0;
    let inv = select(0.0, 1.0 / sqrt(len2), ok);
    return vec3<f32>(select(fallback.x, v.x * inv, ok), select(fallback.y, v.y * inv, ok),
        select(fallback.z, v.z * inv, ok));
}

// The refraction of wo through the facet normal m (Walter et al. 2007, eq. 40; the Rust
// kernel's refract): with c = wo.m, the relative index eta_t = eta (c >= 0) or 1 / eta (c < 0)
// and n = +-m on wo's side, sin^2_t = (1 - c^2) / eta_t^2 (1 under total internal reflection),
// wi = normalize(n (|c| - eta_t cos_t) - wo), or -n where that is the zero vector.
fn brdf_rough_dielectric_refract(wo: vec3<f32>, m: vec3<f32>, eta: f32) -> vec3<f32> {
    let c0 = fma(wo.x, m.x, fma(wo.y, m.y, wo.z * m.z));
    let back = c0 < 0.0;
    let eta_t = select(eta, 1.0 / eta, back);
    let n = select(m, vec3<f32>(-m.x, -m.y, -m.z), back);
    let c = min(abs(c0), 1.0);
    let sin2_i = max((1.0 - c) * (1.0 + c), 0.0);
    let e2 = eta_t * eta_t;
    // A product, so that an eta_t^2 that underflows gives total reflection, not 0 / 0.
    let tir = (sin2_i >= e2) & (sin2_i > 0.0);
    let sin2_t = min(select(sin2_i / max(e2, 1.17549435e-38), 1.0, tir), 1.0);
    let cos_t = sqrt(max(1.0 - sin2_t, 0.0));
    let k = c - min(eta_t, BRDF_F32_MAX) * cos_t;
    let wi = vec3<f32>(n.x * k - wo.x, n.y * k - wo.y, n.z * k - wo.z);
    return brdf_rough_dielectric_normalize_or(wi, vec3<f32>(-n.x, -n.y, -n.z));
}

// The outputs of rough_dielectric_ggx_sample and rough_dielectric_beckmann_sample from the
// chosen direction wi (a reflection where choose_r), its pdf p and G2 / G1 (ratio): a live
// sample (a reflection that stays on wo's side, a refraction that crosses) with p > 0 keeps p
// and its weight, ratio times the capped (1 / eta')^2 of a refraction in radiance transport;
// any other keeps wi with pdf 0 and weight 0; eta = 1 is the Dirac pass-through.
fn brdf_rough_dielectric_sample_out(
    wo: vec3<f32>, wi: vec3<f32>, choose_r: bool, p: f32, ratio: f32, eta: f32, transport: u32,
) -> array<f32, 5> {
    let same = wo.z * wi.z > 0.0;
    let cross = wo.z * wi.z < 0.0;
    let live = (choose_r & same) | (!choose_r & cross);
    // (1 / eta')^2 capped, as in brdf_rough_dielectric_jacobian.
    let r = min(1.0 / select(eta, 1.0 / eta, wo.z < 0.0), BRDF_F32_MAX);
    let rc = min(r, 18446742974197923840.0);
    let s = select(select(rc * rc, BRDF_F32_MAX, r >= 18446744073709551616.0), 1.0,
        transport == 1u);
    let w = select(brdf_rough_dielectric_cap_mul(ratio, s), ratio, choose_r);
    let keep = live & (p > 0.0);
    // eta = 1: the Dirac pass-through.
    let matched = (eta == 1.0) & !((wo.x == 0.0) & (wo.y == 0.0) & (wo.z == 0.0));
    return array<f32, 5>(select(wi.x, -wo.x, matched), select(wi.y, -wo.y, matched),
        select(wi.z, -wo.z, matched), select(select(0.0, p, keep), BRDF_F32_MAX, matched),
        select(select(0.0, w, keep), 1.0, matched));
}

// Samples the rough dielectric BSDF of a GGX interface: (wi.x, wi.y, wi.z, pdf, weight) with
// the visible normal m of sampling_ggx_vndf_spherical_cap for sign(wo.z) wo (Heitz 2018,
// "Sampling the GGX Distribution of Visible Normals"; Dupuy and Benyoub 2023), the reflection
// 2 (wo.m) m - wo where u0 < F = fresnel_dielectric(wo.m, eta) and the refraction through m
// otherwise (Walter et al. 2007, section 5.3), pdf = rough_dielectric_pdf(0u, ..., wo, wi, eta)
// and the weight G2 / G1(wo) = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)), times
// min(1 / eta', MAX)^2 capped for a refraction in radiance transport (transport 0; importance,
// 1, takes 1), eta' = eta for wo above the surface, 1 / eta below. G2 / G1 is written pole-free
// as |i.z| (|o.z| + s_o) / (|i.z| s_o + |o.z| s_i) (as in brdf_sampling_ggx_reflection_parts).
// A reflection leaving through the other side or a refraction staying on wo's side keeps its
// direction with pdf 0 and weight 0; eta = 1 gives wi = -wo, pdf the largest finite f32 and
// weight 1 (the Dirac pass-through). u0, u1, u2 clamped into [0, 1).
fn rough_dielectric_ggx_sample(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, eta: f32, u0: f32, u1: f32,
    u2: f32, transport: u32,
) -> array<f32, 5> {
    let wo = vec3<f32>(wo_x, wo_y, wo_z);
    let wo_up = select(wo, vec3<f32>(-wo_x, -wo_y, -wo_z), wo_z < 0.0);
    let m = brdf_ggx_vndf_spherical_cap_normal(alpha_x, alpha_y, wo_up, u1, u2);
    let uc0 = brdf_clamp_u(u0);
    let o_m = fma(wo_x, m.x, fma(wo_y, m.y, wo_z * m.z));
    let f_r = fresnel_dielectric(o_m, eta);
    let k = 2.0 * o_m;
    let wr = vec3<f32>(m.x * k - wo_x, m.y * k - wo_y, m.z * k - wo_z);
    let wt = brdf_rough_dielectric_refract(wo, m, eta);
    // Reflection with probability F (1 under total internal reflection).
    let choose_r = uc0 < f_r;
    let wi = select(wt, wr, choose_r);
    let p = rough_dielectric_pdf(0u, alpha_x, alpha_y, wo_x, wo_y, wo_z, wi.x, wi.y, wi.z, eta);
    let o = brdf_ggx_smith(alpha_x, alpha_y, wo);
    let i = brdf_ggx_smith(alpha_x, alpha_y, wi);
    // The floor keeps the unused branch finite where both cosines are 0.
    let ratio = i.x * (o.x + o.z) / max(i.x * o.z + o.x * i.z, 1.17549435e-38);
    return brdf_rough_dielectric_sample_out(wo, wi, choose_r, p, ratio, eta, transport);
}

// rough_dielectric_ggx_sample for a Beckmann interface: the visible normal m of
// sampling_beckmann_vndf for sign(wo.z) wo (Heitz and d'Eon 2014), the same Fresnel choice on
// u0, reflection or refraction, pdf = rough_dielectric_pdf(1u, ...) and weight G2 / G1(wo)
// (times the radiance factor of a refraction), G2 / G1 written pole-free with the finite
// |z| Lambda as |i.z| (|o.z| + |o.z| Lo) / (|o.z| |i.z| + |i.z| |o.z| Lo + |o.z| |i.z| Li)
// (as in brdf_sampling_beckmann_reflection_parts). Edges as rough_dielectric_ggx_sample.
fn rough_dielectric_beckmann_sample(
    alpha_x: f32, alpha_y: f32, wo_x: f32, wo_y: f32, wo_z: f32, eta: f32, u0: f32, u1: f32,
    u2: f32, transport: u32,
) -> array<f32, 5> {
    let wo = vec3<f32>(wo_x, wo_y, wo_z);
    let wo_up = select(wo, vec3<f32>(-wo_x, -wo_y, -wo_z), wo_z < 0.0);
    let m = brdf_beckmann_vndf_normal(alpha_x, alpha_y, wo_up, u1, u2);
    let uc0 = brdf_clamp_u(u0);
    let o_m = fma(wo_x, m.x, fma(wo_y, m.y, wo_z * m.z));
    let f_r = fresnel_dielectric(o_m, eta);
    let k = 2.0 * o_m;
    let wr = vec3<f32>(m.x * k - wo_x, m.y * k - wo_y, m.z * k - wo_z);
    let wt = brdf_rough_dielectric_refract(wo, m, eta);
    // Reflection with probability F (1 under total internal reflection).
    let choose_r = uc0 < f_r;
    let wi = select(wt, wr, choose_r);
    let p = rough_dielectric_pdf(1u, alpha_x, alpha_y, wo_x, wo_y, wo_z, wi.x, wi.y, wi.z, eta);
    let o = brdf_beckmann_smith(alpha_x, alpha_y, wo);
    let i = brdf_beckmann_smith(alpha_x, alpha_y, wi);
    let lo = brdf_beckmann_cos_lambda(o);
    let den = o.x * i.x + i.x * lo + o.x * brdf_beckmann_cos_lambda(i);
    // The floor keeps the unused branch finite where both cosines are 0.
    let ratio = i.x * (o.x + lo) / max(den, 1.17549435e-38);
    return brdf_rough_dielectric_sample_out(wo, wi, choose_r, p, ratio, eta, transport);
}
