//! GGX / Trowbridge-Reitz: the NDF, its exact Smith Lambda, the height-correlated visibility,
//! and the real-time approximations of Smith G that engines ship, each with its measured error.
//!
//! Sources: Trowbridge and Reitz 1975, "Average irregularity representation of a rough surface
//! for ray reflection"; Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction
//! through Rough Surfaces" (EGSR); Heitz 2014, "Understanding the Masking-Shadowing Function in
//! Microfacet-Based BRDFs" (JCGT 3(2)).
//!
//! Roughness: every `alpha` here is the GGX width alpha (Walter et al. 2007's alpha_g), not the
//! perceptual roughness r of a material slider: alpha = r^2, converted by [`alpha_from_perceptual`]
//! (glTF's `roughnessFactor`, Unreal Engine 4's `Roughness` and Filament's `perceptualRoughness`
//! are r). Filament's shader functions take this alpha under the name `roughness`; those of
//! Unreal Engine 4 take its square `a2`. The
//! [roughness conventions](crate::microfacet#roughness-conventions) tabulate the names, and
//! `cargo run --release --example shader_port` checks a port of both engines' formulas.
//!
//! Two entry points for every term: free functions of dot products (`d(n_dot_h, alpha)`), and
//! the [`Ggx`] type implementing [`Microfacet`] on local-frame vectors (isotropic and
//! anisotropic). Cosines passed to the free functions are clamped to [0, 1] (a cosine just
//! above 1 from an unnormalized input becomes 1; a negative one, from a back-facing direction,
//! becomes 0; Lambda and G1 use |c|). Domain of alpha: [0, +inf) finite, clamped to
//! [[`ALPHA_MIN`](crate::microfacet::ALPHA_MIN), [`ALPHA_MAX`](crate::microfacet::ALPHA_MAX)];
//! alpha < 0, NaN or +inf gives NaN; NaN in any input gives NaN; Lambda's pole at the horizon
//! is capped at the largest finite value, and V is 0 when both cosines are 0 (its limit
//! depends on the path; the BRDF is multiplied by a zero cosine there anyway).
//!
//! Precision near the pole: every form here uses sin^2 = (1 - c)(1 + c) (exact 1 - c for
//! c >= 1/2) or, on vectors, x^2 + y^2, never 1 - c^2; and D's denominator is
//! sin^2 + cos^2 alpha^2, a sum of non-negative terms, not 1 + c^2 (alpha^2 - 1), whose
//! rewrite (1 - c^2) + c^2 alpha^2 by GPU compilers cancels for c near 1.
//!
//! Accuracy: max error in ULPs of the correctly rounded result, measured by the MPFR oracle
//! (the papers' definitions, Walter et al. 2007 eqs. 33-34 and Heitz 2014 eqs. 85-86 and
//! 98-99, in tan^2, at 256+ bits) on its stiff and random points (cosines from 1 down to
//! subnormals, alpha from 1e-4 to 1e4), wherever the result is >= 1e-30 (f32) / 1e-300
//! (f64); `cargo test -p brdf-oracle --release --test microfacet -- --nocapture`:
//!
//! | function | f32 | f64 | f32x8 | f64x4 |
//! |---|---|---|---|---|
//! | `d`, `d_aniso`, `Ggx::d` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `lambda` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `Ggx::lambda` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `g1` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `v_correlated` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `Ggx::g2_correlated` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `Ggx::g2_separable` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `Ggx::v_correlated` | 0.50 | 0.50 | 0.50 | 0.50 |
//!
//! These are the deep search's maxima (`docs/accuracy.md`: 10^5 fresh random points per
//! function and type plus a longer hill-climb from the worst of them,
//! `BRDF_ORACLE_DEEP=1 BRDF_ORACLE_RECORD=1 cargo test -p brdf-oracle --release --test
//! accuracy_table -- --nocapture`); every ordinary run (`cargo test -p brdf-oracle --release
//! -- --nocapture`: fresh points, seed printed, and the committed hardest inputs in
//! `oracle/hardest.txt`) holds each function within 0.7 ULP on every lane type.
//!
//! D squares its denominator t = sin^2 + cos^2 alpha^2, so a plain evaluation counts t's
//! rounding twice (5.6 ULP); it is carried to twice the working precision instead (Dekker's
//! two-product and Knuth's two-sum, about 150 extra flops; the isotropic [`d`] on `f32` and
//! `f32x8` is evaluated in f64 instead, where the plain formula's roundings are 2^-29 of an
//! f32 ULP, and rounded once), as are the separable G2's two G1
//! (about 120 extra flops), and both are rounded once. The Smith terms (Lambda, G1, the
//! correlated G2 and V) likewise: a plain evaluation of sqrt(c^2 + alpha^2 sin^2) and the
//! products around it reaches 4.5 ULP (Lambda, f32) to 5.7 ULP (`Ggx::v_correlated`, f64),
//! so q = alpha^2 sin^2, the square root and the outer products are double words and the
//! result is one division with its remainder recovered (about 10x the run time of the plain
//! form: 95-260 ns against 6-27 ns per call on one core, like `d`'s 75-140 ns; the `_fast`
//! companions keep the plain speed). The outer cosines are scaled by a power of two first, so
//! a subnormal cosine (exact as given) never meets a subnormal product.
//!
//! [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual

use crate::domain::{above, nan_unless, nan_where, unit_if_inf};
use crate::dw::{Dw, Rel, two_prod, two_sum};
use crate::error::ParamError;
use crate::microfacet::{Microfacet, clamp_alpha, validate_alphas};
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

