//! The diffuse lobes (`brdf::diffuse`): Burley, the diffuse-Fresnel couplings, EON and the Oren-Nayar
//! family. One test binary per family, so the family links once: `cargo test --test diffuse`
//! runs it, `cargo test --test diffuse <module>::` runs one module. Each module keeps its own
//! feature gate.
//!
//! - `burley_energy`: Burley and its renormalized form: directional albedo
//! - `burley_reciprocity`: Burley: Helmholtz reciprocity
//! - `burley_stability`: Burley: bad and extreme input, lanes
//! - `coupling_energy`: the couplings: directional albedo
//! - `coupling_reciprocity`: the couplings: reciprocity
//! - `coupling_stability`: the couplings: bad and extreme input, lanes
//! - `eon_albedo`: EON's closed-form albedos against integration
//! - `eon_energy`: EON preserves energy
//! - `eon_lambert_limit`: EON at sigma = 0 is Lambert
//! - `eon_multiscatter_range`: EON's multiple-scattering albedo range
//! - `eon_reciprocity`: EON: reciprocity
//! - `eon_sampling`: EON's importance sampling against its pdf
//! - `eon_stability`: EON: stability over the domain
//! - `oren_nayar_energy`: Oren-Nayar family: directional albedo
//! - `oren_nayar_lanes`: Oren-Nayar family: lanes and precision
//! - `oren_nayar_nan`: Oren-Nayar family: NaN in, NaN out
//! - `oren_nayar_reciprocity`: Oren-Nayar family: reciprocity
//! - `oren_nayar_reference`: Oren-Nayar family: dot-product forms against the published angle forms
//! - `oren_nayar_stability`: Oren-Nayar family: no NaN, inf or negative value
//! - `oren_nayar_vcavity`: the full model's L1 against the paper's V-cavity definition

#[path = "../common/mod.rs"]
mod common;

mod burley_energy;
mod burley_reciprocity;
mod burley_stability;
mod coupling_energy;
mod coupling_reciprocity;
mod coupling_stability;
mod eon_albedo;
mod eon_energy;
mod eon_lambert_limit;
mod eon_multiscatter_range;
mod eon_reciprocity;
mod eon_sampling;
mod eon_stability;
mod oren_nayar_energy;
mod oren_nayar_lanes;
mod oren_nayar_nan;
mod oren_nayar_reciprocity;
mod oren_nayar_reference;
mod oren_nayar_stability;
mod oren_nayar_vcavity;
