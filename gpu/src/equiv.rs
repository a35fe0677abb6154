//! The equivalence run: every twin on the GPU over its rows, against the CPU's `f32` result,
//! each value held to the bound [`crate::bound`] derives from the twin's own IR.
//!
//! For a row x (`f32` arguments), let X be the exact value of the WGSL form with its `f32`
//! constants (the interpreter's `f64` value, to about 2^-50) and B its bound: the GPU's g
//! lies within B of X, so |g - c32| <= B + |X - c32| for the CPU's `f32` result c32, and that
//! is what each value is held to. That is only a test of the twin if X is the Rust kernel's
//! value: X must lie within B of the Rust kernel's `f64` result c64 (or, where the `f32`
//! kernel's guards part from the `f64` kernel's by design, within B + [`TWIN_ULP`] ULP of
//! c32). A wrong formula or a missed clamp fails there, on the CPU alone.

use crate::bound::{Interp, Num, ulp32};
use crate::device::Gpu;
use crate::shaders::{Family, Twin, compute_shader};
use brdf_ref::Float;
use brdf_ref::points::{extreme_rows, random_rows};

/// Rows of extremes per kernel (the product of each argument's extremes, drawn down to this).
pub const EXTREME_ROWS: usize = 4096;
/// Random in-domain rows per kernel.
pub const RANDOM_ROWS: usize = 16_384;
/// Random rows per kernel whose cosine-like arguments sit near 0 and 1 (where the stable
/// forms matter).
pub const NEAR_END_ROWS: usize = 8192;

/// How far (in ULP of the CPU's f32 result) the twin's exact value may lie from the Rust
/// f32 kernel's result beyond its bound, where it is not near the f64 kernel's: the crate's
/// f32 kernels are documented within a few ULP of their exact values (README, "Accuracy
/// promises"), 16 leaves room for the least accurate.
pub const TWIN_ULP: f64 = 16.0;

/// One kernel's figures.
#[derive(Clone, Debug, Default)]
pub struct Figures {
    /// The kernel's path.
    pub path: String,
    /// Rows run.
    pub rows: usize,
    /// Output values compared.
    pub compared: usize,
    /// Compared values equal to the CPU's bit for bit.
    pub identical: usize,
    /// Largest ULP distance from the CPU's `f32`.
    pub max_ulp: u64,
    /// Largest ULP distance over the values whose row's arguments and whose GPU and CPU
    /// results are all 0 or normal `f32` numbers: where no flush of a subnormal to 0 (which
    /// WGSL allows, and GPUs do) can be the cause.
    pub max_ulp_normal: u64,
    /// The bound at the row of the largest ULP distance, in ULP of the CPU value.
    pub bound_ulp_at_max: f64,
    /// Smallest bound over the compared values, in ULP of the CPU value.
    pub min_bound_ulp: f64,
    /// Largest measured / bound.
    pub max_ratio: f64,
    /// Where it was reached: the row, the GPU's and the CPU's f32 values.
    pub worst: Option<(Vec<f64>, f32, f32)>,
    /// Values outside their bound (failures), with a description of the first few.
    pub outside: usize,
    /// Values whose twin differs from the Rust kernel by more than the bound on the CPU.
    pub twin_differs: usize,
    /// Values not compared, by reason: the reason, the count, the first row excluded for it.
    pub excluded: Vec<(String, usize, Vec<f64>)>,
    /// The first few failures, described.
    pub failures: Vec<String>,
}

impl Figures {
    /// Values excluded, all reasons together.
    #[must_use]
    pub fn excluded_total(&self) -> usize {
        self.excluded.iter().map(|(_, n, _)| n).sum()
    }

    fn exclude(&mut self, why: &str, n: usize, row: &[f64]) {
        match self.excluded.iter_mut().find(|(w, _, _)| w == why) {
            Some((_, c, _)) => *c += n,
            None => self.excluded.push((why.to_string(), n, row.to_vec())),
        }
    }

    fn fail(&mut self, text: String) {
        if self.failures.len() < 5 {
            self.failures.push(text);
        }
    }
}

/// A grid: the values of each argument, by name.
pub type Grid = &'static [(&'static str, &'static [f64])];

