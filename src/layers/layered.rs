//! The layered glTF material: the metallic-roughness base of [`MetallicRoughness`] with any
//! subset of `KHR_materials_sheen`, `KHR_materials_clearcoat`, `KHR_materials_anisotropy`
//! (and `KHR_materials_specular` / `KHR_materials_ior` through the base's `with_specular` and
//! `with_ior`; `KHR_materials_transmission` / `KHR_materials_volume` and
//! `KHR_materials_iridescence` with the features `transmission` and `iridescence`), evaluated, sampled and given its pdf on local-frame directions (normal = +z,
//! tangent = +x, both directions pointing away from the surface).
//!
//! # The composition (the extensions' layering, top to bottom)
//! ```text
//! base     = kd baseColor / pi + F D V          the metallic-roughness BRDF, D and V of the
//!                                                anisotropic GGX when strength > 0
//!          (+ f_ms, the multiple-scattering lobe, when compensated)
//! sheened  = f_sheen + base s                   s = min(1 - max(sheenColor) E(n.v),
//!                                                       1 - max(sheenColor) E(n.l))
//! f        = clearcoat coat + (1 - clearcoat F_coat(n_c.v)) sheened
//! ```
//!
//! with f_sheen and E of [`sheen`] (the glTF Charlie lobe, E from its built-in table), the
//! coat of [`clearcoat::coat`] about the coat normal n_c, and the anisotropic widths
//! alpha_t = mix(alpha, 1, strength^2), alpha_b = alpha along the rotated tangent
//! ([`anisotropy`]). A material with no layer evaluates exactly as its base: clearcoat 0,
//! a black sheen and strength 0 each leave the base bit for bit (`cargo test --test layers
//! layered::`).
//!
//! The sheen uses the extension's min form of albedo scaling (reciprocal); for many lights at
//! one shading point, [`Layered::at_view`] reads the view's sheen albedo E(n.v) and coat
//! Fresnel once, and its [`Prepared::eval`] (the min form, equal to [`Layered::eval`] bit for
//! bit) reads only E(n.l) per light, while [`Prepared::eval_view_only`] (the extension's
//! view-only form 1 - max(sheenColor) E(n.v)) reads nothing per light. The coat
//! attenuates by F_coat(n_c.v), the extension's choice, which is not reciprocal (see
//! [`clearcoat`] for the other argument).
//!
//! # Multiple scattering
//! [`with_compensation`](Layered::with_compensation) adds Kulla and Conty's lobe
//! ([`crate::ibl::energy::kulla_conty_ggx_rgb`]) to each microfacet lobe *separately*: the base
//! specular gets (1 - metallic) f_ms(F_avg(F0_d, F90_d)) + metallic f_ms(F_avg(baseColor, 1)),
//! and the coat f_ms(F_avg(0.04, 1)), then the layers are mixed. Compensating once on the
//! blended F0 = mix(F0_d, baseColor, metallic) is wrong because the lobe's colour
//! F_ms(F_avg) = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) is not linear in F_avg (three.js and
//! bevy shipped that form and replaced it; the issue trackers hold the fixes). For an
//! anisotropic base the lobe uses alpha = sqrt(alpha_t alpha_b), an approximation (the tables
//! are isotropic). A compensated white metal reflects all the light within 0.5% up to 80
//! degrees: measured within 5.2e-4 for roughness 0.2 to 1 (uncompensated it loses up to
//! 0.69), `cargo test --test layers layered::white_furnace -- --nocapture`. With sheen and a
//! coat on top the albedo stays at most 1 (measured max 0.976 over the test's grid); the
//! furnace is not claimed there (the extensions' layering is not energy conserving).
//!
//! # Transmission (feature `transmission`)
//! `with_transmission` follows KHR_materials_transmission with
//! a thin-walled volume (KHR_materials_volume's thickness 0): in the dielectric base the
//! diffuse lobe is mixed with the transmission lobe by the factor t,
//! mix(kd baseColor / pi, kd baseColor btdf, t), the btdf being the base GGX lobe mirrored
//! through the surface plane (`transmission::thin_walled_btdf`) and kd read at its
//! half vector h_T. wi below the surface then sees only that lobe, times the view side's
//! sheen scaling 1 - max(sheenColor) E(n.v) and coat attenuation 1 - clearcoat F_coat(n_c.v);
//! eval, pdf and sample cover the whole sphere. `with_volume`
//! (KHR_materials_volume) with a positive thickness replaces the mirrored lobe by Walter et
//! al. 2007's refraction lobe into the base's IOR (radiance transport: the transmitted
//! radiance is divided by eta^2, so a white glass of IOR 1.5 has a sphere albedo near
//! 0.96 / 2.25 + 0.04 = 0.47 at normal view). The sampler gives the transmission lobe the
//! weight (coat through) s_v t mean(kd baseColor), taken from the cosine lobes, and draws it
//! from the base GGX's visible normals, reflected and mirrored through the surface plane
//! (thin-walled) or refracted (volumetric). The white furnace over the whole sphere stays
//! at most 1: measured max 0.9983 (`cargo test --test layers transmission:: --
//! --nocapture`). The transmission lobe scatters once: the multiple-scattering compensation
//! does not cover it, and the thin-walled lobe, being the reflection lobe mirrored (with
//! the extension's separable G1 G1), loses what the uncompensated white metal loses: at
//! roughness 1 its albedo is 1 - ln 2 = 0.307 at normal view (where G1(wo) = 1 and the
//! separable and correlated forms agree), 0.523 at 80 degrees against the correlated
//! reflection lobe's 0.668 (`cargo test --test transmission gltf:: -- --nocapture` checks
//! that it is the separable reflection lobe).
//!
//! # Iridescence (feature `iridescence`)
//! `with_iridescence` follows KHR_materials_iridescence ("Implementation Notes"): each lobe's
//! Fresnel is mixed towards the thin film's by the factor f,
//! F_dielectric' = mix(F_dielectric, F_film(F0_d), f) with F0_d the dielectric's F0 (the
//! specular weight and colour included, as the extension's `specular_weight * base_f0`) and
//! F_metal' = mix(F_metal, F_film(baseColor), f), the base colour read as the metal's F0
//! (`iridescent_conductor_layer`); the film over a base of F0 is `crate::iridescence`'s
//! Airy summation over the base index (1 + sqrt(F0)) / (1 - sqrt(F0)) with no extinction, in
//! RGB. The diffuse weight follows the coupling from the mixed Fresnel (glTF:
//! 1 - max_rgb F_dielectric', the extension's `rgb_mix`), and the compensation lobes read
//! F_avg mixed the same way, the film's average read at mu* = 0.456 where Schlick's weight
//! is its average 1/21. Two choices differ from the Khronos Sample Viewer (`pbr.frag`,
//! `iridescence.glsl`): the film is read at v.h, as every Fresnel of the material (the viewer
//! reads it once at n.v, which is not reciprocal), and by exact Fresnel with both
//! polarizations (the viewer uses Schlick's form); as in the viewer, thickness 0 turns the
//! film off (factor 0), which leaves the base's Schlick Fresnel where a vanishing film would
//! give the exact one. The film's outside medium is air, also under a clearcoat (the viewer's
//! `evalIridescence(1.0, ...)`).
//!
//! # Sampling
//! One-sample lobe selection by the lobes' estimated albedos at wo: coat clearcoat
//! F_coat(n_c.v), then, scaled by what the coat lets through, the base specular (the mean of
//! the mixed F at n.v) and the cosine lobes (sheen max(sheenColor) E(n.v) plus the base
//! diffuse kd baseColor with kd at the hemispherical Schlick average 1/21), the base lobes
//! scaled by 1 - max(sheenColor) E(n.v). The estimates miss what depends on the light (the
//! diffuse weight's v.h, the coat's tilt, a base dimmed by the sheen only towards grazing
//! lights), so a lobe estimated near 0 can still be bright in places, and a one-sample
//! estimator divides by the probability of the lobe it drew: fireflies. The probabilities
//! are therefore floored as the metallic-roughness sampler's: each estimated weight w_i / sum
//! below [`LOBE_PROBABILITY_MIN`] = 1/16 is raised to it unless w_i = 0 (the lobe is absent
//! or contributes nothing at this view), then all are renormalized, so every live lobe has
//! at least 1/16 / (1 + 3/16) = 1/19 and its sample weight is at most 19 times its value
//! over its own density. The coat is sampled by GGX visible normals in the
//! coat normal's frame, the base specular by anisotropic GGX visible normals in the rotated
//! tangent frame, sheen and diffuse by the cosine hemisphere (the sheen lobe is broad). The
//! pdf is the mixture's.
//!
//! Sources: The Khronos Group, "KHR_materials_sheen", "KHR_materials_clearcoat",
//! "KHR_materials_anisotropy", "KHR_materials_specular", "KHR_materials_ior",
//! "KHR_materials_iridescence" (ratified), their "Implementation" sections; the Khronos
//! glTF-Sample-Viewer's `pbr.frag`; Belcour and Barla 2017, "A Practical Extension to
//! Microfacet Theory for the Modeling of Varying Iridescence"; glTF 2.0 Appendix B; Kulla and Conty 2017, "Revisiting
//! Physically Based Shading at Imageworks"; Heitz 2018, "Sampling the GGX Distribution of
//! Visible Normals".

