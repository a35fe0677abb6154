//! The rough dielectric BSDF: reflection and refraction through a microfacet interface
//! between two dielectrics (glass, water), after Walter, Marschner, Li and Torrance 2007,
//! "Microfacet Models for Refraction through Rough Surfaces" (EGSR), for any [`Microfacet`]
//! distribution (`ggx::Ggx`, `beckmann::Beckmann`, isotropic or anisotropic).
//!
//! # Conventions
//! Directions are unit vectors in the local shading frame (normal = +z), both pointing away
//! from the surface; `wo` is the direction the quantity being transported leaves along (the
//! camera side of a radiance path), `wi` the one it arrives from. `eta` = n_inside /
//! n_outside is the relative index of the medium below the surface (z < 0) over the one
//! above it, as in `fresnel::dielectric`; a direction with z < 0 lies inside. From inside,
//! the relative index the light sees is 1 / eta. The facet normals always face +z.
//!
//! With eta' the index on wi's side over the index on wo's side (eta' = 1 for reflection,
//! eta for wo outside and wi inside, 1 / eta the other way round):
//!
//! - the generalized half vector ([`half_vector`]; Walter et al. 2007, eq. 16) is
//!   h = +-normalize(wo + eta' wi), the sign making h.z >= 0; it is the facet normal that
//!   reflects (eta' = 1) or refracts wo into wi;
//! - reflection: f_r = D(h) G2 F(wo.h) / (4 |wo.z| |wi.z|) (eq. 20);
//! - transmission: f_t = D(h) G2 (1 - F(wo.h)) |wi.h| |wo.h| / (|wi.z| |wo.z| (wi.h + wo.h / eta')^2)
//!   times s (eq. 21), where (wi.h + wo.h / eta')^2 / |wi.h| is the inverse of the Jacobian
//!   d(omega_h) / d(omega_i) of refraction (eq. 17);
//! - F is the exact unpolarized dielectric Fresnel reflectance at wo.h (`fresnel::dielectric`;
//!   total internal reflection gives F = 1 and no transmission); G2 = 1 / (1 + Lambda(wo) +
//!   Lambda(wi)) is the height-correlated Smith term in the form pbrt-v4's `DielectricBxDF`
//!   uses for both lobes (Heitz 2014, "Understanding the Masking-Shadowing Function", gives
//!   the exact height-correlated transmission term as a Beta function; this form is never
//!   above G1(wo), which keeps the lobe energy-conserving, and loses a little more energy at
//!   grazing angles);
//! - a facet contributes only where both directions see its own side: wo.h wo.z > 0 and
//!   wi.h wi.z > 0 (pbrt-v4's back-facing test), else f = 0.
//!
//! # Radiance and importance ([`Transport`])
//! Radiance divided by the square of the index of its medium is invariant along a refracted
//! ray (Veach 1997, "Robust Monte Carlo Methods for Light Transport Simulation", section 5.2),
//! so the BTDF of radiance carries the factor s = 1 / eta'^2 = (n_wo / n_wi)^2
//! ([`Transport::Radiance`], paths traced from the camera; pbrt-v4's `TransportMode::Radiance`)
//! and that of importance (paths traced from the lights, photons) does not (s = 1,
//! [`Transport::Importance`]). The two are adjoint: f_importance(wo, wi) = f_radiance(wi, wo),
//! and the radiance BTDF obeys the generalized reciprocity f_t(wo, wi) / n_wo^2 =
//! f_t(wi, wo) / n_wi^2. Energy: for light arriving along wo, the fraction scattered is the
//! integral of f_importance(wo, wi) |wi.z| over the sphere of wi, at most 1; the radiance form
//! integrates to the same reflection plus eta'^-2 times the transmission.
//!
//! # Sampling
//! `ggx_sample` and `beckmann_sample` draw a visible facet normal (`sampling::ggx_vndf_spherical_cap`,
//! `sampling::beckmann_vndf`) as seen from wo's side, choose reflection with probability
//! F(wo.m) and refraction otherwise, and return (wi, pdf, weight) with the combined pdf of
//! both lobes ([`pdf`]) and weight = f |wi.z| / pdf = G2 / G1(wo) (times s for a refraction):
//! the D, the Fresnel factor and the Jacobians cancel, as in Heitz and d'Eon 2014,
//! "Importance Sampling Microfacet-Based BSDFs using the Distribution of Visible Normals".
//! pbrt-v4's `DielectricBxDF::Sample_f` and Mitsuba 3's `roughdielectric` sample the same way.
//!
//! # Edges
//! eta = 1 (index-matched media): the interface is invisible. [`eval`] and [`pdf`] are 0 for
//! every pair of directions, and the samplers return the Dirac pass-through wi = -wo with
//! weight 1 and pdf `T::MAX` standing for the Dirac's infinite density (pbrt-v4 likewise
//! treats eta = 1 as a specular interface). alpha is clamped to [`ALPHA_MIN`],
//! [`ALPHA_MAX`] as everywhere in the crate; eta near 1 gives a transmission lobe of width
//! about alpha |eta - 1|, evaluated without cancellation in the half vector.
//!
//! [`ALPHA_MIN`]: crate::microfacet::ALPHA_MIN
//! [`ALPHA_MAX`]: crate::microfacet::ALPHA_MAX

