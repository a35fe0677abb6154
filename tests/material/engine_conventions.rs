//! `engine::Convention` against each engine's own shader code, transcribed to `f32` below (the
//! oracle of this test: every transcription keeps its engine's operation order, constants,
//! epsilons and cancellation-prone forms; GLSL's `mix(x, y, a)` is x (1 - a) + y a, no fused
//! multiply-adds). On a grid of cosines (n.h up to 1 - 2^-24 and 1, n.v and n.l down to 1e-5),
//! roughness (below every floor), F0 / base colour and metallic:
//!
//! - where the transcription is itself accurate (within [`ACCURATE`] ULP of the crate's `f64`
//!   evaluation of the same convention), the crate's `f32` `brdf`, `specular` and `diffuse`
//!   agree with it within [`AGREE`] ULP;
//! - where it is not, the test prints how many digits the engine's form loses (three.js's and
//!   the glTF viewer's `NoH^2 (a^2 - 1) + 1` near n.h = 1, Filament's and bevy's `1 - NoH^2`),
//!   and asserts the magnitude found;
//! - the engines differ where their conventions do (roughness floors, guards, F90, diffuse);
//! - `f32x8` lanes equal the scalar results (bit for bit where the kernels use arithmetic
//!   only, within the exp2 lane bound for the spherical-Gaussian Fresnel).
//!
//! `cargo test --all-features --test material engine_conventions:: -- --nocapture` prints the tables.
//!
//! What the transcriptions leave out, as `Convention` does (module docs): Filament's and
//! bevy's energy compensation (set to 1), three.js's `geometryRoughness` (a flat surface),
//! bevy's light radius (0), and the n.l factor (every engine multiplies by it outside the
//! BRDF; the glTF viewer's mixes are linear, so it factors out).
#![cfg(feature = "engine")]
// The transcriptions keep each engine's own constants (its PI, three.js's RECIPROCAL_PI) and
// its own clamps, which clippy would replace.
#![allow(
    clippy::excessive_precision,
    clippy::many_single_char_names,
    clippy::approx_constant,
    clippy::manual_clamp,
    clippy::type_complexity
)]

use brdf::engine::{
    self, ALL, BEVY, Convention, FILAMENT, KHRONOS_SAMPLE_VIEWER, THREE_JS, UNREAL_4,
};
use brdf::wide::f32x8;
use brdf::{Cosines, V3};

/// A transcription whose result is within this many ULP of the crate's `f64` evaluation
/// counts as accurate at that point. Why 8: each transcription is a chain of 10 to 20
/// roundings without a cancellation where it is well conditioned, so it lands within a few
/// ULP there; a cancelling form lands thousands of ULP away, far from this threshold.
const ACCURATE: f64 = 8.0;

/// Bound on the crate's own `f32` error against its `f64` evaluation, over the whole grid.
/// Measured 5.1 (three.js) to 9.96 (Unreal Engine 4: the separable Schlick-GGX visibility,
/// the exp2 Fresnel weight and three products, each rounded once).
const CRATE_F32: f64 = 12.0;

/// Bound on |crate f32 - transcription f32| where the transcription is accurate: both lie
/// within [`ACCURATE`] (the transcription, by selection) and [`CRATE_F32`] (the crate) of the
/// same `f64` value, so they lie within the sum of each other. Measured (brdf): three.js 9,
/// Filament 9, bevy 9, Unreal Engine 4 12, glTF viewer 11.
const AGREE: f64 = ACCURATE + CRATE_F32;

/// |a - b| in units of the f32 spacing at the larger of the two (0 when both are 0; infinite
/// when exactly one is NaN).
fn ulps(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        return if a.is_nan() && b.is_nan() {
            0.0
        } else {
            f64::INFINITY
        };
    }
    if a == b {
        return 0.0;
    }
    let m = a.abs().max(b.abs()).max(f64::from(f32::MIN_POSITIVE));
    let ulp = 2f64.powi(m.log2().floor() as i32 - 23);
    (a - b).abs() / ulp
}

fn ulps3(a: [f32; 3], b: [f64; 3]) -> f64 {
    (0..3)
        .map(|i| ulps(f64::from(a[i]), b[i]))
        .fold(0.0, f64::max)
}

fn ulps33(a: [f32; 3], b: [f32; 3]) -> f64 {
    (0..3)
        .map(|i| ulps(f64::from(a[i]), f64::from(b[i])))
        .fold(0.0, f64::max)
}

fn sat(x: f32) -> f32 {
    x.clamp(0.0, 1.0)
}

/// One grid point: cosines, base colour, metallic, perceptual roughness.
#[derive(Clone, Copy, Debug)]
struct P {
    nv: f32,
    nl: f32,
    nh: f32,
    vh: f32,
    base: [f32; 3],
    m: f32,
    r: f32,
}

/// The (specular, diffuse) of a transcription, RGB, without n.l; the BRDF is their sum.
type Lobes = ([f32; 3], [f32; 3]);

