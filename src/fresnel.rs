//! Fresnel reflectance: the exact dielectric (unpolarized and polarized) and conductor
//! equations, Schlick's approximation and its variants, the F82-tint metal model, and the
//! hemispherical average of the dielectric term.
//!
//! Conventions: `cos_theta_i` is the cosine between the incident direction and the normal on
//! the side the light arrives from; `eta = n_t / n_i` is the relative index of refraction
//! across the interface (glass in air: 1.5). Cosines passed to the Schlick forms are clamped
//! to [0, 1].
//!
//! The exact forms are written so that the (eta^2 - 1) factor of the reflected amplitude is
//! explicit: eta = 1 gives exactly 0 at every angle and eta = 1 +- 1e-6 loses no digits to
//! cancellation (the textbook (c - eta cos_t) / (c + eta cos_t) subtracts two nearly equal
//! numbers there).
//!
//! f32 against f64 on the same inputs (`cargo test --test stability -- --nocapture`):
//! `dielectric` within 5 ulps for eta > 1 and within 49 for eta < 1, whose worst case sits at
//! the critical angle (infinite slope); `conductor` within 11; `schlick` within 5.

use crate::real::Real;
use crate::vec3::V3;

/// Normal-incidence reflectance of a dielectric: F0 = ((eta - 1) / (eta + 1))^2 (Fresnel's
/// equations at theta = 0; the "F0 from IOR" of real-time engines). Domain eta > 0; F0(1) = 0.
#[inline]
#[must_use]
pub fn f0_from_ior<T: Real>(eta: T) -> T {
    ((eta - T::ONE) / (eta + T::ONE)).sq()
}

/// The index of refraction (>= 1) with normal-incidence reflectance `f0`:
/// eta = (1 + sqrt(F0)) / (1 - sqrt(F0)). Domain F0 in [0, 1): F0 = 0 gives 1; F0 >= 1 gives
/// +inf (a perfect mirror has no finite dielectric IOR).
#[inline]
#[must_use]
pub fn ior_from_f0<T: Real>(f0: T) -> T {
    let s = f0.saturate().sqrt();
    let den = T::ONE - s;
    T::select(den.simd_gt(T::ZERO), (T::ONE + s) / den, T::INFINITY)
}

/// (1 - c)^5 for c clamped to [0, 1], by multiplication.
#[inline]
fn one_minus_pow5<T: Real>(cos_theta: T) -> T {
    (T::ONE - cos_theta.saturate()).powi(5)
}

/// Schlick's approximation F = F0 + (1 - F0)(1 - c)^5 (Schlick 1994, "An Inexpensive BRDF
/// Model for Physically-based Rendering", eq. 15). Exact at c = 1 (F0) and c = 0 (1). The
/// factor is (1 - c)^5, not the (1 - c^5) some course notes print. Approximation: max abs error
/// against [`dielectric`] 0.060 for eta = 1.33, 0.036 for 1.5, 0.074 for 2.4, 0.125 for 3, all
/// near c = 0.1 (`cargo test --test fresnel_approximations -- --nocapture`).
#[inline]
#[must_use]
pub fn schlick<T: Real>(f0: T, v_dot_h: T) -> T {
    lerp_exact(f0, T::ONE, one_minus_pow5(v_dot_h))
}

/// (1 - w) a + w b: exactly a at w = 0 and exactly b at w = 1 (a + w (b - a) rounds at w = 1).
#[inline]
fn lerp_exact<T: Real>(a: T, b: T, w: T) -> T {
    a.mul_add(T::ONE - w, w * b)
}

/// Schlick's approximation with an explicit grazing value: F = F0 + (F90 - F0)(1 - c)^5
/// (used with F90 != 1 by Burley 2012's diffuse and for specular occlusion).
#[inline]
#[must_use]
pub fn schlick_f90<T: Real>(f0: T, f90: T, v_dot_h: T) -> T {
    lerp_exact(f0, f90, one_minus_pow5(v_dot_h))
}

/// [`schlick`] for an RGB F0 (x = r, y = g, z = b), sharing the (1 - c)^5 factor.
#[inline]
#[must_use]
pub fn schlick_rgb<T: Real>(f0: V3<T>, v_dot_h: T) -> V3<T> {
    let w = one_minus_pow5(v_dot_h);
    V3::new(
        lerp_exact(f0.x, T::ONE, w),
        lerp_exact(f0.y, T::ONE, w),
        lerp_exact(f0.z, T::ONE, w),
    )
}

