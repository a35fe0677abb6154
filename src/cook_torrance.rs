//! The Cook-Torrance microfacet specular BRDF, f = D(h) G2(wo, wi) F(wo.h) / (4 |n.wo| |n.wi|),
//! evaluated as D V F with the visibility V = G2 / (4 |n.wo| |n.wi|) of
//! [`Microfacet::v_correlated`], so nothing divides by a vanishing cosine.
//!
//! Sources: Cook and Torrance 1982, "A Reflectance Model for Computer Graphics"; Walter,
//! Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through Rough Surfaces",
//! eq. 20 (the 1/4 Jacobian); Heitz 2014, "Understanding the Masking-Shadowing Function",
//! eq. 99 (height-correlated G2).
//!
//! Directions are local-frame unit vectors pointing away from the surface. The BRDF is 0 when
//! either direction is at or below the horizon (reflection only). Energy: with F = 1 the
//! directional albedo is below 1 and falls with roughness, since single scattering drops the
//! light that bounces more than once between microfacets (`tests/cook_torrance/energy.rs`
//! prints the loss).
//!
//! Entry points: [`eval`] and [`eval_rgb`] on directions with any Fresnel closure; the
//! shader-style dot-product forms `ggx` and `beckmann` with a precomputed F; and, for the
//! common full BRDFs, `ggx_conductor_rgb` (a metal from RGB eta and k), `ggx_schlick_rgb`
//! (glTF / Filament: Schlick with an RGB F0) and `ggx_dielectric` (the exact dielectric
//! Fresnel of eta), with the same three for Beckmann (`beckmann_conductor_rgb`, ...).

use crate::domain::{above_horizon, nan_where};
use crate::fresnel;
#[cfg(any(feature = "ggx", feature = "beckmann"))]
use crate::fresnel::ComplexIor;
#[cfg(any(feature = "ggx", feature = "beckmann"))]
use crate::microfacet::Alpha;
use crate::microfacet::Microfacet;
use crate::real::Real;
use crate::shading::Cosines;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

/// The half vector h = normalize(wo + wi) and v.h, with the guard for wo = -wi (h undefined):
/// h falls back to the normal there, which only happens below the horizon, where `eval`
/// returns 0 anyway. A NaN or infinite component of wo or wi gives NaN in h and v.h (crate
/// docs, "Bad input", rules 1 and 5; an infinite sum would normalize to the fallback).
#[inline]
#[must_use]
pub fn half_vector<T: Real>(wo: V3<T>, wi: V3<T>) -> (V3<T>, T) {
    let bad = any_nonfinite3(wo) | any_nonfinite3(wi);
    let h = (wo + wi).normalize_or(V3::unit_z());
    let h = V3::select(bad, V3::splat(T::splat(f64::NAN)), h);
    (h, nan_where(bad, wo.dot(h).saturate()))
}

/// The two cosines of the half vector, n.h and v.h, from unit directions wo and wi, without
/// forming h: with s = wo + wi, |s|^2 = 2 + 2 wo.wi = 4 (v.h)^2, so
///
/// v.h = |s| / 2, n.h = s.z / |s|
///
/// (one square root and one division; [`half_vector`] followed by `h.z` and `wo.dot(h)` costs
/// three more multiplications, a dot product and a clamp). For any lengths, |s| / 2 is the
/// mean of wo.h and wi.h, so the pair is symmetric in wo and wi (reciprocity holds bit for
/// bit), and |s|^2 is summed from the components of s, which carry no cancellation: both
/// cosines stay accurate when wo and wi are nearly opposite, where [`half_vector`]'s wo.h
/// carries wo's length error (its rounding) divided by 1 + wo.wi. Domain: unit vectors.
/// v.h is clamped to 1; where wo = -wi exactly (h undefined) the result is n.h = 1 (as
/// [`half_vector`] falls back to the normal) and v.h = 0 (where [`half_vector`] gives wo.z);
/// a NaN or infinite component gives NaN in both. Within 3 ULP of the same formulas evaluated in
/// f64 from the same f32 directions; within 8 ULP of [`half_vector`]'s cosines where
/// 1 + wo.wi > 0.3, while closer to opposite directions [`half_vector`]'s own error takes
/// over (`cargo test --test cook_torrance rgb::half_cosines -- --nocapture`).
#[inline]
#[must_use]
pub fn half_cosines<T: Real>(wo: V3<T>, wi: V3<T>) -> (T, T) {
    let c = Cosines::from_local(wo, wi);
    (c.n_dot_h, c.v_dot_h)
}

/// D(h) V(wo, wi) capped at MAX (0 where either direction is at or below the horizon, NaN
/// where any component is NaN or infinite) and v.h: the part of the BRDF every Fresnel form multiplies.
///
/// Why the cap: V is itself capped at MAX where both cosines are tiny, and D > 1 would then
/// overflow the product to inf (and inf times a zero Fresnel to NaN).
#[inline]
fn masked_dv<T: Real, M: Microfacet<T> + ?Sized>(m: &M, wo: V3<T>, wi: V3<T>) -> (T, T) {
    let (h, v_dot_h) = half_vector(wo, wi);
    let dv = (m.d(h) * m.v_correlated(wo, wi)).min(T::MAX);
    let dv = above_horizon(wo.z, wi.z, dv);
    (
        nan_where(any_nonfinite3(wo) | any_nonfinite3(wi), dv),
        v_dot_h,
    )
}

/// f = D(h) V(wo, wi) F, with F given by the caller as a function of v.h (any Fresnel form of
/// [`crate::fresnel`], or a constant). 0 where wo.z <= 0 or wi.z <= 0.
///
/// Reciprocal (f(wo, wi) = f(wi, wo)) because h, v.h = l.h and V are symmetric in the two
/// directions.
#[inline]
#[must_use]
pub fn eval<T: Real, M: Microfacet<T> + ?Sized>(
    m: &M,
    wo: V3<T>,
    wi: V3<T>,
    fresnel: impl Fn(T) -> T,
) -> T {
    let (dv, v_dot_h) = masked_dv(m, wo, wi);
    (dv * fresnel(v_dot_h)).min(T::MAX)
}

/// Cook-Torrance with the exact dielectric Fresnel term of relative IOR `eta`
/// ([`fresnel::dielectric`]).
#[inline]
#[must_use]
pub fn dielectric<T: Real, M: Microfacet<T> + ?Sized>(m: &M, wo: V3<T>, wi: V3<T>, eta: T) -> T {
    eval(m, wo, wi, |c| fresnel::dielectric(c, eta))
}

/// Cook-Torrance with the exact conductor Fresnel term of complex IOR eta + i k
/// ([`fresnel::conductor`]), one channel.
#[inline]
#[must_use]
pub fn conductor<T: Real, M: Microfacet<T> + ?Sized>(
    m: &M,
    wo: V3<T>,
    wi: V3<T>,
    eta: T,
    k: T,
) -> T {
    eval(m, wo, wi, |c| fresnel::conductor(c, eta, k))
}

