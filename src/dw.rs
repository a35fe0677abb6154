//! Error-free transformations and double-word arithmetic, shared by every module that needs
//! a result rounded once at the end of a chain instead of at every step: the exact Fresnel
//! forms, the GGX and Beckmann D and Smith terms, Burley's and Oren-Nayar's diffuse, the
//! Phong normalizations.
//!
//! Two representations of a number to about twice the working precision:
//! - [`Dw`]: the unevaluated sum hi + lo, |lo| at most about half an ULP of hi (Dekker 1971,
//!   "A floating-point technique for extending the available precision"; the operations are
//!   the "sloppy" double-word sum and product analysed by Joldes, Muller and Popescu 2017,
//!   "Tight and rigorous error bounds for basic building blocks of double-word arithmetic").
//! - [`Rel`]: a positive value carried as hi (1 + rel), its relative correction, for the
//!   microfacet terms where a rounding is squared or multiplied by a large exponent and what
//!   matters is the relative error.
//!
//! Every operation is built from plain `+`, `-`, `*` and `/`, except the error of a product
//! ([`two_prod`], [`two_sq`]), which targets with FMA form with one fused multiply-add
//! (Ogita, Rump and Oishi 2005, Algorithm 3.5) instead of Dekker's 17 operations: both are
//! exact on the domain each function states, where they give the same bits, so results agree
//! between targets and lane types there (outside it, at products below 2^-102 in f32, the
//! two lose different low bits of an error term far below the result's last place). The
//! transformations are exact (error-free) while nothing overflows and no partial product
//! underflows; each function states its range.

use crate::real::Real;

/// True for a 24-bit significand (f32 and its lanes), false for 53 bits (f64 and its lanes).
#[inline]
pub(crate) fn single<T: Real>() -> bool {
    let eps: f64 = T::EPSILON.lane(0).into();
    eps > 1e-10
}