/// [`schlick_f90`] for RGB F0 and F90 (x = r, y = g, z = b), sharing the (1 - c)^5 factor.
#[inline]
#[must_use]
pub fn schlick_f90_rgb<T: Real>(f0: V3<T>, f90: V3<T>, v_dot_h: T) -> V3<T> {
    let w = one_minus_pow5(v_dot_h);
    V3::new(
        lerp_exact(f0.x, f90.x, w),
        lerp_exact(f0.y, f90.y, w),
        lerp_exact(f0.z, f90.z, w),
    )
}

/// Schlick with the power replaced by a spherical-Gaussian exp2 fit:
/// F = F0 + (1 - F0) 2^((-5.55473 c - 6.98316) c) (Karis 2013, "Real Shading in Unreal Engine
/// 4"). Approximation of [`schlick`], within 0.0037 of it for eta in [1.33, 3]; 1 at c = 0,
/// F0 + (1 - F0) 2^-12.5 at c = 1 (not exactly F0).
#[inline]
#[must_use]
pub fn schlick_sg<T: Real>(f0: T, v_dot_h: T) -> T {
    let c = v_dot_h.saturate();
    let w = (c.mul_add(T::splat(-5.55473), T::splat(-6.98316)) * c).exp2();
    lerp_exact(f0, T::ONE, w)
}

/// s- and p-polarized reflectances of a dielectric interface: (Rs, Rp) = (r_perp^2, r_par^2)
/// (Fresnel 1823; Born and Wolf, "Principles of Optics", section 1.5).
///
/// With c = |cos_theta_i| and k = eta^2 - 1 + c^2 (= (eta cos_theta_t)^2):
/// r_perp = -(eta^2 - 1) / (c + sqrt(k))^2 and
/// r_par = (eta^2 - 1) ((eta^2 + 1) c^2 - 1) / (eta^2 c + sqrt(k))^2,
/// algebraically equal to the textbook ratios but without their cancellation.
///
/// A negative `cos_theta_i` means the light arrives from the transmitted side: eta is
/// replaced by 1/eta. k < 0 is total internal reflection: (1, 1). Domain: eta > 0 and finite,
/// cos_theta_i in [-1, 1] (clamped). eta = 1 gives (0, 0) at every angle; c = 0 gives (1, 1)
/// for eta != 1.
#[inline]
#[must_use]
pub fn dielectric_polarized<T: Real>(cos_theta_i: T, eta: T) -> (T, T) {
    let inside = cos_theta_i.simd_lt(T::ZERO);
    let eta = T::select(inside, eta.recip(), eta);
    let c = cos_theta_i.abs().min(T::ONE);
    let eta2 = eta * eta;
    let eta2_m1 = (eta - T::ONE) * (eta + T::ONE);
    let k = c.mul_add(c, eta2_m1);
    let tir = k.simd_lt(T::ZERO);
    let root = k.sqrt_nonneg();
    // (c + root)^2 expanded as c (c + 2 root) + k, so that c = 0 gives exactly k and
    // r = -1 exactly (grazing incidence reflects everything).
    let d_perp = c.mul_add(c + T::TWO * root, k);
    let e2c = eta2 * c;
    let d_par = e2c.mul_add(e2c + T::TWO * root, k);
    // d = 0 only for c = 0 with eta = 1: no interface, no reflection.
    let r_perp = T::select(d_perp.simd_gt(T::ZERO), -eta2_m1 / d_perp, T::ZERO);
    let r_par = T::select(
        d_par.simd_gt(T::ZERO),
        eta2_m1 * (eta2 + T::ONE).mul_add(c * c, -T::ONE) / d_par,
        T::ZERO,
    );
    let rs = T::select(tir, T::ONE, r_perp.sq().min(T::ONE));
    let rp = T::select(tir, T::ONE, r_par.sq().min(T::ONE));
    (rs, rp)
}

/// Exact unpolarized Fresnel reflectance of a dielectric, F = (Rs + Rp) / 2 from
/// [`dielectric_polarized`] (same conventions: negative cosine flips eta, total internal
/// reflection gives 1, eta = 1 gives 0).
#[inline]
#[must_use]
pub fn dielectric<T: Real>(cos_theta_i: T, eta: T) -> T {
    let (rs, rp) = dielectric_polarized(cos_theta_i, eta);
    T::HALF * (rs + rp)
}

