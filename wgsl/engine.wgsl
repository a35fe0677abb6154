// brdf: five real-time engines' metallic-roughness conventions, the twins of the Rust module
// `engine` (`engine::Convention`'s methods). Needs common.wgsl, ggx.wgsl, fresnel.wgsl and
// diffuse.wgsl.
//
// The receiver is `convention`, an index into `engine::ALL` (the reference CLI's argument):
// 0 = three.js, 1 = Filament, 2 = bevy, 3 = Unreal Engine 4 (Karis 2013), 4 = the Khronos
// glTF sample viewer. Each twin selects that engine's floors, guards, Fresnel weight, F90 rule
// and diffuse lobe, and evaluates them with the crate's stable kernels (ggx_d,
// ggx_v_correlated, ggx_v_schlick, fresnel_schlick, fresnel_schlick_sg, diffuse_lambert,
// diffuse_burley) in the Rust method's order of operations. A shader author porting from one
// of these engines can run the twin beside the engine's own shader code on the same inputs:
// where the two part, the engine's form has lost digits (three.js's and the sample viewer's
// NoH^2 (a^2 - 1) + 1 near n.h = 1, Filament's and bevy's 1 - NoH^2) or the port has changed
// a convention. Every choice is a `select` on `convention` (no branch), so all five are
// evaluated and one kept; a `convention` above 4 gives the glTF sample viewer's values.

// The perceptual roughness floor: three.js 0.0525 (`lights_physical_fragment.glsl.js`),
// Filament 0.045 (`MIN_PERCEPTUAL_ROUGHNESS`, desktop), bevy 0.089
// (`perceptualRoughnessToRoughness`), none for Unreal Engine 4 and the sample viewer.
fn brdf_engine_roughness_floor(convention: u32) -> f32 {
    return select(select(select(0.0, 0.089, convention == 2u), 0.045, convention == 1u), 0.0525,
        convention == 0u);
}

// The perceptual roughness r clamped to [floor, 1] (Convention::clamped_roughness).
fn brdf_engine_clamped_roughness(convention: u32, r: f32) -> f32 {
    return min(max(r, brdf_engine_roughness_floor(convention)), 1.0);
}

// Filament and bevy raise n.v > 0 to 1e-4 (`MIN_N_DOT_V`, bevy's `max(NdotV, 0.0001)`); the
// others leave it. n.v <= 0 passes unchanged, for the horizon test to read.
fn brdf_engine_floored_n_dot_v(convention: u32, n_dot_v: f32) -> f32 {
    let floored = (convention == 1u) | (convention == 2u);
    return select(n_dot_v, max(n_dot_v, 1e-4), floored & (n_dot_v > 0.0));
}

// Schlick's weight w(v.h): (1 - v.h)^5 (Filament, bevy, the sample viewer) as
// fresnel_schlick(0, v.h), or Karis 2013's 2^((-5.55473 v.h - 6.98316) v.h) (three.js, Unreal
// Engine 4) as fresnel_schlick_sg(0, v.h): 0 (1 - w) + 1 w is exactly w.
fn brdf_engine_schlick_weight(convention: u32, v_dot_h: f32) -> f32 {
    let sg = (convention == 0u) | (convention == 3u);
    return select(fresnel_schlick(0.0, v_dot_h), fresnel_schlick_sg(0.0, v_dot_h), sg);
}

// The GGX width alpha = clamp(r, floor, 1)^2 of the perceptual roughness r, floored at
// ALPHA_MIN = 1e-4 where the engine's floor is lower (Unreal Engine 4 and the sample viewer
// have none). r in [0, 1].
fn engine_Convention_alpha(convention: u32, perceptual_roughness: f32) -> f32 {
    return microfacet_alpha_from_perceptual(
        brdf_engine_clamped_roughness(convention, perceptual_roughness));
}

// F90 of F0: saturate(16.5 (f0.r + f0.g + f0.b)) for Filament and bevy (`fresnel(f0, LoH)`,
// 50 x 0.33), 1 for the others. F0 channels in [0, 1].
fn engine_Convention_f90(convention: u32, f0_r: f32, f0_g: f32, f0_b: f32) -> f32 {
    let sum_rule = (convention == 1u) | (convention == 2u);
    return select(1.0, min(16.5 * (f0_r + f0_g + f0_b), 1.0), sum_rule);
}

// The engine's Schlick Fresnel F0 (1 - w) + F90 w per channel, w of
// brdf_engine_schlick_weight, v.h clamped to [0, 1]: exactly F0 at w = 0 and F90 at w = 1.
fn engine_Convention_fresnel(
    convention: u32, f0_r: f32, f0_g: f32, f0_b: f32, f90: f32, v_dot_h: f32,
) -> vec3<f32> {
    let w = brdf_engine_schlick_weight(convention, v_dot_h);
    return vec3<f32>(brdf_lerp(f0_r, f90, w), brdf_lerp(f0_g, f90, w), brdf_lerp(f0_b, f90, w));
}

// The engine's GGX D: ggx_d, capped for Filament, whose denominator t = 1 - NoH^2 + (NoH a)^2
// is floored at 0.0023 (keeps D below the largest f16): alpha^2 / (pi max(t, g)^2) =
// min(D, (alpha / g)^2 / pi).
fn brdf_engine_d(convention: u32, n_dot_h: f32, alpha: f32) -> f32 {
    let d = ggx_d(n_dot_h, alpha);
    let k = alpha / 0.0023;
    return select(d, min(d, k * k * BRDF_FRAC_1_PI), convention == 1u);
}

