//! Engine conventions as data: the roughness floor, Fresnel form, visibility guard and diffuse
//! term of five real-time renderers, evaluated with the crate's own kernels.
//!
//! A shader ported from three.js, Filament, bevy, Unreal Engine 4 or the Khronos glTF sample
//! viewer computes the same metallic-roughness BRDF in five slightly different ways: each clamps
//! perceptual roughness to its own floor, picks a Fresnel approximation and a rule for its
//! grazing value F90, guards the visibility term against division by zero with its own epsilon,
//! and weights its diffuse lobe its own way. [`Convention`] holds those choices as plain data
//! (public fields of small enums and numbers), and its methods evaluate them with the crate's
//! numerically careful kernels ([`ggx::d`], [`ggx::v_correlated`], [`ggx::v_schlick`],
//! [`fresnel::schlick`], [`fresnel::schlick_sg`], [`diffuse::lambert`], [`diffuse::burley`]),
//! applying each engine's floors and guards where that engine applies them. The result is the
//! engine's BRDF without the rounding its shader form adds (three.js's and the glTF viewer's
//! `NoH^2 (a^2 - 1) + 1` keeps no digit of a small alpha near n.h = 1, for one).
//!
//! ```
//! use brdf::engine::{ALL, BEVY, THREE_JS};
//! use brdf::{Cosines, V3};
//!
//! let c = Cosines { n_dot_v: 0.8_f32, n_dot_l: 0.6, n_dot_h: 0.99, v_dot_h: 0.96 };
//! let gold = V3::new(1.0, 0.766, 0.336);
//! // A smooth metal below three.js's roughness floor (0.0525) and above bevy's (0.089)...
//! let t = THREE_JS.brdf(c, gold, 1.0, 0.04);
//! let b = BEVY.brdf(c, gold, 1.0, 0.04);
//! assert!(t.x != b.x); // ...shades differently in each engine.
//! for e in ALL {
//!     assert!(e.brdf(c, gold, 0.5, 0.5).x.is_finite(), "{}", e.name);
//! }
//! ```
//!
//! # What differs (punctual light, metallic-roughness core, default material)
//! | | three.js | Filament | bevy | Unreal Engine 4 | glTF sample viewer |
//! |---|---|---|---|---|---|
//! | roughness floor | 0.0525 | 0.045 | 0.089 | none | none |
//! | n.v floor | none | 1e-4 | 1e-4 | none | none |
//! | D | GGX | GGX, denominator >= 0.0023 | GGX | GGX | GGX |
//! | V | correlated Smith, 0.5 / max(den, 1e-6) | correlated Smith, 0.5 / max(den, 7.7e-6) | correlated Smith, no guard | Schlick-GGX, k = (r + 1)^2 / 8 | correlated Smith, 0 for den <= 0 |
//! | Fresnel | Schlick, spherical-Gaussian exp2 | Schlick pow5 | Schlick pow5 | Schlick, spherical-Gaussian exp2 | Schlick pow5 |
//! | F90 | 1 | saturate(16.5 (f0.r + f0.g + f0.b)) | saturate(16.5 (f0.r + f0.g + f0.b)) | 1 | 1 |
//! | diffuse | Lambert | Lambert | Burley of alpha | Lambert | Lambert |
//! | diffuse weight | 1 - metallic | 1 - metallic | 1 - metallic | 1 - metallic | (1 - metallic)(1 - F_dielectric) |
//!
//! Every engine squares the (clamped) perceptual roughness into alpha and takes F0 =
//! lerp(0.04, base colour, metallic) for its default dielectric (three.js's
//! `MeshStandardMaterial`, Filament's reflectance 0.5, bevy's reflectance 0.5, Unreal's
//! `Specular` 0.5, glTF's IOR 1.5). Every method below returns the BRDF without the n.l factor:
//! all five engines multiply by n.l (and the light's intensity) outside the BRDF, the glTF
//! viewer inside its mix, which is linear, so the factor moves out unchanged.
//!
//! # Left out, on purpose
//! Filament and bevy multiply their specular lobe by an energy-compensation factor from a
//! DFG table or fit (`pixel.energyCompensation`, bevy's `specular_multiscatter`); three.js
//! widens roughness by the screen-space derivative of the normal (`geometryRoughness`); bevy
//! widens it for spherical lights. These depend on more than the BRDF's arguments and are
//! omitted (a flat surface, a point light, energy compensation 1); multiply by
//! the `ibl::energy` or `ibl::dfg` factors (feature `ibl`) to add them back.
//!
//! # Domains and bad input
//! The crate's rule holds on every method (crate docs, "Bad input"): base colour, metallic,
//! roughness, F0 and F90 in [0, 1], NaN outside and for NaN; cosines clamped to [0, 1]; 0 where
//! n.v <= 0 or n.l <= 0 (engines that floor n.v at 1e-4 shade a view below the horizon; this
//! module does not); finite for finite in-domain input, on every lane type. Where an engine has
//! no roughness floor (Unreal Engine 4, the glTF viewer, whose D is 0 / 0 at alpha = 0,
//! n.h = 1), the crate's [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN) floor applies instead.
//!
//! # Sources
//! Each constant's [`Source`] names the repository, files and revision its facts were read from.
//! Unreal Engine 4's shader source (`Engine/Shaders/Private/BRDF.ush`) is not public: its
//! convention here is the one Karis 2013, "Real Shading in Unreal Engine 4" (SIGGRAPH course
//! notes), publishes; the shipping shaders may differ from the notes, and are not checked here.
//!
//! [`ggx::d`]: crate::ggx::d
//! [`ggx::v_correlated`]: crate::ggx::v_correlated
//! [`ggx::v_schlick`]: crate::ggx::v_schlick
//! [`fresnel::schlick`]: crate::fresnel::schlick
//! [`fresnel::schlick_sg`]: crate::fresnel::schlick_sg
//! [`diffuse::lambert`]: crate::diffuse::lambert
//! [`diffuse::burley`]: crate::diffuse::burley