/// Exact unpolarized Fresnel reflectance of a conductor with complex relative IOR
/// eta + i k (Born and Wolf, section 14.2; the complex form of [`dielectric_polarized`]):
/// with s = sqrt(eta_c^2 - 1 + c^2) complex, r_perp = (c - s) / (c + s),
/// r_par = (eta_c^2 c - s) / (eta_c^2 c + s), F = (|r_perp|^2 + |r_par|^2) / 2.
///
/// Domain: eta > 0, k >= 0, both finite (k up to 1e3 and beyond: the terms stay within
/// (eta^2 + k^2)^2 ~ 1e12); cos_theta_i clamped to [0, 1]. k = 0 equals [`dielectric`] for the
/// same eta (to rounding); c = 0 gives 1.
#[inline]
#[must_use]
pub fn conductor<T: Real>(cos_theta_i: T, eta: T, k: T) -> T {
    let c = cos_theta_i.saturate();
    // eta_c^2 = (eta^2 - k^2) + i 2 eta k
    let w_re = (eta - k) * (eta + k);
    let w_im = T::TWO * eta * k;
    // s^2 = eta_c^2 - 1 + c^2 = (eta^2 - 1) - k^2 + c^2, with eta^2 - 1 factored.
    let (s_re, s_im) = complex_sqrt(c.mul_add(c, (eta - T::ONE) * (eta + T::ONE)) - k * k, w_im);
    let perp = ratio_norm2(c - s_re, -s_im, c + s_re, s_im);
    let par = ratio_norm2(
        w_re.mul_add(c, -s_re),
        w_im.mul_add(c, -s_im),
        w_re.mul_add(c, s_re),
        w_im.mul_add(c, s_im),
    );
    (T::HALF * (perp + par)).saturate()
}

/// [`conductor`] per channel for RGB eta and k (x = r, y = g, z = b).
#[inline]
#[must_use]
pub fn conductor_rgb<T: Real>(cos_theta_i: T, eta: V3<T>, k: V3<T>) -> V3<T> {
    V3::new(
        conductor(cos_theta_i, eta.x, k.x),
        conductor(cos_theta_i, eta.y, k.y),
        conductor(cos_theta_i, eta.z, k.z),
    )
}

/// |a + ib|^2 / |c + id|^2, 0 where the denominator is 0.
#[inline]
fn ratio_norm2<T: Real>(a: T, b: T, c: T, d: T) -> T {
    let den = c.mul_add(c, d * d);
    T::select(den.simd_gt(T::ZERO), a.mul_add(a, b * b) / den, T::ZERO)
}

/// Principal square root of re + i im, without the cancellation of sqrt((|z| - re) / 2) for
/// re > 0 (Press et al., "Numerical Recipes", section 5.5).
#[inline]
fn complex_sqrt<T: Real>(re: T, im: T) -> (T, T) {
    let norm = re.mul_add(re, im * im).sqrt();
    let t = (T::HALF * (norm + re.abs())).sqrt();
    let safe_t = T::select(t.simd_gt(T::ZERO), t, T::ONE);
    let other = im.abs() / (T::TWO * safe_t);
    let other = T::select(t.simd_gt(T::ZERO), other, T::ZERO);
    let non_neg = re.simd_ge(T::ZERO);
    let out_re = T::select(non_neg, t, other);
    let out_im_mag = T::select(non_neg, other, t);
    (out_re, out_im_mag.copysign(im))
}

/// The cosine mu_bar = 1/7 (theta = 81.8 degrees) at which the F82-tint model is pinned: the
/// maximum of mu (1 - mu)^6, so the correction never overshoots (Kutz, Hasan, Edmondson 2021).
pub const F82_MU: f64 = 1.0 / 7.0;

/// Generalized Schlick with an F82 tint for metals (Hoffman 2019, "Fresnel Equations
/// Considered Harmful"; Kutz, Hasan, Edmondson 2021, "Novel aspects of the Adobe Standard
/// Material"): F(mu) = schlick(F0, mu) - b mu (1 - mu)^6, with
/// b = schlick(F0, mu_bar) (1 - tint) / (mu_bar (1 - mu_bar)^6), mu_bar = [`F82_MU`], so that
/// F(mu_bar) = tint * schlick(F0, mu_bar): the dip of real metals near grazing.
///
/// Domain: F0 and tint in [0, 1]; cosine clamped to [0, 1]. tint = 1 is plain Schlick. The
/// result is clamped at 0 (for tint < 1 and small F0 the fitted dip can cross below 0 by a
/// rounding-sized amount).
#[inline]
#[must_use]
pub fn schlick_f82<T: Real>(f0: T, f82_tint: T, cos_theta: T) -> T {
    let mu_bar = T::splat(F82_MU);
    let denom = T::splat(F82_MU * libm::pow(1.0 - F82_MU, 6.0));
    let b = schlick(f0, mu_bar) * (T::ONE - f82_tint) / denom;
    let mu = cos_theta.saturate();
    let dip = b * mu * (T::ONE - mu).powi(6);
    (schlick(f0, mu) - dip).max(T::ZERO)
}

