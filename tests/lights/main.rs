//! Punctual lights (`brdf::lights`). One test binary per family, so the family links once: `cargo
//! test --test lights` runs it, `cargo test --test lights <module>::` runs one module. Each module
//! keeps its own feature gate.
//!
//! - `punctual`: strength conventions, falloffs, spot cones, bad input and lanes

#[path = "../common/mod.rs"]
mod common;

mod punctual;