use crate::domain::{above_horizon, in_unit, nan_unless, nan_where};
use crate::microfacet::alpha_from_perceptual;
use crate::real::Real;
use crate::shading::Cosines;
use crate::vec3::V3;
use crate::{diffuse, fresnel, ggx};

/// True where any of the four cosines is NaN.
#[inline]
fn any_nan<T: Real>(c: Cosines<T>) -> T::Mask {
    c.n_dot_v.is_nan() | c.n_dot_l.is_nan() | c.n_dot_h.is_nan() | c.v_dot_h.is_nan()
}

/// Where a convention's facts were read: a repository (or publication) and the files in it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Source {
    /// `owner/name` of the repository, or the publication for Unreal Engine 4.
    pub repository: &'static str,
    /// The files read, each with the commit or release tag of the copy read.
    pub files: &'static [SourceFile],
}

/// One file of a [`Source`] and the revision it was read at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SourceFile {
    /// Path in the repository (or section of the publication).
    pub path: &'static str,
    /// Commit hash or release tag of the copy read (or the publication year).
    pub revision: &'static str,
    /// What the convention takes from it.
    pub provides: &'static str,
}

/// How perceptual roughness r (after the floor) becomes the GGX width alpha.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlphaRemap {
    /// alpha = r^2 (Burley 2012): every engine here.
    Squared,
}

/// Which Schlick weight w(v.h) the Fresnel term F = F0 + (F90 - F0) w uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FresnelForm {
    /// w = (1 - v.h)^5 (Schlick 1994): [`fresnel::schlick`].
    SchlickPow5,
    /// w = 2^((-5.55473 v.h - 6.98316) v.h), the spherical-Gaussian fit of Karis 2013:
    /// [`fresnel::schlick_sg`]. 2^-12.54 (not 0) at v.h = 1.
    SchlickSphericalGaussian,
}

/// How an engine derives the grazing reflectance F90 from F0 in its metallic-roughness path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum F90Rule {
    /// F90 = 1.
    One,
    /// F90 = saturate(scale (f0.r + f0.g + f0.b)): Filament's and bevy's `fresnel(f0, LoH)`
    /// with scale = 50 x 0.33 = 16.5, so any F0 above 2% reflects fully at grazing and a
    /// darker one (a pre-baked cavity) less.
    SaturatedF0Sum {
        /// The factor on the channel sum (16.5).
        scale: f64,
    },
}

/// The visibility term V = G2 / (4 n.v n.l) and the guard an engine puts on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Visibility {
    /// Height-correlated Smith GGX, [`ggx::v_correlated`], as the
    /// engines write it: V = 0.5 / max(den, `denominator_floor`), den = n.l sqrt(n.v^2 (1 -
    /// alpha^2) + alpha^2) + n.v sqrt(n.l^2 (1 - alpha^2) + alpha^2). A floor of 0 means no
    /// guard (den > 0 wherever n.v > 0 and n.l > 0, so none is needed there).
    SmithGgxCorrelated {
        /// The lower bound the engine puts on den (three.js 1e-6, Filament 7.7e-6).
        denominator_floor: f64,
    },
    /// Separable Schlick-GGX with k = (r + 1)^2 / 8 of the perceptual roughness r, Karis
    /// 2013's remap for analytic lights: [`ggx::v_schlick`] with
    /// [`ggx::schlick_k_analytic`].
    SchlickGgxAnalytic,
}

