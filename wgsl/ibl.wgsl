// brdf: image-based lighting terms a shader evaluates per pixel, the twins of the Rust module
// `ibl::dfg` (the analytic split-sum fits [A, B], the split-sum specular and the roughness-mip
// mappings). Needs common.wgsl. The DFG table, prefilter samples, irradiance and the
// multiple-scattering compensation have no twin yet.

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
