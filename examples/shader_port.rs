//! Porting an engine's GGX specular to this crate, and checking the port.
//!
//! The one trap is the roughness argument. Three quantities go by that name:
//!
//! | quantity | what it is | called |
//! |---|---|---|
//! | perceptual roughness r | the artist's slider, in [0, 1] | glTF `roughnessFactor`, UE4 material `Roughness`, Filament `perceptualRoughness` |
//! | alpha = r^2 | the GGX width (Walter et al. 2007's alpha_g) | this crate's `alpha`; Filament's shader argument `roughness` |
//! | alpha^2 = r^4 | what the NDF's formula squares | UE4's `a2` (`BRDF.ush`: `a2 = Pow4(Roughness)`) |
//!
//! Every crate function taking `alpha` wants the middle row; convert a slider value with
//! `brdf::microfacet::alpha_from_perceptual` (r^2, clamped to [`ALPHA_MIN`, `ALPHA_MAX`]).
//!
//! The engine formulas, as functions of those quantities (re-expressed here, evaluated by the
//! `*_port` functions below in the engines' own operation order, on `f32` or `f64`):
//!
//! - Filament, `D_GGX(roughness = alpha, NoH)` ("Physically Based Rendering in Filament",
//!   section 4.4.1; shader `surface_brdf.fs`): k = alpha / ((1 - NoH^2) + (NoH alpha)^2),
//!   D = k^2 / pi. (The design document lists the arguments as `(NoH, roughness)`, the shader
//!   as `(roughness, NoH, h)`: the order differs, the meaning, alpha, does not.)
//! - Filament, `V_SmithGGXCorrelated(roughness = alpha, NoV, NoL)` (section 4.4.2): with
//!   a2 = alpha^2, V = 0.5 / (NoL sqrt(NoV^2 (1 - a2) + a2) + NoV sqrt(NoL^2 (1 - a2) + a2)).
//! - Unreal Engine 4, `D_GGX(a2 = alpha^2, NoH)` (`BRDF.ush`): d = (NoH a2 - NoH) NoH + 1,
//!   D = a2 / (pi d^2). Older UE4 releases took the perceptual `Roughness` itself and squared
//!   it twice inside.
//! - Unreal Engine 4, `Vis_SmithJoint(a2 = alpha^2, NoV, NoL)`: the same V as Filament's.
//!
//! Crate equivalents: `brdf::ggx::d(n_dot_h, alpha)` and
//! `brdf::ggx::v_correlated(n_dot_v, n_dot_l, alpha)`, cosines first, alpha last.
//!
//! This program checks, at a grid of points, that the ports in `f64` agree with the crate (D to
//! 1e-10 relative: the engine forms' 1 - NoH^2 and (a2 - 1) + 1 cancel near the peak, an error
//! up to eps / alpha^2 = 2.7e-11 at alpha = 0.002; V to 1e-14, a few rounding errors), and that
//! the crate's `f32` is within 4 ULP of its `f64` there. It prints how far the engine forms
//! drift in `f32`, and the factors a mixed-up convention costs. It exits non-zero on a failed
//! check.
//!
//! `cargo run --release --example shader_port`
use brdf::Real;
use brdf::ggx;
use brdf::microfacet::alpha_from_perceptual;
use std::process::ExitCode;

/// Filament's `D_GGX`, argument `roughness` = alpha.
fn filament_d_ggx_port<T: Real>(roughness: T, n_dot_h: T) -> T {
    let one_minus_noh2 = T::ONE - n_dot_h * n_dot_h;
    let a = n_dot_h * roughness;
    let k = roughness / (one_minus_noh2 + a * a);
    k * k * T::FRAC_1_PI
}

/// Filament's `V_SmithGGXCorrelated`, argument `roughness` = alpha.
fn filament_v_smith_ggx_correlated_port<T: Real>(roughness: T, n_dot_v: T, n_dot_l: T) -> T {
    let a2 = roughness * roughness;
    let lambda_v = n_dot_l * ((n_dot_v - a2 * n_dot_v) * n_dot_v + a2).sqrt();
    let lambda_l = n_dot_v * ((n_dot_l - a2 * n_dot_l) * n_dot_l + a2).sqrt();
    T::HALF / (lambda_v + lambda_l)
}