/// The diffuse lobe.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiffuseLobe {
    /// rho / pi: [`diffuse::lambert`].
    Lambert,
    /// Burley 2012 fed the GGX width alpha as its roughness (bevy's `Fd_Burley` reads
    /// `layers[0].roughness`, which holds alpha = r^2, not r):
    /// [`diffuse::burley`]`(n.v, n.l, v.h, rho, alpha)`.
    BurleyOfAlpha,
}

/// How [`Convention::brdf`] weights the diffuse lobe of base colour c.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiffuseWeight {
    /// diffuse colour = c (1 - metallic), lobes added: three.js, Filament, bevy, Karis 2013.
    OneMinusMetallic,
    /// diffuse colour = c (1 - metallic)(1 - F_dielectric(v.h)) per channel, F_dielectric the
    /// dielectric's Schlick term with F90 = 1: the glTF 2.0 Appendix B composition
    /// `mix(mix(diffuse, specular, F_dielectric), F_metal specular, metallic)`.
    OneMinusMetallicOneMinusF,
}

/// An engine's metallic-roughness conventions, as data. See the [module docs](self) for the
/// table of differences; the fields are public so a porter can read (or, for a renderer not
/// listed, write) every choice.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Convention {
    /// The engine's name.
    pub name: &'static str,
    /// Where the facts below were read.
    pub source: Source,
    /// Lower clamp of the perceptual roughness r before the remap (the upper clamp is 1 for
    /// all five); 0 = none, where the crate's `ALPHA_MIN` floor still applies.
    pub roughness_floor: f64,
    /// r to alpha.
    pub alpha_remap: AlphaRemap,
    /// Lower clamp of n.v for n.v > 0 (Filament's `MIN_N_DOT_V`, bevy's `max(NdotV, 0.0001)`);
    /// 0 = none.
    pub n_dot_v_floor: f64,
    /// Lower clamp of the GGX denominator t = (1 - n.h^2) + (n.h alpha)^2 in
    /// D = alpha^2 / (pi t^2) (Filament's 0.0023, which keeps D below the largest `f16`);
    /// 0 = none.
    pub ndf_denominator_floor: f64,
    /// The visibility term and its guard.
    pub visibility: Visibility,
    /// The Schlick weight.
    pub fresnel: FresnelForm,
    /// F90 of the metallic-roughness path.
    pub f90: F90Rule,
    /// F0 of the default dielectric.
    pub dielectric_f0: f64,
    /// The diffuse lobe.
    pub diffuse: DiffuseLobe,
    /// The diffuse weight in [`Convention::brdf`].
    pub diffuse_weight: DiffuseWeight,
}

/// three.js `MeshStandardMaterial` (WebGL renderer), direct lighting.
pub const THREE_JS: Convention = Convention {
    name: "three.js",
    source: Source {
        repository: "mrdoob/three.js",
        files: &[
            SourceFile {
                path: "src/renderers/shaders/ShaderChunk/bsdfs.glsl.js",
                revision: "12f550e0f44f68e5b6c946dd242ee08e42d209e4",
                provides: "F_Schlick (exp2 weight, f0 (1 - w) + f90 w), BRDF_Lambert",
            },
            SourceFile {
                path: "src/renderers/shaders/ShaderChunk/lights_physical_pars_fragment.glsl.js",
                revision: "r16x release build (BRDF_GGX, V_GGX_SmithCorrelated, D_GGX and \
                           RE_Direct_Physical read from a bundled build; commit not pinned)",
                provides: "D_GGX, V_GGX_SmithCorrelated, BRDF_GGX, RE_Direct_Physical (additive lobes)",
            },
            SourceFile {
                path: "src/renderers/shaders/ShaderChunk/lights_physical_fragment.glsl.js",
                revision: "r16x release build (same bundle; commit not pinned)",
                provides: "roughness = min(max(r, 0.0525) + geometryRoughness, 1), diffuseColor \
                           = base (1 - metalness), specularColor = mix(0.04, base, metalness), \
                           specularF90 = 1",
            },
            SourceFile {
                path: "src/renderers/shaders/ShaderChunk/common.glsl.js",
                revision: "cfa421245d0ea3a21de6a29a8950e04ce6995df8",
                provides: "EPSILON = 1e-6",
            },
        ],
    },
    roughness_floor: 0.0525,
    alpha_remap: AlphaRemap::Squared,
    n_dot_v_floor: 0.0,
    ndf_denominator_floor: 0.0,
    visibility: Visibility::SmithGgxCorrelated {
        denominator_floor: 1e-6,
    },
    fresnel: FresnelForm::SchlickSphericalGaussian,
    f90: F90Rule::One,
    dielectric_f0: 0.04,
    diffuse: DiffuseLobe::Lambert,
    diffuse_weight: DiffuseWeight::OneMinusMetallic,
};

