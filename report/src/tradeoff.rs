//! Error against run time: every form of every kernel family the crate offers more than one
//! form of, plus the textbook single-precision form engines ship, measured in one run.
//!
//! Error: each form's `f32` result (scalar and `f32x8` lanes) against a reference evaluated in
//! `f64` at the same, `f32`-rounded, inputs (the crate's exact `f64` kernel, within 4 ULP of
//! the correctly rounded value by the MPFR oracle, so about 2^-29 of an `f32` ULP). Points:
//! random over the family's stated domain, then (full mode) a local search around the worst
//! points found, perturbing the uniforms that generated them at shrinking scales. Only results
//! whose reference is at least 1e-30 count (as in the oracle's table). Run time: ns per element
//! through `brdf::batch` on `f32`, `f64` and `f32x8`, the median of repeated batches with the
//! fastest and slowest batch, all forms interleaved round by round so that machine noise hits
//! them alike.

use crate::textbook;
use brdf::ibl::dfg;
use brdf::wide::f32x8;
use brdf::{Cosines, Real, V3, batch, beckmann, diffuse, fresnel, ggx, material, phong};
use std::hint::black_box;
use std::sync::OnceLock;
use std::time::Instant;

/// Inputs of a family (at most this many).
const MAX_IN: usize = 8;

/// Evaluates a form over structure-of-arrays inputs into outputs.
type Run<S> = fn(&[Vec<S>], &mut [Vec<S>]);

/// One form of a kernel.
pub struct Form {
    /// The crate path or a description (`ggx::d`, `textbook (Filament D_GGX)`).
    pub name: &'static str,
    /// The engines' form, not the crate's.
    pub textbook: bool,
    /// Scalar `f32` through `batch::run::<f32>`.
    pub f32: Run<f32>,
    /// Scalar `f64`, where the form exists in `f64`.
    pub f64: Option<Run<f64>>,
    /// Eight `f32` lanes through `batch::run::<f32x8>`, where the form runs on lanes.
    pub x8: Option<Run<f32>>,
}

/// A family: the forms of one quantity, a reference, and the domain they are compared over.
pub struct Family {
    /// The quantity (`GGX D`).
    pub name: &'static str,
    /// The stated domain, in words.
    pub domain: &'static str,
    /// What the reference is.
    pub reference_name: &'static str,
    /// Number of inputs.
    pub inputs: usize,
    /// Number of outputs compared.
    pub outputs: usize,
    /// Maps uniforms in [0, 1) to one input point in the domain.
    pub sample: fn(&[f64; MAX_IN]) -> [f64; MAX_IN],
    /// The reference at one point (inputs already rounded to `f32`).
    pub reference: fn(&[f64]) -> [f64; 3],
    /// Whether the family is drawn in the Pareto plot (the lane transcendentals are not).
    pub plot: bool,
    /// Points to sample in full mode, when the reference is costly (else the default).
    pub points: Option<usize>,
    /// The forms.
    pub forms: Vec<Form>,
}

/// A form over the family's inputs `[name = index, ...]` returning `[T; n]`, on f32, f64
/// and f32x8 through `batch::run`.
macro_rules! form {
    ($name:expr, $textbook:expr, [$($a:ident = $i:literal),*], |$t:ident| $body:expr) => {{
        fn go<$t: Real>(ins: &[Vec<$t::Scalar>], outs: &mut [Vec<$t::Scalar>]) {
            let inputs = [$(ins[$i].as_slice()),*];
            let mut it = outs.iter_mut();
            let first = it.next().map(|v| v.as_mut_slice()).unwrap_or_default();
            let rest: Vec<&mut [$t::Scalar]> = it.map(|v| v.as_mut_slice()).collect();
            run_outputs::<$t, _>(inputs, first, rest, |[$($a),*]| $body);
        }
        Form {
            name: $name,
            textbook: $textbook,
            f32: go::<f32>,
            f64: Some(go::<f64>),
            x8: Some(go::<f32x8>),
        }
    }};
}

/// `batch::run` with one, two or three outputs from a kernel returning `[T; 3]` (unused
/// outputs ignored). The kernels' outputs beyond `outs` are computed and dropped.
fn run_outputs<T: Real, const I: usize>(
    inputs: [&[T::Scalar]; I],
    first: &mut [T::Scalar],
    mut rest: Vec<&mut [T::Scalar]>,
    mut kernel: impl FnMut([T; I]) -> [T; 3],
) {
    let r = match rest.len() {
        0 => batch::run::<T, I, 1>(inputs, [first], |x| [kernel(x)[0]]),
        1 => {
            let b = rest.remove(0);
            batch::run::<T, I, 2>(inputs, [first, b], |x| {
                let y = kernel(x);
                [y[0], y[1]]
            })
        }
        _ => {
            let b = rest.remove(0);
            let c = rest.remove(0);
            batch::run::<T, I, 3>(inputs, [first, b, c], kernel)
        }
    };
    debug_assert!(r.is_ok());
}

