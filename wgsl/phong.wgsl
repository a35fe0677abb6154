// brdf: the Phong family, the twins of the Rust module `phong` (classic, modified and
// normalized Phong, Blinn-Phong with exact and approximate normalization, the Blinn-Phong
// NDF). Needs common.wgsl. Exponents are finite and >= 0; `pow` is WGSL's, whose accuracy the
// specification inherits from exp2(y log2(x)), so large exponents carry large bounds.

// 1 / (2 pi) and 1 / (8 pi), rounded to f32.
const BRDF_FRAC_1_2PI: f32 = 0.159154943091895335769;
const BRDF_FRAC_1_8PI: f32 = 0.0397887357729738339422;

// c^n for c in (0, 1] (c above 1 counts as 1), 0 for c <= 0.
fn brdf_phong_lobe(c: f32, exponent: f32) -> f32 {
    return select(0.0, pow(min(c, 1.0), exponent), c > 0.0);
}

// The normalization (n + 2) / (2 pi) of the normalized Phong lobe (Lewis 1994, "Making
// Shaders More Physically Plausible").
fn phong_phong_normalization(exponent: f32) -> f32 {
    return (exponent + 2.0) * BRDF_FRAC_1_2PI;
}

// The exact Blinn-Phong normalization (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) (Akenine-Moller,
// Haines, Hoffman 2008, "Real-Time Rendering", 3rd ed., eq. 7.48), with the Rust kernel's
// scaling by 2^-64 above n = 2^64, where (n + 4) / (n + 2^(-n/2)) rounds to 1.
fn phong_blinn_phong_normalization_exact(exponent: f32) -> f32 {
    let big = exponent > 1.8446744073709552e19;
    let m = select(exponent, 0.0, big);
    let p = pow(0.5, 0.5 * m);
    let small = (m + 2.0) * BRDF_FRAC_1_8PI * ((m + 4.0) / (m + p));
    let large = (exponent * 5.421010862427522e-20) * BRDF_FRAC_1_8PI;
    return select(small, large, big) * select(1.0, 1.8446744073709552e19, big);
}

// The common approximation (n + 8) / (8 pi) of the Blinn-Phong normalization (Akenine-Moller,
// Haines, Hoffman 2008).
fn phong_blinn_phong_normalization_approx(exponent: f32) -> f32 {
    return (exponent + 8.0) * BRDF_FRAC_1_8PI;
}

// 0 unless both cosines are above the horizon.
fn brdf_phong_above_horizon(n_dot_v: f32, n_dot_l: f32, value: f32) -> f32 {
    return select(0.0, value, (n_dot_v > 0.0) & (n_dot_l > 0.0));
}

// Phong's classic lobe as a BRDF, ks (r.l)^n / n.l (Phong 1975, "Illumination for Computer
// Generated Pictures"); n.l floored at the smallest normal f32 in the division.
fn phong_classic(n_dot_v: f32, n_dot_l: f32, r_dot_l: f32, ks: f32, exponent: f32) -> f32 {
    let f = ks / max(n_dot_l, 1.17549435e-38) * brdf_phong_lobe(r_dot_l, exponent);
    return brdf_phong_above_horizon(n_dot_v, n_dot_l, f);
}

// The modified (reciprocal) Phong lobe ks (r.l)^n (Lewis 1994).
fn phong_modified(n_dot_v: f32, n_dot_l: f32, r_dot_l: f32, ks: f32, exponent: f32) -> f32 {
    return brdf_phong_above_horizon(n_dot_v, n_dot_l, ks * brdf_phong_lobe(r_dot_l, exponent));
}

// The normalized Phong lobe ks (n + 2) / (2 pi) (r.l)^n (Lewis 1994).
fn phong_normalized(n_dot_v: f32, n_dot_l: f32, r_dot_l: f32, ks: f32, exponent: f32) -> f32 {
    let f = (exponent + 2.0) * BRDF_FRAC_1_2PI * ks * brdf_phong_lobe(r_dot_l, exponent);
    return brdf_phong_above_horizon(n_dot_v, n_dot_l, f);
}

// Lambert plus normalized Phong, kd / pi + ks (n + 2) / (2 pi) (r.l)^n (Lewis 1994).
fn phong_diffuse_specular(
    n_dot_v: f32, n_dot_l: f32, r_dot_l: f32, kd: f32, ks: f32, exponent: f32,
) -> f32 {
    let spec = ks * phong_phong_normalization(exponent) * brdf_phong_lobe(r_dot_l, exponent);
    return brdf_phong_above_horizon(n_dot_v, n_dot_l, fma(kd, BRDF_FRAC_1_PI, spec));
}