/// sin^2 = (1 - c)(1 + c) for c in [0, 1] to twice the working precision: both factors
/// exact by [`two_sum`], their product by [`Dw::mul`].
#[inline]
fn sin2_dw<T: Real>(c: T) -> Dw<T> {
    let (d, dl) = two_sum(T::ONE, -c);
    let (p, pl) = two_sum(T::ONE, c);
    Dw { hi: d, lo: dl }.mul(Dw { hi: p, lo: pl })
}

/// The power of two S by which the Smith forms scale an exact outer cosine, and 1 / S
/// (2^60 in f32, 2^500 in f64): S c of the smallest subnormal c is a normal number whose
/// products with the square roots below (>= ALPHA_MIN sin or c) keep exact two-products;
/// S q <= S ALPHA_MAX^2 cannot overflow, nor can G2's numerator (2 S c_o)(S c_i) <= 2 S^2.
#[inline]
fn cos_scale<T: Real>() -> (T, T) {
    let (s, inv) = if crate::dw::single::<T>() {
        (1.152_921_504_606_847e18, 8.673_617_379_884_035e-19)
    } else {
        (3.273_390_607_896_142e150, 3.054_936_363_499_605e-151)
    };
    (T::splat(s), T::splat(inv))
}

/// n / d rounded once for double words n, d with d.hi > 0: the quotient's own rounding
/// recovered from the exact remainder n.hi - q d.hi (one more division), so the result is
/// within 0.5 ULP plus second-order terms. An infinite or NaN quotient is returned as is.
#[inline]
fn quot<T: Real>(n: Dw<T>, d: Dw<T>) -> T {
    let q = n.hi / d.hi;
    let (p, e) = two_prod(q, d.hi);
    let corr = (((n.hi - p) - e) + (n.lo - q * d.lo)) / d.hi;
    T::select(q.is_finite(), q + corr, q)
}

/// The Smith forms of the isotropic GGX at |cos| c and q = alpha^2 sin^2 (a double word):
/// the square root s = sqrt(c^2 + q) = c (1 + 2 Lambda), to twice the working precision.
#[inline]
fn root_dw<T: Real>(c: T, q: Dw<T>) -> Dw<T> {
    q.add(Dw::square(c)).sqrt()
}

/// q = alpha^2 (1 - c)(1 + c) to twice the working precision.
#[inline]
fn q_iso<T: Real>(c: T, a: T) -> Dw<T> {
    Dw::square(a).mul(sin2_dw(c))
}

/// Lambda = q / (2 c (s + c)) for c = |cos| and the double words q and s = sqrt(c^2 + q)
/// ([`root_dw`]), rounded once. Numerator and denominator are scaled by S ([`cos_scale`]):
/// a subnormal c (exact as given) then never meets a subnormal product. The pole q / 0 is
/// capped at MAX; NaN propagates.
#[inline]
fn lambda_dw<T: Real>(c: T, q: Dw<T>, s: Dw<T>) -> T {
    let (sc, _) = cos_scale::<T>();
    let den = s.add_t(c).mul(Dw::exact(T::TWO * (sc * c)));
    quot(q.scale(sc), den).min(T::MAX)
}

/// S (c_l s_v + c_v s_l), the denominator of the height-correlated G2 and V scaled by S
/// ([`cos_scale`]), with s = sqrt(c^2 + q) of each direction: 1 + Lambda_v + Lambda_l =
/// (s_v / c_v + s_l / c_l) / 2, so G2 = 2 c_v c_l / (c_l s_v + c_v s_l) and
/// V = G2 / (4 c_v c_l) = 0.5 / (c_l s_v + c_v s_l), both free of Lambda's pole.
#[inline]
fn correlated_den<T: Real>(cv: T, sv: Dw<T>, cl: T, sl: Dw<T>) -> Dw<T> {
    let (sc, _) = cos_scale::<T>();
    sv.mul(Dw::exact(sc * cl)).add(sl.mul(Dw::exact(sc * cv)))
}

/// V = 0.5 S / den for den = [`correlated_den`], rounded once: 0 where den is 0 (both cosines
/// 0), capped at MAX.
#[inline]
fn v_from_den<T: Real>(den: Dw<T>) -> T {
    let half_s = Dw::exact(T::HALF * cos_scale::<T>().0);
    let ok = den.hi.simd_gt(T::ZERO);
    let safe = Dw::select(ok, den, Dw::exact(T::ONE));
    T::select(ok, quot(half_s, safe).min(T::MAX), T::ZERO)
}

/// The GGX (Trowbridge-Reitz) distribution with width alpha_x along the local x axis and alpha_y
/// along y (alpha, not perceptual roughness: alpha = r^2, see [`alpha_from_perceptual`]).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ggx<T> {
    alpha_x: T,
    alpha_y: T,
}

impl<T: Real> Ggx<T> {
    /// An anisotropic GGX from the widths alpha_x, alpha_y (for a material's perceptual roughness
    /// r, alpha = r^2: [`alpha_from_perceptual`]). Both alphas must be finite and >= 0 in every
    /// lane, else [`ParamError`]; values below [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN)
    /// (including 0) are stored as given and clamped when evaluated.
    ///
    /// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
    pub fn new(alpha_x: T, alpha_y: T) -> Result<Self, ParamError> {
        validate_alphas(alpha_x, alpha_y)?;
        Ok(Self { alpha_x, alpha_y })
    }

