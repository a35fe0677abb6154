//! The committed list of hardest inputs, `oracle/hardest.txt`: for every case, type and build
//! (the default build and one with FMA), the points where a deep search (`BRDF_ORACLE_DEEP=1`,
//! fresh points plus a hill-climb) found the largest errors. Every run measures them beside its
//! fresh points, so a bound once broken stays tested, and the published table
//! (`docs/accuracy.md`) is measured on them alone: the same figures on every run.
//!
//! Points that reviews and users reported carry the build `reported`: no search rewrites
//! them. A point of a function split by conditioning counts in whichever half its condition
//! number puts it (`crate::harness`), so a reported point may be listed under both names.
//!
//! One point per line, tab-separated: the build (`default`, `fma` or `reported`), the case name, the type
//! (`f32` or `f64`), then the arguments separated by spaces, each printed so that it reads
//! back to the same `f64` (and, for `f32` points, the same `f32`). Lines starting with `#`
//! are comments.
//!
//! Regenerate (after a kernel changes, and before the table is blessed):
//! `BRDF_ORACLE_DEEP=1 BRDF_ORACLE_RECORD=1 cargo test -p brdf-oracle --release --test accuracy_table -- --nocapture`
//! replaces the current build's lines with the highest-scoring points of that run (the
//! committed points included, so the list never loses a point that is still among the
//! worst); the other build's lines are kept.

use crate::harness::Ty;

/// The file, relative to the oracle crate's root.
pub const FILE: &str = "hardest.txt";

/// The build this binary is: `fma` when compiled with the FMA target feature (`mul_add`
/// fuses), else `default`.
#[must_use]
pub fn build() -> &'static str {
    if cfg!(target_feature = "fma") {
        "fma"
    } else {
        "default"
    }
}

/// One hardest input.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// `default` or `fma`.
    pub build: String,
    /// The case name.
    pub case: String,
    /// The type the point was found in.
    pub ty: Ty,
    /// The arguments.
    pub point: Vec<f64>,
}

/// The path of [`FILE`].
#[must_use]
pub fn path() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(FILE)
}

/// Parses the list; a malformed line is an error naming it.
///
/// # Errors
/// A line without four fields, with an unknown type or an argument that is not a number.
pub fn parse(text: &str) -> Result<Vec<Entry>, String> {
    let mut out = Vec::new();
    for (n, line) in text.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let bad = || format!("{FILE}:{}: malformed line {line:?}", n + 1);
        let f: Vec<&str> = line.split('\t').collect();
        let [build, case, ty, args] = f[..] else {
            return Err(bad());
        };
        let ty = match ty {
            "f32" => Ty::F32,
            "f64" => Ty::F64,
            _ => return Err(bad()),
        };
        let point = args
            .split(' ')
            .map(str::parse::<f64>)
            .collect::<Result<Vec<f64>, _>>()
            .map_err(|_| bad())?;
        out.push(Entry {
            build: build.to_string(),
            case: case.to_string(),
            ty,
            point,
        });
    }
    Ok(out)
}

/// The list as a file.
#[must_use]
pub fn render(entries: &[Entry]) -> String {
    let mut s = String::from(
        "# The hardest inputs the oracle's deep search found (oracle/src/hardest.rs).\n\
         # build\tcase\ttype\targuments\n",
    );
    for e in entries {
        let ty = match e.ty {
            Ty::F32 => "f32",
            Ty::F64 => "f64",
        };
        let args: Vec<String> = e.point.iter().map(|v| format!("{v:e}")).collect();
        s.push_str(&format!(
            "{}\t{}\t{ty}\t{}\n",
            e.build,
            e.case,
            args.join(" ")
        ));
    }
    s
}

/// The committed list, read once per process (empty when the file is missing).
///
/// # Panics
/// When the file exists but does not parse: a corrupt list must not pass silently.
#[must_use]
pub fn all() -> &'static [Entry] {
    static ALL: std::sync::OnceLock<Vec<Entry>> = std::sync::OnceLock::new();
    ALL.get_or_init(|| match std::fs::read_to_string(path()) {
        Ok(text) => parse(&text).unwrap_or_else(|e| panic!("{e}")),
        Err(_) => Vec::new(),
    })
}

/// The committed hardest points of `case` in `ty`, from both builds.
#[must_use]
pub fn points(case: &str, ty: Ty) -> Vec<Vec<f64>> {
    all()
        .iter()
        .filter(|e| e.case == case && e.ty == ty)
        .map(|e| e.point.clone())
        .collect()
}

/// Writes the list with this build's entries of the cases `replaced` (every case when
/// `None`) replaced by `fresh`; other builds' and other cases' entries are kept.
///
/// # Errors
/// When the file cannot be written.
pub fn save(fresh: Vec<Entry>, replaced: Option<&[&str]>) -> std::io::Result<()> {
    // Stable order: by case as first seen in `fresh` (then in the other builds' lines), then
    // build, then type.
    let mut order: Vec<String> = Vec::new();
    for e in fresh.iter().chain(all()) {
        if !order.contains(&e.case) {
            order.push(e.case.clone());
        }
    }
    let mut entries: Vec<Entry> = all()
        .iter()
        .filter(|e| e.build != build() || replaced.is_some_and(|r| !r.contains(&e.case.as_str())))
        .cloned()
        .collect();
    entries.extend(fresh);
    entries.sort_by_key(|e| {
        (
            order.iter().position(|c| *c == e.case),
            e.build.clone(),
            e.ty == Ty::F64,
        )
    });
    std::fs::write(path(), render(&entries))
}