/// Veltkamp's split of `a` into `(hi, lo)`, a = hi + lo exactly, hi holding the upper half
/// of the significand (12 bits of f32's 24, 26 of f64's 53) and lo the rest (11 resp. 26
/// bits plus a sign), so that products of the halves are exact (Dekker 1971, section 5;
/// Knuth, TAOCP vol. 2, 4.2.2). The factor is 2^ceil(p / 2) + 1 for the p-bit significand:
/// 2^12 + 1 (f32), 2^27 + 1 (f64).
///
/// Domain: |a| below (2 - 2^-12) 2^127 (f32) or (2 - 2^-27) 2^1023 (f64), that is every
/// finite value but the top 2^11 resp. 2^26 significands, where hi itself rounds up to
/// 2^128 resp. 2^1024 and overflows. factor * a would overflow long before that, so above
/// 2^100 (f32) or about 2^960 (f64) `a` is split scaled by 2^-32 and both parts are scaled
/// back (both scalings exact). NaN gives NaN parts; an infinite `a` gives NaN.
#[inline]
#[must_use]
pub(crate) fn split<T: Real>(a: T) -> (T, T) {
    let (factor, large) = if single::<T>() {
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

/// TwoProduct: `(p, e)` with p = fl(a b) and a b = p + e exactly, from Veltkamp's splits
/// without FMA (Dekker 1971, "mul12"; Ogita, Rump and Oishi 2005, "Accurate sum and dot
/// product", Algorithm 3.3).
///
/// Exact when a b does not overflow and e is not below the subnormal range: |a b| at least
/// 2^-102 (f32) or 2^-969 (f64) suffices; below it e loses bits, still with
/// |p + e - a b| far below one ULP of the result's scale in every caller. The partial products
/// ah bh stay finite for |a b| below the largest finite value divided by 2 (the splits add at
/// most one bit).
#[inline]
#[must_use]
pub(crate) fn two_prod<T: Real>(a: T, b: T) -> (T, T) {
    let p = a * b;
    if FUSED {
        // e = a b - p rounded once: exact, since a b - p is representable.
        return (p, a.mul_add(b, -p));
    }
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, al * bl - (((p - ah * bh) - al * bh) - ah * bl))
}

/// c - a b rounded once, for a product a b close enough to c that c - fl(a b) is exact
/// (fl(a b) within [c / 2, 2 c], Sterbenz's lemma, or c = 0): the residual of a division
/// (c - q d for q = fl(c / d)) or of a range reduction (n - x for n = round(x)). One fused
/// multiply-add where the target has them; otherwise c - fl(a b) minus the product's exact
/// error from [`two_prod`] (same domain). Both round the same exact value once when it is
/// representable.
#[inline]
#[must_use]
pub(crate) fn sub_prod<T: Real>(c: T, a: T, b: T) -> T {
    if FUSED {
        return (-a).mul_add(b, c);
    }
    let (p, e) = two_prod(a, b);
    (c - p) - e
}

/// a^2 - k rounded once, for k a power of two with |a^2 - k| exact after the subtraction of
/// fl(a^2) (a^2 below 2^24 k in f32, 2^53 k in f64): one fused multiply-add where the target
/// has them, otherwise (fl(a^2) - k) + the square's exact error ([`two_sq`]), which rounds the
/// same exact value once.
#[inline]
#[must_use]
pub(crate) fn sq_minus<T: Real>(a: T, k: T) -> T {
    if FUSED {
        return a.mul_add(a, -k);
    }
    let (p, e) = two_sq(a);
    (p - k) + e
}

/// Whether `Real::mul_add` is fused on this target (x86 with FMA, aarch64 with NEON): then
/// the error of a product takes one instruction.
const FUSED: bool = cfg!(any(
    target_feature = "fma",
    all(target_arch = "aarch64", target_feature = "neon")
));

/// TwoProduct of `a` with itself, `(p, e)` with a^2 = p + e exactly: [`two_prod`] with one
/// split instead of two (Dekker 1971, "mul12" for equal factors). Same domain as
/// [`two_prod`].
#[inline]
#[must_use]
pub(crate) fn two_sq<T: Real>(a: T) -> (T, T) {
    let p = a * a;
    if FUSED {
        return (p, a.mul_add(a, -p));
    }
    let (ah, al) = split(a);
    (p, al * al - ((p - ah * ah) - T::TWO * ah * al))
}

/// TwoSum: `(s, e)` with s = fl(a + b) and a + b = s + e exactly, for operands in any order
/// (Knuth, TAOCP vol. 2, 4.2.2, Theorem B; Ogita, Rump and Oishi 2005, Algorithm 3.1). Six
/// operations. Exact for every pair of finite operands whose sum does not overflow.
#[inline]
#[must_use]
pub(crate) fn two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Fast2Sum: `(s, e)` with s = fl(a + b) and a + b = s + e exactly, in three operations,
/// provided a = 0 or the exponent of a is at least that of b (|a| >= |b| suffices; Dekker
/// 1971, "add12"; Knuth, TAOCP vol. 2, 4.2.2, Theorem C). This is the renormalization of a
/// double word whose high part dominates; for operands in unknown order use [`two_sum`].
#[inline]
#[must_use]
pub(crate) fn fast_two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    (s, b - (s - a))
}

/// The power of two nearest `a` (ties to even significand, so 1.5 gives 2), with `a`'s sign:
/// a Veltkamp split keeping one significant bit (factor 2^(p - 1) + 1). Domain |a| below the
/// largest finite value divided by 2^24 (f32) or 2^53 (f64); 0 gives 0.
#[inline]
#[must_use]
pub(crate) fn pow2_nearest<T: Real>(a: T) -> T {
    let factor = if single::<T>() {
        8_388_609.0
    } else {
        4_503_599_627_370_497.0
    };
    let t = T::splat(factor) * a;
    t - (t - a)
}

/// A double word: the unevaluated sum hi + lo with |lo| at most about half an ULP of hi,
/// about twice the working precision (48 bits for f32, 106 for f64).
///
/// The sum and product are the sloppy double-word operations (the low parts' own product is
/// dropped; relative error a few u^2, u the unit roundoff), each renormalized once with
/// [`fast_two_sum`]. Exponents stay far from the overflow and underflow thresholds in every
/// caller, or the caller scales first (see [`Dw::scale`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Dw<T> {
    /// The leading part: the value rounded to the working precision.
    pub(crate) hi: T,
    /// The rest, value - hi.
    pub(crate) lo: T,
}

