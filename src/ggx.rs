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
//! | `lambda` | 3.11 | 2.90 | 3.11 | 2.90 |
//! | `Ggx::lambda` | 3.04 | 3.76 | 3.04 | 3.76 |
//! | `g1` | 1.75 | 2.09 | 1.75 | 2.09 |
//! | `v_correlated` | 2.49 | 3.65 | 2.49 | 3.65 |
//! | `Ggx::g2_correlated` | 3.18 | 3.92 | 3.18 | 3.92 |
//! | `Ggx::g2_separable` | 0.50 | 0.50 | 0.50 | 0.50 |
//! | `Ggx::v_correlated` | 2.98 | 3.56 | 2.98 | 3.56 |
//!
//! D squares its denominator t = sin^2 + cos^2 alpha^2, so a plain evaluation counts t's
//! rounding twice (5.6 ULP); it is carried to twice the working precision instead (Dekker's
//! two-product and Knuth's two-sum, about 150 extra flops), as are the separable G2's two G1
//! (about 120 extra flops), and both are rounded once. Lambda divides by 2 cos last, so a
//! subnormal cosine (exact as given) never meets a subnormal product.
//!
//! [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual

use crate::domain::{above, any_nan3, nan_unless, nan_where};
use crate::dw::Rel;
use crate::error::ParamError;
use crate::microfacet::{Microfacet, clamp_alpha, validate_alphas};
use crate::real::Real;
use crate::vec3::V3;

/// `(1 - c)(1 + c)` for c in [0, 1]: sin^2 without the cancellation of `1 - c*c`.
#[inline]
fn sin2_from_cos<T: Real>(c: T) -> T {
    (T::ONE - c) * (T::ONE + c)
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
        nan_where(any_nan3(m) | ax.is_nan() | ay.is_nan(), value)
    }

    /// Lambda(w) = (sqrt(1 + alpha^2 tan^2) - 1) / 2 (Heitz 2014 eq. 86), evaluated as
    /// q / (2 |z| (sqrt(z^2 + q) + |z|)) with q = ax^2 x^2 + ay^2 y^2: no cancellation for
    /// small alpha tan; the pole at the horizon (q / 0) is capped at the largest finite value.
    #[inline]
    fn lambda(&self, w: V3<T>) -> T {
        let c = w.z.abs();
        let q = self.projected_roughness2(w);
        lambda_of(c, q)
    }

    /// G1 = 1 / (1 + Lambda) = 2 |z| / (|z| + sqrt(z^2 + q)) with q = ax^2 x^2 + ay^2 y^2
    /// (Walter et al. 2007 eq. 34 on vectors), evaluated to twice the working precision and
    /// rounded once: within 1 ULP. 1 at the normal, 0 at the horizon; NaN for NaN in any
    /// component.
    #[inline]
    fn g1(&self, w: V3<T>) -> T {
        self.g1_dw(w).value()
    }

    /// G1(wo) G1(wi), the product formed before the one rounding (see [`Ggx::g1`]).
    #[inline]
    fn g2_separable(&self, wo: V3<T>, wi: V3<T>) -> T {
        self.g1_dw(wo).mul(self.g1_dw(wi)).value()
    }

    /// |z| Lambda = q / (2 (sqrt(z^2 + q) + |z|)): alpha sin(theta) / 2 at the horizon.
    #[inline]
    fn cos_lambda(&self, w: V3<T>) -> T {
        let c = w.z.abs();
        let q = self.projected_roughness2(w);
        q / (T::TWO * (c.mul_add(c, q).sqrt() + c))
    }
}