/// Filament's standard lit model at `FILAMENT_QUALITY_HIGH` on desktop (correlated Smith
/// visibility, Lambert diffuse, no clear coat, reflectance 0.5).
pub const FILAMENT: Convention = Convention {
    name: "Filament",
    source: Source {
        repository: "google/filament",
        files: &[
            SourceFile {
                path: "shaders/src/surface_brdf.fs",
                revision: "828846b024da5045afed13502331e1cb5e9670c1",
                provides: "D_GGX (max(1 - NoH^2 + (NoH a)^2, 0.0023)), V_SmithGGXCorrelated \
                           (max(den, 0.0000077)), F_Schlick pow5, fresnel() f90 = \
                           saturate(dot(f0, 50 * 0.33)), Fd_Lambert",
            },
            SourceFile {
                path: "shaders/src/surface_shading_model_standard.fs",
                revision: "a5fba7078225b9d7c97ca35f24d0c0d7507b63e3",
                provides: "surfaceShading: Fd + Fr energyCompensation, times NoL outside",
            },
            SourceFile {
                path: "shaders/src/common_material.fs",
                revision: "90818706ecf5a4c33a89b3f317335021f8e31cd3",
                provides: "MIN_PERCEPTUAL_ROUGHNESS 0.045 (desktop), MIN_N_DOT_V 1e-4, \
                           computeDiffuseColor, computeF0, computeDielectricF0",
            },
        ],
    },
    roughness_floor: 0.045,
    alpha_remap: AlphaRemap::Squared,
    n_dot_v_floor: 1e-4,
    ndf_denominator_floor: 0.0023,
    visibility: Visibility::SmithGgxCorrelated {
        denominator_floor: 0.0000077,
    },
    fresnel: FresnelForm::SchlickPow5,
    f90: F90Rule::SaturatedF0Sum { scale: 16.5 },
    dielectric_f0: 0.04,
    diffuse: DiffuseLobe::Lambert,
    diffuse_weight: DiffuseWeight::OneMinusMetallic,
};

/// bevy's `StandardMaterial` (reflectance 0.5, no clear coat or anisotropy), point light of
/// radius 0.
pub const BEVY: Convention = Convention {
    name: "bevy",
    source: Source {
        repository: "bevyengine/bevy",
        files: &[
            SourceFile {
                path: "crates/bevy_pbr/src/render/pbr_lighting.wgsl",
                revision: "v0.15.0 (3f2baf8ecd7f8948fb67cf11b0f2811d7a1ca1ae)",
                provides: "D_GGX, V_SmithGGXCorrelated (no guard), F_Schlick_vec pow5, fresnel() \
                           f90 = saturate(dot(f0, 50 * 0.33)), Fd_Burley(roughness = alpha), \
                           perceptualRoughnessToRoughness (clamp 0.089..1), point_light \
                           (diffuse + specular)",
            },
            SourceFile {
                path: "crates/bevy_pbr/src/render/pbr_functions.wgsl",
                revision: "v0.15.0 (3f2baf8ecd7f8948fb67cf11b0f2811d7a1ca1ae)",
                provides: "NdotV = max(dot(N, V), 0.0001), calculate_diffuse_color, calculate_F0",
            },
        ],
    },
    roughness_floor: 0.089,
    alpha_remap: AlphaRemap::Squared,
    n_dot_v_floor: 1e-4,
    ndf_denominator_floor: 0.0,
    visibility: Visibility::SmithGgxCorrelated {
        denominator_floor: 0.0,
    },
    fresnel: FresnelForm::SchlickPow5,
    f90: F90Rule::SaturatedF0Sum { scale: 16.5 },
    dielectric_f0: 0.04,
    diffuse: DiffuseLobe::BurleyOfAlpha,
    diffuse_weight: DiffuseWeight::OneMinusMetallic,
};

/// Unreal Engine 4 as Karis 2013 publishes it (analytic lights, `Specular` 0.5).
pub const UNREAL_4: Convention = Convention {
    name: "Unreal Engine 4",
    source: Source {
        repository: "Karis 2013, \"Real Shading in Unreal Engine 4\", SIGGRAPH 2013 course \
                     \"Physically Based Shading in Theory and Practice\" (BRDF.ush is not public)",
        files: &[SourceFile {
            path: "course notes, \"Shading Model\": Diffuse BRDF, Specular D, G and F",
            revision: "2013",
            provides: "Lambert c_diff / pi, GGX D with alpha = Roughness^2, Schlick G with k = \
                       (Roughness + 1)^2 / 8, Fresnel 2^((-5.55473 VoH - 6.98316) VoH), \
                       SpecularColor = lerp(0.08 Specular, BaseColor, Metallic)",
        }],
    },
    roughness_floor: 0.0,
    alpha_remap: AlphaRemap::Squared,
    n_dot_v_floor: 0.0,
    ndf_denominator_floor: 0.0,
    visibility: Visibility::SchlickGgxAnalytic,
    fresnel: FresnelForm::SchlickSphericalGaussian,
    f90: F90Rule::One,
    dielectric_f0: 0.04,
    diffuse: DiffuseLobe::Lambert,
    diffuse_weight: DiffuseWeight::OneMinusMetallic,
};