/// Grids of stability cases, by family (a kernel path's prefix) and argument name: every
/// combination of the listed values is a row. The thin film: thickness 0 (the bare base),
/// inside the 30 nm blend and at its maximum; a film index equal to the outside index (no top
/// interface) and at its maximum; a base index equal to the film's or the outside's, and below
/// them (total reflection inside the film); a conductor's k from 0 to 1e30; normal and grazing
/// incidence.
///
/// The engines' conventions (`engine::Convention`, every `convention`): perceptual roughness
/// 0, below every engine's floor (0.03), at the floors (Filament 0.045, three.js 0.0525, bevy
/// 0.089) and up to 1; n.v 0, below Filament's and bevy's floor 1e-4 and at it; n.l 0 and
/// 1e-5; n.h 0 and next to 1 (where the engines' own D forms cancel); v.h 0, 1e-4 and 1 (the
/// Fresnel weights' ends); F0 summing to 0, below 0.0606 (F90 < 1 in Filament and bevy) and
/// above; metallic 0 and 1.
///
/// The layered glTF material (`layers::layered::Layered`): each extension off (at its glTF
/// default, which must leave the base bit for bit) and on; a base with a channel of 1 (the
/// film over a base index capped at the largest f32), dielectric and metal, roughness 0 (the
/// alpha floor) and 1/2; the film's thickness 0 (off whatever its factor); a thin-walled and
/// a volumetric transmission; views at 16 and 37 degrees (in two azimuths, for the
/// anisotropy's rotation) and at the horizon; lights back-scattered, retro-reflected and
/// below the surface (the transmission lobe); the sampler's lobe choice across the four lobes.
/// No cosine is exactly 1 and no half vector the
/// normal: the sheen's twin raises 0 to a power there, which WGSL's pow (exp2 of log2) does
/// not promise.
pub const GRIDS: &[(&str, Grid)] = &[
    (
        "iridescence::",
        &[
            ("thickness", &[0.0, 1e-3, 29.9, 30.0, 300.0, 10_000.0]),
            ("ior", &[1.0, 1.33, 2.5, 10.0]),
            ("outside_ior", &[1.0, 1.33, 2.5]),
            ("base_ior", &[1.0, 1.33, 1.5, 0.3]),
            ("base_eta", &[1.0, 0.2, 1.5]),
            ("base_k", &[0.0, 3.0, 1e3, 1e30]),
            ("cos_theta", &[0.0, 1e-4, 0.5, 0.999_999_94, 1.0]),
        ],
    ),
    (
        "engine::Convention::alpha",
        &[
            ("convention", ENGINES),
            (
                "perceptual_roughness",
                &[
                    0.0,
                    1e-3,
                    0.01,
                    0.03,
                    0.045,
                    0.0525,
                    0.089,
                    0.1,
                    0.5,
                    0.999_999_94,
                    1.0,
                ],
            ),
        ],
    ),
    (
        "engine::Convention::f90",
        &[
            ("convention", ENGINES),
            ("f0_r", &[0.0, 1e-3, 0.004, 0.02, 0.04, 1.0]),
            ("f0_g", &[0.0, 1e-3, 0.004, 0.02, 0.04, 1.0]),
            ("f0_b", &[0.0, 1e-3, 0.004, 0.02, 0.04, 1.0]),
        ],
    ),
    (
        "engine::Convention::fresnel",
        &[
            ("convention", ENGINES),
            ("f0_r", &[0.0, 0.04, 1.0]),
            ("f0_g", &[0.0, 0.04, 1.0]),
            ("f0_b", &[0.0, 0.04, 1.0]),
            ("f90", &[0.0, 0.5, 1.0]),
            ("v_dot_h", &[0.0, 1e-4, 0.5, 0.999_999_94, 1.0]),
        ],
    ),
    (
        "engine::Convention::specular",
        &[
            ("convention", ENGINES),
            ("n_dot_v", &[0.0, 1e-5, 1e-4, 0.5, 1.0]),
            ("n_dot_l", &[0.0, 1e-5, 0.5, 1.0]),
            ("n_dot_h", &[0.0, 0.5, 0.999_999_94, 1.0]),
            ("v_dot_h", &[0.0, 1e-4, 1.0]),
            ("roughness", &[0.0, 0.03, 0.0525, 0.5, 1.0]),
            ("f0_r", &[0.0, 0.04, 1.0]),
            ("f0_g", &[0.5]),
            ("f0_b", &[0.5]),
            ("f90", &[0.0, 1.0]),
        ],
    ),
    (
        "engine::Convention::diffuse",
        &[
            ("convention", ENGINES),
            ("n_dot_v", &[0.0, 1e-5, 1e-4, 0.5, 1.0]),
            ("n_dot_l", &[0.0, 1e-5, 0.5, 1.0]),
            ("n_dot_h", &[0.5]),
            ("v_dot_h", &[0.0, 0.5, 1.0]),
            ("roughness", &[0.0, 0.03, 0.5, 1.0]),
            ("diffuse_color_r", &[0.0, 0.5, 1.0]),
            ("diffuse_color_g", &[0.5]),
            ("diffuse_color_b", &[1.0]),
        ],
    ),
    (
        "engine::Convention::brdf",
        &[
            ("convention", ENGINES),
            ("n_dot_v", &[0.0, 1e-5, 1e-4, 0.5, 1.0]),
            ("n_dot_l", &[0.0, 1e-5, 0.5, 1.0]),
            ("n_dot_h", &[0.5, 0.999_999_94, 1.0]),
            ("v_dot_h", &[0.0, 0.5, 1.0]),
            ("base_color_r", &[0.0, 0.01, 1.0]),
            ("base_color_g", &[0.01, 0.5]),
            ("base_color_b", &[0.02]),
            ("metallic", &[0.0, 1.0]),
            ("roughness", &[0.0, 0.0525, 1.0]),
        ],
    ),
    (
        "layers::layered::",
        &[
            ("base_color_r", &[0.9]),
            ("base_color_g", &[0.5]),
            ("base_color_b", &[1.0]),
            ("metallic", &[0.0, 1.0]),
            ("roughness", &[0.0, 0.5]),
            ("sheen_color_r", &[0.0, 0.8]),
            ("sheen_color_g", &[0.0]),
            ("sheen_color_b", &[0.0]),
            ("sheen_roughness", &[0.3]),
            ("clearcoat", &[0.0, 1.0]),
            ("clearcoat_roughness", &[0.1]),
            ("anisotropy_strength", &[0.0, 0.8]),
            ("anisotropy_rotation", &[0.5]),
            ("iridescence_factor", &[0.0, 1.0]),
            ("iridescence_thickness", &[0.0, 400.0]),
            ("iridescence_ior", &[1.3]),
            ("transmission", &[0.0, 1.0]),
            ("volume_thickness", &[0.0, 1.0]),
            ("volume_attenuation_color_r", &[1.0]),
            ("volume_attenuation_color_g", &[1.0]),
            ("volume_attenuation_color_b", &[1.0]),
            ("volume_attenuation_distance", &[1.0]),
            ("wo_x", &[0.0, 0.6, 1.0, 0.28]),
            ("wo_y", &[0.0, 0.6]),
            ("wo_z", &[0.0, 0.8, 0.96]),
            ("wi_x", &[-0.8, 0.6]),
            ("wi_y", &[0.0]),
            ("wi_z", &[0.6, -0.6, 0.8, -0.8]),
            ("u1", &[0.02, 0.3, 0.6, 0.97]),
            ("u2", &[0.3]),
        ],
    ),
];

