//! Diffuse lobes: Lambert, Oren-Nayar (qualitative, full, Fujii's improved form and the
//! energy-preserving EON), Burley's diffuse and its renormalized form, and the couplings that
//! weight a diffuse lobe by the energy a specular layer leaves it.
//!
//! | file | what lives there |
//! |---|---|
//! | `mod.rs` | Lambert, the shared conventions |
//! | `oren_nayar.rs` | Oren-Nayar qualitative and full models, Fujii's improved form |
//! | `eon.rs` | EON: energy-preserving Oren-Nayar, its albedo and importance sampling |
//! | `burley.rs` | Burley's diffuse, Lagarde and de Rousiers' renormalized form |
//! | `coupling.rs` | diffuse-Fresnel couplings |
//!
//! Conventions shared by every lobe here:
//! - Dot-product entry points take the cosines first (`n_dot_v`, `n_dot_l`, then `v_dot_l` or
//!   `l_dot_h` where the lobe needs them) and the parameters after; they return the BRDF f
//!   (without the cosine n.l). They validate nothing: a parameter outside its documented domain
//!   gives NaN, a NaN input gives NaN, and a direction at or below the horizon gives 0.
//! - The third cosine differs by lobe, as in the shaders each form comes from: the Oren-Nayar
//!   family and EON take `v_dot_l` (their s = v.l - (n.v)(n.l)); Burley's forms take `l_dot_h`
//!   (Filament's `Fd_Burley(NoV, NoL, LoH, roughness)`), and the couplings take Fresnel values.
//! - The roughness parameter means different things in different models, so the same number
//!   gives different looks:
//!
//!   | lobe | parameter | meaning | domain |
//!   |---|---|---|---|
//!   | [`oren_nayar`], [`oren_nayar_full`] | `sigma` | standard deviation of the facet slope angle, radians | >= 0 |
//!   | [`oren_nayar_fujii`], [`eon`] | `sigma` | Fujii's ratio B / A of the two terms (OpenPBR's `diffuse_roughness`) | [0, 1] |
//!   | [`burley`], [`burley_renormalized`] | `roughness` | perceptual roughness r (GGX alpha = r^2) | [0, 1] |
//!
//!   [`oren_nayar_fujii`] documents how to map an Oren-Nayar sigma to Fujii's.
//! - Each lobe also has a parameter type whose constructor validates (returning
//!   [`ParamError`]), with `eval(wo, wi)` on local-frame unit vectors
//!   (normal = +z).

use crate::domain::{above_horizon, in_unit, nan_unless, nan_where};
use crate::dw::Dw;
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

mod burley;
mod coupling;
mod eon;
mod oren_nayar;

pub use burley::*;
pub use coupling::*;
pub use eon::*;
pub use oren_nayar::*;

/// Fujii's shape 1 + sigma s / t (Fujii 2012; EON's single scattering) as a numerator in
/// double words and a divisor: (t' + sigma s, t') with t' = t = max(n.v, n.l), floored at the
/// smallest normal float, where s > 0 and sigma > 0, else t' = 1. s = v.l - (n.v)(n.l) is formed exactly
/// (Dekker's product) and clamped into [-1, 1], its range for unit vectors. For s < 0 the sum
/// 1 + sigma s cancels (to 0 at sigma = 1, s = -1: opposite grazing directions), so neither
/// s nor sigma s is rounded first; for s > 0 nothing cancels and the caller divides by t'
/// last, once (s / t' reaches 1 / MIN_POSITIVE, too large for Dekker's split). With sigma in
/// [0, 1] the numerator is >= 0 and at most 2.
#[inline]
fn fujii_shape<T: Real>(n_dot_v: T, n_dot_l: T, v_dot_l: T, sigma: T) -> (Dw<T>, T) {
    let s = Dw::exact(v_dot_l).add(Dw::product(-n_dot_v, n_dot_l));
    // On hi, inclusive: hi = -1 with lo < 0 is below -1 (lo changes the value by less than
    // half an ULP, so clamping it away costs nothing).
    let s = Dw::select(s.hi.simd_ge(T::ONE), Dw::exact(T::ONE), s);
    let s = Dw::select(s.hi.simd_le(-T::ONE), Dw::exact(-T::ONE), s);
    // t' = 1 also at sigma = 0, where the shape is then exactly 1 / 1 (Lambert's bits).
    let t = T::select(
        s.hi.simd_gt(T::ZERO) & sigma.simd_gt(T::ZERO),
        n_dot_v.max(n_dot_l).max(T::MIN_POSITIVE),
        T::ONE,
    );
    (s.mul(Dw::exact(sigma)).add(Dw::exact(t)), t)
}

/// rho / pi * x rounded once (1 / pi carried in double words): the common factor of every
/// lobe here, so that each of them at zero roughness (x = 1) gives [`lambert`]'s bits.
#[inline]
fn rho_over_pi<T: Real>(rho: T, x: T) -> T {
    Dw::frac_1_pi()
        .mul(Dw::exact(rho))
        .mul(Dw::exact(x))
        .value()
}

/// `value`, or NaN where a component of `wo` or `wi` is NaN. The types' `eval` read only some
/// components (Lambert only the two z), and a NaN in another one must still give NaN.
#[inline]
fn nan_if_nan_dir<T: Real>(wo: V3<T>, wi: V3<T>, value: T) -> T {
    nan_where(any_nonfinite3(wo) | any_nonfinite3(wi), value)
}

/// Lambert's diffuse BRDF, f = rho / pi: light scattered equally into every direction of the
/// upper hemisphere, with directional albedo rho at every angle.
///
/// Domain: rho in [0, 1]. Edges: 0 where `n_dot_v <= 0` or `n_dot_l <= 0`; NaN for a NaN
/// input or rho outside [0, 1], also below the horizon.
///
/// Accuracy: rho / pi rounded once (1 / pi carried in double words): within 0.7 ULP of the
/// correctly rounded value on every lane type, max 0.50 found (MPFR oracle,
/// `cargo test -p brdf-oracle --release --test lobes -- --nocapture`).
///
/// Source: Lambert 1760, "Photometria"; the 1/pi normalization makes the integral of
/// f cos(theta_i) over the hemisphere equal rho.
#[inline]
#[must_use]
pub fn lambert<T: Real>(n_dot_v: T, n_dot_l: T, rho: T) -> T {
    // The domain check wraps the horizon guard so a bad rho is NaN on both sides of it.
    nan_unless(
        in_unit(rho),
        above_horizon(n_dot_v, n_dot_l, rho_over_pi(rho, T::ONE)),
    )
}

/// A Lambertian lobe of albedo rho in [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambert<T> {
    rho: T,
}

impl<T: Real> Lambert<T> {
    /// A Lambertian lobe; rho must lie in [0, 1] in every lane, else [`ParamError`].
    pub fn new(rho: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(rho), "rho", "in [0, 1]")?;
        Ok(Self { rho })
    }

    /// The albedo rho.
    #[inline]
    #[must_use]
    pub fn rho(&self) -> T {
        self.rho
    }

    /// f(wo, wi) = rho / pi for wo and wi above the horizon, else 0 ([`lambert`]); NaN where
    /// any component of wo or wi is NaN or infinite.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        nan_if_nan_dir(wo, wi, lambert(wo.z, wi.z, self.rho))
    }
}