#[cfg(any(feature = "ggx", feature = "beckmann"))]
use crate::domain::nan_unless;
use crate::domain::nan_where;
use crate::fresnel;
use crate::microfacet::Microfacet;
use crate::real::Real;
use crate::vec3::{V3, any_nonfinite3, is_zero3};

#[cfg(feature = "beckmann")]
use crate::beckmann::Beckmann;
#[cfg(feature = "ggx")]
use crate::ggx::Ggx;

/// Which quantity a path carries, which decides the refraction factor s of the BTDF (module
/// docs, "Radiance and importance").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Transport {
    /// Radiance (paths from the camera): the BTDF carries s = (n_wo / n_wi)^2, the (eta')^-2 of
    /// Walter et al. 2007 eq. 21 and pbrt-v4's `TransportMode::Radiance`.
    Radiance,
    /// Importance (paths from the lights, photon mapping): s = 1; the adjoint of
    /// [`Transport::Radiance`], f_importance(wo, wi) = f_radiance(wi, wo).
    Importance,
}

/// True where eta is in (0, MAX] (false for NaN, 0, negatives and +inf).
#[inline]
fn eta_ok<T: Real>(eta: T) -> T::Mask {
    eta.simd_gt(T::ZERO) & eta.simd_lt(T::INFINITY)
}

/// eta' = n_wi / n_wo of a pair on opposite sides, from wo.z: eta where wo is outside, 1 / eta
/// where it is inside.
#[inline]
fn eta_rel<T: Real>(wo_z: T, eta: T) -> T {
    T::select(wo_z.simd_lt(T::ZERO), eta.recip(), eta)
}

/// The (unnormalized, unflipped) generalized half vector as a positive multiple of
/// wo + eta' wi: wi + wo / eta' where eta' > 1, so that neither term overflows for any eta in
/// (0, MAX].
#[inline]
fn raw_half<T: Real>(wo: V3<T>, wi: V3<T>, etap: T) -> V3<T> {
    let big = etap.simd_gt(T::ONE);
    V3::select(big, wi + wo * etap.recip(), wi * etap + wo)
}

/// The generalized half vector of a pair, its eta' and whether the pair is a reflection.
/// h is (0, 0, 1) where wo + eta' wi is the zero vector (then `degenerate` holds).
#[inline]
fn half_parts<T: Real>(wo: V3<T>, wi: V3<T>, eta: T) -> (V3<T>, T, T::Mask, T::Mask) {
    let reflect = (wo.z * wi.z).simd_gt(T::ZERO);
    let etap = T::select(reflect, T::ONE, eta_rel(wo.z, eta));
    let raw = raw_half(wo, wi, etap);
    let degenerate = is_zero3(raw);
    let h = raw.normalize_or(V3::unit_z());
    let h = V3::select(h.z.simd_lt(T::ZERO), -h, h);
    (h, etap, reflect, degenerate)
}