/// Unreal Engine 4's `D_GGX`, argument `a2` = alpha^2.
fn ue4_d_ggx_port<T: Real>(a2: T, n_dot_h: T) -> T {
    let d = (n_dot_h * a2 - n_dot_h) * n_dot_h + T::ONE;
    a2 / (T::PI * d * d)
}

/// Unreal Engine 4's `Vis_SmithJoint`, argument `a2` = alpha^2.
fn ue4_vis_smith_joint_port<T: Real>(a2: T, n_dot_v: T, n_dot_l: T) -> T {
    let smith_v = n_dot_l * ((n_dot_v - n_dot_v * a2) * n_dot_v + a2).sqrt();
    let smith_l = n_dot_v * ((n_dot_l - n_dot_l * a2) * n_dot_l + a2).sqrt();
    T::HALF / (smith_v + smith_l)
}

/// |a - b| / |b|.
fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Largest relative error seen, and where.
#[derive(Default)]
struct Worst {
    err: f64,
    at: String,
}

impl Worst {
    fn see(&mut self, err: f64, at: impl FnOnce() -> String) {
        if err > self.err || err.is_nan() {
            (self.err, self.at) = (err, at());
        }
    }
}

/// Prints one check; true if `worst` is within `bound` (NaN never is).
fn report(what: &str, worst: &Worst, bound: f64) -> bool {
    let ok = worst.err <= bound;
    let verdict = if ok { "ok" } else { "FAIL" };
    println!(
        "{what:<52} max {:.1e} <= {bound:.0e}  {verdict}  (worst at {})",
        worst.err, worst.at
    );
    ok
}

