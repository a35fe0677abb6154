//! Light through and between surfaces: the rough dielectric's white furnace beside the
//! conductor's, and the thin film's colour over its thickness.

use brdf::V3;
use brdf::ggx::Ggx;
use brdf::integrate::{directional_albedo, directional_albedo_sphere};
use brdf::iridescence::{self, ThinFilm, XYZ_TO_REC709};
use brdf::rough_dielectric::{self as rd, Transport};

/// The direction at `deg` degrees from +z (inside the surface above 90).
fn dir(deg: f64) -> V3<f64> {
    let t = deg.to_radians();
    V3::new(t.sin(), 0.0, t.cos())
}

/// The smooth interface's refracted direction of `wo` (eta = inside / outside), if any: the
/// transmission lobe's peak, for the integrator.
fn refracted(wo: V3<f64>, eta: f64) -> Option<V3<f64>> {
    let (n, e) = if wo.z >= 0.0 {
        (1.0, eta)
    } else {
        (-1.0, 1.0 / eta)
    };
    let c = wo.z.abs();
    let s2 = (1.0 - c * c) / (e * e);
    (s2 < 1.0).then(|| {
        let w = V3::new(0.0, 0.0, n) * (c / e - (1.0 - s2).sqrt()) - wo * (1.0 / e);
        w * (1.0 / w.length())
    })
}

/// Single-scattering loss 1 - E of the GGX rough dielectric (glass, eta 1.5, importance
/// transport: the fraction of the light arriving along wo that is scattered, over the whole
/// sphere) from outside and inside, beside the GGX conductor's (F = 1).
pub fn dielectric_energy_section(quick: bool) {
    outln!("\n## Rough dielectric: white furnace over the sphere (Walter et al. 2007)\n");
    outln!(
        "Single-scattering loss 1 - E of `rough_dielectric::eval` (GGX, eta = 1.5, importance \
         transport, reflection plus transmission integrated over the whole sphere by \
         `integrate::directional_albedo_sphere`) from outside (theta_o from +z) and inside \
         (from -z), beside the GGX conductor's (`cook_torrance::eval` with F = 1, the upper \
         hemisphere). 0 is lossless; the loss is the light that the model's single scattering \
         drops between facets.\n"
    );
    let thetas = [0.0, 60.0, 80.0];
    out!("| alpha |");
    for t in thetas {
        out!(" glass, outside {t} deg |");
    }
    for t in thetas {
        out!(" glass, inside {t} deg |");
    }
    for t in thetas {
        out!(" conductor {t} deg |");
    }
    outln!("\n|---|{}", "---|".repeat(3 * thetas.len()));
    let alphas: &[f64] = if quick {
        &[0.1, 0.5]
    } else {
        &[0.05, 0.1, 0.3, 0.6, 1.0]
    };
    for &alpha in alphas {
        let Ok(g) = Ggx::isotropic(alpha) else {
            continue;
        };
        out!("| {alpha} |");
        for inside in [false, true] {
            for t in thetas {
                let wo = dir(if inside { 180.0 - t } else { t });
                let peaks: Vec<V3<f64>> = refracted(wo, 1.5).into_iter().collect();
                let e = directional_albedo_sphere(
                    wo,
                    |o, i| rd::eval(&g, o, i, 1.5, Transport::Importance),
                    &peaks,
                );
                out!(" {:.2e} |", 1.0 - e.value);
            }
        }
        for t in thetas {
            let e = directional_albedo(dir(t), |o, i| brdf::cook_torrance::eval(&g, o, i, |_| 1.0));
            out!(" {:.2e} |", 1.0 - e.value);
        }
        outln!();
    }
}

/// sRGB-encoded 8-bit value of a linear channel in [0, 1].
fn srgb8(x: f64) -> u8 {
    let x = x.clamp(0.0, 1.0);
    let e = if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    };
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let v = (e * 255.0).round() as u8;
    v
}

/// The thin film's colour at normal view over its thickness: a soap-like film (n 1.33) on
/// glass and an oxide-like film (n 2.0) on an aluminium-like conductor.
pub fn iridescence_strip_section() {
    outln!("\n## Thin-film iridescence over thickness (Belcour and Barla 2017)\n");
    outln!(
        "`iridescence::dielectric` (film n = 1.33 on glass, n = 1.5) and \
         `iridescence::conductor` (film n = 2.0 on n = 1.1 + 6.8i) at normal view from air: \
         CIE XYZ (equal-energy white), then linear Rec.709 by `XYZ_TO_REC709`, clamped, as \
         sRGB-encoded hex. Thickness 0 is the bare base's Fresnel reflectance.\n"
    );
    outln!(
        "| thickness (nm) | soap film XYZ | soap film sRGB | oxide on metal XYZ | oxide on metal sRGB |"
    );
    outln!("|---|---|---|---|---|");
    let hex = |xyz: V3<f64>| {
        let m = XYZ_TO_REC709;
        let c = |r: usize| m[r][0] * xyz.x + m[r][1] * xyz.y + m[r][2] * xyz.z;
        format!("#{:02x}{:02x}{:02x}", srgb8(c(0)), srgb8(c(1)), srgb8(c(2)))
    };
    for step in 0..=16 {
        let d = 50.0 * f64::from(step);
        let (Ok(soap), Ok(oxide)) = (ThinFilm::new(d, 1.33), ThinFilm::new(d, 2.0)) else {
            continue;
        };
        let a = iridescence::dielectric(&soap, 1.0, 1.5, 1.0);
        let b = iridescence::conductor(&oxide, 1.0, 1.1, 6.8, 1.0);
        outln!(
            "| {d} | {:.3}, {:.3}, {:.3} | {} | {:.3}, {:.3}, {:.3} | {} |",
            a.x,
            a.y,
            a.z,
            hex(a),
            b.x,
            b.y,
            b.z,
            hex(b)
        );
    }
}
