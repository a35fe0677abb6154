//! The report's layers section: directional albedos of the glTF extension lobes (sheen,
//! clearcoat) and of the metallic-roughness base, before and after the layering dims the base
//! (the sheen's albedo scaling, the coat's Fresnel attenuation), over roughness and the view
//! cosine mu, by the public integrator.

use brdf::integrate::directional_albedo;
use brdf::layers::layered::Layered;
use brdf::layers::{clearcoat, sheen};
use brdf::shading::Cosines;
use brdf::{ParamError, V3};

/// The view at cosine `mu` in the xz plane.
fn wo_at(mu: f64) -> V3<f64> {
    V3::new(((1.0 - mu) * (1.0 + mu)).sqrt(), 0.0, mu)
}

/// The albedo of `f` (its first channel) at the view of cosine `mu`.
fn albedo(mu: f64, f: impl FnMut(V3<f64>, V3<f64>) -> f64) -> f64 {
    directional_albedo(wo_at(mu), f).value
}

/// Prints the albedo table: per (roughness r, mu), the sheen lobe (white sheen colour, sheen
/// roughness r), the clearcoat lobe (clearcoat 1, roughness r), the grey dielectric base
/// (baseColor 0.8, roughness r) alone, under the sheen's albedo scaling (the extension's min
/// form and its view-only form), under sheen and coat, and the layered material whole.
/// `quick` keeps three roughnesses and three cosines.
///
/// # Errors
/// A material parameter out of its domain (none on this grid).
pub fn albedo_section(quick: bool) -> Result<(), ParamError> {
    outln!("\n## Layers: albedo of sheen, coat and base, before and after albedo scaling\n");
    outln!(
        "Directional albedo by the public integrator (`brdf::integrate::directional_albedo`), \
         per perceptual roughness r (the sheen's, the coat's and the base's, all r) and view \
         cosine mu. Sheen: the glTF Charlie lobe with sheenColor 1 (D_charlie V_charlie). Coat: \
         clearcoat 1, F0 0.04, GGX with the exact Smith V. Base: baseColor 0.8, metallic 0. \
         \"base x s\": the base times the sheen's albedo scaling \
         s = min(1 - E(mu), 1 - E(n.l)) (KHR_materials_sheen, the form `Layered::eval` and \
         `Prepared::eval` use); \"view-only\": times 1 - E(mu), the extension's cheaper form \
         (`Prepared::eval_view_only`); \"base x s x (1 - F_c)\": also under the coat's Fresnel \
         attenuation 1 - F_coat(mu); \"layered\": the whole material (sheen, coat, base). E is \
         the crate's built-in sheen table (`layers::sheen::albedo`). Regenerate: `cargo run \
         --release -p brdf-report`.\n"
    );
    outln!(
        "| r | mu | sheen | coat | base | base x s | base x view-only | base x s x (1 - F_c) | \
         layered |"
    );
    outln!("|---|---|---|---|---|---|---|---|---|");
    let (rs, mus): (&[f64], &[f64]) = if quick {
        (&[0.2, 0.6, 1.0], &[0.2, 0.6, 1.0])
    } else {
        (&[0.1, 0.3, 0.5, 0.7, 1.0], &[0.1, 0.3, 0.5, 0.7, 1.0])
    };
    let mut worst: f64 = 0.0;
    for &r in rs {
        let alpha = r * r;
        let base = Layered::new(V3::splat(0.8), 0.0, r)?;
        let full = base.with_sheen(V3::splat(1.0), r)?.with_clearcoat(1.0, r)?;
        let coat_alpha = alpha.max(brdf::microfacet::ALPHA_MIN);
        for &mu in mus {
            let e_v = sheen::albedo(mu, alpha);
            let e_sheen = albedo(mu, |o, i| {
                sheen::charlie(Cosines::from_local(o, i), V3::splat(1.0), alpha).x
            });
            let e_coat = albedo(mu, |o, i| {
                clearcoat::coat(Cosines::from_local(o, i), coat_alpha)
            });
            let e_base = albedo(mu, |o, i| base.eval(o, i).x);
            let scaled = |o: V3<f64>, i: V3<f64>| {
                let s = sheen::albedo_scaling(V3::splat(1.0), e_v, sheen::albedo(i.z, alpha));
                base.eval(o, i).x * s
            };
            let e_scaled = albedo(mu, scaled);
            let e_view_only = (1.0 - e_v) * e_base;
            let e_coated = (1.0 - clearcoat::fresnel(mu)) * e_scaled;
            let e_full = albedo(mu, |o, i| full.eval(o, i).x);
            worst = worst.max(e_full);
            outln!(
                "| {r} | {mu} | {e_sheen:.4} | {e_coat:.4} | {e_base:.4} | {e_scaled:.4} | \
                 {e_view_only:.4} | {e_coated:.4} | {e_full:.4} |"
            );
        }
    }
    outln!(
        "\nThe layered column is the sheen and coat on top of the last-but-one column; its \
         largest value on this grid is {worst:.4} (at most 1: `cargo test --test layers \
         layered::layered_albedo_is_at_most_one`). The sheen's albedo passes 1 at grazing \
         views of the smoothest sheens (the Lambda fit's flaw, `layers::sheen::ALBEDO_TABLE`); \
         the table clamps E to 1 there. The base alone can pass 1 at grazing views of smooth \
         surfaces (1.08 at r 0.2, mu 0.2): glTF's composition mixes the diffuse and the specular \
         by F(v.h) per direction, not by the specular's directional albedo, so it is not \
         energy conserving (`material::MetallicRoughness`).\n"
    );
    Ok(())
}
