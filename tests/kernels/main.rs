//! Rules every public kernel keeps, across the families. One test binary per family, so the family
//! links once: `cargo test --test kernels` runs it, `cargo test --test kernels <module>::` runs one
//! module. Each module keeps its own feature gate.
//!
//! - `bad_input`: the crate's bad-input rule on every kernel and lane type, and a scan of `src/`
//!   for kernels missing from it
//! - `fast_variants`: the `_fast` variants within a stated error of their exact forms
//! - `stability`: stability on stiff and extreme inputs

#[path = "../common/mod.rs"]
mod common;

mod bad_input;
mod fast_variants;
mod stability;