    /// The crate's own constructor for free functions that take alpha unvalidated: evaluation
    /// maps an out-of-domain alpha to NaN, so nothing here can skip the domain rule.
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

    /// An isotropic GGX, `alpha_x = alpha_y = alpha` (the width, not perceptual roughness:
    /// `Ggx::isotropic(alpha_from_perceptual(r))` for a slider value r); same validation as
    /// [`Ggx::new`].
    pub fn isotropic(alpha: T) -> Result<Self, ParamError> {
        Self::new(alpha, alpha)
    }

    /// Both alphas clamped to [ALPHA_MIN, ALPHA_MAX] (NaN where out of domain, which only
    /// the crate's unchecked constructor can store).
    #[inline]
    pub(crate) fn clamped_alphas(&self) -> (T, T) {
        (clamp_alpha(self.alpha_x), clamp_alpha(self.alpha_y))
    }

    /// G1 of `w` = 2 |z| / (|z| + sqrt(z^2 + q)) carried to twice the working precision:
    /// q's three roundings and the square root's would otherwise add up to 2 ULP, and the
    /// separable G2 multiplies two of them.
    #[inline]
    fn g1_dw(&self, w: V3<T>) -> Rel<T> {
        // A zero vector takes the horizon's G1, 0, instead of 0 / 0.
        let w = crate::vec3::horizon_if_zero3(w);
        let (ax, ay) = self.clamped_alphas();
        let c = Rel::exact(w.z.abs());
        let px = Rel::exact(ax).mul(Rel::exact(w.x));
        let py = Rel::exact(ay).mul(Rel::exact(w.y));
        let s = px.mul(px).add(py.mul(py)).add(c.mul(c)).sqrt();
        // 0 at the horizon (2 |z| = 0 over alpha sin > 0).
        Rel::exact(T::TWO * c.hi).div(c.add(s))
    }

    /// `alpha_x^2 x^2 + alpha_y^2 y^2` = alpha^2 tan^2(theta) cos^2(theta) of `w`.
    #[inline]
    fn projected_roughness2(&self, w: V3<T>) -> T {
        let (ax, ay) = self.clamped_alphas();
        (ax * w.x).mul_add(ax * w.x, (ay * w.y) * (ay * w.y))
    }

    /// |z|, q = alpha_x^2 x^2 + alpha_y^2 y^2 and s = sqrt(z^2 + q) of `w`, q and s to twice
    /// the working precision (Dekker's exact products).
    #[inline]
    fn smith_dw(&self, w: V3<T>) -> (T, Dw<T>, Dw<T>) {
        // A zero vector takes the horizon's values (the capped Lambda pole) instead of 0 / 0.
        let w = crate::vec3::horizon_if_zero3(w);
        let (ax, ay) = self.clamped_alphas();
        let c = w.z.abs();
        let q = Dw::product(ax, w.x).sq().add(Dw::product(ay, w.y).sq());
        (c, q, root_dw(c, q))
    }
}

impl<T: Real> Microfacet<T> for Ggx<T> {
    /// D(m) = 1 / (pi ax ay (x^2/ax^2 + y^2/ay^2 + z^2)^2) for m.z > 0, else 0 (Walter et al.
    /// 2007 eq. 33 in the anisotropic form of Heitz 2014 eq. 85, without tan or cos^4).
    #[inline]
    fn d(&self, m: V3<T>) -> T {
        let (ax, ay) = self.clamped_alphas();
        let u = Rel::exact(m.x).div(Rel::exact(ax));
        let v = Rel::exact(m.y).div(Rel::exact(ay));
        // t carried to twice the precision: its rounding would count twice in t^2.
        let t = u
            .mul(u)
            .add(v.mul(v))
            .add(Rel::exact(m.z).mul(Rel::exact(m.z)));
        let den = Rel::exact(ax)
            .mul(Rel::exact(ay))
            .mul(t.mul(t))
            .mul(Rel::pi());
        // For a unit m, t >= 1 / ALPHA_MAX^2, so t^2 stays normal; the cap only guards a
        // non-unit m.
        let d = Rel::exact(T::ONE).div(den).value().min(T::MAX);
        let value = above(m.z, d);
        nan_where(any_nonfinite3(m) | ax.is_nan() | ay.is_nan(), value)
    }

    /// Lambda(w) = (sqrt(1 + alpha^2 tan^2) - 1) / 2 (Heitz 2014 eq. 86), evaluated as
    /// q / (2 |z| (sqrt(z^2 + q) + |z|)) with q = ax^2 x^2 + ay^2 y^2: no cancellation for
    /// small alpha tan; the pole at the horizon (q / 0) is capped at the largest finite value.
    ///
    /// q and the square root are carried to twice the working precision and the result is
    /// rounded once (module docs).
    #[inline]
    fn lambda(&self, w: V3<T>) -> T {
        let (c, q, s) = self.smith_dw(w);
        lambda_dw(c, q, s)
    }

    /// G1 = 1 / (1 + Lambda) = 2 |z| / (|z| + sqrt(z^2 + q)) with q = ax^2 x^2 + ay^2 y^2
    /// (Walter et al. 2007 eq. 34 on vectors), evaluated to twice the working precision and
    /// rounded once: within 1 ULP. 1 at the normal, 0 at the horizon; NaN for NaN in any
    /// component.
    #[inline]
    fn g1(&self, w: V3<T>) -> T {
        // An infinite component would round the quotient to a plausible 0 (rule 5).
        nan_where(any_nonfinite3(w), self.g1_dw(w).value())
    }