/// The generalized half vector h = +-normalize(wo + eta' wi) with h.z >= 0 (Walter et al. 2007,
/// eq. 16; module docs): eta' = 1 where wo and wi lie on the same side (wo.z wi.z > 0, the
/// usual half vector of reflection), else the index on wi's side over that on wo's (eta for wo
/// outside, 1 / eta for wo inside). It is the facet normal that reflects or refracts wo into wi.
///
/// Domain: wo, wi unit local-frame vectors; eta in (0, MAX], finite (= n_inside / n_outside).
/// Edges: where wo + eta' wi is the zero vector (wi = -wo with eta = 1; a zero-length
/// direction pair) h is (0, 0, 1); a pair on opposite sides whose h has h.wo h.wi >= 0 is no
/// refraction pair, and h is returned anyway (the BSDF is 0 there). NaN or an infinite
/// component in wo or wi, NaN eta and eta outside (0, MAX] give a NaN vector.
///
/// ```
/// # #[cfg(feature = "ggx")] {
/// use brdf::{V3, rough_dielectric::half_vector};
/// // A ray from above refracted into glass (eta 1.5) along the facet normal n_f:
/// let wo = V3::new(0.6_f64, 0.0, 0.8);
/// let h = half_vector(wo, V3::new(-0.4, 0.0, -(1.0_f64 - 0.16).sqrt()), 1.5);
/// assert!(h.z > 0.0 && (h.length() - 1.0).abs() < 1e-12);
/// # }
/// ```
#[inline]
#[must_use]
pub fn half_vector<T: Real>(wo: V3<T>, wi: V3<T>, eta: T) -> V3<T> {
    let (h, _, _, _) = half_parts(wo, wi, eta);
    let bad = any_nonfinite3(wo) | any_nonfinite3(wi) | !eta_ok(eta);
    V3::select(bad, V3::splat(T::splat(f64::NAN)), h)
}

/// Product of two finite non-negative factors capped at MAX (never inf, so a later factor 0
/// gives 0, not NaN).
#[inline]
fn cap_mul<T: Real>(a: T, b: T) -> T {
    (a * b).min(T::MAX)
}

/// What both lobes of a direction pair share: the generalized half vector and its parts
/// ([`half_parts`]), the cosines with h, D(h), the height-correlated G2 and 1 / |wo.z wi.z|.
struct Pair<T: Real> {
    h: V3<T>,
    etap: T,
    reflect: T::Mask,
    /// Each direction sees the facet's own side (a facet seen from behind neither reflects
    /// nor refracts between them; this also drops the zero vectors, cosine 0), h is not
    /// degenerate, and eta != 1.
    live: T::Mask,
    co: T,
    o_h: T,
    i_h: T,
    d: T,
    g2: T,
    inv_cos: T,
}

#[inline]
fn pair<T: Real, M: Microfacet<T> + ?Sized>(dist: &M, wo: V3<T>, wi: V3<T>, eta: T) -> Pair<T> {
    let (h, etap, reflect, degenerate) = half_parts(wo, wi, eta);
    let (co, ci) = (wo.z, wi.z);
    let (o_h, i_h) = (wo.dot(h), wi.dot(h));
    let facing = (o_h * co).simd_gt(T::ZERO) & (i_h * ci).simd_gt(T::ZERO);
    Pair {
        h,
        etap,
        reflect,
        live: facing & !degenerate & (eta - T::ONE).abs().simd_gt(T::ZERO),
        co,
        o_h,
        i_h,
        d: dist.d(h),
        g2: (T::ONE + dist.lambda(wo) + dist.lambda(wi)).recip(),
        inv_cos: (co.abs() * ci.abs()).recip().min(T::MAX),
    }
}