fn main() -> ExitCode {
    // Perceptual roughness from Filament's desktop floor (0.045, see below) to 1; cosines from
    // the highlight's peak to grazing.
    let perceptual = [0.045, 0.1, 0.25, 0.5, 0.75, 1.0];
    let n_dot_h = [1.0, 0.9999, 0.999, 0.99, 0.9, 0.7, 0.4, 0.1];
    let cosines = [1.0, 0.8, 0.5, 0.2, 0.05, 0.01];
    // One ULP of an f32 result is at most 2^-23 of it.
    let f32_ulp = f32::EPSILON as f64;

    let (mut d_fil, mut d_ue4, mut d_crate32, mut d_fil32) = Default::default();
    let (mut v_fil, mut v_ue4, mut v_crate32, mut v_fil32) = Default::default();
    for &r in &perceptual {
        // The conversion every port needs: slider value -> alpha (-> alpha^2 for UE4).
        let alpha: f64 = alpha_from_perceptual(r);
        let alpha32: f32 = alpha_from_perceptual(r as f32);
        for &c in &n_dot_h {
            let at = || format!("r {r}, NoH {c}");
            let want = ggx::d(c, alpha);
            Worst::see(&mut d_fil, rel(filament_d_ggx_port(alpha, c), want), at);
            Worst::see(&mut d_ue4, rel(ue4_d_ggx_port(alpha * alpha, c), want), at);
            // f32 against f64 at the same f32 inputs: the figures measure arithmetic only.
            let c32 = c as f32;
            let want32 = ggx::d(c32 as f64, alpha32 as f64);
            Worst::see(&mut d_crate32, rel(ggx::d(c32, alpha32) as f64, want32), at);
            let port32 = filament_d_ggx_port(alpha32, c32) as f64;
            Worst::see(&mut d_fil32, rel(port32, want32), at);
        }
        for &nv in &cosines {
            for &nl in &cosines {
                let at = || format!("r {r}, NoV {nv}, NoL {nl}");
                let want = ggx::v_correlated(nv, nl, alpha);
                let fil = filament_v_smith_ggx_correlated_port(alpha, nv, nl);
                Worst::see(&mut v_fil, rel(fil, want), at);
                let ue4 = ue4_vis_smith_joint_port(alpha * alpha, nv, nl);
                Worst::see(&mut v_ue4, rel(ue4, want), at);
                let (v32, l32) = (nv as f32, nl as f32);
                let want32 = ggx::v_correlated(v32 as f64, l32 as f64, alpha32 as f64);
                let crate32 = ggx::v_correlated(v32, l32, alpha32) as f64;
                Worst::see(&mut v_crate32, rel(crate32, want32), at);
                let fil32 = filament_v_smith_ggx_correlated_port(alpha32, v32, l32) as f64;
                Worst::see(&mut v_fil32, rel(fil32, want32), at);
            }
        }
    }

    let mut ok = true;
    println!("Ports against the crate (relative error):");
    ok &= report("Filament D_GGX(alpha, NoH), f64 = ggx::d", &d_fil, 1e-10);
    ok &= report("UE4 D_GGX(alpha^2, NoH), f64 = ggx::d", &d_ue4, 1e-10);
    ok &= report(
        "Filament V_SmithGGXCorrelated(alpha, ..), f64",
        &v_fil,
        1e-14,
    );
    ok &= report("UE4 Vis_SmithJoint(alpha^2, ..), f64", &v_ue4, 1e-14);
    let four_ulp = 4.0 * f32_ulp;
    ok &= report(
        "crate ggx::d, f32 against f64 (4 ULP)",
        &d_crate32,
        four_ulp,
    );
    ok &= report(
        "crate ggx::v_correlated, f32 vs f64 (4 ULP)",
        &v_crate32,
        four_ulp,
    );
    println!("Engine forms in f32 (informative: shaders run in f32 or f16):");
    println!(
        "  Filament D_GGX in f32: max rel error {:.1e} at {} (1 - NoH^2 cancels near NoH = 1)",
        d_fil32.err, d_fil32.at
    );
    println!(
        "  Filament V_SmithGGXCorrelated in f32: max rel error {:.1e} at {}",
        v_fil32.err, v_fil32.at
    );

    // What a mixed-up convention costs at the highlight's peak, where D = 1 / (pi alpha^2).
    let r = 0.3;
    let alpha = alpha_from_perceptual(r);
    let right = ggx::d(1.0, alpha);
    println!("Mixed-up conventions at perceptual roughness {r} (alpha {alpha:.2}), NoH = 1:");
    let mixups = [
        (
            "r where alpha is expected (ggx::d, Filament)",
            ggx::d(1.0, r),
            r * r,
        ),
        (
            "alpha where UE4's a2 is expected",
            ue4_d_ggx_port(alpha, 1.0),
            alpha,
        ),
        (
            "UE4's a2 where alpha is expected",
            ggx::d(1.0, alpha * alpha),
            1.0 / (alpha * alpha),
        ),
    ];
    for (what, wrong, factor) in mixups {
        println!(
            "  {what:<46} D x {:.4} (expected x {factor:.4})",
            wrong / right
        );
        ok &= rel(wrong / right, factor) < 1e-12;
    }

    // Filament clamps perceptual roughness to 0.045 on desktop (alpha 0.002025) and to 0.089 on
    // mobile (alpha 0.007921, so that r^4 stays above f16's smallest normal); the crate clamps
    // alpha at ALPHA_MIN = 1e-4 (r = 0.01). To reproduce Filament below its floor, clamp r first.
    let r = 0.02;
    let filament = filament_d_ggx_port(alpha_from_perceptual(0.045f64), 1.0);
    let crate_unclamped = ggx::d(1.0, alpha_from_perceptual(r));
    let crate_clamped = ggx::d(1.0, alpha_from_perceptual(f64::max(r, 0.045)));
    println!("Below Filament's floor, r = {r}: peak D");
    println!("  crate {crate_unclamped:.4e}, Filament {filament:.4e}");
    println!("  crate after r = max(r, 0.045): {crate_clamped:.4e} (want Filament's)");
    ok &= rel(crate_clamped, filament) < 1e-12;

    if ok {
        println!("shader_port: every port agrees with the crate");
        ExitCode::SUCCESS
    } else {
        println!("shader_port: FAILED (see the FAIL lines)");
        ExitCode::FAILURE
    }
}
