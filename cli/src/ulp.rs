//! ULP distances and the statistics `brdf-ref diff` prints.
//!
//! The distance between two floats of one type is the difference of their positions in the
//! type's ordered integer representation (the bits of a non-negative float read as an
//! integer, negated for a negative one), so adjacent floats are 1 apart, +0 and -0 are 0
//! apart, and the distance crosses zero without a jump. Two NaNs are 0 apart (both sides
//! agree there is no value); a NaN against a number, or an infinity against a finite value
//! or the opposite infinity, has no ULP distance and is counted as a mismatch instead.

use crate::table::Float;

/// The position of `x` (a value of type `ty`, given as an `f64`) in the ordered integer
/// representation of `ty`.
#[must_use]
pub fn ordered(x: f64, ty: Float) -> i128 {
    match ty {
        Float::F32 => {
            #[allow(clippy::cast_possible_truncation)]
            let b = (x as f32).to_bits();
            let mag = i128::from(b & 0x7FFF_FFFF);
            if b >> 31 == 1 { -mag } else { mag }
        }
        Float::F64 => {
            let b = x.to_bits();
            let mag = i128::from(b & 0x7FFF_FFFF_FFFF_FFFF);
            if b >> 63 == 1 { -mag } else { mag }
        }
    }
}

/// How two values of one output compare.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compare {
    /// Both are numbers (or both NaN, or the same infinity): their ULP distance.
    Ulp(u128),
    /// One is NaN and the other is not.
    NanMismatch,
    /// One is infinite and the other is finite or the opposite infinity.
    InfMismatch,
}

/// The comparison of `a` and `b`, values of type `ty`.
#[must_use]
pub fn compare(a: f64, b: f64, ty: Float) -> Compare {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => return Compare::Ulp(0),
        (true, false) | (false, true) => return Compare::NanMismatch,
        _ => {}
    }
    if a.is_infinite() || b.is_infinite() {
        return if a == b {
            Compare::Ulp(0)
        } else {
            Compare::InfMismatch
        };
    }
    Compare::Ulp((ordered(a, ty) - ordered(b, ty)).unsigned_abs())
}

/// |a - b| / max(|a|, |b|), 0 where both are 0 (finite `a`, `b`).
#[must_use]
pub fn relative(a: f64, b: f64) -> f64 {
    let m = a.abs().max(b.abs());
    if m == 0.0 { 0.0 } else { (a - b).abs() / m }
}

/// The histogram buckets' labels: 0, 1, 2, 3-4, 5-8, ..., 2^19+1-2^20, > 2^20.
pub const BUCKETS: usize = 23;

/// The bucket of a ULP distance (see [`bucket_label`]).
#[must_use]
pub fn bucket(ulp: u128) -> usize {
    match ulp {
        0 => 0,
        1 => 1,
        2 => 2,
        u if u > 1 << 20 => BUCKETS - 1,
        // 2^(k-1) + 1 ..= 2^k for k = 2 ..= 20 is bucket k + 1.
        u => {
            let k = 128 - (u - 1).leading_zeros() as usize;
            k + 1
        }
    }
}

/// The label of bucket `i`: "0", "1", "2", "3-4", "5-8", ..., "> 2^20".
#[must_use]
pub fn bucket_label(i: usize) -> String {
    match i {
        0..=2 => i.to_string(),
        i if i == BUCKETS - 1 => "> 2^20".to_string(),
        i => {
            let k = i - 1;
            format!("{}-{}", (1u64 << (k - 1)) + 1, 1u64 << k)
        }
    }
}

/// The statistics of one output over the compared rows.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Rows compared.
    pub rows: usize,
    /// ULP distances of the rows with one (sorted by [`Stats::finish`]).
    pub ulps: Vec<u128>,
    /// Relative differences of the rows with a ULP distance where both values are finite
    /// (sorted by [`Stats::finish`]).
    pub rels: Vec<f64>,
    /// Rows where exactly one value is NaN.
    pub nan_mismatches: usize,
    /// Rows where an infinity meets a finite value or the opposite infinity.
    pub inf_mismatches: usize,
    /// Rows per histogram bucket.
    pub histogram: [usize; BUCKETS],
}

impl Stats {
    /// Adds one row's comparison of the crate's value `a` and the shader's `b`.
    pub fn add(&mut self, a: f64, b: f64, ty: Float) -> Compare {
        self.rows += 1;
        let c = compare(a, b, ty);
        match c {
            Compare::Ulp(u) => {
                self.ulps.push(u);
                self.histogram[bucket(u)] += 1;
                if a.is_finite() && b.is_finite() {
                    self.rels.push(relative(a, b));
                }
            }
            Compare::NanMismatch => self.nan_mismatches += 1,
            Compare::InfMismatch => self.inf_mismatches += 1,
        }
        c
    }

    /// Sorts the distances so [`Stats::max_ulp`] and the medians can be read.
    pub fn finish(&mut self) {
        self.ulps.sort_unstable();
        self.rels.sort_by(f64::total_cmp);
    }

    /// The largest ULP distance (0 without rows).
    #[must_use]
    pub fn max_ulp(&self) -> u128 {
        self.ulps.last().copied().unwrap_or(0)
    }

    /// The median ULP distance (the lower middle for an even count; 0 without rows).
    #[must_use]
    pub fn median_ulp(&self) -> u128 {
        median(&self.ulps).unwrap_or(0)
    }

    /// The largest relative difference.
    #[must_use]
    pub fn max_rel(&self) -> f64 {
        self.rels.last().copied().unwrap_or(0.0)
    }

    /// The median relative difference.
    #[must_use]
    pub fn median_rel(&self) -> f64 {
        median(&self.rels).unwrap_or(0.0)
    }
}

fn median<T: Copy>(sorted: &[T]) -> Option<T> {
    if sorted.is_empty() {
        None
    } else {
        Some(sorted[(sorted.len() - 1) / 2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adjacent_floats_are_one_ulp_apart_across_zero() {
        let ty = Float::F32;
        let next = f64::from(f32::from_bits(1));
        assert_eq!(compare(0.0, next, ty), Compare::Ulp(1));
        assert_eq!(compare(-next, next, ty), Compare::Ulp(2));
        assert_eq!(compare(0.0, -0.0, ty), Compare::Ulp(0));
        assert_eq!(
            compare(1.0, f64::from(1.0f32 + f32::EPSILON), ty),
            Compare::Ulp(1)
        );
        assert_eq!(
            compare(1.0, 1.0 + f64::EPSILON, Float::F64),
            Compare::Ulp(1)
        );
        assert_eq!(compare(f64::NAN, f64::NAN, ty), Compare::Ulp(0));
        assert_eq!(compare(f64::NAN, 1.0, ty), Compare::NanMismatch);
        assert_eq!(compare(f64::INFINITY, 1.0, ty), Compare::InfMismatch);
        assert_eq!(compare(f64::INFINITY, f64::INFINITY, ty), Compare::Ulp(0));
    }

    #[test]
    fn buckets_cover_powers_of_two() {
        assert_eq!(bucket_label(bucket(3)), "3-4");
        assert_eq!(bucket_label(bucket(4)), "3-4");
        assert_eq!(bucket_label(bucket(5)), "5-8");
        assert_eq!(bucket_label(bucket(1 << 20)), "524289-1048576");
        assert_eq!(bucket_label(bucket((1 << 20) + 1)), "> 2^20");
        assert_eq!(bucket(u128::MAX), BUCKETS - 1);
    }
}
