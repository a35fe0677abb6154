//! Diffuse-Fresnel couplings: how much of a diffuse lobe survives a specular interface.
//!
//! Light that a specular layer reflects (fraction F) never reaches the diffuse substrate, so
//! renderers scale the diffuse lobe by a Fresnel complement. The forms differ in reciprocity
//! and energy:
//!
//! | form | reciprocal | diffuse + specular albedo (rho = 1, specular albedo <= F(n.v)) |
//! |---|---|---|
//! | [`fresnel_weight_normalized`]: (1 - F(wi)) / (1 - F0) | no | exceeds 1: up to 1.948 |
//! | [`fresnel_weight_symmetric`]: (1 - F(wi)) (1 - F(wo)) | yes | <= 1 (max 0.9993) |
//! | [`shirley_coupled`]: Shirley et al. 1997 | yes | <= 1, = 1 with a Fresnel mirror |
//! | [`ashikhmin_shirley`]: Ashikhmin and Shirley 2000 | yes | <= 1 (max 0.9978) |
//! | [`fresnel_mix`] with F(n.v) | no | <= 1 (a convex mix of albedos) |
//! | [`fresnel_mix`] with F(v.h) | yes | not guaranteed (0.99996 with a Phong lobe) |
//!
//! Figures: Schlick F with F0 in {0.04, 0.2, 0.5}, theta_o up to 89.9 deg, the specular lobe a
//! perfect Fresnel mirror (albedo F(n.v)) or F(n.v) times a normalized Phong lobe (n = 20);
//! the worst of the two is shown. The one-sided weight's diffuse albedo is 20/21 at every
//! view angle, so adding the mirror's F(n.v) gives 1.948 at 89.9 deg.
//!
//! The weights take Fresnel values as plain numbers so that any Fresnel (Schlick, exact
//! dielectric, conductor) and any cosine convention can be used; the Schlick forms are
//! conveniences. Measured figures: `cargo test --no-default-features --features
//! diffuse,integrate --test diffuse -- --nocapture coupling_energy:: coupling_reciprocity::`.
//! Precision: f32 within 2.4e-7 of f64 for every function here (absolute, on unit-scale inputs),
//! lanes bit-identical to scalars (`--test diffuse coupling_stability::`).

use crate::domain::{above_horizon, checked_unit, in_unit, nan_unless};
use crate::error::{ParamError, require};
use crate::fresnel::schlick;
use crate::real::Real;
use crate::vec3::V3;

/// Both in [0, 1] (false for NaN).
#[inline]
fn unit_pair<T: Real>(a: T, b: T) -> T::Mask {
    in_unit(a) & in_unit(b)
}

/// The one-sided diffuse weight w = (1 - F(wi)) / (1 - F0): the light that enters the surface
/// through the interface at wi, renormalized so that the weight is 1 at normal incidence
/// (where F = F0). Multiply a diffuse lobe by it.
///
/// `fresnel_l` is F(wi), evaluated at whatever cosine the caller chooses (n.l for a smooth
/// interface, l.h for a microfacet one). With Schlick's F at n.l the weight is
/// 1 - (1 - n.l)^5 for every F0.
///
/// Not reciprocal: it depends on wi alone, so lambert x w gives f(wo, wi) != f(wi, wo)
/// wherever F(wi) != F(wo); with Schlick at n.l the relative asymmetry reaches 0.99995 (cosines
/// 1 and 1e-5; `--test diffuse coupling_reciprocity::`). Nor does it bound energy: it ignores
/// the light the specular lobe takes at wo, so with a Fresnel mirror on top the albedo reaches
/// 20/21 + F(n.v), 1.948 at 89.9 deg (`--test diffuse coupling_energy::`).
///
/// Domain: `fresnel_l` in [0, 1], `f0` in [0, 1) (NaN outside; a metal, F0 = 1, has no
/// diffuse lobe to weight). Output in [0, 1 / (1 - F0)].
#[inline]
#[must_use]
pub fn fresnel_weight_normalized<T: Real>(fresnel_l: T, f0: T) -> T {
    let f0_ok = f0.simd_ge(T::ZERO) & f0.simd_lt(T::ONE);
    (T::ONE - checked_unit(fresnel_l)) / (T::ONE - nan_unless(f0_ok, f0))
}

/// The symmetric diffuse weight w = (1 - F(wi)) (1 - F(wo)): light enters through the
/// interface at wi and leaves through it at wo. Reciprocal (symmetric in wi and wo), and
/// lambert x w has directional albedo <= rho (1 - F(wo)), so a specular lobe of albedo
/// <= F(wo) added to it keeps the sum <= 1.
///
/// The Fresnel values are plain numbers (any Fresnel, any cosine). Unnormalized, this weight
/// loses the light that the interface reflects back down (the albedo is rho (1 - F(wo)) times
/// a hemispherical average of 1 - F(wi), not rho (1 - F(wo))); [`shirley_coupled`] and
/// [`ashikhmin_shirley`] are its normalized Schlick forms.
///
/// Source: the coupled form of Shirley, Hu, Smits and Lafortune 1997, "A Practitioners'
/// Assessment of Light Reflection Models", Pacific Graphics.
///
/// Domain: both Fresnel values in [0, 1] (NaN outside). Output in [0, 1].
#[inline]
#[must_use]
pub fn fresnel_weight_symmetric<T: Real>(fresnel_v: T, fresnel_l: T) -> T {
    (T::ONE - checked_unit(fresnel_v)) * (T::ONE - checked_unit(fresnel_l))
}