use crate::domain::{above_horizon, finite_dirs, in_unit, nan_where};
use crate::error::{ParamError, require};
use crate::frame::Frame;
use crate::ggx::{self, Ggx};
use crate::ibl::energy::{fresnel_avg_schlick, kulla_conty_ggx, kulla_conty_ggx_rgb};
#[cfg(feature = "iridescence")]
use crate::iridescence::{self, ThinFilm};
use crate::layers::{anisotropy, clearcoat, sheen};
use crate::material::{
    Film, LOBE_PROBABILITY_MIN, MetallicRoughness, SCHLICK_WEIGHT_AVERAGE, fresnel_and_kd_film,
    schlick_weights,
};
use crate::microfacet::alpha_from_perceptual;
use crate::real::Real;
use crate::sampling;
use crate::shading::{Cosines, ShadingPoint};
use crate::vec3::{V3, any_nonfinite3};

/// The layered glTF material (module docs). Built from a base with [`Layered::new`] or
/// [`Layered::from_base`] and layered by the `with_*` methods, each validating its own
/// arguments.
///
/// ```
/// use brdf::V3;
/// use brdf::layers::layered::Layered;
///
/// let velvet_car_paint = Layered::new(V3::new(0.6, 0.05, 0.05), 0.0, 0.5)?
///     .with_sheen(V3::new(0.8, 0.3, 0.3), 0.4)?
///     .with_clearcoat(1.0, 0.05)?
///     .with_compensation(true);
/// let (wo, wi) = (V3::new(0.0, 0.6, 0.8), V3::new(0.0, -0.6, 0.8));
/// let rgb = velvet_car_paint.eval(wo, wi);
/// assert!(rgb.x > rgb.y);
/// let (l, pdf) = velvet_car_paint.sample(wo, 0.3, 0.7);
/// assert_eq!(pdf, velvet_car_paint.pdf(wo, l));
/// # Ok::<(), brdf::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layered<T> {
    base: MetallicRoughness<T>,
    sheen_color: V3<T>,
    sheen_alpha: T,
    clearcoat: T,
    coat_alpha: T,
    coat_normal: V3<T>,
    strength: T,
    aniso_cos: T,
    aniso_sin: T,
    compensate: bool,
    #[cfg(feature = "transmission")]
    transmission: T,
    #[cfg(feature = "transmission")]
    thickness: T,
    /// KHR_materials_iridescence: the factor and the film; `None` costs nothing per eval.
    #[cfg(feature = "iridescence")]
    iridescence: Option<(T, ThinFilm<T>)>,
}

/// mu* = 1 - 21^(-1/5): the cosine where Schlick's weight (1 - mu)^5 equals its
/// hemispherical average 1/21 ([`SCHLICK_WEIGHT_AVERAGE`]).
const AVERAGE_COS: f64 = 0.456_053_557_111_121_5;

/// Largest |length - 1| accepted for the coat normal: a shader's `normalize` in f16 is
/// within 1e-3.
const UNIT_TOLERANCE: f64 = 1e-3;

impl<T: Real> Layered<T> {
    /// A material with no layer over the glTF base of [`MetallicRoughness::new`] (same
    /// arguments, domains and errors).
    pub fn new(base_color: V3<T>, metallic: T, roughness: T) -> Result<Self, ParamError> {
        Ok(Self::from_base(MetallicRoughness::new(
            base_color, metallic, roughness,
        )?))
    }

    /// A material with no layer over `base` (its IOR, specular and coupling included).
    #[must_use]
    pub fn from_base(base: MetallicRoughness<T>) -> Self {
        Self {
            base,
            sheen_color: V3::splat(T::ZERO),
            sheen_alpha: T::ONE,
            clearcoat: T::ZERO,
            coat_alpha: T::ONE,
            coat_normal: V3::unit_z(),
            strength: T::ZERO,
            aniso_cos: T::ONE,
            aniso_sin: T::ZERO,
            compensate: false,
            #[cfg(feature = "transmission")]
            transmission: T::ZERO,
            #[cfg(feature = "transmission")]
            thickness: T::ZERO,
            #[cfg(feature = "iridescence")]
            iridescence: None,
        }
    }

