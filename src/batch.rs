//! Batch evaluation over structure-of-arrays slices: any kernel written against [`Real`]
//! applied to whole slices, eight `f32` or four `f64` elements at a time, with a correct tail,
//! allocation-free. What a wavefront renderer, a look-up-table builder and the crate's own
//! benchmarks use.
//!
//! ```
//! # #[cfg(feature = "ggx")]
//! # fn main() -> Result<(), brdf::ParamError> {
//! use brdf::{batch, ggx};
//!
//! // GGX D for 1000 (n.h, alpha) pairs, stored as two input slices and one output slice.
//! let n_dot_h: Vec<f32> = (0..1000).map(|i| i as f32 / 999.0).collect();
//! let alpha = vec![0.3f32; 1000];
//! let mut d = vec![0.0f32; 1000];
//! batch::run_f32([&n_dot_h, &alpha], [&mut d], |[c, a]| [ggx::d(c, a)])?;
//! assert_eq!(d[999], ggx::d(1.0f32, 0.3));
//! # Ok(())
//! # }
//! # #[cfg(not(feature = "ggx"))]
//! # fn main() {}
//! ```
//!
//! The kernel receives `I` lane values (one per input slice) and returns `O` (one per output
//! slice): several inputs and outputs (a direction's three components, an RGB result) are
//! just more slices. [`run_f32`] runs on `f32x8`, [`run_f64`] on `f64x4`, and [`run`] on any
//! lane type, scalars included (to compare a lane path against its scalar path on the same
//! data).
//!
//! Speed: write the kernel as a `move` closure when it captures parameters (`move |[c]|
//! [fresnel::conductor_fast(c, eta, k)]`). A closure that borrows them makes the compiler
//! reload them after every store to an output (it cannot prove that the output slices, which
//! reach the loop inside an array, do not alias them) and redo for every group the work that
//! depends on them alone: a rough conductor with constant alpha, eta and k took 1.3x as long
//! borrowed as moved (`bench/benches/throughput.rs`'s timing mode, rows `rough_conductor_fast` and
//! `rough_conductor_fast_borrowed`, native build). The loop itself has no bounds check, so
//! that work is hoisted out of it once the parameters are values.
//!
//! The tail: when the length is not a multiple of the lane count, the last group is loaded
//! with its missing lanes set to the group's last element (a valid input, so a kernel sees
//! no value the caller did not give), evaluated, and only the real elements are stored.
//! Each element's result is the same as that of evaluating the kernel on it alone: lanes do
//! not interact (the crate's kernels guarantee it; a custom kernel that mixes lanes breaks
//! it).

use crate::error::ParamError;
use crate::real::Real;
use wide::{f32x8, f64x4};

/// `kernel` applied element by element over `inputs` into `outputs`, `T::LANES` elements per
/// call: every input and output slice must have the same length (else an error, and nothing
/// is written). Returns the number of elements evaluated.
///
/// # Errors
/// [`ParamError`] naming `inputs` or `outputs` when a slice's length differs from the first
/// input's (or, with no input, the first output's).
pub fn run<T: Real, const I: usize, const O: usize>(
    inputs: [&[T::Scalar]; I],
    outputs: [&mut [T::Scalar]; O],
    kernel: impl FnMut([T; I]) -> [T; O],
) -> Result<usize, ParamError> {
    let n = match (inputs.first(), outputs.first()) {
        (Some(s), _) => s.len(),
        (None, Some(s)) => s.len(),
        (None, None) => return Ok(0),
    };
    if inputs.iter().any(|s| s.len() != n) {
        return Err(ParamError {
            param: "inputs",
            expected: "slices of one length",
        });
    }
    if outputs.iter().any(|s| s.len() != n) {
        return Err(ParamError {
            param: "outputs",
            expected: "slices of the inputs' length",
        });
    }
    match T::LANES {
        8 => groups::<T, 8, I, O>(n, inputs, outputs, kernel),
        4 => groups::<T, 4, I, O>(n, inputs, outputs, kernel),
        _ => groups::<T, 1, I, O>(n, inputs, outputs, kernel),
    }
    Ok(n)
}

/// A slice as whole groups of N elements and the tail.
type Part<'a, S, const N: usize> = (&'a [[S; N]], &'a [S]);
/// A mutable slice as whole groups of N elements and the tail.
type PartMut<'a, S, const N: usize> = (&'a mut [[S; N]], &'a mut [S]);

