//! The Phong family (`brdf::phong`). One test binary per family, so the family links once: `cargo
//! test --test phong` runs it, `cargo test --test phong <module>::` runs one module. Each module
//! keeps its own feature gate.
//!
//! - `energy`: directional albedo
//! - `normalization`: normalization factors against independent routes
//! - `reciprocity`: Helmholtz reciprocity
//! - `stability`: bad and extreme input on every lane type

#[path = "../common/mod.rs"]
mod common;

mod energy;
mod normalization;
mod reciprocity;
mod stability;
