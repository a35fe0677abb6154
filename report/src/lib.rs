//! The main job: `cargo run --release -p brdf-report [-- --quick] [-- --out DIR]`.
//!
//! Writes one folder (default `out/report`, named on stdout) that a person reads:
//! `report.md`, a CSV beside every table, and the images. At its heart the error of every
//! form of every kernel family against its run time, measured in the same run; then the
//! stability of every kernel on its domain's extreme inputs, the energy (directional albedo)
//! of each model, and the crate's checks (integrators, lanes, normalization, furnaces,
//! tonemapping, diffuse and Phong lobes, lights, image-based lighting, the accuracy table).
//! stdout gets the summary; stderr a progress line per stage.
//!
//! A library with a one-line binary (`main.rs`): a library starts compiling as soon as the
//! reference CLI's metadata exists, in parallel with the CLI's own code generation, where a
//! binary would wait for all of it (the report's cold build on 2 cores: 49 s as a binary).

#[macro_use]
mod md;
mod energy;
pub mod pictures;
mod plot;
mod sections;
mod stability;
mod textbook;
mod tradeoff;

use sections::transmission as transmission_section;
use sections::{
    checks, gpu as gpu_section, ibl as ibl_section, layers as layers_section, lobes,
    tonemap as tonemap_section,
};
use std::error::Error;
use std::path::{Path, PathBuf};
use std::time::Instant;
use tradeoff::{Budget, Measured};

struct Args {
    quick: bool,
    out: PathBuf,
    env: Option<PathBuf>,
    docs: bool,
    pictures: bool,
}

fn args() -> Result<Args, String> {
    let mut a = Args {
        quick: false,
        out: PathBuf::from("out/report"),
        env: None,
        docs: false,
        pictures: false,
    };
    let mut it = std::env::args().skip(1);
    while let Some(x) = it.next() {
        match x.as_str() {
            "--quick" => a.quick = true,
            "--out" => a.out = it.next().ok_or("--out needs a folder")?.into(),
            "--env" => a.env = Some(it.next().ok_or("--env needs a .hdr file")?.into()),
            "--docs" => a.docs = true,
            "--pictures" => a.pictures = true,
            "-h" | "--help" => {
                println!(
                    "brdf-report: the crate's report.\n\n\
                     Usage: cargo run --release -p brdf-report -- [--quick] [--out DIR] [--env FILE.hdr] [--docs]\n\n\
                     --quick         fewer points, rounds and grid cells (seconds; what CI runs)\n\
                     --out DIR       the folder to write (default out/report)\n\
                     --env FILE.hdr  light the renders with a Radiance equirectangular file\n\
                     --pictures      only the renders and plots that need no measurement\n\
                     --docs          also rewrite the README's pictures under docs/ (material\n\
                     \x20               chart, Pareto plot and its data, docs/pareto.csv)"
                );
                std::process::exit(0);
            }
            other => return Err(format!("unknown argument `{other}` (try --help)")),
        }
    }
    Ok(a)
}

/// Runs a stage, printing its name and duration on stderr.
fn stage<R>(name: &str, t0: Instant, f: impl FnOnce() -> R) -> R {
    let t = Instant::now();
    eprintln!("[{:6.1} s] {name} ...", t0.elapsed().as_secs_f64());
    let r = f();
    eprintln!(
        "[{:6.1} s] {name}: done in {:.1} s",
        t0.elapsed().as_secs_f64(),
        t.elapsed().as_secs_f64()
    );
    r
}

fn fmt_err(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.2e}")
    }
}

fn fmt_ulp(x: f64) -> String {
    if x.is_infinite() {
        "inf".into()
    } else if x >= 1e4 {
        format!("{x:.1e}")
    } else {
        format!("{x:.2}")
    }
}

fn fmt_ns(s: &tradeoff::Spread) -> String {
    let f = |x: f64| {
        if x >= 100.0 {
            format!("{x:.0}")
        } else if x >= 10.0 {
            format!("{x:.1}")
        } else {
            format!("{x:.2}")
        }
    };
    format!("{} [{}, {}]", f(s.median), f(s.min), f(s.max))
}

