//! Stability: every kernel of the reference table on the extreme inputs of its documented
//! domain (`brdf_ref::Domain::extremes`: both ends or the floats just inside open ends, one
//! rounding inside each end, 0, -0, the smallest subnormal and normal, 1 - 2^-24 (f32) /
//! 1 - 2^-53 (f64), 1 + eps, 1e-6 from 1, the microfacet clamps ALPHA_MIN and ALPHA_MAX, the
//! largest finite float where the domain reaches it, +inf where it is allowed; unit vectors
//! from a list of extreme directions), combined across arguments by
//! `brdf_ref::points::extreme_rows` (every combination up to a cap, else every extreme of
//! every argument at least once and deterministic random rows), on `f32`, `f64` and the lanes. Counts NaN, inf and results outside the output's
//! stated range: for in-domain input the crate promises none of the three.

use brdf::wide::{f32x8, f64x4};
use brdf_ref::points::extreme_rows;
use brdf_ref::{Float, Kernel};

/// Counts for one kernel on one float type.
#[derive(Clone, Debug, Default)]
pub struct Counts {
    /// Input combinations evaluated.
    pub combos: usize,
    /// NaN outputs.
    pub nan: usize,
    /// Infinite outputs (counted only where the output's range excludes them).
    pub inf: usize,
    /// Finite outputs outside the stated range.
    pub out_of_range: usize,
    /// Lane results that differ from the scalar result (bits; NaN = NaN).
    pub lane_mismatch: usize,
    /// The first failing input, for the report.
    pub first_bad: Option<(Vec<f64>, Vec<f64>)>,
}

/// One kernel's counts in f32 and f64.
#[derive(Clone, Debug)]
pub struct Row {
    /// The kernel's path.
    pub path: &'static str,
    /// Counts on f32 (lanes: f32x8).
    pub f32: Counts,
    /// Counts on f64 (lanes: f64x4).
    pub f64: Counts,
}

macro_rules! check_type {
    ($name:ident, $t:ty, $lanes:ty, $n:literal, $field:ident, $lane_field:ident, $float:expr) => {
        fn $name(k: &Kernel, cap: usize) -> Counts {
            let points = extreme_rows(k, $float, cap);
            let mut c = Counts {
                combos: points.len(),
                ..Counts::default()
            };
            let nout = k.outputs.len();
            let mut y = vec![0.0 as $t; nout];
            let mut scalar_out: Vec<Vec<$t>> = Vec::with_capacity(points.len());
            for p in &points {
                let x: Vec<$t> = p.iter().map(|&v| v as $t).collect();
                (k.$field)(&x, &mut y);
                let mut bad = false;
                for (o, &v) in k.outputs.iter().zip(&y) {
                    let v = f64::from(v);
                    if v.is_nan() {
                        c.nan += 1;
                        bad = true;
                    } else if v.is_infinite() && !o.range.contains_as(v, $float) {
                        c.inf += 1;
                        bad = true;
                    } else if !o.range.contains_as(v, $float) {
                        c.out_of_range += 1;
                        bad = true;
                    }
                }
                if bad && c.first_bad.is_none() {
                    c.first_bad = Some((p.clone(), y.iter().map(|&v| f64::from(v)).collect()));
                }
                scalar_out.push(y.clone());
            }
            // Lanes: the same points, $n at a time, against the scalar results.
            let nin = k.args.len();
            for (chunk, outs) in points.chunks($n).zip(scalar_out.chunks($n)) {
                let x: Vec<$lanes> = (0..nin)
                    .map(|j| {
                        let mut a = [0.0 as $t; $n];
                        for (i, slot) in a.iter_mut().enumerate() {
                            *slot = chunk[i.min(chunk.len() - 1)][j] as $t;
                        }
                        <$lanes>::from(a)
                    })
                    .collect();
                let mut ly = vec![<$lanes>::from([0.0 as $t; $n]); nout];
                (k.$lane_field)(&x, &mut ly);
                for (i, s) in outs.iter().enumerate() {
                    for (o, lane) in ly.iter().enumerate() {
                        let l = lane.to_array()[i];
                        if l.to_bits() != s[o].to_bits() && !(l.is_nan() && s[o].is_nan()) {
                            c.lane_mismatch += 1;
                        }
                    }
                }
            }
            c
        }
    };
}

check_type!(check_f32, f32, f32x8, 8, f32, f32x8, Float::F32);
check_type!(check_f64, f64, f64x4, 4, f64, f64x4, Float::F64);

/// Every kernel of the table, at most `cap` combinations per kernel and type.
pub fn run(cap: usize) -> Vec<Row> {
    brdf_ref::KERNELS
        .iter()
        .map(|k| Row {
            path: k.path,
            f32: check_f32(k, cap),
            f64: check_f64(k, cap),
        })
        .collect()
}
