//! Thin-film iridescence (`brdf::iridescence`): `cargo test --test iridescence`.
//!
//! - `limits`: a vanishing film (thickness 0, or the outside's index) is the bare base's
//!   Fresnel reflectance, dielectric and conductor
//! - `spectral`: the analytic XYZ result against the Airy reflectance integrated over
//!   wavelength with the CIE 1931 colour-matching functions by quadrature
//! - `domain`: values in [0, 1], finite on the extreme grid, lanes against scalars, NaN rule
//! - `viewer`: against a transcription of the Khronos sample viewer, each of its four
//!   differences shown alone
#![cfg(feature = "iridescence")]

mod domain;
#[cfg(feature = "fresnel")]
mod limits;
mod spectral;
mod viewer;
