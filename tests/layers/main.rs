//! The glTF extension lobes (`brdf::layers`). One test binary for the family:
//! `cargo test --test layers` runs it, `cargo test --test layers <module>::` one module. Each
//! module keeps its own feature gate.
//!
//! - `sheen`: normalization, reciprocity, energy, extremes, lanes against scalars
//! - `sheen_albedo`: the built-in table and the published fits against the integrators
//! - `sheen_engines`: against transcriptions of the Khronos sample viewer and three.js
//! - `clearcoat`: clearcoat 0 is the base, reciprocity, energy, Kelemen's error, the viewer
//!   and three.js (lobe and layering)
//! - `specular`: KHR_materials_ior / specular against the metallic-roughness material and
//!   three.js
//! - `anisotropy`: strength 0 is isotropic, direction, bent reflection against the viewer,
//!   the stretched lobe against three.js
//! - `layered`: the layered material: zero layers, furnace, energy, per-lobe compensation,
//!   reciprocity, sampler chi-square, extremes and lanes
//! - `transmission`: KHR_materials_transmission in the layered material: zero is the material
//!   without it, the furnace over the sphere, the sampler over the sphere, NaN on every lane
//! - `iridescence`: KHR_materials_iridescence in the layered material: zero is the material
//!   without it, a vanishing film is the exact Fresnel, furnace, reciprocity, sampler, lanes
//! - `prepared`: the material prepared per shading point against the direct eval; the
//!   view-only albedo scaling against the min form

#[path = "../common/mod.rs"]
mod common;

mod anisotropy;
mod clearcoat;
#[cfg(feature = "iridescence")]
mod iridescence;
mod layered;
mod prepared;
mod sheen;
mod sheen_albedo;
mod sheen_engines;
mod specular;
mod transmission;