/// Cook-Torrance with an RGB Fresnel term (for example [`fresnel::schlick_rgb`] or
/// [`fresnel::conductor_rgb`]): D V is computed once and scaled per channel.
#[inline]
#[must_use]
pub fn eval_rgb<T: Real, M: Microfacet<T> + ?Sized>(
    m: &M,
    wo: V3<T>,
    wi: V3<T>,
    fresnel: impl Fn(T) -> V3<T>,
) -> V3<T> {
    let (dv, v_dot_h) = masked_dv(m, wo, wi);
    let f = fresnel(v_dot_h) * dv;
    V3::new(f.x.min(T::MAX), f.y.min(T::MAX), f.z.min(T::MAX))
}

/// Dot-product entry point of isotropic GGX Cook-Torrance: f = D(n.h) V(n.v, n.l) F, with
/// [`crate::ggx::d`] and [`crate::ggx::v_correlated`], F given by the caller (the shader
/// form: `D_GGX * V_SmithGGXCorrelated * F`). `c` is the shading point's [`Cosines`], `alpha`
/// the roughness as an [`Alpha`] (not the perceptual roughness: [`Alpha::from_perceptual`]); F is
/// given, so its v.h only passes a NaN on (the F the caller formed from it).
///
/// Domain: cosines in [-1, 1] (clamped to [0, 1]; 0 where n.l <= 0 or n.v <= 0), alpha in
/// [0, +inf) finite (clamped to [ALPHA_MIN, ALPHA_MAX]), F >= 0 finite. NaN for NaN in any
/// input, alpha < 0 or +inf, F < 0 or +inf. Never inf: D V and D V F are capped at the largest finite value
/// (reached only when both cosines are near 0, where the BRDF is multiplied by n.l anyway).
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx<T: Real>(c: Cosines<T>, alpha: Alpha<T>, fresnel: T) -> T {
    let alpha = alpha.0;
    let dv = ggx_dv(c, alpha);
    assemble(dv, c, alpha, fresnel)
}

/// D V of the isotropic GGX (`crate::ggx::dv`: the product of `ggx::d` and
/// `ggx::v_correlated` on f64 types, one f64 quotient rounded once on f32 types; [`assemble`]
/// caps it): shared by [`ggx`] and its Fresnel-specific forms so that they agree bit for bit.
#[cfg(feature = "ggx")]
#[inline]
fn ggx_dv<T: Real>(c: Cosines<T>, alpha: T) -> T {
    crate::ggx::dv(c.n_dot_h, c.n_dot_v, c.n_dot_l, alpha)
}

/// (D V capped at MAX) F capped at MAX, 0 below the horizon, NaN for NaN input, alpha outside
/// [0, +inf) or F outside [0, +inf): the shared tail of the dot-product entry points. Capping D V before the
/// multiplication by F keeps a zero F from meeting an infinite D V (0 inf = NaN).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn assemble<T: Real>(dv: T, c: Cosines<T>, alpha: T, fresnel: T) -> T {
    let value = (dv.min(T::MAX) * fresnel).min(T::MAX);
    let value = above_horizon(c.n_dot_v, c.n_dot_l, value);
    // F = +inf is out of the domain (rule 5), not a cap at MAX.
    let ok = crate::microfacet::alpha_ok(alpha)
        & fresnel.simd_ge(T::ZERO)
        & fresnel.simd_lt(T::INFINITY);
    crate::domain::nan_unless(
        ok,
        nan_where(c.n_dot_h.is_nan() | c.v_dot_h.is_nan(), value),
    )
}

/// Dot-product entry point of isotropic Beckmann Cook-Torrance with the height-correlated
/// Smith G2 = 1 / (1 + Lambda(v) + Lambda(l)): f = D G2 F / (4 n.l n.v), evaluated as
/// D F / (4 (n.l n.v + n.l n.v Lambda(v) + n.v n.l Lambda(l))) so that grazing cosines give
/// 0 instead of 0 / 0. Domain, edges and caps as `ggx`.
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann<T: Real>(c: Cosines<T>, alpha: Alpha<T>, fresnel: T) -> T {
    let alpha = alpha.0;
    let dv = beckmann_dv(c, alpha);
    assemble(dv, c, alpha, fresnel)
}

/// D V of the isotropic Beckmann (uncapped; [`assemble`] caps it): shared by [`beckmann`] and
/// its Fresnel-specific forms so that they agree bit for bit.
#[cfg(feature = "beckmann")]
#[inline]
fn beckmann_dv<T: Real>(c: Cosines<T>, alpha: T) -> T {
    let (cv, cl) = (c.n_dot_v.saturate(), c.n_dot_l.saturate());
    let dist = crate::beckmann::Beckmann::new_unchecked(alpha, alpha);
    let (wv, wl) = (cosine_direction(cv), cosine_direction(cl));
    crate::beckmann::d(c.n_dot_h, alpha) * dist.v_correlated(wv, wl)
}

/// A unit direction with cos(theta) = c in the xz plane (isotropic terms depend on c only).
#[cfg(feature = "beckmann")]
#[inline]
fn cosine_direction<T: Real>(c: T) -> V3<T> {
    V3::new(((T::ONE - c) * (T::ONE + c)).sqrt_nonneg(), T::ZERO, c)
}

/// The RGB tail of the Fresnel-specific entry points: [`assemble`] once per channel with the
/// same D V, so each channel equals the scalar entry point with that channel's F bit for bit.
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn assemble_rgb<T: Real>(dv: T, c: Cosines<T>, alpha: T, f: V3<T>) -> V3<T> {
    let ch = |f: T| assemble(dv, c, alpha, f);
    V3::new(ch(f.x), ch(f.y), ch(f.z))
}

