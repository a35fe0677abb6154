//! Question answered: how many elements per second does each kernel evaluate over
//! structure-of-arrays slices, on scalar `f32` / `f64` and on `f32x8` / `f64x4` lanes through
//! [`brdf::batch`], and how far is each figure from the memory floor of the same bytes?
//!
//! Run: `cargo bench -p brdf-bench --bench throughput` (about five minutes). For the figures a user of
//! `-C target-cpu=native` gets: `RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=target/native
//! cargo bench -p brdf-bench --bench throughput` (a separate target dir keeps both builds).
//!
//! Groups and rows: one group per kernel and batch size (`ggx_d/100000`, ...), with the rows
//! `f32`, `f64` (scalar, through `batch::run::<f32>` / `run::<f64>`: one element per call),
//! `f32x8`, `f64x4` (`batch::run_f32` / `run_f64`), and the floor rows (the scalar rows stop at
//! 10^6 elements: compute-bound, they run at the same `elem/s` at 10^7). Every row reports
//! `elem/s` (`Throughput::Elements`, one element = one BRDF evaluation), 10^3 to 10^7 elements
//! (10^3, 10^5 and 10^7 for the two full BRDFs). Inputs are cosines of random directions,
//! uniform on the hemisphere (fixed seed): n.h, n.v, n.l, v.h of a view and a light direction
//! and their half vector.
//!
//! The memory floor: the rows `copy_f32` / `copy_f64` (in the one-input groups: `out` filled
//! from the input slice by `copy_from_slice`, the same bytes a D kernel reads and writes) and
//! `floor_f32` / `floor_f64` (in the four-input groups: a `batch` pass over the same input and
//! output slices whose kernel only adds its inputs, so it moves the same bytes and computes
//! almost nothing). Read a kernel as a multiple of the floor by dividing the floor row's
//! `elem/s` by the kernel row's `elem/s` of the same group and float width (`f32` and `f32x8`
//! against `*_f32`, `f64` and `f64x4` against `*_f64`): 1.0 means the kernel runs at memory
//! speed, 3.0 that it takes three times as long as moving its bytes. At 10^3 and 10^4 the
//! slices sit in cache and the floor is a cache floor; at 10^7 (40 MB per `f32` slice) it is
//! the DRAM floor the issue of slice throughput is about.
//!
//! Kernels (parameters fixed, alpha = 0.3, the width, not perceptual roughness):
//! - `ggx_d`: `ggx::d(n.h, alpha)`; `beckmann_d`: `beckmann::d(n.h, alpha)`.
//! - `ggx_d_fast`, `beckmann_d_fast`: `ggx::d_fast`, `beckmann::d_fast` (working precision,
//!   their error against the exact forms in their docs).
//! - `rough_conductor`: D V F n.l with `cook_torrance::ggx` (GGX D, height-correlated Smith V)
//!   and `fresnel::conductor(v.h, 0.2, 3.0)`, one channel: what a renderer's BSDF evaluation
//!   returns (f times the cosine, as Mitsuba 3's `roughconductor` `eval` does).
//! - `rough_conductor_fast`: the same term with `ggx::d_fast` and `fresnel::conductor_fast`
//!   (V stays `ggx::v_correlated`).
//! - `ggx_lambert`: `cook_torrance::ggx` with `fresnel::schlick(0.04, v.h)` plus
//!   `diffuse::lambert(rho = 0.5)`, one channel.
//! - `material_gltf`: `material::gltf`, base colour (0.9, 0.6, 0.3), metallic 0.5, roughness
//!   0.5; three output slices (RGB).
//!
//! Side-by-side against Mitsuba 3 on the same batch: `bench/mitsuba/README.md`. For that
//! script this binary also has a timing mode, run when the environment variable
//! `BRDF_THROUGHPUT_INPUT` names a raw file (six little-endian `f32` arrays of equal length:
//! view x, y, z, then light x, y, z, unit vectors with z > 0): it times `ggx_d`, `ggx_d_plain`
//! (GGX D in working precision, no error-free transformations: a yardstick, not a crate kernel),
//! `ggx_d_fast`, `beckmann_d`, `beckmann_d_fast`,
//! `rough_conductor` and `rough_conductor_fast` (`cook_torrance::ggx_conductor_local` and
//! `ggx_conductor_local_fast` from the directions, times n.l), `rough_conductor_cosines` (from
//! the directions: half vector, cosines, then `cook_torrance::ggx` with `fresnel::conductor`),
//! `rough_conductor_cosines_fast` (the cosines of the half vector by
//! `cook_torrance::half_cosines`, then the fast term), `rough_conductor_fast_borrowed` (that
//! kernel as a closure that borrows its parameters instead of moving them: see the `batch`
//! module docs),
//! `material_gltf` and `material_gltf_fast` (`material::gltf` and `gltf_fast` from the
//! directions through `half_cosines`, base colour (0.9, 0.6, 0.3), metallic 0.5, roughness 0.5,
//! three output slices), `material_textbook_scalar` and `material_textbook_inlined` (the same
//! BRDF as a shader author transcribes Filament's `surface_brdf.fs` into scalar `f32`, called
//! once per element out of line, and inlined into the loop where LLVM may vectorize it:
//! yardsticks, not crate kernels) and the copy floor on `f32x8` with `std::time::Instant`, after one untimed run of each,
//! `BRDF_THROUGHPUT_RUNS` times (default 7), and prints one line per run:
//! `time <kernel> <milliseconds>`. With `BRDF_THROUGHPUT_PARALLEL=1` every `batch` row runs
//! through `batch::par_run_f32` on all cores (rayon's global pool; the textbook scalar row
//! and the copy stay on one thread). With `BRDF_THROUGHPUT_OUTPUT=<dir>` it also writes each
//! kernel's outputs there as raw `f32` (`<kernel>.f32`; the material rows' red channel), for
//! the script to compare values. `BRDF_THROUGHPUT_ONLY=<kernel>,<kernel>` runs only the kernels
//! named (to profile one with `perf record`). With `BRDF_THROUGHPUT_CLOCK=cpu` (one thread only)
//! each run is timed by the thread's CPU clock instead of the wall clock, which leaves out the
//! time the thread waited for a core on a shared machine.

