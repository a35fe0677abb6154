//! The plots: microfacet distributions and shadowing, Fresnel curves, directional albedo
//! against roughness per lobe. Each returns its file name.

use std::error::Error;
use std::path::Path;

use brdf::beckmann::{self, Beckmann};
use brdf::ggx::{self, Ggx};
use brdf::ibl::energy;
use brdf::integrate::directional_albedo_with;
use brdf::material::MetallicRoughness;
use brdf::microfacet::alpha_from_perceptual;
use brdf::{V3, cook_torrance, diffuse, fresnel};

use crate::plot::{self, LinePlot, Series};

type Res<T = ()> = Result<T, Box<dyn Error>>;

const ALPHAS: [(f64, (u8, u8, u8)); 4] = [
    (0.1, (31, 119, 180)),
    (0.25, (44, 160, 44)),
    (0.5, (214, 39, 40)),
    (0.8, (148, 103, 189)),
];

fn degrees(n: usize, hi: f64) -> impl Iterator<Item = f64> {
    (0..=n).map(move |i| hi * i as f64 / n as f64)
}

/// D(theta_h) of GGX (solid) and Beckmann (dashed) for several alpha, log scale.
pub fn ndf(dir: &Path) -> Res<String> {
    let mut s = Vec::new();
    for (a, c) in ALPHAS {
        let pts = |f: &dyn Fn(f64) -> f64| {
            degrees(400, 89.5)
                .map(|t| (t, f(t.to_radians().cos())))
                .collect::<Vec<_>>()
        };
        s.push(Series::new(format!("GGX, alpha = {a}"), pts(&|c| ggx::d(c, a))).styled(c, false));
        s.push(
            Series::new(
                format!("Beckmann, alpha = {a}"),
                pts(&|c| beckmann::d(c, a)),
            )
            .styled(c, true),
        );
    }
    let name = "ndf_ggx_beckmann.png";
    plot::lines(
        &dir.join(name),
        &LinePlot {
            title: "Normal distribution D(theta_h): GGX (solid) against Beckmann (dashed)",
            x_label: "theta_h, angle between the microfacet normal and n (degrees)",
            y_label: "D (1/sr, log scale)",
            log_x: false,
            log_y: true,
            y_range: (1e-4, 100.0),
        },
        &s,
    )?;
    Ok(name.into())
}

/// Smith G1(theta) of GGX and Beckmann for several alpha.
pub fn g1(dir: &Path) -> Res<String> {
    let mut s = Vec::new();
    for (a, c) in ALPHAS {
        let pts = |f: &dyn Fn(f64) -> f64| {
            degrees(400, 90.0)
                .map(|t| (t, f(t.to_radians().cos().max(1e-6))))
                .collect::<Vec<_>>()
        };
        s.push(Series::new(format!("GGX, alpha = {a}"), pts(&|c| ggx::g1(c, a))).styled(c, false));
        s.push(
            Series::new(
                format!("Beckmann, alpha = {a}"),
                pts(&|c| beckmann::g1(c, a)),
            )
            .styled(c, true),
        );
    }
    let name = "g1_ggx_beckmann.png";
    plot::lines(
        &dir.join(name),
        &LinePlot {
            title: "Smith masking G1(theta): GGX (solid) against Beckmann (dashed)",
            x_label: "theta, angle between the direction and n (degrees)",
            y_label: "G1 (fraction of visible microfacet area)",
            log_x: false,
            log_y: false,
            y_range: (0.0, 1.02),
        },
        &s,
    )?;
    Ok(name.into())
}