// ---------------------------------------------------------------------------------------
// three.js: bsdfs.glsl.js @ 12f550e0f44f68e5b6c946dd242ee08e42d209e4 (F_Schlick, D_GGX,
// V_GGX_SmithCorrelated, BRDF_GGX, BRDF_Lambert); common.glsl.js @
// cfa421245d0ea3a21de6a29a8950e04ce6995df8 (EPSILON, RECIPROCAL_PI, pow2, saturate);
// lights_physical_fragment.glsl.js and RE_Direct_Physical of lights_physical_pars_fragment
// (r16x build): roughness = min(max(r, 0.0525) + 0, 1), diffuseColor = base (1 - metalness),
// specularColor = mix(vec3(0.04), base, metalness), specularF90 = 1.
mod three {
    const EPSILON: f32 = 1e-6;
    const RECIPROCAL_PI: f32 = 0.31830988618;
    fn pow2(x: f32) -> f32 {
        x * x
    }
    pub fn f_schlick(f0: f32, f90: f32, dot_vh: f32) -> f32 {
        let fresnel = ((-5.55473 * dot_vh - 6.98316) * dot_vh).exp2();
        f0 * (1.0 - fresnel) + (f90 * fresnel)
    }
    pub fn v_ggx_smith_correlated(alpha: f32, dot_nl: f32, dot_nv: f32) -> f32 {
        let a2 = pow2(alpha);
        let gv = dot_nl * (a2 + (1.0 - a2) * pow2(dot_nv)).sqrt();
        let gl = dot_nv * (a2 + (1.0 - a2) * pow2(dot_nl)).sqrt();
        0.5 / (gv + gl).max(EPSILON)
    }
    pub fn d_ggx(alpha: f32, dot_nh: f32) -> f32 {
        let a2 = pow2(alpha);
        let denom = pow2(dot_nh) * (a2 - 1.0) + 1.0;
        RECIPROCAL_PI * a2 / pow2(denom)
    }
    pub fn roughness(r: f32) -> f32 {
        r.max(0.0525).min(1.0)
    }
    pub fn lobes(p: super::P) -> super::Lobes {
        let roughness = roughness(p.r);
        let alpha = pow2(roughness);
        let (dot_nl, dot_nv, dot_nh, dot_vh) = (
            super::sat(p.nl),
            super::sat(p.nv),
            super::sat(p.nh),
            super::sat(p.vh),
        );
        let v = v_ggx_smith_correlated(alpha, dot_nl, dot_nv);
        let d = d_ggx(alpha, dot_nh);
        let spec = p.base.map(|b| {
            let f0 = 0.04 * (1.0 - p.m) + b * p.m;
            f_schlick(f0, 1.0, dot_vh) * (v * d)
        });
        let diff = p.base.map(|b| RECIPROCAL_PI * (b * (1.0 - p.m)));
        (spec, diff)
    }
}

// ---------------------------------------------------------------------------------------
// Filament: shaders/src/surface_brdf.fs @ 828846b024da5045afed13502331e1cb5e9670c1 (D_GGX
// desktop branch, V_SmithGGXCorrelated, F_Schlick, fresnel, Fd_Lambert);
// surface_shading_model_standard.fs @ a5fba7078225b9d7c97ca35f24d0c0d7507b63e3 (isotropicLobe
// (D V) F, surfaceShading Fd + Fr, energyCompensation 1); common_material.fs @
// 90818706ecf5a4c33a89b3f317335021f8e31cd3 (MIN_PERCEPTUAL_ROUGHNESS 0.045, clampNoV 1e-4,
// computeDiffuseColor, computeF0, computeDielectricF0(0.5)); common_math.fs (PI, pow5 =
// x2 x2 x).
mod filament {
    const PI: f32 = 3.14159265359;
    fn pow5(x: f32) -> f32 {
        let x2 = x * x;
        x2 * x2 * x
    }
    pub fn d_ggx(roughness: f32, noh: f32) -> f32 {
        let one_minus_noh_squared = 1.0 - noh * noh;
        let a = noh * roughness;
        let k = roughness / (one_minus_noh_squared + a * a).max(0.0023);
        k * (k * (1.0 / PI))
    }
    pub fn v_smith_ggx_correlated(roughness: f32, nov: f32, nol: f32) -> f32 {
        let a2 = roughness * roughness;
        let lambda_v = nol * ((nov - a2 * nov) * nov + a2).sqrt();
        let lambda_l = nov * ((nol - a2 * nol) * nol + a2).sqrt();
        0.5 / (lambda_v + lambda_l).max(0.0000077)
    }
    pub fn f_schlick(f0: f32, f90: f32, voh: f32) -> f32 {
        f0 + (f90 - f0) * pow5(1.0 - voh)
    }
    pub fn lobes(p: super::P) -> super::Lobes {
        let perceptual = p.r.clamp(0.045, 1.0);
        let roughness = perceptual * perceptual;
        let nov = p.nv.max(1e-4);
        let (nol, noh, loh) = (super::sat(p.nl), super::sat(p.nh), super::sat(p.vh));
        let reflectance = 0.16 * 0.5 * 0.5;
        let f0 = p.base.map(|b| b * p.m + (reflectance * (1.0 - p.m)));
        let f90 = super::sat(f0[0] * (50.0 * 0.33) + f0[1] * (50.0 * 0.33) + f0[2] * (50.0 * 0.33));
        let d = d_ggx(roughness, noh);
        let v = v_smith_ggx_correlated(roughness, nov, nol);
        let spec = f0.map(|f| (d * v) * f_schlick(f, f90, loh));
        let diff = p.base.map(|b| (b * (1.0 - p.m)) * (1.0 / PI));
        (spec, diff)
    }
}