/// The Khronos glTF-Sample-Viewer's punctual lights (glTF 2.0 Appendix B, IOR 1.5, no
/// extensions).
pub const KHRONOS_SAMPLE_VIEWER: Convention = Convention {
    name: "Khronos glTF sample viewer",
    source: Source {
        repository: "KhronosGroup/glTF-Sample-Viewer",
        files: &[
            SourceFile {
                path: "source/Renderer/shaders/brdf.glsl",
                revision: "d0b428c8946052cb640c4cf772686eb6c3abf3c2",
                provides: "F_Schlick pow5 (clamped 1 - VdotH), V_GGX (0 for den <= 0), D_GGX, \
                           BRDF_lambertian, BRDF_specularGGX",
            },
            SourceFile {
                path: "source/Renderer/shaders/pbr.frag",
                revision: "31732a895183cb6665e7714f02f491e5b9e09f02 (stored copy; the \
                           composition was read from excerpts of the same code)",
                provides: "mix(mix(l_diffuse, l_specular, dielectric_fresnel), metal_fresnel \
                           l_specular, metallic)",
            },
            SourceFile {
                path: "source/Renderer/shaders/material_info.glsl",
                revision: "4e1b2ec37a13afae4eebf86ca0b677a2ee7fadb9 (stored copy)",
                provides: "perceptualRoughness = clamp(r, 0, 1), alphaRoughness = r^2 (no floor)",
            },
        ],
    },
    roughness_floor: 0.0,
    alpha_remap: AlphaRemap::Squared,
    n_dot_v_floor: 0.0,
    ndf_denominator_floor: 0.0,
    visibility: Visibility::SmithGgxCorrelated {
        denominator_floor: 0.0,
    },
    fresnel: FresnelForm::SchlickPow5,
    f90: F90Rule::One,
    dielectric_f0: 0.04,
    diffuse: DiffuseLobe::Lambert,
    diffuse_weight: DiffuseWeight::OneMinusMetallicOneMinusF,
};

/// The five conventions, in the order of the reference CLI's `convention` argument (0 =
/// three.js, 1 = Filament, 2 = bevy, 3 = Unreal Engine 4, 4 = Khronos glTF sample viewer).
pub const ALL: [Convention; 5] = [THREE_JS, FILAMENT, BEVY, UNREAL_4, KHRONOS_SAMPLE_VIEWER];

impl Convention {
    /// The GGX width alpha of perceptual roughness r as the engine forms it:
    /// alpha = clamp(r, `roughness_floor`, 1)^2 ([`AlphaRemap::Squared`]), floored at the
    /// crate's [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN) = 1e-4 (r = 0.01) where the
    /// engine's own floor is lower (Unreal Engine 4 and the glTF viewer have none, and give
    /// 0 / 0 at alpha = 0).
    ///
    /// Domain r in [0, 1] (glTF's `roughnessFactor`, three.js's `roughness`, Filament's and
    /// bevy's `perceptual_roughness`, Unreal's `Roughness`); outside and NaN give NaN.
    /// Below the floor every r gives the floor's alpha (three.js: 0.0525^2 = 0.00275625).
    ///
    /// Sources: three.js `lights_physical_fragment.glsl.js`, Filament `common_material.fs`
    /// (`MIN_PERCEPTUAL_ROUGHNESS`), bevy `pbr_lighting.wgsl` (`perceptualRoughnessToRoughness`),
    /// Karis 2013, glTF-Sample-Viewer `material_info.glsl`, at the revisions of each
    /// constant's [`Source`].
    #[inline]
    #[must_use]
    pub fn alpha<T: Real>(&self, perceptual_roughness: T) -> T {
        let r = self.clamped_roughness(perceptual_roughness);
        let alpha = match self.alpha_remap {
            AlphaRemap::Squared => alpha_from_perceptual(r),
        };
        nan_unless(in_unit(perceptual_roughness), alpha)
    }

    /// r clamped to [`roughness_floor`, 1] (NaN passes to the caller's domain check).
    #[inline]
    fn clamped_roughness<T: Real>(&self, r: T) -> T {
        r.max(T::splat(self.roughness_floor)).min(T::ONE)
    }

