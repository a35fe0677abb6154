// brdf: local shading-frame trigonometry, the twins of the Rust module `frame` (the normal is z;
// Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., 3.8.3). Needs common.wgsl.
// The frame construction has no twin yet.

// cos(theta) = w.z.
fn frame_cos_theta(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return w_z;
}

// cos^2(theta) = w.z^2.
fn frame_cos2_theta(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return w_z * w_z;
}

// |cos(theta)| = |w.z|.
fn frame_abs_cos_theta(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return abs(w_z);
}

// sin^2(theta) = w.x^2 + w.y^2 (no cancellation near the pole, unlike 1 - w.z^2).
fn frame_sin2_theta(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return fma(w_x, w_x, w_y * w_y);
}

// sin(theta) = sqrt(w.x^2 + w.y^2).
fn frame_sin_theta(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return sqrt(frame_sin2_theta(w_x, w_y, w_z));
}

// tan^2(theta) = sin^2 / cos^2.
fn frame_tan2_theta(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    return frame_sin2_theta(w_x, w_y, w_z) / frame_cos2_theta(w_x, w_y, w_z);
}

// cos(phi) = w.x / sin(theta) clamped to [-1, 1]; 1 at the pole.
fn frame_cos_phi(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    let s = frame_sin_theta(w_x, w_y, w_z);
    let pole = s == 0.0;
    return select(clamp(w_x / select(s, 1.0, pole), -1.0, 1.0), 1.0, pole);
}

// sin(phi) = w.y / sin(theta) clamped to [-1, 1]; 0 at the pole.
fn frame_sin_phi(w_x: f32, w_y: f32, w_z: f32) -> f32 {
    let s = frame_sin_theta(w_x, w_y, w_z);
    let pole = s == 0.0;
    return select(clamp(w_y / select(s, 1.0, pole), -1.0, 1.0), 0.0, pole);
}

// The unit direction (sin t cos p, sin t sin p, cos t) of spherical angles (pbrt-v4,
// SphericalDirection). WGSL's sin and cos are promised to an absolute 2^-11 only on [-pi, pi].
fn frame_spherical_direction(theta: f32, phi: f32) -> vec3<f32> {
    let st = sin(theta);
    return vec3<f32>(st * cos(phi), st * sin(phi), cos(theta));
}