fn one<T: Real>(x: T) -> [T; 3] {
    [x, T::ZERO, T::ZERO]
}

/// Log-uniform in [lo, hi].
fn log_uniform(u: f64, lo: f64, hi: f64) -> f64 {
    (lo.ln() + u * (hi / lo).ln()).exp()
}

/// A cosine in [0, 1]: uniform half the time, else within 10^-1 .. 10^-7 of 1 (where the
/// narrow lobes and the cancellations live), chosen by `pick`.
fn cosine(pick: f64, u: f64) -> f64 {
    if pick < 0.5 {
        u
    } else {
        1.0 - 10f64.powf(-1.0 - 6.0 * u)
    }
}

/// A cosine in [1e-4, 1]: log-uniform (grazing angles as often as the rest).
fn cosine_grazing(u: f64) -> f64 {
    log_uniform(u, 1e-4, 1.0)
}

/// Uniform hemisphere direction (z >= 0) from two uniforms.
fn hemisphere(u1: f64, u2: f64) -> [f64; 3] {
    let z = u1.max(1e-4);
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * std::f64::consts::PI * u2;
    [r * phi.cos(), r * phi.sin(), z]
}

fn r3(x: f64) -> [f64; 3] {
    [x, 0.0, 0.0]
}

fn table() -> &'static [[f32; 3]] {
    static TABLE: OnceLock<Vec<[f32; 3]>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut t = vec![[0.0f32; 3]; DFG_N * DFG_N];
        // 8192 samples: each cell within about 3e-4 of its integral.
        if dfg::table(&mut t, DFG_N, DFG_N, 8192).is_err() {
            t.fill([f32::NAN; 3]);
        }
        t
    })
}

/// The DFG table's size (per side), as engines ship it.
pub const DFG_N: usize = 32;

fn dfg_table_run(ins: &[Vec<f32>], outs: &mut [Vec<f32>]) {
    let t = table();
    for (i, o) in outs[0].iter_mut().enumerate() {
        let [a, b, _] = dfg::lookup(t, DFG_N, DFG_N, ins[0][i], ins[1][i]);
        *o = ins[2][i] * a + b;
    }
}

