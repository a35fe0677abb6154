//! The report's image-based-lighting and energy-compensation sections: the split-sum DFG
//! terms and the fits engines ship against them, the roughness-to-mip mappings, irradiance
//! by quadrature and SH9, the single-sample IBL bug against the split-sum path on a sky with a
//! sun, and the multiple-scattering white furnace before and after compensation.

#[path = "../../../tests/scenes/s0.rs"]
mod s0;

use brdf::V3;
use brdf::cook_torrance;
use brdf::ggx::Ggx;
use brdf::ibl::{dfg, energy, irradiance};
use brdf::integrate::directional_albedo;
use brdf::microfacet::ALPHA_MIN;

/// The DFG table (A, B, E), the fits against it, and the mip mappings.
pub fn dfg_section() {
    outln!("\n## Image-based lighting: the split-sum DFG terms (GGX, height-correlated Smith)\n");
    outln!(
        "A and B weigh F0 and F90 (albedo = F0 A + F90 B), E = A + B is the albedo with F = 1; \
         {} samples per entry (`ibl::dfg::DEFAULT_SAMPLES`, every entry of a 64 x 64 table \
         within 1e-4: `cargo test --test ibl dfg_accuracy:: -- --nocapture`).\n",
        dfg::DEFAULT_SAMPLES
    );
    let novs = [0.05, 0.25, 0.5, 0.75, 1.0];
    out!("| roughness r |");
    for n in novs {
        out!(" NoV {n}: A / B / E |");
    }
    outln!("\n|---|{}", "---|".repeat(novs.len()));
    for r in [0.1, 0.3, 0.5, 0.7, 1.0] {
        out!("| {r} |");
        for n in novs {
            let [a, b, e] = dfg::dfg(n, r * r, dfg::DEFAULT_SAMPLES);
            out!(" {a:.4} / {b:.4} / {e:.4} |");
        }
        outln!();
    }

    // The fits against a 32 x 32 table (4096 samples per entry: within 4e-4 of exact, far
    // below the fits' errors).
    const N: usize = 32;
    let mut table = vec![[0.0f32; 3]; N * N];
    if dfg::table(&mut table, N, N, 4096).is_err() {
        outln!("(table build failed)");
        return;
    }
    outln!(
        "\nThe analytic fits engines ship, against that table ({N} x {N} cell centres, 4096 \
         samples per entry); max |error| (RMS), over all cells and over NoV >= 0.25. The fits \
         were made for other models (UE4's LUT uses the separable Schlick-Smith G, Lazarov a \
         Blinn-Phong lobe), which is most of their error. Run time against the table lookup: \
         `cargo bench -p brdf-bench --bench ibl`.\n"
    );
    outln!("| fit | A | B | A, NoV >= 0.25 | B, NoV >= 0.25 |");
    outln!("|---|---|---|---|---|");
    type Fit = fn(f64, f64) -> [f64; 2];
    let fits: [(&str, Fit); 4] = [
        ("Karis 2014 (UE4 mobile)", dfg::karis_mobile::<f64>),
        ("Lazarov 2013", dfg::lazarov::<f64>),
        (
            "Narkowicz 2014, Lazarov form",
            dfg::narkowicz_lazarov::<f64>,
        ),
        (
            "Narkowicz 2014, polynomial",
            dfg::narkowicz_polynomial::<f64>,
        ),
    ];
    for (name, fit) in fits {
        let mut st = [[0.0f64; 3]; 4]; // (max, sum sq, count) for A, B, A25, B25
        for j in 0..N {
            for i in 0..N {
                let nov = (i as f64 + 0.5) / N as f64;
                let r = (j as f64 + 0.5) / N as f64;
                let [fa, fb] = fit(nov, r);
                let t = table[j * N + i];
                let (ea, eb) = ((fa - f64::from(t[0])).abs(), (fb - f64::from(t[1])).abs());
                let mut acc = |k: usize, e: f64| {
                    st[k][0] = st[k][0].max(e);
                    st[k][1] += e * e;
                    st[k][2] += 1.0;
                };
                acc(0, ea);
                acc(1, eb);
                if nov >= 0.25 {
                    acc(2, ea);
                    acc(3, eb);
                }
            }
        }
        out!("| {name} |");
        for s in st {
            out!(" {:.3} ({:.3}) |", s[0], (s[1] / s[2]).sqrt());
        }
        outln!();
    }

    outln!(
        "\nRoughness to mip level of a prefiltered cube with 8 levels (UE4: linear in r from the \
         top mip; Filament: lod = L r (2 - r), L = levels - 1; UE4's capture mapping: \
         `ComputeReflectionCaptureMipFromRoughness`, which goes negative below r = 0.056 on 8 \
         levels: the sampler clamps it to mip 0).\n"
    );
    outln!("| roughness r | linear | Filament | UE4 capture |");
    outln!("|---|---|---|---|");
    for r in [0.0, 0.1, 0.25, 0.5, 0.75, 1.0] {
        outln!(
            "| {r} | {:.3} | {:.3} | {:.3} |",
            dfg::mip_from_roughness_linear(r, 8.0),
            dfg::lod_from_roughness_filament(r, 7.0),
            dfg::mip_from_roughness_ue4(r, 7.0)
        );
    }
}

