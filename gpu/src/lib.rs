//! `brdf-gpu`: the WGSL twins of `brdf`'s kernels (`brdf::wgsl`), validated, translated and
//! run on a GPU API against the CPU.
//!
//! | module | what lives there |
//! |---|---|
//! | [`shaders`] | which kernel each WGSL function twins, signatures against the reference table, the compute shader of a kernel, translation to SPIR-V, GLSL, HLSL, MSL |
//! | [`bound`] | the error bound the WGSL specification's accuracy table implies, computed from a function's naga IR |
//! | [`device`] | one compute dispatch through `wgpu` |
//! | [`contrast`] | GGX D in the crate's stable form and in the textbook form, on the same adapter |
//! | [`equiv`] | the rows, the comparison with the CPU's `f32`, the per-kernel figures, Markdown and CSV |
//!
//! The tests (`cargo test -p brdf-gpu --release`) validate and translate every twin, check
//! the translations with `spirv-val` and `glslangValidator`, hold the signatures to the
//! table, and run every twin on the adapter wgpu finds (Mesa's lavapipe in CI). The binary
//! `brdf-gpu-equiv` runs the same equivalence on any machine and writes the figures.

pub mod bound;
pub mod contrast;
pub mod device;
pub mod equiv;
pub mod shaders;