/// The machine, as far as the program can tell.
fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let mut features = Vec::new();
    if cfg!(target_feature = "avx2") {
        features.push("avx2");
    }
    if cfg!(target_feature = "fma") {
        features.push("fma");
    }
    if cfg!(target_feature = "sse4.1") {
        features.push("sse4.1");
    }
    let features = if features.is_empty() {
        "baseline (no -C target-cpu; f32x8 as two SSE halves, no FMA)".to_string()
    } else {
        features.join(", ")
    };
    format!(
        "{cpu}, {threads} hardware threads; {} build, target features: {features}",
        std::env::consts::ARCH
    )
}

fn tradeoff_section(measured: &[Measured], fams: &[tradeoff::Family], budget: &Budget) -> String {
    outln!("## Error against run time\n");
    outln!(
        "Every form of every kernel family the crate offers more than one of, and the textbook \
         single-precision form engines ship (*textbook* rows), measured in this run. Error: the \
         `f32` result (scalar, and `f32x8` lanes for the last ULP column) against the \
         reference in `f64` at the same `f32`-rounded inputs, over {} random points per family \
         (the DFG family: fewer, its reference is a 32768-sample quadrature){}; only results \
         whose reference is at least 1e-30 count. Run time: ns per element through \
         `brdf::batch` over {} elements, median [fastest, slowest] of {} rounds, all forms \
         interleaved round by round. Scalar `f32` loops may be auto-vectorized by the compiler \
         where a form has no branch and no call (the textbook rows).\n",
        budget.points,
        if budget.refine {
            ", then 8 x 320 neighbours of each form's 8 worst points in the uniforms that \
             generated them (scales 1e-2 to 1e-7)"
        } else {
            " (quick mode: no search around the worst points)"
        },
        budget.batch,
        budget.rounds
    );
    let mut table = String::new();
    table.push_str(
        "| family | form | max rel. error | mean rel. error | max abs. error | max ULP f32 | max ULP f32x8 | ns f32 | ns f64 | ns/element f32x8 |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for m in measured {
        let form = if m.textbook {
            format!("*{}*", m.form)
        } else {
            format!("`{}`", m.form)
        };
        let nonfinite = if m.nonfinite > 0 {
            format!(" ({} non-finite)", m.nonfinite)
        } else {
            String::new()
        };
        table.push_str(&format!(
            "| {} | {form}{nonfinite} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            m.family,
            fmt_err(m.max_rel),
            fmt_err(m.mean_rel),
            fmt_err(m.max_abs),
            fmt_ulp(m.max_ulp),
            m.max_ulp_x8.map_or("-".into(), fmt_ulp),
            fmt_ns(&m.ns_f32),
            m.ns_f64.as_ref().map_or("-".into(), fmt_ns),
            m.ns_x8.as_ref().map_or("-".into(), fmt_ns),
        ));
    }
    out!("{table}");
    outln!(
        "\nPareto front per family (the forms no other form of the family beats in both max \
         relative error and ns per element on `f32x8`, or on `f32` where a form has no lane \
         path), fastest first:\n"
    );
    for f in fams {
        let rows: Vec<&Measured> = measured.iter().filter(|m| m.family == f.name).collect();
        let ns = |m: &Measured| m.ns_x8.as_ref().map_or(m.ns_f32.median, |s| s.median);
        let mut front: Vec<&Measured> = rows
            .iter()
            .copied()
            .filter(|m| {
                !rows.iter().any(|o| {
                    ns(o) <= ns(m)
                        && o.max_rel <= m.max_rel
                        && (ns(o) < ns(m) || o.max_rel < m.max_rel)
                })
            })
            .collect();
        front.sort_by(|a, b| ns(a).total_cmp(&ns(b)));
        let names: Vec<String> = front
            .iter()
            .map(|m| format!("`{}` ({}, {:.2} ns)", m.form, fmt_err(m.max_rel), ns(m)))
            .collect();
        outln!("- **{}**: {}", f.name, names.join(" -> "));
    }
    outln!("\nDomains and references:\n");
    for f in fams {
        outln!(
            "- **{}**: {}; reference {}.",
            f.name,
            f.domain,
            f.reference_name
        );
    }
    outln!("\nThe worst input found per form:\n");
    outln!("| family | form | worst input | points |\n|---|---|---|---:|");
    for m in measured {
        let w: Vec<String> = m.worst.iter().map(|x| format!("{x:e}")).collect();
        outln!(
            "| {} | `{}` | {} | {} |",
            m.family,
            m.form,
            w.join(", "),
            m.points
        );
    }
    outln!("\n![Error against run time](pareto.png)\n");
    table
}

