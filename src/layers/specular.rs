//! `KHR_materials_ior` and `KHR_materials_specular`: the dielectric's F0 from its index of
//! refraction, tinted and weighted by the specular colour and factor, and the F90 rule.
//!
//! ```text
//! F0_ior     = ((ior - 1) / (ior + 1))^2     (ior = 0: F0_ior = 1, the extension's special value)
//! F0_d       = min(F0_ior specularColor, 1) specular        per channel
//! F90_d      = specular                                      the dielectric's F90
//! F0_metal   = baseColor, F90_metal = 1                      unchanged by the extensions
//! ```
//!
//! [`Ior`] and [`Specular`] validate the glTF parameters once; [`f0_from_ior`] and
//! [`dielectric_f0`] are the unvalidated kernels (NaN outside their domains). The
//! `material::MetallicRoughness` material applies the same rule
//! through its `with_ior` and `with_specular`.
//!
//! Sources: The Khronos Group, "KHR_materials_ior" (ratified), "Implementation";
//! "KHR_materials_specular" (ratified), "Implementation".

use crate::domain::{in_unit, nan_unless};
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

/// F0 from an index of refraction with KHR_materials_ior's special value:
/// F0 = ((ior - 1) / (ior + 1))^2 for ior >= 1, and F0 = 1 for ior = 0 (the value the
/// extension reserves for converting specular-glossiness materials).
///
/// Domain: ior = 0 or ior in [1, MAX]; NaN for NaN, ior in (0, 1), ior < 0 or +inf. Output in
/// [0, 1). For ior >= 1 it is [`crate::fresnel::f0_from_ior`] (its accuracy).
///
/// Source: KHR_materials_ior, "Implementation".
#[inline]
#[must_use]
pub fn f0_from_ior<T: Real>(ior: T) -> T {
    let zero = ior.simd_eq(T::ZERO);
    let ok = zero | (ior.simd_ge(T::ONE) & ior.is_finite());
    let safe = T::select(zero, T::ONE, ior);
    nan_unless(
        ok,
        T::select(zero, T::ONE, crate::fresnel::f0_from_ior(safe)),
    )
}

/// The dielectric F0 of KHR_materials_specular: min(f0_ior specular_color, 1) specular per
/// channel. Its F90 is `specular` itself (the extension's rule: a specular factor below 1
/// darkens grazing reflection too); metals keep F0 = baseColor, F90 = 1.
///
/// Domain: `f0_ior` in [0, 1] ([`f0_from_ior`]); `specular` in [0, 1]; `specular_color` each
/// channel finite and >= 0 (the extension allows colours above 1, so that F0 can exceed the
/// IOR's; the min keeps it a reflectance). NaN for NaN input or a value outside its domain.
///
/// Source: KHR_materials_specular, "Implementation" (`dielectric_f0`).
#[inline]
#[must_use]
pub fn dielectric_f0<T: Real>(f0_ior: T, specular: T, specular_color: V3<T>) -> V3<T> {
    let ok = in_unit(f0_ior) & in_unit(specular);
    let ch = |c: T| {
        let c_ok = c.simd_ge(T::ZERO) & c.is_finite();
        nan_unless(ok & c_ok, (f0_ior * c).min(T::ONE) * specular)
    };
    V3::new(
        ch(specular_color.x),
        ch(specular_color.y),
        ch(specular_color.z),
    )
}

/// A validated index of refraction (KHR_materials_ior's `ior`): 0 (the special value,
/// F0 = 1) or finite and >= 1. The glTF default is 1.5.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ior<T>(T);

impl<T: Real> Ior<T> {
    /// `ior` = 0 or finite and >= 1 in every lane, else [`ParamError`] (`"ior"`).
    pub fn new(ior: T) -> Result<Self, ParamError> {
        let ok = ior.simd_eq(T::ZERO) | (ior.simd_ge(T::ONE) & ior.is_finite());
        require::<T>(ok, "ior", "0 or finite and >= 1")?;
        Ok(Self(ior))
    }

    /// The index of refraction, as given.
    #[inline]
    #[must_use]
    pub fn value(&self) -> T {
        self.0
    }

    /// Its F0 ([`f0_from_ior`]).
    #[inline]
    #[must_use]
    pub fn f0(&self) -> T {
        f0_from_ior(self.0)
    }
}

/// Validated KHR_materials_specular parameters: `specularFactor` in [0, 1] and
/// `specularColorFactor` with each channel finite and >= 0. The glTF default is 1 and (1, 1, 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Specular<T> {
    factor: T,
    color: V3<T>,
}

impl<T: Real> Specular<T> {
    /// `factor` in [0, 1] (`"specular"`) and `color` each channel finite and >= 0
    /// (`"specular_color"`), else [`ParamError`].
    pub fn new(factor: T, color: V3<T>) -> Result<Self, ParamError> {
        require::<T>(in_unit(factor), "specular", "in [0, 1]")?;
        let ok = |c: T| c.simd_ge(T::ZERO) & c.is_finite();
        require::<T>(
            ok(color.x) & ok(color.y) & ok(color.z),
            "specular_color",
            "each channel finite and >= 0",
        )?;
        Ok(Self { factor, color })
    }

    /// The specular factor.
    #[inline]
    #[must_use]
    pub fn factor(&self) -> T {
        self.factor
    }

    /// The specular colour.
    #[inline]
    #[must_use]
    pub fn color(&self) -> V3<T> {
        self.color
    }

    /// The dielectric's F0 for `ior`: [`dielectric_f0`]`(ior.f0(), factor, color)`.
    #[inline]
    #[must_use]
    pub fn dielectric_f0(&self, ior: &Ior<T>) -> V3<T> {
        dielectric_f0(ior.f0(), self.factor, self.color)
    }

    /// The dielectric's F90: the specular factor.
    #[inline]
    #[must_use]
    pub fn dielectric_f90(&self) -> T {
        self.factor
    }
}
