//! Energy of the metallic-roughness material, measured with the public integrator: the
//! directional albedo rho(wo) = integral of f(wo, wi) cos(theta_i) dwi per RGB channel, over
//! perceptual roughness {0, 0.05, 0.25, 0.5, 0.75, 1} and theta_o up to 89 degrees.
//!
//! - A white metal (base colour 1, metallic 1: F = 1) conserves energy, rho <= 1, and the table
//!   shows the single-scattering loss of rough metals (the light that bounces more than once
//!   between microfacets, which the model drops).
//! - A white dielectric (base colour 1, metallic 0) does not: every coupling's diffuse weight
//!   ignores the energy the specular lobe takes, so rho exceeds 1, most at grazing view. The
//!   tables print by how much, and the test pins the maxima the module docs quote.
#![cfg(all(feature = "material", feature = "integrate"))]

use brdf::V3;
use brdf::integrate::directional_albedo;
use brdf::material::{DiffuseCoupling, MetallicRoughness};

const ROUGHNESS: [f64; 6] = [0.0, 0.05, 0.25, 0.5, 0.75, 1.0];
const THETAS_DEG: [f64; 7] = [0.0, 30.0, 60.0, 75.0, 85.0, 88.0, 89.0];

fn wo_at(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin(), 0.0, t.cos())
}

/// Directional albedo of channel `c` (0 = red) and the integrator's error estimate.
fn albedo(m: &MetallicRoughness<f64>, theta_deg: f64, c: usize) -> (f64, f64) {
    let e = directional_albedo(wo_at(theta_deg), |o, i| {
        let f = m.eval(o, i);
        [f.x, f.y, f.z][c]
    });
    (e.value, e.error)
}

/// Prints rho per (roughness, theta_o) for channel 0 and returns the table.
fn table(name: &str, make: impl Fn(f64) -> MetallicRoughness<f64>) -> Vec<Vec<(f64, f64)>> {
    println!("\n{name}: directional albedo rho(theta_o)");
    print!("{:>9}", "roughness");
    for t in THETAS_DEG {
        print!(" {:>8}", format!("{t}deg"));
    }
    println!();
    let mut out = Vec::new();
    for r in ROUGHNESS {
        let m = make(r);
        print!("{r:>9}");
        let mut row = Vec::new();
        for t in THETAS_DEG {
            let (rho, err) = albedo(&m, t, 0);
            print!(" {rho:>8.5}");
            row.push((rho, err));
        }
        println!();
        out.push(row);
    }
    out
}

/// Worst (largest) rho - 1 - err over a table, and where.
fn worst_excess(t: &[Vec<(f64, f64)>]) -> (f64, f64, f64) {
    let mut worst = (f64::NEG_INFINITY, 0.0, 0.0);
    for (ri, row) in t.iter().enumerate() {
        for (ti, (rho, err)) in row.iter().enumerate() {
            if rho - 1.0 - err > worst.0 {
                worst = (rho - 1.0 - err, ROUGHNESS[ri], THETAS_DEG[ti]);
            }
        }
    }
    worst
}

#[test]
fn white_metal_conserves_energy_and_prints_its_single_scattering_loss() {
    // base colour 1, metallic 1: F = 1 at every angle, f = D V.
    let white = table("white metal (F0 = 1)", |r| {
        MetallicRoughness::new(V3::splat(1.0), 1.0, r).unwrap()
    });
    let (excess, r, t) = worst_excess(&white);
    println!("largest rho - 1 - integrator error: {excess:.1e} (roughness {r}, {t} deg)");
    // Energy conservation; the integrator's own error is the only slack allowed.
    assert!(
        excess <= 1e-9,
        "white metal gains energy at roughness {r}, {t} deg"
    );
    // A smooth white metal is a mirror: nothing lost at normal view (roughness 0 is the
    // floored alpha 1e-4, roughness 0.05 is alpha 0.0025).
    assert!((white[0][0].0 - 1.0).abs() < 1e-6 && (white[1][0].0 - 1.0).abs() < 1e-4);
    // Roughness 1 (alpha 1) at normal view loses ln 2 (rho = 1 - ln 2, the closed form of
    // the height-correlated GGX; see tests/cook_torrance/energy.rs).
    assert!((white[5][0].0 - (1.0 - core::f64::consts::LN_2)).abs() < 1e-6);
    println!(
        "loss at roughness 1, normal view: {:.5} (missing multiple scattering)",
        1.0 - white[5][0].0
    );
    // Per channel: a gold-coloured metal stays below the white one in every channel.
    let gold = MetallicRoughness::new(V3::new(1.0, 0.766, 0.336), 1.0, 0.5).unwrap();
    let white_half = MetallicRoughness::new(V3::splat(1.0), 1.0, 0.5).unwrap();
    for t in THETAS_DEG {
        let w = albedo(&white_half, t, 0);
        for c in 0..3 {
            let g = albedo(&gold, t, c);
            assert!(
                g.0 <= w.0 + g.1 + w.1,
                "gold channel {c} at {t} deg: {g:?} > {w:?}"
            );
        }
    }
}