impl<T: Real> Dw<T> {
    /// A working-precision number, carried with no error.
    #[inline]
    #[must_use]
    pub(crate) fn exact(x: T) -> Self {
        Self { hi: x, lo: T::ZERO }
    }

    /// hi + lo renormalized by [`fast_two_sum`] (|hi| >= |lo|, or hi = 0, is the caller's
    /// promise).
    #[inline]
    #[must_use]
    pub(crate) fn norm(hi: T, lo: T) -> Self {
        let (hi, lo) = fast_two_sum(hi, lo);
        Self { hi, lo }
    }

    /// a b, exactly ([`two_prod`]).
    #[inline]
    #[must_use]
    pub(crate) fn product(a: T, b: T) -> Self {
        let (hi, lo) = two_prod(a, b);
        Self { hi, lo }
    }

    /// a^2, exactly ([`two_sq`]).
    #[inline]
    #[must_use]
    pub(crate) fn square(a: T) -> Self {
        let (hi, lo) = two_sq(a);
        Self { hi, lo }
    }

    /// a + b, exactly ([`two_sum`], any order).
    #[inline]
    #[must_use]
    pub(crate) fn sum(a: T, b: T) -> Self {
        let (hi, lo) = two_sum(a, b);
        Self { hi, lo }
    }