macro_rules! transcendental {
    ($name:literal, $f:ident, $lf:ident, $lo:expr, $hi:expr, $log:expr, $domain:literal) => {
        Family {
            name: concat!("Real::", $name),
            domain: $domain,
            reference_name: concat!("f64 ", $name, " (libm)"),
            inputs: 1,
            outputs: 1,
            sample: |u| {
                let x = if $log {
                    log_uniform(u[0], $lo, $hi)
                } else {
                    $lo + ($hi - $lo) * u[0]
                };
                [x, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
            },
            reference: |x| r3(libm::$lf(x[0])),
            plot: false,
            points: None,
            forms: vec![form!(
                concat!("Real::", $name, " (f32: libm; lanes: wide)"),
                false,
                [x = 0],
                |T| one(x.$f())
            )],
        }
    };
}

/// Every family with its forms.
#[allow(clippy::too_many_lines)]
pub fn families() -> Vec<Family> {
    vec![
        Family {
            name: "GGX D",
            domain: "n.h in [0, 1] (half of the points within 1e-1 to 1e-7 of 1), alpha in [1e-3, 1] log-uniform",
            reference_name: "ggx::d in f64",
            inputs: 2,
            outputs: 1,
            sample: |u| {
                [
                    cosine(u[0], u[1]),
                    log_uniform(u[2], 1e-3, 1.0),
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                ]
            },
            reference: |x| r3(ggx::d(x[0], x[1])),
            plot: true,
            points: None,
            forms: vec![
                form!("ggx::d", false, [c = 0, a = 1], |T| one(ggx::d(c, a))),
                form!("ggx::d_fast", false, [c = 0, a = 1], |T| one(ggx::d_fast(
                    c, a
                ))),
                form!(
                    "textbook D_GGX (Filament, glTF)",
                    true,
                    [c = 0, a = 1],
                    |T| one(textbook::ggx_d(c, a))
                ),
            ],
        },
        Family {
            name: "Beckmann D",
            domain: "n.h in [0, 1] (half of the points within 1e-1 to 1e-7 of 1), alpha in [1e-3, 1] log-uniform",
            reference_name: "beckmann::d in f64",
            inputs: 2,
            outputs: 1,
            sample: |u| {
                [
                    cosine(u[0], u[1]),
                    log_uniform(u[2], 1e-3, 1.0),
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                ]
            },
            reference: |x| r3(beckmann::d(x[0], x[1])),
            plot: true,
            points: None,
            forms: vec![
                form!("beckmann::d", false, [c = 0, a = 1], |T| one(beckmann::d(
                    c, a
                ))),
                form!("beckmann::d_fast", false, [c = 0, a = 1], |T| one(
                    beckmann::d_fast(c, a)
                )),
                form!(
                    "textbook Beckmann D (Walter 2007 eq. 25)",
                    true,
                    [c = 0, a = 1],
                    |T| one(textbook::beckmann_d(c, a))
                ),
            ],
        },
        Family {
            name: "GGX V (Smith)",
            domain: "n.v, n.l in [1e-12, 1] log-uniform (grazing to the limit of f32 rendering), alpha in [1e-4, 1] log-uniform (down to the crate's floor)",
            reference_name: "ggx::v_correlated in f64 (height-correlated)",
            inputs: 3,
            outputs: 1,
            sample: |u| {
                [
                    log_uniform(u[0], 1e-12, 1.0),
                    log_uniform(u[1], 1e-12, 1.0),
                    log_uniform(u[2], 1e-4, 1.0),
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                ]
            },
            reference: |x| r3(ggx::v_correlated(x[0], x[1], x[2])),
            plot: true,
            points: None,
            forms: vec![
                form!("ggx::v_correlated", false, [v = 0, l = 1, a = 2], |T| one(
                    ggx::v_correlated(v, l, a)
                )),
                form!(
                    "ggx::v_correlated_hammon",
                    false,
                    [v = 0, l = 1, a = 2],
                    |T| one(ggx::v_correlated_hammon(v, l, a))
                ),
                form!(
                    "ggx::v_correlated_fast (Filament)",
                    false,
                    [v = 0, l = 1, a = 2],
                    |T| one(ggx::v_correlated_fast(v, l, a))
                ),
                form!(
                    "ggx::v_schlick, k = schlick_k_ibl (alpha/2)",
                    false,
                    [v = 0, l = 1, a = 2],
                    |T| one(ggx::v_schlick(v, l, ggx::schlick_k_ibl(a)))
                ),
                form!(
                    "ggx::v_schlick, k = schlick_k_analytic ((r+1)^2/8)",
                    false,
                    [v = 0, l = 1, a = 2],
                    |T| one(ggx::v_schlick(v, l, ggx::schlick_k_analytic(a.sqrt())))
                ),
                form!(
                    "textbook V_SmithGGXCorrelated (Filament, glTF)",
                    true,
                    [v = 0, l = 1, a = 2],
                    |T| one(textbook::ggx_v(v, l, a))
                ),
            ],
        },
        Family {
            name: "Beckmann Lambda",
            domain: "n.v in [1e-4, 1 - 1e-7] log-uniform in 1 - n.v half of the time, alpha in [1e-3, 1] log-uniform; Lambda >= 1e-30 counted",
            reference_name: "beckmann::lambda in f64 (exact, cancellation-free)",
            inputs: 2,
            outputs: 1,
            sample: |u| {
                let c = if u[2] < 0.5 {
                    cosine_grazing(u[0])
                } else {
                    1.0 - log_uniform(u[0], 1e-7, 1.0 - 1e-4)
                };
                [
                    c,
                    log_uniform(u[1], 1e-3, 1.0),
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                ]
            },
            reference: |x| r3(beckmann::lambda(x[0], x[1])),
            plot: true,
            points: None,
            forms: vec![
                form!("beckmann::lambda (exact)", false, [c = 0, a = 1], |T| one(
                    beckmann::lambda(c, a)
                )),
                form!(
                    "beckmann::lambda_walter (rational, 0 for a >= 1.6)",
                    false,
                    [c = 0, a = 1],
                    |T| one(beckmann::lambda_walter(c, a))
                ),
                form!(
                    "textbook Lambda (erfc, Heitz 2014 eq. 83)",
                    true,
                    [c = 0, a = 1],
                    |T| one(textbook::beckmann_lambda(c, a))
                ),
            ],
        },
        Family {
            name: "Beckmann G1",
            domain: "n.v in [1e-4, 1] log-uniform, alpha in [1e-3, 1] log-uniform; G1 = 1 / (1 + Lambda)",
            reference_name: "beckmann::g1 in f64 (exact Lambda, erfc)",
            inputs: 2,
            outputs: 1,
            sample: |u| {
                [
                    cosine_grazing(u[0]),
                    log_uniform(u[1], 1e-3, 1.0),
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                ]
            },
            reference: |x| r3(beckmann::g1(x[0], x[1])),
            plot: true,
            points: None,
            forms: vec![
                form!("beckmann::g1 (exact Lambda)", false, [c = 0, a = 1], |T| {
                    one(beckmann::g1(c, a))
                }),
                form!(
                    "1 / (1 + beckmann::lambda_walter) (rational)",
                    false,
                    [c = 0, a = 1],
                    |T| one(T::ONE / (T::ONE + beckmann::lambda_walter(c, a)))
                ),
                form!(
                    "textbook exact Lambda (erfc, Heitz 2014 eq. 83)",
                    true,
                    [c = 0, a = 1],
                    |T| one(textbook::beckmann_g1(c, a))
                ),
            ],
        },
        Family {
            name: "Dielectric Fresnel",
            domain: "cos in [0, 1], eta in [1.05, 2.5] (light from the outside)",
            reference_name: "fresnel::dielectric in f64",
            inputs: 2,
            outputs: 1,
            sample: |u| [u[0], 1.05 + 1.45 * u[1], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            reference: |x| r3(fresnel::dielectric(x[0], x[1])),
            plot: true,
            points: None,
            forms: vec![
                form!("fresnel::dielectric", false, [c = 0, e = 1], |T| one(
                    fresnel::dielectric(c, e)
                )),
                form!("fresnel::dielectric_fast", false, [c = 0, e = 1], |T| one(
                    fresnel::dielectric_fast(c, e)
                )),
                form!(
                    "fresnel::schlick(f0_from_ior(eta))",
                    false,
                    [c = 0, e = 1],
                    |T| one(fresnel::schlick(fresnel::f0_from_ior(e), c))
                ),
                form!(
                    "fresnel::schlick_sg(f0_from_ior(eta)) (exp2)",
                    false,
                    [c = 0, e = 1],
                    |T| one(fresnel::schlick_sg(fresnel::f0_from_ior(e), c))
                ),
                form!(
                    "textbook FrDielectric (pbrt-v3)",
                    true,
                    [c = 0, e = 1],
                    |T| one(textbook::fresnel_dielectric(c, e))
                ),
            ],
        },
        Family {
            name: "Conductor Fresnel",
            domain: "cos in [0, 1], eta in [0.05, 3], k in [1, 8] (metals); Schlick's F0 and F82's tint exact for each (eta, k)",
            reference_name: "fresnel::conductor in f64",
            inputs: 5,
            outputs: 1,
            sample: |u| {
                let (c, eta, k) = (u[0], 0.05 + 2.95 * u[1], 1.0 + 7.0 * u[2]);
                let f0 = fresnel::conductor(1.0, eta, k);
                let tint = fresnel::conductor(fresnel::F82_MU, eta, k)
                    / fresnel::schlick(f0, fresnel::F82_MU);
                [c, eta, k, f0, tint.min(1.0), 0.0, 0.0, 0.0]
            },
            reference: |x| r3(fresnel::conductor(x[0], x[1], x[2])),
            plot: true,
            points: None,
            forms: vec![
                form!("fresnel::conductor", false, [c = 0, e = 1, k = 2], |T| one(
                    fresnel::conductor(c, e, k)
                )),
                form!(
                    "fresnel::conductor_fast",
                    false,
                    [c = 0, e = 1, k = 2],
                    |T| one(fresnel::conductor_fast(c, e, k))
                ),
                form!("fresnel::schlick (F0 given)", false, [c = 0, f0 = 3], |T| {
                    one(fresnel::schlick(f0, c))
                }),
                form!(
                    "fresnel::schlick_f82 (F0, tint given)",
                    false,
                    [c = 0, f0 = 3, t = 4],
                    |T| one(fresnel::schlick_f82(f0, t, c))
                ),
                form!(
                    "textbook FrConductor (pbrt-v3, Lagarde 2013)",
                    true,
                    [c = 0, e = 1, k = 2],
                    |T| one(textbook::fresnel_conductor(c, e, k))
                ),
            ],
        },
        Family {
            name: "Blinn-Phong normalization",
            domain: "exponent in [1, 1e4] log-uniform",
            reference_name: "phong::blinn_phong_normalization_exact in f64",
            inputs: 1,
            outputs: 1,
            sample: |u| {
                [
                    log_uniform(u[0], 1.0, 1e4),
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                ]
            },
            reference: |x| r3(phong::blinn_phong_normalization_exact(x[0])),
            plot: true,
            points: None,
            forms: vec![
                form!(
                    "phong::blinn_phong_normalization_exact",
                    false,
                    [n = 0],
                    |T| one(phong::blinn_phong_normalization_exact(n))
                ),
                form!(
                    "phong::blinn_phong_normalization_approx ((n+8)/(8 pi))",
                    false,
                    [n = 0],
                    |T| one(phong::blinn_phong_normalization_approx(n))
                ),
                form!(
                    "(n+2)/(2 pi) (Phong's constant on Blinn-Phong)",
                    true,
                    [n = 0],
                    |T| one(phong::phong_normalization(n))
                ),
            ],
        },
        Family {
            name: "EON diffuse",
            domain: "v, l uniform on the hemisphere (n.v, n.l >= 1e-4), rho in [0, 1], sigma in [0, 1]",
            reference_name: "diffuse::eon in f64 (exact FON albedo)",
            inputs: 5,
            outputs: 1,
            sample: |u| {
                let (v, l) = (hemisphere(u[0], u[1]), hemisphere(u[2], u[3]));
                let vl = v[0] * l[0] + v[1] * l[1] + v[2] * l[2];
                [v[2], l[2], vl, u[4], u[5], 0.0, 0.0, 0.0]
            },
            reference: |x| r3(diffuse::eon(x[0], x[1], x[2], x[3], x[4])),
            plot: true,
            points: None,
            forms: vec![
                form!(
                    "diffuse::eon",
                    false,
                    [v = 0, l = 1, vl = 2, r = 3, s = 4],
                    |T| one(diffuse::eon(v, l, vl, r, s))
                ),
                form!(
                    "diffuse::eon_approx (quartic albedo fit)",
                    false,
                    [v = 0, l = 1, vl = 2, r = 3, s = 4],
                    |T| one(diffuse::eon_approx(v, l, vl, r, s))
                ),
            ],
        },
        Family {
            name: "Split-sum DFG",
            domain: "F0 A + B for n.v in [0.01, 1], perceptual roughness in [0, 1], F0 in [0.02, 1]",
            reference_name: "ibl::dfg::dfg quadrature (32768 samples, within 1e-4)",
            inputs: 3,
            outputs: 1,
            sample: |u| {
                [
                    0.01 + 0.99 * u[0],
                    u[1],
                    0.02 + 0.98 * u[2],
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                ]
            },
            reference: |x| {
                let [a, b, _] = dfg::dfg(x[0], x[1] * x[1], dfg::DEFAULT_SAMPLES);
                r3(x[2] * a + b)
            },
            plot: true,
            points: Some(2000),
            forms: vec![
                Form {
                    name: "ibl::dfg::lookup (32 x 32 table, bilinear)",
                    textbook: false,
                    f32: dfg_table_run,
                    f64: None,
                    x8: None,
                },
                form!(
                    "ibl::dfg::karis_mobile",
                    false,
                    [v = 0, r = 1, f0 = 2],
                    |T| {
                        let [a, b] = dfg::karis_mobile(v, r);
                        one(f0 * a + b)
                    }
                ),
                form!("ibl::dfg::lazarov", false, [v = 0, r = 1, f0 = 2], |T| {
                    let [a, b] = dfg::lazarov(v, r);
                    one(f0 * a + b)
                }),
                form!(
                    "ibl::dfg::narkowicz_lazarov",
                    false,
                    [v = 0, r = 1, f0 = 2],
                    |T| {
                        let [a, b] = dfg::narkowicz_lazarov(v, r);
                        one(f0 * a + b)
                    }
                ),
                form!(
                    "ibl::dfg::narkowicz_polynomial",
                    false,
                    [v = 0, r = 1, f0 = 2],
                    |T| {
                        let [a, b] = dfg::narkowicz_polynomial(v, r);
                        one(f0 * a + b)
                    }
                ),
            ],
        },
        Family {
            name: "glTF material",
            domain: "v, l uniform on the hemisphere (n.v, n.l >= 1e-4), base colour channels, metallic, perceptual roughness in [0, 1]",
            reference_name: "material::gltf in f64",
            inputs: 7,
            outputs: 3,
            sample: |u| {
                let (v, l) = (hemisphere(u[0], u[1]), hemisphere(u[2], u[3]));
                let h = [v[0] + l[0], v[1] + l[1], v[2] + l[2]];
                let n = (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]).sqrt();
                let h = [h[0] / n, h[1] / n, h[2] / n];
                let vh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
                [v[2], l[2], h[2], vh, u[4], u[5], u[6], 0.0]
            },
            reference: |x| {
                let c = material::gltf(
                    Cosines {
                        n_dot_v: x[0],
                        n_dot_l: x[1],
                        n_dot_h: x[2],
                        v_dot_h: x[3],
                    },
                    V3::new(x[4], 0.5 * x[4], 0.25),
                    x[5],
                    x[6],
                );
                [c.x, c.y, c.z]
            },
            plot: true,
            points: None,
            forms: vec![
                form!(
                    "material::gltf",
                    false,
                    [v = 0, l = 1, h = 2, vh = 3, b = 4, m = 5, r = 6],
                    |T| {
                        let cosines = Cosines {
                            n_dot_v: v,
                            n_dot_l: l,
                            n_dot_h: h,
                            v_dot_h: vh,
                        };
                        let c =
                            material::gltf(cosines, V3::new(b, T::HALF * b, T::splat(0.25)), m, r);
                        [c.x, c.y, c.z]
                    }
                ),
                form!(
                    "textbook glTF Appendix B (compact form)",
                    true,
                    [v = 0, l = 1, h = 2, vh = 3, b = 4, m = 5, r = 6],
                    |T| {
                        [
                            textbook::gltf(v, l, h, vh, b, m, r),
                            textbook::gltf(v, l, h, vh, T::HALF * b, m, r),
                            textbook::gltf(v, l, h, vh, T::splat(0.25), m, r),
                        ]
                    }
                ),
            ],
        },
        transcendental!("exp", exp, exp, -87.0, 88.0, false, "x in [-87, 88]"),
        transcendental!("exp2", exp2, exp2, -126.0, 127.0, false, "x in [-126, 127]"),
        transcendental!(
            "ln",
            ln,
            log,
            1e-30,
            1e30,
            true,
            "x in [1e-30, 1e30] log-uniform"
        ),
        transcendental!("sin", sin, sin, -100.0, 100.0, false, "x in [-100, 100]"),
        transcendental!("cos", cos, cos, -100.0, 100.0, false, "x in [-100, 100]"),
        transcendental!(
            "atan",
            atan,
            atan,
            1e-6,
            1e6,
            true,
            "x in [1e-6, 1e6] log-uniform"
        ),
        transcendental!("acos", acos, acos, -1.0, 1.0, false, "x in [-1, 1]"),
        transcendental!("erf", erf, erf, -4.0, 4.0, false, "x in [-4, 4]"),
        transcendental!("erfc", erfc, erfc, -1.0, 9.0, false, "x in [-1, 9]"),
        transcendental!(
            "sqrt",
            sqrt,
            sqrt,
            1e-30,
            1e30,
            true,
            "x in [1e-30, 1e30] log-uniform"
        ),
    ]
}

/// Median and extremes of repeated timings, ns per element.
#[derive(Clone, Copy, Debug, Default)]
pub struct Spread {
    /// Median over the rounds.
    pub median: f64,
    /// Fastest round.
    pub min: f64,
    /// Slowest round.
    pub max: f64,
}

fn spread(mut v: Vec<f64>) -> Spread {
    if v.is_empty() {
        return Spread::default();
    }
    v.sort_by(f64::total_cmp);
    Spread {
        median: v[v.len() / 2],
        min: v[0],
        max: v[v.len() - 1],
    }
}

/// What one form measured.
#[derive(Clone, Debug, Default)]
pub struct Measured {
    /// Family name.
    pub family: &'static str,
    /// Form name.
    pub form: &'static str,
    /// Textbook row.
    pub textbook: bool,
    /// Max relative error of the `f32` result.
    pub max_rel: f64,
    /// Mean relative error of the `f32` result.
    pub mean_rel: f64,
    /// Max absolute error of the `f32` result.
    pub max_abs: f64,
    /// Max error in `f32` ULPs of the scalar `f32` result.
    pub max_ulp: f64,
    /// Max error in `f32` ULPs of the `f32x8` result (None: no lane path).
    pub max_ulp_x8: Option<f64>,
    /// Non-finite results on finite references.
    pub nonfinite: usize,
    /// Points counted.
    pub points: usize,
    /// The inputs of the worst relative error.
    pub worst: Vec<f64>,
    /// Scalar f32, ns per evaluation.
    pub ns_f32: Spread,
    /// Scalar f64, ns per evaluation.
    pub ns_f64: Option<Spread>,
    /// f32x8 through batch, ns per element.
    pub ns_x8: Option<Spread>,
}

/// Measurement sizes.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// Random points per family for the error.
    pub points: usize,
    /// Whether to search around the worst points.
    pub refine: bool,
    /// Elements per timed batch.
    pub batch: usize,
    /// Timed rounds.
    pub rounds: usize,
}