/// The value of both lobes at a pair: (f, pdf) for `eval` and `pdf`, sharing one half vector.
#[inline]
fn lobes<T: Real, M: Microfacet<T> + ?Sized>(
    dist: &M,
    wo: V3<T>,
    wi: V3<T>,
    eta: T,
    transport: Transport,
) -> (T, T) {
    let Pair {
        h,
        etap,
        reflect,
        live,
        co,
        o_h,
        i_h,
        d,
        g2,
        inv_cos,
    } = pair(dist, wo, wi, eta);
    let f_r = fresnel::dielectric(o_h, eta);
    let t = T::ONE - f_r;
    // Reflection: D G2 F / (4 |co| |ci|).
    let fr = cap_mul(cap_mul(d * g2, f_r), T::splat(0.25) * inv_cos);
    // Transmission: D G2 T |i.h| |o.h| / (|ci| |co| (i.h + o.h / eta')^2) times s.
    let (dwh, s) = refraction_jacobian(o_h, i_h, etap, transport);
    let ft = cap_mul(
        cap_mul(cap_mul(d * g2, t), cap_mul(o_h.abs(), inv_cos)),
        dwh,
    );
    let ft = cap_mul(ft, s);
    let f = T::select(live, T::select(reflect, fr, ft), T::ZERO);
    // pdf: the visible-normal density of the facet as seen from wo's side, times the lobe's
    // Jacobian and the probability of choosing that lobe (F or 1 - F).
    let wo_up = V3::select(co.simd_lt(T::ZERO), -wo, wo);
    let pm = dist.d_visible(wo_up, h);
    let pr = cap_mul(
        cap_mul(pm, (T::splat(4.0) * o_h.abs()).recip().min(T::MAX)),
        f_r,
    );
    let pt = cap_mul(cap_mul(pm, dwh), t);
    let p = T::select(live, T::select(reflect, pr, pt), T::ZERO);
    let bad = any_nonfinite3(wo) | any_nonfinite3(wi) | !eta_ok(eta);
    (
        nan_where(bad | f.is_nan(), f),
        nan_where(bad | p.is_nan(), p),
    )
}

/// Walter et al. 2007's BTDF without its Fresnel factor, for the glTF composition that
/// weighs it by a Schlick factor of its own (`transmission::dielectric_bsdf`):
/// (D(h) G2 |wi.h| |wo.h| / (|wi.z| |wo.z| (wi.h + wo.h / eta')^2) s, wo.h), 0 where the pair
/// is no refraction pair (same side, back-facing h, degenerate h, eta = 1). Finite inputs
/// only (the caller applies the NaN rule).
#[cfg_attr(not(feature = "ggx"), allow(dead_code))]
#[inline]
pub(crate) fn btdf_without_fresnel<T: Real, M: Microfacet<T> + ?Sized>(
    dist: &M,
    wo: V3<T>,
    wi: V3<T>,
    eta: T,
    transport: Transport,
) -> (T, T) {
    let Pair {
        etap,
        reflect,
        live,
        o_h,
        i_h,
        d,
        g2,
        inv_cos,
        ..
    } = pair(dist, wo, wi, eta);
    let (dwh, s) = refraction_jacobian(o_h, i_h, etap, transport);
    let ft = cap_mul(cap_mul(d * g2, cap_mul(o_h.abs(), inv_cos)), dwh);
    (T::select(live & !reflect, cap_mul(ft, s), T::ZERO), o_h)
}

/// d(omega_h) / d(omega_i) = |i.h| / (i.h + o.h / eta')^2 (Walter et al. 2007 eq. 17), capped
/// at MAX, formed as |i.h| eta'^2 / (eta' i.h + o.h)^2 where eta' < 1 so that o.h / eta'
/// cannot overflow; and the transport factor s (1 / eta'^2 for radiance, capped; 1).
#[inline]
fn refraction_jacobian<T: Real>(o_h: T, i_h: T, etap: T, transport: Transport) -> (T, T) {
    let small = etap.simd_lt(T::ONE);
    let sum = T::select(small, etap.mul_add(i_h, o_h), i_h + o_h / etap);
    let num = T::select(small, cap_mul(i_h.abs(), etap * etap), i_h.abs());
    let dwh = T::select(
        sum.simd_eq(T::ZERO),
        T::ZERO,
        (num / (sum * sum)).min(T::MAX),
    );
    let s = match transport {
        Transport::Radiance => etap.recip().min(T::MAX).sq().min(T::MAX),
        Transport::Importance => T::ONE,
    };
    (dwh, s)
}

