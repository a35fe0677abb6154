//! Double-word arithmetic: a value carried as an unevaluated sum hi + lo of two floats of the
//! lane type, so a chain of products and sums rounds once, at the end, instead of at every
//! step (Dekker 1971, "A floating-point technique for extending the available precision";
//! Knuth's two-sum). Burley's diffuse uses it for its two (1 - cos)^5 factors, whose
//! roundings would otherwise add up to about 4 ULP.
//!
//! Shared by `diffuse` and `phong` (each includes this file as its own private module and uses
//! a subset of it, hence the `dead_code` allowance).
//!
//! Every operation is built from plain `+`, `-` and `*` (no fused multiply-add), so it gives
//! the same bits on every target and on every lane type. The transformations are exact while
//! nothing overflows or underflows; the callers keep every operand below 4 in magnitude, where
//! an underflowing low part only loses digits far below the result's last place.

#![allow(dead_code)]

use crate::real::Real;

/// hi + lo with |lo| at most half an ULP of hi.
#[derive(Clone, Copy, Debug)]
pub(super) struct Dw<T> {
    pub(super) hi: T,
    pub(super) lo: T,
}

/// Veltkamp's split of `a` into a high part with half the significand bits and the exact
/// rest: the factor is 2^ceil(p / 2) + 1 for the p-bit significand (2^12 + 1 for f32,
/// 2^27 + 1 for f64). Above 2^100 (f32) or 2^960 (f64) `a` is split scaled by 2^-32, and the
/// parts scaled back (exactly): factor * a would overflow near the largest finite value.
#[inline]
fn split<T: Real>(a: T) -> (T, T) {
    let eps: f64 = T::EPSILON.lane(0).into();
    let (factor, large) = if eps > 1e-10 {
        (4097.0, 1.267_650_600_228_229_4e30)
    } else {
        (134_217_729.0, 9.745_314_011_4e288)
    };
    let big = a.abs().simd_gt(T::splat(large));
    let a_s = a * T::select(big, T::splat(2.328_306_436_538_696_3e-10), T::ONE);
    let t = T::splat(factor) * a_s;
    let hi = t - (t - a_s);
    let up = T::select(big, T::splat(4_294_967_296.0), T::ONE);
    (hi * up, (a_s - hi) * up)
}

/// The exact product a b = p + e (Dekker's two-product).
#[inline]
fn two_prod<T: Real>(a: T, b: T) -> Dw<T> {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = al * bl - (((p - ah * bh) - al * bh) - ah * bl);
    Dw { hi: p, lo: e }
}

/// The exact sum a + b = s + e (Knuth's two-sum, for operands of any order).
#[inline]
fn two_sum<T: Real>(a: T, b: T) -> Dw<T> {
    let s = a + b;
    let bb = s - a;
    Dw {
        hi: s,
        lo: (a - (s - bb)) + (b - bb),
    }
}

impl<T: Real> Dw<T> {
    /// A float with no error.
    #[inline]
    pub(super) fn exact(x: T) -> Self {
        Self { hi: x, lo: T::ZERO }
    }

    /// a * b, exactly.
    #[inline]
    pub(super) fn product(a: T, b: T) -> Self {
        two_prod(a, b)
    }

    /// a + b, exactly.
    #[inline]
    pub(super) fn sum(a: T, b: T) -> Self {
        two_sum(a, b)
    }

    /// A constant known to more than twice the lane type's precision, as its nearest f64
    /// `hi` plus the f64 `tail` (the rest, `x - hi`): rounded to the lane type, hi and the
    /// remainder of hi + tail.
    #[inline]
    pub(super) fn constant(hi: f64, tail: f64) -> Self {
        let h = T::splat(hi);
        let hf: f64 = h.lane(0).into();
        // hi - hf is exact in f64 (Sterbenz), and 0 when T is f64.
        Self {
            hi: h,
            lo: T::splat((hi - hf) + tail),
        }
    }

    /// 1/pi = 0.3183098861837907 - 1.9678676675182486e-17 (to 106 bits).
    #[inline]
    pub(super) fn frac_1_pi() -> Self {
        Self::constant(core::f64::consts::FRAC_1_PI, -1.967_867_667_518_248_6e-17)
    }

    /// The sum, rounded once to double-word precision.
    #[inline]
    #[allow(clippy::should_implement_trait)]
    pub(super) fn add(self, o: Self) -> Self {
        let s = two_sum(self.hi, o.hi);
        let lo = s.lo + (self.lo + o.lo);
        two_sum(s.hi, lo)
    }

    /// The product, rounded once to double-word precision (lo * lo is below its last place).
    #[inline]
    #[allow(clippy::should_implement_trait)]
    pub(super) fn mul(self, o: Self) -> Self {
        let p = two_prod(self.hi, o.hi);
        let lo = p.lo + (self.hi * o.lo + self.lo * o.hi);
        two_sum(p.hi, lo)
    }

    /// The quotient, rounded once to double-word precision: the first quotient's remainder
    /// self - q o is formed in double words and divided again.
    #[inline]
    #[allow(clippy::should_implement_trait)]
    pub(super) fn div(self, o: Self) -> Self {
        let q1 = self.hi / o.hi;
        let r = self.add(o.mul(Self::exact(-q1)));
        two_sum(q1, r.hi / o.hi)
    }

    /// `a` where `m` is set, else `b`, lane by lane.
    #[inline]
    pub(super) fn select(m: T::Mask, a: Self, b: Self) -> Self {
        Self {
            hi: T::select(m, a.hi, b.hi),
            lo: T::select(m, a.lo, b.lo),
        }
    }

    /// The value rounded to the lane type.
    #[inline]
    pub(super) fn value(self) -> T {
        self.hi + self.lo
    }
}