/// A splitmix64 generator: the report's points are the same on every run.
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }
    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// The f32 ULP at the magnitude of `r` (2^-149 below the smallest normal).
pub fn ulp32(r: f64) -> f64 {
    let a = r.abs();
    if a < f64::from(f32::MIN_POSITIVE) {
        return 2f64.powi(-149);
    }
    let e = ((a.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    2f64.powi(e - 23)
}

/// Structure-of-arrays inputs, rounded to `f32` and in `f64`.
type Soa = (Vec<Vec<f32>>, Vec<Vec<f64>>);

/// SoA inputs of a family at points generated from uniforms.
fn inputs_at(fam: &Family, us: &[[f64; MAX_IN]]) -> Soa {
    let mut x32 = vec![Vec::with_capacity(us.len()); fam.inputs];
    let mut x64 = vec![Vec::with_capacity(us.len()); fam.inputs];
    for u in us {
        let p = (fam.sample)(u);
        for j in 0..fam.inputs {
            x32[j].push(p[j] as f32);
            x64[j].push(p[j]);
        }
    }
    (x32, x64)
}

/// Per-point errors of a form: (relative error, f32 ULP of scalar, f32 ULP of lanes),
/// NaN where the point does not count.
struct Errors {
    rel: Vec<f64>,
    abs: Vec<f64>,
    ulp: Vec<f64>,
    ulp_x8: Vec<f64>,
    nonfinite: usize,
}

fn errors(fam: &Family, form: &Form, x32: &[Vec<f32>], refs: &[[f64; 3]]) -> Errors {
    let n = refs.len();
    let mut out = vec![vec![0.0f32; n]; fam.outputs];
    (form.f32)(x32, &mut out);
    let mut lanes = vec![vec![0.0f32; n]; fam.outputs];
    if let Some(x8) = form.x8 {
        x8(x32, &mut lanes);
    }
    let mut e = Errors {
        rel: vec![f64::NAN; n],
        abs: vec![f64::NAN; n],
        ulp: vec![f64::NAN; n],
        ulp_x8: vec![f64::NAN; n],
        nonfinite: 0,
    };
    for i in 0..n {
        for (o, (scalar, lane)) in out.iter().zip(&lanes).enumerate() {
            let r = refs[i][o];
            if !r.is_finite() || r.abs() < 1e-30 {
                continue;
            }
            let y = f64::from(scalar[i]);
            if !y.is_finite() {
                e.nonfinite += 1;
                continue;
            }
            let rel = (y - r).abs() / r.abs();
            let ulp = (y - r).abs() / ulp32(r);
            let ulp8 = (f64::from(lane[i]) - r).abs() / ulp32(r);
            let m = |a: f64, b: f64| if a.is_nan() { b } else { a.max(b) };
            e.rel[i] = m(e.rel[i], rel);
            e.abs[i] = m(e.abs[i], (y - r).abs());
            e.ulp[i] = m(e.ulp[i], ulp);
            if form.x8.is_some() {
                e.ulp_x8[i] = m(
                    e.ulp_x8[i],
                    if ulp8.is_nan() { f64::INFINITY } else { ulp8 },
                );
            }
        }
    }
    e
}

fn reference_at(fam: &Family, x32: &[Vec<f32>]) -> Vec<[f64; 3]> {
    let n = x32.first().map_or(0, Vec::len);
    (0..n)
        .map(|i| {
            let p: Vec<f64> = x32.iter().map(|c| f64::from(c[i])).collect();
            (fam.reference)(&p)
        })
        .collect()
}

/// Measures the error of every form of `fam`: random points, then (if `budget.refine`) a
/// local search around each form's worst points.
pub fn measure_errors(fam: &Family, budget: &Budget, seed: u64) -> Vec<Measured> {
    let mut rng = Rng::new(seed);
    let points = if budget.refine {
        fam.points.unwrap_or(budget.points)
    } else {
        fam.points
            .map_or(budget.points, |p| p.min(budget.points / 10).max(200))
    };
    let us: Vec<[f64; MAX_IN]> = (0..points)
        .map(|_| core::array::from_fn(|_| rng.uniform()))
        .collect();
    let (x32, _) = inputs_at(fam, &us);
    let refs = reference_at(fam, &x32);
    let mut results = Vec::new();
    for form in &fam.forms {
        let mut e = errors(fam, form, &x32, &refs);
        let mut all_us = us.clone();
        let mut all_x = x32.clone();
        if budget.refine {
            // Neighbours of the 8 worst points, in the uniforms that generated them, at scales
            // 1e-2 down to 1e-7: a bound should survive its own worst case's neighbourhood.
            let mut order: Vec<usize> = (0..all_us.len()).filter(|&i| !e.rel[i].is_nan()).collect();
            order.sort_by(|&a, &b| e.rel[b].total_cmp(&e.rel[a]));
            let seeds: Vec<[f64; MAX_IN]> = order.iter().take(8).map(|&i| all_us[i]).collect();
            let mut near = Vec::new();
            for s in &seeds {
                for scale in [1e-2, 1e-3, 1e-4, 1e-5, 1e-7] {
                    for _ in 0..if fam.points.is_some() { 4 } else { 64 } {
                        near.push(core::array::from_fn(|j| {
                            (s[j] + scale * (2.0 * rng.uniform() - 1.0)).clamp(0.0, 1.0 - 1e-12)
                        }));
                    }
                }
            }
            let (nx, _) = inputs_at(fam, &near);
            let nrefs = reference_at(fam, &nx);
            let ne = errors(fam, form, &nx, &nrefs);
            e.rel.extend(ne.rel);
            e.abs.extend(ne.abs);
            e.ulp.extend(ne.ulp);
            e.ulp_x8.extend(ne.ulp_x8);
            e.nonfinite += ne.nonfinite;
            all_us.extend(near);
            for (a, b) in all_x.iter_mut().zip(nx) {
                a.extend(b);
            }
        }
        let counted: Vec<usize> = (0..e.rel.len()).filter(|&i| !e.rel[i].is_nan()).collect();
        let worst_i = counted
            .iter()
            .copied()
            .max_by(|&a, &b| e.rel[a].total_cmp(&e.rel[b]));
        let fold = |v: &[f64]| {
            v.iter()
                .filter(|x| !x.is_nan())
                .fold(0.0f64, |a, &b| a.max(b))
        };
        results.push(Measured {
            family: fam.name,
            form: form.name,
            textbook: form.textbook,
            max_rel: fold(&e.rel),
            max_abs: fold(&e.abs),
            mean_rel: counted.iter().map(|&i| e.rel[i]).sum::<f64>() / counted.len().max(1) as f64,
            max_ulp: fold(&e.ulp),
            max_ulp_x8: form.x8.map(|_| fold(&e.ulp_x8)),
            nonfinite: e.nonfinite,
            points: counted.len(),
            worst: worst_i
                .map(|i| all_x.iter().map(|c| f64::from(c[i])).collect())
                .unwrap_or_default(),
            ..Measured::default()
        });
    }
    results
}

/// One timed batch: ns per element of `run` over `x` into `outs` (`n` elements).
fn timed<S>(run: Run<S>, x: &[Vec<S>], outs: &mut [Vec<S>], n: f64) -> f64 {
    let t = Instant::now();
    run(black_box(x), outs);
    let dt = t.elapsed().as_secs_f64();
    black_box(&outs);
    dt * 1e9 / n
}

/// Times every form of every family, interleaved round by round, and fills the `ns_*`
/// fields of `measured` (in the order of `families` and their forms).
pub fn measure_times(
    fams: &[Family],
    measured: &mut [Measured],
    budget: &Budget,
    mut progress: impl FnMut(usize),
) {
    let mut rng = Rng::new(7);
    let data: Vec<Soa> = fams
        .iter()
        .map(|fam| {
            let us: Vec<[f64; MAX_IN]> = (0..budget.batch)
                .map(|_| core::array::from_fn(|_| rng.uniform()))
                .collect();
            inputs_at(fam, &us)
        })
        .collect();
    let forms: Vec<(usize, &Form)> = fams
        .iter()
        .enumerate()
        .flat_map(|(i, f)| f.forms.iter().map(move |form| (i, form)))
        .collect();
    let mut t32 = vec![Vec::new(); forms.len()];
    let mut t64 = vec![Vec::new(); forms.len()];
    let mut t8 = vec![Vec::new(); forms.len()];
    let n = budget.batch as f64;
    let mut o32: Vec<Vec<f32>> = vec![vec![0.0; budget.batch]; 3];
    let mut o64: Vec<Vec<f64>> = vec![vec![0.0; budget.batch]; 3];
    // One untimed round first: page faults, table builds and cold caches stay out.
    for round in 0..=budget.rounds {
        for (k, (fi, form)) in forms.iter().enumerate() {
            let fam = &fams[*fi];
            let (x32, x64) = &data[*fi];
            let keep = round > 0;
            let ns = timed(form.f32, x32, &mut o32[..fam.outputs], n);
            if keep {
                t32[k].push(ns);
            }
            if let Some(f) = form.f64 {
                let ns = timed(f, x64, &mut o64[..fam.outputs], n);
                if keep {
                    t64[k].push(ns);
                }
            }
            if let Some(f) = form.x8 {
                let ns = timed(f, x32, &mut o32[..fam.outputs], n);
                if keep {
                    t8[k].push(ns);
                }
            }
        }
        progress(round);
    }
    for (k, m) in measured.iter_mut().enumerate() {
        m.ns_f32 = spread(std::mem::take(&mut t32[k]));
        m.ns_f64 = forms[k].1.f64.map(|_| spread(std::mem::take(&mut t64[k])));
        m.ns_x8 = forms[k].1.x8.map(|_| spread(std::mem::take(&mut t8[k])));
    }
}