/// The Fresnel mix f = (1 - F) f_diffuse + F f_specular: the specular lobe takes the fraction F
/// and the diffuse lobe the rest.
///
/// With F = F(n.v) (a view-dependent weight, as in many real-time engines) the directional
/// albedo is the convex combination (1 - F) a_d(wo) + F a_s(wo), so it is <= 1 whenever both
/// lobes' albedos are; but f(wo, wi) != f(wi, wo) (not reciprocal), because the weights
/// follow wo alone. With F = F(v.h) = F(l.h) the mix is reciprocal when both lobes are, but
/// the albedo bound is lost (F varies over wi, so the mix is no convex combination of
/// albedos).
///
/// Domain: `fresnel` in [0, 1]; `f_diffuse` and `f_specular` finite and >= 0, up to the
/// largest finite float; NaN outside these domains and for NaN input. Evaluated as
/// f_diffuse + F (f_specular - f_diffuse): the difference of two non-negative floats cannot
/// overflow, and the result stays within [min, max] of the two values up to one rounding of
/// that difference (one ulp), so it is finite and non-negative.
#[inline]
#[must_use]
pub fn fresnel_mix<T: Real>(f_diffuse: T, f_specular: T, fresnel: T) -> T {
    let lobe_ok = |f: T| f.simd_ge(T::ZERO) & f.is_finite();
    nan_unless(
        lobe_ok(f_diffuse) & lobe_ok(f_specular),
        checked_unit(fresnel).mul_add(f_specular - f_diffuse, f_diffuse),
    )
}

/// [`fresnel_mix`] with Schlick's F = F0 + (1 - F0)(1 - c)^5 ([`schlick`]) at `cos_theta`:
/// pass n.v for the view-dependent (non-reciprocal, energy-bounded) mix or v.h for the
/// reciprocal one.
///
/// Domain: `f0` in [0, 1] (NaN outside); `cos_theta` clamped into [0, 1].
#[inline]
#[must_use]
pub fn fresnel_mix_schlick<T: Real>(f_diffuse: T, f_specular: T, f0: T, cos_theta: T) -> T {
    fresnel_mix(f_diffuse, f_specular, schlick(checked_unit(f0), cos_theta))
}

/// 21 / (20 pi): 1 / integral of (1 - (1 - cos)^5) cos over the hemisphere, since
/// integral_0^1 (1 - c)^5 c dc = 1/42 gives 2 pi (1/2 - 1/42) = 20 pi / 21.
const SHIRLEY_NORM: f64 = 21.0 / (20.0 * core::f64::consts::PI);

/// 28 / (23 pi): 1 / integral of (1 - (1 - cos/2)^5) cos over the hemisphere, since
/// integral_0^1 (1 - c/2)^5 c dc = 5/56 gives 2 pi (1/2 - 5/56) = 23 pi / 28.
const ASHIKHMIN_SHIRLEY_NORM: f64 = 28.0 / (23.0 * core::f64::consts::PI);

/// Shirley et al.'s coupled diffuse under a smooth Schlick interface:
///
/// f = 21 / (20 pi) rho (1 - F0) (1 - (1 - n.l)^5) (1 - (1 - n.v)^5),
///
/// the symmetric weight (1 - F(n.l))(1 - F(n.v)) with Schlick's F, divided by (1 - F0) and
/// normalized so that the directional albedo is exactly rho (1 - F(n.v)): all the light the
/// interface transmits comes back out. So with a specular lobe of albedo <= F(n.v) (a Fresnel
/// mirror, or any lobe of albedo <= 1 scaled by F(n.v)) the sum stays <= 1. Reciprocal.
///
/// Domain: rho in [0, 1], f0 in [0, 1] (NaN outside, for every direction); 0 where
/// `n_dot_v <= 0` or `n_dot_l <= 0`; cosines above 1 are clamped to 1. Output in
/// [0, 21 rho (1 - F0) / (20 pi)].
///
/// Source: Shirley, Hu, Smits and Lafortune 1997, "A Practitioners' Assessment of Light
/// Reflection Models", Pacific Graphics (also Akenine-Moller et al. 2018, "Real-Time
/// Rendering", 4th ed., eq. 9.64).
#[inline]
#[must_use]
pub fn shirley_coupled<T: Real>(n_dot_v: T, n_dot_l: T, rho: T, f0: T) -> T {
    let t = |c: T| T::ONE - (T::ONE - c.saturate()).powi(5);
    let scale = rho * (T::ONE - f0) * T::splat(SHIRLEY_NORM);
    // The parameter check wraps the horizon cut, so a bad parameter is NaN on every direction.
    nan_unless(
        unit_pair(rho, f0),
        above_horizon(n_dot_v, n_dot_l, scale * t(n_dot_l) * t(n_dot_v)),
    )
}