    /// G1(wo) G1(wi), the product formed before the one rounding (see [`Ggx::g1`]).
    #[inline]
    fn g2_separable(&self, wo: V3<T>, wi: V3<T>) -> T {
        let g2 = self.g1_dw(wo).mul(self.g1_dw(wi)).value();
        nan_where(any_nonfinite3(wo) | any_nonfinite3(wi), g2)
    }

    /// G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014 eq. 99), evaluated as
    /// 2 |o.z| |i.z| / (|i.z| s_o + |o.z| s_i) with s = sqrt(z^2 + q), which is the same
    /// quantity without Lambda's pole (1 + 2 Lambda = s / |z|), to twice the working precision
    /// and rounded once. 0 when either direction is at the horizon; NaN for NaN input.
    #[inline]
    fn g2_correlated(&self, wo: V3<T>, wi: V3<T>) -> T {
        let (co, _, so) = self.smith_dw(wo);
        let (ci, _, si) = self.smith_dw(wi);
        let den = correlated_den(co, so, ci, si);
        // S G2 = (2 S c_o)(S c_i) / (S den), then scaled back (exact while G2 is normal):
        // with S c_o alone, 2 S c_o c_i is subnormal for cosines where G2 is not.
        let (sc, inv_sc) = cos_scale::<T>();
        let num = Dw::product(T::TWO * (sc * co), sc * ci);
        let ok = den.hi.simd_gt(T::ZERO);
        let g2 = quot(num, Dw::select(ok, den, Dw::exact(T::ONE))) * inv_sc;
        let g2 = T::select(ok, g2.min(T::ONE), T::ZERO);
        nan_where(
            any_nonfinite3(wo) | any_nonfinite3(wi) | den.hi.is_nan(),
            g2,
        )
    }

    /// V = G2 / (4 |o.z| |i.z|) = 0.5 / (|i.z| s_o + |o.z| s_i) with s = sqrt(z^2 + q)
    /// (see [`Ggx::g2_correlated`]), to twice the working precision and rounded once. Edges
    /// as the trait's: 0 when both cosines are 0, capped at MAX, NaN for NaN input.
    #[inline]
    fn v_correlated(&self, wo: V3<T>, wi: V3<T>) -> T {
        let (co, _, so) = self.smith_dw(wo);
        let (ci, _, si) = self.smith_dw(wi);
        let den = correlated_den(co, so, ci, si);
        nan_where(
            any_nonfinite3(wo) | any_nonfinite3(wi) | den.hi.is_nan(),
            v_from_den(den),
        )
    }

    /// |z| Lambda = q / (2 (sqrt(z^2 + q) + |z|)): alpha sin(theta) / 2 at the horizon.
    #[inline]
    fn cos_lambda(&self, w: V3<T>) -> T {
        // A zero vector takes the horizon's value instead of 0 / 0.
        let w = crate::vec3::horizon_if_zero3(w);
        let c = w.z.abs();
        let q = self.projected_roughness2(w);
        nan_where(
            any_nonfinite3(w),
            q / (T::TWO * (c.mul_add(c, q).sqrt() + c)),
        )
    }
}

/// Isotropic GGX NDF of the cosine between normal and half vector:
/// D = alpha^2 / (pi ((1 - c)(1 + c) + c^2 alpha^2)^2) for c = n_dot_h in (0, 1], 0 for
/// c <= 0 (Walter et al. 2007 eq. 33; the denominator is the cancellation-free rewrite of
/// (1 + c^2 (alpha^2 - 1))^2). D(1) = 1 / (pi alpha^2), the peak for alpha <= 1 (for
/// alpha > 1 the largest value is alpha^2 / pi, toward c = 0). Domain: n_dot_h in [-1, 1]
/// (above 1 clamped to 1), alpha in [0, +inf) finite, clamped to [ALPHA_MIN, ALPHA_MAX]; NaN
/// for NaN input, alpha < 0 or +inf. Correctly rounded to within 0.5 ULP (module docs), the
/// result rounded once: on `f64` and `f64x4` every rounding is recovered by error-free
/// transformations (double words, about 150 extra flops); on `f32` and `f32x8` the plain
/// formula is evaluated in f64 (`f32x8` as two `f64x4` halves, lane for lane the scalar
/// operations), where c^2 and alpha^2 are exact and t = (1 - c^2) + c^2 alpha^2, t^2 and the
/// one division carry six roundings of 2^-53 in all, below 2^-26 of an f32 ULP (D is never below
/// 3e-9, so no result is subnormal). Run time on `f32x8` (native build, one core of an AMD
/// EPYC (Zen 4), 10^6 uniform cosines through [`crate::batch::run_f32`], CPU time): 0.38 ms,
/// 2.1x [`d_fast`] and 0.56x Mitsuba 3's `eval` on the same batch (`bench/mitsuba/compare.py
/// --n 1000000`, its README's table).
///
/// `alpha` is the GGX width, not perceptual roughness: alpha = r^2 for a material's roughness r
/// ([`alpha_from_perceptual`]). Filament's `D_GGX(roughness, NoH)` takes this same alpha as
/// `roughness`; Unreal Engine 4's `D_GGX(a2, NoH)` takes a2 = alpha^2. Mind the argument
/// order when porting: both engines pass the roughness first, this function takes the cosine
/// first (every kernel here lists cosines before parameters), and both arguments have the
/// same type, so a swapped call compiles.
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn d<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a = clamp_alpha(alpha);
    let c = n_dot_h.min(T::ONE);
    let d = T::via_f64([c, a], DIso, crate::real::sealed::Token::NEW);
    nan_where(a.is_nan(), above(n_dot_h, d))
}

