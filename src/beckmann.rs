//! Beckmann: the NDF, its exact Smith Lambda (with erf), Walter et al.'s rational
//! approximation of it, and the Blinn-Phong exponent conversion.
//!
//! Sources: Beckmann and Spizzichino 1963, "The Scattering of Electromagnetic Waves from Rough
//! Surfaces"; Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through
//! Rough Surfaces" (EGSR), eqs. 25-27; Heitz 2014, "Understanding the Masking-Shadowing Function
//! in Microfacet-Based BRDFs" (JCGT 3(2)), eqs. 80-83.
//!
//! Roughness: every `alpha` here is the Beckmann width alpha, the RMS slope of the microsurface
//! (Walter et al. 2007's alpha_b), not the perceptual roughness r of a material slider. For a
//! slider value use alpha = r^2 ([`alpha_from_perceptual`], the same mapping as for GGX), or
//! [`alpha_from_blinn_phong`] for a Blinn-Phong exponent. The
//! [roughness conventions](crate::microfacet#roughness-conventions) tabulate engines' names.
//!
//! Same conventions as the `ggx` module: free functions of dot products with cosines clamped to
//! [0, 1], the [`Beckmann`] type on local-frame vectors, alpha clamped to
//! [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN), [`ALPHA_MAX`](crate::microfacet::ALPHA_MAX)
//! (NaN for alpha < 0, NaN or +inf), NaN in any input gives NaN, poles capped at the largest
//! finite value.
//!
//! Accuracy. D's exponent E = tan^2 / alpha^2 and Lambda's a^2 = 1 / (alpha tan)^2 are carried
//! as a value plus its first-order rounding error (Dekker's exact products, the exact division
//! remainder, sin^2 = (1 - c)(1 + c) from exact factors), so exp does not multiply their
//! rounding by E (up to 700 in f64); D's remaining factors are recovered the same way and
//! rounded once. The isotropic [`d`] on `f32` and `f32x8` is instead evaluated in f64, where
//! the same formula needs no recovered roundings, and rounded to f32 once. Lambda is evaluated in a form without cancellation (see [`lambda`]); where
//! cos^2 is too small for an exact two-product (a below 1e-8), Lambda is taken from
//! 1 / a = alpha sin / cos directly. Error in ULPs of the correctly rounded result,
//! measured by the MPFR oracle (Walter et al. 2007 eq. 25 and Heitz 2014 eqs. 80 and 83 with
//! erfc, at 256+ bits) on its stiff and random points (cosines from 1 down to subnormals,
//! alpha from 1e-4 to 1e4, a from 0.1 to 1e6), wherever the result is >= 1e-30 (f32) /
//! 1e-300 (f64). Each entry is the bound every oracle run holds (`oracle/src/bounds.rs`; the
//! larger of the default and FMA builds) and, in parentheses, the max found by the deep search
//! (`docs/accuracy.md`):
//!
//! | function | f32 | f64 | f32x8 | f64x4 |
//! |---|---|---|---|---|
//! | `d` | 0.7 (0.54) | 1.7 (1.52) | 0.7 (0.54) | 2.2 (1.96) |
//! | `Beckmann::d` | 1.7 (1.45) | 1.8 (1.57) | 1.8 (1.63) | 2.4 (2.18) |
//! | `lambda` | 2.5 (2.27) | 2.0 (1.77) | 2.5 (2.27) | 2.3 (2.11) |
//! | `g1` | 3.3 (3.14) | 2.4 (2.22) | 3.3 (3.14) | 2.4 (2.22) |
//! | `Beckmann::lambda` | 3.3 (3.06) | 1.9 (1.69) | 3.3 (3.06) | 2.2 (2.03) |
//! | `Beckmann::v_correlated` | 1.2 (0.99) | 1.2 (0.99) | 1.2 (0.97) | 1.2 (0.99) |
//!
//! Ordinary run: `cargo test -p brdf-oracle --release -- --nocapture` (fresh points each run,
//! seed printed, plus the committed hardest inputs in `oracle/hardest.txt`); deep search:
//! `BRDF_ORACLE_DEEP=1 BRDF_ORACLE_RECORD=1 cargo test -p brdf-oracle --release --test
//! accuracy_table -- --nocapture` (10^5 fresh points per function and type plus a longer
//! climb).
//!
//! Lambda's factors P = exp(-a^2) K / (2 sqrt(pi)) and Q = a (a + K) are carried with the
//! relative correction of every rounding (K's series to twice the working precision in its
//! last steps, a's own rounding recovered and propagated through K' = 2 (a + K) K - 1), so
//! exp's error and one final rounding remain (the table's maxima come from the deep search's
//! 10^5 fresh points per function and type, cosines down to the smallest subnormal, plus its
//! hill-climb).
//!
//! (The lanes' exp is a polynomial within 1 ULP (f32x8) / 2 ULP (f64x4) of the scalar one;
//! see `crate::real`.)
//!
//! [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual

use crate::domain::nan_where;
use crate::dw::{Dw, Rel, two_prod, two_sum};
use crate::error::ParamError;
use crate::microfacet::{Microfacet, clamp_alpha, validate_alphas};
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

/// 1 / (2 sqrt(pi)).
const FRAC_1_2SQRT_PI: f64 = 0.282_094_791_773_878_14;

/// The exponent E = tan^2(theta) / alpha^2 = (1 - c^2) / (c^2 alpha^2) of the isotropic
/// Beckmann D, with c^2 alpha^2 (the denominator, for D's own c^4 alpha^2 below).
#[inline]
fn exponent_iso<T: Real>(c: T, alpha: T) -> (Rel<T>, Rel<T>) {
    let c2 = Rel::exact(c).mul(Rel::exact(c));
    let c2a2 = c2.mul(Rel::exact(alpha).mul(Rel::exact(alpha)));
    (Rel::one_minus_sq(c).div(c2a2), c2)
}

/// exp(-E) / (pi den) for E and den carried with their corrections: the rounding of E is
/// compensated (exp(-hi) (1 - lo)) and exp's argument is shifted by 64 ln 2 where E > 64, so
/// exp(-E) cannot fall into the subnormal range while D itself is a normal number.
#[inline]
fn exp_neg_over<T: Real>(e: Rel<T>, den: Rel<T>) -> T {
    const SHIFT: f64 = 64.0 * core::f64::consts::LN_2;
    // SHIFT = shift_hi + shift_lo in the lane type.
    let shift_hi_t = T::splat(SHIFT);
    let shift_hi: f64 = shift_hi_t.lane(0).into();
    // 64 (ln 2 - fl64(ln 2)) = 1.4842e-15.
    let shift_lo_t = T::splat((SHIFT - shift_hi) + 1.484_189_960_861_632e-15);
    let big = e.hi.simd_gt(T::splat(64.0));
    let (h, l) = two_sum(e.hi, -T::select(big, shift_hi_t, T::ZERO));
    let lo = e.lo() + l - T::select(big, shift_lo_t, T::ZERO);
    let scale = T::select(big, T::splat(5.421_010_862_427_522e-20), T::ONE);
    // pi den with its rounding recovered; z^4 underflows only where exp(-E) is already 0,
    // and the max keeps scale / den finite there (so 0 x inf cannot occur).
    let pden = den.mul(Rel::pi());
    let pden = Rel {
        hi: pden.hi.max(T::MIN_POSITIVE),
        rel: pden.rel,
    };
    let q = Rel::exact(scale).div(pden);
    // exp(-(h + lo)) = exp(-h) (1 - lo) to first order (|lo| is a few ULP of E).
    let x = Rel {
        hi: (-h).exp(),
        rel: -lo,
    };
    // One rounding of the whole correction: the result is exp's error plus 0.5 ULP.
    x.mul(q).value()
}

