//! `brdf._native`: the extension module behind the Python package `brdf` (python/py/brdf).
//!
//! It exposes the reference CLI's kernel table (`brdf_ref::KERNELS`) as data, one evaluator
//! per float type over it, the parameter types' validation, and the integrators with a Python
//! callable; the package builds its submodules (`brdf.ggx.d`, ...) from that data at import.
//!
//! | function | what |
//! |---|---|
//! | [`kernels`] | the table: path, summary, arguments and domains, outputs, constraints, doc |
//! | [`eval_f64`], [`eval_f32`] | one kernel over contiguous 1-D arrays (length n, or 1 to broadcast) |
//! | [`eval_row`] | one kernel on one row, scalar or lane entry: the tests' reference |
//! | [`check_rows`] | the CLI's domain and constraint checks on every row (`check=True`) |
//! | [`validate`] | a parameter type's constructor on its arguments: `ValueError` naming the bad one |
//! | [`integrate`] | `brdf::integrate`'s integrators over a Python callable on arrays of directions |

use brdf::wide::{f32x8, f64x4};
use brdf::{Mask, Real};
use brdf_ref::table::Eval;
use brdf_ref::{KERNELS, Kernel};
use numpy::{PyReadonlyArray1, PyReadwriteArray1, PyUntypedArrayMethods};
use pyo3::exceptions::{PyIndexError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rayon::prelude::*;

mod docs {
    include!(concat!(env!("OUT_DIR"), "/docs.rs"));
}
mod integrators;
mod params;

/// Elements per thread task: below twice this an array runs on the calling thread, so small
/// arrays never pay the pool's hand-off; 32768 elements are tens of microseconds of work even
/// for the cheapest kernel (python/bench.py), well above a hand-off.
const CHUNK: usize = 1 << 15;

fn kernel(index: usize) -> PyResult<&'static Kernel> {
    KERNELS
        .get(index)
        .ok_or_else(|| PyIndexError::new_err(format!("no kernel {index}")))
}

fn lookup(table: &'static [(&'static str, &'static str)], key: &str) -> Option<&'static str> {
    table
        .binary_search_by(|(k, _)| (*k).cmp(key))
        .ok()
        .map(|i| table[i].1)
}

/// The Rust doc comment of a table path: the function's own; for a method without one, its
/// trait's (found by build.rs); else `None`.
fn doc_of(path: &str) -> Option<&'static str> {
    lookup(docs::FN_DOCS, path)
}

/// The kernel table as a list of dicts (in table order): `path`, `summary`, `args` (name,
/// domain text, lo, hi, lo_open, hi_open, integer), `outputs` (name, range text),
/// `constraints` (in words), `unit_vectors` (argument index triples), `doc` (the Rust doc
/// comment, or None), `type_doc` (the doc of the type a method belongs to, or None).
#[pyfunction]
fn kernels(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for k in KERNELS {
        let d = PyDict::new(py);
        d.set_item("path", k.path)?;
        d.set_item("summary", k.summary)?;
        let args: Vec<_> = k
            .args
            .iter()
            .map(|a| {
                let m = a.domain;
                (a.name, m.text, m.lo, m.hi, m.lo_open, m.hi_open, m.integer)
            })
            .collect();
        d.set_item("args", args)?;
        let outs: Vec<_> = k.outputs.iter().map(|o| (o.name, o.range.text)).collect();
        d.set_item("outputs", outs)?;
        d.set_item("constraints", k.constraints_all())?;
        d.set_item("unit_vectors", k.unit_vectors())?;
        d.set_item("doc", doc_of(k.path))?;
        let owner = k.path.rsplit_once("::").map(|(o, _)| o);
        d.set_item("type_doc", owner.and_then(|o| doc_of(&format!("{o}::"))))?;
        list.append(d)?;
    }
    Ok(list)
}

/// The inner doc (`//!`) of a module of the crate by its Rust path (`ggx`, `ibl::dfg`).
#[pyfunction]
fn module_doc(path: &str) -> Option<&'static str> {
    lookup(docs::MOD_DOCS, path)
}

/// Loads and stores of a scalar type from and to slices (the `lanes=False` path; the lane
/// path runs through the table's whole-array entries, [`Kernel::f64_arrays`]).
trait Pack: Real {
    /// The value `s[0]`.
    fn load(s: &[Self::Scalar]) -> Self;
    /// The value into `s[0]`.
    fn store(self, s: &mut [Self::Scalar]);
}

