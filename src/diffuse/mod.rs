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

use crate::domain::{above_horizon, in_unit, nan_unless};
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

mod burley;
mod coupling;
mod eon;
mod oren_nayar;

pub use burley::*;
pub use coupling::*;
pub use eon::*;
pub use oren_nayar::*;

/// Lambert's diffuse BRDF, f = rho / pi: light scattered equally into every direction of the
/// upper hemisphere, with directional albedo rho at every angle.
///
/// Domain: rho in [0, 1]. Edges: 0 where `n_dot_v <= 0` or `n_dot_l <= 0`; NaN for a NaN
/// input or rho outside [0, 1], also below the horizon.
///
/// Source: Lambert 1760, "Photometria"; the 1/pi normalization makes the integral of
/// f cos(theta_i) over the hemisphere equal rho.
#[inline]
#[must_use]
pub fn lambert<T: Real>(n_dot_v: T, n_dot_l: T, rho: T) -> T {
    // The domain check wraps the horizon guard so a bad rho is NaN on both sides of it.
    nan_unless(
        in_unit(rho),
        above_horizon(n_dot_v, n_dot_l, rho * T::FRAC_1_PI),
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

    /// f(wo, wi) = rho / pi for wo and wi above the horizon, else 0 ([`lambert`]).
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> T {
        lambert(wo.z, wi.z, self.rho)
    }
}