/// Chebyshev coefficients of K(a) = 1 / (sqrt(pi) erfcx(a)) - a on [0, 4] in x = (a - 2) / 2
/// (interpolation at 41 Chebyshev nodes in 150-bit arithmetic; the terms beyond the 31st are
/// below 1e-18, 1e-17 of K).
const K_CHEB: [f64; 31] = [
    0.27075399380585063,
    -0.20371486268284028,
    0.06595928796018642,
    -0.018468086265551024,
    0.004390502338309677,
    -0.0008305750526057591,
    9.587835485797977e-05,
    9.295267526118017e-06,
    -9.787406286900458e-06,
    3.5353579265136176e-06,
    -8.642903486443534e-07,
    1.3503729215244626e-07,
    3.728222829750325e-11,
    -9.166773194474246e-09,
    3.959874464341713e-09,
    -1.087014439953078e-09,
    1.9929253545178303e-10,
    -1.1648985427463841e-11,
    -8.684373754075395e-12,
    4.576867189435587e-12,
    -1.388741281461136e-12,
    2.8710114449542646e-13,
    -2.871442696774278e-14,
    -7.392213810049755e-15,
    5.203866957280391e-15,
    -1.7513103849428683e-15,
    4.011929200428336e-16,
    -5.314662206376165e-17,
    -4.688123898625463e-18,
    5.723693998887793e-18,
    -2.1651045181374035e-18,
];

/// K(a) = 1 / (sqrt(pi) erfcx(a)) - a for a >= 0, in (0, 1 / sqrt(pi)]: the tail of the
/// continued fraction sqrt(pi) erfcx(a) = 1 / (a + (1/2) / (a + 1 / (a + (3/2) / (a + ...))))
/// (Abramowitz and Stegun 7.1.14). On [0, 4] a Chebyshev series (31 terms in f64, 15 in f32);
/// above 4 the continued fraction itself, 22 levels in f64 and 8 in f32, started from its
/// fixed point (k / 2) / (a + t) = t. Both are evaluated in every lane (no data-dependent
/// loop), so lanes equal scalars.
///
/// K is returned as a double word: the series' terms from the fourth on (below 0.005) are
/// summed in working precision, the last three Clenshaw steps and the final one (whose b are
/// of K's own size, up to 0.2 against K = 0.12 at a = 4, and whose roundings would each cost
/// about an ULP of K), with x = (a - 2) / 2 and the coefficients exact, in double words; the
/// continued fraction's last level, 1 / 2 / (a + t), is divided with its remainder.
#[inline]
fn k_of_a<T: Real>(a: T) -> Dw<T> {
    let eps: f64 = T::EPSILON.lane(0).into();
    let (terms, levels) = if eps > 1e-10 { (15, 8) } else { (31, 22) };
    // Clenshaw's recurrence on x = (a - 2) / 2 in [-1, 1]; 2x = a - 2 exactly as a double
    // word (a - 2 is inexact below a = 1).
    let (x2, x2_lo) = two_sum(a.min(T::splat(4.0)), -T::TWO);
    let (mut b1, mut b2) = (T::ZERO, T::ZERO);
    for &c in K_CHEB[4..terms].iter().rev() {
        let b0 = x2.mul_add(b1, T::splat(c) - b2);
        b2 = b1;
        b1 = b0;
    }
    let two_x = Dw { hi: x2, lo: x2_lo };
    let (mut d1, mut d2) = (Dw::exact(b1), Dw::exact(b2));
    for &c in K_CHEB[1..4].iter().rev() {
        let d0 = two_x.mul(d1).add(Dw::constant(c, 0.0)).add(d2.neg());
        d2 = d1;
        d1 = d0;
    }
    let fit = two_x
        .mul(d1)
        .scale(T::HALF)
        .add(Dw::constant(K_CHEB[0], 0.0))
        .add(d2.neg());
    let ac = a.max(T::splat(4.0));
    let n1 = T::splat(f64::from(levels + 1));
    let mut t = n1 / (ac + ac.mul_add(ac, T::TWO * n1).sqrt());
    for k in (2..=levels).rev() {
        t = T::splat(f64::from(k) * 0.5) / (ac + t);
    }
    // The last level 0.5 / (a + t), a + t exact as a double word, with the quotient's
    // remainder (1 / (a + t) = 2 q to first order in the correction).
    let (dh, dl) = two_sum(ac, t);
    let q = T::HALF / dh;
    let (p, e) = two_prod(q, dh);
    let cf = Dw::norm(q, (((T::HALF - p) - e) - q * dl) * (T::TWO * q));
    Dw::select(a.simd_lt(T::splat(4.0)), fit, cf)
}

/// P = exp(-a^2) K(a) / (2 sqrt(pi)) and K(a), from a = 1 / (alpha tan(theta)) and a^2
/// carried exactly: Lambda = P / (a (a + K)) and |cos| Lambda = r P / (a + K). P is carried
/// with the relative correction of each rounding (exp's own error aside), so that the
/// caller rounds Lambda once.
///
/// Walter et al.'s Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 is a difference that
/// cancels as a grows; with erfc(a) = exp(-a^2) / (sqrt(pi) (a + K)) it is
/// exp(-a^2) / (2 sqrt(pi)) (1 / a - 1 / (a + K)) = exp(-a^2) K / (2 sqrt(pi) a (a + K)):
/// a product of positive factors, no cancellation anywhere.
#[inline]
fn lambda_parts<T: Real>(a: T, a_rel: T, a2: Rel<T>) -> (Rel<T>, Rel<T>) {
    // Beyond a = 1e4 exp(-a^2) is 0 in every float type; the cap keeps the continued fraction
    // and the split finite (a is +inf at the normal).
    let ac = a.min(T::splat(1e4));
    let kd = k_of_a(ac);
    // K at the exact a = ac (1 + a_rel): K' = 2 (a + K) K - 1 (from erfcx' = 2 a erfcx
    // - 2 / sqrt(pi)), so K gains K' a a_rel; a_rel is 0 where a is capped.
    let a_rel = T::select(a.simd_lt(T::splat(1e4)), a_rel, T::ZERO);
    let slope = (T::TWO * (ac + kd.hi)).mul_add(kd.hi, -T::ONE);
    let k = Rel {
        hi: kd.hi,
        rel: (kd.lo + slope * (ac * a_rel)) / kd.hi,
    };
    // exp(-(hi + lo)) = exp(-hi) (1 - lo) to first order.
    let e = Rel {
        hi: (-a2.hi).exp(),
        rel: -a2.lo(),
    };
    (e.mul(k).mul(frac_1_2sqrt_pi()), k)
}

