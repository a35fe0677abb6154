//! glTF's transmissive dielectric: `KHR_materials_transmission` (how much of the light that
//! enters the surface is transmitted rather than diffusely re-emitted) and
//! `KHR_materials_volume` (whether the surface is a thin wall or the boundary of a volume, and
//! Beer-Lambert attenuation inside it), as pure functions of validated parameters.
//!
//! Sources: the Khronos glTF extension specifications `KHR_materials_transmission` (section
//! "Transmission BTDF" and its implementation notes) and `KHR_materials_volume` (sections
//! "Thin-walled and volumetric", "Attenuation"), and the core glTF 2.0 specification,
//! appendix B ("BRDF implementation"). The composition is
//!
//! ```text
//! f = F specular_brdf + (1 - F) ((1 - t) base_color / pi + t base_color specular_btdf)
//! ```
//!
//! with F = `fresnel::schlick(f0, |wo.h|)`, f0 = ((ior - 1) / (ior + 1))^2 and t the
//! transmission (`transmissionFactor` times the red channel of `transmissionTexture`). The
//! BTDF has two readings, chosen by the volume's thickness:
//!
//! - **thin-walled** (thickness 0, or no `KHR_materials_volume`): two back-to-back surfaces with
//!   no net refraction; the BTDF is the reflection lobe mirrored through the surface plane,
//!   `thin_walled_btdf`, with the half vector h_T = normalize(wo + wi'), wi' = (wi.x, wi.y,
//!   -wi.z);
//! - **volumetric** (thickness > 0): the surface bounds a volume of index `ior`; the BTDF is
//!   Walter et al. 2007's refraction lobe (`rough_dielectric`, radiance transport, without its
//!   own Fresnel factor, which the composition's 1 - F replaces), with the generalized half
//!   vector.
//!
//! The draft of `KHR_materials_volume` writes the BTDF with the view direction on the incident
//! side, ior_o^2 / (ior_i V.H + ior_o L.H)^2: that is the importance (adjoint) form, which
//! differs from the radiance form by (n_L / n_V)^2; this module uses the radiance form, as
//! pbrt-v4 and Mitsuba 3 do for camera paths (`rough_dielectric`, "Radiance and importance").

use crate::domain::nan_unless;
#[cfg(feature = "ggx")]
use crate::domain::nan_where;
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;
#[cfg(feature = "ggx")]
use crate::vec3::any_nonfinite3;

#[cfg(feature = "ggx")]
use crate::ggx::Ggx;
#[cfg(feature = "ggx")]
use crate::microfacet::Microfacet;

/// `KHR_materials_transmission`'s transmission t: the fraction of the light that enters the
/// surface (is not specularly reflected) that is transmitted rather than diffusely re-emitted,
/// `transmissionFactor` times the red channel of `transmissionTexture`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transmission<T> {
    factor: T,
}

impl<T: Real> Transmission<T> {
    /// t in [0, 1] in every lane (glTF's `transmissionFactor` range; its default, 0, is an
    /// opaque dielectric), else [`ParamError`].
    pub fn new(factor: T) -> Result<Self, ParamError> {
        require::<T>(crate::domain::in_unit(factor), "factor", "in [0, 1]")?;
        Ok(Self { factor })
    }

    /// t, as given.
    #[inline]
    #[must_use]
    pub fn factor(&self) -> T {
        self.factor
    }
}

/// `KHR_materials_volume`: the thickness of the volume under the surface (0: thin-walled) and
/// its Beer-Lambert attenuation, `attenuationColor` reached after `attenuationDistance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Volume<T> {
    thickness: T,
    attenuation_color: V3<T>,
    attenuation_distance: T,
}