    /// KHR_materials_sheen: `color` each channel in [0, 1] (`"sheen_color"`), perceptual
    /// `roughness` in [0, 1] (`"sheen_roughness"`, alpha = roughness^2), else [`ParamError`].
    pub fn with_sheen(self, color: V3<T>, roughness: T) -> Result<Self, ParamError> {
        require::<T>(
            in_unit(color.x) & in_unit(color.y) & in_unit(color.z),
            "sheen_color",
            "each channel in [0, 1]",
        )?;
        require::<T>(in_unit(roughness), "sheen_roughness", "in [0, 1]")?;
        Ok(Self {
            sheen_color: color,
            sheen_alpha: roughness * roughness,
            ..self
        })
    }

    /// KHR_materials_clearcoat: the layer's weight `clearcoat` in [0, 1] (`"clearcoat"`) and
    /// its perceptual `roughness` in [0, 1] (`"clearcoat_roughness"`; alpha = roughness^2,
    /// floored at [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN)), else [`ParamError`].
    pub fn with_clearcoat(self, clearcoat: T, roughness: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(clearcoat), "clearcoat", "in [0, 1]")?;
        require::<T>(in_unit(roughness), "clearcoat_roughness", "in [0, 1]")?;
        Ok(Self {
            clearcoat,
            coat_alpha: alpha_from_perceptual(roughness),
            ..self
        })
    }

    /// The coat's own normal in the local frame (glTF's `clearcoatNormalTexture`): finite,
    /// unit length within 1e-3 and above the horizon (z > 0), else [`ParamError`]
    /// (`"clearcoat_normal"`). The default is the shading normal +z.
    pub fn with_clearcoat_normal(self, n: V3<T>) -> Result<Self, ParamError> {
        let len = n.length();
        let ok = (len - T::ONE).abs().simd_le(T::splat(UNIT_TOLERANCE)) & n.z.simd_gt(T::ZERO);
        require::<T>(ok, "clearcoat_normal", "finite, unit length, z > 0")?;
        Ok(Self {
            coat_normal: n,
            ..self
        })
    }

    /// [`with_clearcoat_normal`](Self::with_clearcoat_normal) from world space: the coat's
    /// world-space unit normal `n` (glTF's `clearcoatNormalTexture` decoded through the
    /// mesh's TBN, as the base's normal map) taken into the local frame of the shading point
    /// `sp`, the same frame [`eval_world`](Self::eval_world) uses; equal to
    /// `self.with_clearcoat_normal(sp.local(n))`, with its checks: finite, unit length within
    /// 1e-3 and on the outer side of the shading normal (n . N > 0), else [`ParamError`]
    /// (`"clearcoat_normal"`). The material then holds the coat normal of this shading point:
    /// evaluate it with the same `sp`.
    pub fn with_clearcoat_normal_world(
        self,
        sp: &ShadingPoint<T>,
        n: V3<T>,
    ) -> Result<Self, ParamError> {
        self.with_clearcoat_normal(sp.local(n))
    }

    /// KHR_materials_anisotropy: `strength` in [0, 1] (`"anisotropy_strength"`) and the
    /// direction's `rotation` in radians from the tangent +x, finite (`"anisotropy_rotation"`),
    /// else [`ParamError`].
    pub fn with_anisotropy(self, strength: T, rotation: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(strength), "anisotropy_strength", "in [0, 1]")?;
        require::<T>(rotation.is_finite(), "anisotropy_rotation", "finite")?;
        let d = anisotropy::direction(T::ONE, T::ZERO, rotation);
        Ok(Self {
            strength,
            aniso_cos: d.x,
            aniso_sin: d.y,
            ..self
        })
    }

    /// KHR_materials_iridescence: the iridescence `factor` in [0, 1] (`"iridescence"`, else
    /// [`ParamError`]) and the thin film (thickness in nanometres and index, validated by
    /// [`ThinFilm::new`]; glTF's defaults are 400 nm, the `iridescenceThicknessMaximum`, and
    /// 1.3). Each lobe's Fresnel is mixed towards the film's by the factor (module docs,
    /// "Iridescence"). Factor 0, and thickness 0 (the Sample Viewer's rule), are the material
    /// without it, bit for bit.
    ///
    /// ```
    /// use brdf::V3;
    /// use brdf::iridescence::ThinFilm;
    /// use brdf::layers::layered::Layered;
    ///
    /// let plain = Layered::new(V3::new(0.9, 0.6, 0.3), 1.0, 0.3)?;
    /// let tinted = plain.with_iridescence(1.0, ThinFilm::new(400.0, 1.3)?)?;
    /// let (wo, wi) = (V3::new(0.0, 0.6, 0.8), V3::new(0.0, -0.6, 0.8));
    /// assert_ne!(tinted.eval(wo, wi), plain.eval(wo, wi));
    /// let off = plain.with_iridescence(0.0, ThinFilm::new(400.0, 1.3)?)?;
    /// assert_eq!(off.eval(wo, wi), plain.eval(wo, wi));
    /// # Ok::<(), brdf::ParamError>(())
    /// ```
    #[cfg(feature = "iridescence")]
    pub fn with_iridescence(self, factor: T, film: ThinFilm<T>) -> Result<Self, ParamError> {
        require::<T>(in_unit(factor), "iridescence", "in [0, 1]")?;
        Ok(Self {
            iridescence: Some((factor, film)),
            ..self
        })
    }

    /// KHR_materials_transmission, thin-walled (`KHR_materials_volume` with thickness 0): the
    /// transmission factor t in [0, 1] (`"transmission"`), else [`ParamError`]. The dielectric
    /// base's diffuse lobe kd baseColor / pi is scaled by 1 - t and, for wi below the surface,
    /// the transmission lobe kd(h_T) t baseColor btdf is added, btdf the base GGX mirrored
    /// through the surface plane ([`crate::transmission::thin_walled_btdf`], h_T its half
    /// vector), seen through the layers above (module docs, "Transmission"). Metals do not
    /// transmit (kd carries 1 - metallic). t = 0 is the material without it, bit for bit.
    #[cfg(feature = "transmission")]
    pub fn with_transmission(self, transmission: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(transmission), "transmission", "in [0, 1]")?;
        Ok(Self {
            transmission,
            ..self
        })
    }

    /// KHR_materials_volume: the transmission lobe's reading by the volume's thickness (see
    /// [`crate::transmission::Volume`], validated there). Thickness 0 (the default) keeps the
    /// thin-walled lobe of [`with_transmission`](Self::with_transmission); a positive
    /// thickness makes the surface the boundary of a volume of index eta and the lobe Walter
    /// et al. 2007's refraction lobe (radiance transport, without its own Fresnel: kd carries
    /// 1 - F), eta the dielectric base's IOR read back from its F0,
    /// eta = (1 + sqrt(F0)) / (1 - sqrt(F0)) with F0 the mean of the dielectric F0's channels
    /// (exactly KHR_materials_ior's ior while KHR_materials_specular is at its defaults).
    /// eta = 1 (F0 = 0) makes the refraction lobe a Dirac; the thin-walled lobe stands in
    /// for it there. The attenuation colour and distance act along the path inside the volume
    /// ([`crate::transmission::Volume::transmittance`]), the renderer's business, not the
    /// surface's. Without transmission (t = 0) the volume changes nothing.
    #[cfg(feature = "transmission")]
    #[must_use]
    pub fn with_volume(self, volume: crate::transmission::Volume<T>) -> Self {
        Self {
            thickness: volume.thickness(),
            ..self
        }
    }

    /// The volumetric reading's relative index eta (>= 1; [`Self::with_volume`]) and whether
    /// the lobe is the thin-walled one (thickness 0, or eta within rounding of 1).
    #[cfg(feature = "transmission")]
    #[inline]
    fn volume_eta(&self) -> (T, T::Mask) {
        let f0 = self.base.dielectric_f0();
        let r = ((f0.x + f0.y + f0.z) * T::splat(1.0 / 3.0))
            .clamp(T::ZERO, T::ONE)
            .sqrt_nonneg();
        let eta = ((T::ONE + r) / (T::ONE - r).max(T::MIN_POSITIVE)).min(T::MAX);
        // Below 1 + 1e-4 the refraction lobe is narrower than the GGX floor resolves.
        let thin = self.thickness.simd_le(T::ZERO) | eta.simd_le(T::splat(1.0 + 1e-4));
        (eta, thin)
    }

    /// The transmission lobe's BTDF (no Fresnel, no colour) and the half vector whose
    /// wo.h feeds its Fresnel: thin-walled or volumetric by [`Self::volume_eta`].
    #[cfg(feature = "transmission")]
    #[inline]
    fn btdf_and_half(&self, wo: V3<T>, wi: V3<T>) -> (T, V3<T>) {
        use crate::rough_dielectric::{Transport, btdf_without_fresnel};
        let (eta, thin) = self.volume_eta();
        let (wo_a, wi_a) = (self.aniso_local(wo), self.aniso_local(wi));
        let ggx = self.base_ggx();
        let f_thin = crate::transmission::thin_walled_btdf(&ggx, wo_a, wi_a);
        let (f_vol, _) = btdf_without_fresnel(&ggx, wo_a, wi_a, eta, Transport::Radiance);
        let h_thin = (wo + V3::new(wi.x, wi.y, -wi.z)).normalize_or(V3::unit_z());
        let h_vol = self.refraction_half(wo, wi, eta);
        (
            T::select(thin, f_thin, f_vol),
            V3::select(thin, h_thin, h_vol),
        )
    }

    /// The generalized half vector of a refraction from wo (outside) to wi (inside, index
    /// eta): h = -normalize(wo + eta wi) (Walter et al. 2007 eq. 16), +z where degenerate.
    #[cfg(feature = "transmission")]
    #[inline]
    fn refraction_half(&self, wo: V3<T>, wi: V3<T>, eta: T) -> V3<T> {
        -(wo + wi * eta).normalize_or(-V3::unit_z())
    }

    /// The film's factor (0 where the film's thickness is 0) and its RGB reflectance at
    /// `cos_theta` over the dielectric base and over the metal base ([`film_rgb`]).
    #[inline]
    fn film(&self, cos_theta: T) -> Option<Film<T>> {
        #[cfg(feature = "iridescence")]
        {
            let b = &self.base;
            self.iridescence.map(|(factor, film)| {
                let off = film.thickness().simd_eq(T::ZERO);
                (
                    T::select(off, T::ZERO, factor),
                    film_rgb(&film, b.dielectric_f0(), cos_theta),
                    film_rgb(&film, b.base_color(), cos_theta),
                )
            })
        }
        #[cfg(not(feature = "iridescence"))]
        {
            let _ = cos_theta;
            None
        }
    }

    /// The base's mixed Fresnel F and diffuse weight kd for the Schlick weights of
    /// `cos_theta`, with the film's Fresnel mixed in ([`fresnel_and_kd_film`]).
    #[inline]
    fn fresnel_kd(&self, cos_theta: T) -> (V3<T>, V3<T>) {
        self.fresnel_kd_weights(schlick_weights(cos_theta), cos_theta)
    }

    /// [`Self::fresnel_kd`] with the Schlick weights given (the film read at `cos_theta`).
    #[inline]
    fn fresnel_kd_weights(&self, weights: (T, T), cos_theta: T) -> (V3<T>, V3<T>) {
        let b = &self.base;
        fresnel_and_kd_film(
            weights,
            b.base_color(),
            b.metallic(),
            b.dielectric_f0(),
            b.dielectric_f90(),
            b.coupling(),
            self.film(cos_theta),
        )
    }

    /// F and kd at the hemispherical average: Schlick weight 1/21, the film read at the angle
    /// mu* = 1 - 21^(-1/5) = 0.456 where Schlick's weight takes that value (a one-point
    /// reading of the film's average, exact for Schlick's F).
    #[inline]
    fn fresnel_kd_average(&self) -> (V3<T>, V3<T>) {
        self.fresnel_kd_weights(
            (
                T::splat(SCHLICK_WEIGHT_AVERAGE),
                T::splat(1.0 - SCHLICK_WEIGHT_AVERAGE),
            ),
            T::splat(AVERAGE_COS),
        )
    }

    /// The same material with the per-lobe multiple-scattering compensation on or off
    /// (module docs). Off by default, as in the extensions.
    #[must_use]
    pub fn with_compensation(self, on: bool) -> Self {
        Self {
            compensate: on,
            ..self
        }
    }

    /// `w` in the anisotropy frame (tangent rotated by the direction).
    #[inline]
    fn aniso_local(&self, w: V3<T>) -> V3<T> {
        let (c, s) = (self.aniso_cos, self.aniso_sin);
        V3::new(c * w.x + s * w.y, c * w.y - s * w.x, w.z)
    }

    /// `w` from the anisotropy frame back to the local frame.
    #[inline]
    fn aniso_world(&self, w: V3<T>) -> V3<T> {
        let (c, s) = (self.aniso_cos, self.aniso_sin);
        V3::new(c * w.x - s * w.y, s * w.x + c * w.y, w.z)
    }

    /// The base specular's GGX in the anisotropy frame.
    #[inline]
    fn base_ggx(&self) -> Ggx<T> {
        let a = self.base.alpha();
        Ggx::new_unchecked(anisotropy::alpha_t(a.min(T::ONE), self.strength).max(a), a)
    }

    /// The coat's isotropic GGX.
    #[inline]
    fn coat_ggx(&self) -> Ggx<T> {
        Ggx::new_unchecked(self.coat_alpha, self.coat_alpha)
    }

    /// The BRDF f(wo, wi) in RGB (not multiplied by the cosine), the composition of the
    /// module docs with h = normalize(wo + wi). 0 where wo.z <= 0 or wi.z <= 0; NaN where a
    /// component of wo or wi is NaN or infinite.
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> V3<T> {
        let e_v = sheen::albedo(wo.z, self.sheen_alpha);
        let e_l = sheen::albedo(wi.z, self.sheen_alpha);
        let f_coat = clearcoat::fresnel(self.coat_normal.dot(wo));
        self.eval_with(wo, wi, e_v, e_l, f_coat)
    }

    /// The material prepared at the view `wo` (local frame) for many lights: the sheen albedo
    /// E(n.v) and the coat's Fresnel F_coat(n_c.v) are read once here, not per light
    /// ([`Prepared`]). Cost: one table lookup and one Schlick Fresnel.
    #[must_use]
    pub fn at_view(&self, wo: V3<T>) -> Prepared<T> {
        Prepared {
            material: *self,
            wo,
            e_v: sheen::albedo(wo.z, self.sheen_alpha),
            f_coat: clearcoat::fresnel(self.coat_normal.dot(wo)),
        }
    }

    /// [`eval`](Self::eval) with the view's sheen albedo `e_v`, the light's `e_l` and the
    /// coat's Fresnel at the view `f_coat` given.
    #[inline]
    fn eval_with(&self, wo: V3<T>, wi: V3<T>, e_v: T, e_l: T, f_coat: T) -> V3<T> {
        let h = (wo + wi).normalize_or(V3::unit_z());
        let v_dot_h = wo.dot(h);
        let c = Cosines {
            n_dot_v: wo.z,
            n_dot_l: wi.z,
            n_dot_h: h.z,
            v_dot_h,
        };
        let b = &self.base;
        let (f, kd) = self.fresnel_kd(v_dot_h);
        // D V: the isotropic kernels where strength is 0 (so the base is bit for bit the
        // metallic-roughness material's), the anisotropic GGX elsewhere.
        let alpha = b.alpha();
        let iso = ggx::d(h.z, alpha) * ggx::v_correlated(wo.z, wi.z, alpha);
        let ggx = self.base_ggx();
        use crate::microfacet::Microfacet;
        let aniso = ggx.d(self.aniso_local(h))
            * ggx.v_correlated(self.aniso_local(wo), self.aniso_local(wi));
        let dv = T::select(self.strength.simd_eq(T::ZERO), iso, aniso).min(T::MAX);
        let base = b.base_color();
        let mut spec_ms = V3::splat(T::ZERO);
        if self.compensate {
            let m = b.metallic();
            let a_eff = (ggx.alpha_x() * ggx.alpha_y()).sqrt();
            let f0_d = b.dielectric_f0();
            let f90_d = b.dielectric_f90();
            let favg_d = V3::new(
                fresnel_avg_schlick(f0_d.x, f90_d),
                fresnel_avg_schlick(f0_d.y, f90_d),
                fresnel_avg_schlick(f0_d.z, f90_d),
            );
            let favg_m = V3::new(
                fresnel_avg_schlick(base.x, T::ONE),
                fresnel_avg_schlick(base.y, T::ONE),
                fresnel_avg_schlick(base.z, T::ONE),
            );
            // The film's averages read at mu* (as in `fresnel_kd_average`), mixed per lobe.
            let (favg_d, favg_m) = match self.film(T::splat(AVERAGE_COS)) {
                Some((factor, film_d, film_m)) => {
                    let off = factor.simd_eq(T::ZERO);
                    let mix =
                        |a: V3<T>, b: V3<T>| V3::select(off, a, a * (T::ONE - factor) + b * factor);
                    (mix(favg_d, film_d), mix(favg_m, film_m))
                }
                None => (favg_d, favg_m),
            };
            let ms_d = kulla_conty_ggx_rgb(wo.z, wi.z, a_eff, favg_d);
            let ms_m = kulla_conty_ggx_rgb(wo.z, wi.z, a_eff, favg_m);
            spec_ms = ms_d * (T::ONE - m) + ms_m * m;
        }
        // KHR_materials_transmission moves the fraction t of the diffuse lobe below the
        // surface; t = 0 multiplies by exactly 1, leaving the base bit for bit.
        #[cfg(feature = "transmission")]
        let keep = T::ONE - self.transmission;
        #[cfg(not(feature = "transmission"))]
        let keep = T::ONE;
        let channel = |fc: T, kc: T, bc: T, ms: T| {
            let value = fc.mul_add(dv, kc * bc * T::FRAC_1_PI * keep) + ms;
            above_horizon(wo.z, wi.z, value.min(T::MAX))
        };
        let base_f = V3::new(
            channel(f.x, kd.x, base.x, spec_ms.x),
            channel(f.y, kd.y, base.y, spec_ms.y),
            channel(f.z, kd.z, base.z, spec_ms.z),
        );
        // Sheen over the base: f_sheen + base s, one fused multiply-add per channel, so a
        // black sheen (f_sheen = 0, s = 1) leaves the base bit for bit.
        let s = sheen::albedo_scaling(self.sheen_color, e_v, e_l);
        let f_sheen = sheen::charlie(c, self.sheen_color, self.sheen_alpha);
        let sheened = V3::new(
            base_f.x.mul_add(s, f_sheen.x),
            base_f.y.mul_add(s, f_sheen.y),
            base_f.z.mul_add(s, f_sheen.z),
        );
        // The coat about its own normal.
        let nc = self.coat_normal;
        let cc = Cosines {
            n_dot_v: nc.dot(wo),
            n_dot_l: nc.dot(wi),
            n_dot_h: nc.dot(h),
            v_dot_h,
        };
        let mut coat = clearcoat::coat(cc, self.coat_alpha);
        if self.compensate {
            let favg = fresnel_avg_schlick(T::splat(clearcoat::F0), T::ONE);
            coat += kulla_conty_ggx(cc.n_dot_v, cc.n_dot_l, self.coat_alpha, favg);
        }
        let out = clearcoat::layer(sheened, coat, self.clearcoat, f_coat);
        let out = out.map(|x| above_horizon(wo.z, wi.z, x));
        #[cfg(feature = "transmission")]
        let out = self.with_transmitted(out, wo, wi, e_v, f_coat);
        let fin = |x: T| finite_dirs(wo, wi, x);
        V3::new(fin(out.x), fin(out.y), fin(out.z))
    }

    /// `reflected` where wi is above the surface; below it (wo above, t > 0) the
    /// transmission lobe (thin-walled or volumetric) kd(h_T) t baseColor btdf, dimmed by the sheen's view-side scaling
    /// 1 - max(sheenColor) E(n.v) and the coat's 1 - clearcoat F_coat(n_c.v) (the light leaves
    /// through both layers on the view's side).
    #[cfg(feature = "transmission")]
    #[inline]
    fn with_transmitted(&self, reflected: V3<T>, wo: V3<T>, wi: V3<T>, e_v: T, f_coat: T) -> V3<T> {
        let t = self.transmission;
        let b = &self.base;
        let (btdf, h_t) = self.btdf_and_half(wo, wi);
        let (_, kd) = self.fresnel_kd(wo.dot(h_t).clamp(T::ZERO, T::ONE));
        let m = self.sheen_max();
        let through = (T::ONE - self.clearcoat * f_coat) * (T::ONE - m * e_v) * t * btdf;
        let live = t.simd_gt(T::ZERO) & wo.z.simd_gt(T::ZERO) & wi.z.simd_lt(T::ZERO);
        let base = b.base_color();
        let lobe = |kc: T, bc: T, r: T| T::select(live, (kc * bc * through).min(T::MAX), r);
        V3::new(
            lobe(kd.x, base.x, reflected.x),
            lobe(kd.y, base.y, reflected.y),
            lobe(kd.z, base.z, reflected.z),
        )
    }

    /// max(sheenColor).
    #[inline]
    fn sheen_max(&self) -> T {
        self.sheen_color
            .x
            .max(self.sheen_color.y)
            .max(self.sheen_color.z)
    }

    /// The lobe-selection probabilities at wo: (coat, base specular, cosine lobes), summing
    /// to 1 without transmission; with it, the transmission lobe takes the rest, 1 minus
    /// their sum (module docs, "Sampling"). Each lobe whose estimated albedo at wo is
    /// positive has at least 1/19 (the floor [`LOBE_PROBABILITY_MIN`] = 1/16 after
    /// renormalization over at most four lobes: 1/16 / (1 + 3/16)); a lobe of estimate 0
    /// has 0. NaN where a component of wo is NaN or infinite.
    #[must_use]
    pub fn lobe_probabilities(&self, wo: V3<T>) -> V3<T> {
        self.lobe_weights(wo).0
    }

    /// (coat, base specular, cosine lobes) and the transmission lobe's probability, summing
    /// to 1.
    #[inline]
    fn lobe_weights(&self, wo: V3<T>) -> (V3<T>, T) {
        let b = &self.base;
        let mean = |c: V3<T>| (c.x + c.y + c.z) * T::splat(1.0 / 3.0);
        let (f, _) = self.fresnel_kd(wo.z);
        let (_, kd) = self.fresnel_kd_average();
        let w_coat = self.clearcoat * clearcoat::fresnel(self.coat_normal.dot(wo));
        let through = T::ONE - w_coat;
        let m = self.sheen_max();
        let e_v = sheen::albedo(wo.z, self.sheen_alpha);
        let s_v = T::ONE - m * e_v;
        let w_spec = through * s_v * mean(f);
        let base = b.base_color();
        let diffuse = V3::new(kd.x * base.x, kd.y * base.y, kd.z * base.z);
        // The transmission lobe's share of the diffuse weight; t = 0 multiplies by exactly 1
        // and adds exactly 0.
        #[cfg(feature = "transmission")]
        let t = self.transmission;
        #[cfg(not(feature = "transmission"))]
        let t = T::ZERO;
        let w_cos = through * (m * e_v + s_v * (mean(diffuse) * (T::ONE - t)));
        let w_trans = through * s_v * mean(diffuse) * t;
        let sum = w_coat + w_spec + w_cos + w_trans;
        // Nothing reflects (a black, non-specular base without layers): any lobe will do.
        let empty = sum.simd_le(T::ZERO);
        let safe = T::select(empty, T::ONE, sum);
        // The floor (module docs, "Sampling"): each lobe of positive weight gets at least
        // LOBE_PROBABILITY_MIN of the estimate, a lobe of weight 0 (absent, or dark at this
        // view) keeps 0, then all are renormalized.
        let lo = T::splat(LOBE_PROBABILITY_MIN);
        let floor = |w: T| T::select(w.simd_gt(T::ZERO), (w / safe).max(lo), T::ZERO);
        let (f_coat, f_spec, f_cos, f_trans) =
            (floor(w_coat), floor(w_spec), floor(w_cos), floor(w_trans));
        let total = f_coat + f_spec + f_cos + f_trans;
        let total = T::select(empty, T::ONE, total);
        let p = V3::new(
            T::select(empty, T::ZERO, f_coat / total),
            T::select(empty, T::ZERO, f_spec / total),
            T::select(empty, T::ONE, f_cos / total),
        );
        let p_trans = T::select(empty, T::ZERO, f_trans / total);
        let bad = any_nonfinite3(wo);
        (
            V3::new(
                nan_where(bad, p.x),
                nan_where(bad, p.y),
                nan_where(bad, p.z),
            ),
            nan_where(bad, p_trans),
        )
    }

    /// The one-sample mixture pdf (solid angle) of [`sample`](Self::sample): P_coat p_coat +
    /// P_spec p_spec + P_cos max(0, wi.z) / pi, with P from
    /// [`lobe_probabilities`](Self::lobe_probabilities), p_coat the GGX visible-normal
    /// reflection density in the coat normal's frame and p_spec the anisotropic one in the
    /// rotated tangent frame ([`sampling::visible_normal_pdf`], [`sampling::reflect_pdf`]).
    /// A zero-length wo or wi gives 0; a NaN or infinite component of wo or wi gives NaN.
    #[must_use]
    pub fn pdf(&self, wo: V3<T>, wi: V3<T>) -> T {
        let (p, p_trans) = self.lobe_weights(wo);
        let h = (wo + wi).normalize_or(V3::unit_z());
        let wo_dot_h = wo.dot(h);
        let spec = sampling::reflect_pdf(
            sampling::visible_normal_pdf(
                &self.base_ggx(),
                self.aniso_local(wo),
                self.aniso_local(h),
            ),
            wo_dot_h,
        );
        let frame = Frame::from_normal(self.coat_normal);
        let coat = sampling::reflect_pdf(
            sampling::visible_normal_pdf(&self.coat_ggx(), frame.to_local(wo), frame.to_local(h)),
            wo_dot_h,
        );
        let cos = sampling::cosine_hemisphere_pdf(wi);
        let pdf = p.x * coat + p.y * spec + p.z * cos;
        #[cfg(feature = "transmission")]
        let pdf = T::select(
            p_trans.simd_gt(T::ZERO),
            p_trans.mul_add(self.transmission_pdf(wo, wi), pdf),
            pdf,
        );
        #[cfg(not(feature = "transmission"))]
        let _ = p_trans;
        let zero = crate::vec3::is_zero3(wo) | crate::vec3::is_zero3(wi);
        finite_dirs(wo, wi, T::select(zero, T::ZERO, pdf))
    }

    /// The transmission lobe's density at wi: thin-walled, the base specular's at wi mirrored
    /// through the surface plane (the sampler mirrors a specular sample); volumetric, the
    /// visible-normal density of h = -normalize(wo + eta wi) times the refraction Jacobian
    /// eta^2 |wi.h| / (wo.h + eta wi.h)^2 (Walter et al. 2007 eq. 17), 0 where (wo, wi) is no
    /// refraction pair (wo.h <= 0 or wi.h >= 0).
    #[cfg(feature = "transmission")]
    #[inline]
    fn transmission_pdf(&self, wo: V3<T>, wi: V3<T>) -> T {
        let (eta, thin) = self.volume_eta();
        let ggx = self.base_ggx();
        let wo_a = self.aniso_local(wo);
        let h_thin = (wo + V3::new(wi.x, wi.y, -wi.z)).normalize_or(V3::unit_z());
        let p_thin = sampling::reflect_pdf(
            sampling::visible_normal_pdf(&ggx, wo_a, self.aniso_local(h_thin)),
            wo.dot(h_thin),
        );
        let h = self.refraction_half(wo, wi, eta);
        let (o_h, i_h) = (wo.dot(h), wi.dot(h));
        let pair = o_h.simd_gt(T::ZERO) & i_h.simd_lt(T::ZERO);
        let denom = eta.mul_add(i_h, o_h);
        let jacobian = (eta * eta * i_h.abs() / (denom * denom)).min(T::MAX);
        let p_vol =
            (sampling::visible_normal_pdf(&ggx, wo_a, self.aniso_local(h)) * jacobian).min(T::MAX);
        let p_vol = T::select(pair, p_vol, T::ZERO);
        T::select(thin, p_thin, p_vol)
    }

    /// Draws wi for the view `wo` by one-sample lobe selection and returns (wi, pdf) with
    /// pdf = [`pdf`](Self::pdf)(wo, wi). `u1` picks the lobe (coat, base specular, cosine, in
    /// that order) and is rescaled to [0, 1) within it; `u2` is passed on. A reflected
    /// sample can fall below the horizon (returned with its pdf; [`eval`](Self::eval) is 0
    /// there). A NaN or infinite component of wo, or a NaN u1 or u2, gives a NaN direction
    /// and pdf.
    #[must_use]
    pub fn sample(&self, wo: V3<T>, u1: T, u2: T) -> (V3<T>, T) {
        let (p, p_trans) = self.lobe_weights(wo);
        let nan_u = u1.is_nan() | u2.is_nan();
        let u1 = u1.clamp(T::ZERO, T::ONE - T::EPSILON * T::HALF);
        let c1 = p.x;
        let c2 = p.x + p.y;
        // c2 can round just below 1 when the cosine lobes have probability 0: u1 above it
        // then still picks the specular lobe, never a lobe of probability 0.
        let c3 = c2 + p.z;
        let no_trans = p_trans.simd_le(T::ZERO);
        let is_coat = u1.simd_lt(c1);
        let is_spec = !is_coat & (u1.simd_lt(c2) | (p.z.simd_le(T::ZERO) & no_trans));
        // Likewise the cosine lobes take u1 above c3 when transmission has probability 0.
        let is_cos = !is_coat & !is_spec & (u1.simd_lt(c3) | no_trans);
        let below1 = |x: T| x.clamp(T::ZERO, T::ONE - T::EPSILON * T::HALF);
        let u_coat = below1(u1 / p.x);
        let u_spec = below1((u1 - c1) / p.y);
        let u_cos = below1((u1 - c2) / p.z);
        let u_trans = below1((u1 - c3) / p_trans);
        let frame = Frame::from_normal(self.coat_normal);
        let wo_c = frame.to_local(wo);
        let (m_c, _) = sampling::ggx_vndf(&self.coat_ggx(), wo_c, u_coat, u2);
        let wi_coat = frame.to_world(wo_c.mirror(m_c));
        let wo_a = self.aniso_local(wo);
        let (m_a, _) = sampling::ggx_vndf(&self.base_ggx(), wo_a, u_spec, u2);
        let wi_spec = self.aniso_world(wo_a.mirror(m_a));
        let (wi_cos, _) = sampling::cosine_hemisphere(u_cos, u2);
        #[cfg(feature = "transmission")]
        let wi_trans = self.sample_transmission(wo_a, u_trans, u2);
        #[cfg(not(feature = "transmission"))]
        let wi_trans = {
            let _ = u_trans;
            wi_cos
        };
        let wi = V3::select(
            is_coat,
            wi_coat,
            V3::select(is_spec, wi_spec, V3::select(is_cos, wi_cos, wi_trans)),
        );
        let bad = any_nonfinite3(wo) | nan_u;
        let wi = V3::new(
            nan_where(bad, wi.x),
            nan_where(bad, wi.y),
            nan_where(bad, wi.z),
        );
        (wi, self.pdf(wo, wi))
    }

    /// A transmission-lobe direction for `wo_a` (anisotropy frame): a visible normal m of the
    /// base GGX, then the reflection about m mirrored through the surface plane
    /// (thin-walled), or the refraction through m into index eta (Snell's law in vector form,
    /// Walter et al. 2007 eq. 40: wi = (c - eta cos_t) m - wo, normalized, c = wo.m,
    /// eta cos_t = sqrt(eta^2 - 1 + c^2); eta >= 1, so never total internal reflection).
    #[cfg(feature = "transmission")]
    #[inline]
    fn sample_transmission(&self, wo_a: V3<T>, u1: T, u2: T) -> V3<T> {
        let (eta, thin) = self.volume_eta();
        let (m, _) = sampling::ggx_vndf(&self.base_ggx(), wo_a, u1, u2);
        let r = wo_a.mirror(m);
        let thin_a = V3::new(r.x, r.y, -r.z);
        let c = wo_a.dot(m).clamp(T::ZERO, T::ONE);
        let eta_cos_t = (eta.mul_add(eta, -T::ONE) + c * c)
            .sqrt_nonneg()
            .min(T::MAX);
        let vol_a = (m * (c - eta_cos_t) - wo_a).normalize_or(-V3::unit_z());
        self.aniso_world(V3::select(thin, thin_a, vol_a))
    }

    /// [`eval`](Self::eval) from world space: f(v, l) at the shading point `sp` and the
    /// world-space unit light direction `l`. Build `sp` with
    /// [`ShadingPoint::from_frame`] from the mesh's tangent frame
    /// ([`Frame::from_axes`]`(t, b, n)`), so that the anisotropy direction and rotation are
    /// measured from the glTF tangent; [`ShadingPoint::new`] picks an arbitrary tangent, fine
    /// without anisotropy. Equal to `self.eval(sp.wo(), sp.local(l))`.
    #[must_use]
    pub fn eval_world(&self, sp: &ShadingPoint<T>, l: V3<T>) -> V3<T> {
        self.eval(sp.wo(), sp.local(l))
    }

    /// [`pdf`](Self::pdf) from world space: the solid-angle pdf of drawing the world-space
    /// direction `l` at `sp` with [`sample_world`](Self::sample_world).
    #[must_use]
    pub fn pdf_world(&self, sp: &ShadingPoint<T>, l: V3<T>) -> T {
        self.pdf(sp.wo(), sp.local(l))
    }

    /// [`sample`](Self::sample) in world space: (l, pdf) with l = `sp.world(wi)`.
    #[must_use]
    pub fn sample_world(&self, sp: &ShadingPoint<T>, u1: T, u2: T) -> (V3<T>, T) {
        let (wi, pdf) = self.sample(sp.wo(), u1, u2);
        (sp.world(wi), pdf)
    }
}