// ---------------------------------------------------------------------------------------
// bevy v0.15.0 (3f2baf8ecd7f8948fb67cf11b0f2811d7a1ca1ae): crates/bevy_pbr/src/render/
// pbr_lighting.wgsl (D_GGX, V_SmithGGXCorrelated, F_Schlick_vec, F_Schlick, fresnel,
// Fd_Burley, perceptualRoughnessToRoughness, specular with specular_intensity 1 and the
// multiscatter factor 1, point_light diffuse + specular) and pbr_functions.wgsl (NdotV =
// max(., 0.0001), calculate_diffuse_color, calculate_F0 with reflectance 0.5); PI from
// bevy_render maths.
mod bevy {
    const PI: f32 = 3.141592653589793;
    pub fn d_ggx(roughness: f32, ndoth: f32) -> f32 {
        let one_minus_ndoth_squared = 1.0 - ndoth * ndoth;
        let a = ndoth * roughness;
        let k = roughness / (one_minus_ndoth_squared + a * a);
        k * k * (1.0 / PI)
    }
    pub fn v_smith_ggx_correlated(roughness: f32, ndotv: f32, ndotl: f32) -> f32 {
        let a2 = roughness * roughness;
        let lambda_v = ndotl * ((ndotv - a2 * ndotv) * ndotv + a2).sqrt();
        let lambda_l = ndotv * ((ndotl - a2 * ndotl) * ndotl + a2).sqrt();
        0.5 / (lambda_v + lambda_l)
    }
    fn f_schlick(f0: f32, f90: f32, vdoth: f32) -> f32 {
        f0 + (f90 - f0) * (1.0 - vdoth).powf(5.0)
    }
    fn fd_burley(roughness: f32, ndotv: f32, ndotl: f32, ldoth: f32) -> f32 {
        let f90 = 0.5 + 2.0 * roughness * ldoth * ldoth;
        let light_scatter = f_schlick(1.0, f90, ndotl);
        let view_scatter = f_schlick(1.0, f90, ndotv);
        light_scatter * view_scatter * (1.0 / PI)
    }
    pub fn lobes(p: super::P) -> super::Lobes {
        let clamped = p.r.clamp(0.089, 1.0);
        let roughness = clamped * clamped;
        let ndotv = p.nv.max(0.0001);
        let (ndotl, ndoth, ldoth) = (super::sat(p.nl), super::sat(p.nh), super::sat(p.vh));
        let reflectance = 0.5;
        let f0 = p
            .base
            .map(|b| 0.16 * reflectance * reflectance * (1.0 - p.m) + b * p.m);
        let f90 = super::sat(f0[0] * (50.0 * 0.33) + f0[1] * (50.0 * 0.33) + f0[2] * (50.0 * 0.33));
        let d = d_ggx(roughness, ndoth);
        let v = v_smith_ggx_correlated(roughness, ndotv, ndotl);
        let spec = f0.map(|f| (1.0 * d * v) * f_schlick(f, f90, ldoth));
        let burley = fd_burley(roughness, ndotv, ndotl, ldoth);
        let diff = p
            .base
            .map(|b| b * (1.0 - p.m) * (1.0 - 0.0) * (1.0 - 0.0) * burley);
        (spec, diff)
    }
}

// ---------------------------------------------------------------------------------------
// Unreal Engine 4 as Karis 2013, "Real Shading in Unreal Engine 4" (SIGGRAPH course notes),
// writes it (BRDF.ush is not public): f = D F G / (4 NoL NoV) + c_diff / pi with alpha =
// Roughness^2, D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), G = G1(l) G1(v), G1(x) =
// x / (x (1 - k) + k), k = (Roughness + 1)^2 / 8, F = F0 + (1 - F0) 2^((-5.55473 v.h -
// 6.98316) v.h), c_diff = base (1 - metallic), F0 = lerp(0.08 Specular, base, metallic) with
// Specular 0.5. No roughness floor; cosines saturated.
mod ue4 {
    const PI: f32 = 3.1415926535897932;
    pub fn d_ggx(a: f32, noh: f32) -> f32 {
        let a2 = a * a;
        let d = (noh * noh) * (a2 - 1.0) + 1.0;
        a2 / (PI * d * d)
    }
    fn g1(x: f32, k: f32) -> f32 {
        x / (x * (1.0 - k) + k)
    }
    fn f_schlick(f0: f32, voh: f32) -> f32 {
        f0 + (1.0 - f0) * ((-5.55473 * voh - 6.98316) * voh).exp2()
    }
    pub fn lobes(p: super::P) -> super::Lobes {
        let roughness = super::sat(p.r);
        let a = roughness * roughness;
        let k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
        let (nov, nol, noh, voh) = (
            super::sat(p.nv),
            super::sat(p.nl),
            super::sat(p.nh),
            super::sat(p.vh),
        );
        let d = d_ggx(a, noh);
        let g = g1(nol, k) * g1(nov, k);
        let spec = p.base.map(|b| {
            let f0 = 0.08 * 0.5 * (1.0 - p.m) + b * p.m;
            d * f_schlick(f0, voh) * g / (4.0 * nol * nov)
        });
        let diff = p.base.map(|b| b * (1.0 - p.m) / PI);
        (spec, diff)
    }
}