fn stability_section(rows: &[stability::Row], cap: usize) -> (usize, usize, usize) {
    outln!("\n## Stability on the extreme inputs of every domain\n");
    outln!(
        "Every kernel of the reference table (`brdf-ref --list`), on the extremes of each \
         argument's documented domain (both ends, one rounding inside each end, 0, -0, the \
         smallest subnormal and normal, 1 - eps/2, 1 + eps, 1e-6 from 1, the largest finite \
         float where the domain reaches it, +inf where allowed), every combination across \
         arguments up to {cap} rows per kernel (`brdf_ref::points::extreme_rows`: all of them \
         where they fit, else every extreme of every argument at least once and deterministic \
         random rows; rows breaking a documented relation between arguments are left out). \
         Counted: NaN outputs, infinite outputs, finite outputs outside the output's stated \
         range (the promise is none of the three), and lane results (`f32x8`, `f64x4`) that \
         differ in any bit from the scalar result (expected, by a few ULP, where a kernel calls \
         a transcendental: the lane polynomials are 1 to 3 ULP from libm; `cargo test -p \
         brdf-ref` bounds each such kernel and lists the larger differences as known issues).\n"
    );
    outln!(
        "| kernel | combos f32 / f64 | NaN f32 / f64 | inf f32 / f64 | out of range f32 / f64 | lanes differ f32x8 / f64x4 | first failing input (f32, else f64) |\n\
         |---|---:|---:|---:|---:|---:|---|"
    );
    let (mut bad_kernels, mut bad_outputs, mut lane_kernels) = (0, 0, 0);
    for r in rows {
        let bad = |c: &stability::Counts| c.nan + c.inf + c.out_of_range;
        let b = bad(&r.f32) + bad(&r.f64);
        if b > 0 {
            bad_kernels += 1;
            bad_outputs += b;
        }
        if r.f32.lane_mismatch + r.f64.lane_mismatch > 0 {
            lane_kernels += 1;
        }
        let first = r
            .f32
            .first_bad
            .as_ref()
            .or(r.f64.first_bad.as_ref())
            .map_or(String::new(), |(x, y)| format!("{x:?} -> {y:?}"));
        outln!(
            "| `{}` | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | {first} |",
            r.path,
            r.f32.combos,
            r.f64.combos,
            r.f32.nan,
            r.f64.nan,
            r.f32.inf,
            r.f64.inf,
            r.f32.out_of_range,
            r.f64.out_of_range,
            r.f32.lane_mismatch,
            r.f64.lane_mismatch
        );
    }
    outln!(
        "\n{bad_kernels} of {} kernels have at least one NaN, inf or out-of-range output on \
         in-domain input ({bad_outputs} outputs in all); the lanes of {lane_kernels} differ from \
         their scalars somewhere.",
        rows.len()
    );
    (bad_kernels, bad_outputs, lane_kernels)
}