use brdf::Cosines;
use brdf::microfacet::Alpha;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3, batch, beckmann, cook_torrance, diffuse, fresnel, ggx, material};
use criterion::{BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group};
use std::hint::black_box;
use std::time::{Duration, Instant};

const ALPHA: f64 = 0.3;
const ETA: f64 = 0.2;
const K: f64 = 3.0;
const F0: f64 = 0.04;
const RHO: f64 = 0.5;

/// GGX D of n.h.
#[inline]
fn ggx_d<T: Real>([nh]: [T; 1]) -> [T; 1] {
    [ggx::d(nh, T::splat(ALPHA))]
}

/// Beckmann D of n.h.
#[inline]
fn beckmann_d<T: Real>([nh]: [T; 1]) -> [T; 1] {
    [beckmann::d(nh, T::splat(ALPHA))]
}

/// GGX D of n.h in working precision.
#[inline]
fn ggx_d_fast<T: Real>([nh]: [T; 1]) -> [T; 1] {
    [ggx::d_fast(nh, T::splat(ALPHA))]
}

/// Beckmann D of n.h in working precision.
#[inline]
fn beckmann_d_fast<T: Real>([nh]: [T; 1]) -> [T; 1] {
    [beckmann::d_fast(nh, T::splat(ALPHA))]
}

/// D V F n.l of a rough conductor, one channel.
#[inline]
fn rough_conductor<T: Real>([nh, nv, nl, vh]: [T; 4]) -> [T; 1] {
    let f = fresnel::conductor(vh, T::splat(ETA), T::splat(K));
    [cook_torrance::ggx(
        Cosines {
            n_dot_v: nv,
            n_dot_l: nl,
            n_dot_h: nh,
            v_dot_h: vh,
        },
        Alpha(T::splat(ALPHA)),
        f,
    ) * nl.saturate()]
}

