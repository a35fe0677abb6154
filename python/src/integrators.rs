//! `brdf::integrate`'s integrators over a Python callable that takes arrays of directions.
//!
//! The integrators are adaptive and call their integrand one direction at a time; a Python
//! call per direction would cost microseconds each. Instead the integration is replayed:
//! each pass runs the Rust integrator with every value known so far and a placeholder 0 for
//! the others, collecting the directions it asked for that had no value; the callable then
//! gets all of those in one call (arrays of shape (n, 3)), and the next pass runs with them.
//! A pass that asks for nothing new ran on true values only, so its result is exactly what
//! the integrator gives with the callable called direction by direction (the integrator is
//! deterministic). The initial partition arrives in the first call, each level of
//! refinement in one more: a few to a few dozen calls in all. The callable must be a
//! function of the directions alone (the same direction always gives the same value).

use brdf::V3;
use brdf::integrate::{self as brdf_integrate, Config, Estimate};
use numpy::{PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use std::collections::{HashMap, HashSet};

/// Up to two directions' components as bits, the cache key.
type Key = [u64; 6];

/// The integrand an integration pass is handed: a value per key (0 where none is known yet).
type Integrand<'a> = &'a mut dyn FnMut(Key) -> f64;

/// Passes before giving up: each pass adds at least one direction the final result needs, so
/// this is only reached by an integrand that keeps the integrator refining a new level every
/// pass past any realistic depth.
const MAX_PASSES: usize = 10_000;

struct Replay<'py> {
    py: Python<'py>,
    f: Bound<'py, PyAny>,
    /// Directions the callable takes (1 or 2).
    arity: usize,
    f32: bool,
    cache: HashMap<Key, f64>,
    calls: u64,
}

impl Replay<'_> {
    /// Runs `body` (an integration whose integrand is the closure it is handed) until a
    /// pass needs no new value.
    fn run<R>(&mut self, body: &dyn Fn(Integrand<'_>) -> R) -> PyResult<R> {
        for _ in 0..MAX_PASSES {
            let mut missing: Vec<Key> = Vec::new();
            let mut seen: HashSet<Key> = HashSet::new();
            let cache = &self.cache;
            let r = body(&mut |k| match cache.get(&k) {
                Some(v) => *v,
                None => {
                    if seen.insert(k) {
                        missing.push(k);
                    }
                    0.0
                }
            });
            if missing.is_empty() {
                return Ok(r);
            }
            let values = self.call(&missing)?;
            self.cache.extend(missing.into_iter().zip(values));
        }
        Err(PyRuntimeError::new_err(format!(
            "the integration still asked for new directions after {MAX_PASSES} passes"
        )))
    }

    /// The callable on the directions of `keys`: its values, widened to `f64` (rounded to
    /// `f32` first for an `f32` integration, as the Rust `_f32` integrators do).
    fn call(&mut self, keys: &[Key]) -> PyResult<Vec<f64>> {
        let n = keys.len();
        let mut args = Vec::with_capacity(self.arity);
        for d in 0..self.arity {
            let rows: Vec<Vec<f64>> = keys
                .iter()
                .map(|k| (0..3).map(|c| f64::from_bits(k[3 * d + c])).collect())
                .collect();
            let a = PyArray2::from_vec2(self.py, &rows)
                .map_err(|e| PyValueError::new_err(e.to_string()))?;
            let a = if self.f32 {
                a.call_method1("astype", ("float32",))?
            } else {
                a.into_any()
            };
            args.push(a);
        }
        let out = self.f.call1(pyo3::types::PyTuple::new(self.py, args)?)?;
        self.calls += 1;
        let np = self.py.import("numpy")?;
        let dtype = if self.f32 { "float32" } else { "float64" };
        let arr = np.call_method1("asarray", (out, dtype))?;
        let shape: Vec<usize> = arr.getattr("shape")?.extract()?;
        if shape != [n] {
            return Err(PyValueError::new_err(format!(
                "the integrand was given {n} directions and returned shape {shape:?}, not ({n},)"
            )));
        }
        let arr = np.call_method1("ascontiguousarray", (arr, "float64"))?;
        let a = arr.cast_into::<numpy::PyArray1<f64>>()?;
        let ro = a.readonly();
        Ok(ro.as_slice()?.to_vec())
    }
}

