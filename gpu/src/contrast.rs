//! Why the stable forms: GGX D in the crate's form and in the textbook form engines ship, run
//! on the same adapter against the CPU's correctly rounded `ggx::d`.
//!
//! The textbook form (Walter et al. 2007, eq. 33, as Unreal Engine 4's `D_GGX` writes it,
//! Karis 2013) is a^2 / (pi ((c a^2 - c) c + 1)^2): near c = 1 the sum (c a^2 - c) c + 1
//! cancels to about a^2 and keeps few of its digits in `f32` for small a. The crate's twin
//! `ggx_d` forms it as (1 - c)(1 + c) + c^2 a^2, which does not cancel.

use crate::device::Gpu;
use crate::equiv::ulp_distance;

/// Cosines of the grid: i / 4096 for i = 1..=4096 (n.h in (0, 1]).
pub const COSINES: usize = 4096;
/// Widths of the grid: 64 values log-spaced over [1e-3, 1].
pub const ALPHAS: usize = 64;

/// The figures of one form over the grid.
#[derive(Clone, Debug)]
pub struct Form {
    /// The form's name.
    pub name: &'static str,
    /// Values bit-identical to the CPU's `ggx::d` in `f32`.
    pub identical: usize,
    /// Values compared (the grid's size).
    pub compared: usize,
    /// Largest ULP distance from the CPU.
    pub max_ulp: u64,
    /// Where: (n.h, alpha).
    pub worst: (f32, f32),
}

const TEXTBOOK: &str = "
fn textbook_d_ggx(n_dot_h: f32, alpha: f32) -> f32 {
    let a2 = alpha * alpha;
    let f = (n_dot_h * a2 - n_dot_h) * n_dot_h + 1.0;
    return a2 / (3.14159265358979 * f * f);
}
";

/// The grid, as (n.h, alpha) rows.
#[must_use]
pub fn grid() -> Vec<[f32; 2]> {
    let mut rows = Vec::with_capacity(COSINES * ALPHAS);
    for j in 0..ALPHAS {
        #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
        let alpha = 10f64.powf(-3.0 + 3.0 * j as f64 / (ALPHAS - 1) as f64) as f32;
        for i in 1..=COSINES {
            #[allow(clippy::cast_precision_loss)]
            let c = i as f32 / COSINES as f32;
            rows.push([c, alpha]);
        }
    }
    rows
}

/// Both forms on `gpu` over [`grid`], against the CPU's `ggx::d`.
#[must_use]
pub fn run(gpu: &Gpu) -> [Form; 2] {
    let rows = grid();
    let inputs: Vec<f32> = rows.iter().flatten().copied().collect();
    let cpu: Vec<f32> = rows.iter().map(|r| brdf::ggx::d(r[0], r[1])).collect();
    let shader = |call: &str, extra: &str| {
        format!(
            "{}{}{extra}
@group(0) @binding(0) var<storage, read> brdf_in: array<f32>;
@group(0) @binding(1) var<storage, read_write> brdf_out: array<f32>;

@compute @workgroup_size({})
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {{
    let i = gid.x;
    if i >= arrayLength(&brdf_out) {{
        return;
    }}
    brdf_out[i] = {call}(brdf_in[2u * i], brdf_in[2u * i + 1u]);
}}
",
            brdf::wgsl::COMMON,
            brdf::wgsl::GGX,
            crate::shaders::WORKGROUP
        )
    };
    let forms = [
        ("brdf::wgsl ggx_d", shader("ggx_d", "")),
        ("textbook D_GGX", shader("textbook_d_ggx", TEXTBOOK)),
    ];
    forms.map(|(name, src)| {
        let out = gpu.run(&src, &inputs, rows.len(), 1);
        let mut f = Form {
            name,
            identical: 0,
            compared: rows.len(),
            max_ulp: 0,
            worst: (0.0, 0.0),
        };
        for ((g, c), r) in out.iter().zip(&cpu).zip(&rows) {
            let u = if g.is_finite() {
                ulp_distance(*g, *c)
            } else {
                u64::MAX
            };
            if u == 0 {
                f.identical += 1;
            }
            if u > f.max_ulp {
                f.max_ulp = u;
                f.worst = (r[0], r[1]);
            }
        }
        f
    })
}

/// The two forms as a Markdown section.
#[must_use]
pub fn markdown(forms: &[Form]) -> String {
    let mut s = format!(
        "\n## Why the stable form: GGX D near n.h = 1\n\n{COSINES} cosines i / {COSINES} x \
         {ALPHAS} alphas log-spaced over [1e-3, 1], each form on this adapter against the CPU's \
         correctly rounded `ggx::d` in f32.\n\n\
         | form | bit-identical | max ULP | at (n.h, alpha) |\n|---|---:|---:|---|\n"
    );
    for f in forms {
        #[allow(clippy::cast_precision_loss)]
        let share = 100.0 * f.identical as f64 / f.compared as f64;
        s += &format!(
            "| {} | {share:.1}% | {} | ({}, {}) |\n",
            f.name, f.max_ulp, f.worst.0, f.worst.1
        );
    }
    s
}