/// 1 / (2 sqrt(pi)) in the lane type with its relative rounding error
/// (1 / (2 sqrt(pi)) = 0.28209479177387814 + 3.8338649e-18).
#[inline]
fn frac_1_2sqrt_pi<T: Real>() -> Rel<T> {
    let hi_t = T::splat(FRAC_1_2SQRT_PI);
    let hi: f64 = hi_t.lane(0).into();
    Rel {
        hi: hi_t,
        rel: T::splat(((FRAC_1_2SQRT_PI - hi) + 3.833_864_903_291_47e-18) / hi),
    }
}

/// The argument a = 1 / (alpha tan(theta)) of the Smith terms in the forms they need.
#[derive(Clone, Copy)]
struct Arg<T: Real> {
    /// a itself.
    a: T,
    /// The relative rounding error of `a`, (a_exact - a) / a (0 where a is 0 or inf).
    a_rel: T,
    /// a^2, carried exactly (see [`finish_a`]).
    a2: Rel<T>,
    /// r = alpha(phi) sin(theta) and |z| = |cos(theta)|, a = |z| / r (kept apart: 1 / a
    /// overflows f32 at z = 1e-38).
    r: T,
    /// |cos(theta)|.
    z: T,
    /// Where a is below 1e-8 (f32) or 1e-130 (f64) and taken from `inv_a`'s side.
    tiny: T::Mask,
}

/// Lambda = P / Q with Q = a (a + K) = a^2 + a K, from [`lambda_parts`]: (P, Q, K), P and Q
/// carried with their relative corrections.
#[inline]
fn lambda_pq<T: Real>(x: Arg<T>) -> (Rel<T>, Rel<T>, T) {
    let (p, k) = lambda_parts(x.a, x.a_rel, x.a2);
    // a^2 carried exactly: the rounding of a (amplified about threefold through a (a + K))
    // then only enters through a K, itself corrected by a's own rounding error. At
    // a = +inf (the normal) P = 0 and Q = inf.
    let capped = x.a.simd_lt(T::splat(1e4));
    let a = Rel {
        hi: x.a.min(T::splat(1e4)),
        rel: T::select(capped, x.a_rel, T::ZERO),
    };
    (p, x.a2.add(a.mul(k)), k.hi)
}

/// P / Q rounded once, 0 where P is 0 (at the normal, where Q is infinite).
#[inline]
fn ratio_pq<T: Real>(p: Rel<T>, q: Rel<T>) -> T {
    let ok = p.hi.simd_gt(T::ZERO) & q.hi.is_finite();
    T::select(ok, p.div(q).value(), T::ZERO)
}

/// Lambda from [`lambda_pq`], its pole at a = 0 capped at MAX. Where a is tiny (a subnormal
/// in f32 at c = 1e-38, which would lose most of its bits) Lambda = (P / (a + K)) / a is
/// evaluated as ((P / (a + K)) r) / |z|, 1 / a = r / |z| (never formed: it overflows).
#[inline]
fn lambda_from<T: Real>(x: Arg<T>) -> T {
    let (p, q, k) = lambda_pq(x);
    lambda_of_pq(x, p, q, k)
}

/// [`lambda_from`] for P, Q and K already evaluated.
#[inline]
fn lambda_of_pq<T: Real>(x: Arg<T>, p: Rel<T>, q: Rel<T>, k: T) -> T {
    let small = ((p.value() / (x.a + k)) * x.r) / x.z;
    // The selects in `ratio_pq` would turn a NaN a (NaN input, alpha out of domain) into 0.
    nan_where(
        x.a.is_nan(),
        T::select(x.tiny, small, ratio_pq(p, q)).min(T::MAX),
    )
}

/// G1 = 1 / (1 + Lambda) = Q / (Q + P): one rounding fewer than through Lambda, P and Q
/// carried with their corrections. 1 at the normal (P = 0), 0 at the horizon.
#[inline]
fn g1_from<T: Real>(x: Arg<T>) -> T {
    let (p, q, k) = lambda_pq(x);
    let l = lambda_of_pq(x, p, q, k);
    // At the capped pole 1 / (1 + MAX) would be a subnormal, not the limit 0.
    let via_lambda = T::select(l.simd_eq(T::MAX), T::ZERO, (T::ONE + l).recip());
    let direct = T::select(
        p.hi.simd_eq(T::ZERO) | !q.hi.is_finite(),
        T::ONE,
        q.div(q.add(p)).value(),
    );
    nan_where(x.a.is_nan(), T::select(x.tiny, via_lambda, direct))
}

/// The Beckmann distribution with width alpha_x along local x and alpha_y along y (alpha is
/// the RMS slope, not perceptual roughness; see [`alpha_from_perceptual`] and
/// [`alpha_from_blinn_phong`]).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Beckmann<T> {
    alpha_x: T,
    alpha_y: T,
}

impl<T: Real> Beckmann<T> {
    /// An anisotropic Beckmann. Both alphas must be finite and >= 0 in every lane, else
    /// [`ParamError`]. Any such alpha is accepted and stored as given; evaluation clamps it to
    /// [ALPHA_MIN, ALPHA_MAX] (`crate::microfacet`).
    pub fn new(alpha_x: T, alpha_y: T) -> Result<Self, ParamError> {
        validate_alphas(alpha_x, alpha_y)?;
        Ok(Self { alpha_x, alpha_y })
    }

    /// The crate's own constructor for free functions that take alpha unvalidated: evaluation
    /// maps an out-of-domain alpha to NaN, so nothing here can skip the domain rule.
    #[cfg_attr(not(feature = "cook-torrance"), allow(dead_code))]
    #[inline]
    pub(crate) const fn new_unchecked(alpha_x: T, alpha_y: T) -> Self {
        Self { alpha_x, alpha_y }
    }

    /// alpha along the tangent (local x), as given to the constructor.
    #[inline]
    #[must_use]
    pub fn alpha_x(&self) -> T {
        self.alpha_x
    }

    /// alpha along the bitangent (local y), as given to the constructor.
    #[inline]
    #[must_use]
    pub fn alpha_y(&self) -> T {
        self.alpha_y
    }

    /// An isotropic Beckmann, `alpha_x = alpha_y = alpha` (the RMS slope, not perceptual
    /// roughness); same validation as [`Beckmann::new`].
    pub fn isotropic(alpha: T) -> Result<Self, ParamError> {
        Self::new(alpha, alpha)
    }

    /// Both alphas clamped to [ALPHA_MIN, ALPHA_MAX] (NaN where out of domain, which only
    /// the crate's unchecked constructor can store).
    #[inline]
    pub(crate) fn clamped_alphas(&self) -> (T, T) {
        (clamp_alpha(self.alpha_x), clamp_alpha(self.alpha_y))
    }

    /// r = sqrt(ax^2 x^2 + ay^2 y^2) = alpha(phi) sin(theta), a^2 = z^2 / r^2 carried exactly,
    /// and a = |z| / r, of `w`.
    #[inline]
    fn a_of_w(&self, w: V3<T>) -> (Rel<T>, Arg<T>) {
        // A zero vector takes the horizon's a = 0 (G1 = 0, the capped Lambda pole) instead of
        // a = 0 / 0.
        let w = crate::vec3::horizon_if_zero3(w);
        let (ax, ay) = self.clamped_alphas();
        let px = Rel::exact(ax).mul(Rel::exact(w.x));
        let py = Rel::exact(ay).mul(Rel::exact(w.y));
        let r2 = px.mul(px).add(py.mul(py));
        let z2 = Rel::exact(w.z).mul(Rel::exact(w.z));
        let (r_hi, r_corr) = sqrt_dw(r2);
        let r = r_hi + r_corr;
        let r_rel = T::select(r.simd_gt(T::ZERO), ((r_hi - r) + r_corr) / r, T::ZERO);
        let arg = finish_a(z2.div(r2), z2.hi, r, w.z.abs());
        (Rel { hi: r, rel: r_rel }, arg)
    }

