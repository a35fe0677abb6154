//! `docs/accuracy.md` is the table this oracle measures today: the test fails when the file
//! differs from a fresh measurement, and `BLESS=1` rewrites it
//! (`BLESS=1 cargo test -p brdf-oracle --release --test accuracy_table`). It also prints the
//! bounds the measurement suggests (`-- --nocapture`), for pasting into
//! `oracle/src/bounds.rs`. The README quotes the same table between two marker comments; it
//! is checked and blessed with the file.

use brdf_oracle::harness::Options;
use brdf_oracle::table;

/// The published table equals the measured one.
#[test]
fn accuracy_doc_matches_measurement() {
    let rows = table::measure_all(Options::default());
    let fresh = table::markdown(&rows);
    println!("{fresh}");
    println!(
        "suggested bounds (oracle/src/bounds.rs):\n{}",
        table::suggested_bounds(&rows)
    );
    let path = table::doc_path();
    let readme_path = path
        .parent()
        .and_then(|docs| docs.parent())
        .expect("docs/ sits in the repository root")
        .join("README.md");
    let readme = std::fs::read_to_string(&readme_path).expect("README.md is readable");
    let fresh_readme = with_readme_table(&readme, &fresh);
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(&path, &fresh).expect("docs/accuracy.md is writable");
        std::fs::write(&readme_path, &fresh_readme).expect("README.md is writable");
        return;
    }
    let current = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        current == fresh,
        "{} differs from the measured table; regenerate it with `{}`",
        path.display(),
        table::BLESS_COMMAND
    );
    assert!(
        readme == fresh_readme,
        "README.md's accuracy table differs from the measured one; regenerate it with `{}`",
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