/// Rough conductor (metal), isotropic GGX, RGB: per channel c (x = r, y = g, z = b),
/// f_c = D(n.h) V(n.v, n.l) F_c with the exact conductor Fresnel
/// F_c = [`fresnel::conductor`](v.h, eta_c, k_c) of the complex IOR eta_c + i k_c.
///
/// Each channel equals [`ggx`]`(c, alpha, fresnel::conductor(c.v_dot_h, ior.eta.c, ior.k.c))`
/// bit for bit; D V is evaluated once. The
/// direction-vector form is [`eval_rgb`] with [`fresnel::conductor_rgb`].
///
/// Domain: cosines in [-1, 1]; n.v and n.l clamped to [0, 1] (0 where either is <= 0); v.h
/// clamped to [0, 1] (for a reflection v.h = |v + l| / 2 >= 0); alpha in [0, +inf) finite,
/// clamped to [ALPHA_MIN, ALPHA_MAX]; per channel eta in (0, MAX] and k in [0, MAX] (`ior`, named so
/// the two cannot be swapped). NaN for a
/// NaN input or alpha < 0 or +inf (every channel), and in a channel whose eta or k is outside
/// its domain. Never inf: D V and D V F are capped at the largest finite value.
///
/// Sources: Cook and Torrance 1982, "A Reflectance Model for Computer Graphics"; Walter et al.
/// 2007, "Microfacet Models for Refraction through Rough Surfaces" (GGX D, eq. 33; the 1/4
/// Jacobian, eq. 20); Heitz 2014, "Understanding the Masking-Shadowing Function in
/// Microfacet-Based BRDFs" (height-correlated G2, eq. 99); Born and Wolf, "Principles of
/// Optics", section 14.2 (reflection at a conducting surface).
///
/// ```
/// use brdf::fresnel::ComplexIor;
/// use brdf::microfacet::Alpha;
/// use brdf::{Cosines, V3, cook_torrance};
/// // A gold-like conductor: red and green reflect more than blue.
/// let gold = ComplexIor { eta: V3::new(0.18, 0.42, 1.37), k: V3::new(3.42, 2.35, 1.77) };
/// let c = Cosines { n_dot_v: 0.8, n_dot_l: 0.7, n_dot_h: 0.95, v_dot_h: 0.9 };
/// let f = cook_torrance::ggx_conductor_rgb(c, Alpha(0.3), gold);
/// assert!(f.x > f.z && f.y > f.z && f.z > 0.0);
/// // Below the horizon: nothing.
/// let dark = cook_torrance::ggx_conductor_rgb(Cosines { n_dot_l: -0.1, ..c }, Alpha(0.3), gold);
/// assert_eq!(dark, V3::splat(0.0));
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_conductor_rgb<T: Real>(c: Cosines<T>, alpha: Alpha<T>, ior: ComplexIor<V3<T>>) -> V3<T> {
    let alpha = alpha.0;
    let f = fresnel::conductor_rgb(c.v_dot_h.saturate(), ior.eta, ior.k);
    let dv = ggx_dv(c, alpha);
    assemble_rgb(dv, c, alpha, f)
}

/// The working-precision tier of [`ggx_conductor_rgb`]: the same rough conductor, domain,
/// edges and bad input, with [`crate::ggx::d_fast`] for D and
/// [`fresnel::conductor_fast`] for each channel's F (V is [`crate::ggx::v_correlated`], as
/// in the exact tier). For a renderer shading millions of points per frame on lanes: the exact
/// tier's D and F cost about 150 and 290 extra flops.
///
/// Accuracy against [`ggx_conductor_rgb`] on the same inputs, per channel: D and F each bring
/// their own relative error (5.3e-7 and 6.0e-7 in f32, 9.1e-16 and 1.3e-15 in f64, in their
/// docs) and each tier one rounding of the products, so within 1.5e-6 (f32) / 2.6e-15 (f64)
/// relative, where a 1-ULP change of v.h moves F by at most 8 ULP (near a conductor's critical
/// angle with k near 0, [`fresnel::conductor_fast`]'s own caveat applies). Measured over
/// 4 million random cosines (n.v and n.l down to 1e-6), alpha from ALPHA_MIN to 1, three
/// metals and eta, k log-uniform over [1e-3, 1e3] (with k >= 0.1 or eta >= 1): 8.7e-7 (f32),
/// 1.8e-15 (f64) (`BRDF_FAST_TIER_POINTS=4000000 cargo test --all-features --test
/// cook_torrance fast_tier:: -- --nocapture`). Lanes equal the scalar results bit for bit.
///
/// Sources: as [`ggx_conductor_rgb`]; D as Filament's `D_GGX` (Guy and Agopian,
/// "Physically Based Rendering in Filament", section 4.4).
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_conductor_rgb_fast<T: Real>(
    c: Cosines<T>,
    alpha: Alpha<T>,
    ior: ComplexIor<V3<T>>,
) -> V3<T> {
    let alpha = alpha.0;
    let v_dot_h = c.v_dot_h.saturate();
    let f = V3::new(
        fresnel::conductor_fast(v_dot_h, ior.eta.x, ior.k.x),
        fresnel::conductor_fast(v_dot_h, ior.eta.y, ior.k.y),
        fresnel::conductor_fast(v_dot_h, ior.eta.z, ior.k.z),
    );
    let dv = crate::ggx::d_fast(c.n_dot_h, alpha)
        * crate::ggx::v_correlated(c.n_dot_v, c.n_dot_l, alpha);
    assemble_rgb(dv, c, alpha, f)
}

