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
    mut outputs: [&mut [T::Scalar]; O],
    mut kernel: impl FnMut([T; I]) -> [T; O],
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
    let lanes = T::LANES;
    let full = n - n % lanes;
    let mut base = 0;
    while base < full {
        let x: [T; I] = core::array::from_fn(|k| {
            let s = &inputs[k][base..base + lanes];
            T::from_fn(|l| s[l])
        });
        let y = kernel(x);
        for (out, v) in outputs.iter_mut().zip(y) {
            let s = &mut out[base..base + lanes];
            for (l, e) in s.iter_mut().enumerate() {
                *e = v.lane(l);
            }
        }
        base += lanes;
    }
    let rem = n - full;
    if rem > 0 {
        let x: [T; I] = core::array::from_fn(|k| {
            let s = &inputs[k][full..];
            T::from_fn(|l| s[l.min(rem - 1)])
        });
        let y = kernel(x);
        for (out, v) in outputs.iter_mut().zip(y) {
            for (l, e) in out[full..].iter_mut().enumerate() {
                *e = v.lane(l);
            }
        }
    }
    Ok(n)
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
