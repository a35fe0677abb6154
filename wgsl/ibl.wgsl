// brdf: image-based lighting terms a shader evaluates per pixel, the twins of the Rust module
// `ibl::dfg` (the analytic split-sum fits [A, B], the split-sum specular and the roughness-mip
// mappings), and of `ibl::irradiance`'s evaluation of nine spherical-harmonic coefficients
// (radiance and irradiance), and of `ibl::energy`'s per-pixel multiple-scattering terms (the
// tables they read are textures in a shader). Needs common.wgsl. The DFG table, prefilter
// samples, the SH projection and the table lookups have no twin.

// 0 at and below the horizon (n.v <= 0), the fit's value above (ibl::dfg::fit_guard).
fn brdf_ibl_fit_guard(n_dot_v: f32, v: f32) -> f32 {
    return select(0.0, v, n_dot_v > 0.0);
}

// Karis's mobile fit of [A, B] (Karis 2014, "Physically Based Shading on Mobile"; Unreal
// Engine 4's EnvBRDFApprox) from the perceptual roughness r:
// (rx, ry, rz, rw) = r (-1, -0.0275, -0.572, 0.022) + (1, 0.0425, 1.04, -0.04),
// a004 = min(rx^2, 2^(-9.28 n.v)) rx + ry, A = -1.04 a004 + rz, B = 1.04 a004 + rw.
fn ibl_dfg_karis_mobile(n_dot_v: f32, roughness: f32) -> vec2<f32> {
    let nv = min(n_dot_v, 1.0);
    let rx = 1.0 - roughness;
    let ry = fma(roughness, -0.0275, 0.0425);
    let rz = fma(roughness, -0.572, 1.04);
    let rw = fma(roughness, 0.022, -0.04);
    let a004 = fma(min(rx * rx, exp2(-9.28 * nv)), rx, ry);
    return vec2<f32>(
        brdf_ibl_fit_guard(n_dot_v, fma(a004, -1.04, rz)),
        brdf_ibl_fit_guard(n_dot_v, fma(a004, 1.04, rw)),
    );
}

// Karis's mobile fit for non-metals: the a004 term alone (Karis 2014, EnvBRDFApproxNonmetal).
fn ibl_dfg_karis_mobile_nonmetal(n_dot_v: f32, roughness: f32) -> f32 {
    let nv = min(n_dot_v, 1.0);
    let rx = 1.0 - roughness;
    let ry = fma(roughness, -0.0275, 0.0425);
    return brdf_ibl_fit_guard(n_dot_v, fma(min(rx * rx, exp2(-9.28 * nv)), rx, ry));
}

// Lazarov's environment BRDF fit for normalized Blinn-Phong (Lazarov 2013, "Getting More
// Physical in Call of Duty: Black Ops II"), g = 1 - r.
fn ibl_dfg_lazarov(n_dot_v: f32, roughness: f32) -> vec2<f32> {
    let nv = min(n_dot_v, 1.0);
    let g = 1.0 - roughness;
    // 1 / 0.96, (0.0275 - 0.25 0.04) / 0.96 and (0.015 - 0.75 0.04) / 0.96.
    let tx = g * 1.0416666666666667;
    let ty = g * 0.475;
    let tz = fma(g, 0.018229166666666668, -0.015625);
    let tw = fma(g, 0.25, 0.75);
    let a0 = fma(tx, min(ty, exp2(-9.28 * nv)), tz);
    return vec2<f32>(brdf_ibl_fit_guard(n_dot_v, tw - a0), brdf_ibl_fit_guard(n_dot_v, a0));
}

// Narkowicz's refit of Lazarov's form to GGX (Narkowicz 2014, "Analytical DFG Term for IBL",
// EnvDFGLazarov).
fn ibl_dfg_narkowicz_lazarov(n_dot_v: f32, roughness: f32) -> vec2<f32> {
    let nv = min(n_dot_v, 1.0);
    let g = 1.0 - roughness;
    let tx = fma(g, 0.5745, 0.5753);
    let ty = fma(g, 1.548, -0.2511);
    let tz = fma(g, -0.02397, -0.02066);
    let tw = fma(g, 1.301, 0.4755);
    let bias = saturate(fma(tx, min(ty, exp2(-7.672 * nv)), tz));
    let delta = saturate(tw);
    return vec2<f32>(brdf_ibl_fit_guard(n_dot_v, delta - bias), brdf_ibl_fit_guard(n_dot_v, bias));
}