/// The rough conductor of [`rough_conductor`] with the working-precision D and F:
/// `ggx::d_fast` times `ggx::v_correlated` times `fresnel::conductor_fast`, times n.l.
#[inline]
fn rough_conductor_fast<T: Real>([nh, nv, nl, vh]: [T; 4]) -> [T; 1] {
    let a = T::splat(ALPHA);
    let f = fresnel::conductor_fast(vh, T::splat(ETA), T::splat(K));
    [fast_term(nh, nv, nl, a, f) * nl.saturate()]
}

/// D V F with `ggx::d_fast`, assembled like `cook_torrance::ggx` (D V capped, then times F,
/// capped): 0 below either horizon, NaN for NaN cosines.
#[inline]
fn fast_term<T: Real>(nh: T, nv: T, nl: T, a: T, f: T) -> T {
    let v = ((ggx::d_fast(nh, a) * ggx::v_correlated(nv, nl, a)).min(T::MAX) * f).min(T::MAX);
    let above = nv.simd_gt(T::ZERO) & nl.simd_gt(T::ZERO);
    let nan = nv.is_nan() | nl.is_nan();
    T::select(above, v, T::select(nan, T::splat(f64::NAN), T::ZERO))
}

/// GGX Cook-Torrance with Schlick's F plus Lambert, one channel.
#[inline]
fn ggx_lambert<T: Real>([nh, nv, nl, vh]: [T; 4]) -> [T; 1] {
    let a = T::splat(ALPHA);
    let spec = cook_torrance::ggx(
        Cosines {
            n_dot_v: nv,
            n_dot_l: nl,
            n_dot_h: nh,
            v_dot_h: vh,
        },
        Alpha(a),
        fresnel::schlick(T::splat(F0), vh),
    );
    [spec + diffuse::lambert(nv, nl, T::splat(RHO))]
}

/// The glTF metallic-roughness material, RGB.
#[inline]
fn material_gltf<T: Real>([nh, nv, nl, vh]: [T; 4]) -> [T; 3] {
    let base = V3::new(T::splat(0.9), T::splat(0.6), T::splat(0.3));
    let f = material::gltf(
        Cosines {
            n_dot_v: nv,
            n_dot_l: nl,
            n_dot_h: nh,
            v_dot_h: vh,
        },
        base,
        T::splat(0.5),
        T::splat(0.5),
    );
    [f.x, f.y, f.z]
}

/// The floor kernel: reads every input, writes every output, one addition per element.
#[inline]
fn floor_pass<T: Real, const O: usize>([a, b, c, d]: [T; 4]) -> [T; O] {
    [(a + b) + (c + d); O]
}

/// SplitMix64 (Steele, Lea and Flood 2014): a fixed-seed stream of uniforms in [0, 1).
struct SplitMix(u64);

impl SplitMix {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A direction uniform on the upper hemisphere (z = u1, phi = 2 pi u2).
    fn hemisphere(&mut self) -> [f64; 3] {
        let z = self.uniform();
        let phi = 2.0 * std::f64::consts::PI * self.uniform();
        let s = ((1.0 - z) * (1.0 + z)).sqrt();
        [s * phi.cos(), s * phi.sin(), z]
    }
}

/// SoA cosines n.h, n.v, n.l, v.h of `n` random (view, light) pairs, in f64 and f32.
fn cosines(n: usize) -> ([Vec<f64>; 4], [Vec<f32>; 4]) {
    let mut rng = SplitMix(0x5eed_0013);
    let mut c64: [Vec<f64>; 4] = core::array::from_fn(|_| Vec::with_capacity(n));
    for _ in 0..n {
        let (v, l) = (rng.hemisphere(), rng.hemisphere());
        let h = [v[0] + l[0], v[1] + l[1], v[2] + l[2]];
        let len = (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]).sqrt();
        let h = h.map(|x| x / len);
        let vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
        for (s, x) in c64.iter_mut().zip([h[2], v[2], l[2], vh]) {
            s.push(x);
        }
    }
    let c32 = core::array::from_fn(|k| c64[k].iter().map(|&x| x as f32).collect());
    (c64, c32)
}

