//! Rendering of the measurements: the detailed rows the tests print, and the Markdown table
//! of `docs/accuracy.md`.

use crate::bounds::{self, Bound};
use crate::cases;
use crate::harness::{Case, ILL_CONDITIONED, Measurement, Options, Stats, measure};

/// The command that regenerates `docs/accuracy.md` (the current build's table) from the
/// committed hardest inputs.
pub const BLESS_COMMAND: &str = "BLESS=1 cargo test -p brdf-oracle --release --test accuracy_table";

/// The command that runs the deep search and records its hardest inputs
/// (`oracle/hardest.txt`); run it before [`BLESS_COMMAND`] whenever a kernel changes.
pub const DEEP_COMMAND: &str = "BRDF_ORACLE_DEEP=1 BRDF_ORACLE_RECORD=1 cargo test -p brdf-oracle --release --test accuracy_table -- --nocapture";

/// The FMA build's flags, as the commands above take them in `RUSTFLAGS`.
pub const FMA_FLAGS: &str = "-C target-feature=+fma";

/// Whether `name` is one half of a function split by conditioning.
#[must_use]
pub fn is_split(name: &str) -> bool {
    name.ends_with(ILL_CONDITIONED)
        || cases::all()
            .iter()
            .any(|c| c.name.strip_suffix(ILL_CONDITIONED) == Some(name))
}

/// Where `docs/accuracy.md` lives.
#[must_use]
pub fn doc_path() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/accuracy.md")
}

/// A max ULP figure: two decimals, `inf` for a NaN or inf result, failures counted.
fn figure(s: &Stats) -> String {
    let v = if s.max_ulp.is_finite() {
        format!("{:.2}", s.max_ulp)
    } else {
        "inf".to_string()
    };
    if s.failures > 0 {
        format!("{v} ({} fail)", s.failures)
    } else {
        v
    }
}

/// The header of [`detail_row`].
#[must_use]
pub fn detail_header() -> String {
    format!(
        "{:<36} {:>14} {:>14} {:>14} {:>14}  {:>11} {:>13} {:>9}  bound f32/f64/f32x8/f64x4; worst f32 / f64 args",
        "function", "f32", "f64", "f32x8", "f64x4", "points", "tiny f32/f64", "overflow"
    )
}

/// One measured row with its bound and worst points.
#[must_use]
pub fn detail_row(case: &Case, m: &Measurement, b: &Bound) -> String {
    format!(
        "{:<36} {:>14} {:>14} {:>14} {:>14}  {:>5}/{:<5} {:>6}/{:<6} {:>4}/{:<4}  {}/{}/{}/{}; {:?} / {:?}",
        case.name,
        figure(&m.f32),
        figure(&m.f64),
        figure(&m.f32x8),
        figure(&m.f64x4),
        m.f32.points,
        m.f64.points,
        m.f32.tiny,
        m.f64.tiny,
        m.f32.overflow,
        m.f64.overflow,
        b.f32,
        b.f64,
        b.f32x8,
        b.f64x4,
        m.f32.worst,
        m.f64.worst,
    )
}

/// Measures every case (in parallel over the machine's cores) and returns them in table order.
#[must_use]
pub fn measure_all(opts: Options) -> Vec<(Case, Measurement)> {
    measure_all_of(opts, |_| true)
}

/// [`measure_all`] of the cases whose name `keep` accepts.
#[must_use]
pub fn measure_all_of(opts: Options, keep: impl Fn(&str) -> bool) -> Vec<(Case, Measurement)> {
    let all: Vec<Case> = cases::all().into_iter().filter(|c| keep(c.name)).collect();
    let split: Vec<bool> = all.iter().map(|c| is_split(c.name)).collect();
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(vec![None; all.len()]);
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(case) = all.get(i) else { break };
                    let m = measure(
                        case,
                        Options {
                            split: split[i],
                            ..opts
                        },
                    );
                    results.lock().expect("no panic while holding the lock")[i] = Some(m);
                }
            });
        }
    });
    let results = results
        .into_inner()
        .expect("no panic while holding the lock");
    all.into_iter()
        .zip(results)
        .map(|(c, m)| (c, m.expect("every case measured")))
        .collect()
}

