//! The report's diffuse, Phong, material and light sections: directional albedo tables by the
//! public integrator, the Phong comparison (reciprocity, energy, peaks) and the
//! metallic-roughness white furnace.

use brdf::diffuse::{
    Burley, BurleyRenormalized, Eon, Lambert, OrenNayar, OrenNayarFujii, OrenNayarFull,
};
use brdf::integrate::{self, directional_albedo};
use brdf::lights;
use brdf::material::MetallicRoughness;
use brdf::phong::{self, ClassicPhong, ModifiedPhong, NormalizedBlinnPhong, NormalizedPhong};
use brdf::{ParamError, V3};

const THETAS: [f64; 7] = [0.0, 30.0, 60.0, 75.0, 85.0, 89.0, 89.9];

fn wo_at(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin(), 0.0, t.cos())
}

fn header(first: &str) {
    out!("| {first} |");
    for t in THETAS {
        out!(" {t} |");
    }
    outln!();
    outln!("|---|{}", "---|".repeat(THETAS.len()));
}

/// One table row: the albedo of `f` at each theta_o; returns the row's maximum.
fn albedo_row(name: &str, f: impl Fn(V3<f64>, V3<f64>) -> f64) -> f64 {
    out!("| {name} |");
    let mut max: f64 = 0.0;
    for t in THETAS {
        let a = directional_albedo(wo_at(t), &f).value;
        out!(" {a:.4} |");
        max = max.max(a);
    }
    outln!();
    max
}

/// Directional albedo of every diffuse lobe with rho = 1.
pub fn diffuse_albedo() -> Result<(), ParamError> {
    outln!("\n## Diffuse lobes: directional albedo with rho = 1 (a white furnace; 1 is ideal)\n");
    header("lobe \\ theta_o");
    let lambert = Lambert::new(1.0)?;
    albedo_row("Lambert", |o, i| lambert.eval(o, i));
    for sigma in [0.25, 0.5, 1.0] {
        let on = OrenNayar::new(1.0, sigma)?;
        albedo_row(&format!("Oren-Nayar qualitative, sigma {sigma}"), |o, i| {
            on.eval(o, i)
        });
        let full = OrenNayarFull::new(1.0, sigma)?;
        albedo_row(&format!("Oren-Nayar full, sigma {sigma}"), |o, i| {
            full.eval(o, i)
        });
    }
    for sigma in [0.5, 1.0] {
        let fujii = OrenNayarFujii::new(1.0, sigma)?;
        albedo_row(&format!("Fujii, sigma {sigma}"), |o, i| fujii.eval(o, i));
        let eon = Eon::new(1.0, sigma)?;
        albedo_row(&format!("EON, sigma {sigma}"), |o, i| eon.eval(o, i));
    }
    for r in [0.5, 1.0] {
        let b = Burley::new(1.0, r)?;
        albedo_row(&format!("Burley, roughness {r}"), |o, i| b.eval(o, i));
        let b = BurleyRenormalized::new(1.0, r)?;
        albedo_row(&format!("Burley renormalized, roughness {r}"), |o, i| {
            b.eval(o, i)
        });
    }
    outln!(
        "\nOren-Nayar (both published forms) and Burley's diffuse are fits, not energy-conserving \
         models: their albedo leaves 1 in both directions. EON adds the multiple-scattering lobe \
         that brings Fujii's form back to 1. Full tables: `cargo test --test diffuse -- \
         --nocapture oren_nayar_energy:: eon_energy:: burley_energy::`."
    );
    Ok(())
}

/// A lobe of the Phong family with its exponent bound, as a closure over local directions.
type Lobe = Box<dyn Fn(V3<f64>, V3<f64>) -> f64>;

/// One row of the Phong table: reciprocity at n = 16 and the largest albedo over a grid of
/// exponents and view angles.
fn phong_row(name: &str, make: impl Fn(f64) -> Result<Lobe, ParamError>) -> Result<(), ParamError> {
    let lobe = make(16.0)?;
    let rec = integrate::reciprocity(&lobe);
    let (mut max, mut at) = (0.0_f64, (0.0, 0.0));
    for n in [0.5, 2.0, 8.0, 64.0, 1e3, 1e4] {
        let lobe = make(n)?;
        for t in THETAS {
            let a = directional_albedo(wo_at(t), &lobe).value;
            if a > max {
                (max, at) = (a, (n, t));
            }
        }
    }
    outln!(
        "| {name} | {:.3e} | {max:.4} (n = {}, theta_o = {} deg) |",
        rec.max_rel,
        at.0,
        at.1
    );
    Ok(())
}