// ---------------------------------------------------------------------------------------
// Khronos glTF-Sample-Viewer: source/Renderer/shaders/brdf.glsl @
// d0b428c8946052cb640c4cf772686eb6c3abf3c2 (F_Schlick(vec3, vec3, float) with pow, V_GGX,
// D_GGX, BRDF_lambertian, BRDF_specularGGX); pbr.frag (dielectric_fresnel = F_Schlick(0.04 x
// specularWeight 1, f90_dielectric 1, |VdotH|), metal_fresnel = F_Schlick(base, 1, |VdotH|),
// l_dielectric_brdf = mix(l_diffuse, l_specular, dielectric_fresnel), l_color =
// mix(l_dielectric_brdf, metal_fresnel l_specular, metallic)); material_info.glsl
// (perceptualRoughness = clamp(r, 0, 1), alphaRoughness = r^2). M_PI = 3.141592653589793.
mod khronos {
    const M_PI: f32 = 3.141592653589793;
    pub fn f_schlick(f0: f32, f90: f32, vdoth: f32) -> f32 {
        f0 + (f90 - f0) * (1.0 - vdoth).clamp(0.0, 1.0).powf(5.0)
    }
    pub fn v_ggx(ndotl: f32, ndotv: f32, alpha_roughness: f32) -> f32 {
        let alpha_roughness_sq = alpha_roughness * alpha_roughness;
        let ggxv = ndotl * (ndotv * ndotv * (1.0 - alpha_roughness_sq) + alpha_roughness_sq).sqrt();
        let ggxl = ndotv * (ndotl * ndotl * (1.0 - alpha_roughness_sq) + alpha_roughness_sq).sqrt();
        let ggx = ggxv + ggxl;
        if ggx > 0.0 { 0.5 / ggx } else { 0.0 }
    }
    pub fn d_ggx(ndoth: f32, alpha_roughness: f32) -> f32 {
        let alpha_roughness_sq = alpha_roughness * alpha_roughness;
        let f = (ndoth * ndoth) * (alpha_roughness_sq - 1.0) + 1.0;
        alpha_roughness_sq / (M_PI * f * f)
    }
    fn mix(x: f32, y: f32, a: f32) -> f32 {
        x * (1.0 - a) + y * a
    }
    /// The whole BRDF (the mixes do not separate into a diffuse and a specular lobe the way
    /// the additive engines do): returned as (brdf, 0).
    pub fn lobes(p: super::P) -> super::Lobes {
        let perceptual = super::sat(p.r);
        let alpha = perceptual * perceptual;
        let (ndotl, ndotv, ndoth, vdoth) = (
            super::sat(p.nl),
            super::sat(p.nv),
            super::sat(p.nh),
            super::sat(p.vh),
        );
        let l_specular = v_ggx(ndotl, ndotv, alpha) * d_ggx(ndoth, alpha);
        let f_d = f_schlick(0.04 * 1.0, 1.0, vdoth.abs());
        let color = p.base.map(|b| {
            let l_diffuse = b / M_PI;
            let metal_fresnel = f_schlick(b, 1.0, vdoth.abs());
            let l_metal = metal_fresnel * l_specular;
            let l_dielectric = mix(l_diffuse, l_specular, f_d);
            mix(l_dielectric, l_metal, p.m)
        });
        (color, [0.0; 3])
    }
}

/// The engines with their transcriptions, in `engine::ALL`'s order.
fn engines() -> [(Convention, fn(P) -> Lobes); 5] {
    [
        (THREE_JS, three::lobes),
        (FILAMENT, filament::lobes),
        (BEVY, bevy::lobes),
        (UNREAL_4, ue4::lobes),
        (KHRONOS_SAMPLE_VIEWER, khronos::lobes),
    ]
}

fn cos<T: brdf::Real>(p: &P, f: impl Fn(f32) -> T) -> Cosines<T> {
    Cosines {
        n_dot_v: f(p.nv),
        n_dot_l: f(p.nl),
        n_dot_h: f(p.nh),
        v_dot_h: f(p.vh),
    }
}

fn v3f(x: [f32; 3]) -> V3<f32> {
    V3::new(x[0], x[1], x[2])
}

fn v3d(x: [f32; 3]) -> V3<f64> {
    V3::new(f64::from(x[0]), f64::from(x[1]), f64::from(x[2]))
}

/// The crate's (specular, diffuse) of a convention, as `brdf` composes them, in f32 and f64.
fn crate_lobes32(e: &Convention, p: &P) -> ([f32; 3], [f32; 3], [f32; 3]) {
    let c = cos(p, |x| x);
    let total = e.brdf(c, v3f(p.base), p.m, p.r).to_array();
    let f0 = V3::new(p.base[0], p.base[1], p.base[2]).map(|b| 0.04f32.mul_add(1.0 - p.m, b * p.m));
    let spec = e.specular(c, p.r, f0, e.f90(f0)).to_array();
    let diff = e.diffuse(c, p.r, v3f(p.base) * (1.0 - p.m)).to_array();
    (total, spec, diff)
}