/// Groups `name/<n>` for every n in `sizes`: the kernel on the four lane types, and the floor.
fn group<const I: usize, const O: usize>(
    c: &mut Criterion,
    name: &str,
    sizes: &[usize],
    data: &([Vec<f64>; 4], [Vec<f32>; 4]),
    kernels: Kernels<I, O>,
) {
    let nmax = *sizes.iter().max().unwrap_or(&0);
    let mut out64: [Vec<f64>; O] = core::array::from_fn(|_| vec![0.0; nmax]);
    let mut out32: [Vec<f32>; O] = core::array::from_fn(|_| vec![0.0; nmax]);
    for &n in sizes {
        let mut g = c.benchmark_group(format!("{name}/{n}"));
        g.sampling_mode(SamplingMode::Flat)
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_millis(1500))
            .throughput(Throughput::Elements(n as u64));
        let in64: [&[f64]; I] = core::array::from_fn(|k| &data.0[k][..n]);
        let in32: [&[f32]; I] = core::array::from_fn(|k| &data.1[k][..n]);
        let mut o64: [&mut [f64]; O] = out64.each_mut().map(|v| &mut v[..n]);
        let mut o32: [&mut [f32]; O] = out32.each_mut().map(|v| &mut v[..n]);
        macro_rules! row {
            ($label:expr, $ins:expr, $outs:expr, $run:expr) => {
                g.bench_function(BenchmarkId::from_parameter($label), |b| {
                    b.iter(|| {
                        let outs = $outs.each_mut().map(|s| &mut **s);
                        $run(black_box($ins), outs).unwrap_or(0)
                    })
                });
            };
        }
        if n <= SCALAR_MAX {
            row!("f32", in32, o32, |i, o| batch::run::<f32, I, O>(
                i,
                o,
                kernels.f32
            ));
            row!("f64", in64, o64, |i, o| batch::run::<f64, I, O>(
                i,
                o,
                kernels.f64
            ));
        }
        row!("f32x8", in32, o32, |i, o| batch::run_f32(
            i,
            o,
            kernels.f32x8
        ));
        row!("f64x4", in64, o64, |i, o| batch::run_f64(
            i,
            o,
            kernels.f64x4
        ));
        match kernels.floor {
            Floor::Copy => {
                row!(
                    "copy_f32",
                    in32,
                    o32,
                    |i: [&[f32]; I], o: [&mut [f32]; O]| {
                        for (dst, src) in o.into_iter().zip(i) {
                            dst.copy_from_slice(src);
                        }
                        Ok::<usize, ()>(n)
                    }
                );
                row!(
                    "copy_f64",
                    in64,
                    o64,
                    |i: [&[f64]; I], o: [&mut [f64]; O]| {
                        for (dst, src) in o.into_iter().zip(i) {
                            dst.copy_from_slice(src);
                        }
                        Ok::<usize, ()>(n)
                    }
                );
            }
            Floor::Pass(p32, p64) => {
                row!("floor_f32", in32, o32, |i, o| batch::run_f32(i, o, p32));
                row!("floor_f64", in64, o64, |i, o| batch::run_f64(i, o, p64));
            }
        }
        g.finish();
    }
}

/// The floor a group is measured against.
enum Floor<const I: usize, const O: usize> {
    /// Inputs copied to outputs (one input, one output).
    Copy,
    /// A `batch` pass over the same slices that only adds its inputs.
    Pass(fn([f32x8; I]) -> [f32x8; O], fn([f64x4; I]) -> [f64x4; O]),
}

/// One kernel instantiated on the four lane types, and its floor.
struct Kernels<const I: usize, const O: usize> {
    f32: fn([f32; I]) -> [f32; O],
    f64: fn([f64; I]) -> [f64; O],
    f32x8: fn([f32x8; I]) -> [f32x8; O],
    f64x4: fn([f64x4; I]) -> [f64x4; O],
    floor: Floor<I, O>,
}

/// The scalar rows stop at 10^6: a scalar loop is compute-bound from 10^3 on (its `elem/s` at
/// 10^7 equals that at 10^6), and ten samples of 10^7 scalar evaluations take minutes.
const SCALAR_MAX: usize = 1_000_000;
const ALL: [usize; 5] = [1_000, 10_000, 100_000, 1_000_000, 10_000_000];
const FEW: [usize; 3] = [1_000, 100_000, 10_000_000];

