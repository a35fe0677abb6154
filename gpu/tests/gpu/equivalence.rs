//! Every twin runs on the adapter wgpu finds (Mesa's lavapipe in CI) over extremes, random
//! rows and rows near the ends of the cosines, and every value stays within the bound the
//! WGSL accuracy table gives its form, plus the CPU f32 result's own error
//! (`brdf_gpu::equiv`). Without an adapter the test fails with "SKIPPED: no adapter"
//! unless `BRDF_GPU_ALLOW_NO_ADAPTER=1`.

use brdf_gpu::device::Gpu;
use brdf_gpu::equiv::{cpu_row, grid_rows, rows, run_kernel};
use brdf_gpu::shaders::{families, twins};

fn gpu() -> Option<Gpu> {
    let g = Gpu::new();
    if g.is_none() {
        eprintln!("SKIPPED: no adapter (install mesa-vulkan-drivers and libvulkan1)");
        assert!(
            std::env::var("BRDF_GPU_ALLOW_NO_ADAPTER").as_deref() == Ok("1"),
            "no wgpu adapter: the GPU equivalence was not run (set BRDF_GPU_ALLOW_NO_ADAPTER=1 \
             to accept that)"
        );
    }
    g
}

#[test]
fn every_twin_on_the_gpu_stays_within_its_spec_derived_bound() {
    let Some(gpu) = gpu() else { return };
    println!("adapter: {}", gpu.describe());
    let fams = families();
    let (with, _) = twins(&fams);
    let mut failures = Vec::new();
    for t in &with {
        let f = run_kernel(&gpu, t, &fams, &rows(t.kernel));
        println!(
            "{:34} max {:>6} ULP, {:>6} of {:>6} identical, max/bound {:.3}, excluded {}",
            f.path,
            f.max_ulp,
            f.identical,
            f.compared,
            f.max_ratio,
            f.excluded_total()
        );
        assert!(f.compared > 0, "{}: nothing compared", f.path);
        if f.outside + f.twin_differs > 0 {
            failures.extend(f.failures);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_twin_with_another_formula_is_caught_on_the_cpu() {
    // ggx_d with pi written 3.14: the form's exact value leaves the Rust kernel's by more
    // than its bound, before any GPU runs.
    let mut fams = families();
    let fam = fams
        .iter()
        .position(|f| f.name == "ggx")
        .expect("ggx family");
    let broken = fams[fam]
        .source
        .replace("(t * t * BRDF_PI)", "(t * t * 3.14)");
    assert_ne!(broken, fams[fam].source, "the form to break is in ggx.wgsl");
    fams[fam].module = naga::front::wgsl::parse_str(&broken).expect("parses");
    let (with, _) = twins(&fams);
    let t = with.iter().find(|t| t.name == "ggx_d").expect("ggx_d");
    let mut interp = brdf_gpu::bound::Interp::new(&fams[fam].module);
    let row = [0.5, 0.25];
    let cpu = cpu_row(t, &mut interp, &row).expect("compared");
    assert!((cpu.form[0].v - cpu.c64[0]).abs() > cpu.form[0].e);
}

#[test]
fn a_thin_film_without_the_bases_phase_shift_is_caught_on_the_cpu() {
    // iridescence_conductor with the film -> base coefficient r23 replaced by its modulus (the
    // phase shift a metal gives the reflected wave dropped): over the thin film's grid of
    // stability cases, the form's exact value leaves the Rust kernel's by more than its bound
    // on many rows, before any GPU runs.
    let mut fams = families();
    let fam = fams
        .iter()
        .position(|f| f.name == "iridescence")
        .expect("iridescence family");
    let broken = fams[fam]
        .source
        .replace("vec2<f32>(r23.y, r23.z)", "vec2<f32>(sqrt(r23.x), 0.0)");
    assert_ne!(
        broken, fams[fam].source,
        "the form to break is in iridescence.wgsl"
    );
    fams[fam].module = naga::front::wgsl::parse_str(&broken).expect("parses");
    let (with, _) = twins(&fams);
    let t = with
        .iter()
        .find(|t| t.name == "iridescence_conductor")
        .expect("iridescence_conductor");
    let mut interp = brdf_gpu::bound::Interp::new(&fams[fam].module);
    let (mut compared, mut caught) = (0, 0);
    for row in grid_rows(t.kernel) {
        if let Ok(cpu) = cpu_row(t, &mut interp, &row) {
            compared += 1;
            if (0..3).any(|o| (cpu.form[o].v - cpu.c64[o]).abs() > cpu.form[o].e) {
                caught += 1;
            }
        }
    }
    println!("{caught} of {compared} rows caught");
    // A tenth: the grid's thick films, grazing rows and bases matching the film carry no
    // interference, so no phase to drop.
    assert!(caught * 10 > compared, "{caught} of {compared}");
}

#[test]
fn the_stable_ggx_d_stays_closer_to_the_cpu_than_the_textbook_form() {
    // Near n.h = 1 at small alpha the textbook denominator 1 + c^2 (a^2 - 1) cancels; the
    // twin's (1 - c)(1 + c) + c^2 a^2 does not (brdf_gpu::contrast).
    let Some(gpu) = gpu() else { return };
    let [ours, textbook] = brdf_gpu::contrast::run(&gpu);
    println!(
        "{}",
        brdf_gpu::contrast::markdown(&[ours.clone(), textbook.clone()])
    );
    assert!(
        ours.max_ulp < textbook.max_ulp,
        "ours {} ULP, textbook {} ULP",
        ours.max_ulp,
        textbook.max_ulp
    );
}