// The engine's V of the floored n.v: the height-correlated Smith V, 0.5 / max(den, g) =
// min(V, 0.5 / g) with g = 1e-6 for three.js (`EPSILON`) and 7.7e-6 for Filament (0.5 / g
// rounded to f32: 500000 and 64935.066), no guard for bevy and the sample viewer; Unreal
// Engine 4's separable Schlick-GGX with k = (r + 1)^2 / 8 of the clamped perceptual r.
fn brdf_engine_v(convention: u32, n_dot_v: f32, n_dot_l: f32, alpha: f32, r: f32) -> f32 {
    let v = ggx_v_correlated(n_dot_v, n_dot_l, alpha);
    let guarded = select(select(v, min(v, 64935.066), convention == 1u), min(v, 500000.0),
        convention == 0u);
    let schlick = ggx_v_schlick(n_dot_v, n_dot_l, ggx_schlick_k_analytic(r));
    return select(guarded, schlick, convention == 3u);
}

// The engine's specular lobe D V F per channel for one punctual light, without n.l: alpha of
// engine_Convention_alpha, n.v floored (brdf_engine_floored_n_dot_v), D and V under the
// engine's guards, D V capped at the largest finite f32, F of engine_Convention_fresnel; 0
// where n.v <= 0 or n.l <= 0 (the cosines as given, before the floor).
fn engine_Convention_specular(
    convention: u32, n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, roughness: f32,
    f0_r: f32, f0_g: f32, f0_b: f32, f90: f32,
) -> vec3<f32> {
    let alpha = engine_Convention_alpha(convention, roughness);
    let nv = brdf_engine_floored_n_dot_v(convention, n_dot_v);
    let d = brdf_engine_d(convention, n_dot_h, alpha);
    let v = brdf_engine_v(convention, nv, n_dot_l, alpha,
        brdf_engine_clamped_roughness(convention, roughness));
    let dv = min(d * v, BRDF_F32_MAX);
    let f = engine_Convention_fresnel(convention, f0_r, f0_g, f0_b, f90, v_dot_h);
    return vec3<f32>(brdf_above_horizon(n_dot_v, n_dot_l, f.x * dv),
        brdf_above_horizon(n_dot_v, n_dot_l, f.y * dv),
        brdf_above_horizon(n_dot_v, n_dot_l, f.z * dv));
}

// One channel of the engine's diffuse lobe of the floored n.v: rho / pi (Lambert), or for
// bevy Burley 2012 fed alpha as its roughness (`Fd_Burley` reads the squared roughness).
fn brdf_engine_diffuse_lobe(
    convention: u32, nv: f32, n_dot_l: f32, v_dot_h: f32, rho: f32, alpha: f32,
) -> f32 {
    return select(diffuse_lambert(nv, n_dot_l, rho),
        diffuse_burley(nv, n_dot_l, v_dot_h, rho, alpha), convention == 2u);
}

// The engine's diffuse lobe for the (already weighted) diffuse colour, per channel, without
// n.l; 0 where n.v <= 0 or n.l <= 0.
fn engine_Convention_diffuse(
    convention: u32, n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32, roughness: f32,
    diffuse_color_r: f32, diffuse_color_g: f32, diffuse_color_b: f32,
) -> vec3<f32> {
    let nv = brdf_engine_floored_n_dot_v(convention, n_dot_v);
    let alpha = engine_Convention_alpha(convention, roughness);
    return vec3<f32>(
        brdf_engine_diffuse_lobe(convention, nv, n_dot_l, v_dot_h, diffuse_color_r, alpha),
        brdf_engine_diffuse_lobe(convention, nv, n_dot_l, v_dot_h, diffuse_color_g, alpha),
        brdf_engine_diffuse_lobe(convention, nv, n_dot_l, v_dot_h, diffuse_color_b, alpha));
}

// 1 - (1 - c)^5 without cancellation: c (1 + s + s^2 + s^3 + s^4), s = 1 - c, c = v.h clamped
// to [0, 1] (the pow5 weight's complement, Convention::one_minus_schlick_weight; only the
// sample viewer, a pow5 engine, reads it).
fn brdf_engine_one_minus_pow5(v_dot_h: f32) -> f32 {
    let c = saturate(v_dot_h);
    let s = 1.0 - c;
    return c * fma(s, fma(s, fma(s, s + 1.0, 1.0), 1.0), 1.0);
}

// The engine's metallic-roughness BRDF for one punctual light, RGB, without n.l:
// F0 = lerp(0.04, base, metallic) = 0.04 (1 - m) + base m, F90 of engine_Convention_f90,
// specular + diffuse of the base colour weighted by kd = 1 - m, or for the sample viewer
// (glTF 2.0 Appendix B's mix) kd = (1 - m)(1 - 0.04)(1 - (1 - v.h)^5).
fn engine_Convention_brdf(
    convention: u32, n_dot_v: f32, n_dot_l: f32, n_dot_h: f32, v_dot_h: f32,
    base_color_r: f32, base_color_g: f32, base_color_b: f32, metallic: f32, roughness: f32,
) -> vec3<f32> {
    let one_minus_m = 1.0 - metallic;
    let f0 = vec3<f32>(fma(0.04, one_minus_m, base_color_r * metallic),
        fma(0.04, one_minus_m, base_color_g * metallic),
        fma(0.04, one_minus_m, base_color_b * metallic));
    let spec = engine_Convention_specular(convention, n_dot_v, n_dot_l, n_dot_h, v_dot_h,
        roughness, f0.x, f0.y, f0.z, engine_Convention_f90(convention, f0.x, f0.y, f0.z));
    let kd = select(one_minus_m, one_minus_m * 0.96 * brdf_engine_one_minus_pow5(v_dot_h),
        convention >= 4u);
    let diff = engine_Convention_diffuse(convention, n_dot_v, n_dot_l, n_dot_h, v_dot_h,
        roughness, base_color_r * kd, base_color_g * kd, base_color_b * kd);
    return spec + diff;
}