/// The Markdown of this build's section of `docs/accuracy.md` for these measurements (made
/// with [`Options::hardest_only`], so the figures are those of the committed hardest inputs).
#[must_use]
pub fn markdown(rows: &[(Case, Measurement)]) -> String {
    let fma = cfg!(target_feature = "fma");
    let mut s = String::new();
    if fma {
        s.push_str(&format!(
            "Built with `RUSTFLAGS=\"{FMA_FLAGS}\"`, where `mul_add` fuses: the same measurement as above.\n\n"
        ));
    } else {
        s.push_str(
            "Max error in ULPs of the correctly rounded result (MPFR at 256 bits and more, from each function's published definition), counting results >= 1e-30 (f32) and >= 1e-300 (f64); smaller ones are checked to be within that absolute threshold, overflowing ones to be capped at the largest finite value. ",
        );
        s.push_str(
            "Each figure is the largest error the deep search found over the function's whole documented domain: fresh random points (both sides of every internal branch and both ends of every argument's range) and a hill-climb from the worst of them, across runs with different seeds. The points where it was reached are committed (`oracle/hardest.txt`) and the table is measured on them, so it reads the same on every run; every CI run measures them again beside a few thousand fresh points and a short climb, against the bounds in `oracle/src/bounds.rs` (each figure plus 0.3 ULP, rounded up to 0.1).\n\n",
        );
        s.push_str(&format!(
            "Deep search and record: `{DEEP_COMMAND}`; then regenerate this file: `{BLESS_COMMAND}` (each once more with `RUSTFLAGS=\"{FMA_FLAGS}\"` for the FMA section).\n\n"
        ));
        s.push_str(
            "Rows marked (ill-conditioned) hold the points where one rounding of the cosine (or of a colour channel) moves the exact result by more than 8 ULPs (kappa > 8): their figure is max(raw - kappa / 2), the raw error less what one rounding of the input explains, so a kernel that is exact up to its input's rounding scores at most 0; the table below the main one gives their raw error and kappa.\n\n",
        );
    }
    s.push_str("| function | f32 | f64 | f32x8 | f64x4 | reference |\n");
    s.push_str("|---|---:|---:|---:|---:|---|\n");
    for (case, m) in rows {
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} |\n",
            case.name,
            figure(&m.f32),
            figure(&m.f64),
            figure(&m.f32x8),
            figure(&m.f64x4),
            case.source
        ));
    }
    s.push_str(
        "\nIll-conditioned rows: the largest raw error in ULPs and the condition number kappa where it occurs (one rounding of the input explains kappa / 2).\n\n",
    );
    s.push_str("| function | f32 raw (kappa) | f64 raw (kappa) | f32x8 raw (kappa) | f64x4 raw (kappa) |\n");
    s.push_str("|---|---:|---:|---:|---:|\n");
    for (case, m) in rows
        .iter()
        .filter(|(c, _)| c.name.ends_with(ILL_CONDITIONED))
    {
        let cell = |st: &Stats| format!("{:.2} ({:.3e})", st.max_raw, st.kappa_at_raw);
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} |\n",
            case.name,
            cell(&m.f32),
            cell(&m.f64),
            cell(&m.f32x8),
            cell(&m.f64x4),
        ));
    }
    s
}

/// The section markers of this build in `docs/accuracy.md`.
#[must_use]
pub fn section_markers() -> (String, String) {
    let b = crate::hardest::build();
    (
        format!("<!-- build: {b} -->"),
        format!("<!-- end build: {b} -->"),
    )
}

/// `doc` with this build's section replaced by `table` (appended when absent).
#[must_use]
pub fn with_section(doc: &str, table: &str) -> String {
    let (start, end) = section_markers();
    match (doc.find(&start), doc.find(&end)) {
        (Some(a), Some(b)) if a < b => format!("{}{start}\n{table}{}", &doc[..a], &doc[b..]),
        // No section yet: the FMA build's goes after the default one; the default build's
        // starts the file.
        _ if cfg!(target_feature = "fma") => {
            format!("{doc}\n## FMA build\n\n{start}\n{table}{end}\n")
        }
        _ => format!("{start}\n{table}{end}\n"),
    }
}

/// The margin a bound keeps above the deep search's figure, in ULPs ([`suggested_bound`]).
///
/// Fresh points of ordinary runs found errors up to 0.24 ULP above a deep search's figure
/// (`phong::normalized` on f32: 1.50 searched, 1.74 found; `tonemap::agx_threejs` on f64:
/// 0.55 and 0.78; `fresnel::schlick` on f32: 3.05 and 3.23), so 0.15 was too thin. With the
/// rounding up to 0.1 the bound stays below the score plus 0.4, under the half ULP that one
/// more rounding adds, so `tests/harness.rs` still proves every bound tight.
pub const MARGIN: f64 = 0.3;

/// The bound a max score suggests: the score plus [`MARGIN`], rounded up to the next 0.1
/// (below the half ULP one more rounding adds, so the bound stays tight), and no more than
/// [`bounds::TARGET`] for a score below it (the promise, and still within half an ULP of
/// the score when it is above 3.5).
#[must_use]
pub fn suggested_bound(max_ulp: f64) -> f64 {
    // The 1e-9 keeps a score like 3.1 (+ 0.3 = 3.4000000000000004 in binary) at 3.4.
    let b = ((max_ulp + MARGIN) * 10.0 - 1e-9).ceil() / 10.0;
    if max_ulp < bounds::TARGET {
        b.min(bounds::TARGET)
    } else {
        b
    }
}

/// The lowest score an ill-conditioned row's bound is made from ([`suggested_bounds`]).
pub const ILL_FLOOR: f64 = -3.55;

/// The [`bounds::BOUNDS`] rows these measurements suggest, as Rust source (printed by the
/// table test so retuning is a paste). In an FMA build, the `.fma(...)` figures.
#[must_use]
pub fn suggested_bounds(rows: &[(Case, Measurement)]) -> String {
    let mut s = String::new();
    for (case, m) in rows {
        let cur = bounds::bound(case.name);
        // An ill-conditioned row's score approaches 0.5 - 8 / 2 = -3.5 for any kernel that
        // rounds its result (half an ulp where kappa is just above 8), so a lower figure only
        // says the search drew no such point: its bound is at least that of -3.55 (-3.2).
        let ill = case.name.ends_with(ILL_CONDITIONED);
        let f = |st: &Stats| {
            suggested_bound(if ill {
                st.max_ulp.max(ILL_FLOOR)
            } else {
                st.max_ulp
            })
        };
        s.push_str(&format!(
            "    b(\"{}\", {:.1}, {:.1}, {:.1}, {:.1}){},{}\n",
            case.name,
            f(&m.f32),
            f(&m.f64),
            f(&m.f32x8),
            f(&m.f64x4),
            if cfg!(target_feature = "fma") {
                " /* fma */"
            } else {
                ""
            },
            if cur.why.is_empty() {
                String::new()
            } else {
                format!(" // {}", cur.why)
            }
        ));
    }
    s
}