/// The rough dielectric BSDF f(wo, wi), reflection and transmission together (Walter et al.
/// 2007, eq. 20 and 21; module docs for the formula, the conventions and `transport`):
/// f = D(h) G2 F / (4 |wo.z| |wi.z|) for wo, wi on the same side, and
/// f = s D(h) G2 (1 - F) |wi.h| |wo.h| / (|wi.z| |wo.z| (wi.h + wo.h / eta')^2) across the
/// interface, with h = [`half_vector`]`(wo, wi, eta)` and F = `fresnel::dielectric(wo.h, eta)`.
/// Multiply by |wi.z| for the scattering integrand. Cross-checked against pbrt-v4's
/// `DielectricBxDF::f` (`src/pbrt/bxdfs.cpp`) and Mitsuba 3's `roughdielectric` plugin.
///
/// Domain: wo, wi unit local-frame vectors anywhere on the sphere; eta in (0, MAX], finite.
/// Edges: 0 where either direction lies on the horizon or is the zero vector, where a
/// direction sees the back of the facet h, under total internal reflection for the
/// transmitted pair (F = 1), and everywhere for eta = 1 (a Dirac pass-through, module docs,
/// "Edges"); capped at the largest finite value (the peak of a mirror-like lobe at grazing
/// angles). NaN or an infinite component in wo or wi, NaN eta, and eta outside (0, MAX]
/// give NaN.
///
/// ```
/// # #[cfg(feature = "ggx")] {
/// use brdf::rough_dielectric::{Transport, eval};
/// use brdf::{V3, ggx::Ggx};
/// let ggx = Ggx::isotropic(0.3).unwrap();
/// let (wo, wi) = (V3::new(0.0_f64, 0.6, 0.8), V3::new(0.0, -0.3, -(0.91_f64).sqrt()));
/// let rad = eval(&ggx, wo, wi, 1.5, Transport::Radiance);
/// let imp = eval(&ggx, wo, wi, 1.5, Transport::Importance);
/// assert!(rad > 0.0 && ((imp / rad) - 1.5 * 1.5).abs() < 1e-12); // s = 1 / eta'^2
/// # }
/// ```
#[inline]
#[must_use]
pub fn eval<T: Real, M: Microfacet<T> + ?Sized>(
    dist: &M,
    wo: V3<T>,
    wi: V3<T>,
    eta: T,
    transport: Transport,
) -> T {
    lobes(dist, wo, wi, eta, transport).0
}

/// pdf (solid angle) of `ggx_sample` and `beckmann_sample` at wi, both lobes combined, for
/// multiple importance sampling: with h = [`half_vector`]`(wo, wi, eta)`, F = F(wo.h) and
/// D_v(h) the visible-normal density seen from wo's side (`Microfacet::d_visible` of
/// sign(wo.z) wo),
/// pdf = F D_v(h) / (4 |wo.h|) for wi on wo's side (Walter et al. 2007 eq. 14), and
/// pdf = (1 - F) D_v(h) |wi.h| / (wi.h + wo.h / eta')^2 across the interface (eq. 17).
///
/// Domain: unit vectors, eta in (0, MAX] finite. Integrates over the sphere of wi to the
/// probability that the sampler returns a live sample (a reflection that stays on wo's side
/// or a refraction that crosses), at most 1. Edges: 0 where [`eval`] is 0 by an edge (horizon,
/// zero vector, back-facing h, eta = 1); capped at the largest finite value. NaN as [`eval`].
#[inline]
#[must_use]
pub fn pdf<T: Real, M: Microfacet<T> + ?Sized>(dist: &M, wo: V3<T>, wi: V3<T>, eta: T) -> T {
    lobes(dist, wo, wi, eta, Transport::Importance).1
}