impl<T: Real> Volume<T> {
    /// A volume: `thickness` in [0, MAX] (glTF's `thicknessFactor`, in the mesh's units; 0
    /// makes the material thin-walled), `attenuation_color` in [0, 1] per channel (the colour
    /// white light turns into after `attenuation_distance`), `attenuation_distance` in
    /// (0, MAX] (world units). glTF's defaults are thickness 0, colour (1, 1, 1) and distance
    /// +infinity (no attenuation); infinities are outside every domain of this crate, so give
    /// that default as `T::MAX`, which attenuates by c^(x / MAX), 1 to rounding for every
    /// path length x below 1e290 (f64) / 1e30 (f32). Else [`ParamError`].
    pub fn new(
        thickness: T,
        attenuation_color: V3<T>,
        attenuation_distance: T,
    ) -> Result<Self, ParamError> {
        require::<T>(
            thickness.simd_ge(T::ZERO) & thickness.simd_le(T::MAX),
            "thickness",
            "in [0, MAX], finite",
        )?;
        let c = attenuation_color;
        let unit = crate::domain::in_unit(c.x) & crate::domain::in_unit(c.y);
        require::<T>(
            unit & crate::domain::in_unit(c.z),
            "attenuation_color",
            "in [0, 1] per channel",
        )?;
        require::<T>(
            attenuation_distance.simd_gt(T::ZERO) & attenuation_distance.simd_le(T::MAX),
            "attenuation_distance",
            "in (0, MAX], finite",
        )?;
        Ok(Self {
            thickness,
            attenuation_color,
            attenuation_distance,
        })
    }

    /// The thickness, as given (0: thin-walled).
    #[inline]
    #[must_use]
    pub fn thickness(&self) -> T {
        self.thickness
    }

    /// Beer-Lambert transmittance after a path of length x inside the volume (the
    /// `KHR_materials_volume` specification, "Attenuation"):
    /// T(x) = c^(x / d) = exp(-sigma x) per channel, with c the attenuation colour, d the
    /// attenuation distance and sigma = -ln(c) / d ([`Volume::attenuation_coefficient`]).
    /// T(d) = c, T(0) = 1, T(a + b) = T(a) T(b).
    ///
    /// Domain: path_length in [0, MAX], finite. Edges: a channel with c = 1 gives 1; c = 0
    /// gives 0 for x > 0 and 1 for x = 0; the result underflows smoothly to 0. NaN path
    /// length, a negative one or +inf gives NaN in every channel.
    #[inline]
    #[must_use]
    pub fn transmittance(&self, path_length: T) -> V3<T> {
        let x = path_length;
        let ratio = x / self.attenuation_distance;
        let channel = |c: T| {
            // c^r = exp(r ln c); ln 0 = -inf and r = 0 would give NaN, ln 1 = 0 and an
            // overflowing r likewise: both ends are selected instead.
            let v = (ratio * c.ln()).exp();
            let v = T::select(x.simd_eq(T::ZERO) | c.simd_eq(T::ONE), T::ONE, v);
            T::select(c.simd_eq(T::ZERO) & x.simd_gt(T::ZERO), T::ZERO, v)
        };
        let ok = x.simd_ge(T::ZERO) & x.simd_le(T::MAX);
        self.attenuation_color.map(|c| nan_unless(ok, channel(c)))
    }

    /// The attenuation (extinction) coefficient sigma = -ln(c) / d per channel, in inverse
    /// world units (`KHR_materials_volume`, "Attenuation": the colour-and-distance form of
    /// sigma). 0 for c = 1; c = 0 (total absorption at any depth) gives +inf mathematically and
    /// is capped at MAX.
    #[inline]
    #[must_use]
    pub fn attenuation_coefficient(&self) -> V3<T> {
        let d = self.attenuation_distance;
        self.attenuation_color
            .map(|c| (-c.ln() / d).min(T::MAX).max(T::ZERO))
    }
}