/// The Phong comparison: the classic form against the reciprocal and normalized ones.
pub fn phong_comparison() -> Result<(), ParamError> {
    outln!("\n## Phong family: reciprocity, energy and peaks (ks = 1)\n");
    outln!(
        "| model | reciprocity max rel | max albedo over n in {{0.5, 2, 8, 64, 1e3, 1e4}} and theta_o |"
    );
    outln!("|---|---|---|");
    phong_row("classic ks (r.l)^n / (n.l)", |n| {
        let l = ClassicPhong::new(1.0, n)?;
        Ok(Box::new(move |o, i| l.eval(o, i)))
    })?;
    phong_row("modified ks (r.l)^n", |n| {
        let l = ModifiedPhong::new(1.0, n)?;
        Ok(Box::new(move |o, i| l.eval(o, i)))
    })?;
    phong_row("normalized ks (n + 2) / (2 pi) (r.l)^n", |n| {
        let l = NormalizedPhong::new(1.0, n)?;
        Ok(Box::new(move |o, i| l.eval(o, i)))
    })?;
    phong_row("Blinn-Phong, exact normalization", |n| {
        let l = NormalizedBlinnPhong::new(1.0, n)?;
        Ok(Box::new(move |o, i| l.eval(o, i)))
    })?;

    outln!(
        "\nPeak (mirror direction) of normalized Phong against classic Phong at normal incidence:\n"
    );
    outln!("| n | classic peak | normalized peak | normalized / classic |");
    outln!("|---|---|---|---|");
    for n in [1.0, 2.0, 4.0, 16.0, 64.0, 1e3] {
        let classic = phong::classic(1.0, 1.0, 1.0, 1.0, n);
        let normalized = phong::normalized(1.0, 1.0, 1.0, 1.0, n);
        outln!(
            "| {n} | {classic:.4} | {normalized:.4} | {:.4} |",
            normalized / classic
        );
    }
    outln!(
        "\nA wide normalized lobe (n < 2 pi - 2) is dimmer at its peak than classic Phong and a \
         tight one brighter, because the normalized lobe keeps its integral fixed while the \
         classic one loses energy as it narrows."
    );
    let mut worst = (0.0_f64, 0.0);
    for i in 0..=40_000 {
        let n = i as f64 * 0.25;
        let exact = phong::blinn_phong_normalization_exact(n);
        let rel = (phong::blinn_phong_normalization_approx(n) - exact).abs() / exact;
        if rel > worst.0 {
            worst = (rel, n);
        }
    }
    outln!(
        "\nBlinn-Phong normalization (n + 8) / (8 pi) against the exact one over n in [0, 1e4]: \
         max relative error {:.4} at n = {}.",
        worst.0,
        worst.1
    );
    Ok(())
}

/// White furnace of the metallic-roughness material: a metal with F0 = 1 and a white
/// dielectric, per channel (they are grey, so the green channel stands for all three).
pub fn material_furnace() -> Result<(), ParamError> {
    outln!("\n## Metallic-roughness material: directional albedo (green channel; 1 is ideal)\n");
    header("material \\ theta_o");
    for (name, metallic) in [
        ("metal, base colour 1", 1.0),
        ("dielectric, base colour 1", 0.0),
    ] {
        for r in [0.0, 0.25, 0.5, 1.0] {
            let m = MetallicRoughness::new(V3::splat(1.0), metallic, r)?;
            albedo_row(&format!("{name}, roughness {r}"), |o, i| m.eval(o, i).y);
        }
    }
    outln!(
        "\nThe rough metal loses what single-scattering GGX loses (the energy-loss table above). \
         The glTF dielectric, whose diffuse layer is weighted by 1 - F(v.h), is not energy \
         conserving at grazing view: its specular layer reflects F(theta_o) while the diffuse \
         layer keeps most of its albedo, as the glTF specification notes for its fresnel_mix. \
         Full tables and the other couplings: `cargo test --test material energy:: -- --nocapture`."
    );
    Ok(())
}

/// The punctual-light falloffs at a few distances.
pub fn light_falloffs() {
    outln!("\n## Punctual lights: distance falloff (radius 4, minimum distance 0.01)\n");
    outln!(
        "| d | 1 / d^2 | windowed (UE4) | windowed 1 / d^2 (Frostbite) | 1 / (1 + 0.1 d + 0.01 d^2) |"
    );
    outln!("|---|---|---|---|---|");
    for d in [0.0, 0.5, 1.0, 2.0, 3.0, 3.9, 4.0, f64::INFINITY] {
        outln!(
            "| {d} | {:.4} | {:.4} | {:.4} | {:.4} |",
            lights::inverse_square(d, 0.01),
            lights::windowed(d, 4.0),
            lights::windowed_inverse_square(d, 4.0, 0.01),
            lights::polynomial(d, 1.0, 0.1, 0.01),
        );
    }
}