/// Rough conductor (metal), isotropic GGX, one channel, from the two local-frame directions:
/// f = D(h) V(wo, wi) F(v.h) with h = s / |s|, s = wo + wi, evaluated from the components of s
/// so that D does not depend on n.h alone:
///
/// D = alpha^2 |s|^4 / (pi (s_x^2 + s_y^2 + alpha^2 s_z^2)^2) (Walter et al. 2007 eq. 33 with
/// tan^2(theta_h) = (s_x^2 + s_y^2) / s_z^2), v.h = wo.s / |s|,
/// V = 0.5 / (n.l sqrt(alpha^2 + n.v^2 (1 - alpha^2)) + n.v sqrt(alpha^2 + n.l^2 (1 - alpha^2)))
/// (Heitz 2014 eq. 99), F = [`fresnel::conductor`](v.h, eta, k).
///
/// Near the peak of a narrow lobe 1 - (n.h)^2 is small and a cosine n.h rounded to the working
/// precision loses most of its digits (a 1-ULP change of n.h moves D by up to 4 / alpha^2
/// ULP: 44 ULP at alpha = 0.3), which the dot-product entry point [`ggx`] cannot recover;
/// s_x^2 + s_y^2 keeps them.
///
/// Domain: unit vectors wo and wi (the formulas read their components as given), alpha in
/// [0, +inf) finite, clamped to [ALPHA_MIN, ALPHA_MAX]; eta in (0, MAX], k in [0, MAX]. 0
/// where wo.z <= 0 or wi.z <= 0; capped at the largest finite value; NaN for NaN or infinite
/// components, alpha < 0 or +inf, eta <= 0, k < 0, or infinite eta or k.
///
/// Accuracy: on `f64` and `f64x4` these formulas in the lane type's arithmetic, with
/// [`fresnel::conductor`] (correctly rounded to a few ULP) for F: D V carries about twenty
/// roundings, and the whole is within 1e-14 relative of the generic assembly [`conductor`]
/// with [`crate::ggx::Ggx`] (D of the normalized h in double words, V from the vectors'
/// components) on unit directions with |wo + wi| >= 1/8 (4.2e-15 found over 40 x 50 000
/// random directions and parameters, default and `-C target-cpu=native` builds). Nearer
/// opposite directions both round the sum of the f64 components, which moves h by up to
/// about 2^-52 / |wo + wi| radians, and D by up to 2 / alpha relative per radian: there they
/// agree within 1e-14 + 4e-16 (1 + 2 / alpha) / |wo + wi| (1.8e-16 / |wo + wi| found).
///
/// On `f32` and `f32x8` the same function is evaluated in f64 (`f32x8` as one `f64x8` register
/// where the target has AVX-512, as two `f64x4` halves otherwise; lane for lane the scalar
/// operations) and rounded to f32 once (a result below f32's smallest normal number from normal
/// numbers, as [`fresnel::conductor`]'s), in a form with fewer roots and divisions. F depends on
/// the directions only through c = x / sqrt(y) with x = wo.s and y = |s|^2, and is unchanged
/// when (x, y) is scaled to (r x, r^2 y): with z = N^2 - sin^2 = u + c^2 (u = N^2 - 1),
/// y z = u y + x^2 is a polynomial, |c + s|^2 y, (A + B) y^2 and A y^2 of
/// [`fresnel::conductor`]'s form are polynomials in x, y, |y z| and sqrt(y (|z| + |Re z|)), so that
/// F = num / (p^2 q) takes two square roots (|y z| and sqrt(|y z| + |Re y z|)) and neither |s| nor
/// the quotient wo.s / |s|. r is the bit-pattern seed of 1 / sqrt(y), which puts y within 7 % of 1
/// and every magnitude where it was with c in [0, 1]. Re(u) enters y z as the exact unevaluated
/// sum of eta^2 - k^2 - 1 (two error-free additions; the squares of f32 inputs are exact), so that
/// Re(N^2) is kept where |N| is below 2^-27 and Re(u) alone would round to -1 (at normal
/// incidence y z would then be 0 and F 0 / 0). F's quotient is folded into D V's:
/// f = (num alpha^2 |s|^4 g) / (2 pi p^2 q t^2 den g), g the square of the bit-pattern seed of
/// 1 / sqrt(t^2 den), which keeps both products inside f64's normal range. V's two roots are
/// correctly rounded f64 square roots where the target has AVX-512, elsewhere an f32
/// reciprocal root (correctly rounded f32 `sqrt` and division, the same bits on every target)
/// and one Newton step in f64 (within 4e-14 relative): one choice per target, whichever was
/// faster (below). Error budget before the rounding to f32: the two roundings of r move c by
/// 2^-52; F's polynomials, roots and products about thirty roundings of 2^-53; D V about
/// twenty, V's roots 4e-14 each at most; together below 1e-13 relative, 2e-6 of an f32 ULP
/// beside the rounding's 0.5: within 1 ULP of the f64 tier on the same directions (0.500 found over
/// 40 x 200 000 random directions and parameters, seeds 1 to 40, default and
/// `-C target-cpu=native` builds, and 0.5000 on an edge grid of grazing, opposite and equal
/// directions, alpha near both clamps, eta and k from 2^-126 to f32::MAX and eta within 2^-20
/// of 1, where F is well conditioned; `BRDF_TEST_SEED=<n> cargo test --all-features --test
/// cook_torrance local:: -- --nocapture`). Against a correctly rounded (MPFR) evaluation from
/// the same f32 inputs where F is well conditioned: 0.500000004 ULP found (random, whole-domain
/// and edge-grid points and a local search from the worst, 3 seeds of 1.25 x 10^6 points,
/// default and native builds; `BRDF_ORACLE_POINTS=<n> cargo test -p brdf-oracle --release
/// --test conductor_local -- --nocapture`). Near the critical angle of a denser-side interface
/// (eta < 1, k near 0) F turns with c faster than the rounding of c^2 (2^-52 relative) can
/// follow: there the error is that rounding's, up to 4 % found (6.7e5 ULP at eta = 3.6e-4,
/// k = 1e-30), within 4 times the change of the exact value when c^2 moves by 2^-51. A NaN or
/// infinite component makes |s|^2 NaN or infinite, which the f64 evaluation maps to NaN.
///
/// Run time on `f32x8` (a Zen 4 core, `-C target-cpu=native`, `bench/mitsuba/compare.py
/// --n 1000000`, one interleaved run, load average 1.2 on 2 cores): 3.49 ms per 10^6
/// hemisphere direction pairs times n.l, 1.76 times Mitsuba 3's LLVM back end on the same
/// pairs (1.99 ms, whose f32 arithmetic is 21 ULP off where this is 1.5). Two `f64x4` halves
/// with V's roots from f32 seeds took 2.65 times; with `f64x8` lanes the hardware f64 roots
/// cost less than those seeds with their conversions between 512- and 256-bit registers,
/// and on `f64x4` halves (the same core built with `-C target-cpu=x86-64-v3`, AVX2 and FMA
/// only) the other way round: 5.4 ms with the seeds against 9.3 with `vsqrtpd` (5.9 for the
/// form before this one). More in `bench/mitsuba/README.md`.
///
/// Sources: as [`ggx_conductor_rgb`]; the half-vector form of D as Mitsuba 3's
/// `MicrofacetDistribution::eval` (`include/mitsuba/render/microfacet.h`).
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_conductor_local<T: Real>(wo: V3<T>, wi: V3<T>, alpha: Alpha<T>, eta: T, k: T) -> T {
    let a = crate::microfacet::clamp_alpha(alpha.0);
    let x = [wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, a, eta, k];
    // NaN components give NaN inside (`ConductorLocal`); the parameters are checked here, once
    // for a loop with fixed parameters.
    let value = T::via_f64(x, ConductorLocal, crate::real::sealed::Token::NEW);
    crate::domain::nan_unless(local_params_ok(a, eta, k), value)
}

/// Where the parameters of [`ggx_conductor_local`] and [`ggx_conductor_local_fast`] are in
/// their domain (an invalid eta or k gives an unspecified F, and the f32 rounding does not
/// keep a NaN): eta valid, k in [0, MAX], the clamped alpha not NaN. The same for every lane
/// of a loop with fixed parameters, where it is computed once.
#[cfg(feature = "ggx")]
#[inline]
fn local_params_ok<T: Real>(a: T, eta: T, k: T) -> T::Mask {
    fresnel::valid_eta(eta) & k.simd_ge(T::ZERO) & k.simd_le(T::MAX) & !a.is_nan()
}

/// NaN where [`ggx_conductor_local_fast`]'s inputs are out of their domain:
/// [`local_params_ok`], and `probe` NaN exactly where a component of wo or wi is NaN or
/// infinite (the caller forms it as 0 |wo + wi|^2), 0 elsewhere; it is compared, not added,
/// so that a subnormal result meets no arithmetic.
#[cfg(feature = "ggx")]
#[inline]
fn local_guards<T: Real>(probe: T, a: T, eta: T, k: T, value: T) -> T {
    crate::domain::nan_unless(local_params_ok(a, eta, k), nan_where(probe.is_nan(), value))
}

/// The value of [`ggx_conductor_local`] for the clamped alpha (invalid eta, k or NaN give an
/// unspecified value, which the caller replaces): [`conductor`] with [`crate::ggx::Ggx`] in
/// f64 and f64x4, one f64 evaluation from the components rounded once in f32 and f32x8.
#[cfg(feature = "ggx")]
#[derive(Clone, Copy)]
struct ConductorLocal;

