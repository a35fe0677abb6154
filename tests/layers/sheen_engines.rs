//! The sheen lobe against independent f32 transcriptions of two engines' shader code:
//!
//! - the Khronos glTF Sample Viewer, `source/Renderer/shaders/brdf.glsl` at commit
//!   d0b428c8946052cb640c4cf772686eb6c3abf3c2 (`D_Charlie`, `lambdaSheenNumericHelper`,
//!   `lambdaSheen`, `V_Sheen`);
//! - three.js, `src/renderers/shaders/ShaderChunk/bsdfs.glsl.js` at commit
//!   12f550e0f44f68e5b6c946dd242ee08e42d209e4 (`D_Charlie`, `V_Neubelt`; later releases
//!   moved both, unchanged, into `lights_physical_pars_fragment.glsl.js`).
//!
//! Differences, each excluded from the comparison with its reason: the sample viewer clamps
//! V to [0, 1] and three.js saturates V_neubelt (the crate does not: compared where the
//! engine's V is below 1, that is away from grazing pairs); three.js floors sin^2(theta_h) at
//! 2^-7 for fp16 (compared where sin^2 is above it).
#![cfg(feature = "sheen")]

use brdf::layers::sheen::{d_charlie, v_charlie, v_neubelt};

fn mix(x: f32, y: f32, a: f32) -> f32 {
    x * (1.0 - a) + y * a
}

mod viewer {
    use super::mix;
    const M_PI: f32 = core::f32::consts::PI;

    pub fn lambda_helper(x: f32, alpha_g: f32) -> f32 {
        let t = (1.0 - alpha_g) * (1.0 - alpha_g);
        let a = mix(21.5473, 25.3245, t);
        let b = mix(3.82987, 3.32435, t);
        let c = mix(0.19823, 0.16801, t);
        let d = mix(-1.97760, -1.27393, t);
        let e = mix(-4.32054, -4.85967, t);
        a / (1.0 + b * x.powf(c)) + d * x + e
    }

    pub fn lambda_sheen(cos_theta: f32, alpha_g: f32) -> f32 {
        if cos_theta.abs() < 0.5 {
            lambda_helper(cos_theta, alpha_g).exp()
        } else {
            (2.0 * lambda_helper(0.5, alpha_g) - lambda_helper(1.0 - cos_theta, alpha_g)).exp()
        }
    }

    /// V_Sheen without its final clamp (returned separately).
    pub fn v_sheen_unclamped(n_dot_l: f32, n_dot_v: f32, sheen_roughness: f32) -> f32 {
        let r = sheen_roughness.max(0.000001);
        let alpha_g = r * r;
        1.0 / ((1.0 + lambda_sheen(n_dot_v, alpha_g) + lambda_sheen(n_dot_l, alpha_g))
            * (4.0 * n_dot_v * n_dot_l))
    }

    pub fn d_charlie(sheen_roughness: f32, n_dot_h: f32) -> f32 {
        let r = sheen_roughness.max(0.000001);
        let alpha_g = r * r;
        let inv_r = 1.0 / alpha_g;
        let cos2h = n_dot_h * n_dot_h;
        let sin2h = 1.0 - cos2h;
        (2.0 + inv_r) * sin2h.powf(inv_r * 0.5) / (2.0 * M_PI)
    }
}

mod threejs {
    const PI: f32 = core::f32::consts::PI;
    pub fn d_charlie(roughness: f32, dot_nh: f32) -> f32 {
        let alpha = roughness * roughness;
        let inv_alpha = 1.0 / alpha;
        let cos2h = dot_nh * dot_nh;
        let sin2h = (1.0 - cos2h).max(0.0078125);
        (2.0 + inv_alpha) * sin2h.powf(inv_alpha * 0.5) / (2.0 * PI)
    }
    pub fn v_neubelt(dot_nv: f32, dot_nl: f32) -> f32 {
        (1.0 / (4.0 * (dot_nl + dot_nv - dot_nl * dot_nv))).clamp(0.0, 1.0)
    }
}

const ROUGH: [f32; 6] = [0.1, 0.3, 0.5, 0.7, 0.9, 1.0];

fn cosines() -> impl Iterator<Item = f32> {
    (1..=40).map(|i| i as f32 / 40.0)
}

fn rel(a: f32, b: f32) -> f64 {
    let (a, b) = (f64::from(a), f64::from(b));
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

#[test]
fn sample_viewer_charlie_d_and_v_agree_to_f32_rounding() {
    let (mut wd, mut wv, mut compared) = (0.0f64, 0.0f64, 0usize);
    for r in ROUGH {
        let alpha = r * r;
        for c in cosines() {
            // D: the viewer's 1 - cos^2 cancels near n.h = 1 where the crate's
            // (1 - c)(1 + c) does not; up to n.h = 0.95 both are accurate.
            if c <= 0.95 && viewer::d_charlie(r, c) > 1e-30 {
                wd = wd.max(rel(d_charlie(c, alpha), viewer::d_charlie(r, c)));
            }
            for l in cosines() {
                let theirs = viewer::v_sheen_unclamped(l, c, r);
                if theirs < 1.0 {
                    compared += 1;
                    wv = wv.max(rel(v_charlie(c, l, alpha), theirs));
                }
            }
        }
    }
    println!("sample viewer: D max rel {wd:.2e}, V max rel {wv:.2e} over {compared} (V < 1) pairs");
    // pow with exponents up to 50 (alpha = 0.01) amplifies one rounding of sin^2 fiftyfold:
    // 1e-4 covers it; V is exp of a sum of terms near 20, each rounded: 5e-5.
    assert!(wd < 1e-4, "D: {wd}");
    assert!(wv < 5e-5, "V: {wv}");
    assert!(compared > 4000);
}

#[test]
fn threejs_charlie_d_and_neubelt_v_agree_to_f32_rounding() {
    let (mut wd, mut wv) = (0.0f64, 0.0f64);
    for r in ROUGH {
        let alpha = r * r;
        for c in cosines() {
            if 1.0 - c * c > 0.0078125 && c <= 0.95 && threejs::d_charlie(r, c) > 1e-30 {
                wd = wd.max(rel(d_charlie(c, alpha), threejs::d_charlie(r, c)));
            }
            for l in cosines() {
                // three.js saturates V: compared where its V is below 1.
                let theirs = threejs::v_neubelt(c, l);
                if theirs < 1.0 {
                    wv = wv.max(rel(v_neubelt(c, l), theirs));
                }
            }
        }
    }
    println!("three.js: D max rel {wd:.2e}, V_neubelt max rel {wv:.2e}");
    assert!(wd < 1e-4, "D: {wd}");
    // Three roundings of the denominator, one of the quotient: within 4 epsilon.
    assert!(wv < 4.0 * f64::from(f32::EPSILON), "V: {wv}");
}
