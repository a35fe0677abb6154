//! Burley's diffuse (the Disney diffuse) and Lagarde and de Rousiers' renormalized form.
//!
//! Both take the *perceptual* roughness r in [0, 1], the artist-facing slider of the Disney
//! and Frostbite material models, whose GGX width is alpha = r^2. Pass r, not alpha.
//!
//! Neither lobe conserves energy exactly. Directional albedo with rho = 1, by adaptive
//! cubature, and the grazing limit theta_o -> 90 deg in closed form (`cargo test
//! --no-default-features --features diffuse,integrate --test diffuse burley_energy:: --
//! --nocapture`):
//!
//! | form | r | 0 deg | 60 deg | 80 deg | 89.99 deg | limit at 90 deg |
//! |---|---|---|---|---|---|---|
//! | Burley | 0 | 0.9762 | 0.9609 | 0.7881 | 0.4885 | 0.4881 |
//! | Burley | 0.4 | 1.0000 | 0.9987 | 0.9768 | 0.8993 | 0.8992 |
//! | Burley | 0.6 | 1.0119 | 1.0179 | 1.0745 | 1.1131 | 1.1131 |
//! | Burley | 1 | 1.0357 | 1.0569 | 1.2767 | 1.5572 | 1.5575 |
//! | renormalized | 0 | 0.9524 | 0.9226 | 0.5854 | 0.0008 | 0 |
//! | renormalized | 0.6 | 0.7992 | 0.7990 | 0.7876 | 0.7206 | 0.7205 |
//! | renormalized | 0.9 | 0.7151 | 0.7260 | 0.8373 | 0.9674 | 0.9676 |
//! | renormalized | 1 | 0.6859 | 0.6999 | 0.8455 | 1.0313 | 1.0315 |
//!
//! Closed forms: at normal incidence Burley's albedo is 1 + (5 r - 2) / 84 and the
//! renormalized one (1 + (7 r - 4) / 84) k with k = 1 - r (1 - 1/1.51); at grazing both are
//! k (a + (a^2 - a) / 21 + 11 r^2 / 504) with a = 1/2 + r (Burley, k = 1) or a = 3 r / 2.
//!
//! So Burley's diffuse adds energy for r > 0.4 (head-on) or r > 0.5 (grazing), up to 56% at
//! r = 1. The renormalization divides r = 1 by 1.51, slightly less than Burley's grazing
//! albedo 1.5575 there, so it still exceeds 1 for r above about 0.95 near grazing (by 3.1%
//! at r = 1); elsewhere it stays below 1, and well below: 0.69 head-on at r = 1, and towards
//! 0 at grazing for r = 0, where its F_D90 = 0.

use crate::domain::{above_horizon, in_unit, nan_unless};
use crate::dw::Dw;
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

/// Both parameters in [0, 1] (false for NaN).
#[inline]
fn params_ok<T: Real>(rho: T, roughness: T) -> T::Mask {
    rho.simd_ge(T::ZERO)
        & rho.simd_le(T::ONE)
        & roughness.simd_ge(T::ZERO)
        & roughness.simd_le(T::ONE)
}

/// cos^2(theta_d) from the half-angle identity cos^2(theta_d) = (1 + wo.wi) / 2, which needs
/// no half vector: normalizing wo + wi would divide by zero for opposite directions.
#[inline]
fn cos2_d_from_directions<T: Real>(wo: V3<T>, wi: V3<T>) -> T {
    ((T::ONE + wo.dot(wi)) * T::HALF).saturate()
}

/// (1 - c)^5 for c clamped into [0, 1], in double words: 1 - c is exact as a two-sum and
/// each of the three products rounds below the last place of the lane type.
#[inline]
fn one_minus_pow5<T: Real>(c: T) -> Dw<T> {
    let y = Dw::sum(T::ONE, -c.saturate());
    let y2 = y.mul(y);
    y2.mul(y2).mul(y)
}

/// Schlick's shape with F0 = 1: 1 + (F_D90 - 1)(1 - c)^5, given F_D90 - 1.
#[inline]
fn factor<T: Real>(fd90_minus_1: Dw<T>, c: T) -> Dw<T> {
    fd90_minus_1.mul(one_minus_pow5(c)).add(Dw::exact(T::ONE))
}

/// rho / pi k (1 + (F_D90 - 1)(1 - n.l)^5) (1 + (F_D90 - 1)(1 - n.v)^5) with the bad-input
/// rule: the whole product is carried in double words and rounded once.
#[inline]
fn assemble<T: Real>(
    n_dot_v: T,
    n_dot_l: T,
    fd90_minus_1: Dw<T>,
    k: Dw<T>,
    rho: T,
    roughness: T,
    cos2_d: T,
) -> T {
    let light = factor(fd90_minus_1, n_dot_l);
    let view = factor(fd90_minus_1, n_dot_v);
    let f = Dw::frac_1_pi()
        .mul(Dw::exact(rho))
        .mul(k)
        .mul(light)
        .mul(view)
        .value();
    // The parameter check wraps the horizon cut, so a bad parameter (or a NaN l.h, which the
    // cut would turn into 0) is NaN on every direction.
    nan_unless(
        params_ok(rho, roughness) & !cos2_d.is_nan(),
        above_horizon(n_dot_v, n_dot_l, f),
    )
}