/// The isotropic D of [`d`] for c = min(n_dot_h, 1) and the clamped alpha (c <= 0 is replaced
/// by the caller): double words in f64 and f64x4, one f64 evaluation rounded once in f32 and
/// f32x8.
#[derive(Clone, Copy)]
struct DIso;

impl crate::real::sealed::Widened<2> for DIso {
    /// D >= 1 / (pi max(1, alpha^2)) >= 3e-9: never below f32's smallest normal number.
    const TINY: bool = false;

    #[inline]
    fn native<T: Real>(self, [c, a]: [T; 2]) -> T {
        // Every rounding recovered (Dekker products, Knuth sums): the denominator's t is
        // squared, so a plain evaluation counts its rounding twice.
        let a2 = Rel::exact(a).mul(Rel::exact(a));
        let t = Rel::one_minus_sq(c).add(Rel::exact(c).mul(Rel::exact(c)).mul(a2));
        a2.div(t.mul(t).mul(Rel::pi())).value()
    }

    #[inline]
    fn wide<W: Real<Scalar = f64>>(self, [c, a]: [W; 2]) -> W {
        // c^2 and alpha^2 are exact (48 significant bits); 1 - c^2, t = (1 - c^2) + c^2 alpha^2
        // (a sum of non-negative terms), t^2 and the quotient round once each (pi and its
        // product once more): within 6 units of 2^-53 of D, which then rounds to f32 once.
        let c2 = c * c;
        let a2 = a * a;
        let t = c2.mul_add(a2, W::ONE - c2);
        (a2 * W::splat(core::f64::consts::FRAC_1_PI)) / (t * t)
    }
}

/// Isotropic GGX NDF in working precision, the fast companion of [`d`]: the same
/// D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), evaluated as real-time engines do
/// (Filament's `D_GGX`, Guy and Agopian 2018, "Physically Based Rendering in Filament"):
/// k = alpha / ((1 - c)(1 + c) + (c alpha)^2), D = k^2 / pi, for c = n_dot_h in (0, 1], 0 for
/// c <= 0 (Walter et al. 2007 eq. 33). sin^2 is 1 - c^2 in one fused multiply-add on targets
/// with FMA, otherwise 1 - c c below c = 1/2 (nothing cancels there) and the product
/// (1 - c)(1 + c) above, so the denominator does not cancel near c = 1 (where 1 - c c with
/// two roundings keeps no digit of alpha^2 for alpha below about 2^-12 in f32).
///
/// Domain, edges and bad input exactly as [`d`]: n_dot_h in [-1, 1] (above 1 clamped to 1),
/// alpha in [0, +inf) finite, clamped to [ALPHA_MIN, ALPHA_MAX] (the width, not perceptual
/// roughness); D(1) = 1 / (pi alpha^2), the peak for alpha <= 1; NaN for NaN input,
/// alpha < 0 or +inf; the result is capped at the largest finite value (never reached:
/// D <= max(1 / (pi ALPHA_MIN^2), ALPHA_MAX^2 / pi) = 3.2e7).
///
/// Accuracy: about ten flops and one division in working precision, against about 150 extra
/// flops for [`d`]'s single rounding. Max error against [`d`] over cosines from 0 through 1e-7
/// to 1 and alpha over [ALPHA_MIN, ALPHA_MAX] (65 000 points per type): 7 ULP, relative
/// 5.3e-7 (f32); 8 ULP, relative 9.1e-16 (f64); the same on f32x8 and f64x4, whose lanes equal
/// the scalar results bit for bit (`cargo test --all-features --test kernels fast_variants:: --
/// --nocapture`, default x86-64 build).
#[inline]
#[must_use]
pub fn d_fast<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a = clamp_alpha(alpha);
    let c = n_dot_h.min(T::ONE);
    let ca = c * a;
    let s2 = crate::microfacet::sin2_working(c);
    let k = a / ca.mul_add(ca, s2);
    let d = (k * k * T::FRAC_1_PI).min(T::MAX);
    nan_where(a.is_nan(), above(n_dot_h, d))
}

/// Anisotropic GGX NDF from the half vector's components in the shading frame:
/// D = 1 / (pi ax ay ((t.h/ax)^2 + (b.h/ay)^2 + (n.h)^2)^2), 0 for n_dot_h <= 0 (Heitz 2014
/// eq. 85; Burley 2012). `t_dot_h`, `b_dot_h`: the half vector against tangent and bitangent;
/// `alpha_x`, `alpha_y`: the widths along them, each an alpha as in [`d`] (not perceptual
/// roughness). Domain: components of a unit vector; alphas as [`d`]; NaN for NaN in any input.
/// The three are cosines: +-inf counts as +-1 (crate docs, "Bad input", rules 3 and 5).
#[inline]
#[must_use]
pub fn d_aniso<T: Real>(n_dot_h: T, t_dot_h: T, b_dot_h: T, alpha_x: T, alpha_y: T) -> T {
    // As cosines, before `Ggx::d` reads them as a direction (where an infinity is NaN).
    let m = V3::new(
        unit_if_inf(t_dot_h),
        unit_if_inf(b_dot_h),
        unit_if_inf(n_dot_h),
    );
    Ggx::new_unchecked(alpha_x, alpha_y).d(m)
}

