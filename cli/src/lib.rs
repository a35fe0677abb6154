//! The reference CLI's library: the table of every public scalar kernel of `brdf`
//! ([`table::KERNELS`]), with each argument's name, order and domain, each output's range and
//! the function itself on `f32`, `f64`, `f32x8` and `f64x4`.
//!
//! One table drives the CLI (`brdf-ref --list`, evaluation and diff), the report's stability
//! section and the tests that hold the table to the crate's functions.
//!
//! | module | what lives there |
//! |---|---|
//! | [`table`] | the kernels, their domains and ranges, the rules from signature to columns |
//! | [`points`] | extreme and random in-domain rows of a kernel (the sweeps) |
//! | [`ulp`] | ULP distance, histogram buckets, the statistics of `diff` |
//! | [`app`] | the command line: `--list`, `eval`, `diff`, the help text |

#![deny(missing_docs)]

pub mod app;
pub mod points;
pub mod table;
pub mod ulp;

pub use table::{Arg, Constraint, Domain, Float, KERNELS, Kernel, Output, find};
