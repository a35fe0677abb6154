// brdf: punctual lights, the twins of the Rust module `lights` (reflected radiance in the
// radiometric and pi c_light conventions, irradiance, distance falloffs, spot cones). Needs
// common.wgsl.

// f E n.l k for n.l > 0, 0 otherwise, capped at the largest finite f32 (lights::reflected).
fn brdf_lights_reflected(f: f32, e_perp: f32, n_dot_l: f32, k: f32) -> f32 {
    let lit = min(f * (e_perp * n_dot_l) * k, BRDF_F32_MAX);
    return select(0.0, lit, n_dot_l > 0.0);
}

// Radiance reflected from a punctual light, L = f E_perp n.l (the rendering equation with a
// delta light; Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., 12.1).
fn lights_radiance(f: f32, e_perp: f32, n_dot_l: f32) -> f32 {
    return brdf_lights_reflected(f, e_perp, n_dot_l, 1.0);
}

// The same in the real-time convention L = pi f c_light n.l (Hoffman 2010, "Physically-Based
// Shading Models in Film and Game Production"), c_light the light's "colour".
fn lights_radiance_pi(f: f32, c_light: f32, n_dot_l: f32) -> f32 {
    return brdf_lights_reflected(f, c_light, n_dot_l, BRDF_PI);
}

// lights_radiance_pi per channel.
fn lights_radiance_pi_rgb(
    f_r: f32, f_g: f32, f_b: f32, c_light_r: f32, c_light_g: f32, c_light_b: f32, n_dot_l: f32,
) -> vec3<f32> {
    return vec3<f32>(
        lights_radiance_pi(f_r, c_light_r, n_dot_l),
        lights_radiance_pi(f_g, c_light_g, n_dot_l),
        lights_radiance_pi(f_b, c_light_b, n_dot_l),
    );
}

// Irradiance E = E_perp max(n.l, 0) (Lambert's cosine law).
fn lights_irradiance(e_perp: f32, n_dot_l: f32) -> f32 {
    return lights_radiance(1.0, e_perp, n_dot_l);
}

// Inverse-square falloff 1 / max(d, d_min)^2, capped at the largest finite f32.
fn lights_inverse_square(distance: f32, min_distance: f32) -> f32 {
    let d = max(distance, min_distance);
    return min(1.0 / (d * d), BRDF_F32_MAX);
}

// Karis's window saturate(1 - (d / r)^4)^2 (Karis 2013, "Real Shading in Unreal Engine 4"),
// 0 for r = 0.
fn brdf_lights_window(distance: f32, radius: f32) -> f32 {
    let q = distance / radius;
    let q2 = q * q;
    let w = saturate(1.0 - q2 * q2);
    return select(w * w, 0.0, radius == 0.0);
}

// Unreal Engine 4's windowed falloff window(d, r) / (d^2 + 1) (Karis 2013).
fn lights_windowed(distance: f32, radius: f32) -> f32 {
    return brdf_lights_window(distance, radius) / fma(distance, distance, 1.0);
}

// Filament's windowed inverse square, window(d, r) / max(d, d_min)^2 (Guy and Agopian 2018,
// "Physically Based Rendering in Filament", 5.2.2).
fn lights_windowed_inverse_square(distance: f32, radius: f32, min_distance: f32) -> f32 {
    return brdf_lights_window(distance, radius) * lights_inverse_square(distance, min_distance);
}

// The classic polynomial attenuation 1 / (k_c + k_l d + k_q d^2) (OpenGL's fixed pipeline;
// Direct3D 9), a zero coefficient dropping its term, capped at the largest finite f32.
fn lights_polynomial(distance: f32, constant: f32, linear: f32, quadratic: f32) -> f32 {
    let lin = select(0.0, linear * distance, linear > 0.0);
    let quad = select(0.0, quadratic * distance * distance, quadratic > 0.0);
    return min(1.0 / (constant + lin + quad), BRDF_F32_MAX);
}

// A spot cone's smooth edge t^2, t = saturate((cos - cos_outer) / (cos_inner - cos_outer))
// (glTF KHR_lights_punctual; Filament); a hard edge (step at cos_outer) where the two cosines
// are equal.
fn lights_spot_cone(cos_angle: f32, cos_outer: f32, cos_inner: f32) -> f32 {
    let width = cos_inner - cos_outer;
    let hard = width == 0.0;
    let t = saturate((cos_angle - cos_outer) / select(width, 1.0, hard));
    let step = select(0.0, 1.0, cos_angle >= cos_outer);
    return select(t * t, step, hard);
}

// `lights::SpotCone` from its constructor's angles (inner <= outer in [0, pi]): cos_outer is
// min(cos(outer), cos(inner)), so that rounding cannot order them the wrong way.
fn lights_SpotCone_eval(inner: f32, outer: f32, cos_angle: f32) -> f32 {
    let cos_inner = cos(inner);
    return lights_spot_cone(cos_angle, min(cos(outer), cos_inner), cos_inner);
}