macro_rules! pack_scalar {
    ($t:ty) => {
        impl Pack for $t {
            #[inline]
            fn load(s: &[$t]) -> Self {
                s[0]
            }
            #[inline]
            fn store(self, s: &mut [$t]) {
                s[0] = self;
            }
        }
    };
}
pack_scalar!(f32);
pack_scalar!(f64);

/// Evaluates `eval` over `n` elements in groups of `L::LANES`: input `i` is `ins[i]` (length
/// `n`, or 1 for one value broadcast to every element), outputs are written to `outs` (length
/// `n` each). A partial last group repeats its last element in the missing lanes (a value
/// the caller gave, as `brdf::batch` does), and only the real elements are stored. Each
/// element's outputs are those of its row splat to every lane (the lanes NaN appears in are
/// evaluated again alone, see inside).
fn run_lanes<L: Pack>(eval: Eval<L>, ins: &[&[L::Scalar]], outs: &mut [&mut [L::Scalar]], n: usize)
where
    L::Scalar: Copy,
{
    let w = L::LANES;
    // UNROLL groups are gathered, evaluated back to back and stored: the calls carry no
    // dependency on each other, so the processor overlaps their latency chains.
    const UNROLL: usize = 4;
    let init: Vec<L> = ins.iter().map(|s| L::from_scalar(s[0])).collect();
    let mut x: [Vec<L>; UNROLL] = core::array::from_fn(|_| init.clone());
    let mut y: [Vec<L>; UNROLL] = core::array::from_fn(|_| vec![L::ZERO; outs.len()]);
    let mut start = 0;
    while start < n {
        let block = (n - start).div_ceil(w).min(UNROLL);
        for (g, xg) in x.iter_mut().enumerate().take(block) {
            let s0 = start + g * w;
            let len = w.min(n - s0);
            for (xi, s) in xg.iter_mut().zip(ins) {
                if s.len() != 1 {
                    let sl = &s[s0..s0 + len];
                    *xi = if len == w {
                        L::load(sl)
                    } else {
                        L::from_fn(|i| sl[i.min(len - 1)])
                    };
                }
            }
        }
        for (xg, yg) in x.iter().zip(y.iter_mut()).take(block) {
            eval(xg, yg);
        }
        for g in 0..block {
            let s0 = start + g * w;
            let len = w.min(n - s0);
            for (o, v) in outs.iter_mut().zip(&y[g]) {
                v.store(&mut o[s0..s0 + len]);
            }
            if w > 1 && y[g].iter().any(|v| v.is_nan().any()) {
                // A lane holding NaN may owe it to its neighbours: a kernel that builds a
                // validated parameter type (`Ggx::new`, `PhongDiffuseSpecular::new`) gets NaN
                // in every lane when one lane's parameters are invalid (the constructor checks
                // all lanes). Such a lane is evaluated again alone, its row in every lane, so
                // each element's result depends on its own inputs only, as numpy users expect.
                for i in 0..len {
                    if y[g].iter().any(|v| is_nan(v.lane(i))) {
                        let xi: Vec<L> = x[g].iter().map(|v| L::from_scalar(v.lane(i))).collect();
                        let mut yi = vec![L::ZERO; y[g].len()];
                        eval(&xi, &mut yi);
                        for (o, v) in outs.iter_mut().zip(&yi) {
                            o[s0 + i] = v.lane(0);
                        }
                    }
                }
            }
        }
        start += block * w;
    }
}

/// NaN test on a lane value (NaN is the one value unequal to itself).
#[allow(clippy::eq_op)]
fn is_nan<S: PartialOrd + Copy>(v: S) -> bool {
    v != v
}

/// `run(ins, outs, n)` split over rayon's pool in tasks of [`CHUNK`] elements when `n` is large.
fn run_par<S: Copy + Send + Sync>(
    run: impl Fn(&[&[S]], &mut [&mut [S]], usize) + Sync,
    ins: &[&[S]],
    outs: &mut [&mut [S]],
    n: usize,
) {
    if n < 2 * CHUNK {
        run(ins, outs, n);
        return;
    }
    // One task per chunk: the chunk's slice of every input (or the broadcast value) and of
    // every output.
    let tasks = n.div_ceil(CHUNK);
    let mut out_chunks: Vec<Vec<&mut [S]>> = (0..tasks).map(|_| Vec::new()).collect();
    for o in outs.iter_mut() {
        for (t, c) in o.chunks_mut(CHUNK).enumerate() {
            out_chunks[t].push(c);
        }
    }
    out_chunks
        .into_par_iter()
        .enumerate()
        .for_each(|(t, mut oc)| {
            let lo = t * CHUNK;
            let hi = (lo + CHUNK).min(n);
            let ic: Vec<&[S]> = ins
                .iter()
                .map(|s| if s.len() == 1 { *s } else { &s[lo..hi] })
                .collect();
            run(&ic, &mut oc, hi - lo);
        });
}

