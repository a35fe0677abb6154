//! The rough dielectric BSDF (`brdf::rough_dielectric`) and the whole-sphere integrators it
//! needs. One test binary for the family: `cargo test --test transmission`.
//!
//! - `energy`: white furnace over the sphere, both sides, its limit as alpha -> 0, the
//!   single-scattering loss beside the conductor's, the sampler's mean weight
//! - `reciprocity`: generalized reciprocity and the radiance / importance adjoint
//! - `sampling`: the sampler against its pdf by chi-square over the whole sphere
//! - `edges`: eta = 1, total internal reflection, bad input, lanes against scalars
//! - `gltf`: `KHR_materials_transmission` and `KHR_materials_volume`
#![cfg(all(
    feature = "transmission",
    feature = "ggx",
    feature = "beckmann",
    feature = "integrate",
    feature = "cook-torrance"
))]

#[path = "../common/mod.rs"]
mod common;

mod edges;
mod energy;
mod gltf;
mod reciprocity;
mod sampling;

use brdf::V3;

/// The unit direction at polar angle `theta_deg` (from +z; above 90 it lies inside) and
/// azimuth `phi_deg`.
pub fn dir(theta_deg: f64, phi_deg: f64) -> V3<f64> {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    V3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

/// The direction that a smooth interface of relative index `eta` (inside over outside)
/// refracts `wo` into, if any: the peak of the transmission lobe.
pub fn refracted(wo: V3<f64>, eta: f64) -> Option<V3<f64>> {
    let (n, e) = if wo.z >= 0.0 {
        (1.0, eta)
    } else {
        (-1.0, 1.0 / eta)
    };
    let c = wo.z.abs();
    let s2 = (1.0 - c * c) / (e * e);
    (s2 < 1.0).then(|| {
        let ct = (1.0 - s2).sqrt();
        let w = V3::new(0.0, 0.0, n) * (c / e - ct) - wo * (1.0 / e);
        w * (1.0 / w.length())
    })
}