/// Irradiance by quadrature and SH9, and the single-sample bug against the split sum.
pub fn irradiance_section() {
    outln!("\n## Image-based lighting: irradiance and the split-sum path\n");
    let e = irradiance::irradiance(V3::new(0.0, 0.0, 1.0), |_| V3::splat(1.0), 64);
    let sh = irradiance::project(|_| V3::splat(1.0), 64).irradiance(V3::new(0.0, 0.0, 1.0));
    outln!(
        "A constant environment L = 1 gives E = pi: quadrature {:.15} (error {:.1e}), SH9 \
         {:.15} (error {:.1e}).",
        e.x,
        (e.x - core::f64::consts::PI).abs(),
        sh.x,
        (sh.x - core::f64::consts::PI).abs()
    );
    // SH9 against quadrature on the scene's sky (with and without its sun).
    let sky = |d: V3<f64>| {
        let c = d.dot(s0::sun_dir()).min(1.0);
        s0::env(d) - V3::new(1.0, 0.9, 0.75) * ((-(1.0 - c) / 9.5e-4).exp() * 2000.0)
    };
    let sh_sky = irradiance::project(sky, 128);
    let sh_sun = irradiance::project(s0::env, 128);
    let (mut worst_sky, mut worst_sun) = (0.0f64, 0.0f64);
    for k in 0..200 {
        // A Fibonacci set of normals over the sphere.
        let z = 1.0 - (2.0 * k as f64 + 1.0) / 200.0;
        let phi = k as f64 * 2.399_963_229_728_653;
        let s = (1.0 - z * z).sqrt();
        let n = V3::new(s * phi.cos(), s * phi.sin(), z);
        let q_sky = irradiance::irradiance(n, sky, 96);
        let q_sun = irradiance::irradiance(n, s0::env, 96);
        worst_sky = worst_sky.max(s0::rel(sh_sky.irradiance(n), q_sky));
        worst_sun = worst_sun.max(s0::rel(sh_sun.irradiance(n), q_sun));
    }
    outln!(
        "SH9 irradiance against quadrature over 200 normals, max relative error: the sky alone \
         {:.2}%, the sky with its sun {:.1}% (band-2 truncation of a 2.5-degree sun of \
         radiance 2000; `cargo test --test ibl irradiance_sh9_error:: -- --nocapture` bounds SH9 \
         on its own sky and sun).\n",
        100.0 * worst_sky,
        100.0 * worst_sun
    );
    outln!(
        "The single-sample IBL bug (one sample along n for diffuse, a lerp toward it for \
         roughness, both at full weight) against the split-sum path (kD = (1 - F)(1 - \
         metallic), quadrature or SH9 irradiance, GGX-prefiltered radiance times F0 A + B), \
         on that sky with its sun; reference: the reflectance integral of the metallic-roughness \
         BRDF on a 1500 x 3000 grid. Relative error (max over RGB):\n"
    );
    outln!(
        "| surface | split sum | split sum, SH9 | single sample | white furnace: split sum / single sample |"
    );
    outln!("|---|---|---|---|---|");
    for s in s0::surfaces() {
        let want = s0::reference(&s, s0::env, 1500);
        let p = s0::paths(&s, s0::env);
        let white = s0::Surface {
            base: V3::splat(1.0),
            ..s
        };
        let w = s0::paths(&white, s0::white);
        outln!(
            "| {} | {:.1}% | {:.1}% | {:.0}% | {:.4} / {:.4} |",
            s.name,
            100.0 * s0::rel(p.fixed, want),
            100.0 * s0::rel(p.fixed_sh9, want),
            100.0 * s0::rel(p.bug, want),
            w.fixed.y,
            w.bug.y
        );
    }
}

