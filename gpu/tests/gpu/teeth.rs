//! The equivalence has teeth for the composed twins: each twin broken by hand (a wrong
//! constant, swapped arguments, a wrong engine's branch) leaves the Rust kernel by more than
//! its bound on its stability grid (`brdf_gpu::equiv::GRIDS`), on the CPU alone, before any
//! GPU runs. The counts are printed (`cargo test -p brdf-gpu --release teeth -- --nocapture`).

use brdf_gpu::bound::{Interp, ulp32};
use brdf_gpu::equiv::{TWIN_ULP, cpu_row, grid_rows};
use brdf_gpu::shaders::{families, twins};

/// Output values of the grid rows of `kernel` whose twin, with `from` replaced by `to` in its
/// family's source, leaves the Rust kernel by more than its bound (the criterion of
/// `equiv::run_kernel`), and the values compared.
fn caught(family: &str, kernel: &str, from: &str, to: &str) -> (usize, usize) {
    let mut fams = families();
    let fam = fams
        .iter()
        .position(|f| f.name == family)
        .unwrap_or_else(|| panic!("no family {family}"));
    let broken = fams[fam].source.replacen(from, to, 1);
    assert_ne!(
        broken, fams[fam].source,
        "{from:?} is not in {family}'s WGSL"
    );
    fams[fam].module = naga::front::wgsl::parse_str(&broken).expect("the broken twin parses");
    let (with, _) = twins(&fams);
    let t = with
        .iter()
        .find(|t| t.kernel.path == kernel)
        .unwrap_or_else(|| panic!("no twin of {kernel}"));
    let mut interp = Interp::new(&fams[t.family].module);
    let (mut compared, mut out) = (0, 0);
    for row in grid_rows(t.kernel) {
        let Ok(cpu) = cpu_row(t, &mut interp, &row) else {
            continue;
        };
        for (o, f) in cpu.form.iter().enumerate() {
            let (c32, c64) = (f64::from(cpu.c32[o]), cpu.c64[o]);
            compared += 1;
            let near64 = (f.v - c64).abs() <= f.e + f64::from(f32::MIN_POSITIVE);
            let near32 = (f.v - c32).abs() <= f.e + TWIN_ULP * ulp32(c32);
            if !(near64 || near32) {
                out += 1;
            }
        }
    }
    println!("{kernel}: {from:?} -> {to:?}: {out} of {compared} values leave the bound");
    (out, compared)
}

/// Asserts that the break is caught on at least `min_share` of the grid's values.
fn assert_caught(family: &str, kernel: &str, from: &str, to: &str, min_share: f64) {
    let (out, compared) = caught(family, kernel, from, to);
    assert!(compared > 0, "{kernel}: nothing compared");
    #[allow(clippy::cast_precision_loss)]
    let share = out as f64 / compared as f64;
    assert!(
        share >= min_share,
        "{kernel}: {from:?} -> {to:?} caught on {out} of {compared} values"
    );
}

#[test]
fn broken_engine_twins_leave_their_bound_on_the_grid() {
    // A wrong constant: bevy's roughness floor 0.089 read as 0.08 (its grid rows below the
    // floor: roughness 0, 1e-3, 0.01, 0.03, 0.045, 0.0525 of bevy's 5 x 11 = 55).
    assert_caught(
        "engine",
        "engine::Convention::alpha",
        "select(0.0, 0.089, convention == 2u)",
        "select(0.0, 0.08, convention == 2u)",
        0.05,
    );
    // A wrong constant: Filament's and bevy's F90 scale 16.5 read as 15.
    assert_caught(
        "engine",
        "engine::Convention::f90",
        "16.5 *",
        "15.0 *",
        0.01,
    );
    // A wrong engine's branch: the exp2 weight for bevy (2) instead of Unreal Engine 4 (3).
    assert_caught(
        "engine",
        "engine::Convention::fresnel",
        "(convention == 0u) | (convention == 3u)",
        "(convention == 0u) | (convention == 2u)",
        0.1,
    );
    // Swapped arguments: D read at v.h instead of n.h.
    assert_caught(
        "engine",
        "engine::Convention::specular",
        "brdf_engine_d(convention, n_dot_h, alpha)",
        "brdf_engine_d(convention, v_dot_h, alpha)",
        0.2,
    );
    // A wrong constant: Filament's visibility guard 0.5 / 7.7e-6 read as 0.5 / 7.7e-5.
    assert_caught(
        "engine",
        "engine::Convention::specular",
        "min(v, 64935.066)",
        "min(v, 6493.5066)",
        0.005,
    );
    // A wrong engine's branch: Burley's diffuse for Filament (1) instead of bevy (2).
    assert_caught(
        "engine",
        "engine::Convention::diffuse",
        "diffuse_burley(nv, n_dot_l, v_dot_h, rho, alpha), convention == 2u",
        "diffuse_burley(nv, n_dot_l, v_dot_h, rho, alpha), convention == 1u",
        0.1,
    );
    // A wrong engine's branch: the glTF diffuse weight for Unreal Engine 4 (3) too.
    assert_caught(
        "engine",
        "engine::Convention::brdf",
        "convention >= 4u",
        "convention >= 3u",
        0.015,
    );
    // Swapped arguments: the F0 lerp's weights exchanged (metallic for 1 - metallic).
    assert_caught(
        "engine",
        "engine::Convention::brdf",
        "fma(0.04, one_minus_m, base_color_r * metallic)",
        "fma(0.04, metallic, base_color_r * one_minus_m)",
        0.05,
    );
}

