//! The GPU section: the WGSL twins against the CPU, read from the snapshots `brdf-gpu-equiv`
//! committed under `gpu/results/<adapter>/` (one per GPU driver the twins ran on). The report
//! itself runs no GPU code, so its build needs no graphics stack; the snapshots say which
//! adapter, driver and date each figure comes from.

use std::path::{Path, PathBuf};

/// One adapter's snapshot.
struct Snapshot {
    /// The folder's name under `gpu/results/`.
    name: String,
    /// The `Adapter:` line of its Markdown (name, driver, API, device type).
    adapter: String,
    /// The `Date:` line's date.
    date: String,
    /// Per kernel: (path, compared values, bit-identical values, max ULP, max measured / bound,
    /// excluded, outside the bound).
    rows: Vec<Row>,
    /// The stable-form table's rows: (form, bit-identical, max ULP, where).
    ggx: Vec<[String; 4]>,
    /// The kernels without a twin, each line "`path`: reason" as the snapshot lists them.
    without: Vec<String>,
}

struct Row {
    kernel: String,
    compared: f64,
    identical: f64,
    max_ulp: f64,
    /// The same over values with normal arguments and results (NaN in older snapshots).
    max_ulp_normal: f64,
    ratio: f64,
    excluded: f64,
    outside: f64,
}

/// Where the snapshots live: `gpu/results/` of the repository the report was built from.
fn results_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../gpu/results")
}

fn read(dir: &Path) -> Option<Snapshot> {
    let md = std::fs::read_to_string(dir.join("gpu-equivalence.md")).ok()?;
    let csv = std::fs::read_to_string(dir.join("gpu-equivalence.csv")).ok()?;
    let line = |prefix: &str| {
        md.lines()
            .find_map(|l| l.strip_prefix(prefix))
            .map(|s| s.trim().to_string())
            .unwrap_or_default()
    };
    let date = line("Date:").split(' ').next().unwrap_or("").to_string();
    let mut rows = Vec::new();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next()?.split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name);
    let (ck, cc, ci, cu, cr, ce, co) = (
        col("kernel")?,
        col("compared")?,
        col("bit_identical")?,
        col("max_ulp")?,
        col("max_ratio")?,
        col("excluded")?,
        col("outside_bound")?,
    );
    let cn = col("max_ulp_normal");
    for l in lines {
        let f: Vec<&str> = l.split(',').collect();
        let num = |i: usize| {
            f.get(i)
                .and_then(|s| s.parse::<f64>().ok())
                .unwrap_or(f64::NAN)
        };
        rows.push(Row {
            kernel: f.get(ck)?.to_string(),
            compared: num(cc),
            identical: num(ci),
            max_ulp: num(cu),
            max_ulp_normal: cn.map_or(f64::NAN, num),
            ratio: num(cr),
            excluded: num(ce),
            outside: num(co),
        });
    }
    // The stable-form table: the rows after its heading.
    let mut ggx = Vec::new();
    if let Some(i) = md.find("## Why the stable form") {
        for l in md[i..]
            .lines()
            .filter(|l| l.starts_with("| ") && !l.starts_with("| form"))
        {
            let cells: Vec<String> = l
                .trim_matches('|')
                .split('|')
                .map(|c| c.trim().to_string())
                .collect();
            if cells.len() == 4 {
                ggx.push([
                    cells[0].clone(),
                    cells[1].clone(),
                    cells[2].clone(),
                    cells[3].clone(),
                ]);
            }
        }
    }
    // The kernels without a twin: the list after its heading, one "- `path`: reason" a line.
    let without = md
        .find("without a WGSL twin")
        .map(|i| {
            md[i..]
                .lines()
                .skip(1)
                .skip_while(|l| l.trim().is_empty())
                .take_while(|l| l.starts_with("- `"))
                .map(|l| l.trim_start_matches("- ").to_string())
                .collect()
        })
        .unwrap_or_default();
    Some(Snapshot {
        name: dir.file_name()?.to_string_lossy().into_owned(),
        adapter: line("Adapter:"),
        date,
        rows,
        ggx,
        without,
    })
}

fn fmt_ulp(x: f64) -> String {
    if x.is_nan() {
        "-".into()
    } else if x < 1e5 {
        format!("{x:.0}")
    } else {
        format!("{x:.1e}")
    }
}