/// Refraction of wo through the facet normal m (Snell's law in vector form; Walter et al. 2007
/// eq. 40): wi = (wo.m / eta_t - cos_t) n - wo / eta_t with n = m on wo's side of the facet
/// and eta_t the relative index across it, evaluated as the positive multiple
/// n (c - eta_t cos_t) - wo (no division by eta_t) and normalized. Returns wi and whether the
/// light is totally reflected instead (sin^2 theta_t >= 1).
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn refract<T: Real>(wo: V3<T>, m: V3<T>, eta: T) -> (V3<T>, T::Mask) {
    let c = wo.dot(m);
    let back = c.simd_lt(T::ZERO);
    let eta_t = T::select(back, eta.recip(), eta);
    let n = V3::select(back, -m, m);
    let c = c.abs().min(T::ONE);
    let sin2_i = ((T::ONE - c) * (T::ONE + c)).max(T::ZERO);
    let e2 = eta_t * eta_t;
    // sin^2_t = sin^2_i / eta_t^2 >= 1; written as a product so that an eta_t^2 that
    // underflows to 0 gives total reflection, not 0 / 0.
    let tir = sin2_i.simd_ge(e2) & sin2_i.simd_gt(T::ZERO);
    let sin2_t = T::select(tir, T::ONE, sin2_i / e2.max(T::MIN_POSITIVE)).min(T::ONE);
    let cos_t = (T::ONE - sin2_t).sqrt_nonneg();
    let wi = n * (c - eta_t.min(T::MAX) * cos_t) - wo;
    (wi.normalize_or(-n), tir)
}

/// The shared body of the samplers, from a visible facet normal m drawn for wo's side.
#[cfg(any(feature = "ggx", feature = "beckmann"))]
#[inline]
fn sample_from_normal<T: Real, M: Microfacet<T> + ?Sized>(
    dist: &M,
    wo: V3<T>,
    m: V3<T>,
    eta: T,
    u0: T,
    transport: Transport,
) -> (V3<T>, T, T) {
    let u0 = u0.clamp(T::ZERO, T::ONE - T::EPSILON * T::HALF);
    let o_m = wo.dot(m);
    let f_r = fresnel::dielectric(o_m, eta);
    let wr = m * (T::TWO * o_m) - wo;
    let (wt, _) = refract(wo, m, eta);
    // Reflection with probability F (F = 1 under total internal reflection).
    let choose_r = u0.simd_lt(f_r);
    let wi = V3::select(choose_r, wr, wt);
    // A live sample: a reflection that stays on wo's side, a refraction that crosses.
    let same = (wo.z * wi.z).simd_gt(T::ZERO);
    let cross = (wo.z * wi.z).simd_lt(T::ZERO);
    let live = (choose_r & same) | (!choose_r & cross);
    let p = pdf(dist, wo, wi, eta);
    // weight = f |wi.z| / pdf = G2 / G1(wo) = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)),
    // times s for a refraction in radiance transport.
    let lo = T::ONE + dist.lambda(wo);
    let ratio = lo / (lo + dist.lambda(wi));
    let s = match transport {
        Transport::Radiance => eta_rel(wo.z, eta).recip().min(T::MAX).sq().min(T::MAX),
        Transport::Importance => T::ONE,
    };
    let w = T::select(choose_r, ratio, cap_mul(ratio, s));
    let keep = live & p.simd_gt(T::ZERO);
    let (p, w) = (T::select(keep, p, T::ZERO), T::select(keep, w, T::ZERO));
    // Decided before the pass-through below replaces p: a NaN sample or alpha reaches m.
    let bad = any_nonfinite3(wo) | any_nonfinite3(m) | u0.is_nan() | !eta_ok(eta);
    let bad = bad | p.is_nan() | w.is_nan();
    // eta = 1: the Dirac pass-through (module docs, "Edges").
    let matched = eta.simd_eq(T::ONE) & !is_zero3(wo);
    let wi = V3::select(matched, -wo, wi);
    let p = T::select(matched, T::MAX, p);
    let w = T::select(matched, T::ONE, w);
    let nan = T::splat(f64::NAN);
    (
        V3::select(bad, V3::splat(nan), wi),
        T::select(bad, nan, p),
        nan_unless(!bad, w),
    )
}

