//! Energy: directional albedo over (roughness, theta_o) for each model, by the public
//! integrator, as tables (in the Markdown) and heat maps.

use brdf::beckmann::Beckmann;
use brdf::cook_torrance;
use brdf::diffuse::Eon;
use brdf::ggx::Ggx;
use brdf::ibl::energy;
use brdf::integrate::directional_albedo;
use brdf::material::MetallicRoughness;
use brdf::{ParamError, V3};

/// One model's albedo grid.
pub struct Grid {
    /// The model, as the heat map's title names it.
    pub model: String,
    /// What the roughness axis is (alpha, perceptual r, sigma).
    pub roughness_label: &'static str,
    /// Roughness values (rows).
    pub roughness: Vec<f64>,
    /// theta_o in degrees (columns).
    pub theta: Vec<f64>,
    /// albedo[row][column].
    pub albedo: Vec<Vec<f64>>,
    /// File name stem.
    pub stem: &'static str,
}

fn wo(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin(), 0.0, t.cos())
}

fn grid(
    model: &str,
    stem: &'static str,
    roughness_label: &'static str,
    roughness: &[f64],
    theta: &[f64],
    f: impl Fn(f64, V3<f64>, V3<f64>) -> Result<f64, ParamError>,
) -> Result<Grid, ParamError> {
    let mut albedo = Vec::new();
    for &r in roughness {
        let mut row = Vec::new();
        for &t in theta {
            // Validate the parameters once outside the integrand.
            f(r, V3::unit_z(), V3::unit_z())?;
            let a = directional_albedo(wo(t), |o, i| f(r, o, i).unwrap_or(f64::NAN)).value;
            row.push(a);
        }
        albedo.push(row);
    }
    Ok(Grid {
        model: model.to_string(),
        roughness_label,
        roughness: roughness.to_vec(),
        theta: theta.to_vec(),
        albedo,
        stem,
    })
}

/// The albedo grids of five models: GGX and Beckmann Cook-Torrance with F = 1 (the
/// single-scattering loss), GGX with Kulla-Conty's compensation lobe, the glTF material as a
/// white dielectric, and EON with rho = 1.
pub fn grids(quick: bool) -> Result<Vec<Grid>, ParamError> {
    let (alphas, thetas): (Vec<f64>, Vec<f64>) = if quick {
        (vec![0.05, 0.5, 1.0], vec![0.0, 60.0, 85.0])
    } else {
        (
            vec![0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0],
            vec![0.0, 20.0, 40.0, 60.0, 70.0, 80.0, 85.0, 89.0],
        )
    };
    Ok(vec![
        grid(
            "GGX Cook-Torrance, F = 1",
            "albedo_ggx",
            "alpha",
            &alphas,
            &thetas,
            |a, o, i| {
                let g = Ggx::new(a, a)?;
                Ok(cook_torrance::eval(&g, o, i, |_| 1.0))
            },
        )?,
        grid(
            "Beckmann Cook-Torrance, F = 1",
            "albedo_beckmann",
            "alpha",
            &alphas,
            &thetas,
            |a, o, i| {
                let b = Beckmann::new(a, a)?;
                Ok(cook_torrance::eval(&b, o, i, |_| 1.0))
            },
        )?,
        grid(
            "GGX, F = 1, with Kulla-Conty compensation",
            "albedo_ggx_kulla_conty",
            "alpha",
            &alphas,
            &thetas,
            |a, o, i| {
                let g = Ggx::new(a, a)?;
                Ok(cook_torrance::eval(&g, o, i, |_| 1.0)
                    + energy::kulla_conty_ggx(o.z, i.z, a, 1.0))
            },
        )?,
        grid(
            "glTF material, white dielectric (base 1, metallic 0)",
            "albedo_gltf_dielectric",
            "perceptual roughness r (alpha = r^2)",
            &alphas,
            &thetas,
            |r, o, i| {
                let m = MetallicRoughness::new(V3::splat(1.0), 0.0, r)?;
                Ok(m.eval(o, i).y)
            },
        )?,
        grid(
            "EON diffuse, rho = 1",
            "albedo_eon",
            "sigma",
            &alphas,
            &thetas,
            |s, o, i| {
                let e = Eon::new(1.0, s)?;
                Ok(e.eval(o, i))
            },
        )?,
    ])
}
