//! The glTF extension lobes (`brdf::layers`). One test binary for the family:
//! `cargo test --test layers` runs it, `cargo test --test layers <module>::` one module. Each
//! module keeps its own feature gate.
//!
//! - `sheen`: normalization, reciprocity, energy, extremes, lanes against scalars
//! - `sheen_albedo`: the built-in table and the published fits against the integrators
//! - `sheen_engines`: against transcriptions of the Khronos sample viewer and three.js

#[path = "../common/mod.rs"]
mod common;

mod sheen;
mod sheen_albedo;
mod sheen_engines;