/// Samples the rough dielectric BSDF of a GGX interface and returns (wi, pdf, weight): a
/// visible facet normal m for wo's side (`sampling::ggx_vndf_spherical_cap` of sign(wo.z) wo;
/// Heitz 2018, "Sampling the GGX Distribution of Visible Normals"; Dupuy and Benyoub 2023),
/// reflection wi = 2 (wo.m) m - wo where u0 < F(wo.m) and refraction through m otherwise
/// (Walter et al. 2007, section 5.3, choosing the lobe by Fresnel), the combined pdf of both
/// lobes [`pdf`]`(ggx, wo, wi, eta)` (the same value, bit for bit), and the weight
/// f |wi.z| / pdf = G2 / G1(wo) = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)), times
/// (n_wo / n_wi)^2 for a refraction in [`Transport::Radiance`] (module docs, "Sampling").
///
/// u0 picks the lobe, u1 and u2 the facet normal (as `sampling::ggx_vndf_spherical_cap`); each
/// is clamped into [0, 1). Domain: wo a unit vector on either side of the surface; eta in
/// (0, MAX], finite. Edges: a reflection that leaves through the surface's other side or a
/// refraction that stays on wo's side (grazing views, steep facets) is returned as drawn with
/// pdf 0 and weight 0 (no sample; pbrt-v4 returns none there); under total internal
/// reflection F = 1, so only reflection is drawn; eta = 1 returns wi = -wo, weight 1 and
/// pdf `T::MAX` (the Dirac pass-through, module docs "Edges"); wo on the horizon or the
/// zero vector gives pdf 0 and weight 0. NaN or an infinite component in wo, a NaN sample,
/// NaN eta and eta outside (0, MAX] give a NaN wi (all three components), pdf and weight.
///
/// ```
/// use brdf::rough_dielectric::{Transport, ggx_sample, pdf};
/// use brdf::{V3, ggx::Ggx};
/// let ggx = Ggx::isotropic(0.2).unwrap();
/// let wo = V3::new(0.6_f64, 0.0, 0.8);
/// let (wi, p, w) = ggx_sample(&ggx, wo, 1.5, 0.9, 0.3, 0.6, Transport::Importance);
/// assert!(wi.z < 0.0 && p > 0.0 && w > 0.0 && w <= 1.0); // u0 = 0.9 > F: refracted
/// assert_eq!(p, pdf(&ggx, wo, wi, 1.5));
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn ggx_sample<T: Real>(
    ggx: &Ggx<T>,
    wo: V3<T>,
    eta: T,
    u0: T,
    u1: T,
    u2: T,
    transport: Transport,
) -> (V3<T>, T, T) {
    let wo_up = V3::select(wo.z.simd_lt(T::ZERO), -wo, wo);
    let (m, _) = crate::sampling::ggx_vndf_spherical_cap(ggx, wo_up, u1, u2);
    sample_from_normal(ggx, wo, m, eta, u0, transport)
}

/// [`ggx_sample`] for a Beckmann interface: the visible facet normal from
/// `sampling::beckmann_vndf` of sign(wo.z) wo (Heitz and d'Eon 2014, "Importance Sampling
/// Microfacet-Based BSDFs using the Distribution of Visible Normals"), then the same lobe
/// choice, pdf ([`pdf`]`(beckmann, wo, wi, eta)`, bit for bit), weight, domain and edges.
///
/// ```
/// use brdf::rough_dielectric::{Transport, beckmann_sample};
/// use brdf::{V3, beckmann::Beckmann};
/// let b = Beckmann::isotropic(0.2).unwrap();
/// // From inside glass, beyond the critical angle (41.8 degrees): every sample reflects.
/// let wo = V3::new(0.9_f64, 0.0, -(0.19_f64).sqrt());
/// let (wi, p, w) = beckmann_sample(&b, wo, 1.5, 0.99, 0.5, 0.5, Transport::Radiance);
/// assert!(wi.z < 0.0 && p > 0.0 && w > 0.0);
/// ```
#[cfg(feature = "beckmann")]
#[inline]
#[must_use]
pub fn beckmann_sample<T: Real>(
    beckmann: &Beckmann<T>,
    wo: V3<T>,
    eta: T,
    u0: T,
    u1: T,
    u2: T,
    transport: Transport,
) -> (V3<T>, T, T) {
    let wo_up = V3::select(wo.z.simd_lt(T::ZERO), -wo, wo);
    let (m, _) = crate::sampling::beckmann_vndf(beckmann, wo_up, u1, u2);
    sample_from_normal(beckmann, wo, m, eta, u0, transport)
}