/// The layered material prepared at one shading point's view direction ([`Layered::at_view`]),
/// to be evaluated for each light without re-reading what depends on the view alone: the
/// sheen albedo E(n.v) and the coat's Fresnel F_coat(n_c.v).
///
/// Two forms of the sheen's albedo scaling of the layer below:
/// - [`eval`](Self::eval), the form KHR_materials_sheen specifies ("Albedo-scaling
///   technique"): s = min(1 - max(sheenColor) E(n.v), 1 - max(sheenColor) E(n.l)), with
///   E(n.v) read once here and E(n.l) per light (it depends on the light). Reciprocal, and
///   equal to [`Layered::eval`] bit for bit (`cargo test --test layers layered::prepared`).
/// - [`eval_view_only`](Self::eval_view_only), the cheaper form the extension allows ("to
///   trade a bit of accuracy for more performance"): s = 1 - max(sheenColor) E(n.v), one
///   value for every light and the environment, no lookup per light. Not reciprocal; equal
///   to the min form where E(n.l) <= E(n.v).
///
/// ```
/// use brdf::V3;
/// use brdf::layers::layered::Layered;
///
/// let m = Layered::new(V3::new(0.5, 0.4, 0.3), 0.0, 0.6)?.with_sheen(V3::splat(0.7), 0.5)?;
/// let wo = V3::new(0.0, 0.6, 0.8);
/// let at = m.at_view(wo);
/// for wi in [V3::new(0.6, 0.0, 0.8), V3::new(0.0, -0.8, 0.6)] {
///     assert_eq!(at.eval(wi), m.eval(wo, wi));
/// }
/// # Ok::<(), brdf::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prepared<T> {
    material: Layered<T>,
    wo: V3<T>,
    e_v: T,
    f_coat: T,
}