/// Every choice of `engine::Convention`'s receiver (an index into `engine::ALL`).
const ENGINES: &[f64] = &[0.0, 1.0, 2.0, 3.0, 4.0];

/// The rows of [`GRIDS`] for `k` (none where no grid names its family), in `f32`.
///
/// # Panics
/// If a grid lacks one of the kernel's arguments.
#[must_use]
pub fn grid_rows(k: &brdf_ref::Kernel) -> Vec<Vec<f64>> {
    let Some((_, grid)) = GRIDS.iter().find(|(p, _)| k.path.starts_with(p)) else {
        return Vec::new();
    };
    let mut rows = vec![Vec::new()];
    for a in k.args {
        let (_, values) = grid
            .iter()
            .find(|(n, _)| *n == a.name)
            .unwrap_or_else(|| panic!("{}: the grid has no {}", k.path, a.name));
        rows = rows
            .into_iter()
            .flat_map(|r| {
                values.iter().map(move |&x| {
                    let mut r = r.clone();
                    #[allow(clippy::cast_possible_truncation)]
                    r.push(f64::from(x as f32));
                    r
                })
            })
            .collect();
    }
    rows.retain(|r| k.broken_constraint(r, Float::F32).is_none());
    rows
}

/// The rows of a kernel: extremes, random rows, random rows with cosines near 0 and 1, its
/// family's grid of stability cases ([`GRIDS`]), all in `f32`.
#[must_use]
pub fn rows(k: &brdf_ref::Kernel) -> Vec<Vec<f64>> {
    let mut rows = extreme_rows(k, Float::F32, EXTREME_ROWS);
    rows.extend(grid_rows(k));
    rows.extend(random_rows(k, Float::F32, RANDOM_ROWS, 1));
    let near = |j: u32, up: bool| {
        let t = f64::powi(2.0, -i32::try_from(j).expect("small"));
        f64::from((if up { 1.0 - t } else { t }) as f32)
    };
    let unit_like = |d: &brdf_ref::Domain| d.lo >= -1.0 && d.hi <= 1.0 && !d.integer;
    for (i, mut r) in random_rows(k, Float::F32, NEAR_END_ROWS, 2)
        .into_iter()
        .enumerate()
    {
        let mut changed = false;
        for (j, a) in k.args.iter().enumerate() {
            // A unit vector's components stay as drawn (their length is a constraint).
            if unit_like(&a.domain) && a.domain != brdf_ref::Domain::DIR {
                let sel = (i * 7 + j * 13) % 48;
                #[allow(clippy::cast_possible_truncation)]
                let v = near(1 + (sel % 24) as u32, sel >= 24);
                if a.domain.contains_as(v, Float::F32) {
                    r[j] = v;
                    changed = true;
                }
            }
        }
        if changed && k.broken_constraint(&r, Float::F32).is_none() {
            rows.push(r);
        }
    }
    rows
}

