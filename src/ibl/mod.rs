//! Image-based lighting and multiple-scattering energy compensation: everything a renderer
//! needs to light a surface from an environment, without allocating (every table is written
//! into a buffer the caller owns).
//!
//! - [`dfg`]: the split-sum DFG table of GGX with height-correlated Smith (Karis 2013), the
//!   analytic fits engines ship, the split-sum specular and the roughness-to-mip mapping.
//! - [`prefilter`]: GGX importance samples with weights for prefiltering a radiance cube,
//!   and the pdf-based mip bias of filtered importance sampling (Krivanek and Colbert 2008).
//! - [`irradiance`]: the cosine convolution of a radiance function by quadrature, and
//!   9-coefficient spherical harmonics (Ramamoorthi and Hanrahan 2001).
//! - [`energy`]: multiple-scattering compensation, Kulla and Conty 2017's lobe and the
//!   split-sum form of Fdez-Aguera 2019 / Turquin 2019.

pub mod dfg;
pub mod energy;
pub mod irradiance;
pub mod prefilter;
