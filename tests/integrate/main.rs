//! The public hemisphere integrators (`brdf::integrate`). One test binary per family, so the family
//! links once: `cargo test --test integrate` runs it, `cargo test --test integrate <module>::` runs
//! one module. Each module keeps its own feature gate.
//!
//! - `accuracy`: documented accuracy on integrands with known integrals
//! - `bad_input`: NaN and infinite arguments, the configuration included, give a NaN estimate
//! - `error_estimates`: the reported error bounds the actual error
//! - `generic`: the `_f32` integrators against the f64 ones
//! - `sphere`: the whole-sphere integrators on integrals with closed forms, both halves

#[path = "../common/mod.rs"]
mod common;

mod accuracy;
mod bad_input;
mod error_estimates;
mod generic;
mod sphere;