// Blinn's lobe ks (n.h)^n (Blinn 1977, "Models of Light Reflection for Computer Synthesized
// Pictures").
fn phong_blinn_phong(n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, ks: f32, exponent: f32) -> f32 {
    return brdf_phong_above_horizon(n_dot_v, n_dot_l, ks * brdf_phong_lobe(n_dot_h, exponent));
}

// Blinn-Phong with the approximate normalization, ks (n + 8) / (8 pi) (n.h)^n.
fn phong_blinn_phong_normalized_approx(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, ks: f32, exponent: f32,
) -> f32 {
    let f = ks * phong_blinn_phong_normalization_approx(exponent)
        * brdf_phong_lobe(n_dot_h, exponent);
    return brdf_phong_above_horizon(n_dot_v, n_dot_l, f);
}

// The Blinn-Phong NDF (n + 2) / (2 pi) (n.h)^n (Blinn 1977; Walter et al. 2007, eq. 30).
fn phong_blinn_phong_ndf(n_dot_h: f32, exponent: f32) -> f32 {
    return phong_phong_normalization(exponent) * brdf_phong_lobe(n_dot_h, exponent);
}

// Blinn-Phong with the exact normalization, ks c(n) (n.h)^n, c(n) as in
// phong_blinn_phong_normalization_exact (albedo 1 at normal incidence).
fn phong_blinn_phong_normalized(
    n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, ks: f32, exponent: f32,
) -> f32 {
    let f = ks * phong_blinn_phong_normalization_exact(exponent)
        * brdf_phong_lobe(n_dot_h, exponent);
    return brdf_phong_above_horizon(n_dot_v, n_dot_l, f);
}

// The parameter types (`phong::ClassicPhong`, ...) on local-frame directions: r.l is wo's
// mirror about the normal dotted with wi, n.h the half vector's cosine (0 where wo = -wi).

// r.l = wo.z wi.z - (wo.x wi.x + wo.y wi.y).
fn brdf_phong_r_dot_l(wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32) -> f32 {
    return fma(wo_z, wi_z, -fma(wo_x, wi_x, wo_y * wi_y));
}

// n.h = (wo + wi).z / |wo + wi|, 0 where wo + wi = 0.
fn brdf_phong_n_dot_h(wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32) -> f32 {
    let hx = wo_x + wi_x;
    let hy = wo_y + wi_y;
    let hz = wo_z + wi_z;
    let len2 = fma(hx, hx, fma(hy, hy, hz * hz));
    return select(hz / sqrt(len2), 0.0, len2 == 0.0);
}

// `phong::ClassicPhong` on local-frame directions.
fn phong_ClassicPhong_eval(
    ks: f32, exponent: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let r_dot_l = brdf_phong_r_dot_l(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return phong_classic(wo_z, wi_z, r_dot_l, ks, exponent);
}

// `phong::ModifiedPhong` on local-frame directions.
fn phong_ModifiedPhong_eval(
    ks: f32, exponent: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let r_dot_l = brdf_phong_r_dot_l(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return phong_modified(wo_z, wi_z, r_dot_l, ks, exponent);
}

// `phong::NormalizedPhong` on local-frame directions.
fn phong_NormalizedPhong_eval(
    ks: f32, exponent: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let r_dot_l = brdf_phong_r_dot_l(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return phong_normalized(wo_z, wi_z, r_dot_l, ks, exponent);
}

// `phong::BlinnPhong` on local-frame directions.
fn phong_BlinnPhong_eval(
    ks: f32, exponent: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let n_dot_h = brdf_phong_n_dot_h(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return phong_blinn_phong(wo_z, wi_z, n_dot_h, ks, exponent);
}

// `phong::NormalizedBlinnPhong` on local-frame directions.
fn phong_NormalizedBlinnPhong_eval(
    ks: f32, exponent: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let n_dot_h = brdf_phong_n_dot_h(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return phong_blinn_phong_normalized(wo_z, wi_z, n_dot_h, ks, exponent);
}

// `phong::ApproxNormalizedBlinnPhong` on local-frame directions.
fn phong_ApproxNormalizedBlinnPhong_eval(
    ks: f32, exponent: f32, wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let n_dot_h = brdf_phong_n_dot_h(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return phong_blinn_phong_normalized_approx(wo_z, wi_z, n_dot_h, ks, exponent);
}

// `phong::PhongDiffuseSpecular` on local-frame directions.
fn phong_PhongDiffuseSpecular_eval(
    kd: f32, ks: f32, exponent: f32,
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32,
) -> f32 {
    let r_dot_l = brdf_phong_r_dot_l(wo_x, wo_y, wo_z, wi_x, wi_y, wi_z);
    return phong_diffuse_specular(wo_z, wi_z, r_dot_l, kd, ks, exponent);
}
