//! The float and lane abstraction (`brdf::Real`, `V3`, `Frame`, `batch`). One test binary per
//! family, so the family links once: `cargo test --test lanes` runs it, `cargo test --test lanes
//! <module>::` runs one module. Each module keeps its own feature gate.
//!
//! - `batch`: `batch::run` equals the kernel element by element
//! - `batch_par`: `batch::par_run` (feature `rayon`) equals `batch::run`
//! - `exp`: the f32x8 lane exp
//! - `frame`: shading frames are orthonormal and round-trip
//! - `scalar_instructions`: scalar `mul_add` and `sqrt` keep their definitions
//! - `vec3_ergonomics`: `V3` against glam
//! - `vs_scalar`: every lane function against the scalar path

#[path = "../common/mod.rs"]
mod common;

mod batch;
mod batch_par;
mod exp;
mod frame;
mod scalar_instructions;
mod vec3_ergonomics;
mod vs_scalar;