impl<T: Real> Prepared<T> {
    /// f(wo, wi) in RGB with the extension's min form of albedo scaling, E(n.v) and
    /// F_coat(n_c.v) taken from the preparation: [`Layered::eval`]`(wo, wi)` bit for bit, with
    /// its domain and edges (0 below either horizon, NaN for a NaN or infinite component of
    /// wo or wi).
    #[must_use]
    pub fn eval(&self, wi: V3<T>) -> V3<T> {
        let m = &self.material;
        let e_l = sheen::albedo(wi.z, m.sheen_alpha);
        m.eval_with(self.wo, wi, self.e_v, e_l, self.f_coat)
    }

    /// f(wo, wi) in RGB with the extension's view-only albedo scaling
    /// s = 1 - max(sheenColor) E(n.v): no sheen albedo read per light. Equal to
    /// [`eval`](Self::eval) for a black sheen, and wherever E(n.l) <= E(n.v); above it
    /// (grazing lights of rough sheens) the base is dimmed less than by the min form. Same
    /// domain and edges as [`Layered::eval`].
    #[must_use]
    pub fn eval_view_only(&self, wi: V3<T>) -> V3<T> {
        self.material
            .eval_with(self.wo, wi, self.e_v, self.e_v, self.f_coat)
    }
}