/// Isotropic GGX NDF of the cosine between normal and half vector:
/// D = alpha^2 / (pi ((1 - c)(1 + c) + c^2 alpha^2)^2) for c = n_dot_h in (0, 1], 0 for
/// c <= 0 (Walter et al. 2007 eq. 33; the denominator is the cancellation-free rewrite of
/// (1 + c^2 (alpha^2 - 1))^2). D(1) = 1 / (pi alpha^2), the peak for alpha <= 1 (for
/// alpha > 1 the largest value is alpha^2 / pi, toward c = 0). Domain: n_dot_h in [-1, 1]
/// (above 1 clamped to 1), alpha in [0, +inf) finite, clamped to [ALPHA_MIN, ALPHA_MAX]; NaN
/// for NaN input, alpha < 0 or +inf. Correctly rounded to within 0.5 ULP (module docs): every
/// rounding is recovered by error-free transformations and the result rounded once.
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
    // Every rounding recovered (Dekker products, Knuth sums): the denominator's t is squared,
    // so a plain evaluation counts its rounding twice.
    let a2 = Rel::exact(a).mul(Rel::exact(a));
    let t = Rel::one_minus_sq(c).add(Rel::exact(c).mul(Rel::exact(c)).mul(a2));
    let d = a2.div(t.mul(t).mul(Rel::pi())).value();
    nan_where(a.is_nan(), above(n_dot_h, d))
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
/// the scalar results bit for bit (`cargo test --all-features --test fast_variants --
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
#[inline]
#[must_use]
pub fn d_aniso<T: Real>(n_dot_h: T, t_dot_h: T, b_dot_h: T, alpha_x: T, alpha_y: T) -> T {
    Ggx::new_unchecked(alpha_x, alpha_y).d(V3::new(t_dot_h, b_dot_h, n_dot_h))
}

/// Smith Lambda of the isotropic GGX for a direction at cosine `n_dot_v`:
/// Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2, evaluated without cancellation as
/// q / (2 c (sqrt(c^2 + q) + c)), q = alpha^2 (1 - c)(1 + c) (Heitz 2014 eq. 86).
/// |n_dot_v| is used (Lambda is symmetric) and clamped to 1; the pole at c = 0 is capped at
/// the largest finite value. alpha as [`d`] (the width, = perceptual roughness^2 via
/// [`alpha_from_perceptual`]); NaN for NaN input. Within 3.2 ULP (f32) / 2.9 ULP (f64), subnormal
/// cosines included (module docs).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn lambda<T: Real>(n_dot_v: T, alpha: T) -> T {
    let c = n_dot_v.abs().min(T::ONE);
    let a = clamp_alpha(alpha);
    let q = a * a * sin2_from_cos(c);
    lambda_of(c, q)
}

/// Lambda = q / (2 c (sqrt(c^2 + q) + c)) for c = |cos| and q = alpha^2 sin^2, divided in the
/// order (q / (sqrt(c^2 + q) + c)) / (2 c): the first quotient is about alpha sin, a normal
/// number, and the exact 2c (even a subnormal one: 1e-40 in f32, 1e-310 in f64) enters
/// through one correctly rounded division. The product 2 c (sqrt + c) would itself be a
/// subnormal there and lose most of its bits. The pole q / 0 is capped at MAX.
#[inline]
fn lambda_of<T: Real>(c: T, q: T) -> T {
    (q / (c.mul_add(c, q).sqrt() + c) / (T::TWO * c)).min(T::MAX)
}