// Narkowicz's polynomial DFG fit (Narkowicz 2014, EnvDFGPolynomial), x = 1 - r, y = n.v.
fn ibl_dfg_narkowicz_polynomial(n_dot_v: f32, roughness: f32) -> vec2<f32> {
    let y = min(n_dot_v, 1.0);
    let x = 1.0 - roughness;
    let bias_x = x * fma(x, 1.895, -0.1688);
    let bias_y = fma(y, fma(y, fma(y, -5.069, 8.404), -4.853), 0.9903);
    let bias = saturate(min(bias_x, bias_y));
    let delta = saturate(0.6045 + fma(x, 1.699, y * -0.5228)
        + x * fma(x, fma(x, 2.661, -3.603), y * 1.404) + y * y * 0.1939);
    return vec2<f32>(brdf_ibl_fit_guard(n_dot_v, delta - bias), brdf_ibl_fit_guard(n_dot_v, bias));
}

// One channel of the split-sum specular L (F0 A + F90 B), both products capped to +-MAX.
fn brdf_ibl_specular(l: f32, f: f32, fb: f32, a: f32) -> f32 {
    let inner = clamp(fma(f, a, fb), -BRDF_F32_MAX, BRDF_F32_MAX);
    return clamp(l * inner, -BRDF_F32_MAX, BRDF_F32_MAX);
}

// The split-sum specular radiance, per channel L_prefiltered (F0 A + F90 B) (Karis 2013, "Real
// Shading in Unreal Engine 4").
fn ibl_dfg_specular(
    prefiltered_r: f32, prefiltered_g: f32, prefiltered_b: f32,
    f0_r: f32, f0_g: f32, f0_b: f32, f90: f32, a: f32, b: f32,
) -> vec3<f32> {
    let fb = f90 * b;
    return vec3<f32>(
        brdf_ibl_specular(prefiltered_r, f0_r, fb, a),
        brdf_ibl_specular(prefiltered_g, f0_g, fb, a),
        brdf_ibl_specular(prefiltered_b, f0_b, fb, a),
    );
}

// The split-sum specular radiance from Filament's two DFG channels (x = B, y = E = A + B), per
// channel L_prefiltered mix(x, y, F0) = L (x + F0 (y - x)) (Filament's `specularDFG`; Guy and
// Agopian, "Physically Based Rendering in Filament", 5.3.4.3), capped to +-MAX as above.
fn ibl_dfg_specular_filament(
    prefiltered_r: f32, prefiltered_g: f32, prefiltered_b: f32,
    f0_r: f32, f0_g: f32, f0_b: f32, dfg_x: f32, dfg_y: f32,
) -> vec3<f32> {
    let diff = clamp(dfg_y - dfg_x, -BRDF_F32_MAX, BRDF_F32_MAX);
    return vec3<f32>(
        brdf_ibl_specular(prefiltered_r, f0_r, dfg_x, diff),
        brdf_ibl_specular(prefiltered_g, f0_g, dfg_x, diff),
        brdf_ibl_specular(prefiltered_b, f0_b, dfg_x, diff),
    );
}

// The mip of a roughness on a linear mapping, r (n_mips - 1).
fn ibl_dfg_mip_from_roughness_linear(roughness: f32, n_mips: f32) -> f32 {
    return roughness * (n_mips - 1.0);
}

// Its inverse, mip / (n_mips - 1).
fn ibl_dfg_roughness_from_mip_linear(mip: f32, n_mips: f32) -> f32 {
    return mip / (n_mips - 1.0);
}

// Filament's level of detail of a roughness, L r (2 - r) (Guy and Agopian 2018, 5.3.4.4).
fn ibl_dfg_lod_from_roughness_filament(roughness: f32, roughness_one_level: f32) -> f32 {
    return roughness_one_level * roughness * (2.0 - roughness);
}

// Its inverse, 1 - sqrt(1 - lod / L).
fn ibl_dfg_roughness_from_lod_filament(lod: f32, roughness_one_level: f32) -> f32 {
    return 1.0 - sqrt(max(1.0 - lod / roughness_one_level, 0.0));
}

// Unreal Engine 4's mip of a roughness, max_mip - 1 - (1 - 1.2 log2(max(r, 0.001))) (Karis
// 2013), log2 as ln times log2(e) as in the Rust kernel.
fn ibl_dfg_mip_from_roughness_ue4(roughness: f32, cubemap_max_mip: f32) -> f32 {
    let log2_r = log(max(roughness, 0.001)) * 1.4426950408889634;
    let level_from_1x1 = fma(-1.2, log2_r, 1.0);
    return cubemap_max_mip - 1.0 - level_from_1x1;
}

