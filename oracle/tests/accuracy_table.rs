//! `docs/accuracy.md` is the table of the committed hardest inputs (`oracle/hardest.txt`),
//! measured anew: the test fails when the file differs from that measurement, and `BLESS=1`
//! rewrites the current build's section
//! (`BLESS=1 cargo test -p brdf-oracle --release --test accuracy_table`). The README quotes the
//! default build's table between two marker comments; it is checked and blessed with the
//! file. The test also prints the bounds the measurement suggests (`-- --nocapture`), for
//! pasting into `oracle/src/bounds.rs`.
//!
//! With `BRDF_ORACLE_RECORD=1` it instead measures every case on fresh points with the
//! hill-climb (deep with `BRDF_ORACLE_DEEP=1`) and replaces the current build's lines of
//! `oracle/hardest.txt` with the highest-scoring points found; bless the table afterwards.
//! `BRDF_ORACLE_CASES=name,name` limits the search and the rewrite to those cases.

use brdf_oracle::harness::{ILL_CONDITIONED, Options, Ty};
use brdf_oracle::{hardest, table};

/// The published table equals the measured one (or, when recording, the hardest inputs are
/// rewritten).
#[test]
fn accuracy_doc_matches_measurement() {
    if std::env::var_os("BRDF_ORACLE_RECORD").is_some() {
        record();
        return;
    }
    let rows = table::measure_all(Options {
        hardest_only: true,
        ..Options::default()
    });
    let fresh = table::markdown(&rows);
    println!("{fresh}");
    println!(
        "suggested bounds (oracle/src/bounds.rs):\n{}",
        table::suggested_bounds(&rows)
    );
    let path = table::doc_path();
    let current = std::fs::read_to_string(&path).unwrap_or_default();
    let fresh_doc = table::with_section(&current, &fresh);
    let readme_path = path
        .parent()
        .and_then(|docs| docs.parent())
        .expect("docs/ sits in the repository root")
        .join("README.md");
    let readme = std::fs::read_to_string(&readme_path).expect("README.md is readable");
    let fma = cfg!(target_feature = "fma");
    let fresh_readme = if fma {
        readme.clone()
    } else {
        with_readme_table(&readme, &fresh)
    };
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(&path, &fresh_doc).expect("docs/accuracy.md is writable");
        std::fs::write(&readme_path, &fresh_readme).expect("README.md is writable");
        return;
    }
    assert!(
        current == fresh_doc,
        "{} ({} build) differs from the measured table; regenerate it with `{}`{}",
        path.display(),
        hardest::build(),
        table::BLESS_COMMAND,
        if fma {
            format!(" and RUSTFLAGS=\"{}\"", table::FMA_FLAGS)
        } else {
            String::new()
        }
    );
    assert!(
        readme == fresh_readme,
        "README.md's accuracy table differs from the measured one; regenerate it with `{}`",
        table::BLESS_COMMAND
    );
}

/// Distinct hardest points recorded per (case, lane type).
const KEEP: usize = 3;

/// Whether two points are in the same region: every coordinate within a relative 1e-3.
fn near(a: &[f64], b: &[f64]) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= 1e-3 * x.abs().max(y.abs()))
}

/// Measures every case on fresh points with the climb and records the highest-scoring points
/// of each (case, type) as this build's hardest inputs.
fn record() {
    // BRDF_ORACLE_CASES=name,name: search and record only these cases.
    let only: Option<Vec<String>> = std::env::var("BRDF_ORACLE_CASES")
        .ok()
        .map(|v| v.split(',').map(|s| s.trim().to_string()).collect());
    let rows: Vec<_> = table::measure_all_of(Options::default(), |name| {
        only.as_ref().is_none_or(|o| o.iter().any(|n| n == name))
    });
    println!(
        "suggested bounds from this search (oracle/src/bounds.rs):\n{}",
        table::suggested_bounds(&rows)
    );
    let mut entries = Vec::new();
    for (case, m) in &rows {
        for (ty, stats) in [(Ty::F32, [&m.f32, &m.f32x8]), (Ty::F64, [&m.f64, &m.f64x4])] {
            // The worst point of each lane type, then up to two more from other regions (a
            // climb leaves its neighbours at the top).
            let mut pts: Vec<Vec<f64>> = Vec::new();
            for st in stats {
                // An ill-conditioned row's largest raw error too, for its raw column.
                if case.name.ends_with(ILL_CONDITIONED)
                    && !st.worst_raw.is_empty()
                    && !pts.contains(&st.worst_raw)
                {
                    pts.push(st.worst_raw.clone());
                }
                let mut kept = 0;
                for (_, p) in &st.top {
                    if kept < KEEP && !pts.iter().any(|q| near(p, q)) {
                        pts.push(p.clone());
                        kept += 1;
                    }
                }
            }
            entries.extend(pts.into_iter().map(|point| hardest::Entry {
                build: hardest::build().to_string(),
                case: case.name.to_string(),
                ty,
                point,
            }));
        }
        println!(
            "{:<48} f32 {:>8.3} f64 {:>8.3} f32x8 {:>8.3} f64x4 {:>8.3}  points {} / {}",
            case.name,
            m.f32.max_ulp,
            m.f64.max_ulp,
            m.f32x8.max_ulp,
            m.f64x4.max_ulp,
            m.f32.points,
            m.f64.points
        );
    }
    let names: Vec<&str> = rows.iter().map(|(c, _)| c.name).collect();
    hardest::save(entries, only.is_some().then_some(names.as_slice()))
        .expect("oracle/hardest.txt is writable");
    println!(
        "recorded {} ({} build); now bless the table: {}",
        hardest::path().display(),
        hardest::build(),
        table::BLESS_COMMAND
    );
}

/// `readme` with the text between the accuracy-table markers replaced by `table`.
fn with_readme_table(readme: &str, table: &str) -> String {
    const START: &str = "<!-- accuracy table:";
    const END: &str = "<!-- end accuracy table -->";
    let start = readme
        .find(START)
        .expect("README.md has the accuracy-table start marker");
    let body = start + readme[start..].find('\n').expect("marker line ends") + 1;
    let end = readme
        .find(END)
        .expect("README.md has the accuracy-table end marker");
    format!("{}{}{}", &readme[..body], table, &readme[end..])
}
