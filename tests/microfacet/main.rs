//! The microfacet models (`brdf::ggx`, `brdf::beckmann`, `brdf::microfacet`): domains, NDF
//! normalization and the Smith terms. One test binary per family, so the family links once: `cargo
//! test --test microfacet` runs it, `cargo test --test microfacet <module>::` runs one module. Each
//! module keeps its own feature gate.
//!
//! - `domains`: every public microfacet function over its domain, edges and bad input
//! - `ndf_normalization`: each NDF's projected area is one
//! - `smith_approximations`: the real-time Smith approximations' errors against the exact forms
//! - `smith_weak_furnace`: Smith's weak white furnace test

#[path = "../common/mod.rs"]
mod common;

mod domains;
mod ndf_normalization;
mod smith_approximations;
mod smith_weak_furnace;
