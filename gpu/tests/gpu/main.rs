//! The WGSL twins: validated, translated, checked by the shading languages' own validators,
//! held to the reference table's signatures, run on the adapter wgpu finds and held to the
//! bound the WGSL accuracy table implies.
//!
//! | module | property |
//! |---|---|
//! | `translate` | every twin parses, validates, and translates to SPIR-V (spirv-val), GLSL (glslangValidator), HLSL, MSL |
//! | `signatures` | every WGSL function has its Rust twin's name, parameters and outputs |
//! | `equivalence` | every twin on the GPU stays within its spec-derived bound of the CPU's f32 |
//! | `compose` | no name is defined twice; the families compose as naga_oil modules |
//! | `coverage` | every kernel of the shader families has a twin or a stated reason |
//! | `readme` | the README's wgpu example is this crate's code and builds a pipeline |
//! | `teeth` | the composed twins broken by hand (a constant, an argument, a branch) leave their bound on their grids |

mod compose;
mod coverage;
mod equivalence;
mod readme;
mod signatures;
mod teeth;
mod translate;