fn crate_lobes64(e: &Convention, p: &P) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let c = cos(p, f64::from);
    let (m, r) = (f64::from(p.m), f64::from(p.r));
    let total = e.brdf(c, v3d(p.base), m, r).to_array();
    let f0 = v3d(p.base).map(|b| 0.04f64.mul_add(1.0 - m, b * m));
    let spec = e.specular(c, r, f0, e.f90(f0)).to_array();
    let diff = e.diffuse(c, r, v3d(p.base) * (1.0 - m)).to_array();
    (total, spec, diff)
}

const NH_NEAR_1: [f32; 4] = [
    0.999,
    1.0 - 1.0 / 1_048_576.0,
    1.0 - 1.0 / 16_777_216.0,
    1.0,
];

fn grid() -> Vec<P> {
    let cosines = [1e-5_f32, 1e-4, 0.01, 0.1, 0.5, 0.9, 1.0];
    let nhs = [
        0.0_f32,
        0.5,
        0.9,
        0.99,
        NH_NEAR_1[0],
        NH_NEAR_1[1],
        NH_NEAR_1[2],
        1.0,
    ];
    let vhs = [0.0_f32, 0.01, 0.3, 0.7, 1.0];
    let roughs = [0.0_f32, 0.005, 0.02, 0.05, 0.0525, 0.1, 0.3, 0.5, 0.8, 1.0];
    let metals = [0.0_f32, 0.5, 1.0];
    let bases = [[0.9_f32, 0.6, 0.3], [0.01, 0.02, 0.005], [1.0, 1.0, 1.0]];
    let mut out = Vec::new();
    for &nv in &cosines {
        for &nl in &cosines {
            for &nh in &nhs {
                for &vh in &vhs {
                    for &r in &roughs {
                        for &m in &metals {
                            for &base in &bases {
                                out.push(P {
                                    nv,
                                    nl,
                                    nh,
                                    vh,
                                    base,
                                    m,
                                    r,
                                });
                            }
                        }
                    }
                }
            }
        }
    }
    out
}

/// Per-engine agreement figures over the grid.
#[derive(Default, Debug)]
struct Stats {
    points: usize,
    accurate: usize,
    /// max |crate f32 - transcription| where the transcription is accurate, per output.
    agree_total: f64,
    agree_spec: f64,
    agree_diff: f64,
    /// max |crate f32 - crate f64| over the whole grid.
    crate_err: f64,
    /// max |transcription - crate f64| over the whole grid, and where.
    engine_err: f64,
    engine_worst: Option<P>,
    /// Points where the transcription is not accurate, by n.h and by v.h value.
    inaccurate_by_nh: std::collections::BTreeMap<String, usize>,
    inaccurate_by_vh: std::collections::BTreeMap<String, usize>,
    inaccurate_by_cos: std::collections::BTreeMap<String, usize>,
}

/// Points where the engine's convention is not the crate's by design: roughness below the
/// crate's ALPHA_MIN floor (r < 0.01) in an engine without its own floor, and a half vector
/// on the horizon (n.h = 0, where the crate's D is 0 and the engines' alpha^2 / pi).
fn by_design(e: &Convention, p: &P) -> bool {
    (e.roughness_floor < 0.01 && p.r < 0.01) || p.nh <= 0.0
}

fn measure(e: &Convention, lobes: fn(P) -> Lobes) -> Stats {
    let mut s = Stats::default();
    for p in grid() {
        if by_design(e, &p) {
            continue;
        }
        s.points += 1;
        let (t_spec, t_diff) = lobes(p);
        let t_total = [0, 1, 2].map(|i| t_spec[i] + t_diff[i]);
        let (c_total, c_spec, c_diff) = crate_lobes32(e, &p);
        let (r_total, r_spec, r_diff) = crate_lobes64(e, &p);
        s.crate_err = s.crate_err.max(ulps3(c_total, r_total));
        let err = ulps3(t_total, r_total);
        if err > s.engine_err {
            s.engine_err = err;
            s.engine_worst = Some(p);
        }
        if err > ACCURATE {
            *s.inaccurate_by_nh.entry(format!("{}", p.nh)).or_default() += 1;
            *s.inaccurate_by_vh.entry(format!("{}", p.vh)).or_default() += 1;
            *s.inaccurate_by_cos
                .entry(format!("{}", p.nv.min(p.nl)))
                .or_default() += 1;
        }
        if err <= ACCURATE {
            s.accurate += 1;
            s.agree_total = s.agree_total.max(ulps33(c_total, t_total));
        }
        // The lobes separately, where the transcription's lobe is accurate (the glTF viewer's
        // composition has no separate lobes: its total is compared above).
        if e.diffuse_weight == engine::DiffuseWeight::OneMinusMetallic {
            if ulps3(t_spec, r_spec) <= ACCURATE {
                s.agree_spec = s.agree_spec.max(ulps33(c_spec, t_spec));
            }
            if ulps3(t_diff, r_diff) <= ACCURATE {
                s.agree_diff = s.agree_diff.max(ulps33(c_diff, t_diff));
            }
        }
    }
    s
}

