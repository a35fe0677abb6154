//! Image-based lighting (`brdf::ibl`): the DFG table and fits, multiple-scattering energy, SH9
//! irradiance, prefilter samples, and scene S0. One test binary per family, so the family links
//! once: `cargo test --test ibl` runs it, `cargo test --test ibl <module>::` runs one module. Each
//! module keeps its own feature gate.
//!
//! - `dfg_accuracy`: the DFG table against the exact split-sum integrals
//! - `dfg_approximations`: the analytic DFG fits against the table
//! - `dfg_filament`: Filament's two-channel DFG table and its mix
//! - `dfg_nan`: bad input of the DFG kernels
//! - `energy_conservation`: compensated GGX never gains energy
//! - `energy_furnace`: white furnace of the compensated GGX
//! - `energy_lanes`: bad input and lanes of `ibl::energy`
//! - `energy_reciprocity`: reciprocity of Kulla-Conty's lobe
//! - `energy_saturation`: Kulla-Conty's Fresnel term saturates coloured metals
//! - `energy_tables`: the built-in albedo tables against their estimators
//! - `extreme_inputs`: the split-sum helpers at the edges of their domains
//! - `irradiance_bad_input`: bad input of the SH9 kernels
//! - `irradiance_constant`: a constant environment's irradiance is pi L
//! - `irradiance_sh9_error`: SH9 against an independent reference
//! - `irradiance_sh9_exact`: SH9 is exact on band-limited environments
//! - `prefilter_bad_input`: bad input of the prefilter kernels
//! - `prefilter_mip_level`: the filtered-importance-sampling mip level
//! - `prefilter_normalisation`: the prefilter weights are normalised
//! - `prefilter_pdf`: prefilter directions follow the pdf they report
//! - `prefilter_reference`: the prefilter sample set against the GGX-prefiltered value
//! - `seed_s0`: scene S0 (`tests/scenes/s0.rs`, shared with the report)

#[path = "../common/mod.rs"]
mod common;

mod dfg_accuracy;
mod dfg_approximations;
mod dfg_filament;
mod dfg_nan;
mod energy_conservation;
mod energy_furnace;
mod energy_lanes;
mod energy_reciprocity;
mod energy_saturation;
mod energy_tables;
mod extreme_inputs;
mod irradiance_bad_input;
mod irradiance_constant;
mod irradiance_sh9_error;
mod irradiance_sh9_exact;
mod prefilter_bad_input;
mod prefilter_mip_level;
mod prefilter_normalisation;
mod prefilter_pdf;
mod prefilter_reference;
mod seed_s0;