// Its inverse, 2^((1 - (max_mip - 1 - mip)) / 1.2), capped at the largest finite f32.
fn ibl_dfg_roughness_from_mip_ue4(mip: f32, cubemap_max_mip: f32) -> f32 {
    let level_from_1x1 = cubemap_max_mip - 1.0 - mip;
    return min(exp2((1.0 - level_from_1x1) * 0.8333333333333334), BRDF_F32_MAX);
}

// The real spherical harmonics' constants of bands 0..2 (Ramamoorthi and Hanrahan 2001, "An
// Efficient Representation for Irradiance Environment Maps", eq. 3), rounded to f32 from the
// exact values: 1 / (2 sqrt(pi)), sqrt(3 / (4 pi)), sqrt(15 / pi) / 2, sqrt(5 / pi) / 4,
// sqrt(15 / pi) / 4.
const BRDF_SH_C0: f32 = 0.28209479177387814;
const BRDF_SH_C1: f32 = 0.4886025119029199;
const BRDF_SH_C2: f32 = 1.0925484305920792;
const BRDF_SH_C3: f32 = 0.31539156525252005;
const BRDF_SH_C4: f32 = 0.5462742152960396;
// Their eq. 13's c1..c5 with the clamped cosine's A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4,
// evaluated in f64 and rounded to f32 (c1 = A_2 C4, c2 = A_1 C1 / 2, c3 = 3 A_2 C3,
// c4 = A_0 C0, c5 = A_2 C3), as the Rust kernel rounds them.
const BRDF_SH_K1: f32 = 0.4290427654048917;
const BRDF_SH_K2: f32 = 0.5116633539732441;
const BRDF_SH_K3: f32 = 0.7431238683011271;
const BRDF_SH_K4: f32 = 0.8862269254527579;
const BRDF_SH_K5: f32 = 0.24770795610037571;

// The nine real spherical harmonics of bands 0..2 at a unit d (Ramamoorthi and Hanrahan 2001,
// eq. 3) in the order k = l (l + 1) + m: C0, C1 y, C1 z, C1 x, C2 x y, C2 y z,
// C3 (3 z^2 - 1), C2 x z, C4 (x^2 - y^2), without the Condon-Shortley phase (every constant
// positive; bases with the phase negate k = 1, 3, 5, 7). Not normalised here.
fn ibl_irradiance_sh9_basis(d_x: f32, d_y: f32, d_z: f32) -> array<f32, 9> {
    return array<f32, 9>(
        BRDF_SH_C0,
        BRDF_SH_C1 * d_y,
        BRDF_SH_C1 * d_z,
        BRDF_SH_C1 * d_x,
        BRDF_SH_C2 * d_x * d_y,
        BRDF_SH_C2 * d_y * d_z,
        BRDF_SH_C3 * (3.0 * d_z * d_z - 1.0),
        BRDF_SH_C2 * d_x * d_z,
        BRDF_SH_C4 * (d_x * d_x - d_y * d_y),
    );
}

// One channel of sum_k L_k Y_k(x, y, z), the basis in the order k = l (l + 1) + m without the
// Condon-Shortley phase (ibl::irradiance::sh9_basis), summed in order k = 0..8.
fn brdf_ibl_sh9_eval(
    l0: f32, l1: f32, l2: f32, l3: f32, l4: f32, l5: f32, l6: f32, l7: f32, l8: f32,
    x: f32, y: f32, z: f32,
) -> f32 {
    let y0 = BRDF_SH_C0;
    let y1 = BRDF_SH_C1 * y;
    let y2 = BRDF_SH_C1 * z;
    let y3 = BRDF_SH_C1 * x;
    let y4 = BRDF_SH_C2 * x * y;
    let y5 = BRDF_SH_C2 * y * z;
    let y6 = BRDF_SH_C3 * (3.0 * z * z - 1.0);
    let y7 = BRDF_SH_C2 * x * z;
    let y8 = BRDF_SH_C4 * (x * x - y * y);
    return l0 * y0 + l1 * y1 + l2 * y2 + l3 * y3 + l4 * y4 + l5 * y5 + l6 * y6 + l7 * y7
        + l8 * y8;
}