    /// F90 of F0 by the engine's rule ([`F90Rule`]): 1, or saturate(16.5 (f0.r + f0.g + f0.b))
    /// for Filament and bevy (so F90 < 1 only for F0 summing below 0.0606: a metal darker than
    /// 2% per channel).
    ///
    /// Domain: each channel of `f0` in [0, 1]; outside and NaN give NaN.
    ///
    /// Sources: Filament `surface_brdf.fs` (`fresnel(f0, LoH)`), bevy `pbr_lighting.wgsl`
    /// (`fresnel`); three.js `lights_physical_fragment.glsl.js` (`specularF90 = 1.0`), Karis 2013
    /// (F90 = 1), glTF-Sample-Viewer `brdf.glsl` (`F_Schlick(f0, VdotH)`, f90 = 1).
    #[inline]
    #[must_use]
    pub fn f90<T: Real>(&self, f0: V3<T>) -> T {
        let ok = in_unit(f0.x) & in_unit(f0.y) & in_unit(f0.z);
        let v = match self.f90 {
            F90Rule::One => T::ONE,
            F90Rule::SaturatedF0Sum { scale } => {
                (T::splat(scale) * (f0.x + f0.y + f0.z)).min(T::ONE)
            }
        };
        nan_unless(ok, v)
    }

    /// The engine's Schlick Fresnel term F = F0 + (F90 - F0) w per channel, with
    /// w = (1 - v.h)^5 ([`FresnelForm::SchlickPow5`], Filament, bevy, the glTF viewer) or
    /// w = 2^((-5.55473 v.h - 6.98316) v.h) ([`FresnelForm::SchlickSphericalGaussian`],
    /// three.js and Karis 2013), evaluated as F0 (1 - w) + F90 w (exactly F0 where w = 0 and
    /// F90 where w = 1).
    ///
    /// Domain: `f0` channels and `f90` in [0, 1] (outside and NaN give NaN in every channel);
    /// `v_dot_h` clamped to [0, 1] as every engine saturates it (NaN gives NaN). Edges: v.h = 0 gives F90; v.h =
    /// 1 gives F0 for pow5 and F0 + (F90 - F0) 2^-12.54 for the exp2 fit. The weight is
    /// [`fresnel::schlick`]'s (rounding of 1 - v.h restored, within
    /// 3.2 ULP) or [`fresnel::schlick_sg`]'s.
    ///
    /// Sources: three.js `bsdfs.glsl.js` (`F_Schlick`), Filament `surface_brdf.fs`
    /// (`F_Schlick`), bevy `pbr_lighting.wgsl` (`F_Schlick_vec`), Karis 2013 (Fresnel),
    /// glTF-Sample-Viewer `brdf.glsl` (`F_Schlick`), at each [`Source`]'s revision.
    #[inline]
    #[must_use]
    pub fn fresnel<T: Real>(&self, f0: V3<T>, f90: T, v_dot_h: T) -> V3<T> {
        let w = self.schlick_weight(v_dot_h);
        // One check for all channels: a bad (or NaN) channel makes the colour NaN, as it does
        // in every RGB kernel of this module.
        let ok = in_unit(f90) & in_unit(f0.x) & in_unit(f0.y) & in_unit(f0.z);
        f0.map(|f| nan_unless(ok, f.mul_add(T::ONE - w, w * f90)))
    }

    /// w of [`Convention::fresnel`]: `schlick(0, c)` and `schlick_sg(0, c)` are exactly their
    /// weights (0 (1 - w) + 1 w rounds to w). NaN for a NaN cosine.
    #[inline]
    fn schlick_weight<T: Real>(&self, v_dot_h: T) -> T {
        let w = match self.fresnel {
            FresnelForm::SchlickPow5 => fresnel::schlick(T::ZERO, v_dot_h),
            FresnelForm::SchlickSphericalGaussian => fresnel::schlick_sg(T::ZERO, v_dot_h),
        };
        nan_where(v_dot_h.is_nan(), w)
    }

    /// 1 - w without cancellation: for pow5, 1 - (1 - c)^5 = c (1 + s + s^2 + s^3 + s^4) with
    /// s = 1 - c, a sum of positive terms (1 - w as written keeps no digit as c -> 0, where
    /// 1 - w = 5c + ...); for the exp2 fit, 1 - w as written.
    #[inline]
    fn one_minus_schlick_weight<T: Real>(&self, v_dot_h: T) -> T {
        match self.fresnel {
            FresnelForm::SchlickPow5 => {
                let c = v_dot_h.saturate();
                let s = T::ONE - c;
                let sum = s.mul_add(s.mul_add(s.mul_add(s + T::ONE, T::ONE), T::ONE), T::ONE);
                nan_where(v_dot_h.is_nan(), c * sum)
            }
            FresnelForm::SchlickSphericalGaussian => T::ONE - self.schlick_weight(v_dot_h),
        }
    }

    /// n.v raised to the engine's floor where it is positive; <= 0 and NaN pass unchanged
    /// (the horizon and NaN checks read them).
    #[inline]
    fn floored_n_dot_v<T: Real>(&self, n_dot_v: T) -> T {
        T::select(
            n_dot_v.simd_gt(T::ZERO),
            n_dot_v.max(T::splat(self.n_dot_v_floor)),
            n_dot_v,
        )
    }