/// Burley's lobe given cos^2(theta_d) in [0, 1] as a double word.
#[inline]
fn burley_core<T: Real>(n_dot_v: T, n_dot_l: T, cos2_d: Dw<T>, rho: T, roughness: T) -> T {
    // F_D90 - 1 = 2 r cos^2(theta_d) - 1/2 (2 r is exact).
    let a = cos2_d
        .mul(Dw::exact(T::TWO * roughness))
        .add(Dw::exact(-T::HALF));
    assemble(
        n_dot_v,
        n_dot_l,
        a,
        Dw::exact(T::ONE),
        rho,
        roughness,
        cos2_d.hi,
    )
}

/// Burley's diffuse BRDF (the diffuse lobe of the Disney principled BRDF):
///
/// f = rho / pi (1 + (F_D90 - 1)(1 - n.l)^5) (1 + (F_D90 - 1)(1 - n.v)^5),
/// F_D90 = 1/2 + 2 r cos^2(theta_d), cos(theta_d) = l.h,
///
/// with r the perceptual roughness (GGX alpha = r^2). Smooth surfaces (F_D90 < 1) darken at
/// grazing angles, rough ones (F_D90 > 1) brighten: a retro-reflective rim.
///
/// Domain: rho in [0, 1], roughness in [0, 1] (NaN outside, for every direction, and for
/// NaN). Cosines: 0 where
/// `n_dot_v <= 0` or `n_dot_l <= 0`; cosines above 1 and `l_dot_h` outside [0, 1] are clamped
/// into [0, 1]. Output in [0, 6.25 rho / pi] (the maximum at r = 1, both directions grazing,
/// l.h = 1).
///
/// Precision: the whole product is carried in double-word arithmetic (Dekker 1971) and
/// rounded once: within 0.7 ULP of the correctly rounded value on f32, f64, f32x8 and f64x4
/// (MPFR oracle, `cargo test -p brdf-oracle --release --test lobes -- --nocapture`; max 0.50
/// found by its deep search), and lanes bit-identical to scalars
/// (`--test diffuse burley_stability::`).
///
/// Not energy conserving: its directional albedo exceeds rho for r > 0.4, by up to 56% (1.5575
/// rho for r = 1 at grazing; see the module docs). Reciprocal: l.h = v.h.
///
/// Source: Burley 2012, "Physically-Based Shading at Disney", SIGGRAPH course notes,
/// section 5.3 (diffuse model details).
#[inline]
#[must_use]
pub fn burley<T: Real>(n_dot_v: T, n_dot_l: T, l_dot_h: T, rho: T, roughness: T) -> T {
    let lh = l_dot_h.saturate();
    burley_core(n_dot_v, n_dot_l, Dw::product(lh, lh), rho, roughness)
}

/// [`burley`] with the renormalization of Lagarde and de Rousiers (the Frostbite listing
/// `Fr_DisneyDiffuse`, divided by pi as their caller does):
///
/// f = rho / pi k (1 + (F_D90 - 1)(1 - n.l)^5) (1 + (F_D90 - 1)(1 - n.v)^5),
/// F_D90 = r / 2 + 2 r cos^2(theta_d), k = 1 + r (1 / 1.51 - 1),
///
/// i.e. their energyBias = lerp(0, 1/2, r) replaces Burley's constant 1/2 and their
/// energyFactor = lerp(1, 1/1.51, r) scales the result. r is the perceptual roughness: the
/// listing's `linearRoughness`, which the notes square to get GGX alpha (section 3.2); the
/// same r as [`burley`], with which it agrees exactly at r = 1 up to the factor 1/1.51.
///
/// Domain, edges and precision as [`burley`] (within 0.7 ULP, max 0.50 found,
/// `cargo test -p brdf-oracle --release --test lobes -- --nocapture`). Output in
/// [0, 6.25 rho / (1.51 pi)]. At r = 0,
/// F_D90 = 0, so f goes to 0 as either direction goes to grazing.
///
/// Closer to energy conserving, not exactly: for rho = 1 its directional albedo stays below 1
/// except for r above about 0.95 near grazing views, where it reaches 1.0315 (r = 1; module
/// docs).
/// Reciprocal.
///
/// Source: Lagarde and de Rousiers 2014, "Moving Frostbite to Physically Based Rendering 3.0",
/// SIGGRAPH course notes, section 3.1 (material models), listing `Fr_DisneyDiffuse`.
#[inline]
#[must_use]
pub fn burley_renormalized<T: Real>(n_dot_v: T, n_dot_l: T, l_dot_h: T, rho: T, roughness: T) -> T {
    let lh = l_dot_h.saturate();
    renormalized_core(n_dot_v, n_dot_l, Dw::product(lh, lh), rho, roughness)
}

