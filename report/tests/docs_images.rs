//! The README's pictures under `docs/` are current: each is re-rendered here from what
//! produces it and compared with the committed PNG, decoded, pixel by pixel.
//!
//! Why a pixel comparison with a tolerance rather than a hash: the material chart's shading
//! runs through libm and the crate's kernels, whose last bits differ between builds with and
//! without FMA (and between libm versions); a hash of the PNG would fail on such a machine
//! although nothing a reader can see changed. A change that matters (a kernel, the
//! environment, the layout, a label) moves many pixels, or all of them a little (an exposure
//! 8 % higher moves the chart's mean by about a level). The bound: at most 0.2 % of the
//! channel values may differ by more than 2 levels of 255, the mean difference must stay at
//! or below 0.25 level, and the sizes must match. The Pareto plot is redrawn from its committed data (`docs/pareto.csv`:
//! run times are this machine's, so they are data, not something to recompute), and that
//! data must name exactly the forms the report measures today.
//!
//! To refresh all three after a change: `cargo run --release -p brdf-report -- --docs`.

use std::path::{Path, PathBuf};

use brdf_report::pictures;

fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs")
}

const REFRESH: &str = "refresh with `cargo run --release -p brdf-report -- --docs`";

/// Decodes both PNGs and fails unless they have the same size, at most 0.2 % of their channel
/// values differ by more than 2 levels and the mean difference is at most 0.25 level.
fn assert_close(committed: &Path, fresh: &Path) {
    let (w0, h0, a) = pictures::read_png(committed)
        .unwrap_or_else(|e| panic!("{}: {e}; {REFRESH}", committed.display()));
    let (w1, h1, b) = pictures::read_png(fresh).expect("the fresh render reads back");
    assert_eq!(
        (w0, h0),
        (w1, h1),
        "{} is {w0} x {h0}, a fresh render {w1} x {h1}: stale; {REFRESH}",
        committed.display()
    );
    let far = a
        .iter()
        .zip(&b)
        .filter(|(x, y)| x.abs_diff(**y) > 2)
        .count();
    let allowed = a.len() / 500;
    let mean = a
        .iter()
        .zip(&b)
        .map(|(x, y)| f64::from(x.abs_diff(*y)))
        .sum::<f64>()
        / a.len() as f64;
    assert!(
        far <= allowed && mean <= 0.25,
        "{}: {far} channel values differ by more than 2 levels from a fresh render (at most \
         {allowed} may), mean difference {mean:.3} levels (at most 0.25): stale; {REFRESH}",
        committed.display()
    );
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("docs_images");
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    dir.join(name)
}

#[test]
fn committed_material_chart_matches_a_fresh_render() {
    let fresh = scratch("material_chart.png");
    pictures::docs_material_chart(&fresh).expect("renders");
    assert_close(&docs().join("material_chart.png"), &fresh);
}

#[test]
fn committed_pareto_plot_matches_its_data() {
    let csv = std::fs::read_to_string(docs().join("pareto.csv"))
        .unwrap_or_else(|e| panic!("docs/pareto.csv: {e}; {REFRESH}"));
    let points = pictures::parse_pareto_csv(&csv).expect("docs/pareto.csv parses");
    let fresh = scratch("pareto.png");
    pictures::docs_pareto(&points, &fresh).expect("draws");
    assert_close(&docs().join("pareto.png"), &fresh);
}

#[test]
fn committed_pareto_data_names_every_form_measured_today() {
    let csv = std::fs::read_to_string(docs().join("pareto.csv"))
        .unwrap_or_else(|e| panic!("docs/pareto.csv: {e}; {REFRESH}"));
    let committed: Vec<(String, String)> = pictures::parse_pareto_csv(&csv)
        .expect("docs/pareto.csv parses")
        .into_iter()
        .map(|p| (p.family, p.form))
        .collect();
    assert_eq!(
        committed,
        pictures::pareto_forms(),
        "docs/pareto.csv's forms differ from the report's: stale; {REFRESH}"
    );
}

#[test]
fn the_comparison_catches_a_changed_picture() {
    // The tolerance must not swallow a real change: a chart rendered at another size, or
    // with one cell's worth of pixels changed, fails.
    let fresh = scratch("material_chart_check.png");
    pictures::docs_material_chart(&fresh).expect("renders");
    let (w, h, mut px) = pictures::read_png(&fresh).expect("reads");
    let n = px.len() / 50;
    for v in &mut px[..n] {
        *v = v.wrapping_add(128);
    }
    let changed = scratch("material_chart_changed.png");
    pictures::write_png(&changed, w, h, &px).expect("writes");
    let r = std::panic::catch_unwind(|| assert_close(&fresh, &changed));
    assert!(
        r.is_err(),
        "2 % of the values moved by 128 levels went unnoticed"
    );
}