// The band-limited radiance sum_k L_k Y_k(dir) of nine RGB spherical-harmonic coefficients
// (Ramamoorthi and Hanrahan 2001, eq. 3 for the basis) at a unit dir, per channel: the
// environment seen through SH9 (it rings and may go negative near sharp features). The
// coefficients as Sh9::from_coeffs takes them, coefficient by coefficient, r g b each.
fn ibl_irradiance_Sh9_eval(
    coeffs_0_r: f32, coeffs_0_g: f32, coeffs_0_b: f32,
    coeffs_1_r: f32, coeffs_1_g: f32, coeffs_1_b: f32,
    coeffs_2_r: f32, coeffs_2_g: f32, coeffs_2_b: f32,
    coeffs_3_r: f32, coeffs_3_g: f32, coeffs_3_b: f32,
    coeffs_4_r: f32, coeffs_4_g: f32, coeffs_4_b: f32,
    coeffs_5_r: f32, coeffs_5_g: f32, coeffs_5_b: f32,
    coeffs_6_r: f32, coeffs_6_g: f32, coeffs_6_b: f32,
    coeffs_7_r: f32, coeffs_7_g: f32, coeffs_7_b: f32,
    coeffs_8_r: f32, coeffs_8_g: f32, coeffs_8_b: f32,
    dir_x: f32, dir_y: f32, dir_z: f32,
) -> vec3<f32> {
    return vec3<f32>(
        brdf_ibl_sh9_eval(coeffs_0_r, coeffs_1_r, coeffs_2_r, coeffs_3_r, coeffs_4_r,
            coeffs_5_r, coeffs_6_r, coeffs_7_r, coeffs_8_r, dir_x, dir_y, dir_z),
        brdf_ibl_sh9_eval(coeffs_0_g, coeffs_1_g, coeffs_2_g, coeffs_3_g, coeffs_4_g,
            coeffs_5_g, coeffs_6_g, coeffs_7_g, coeffs_8_g, dir_x, dir_y, dir_z),
        brdf_ibl_sh9_eval(coeffs_0_b, coeffs_1_b, coeffs_2_b, coeffs_3_b, coeffs_4_b,
            coeffs_5_b, coeffs_6_b, coeffs_7_b, coeffs_8_b, dir_x, dir_y, dir_z),
    );
}

// One channel of Ramamoorthi and Hanrahan 2001's eq. 13 (in the Rust kernel's grouping):
// E = c1 L22 (x^2 - y^2) + c3 L20 z^2 + c4 L00 - c5 L20
//   + 2 c1 (L2-2 xy + L21 xz + L2-1 yz) + 2 c2 (L11 x + L1-1 y + L10 z).
fn brdf_ibl_sh9_irradiance(
    l00: f32, l1m1: f32, l10: f32, l11: f32, l2m2: f32, l2m1: f32, l20: f32, l21: f32,
    l22: f32, x: f32, y: f32, z: f32,
) -> f32 {
    let linear = (l11 * x + l1m1 * y + l10 * z) * (2.0 * BRDF_SH_K2);
    let cross = (l2m2 * (x * y) + l21 * (x * z) + l2m1 * (y * z)) * (2.0 * BRDF_SH_K1);
    return l22 * (BRDF_SH_K1 * (x * x - y * y)) + l20 * (BRDF_SH_K3 * z * z) + l00 * BRDF_SH_K4
        - l20 * BRDF_SH_K5 + cross + linear;
}

// Irradiance E(n) = sum_lm A_l L_lm Y_lm(n) at a unit normal n from nine RGB spherical-harmonic
// coefficients of the radiance (Ramamoorthi and Hanrahan 2001, eq. 13; A_l the clamped
// cosine's bands, eq. 9), per channel. Not clamped: SH9 of a sharp light can give E < 0 facing
// away from it. A constant environment L gives pi L.
fn ibl_irradiance_Sh9_irradiance(
    coeffs_0_r: f32, coeffs_0_g: f32, coeffs_0_b: f32,
    coeffs_1_r: f32, coeffs_1_g: f32, coeffs_1_b: f32,
    coeffs_2_r: f32, coeffs_2_g: f32, coeffs_2_b: f32,
    coeffs_3_r: f32, coeffs_3_g: f32, coeffs_3_b: f32,
    coeffs_4_r: f32, coeffs_4_g: f32, coeffs_4_b: f32,
    coeffs_5_r: f32, coeffs_5_g: f32, coeffs_5_b: f32,
    coeffs_6_r: f32, coeffs_6_g: f32, coeffs_6_b: f32,
    coeffs_7_r: f32, coeffs_7_g: f32, coeffs_7_b: f32,
    coeffs_8_r: f32, coeffs_8_g: f32, coeffs_8_b: f32,
    n_x: f32, n_y: f32, n_z: f32,
) -> vec3<f32> {
    return vec3<f32>(
        brdf_ibl_sh9_irradiance(coeffs_0_r, coeffs_1_r, coeffs_2_r, coeffs_3_r, coeffs_4_r,
            coeffs_5_r, coeffs_6_r, coeffs_7_r, coeffs_8_r, n_x, n_y, n_z),
        brdf_ibl_sh9_irradiance(coeffs_0_g, coeffs_1_g, coeffs_2_g, coeffs_3_g, coeffs_4_g,
            coeffs_5_g, coeffs_6_g, coeffs_7_g, coeffs_8_g, n_x, n_y, n_z),
        brdf_ibl_sh9_irradiance(coeffs_0_b, coeffs_1_b, coeffs_2_b, coeffs_3_b, coeffs_4_b,
            coeffs_5_b, coeffs_6_b, coeffs_7_b, coeffs_8_b, n_x, n_y, n_z),
    );
}