/// The thin-walled BTDF of `KHR_materials_transmission` (its implementation notes): the GGX
/// specular lobe seen through the surface, with the transmission half vector
/// h_T = normalize(wo + wi'), wi' = (wi.x, wi.y, -wi.z) (wi mirrored through the surface
/// plane), f = D(h_T) G_T / (4 |wo.z| |wi.z|), G_T = G1(wo) G1(wi) (the specification's
/// separable Smith form; the sample viewer uses the height-correlated one), with the step
/// functions chi+(h_T.wi') and chi+(h_T.wo): the reflection lobe at (wo, wi'). For
/// alpha_x = alpha_y this is the specification's V_T D_T with its steps read on the mirrored
/// direction (see the source for why); anisotropic alphas use the anisotropic D and Lambda.
/// No Fresnel, base colour or transmission factor: [`dielectric_bsdf`] composes them.
///
/// Domain: wo above the surface (wo.z > 0), wi below it (wi.z < 0), unit vectors. Edges: 0 for
/// wi on wo's side, for wo at or below the horizon, for wi on the horizon and where a step
/// function is 0; capped at MAX. NaN or an infinite component in wo or wi gives NaN.
///
/// ```
/// use brdf::{V3, ggx::Ggx, transmission::thin_walled_btdf};
/// let g = Ggx::isotropic(0.3).unwrap();
/// // Straight through a thin wall: the peak of the lobe, where h_T is the normal.
/// let peak = thin_walled_btdf(&g, V3::new(0.0_f64, 0.0, 1.0), V3::new(0.0, 0.0, -1.0));
/// let off = thin_walled_btdf(&g, V3::new(0.0_f64, 0.0, 1.0), V3::new(0.6, 0.0, -0.8));
/// assert!(peak > off && off > 0.0);
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn thin_walled_btdf<T: Real>(ggx: &Ggx<T>, wo: V3<T>, wi: V3<T>) -> T {
    let mirrored = V3::new(wi.x, wi.y, -wi.z);
    let h = (wo + mirrored).normalize_or(V3::unit_z());
    // The specification's step functions chi+(h_T.L / N.L), read on the mirrored L: on L
    // itself they would cut the lobe wherever h_T.wi' > 2 h_T.z |wi.z| (1.8% of the
    // transmitted energy at alpha 0.1, normal view), against the prose ("exactly the same as
    // the specular lobe except sampled along the line of sight") and the Khronos sample
    // viewer, which evaluates the lobe at the mirrored direction.
    let steps = h.dot(mirrored).simd_gt(T::ZERO) & h.dot(wo).simd_gt(T::ZERO);
    let live = steps & wo.z.simd_gt(T::ZERO) & wi.z.simd_lt(T::ZERO);
    let g = ggx.g1(wo) * ggx.g1(wi);
    let inv = (T::splat(4.0) * wo.z.abs() * wi.z.abs())
        .recip()
        .min(T::MAX);
    let f = ((ggx.d(h) * g).min(T::MAX) * inv).min(T::MAX);
    let f = T::select(live, f, T::ZERO);
    nan_where(any_nonfinite3(wo) | any_nonfinite3(wi) | f.is_nan(), f)
}