/// ULP distance between two finite `f32`.
#[must_use]
pub fn ulp_distance(a: f32, b: f32) -> u64 {
    let ord = |x: f32| {
        let b = x.to_bits();
        let m = i64::from(b & 0x7FFF_FFFF);
        if b >> 31 == 1 { -m } else { m }
    };
    (ord(a) - ord(b)).unsigned_abs()
}

/// The CPU side of one row: the interpreter's value and bound per output, the CPU's `f32`
/// and `f64` results, or why the row is not compared.
pub struct CpuRow {
    /// Interpreter values and bounds.
    pub form: Vec<Num>,
    /// The Rust kernel on `f32`.
    pub c32: Vec<f32>,
    /// The Rust kernel on `f64`, on the same (f32) arguments.
    pub c64: Vec<f64>,
}

/// The CPU side of `row` for `twin`.
///
/// # Errors
/// Why WGSL promises nothing for this row.
pub fn cpu_row(twin: &Twin, interp: &mut Interp<'_>, row: &[f64]) -> Result<CpuRow, String> {
    let k = twin.kernel;
    if row.iter().any(|x| !x.is_finite()) {
        return Err("an infinite argument".into());
    }
    #[allow(clippy::cast_possible_truncation)]
    let r32: Vec<f32> = row.iter().map(|&x| x as f32).collect();
    let r64: Vec<f64> = r32.iter().map(|&x| f64::from(x)).collect();
    let mut c32 = vec![0.0f32; k.outputs.len()];
    let mut c64 = vec![0.0f64; k.outputs.len()];
    (k.f32)(&r32, &mut c32);
    (k.f64)(&r64, &mut c64);
    if c32.iter().any(|x| !x.is_finite()) || c64.iter().any(|x| !x.is_finite()) {
        return Err("the CPU result is not finite".into());
    }
    let form = interp.run(&twin.name, &r64).map_err(str::to_string)?;
    if form
        .iter()
        .any(|n| n.v != 0.0 && n.v.abs() < f64::from(f32::MIN_POSITIVE))
    {
        return Err("the result is subnormal".into());
    }
    Ok(CpuRow { form, c32, c64 })
}