    /// |z| Lambda = r P / (a + K) of `w` (see [`lambda_parts`]) with its relative
    /// correction; 0 at the normal (r = 0, a = inf).
    #[inline]
    fn cos_lambda_rel(&self, w: V3<T>) -> Rel<T> {
        let (r, x) = self.a_of_w(w);
        let (p, k) = lambda_parts(x.a, x.a_rel, x.a2);
        let capped = x.a.simd_lt(T::splat(1e4));
        let a = Rel {
            hi: x.a.min(T::splat(1e4)),
            rel: T::select(capped, x.a_rel, T::ZERO),
        };
        let v = r.mul(p).div(a.add(k));
        // NaN (alpha out of domain) fails both comparisons: keep it rather than 0.
        let ok = (r.hi.simd_gt(T::ZERO) & p.hi.simd_gt(T::ZERO)) | x.a.is_nan() | r.hi.is_nan();
        Rel {
            hi: T::select(ok, v.hi, T::ZERO),
            rel: T::select(ok, v.rel, T::ZERO),
        }
    }
}

impl<T: Real> Microfacet<T> for Beckmann<T> {
    /// D(m) = exp(-(x^2/ax^2 + y^2/ay^2) / z^2) / (pi ax ay z^4) for m.z > 0, else 0 (Walter
    /// et al. 2007 eq. 25, anisotropic as Heitz 2014 eq. 80). The exponent is
    /// tan^2(theta) / alpha^2, not the h.h some course notes print.
    #[inline]
    fn d(&self, m: V3<T>) -> T {
        let (ax, ay) = self.clamped_alphas();
        let u = Rel::exact(m.x).div(Rel::exact(ax));
        let v = Rel::exact(m.y).div(Rel::exact(ay));
        let z2 = Rel::exact(m.z).mul(Rel::exact(m.z));
        let e = u.mul(u).add(v.mul(v)).div(z2);
        let den = Rel::exact(ax).mul(Rel::exact(ay)).mul(z2).mul(z2);
        let value = T::select(m.z.simd_gt(T::ZERO), exp_neg_over(e, den), T::ZERO);
        nan_where(any_nonfinite3(m) | ax.is_nan() | ay.is_nan(), value)
    }

    /// Exact Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 with a = |z| / (alpha(phi)
    /// sin(theta)) (Heitz 2014 eq. 83), evaluated without cancellation as
    /// exp(-a^2) K(a) / (2 sqrt(pi) a (a + K(a))) (see [`lambda`]). Pole at the horizon capped
    /// at the largest finite value; 0 at the normal; NaN for a NaN or infinite component.
    #[inline]
    fn lambda(&self, w: V3<T>) -> T {
        let (_, x) = self.a_of_w(w);
        nan_where(any_nonfinite3(w), lambda_from(x))
    }

    /// G1 = 1 / (1 + Lambda) = a (a + K) / (a (a + K) + P) in the notation of [`lambda`]:
    /// one rounding fewer than through Lambda. 1 at the normal, 0 at the horizon; NaN for NaN
    /// in any component.
    #[inline]
    fn g1(&self, w: V3<T>) -> T {
        let (_, x) = self.a_of_w(w);
        nan_where(any_nonfinite3(w), g1_from(x))
    }

    /// |z| Lambda = r exp(-a^2) K(a) / (2 sqrt(pi) (a + K(a))) with r = alpha(phi)
    /// sin(theta): r / (2 sqrt(pi)) at the horizon, 0 at the normal; NaN for NaN in any
    /// component.
    #[inline]
    fn cos_lambda(&self, w: V3<T>) -> T {
        // At the normal r = 0 and a = inf: P = 0 and the product is 0 * 0.
        nan_where(any_nonfinite3(w), self.cos_lambda_rel(w).value())
    }

    /// V = 1 / (4 (|o.z| |i.z| + |i.z| |o.z| Lambda(o) + |o.z| |i.z| Lambda(i))) as in the
    /// trait, with every product and sum carried with its relative correction (each
    /// |z| Lambda from [`Beckmann::cos_lambda`]'s form) and rounded once: the trait's plain
    /// sum adds five roundings to the two of |z| Lambda. Edges as the trait's: 0 when both
    /// cosines are 0, capped at MAX, NaN for NaN input.
    #[inline]
    fn v_correlated(&self, wo: V3<T>, wi: V3<T>) -> T {
        // Both outer cosines scaled by the power of two S (2^60 in f32, 2^500 in f64; exact):
        // at subnormal cosines the products |i.z| |o.z| Lambda(o) would be subnormal and lose
        // bits; V = (S / 4) / (S den) is the same quotient, and S den cannot overflow.
        let sc = T::splat(if crate::dw::single::<T>() {
            1.152_921_504_606_847e18
        } else {
            3.273_390_607_896_142e150
        });
        let (co, ci) = (wo.z.abs(), wi.z.abs());
        let (so, si) = (Rel::exact(sc * co), Rel::exact(sc * ci));
        let den = so
            .mul(Rel::exact(ci))
            .add(si.mul(self.cos_lambda_rel(wo)))
            .add(so.mul(self.cos_lambda_rel(wi)));
        let ok = den.hi.simd_gt(T::ZERO);
        let safe = Rel {
            hi: T::select(ok, den.hi, T::ONE),
            rel: den.rel,
        };
        let v = Rel::exact(T::splat(0.25) * sc)
            .div(safe)
            .value()
            .min(T::MAX);
        nan_where(
            any_nonfinite3(wo) | any_nonfinite3(wi) | den.hi.is_nan(),
            T::select(ok, v, T::ZERO),
        )
    }
}