/// The glTF dielectric BSDF with `KHR_materials_transmission` (and `KHR_materials_volume`'s
/// reading of the BTDF), per RGB channel (module docs for the formula and its sources):
///
/// - wi on wo's side: F D V + (1 - F)(1 - t) base_color / pi, with h = normalize(wo + wi),
///   D V the GGX lobe with the height-correlated visibility (`Microfacet::v_correlated`), as
///   the core glTF BRDF;
/// - wi through the surface: (1 - F) t base_color btdf, with btdf = [`thin_walled_btdf`] and
///   h = h_T where `volume.thickness()` is 0, else Walter et al. 2007's refraction lobe into
///   the index `ior` (radiance transport) and h the generalized half vector
///   (`rough_dielectric::half_vector`);
///
/// F = `fresnel::schlick(f0_from_ior(ior), |wo.h|)` (glTF's `fresnel_mix`). Metallic
/// materials do not transmit (`KHR_materials_transmission`, "Transparent metals"): mix this
/// with the metal lobe by the metallic factor outside.
///
/// Domain: wo above the surface (the viewer's side; a path inside a volume is
/// `rough_dielectric`'s business), wi anywhere on the sphere, unit vectors; base_color in
/// [0, 1] per channel; ior in (0, MAX] (`KHR_materials_ior`; 1.5 by default). Edges: 0 for wo
/// at or below the horizon and for wi on the horizon; ior = 1 gives no reflection (F = 0) and,
/// in the volumetric reading, no transmission lobe (a Dirac, `rough_dielectric`, "Edges");
/// capped at MAX. NaN or an infinite component in wo or wi, a NaN or out-of-domain base
/// colour channel (in that channel) and NaN or out-of-domain ior give NaN.
///
/// ```
/// use brdf::transmission::{Transmission, Volume, dielectric_bsdf};
/// use brdf::{V3, ggx::Ggx};
/// let g = Ggx::isotropic(0.09).unwrap();
/// let clear = Transmission::new(1.0).unwrap();
/// let thin = Volume::new(0.0, V3::new(1.0, 1.0, 1.0), f64::MAX).unwrap();
/// let wo = V3::new(0.0_f64, 0.0, 1.0);
/// let through = dielectric_bsdf(&g, wo, V3::new(0.0, 0.0, -1.0), V3::new(1.0, 0.5, 0.2), 1.5, &clear, &thin);
/// assert!(through.x > through.y && through.y > through.z && through.z > 0.0); // tinted
/// ```
#[cfg(feature = "ggx")]
#[inline]
#[must_use]
pub fn dielectric_bsdf<T: Real>(
    ggx: &Ggx<T>,
    wo: V3<T>,
    wi: V3<T>,
    base_color: V3<T>,
    ior: T,
    transmission: &Transmission<T>,
    volume: &Volume<T>,
) -> V3<T> {
    use crate::rough_dielectric::{Transport, btdf_without_fresnel};
    let t = transmission.factor;
    let f0 = crate::fresnel::f0_from_ior(ior);
    let same = (wo.z * wi.z).simd_gt(T::ZERO);
    // Reflection side.
    let h_r = (wo + wi).normalize_or(V3::unit_z());
    let f_r = crate::fresnel::schlick(f0, wo.dot(h_r).abs().min(T::ONE));
    let spec = (ggx.d(h_r) * ggx.v_correlated(wo, wi)).min(T::MAX);
    let diffuse_w = (T::ONE - f_r) * (T::ONE - t) * T::FRAC_1_PI;
    // Transmission side: thin-walled or volumetric.
    let mirrored = V3::new(wi.x, wi.y, -wi.z);
    let h_thin = (wo + mirrored).normalize_or(V3::unit_z());
    let thin = thin_walled_btdf(ggx, wo, wi);
    let (vol, o_h) = btdf_without_fresnel(ggx, wo, wi, ior, Transport::Radiance);
    let is_thin = volume.thickness.simd_eq(T::ZERO);
    let btdf = T::select(is_thin, thin, vol);
    let c_t = T::select(is_thin, wo.dot(h_thin), o_h).abs().min(T::ONE);
    let f_t = crate::fresnel::schlick(f0, c_t);
    let trans_w = ((T::ONE - f_t) * t * btdf).min(T::MAX);
    let above = wo.z.simd_gt(T::ZERO) & wi.z.simd_ne_zero();
    let bad = any_nonfinite3(wo) | any_nonfinite3(wi) | f0.is_nan();
    base_color.map(|c| {
        let refl = (f_r * spec).min(T::MAX) + diffuse_w * c;
        let v = T::select(same, refl, (trans_w * c).min(T::MAX));
        let v = T::select(above, v, T::ZERO);
        nan_where(bad | !crate::domain::in_unit(c), v)
    })
}

/// `x != 0` as a mask (false for NaN).
#[cfg(feature = "ggx")]
trait NeZero: Real {
    fn simd_ne_zero(self) -> Self::Mask {
        self.simd_gt(Self::ZERO) | self.simd_lt(Self::ZERO)
    }
}
#[cfg(feature = "ggx")]
impl<T: Real> NeZero for T {}