/// Runs `twin` on the GPU over `rows` and holds every value to its bound.
#[must_use]
pub fn run_kernel(gpu: &Gpu, twin: &Twin, families: &[Family], rows: &[Vec<f64>]) -> Figures {
    let k = twin.kernel;
    let no = k.outputs.len();
    let module = &families[twin.family].module;
    let mut interp = Interp::new(module);
    let mut fig = Figures {
        path: k.path.to_string(),
        rows: rows.len(),
        min_bound_ulp: f64::INFINITY,
        ..Figures::default()
    };
    #[allow(clippy::cast_possible_truncation)]
    let inputs: Vec<f32> = rows.iter().flatten().map(|&x| x as f32).collect();
    let gpu_out = gpu.run(&compute_shader(twin, families), &inputs, rows.len(), no);
    let normal = |x: f64| x == 0.0 || x.abs() >= f64::from(f32::MIN_POSITIVE);
    for (i, row) in rows.iter().enumerate() {
        #[allow(clippy::cast_possible_truncation)]
        let row_normal = row.iter().all(|&x| normal(f64::from(x as f32)));
        let cpu = match cpu_row(twin, &mut interp, row) {
            Ok(c) => c,
            Err(why) => {
                fig.exclude(&why, no, row);
                continue;
            }
        };
        for o in 0..no {
            let g = gpu_out[i * no + o];
            // The f64 kernel caps poles at f64's largest value, the f32 one (and the twin) at
            // f32's: the same cap, in the type at hand.
            let max32 = f64::from(f32::MAX);
            let (f, c32, c64) = (cpu.form[o], cpu.c32[o], cpu.c64[o].clamp(-max32, max32));
            // The twin is the same function where its exact value lies within its bound of
            // the Rust kernel's: the f64 kernel's, or, where the f32 kernel's guards differ
            // from the f64 kernel's by design (a floor at f32's smallest normal, f32's
            // underflow), the f32 kernel's within TWIN_ULP more.
            let near64 = (f.v - c64).abs() <= f.e + f64::from(f32::MIN_POSITIVE);
            let near32 = (f.v - f64::from(c32)).abs() <= f.e + TWIN_ULP * ulp32(f64::from(c32));
            if !(near64 || near32) {
                fig.twin_differs += 1;
                fig.fail(format!(
                    "{} row {row:?} output {o}: the WGSL form is {} where the Rust kernel gives \
                     {c32} (f32), {c64} (f64); bound {}",
                    k.path, f.v, f.e
                ));
            }
            // |g - c32| <= |g - X| + |X - c32| <= B + |X - c32|, with a hair of slack for
            // the f64 arithmetic of this sum (a GPU taking the other side of an uncertain
            // select lands exactly on the bound).
            let allowed = (f.e + (f.v - f64::from(c32)).abs()) * (1.0 + f64::powi(2.0, -40))
                + f64::from(f32::from_bits(1));
            fig.compared += 1;
            if !g.is_finite() {
                fig.outside += 1;
                fig.fail(format!("{} row {row:?} output {o}: GPU gave {g}", k.path));
                continue;
            }
            let diff = (f64::from(g) - f64::from(c32)).abs();
            let ulp = ulp_distance(g, c32);
            if ulp == 0 {
                fig.identical += 1;
            }
            if row_normal && normal(f64::from(g)) && normal(f64::from(c32)) {
                fig.max_ulp_normal = fig.max_ulp_normal.max(ulp);
            }
            let unit = ulp32(f64::from(c32));
            let bound_ulp = allowed / unit;
            fig.min_bound_ulp = fig.min_bound_ulp.min(bound_ulp);
            // The first value, or a new largest distance.
            if ulp > fig.max_ulp || fig.bound_ulp_at_max == 0.0 {
                fig.max_ulp = ulp;
                fig.bound_ulp_at_max = bound_ulp;
            }
            let ratio = diff / allowed;
            if ratio > fig.max_ratio {
                fig.max_ratio = ratio;
                fig.worst = Some((row.clone(), g, c32));
            }
            if ratio > 1.0 {
                fig.outside += 1;
                fig.fail(format!(
                    "{} row {row:?} output {o}: GPU {g}, CPU f32 {c32} ({ulp} ULP), bound \
                     {bound_ulp:.2} ULP",
                    k.path
                ));
            }
        }
    }
    fig
}

