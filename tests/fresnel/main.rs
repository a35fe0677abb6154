//! Fresnel terms (`brdf::fresnel`): the approximations' errors, the exact terms over their domains
//! and their identities. One test binary per family, so the family links once: `cargo test --test
//! fresnel` runs it, `cargo test --test fresnel <module>::` runs one module. Each module keeps its
//! own feature gate.
//!
//! - `approximations`: Schlick and the other fits against the exact equations
//! - `domains`: the exact terms over their whole documented domain (proptest)
//! - `properties`: identities of the exact equations and every term a probability

#[path = "../common/mod.rs"]
mod common;

mod approximations;
mod domains;
mod properties;
