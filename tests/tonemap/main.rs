//! Colour and tonemapping (`brdf::color`, `brdf::tonemap`). One test binary per family, so the
//! family links once: `cargo test --test tonemap` runs it, `cargo test --test tonemap <module>::`
//! runs one module. Each module keeps its own feature gate.
//!
//! - `against_peers`: our operators against the engines' (`tests/peers/`, shared with the report)
//! - `color_domains`: transfer functions, luminance and every operator over their domains
//! - `color_transfer`: sRGB and Rec.709 round trips
//! - `extreme_parameters`: the parametric tone curves at extreme parameters
//! - `properties`: f(0) = 0, monotonicity and range of every operator

#[path = "../common/mod.rs"]
mod common;

mod against_peers;
mod color_domains;
mod color_transfer;
mod extreme_parameters;
mod properties;