#[cfg(feature = "ggx")]
impl crate::real::sealed::Widened<9> for ConductorLocal {
    /// F of N near 1 falls below f32's smallest normal number.
    const TINY: bool = true;

    #[inline]
    fn native<T: Real>(self, [vx, vy, vz, lx, ly, lz, a, eta, k]: [T; 9]) -> T {
        let (wo, wi) = (V3::new(vx, vy, vz), V3::new(lx, ly, lz));
        let s = wo + wi;
        let (sxy, ss) = local_sums(s);
        let v_dot_h = (wo.dot(s) / ss.sqrt()).saturate();
        let dv = local_dv(
            s.z,
            sxy,
            ss,
            vz.saturate(),
            lz.saturate(),
            a,
            T::MAX,
            T::sqrt,
        );
        let f = fresnel::conductor(v_dot_h, eta, k);
        let above = vz.simd_gt(T::ZERO) & lz.simd_gt(T::ZERO);
        // |s|^2 is finite exactly where every component is (for components below 1e150).
        crate::domain::nan_unless(ss.simd_le(T::MAX), T::select(above, dv * f, T::ZERO))
    }

    /// The value before its rounding (`single` and `lanes8` below round it with
    /// `crate::widen`'s subnormal-safe rounding).
    #[inline]
    fn wide<W: Real<Scalar = f64>>(self, x: [W; 9]) -> W {
        Self::value(x)
    }

    #[inline]
    fn single(self, x: [f32; 9]) -> f32 {
        let v = Self::value(x.map(f64::from));
        crate::widen::join_tiny_f32(
            crate::widen::tiny_big(v, 1.0),
            crate::widen::tiny_small(v, 1.0),
        )
    }

    /// With AVX-512, all eight lanes as one `f64x8` register: half the instructions of two
    /// `f64x4` halves. Elsewhere two `f64x4` halves one after the other (an `f64x8` made of
    /// two `f64x4` needs twice the registers, and spilling them took 1.7 times as long on
    /// an AVX2 build). The same operations lane for lane either way.
    #[inline]
    fn lanes8(self, x: [crate::wide::f32x8; 9]) -> crate::wide::f32x8 {
        #[cfg(target_feature = "avx512f")]
        let v = Self::value(x.map(crate::widen::widen8));
        #[cfg(not(target_feature = "avx512f"))]
        let v = {
            let lo = Self::value(x.map(|v| crate::real::widen_half(v, 0))).to_array();
            let hi = Self::value(x.map(|v| crate::real::widen_half(v, 4))).to_array();
            crate::wide::f64x8::new([lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]])
        };
        let one = crate::wide::f64x8::splat(1.0);
        crate::widen::join_tiny_f32x8(
            crate::widen::tiny_big(v, one),
            crate::widen::tiny_small(v, one),
        )
    }
}

#[cfg(feature = "ggx")]
impl ConductorLocal {
    /// D V F in f64 from f32 inputs widened exactly, on `f64`, `f64x4` and `f64x8` alike.
    #[inline]
    fn value<W: crate::widen::F64Ops>([vx, vy, vz, lx, ly, lz, a, eta, k]: [W; 9]) -> W {
        // Sums of two f32 components and their squares carry a rounding of 2^-53 at most; no
        // intermediate leaves f64's normal range for f32 inputs (|s| >= 2^-149 where it is not
        // 0). The cap at f32's largest finite value keeps D V F finite after the rounding.
        // The longest chain of dependent operations runs through F's two nested roots (on
        // `vsqrtpd`) and the one division; everything else is arranged beside it.
        let zero = W::splat(0.0);
        let one = W::splat(1.0);
        let s = [vx + lx, vy + ly, vz + lz];
        let sxy = s[0].mul_add(s[0], s[1] * s[1]);
        let ss = s[2].mul_add(s[2], sxy);
        let wo_s = vx.mul_add(s[0], vy.mul_add(s[1], vz * s[2]));
        let (f_num, f_p, f_q) = fresnel::ConductorWide::new(eta, k).of_projection(wo_s, ss);
        // V's two roots (`v_root`; their argument alpha^2 (1 - c^2) + c^2 lies in [1e-8, 1e8]
        // for the clamped alpha).
        let cap = W::splat(f64::from(f32::MAX));
        let (cv, cl) = (vz.max(zero).min(one), lz.max(zero).min(one));
        let a2 = a * a;
        let t = a2.mul_add(s[2] * s[2], sxy);
        let root = |c: W| v_root(a2.mul_add(sin2_lanes(c), c * c));
        let den = cl.mul_add(root(cv), cv * root(cl));
        let num = (a2 * W::splat(0.5 * core::f64::consts::FRAC_1_PI)) * (ss * ss);
        // D V = num / dv_den lies in [2^-50, 2^243] for f32 inputs, dv_den in [2^-812, 2^75]:
        // both scaled by g^2 (g the seed of 1 / sqrt(dv_den), within 3.5 %), the numerator
        // is about D V and the denominator F's p^2 q (below 2^900) times about 1, so the one
        // quotient of D V F meets no overflow where F's own would not (F's numerator exceeds
        // 2^780 only for |N| so large that F is near 1, where D V F above f32::MAX is capped
        // as it should be). The floor keeps 0 / 0 out where t^2 den underflows (it does not
        // for f32 inputs).
        let dv_den = ((t * t) * den).max(W::splat(f64::MIN_POSITIVE));
        let g = dv_den.rsqrt_bits();
        let g2 = g * g;
        let value = (((num * g2) * f_num) / ((f_p * f_p) * (f_q * (dv_den * g2)))).min(cap);
        let above = vz.gt(zero) & lz.gt(zero);
        // |s|^2 is finite exactly where every component is (f32 components: no overflow).
        W::select(
            W::splat(f64::MAX).ge(ss),
            W::select(above, value, zero),
            W::splat(f64::NAN),
        )
    }
}

/// sqrt(x) for x in [2^-100, 2^100] on f64 lanes, for V's two roots: with AVX-512 the
/// correctly rounded root (on a Zen 4 core 8 lanes of `vsqrtpd` cost less than
/// [`sqrt_by_f32`]'s seeds with their conversions between 512- and 256-bit registers: 3.5
/// against 3.9 ms per 10^6 rough conductor evaluations); elsewhere [`sqrt_by_f32`] (on the
/// same core built for AVX2 alone, `vsqrtpd` on 4 lanes took 9.3 ms against 5.4). One
/// choice per target, so that `f32` and `f32x8` agree bit for bit.
#[cfg(feature = "ggx")]
#[inline]
fn v_root<W: crate::widen::F64Ops>(x: W) -> W {
    #[cfg(target_feature = "avx512f")]
    {
        x.sqrt()
    }
    #[cfg(not(target_feature = "avx512f"))]
    {
        sqrt_by_f32(x)
    }
}