    /// A constant known to more than twice the lane type's precision, given as its nearest
    /// f64 `hi` plus the f64 `tail` (the rest, x - hi): rounded to the lane type, hi and the
    /// remainder of hi + tail.
    #[inline]
    #[must_use]
    pub(crate) fn constant(hi: f64, tail: f64) -> Self {
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
    #[must_use]
    pub(crate) fn frac_1_pi() -> Self {
        Self::constant(core::f64::consts::FRAC_1_PI, -1.967_867_667_518_248_6e-17)
    }

    /// `a` where `m` is set, else `b`, lane by lane.
    #[inline]
    #[must_use]
    pub(crate) fn select(m: T::Mask, a: Self, b: Self) -> Self {
        Self {
            hi: T::select(m, a.hi, b.hi),
            lo: T::select(m, a.lo, b.lo),
        }
    }

    /// -self, exactly.
    #[inline]
    #[must_use]
    pub(crate) fn neg(self) -> Self {
        Self {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// self f for a power of two f: exact unless a part leaves the normal range.
    #[inline]
    #[must_use]
    pub(crate) fn scale(self, f: T) -> Self {
        Self {
            hi: self.hi * f,
            lo: self.lo * f,
        }
    }

    /// 2 self, exactly (below the overflow threshold).
    #[inline]
    #[must_use]
    pub(crate) fn scale2(self) -> Self {
        Self {
            hi: T::TWO * self.hi,
            lo: T::TWO * self.lo,
        }
    }

    /// The sum, rounded once to double-word precision.
    #[inline]
    #[must_use]
    #[allow(clippy::should_implement_trait)]
    pub(crate) fn add(self, o: Self) -> Self {
        let (s, e) = two_sum(self.hi, o.hi);
        Self::norm(s, e + (self.lo + o.lo))
    }

    /// The sum with a working-precision number, rounded once to double-word precision.
    #[inline]
    #[must_use]
    pub(crate) fn add_t(self, o: T) -> Self {
        let (s, e) = two_sum(self.hi, o);
        Self::norm(s, e + self.lo)
    }

    /// The product, rounded once to double-word precision (lo lo is below its last place).
    #[inline]
    #[must_use]
    #[allow(clippy::should_implement_trait)]
    pub(crate) fn mul(self, o: Self) -> Self {
        let (p, e) = two_prod(self.hi, o.hi);
        Self::norm(p, e + (self.hi * o.lo + self.lo * o.hi))
    }

    /// self^2 (as [`Dw::mul`], with one split).
    #[inline]
    #[must_use]
    pub(crate) fn sq(self) -> Self {
        let (p, e) = two_sq(self.hi);
        Self::norm(p, e + T::TWO * self.hi * self.lo)
    }

    /// The quotient, rounded once to double-word precision: the first quotient's remainder
    /// self - q o is formed in double words and divided again.
    #[inline]
    #[must_use]
    #[allow(clippy::should_implement_trait)]
    pub(crate) fn div(self, o: Self) -> Self {
        let q1 = self.hi / o.hi;
        let r = self.add(o.mul(Self::exact(-q1)));
        Self::norm(q1, r.hi / o.hi)
    }

    /// The square root (0 for a non-positive hi), one Newton correction from sqrt(hi) on the
    /// exact residual hi - r^2.
    #[inline]
    #[must_use]
    pub(crate) fn sqrt(self) -> Self {
        let r = self.hi.sqrt_nonneg();
        let pos = r.simd_gt(T::ZERO);
        let (p, e) = two_prod(r, r);
        let safe = T::select(pos, r, T::ONE);
        let corr = (((self.hi - p) - e) + self.lo) / (T::TWO * safe);
        Self::norm(r, T::select(pos, corr, T::ZERO))
    }

    /// self / d rounded once to the working precision (with the first-order terms of both low
    /// parts); 0 where d is 0.
    #[inline]
    #[must_use]
    pub(crate) fn ratio(self, d: Self) -> T {
        let ok = !d.hi.simd_eq(T::ZERO);
        let dh = T::select(ok, d.hi, T::ONE);
        let q = self.hi / dh;
        T::select(ok, q + (self.lo - q * d.lo) / dh, T::ZERO)
    }

    /// re^2 + im^2 for double words re and im, one renormalization. The cross terms use
    /// `Real::mul_add` (fused on FMA targets: the last bit of this term, far below the
    /// result's last place, may differ between targets).
    #[inline]
    #[must_use]
    pub(crate) fn abs2(re: Self, im: Self) -> Self {
        let (a, ea) = two_sq(re.hi);
        let (b, eb) = two_sq(im.hi);
        let (s, e) = two_sum(a, b);
        let cross = T::TWO * re.hi.mul_add(re.lo, im.hi * im.lo);
        Self::norm(s, e + ((ea + eb) + cross))
    }

    /// The value rounded to the working precision.
    #[inline]
    #[must_use]
    pub(crate) fn value(self) -> T {
        self.hi + self.lo
    }
}

/// A positive value carried as hi (1 + rel): `rel` is the relative correction that the
/// error-free transformations recover from each rounding (|rel| stays near one ULP, so its
/// own products are second order). Used where a rounding would otherwise be amplified:
/// squared (the GGX D denominator) or multiplied by a large exponent (Beckmann's exp(-E)).
/// Unlike [`Dw`] the correction keeps its meaning when hi is later raised to a power or
/// exponentiated, and a value near the overflow or underflow threshold needs no low part.
#[derive(Clone, Copy)]
pub(crate) struct Rel<T> {
    /// The value rounded to the working precision.
    pub(crate) hi: T,
    /// (value - hi) / hi.
    pub(crate) rel: T,
}

/// `e / p`, 0 where `p` is 0 (an exact zero has no relative error).
#[inline]
fn ratio<T: Real>(e: T, p: T) -> T {
    T::select(p.simd_eq(T::ZERO), T::ZERO, e / p)
}

impl<T: Real> Rel<T> {
    /// A value with no rounding error.
    #[inline]
    #[must_use]
    pub(crate) fn exact(x: T) -> Self {
        Self {
            hi: x,
            rel: T::ZERO,
        }
    }

    /// pi = `T::PI` (1 + rel).
    #[inline]
    #[must_use]
    pub(crate) fn pi() -> Self {
        let pi_t: f64 = T::PI.lane(0).into();
        // pi - fl64(pi) = 1.2246e-16.
        let rel = ((core::f64::consts::PI - pi_t) + 1.224_646_799_147_353_2e-16) / pi_t;
        Self {
            hi: T::PI,
            rel: T::splat(rel),
        }
    }

    /// The product, its rounding recovered by [`two_prod`].
    #[inline]
    #[must_use]
    #[allow(clippy::should_implement_trait)]
    pub(crate) fn mul(self, o: Self) -> Self {
        let (p, e) = two_prod(self.hi, o.hi);
        Self {
            hi: p,
            rel: self.rel + o.rel + ratio(e, p),
        }
    }

    /// The quotient, its rounding recovered from the exact remainder hi - q o.hi.
    #[inline]
    #[must_use]
    #[allow(clippy::should_implement_trait)]
    pub(crate) fn div(self, o: Self) -> Self {
        let q = self.hi / o.hi;
        let (t, u) = two_prod(q, o.hi);
        let r = (self.hi - t) - u;
        Self {
            hi: q,
            rel: self.rel - o.rel + ratio(r, self.hi),
        }
    }

    /// Sum of two non-negative values.
    #[inline]
    #[must_use]
    #[allow(clippy::should_implement_trait)]
    pub(crate) fn add(self, o: Self) -> Self {
        let (s, e) = two_sum(self.hi, o.hi);
        Self {
            hi: s,
            rel: ratio(e + self.hi * self.rel + o.hi * o.rel, s),
        }
    }

    /// The absolute low part hi rel, 0 where it is not finite (hi = 0 or inf at a pole,
    /// where the value is exact anyway).
    #[inline]
    #[must_use]
    pub(crate) fn lo(self) -> T {
        let lo = self.hi * self.rel;
        T::select(lo.is_finite(), lo, T::ZERO)
    }

    /// The square root, the rounding of sqrt(hi) recovered from the exact residual
    /// hi - s^2: sqrt(hi (1 + rel)) = s (1 + (hi - s^2) / (2 s^2) + rel / 2) to first order.
    /// Where hi is below the smallest normal (its rel made by inexact two-products) or 0, the
    /// correction is dropped.
    #[inline]
    #[must_use]
    pub(crate) fn sqrt(self) -> Self {
        let s = self.hi.sqrt();
        let (t, u) = two_prod(s, s);
        let rel = ((self.hi - t) - u) / (T::TWO * self.hi) + self.rel * T::HALF;
        let usable = rel.is_finite() & self.hi.simd_ge(T::MIN_POSITIVE);
        Self {
            hi: s,
            rel: T::select(usable, rel, T::ZERO),
        }
    }

    /// hi (1 + rel) rounded once: the value to return. The product adds at most one rounding
    /// of the result's size to the correction, so this is within 0.5 ULP plus the
    /// second-order terms.
    #[inline]
    #[must_use]
    pub(crate) fn value(self) -> T {
        self.hi + self.lo()
    }

    /// sin^2 = 1 - c^2 = (1 - c)(1 + c) for c in [0, 1], carried to twice the working
    /// precision (both factors exact by [`two_sum`], their product by [`two_prod`]). Near
    /// c = 1 a plain 1 - fl(c^2) keeps the rounding of c^2, which is relatively huge against
    /// the small sin^2; the factored form has none.
    #[inline]
    #[must_use]
    pub(crate) fn one_minus_sq(c: T) -> Self {
        let (d, dl) = two_sum(T::ONE, -c);
        let (p, pl) = two_sum(T::ONE, c);
        let (h, e) = two_prod(d, p);
        let lo = e + (d * pl + dl * p);
        let s = h + lo;
        Self {
            hi: s,
            rel: ratio((h - s) + lo, s),
        }
    }
}

#[cfg(test)]
mod tests {
    //! Exactness of the error-free transformations, checked without wider floats: f32
    //! results against f64 arithmetic (exact for these operand sizes), f64 results against
    //! integer arithmetic on the significands (i128).
    use super::*;
    use crate::wide::{f32x8, f64x4};

    /// xorshift64*: deterministic operands spread over many binades.
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
        }
        /// Random sign and significand, exponent in [lo, hi).
        fn f64_in(&mut self, lo: i32, hi: i32) -> f64 {
            let r = self.next();
            let m = 1.0 + (r >> 11) as f64 / (1u64 << 53) as f64;
            let span = (hi - lo) as u64;
            let e = lo + ((r & 0x3ff) % span) as i32;
            let x = m * 2f64.powi(e);
            if r & 0x400 == 0 { x } else { -x }
        }
        fn f32_in(&mut self, lo: i32, hi: i32) -> f32 {
            self.f64_in(lo, hi) as f32
        }
    }

    /// x = m 2^e with m an integer (x finite, nonzero or zero).
    fn parts(x: f64) -> (i128, i32) {
        let b = x.to_bits();
        let exp = ((b >> 52) & 0x7ff) as i32;
        let frac = (b & ((1 << 52) - 1)) as i128;
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1 << 52), exp - 1075)
        };
        (if x < 0.0 { -m } else { m }, e)
    }

    /// x / 2^e as an integer; panics unless exact.
    fn at_scale(x: f64, e: i32) -> i128 {
        if x == 0.0 {
            return 0;
        }
        let (m, ex) = parts(x);
        let tz = m.trailing_zeros() as i32;
        let (m, ex) = (m >> tz, ex + tz);
        assert!(ex >= e, "{x:e} is not a multiple of 2^{e}");
        m << (ex - e)
    }

    #[test]
    fn f32_two_prod_and_two_sq_are_exact() {
        let mut rng = Rng(0x1234_5678_9abc_def1);
        for _ in 0..100_000 {
            let a = rng.f32_in(-40, 40);
            let b = rng.f32_in(-40, 40);
            let exact = f64::from(a) * f64::from(b);
            let (p, e) = two_prod(a, b);
            assert_eq!(p, a * b);
            assert_eq!(f64::from(p) + f64::from(e), exact, "{a:e} * {b:e}");
            let (p, e) = two_sq(a);
            assert_eq!(f64::from(p) + f64::from(e), f64::from(a) * f64::from(a));
        }
    }

    #[test]
    fn f32_split_is_exact_with_half_width_parts_up_to_max() {
        let mut rng = Rng(0x0fed_cba9_8765_4321);
        // The largest value whose 12-bit high part does not round up to 2^128.
        let top = f32::from_bits(f32::MAX.to_bits() - (1 << 11));
        let edges = [top, -top, f32::MIN_POSITIVE, 1.0];
        for i in 0..200_000 {
            let a = if i < edges.len() {
                edges[i]
            } else {
                rng.f32_in(-126, 127).clamp(-top, top)
            };
            let (h, l) = split(a);
            assert_eq!(f64::from(h) + f64::from(l), f64::from(a), "{a:e}");
            // hi has at most 12 significant bits, lo at most 12: their products are exact.
            for part in [h, l] {
                let m = parts(f64::from(part)).0.unsigned_abs();
                if m != 0 {
                    let bits = 128 - m.leading_zeros() - m.trailing_zeros();
                    assert!(bits <= 12, "{a:e}: part {part:e} has {bits} bits");
                }
            }
        }
    }

    #[test]
    fn f32_two_sum_and_fast_two_sum_are_exact() {
        let mut rng = Rng(0xdead_beef_cafe_f00d);
        for _ in 0..100_000 {
            // Exponents within 28 of each other: the f64 sum of two such f32 is exact.
            let a = rng.f32_in(-14, 14);
            let b = rng.f32_in(-14, 14);
            let exact = f64::from(a) + f64::from(b);
            let (s, e) = two_sum(a, b);
            assert_eq!(s, a + b);
            assert_eq!(f64::from(s) + f64::from(e), exact);
            let (big, small) = if a.abs() >= b.abs() { (a, b) } else { (b, a) };
            assert_eq!(fast_two_sum(big, small), (s, e));
        }
    }

    #[test]
    fn f64_two_prod_and_two_sum_are_exact_in_integers() {
        let mut rng = Rng(0x5555_aaaa_1234_4321);
        for _ in 0..100_000 {
            // |a b| above 2^-969: the error term is a normal number.
            let a = rng.f64_in(-400, 400);
            let b = rng.f64_in(-400, 400);
            let (ma, ea) = parts(a);
            let (mb, eb) = parts(b);
            let (p, e) = two_prod(a, b);
            let scale = ea + eb;
            assert_eq!(
                at_scale(p, scale) + at_scale(e, scale),
                ma * mb,
                "{a:e} * {b:e}"
            );
            let (p2, e2) = two_sq(a);
            assert_eq!(at_scale(p2, 2 * ea) + at_scale(e2, 2 * ea), ma * ma);
            // Sums: operands within 60 binades so the integer sum fits i128.
            let c = rng.f64_in(-30, 30);
            let d = rng.f64_in(-30, 30);
            let (mc, ec) = parts(c);
            let (md, ed) = parts(d);
            let lo = ec.min(ed);
            let (s, t) = two_sum(c, d);
            assert_eq!(
                at_scale(s, lo) + at_scale(t, lo),
                (mc << (ec - lo)) + (md << (ed - lo))
            );
        }
    }

    #[test]
    fn dw_operations_carry_twice_the_precision() {
        // Dw<f32> ops against f64: relative error below 2^-44 (a few u^2 with u = 2^-24).
        let mut rng = Rng(0x7777_1111_2222_3333);
        for _ in 0..50_000 {
            let (a, b, c) = (rng.f32_in(-8, 8), rng.f32_in(-8, 8), rng.f32_in(-8, 8));
            let x = Dw::product(a, b);
            let y = Dw::exact(c);
            let xf = f64::from(a) * f64::from(b);
            let cf = f64::from(c);
            let dwf = |d: Dw<f32>| f64::from(d.hi) + f64::from(d.lo);
            let rel = |got: f64, want: f64| ((got - want) / want).abs();
            assert!(rel(dwf(x.mul(y)), xf * cf) < 2f64.powi(-44));
            assert!(rel(dwf(x.div(y)), xf / cf) < 2f64.powi(-44));
            assert!(rel(dwf(x.sq()), xf * xf) < 2f64.powi(-44));
            if xf * cf > 0.0 {
                assert!(rel(dwf(x.add(y)), xf + cf) < 2f64.powi(-44));
            }
            if xf > 0.0 {
                assert!(rel(dwf(x.sqrt()), xf.sqrt()) < 2f64.powi(-44));
            }
        }
    }

    #[test]
    fn lanes_equal_scalars() {
        let mut rng = Rng(0x9999_8888_7777_6666);
        for _ in 0..10_000 {
            let a: [f32; 8] = core::array::from_fn(|_| rng.f32_in(-126, 127));
            let b: [f32; 8] = core::array::from_fn(|_| rng.f32_in(-20, 20));
            let (p, e) = two_prod(f32x8::from(a), f32x8::from(b));
            let (h, l) = split(f32x8::from(a));
            for i in 0..8 {
                let (ps, es) = two_prod(a[i], b[i]);
                assert_eq!(
                    (p.lane(i).to_bits(), e.lane(i).to_bits()),
                    (ps.to_bits(), es.to_bits())
                );
                let (hs, ls) = split(a[i]);
                assert_eq!(
                    (h.lane(i).to_bits(), l.lane(i).to_bits()),
                    (hs.to_bits(), ls.to_bits())
                );
            }
            let c: [f64; 4] = core::array::from_fn(|_| rng.f64_in(-1000, 1000));
            let d: [f64; 4] = core::array::from_fn(|_| rng.f64_in(-20, 20));
            let (p, e) = two_prod(f64x4::from(c), f64x4::from(d));
            for i in 0..4 {
                let (ps, es) = two_prod(c[i], d[i]);
                assert_eq!(
                    (p.lane(i).to_bits(), e.lane(i).to_bits()),
                    (ps.to_bits(), es.to_bits())
                );
            }
        }
    }

    #[test]
    fn pow2_nearest_rounds_to_a_power_of_two() {
        for (x, want) in [
            (1.4_f64, 1.0),
            (1.6, 2.0),
            (-3.0, -4.0),
            (0.7, 0.5),
            (0.0, 0.0),
        ] {
            assert_eq!(pow2_nearest(x), want);
            assert_eq!(pow2_nearest(x as f32), want as f32);
        }
    }
}
