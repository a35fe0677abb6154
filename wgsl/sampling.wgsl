// brdf: sampling densities a shader needs to weight its samples, the twins of the Rust module
// `sampling` (the cosine-hemisphere pdf and the half-vector-to-reflection Jacobian). Needs
// common.wgsl. The samplers themselves and the microfacet pdfs have no twin yet.

// The pdf max(0, w.z) / pi of cosine-weighted hemisphere sampling (Pharr, Jakob, Humphreys,
// "Physically Based Rendering", 4th ed., A.5.3).
fn sampling_cosine_hemisphere_pdf(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return max(w_z, 0.0) * BRDF_FRAC_1_PI;
}

// The pdf of the reflected direction from the pdf of the microfacet normal,
// pdf_m / (4 |v.h|) (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 14), capped at the largest finite f32; 0 where v.h = 0.
fn sampling_reflect_pdf(pdf_m: f32, v_dot_h: f32) -> f32 {
    let den = 4.0 * abs(v_dot_h);
    return select(0.0, min(pdf_m / den, BRDF_F32_MAX), den > 0.0);
}
