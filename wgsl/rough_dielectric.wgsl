// brdf: the rough dielectric's generalized half vector, the twin of the Rust module
// `rough_dielectric` (its BSDF, pdf and samplers have no twins yet). Needs common.wgsl.

// The generalized half vector h = +-normalize(wo + eta' wi) with h.z >= 0 (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces", eq. 16): eta' = 1 where wo and wi
// lie on the same side, else eta for wo outside and 1 / eta for wo inside. Written, as the Rust
// kernel writes it, as wi + wo / eta' where eta' > 1 (a positive multiple), so that neither
// term overflows for any eta in (0, MAX]. Where the sum is the zero vector, h is (0, 0, 1).
fn rough_dielectric_half_vector(
    wo_x: f32, wo_y: f32, wo_z: f32, wi_x: f32, wi_y: f32, wi_z: f32, eta: f32,
) -> vec3<f32> {
    let etap = select(select(eta, 1.0 / eta, wo_z < 0.0), 1.0, wo_z * wi_z > 0.0);
    let big = etap > 1.0;
    let inv = 1.0 / etap;
    let x = select(wi_x * etap + wo_x, wi_x + wo_x * inv, big);
    let y = select(wi_y * etap + wo_y, wi_y + wo_y * inv, big);
    let z = select(wi_z * etap + wo_z, wi_z + wo_z * inv, big);
    let len2 = x * x + y * y + z * z;
    // A zero sum (wi = -wo at eta' = 1) has no direction: the normal, as in the Rust kernel.
    // The floor keeps the unused branch of the select finite there.
    let s = select(0.0, 1.0 / sqrt(max(len2, 1e-30)), len2 > 0.0);
    let flip = select(s, -s, z < 0.0);
    return select(vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(x * flip, y * flip, z * flip), len2 > 0.0);
}