/// Smith Lambda of the isotropic GGX for a direction at cosine `n_dot_v`:
/// Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2, evaluated without cancellation as
/// q / (2 c (sqrt(c^2 + q) + c)), q = alpha^2 (1 - c)(1 + c) (Heitz 2014 eq. 86).
/// |n_dot_v| is used (Lambda is symmetric) and clamped to 1; the pole at c = 0 is capped at
/// the largest finite value. alpha as [`d`] (the width, = perceptual roughness^2 via
/// [`alpha_from_perceptual`]); NaN for NaN input. Within 0.5 ULP on every lane type (q and the
/// square root carried as double words, one rounding at the end), subnormal cosines included
/// (module docs).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn lambda<T: Real>(n_dot_v: T, alpha: T) -> T {
    let c = n_dot_v.abs().min(T::ONE);
    let q = q_iso(c, clamp_alpha(alpha));
    lambda_dw(c, q, root_dw(c, q))
}

/// Smith masking G1 = 1 / (1 + Lambda) = 2c / (c + sqrt(c^2 + alpha^2 (1 - c^2))) of the isotropic
/// GGX (Walter et al. 2007 eq. 34). 1 at c = 1, 0 at c = 0; uses |n_dot_v| clamped to 1; alpha as
/// [`d`] (the width, = perceptual roughness^2 via [`alpha_from_perceptual`]); NaN for NaN input.
/// Within 0.5 ULP on every lane type (double words, one rounding; module docs).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn g1<T: Real>(n_dot_v: T, alpha: T) -> T {
    let c = n_dot_v.abs().min(T::ONE);
    let q = q_iso(c, clamp_alpha(alpha));
    // At c = 0 this is 0 / alpha = 0, never 0 / 0 (alpha >= ALPHA_MIN).
    quot(Dw::exact(T::TWO * c), root_dw(c, q).add_t(c))
}

/// Height-correlated Smith visibility of the isotropic GGX,
/// V = G2 / (4 NoL NoV) = 0.5 / (NoL sqrt(NoV^2 + alpha^2 (1 - NoV^2)) + NoV sqrt(NoL^2 +
/// alpha^2 (1 - NoL^2))) (Heitz 2014 eq. 99 with eq. 86; the form of Lagarde and de Rousiers
/// 2014, "Moving Frostbite to PBR", with the cancellation-free 1 - c^2).
///
/// `alpha` is the width of [`d`], not perceptual roughness (alpha = r^2:
/// [`alpha_from_perceptual`]). Filament's `V_SmithGGXCorrelated(roughness, NoV, NoL)` takes this
/// alpha as `roughness`; Unreal Engine 4's `Vis_SmithJoint(a2, NoV, NoL)` takes a2 = alpha^2.
///
/// Cosines in [-1, 1], clamped to [0, 1]; alpha as [`d`]. Finite when either cosine is
/// positive (at NoL = 0 it is 0.5 / (NoV alpha)); 0 when both are 0; capped at the largest
/// finite value; NaN for NaN input. Within 0.5 ULP on every lane type, cosines down to
/// subnormals included. On `f64` and `f64x4` both square roots and the outer products are
/// double words, the outer cosines are scaled by a power of two first, and the quotient is
/// rounded once (module docs); Filament's plain form reaches 3.6 ULP (f32) at a fifth of
/// that run time. On `f32` and `f32x8` the plain form is evaluated in f64 (`f32x8` as two
/// `f64x4` halves, lane for lane the scalar operations) and rounded to f32 once: about ten
/// roundings of 2^-53, two square roots and one division.
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn v_correlated<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let a = clamp_alpha(alpha);
    let v = T::via_f64([cv, cl, a], VIso, crate::real::sealed::Token::NEW);
    nan_where(n_dot_v.is_nan() | n_dot_l.is_nan() | a.is_nan(), v)
}

/// The height-correlated V of [`v_correlated`] for the saturated cosines and the clamped
/// alpha: double words in f64 and f64x4, one f64 evaluation rounded once in f32 and f32x8.
#[derive(Clone, Copy)]
struct VIso;

impl crate::real::sealed::Widened<3> for VIso {
    /// V >= 0.5 / (2 max(1, ALPHA_MAX)) = 2.5e-5 where it is not 0.
    const TINY: bool = false;

    #[inline]
    fn native<T: Real>(self, [cv, cl, a]: [T; 3]) -> T {
        // Both outer cosines are scaled by the power of two S (exact; [`cos_scale`]): at
        // cosines near the smallest normal the products NoL sqrt(...) would be subnormal and
        // lose bits; 0.5 S / (S den) is the same quotient.
        let den = correlated_den(cv, root_dw(cv, q_iso(cv, a)), cl, root_dw(cl, q_iso(cl, a)));
        v_from_den(den)
    }

    #[inline]
    fn wide<W: Real<Scalar = f64>>(self, [cv, cl, a]: [W; 3]) -> W {
        // The squares of the f32 cosines and alpha are exact; each root's argument
        // c^2 + alpha^2 (1 - c^2) rounds at most three times, the root, the two outer
        // products, their sum and the quotient once each: about ten roundings of 2^-53 in
        // all. Subnormal f32 cosines have squares far inside f64's normal range; the result,
        // capped at f32's largest finite value, then rounds to f32 once.
        let a2 = a * a;
        let root = |c: W| {
            let c2 = c * c;
            a2.mul_add(W::ONE - c2, c2).sqrt()
        };
        let den = cl.mul_add(root(cv), cv * root(cl));
        let v = (W::HALF / den).min(W::splat(f64::from(f32::MAX)));
        W::select(den.simd_gt(W::ZERO), v, W::ZERO)
    }
}