/// Ashikhmin and Shirley's coupled diffuse term:
///
/// f = 28 / (23 pi) rho (1 - Rs) (1 - (1 - n.l / 2)^5) (1 - (1 - n.v / 2)^5),
///
/// with Rs the specular reflectance at normal incidence (Schlick's F0), and 28 / (23 pi)
/// normalizing each factor's cosine-weighted hemispherical integral to 1. The directional
/// albedo is rho (1 - Rs)(1 - (1 - n.v/2)^5); the halved cosine makes that factor at most
/// 1 - (1 - n.v)^5 = (1 - F(n.v)) / (1 - Rs) for Schlick's F, so the albedo stays
/// <= rho (1 - F(n.v)) and a specular lobe of albedo <= F(n.v) added to it keeps the sum
/// <= 1. Reciprocal.
///
/// Domain: rho in [0, 1], rs in [0, 1] (NaN outside, for every direction); 0 where
/// `n_dot_v <= 0` or `n_dot_l <= 0`; cosines above 1 clamped. Output in
/// [0, 28 rho (1 - Rs) / (23 pi) (31/32)^2].
///
/// Source: Ashikhmin and Shirley 2000, "An Anisotropic Phong BRDF Model", Journal of Graphics
/// Tools 5(2), eq. 5.
#[inline]
#[must_use]
pub fn ashikhmin_shirley<T: Real>(n_dot_v: T, n_dot_l: T, rho: T, rs: T) -> T {
    let t = |c: T| T::ONE - (T::HALF.mul_add(-c.saturate(), T::ONE)).powi(5);
    let scale = rho * (T::ONE - rs) * T::splat(ASHIKHMIN_SHIRLEY_NORM);
    nan_unless(
        unit_pair(rho, rs),
        above_horizon(n_dot_v, n_dot_l, scale * t(n_dot_l) * t(n_dot_v)),
    )
}

/// Validates rho and a normal-incidence reflectance for the coupled lobes.
fn validate<T: Real>(rho: T, f0: T, name: &'static str) -> Result<(), ParamError> {
    require::<T>(in_unit(rho), "rho", "in [0, 1]")?;
    require::<T>(f0.simd_ge(T::ZERO) & f0.simd_le(T::ONE), name, "in [0, 1]")
}

/// Shirley et al.'s coupled diffuse ([`shirley_coupled`]) with validated rho and F0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShirleyCoupled<T> {
    rho: T,
    f0: T,
}

impl<T: Real> ShirleyCoupled<T> {
    /// The coupled diffuse of albedo rho under a Schlick interface of normal reflectance f0;
    /// both must lie in [0, 1] in every lane, else [`ParamError`].
    pub fn new(rho: T, f0: T) -> Result<Self, ParamError> {
        validate(rho, f0, "f0")?;
        Ok(Self { rho, f0 })
    }

    /// The substrate albedo rho.
    #[inline]
    #[must_use]
    pub fn rho(&self) -> T {
        self.rho
    }

    /// The interface's normal-incidence reflectance F0.
    #[inline]
    #[must_use]
    pub fn f0(&self) -> T {
        self.f0
    }

    /// f(wo, wi) of [`shirley_coupled`] on local-frame unit vectors (normal = +z); NaN where
    /// any component of wo or wi is NaN or infinite.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        super::nan_if_nan_dir(wo, wi, shirley_coupled(wo.z, wi.z, self.rho, self.f0))
    }
}

/// Ashikhmin and Shirley's coupled diffuse ([`ashikhmin_shirley`]) with validated rho and Rs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AshikhminShirley<T> {
    rho: T,
    rs: T,
}

impl<T: Real> AshikhminShirley<T> {
    /// The coupled diffuse of albedo rho under a specular layer of normal reflectance rs;
    /// both must lie in [0, 1] in every lane, else [`ParamError`].
    pub fn new(rho: T, rs: T) -> Result<Self, ParamError> {
        validate(rho, rs, "rs")?;
        Ok(Self { rho, rs })
    }

    /// The diffuse albedo rho (the paper's Rd).
    #[inline]
    #[must_use]
    pub fn rho(&self) -> T {
        self.rho
    }

    /// The specular normal-incidence reflectance Rs.
    #[inline]
    #[must_use]
    pub fn rs(&self) -> T {
        self.rs
    }

    /// f(wo, wi) of [`ashikhmin_shirley`] on local-frame unit vectors (normal = +z); NaN where
    /// any component of wo or wi is NaN or infinite.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        super::nan_if_nan_dir(wo, wi, ashikhmin_shirley(wo.z, wi.z, self.rho, self.rs))
    }
}