/// Today's date (UTC) as YYYY-MM-DD, from the system clock (Hinnant's days-to-civil
/// algorithm).
#[must_use]
pub fn today_utc() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let z = i64::try_from(secs / 86_400).unwrap_or(0) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

/// The figures of every twin as a Markdown table.
#[must_use]
pub fn markdown(adapter: &str, figs: &[Figures], without: &[&str]) -> String {
    let mut s = format!(
        "# WGSL twins against the CPU\n\nAdapter: {adapter}\n\nDate: {date} (UTC); \
         `brdf-gpu-equiv`, rows per kernel: its argument extremes (up to {EXTREME_ROWS}), \
         {RANDOM_ROWS} random rows, up to {NEAR_END_ROWS} rows with cosines near 0 and 1, and the \
         grids of stability cases (`GRIDS`: the thin film, the engines' conventions, the \
         layered material).\n\n\
         Each value g is held to |g - c32| <= B + |X - c32|: B the bound the WGSL accuracy \
         table gives the twin's form at that input, X the form's exact value, c32 the CPU's \
         f32 result; bounds in ULP of c32. \"max ULP, normal\" is the largest distance over \
         the values whose arguments and results (GPU and CPU) are all 0 or normal, where no \
         flush of a subnormal to 0 is involved.\n\n\
         | kernel | rows | compared | bit-identical | max ULP | max ULP, normal | \
         bound at max (ULP) | min bound (ULP) | max measured / bound | excluded | \
         outside bound |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        date = today_utc()
    );
    for f in figs {
        s += &format!(
            "| `{}` | {} | {} | {} | {} | {} | {} | {} | {:.3} | {} | {} |\n",
            f.path,
            f.rows,
            f.compared,
            share(f.identical, f.compared),
            f.max_ulp,
            f.max_ulp_normal,
            ulps(f.bound_ulp_at_max),
            ulps(f.min_bound_ulp),
            f.max_ratio,
            f.excluded_total(),
            f.outside + f.twin_differs,
        );
    }
    s += "\nExcluded values, by reason (WGSL promises nothing there), with the first row \
          excluded for it (the arguments in the kernel's order):\n\n";
    for f in figs {
        for (why, n, row) in &f.excluded {
            s += &format!("- `{}`: {n}, {why}: {row:?}\n", f.path);
        }
    }
    s += "\nWhere each kernel came closest to its bound (the row, the GPU's value, the CPU's \
          f32 value):\n\n";
    for f in figs {
        if let Some((row, g, c)) = &f.worst {
            s += &format!(
                "- `{}`: {:.3} of the bound at {row:?}: GPU {g:e}, CPU {c:e}\n",
                f.path, f.max_ratio
            );
        }
    }
    s += &format!(
        "\nKernels of the reference table without a WGSL twin ({}), with the reason:\n\n",
        without.len()
    );
    for p in without {
        let why = crate::shaders::no_twin_reason(p).unwrap_or("no reason recorded");
        s += &format!("- `{p}`: {why}\n");
    }
    s
}

/// The figures as CSV.
#[must_use]
pub fn csv(figs: &[Figures]) -> String {
    let mut s = String::from(
        "kernel,rows,compared,bit_identical,max_ulp,bound_ulp_at_max,min_bound_ulp,\
         max_ratio,excluded,outside_bound,max_ulp_normal\n",
    );
    for f in figs {
        s += &format!(
            "{},{},{},{},{},{},{},{},{},{},{}\n",
            f.path,
            f.rows,
            f.compared,
            f.identical,
            f.max_ulp,
            f.bound_ulp_at_max,
            f.min_bound_ulp,
            f.max_ratio,
            f.excluded_total(),
            f.outside + f.twin_differs,
            f.max_ulp_normal
        );
    }
    s
}

fn share(n: usize, of: usize) -> String {
    if of == 0 {
        return "-".into();
    }
    #[allow(clippy::cast_precision_loss)]
    let p = 100.0 * n as f64 / of as f64;
    format!("{p:.1}%")
}

fn ulps(x: f64) -> String {
    if !x.is_finite() {
        "-".into()
    } else if x >= 1e4 {
        format!("{x:.1e}")
    } else {
        format!("{x:.2}")
    }
}