/// sqrt(x) for x in [2^-100, 2^100] on f64 lanes, within 4e-14 relative: the f32 reciprocal
/// root y0 = 1 / sqrt(fl32(x)) (two correctly rounded f32 operations, the same bits on every
/// target and lane type; within 1.3 2^-23 of 1 / sqrt(x)), halved exactly by the division
/// itself (h0 = 0.5 / sqrt), then one Newton step in f64, s0 = x y0 = (x + x) h0,
/// sqrt(x) = s0 + h0 (x - s0^2), which leaves -1.5 (y0 sqrt(x) - 1)^2 and a few roundings of
/// 2^-53 (`sqrt_by_f32_is_within_its_stated_error`).
#[cfg(feature = "ggx")]
#[cfg_attr(target_feature = "avx512f", allow(dead_code))]
#[inline]
fn sqrt_by_f32<W: crate::widen::F64Ops>(x: W) -> W {
    let h0 = x.half_rsqrt_f32();
    let s0 = (x + x) * h0;
    h0.mul_add((-s0).mul_add(s0, x), s0)
}

/// 1 - c^2 as `crate::microfacet::sin2_working` forms it, on f64 lanes.
#[cfg(feature = "ggx")]
#[inline]
fn sin2_lanes<W: crate::widen::F64Ops>(c: W) -> W {
    #[cfg(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    ))]
    {
        (-c).mul_add(c, W::splat(1.0))
    }
    #[cfg(not(any(
        target_feature = "fma",
        all(target_arch = "aarch64", target_feature = "neon")
    )))]
    {
        let one = W::splat(1.0);
        W::select(
            W::splat(0.5).gt(c),
            (-c).mul_add(c, one),
            (one - c) * (one + c),
        )
    }
}

/// s_x^2 + s_y^2 and |s|^2.
#[cfg(feature = "ggx")]
#[inline]
fn local_sums<T: Real>(s: V3<T>) -> (T, T) {
    let sxy = s.x.mul_add(s.x, s.y * s.y);
    (sxy, s.z.mul_add(s.z, sxy))
}

/// D V = alpha^2 |s|^4 / (2 pi t^2 den) with t = s_x^2 + s_y^2 + alpha^2 s_z^2 (|s|^2 times
/// sin^2 + alpha^2 cos^2 of h) and den = n.l sqrt(alpha^2 + n.v^2 (1 - alpha^2)) + n.v
/// sqrt(alpha^2 + n.l^2 (1 - alpha^2)), one division, capped at `cap`, for the clamped alpha;
/// the cosines are taken as given (the exact tier's callers saturate them; the fast tier's
/// horizon select discards a value at a cosine <= 0). The floor on the denominator keeps 0 / 0 out where |s|^4
/// and t^2 underflow (|s|^2 < 2^-60 in f32, 2^-500 in f64: nearly opposite directions, both
/// that close to the horizon, where the result is finite but not accurate).
#[cfg(feature = "ggx")]
#[inline]
#[allow(clippy::too_many_arguments)] // the kernel's own locals, named as in its docs
fn local_dv<T: Real>(
    sz: T,
    sxy: T,
    ss: T,
    n_dot_v: T,
    n_dot_l: T,
    a: T,
    cap: T,
    sqrt: impl Fn(T) -> T,
) -> T {
    let a2 = a * a;
    let t = a2.mul_add(sz * sz, sxy);
    let root = |c: T| sqrt(a2.mul_add(crate::microfacet::sin2_working(c), c * c));
    let den = n_dot_l.mul_add(root(n_dot_v), n_dot_v * root(n_dot_l));
    ((a2 * T::splat(0.5 * core::f64::consts::FRAC_1_PI)) * (ss * ss)
        / ((t * t) * den).max(T::MIN_POSITIVE))
    .min(cap)
}

/// The working-precision tier of [`ggx_conductor_local`]: the same rough conductor, domain,
/// edges and bad input, evaluated in the lane type's own arithmetic, with one division for
/// D V:
///
/// D V = alpha^2 |s|^4 / (2 pi (s_x^2 + s_y^2 + alpha^2 s_z^2)^2 den), den as V's,
///
/// and F the formulas of [`fresnel::conductor_fast`] (its scalings, its per-(eta, k) part)
/// taken from c^2 = (wo.s)^2 / |s|^2 rather than from c = v.h: 1 - c^2 = 1 - (wo.s)^2 / |s|^2
/// and Re(s^2) = Re(N^2) - 1 + c^2 (N scaled as there) from one reciprocal of |s|^2, and
/// v.h = wo.s sqrt(1 / |s|^2) only where F reads c itself, after its two square roots. The
/// roots then wait for one division instead of a square root and a division (on a Zen 4
/// core, about a fifth less time per `f32x8`: `bench/mitsuba/compare.py`, its README). Unlike
/// [`fresnel::conductor_fast`], Re(s^2) takes that one form at every angle, which loses a few
/// digits more where it cancels (small |N| near normal incidence).
///
/// Accuracy against [`ggx_conductor_local`] on the same inputs: [`fresnel::conductor_fast`]'s
/// relative error plus a few roundings, within 3e-6 (f32) / 4e-15 (f64) relative where both
/// cosines are at least 1e-3 and F is well conditioned (k >= 0.1 or eta >= 1; 1.8e-6 and
/// 2.3e-15 found over 30 sets of 200 000 random directions, alpha from 1e-3 to 1, metals and
/// eta, k log-uniform over [1e-3, 1e3]; `BRDF_TEST_SEED=<n> cargo test --all-features --test
/// cook_torrance local:: -- --nocapture`, default x86-64 build, without fused multiply-adds;
/// 1.4e-6 and 2.3e-15 over seeds 1 to 10 with them, `-C target-cpu=native`). Where F is
/// ill-conditioned (eta < 1 and k < 0.1: the critical angle of a denser-side interface) the
/// f32 error grows: 3.3e-5 found at eta 0.003, k 0.001 near normal incidence (3.7e-5 for the
/// form before this one), and 4e-4 at eta 1e-4, where N^2 - 1 rounds to -1.
/// Against the exact value, and beside Mitsuba 3's own error, on 10^6 hemisphere pairs:
/// `bench/mitsuba/README.md`. Where |wo + wi| < 2^-30 (the two
/// directions nearly opposite, both within 2^-30 of the horizon; 2^-250 in f64) |s|^4 and
/// the denominator leave the normal range: there the result is finite but not accurate, and
/// (unlike the exact tier, which meets no subnormal number for normal inputs) |s|^2 may be
/// subnormal (its reciprocal is taken of max(|s|^2, the smallest normal number)).
///
/// Sources: as [`ggx_conductor_local`].
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_conductor_local_fast<T: Real>(wo: V3<T>, wi: V3<T>, alpha: Alpha<T>, eta: T, k: T) -> T {
    let a = crate::microfacet::clamp_alpha(alpha.0);
    let s = wo + wi;
    let (sxy, ss) = local_sums(s);
    // F from c^2 = (wo.s)^2 / |s|^2: its two roots wait for one division, not for the root
    // |s| and a division; v.h itself is needed only after them. Re(z) = u + c^2 m^2 in
    // `at`'s units (times 2^(2j - 1)); s2 and c may be a rounding outside [0, 1], which F
    // takes as the nearby values. The floor on |s|^2 keeps 1 / |s|^2 finite (0 inf would
    // be NaN) where |s|^2 is 0 or subnormal.
    let n = fresnel::ConductorFast::new(eta, k);
    let ws = wo.dot(s);
    let inv_ss = T::ONE / ss.max(T::MIN_POSITIVE);
    let ws2 = ws * ws;
    let f = n.at(
        (-ws2).mul_add(inv_ss, T::ONE),
        (ws2 * (n.m * n.m * n.z_up)).mul_add(inv_ss, n.u_re * n.z_up),
        ws * inv_ss.sqrt(),
    );
    let dv = local_dv(s.z, sxy, ss, wo.z, wi.z, a, T::MAX, T::sqrt);
    let above = wo.z.simd_gt(T::ZERO) & wi.z.simd_gt(T::ZERO);
    // F <= 1: the product stays finite.
    let value = T::select(above, dv * f, T::ZERO);
    // For unit vectors only a NaN or infinite component makes |s|^2 NaN or infinite.
    local_guards(ss * T::ZERO, a, eta, k, value)
}