/// A metal: name, n and k at 650, 550 and 450 nm, plot colour.
pub type Metal = (&'static str, [f64; 3], [f64; 3], (u8, u8, u8));

/// Complex indices of refraction (n, k) at 650, 550 and 450 nm: the RGB triplets renderers
/// commonly take for these metals, close to Johnson and Christy 1972 ("Optical Constants of
/// the Noble Metals", Phys. Rev. B 6) for gold and copper and to Rakic 1995 (Applied Optics
/// 34(22)) for aluminium.
pub const METALS: [Metal; 3] = [
    (
        "gold",
        [0.143, 0.374, 1.442],
        [3.983, 2.385, 1.603],
        (196, 148, 10),
    ),
    (
        "copper",
        [0.200, 0.924, 1.102],
        [3.912, 2.452, 2.142],
        (184, 84, 40),
    ),
    (
        "aluminium",
        [1.657, 0.880, 0.521],
        [9.224, 6.270, 4.837],
        (110, 110, 125),
    ),
];

/// Fresnel reflectance against the angle of incidence: dielectrics over eta (exact, and
/// Schlick dashed for eta = 1.5), conductors per RGB wavelength.
pub fn fresnel_curves(dir: &Path) -> Res<String> {
    let pts = |f: &dyn Fn(f64) -> f64| {
        degrees(360, 90.0)
            .map(|t| (t, f(t.to_radians().cos())))
            .collect::<Vec<_>>()
    };
    let mut s = Vec::new();
    let greys = [
        (1.33, (90, 150, 220)),
        (1.5, (40, 40, 40)),
        (2.0, (120, 70, 160)),
        (2.42, (40, 160, 140)),
    ];
    for (eta, c) in greys {
        s.push(
            Series::new(
                format!("dielectric, eta = {eta}"),
                pts(&|ct| fresnel::dielectric(ct, eta)),
            )
            .styled(c, false),
        );
    }
    let f0 = fresnel::f0_from_ior(1.5);
    s.push(
        Series::new(
            "Schlick, F0 of eta = 1.5",
            pts(&|ct| fresnel::schlick(f0, ct)),
        )
        .styled((40, 40, 40), true),
    );
    for (name, eta, k, c) in METALS {
        for (ch, nm) in [(0, 650), (1, 550), (2, 450)] {
            let shade = |x: u8| (f64::from(x) * (0.55 + 0.3 * ch as f64)).min(255.0) as u8;
            s.push(
                Series::new(
                    format!("{name} at {nm} nm (n {}, k {})", eta[ch], k[ch]),
                    pts(&|ct| fresnel::conductor(ct, eta[ch], k[ch])),
                )
                .styled((shade(c.0), shade(c.1), shade(c.2)), ch == 1),
            );
        }
    }
    let name = "fresnel.png";
    plot::lines(
        &dir.join(name),
        &LinePlot {
            title: "Fresnel reflectance, unpolarized: dielectrics over eta, metals per wavelength",
            x_label: "angle of incidence (degrees)",
            y_label: "reflectance F (fraction)",
            log_x: false,
            log_y: false,
            y_range: (0.0, 1.0),
        },
        &s,
    )?;
    Ok(name.into())
}

/// Directional albedo at normal incidence and at 60 degrees against perceptual roughness, per
/// lobe ([`directional_albedo_with`]).
pub fn albedo_vs_roughness(dir: &Path, quick: bool) -> Res<String> {
    let steps = if quick { 5 } else { 20 };
    let rs: Vec<f64> = (0..=steps)
        .map(|i| (i as f64 / steps as f64).max(1e-3))
        .collect();
    type Make = fn(f64) -> Option<Box<dyn Fn(V3<f64>, V3<f64>) -> f64>>;
    let lobes: [(&str, Make, (u8, u8, u8)); 7] = [
        (
            "GGX, F = 1",
            |r| {
                let g = Ggx::isotropic(alpha_from_perceptual(r)).ok()?;
                Some(Box::new(move |o, i| cook_torrance::eval(&g, o, i, |_| 1.0)))
            },
            (31, 119, 180),
        ),
        (
            "GGX, F = 1, + Kulla-Conty",
            |r| {
                let a = alpha_from_perceptual(r);
                let g = Ggx::isotropic(a).ok()?;
                Some(Box::new(move |o, i| {
                    cook_torrance::eval(&g, o, i, |_| 1.0)
                        + energy::kulla_conty_ggx(o.z, i.z, a, 1.0)
                }))
            },
            (23, 190, 207),
        ),
        (
            "Beckmann, F = 1",
            |r| {
                let b = Beckmann::isotropic(alpha_from_perceptual(r)).ok()?;
                Some(Box::new(move |o, i| cook_torrance::eval(&b, o, i, |_| 1.0)))
            },
            (255, 127, 14),
        ),
        (
            "glTF material, white dielectric",
            |r| {
                let m = MetallicRoughness::new(V3::splat(1.0), 0.0, r).ok()?;
                Some(Box::new(move |o, i| m.eval(o, i).y))
            },
            (44, 160, 44),
        ),
        (
            "Oren-Nayar qualitative, rho = 1",
            |r| {
                let d = diffuse::OrenNayar::new(1.0, r).ok()?;
                Some(Box::new(move |o, i| d.eval(o, i)))
            },
            (214, 39, 40),
        ),
        (
            "EON, rho = 1",
            |r| {
                let d = diffuse::Eon::new(1.0, r).ok()?;
                Some(Box::new(move |o, i| d.eval(o, i)))
            },
            (148, 103, 189),
        ),
        (
            "Burley, rho = 1",
            |r| {
                let d = diffuse::Burley::new(1.0, r).ok()?;
                Some(Box::new(move |o, i| d.eval(o, i)))
            },
            (140, 86, 75),
        ),
    ];
    let mut s = Vec::new();
    for (name, make, c) in lobes {
        for (theta, dashed) in [(0.0f64, false), (60.0, true)] {
            let t = theta.to_radians();
            let wo = V3::new(t.sin(), 0.0, t.cos());
            let pts = rs
                .iter()
                .map(|&r| {
                    (
                        r,
                        make(r).map_or(f64::NAN, |f| {
                            directional_albedo_with(wo, &f, &super::ALBEDO_TOL).value
                        }),
                    )
                })
                .collect();
            s.push(Series::new(format!("{name}, theta_o = {theta}"), pts).styled(c, dashed));
        }
    }
    let name = "albedo_vs_roughness.png";
    plot::lines(
        &dir.join(name),
        &LinePlot {
            title: "Directional albedo against roughness, per lobe: theta_o = 0 (solid), 60 degrees (dashed)",
            x_label: "perceptual roughness r (alpha = r^2; diffuse lobes: sigma = r, radians for Oren-Nayar)",
            y_label: "directional albedo (1 = no energy lost)",
            log_x: false,
            log_y: false,
            y_range: (0.0, 1.1),
        },
        &s,
    )?;
    Ok(name.into())
}