#[test]
fn each_convention_agrees_with_its_engines_shader_where_the_shader_is_accurate() {
    println!(
        "{:<28} {:>7} {:>9} {:>11} {:>10} {:>10} {:>15} {:>17}",
        "engine",
        "points",
        "accurate",
        "brdf ulp",
        "spec ulp",
        "diff ulp",
        "crate f32 ulp",
        "engine form ulp"
    );
    for (e, lobes) in engines() {
        let s = measure(&e, lobes);
        println!(
            "{:<28} {:>7} {:>9} {:>11.2} {:>10.2} {:>10.2} {:>15.2} {:>17.3e}",
            e.name,
            s.points,
            s.accurate,
            s.agree_total,
            s.agree_spec,
            s.agree_diff,
            s.crate_err,
            s.engine_err
        );
        println!("    engine form's worst point: {:?}", s.engine_worst);
        println!("    inaccurate by n.h: {:?}", s.inaccurate_by_nh);
        println!("    inaccurate by v.h: {:?}", s.inaccurate_by_vh);
        println!("    inaccurate by min(n.v, n.l): {:?}", s.inaccurate_by_cos);
        // A third of the grid (half of its n.h values lie within 0.01 of 1, where the engines'
        // forms cancel) is well conditioned for every engine: the comparison is not vacuous.
        assert!(
            s.accurate * 3 > s.points,
            "{}: only {} of {} points accurate",
            e.name,
            s.accurate,
            s.points
        );
        assert!(
            s.crate_err <= CRATE_F32,
            "{}: crate f32 {} ULP from f64",
            e.name,
            s.crate_err
        );
        for (what, v) in [
            ("brdf", s.agree_total),
            ("specular", s.agree_spec),
            ("diffuse", s.agree_diff),
        ] {
            assert!(
                v <= AGREE,
                "{}: {what} differs from the transcription by {v} ULP",
                e.name
            );
        }
    }
}

/// The cancellation of `NoH^2 (a^2 - 1) + 1` (three.js, the glTF viewer, Karis's notes) and
/// of `1 - NoH^2` (Filament, bevy) near n.h = 1 at each engine's smallest alpha, against the
/// crate's `ggx::d` in f64 (correctly rounded in f32 too: shown as the last column).
#[test]
fn engine_ndf_forms_lose_digits_near_n_dot_h_one() {
    let nhs: Vec<f32> = (0..=64u32)
        .map(|k| 1.0 - k as f32 * f32::EPSILON / 2.0)
        .chain([0.9999, 0.99999])
        .collect();
    println!(
        "{:<28} {:>10} {:>18} {:>16}",
        "engine", "alpha", "engine D max ulp", "ggx::d f32 ulp"
    );
    let forms: [(&str, f32, fn(f32, f32) -> f32, f64); 4] = [
        // (name, alpha at the engine's floor, D(alpha, n.h), the least error the test demands)
        ("three.js D_GGX", 0.0525 * 0.0525, three::d_ggx, 1e4),
        (
            "Khronos D_GGX (r = 0.1)",
            0.1 * 0.1,
            |a, nh| khronos::d_ggx(nh, a),
            1e2,
        ),
        ("UE4 (Karis) D (r = 0.1)", 0.1 * 0.1, ue4::d_ggx, 1e2),
        ("bevy D_GGX", 0.089 * 0.089, bevy::d_ggx, 1e2),
    ];
    for (name, alpha, d, least) in forms {
        let mut worst = 0.0_f64;
        let mut ours = 0.0_f64;
        for &nh in &nhs {
            let reference = brdf::ggx::d(f64::from(nh), f64::from(alpha));
            worst = worst.max(ulps(f64::from(d(alpha, nh)), reference));
            ours = ours.max(ulps(f64::from(brdf::ggx::d(nh, alpha)), reference));
        }
        println!("{name:<28} {alpha:>10.3e} {worst:>18.3e} {ours:>16.2}");
        assert!(
            worst >= least,
            "{name}: only {worst} ULP lost; the form was expected to cancel"
        );
        assert!(ours <= 1.0, "{name}: ggx::d in f32 is {ours} ULP from f64");
    }
    // three.js's loss at its floor, the headline figure: on the order of 1e5 ULP.
    let alpha = 0.0525_f32 * 0.0525;
    let worst = nhs
        .iter()
        .map(|&nh| {
            ulps(
                f64::from(three::d_ggx(alpha, nh)),
                brdf::ggx::d(f64::from(nh), f64::from(alpha)),
            )
        })
        .fold(0.0, f64::max);
    assert!(
        (3e4..3e6).contains(&worst),
        "three.js D_GGX near n.h = 1 lost {worst:e} ULP; measured about 1e5"
    );
    // The crate's convention keeps them: THREE_JS.specular near n.h = 1 within a few ULP of f64.
    let c = |nh: f32| Cosines {
        n_dot_v: 0.9_f32,
        n_dot_l: 0.9,
        n_dot_h: nh,
        v_dot_h: 0.99,
    };
    for &nh in &nhs {
        let a = THREE_JS.specular(c(nh), 0.0, V3::splat(0.04), 1.0).x;
        let cc = Cosines {
            n_dot_v: 0.9,
            n_dot_l: 0.9,
            n_dot_h: f64::from(nh),
            v_dot_h: f64::from(0.99_f32),
        };
        let b = THREE_JS
            .specular(cc, 0.0, V3::splat(f64::from(0.04_f32)), 1.0)
            .x;
        assert!(ulps(f64::from(a), b) <= 8.0, "n.h = {nh}: {a} vs {b}");
    }
}