/// The loop of [`run`] for `N = T::LANES` elements per group, over slices of length `n`
/// (checked by the caller). The slices are viewed as arrays of `[T::Scalar; N]` cut to the
/// same number of whole groups before the loop, so indexing them by group needs no bounds
/// check: the loop has no panic path, and LLVM hoists whatever the kernel computes from
/// loop-invariant arguments (a constant alpha, eta and k) out of it. With a check (and its
/// panic) in the loop, `wide`'s x86 intrinsics may not be moved above it, and a rough
/// conductor redid its per-(eta, k) work, half its time, for every group.
#[inline]
fn groups<T: Real, const N: usize, const I: usize, const O: usize>(
    n: usize,
    inputs: [&[T::Scalar]; I],
    outputs: [&mut [T::Scalar]; O],
    mut kernel: impl FnMut([T; I]) -> [T; O],
) {
    debug_assert_eq!(N, T::LANES);
    let g = n / N;
    // Whole groups, each slice cut to exactly g of them (`split_at_checked` cannot fail for
    // slices of length n; the early return keeps a panic path out of the function).
    let mut ins: [Part<'_, T::Scalar, N>; I] = [(&[], &[]); I];
    for (slot, s) in ins.iter_mut().zip(inputs) {
        let (whole, tail) = s.as_chunks::<N>();
        let Some((whole, _)) = whole.split_at_checked(g) else {
            return;
        };
        *slot = (whole, tail);
    }
    let mut outs: [PartMut<'_, T::Scalar, N>; O] =
        core::array::from_fn(|_| (Default::default(), Default::default()));
    for (slot, s) in outs.iter_mut().zip(outputs) {
        let (whole, tail) = s.as_chunks_mut::<N>();
        let Some((whole, _)) = whole.split_at_mut_checked(g) else {
            return;
        };
        *slot = (whole, tail);
    }
    let pad = [T::Scalar::ZERO; N];
    let mut sink = [T::Scalar::ZERO; N];
    for j in 0..g {
        // `get` with a fallback rather than indexing: j < g always holds, and no bounds check
        // (with its panic) enters the loop; the fallbacks compile to selects.
        let x: [T; I] = core::array::from_fn(|k| {
            let c = ins[k].0.get(j).unwrap_or(&pad);
            T::from_fn(|l| c[l % N])
        });
        let y = kernel(x);
        for (out, v) in outs.iter_mut().zip(y) {
            let c = out.0.get_mut(j).unwrap_or(&mut sink);
            for (l, e) in c.iter_mut().enumerate() {
                *e = v.lane(l);
            }
        }
    }
    let rem = n - g * N;
    if rem > 0 {
        let x: [T; I] = core::array::from_fn(|k| {
            let s = ins[k].1;
            T::from_fn(|l| s.get(l.min(rem - 1)).copied().unwrap_or(T::Scalar::ZERO))
        });
        let y = kernel(x);
        for (out, v) in outs.into_iter().zip(y) {
            for (l, e) in out.1.iter_mut().enumerate() {
                *e = v.lane(l);
            }
        }
    }
}

/// Elements per task of the parallel forms ([`par_run`]): 2^14, a multiple of every lane
/// count. Large enough that a task (tens of microseconds for the cheapest kernel) dwarfs
/// rayon's cost of scheduling it, small enough that 10^6 elements make 61 tasks to balance
/// over the cores.
#[cfg(feature = "rayon")]
pub const PAR_CHUNK: usize = 1 << 14;

/// One chunk of [`par_run`]: its input slices and its output slices.
#[cfg(feature = "rayon")]
type Task<'a, S, const I: usize, const O: usize> = ([&'a [S]; I], [&'a mut [S]; O]);

/// [`run`] over all cores with `rayon`: the slices are cut into chunks of [`PAR_CHUNK`]
/// elements (the last one shorter), and each chunk is one [`run`] on rayon's global thread
/// pool (or the pool of an enclosing `ThreadPool::install`). The kernel is `Fn + Sync + Clone`
/// (a `move` closure over `Copy` parameters is all three), and each chunk runs its own clone:
/// a kernel [`run`] only reaches through a reference keeps its captured parameters in memory
/// the output writes might alias, so the work that depends on them alone (the alpha, eta and
/// k factors of a fixed-parameter loop) is redone for every group of lanes instead of once
/// (the `batch` module docs; in `bench/mitsuba/compare.py --parallel` the fast rough
/// conductor did not scale at all on 2 cores before each chunk had its own copy). Every element's
/// result is bit for bit what [`run`] gives: chunks are whole groups of lanes, so the
/// grouping, and with it each element's evaluation, is [`run`]'s (lanes do not interact;
/// `tests/lanes/batch_par.rs`). Batches of at most one chunk run on the calling thread.
///
/// Behind the feature `rayon`, which needs `std` (the crate stays `no_std` without it).
///
/// # Errors
/// As [`run`]: slices of different lengths (checked before any work, nothing written).
#[cfg(feature = "rayon")]
pub fn par_run<T: Real, const I: usize, const O: usize>(
    inputs: [&[T::Scalar]; I],
    outputs: [&mut [T::Scalar]; O],
    kernel: impl Fn([T; I]) -> [T; O] + Sync + Clone,
) -> Result<usize, ParamError>
where
    T::Scalar: Send + Sync,
{
    use rayon::prelude::*;
    extern crate alloc;
    use alloc::vec::Vec;

    let n = match (inputs.first(), outputs.first()) {
        (Some(s), _) => s.len(),
        (None, Some(s)) => s.len(),
        (None, None) => return Ok(0),
    };
    if inputs.iter().any(|s| s.len() != n) || outputs.iter().any(|s| s.len() != n) {
        // `run` names the slice that differs.
        return run::<T, I, O>(inputs, outputs, kernel);
    }
    if n <= PAR_CHUNK {
        return run::<T, I, O>(inputs, outputs, kernel);
    }
    // One task per chunk: its input slices and its (disjoint) output slices.
    let mut outs: [_; O] = outputs.map(|o| o.chunks_mut(PAR_CHUNK));
    let tasks: Vec<Task<'_, T::Scalar, I, O>> = (0..n.div_ceil(PAR_CHUNK))
        .map(|c| {
            let lo = c * PAR_CHUNK;
            let hi = (lo + PAR_CHUNK).min(n);
            let ins = inputs.map(|s| s.get(lo..hi).unwrap_or(&[]));
            let os = core::array::from_fn(|k| outs[k].next().unwrap_or_default());
            (ins, os)
        })
        .collect();
    tasks.into_par_iter().for_each(|(ins, os)| {
        // Each chunk's slices have one length: `run` cannot fail here. The clone is the
        // chunk's own (see above): its captures are locals the compiler can hoist.
        let _ = run::<T, I, O>(ins, os, kernel.clone());
    });
    Ok(n)
}

/// [`par_run`] on `f32x8` lanes over `f32` slices.
///
/// # Errors
/// As [`run`]: slices of different lengths.
#[cfg(feature = "rayon")]
pub fn par_run_f32<const I: usize, const O: usize>(
    inputs: [&[f32]; I],
    outputs: [&mut [f32]; O],
    kernel: impl Fn([f32x8; I]) -> [f32x8; O] + Sync + Clone,
) -> Result<usize, ParamError> {
    par_run::<f32x8, I, O>(inputs, outputs, kernel)
}

/// [`par_run`] on `f64x4` lanes over `f64` slices.
///
/// # Errors
/// As [`run`]: slices of different lengths.
#[cfg(feature = "rayon")]
pub fn par_run_f64<const I: usize, const O: usize>(
    inputs: [&[f64]; I],
    outputs: [&mut [f64]; O],
    kernel: impl Fn([f64x4; I]) -> [f64x4; O] + Sync + Clone,
) -> Result<usize, ParamError> {
    par_run::<f64x4, I, O>(inputs, outputs, kernel)
}

/// [`run`] on `f32x8` lanes over `f32` slices.
///
/// # Errors
/// As [`run`]: slices of different lengths.
#[inline]
pub fn run_f32<const I: usize, const O: usize>(
    inputs: [&[f32]; I],
    outputs: [&mut [f32]; O],
    kernel: impl FnMut([f32x8; I]) -> [f32x8; O],
) -> Result<usize, ParamError> {
    run::<f32x8, I, O>(inputs, outputs, kernel)
}

/// [`run`] on `f64x4` lanes over `f64` slices.
///
/// # Errors
/// As [`run`]: slices of different lengths.
#[inline]
pub fn run_f64<const I: usize, const O: usize>(
    inputs: [&[f64]; I],
    outputs: [&mut [f64]; O],
    kernel: impl FnMut([f64x4; I]) -> [f64x4; O],
) -> Result<usize, ParamError> {
    run::<f64x4, I, O>(inputs, outputs, kernel)
}