#[test]
fn the_wgsl_sheen_albedo_table_is_the_crates_bit_for_bit() {
    let fams = families();
    let layers = fams.iter().find(|f| f.name == "layers").expect("layers");
    let m = &layers.module;
    let (_, c) = m
        .constants
        .iter()
        .find(|(_, c)| c.name.as_deref() == Some("BRDF_SHEEN_ALBEDO_TABLE"))
        .expect("the table constant");
    let naga::Expression::Compose { components, .. } = &m.global_expressions[c.init] else {
        panic!("the table is not an array")
    };
    let wgsl: Vec<u32> = components
        .iter()
        .map(|&e| match m.global_expressions[e] {
            naga::Expression::Literal(naga::Literal::F32(x)) => x.to_bits(),
            ref other => panic!("entry {other:?}"),
        })
        .collect();
    let rust: Vec<u32> = brdf::layers::sheen::ALBEDO_TABLE
        .iter()
        .map(|x| x.to_bits())
        .collect();
    assert_eq!(wgsl, rust);
}

#[test]
fn broken_layered_twins_leave_their_bound_on_the_grid() {
    // A wrong constant: the dielectric's 1 - F0 read as 0.9 (the diffuse weight).
    assert_caught(
        "layered",
        "layers::layered::Layered::eval",
        "0.96 * one_minus_w",
        "0.9 * one_minus_w",
        0.05,
    );
    // Swapped arguments: the anisotropy frame rotated the other way.
    assert_caught(
        "layered",
        "layers::layered::Layered::eval",
        "c * w.x + s * w.y, c * w.y - s * w.x",
        "c * w.x - s * w.y, c * w.y + s * w.x",
        0.01,
    );
    // A wrong branch: the volumetric lobe where the thin-walled one belongs, and back.
    assert_caught(
        "layered",
        "layers::layered::Layered::eval",
        "select(f_vol, f_thin, thin)",
        "select(f_thin, f_vol, thin)",
        0.01,
    );
    // A wrong constant: the lobe-probability floor 1/16 read as 1/8.
    assert_caught(
        "layered",
        "layers::layered::Layered::lobe_probabilities",
        "0.0625",
        "0.125",
        0.05,
    );
    // Swapped arguments: the average Schlick weights w = 1/21 and 1 - w exchanged.
    assert_caught(
        "layered",
        "layers::layered::Layered::lobe_probabilities",
        "0.0476190485, 0.952380955",
        "0.952380955, 0.0476190485",
        0.05,
    );
    // Swapped arguments: the coat's and the specular lobe's probabilities exchanged.
    assert_caught(
        "layered",
        "layers::layered::Layered::pdf",
        "p.x * coat + p.y * spec",
        "p.x * spec + p.y * coat",
        0.05,
    );
    // A wrong branch: the thin-walled transmission density for the volume, and back.
    assert_caught(
        "layered",
        "layers::layered::Layered::pdf",
        "select(select(0.0, p_vol, pair), p_thin, thin)",
        "select(p_thin, select(0.0, p_vol, pair), thin)",
        0.01,
    );
    // A wrong branch: the coat's direction where the specular lobe was drawn, and back.
    assert_caught(
        "layered",
        "layers::layered::Layered::sample",
        "wi_spec, is_spec), wi_coat, is_coat)",
        "wi_coat, is_spec), wi_spec, is_coat)",
        0.05,
    );
    // Swapped arguments: the specular lobe's u rescaled by the coat's probability.
    assert_caught(
        "layered",
        "layers::layered::Layered::sample",
        "brdf_layered_rescale(u, c1, p.y)",
        "brdf_layered_rescale(u, c1, p.x)",
        0.02,
    );
}
