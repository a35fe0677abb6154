//! Textbook single-precision forms: each kernel as engines and course notes write it, with no
//! guard and no error compensation, generic over [`Real`] so that it runs on the same paths
//! (scalar, lanes, `batch`) as the crate's forms. They are rows of the error-against-run-time
//! table, so a reader sees what the crate's stable forms cost and what they buy.

use brdf::Real;

/// GGX D as Filament's `D_GGX` and glTF 2.0 Appendix B write it:
/// alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2).
pub fn ggx_d<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a2 = alpha * alpha;
    let t = n_dot_h * n_dot_h * (a2 - T::ONE) + T::ONE;
    a2 / (T::PI * t * t)
}

/// Beckmann D as Walter et al. 2007 eq. 25 reads: exp(((n.h)^2 - 1) / (alpha^2 (n.h)^2)) /
/// (pi alpha^2 (n.h)^4).
pub fn beckmann_d<T: Real>(n_dot_h: T, alpha: T) -> T {
    let a2 = alpha * alpha;
    let c2 = n_dot_h * n_dot_h;
    ((c2 - T::ONE) / (a2 * c2)).exp() / (T::PI * a2 * c2 * c2)
}

/// Height-correlated Smith V for GGX as Filament's `V_SmithGGXCorrelated` (and glTF 2.0
/// Appendix B) write it: 0.5 / (n.l sqrt((n.v)^2 (1 - alpha^2) + alpha^2) + n.v sqrt(...)).
pub fn ggx_v<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T) -> T {
    let a2 = alpha * alpha;
    let gv = n_dot_l * (n_dot_v * n_dot_v * (T::ONE - a2) + a2).sqrt();
    let gl = n_dot_v * (n_dot_l * n_dot_l * (T::ONE - a2) + a2).sqrt();
    T::HALF / (gv + gl)
}

/// Beckmann G1 = 1 / (1 + Lambda) with [`beckmann_lambda`].
pub fn beckmann_g1<T: Real>(n_dot_v: T, alpha: T) -> T {
    T::ONE / (T::ONE + beckmann_lambda(n_dot_v, alpha))
}

/// Beckmann Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = n.v / (alpha sqrt(1 -
/// (n.v)^2)), Heitz 2014 eq. 83 as written (the two terms cancel for large a).
pub fn beckmann_lambda<T: Real>(n_dot_v: T, alpha: T) -> T {
    let s = (T::ONE - n_dot_v * n_dot_v).sqrt();
    let a = n_dot_v / (alpha * s);
    ((-(a * a)).exp() / (a * T::PI.sqrt()) - a.erfc()) * T::HALF
}

/// Dielectric Fresnel as pbrt-v3's `FrDielectric` computes it for light arriving from the
/// outside (eta > 1): Snell's law for cos theta_t, then the two amplitude ratios squared.
pub fn fresnel_dielectric<T: Real>(cos_i: T, eta: T) -> T {
    let sin_t = (T::ONE - cos_i * cos_i).max(T::ZERO).sqrt() / eta;
    let cos_t = (T::ONE - sin_t * sin_t).max(T::ZERO).sqrt();
    let r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    (r_parl * r_parl + r_perp * r_perp) * T::HALF
}

/// Conductor Fresnel as pbrt-v3's `FrConductor` (after Lagarde 2013, "Memo on Fresnel
/// equations") computes it: a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2)^2 + 4 eta^2 k^2), then Rs
/// and Rp from t1 = a^2 + b^2 + cos^2, t2 = 2 a cos.
pub fn fresnel_conductor<T: Real>(cos_i: T, eta: T, k: T) -> T {
    let cos2 = cos_i * cos_i;
    let sin2 = T::ONE - cos2;
    let (eta2, k2) = (eta * eta, k * k);
    let t0 = eta2 - k2 - sin2;
    let a2b2 = (t0 * t0 + T::splat(4.0) * eta2 * k2).sqrt();
    let t1 = a2b2 + cos2;
    let a = (T::HALF * (a2b2 + t0)).max(T::ZERO).sqrt();
    let t2 = T::TWO * cos_i * a;
    let rs = (t1 - t2) / (t1 + t2);
    let t3 = cos2 * a2b2 + sin2 * sin2;
    let t4 = t2 * sin2;
    let rp = rs * (t3 - t4) / (t3 + t4);
    T::HALF * (rp + rs)
}

/// The glTF 2.0 metallic-roughness BRDF in Appendix B's compact form, in one colour
/// channel: F = F0 + (1 - F0)(1 - v.h)^5 with F0 = mix(0.04, base, metallic),
/// f = (1 - F) (1 - metallic) base / pi + F D V, alpha = roughness^2, with [`ggx_d`] and
/// [`ggx_v`].
#[allow(clippy::too_many_arguments)]
pub fn gltf<T: Real>(
    n_dot_v: T,
    n_dot_l: T,
    n_dot_h: T,
    v_dot_h: T,
    base: T,
    metallic: T,
    roughness: T,
) -> T {
    let alpha = roughness * roughness;
    let f0 = T::splat(0.04) + (base - T::splat(0.04)) * metallic;
    let m = T::ONE - v_dot_h;
    let m2 = m * m;
    let f = f0 + (T::ONE - f0) * (m2 * m2 * m);
    let diffuse = (T::ONE - f) * (T::ONE - metallic) * base * T::FRAC_1_PI;
    diffuse + f * ggx_d(n_dot_h, alpha) * ggx_v(n_dot_v, n_dot_l, alpha)
}