/// D(n_dot_h) V(n_dot_v, n_dot_l) of the isotropic GGX, [`d`] times [`v_correlated`] (the
/// specular term of a Cook-Torrance BRDF before F): on `f64` and `f64x4` that product; on
/// `f32` and `f32x8` both in f64 with one division, alpha^2 / (2 pi t^2 den) (t and den as in
/// [`d`] and [`v_correlated`]), capped at f32's largest finite value and rounded once, so
/// within 0.5 ULP of the exact product plus about twenty roundings of 2^-53. Edges and bad
/// input as the product's: 0 where n_dot_h <= 0 or both other cosines are 0, NaN for NaN in
/// any input or an alpha out of its domain.
#[cfg(feature = "cook-torrance")]
#[inline]
#[must_use]
pub(crate) fn dv<T: Real>(n_dot_h: T, n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let a = clamp_alpha(alpha);
    let (ch, cv, cl) = (n_dot_h.min(T::ONE), n_dot_v.saturate(), n_dot_l.saturate());
    let x = [ch, cv, cl, a];
    let value = T::via_f64(x, DvIso, crate::real::sealed::Token::NEW);
    let nan = n_dot_h.is_nan() | n_dot_v.is_nan() | n_dot_l.is_nan() | a.is_nan();
    nan_where(nan, value)
}

/// D V of [`dv`] for min(n_dot_h, 1), the saturated cosines and the clamped alpha.
#[cfg(feature = "cook-torrance")]
#[derive(Clone, Copy)]
struct DvIso;

#[cfg(feature = "cook-torrance")]
impl crate::real::sealed::Widened<4> for DvIso {
    /// D V >= 3e-9 2.5e-5 where it is not 0.
    const TINY: bool = false;

    #[inline]
    fn native<T: Real>(self, [ch, cv, cl, a]: [T; 4]) -> T {
        above(ch, DIso.native([ch, a])) * VIso.native([cv, cl, a])
    }

    #[inline]
    fn wide<W: Real<Scalar = f64>>(self, [ch, cv, cl, a]: [W; 4]) -> W {
        // `DIso::wide` and `VIso::wide` with their two divisions merged into one.
        let a2 = a * a;
        let ch2 = ch * ch;
        let t = ch2.mul_add(a2, W::ONE - ch2);
        let root = |c: W| {
            let c2 = c * c;
            a2.mul_add(W::ONE - c2, c2).sqrt()
        };
        let den = cl.mul_add(root(cv), cv * root(cl));
        let value = ((a2 * W::splat(0.5 * core::f64::consts::FRAC_1_PI)) / ((t * t) * den))
            .min(W::splat(f64::from(f32::MAX)));
        W::select(ch.simd_gt(W::ZERO) & den.simd_gt(W::ZERO), value, W::ZERO)
    }
}

/// `0.5 / den` for den > 0 (capped at MAX), 0 for den <= 0: the shared guard of every V form;
/// NaN where either cosine or the parameter is NaN (the select alone would turn them into 0).
#[inline]
fn guarded_half_over<T: Real>(den: T, n_dot_v: T, n_dot_l: T, param: T) -> T {
    let v = T::select(den.simd_gt(T::ZERO), (T::HALF / den).min(T::MAX), T::ZERO);
    nan_where(n_dot_v.is_nan() | n_dot_l.is_nan() | param.is_nan(), v)
}

/// Hammon's fast approximation of the height-correlated visibility:
/// V = 0.5 / lerp(2 NoL NoV, NoL + NoV, alpha) (Hammon 2017, "PBR Diffuse Lighting for
/// GGX+Smith Microsurfaces", GDC). Approximation: max relative error 0.29 against
/// [`v_correlated`] for alpha and cosines in [0.01, 1], worst at alpha = 0.01 with both
/// cosines 0.01 (`cargo test --test microfacet smith_approximations:: -- --nocapture`). Cosines
/// clamped to [0, 1]; 0 when both are 0; alpha as [`d`] (the width r^2, not perceptual roughness);
/// NaN for NaN input.
#[inline]
#[must_use]
pub fn v_correlated_hammon<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let a = clamp_alpha(alpha);
    let two_lv = T::TWO * cl * cv;
    guarded_half_over(two_lv + a * (cl + cv - two_lv), n_dot_v, n_dot_l, a)
}

/// Filament's fast visibility: the square roots of [`v_correlated`] replaced by their linear
/// interpolation in alpha, V = 0.5 / (NoL (NoV (1 - alpha) + alpha) + NoV (NoL (1 - alpha) +
/// alpha)) (Google Filament, "Physically Based Rendering in Filament", section 4.4.2.1,
/// `V_SmithGGXCorrelated_Fast`). Expanded, its denominator is 2 NoL NoV (1 - alpha) +
/// alpha (NoL + NoV): algebraically identical to [`v_correlated_hammon`] (same 0.29 maximum
/// relative error), evaluated in a different order. Cosines clamped to [0, 1]; alpha as [`d`]
/// (Filament's `roughness` argument: the width r^2, not perceptual roughness); NaN for NaN
/// input.
#[inline]
#[must_use]
pub fn v_correlated_fast<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let a = clamp_alpha(alpha);
    let one_minus_a = T::ONE - a;
    let den = cl * cv.mul_add(one_minus_a, a) + cv * cl.mul_add(one_minus_a, a);
    guarded_half_over(den, n_dot_v, n_dot_l, a)
}