fn energy_section(grids: &[energy::Grid], dir: &Path) -> Result<Vec<String>, Box<dyn Error>> {
    outln!("\n## Energy: directional albedo over roughness and theta_o\n");
    outln!(
        "rho(theta_o) = integral of f cos theta_i over the hemisphere, by \
         `brdf::integrate::directional_albedo` (adaptive cubature, error below 1e-5 here). 1 \
         is a white furnace; below 1 is energy lost (single scattering), above 1 created (the \
         glTF dielectric at grazing view: its diffuse layer is weighted by 1 - F(v.h) while its \
         specular layer reflects F, as the glTF specification's fresnel_mix does). All heat \
         maps share one colour scale.\n"
    );
    let top = grids
        .iter()
        .flat_map(|g| g.albedo.iter().flatten())
        .fold(1.05f64, |m, &a| if a.is_finite() { m.max(a) } else { m });
    let mut files = Vec::new();
    for g in grids {
        outln!("### {}\n", g.model);
        out!("| {} \\ theta_o (deg) |", g.roughness_label);
        for t in &g.theta {
            out!(" {t} |");
        }
        outln!("\n|---|{}", "---:|".repeat(g.theta.len()));
        for (r, row) in g.roughness.iter().zip(&g.albedo) {
            out!("| {r} |");
            for a in row {
                out!(" {a:.4} |");
            }
            outln!();
        }
        let name = format!("{}.png", g.stem);
        plot::heatmap(
            &dir.join(&name),
            &format!("Directional albedo: {}", g.model),
            "theta_o (degrees)",
            g.roughness_label,
            &g.theta,
            &g.roughness,
            &g.albedo,
            "directional albedo (1 = no loss)",
            (0.3, top),
        )?;
        outln!("\n![{}]({name})\n", g.model);
        files.push(name);
    }
    Ok(files)
}

fn tonemap_curves(dir: &Path) -> Result<String, Box<dyn Error>> {
    use brdf::V3;
    use brdf::tonemap::Operator;
    let series: Vec<(String, Vec<(f64, f64)>)> = Operator::all()
        .iter()
        .map(|op| {
            let pts = (0..=200)
                .map(|i| {
                    let x = 10f64.powf(-3.0 + 5.0 * f64::from(i) / 200.0);
                    let y = brdf::color::srgb_oetf(op.apply(V3::splat(x)).y);
                    (x, y)
                })
                .collect();
            (checks::op_name(op), pts)
        })
        .collect();
    let name = "tonemap_curves.png".to_string();
    plot::curves(
        &dir.join(&name),
        "Tonemapping operators on a grey ramp",
        "scene-linear input, relative to diffuse white (log scale)",
        "display value, sRGB-encoded (0 = black, 1 = white)",
        true,
        (0.0, 1.0),
        &series,
    )?;
    Ok(name)
}

