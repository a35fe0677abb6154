//! # brdf
//!
//! BRDF math for renderers, physics checks and shader reference: pure functions, one generic
//! source for `f32`, `f64` and SIMD lanes (`f32x8`, `f64x4`), `#![no_std]`, every formula
//! cited and every property (normalization, reciprocity, energy) checked by numerical
//! integration in the test suite.
//!
//! ## Modules
//! | module | what it owns | feature |
//! |---|---|---|
//! | [`real`] | [`Real`]: the float/lane trait, its [`Mask`], lane accuracy bounds | always |
//! | [`vec3`] | [`V3`]: 3-vector of scalars or lanes (structure of arrays), glam conversions | always |
//! | [`frame`] | orthonormal basis from a normal, local-frame `cos_theta`/`tan2_theta`/`cos_phi` | always |
//! | [`error`] | [`ParamError`], returned by parameter constructors | always |
//! | `fresnel` | Schlick (+F90, SG), exact dielectric and polarized, conductor, F82 tint | `fresnel` |
//! | `microfacet` | the `Microfacet` trait (D, Lambda, G1, G2) shared by the NDFs | `microfacet` |
//! | `ggx` | GGX / Trowbridge-Reitz, isotropic and anisotropic, real-time V approximations | `ggx` |
//! | `beckmann` | Beckmann, exact and rational Lambda, Blinn-Phong exponent conversion | `beckmann` |
//! | `cook_torrance` | D G F / (4 NoL NoV) evaluated through V | `cook-torrance` |
//! | `diffuse` | Lambert, Oren-Nayar (qualitative, full, Fujii, EON), Burley, diffuse-Fresnel couplings | `diffuse` |
//! | `phong` | classic, modified and normalized Phong, Blinn-Phong | `phong` |
//! | `material` | the glTF / Filament metallic-roughness BRDF, its parameters and lobe sampling | `material` |
//! | `lights` | punctual light radiance, distance attenuation, spot cones | `lights` |
//! | `sampling` | cosine hemisphere, D cos sampling, visible normals, pdfs | `sampling` |
//! | `tonemap` | tonemapping operators, exposure | `tonemap` |
//! | `color` | sRGB / Rec.709 transfer, luminance, colour matrices | `tonemap` |
//! | `integrate` | hemisphere integrators: albedo, NDF area, weak furnace, reciprocity | `integrate` |
//!
//! ## Tour
//! ```
//! use brdf::{Real, V3, frame::Frame};
//! use brdf::wide::f32x8;
//!
//! // A kernel written once...
//! fn lambert<T: Real>(albedo: T, n_dot_l: T) -> T {
//!     albedo * T::FRAC_1_PI * n_dot_l.max(T::ZERO)
//! }
//! // ...runs on one value
//! let one = lambert(0.5_f32, 1.0);
//! // ...or on eight lanes at a time, bit-identical lane by lane.
//! let eight = lambert(f32x8::splat(0.5), f32x8::splat(1.0));
//! assert_eq!(eight.lane(3), one);
//!
//! // Shading frames work on the same generic vector type.
//! let n = V3::new(0.0_f64, 0.6, 0.8);
//! let f = Frame::from_normal(n);
//! let local = f.to_local(n);
//! assert!((local.z - 1.0).abs() < 1e-15);
//! ```
#![no_std]
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod error;
pub mod frame;
pub mod real;
pub mod vec3;

#[cfg(feature = "beckmann")]
pub mod beckmann;
#[cfg(feature = "tonemap")]
pub mod color;
#[cfg(feature = "cook-torrance")]
pub mod cook_torrance;
#[cfg(feature = "diffuse")]
pub mod diffuse;
mod domain;
#[cfg(feature = "fresnel")]
pub mod fresnel;
#[cfg(feature = "ggx")]
pub mod ggx;
#[cfg(feature = "integrate")]
pub mod integrate;
#[cfg(feature = "lights")]
pub mod lights;
#[cfg(feature = "material")]
pub mod material;
#[cfg(feature = "microfacet")]
pub mod microfacet;
#[cfg(feature = "phong")]
pub mod phong;
#[cfg(feature = "sampling")]
pub mod sampling;
#[cfg(feature = "tonemap")]
pub mod tonemap;

pub use error::ParamError;

/// The vector math crate whose `Vec3`/`DVec3` convert to [`V3`].
pub use glam;
pub use real::{Mask, Real};
pub use vec3::V3;
/// The SIMD crate whose `f32x8` and `f64x4` implement [`Real`].
pub use wide;

/// The README's usage snippet, compiled and run as a doc test.
#[doc = include_str!("../README.md")]
#[cfg(all(doctest, feature = "integrate"))]
pub struct ReadmeDoctests;