#[test]
fn engines_differ_where_their_conventions_do() {
    let base = V3::new(0.9_f32, 0.6, 0.3);
    // Below three.js's 0.0525 floor every r gives the floor's lobe...
    let peak = Cosines {
        n_dot_v: 0.7_f32,
        n_dot_l: 0.7,
        n_dot_h: 1.0,
        v_dot_h: 0.7,
    };
    let at = |e: &Convention, r: f32| e.brdf(peak, base, 0.0, r);
    assert_eq!(at(&THREE_JS, 0.02), at(&THREE_JS, 0.0525));
    assert_eq!(THREE_JS.alpha(0.0_f32), 0.0525_f32 * 0.0525);
    // ...and the five engines disagree there (floors 0.0525, 0.045 with D capped by its 0.0023
    // denominator floor, 0.089, none, none; Karis's Schlick-GGX visibility).
    let values: Vec<f32> = ALL.iter().map(|e| at(e, 0.02).x).collect();
    println!("specular peak at r = 0.02: {values:?}");
    for i in 0..5 {
        for j in 0..i {
            assert!(
                values[i] != values[j],
                "{} and {} agree",
                ALL[i].name,
                ALL[j].name
            );
        }
    }
    // Filament's denominator floor caps its peak: alpha^2 / (pi 0.0023^2) < 1 / (pi alpha^2).
    let alpha = FILAMENT.alpha(0.0_f32);
    let cap = alpha * alpha / (core::f32::consts::PI * 0.0023 * 0.0023);
    let f_spec = FILAMENT.specular(peak, 0.0, V3::splat(1.0), 1.0).x;
    let v = brdf::ggx::v_correlated(0.7_f32, 0.7, alpha);
    assert!(
        (f_spec / (cap * v) - 1.0).abs() < 1e-5,
        "{f_spec} vs {}",
        cap * v
    );
    // three.js's visibility guard: 0.5 / max(den, 1e-6) at n.v = n.l = 1e-5, smooth.
    let tiny = Cosines {
        n_dot_v: 1e-5_f32,
        n_dot_l: 1e-5,
        n_dot_h: 0.5,
        v_dot_h: 0.5,
    };
    let d = brdf::ggx::d(0.5_f32, THREE_JS.alpha(0.0));
    let s = THREE_JS.specular(tiny, 0.0, V3::splat(1.0), 1.0).x;
    assert!(
        (s / (d * 5e5) - 1.0).abs() < 1e-5,
        "guarded V: {s} vs {}",
        d * 5e5
    );
    assert!(BEVY.specular(tiny, 0.1, V3::splat(1.0), 1.0).x > 0.0);
    // F90: Filament and bevy dim the grazing reflection of a dark metal, the others do not.
    let dark = V3::new(0.01_f32, 0.02, 0.005);
    assert!((FILAMENT.f90(dark) - 16.5 * 0.035).abs() < 1e-6);
    assert_eq!(THREE_JS.f90(dark), 1.0);
    let grazing = Cosines {
        n_dot_v: 0.5_f32,
        n_dot_l: 0.5,
        n_dot_h: 0.8,
        v_dot_h: 0.0,
    };
    let f_fil = FILAMENT.fresnel(dark, FILAMENT.f90(dark), 0.0_f32);
    assert!(
        (f_fil.x - 0.5775).abs() < 1e-6
            && KHRONOS_SAMPLE_VIEWER.fresnel(dark, 1.0, 0.0_f32).x == 1.0
    );
    // The spherical-Gaussian fit does not reach F0 at v.h = 1: F0 + (1 - F0) 2^-12.5.
    let f_sg = THREE_JS.fresnel(V3::splat(0.04_f32), 1.0, 1.0).x;
    let expected = 0.04 + 0.96 * 2f32.powf(-5.55473 - 6.98316);
    assert!((f_sg - expected).abs() < 1e-7, "{f_sg} vs {expected}");
    assert_eq!(FILAMENT.fresnel(V3::splat(0.04_f32), 1.0, 1.0).x, 0.04);
    // Diffuse: bevy's Burley darkens a smooth surface at grazing angles, Lambert does not;
    // the glTF viewer removes F_dielectric from the diffuse, the additive engines do not.
    let lambert = FILAMENT.diffuse(grazing, 0.2, base).x;
    let burley = BEVY.diffuse(grazing, 0.2, base).x;
    assert!(burley < lambert, "{burley} vs {lambert}");
    let gltf = KHRONOS_SAMPLE_VIEWER.brdf(grazing, base, 0.0, 0.5).x
        - KHRONOS_SAMPLE_VIEWER
            .specular(grazing, 0.5, V3::splat(0.04), 1.0)
            .x;
    assert!(
        gltf.abs() < 1e-6,
        "at v.h = 0 F_dielectric = 1 leaves no diffuse: {gltf}"
    );
    // Unreal and the glTF viewer have no floor: the crate's ALPHA_MIN applies.
    assert_eq!(UNREAL_4.alpha(0.0_f32), brdf::microfacet::ALPHA_MIN as f32);
    let _ = grazing;
}