fn key1(w: V3<f64>) -> Key {
    [w.x.to_bits(), w.y.to_bits(), w.z.to_bits(), 0, 0, 0]
}

fn key2(a: V3<f64>, b: V3<f64>) -> Key {
    [
        a.x.to_bits(),
        a.y.to_bits(),
        a.z.to_bits(),
        b.x.to_bits(),
        b.y.to_bits(),
        b.z.to_bits(),
    ]
}

fn w32(w: V3<f32>) -> V3<f64> {
    w.map(f64::from)
}

fn v3(w: [f64; 3]) -> V3<f64> {
    V3::new(w[0], w[1], w[2])
}

fn v3f(w: [f64; 3]) -> V3<f32> {
    #[allow(clippy::cast_possible_truncation)]
    V3::new(w[0] as f32, w[1] as f32, w[2] as f32)
}

/// `brdf::integrate`'s integrator `kind` over the Python callable `f` (arrays of shape
/// (n, 3) in, an array of n values out), in `f64` or `f32` (directions rounded to `f32`,
/// values to `f32`, the integration in `f64`, as the crate's `_f32` forms).
///
/// `kind`: `"hemisphere"` (f(w); `peaks`, `abs_tol`, `rel_tol`, `max_evals`),
/// `"directional_albedo"` (f(wo, wi); `wo`, the `Config`), `"ndf_projected_area"` (d(m)),
/// `"smith_weak_furnace"` (`f` = d(m), `g1` = g1(wo, m); `wo`), `"reciprocity"` (f(a, b)).
/// Returns (value, error, evaluations, python_calls); for reciprocity (max_rel, worst a,
/// worst b, pairs, python_calls).
#[pyfunction]
#[pyo3(signature = (kind, f, g1 = None, wo = [0.0, 0.0, 1.0], peaks = vec![], abs_tol = 1e-10, rel_tol = 1e-7, max_evals = 2_000_000, f32 = false))]
#[allow(clippy::too_many_arguments)]
pub fn integrate<'py>(
    py: Python<'py>,
    kind: &str,
    f: Bound<'py, PyAny>,
    g1: Option<Bound<'py, PyAny>>,
    wo: [f64; 3],
    peaks: Vec<[f64; 3]>,
    abs_tol: f64,
    rel_tol: f64,
    max_evals: u64,
    f32: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let cfg = Config {
        abs_tol,
        rel_tol,
        max_evals,
    };
    let arity = match kind {
        "directional_albedo" | "reciprocity" => 2,
        _ => 1,
    };
    let mut main = Replay {
        py,
        f,
        arity,
        f32,
        cache: HashMap::new(),
        calls: 0,
    };
    let est = |e: Estimate, calls: u64| (e.value, e.error, e.evaluations, calls);
    let out = match (kind, f32) {
        ("hemisphere", false) => {
            let p: Vec<V3<f64>> = peaks.iter().map(|&w| v3(w)).collect();
            let e = main.run(&|g| brdf_integrate::hemisphere(|w| g(key1(w)), &p, &cfg))?;
            est(e, main.calls).into_pyobject(py)?.into_any()
        }
        ("hemisphere", true) => {
            let p: Vec<V3<f32>> = peaks.iter().map(|&w| v3f(w)).collect();
            let e = main.run(&|g| {
                #[allow(clippy::cast_possible_truncation)]
                brdf_integrate::hemisphere_f32(|w| g(key1(w32(w))) as f32, &p, &cfg)
            })?;
            est(e, main.calls).into_pyobject(py)?.into_any()
        }
        ("directional_albedo", false) => {
            let e = main.run(&|g| {
                brdf_integrate::directional_albedo_with(v3(wo), |a, b| g(key2(a, b)), &cfg)
            })?;
            est(e, main.calls).into_pyobject(py)?.into_any()
        }
        ("directional_albedo", true) => {
            let e = main.run(&|g| {
                #[allow(clippy::cast_possible_truncation)]
                brdf_integrate::directional_albedo_with_f32(
                    v3f(wo),
                    |a, b| g(key2(w32(a), w32(b))) as f32,
                    &cfg,
                )
            })?;
            est(e, main.calls).into_pyobject(py)?.into_any()
        }
        ("ndf_projected_area", false) => {
            let e = main.run(&|g| brdf_integrate::ndf_projected_area(|m| g(key1(m))))?;
            est(e, main.calls).into_pyobject(py)?.into_any()
        }
        ("ndf_projected_area", true) => {
            let e = main.run(&|g| {
                #[allow(clippy::cast_possible_truncation)]
                brdf_integrate::ndf_projected_area_f32(|m| g(key1(w32(m))) as f32)
            })?;
            est(e, main.calls).into_pyobject(py)?.into_any()
        }
        ("smith_weak_furnace", _) => {
            // Two integrands: G1 is replayed inside D's passes, D's values known first.
            let g1 = g1.ok_or_else(|| PyValueError::new_err("smith_weak_furnace needs g1"))?;
            let mut second = Replay {
                py,
                f: g1,
                arity: 2,
                f32,
                cache: HashMap::new(),
                calls: 0,
            };
            // One combined integrand keyed on m: the product needs both values, so each pass
            // fills both caches for the directions it lacks.
            let e = loop {
                let mut need_d: Vec<Key> = Vec::new();
                let mut need_g: Vec<Key> = Vec::new();
                let (dc, gc) = (&main.cache, &second.cache);
                let mut seen_d = HashSet::new();
                let mut seen_g = HashSet::new();
                let mut dfn = |k: Key| {
                    dc.get(&k).copied().unwrap_or_else(|| {
                        if seen_d.insert(k) {
                            need_d.push(k);
                        }
                        0.0
                    })
                };
                let mut gfn = |k: Key| {
                    gc.get(&k).copied().unwrap_or_else(|| {
                        if seen_g.insert(k) {
                            need_g.push(k);
                        }
                        0.0
                    })
                };
                #[allow(clippy::cast_possible_truncation)]
                let e = if f32 {
                    brdf_integrate::smith_weak_furnace_f32(
                        v3f(wo),
                        |m| dfn(key1(w32(m))) as f32,
                        |a, m| gfn(key2(w32(a), w32(m))) as f32,
                    )
                } else {
                    brdf_integrate::smith_weak_furnace(
                        v3(wo),
                        |m| dfn(key1(m)),
                        |a, m| gfn(key2(a, m)),
                    )
                };
                if need_d.is_empty() && need_g.is_empty() {
                    break e;
                }
                if main.calls as usize + second.calls as usize > 2 * MAX_PASSES {
                    return Err(PyRuntimeError::new_err("the integration did not settle"));
                }
                if !need_d.is_empty() {
                    let v = main.call(&need_d)?;
                    main.cache.extend(need_d.into_iter().zip(v));
                }
                if !need_g.is_empty() {
                    let v = second.call(&need_g)?;
                    second.cache.extend(need_g.into_iter().zip(v));
                }
            };
            est(e, main.calls + second.calls)
                .into_pyobject(py)?
                .into_any()
        }
        ("reciprocity", false) => {
            let r = main.run(&|g| brdf_integrate::reciprocity(|a, b| g(key2(a, b))))?;
            let (a, b) = r.worst;
            (
                r.max_rel,
                [a.x, a.y, a.z],
                [b.x, b.y, b.z],
                r.pairs,
                main.calls,
            )
                .into_pyobject(py)?
                .into_any()
        }
        ("reciprocity", true) => {
            let r = main.run(&|g| {
                #[allow(clippy::cast_possible_truncation)]
                brdf_integrate::reciprocity_f32(|a, b| g(key2(w32(a), w32(b))) as f32)
            })?;
            let (a, b) = r.worst;
            (
                r.max_rel,
                [a.x, a.y, a.z],
                [b.x, b.y, b.z],
                r.pairs,
                main.calls,
            )
                .into_pyobject(py)?
                .into_any()
        }
        _ => return Err(PyValueError::new_err(format!("no integrator `{kind}`"))),
    };
    Ok(out)
}