/// Checks the inputs' lengths (n or 1) and returns n.
fn common_len(lens: &[usize], nargs: usize) -> PyResult<usize> {
    if lens.len() != nargs {
        return Err(PyValueError::new_err(format!(
            "expected {nargs} input arrays, got {}",
            lens.len()
        )));
    }
    let n = lens.iter().copied().filter(|&l| l != 1).max().unwrap_or(1);
    if let Some(l) = lens.iter().find(|&&l| l != 1 && l != n) {
        return Err(PyValueError::new_err(format!(
            "input lengths {l} and {n} differ (each must be n or 1)"
        )));
    }
    Ok(n)
}

macro_rules! evaluator {
    ($(#[$doc:meta])* $name:ident, $s:ty, $scalar:ident, $arrays:ident) => {
        $(#[$doc])*
        #[pyfunction]
        #[pyo3(signature = (index, inputs, outputs, lanes = true, threads = true))]
        fn $name<'py>(
            py: Python<'py>,
            index: usize,
            inputs: Vec<PyReadonlyArray1<'py, $s>>,
            mut outputs: Vec<PyReadwriteArray1<'py, $s>>,
            lanes: bool,
            threads: bool,
        ) -> PyResult<()> {
            let k = kernel(index)?;
            if outputs.len() != k.outputs.len() {
                return Err(PyValueError::new_err(format!(
                    "{} has {} outputs, got {} arrays",
                    k.path,
                    k.outputs.len(),
                    outputs.len()
                )));
            }
            let lens: Vec<usize> = inputs.iter().map(|a| a.len()).collect();
            let n = common_len(&lens, k.args.len())?;
            if outputs.iter().any(|o| o.len() != n) || lens.contains(&0) {
                return if outputs.iter().all(|o| o.len() == 0) {
                    Ok(())
                } else {
                    Err(PyValueError::new_err(format!("every output must have length {n}")))
                };
            }
            let contiguous = |e| PyValueError::new_err(format!("arrays must be contiguous: {e}"));
            let ins: Vec<&[$s]> = inputs
                .iter()
                .map(|a| a.as_slice())
                .collect::<Result<_, _>>()
                .map_err(contiguous)?;
            let mut o: Vec<&mut [$s]> = outputs
                .iter_mut()
                .map(|a| a.as_slice_mut())
                .collect::<Result<_, _>>()
                .map_err(contiguous)?;
            // The lane path: the table's whole-array loop (the kernel inlined into it, no
            // call per group); its length checks hold here, so it always writes.
            let arrays = |i: &[&[$s]], o: &mut [&mut [$s]], n: usize| {
                let _ = (k.$arrays)(i, o, n);
            };
            let scalar = |i: &[&[$s]], o: &mut [&mut [$s]], n: usize| {
                run_lanes::<$s>(k.$scalar, i, o, n);
            };
            py.detach(|| match (lanes, threads) {
                (true, true) => run_par(arrays, &ins, &mut o, n),
                (true, false) => arrays(&ins, &mut o, n),
                (false, true) => run_par(scalar, &ins, &mut o, n),
                (false, false) => scalar(&ins, &mut o, n),
            });
            Ok(())
        }
    };
}

evaluator!(
    /// Kernel `index` of the table on `f64` inputs (each contiguous, length n or 1), written
    /// into `outputs` (one contiguous array of length n per output; numpy allocates them, so
    /// its memory is reused as numpy's own temporaries are). `lanes`: the table's whole-array `f64x4` entry `f64_arrays` (else its scalar `f64` entry, one call per element);
    /// `threads`: split arrays above 65536 elements over rayon's pool. The GIL is released.
    eval_f64, f64, f64, f64_arrays
);
evaluator!(
    /// [`eval_f64`] on `f32` (`f32x8` lanes, or the scalar `f32` entry).
    eval_f32, f32, f32, f32_arrays
);

/// Kernel `index` on one row through the table's own entries, the route the CLI takes: the
/// scalar entry (`lanes = False`) or the lane entry with the row splat to every lane, lane 0
/// kept. `f32 = True` rounds the row to `f32` and runs the `f32`/`f32x8` entries. The tests'
/// reference for the array path.
#[pyfunction]
#[pyo3(signature = (index, row, f32, lanes))]
fn eval_row(index: usize, row: Vec<f64>, f32: bool, lanes: bool) -> PyResult<Vec<f64>> {
    let k = kernel(index)?;
    if row.len() != k.args.len() {
        return Err(PyValueError::new_err(format!(
            "{} takes {} arguments, got {}",
            k.path,
            k.args.len(),
            row.len()
        )));
    }
    let m = k.outputs.len();
    #[allow(clippy::cast_possible_truncation)]
    let out = match (f32, lanes) {
        (false, false) => k.eval_f64(&row),
        (true, false) => k.eval_as(
            &row.iter().map(|&v| f64::from(v as f32)).collect::<Vec<_>>(),
            brdf_ref::Float::F32,
        ),
        (false, true) => {
            let x: Vec<f64x4> = row.iter().map(|&v| f64x4::splat(v)).collect();
            let mut y = vec![f64x4::splat(f64::NAN); m];
            (k.f64x4)(&x, &mut y);
            y.iter().map(|v| v.lane(0)).collect()
        }
        (true, true) => {
            let x: Vec<f32x8> = row.iter().map(|&v| f32x8::splat(v as f32)).collect();
            let mut y = vec![f32x8::splat(f32::NAN); m];
            (k.f32x8)(&x, &mut y);
            y.iter().map(|v| f64::from(v.lane(0))).collect()
        }
    };
    Ok(out)
}

/// The CLI's input check on every row (inputs as `f64` arrays of length n or 1, each value
/// exactly a value of the float type): `ValueError` for the first row with an argument
/// outside its domain ([`brdf_ref::Domain::contains_as`], NaN included) or a broken relation
/// between arguments ([`Kernel::broken_constraint`]: unit vectors, orderings), naming the
/// arguments and the element's flat index.
#[pyfunction]
fn check_rows(index: usize, inputs: Vec<PyReadonlyArray1<'_, f64>>, f32: bool) -> PyResult<()> {
    let k = kernel(index)?;
    let lens: Vec<usize> = inputs.iter().map(|a| a.len()).collect();
    if lens.contains(&0) {
        return Ok(());
    }
    let n = common_len(&lens, k.args.len())?;
    let cols: Vec<&[f64]> = inputs
        .iter()
        .map(|a| a.as_slice())
        .collect::<Result<_, _>>()
        .map_err(|e| PyValueError::new_err(format!("arrays must be contiguous: {e}")))?;
    let ty = if f32 {
        brdf_ref::Float::F32
    } else {
        brdf_ref::Float::F64
    };
    let dotted = k.path.replace("::", ".");
    let mut row = vec![0.0; cols.len()];
    for r in 0..n {
        for ((v, c), a) in row.iter_mut().zip(&cols).zip(k.args) {
            *v = if c.len() == 1 { c[0] } else { c[r] };
            if !a.domain.contains_as(*v, ty) {
                return Err(PyValueError::new_err(format!(
                    "brdf.{dotted}: argument `{}` = {} (element {r}) lies outside its domain {}",
                    a.name, *v, a.domain.text
                )));
            }
        }
        if let Some(b) = k.broken_constraint(&row, ty) {
            let names: Vec<&str> = b.args.iter().map(|&i| k.args[i].name).collect();
            return Err(PyValueError::new_err(format!(
                "brdf.{dotted}: arguments {} (element {r}): {}",
                names.join(", "),
                b.text
            )));
        }
    }
    Ok(())
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(kernels, m)?)?;
    m.add_function(wrap_pyfunction!(module_doc, m)?)?;
    m.add_function(wrap_pyfunction!(eval_f64, m)?)?;
    m.add_function(wrap_pyfunction!(eval_f32, m)?)?;
    m.add_function(wrap_pyfunction!(eval_row, m)?)?;
    m.add_function(wrap_pyfunction!(check_rows, m)?)?;
    m.add_function(wrap_pyfunction!(params::validate, m)?)?;
    m.add_function(wrap_pyfunction!(params::param_types, m)?)?;
    m.add_function(wrap_pyfunction!(integrators::integrate, m)?)?;
    m.add("ALPHA_MIN", brdf::microfacet::ALPHA_MIN)?;
    m.add("ALPHA_MAX", brdf::microfacet::ALPHA_MAX)?;
    Ok(())
}
