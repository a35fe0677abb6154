// brdf: constants and helpers shared by every family's WGSL. Include this first.
//
// Every kernel here is the WGSL twin of the Rust kernel of the same path (`ggx::d` is `ggx_d`),
// with the same arguments in the same order, written in the same numerically stable form but
// in plain f32: where the Rust kernel carries double words (error-free products and sums) to
// round once, the twin keeps the stable form and rounds each operation, because WGSL lets an
// implementation reassociate and contract operations, which undoes error-free transformations
// (W3C WGSL, section "Floating Point Evaluation"). Helpers are prefixed `brdf_`. As in the
// Rust kernels, guards are `select`, `min`, `max`: no branch, no short-circuit `&&` or `||`
// (which lower to branches), `&` and `|` on booleans instead.
//
// WGSL has no NaN or infinity guarantees (an implementation may assume neither occurs), so the
// Rust kernels' NaN-in, NaN-out rule has no twin here: a NaN or infinite input gives an
// unspecified value, and inputs outside a kernel's documented domain are the caller's to avoid.

// pi and 1 / pi, rounded to f32.
const BRDF_PI: f32 = 3.14159265358979323846;
const BRDF_FRAC_1_PI: f32 = 0.318309886183790671538;
// The largest finite f32: results that would overflow are capped here, as in the Rust kernels.
const BRDF_F32_MAX: f32 = 3.40282346638528859812e38;
// microfacet::ALPHA_MIN and ALPHA_MAX: the microfacet width is clamped into [1e-4, 1e4], which
// keeps alpha^2 and the NDF's peak 1 / (pi alpha^2) far inside f32's normal range.
const BRDF_ALPHA_MIN: f32 = 1e-4;
const BRDF_ALPHA_MAX: f32 = 1e4;

// alpha clamped to [ALPHA_MIN, ALPHA_MAX] (microfacet::clamp_alpha without its NaN rule).
fn brdf_clamp_alpha(alpha: f32) -> f32 {
    return clamp(alpha, BRDF_ALPHA_MIN, BRDF_ALPHA_MAX);
}

// `value` above the horizon (c > 0), 0 at or below it.
fn brdf_above(c: f32, value: f32) -> f32 {
    return select(0.0, value, c > 0.0);
}

// 1 - c^2 without cancellation near c = 1: 1 - c c below c = 1/2 (nothing cancels there),
// the product (1 - c)(1 + c) above, where 1 - c is exact (Sterbenz). The Rust kernels' form on
// targets without FMA (microfacet::sin2_working).
fn brdf_sin2(c: f32) -> f32 {
    return select((1.0 - c) * (1.0 + c), 1.0 - c * c, c < 0.5);
}

// 1 - c^2 as (1 - c)(1 + c): 1 - c and 1 + c are exact for c in [1/2, 1], so near c = 1 the
// result keeps its digits where 1 - c c would cancel them.
fn brdf_one_minus_sq(c: f32) -> f32 {
    return (1.0 - c) * (1.0 + c);
}

// (1, 0, 0) for the zero vector (a direction at the horizon), else w (vec3::horizon_if_zero3).
fn brdf_horizon_if_zero(w: vec3<f32>) -> vec3<f32> {
    let zero = (w.x == 0.0) & (w.y == 0.0) & (w.z == 0.0);
    return vec3<f32>(select(w.x, 1.0, zero), select(w.y, 0.0, zero), select(w.z, 0.0, zero));
}

// u clamped to [0, 1 - 2^-24] (sampling::clamp_u): a sample of exactly 1 maps where 1 - 2^-24
// does.
fn brdf_clamp_u(u: f32) -> f32 {
    return clamp(u, 0.0, 0.99999994);
}

// (cos(2 pi u), sin(2 pi u)) for the samplers' azimuths: WGSL promises sin and cos only on
// [-pi, pi] (absolute error 2^-11 there), so they are taken as -cos(t) and -sin(t) with
// t = (2 u - 1) pi', pi' the f32 just below pi, which keeps |t| <= pi.
fn brdf_cos_sin_2pi(u: f32) -> vec2<f32> {
    let t = fma(2.0, u, -1.0) * 3.1415925;
    return vec2<f32>(-cos(t), -sin(t));
}

// The twins of the Rust module `microfacet`'s roughness conversions.

// alpha = r^2 from the perceptual roughness r (glTF's roughnessFactor, Unreal Engine 4's
// Roughness; Burley 2012, "Physically-Based Shading at Disney"; Karis 2013, "Real Shading in
// Unreal Engine 4"), r capped at 100 = sqrt(ALPHA_MAX), alpha clamped to [ALPHA_MIN, ALPHA_MAX].
fn microfacet_alpha_from_perceptual(roughness: f32) -> f32 {
    let r = min(roughness, 100.0);
    return brdf_clamp_alpha(r * r);
}

// The perceptual roughness r = sqrt(alpha) of a width alpha >= 0.
fn microfacet_perceptual_from_alpha(alpha: f32) -> f32 {
    return sqrt(alpha);
}