/// Isotropic Beckmann NDF of n_dot_h: D = exp(-tan^2 / alpha^2) / (pi alpha^2 c^4), with
/// tan^2 = (1 - c^2) / c^2 (Walter et al. 2007 eq. 25). D(1) = 1 / (pi alpha^2), the peak for
/// alpha <= 1 / sqrt(2); for larger alpha the peak, 4 alpha^2 e^(1 / alpha^2 - 2) / pi, lies at
/// c = 1 / (sqrt(2) alpha).
///
/// Domain: n_dot_h in [-1, 1] (above 1 is clamped to 1; <= 0 gives 0), alpha in [0, +inf)
/// finite, clamped to [ALPHA_MIN, ALPHA_MAX]. NaN for NaN input, alpha < 0 or +inf. `alpha` is
/// the RMS slope, not perceptual roughness (from a slider value r: alpha = r^2,
/// [`alpha_from_perceptual`]).
///
/// exp(-E) turns a relative error in E into an absolute one E times larger, so E needs more
/// than the working precision:
///
/// - `f64`, `f64x4`: E is carried with the error of each rounding recovered by Dekker's exact
///   products and the division remainder, D is exp(-E_hi) (1 - E_lo) / (pi alpha^2 c^4) with
///   the denominator's roundings recovered too, and the whole is rounded once (about 150
///   extra flops): within 1.7 ULP (f64) / 2.2 (f64x4), exp's own error included.
/// - `f32`, `f32x8`: the same D is evaluated in f64 and rounded to f32 once; `f32x8` takes
///   its eight lanes as one `f64x8` (one AVX-512 register where the target has them, two
///   `f64x4` otherwise), the scalar's operations lane for lane, so that lanes equal scalars
///   bit for bit. First, in f32, the cosine is raised to c_min = 1 / sqrt(1 + 200 alpha^2),
///   where E = 200 (E in [182, 206] after c_min's f32 roundings, a bound of alpha alone
///   computed once in a loop over cosines): D there is below 1e-60 for every alpha in
///   [ALPHA_MIN, ALPHA_MAX] and rounds to 0, as the true D does at every cosine below it (D
///   grows with c up to its peak, which lies above c_min), c <= 0 included, without a select.
///   Then, in f64, where c^2 and alpha^2 are exact:
///
///   x = E log2(e) = (1 - c^2) q_l, q_l = (log2(e) / alpha^2) / c^2 (the one division; the
///   factor of alpha alone once per alpha), k = floor(x), f = x - k in [0, 1) (exact),
///   D = 2^-f 2^-k Q, Q = (q_l alpha ln(2) / sqrt(pi))^2, 2^-f by a degree-6 polynomial within
///   2.6e-9 (interpolation at the Chebyshev nodes of [0, 1]) and 2^-k from its exponent
///   bits.
///
///   Error budget, relative to D: x carries six roundings of 2^-53 (1/alpha^2, log2(e) and
///   its rounding, the division, 1 - c^2, the product), below 2.0e-13 absolute for x <= 300,
///   so 2^-x is within 1.4e-13; the polynomial 2.6e-9 (0.044 ULP of f32); the other factor
///   and the product about 20 roundings of 2^-53 (2.2e-15): about 2.6e-9 in all before the
///   rounding to f32, 0.045 ULP, so within 0.5 + 0.045 ULP of the exact D. Every product is
///   a normal f64 (D >= 1e-99 for E <= 206).
///
///   The rounding to f32 never meets a subnormal number (on x86 each costs a microcode
///   assist; `tests/lanes/exp.rs` reads the flags that record one): big = max(D, 2^-126) is
///   converted, and small = min(2^-f (2^-k Q 2^149) + 1.5 2^52 - 2^23, 1.5 2^52), one
///   multiply-add beside big's product, holds in its low 32 bits n - 2^23 for n the
///   subnormal result's bit pattern, round(D 2^149) (capped at 2^23 where D is normal); the
///   sum of the two bit patterns is fl32(D) in both ranges (`crate::widen::join_tiny_f32`),
///   with no comparison. NaN in either input reaches D through the f64 steps and the
///   conversion. Within 0.7 ULP (f32, f32x8; 0.54 found by the MPFR oracle's
///   worst-case search `beckmann_d_f32_worst_case_search` in `oracle/tests/microfacet.rs`:
///   fresh points, cosines within 64 ULP of 1, E near the polynomial's interval ends and at
///   c_min, D near 2^-126 and 2^-149, alpha at ALPHA_MIN and ALPHA_MAX, and a hill-climb;
///   scored in ULPs of the correctly rounded f32, 2^-149 below 2^-126; `cargo test -p
///   brdf-oracle --release --test microfacet beckmann_d_f32_worst_case -- --nocapture`, 0.54
///   in the default, FMA and `-C target-cpu=native` builds over 2 * 10^6 points each).
///
/// Measured by the MPFR oracle (module docs). Run time on `f32x8` (native build, one core of an
/// AMD EPYC (Zen 4), 10^6 uniform cosines through [`crate::batch::run_f32`], CPU time, one
/// interleaved run of `bench/mitsuba/compare.py --n 1000000` under a load average of about 5):
/// 0.93 ms, 1.47x Mitsuba 3's `eval` on the same batch (0.63 ms; 1.50x in another run) and
/// 1.5x [`d_fast`]; 2.1x to 2.3x Mitsuba before this form (two `f64x4` halves, e^-r after a
/// rounding to nearest, a second conversion for the subnormal results).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn d<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a = clamp_alpha(alpha);
    // NaN is restored last, since the f32 rounding does not keep it. On f64 types c <= 0
    // gives D = 0 through E = +inf (`DIso::native`); on f32 types the cosine is raised to
    // the floor of `DIso::wide` here, in f32 (c <= 0 included).
    let lo = if crate::dw::single::<T>() {
        c_floor_f32(a)
    } else {
        T::ZERO
    };
    let c = n_dot_h.max(lo).min(T::ONE);
    let value = T::via_f64([c, a], DIso, crate::real::sealed::Token::NEW);
    if crate::dw::single::<T>() {
        // NaN reaches D through the f64 evaluation and its rounding (`DIso::factors`).
        value
    } else {
        nan_where(a.is_nan() | n_dot_h.is_nan(), value)
    }
}

/// Above this exponent E the isotropic D is below 2^-150 for every alpha in [ALPHA_MIN,
/// ALPHA_MAX] and every cosine, so it rounds to 0 in f32: with 1 / (c^2 alpha^2) = E / s2,
/// D = e^-E E^2 alpha^2 / (pi s2^2) <= 4e8 e^-E E^2 / pi < 1e-74 where c^2 <= 1/2 (s2 >= 1/2),
/// and D = e^-E / (pi alpha^2 c^4) <= 4 e^-E / (pi 1e-8) < 1e-79 where c^2 > 1/2.
const E_ZERO_F32: f64 = 200.0;

/// The cosine below which `d` on f32 types raises n_dot_h, where E = E_ZERO_F32:
/// c_min = 1 / sqrt(1 + 200 alpha^2), in f32 (see [`d`]). Its four f32 roundings move E at
/// c_min into [182, 206] (a sweep of 2 * 10^6 log-spaced alphas over [ALPHA_MIN,
/// ALPHA_MAX], fused and unfused multiply-add alike), where D < 1e-66 still rounds to 0
/// (the bound above with E >= 182).
#[inline]
fn c_floor_f32<T: Real>(a: T) -> T {
    (a * a).mul_add(T::splat(E_ZERO_F32), T::ONE).sqrt().recip()
}

/// The isotropic D of `d` for c = min(n_dot_h, 1) and the clamped alpha (c <= 0 is replaced
/// by the caller): double words in f64 and f64x4, one f64 evaluation rounded once in f32 and
/// f32x8.
#[derive(Clone, Copy)]
struct DIso;

impl crate::real::sealed::Widened<2> for DIso {
    const TINY: bool = true;

    #[inline]
    fn native<T: Real>(self, [c, a]: [T; 2]) -> T {
        let (e, c2) = exponent_iso(c, a);
        let den = Rel::exact(a).mul(Rel::exact(a)).mul(c2).mul(c2);
        crate::domain::above(c, exp_neg_over(e, den))
    }

    /// D before its rounding to f32 (`single` and `lanes8` below round D's two factors
    /// with `crate::widen`'s subnormal-safe rounding instead).
    #[inline]
    fn wide<W: Real<Scalar = f64>>(self, x: [W; 2]) -> W {
        let (p, rest) = Self::factors(x);
        p * rest
    }

