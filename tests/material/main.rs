//! The metallic-roughness material (`brdf::material`). One test binary per family, so the family
//! links once: `cargo test --test material` runs it, `cargo test --test material <module>::` runs
//! one module. Each module keeps its own feature gate.
//!
//! - `energy`: directional albedo
//! - `engine_conventions`: the five engines' convention sets against f32 transcriptions of
//!   their shaders
//! - `fast_tier`: the working-precision tier against the exact tier
//! - `gltf_composition`: equals the formulas of glTF, Unreal and Filament
//! - `reciprocity`: Helmholtz reciprocity per RGB channel
//! - `sampling`: the lobe-selection sampler against its pdf
//! - `shading`: `Cosines` and `ShadingPoint`, and the material from world space
//! - `stability`: bad and extreme input (proptest)

#[path = "../common/mod.rs"]
mod common;

mod energy;
mod engine_conventions;
mod fast_tier;
mod gltf_composition;
mod reciprocity;
mod sampling;
mod shading;
mod stability;