/// 1 - 1/1.51 = 51/151: the slope of Frostbite's energyFactor = lerp(1, 1/1.51, r), as its
/// nearest f64 and the rest.
const ENERGY_FACTOR_SLOPE: (f64, f64) = (0.337_748_344_370_860_93, -4.043_858_698_965_802e-18);

/// The renormalized lobe given cos^2(theta_d) in [0, 1] as a double word.
#[inline]
fn renormalized_core<T: Real>(n_dot_v: T, n_dot_l: T, cos2_d: Dw<T>, rho: T, roughness: T) -> T {
    let r = roughness;
    // F_D90 - 1 = r (1/2 + 2 cos^2(theta_d)) - 1 (doubling is exact).
    let two_cos2 = Dw {
        hi: T::TWO * cos2_d.hi,
        lo: T::TWO * cos2_d.lo,
    };
    let a = two_cos2
        .add(Dw::exact(T::HALF))
        .mul(Dw::exact(r))
        .add(Dw::exact(-T::ONE));
    // energyFactor = 1 - r (1 - 1/1.51)
    let (hi, tail) = ENERGY_FACTOR_SLOPE;
    let k = Dw::constant(hi, tail)
        .mul(Dw::exact(-r))
        .add(Dw::exact(T::ONE));
    assemble(n_dot_v, n_dot_l, a, k, rho, r, cos2_d.hi)
}

/// Validates rho and the perceptual roughness for the two Burley types.
fn validate<T: Real>(rho: T, roughness: T) -> Result<(), ParamError> {
    require::<T>(in_unit(rho), "rho", "in [0, 1]")?;
    require::<T>(
        in_unit(roughness),
        "roughness",
        "in [0, 1] (perceptual roughness; GGX alpha = roughness^2)",
    )
}

/// Burley's diffuse lobe ([`burley`]) with validated albedo rho and perceptual roughness r.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Burley<T> {
    rho: T,
    roughness: T,
}

impl<T: Real> Burley<T> {
    /// Burley's diffuse; rho and roughness (perceptual, GGX alpha = roughness^2) must lie in
    /// [0, 1] in every lane, else [`ParamError`].
    pub fn new(rho: T, roughness: T) -> Result<Self, ParamError> {
        validate(rho, roughness)?;
        Ok(Self { rho, roughness })
    }

    /// The albedo rho.
    #[inline]
    #[must_use]
    pub fn rho(&self) -> T {
        self.rho
    }

    /// The perceptual roughness r (GGX alpha = r^2).
    #[inline]
    #[must_use]
    pub fn roughness(&self) -> T {
        self.roughness
    }

    /// f(wo, wi) of [`burley`] for local-frame unit vectors (normal = +z), both pointing away
    /// from the surface; 0 where either is at or below the horizon. cos^2(theta_d) comes from
    /// (1 + wo.wi) / 2, so no half vector is formed.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        let f = burley_core(
            wo.z,
            wi.z,
            Dw::exact(cos2_d_from_directions(wo, wi)),
            self.rho,
            self.roughness,
        );
        super::nan_if_nan_dir(wo, wi, f)
    }
}

/// Lagarde and de Rousiers' renormalized Burley diffuse ([`burley_renormalized`]) with
/// validated albedo rho and perceptual roughness r.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BurleyRenormalized<T> {
    rho: T,
    roughness: T,
}

impl<T: Real> BurleyRenormalized<T> {
    /// The renormalized Burley diffuse; rho and roughness (perceptual, GGX alpha =
    /// roughness^2) must lie in [0, 1] in every lane, else [`ParamError`].
    pub fn new(rho: T, roughness: T) -> Result<Self, ParamError> {
        validate(rho, roughness)?;
        Ok(Self { rho, roughness })
    }

    /// The albedo rho.
    #[inline]
    #[must_use]
    pub fn rho(&self) -> T {
        self.rho
    }

    /// The perceptual roughness r (GGX alpha = r^2).
    #[inline]
    #[must_use]
    pub fn roughness(&self) -> T {
        self.roughness
    }

    /// f(wo, wi) of [`burley_renormalized`] for local-frame unit vectors (normal = +z), both
    /// pointing away from the surface; 0 where either is at or below the horizon.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        let f = renormalized_core(
            wo.z,
            wi.z,
            Dw::exact(cos2_d_from_directions(wo, wi)),
            self.rho,
            self.roughness,
        );
        super::nan_if_nan_dir(wo, wi, f)
    }
}
