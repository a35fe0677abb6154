//! The samplers of `brdf::sampling` draw the distributions of the pdfs they return. One test binary
//! per family, so the family links once: `cargo test --test sampling` runs it, `cargo test --test
//! sampling <module>::` runs one module. Each module keeps its own feature gate.
//!
//! - `beckmann_inversion`: `beckmann_vndf` inverts its slope CDF
//! - `distributions`: every sampler against its pdf (chi-square), pdfs integrate to 1
//! - `reflection`: the Cook-Torrance reflection samplers
//! - `windows`: every sampler over windows of its domain

#[path = "../common/mod.rs"]
mod common;

mod beckmann_inversion;
mod distributions;
mod reflection;
mod windows;