/// Schlick's G1 approximation as used for GGX: G1 = c / (c (1 - k) + k) (Schlick 1994, "An
/// Inexpensive BRDF Model for Physically-based Rendering"; Karis 2013), evaluated as
/// c / (c + k (1 - c)), a sum of non-negative terms (the printed form cancels to 0 at c = 1
/// for k above about 2 / EPSILON and returned +inf). Choose k with [`schlick_k_ibl`] or
/// [`schlick_k_analytic`]. Domain k in (0, +inf) finite (k > 1, from alpha > 2, still gives
/// G1 in [0, 1], for every finite k); k <= 0, NaN or +inf gives NaN; cosine clamped to
/// [0, 1]; 0 at c = 0, 1 at c = 1; NaN for NaN input. With k = alpha / 2 its max abs error
/// against [`g1`] is 0.16 (alpha = 0.01, NoV = 0.01; alpha and NoV in [0.01, 1]).
///
/// k is neither alpha nor perceptual roughness: [`schlick_k_ibl`] takes alpha (k = alpha / 2),
/// [`schlick_k_analytic`] takes the perceptual roughness r (k = (r + 1)^2 / 8).
#[inline]
#[must_use]
pub fn g1_schlick<T: Real>(n_dot_v: T, k: T) -> T {
    let c = n_dot_v.saturate();
    // den = c + k (1 - c) >= min(k, 1) > 0 for c in [0, 1]: no division by zero, and a sum
    // of non-negative terms. The textbook c (1 - k) + k cancels for k > 1 near c = 1: at
    // c = 1 and k above about 2 / EPSILON it is 0 and G1 = 1 / 0 = +inf.
    let den = k.mul_add(T::ONE - c, c);
    nan_unless(k_ok(k), c / den)
}

/// True where a Schlick k lies in its domain (0, +inf) (false for NaN).
#[inline]
fn k_ok<T: Real>(k: T) -> T::Mask {
    k.simd_gt(T::ZERO) & k.simd_lt(T::INFINITY)
}

/// k = alpha / 2: Schlick-GGX matched to Smith-GGX (Karis 2013, "Real Shading in Unreal Engine 4",
/// used for image-based lighting). alpha as [`d`] (clamped, NaN outside its domain), so k is in
/// [5e-5, 5e3]. alpha is the width, not perceptual roughness: Karis's k = alpha / 2 has
/// alpha = Roughness^2 of Unreal Engine 4's `Roughness` slider ([`alpha_from_perceptual`]).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn schlick_k_ibl<T: Real>(alpha: T) -> T {
    clamp_alpha(alpha) * T::HALF
}

/// k = (r + 1)^2 / 8 from perceptual roughness r: Karis 2013's remapping for analytic lights ("Real
/// Shading in Unreal Engine 4"; it reduces the hotness of rough surfaces at grazing angles, and is
/// not an approximation of Smith-GGX). r is the perceptual roughness itself (Unreal Engine 4's
/// `Roughness`, glTF's `roughnessFactor`), not alpha = r^2: unlike every other function here.
/// Domain r in [0, +inf) finite, clamped to sqrt(ALPHA_MAX) = 100; r < 0, NaN or +inf gives NaN.
#[inline]
#[must_use]
pub fn schlick_k_analytic<T: Real>(perceptual_roughness: T) -> T {
    let ok = perceptual_roughness.simd_ge(T::ZERO) & perceptual_roughness.simd_lt(T::INFINITY);
    // r = sqrt(ALPHA_MAX) = 100 is the roughness of the largest alpha; the clamp keeps
    // (r + 1)^2 finite.
    let r = perceptual_roughness.min(T::splat(100.0));
    let r1 = r + T::ONE;
    nan_unless(ok, r1 * r1 * T::splat(0.125))
}

/// Separable Schlick-GGX visibility V = G1(v) G1(l) / (4 NoV NoL)
/// = 1 / (4 (NoV (1 - k) + k)(NoL (1 - k) + k)): the NoV NoL cancel analytically, so it never
/// divides by zero for k > 0. Each factor is evaluated as c + k (1 - c), as in
/// [`g1_schlick`], so a large k does not cancel it to 0 at c = 1. Cosines clamped to [0, 1]; k as [`g1_schlick`]; capped at the
/// largest finite value; NaN for NaN input. With k = alpha / 2 its relative error
/// against [`v_correlated`] reaches -0.97 (it returns 3% of the exact value at alpha = 1 with
/// both cosines 0.01), like every separable G2.
/// k from [`schlick_k_ibl`] (alpha) or [`schlick_k_analytic`] (perceptual roughness).
#[inline]
#[must_use]
pub fn v_schlick<T: Real>(n_dot_v: T, n_dot_l: T, k: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    // c + k (1 - c), not c (1 - k) + k: a sum of non-negative terms (see [`g1_schlick`]).
    let den = T::splat(4.0) * k.mul_add(T::ONE - cv, cv) * k.mul_add(T::ONE - cl, cl);
    let v = T::select(den.simd_gt(T::ZERO), den.recip().min(T::MAX), T::ZERO);
    nan_unless(k_ok(k), nan_where(n_dot_v.is_nan() | n_dot_l.is_nan(), v))
}
