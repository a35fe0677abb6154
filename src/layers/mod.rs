//! The glTF extension lobes layered over the metallic-roughness material: one file per
//! extension, and the material that composes them.
//!
//! | module | glTF extension | what it owns | feature |
//! |---|---|---|---|
//! | `sheen` | `KHR_materials_sheen` | Charlie NDF and its fitted Lambda, Neubelt-Pettineo visibility, Ashikhmin's velvet D, the sheen albedo E (integrated into a caller's buffer, built-in table, published fits), albedo scaling | `sheen` |
//! | `clearcoat` | `KHR_materials_clearcoat` | the GGX coat at IOR 1.5, Kelemen's visibility, the coat-over-base layering with either Fresnel argument | `clearcoat` |
//! | `specular` | `KHR_materials_specular`, `KHR_materials_ior` | validated IOR and specular parameters, F0 from IOR, the dielectric F0 and F90 rule | `specular` |
//! | `anisotropy` | `KHR_materials_anisotropy` | strength and direction onto the anisotropic GGX, the tangent rotation, the bent reflection vector for IBL | `anisotropy` |
//! | `layered` | all of the above | `layered::Layered`: any subset of the extensions over the metallic-roughness base (with transmission and volume, thin-film iridescence under their features); eval, sample, pdf, per-lobe energy compensation | `layered` |
//!
//! Every kernel follows the crate's bad-input rule (crate docs, "Bad input") on `f32`, `f64`,
//! `f32x8` and `f64x4`; every parameter type validates in its constructor.

#[cfg(feature = "anisotropy")]
pub mod anisotropy;
#[cfg(feature = "clearcoat")]
pub mod clearcoat;
#[cfg(feature = "layered")]
pub mod layered;
#[cfg(feature = "sheen")]
pub mod sheen;
#[cfg(feature = "specular")]
pub mod specular;