/// `--pictures`: the renders and the plots that need no measurement, and a report.md that
/// holds only them.
fn pictures_only(a: &Args, t0: Instant) -> Result<(), Box<dyn Error>> {
    let files = stage("pictures", t0, || {
        let opt = pictures::Options {
            env: a.env.clone(),
            quick: a.quick,
        };
        let mut f = pictures::write_all(&a.out, &opt)?;
        f.push(tonemap_curves(&a.out)?);
        Ok::<_, Box<dyn Error>>(f)
    })?;
    if a.docs {
        let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs");
        pictures::docs_material_chart(&docs.join("material_chart.png"))?;
    }
    let text = md::take();
    md::write_folder(&text, &a.out)?;
    println!(
        "Pictures written to {}: {}. Total {:.1} s.",
        a.out.display(),
        files.join(", "),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

/// The whole job: parse the command line, measure, write the folder, print the summary.
///
/// # Errors
/// A file that cannot be written, or a chart that cannot be drawn.
pub fn run() -> Result<(), Box<dyn Error>> {
    let a = match args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("brdf-report: {e}");
            std::process::exit(2);
        }
    };
    let t0 = Instant::now();
    std::fs::create_dir_all(&a.out)?;
    plot::register_fonts();
    let budget = if a.quick {
        Budget {
            points: 2_000,
            refine: false,
            batch: 1024,
            rounds: 3,
        }
    } else {
        Budget {
            points: 200_000,
            refine: true,
            batch: 16_384,
            rounds: 21,
        }
    };
    outln!("# brdf report\n");
    outln!(
        "Generated by `cargo run --release -p brdf-report{}` on {}.\n",
        if a.quick { " -- --quick" } else { "" },
        machine()
    );
    outln!(
        "Sections: error against run time, stability on extreme inputs, energy, then the \
         crate's checks (integrators, lanes, the accuracy table, NDF normalization, Smith's \
         weak furnace, tonemapping, diffuse and Phong lobes, the material furnace, lights, \
         image-based lighting, the WGSL twins on GPUs). Every table has its CSV beside this file.\n"
    );
    if a.pictures {
        return pictures_only(&a, t0);
    }
    let fams = tradeoff::families();
    let mut measured = stage("error of every form", t0, || {
        fams.iter()
            .enumerate()
            .flat_map(|(i, f)| tradeoff::measure_errors(f, &budget, 1000 + i as u64))
            .collect::<Vec<_>>()
    });
    stage("run time of every form", t0, || {
        tradeoff::measure_times(&fams, &mut measured, &budget, |_| {});
    });
    let summary_table = tradeoff_section(&measured, &fams, &budget);
    let points: Vec<plot::ParetoPoint> = measured
        .iter()
        .zip(
            fams.iter()
                .flat_map(|f| f.forms.iter().map(move |_| f.plot)),
        )
        .filter(|(_, p)| *p)
        .map(|(m, _)| plot::ParetoPoint {
            family: m.family.to_string(),
            form: m.form.to_string(),
            x: m.ns_x8.as_ref().map_or(m.ns_f32.median, |s| s.median),
            y: m.max_rel,
        })
        .collect();
    plot::pareto(
        &a.out.join("pareto.png"),
        "Error against run time (f32, one run)",
        "ns per element (f32x8 through batch; f32 where there is no lane path)",
        "max relative error of the f32 result",
        &points,
    )?;
    if a.docs {
        let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs");
        std::fs::write(docs.join("pareto.csv"), pictures::pareto_csv(&points))?;
        pictures::docs_pareto(&points, &docs.join("pareto.png"))?;
        pictures::docs_material_chart(&docs.join("material_chart.png"))?;
        eprintln!("wrote docs/pareto.csv, docs/pareto.png and docs/material_chart.png");
    }
    let cap = if a.quick { 2_000 } else { 20_000 };
    let rows = stage("stability on extreme inputs", t0, || stability::run(cap));
    let (bad_kernels, bad_outputs, lane_kernels) = stability_section(&rows, cap);
    let grids = stage("energy grids", t0, || energy::grids(a.quick))?;
    let mut images = vec!["pareto.png".to_string()];
    images.extend(energy_section(&grids, &a.out)?);
    stage(
        "the crate's checks",
        t0,
        || -> Result<(), Box<dyn Error>> {
            outln!("\n## The crate's checks\n");
            checks::integrator_checks();
            checks::lane_checks();
            checks::accuracy_table();
            checks::microfacet_checks();
            checks::tonemap_table();
            tonemap_section::peers_table();
            lobes::diffuse_albedo()?;
            lobes::phong_comparison()?;
            lobes::material_furnace()?;
            lobes::light_falloffs();
            ibl_section::dfg_section();
            ibl_section::irradiance_section();
            ibl_section::energy_section();
            transmission_section::dielectric_energy_section(a.quick);
            transmission_section::iridescence_strip_section();
            layers_section::albedo_section(a.quick)?;
            gpu_section::gpu_section();
            Ok(())
        },
    )?;
    stage("pictures", t0, || -> Result<(), Box<dyn Error>> {
        let opt = pictures::Options {
            env: a.env.clone(),
            quick: a.quick,
        };
        images.extend(pictures::write_all(&a.out, &opt)?);
        let c = tonemap_curves(&a.out)?;
        outln!(
            "The tone curves: each operator on a grey ramp, sRGB-encoded.\n\n![Tonemap curves]({c})\n"
        );
        images.push(c);
        Ok(())
    })?;
    let text = md::take();
    let csvs = md::write_folder(&text, &a.out)?;
    println!("# brdf report{}\n", if a.quick { " (quick)" } else { "" });
    println!("## Error against run time (f32 error; ns per element)\n");
    print!("{summary_table}");
    println!(
        "\nStability: {bad_kernels} of {} kernels give NaN, inf or out-of-range output somewhere \
         on their domain's extreme inputs ({bad_outputs} outputs; report.md lists them with an \
         input); the lanes of {lane_kernels} differ from their scalars somewhere (lane \
         transcendentals).",
        rows.len()
    );
    println!(
        "\nReport written to {}: report.md, {} CSV files, {} images ({}). Total {:.1} s.",
        a.out.display(),
        csvs.len(),
        images.len(),
        images.join(", "),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