/// Writes the section.
pub fn gpu_section() {
    outln!("\n## GPU: the WGSL twins against the CPU\n");
    let dir = results_dir();
    let mut snaps: Vec<Snapshot> = std::fs::read_dir(&dir)
        .map(|it| {
            it.filter_map(Result::ok)
                .filter(|e| e.path().is_dir())
                .filter_map(|e| read(&e.path()))
                .collect()
        })
        .unwrap_or_default();
    if snaps.is_empty() {
        outln!(
            "No snapshot under `{}`: `cargo run --release -p brdf-gpu --bin brdf-gpu-equiv -- \
             --out gpu/results/<adapter>` writes one.",
            dir.display()
        );
        return;
    }
    // lavapipe first (the CI's driver), then the others by name.
    snaps.sort_by_key(|s| (s.name != "lavapipe", s.name.clone()));
    outln!(
        "Every kernel with a WGSL twin (`brdf::wgsl`, `wgsl/`) ran as a compute shader through \
         wgpu on each adapter below, over its argument extremes, 16 384 random rows and rows \
         with cosines near 0 and 1, against the CPU's `f32` result. Each value is held to the \
         bound the WGSL specification's accuracy table gives the twin's own form at that input \
         (W3C, \"WebGPU Shading Language\", \"Floating Point Accuracy\"; `gpu/src/bound.rs` \
         propagates the per-operation allowances through the twin's naga IR); inputs where \
         WGSL promises nothing are excluded and counted. Snapshots are committed by \
         `brdf-gpu-equiv --out gpu/results/<adapter>` (`gpu/device/run.sh` on a machine with \
         only a GPU driver); this section reads them. \"Max ULP, normal\" is the largest \
         distance where every argument and both results are 0 or normal `f32` numbers: GPUs \
         flush subnormals to 0, which WGSL allows, and a flushed subnormal argument can move a \
         result by any amount (a lobe of n.h = 1.4e-45 becomes the lobe of n.h = 0).\n"
    );
    outln!(
        "| snapshot | adapter and driver | date | kernels | max measured / bound | values outside the bound |"
    );
    outln!("|---|---|---|---:|---:|---:|");
    for s in &snaps {
        let worst = s.rows.iter().map(|r| r.ratio).fold(0.0f64, f64::max);
        let outside: f64 = s.rows.iter().map(|r| r.outside).sum();
        outln!(
            "| {} | {} | {} | {} | {:.3} | {} |",
            s.name,
            s.adapter.replace('|', "/"),
            s.date,
            s.rows.len(),
            worst,
            outside
        );
    }
    outln!();
    let mut head = String::from("| kernel |");
    let mut rule = String::from("|---|");
    for s in &snaps {
        head.push_str(&format!(
            " {0}: max ULP | {0}: max ULP, normal | {0}: bit-identical | {0}: max / bound \
             | {0}: excluded |",
            s.name
        ));
        rule.push_str("---:|---:|---:|---:|---:|");
    }
    outln!("{head}");
    outln!("{rule}");
    for r0 in &snaps[0].rows {
        let mut line = format!("| `{}` |", r0.kernel);
        for s in &snaps {
            match s.rows.iter().find(|r| r.kernel == r0.kernel) {
                Some(r) => line.push_str(&format!(
                    " {} | {} | {:.1}% | {:.3} | {} |",
                    fmt_ulp(r.max_ulp),
                    fmt_ulp(r.max_ulp_normal),
                    100.0 * r.identical / r.compared.max(1.0),
                    r.ratio,
                    r.excluded
                )),
                None => line.push_str(" - | - | - | - | - |"),
            }
        }
        outln!("{line}");
    }
    outln!(
        "\nWhy the stable forms: GGX D near n.h = 1 over 4096 cosines x 64 alphas (1e-3 to 1), \
         the twin and the textbook D_GGX (((n.h a^2 - n.h) n.h + 1)^2, as Unreal Engine 4 \
         writes it) on each adapter, against the CPU's correctly rounded `ggx::d`:\n"
    );
    outln!("| snapshot | form | bit-identical | max ULP | at (n.h, alpha) |");
    outln!("|---|---|---:|---:|---|");
    for s in &snaps {
        for [form, ident, ulp, at] in &s.ggx {
            outln!("| {} | {form} | {ident} | {ulp} | {at} |", s.name);
        }
    }
    let first = &snaps[0];
    outln!(
        "\nKernels of the reference table without a WGSL twin in the `{}` snapshot ({}), with \
         the reason (`brdf_gpu::shaders::NO_TWIN`; the `coverage` test fails for a kernel of the \
         shader families that has neither):\n",
        first.name,
        first.without.len()
    );
    for w in &first.without {
        outln!("- {w}");
    }
}