    #[inline]
    fn single(self, x: [f32; 2]) -> f32 {
        let (p, rest) = Self::factors(x.map(f64::from));
        crate::widen::join_tiny_f32(
            crate::widen::tiny_big(p, rest),
            crate::widen::tiny_small(p, rest),
        )
    }

    /// All eight lanes as one `f64x8` (one AVX-512 register where the target has them):
    /// half the instructions of two `f64x4` halves, the same operations lane for lane.
    #[inline]
    fn lanes8(self, x: [crate::wide::f32x8; 2]) -> crate::wide::f32x8 {
        let [c, a] = x;
        let (p, rest) = Self::factors([crate::widen::widen8(c), crate::widen::widen8(a)]);
        crate::widen::join_tiny_f32x8(
            crate::widen::tiny_big(p, rest),
            crate::widen::tiny_small(p, rest),
        )
    }
}

impl DIso {
    /// D = 2^-f (2^-k q^2 alpha^2 / pi) as (2^-f, the rest), from c (raised to the floor in
    /// f32 by [`d`]) and the clamped alpha, widened from f32 (see [`d`]).
    #[inline]
    fn factors<W: crate::widen::F64Lanes>([c, a]: [W; 2]) -> (W, W) {
        let one = W::splat(1.0);
        let c2 = c * c;
        // q log2(e) = (log2(e) / alpha^2) / c^2; a factor of alpha alone is computed once
        // in a loop over cosines.
        let q_l = ((one / (a * a)) * W::splat(core::f64::consts::LOG2_E)) / c2;
        let x = (one - c2) * q_l;
        let k = x.floor();
        let p = crate::widen::exp2_neg_unit(x - k);
        let qb = q_l * (a * W::splat(LN2_OVER_SQRT_PI));
        (p, crate::widen::pow2_neg(k) * (qb * qb))
    }
}

/// ln(2) / sqrt(pi): q log2(e) times alpha times this is q alpha / sqrt(pi).
const LN2_OVER_SQRT_PI: f64 = 0.391_066_419_137_416_97;