/// Smith masking G1 = 1 / (1 + Lambda) = 2c / (c + sqrt(c^2 + alpha^2 (1 - c^2))) of the isotropic
/// GGX (Walter et al. 2007 eq. 34). 1 at c = 1, 0 at c = 0; uses |n_dot_v| clamped to 1; alpha as
/// [`d`] (the width, = perceptual roughness^2 via [`alpha_from_perceptual`]); NaN for NaN input.
/// Within 1.8 ULP (f32) / 2.1 ULP (f64).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn g1<T: Real>(n_dot_v: T, alpha: T) -> T {
    let c = n_dot_v.abs().min(T::ONE);
    let a = clamp_alpha(alpha);
    let q = a * a * sin2_from_cos(c);
    // At c = 0 this is 0 / alpha = 0, never 0 / 0 (alpha >= ALPHA_MIN).
    T::TWO * c / (c + c.mul_add(c, q).sqrt())
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
/// finite value; NaN for NaN input. Within 2.5 ULP (f32) / 3.7 ULP (f64), cosines down to
/// subnormals included: both outer cosines are scaled by a power of two first (module
/// docs).
///
/// [`alpha_from_perceptual`]: crate::microfacet::alpha_from_perceptual
#[inline]
#[must_use]
pub fn v_correlated<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let a = clamp_alpha(alpha);
    let a2 = a * a;
    // Both outer cosines scaled by the power of two S (exact): at cosines near the smallest
    // normal (2e-308 in f64) the products NoL sqrt(...) are subnormal and lose bits; scaled,
    // they stay normal, and 0.5 S / (S den) is the same quotient. S = 2^40 (f32), 2^70 (f64)
    // lifts the smallest subnormal cosine times ALPHA_MIN above the smallest normal, and
    // S den <= 2 S ALPHA_MAX cannot overflow.
    let eps: f64 = T::EPSILON.lane(0).into();
    let scale = T::splat(if eps > 1e-10 {
        1_099_511_627_776.0
    } else {
        1.180_591_620_717_411_3e21
    });
    let gv = (scale * cl) * (a2 * sin2_from_cos(cv)).mul_add(T::ONE, cv * cv).sqrt();
    let gl = (scale * cv) * (a2 * sin2_from_cos(cl)).mul_add(T::ONE, cl * cl).sqrt();
    let den = gv + gl;
    let v = T::select(
        den.simd_gt(T::ZERO),
        ((T::HALF * scale) / den).min(T::MAX),
        T::ZERO,
    );
    nan_where(n_dot_v.is_nan() | n_dot_l.is_nan() | a.is_nan(), v)
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
/// cosines 0.01 (`cargo test --test smith_approximations -- --nocapture`). Cosines clamped to
/// [0, 1]; 0 when both are 0; alpha as [`d`] (the width r^2, not perceptual roughness); NaN
/// for NaN input.
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
/// Inexpensive BRDF Model for Physically-based Rendering"; Karis 2013). Choose k with
/// [`schlick_k_ibl`] or [`schlick_k_analytic`]. Domain k in (0, +inf) finite (k > 1, from
/// alpha > 2, still gives G1 in [0, 1]); k <= 0, NaN or +inf gives NaN; cosine clamped to
/// [0, 1]; 0 at c = 0, 1 at c = 1; NaN for NaN input. With k = alpha / 2 its max abs error
/// against [`g1`] is 0.16 (alpha = 0.01, NoV = 0.01; alpha and NoV in [0.01, 1]).
///
/// k is neither alpha nor perceptual roughness: [`schlick_k_ibl`] takes alpha (k = alpha / 2),
/// [`schlick_k_analytic`] takes the perceptual roughness r (k = (r + 1)^2 / 8).
#[inline]
#[must_use]
pub fn g1_schlick<T: Real>(n_dot_v: T, k: T) -> T {
    let c = n_dot_v.saturate();
    // den = k (1 - c) + c >= min(k, 1) > 0 for c in [0, 1]: no division by zero.
    let den = c.mul_add(T::ONE - k, k);
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
/// divides by zero for k > 0. Cosines clamped to [0, 1]; k as [`g1_schlick`]; capped at the
/// largest finite value; NaN for NaN input. With k = alpha / 2 its relative error
/// against [`v_correlated`] reaches -0.97 (it returns 3% of the exact value at alpha = 1 with
/// both cosines 0.01), like every separable G2.
/// k from [`schlick_k_ibl`] (alpha) or [`schlick_k_analytic`] (perceptual roughness).
#[inline]
#[must_use]
pub fn v_schlick<T: Real>(n_dot_v: T, n_dot_l: T, k: T) -> T {
    let (cv, cl) = (n_dot_v.saturate(), n_dot_l.saturate());
    let one_minus_k = T::ONE - k;
    let den = T::splat(4.0) * cv.mul_add(one_minus_k, k) * cl.mul_add(one_minus_k, k);
    let v = T::select(den.simd_gt(T::ZERO), den.recip().min(T::MAX), T::ZERO);
    nan_unless(k_ok(k), nan_where(n_dot_v.is_nan() | n_dot_l.is_nan(), v))
}