/// The film's reflectance in linear Rec.709 RGB over a base given by its per-channel F0
/// (KHR_materials_iridescence, "Iridescence Fresnel"): each channel's base index from its F0
/// as the extension's `Fresnel0ToIor`, n = (1 + sqrt(F0)) / (1 - sqrt(F0)) with no
/// extinction (for metals too, the base colour read as F0), under air (outside index 1, as
/// the Sample Viewer), the film's XYZ reflectance by [`iridescence::dielectric`] converted
/// with [`iridescence::XYZ_TO_REC709`] and divided per channel by the conversion of the
/// equal-energy white (1, 1, 1) (row sums 1.205, 0.948, 0.909), so that a spectrally flat
/// reflectance R, the limit of a vanishing film, is (R, R, R): the Sample Viewer reaches the
/// same flat limit by adding the film's flat term unconverted. Each channel clamped to
/// [0, 1] (out-of-gamut colours). F0 = 1 gives an index capped at MAX (the film's base ratio
/// is capped, its F within 4e-6 of 1).
#[cfg(feature = "iridescence")]
#[inline]
fn film_rgb<T: Real>(film: &ThinFilm<T>, f0: V3<T>, cos_theta: T) -> V3<T> {
    let channel = |f0: T, row: [f64; 3]| {
        let r = f0.saturate().sqrt_nonneg();
        let ior = ((T::ONE + r) / (T::ONE - r).max(T::MIN_POSITIVE)).min(T::MAX);
        let xyz = iridescence::dielectric(film, T::ONE, ior, cos_theta);
        let white = row[0] + row[1] + row[2];
        let rgb = T::splat(row[0] / white) * xyz.x
            + T::splat(row[1] / white) * xyz.y
            + T::splat(row[2] / white) * xyz.z;
        rgb.saturate()
    };
    let m = iridescence::XYZ_TO_REC709;
    V3::new(
        channel(f0.x, m[0]),
        channel(f0.y, m[1]),
        channel(f0.z, m[2]),
    )
}