fn bench_throughput(c: &mut Criterion) {
    let data = cosines(10_000_000);
    let nh = (
        [data.0[0].clone(), vec![], vec![], vec![]],
        [data.1[0].clone(), vec![], vec![], vec![]],
    );
    macro_rules! kernels {
        ($k:ident, $floor:expr) => {
            Kernels {
                f32: $k::<f32>,
                f64: $k::<f64>,
                f32x8: $k::<f32x8>,
                f64x4: $k::<f64x4>,
                floor: $floor,
            }
        };
    }
    group(c, "ggx_d", &ALL, &nh, kernels!(ggx_d, Floor::Copy));
    group(
        c,
        "ggx_d_fast",
        &ALL,
        &nh,
        kernels!(ggx_d_fast, Floor::Copy),
    );
    group(
        c,
        "beckmann_d",
        &ALL,
        &nh,
        kernels!(beckmann_d, Floor::Copy),
    );
    group(
        c,
        "beckmann_d_fast",
        &ALL,
        &nh,
        kernels!(beckmann_d_fast, Floor::Copy),
    );
    let pass1 = Floor::Pass(floor_pass::<f32x8, 1>, floor_pass::<f64x4, 1>);
    group(
        c,
        "rough_conductor",
        &ALL,
        &data,
        kernels!(rough_conductor, pass1),
    );
    let pass1 = Floor::Pass(floor_pass::<f32x8, 1>, floor_pass::<f64x4, 1>);
    group(
        c,
        "rough_conductor_fast",
        &ALL,
        &data,
        kernels!(rough_conductor_fast, pass1),
    );
    let pass1 = Floor::Pass(floor_pass::<f32x8, 1>, floor_pass::<f64x4, 1>);
    group(c, "ggx_lambert", &FEW, &data, kernels!(ggx_lambert, pass1));
    let pass3 = Floor::Pass(floor_pass::<f32x8, 3>, floor_pass::<f64x4, 3>);
    group(
        c,
        "material_gltf",
        &FEW,
        &data,
        kernels!(material_gltf, pass3),
    );
}

criterion_group!(benches, bench_throughput);

/// GGX D in working precision, alpha^2 / (pi (1 + c^2 (alpha^2 - 1))^2) for c > 0, without
/// the crate's error-free transformations or guards: not a crate kernel, a yardstick for what
/// `ggx::d`'s 0.5-ULP rounding costs in the timing mode.
#[inline]
fn ggx_d_plain<T: Real>(c: T, alpha: T) -> T {
    let a2 = alpha * alpha;
    let t = (c * c).mul_add(a2 - T::ONE, T::ONE);
    T::select(c.simd_gt(T::ZERO), a2 / (T::PI * t * t), T::ZERO)
}

/// The material rows' parameters: base colour, metallic and perceptual roughness (alpha =
/// 0.25), as `material_gltf`'s.
const MATERIAL_BASE: [f32; 3] = [0.9, 0.6, 0.3];
const MATERIAL_METALLIC: f32 = 0.5;
const MATERIAL_ROUGHNESS: f32 = 0.5;