/// Isotropic Beckmann NDF in working precision, the fast companion of [`d`]: the same
/// D = exp(-tan^2 / alpha^2) / (pi alpha^2 c^4) (Walter et al. 2007 eq. 25) with one division
/// and an exponential of the lane type's own, as renderers evaluate it (Mitsuba 3's
/// `MicrofacetDistribution::eval`, pbrt-v4's Beckmann `D`), but with the exponent carried to
/// about twice the working precision, and arranged so that for normal inputs (and 0) no
/// intermediate is ever a subnormal number (on x86 each costs a microcode assist of about a
/// hundred cycles, and a Beckmann lobe's tail is full of them; `tests/lanes/exp.rs` reads the
/// x86 flags that record one):
///
/// tan4 = 4 / c^2 - 4 = 4 tan^2, t = E log2(e) / 2 = B4 tan4 with B4 = log2(e) / (8 alpha^2),
/// y = 2^-t / (sqrt(pi) alpha c^2), D = y^2.
///
/// exp(-E) turns an absolute error in E into a relative one in D, so a relative rounding of
/// E costs E times as much in D (Mitsuba's E, from (x^2 + y^2) / z^2, carries a few roundings:
/// up to about 2 E ULP). Here v = 2 / c (the one division) and its exact remainder 2 - v c
/// give 4 / c^2 to first order beyond the working precision, v^2 and B4 are split exactly
/// (Dekker's products, one multiply-add each where the target has them), and the exponential
/// takes B4 tan4 as an exact product of its high parts plus a first-order correction
/// (2^-t = 2^-n p(f) with f = n - B4 tan_s from one multiply-add, times 1 - ln(2) B4 x for the
/// low parts x): what is left is a few roundings of D itself and of 2^f, whatever E is. 2^-t
/// is 2^-n p(f) with p a degree-5 polynomial (within 2 ULP of 2^f) on f32 and f32x8, the same
/// operations on both, and libm's exp2 on f64 and f64x4. Cosines below the one where E = 150
/// (f32) / 1380 (f64), c^2 = 1 / (1 + E alpha^2), a bound of alpha alone, are raised to it
/// (c <= 0 included): D is below the smallest normal number there for every alpha in
/// [ALPHA_MIN, ALPHA_MAX], t stays within 108.2 / 995.5, where 2^-t is normal, and no select
/// on E is needed. D = 0 wherever it is below the smallest normal number (y^2 would be
/// subnormal): an absolute error below 1.2e-38 (f32) / 2.3e-308 (f64); a y up to 2^-15
/// (relative) below the root of the smallest normal number is raised to it, so that a D whose
/// exact value is normal is not flushed through y's own error. The factors of alpha alone
/// (B4 and its rounding, 1 / (sqrt(pi) alpha), the cosine floor: two divisions and a square
/// root) are computed in the call; in a loop over cosines with one alpha the compiler computes
/// them once.
///
/// Domain, edges and bad input as [`d`]: n_dot_h in [-1, 1] (above 1 clamped to 1; <= 0
/// gives 0), alpha in [0, +inf) finite, clamped to [ALPHA_MIN, ALPHA_MAX] (the RMS slope, not
/// perceptual roughness); D(1) = 1 / (pi alpha^2), the peak for alpha <= 1 / sqrt(2); NaN for
/// NaN input, alpha < 0 or +inf.
///
/// Accuracy: max error against [`d`] over a grid of cosines from 0 through 1e-7 to 1 and alpha
/// over [ALPHA_MIN, ALPHA_MAX], plus 400 000 random pairs, by range of E (default x86-64 build,
/// without fused multiply-adds), and a search of 4 * 10^6 points per range concentrated at its
/// top E and at cosines within a few ULP of 1 (that build and `-C target-cpu=native`):
///
/// | E = tan^2 / alpha^2 | <= 1 | (1, 10] | (10, 100] | (100, 1000] |
/// |---|---|---|---|---|
/// | f32, f32x8: ULP (relative) | 13 (8.2e-7) | 15 (9.1e-7) | 66 (5.2e-6) | D < 1e-30 |
/// | f64, f64x4: ULP (relative) | 9 (1.3e-15) | 10 (1.3e-15) | 10 (1.3e-15) | 10 (1.3e-15) |
///
/// The search's maxima over all E: f32 30 ULP, 90 with alpha > 334 (at E = 89); f64 14 ULP
/// (the same in both builds).
///
/// The error grows with E in two corners only: on f32 with alpha > 334 (cosines below 2^-12
/// with E < 150), where 4 / c^2 - 4 rounds once more (up to about 2 E ULP: the 66 and 90 above),
/// and at cosines within a few ULP of 1 with alpha near ALPHA_MIN, where the neglected square
/// of v's remainder costs up to about 25 ULP. (`cargo test --all-features --test kernels
/// fast_variants:: -- --nocapture`; errors counted where D >= 1e-30 in f32, 1e-300 in f64; the
/// test asserts 36 + 2 E ULP (f32) and 18 ULP (f64) at each range's top E.) Lanes equal the
/// scalar results bit for bit on every lane type.
///
/// Run time (native build, one core of an AMD EPYC (Zen 4), 10^6 uniform cosines, alpha = 0.3,
/// through [`crate::batch::run_f32`], CPU time, one interleaved run of `bench/mitsuba/compare.py
/// --n 1000000` under a load average of 5): 0.60 ms, 0.93x Mitsuba 3's `eval` on the same batch
/// (0.65 ms), whose error there is 185 ULP against this tier's 12.4 (median 1.3), and 0.42x
/// [`d`]; the form before this one, four roundings in E, took 0.73 ms at 332 ULP (1.15x
/// Mitsuba in a run under a load of 10). Without fused multiply-adds the exact products take
/// Dekker's splits (about 17 operations each instead of one).
#[inline]
#[must_use]
pub fn d_fast<T: Real>(n_dot_h: T, alpha: T) -> T {
    use crate::dw::{sub_prod, two_sq};
    let single = crate::dw::single::<T>();
    // NaN alpha, alpha < 0 or +inf give NaN here, which B4 below carries to D.
    let a = clamp_alpha(alpha);
    // Factors of alpha alone (in a loop over cosines with one alpha, computed once).
    //
    // E_CUT: where E >= 150 (f32) / 1380 (f64), D = e^-E E^2 alpha^2 / (pi s2^2) is below the
    // smallest normal number for every alpha in [ALPHA_MIN, ALPHA_MAX] (that would take
    // s2 < alpha 1e-11, i.e. E < 1e-11 / alpha), and t = E log2(e) / 2 stays within 108.2 /
    // 995.5, where 2^-t is normal. Cosines below the one where E = E_CUT, c^2 = 1 / (1 +
    // E_CUT alpha^2), are raised to it (c <= 0 included): D there is flushed to 0 below, as
    // its exact value would be, without a select on E.
    let (e_cut, y_min) = if single {
        (150.0, 1.084_202_172_485_504_4e-19)
    } else {
        (1380.0, 1.491_668_146_240_041_3e-154)
    };
    let (a2, a2_l) = two_sq(a);
    let c_floor = a2.mul_add(T::splat(e_cut), T::ONE).sqrt().recip();
    // B4 = log2(e) / (8 alpha^2) = B4_h (1 + beta): its rounding beta, from the division's exact
    // remainder, alpha^2's rounding and log2(e) / 8 in two parts (f64: 2.544e-18 below
    // fl(log2(e) / 8); f32: 2.407e-9 below its f32 rounding).
    let k4_lo = if single {
        2.407_453_738_908_272e-9
    } else {
        2.544_409_217_616_379e-18
    };
    let k4 = T::splat(0.180_336_880_111_120_42);
    let b4 = k4 / a2;
    let beta = (sub_prod(k4, b4, a2) - b4 * a2_l + T::splat(k4_lo))
        * T::splat(1.0 / 0.180_336_880_111_120_42);
    // M4 = 1 / (4 sqrt(pi) alpha), and M4 ln(2) B4 for the correction of t's rounding.
    let m4 = T::splat(0.141_047_395_886_939_07) / a;
    let ml = m4 * (T::splat(core::f64::consts::LN_2) * b4);

    // NaN stays NaN (`max` and `min` propagate it from `self`).
    let c = n_dot_h.max(c_floor).min(T::ONE);
    // tan4 = 4 tan^2 = 4 / c^2 - 4 from v = 2 / c (one division) and its exact remainder
    // e2 = 2 - v c: 4 / c^2 = v^2 (1 + e2) to first order and v^2 = w4 + w4_l exactly, so
    // tan4 = tan_h + (w4 e2 + w4_l) with tan_h = w4 - 4 (exact for w4 <= 2^26, 2^55 in f64).
    // The exponential takes tan_s = (v^2 - 4) + w4 e2, two roundings (multiply-adds), within
    // about an ULP of tan4; the rest, tan_r = (tan_h - tan_s) + (w4 e2 + w4_l), is formed
    // beside it (tan_h - tan_s is exact: both lie on the grid of tan_s's ULP or w4's, within
    // 2^24 of its units).
    let v = T::TWO / c;
    let e2 = sub_prod(T::TWO, v, c);
    let (w4, w4_l) = two_sq(v);
    let tan_h = w4 - T::splat(4.0);
    let tan_s = w4.mul_add(e2, crate::dw::sq_minus(v, T::splat(4.0)));
    let tan_r = (tan_h - tan_s) + w4.mul_add(e2, w4_l);
    // t = E log2(e) / 2 = B4 (tan_s + x), x = tan_r + beta tan_s the first-order part;
    // y = 2^-t / (sqrt(pi) alpha c^2) = 2^-(B4 tan_s) (1 - ln(2) B4 x) w4 M4, D = y^2, so that
    // neither 2^-t nor y is subnormal while D is a normal number. The product B4 tan_s is
    // exact in the exponential.
    let x = beta.mul_add(tan_s, tan_r);
    let mk = (-ml).mul_add(x, m4);
    let y = b4.exp2_neg_prod(tan_s, w4 * mk, crate::real::sealed::Token::NEW);
    // y^2 is subnormal below y = 2^-63 (f32) / 2^-511 (f64): those lanes are 0, so no lane
    // ever holds a subnormal number (each costs a microcode assist on x86). The cut lies
    // 2^-15 (relative) below that y, and y between the cut and 2^-63 is raised to 2^-63: a D
    // whose exact value is a normal number near the smallest comes out as that number rather
    // than 0.
    let zero = y.simd_lt(T::splat(y_min * (1.0 - 1.0 / 32768.0)));
    let y = T::select(zero, T::ZERO, y.max(T::splat(y_min)));
    y * y
}

/// a = c / (alpha sqrt(1 - c^2)) = 1 / (alpha tan(theta)): the argument of every Beckmann
/// Smith term. Domain: n_dot_v in [-1, 1] (|c| is used, clamped to 1), alpha (the RMS slope, as
/// in [`d`]; not perceptual roughness) in [0, +inf) finite, clamped to [ALPHA_MIN, ALPHA_MAX];
/// NaN for NaN input, alpha < 0 or +inf. The pole at |c| = 1 is capped at the largest finite
/// value; 0 at c = 0. Within about 1 ULP (the square root of the exactly carried a^2, its own
/// rounding recovered).
#[inline]
#[must_use]
pub fn a_of<T: Real>(n_dot_v: T, alpha: T) -> T {
    a_and_a2(n_dot_v, alpha).a.min(T::MAX)
}

/// a and a^2 = c^2 / (alpha^2 (1 - c^2)), carried exactly.
#[inline]
fn a_and_a2<T: Real>(n_dot_v: T, alpha: T) -> Arg<T> {
    let c = n_dot_v.abs().min(T::ONE);
    let a = clamp_alpha(alpha);
    let c2 = Rel::exact(c).mul(Rel::exact(c));
    let s2 = Rel::one_minus_sq(c);
    let a2 = c2.div(Rel::exact(a).mul(Rel::exact(a)).mul(s2));
    finish_a(a2, c2.hi, a * s2.hi.sqrt(), c)
}