#[cfg(feature = "material")]
#[test]
fn the_gltf_viewer_convention_is_the_crates_gltf_material() {
    for p in grid().into_iter().step_by(7) {
        if p.r < 0.01 {
            continue;
        }
        let c = cos(&p, f64::from);
        let a = KHRONOS_SAMPLE_VIEWER.brdf(c, v3d(p.base), f64::from(p.m), f64::from(p.r));
        let b = brdf::material::gltf(c, v3d(p.base), f64::from(p.m), f64::from(p.r));
        for (x, y) in a.to_array().into_iter().zip(b.to_array()) {
            assert!(
                (x - y).abs() <= 1e-12 * y.abs().max(1e-300),
                "{p:?}: {x} vs {y}"
            );
        }
    }
}

#[test]
fn lanes_equal_scalars() {
    let pts: Vec<P> = grid().into_iter().step_by(3).collect();
    println!("{:<28} {:>12}", "engine", "lane max ulp");
    for e in ALL {
        let mut worst = 0.0_f64;
        for chunk in pts.chunks_exact(8) {
            let lane = |f: fn(&P) -> f32| f32x8::new(core::array::from_fn(|i| f(&chunk[i])));
            let c = Cosines {
                n_dot_v: lane(|p| p.nv),
                n_dot_l: lane(|p| p.nl),
                n_dot_h: lane(|p| p.nh),
                v_dot_h: lane(|p| p.vh),
            };
            let base = V3::new(
                lane(|p| p.base[0]),
                lane(|p| p.base[1]),
                lane(|p| p.base[2]),
            );
            let out = e.brdf(c, base, lane(|p| p.m), lane(|p| p.r));
            let (x, y, z) = (out.x.to_array(), out.y.to_array(), out.z.to_array());
            for (i, p) in chunk.iter().enumerate() {
                let s = e.brdf(cos(p, |v| v), v3f(p.base), p.m, p.r).to_array();
                worst = worst.max(ulps33([x[i], y[i], z[i]], s));
            }
        }
        println!("{:<28} {worst:>12.2}", e.name);
        // Arithmetic-only kernels run the same operations on lanes; the exp2 of the
        // spherical-Gaussian Fresnel is the lanes' polynomial, within 3 ULP of libm's
        // (crate docs), which a product of a few terms carries to the result.
        let bound = if e.fresnel == engine::FresnelForm::SchlickSphericalGaussian {
            4.0
        } else {
            0.0
        };
        assert!(
            worst <= bound,
            "{}: lanes differ from scalars by {worst} ULP",
            e.name
        );
    }
}

#[test]
fn bad_input_gives_nan_and_the_horizon_gives_zero() {
    let c = Cosines {
        n_dot_v: 0.5_f32,
        n_dot_l: 0.5,
        n_dot_h: 0.9,
        v_dot_h: 0.7,
    };
    let base = V3::splat(0.5_f32);
    for e in ALL {
        assert!(e.brdf(c, base, 0.5, 1.1).x.is_nan(), "{}", e.name);
        assert!(e.brdf(c, base, -0.1, 0.5).x.is_nan(), "{}", e.name);
        assert!(
            e.brdf(c, V3::new(0.5, 2.0, 0.5), 0.5, 0.5).y.is_nan(),
            "{}",
            e.name
        );
        assert!(
            e.brdf(
                Cosines {
                    n_dot_h: f32::NAN,
                    ..c
                },
                base,
                0.5,
                0.5
            )
            .x
            .is_nan(),
            "{}",
            e.name
        );
        assert!(e.alpha(f32::NAN).is_nan() && e.alpha(-0.5_f32).is_nan());
        assert!(e.fresnel(base, 1.5, 0.5).x.is_nan() && e.fresnel(base, 1.0, f32::NAN).x.is_nan());
        assert_eq!(
            e.brdf(Cosines { n_dot_l: 0.0, ..c }, base, 0.5, 0.5).x,
            0.0,
            "{}",
            e.name
        );
        assert_eq!(
            e.brdf(Cosines { n_dot_v: -0.2, ..c }, base, 0.5, 0.5).x,
            0.0,
            "{}",
            e.name
        );
        // Subnormal cosines, roughness 0: finite.
        let t = Cosines {
            n_dot_v: 1e-40_f32,
            n_dot_l: 1e-40,
            n_dot_h: 1.0,
            v_dot_h: 1.0,
        };
        assert!(
            e.brdf(t, V3::splat(1.0), 1.0, 0.0).x.is_finite(),
            "{}",
            e.name
        );
    }
}