/// The glTF 2.0 metallic-roughness BRDF (Appendix B's composition, the same function as
/// `material::gltf`) written as a shader author transcribes Filament's `surface_brdf.fs` into
/// scalar `f32`: `D_GGX` with 1 - (n.h)^2 formed as written (it cancels near n.h = 1),
/// `V_SmithGGXCorrelated`, `F_Schlick` with pow5 by multiplications, `Fd_Lambert`, from the
/// view and light directions (normal +z). Not a crate kernel: the textbook row of the timing
/// mode, against which the crate's lanes are measured: called once per element
/// (`material_textbook_scalar`, kept out of line so that it stays one element at a time) and
/// inlined into the loop (`material_textbook_inlined`, which LLVM may vectorize on its own).
#[inline(always)]
fn material_textbook(v: [f32; 3], l: [f32; 3]) -> [f32; 3] {
    let s = [v[0] + l[0], v[1] + l[1], v[2] + l[2]];
    let inv = 1.0 / (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
    let h = [s[0] * inv, s[1] * inv, s[2] * inv];
    let no_v = v[2];
    let no_l = l[2];
    if no_v <= 0.0 || no_l <= 0.0 {
        return [0.0; 3];
    }
    let no_h = h[2].clamp(0.0, 1.0);
    let vo_h = (v[0] * h[0] + v[1] * h[1] + v[2] * h[2]).clamp(0.0, 1.0);
    let roughness = MATERIAL_ROUGHNESS * MATERIAL_ROUGHNESS;
    // D_GGX
    let one_minus_no_h2 = 1.0 - no_h * no_h;
    let a = no_h * roughness;
    let k = roughness / (one_minus_no_h2 + a * a);
    let d = k * k * (1.0 / core::f32::consts::PI);
    // V_SmithGGXCorrelated
    let a2 = roughness * roughness;
    let ggxv = no_l * (no_v * no_v * (1.0 - a2) + a2).sqrt();
    let ggxl = no_v * (no_l * no_l * (1.0 - a2) + a2).sqrt();
    let vis = 0.5 / (ggxv + ggxl);
    // F_Schlick(f0, 1, v.h), pow5 by multiplications
    let x = 1.0 - vo_h;
    let x2 = x * x;
    let w = x2 * x2 * x;
    let f_dielectric = 0.04 + (1.0 - 0.04) * w;
    let kd = (1.0 - MATERIAL_METALLIC) * (1.0 - f_dielectric);
    MATERIAL_BASE.map(|b| {
        let f0 = 0.04 * (1.0 - MATERIAL_METALLIC) + b * MATERIAL_METALLIC;
        let f = f0 + (1.0 - f0) * w;
        kd * b * (1.0 / core::f32::consts::PI) + f * d * vis
    })
}

/// `batch::run_f32`, or `batch::par_run_f32` over all cores when `par`.
fn run8<const I: usize, const O: usize>(
    par: bool,
    inputs: [&[f32]; I],
    outputs: [&mut [f32]; O],
    kernel: impl Fn([f32x8; I]) -> [f32x8; O] + Sync + Clone,
) -> Result<usize, brdf::ParamError> {
    if par {
        batch::par_run_f32(inputs, outputs, kernel)
    } else {
        batch::run_f32(inputs, outputs, kernel)
    }
}

/// [`material_textbook`] kept out of line: one call, one element.
#[inline(never)]
fn material_textbook_out_of_line(v: [f32; 3], l: [f32; 3]) -> [f32; 3] {
    material_textbook(v, l)
}

/// The timing mode for `bench/mitsuba/compare.py` (module docs).
fn timing_mode(path: &str) -> Result<(), String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    if bytes.len() % 24 != 0 || bytes.is_empty() {
        return Err(format!(
            "{path}: length {} is not 6 f32 arrays",
            bytes.len()
        ));
    }
    let n = bytes.len() / 24;
    if std::env::var("BRDF_FTZ").is_ok() {
        #[allow(deprecated)]
        unsafe {
            core::arch::x86_64::_mm_setcsr(core::arch::x86_64::_mm_getcsr() | 0x8040)
        };
    }
    let floats: Vec<f32> = bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    let a: [&[f32]; 6] = core::array::from_fn(|k| &floats[k * n..(k + 1) * n]);
    let runs: usize = std::env::var("BRDF_THROUGHPUT_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(7);
    let out_dir = std::env::var("BRDF_THROUGHPUT_OUTPUT").ok();
    // Over all cores with `batch::par_run_f32` (rayon's global pool) instead of one thread.
    let par = std::env::var("BRDF_THROUGHPUT_PARALLEL").is_ok_and(|v| v == "1");
    let mut out = vec![0.0f32; n];
    let alpha = f32x8::splat(ALPHA as f32);
    let (eta, k) = (f32x8::splat(ETA as f32), f32x8::splat(K as f32));
    type Pass<'a> = Box<dyn FnMut(&mut [f32]) + 'a>;
    // The material rows' green and blue outputs, one pair per row.
    let (mut g4, mut b4) = (vec![0.0f32; n], vec![0.0f32; n]);
    let (mut g1, mut b1, mut g2, mut b2, mut g3, mut b3) = (
        vec![0.0f32; n],
        vec![0.0f32; n],
        vec![0.0f32; n],
        vec![0.0f32; n],
        vec![0.0f32; n],
        vec![0.0f32; n],
    );
    let base8 = V3::new(
        f32x8::splat(MATERIAL_BASE[0]),
        f32x8::splat(MATERIAL_BASE[1]),
        f32x8::splat(MATERIAL_BASE[2]),
    );
    let mut kernels: Vec<(&str, Pass)> = vec![
        ("copy", Box::new(|o: &mut [f32]| o.copy_from_slice(a[2]))),
        (
            "ggx_d",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, [a[2]], [o], move |[z]| [ggx::d(z, alpha)]);
            }),
        ),
        (
            "ggx_d_plain",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, [a[2]], [o], move |[z]| [ggx_d_plain(z, alpha)]);
            }),
        ),
        (
            "ggx_d_fast",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, [a[2]], [o], move |[z]| [ggx::d_fast(z, alpha)]);
            }),
        ),
        (
            "beckmann_d",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, [a[2]], [o], move |[z]| [beckmann::d(z, alpha)]);
            }),
        ),
        (
            "beckmann_d_fast",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, [a[2]], [o], move |[z]| [beckmann::d_fast(z, alpha)]);
            }),
        ),
        (
            "rough_conductor",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, a, [o], move |[vx, vy, vz, lx, ly, lz]| {
                    let (v, l) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
                    [
                        cook_torrance::ggx_conductor_local(v, l, Alpha(alpha), eta, k)
                            * lz.saturate(),
                    ]
                });
            }),
        ),
        (
            "rough_conductor_fast",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, a, [o], move |[vx, vy, vz, lx, ly, lz]| {
                    let (v, l) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
                    [
                        cook_torrance::ggx_conductor_local_fast(v, l, Alpha(alpha), eta, k)
                            * lz.saturate(),
                    ]
                });
            }),
        ),
        (
            // The dot-product route: the cosines of the half vector, then `cook_torrance::ggx`
            // with `fresnel::conductor` (D from n.h alone).
            "rough_conductor_cosines",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, a, [o], move |[vx, vy, vz, lx, ly, lz]| {
                    let (v, l) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
                    let s = v + l;
                    // `Real::recip`, not `wide`'s inherent `recip` (a 12-bit estimate on AVX).
                    let h = s * Real::recip(s.length());
                    let vh = v.dot(h);
                    let f = fresnel::conductor(vh, eta, k);
                    [cook_torrance::ggx(
                        Cosines {
                            n_dot_v: vz,
                            n_dot_l: lz,
                            n_dot_h: h.z,
                            v_dot_h: vh,
                        },
                        Alpha(alpha),
                        f,
                    ) * lz.saturate()]
                });
            }),
        ),
        (
            "rough_conductor_cosines_fast",
            Box::new(|o: &mut [f32]| {
                let _ = run8(par, a, [o], move |[vx, vy, vz, lx, ly, lz]| {
                    let (v, l) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
                    let (nh, vh) = cook_torrance::half_cosines(v, l);
                    let f = fresnel::conductor_fast(vh, eta, k);
                    [fast_term(nh, vz, lz, alpha, f) * lz.saturate()]
                });
            }),
        ),
        (
            // The same kernel as a closure that borrows alpha, eta and k: the cost of not
            // writing `move` (the `batch` module docs).
            "rough_conductor_fast_borrowed",
            Box::new(|o: &mut [f32]| {
                let (alpha, eta, k) = (&alpha, &eta, &k);
                let _ = run8(par, a, [o], |[vx, vy, vz, lx, ly, lz]| {
                    let (v, l) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
                    let (nh, vh) = cook_torrance::half_cosines(v, l);
                    let f = fresnel::conductor_fast(vh, *eta, *k);
                    [fast_term(nh, vz, lz, *alpha, f) * lz.saturate()]
                });
            }),
        ),
        (
            // The glTF material, exact tier, red channel kept (the outputs of the three
            // material rows are compared channel 0 against channel 0).
            "material_gltf",
            Box::new(move |o: &mut [f32]| {
                let _ = run8(
                    par,
                    a,
                    [o, &mut g1[..], &mut b1[..]],
                    move |[vx, vy, vz, lx, ly, lz]| {
                        let (v, l) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
                        let (nh, vh) = cook_torrance::half_cosines(v, l);
                        let f = material::gltf(
                            Cosines {
                                n_dot_v: vz,
                                n_dot_l: lz,
                                n_dot_h: nh,
                                v_dot_h: vh,
                            },
                            base8,
                            f32x8::splat(MATERIAL_METALLIC),
                            f32x8::splat(MATERIAL_ROUGHNESS),
                        );
                        [f.x, f.y, f.z]
                    },
                );
            }),
        ),
        (
            "material_gltf_fast",
            Box::new(move |o: &mut [f32]| {
                let _ = run8(
                    par,
                    a,
                    [o, &mut g2[..], &mut b2[..]],
                    move |[vx, vy, vz, lx, ly, lz]| {
                        let (v, l) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
                        let (nh, vh) = cook_torrance::half_cosines(v, l);
                        let f = material::gltf_fast(
                            Cosines {
                                n_dot_v: vz,
                                n_dot_l: lz,
                                n_dot_h: nh,
                                v_dot_h: vh,
                            },
                            base8,
                            f32x8::splat(MATERIAL_METALLIC),
                            f32x8::splat(MATERIAL_ROUGHNESS),
                        );
                        [f.x, f.y, f.z]
                    },
                );
            }),
        ),
        (
            "material_textbook_scalar",
            Box::new(move |o: &mut [f32]| {
                for i in 0..o.len() {
                    let f = material_textbook_out_of_line(
                        [a[0][i], a[1][i], a[2][i]],
                        [a[3][i], a[4][i], a[5][i]],
                    );
                    o[i] = f[0];
                    g3[i] = f[1];
                    b3[i] = f[2];
                }
            }),
        ),
        (
            "material_textbook_inlined",
            Box::new(move |o: &mut [f32]| {
                for i in 0..o.len() {
                    let f =
                        material_textbook([a[0][i], a[1][i], a[2][i]], [a[3][i], a[4][i], a[5][i]]);
                    o[i] = f[0];
                    g4[i] = f[1];
                    b4[i] = f[2];
                }
            }),
        ),
    ];
    let cpu_clock = !par && std::env::var("BRDF_THROUGHPUT_CLOCK").is_ok_and(|v| v == "cpu");
    let only = std::env::var("BRDF_THROUGHPUT_ONLY").ok();
    let wanted = |name: &str| {
        only.as_ref()
            .is_none_or(|o| o.split(',').any(|k| k == name))
    };
    for (name, pass) in &mut kernels {
        if !wanted(name) {
            continue;
        }
        pass(&mut out);
        if let Some(dir) = &out_dir {
            let raw: Vec<u8> = out.iter().flat_map(|x| x.to_le_bytes()).collect();
            let file = format!("{dir}/{name}.f32");
            std::fs::write(&file, raw).map_err(|e| format!("{file}: {e}"))?;
        }
        for _ in 0..runs {
            let (t, c) = (Instant::now(), thread_cpu_s());
            pass(black_box(&mut out));
            let ms = if cpu_clock {
                (thread_cpu_s() - c) * 1e3
            } else {
                t.elapsed().as_secs_f64() * 1e3
            };
            black_box(&out);
            println!("time {name} {ms:.4}");
        }
    }
    Ok(())
}

/// Seconds of CPU time the calling thread has used (`CLOCK_THREAD_CPUTIME_ID`).
fn thread_cpu_s() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec for the duration of the call, and the clock id
    // is one Linux defines; on failure `ts` stays 0 (the timing mode then reports 0 ms).
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    #[allow(clippy::cast_precision_loss)] // seconds since the thread started: far below 2^53 ns
    let s = ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9;
    s
}

fn main() {
    if let Ok(path) = std::env::var("BRDF_THROUGHPUT_INPUT") {
        if let Err(e) = timing_mode(&path) {
            eprintln!("throughput: {e}");
            std::process::exit(1);
        }
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