/// Isotropic GGX with Schlick's Fresnel of an RGB F0, the glTF 2.0 / Filament / Unreal
/// specular: per channel c, f_c = D(n.h) V(n.v, n.l) (F0_c + (1 - F0_c)(1 - v.h)^5)
/// ([`fresnel::schlick_rgb`]). For glTF's metallic-roughness model F0 = lerp(0.04,
/// base_color, metallic) and alpha = roughness^2.
///
/// Each channel equals [`ggx`]`(c, alpha, fresnel::schlick(f0.c, c.v_dot_h))` bit for bit. Domain and edges as [`ggx_conductor_rgb`], with F0 in [0, 1] per
/// channel (outside, and NaN, give NaN in that channel).
///
/// Sources: as [`ggx_conductor_rgb`], with Schlick 1994, "An Inexpensive BRDF Model for
/// Physically-based Rendering" (eq. 15) for F; the shader form is Filament's
/// `D_GGX * V_SmithGGXCorrelated * F_Schlick`.
///
/// ```
/// use brdf::microfacet::Alpha;
/// use brdf::{Cosines, V3, cook_torrance};
/// let f0 = V3::new(0.04, 0.04, 0.04); // a glTF dielectric base
/// let normal = Cosines { n_dot_v: 1.0, n_dot_l: 1.0, n_dot_h: 1.0, v_dot_h: 1.0 };
/// let f = cook_torrance::ggx_schlick_rgb(normal, Alpha(0.5), f0);
/// // At normal incidence on a mirror-aligned facet: D(1) = 1 / (pi alpha^2), V = 1 / 4, F = F0.
/// let expected = 0.04 / (core::f64::consts::PI * 0.25) / 4.0;
/// assert!((f.x - expected).abs() < 1e-15);
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_schlick_rgb<T: Real>(c: Cosines<T>, alpha: Alpha<T>, f0: V3<T>) -> V3<T> {
    let alpha = alpha.0;
    let f = fresnel::schlick_rgb(f0, c.v_dot_h.saturate());
    let dv = ggx_dv(c, alpha);
    assemble_rgb(dv, c, alpha, f)
}

/// Rough dielectric reflection (the specular layer of plastic, glass, water), isotropic GGX:
/// f = D(n.h) V(n.v, n.l) F with the exact unpolarized dielectric Fresnel
/// F = [`fresnel::dielectric`](v.h, eta) of the relative IOR eta = n_inside / n_outside.
/// eta < 1 (the view inside the denser medium) gives total internal reflection, F = 1, past
/// the critical angle.
///
/// Equals [`ggx`]`(c, alpha, fresnel::dielectric(c.v_dot_h, eta))` bit for bit for v.h in [0, 1]. Domain and edges as [`ggx_conductor_rgb`], with eta in (0, MAX]
/// (eta <= 0, +inf and NaN give NaN). v.h is clamped to [0, 1] before the Fresnel term, so a
/// rounding-negative v.h never selects [`fresnel::dielectric`]'s "light from the other side"
/// branch.
///
/// A colour that scales the specular reflection (a tint multiplying F) is `tint * f` with
/// `tint: V3<T>`, exact channel by channel. glTF's `KHR_materials_specular` tints F0 of a
/// Schlick form instead: that is [`ggx_schlick_rgb`].
///
/// Sources: as [`ggx_conductor_rgb`]; the Fresnel equations for dielectrics, Born and Wolf,
/// "Principles of Optics", section 1.5.
///
/// ```
/// use brdf::microfacet::Alpha;
/// use brdf::{Cosines, cook_torrance};
/// // Glass (eta = 1.5) at normal incidence: F = ((eta - 1) / (eta + 1))^2 = 0.04.
/// let normal = Cosines { n_dot_v: 1.0, n_dot_l: 1.0, n_dot_h: 1.0, v_dot_h: 1.0 };
/// let f = cook_torrance::ggx_dielectric(normal, Alpha(0.5), 1.5);
/// let expected = 0.04 / (core::f64::consts::PI * 0.25) / 4.0;
/// assert!((f - expected).abs() < 1e-15);
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_dielectric<T: Real>(c: Cosines<T>, alpha: Alpha<T>, eta: T) -> T {
    let alpha = alpha.0;
    let f = fresnel::dielectric(c.v_dot_h.saturate(), eta);
    let dv = ggx_dv(c, alpha);
    assemble(dv, c, alpha, f)
}

/// The working-precision tier of [`ggx_dielectric`]: the same rough dielectric reflection,
/// domain, edges and bad input, with [`crate::ggx::d_fast`] for D and
/// [`fresnel::dielectric_fast`] for F (V is [`crate::ggx::v_correlated`], as in the exact
/// tier and in [`ggx_conductor_rgb_fast`]): f = D(n.h) V(n.v, n.l) F(v.h; eta).
///
/// Accuracy against [`ggx_dielectric`] on the same inputs: D and F each bring their own
/// relative error (their docs) and each tier one rounding of the products: within 2.5e-6
/// (f32) / 4e-15 (f64) relative for eta >= 1 (no critical angle; F >= F0 > 0): 8.5e-7 and
/// 1.8e-15 found over 4 million random cosines (n.v and n.l down to 1e-6), alpha from 1e-4 to
/// 1 and eta log-uniform over [1e-3, 1e3] and within 1e-6 of 1, counted where eta >= 1
/// (`BRDF_FAST_TIER_POINTS=4000000 cargo test --release --all-features --test cook_torrance
/// fast_dielectric:: -- --nocapture`). For eta < 1 (light from the denser
/// side) near the critical angle, F's own conditioning applies ([`fresnel::dielectric_fast`]).
/// Lanes equal the scalar results bit for bit.
///
/// Sources: as [`ggx_dielectric`]; D as Filament's `D_GGX` (Guy and Agopian, "Physically
/// Based Rendering in Filament", section 4.4).
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_dielectric_fast<T: Real>(c: Cosines<T>, alpha: Alpha<T>, eta: T) -> T {
    let alpha = alpha.0;
    let f = fresnel::dielectric_fast(c.v_dot_h.saturate(), eta);
    let dv = crate::ggx::d_fast(c.n_dot_h, alpha)
        * crate::ggx::v_correlated(c.n_dot_v, c.n_dot_l, alpha);
    assemble(dv, c, alpha, f)
}