// Kulla and Conty's multiple-scattering lobe (1 - E_o)(1 - E_i) / (pi (1 - E_avg)) (Kulla and
// Conty 2017, "Revisiting Physically Based Shading at Imageworks"; Kelemen and Szirmay-Kalos
// 2001): 0 where a factor is 0, capped at the largest f32 (ibl::energy::kulla_conty_lobe).
fn ibl_energy_kulla_conty_lobe(e_o: f32, e_i: f32, e_avg: f32) -> f32 {
    let num = (1.0 - e_o) * (1.0 - e_i);
    let den = BRDF_PI * (1.0 - e_avg);
    let ok = (den > 0.0) & (num > 0.0);
    return select(0.0, min(num / select(1.0, den, ok), BRDF_F32_MAX), ok);
}

// Kulla and Conty's multiple-scattering Fresnel F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), 1
// where the denominator is 0, capped at 1 (ibl::energy::kulla_conty_fresnel).
fn ibl_energy_kulla_conty_fresnel(f_avg: f32, e_avg: f32) -> f32 {
    let den = 1.0 - f_avg * (1.0 - e_avg);
    let ok = den > 0.0;
    return min(select(1.0, f_avg * f_avg * e_avg / select(1.0, den, ok), ok), 1.0);
}

// The hemispherical average of Schlick's Fresnel, F0 + (F90 - F0) / 21 (Fdez-Aguera 2019,
// ibl::energy::fresnel_avg_schlick).
fn ibl_energy_fresnel_avg_schlick(f0: f32, f90: f32) -> f32 {
    return fma(f90 - f0, 0.047619047619047616, f0);
}

// Turquin's energy-compensation factor 1 + F (1 - E) / E (Turquin 2019, eqs. 14 and 16), the
// quotient capped before the product so that F = 0 gives 1 (ibl::energy::turquin_scale).
fn ibl_energy_turquin_scale(e: f32, f: f32) -> f32 {
    return min(fma(f, min((1.0 - e) / e, BRDF_F32_MAX), 1.0), BRDF_F32_MAX);
}

// Fdez-Aguera's multiple-scattering term Fms Ems = FssEss F_avg Ems / (1 - Ems F_avg), Ems =
// 1 - Ess, 0 where the denominator is 0 (Fdez-Aguera 2019, JCGT 8(1), Listing 1;
// ibl::energy::fdez_aguera_ms).
fn ibl_energy_fdez_aguera_ms(fss_ess: f32, e_ss: f32, f_avg: f32) -> f32 {
    let e_ms = 1.0 - e_ss;
    let den = 1.0 - e_ms * f_avg;
    let ok = den > 0.0;
    return select(0.0, fss_ess * f_avg * e_ms / select(1.0, den, ok), ok);
}

// Fdez-Aguera's split-sum specular (FssEss, Fms Ems) from a DFG pair (A, B) and F0: FssEss =
// F0 A + B, Ess = A + B, F_avg = F0 + (1 - F0) / 21 (Listing 1; ibl::energy::fdez_aguera).
fn ibl_energy_fdez_aguera(a: f32, b: f32, f0: f32) -> vec2<f32> {
    let fss_ess = fma(f0, a, b);
    let ms = ibl_energy_fdez_aguera_ms(fss_ess, a + b, ibl_energy_fresnel_avg_schlick(f0, 1.0));
    return vec2<f32>(fss_ess, ms);
}