    /// The engine's GGX D: [`ggx::d`], capped where the engine floors its
    /// denominator t at g: alpha^2 / (pi max(t, g)^2) = min(D, (alpha / g)^2 / pi).
    #[inline]
    fn d<T: Real>(&self, n_dot_h: T, alpha: T) -> T {
        let d = ggx::d(n_dot_h, alpha);
        if self.ndf_denominator_floor > 0.0 {
            let k = alpha / T::splat(self.ndf_denominator_floor);
            nan_where(d.is_nan(), d.min(k * k * T::FRAC_1_PI))
        } else {
            d
        }
    }

    /// The engine's V ([`Visibility`]) of the floored n.v, n.l, alpha and the clamped
    /// perceptual roughness r (Schlick-GGX's k reads r, not alpha).
    #[inline]
    fn v<T: Real>(&self, n_dot_v: T, n_dot_l: T, alpha: T, r: T) -> T {
        match self.visibility {
            Visibility::SmithGgxCorrelated { denominator_floor } => {
                let v = ggx::v_correlated(n_dot_v, n_dot_l, alpha);
                if denominator_floor > 0.0 {
                    // 0.5 / max(den, g) = min(0.5 / den, 0.5 / g): V is decreasing in den.
                    nan_where(v.is_nan(), v.min(T::splat(0.5 / denominator_floor)))
                } else {
                    v
                }
            }
            Visibility::SchlickGgxAnalytic => {
                ggx::v_schlick(n_dot_v, n_dot_l, ggx::schlick_k_analytic(r))
            }
        }
    }

    /// The engine's specular lobe for one punctual light, without n.l:
    /// f_s = D(n.h, alpha) V(n.v, n.l) F(v.h) per channel, with alpha = [`Convention::alpha`],
    /// n.v raised to `n_dot_v_floor`, D = [`ggx::d`] under the engine's
    /// denominator floor, V by [`Visibility`] under its guard, F = [`Convention::fresnel`].
    ///
    /// Domain: `roughness` (perceptual), `f0` channels and `f90` in [0, 1]; outside and NaN
    /// give NaN (also below the horizon). Cosines clamped to [-1, 1]; 0 where n.v <= 0 or
    /// n.l <= 0; n.h <= 0 gives D = 0. Finite for finite in-domain input: D V is capped at the
    /// largest finite value (reached only where both n.v and n.l are near the smallest
    /// normal in engines without a guard). Accuracy: each factor within a few ULP (D and
    /// the correlated V correctly rounded, the Schlick weight within 3.2 ULP, the engine
    /// guards exact), two products and one fused lerp on top.
    ///
    /// Sources: three.js `BRDF_GGX`, Filament `isotropicLobe`, bevy `specular` (with
    /// `specular_intensity` 1 and energy compensation 1), Karis 2013 (specular BRDF),
    /// glTF-Sample-Viewer `BRDF_specularGGX` times `F_Schlick`, at each [`Source`]'s revision.
    #[inline]
    #[must_use]
    pub fn specular<T: Real>(&self, c: Cosines<T>, roughness: T, f0: V3<T>, f90: T) -> V3<T> {
        let alpha = self.alpha(roughness);
        let nv = self.floored_n_dot_v(c.n_dot_v);
        let d = self.d(c.n_dot_h, alpha);
        let v = self.v(nv, c.n_dot_l, alpha, self.clamped_roughness(roughness));
        let dv = nan_where(d.is_nan() | v.is_nan(), (d * v).min(T::MAX));
        let f = self.fresnel(f0, f90, c.v_dot_h);
        // The checks wrap the horizon guard, so a bad parameter or a NaN cosine is NaN below
        // the horizon too.
        let ok = in_unit(roughness) & in_unit(f90) & in_unit(f0.x) & in_unit(f0.y) & in_unit(f0.z);
        let nan = any_nan(c);
        f.map(|fc| {
            nan_unless(
                ok,
                nan_where(nan, above_horizon(c.n_dot_v, c.n_dot_l, fc * dv)),
            )
        })
    }