/// `ggx_conductor_rgb` with the Beckmann NDF and its height-correlated Smith G2 (the D V
/// of [`beckmann`]): per channel f_c = D(n.h) G2 F_c(v.h; eta_c, k_c) / (4 n.l n.v), each
/// channel equal to [`beckmann`] with `fresnel::conductor(v_dot_h, eta.c, k.c)` bit for bit.
/// Domain (as `ggx_conductor_rgb`): cosines in [-1, 1], n.v and n.l clamped to [0, 1] (0 where
/// either is <= 0), v.h clamped to [0, 1]; alpha in [0, +inf) finite, clamped to [ALPHA_MIN,
/// ALPHA_MAX]; per channel eta in (0, MAX], k in [0, MAX]. NaN for a NaN input or a bad alpha
/// (every channel) and in a channel with a bad eta or k; capped at the largest finite value.
/// Sources: as `ggx_conductor_rgb` (Cook and Torrance 1982; Walter et al. 2007; Heitz 2014;
/// Born and Wolf, section 14.2), with Beckmann and Spizzichino 1963 for D (Walter et al.
/// 2007, eq. 25) and Walter et al. 2007, eq. 27, for its Smith Lambda.
///
/// ```
/// use brdf::fresnel::ComplexIor;
/// use brdf::microfacet::Alpha;
/// use brdf::{Cosines, V3, cook_torrance};
/// let gold = ComplexIor { eta: V3::new(0.18, 0.42, 1.37), k: V3::new(3.42, 2.35, 1.77) };
/// let c = Cosines { n_dot_v: 0.8, n_dot_l: 0.7, n_dot_h: 0.95, v_dot_h: 0.9 };
/// let f = cook_torrance::beckmann_conductor_rgb(c, Alpha(0.3), gold);
/// assert!(f.x > f.z && f.z > 0.0);
/// ```
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_conductor_rgb<T: Real>(
    c: Cosines<T>,
    alpha: Alpha<T>,
    ior: ComplexIor<V3<T>>,
) -> V3<T> {
    let alpha = alpha.0;
    let f = fresnel::conductor_rgb(c.v_dot_h.saturate(), ior.eta, ior.k);
    let dv = beckmann_dv(c, alpha);
    assemble_rgb(dv, c, alpha, f)
}

/// `ggx_schlick_rgb` with the Beckmann D V of [`beckmann`]: per channel
/// f_c = D(n.h) G2 (F0_c + (1 - F0_c)(1 - v.h)^5) / (4 n.l n.v), each channel equal to
/// [`beckmann`] with `fresnel::schlick(f0.c, v_dot_h)` bit for bit. Domain, edges and
/// sources as `ggx_schlick_rgb` and [`beckmann_conductor_rgb`].
///
/// ```
/// use brdf::microfacet::Alpha;
/// use brdf::{Cosines, V3, cook_torrance};
/// let c = Cosines { n_dot_v: 0.8, n_dot_l: 0.7, n_dot_h: 0.95, v_dot_h: 0.9 };
/// let f = cook_torrance::beckmann_schlick_rgb(c, Alpha(0.3), V3::splat(0.04));
/// assert!(f.x > 0.0 && f.x == f.z);
/// ```
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_schlick_rgb<T: Real>(c: Cosines<T>, alpha: Alpha<T>, f0: V3<T>) -> V3<T> {
    let alpha = alpha.0;
    let f = fresnel::schlick_rgb(f0, c.v_dot_h.saturate());
    let dv = beckmann_dv(c, alpha);
    assemble_rgb(dv, c, alpha, f)
}

/// `ggx_dielectric` with the Beckmann D V of [`beckmann`]:
/// f = D(n.h) G2 F(v.h; eta) / (4 n.l n.v), equal to [`beckmann`] with
/// `fresnel::dielectric(v_dot_h, eta)` bit for bit for v.h in [0, 1]. Domain, edges, the tint
/// and sources as `ggx_dielectric` and [`beckmann_conductor_rgb`].
///
/// ```
/// use brdf::microfacet::Alpha;
/// use brdf::{Cosines, cook_torrance};
/// let c = Cosines { n_dot_v: 0.8, n_dot_l: 0.7, n_dot_h: 0.95, v_dot_h: 0.9 };
/// let f: f64 = cook_torrance::beckmann_dielectric(c, Alpha(0.3), 1.5);
/// assert!(f > 0.0 && f.is_finite());
/// ```
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_dielectric<T: Real>(c: Cosines<T>, alpha: Alpha<T>, eta: T) -> T {
    let alpha = alpha.0;
    let f = fresnel::dielectric(c.v_dot_h.saturate(), eta);
    let dv = beckmann_dv(c, alpha);
    assemble(dv, c, alpha, f)
}

#[cfg(all(test, feature = "ggx"))]
mod tests {
    use super::sqrt_by_f32;

    /// `sqrt_by_f32` within its stated 4e-14 (relative, from below, to a few roundings of
    /// 2^-53) of the correctly rounded f64 root over [2^-100, 2^100] (a geometric sweep of
    /// about 10^7 points, and the powers of two with their neighbours), `f64x4` and `f64x8`
    /// lanes equal to the scalar.
    #[test]
    fn sqrt_by_f32_is_within_its_stated_error() {
        let mut worst = 0.0f64;
        let mut check = |x: f64| {
            let got = sqrt_by_f32(x);
            let rel = got / x.sqrt() - 1.0;
            assert!(rel.abs() <= 4e-14 && rel <= 4e-16, "sqrt({x:e}): {rel:e}");
            let lanes = sqrt_by_f32(crate::wide::f64x4::splat(x)).to_array();
            assert!(lanes.iter().all(|l| l.to_bits() == got.to_bits()), "{x:e}");
            let lanes = sqrt_by_f32(crate::wide::f64x8::splat(x)).to_array();
            assert!(lanes.iter().all(|l| l.to_bits() == got.to_bits()), "{x:e}");
            worst = worst.max(rel.abs());
        };
        let mut x = libm::exp2(-100.0);
        while x < libm::exp2(100.0) {
            check(x);
            x *= 1.000_013_7;
        }
        for e in -100..=100 {
            let p = libm::exp2(f64::from(e));
            for q in [p, p * (1.0 + f64::EPSILON), p * (1.0 - f64::EPSILON / 2.0)] {
                check(q);
            }
        }
        assert!(worst <= 4e-14, "{worst:e}");
    }
}
