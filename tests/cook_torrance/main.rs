//! The Cook-Torrance assembly (`brdf::cook_torrance`). One test binary per family, so the family
//! links once: `cargo test --test cook_torrance` runs it, `cargo test --test cook_torrance
//! <module>::` runs one module. Each module keeps its own feature gate.
//!
//! - `energy`: energy and reciprocity, by the public integrators
//! - `fast_check`: the random directions and relative-error sweep both fast tiers' tests share
//! - `fast_dielectric`: the working-precision rough dielectric reflection against the exact tier
//! - `fast_tier`: the working-precision rough conductor against the exact tier
//! - `local`: the rough conductor from the directions, both tiers, against the f64 route
//! - `rgb`: the Fresnel-specific dot-product forms against the generic assembly

#[path = "../common/mod.rs"]
mod common;

mod energy;
mod fast_check;
mod fast_dielectric;
mod fast_tier;
mod local;
mod rgb;