/// a = sqrt(a^2) from a^2 = z^2 / r^2 carried exactly, with r and |z| kept for 1 / a.
///
/// Below z^2 = MIN_POSITIVE / EPSILON^2 (8e-25 in f32, 4e-277 in f64) the rounding error of
/// z^2 is itself subnormal and inexact (at z = 3e-22 in f32, z^2 is a subnormal off by 1%),
/// and a^2 built from it is wrong even where a^2 is a normal number. There a < z / ALPHA_MIN
/// is below 1e-8 (f32), so Lambda = 1 / (2 sqrt(pi) a) - 1/2 + O(a) depends on a alone and
/// is evaluated from r / |z| (a division of exactly rounded operands); a = |z| / r and a^2
/// only enter through a + K and exp(-a^2) = 1.
#[inline]
fn finish_a<T: Real>(a2: Rel<T>, z2: T, r: T, z: T) -> Arg<T> {
    let tiny = z2.simd_lt(T::MIN_POSITIVE / (T::EPSILON * T::EPSILON));
    let direct = z / r;
    let (s, corr) = sqrt_dw(a2);
    let a = s + corr;
    // a's own rounding, relative: (s + corr - a) / a (Fast2Sum, |corr| below an ULP of s).
    let a_rel = T::select(
        a.simd_gt(T::ZERO) & a.is_finite(),
        ((s - a) + corr) / a,
        T::ZERO,
    );
    Arg {
        a: T::select(tiny, direct, a),
        a_rel: T::select(tiny, T::ZERO, a_rel),
        a2: Rel {
            hi: T::select(tiny, direct * direct, a2.hi),
            rel: T::select(tiny, T::ZERO, a2.rel),
        },
        r,
        z,
        tiny,
    }
}

/// sqrt of a value carried as hi (1 + rel): sqrt(hi) (1 + rel / 2), as the rounded root s
/// and its correction (s + corr is the root to about twice the working precision). K / (a (a + K)) in Lambda
/// has a relative sensitivity of about 3 to a, so the few ULP of rel matter. Below the
/// smallest normal (where the two-products that made rel were themselves inexact) rel is
/// ignored.
#[inline]
fn sqrt_dw<T: Real>(x: Rel<T>) -> (T, T) {
    let s = x.hi.sqrt();
    // The exact residual hi - s^2 recovers the rounding of the square root itself:
    // sqrt(hi (1 + rel)) = s + (hi - s^2) / (2 s) + s rel / 2 to first order.
    let (t, u) = two_prod(s, s);
    let corr = ((x.hi - t) - u) / (T::TWO * s) + s * x.rel * T::HALF;
    let usable = corr.is_finite() & x.hi.simd_ge(T::MIN_POSITIVE);
    (s, T::select(usable, corr, T::ZERO))
}

/// Exact Smith Lambda of the isotropic Beckmann distribution (Walter et al. 2007 eq. 27;
/// Heitz 2014 eq. 83): Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = [`a_of`].
///
/// That difference cancels as a grows (both terms approach exp(-a^2) / (a sqrt(pi))), so it
/// is evaluated as exp(-a^2) K / (2 sqrt(pi) a (a + K)), with erfc(a) = exp(-a^2) /
/// (sqrt(pi) (a + K)) defining K (the tail of erfc's continued fraction, Abramowitz and Stegun
/// 7.1.14; a Chebyshev series on [0, 4], the continued fraction above), and a^2 carried
/// exactly into exp.
///
/// Domain: as [`a_of`] (alpha the RMS slope, not perceptual roughness). Edges: the pole at
/// n_dot_v = 0 is capped at the largest finite value (G1 = 1 / (1 + MAX) = 0 exactly), 0 at
/// |n_dot_v| = 1. Within 2.5 ULP (f32, f32x8) / 2.0 ULP (f64) / 2.3 ULP (f64x4), module
/// docs.
#[inline]
#[must_use]
pub fn lambda<T: Real>(n_dot_v: T, alpha: T) -> T {
    lambda_from(a_and_a2(n_dot_v, alpha))
}

/// Smith G1 = 1 / (1 + [`lambda`]) of the isotropic Beckmann distribution, evaluated as
/// a (a + K) / (a (a + K) + P) in the notation of [`lambda`] (one rounding fewer). Same
/// domain (alpha the RMS slope, as in [`d`]); 0 at n_dot_v = 0, 1 at |n_dot_v| = 1; NaN for
/// NaN input or alpha < 0 or +inf. Within 3.3 ULP (f32, f32x8) / 2.4 ULP (f64, f64x4), module
/// docs.
#[inline]
#[must_use]
pub fn g1<T: Real>(n_dot_v: T, alpha: T) -> T {
    g1_from(a_and_a2(n_dot_v, alpha))
}

/// Walter et al.'s rational approximation of the Beckmann Lambda (Walter et al. 2007 eq. 27,
/// the G1 fit (3.535 a + 2.181 a^2) / (1 + 2.276 a + 2.577 a^2) written as Lambda = 1/G1 - 1):
/// Lambda ~ (1 - 1.259 a + 0.396 a^2) / (3.535 a + 2.181 a^2) for a < 1.6, 0 beyond.
/// Approximation: the resulting G1 is within 0.31% (relative) of the exact one for alpha and
/// NoV in [0.01, 1] (`cargo test --test microfacet smith_approximations:: -- --nocapture`). Clamped
/// at 0 (the numerator crosses zero just below a = 1.6). alpha as [`d`] (the RMS slope, not
/// perceptual roughness).
#[inline]
#[must_use]
pub fn lambda_walter<T: Real>(n_dot_v: T, alpha: T) -> T {
    // a_of propagates NaN and a NaN a fails every comparison below: select it explicitly.
    let a = a_of(n_dot_v, alpha);
    let num = a.mul_add(a.mul_add(T::splat(0.396), T::splat(-1.259)), T::ONE);
    let den = a * a.mul_add(T::splat(2.181), T::splat(3.535));
    let v = T::select(a.simd_lt(T::splat(1.6)), (num / den).max(T::ZERO), T::ZERO);
    // At a = 0 (the horizon) num / den is 1 / 0: cap the pole like the exact Lambda.
    nan_where(a.is_nan(), v.min(T::MAX))
}

/// Blinn-Phong exponent n to the Beckmann alpha with the same lobe shape near the peak:
/// alpha = sqrt(2 / (n + 2)) (Walter et al. 2007, section 5.2). The result is an alpha (RMS
/// slope) for [`d`] and [`Beckmann`], not a perceptual roughness. Domain n in [0, +inf) finite
/// (n = 0 gives alpha = 1; alpha falls towards 0 as n grows); n < 0, +inf or NaN gives NaN
/// (crate docs, "Bad input", rule 5). Within 1 ULP.
#[inline]
#[must_use]
pub fn alpha_from_blinn_phong<T: Real>(exponent: T) -> T {
    crate::domain::nan_unless(
        exponent.simd_ge(T::ZERO) & exponent.simd_lt(T::INFINITY),
        (T::TWO / (exponent + T::TWO)).sqrt(),
    )
}

/// Beckmann alpha to the Blinn-Phong exponent n = 2 / alpha^2 - 2 (the inverse of
/// [`alpha_from_blinn_phong`]). Domain alpha in [0, +inf) finite, clamped to [ALPHA_MIN,
/// ALPHA_MAX] (so n <= 2e8); alpha < 0, NaN or +inf gives NaN. alpha > 1 gives a negative n,
/// which no Blinn-Phong lobe has: it is clamped to 0.
#[inline]
#[must_use]
pub fn blinn_phong_from_alpha<T: Real>(alpha: T) -> T {
    let a = clamp_alpha(alpha);
    (T::TWO / (a * a) - T::TWO).max(T::ZERO)
}
