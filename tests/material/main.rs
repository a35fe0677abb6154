//! The metallic-roughness material (`brdf::material`). One test binary per family, so the family
//! links once: `cargo test --test material` runs it, `cargo test --test material <module>::` runs
//! one module. Each module keeps its own feature gate.
//!
//! - `energy`: directional albedo
//! - `gltf_composition`: equals the formulas of glTF, Unreal and Filament
//! - `reciprocity`: Helmholtz reciprocity per RGB channel
//! - `sampling`: the lobe-selection sampler against its pdf
//! - `stability`: bad and extreme input (proptest)

#[path = "../common/mod.rs"]
mod common;

mod energy;
mod gltf_composition;
mod reciprocity;
mod sampling;
mod stability;