/// The white furnace of GGX before and after Kulla-Conty compensation, and the saturation of
/// a coloured F0.
pub fn energy_section() {
    outln!("\n## Multiple-scattering energy compensation (Kulla and Conty 2017)\n");
    outln!(
        "Directional albedo of GGX with F = 1 (a conductor with F0 = 1) by the public \
         integrator: single scattering / with Kulla-Conty's lobe (`ibl::energy::kulla_conty_ggx`, \
         built-in E and E_avg tables). 1 is ideal.\n"
    );
    let thetas = [0.0, 30.0, 60.0, 75.0, 85.0];
    out!("| alpha |");
    for t in thetas {
        out!(" {t} deg |");
    }
    outln!("\n|---|{}", "---|".repeat(thetas.len()));
    let wo = |deg: f64| {
        let t = f64::to_radians(deg);
        V3::new(t.sin(), 0.0, t.cos())
    };
    for alpha in [0.1, 0.25, 0.5, 0.75, 1.0] {
        let Ok(g) = Ggx::isotropic(alpha) else {
            continue;
        };
        out!("| {alpha} |");
        for t in thetas {
            let ss = |o: V3<f64>, i: V3<f64>| cook_torrance::eval(&g, o, i, |_| 1.0);
            let before = directional_albedo(wo(t), ss).value;
            let after = directional_albedo(wo(t), |o, i| {
                ss(o, i) + energy::kulla_conty_ggx(o.z, i.z, alpha, 1.0)
            })
            .value;
            out!(" {before:.3} / {after:.4} |");
        }
        outln!();
    }
    let gold = V3::new(1.0, 0.78, 0.34);
    outln!(
        "\nA coloured F0 (gold-like {:?}, Schlick): albedo at normal view, single scattering / \
         compensated, and the red-to-blue ratio (Kulla-Conty's F_ms = F_avg^2 E_avg / (1 - \
         F_avg (1 - E_avg)) saturates the colour as the light bounces).\n",
        gold.to_array()
    );
    outln!("| alpha | single scattering | compensated | r / b before | r / b after |");
    outln!("|---|---|---|---|---|");
    for alpha in [0.25f64, 0.5, 1.0] {
        let Ok(g) = Ggx::isotropic(alpha.max(ALPHA_MIN)) else {
            continue;
        };
        let mut before = [0.0; 3];
        let mut after = [0.0; 3];
        for (c, f0) in gold.to_array().into_iter().enumerate() {
            let schlick = |o: V3<f64>, i: V3<f64>| {
                cook_torrance::eval(&g, o, i, |vh| brdf::fresnel::schlick(f0, vh))
            };
            let f_avg = energy::fresnel_avg_schlick(f0, 1.0);
            before[c] = directional_albedo(wo(0.0), schlick).value;
            after[c] = directional_albedo(wo(0.0), |o, i| {
                schlick(o, i) + energy::kulla_conty_ggx(o.z, i.z, alpha, f_avg)
            })
            .value;
        }
        outln!(
            "| {alpha} | {:.3} {:.3} {:.3} | {:.3} {:.3} {:.3} | {:.2} | {:.2} |",
            before[0],
            before[1],
            before[2],
            after[0],
            after[1],
            after[2],
            before[0] / before[2],
            after[0] / after[2]
        );
    }
}