    /// The engine's diffuse lobe for a diffuse colour rho (already weighted, as
    /// [`Convention::brdf`] weights it), without n.l: rho / pi ([`DiffuseLobe::Lambert`],
    /// [`diffuse::lambert`]) or Burley 2012 with alpha as its
    /// roughness ([`DiffuseLobe::BurleyOfAlpha`], bevy:
    /// [`diffuse::burley`]`(max(n.v, 1e-4), n.l, v.h, rho, alpha)`),
    /// per channel.
    ///
    /// Domain: `roughness` (perceptual) and each channel of `diffuse_color` in [0, 1];
    /// outside and NaN give NaN in every channel (also below the horizon; the roughness is checked for
    /// Lambert too, which does not read it). 0 where n.v <= 0 or n.l <= 0; v.h clamped to
    /// [0, 1]. Accuracy: [`diffuse::lambert`] and
    /// [`diffuse::burley`] are within 0.7 ULP.
    ///
    /// Sources: three.js `BRDF_Lambert`, Filament `Fd_Lambert` (`BRDF_DIFFUSE` =
    /// `DIFFUSE_LAMBERT`), bevy `Fd_Burley`, Karis 2013 (Lambert), glTF-Sample-Viewer
    /// `BRDF_lambertian`, at each [`Source`]'s revision.
    #[inline]
    #[must_use]
    pub fn diffuse<T: Real>(&self, c: Cosines<T>, roughness: T, diffuse_color: V3<T>) -> V3<T> {
        let ok = in_unit(roughness);
        let nv = self.floored_n_dot_v(c.n_dot_v);
        let lobe = |rho: T| match self.diffuse {
            DiffuseLobe::Lambert => diffuse::lambert(nv, c.n_dot_l, rho),
            DiffuseLobe::BurleyOfAlpha => {
                diffuse::burley(nv, c.n_dot_l, c.v_dot_h, rho, self.alpha(roughness))
            }
        };
        let ok =
            ok & in_unit(diffuse_color.x) & in_unit(diffuse_color.y) & in_unit(diffuse_color.z);
        // n.h and v.h are not read by Lambert, but a NaN in them is still a bug to surface.
        let nan = any_nan(c);
        diffuse_color.map(|rho| nan_unless(ok, nan_where(nan, lobe(rho))))
    }

    /// The engine's metallic-roughness BRDF for one punctual light, RGB, without the n.l
    /// factor (which every engine applies outside it):
    ///
    /// ```text
    /// F0 = lerp(dielectric_f0, base_color, metallic)      (0.04 for all five)
    /// f  = specular(c, roughness, F0, f90(F0)) + diffuse(c, roughness, kd base_color)
    /// kd = 1 - metallic                                  (OneMinusMetallic)
    ///    = (1 - metallic)(1 - F_dielectric(v.h))         (OneMinusMetallicOneMinusF, glTF)
    /// ```
    ///
    /// with F_dielectric = F(dielectric_f0, 1, v.h) and its complement formed without
    /// cancellation (1 - (1 - c)^5 = c (1 + s + s^2 + s^3 + s^4), s = 1 - c).
    ///
    /// Domain: each channel of `base_color`, `metallic` and perceptual `roughness` in [0, 1];
    /// outside and NaN give NaN (also below the horizon). Cosines as
    /// [`Convention::specular`]: 0 where n.v <= 0 or n.l <= 0. Finite for finite in-domain
    /// input. In `f32` within 12 ULP of the `f64` evaluation on the test grid (cosines down to
    /// 1e-5, n.h up to 1, every roughness; measured 5.1 for three.js to 9.96 for Unreal
    /// Engine 4), and within 9 to 12 ULP of each engine's own `f32` shader code wherever that
    /// code is accurate (`cargo test --test material engine_conventions:: -- --nocapture` prints both,
    /// and where the engines' forms lose digits).
    ///
    /// Sources: three.js `RE_Direct_Physical`, Filament `surfaceShading`, bevy `point_light`,
    /// Karis 2013, glTF-Sample-Viewer `pbr.frag`, at each [`Source`]'s revision.
    #[inline]
    #[must_use]
    pub fn brdf<T: Real>(
        &self,
        c: Cosines<T>,
        base_color: V3<T>,
        metallic: T,
        roughness: T,
    ) -> V3<T> {
        let ok = in_unit(base_color.x)
            & in_unit(base_color.y)
            & in_unit(base_color.z)
            & in_unit(metallic);
        let f0d = T::splat(self.dielectric_f0);
        let one_minus_m = T::ONE - metallic;
        // lerp(f0d, b, m) = f0d (1 - m) + b m: exactly f0d at m = 0 and b at m = 1.
        let f0 = base_color.map(|b| f0d.mul_add(one_minus_m, b * metallic));
        let spec = self.specular(c, roughness, f0, self.f90(f0));
        let kd = match self.diffuse_weight {
            DiffuseWeight::OneMinusMetallic => one_minus_m,
            DiffuseWeight::OneMinusMetallicOneMinusF => {
                // 1 - F_dielectric = 1 - f0d - (1 - f0d) w = (1 - f0d)(1 - w) for F90 = 1.
                one_minus_m * (T::ONE - f0d) * self.one_minus_schlick_weight(c.v_dot_h)
            }
        };
        let diff = self.diffuse(c, roughness, base_color * kd);
        let f = spec + diff;
        f.map(|x| nan_unless(ok, x))
    }
}