/// [`schlick_f82`] per channel for RGB F0 and tint.
#[inline]
#[must_use]
pub fn schlick_f82_rgb<T: Real>(f0: V3<T>, f82_tint: V3<T>, cos_theta: T) -> V3<T> {
    V3::new(
        schlick_f82(f0.x, f82_tint.x, cos_theta),
        schlick_f82(f0.y, f82_tint.y, cos_theta),
        schlick_f82(f0.z, f82_tint.z, cos_theta),
    )
}

/// Gauss-Legendre nodes and weights on [0, 1], 24 points (computed to double precision by
/// Newton iteration on P_24; 24 points integrate polynomials of degree 47 exactly).
fn gauss_legendre_24() -> ([f64; 24], [f64; 24]) {
    const N: usize = 24;
    let mut x = [0.0; N];
    let mut w = [0.0; N];
    for i in 0..N {
        // Tricomi's initial guess, then Newton on the Legendre recurrence.
        let mut z = libm::cos(core::f64::consts::PI * (i as f64 + 0.75) / (N as f64 + 0.5));
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for n in 2..=N {
                let p2 = ((2 * n - 1) as f64 * z * p1 - (n - 1) as f64 * p0) / n as f64;
                p0 = p1;
                p1 = p2;
            }
            dp = N as f64 * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// Hemispherical average (first cosine moment) of the dielectric Fresnel term,
/// F_avg(eta) = 2 * integral over mu in [0, 1] of F(mu, eta) mu dmu, the fraction of uniform
/// incident light a smooth interface reflects (Kulla and Conty 2017, "Revisiting Physically
/// Based Shading at Imageworks", where it drives energy compensation).
///
/// Evaluated by quadrature to double precision: for eta < 1 the total-internal-reflection
/// interval [0, mu_c] contributes mu_c^2 exactly and the rest is integrated after the
/// substitution mu = mu_c + (1 - mu_c) t^2, which removes the square-root kink at mu_c. Not a
/// hot-path kernel (48 dielectric evaluations); see [`average_dielectric_fit`] for one.
/// Domain eta > 0, finite; F_avg(1) = 0.
#[must_use]
pub fn average_dielectric(eta: f64) -> f64 {
    let (x, w) = gauss_legendre_24();
    // cos of the critical angle: sqrt(1 - eta^2) for eta < 1.
    let mu_c = if eta < 1.0 {
        libm::sqrt((1.0 - eta) * (1.0 + eta))
    } else {
        0.0
    };
    let span = 1.0 - mu_c;
    let mut sum = 0.0;
    for i in 0..x.len() {
        let t = x[i];
        let mu = t.mul_add(t * span, mu_c);
        sum += w[i] * dielectric(mu, eta) * mu * 2.0 * span * t;
    }
    mu_c * mu_c + 2.0 * sum
}

/// Fast fit of [`average_dielectric`] (Kulla and Conty 2017, slide "Fresnel average"):
/// (eta - 1) / (4.08567 + 1.00071 eta) for eta >= 1, and
/// 0.997118 + 0.1014 eta - 0.965241 eta^2 - 0.130607 eta^3 for eta < 1. Approximation: max
/// abs error 0.0065 against the quadrature over eta in [0.5, 3], at eta = 1.17
/// (`cargo test --test fresnel_approximations -- --nocapture`).
#[inline]
#[must_use]
pub fn average_dielectric_fit<T: Real>(eta: T) -> T {
    let above = (eta - T::ONE) / eta.mul_add(T::splat(1.00071), T::splat(4.08567));
    let below = eta.mul_add(
        eta.mul_add(
            eta.mul_add(T::splat(-0.130607), T::splat(-0.965241)),
            T::splat(0.1014),
        ),
        T::splat(0.997118),
    );
    T::select(eta.simd_ge(T::ONE), above, below)
}