#[test]
fn white_dielectric_gains_the_energy_the_docs_state() {
    let white = |r: f64, c: DiffuseCoupling| {
        MetallicRoughness::new(V3::splat(1.0), 0.0, r)
            .unwrap()
            .with_coupling(c)
    };
    let gltf = table("white dielectric, glTF coupling (1 - F_dielectric)", |r| {
        white(r, DiffuseCoupling::Gltf)
    });
    let one_minus_f = table("white dielectric, (1 - F)(1 - metallic)", |r| {
        white(r, DiffuseCoupling::OneMinusF)
    });
    let additive = table(
        "white dielectric, Filament / UE4 (no Fresnel on diffuse)",
        |r| white(r, DiffuseCoupling::Additive),
    );
    // The specular lobe alone (base colour 0), for the closed forms below.
    let specular = table("dielectric specular lobe alone (base colour 0)", |r| {
        MetallicRoughness::new(V3::splat(0.0), 0.0, r).unwrap()
    });
    for (name, t) in [
        ("glTF", &gltf),
        ("1 - F", &one_minus_f),
        ("additive", &additive),
    ] {
        let max_normal = t.iter().map(|row| row[0].0).fold(0.0, f64::max);
        let max_all = t.iter().flatten().map(|x| x.0).fold(0.0, f64::max);
        println!("{name}: max rho at normal view {max_normal:.4}, over all theta_o {max_all:.4}");
    }
    for (ri, r) in ROUGHNESS.iter().enumerate() {
        for (ti, t) in THETAS_DEG.iter().enumerate() {
            let (g, eg) = gltf[ri][ti];
            let (o, eo) = one_minus_f[ri][ti];
            let (a, ea) = additive[ri][ti];
            let (s, es) = specular[ri][ti];
            // At metallic 0 with an uncoloured F0 the glTF and (1 - F) couplings are the same
            // function.
            assert!((g - o).abs() <= eg + eo + 1e-12, "{r} {t}: {g} vs {o}");
            // Additive: the diffuse lobe alone has albedo exactly 1 (kd = 1, base 1), so
            // rho = 1 + the specular lobe's albedo.
            assert!(
                (a - 1.0 - s).abs() <= ea + es + 1e-7,
                "{r} {t}: {a} vs 1 + {s}"
            );
            // The Fresnel weight only removes diffuse light.
            assert!(g <= a + eg + ea, "{r} {t}: {g} > {a}");
            // Additive gains energy at every angle; glTF conserves it near normal view (its
            // (1 - F(v.h)) removes a little more than the specular lobe takes there) and
            // gains it at grazing view.
            assert!(a > 1.0, "{r} {t}: {a}");
            if *t <= 30.0 {
                assert!(g <= 1.0 + eg, "{r} {t}: {g}");
            }
        }
    }
    // The maxima quoted in the module docs (normal view / any view, 2-digit rounding).
    let max_at = |t: &[Vec<(f64, f64)>], col: Option<usize>| {
        t.iter()
            .flat_map(|row| match col {
                Some(c) => vec![row[c].0],
                None => row.iter().map(|x| x.0).collect(),
            })
            .fold(0.0, f64::max)
    };
    for (name, t, normal, any) in [
        ("glTF", &gltf, 1.00, 1.85),
        ("additive", &additive, 1.04, 1.92),
    ] {
        let (n, a) = (max_at(t, Some(0)), max_at(t, None));
        assert!(
            (n - normal).abs() < 0.005 && (a - any).abs() < 0.005,
            "{name}: {n} {a}"
        );
    }
    // How dark must a glTF dielectric be to conserve energy at every angle? rho is linear in
    // the base colour b: rho(b) = b A_d + A_s, so b <= (1 - A_s) / A_d.
    let mut b_max = f64::INFINITY;
    for (ri, row) in gltf.iter().enumerate() {
        for (ti, (g, _)) in row.iter().enumerate() {
            let a_s = specular[ri][ti].0;
            b_max = b_max.min((1.0 - a_s) / (g - a_s));
        }
    }
    println!(
        "glTF dielectric conserves energy at every tabulated angle for base colour <= {b_max:.3}"
    );
}
