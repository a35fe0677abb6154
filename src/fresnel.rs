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
//! explicit, formed from eta as given on both sides of the interface (never from a rounded
//! 1 / eta): eta = 1 gives exactly 0 at every angle and eta = 1 +- 2^-24 loses no digits to
//! cancellation (the textbook (c - eta cos_t) / (c + eta cos_t) subtracts two nearly equal
//! numbers there). Every finite eta > 0 and k >= 0 gives a finite result in [0, 1].
//!
//! # Accuracy
//! Measured by the workspace's correctly rounded oracle (MPFR at 256 bits and more, from the
//! textbook ratio definitions), in ULPs of the correctly rounded result where it is >= 1e-30
//! (f32) / 1e-300 (f64); lanes equal scalar bit for bit. Every ordinary run
//! (`cargo test -p brdf-oracle --release -- --nocapture`: fresh points over the whole domain,
//! seed printed, plus the committed hardest inputs in `oracle/hardest.txt`) holds each
//! function within the bound below (`oracle/src/bounds.rs`; the larger of the default and FMA
//! builds); in parentheses, the max found by the deep search (`docs/accuracy.md`: 10^5 fresh
//! points per function and type, eta and k log-uniform from the smallest subnormal to MAX,
//! both sides of every internal switch, plus a longer hill-climb;
//! `BRDF_ORACLE_DEEP=1 BRDF_ORACLE_RECORD=1 cargo test -p brdf-oracle --release --test
//! accuracy_table -- --nocapture`):
//!
//! | function | f32, f32x8 | f64, f64x4 |
//! |---|---|---|
//! | `dielectric` | 1.4 (1.24) | 1.4 (1.23) |
//! | `dielectric_polarized` Rs | 0.7 (0.50) | 0.7 (0.50) |
//! | `dielectric_polarized` Rp | 0.7 (0.50) | 0.7 (0.50) |
//! | `conductor` | 0.7 (0.50) | 3.9 (3.69) |
//! | `schlick` | 3.2 (3.05) | 3.5 (3.25) |
//! | `f0_from_ior` | 0.7 (0.50) | 0.7 (0.50) |
//!
//! The dielectric forms carry eta^2, c^2, g, the two denominators, the amplitude ratios
//! r_perp and r_par themselves and their squares in double words (Dekker products and Knuth
//! sums, without FMA, so every target and lane type rounds alike), so that Rs = r_perp^2 and
//! Rp = r_par^2 are rounded once; F = (Rs + Rp) / 2 adds one more rounding.
//! Where a 1-ulp change of the cosine moves the exact result by more than 8 ulps (kappa > 8:
//! within about 2^-12 of the critical cosine, where dF/dcos is infinite, and at Rp's double
//! zero at Brewster's angle) the oracle scores raw - kappa / 2, the raw error less what one
//! rounding of the cosine explains; there the raw error stays below what that rounding
//! explains: raw <= kappa / 2 + B with B = -2.7 (F, f32) / -2.6 (F, f64), -3.3 (Rs, Rp) and -3.3 (conductor, f32) / -0.7
//! (conductor, f64) (`docs/accuracy.md`). Points with eta within a few ulps of 1
//! count as well conditioned (eta - 1 is exact) and are in the table above.
//! The conductor carries N^2 - 1, s^2 = N^2 - sin^2, s (one Newton step), the squared
//! moduli |N^2 - 1|^2 and |c + s|^2 and their quotient |r_perp|^2 in double words as well,
//! since |r_perp|^2 = |N^2 - 1|^2 / |c + s|^4 would otherwise quadruple the roundings of s;
//! its parallel term enters as a ratio of two positive sums that damps its own roundings by
//! half, and F = |r_perp|^2 A / (A + B) is rounded once. On `f32` and `f32x8` the conductor
//! is instead evaluated in f64, where the same cancellation-free arrangement needs neither
//! double words nor scalings, and rounded to f32 once.

use crate::domain::{in_unit, nan_unless};
use crate::dw::{Dw, pow2_nearest, single, two_sum};
use crate::real::Real;
use crate::vec3::V3;

/// eta in (0, MAX]: false for NaN, 0, negatives and +inf.
#[inline]
pub(crate) fn valid_eta<T: Real>(eta: T) -> T::Mask {
    eta.simd_gt(T::ZERO) & eta.simd_le(T::MAX)
}

/// Beyond [1 / 256, 256] [`dielectric_polarized`] evaluates Fresnel's ratios directly: so far
/// from 1 they do not cancel, and eta^4 (the (eta^2 c + g)^2 of the factored form) would
/// overflow f32 near eta = 2^32.
const ETA_RATIO_FORM: f64 = 256.0;

/// Above this max(eta, k) [`conductor`] works with N / max(eta, k): |N|^4 stays below 2^64.
const CONDUCTOR_SCALE_HI: f64 = 65536.0;

/// Normal-incidence reflectance of a dielectric: F0 = ((eta - 1) / (eta + 1))^2 (Fresnel's
/// equations at theta = 0; the "F0 from IOR" of real-time engines). Domain eta in (0, MAX]:
/// F0(1) = 0, F0 -> 1 as eta -> 0 or MAX; eta <= 0, +inf and NaN give NaN. Within 0.7 ulp
/// of the correctly rounded value (one rounding of a double-word result; max 0.50 ulp on every
/// lane type over (0, MAX] in the oracle's deep search, module docs, "Accuracy"; the plain
/// quotient and square reached 4.5 ulps). Cost: about 80
/// flops and two divisions, against 3 flops and one division for the plain form (25 ns
/// against 2 ns per f64 call on x86-64 without FMA): a per-material, not per-sample, cost.
#[inline]
#[must_use]
pub fn f0_from_ior<T: Real>(eta: T) -> T {
    // Above 2^40 (f32) / 2^80 (f64) F0 = 1 - 4 / eta + ... rounds to 1: capping eta there
    // changes nothing and keeps Dekker's products in range.
    let cap = T::splat(if single::<T>() { pow2(40) } else { pow2(80) });
    let e = eta.min(cap);
    // eta -+ 1 exactly (TwoSum), their quotient and its square in double words, rounded once.
    let r = Dw::sum(e, -T::ONE).div(Dw::sum(e, T::ONE));
    nan_unless(valid_eta(eta), r.sq().value())
}

/// The index of refraction (>= 1) with normal-incidence reflectance `f0`:
/// eta = (1 + sqrt(F0)) / (1 - sqrt(F0)). Domain F0 in [0, 1]: F0 = 0 gives 1; F0 = 1 (a
/// perfect mirror has no finite dielectric IOR) and values so close to 1 that the quotient
/// overflows give MAX, the crate's cap for a pole. F0 outside [0, 1] and NaN give NaN.
#[inline]
#[must_use]
pub fn ior_from_f0<T: Real>(f0: T) -> T {
    let s = f0.saturate().sqrt();
    let den = T::ONE - s;
    let eta = T::select(den.simd_gt(T::ZERO), (T::ONE + s) / den, T::MAX).min(T::MAX);
    nan_unless(in_unit(f0), eta)
}

/// Schlick's approximation F = F0 + (1 - F0)(1 - c)^5 (Schlick 1994, "An Inexpensive BRDF
/// Model for Physically-based Rendering", eq. 15). Exact at c = 1 (F0) and c = 0 (1). The
/// factor is (1 - c)^5, not the (1 - c^5) some course notes print. Approximation: max abs error
/// against [`dielectric`] 0.060 for eta = 1.33, 0.036 for 1.5, 0.074 for 2.4, 0.125 for 3, all
/// near c = 0.1 (`cargo test --test fresnel approximations:: -- --nocapture`).
///
/// Domain: F0 in [0, 1] (outside, and NaN, give NaN); the cosine is clamped to [0, 1] (a
/// negative one counts as grazing: 1), NaN gives NaN. Within 3.4 ulps (f32) / 3.5 ulps (f64)
/// of the correctly rounded formula, lanes the same (max 3.23 / 3.25 found; module docs,
/// "Accuracy"): the rounding error of 1 - c is
/// recovered and added back to first order (5 flops), instead of being raised to the 5th
/// power.
#[inline]
#[must_use]
pub fn schlick<T: Real>(f0: T, v_dot_h: T) -> T {
    nan_unless(in_unit(f0), lerp_exact(f0, T::ONE, one_minus_pow5(v_dot_h)))
}

/// (1 - c)^5 for c clamped to [0, 1], with the rounding error e of y = 1 - c (exact by
/// Fast2Sum, since 1 >= c) restored to first order: y^5 + 5 y^4 e. Without it the rounding of
/// 1 - c (for c < 1/2) is multiplied by 5 (4.5 ulps in Schlick's F).
#[inline]
fn one_minus_pow5<T: Real>(cos_theta: T) -> T {
    let c = cos_theta.saturate();
    let y = T::ONE - c;
    let e = (T::ONE - y) - c;
    let y2 = y * y;
    let y4 = y2 * y2;
    y4 * y + y4 * (T::splat(5.0) * e)
}

/// (1 - w) a + w b: exactly a at w = 0 and exactly b at w = 1 (a + w (b - a) rounds at w = 1).
#[inline]
fn lerp_exact<T: Real>(a: T, b: T, w: T) -> T {
    a.mul_add(T::ONE - w, w * b)
}

/// Schlick's approximation with an explicit grazing value: F = F0 + (F90 - F0)(1 - c)^5
/// (used with F90 != 1 by Burley 2012's diffuse and for specular occlusion). F0 and F90 any
/// finite values (Burley's F90 reaches 2.5; infinite or NaN ones give NaN); the cosine as in
/// [`schlick`].
#[inline]
#[must_use]
pub fn schlick_f90<T: Real>(f0: T, f90: T, v_dot_h: T) -> T {
    let ok = f0.is_finite() & f90.is_finite();
    nan_unless(ok, lerp_exact(f0, f90, one_minus_pow5(v_dot_h)))
}

/// [`schlick`] for an RGB F0 (x = r, y = g, z = b), sharing the (1 - c)^5 factor; each
/// channel follows [`schlick`]'s domain.
#[inline]
#[must_use]
pub fn schlick_rgb<T: Real>(f0: V3<T>, v_dot_h: T) -> V3<T> {
    let w = one_minus_pow5(v_dot_h);
    let ch = |f: T| nan_unless(in_unit(f), lerp_exact(f, T::ONE, w));
    V3::new(ch(f0.x), ch(f0.y), ch(f0.z))
}

/// [`schlick_f90`] for RGB F0 and F90 (x = r, y = g, z = b), sharing the (1 - c)^5 factor.
#[inline]
#[must_use]
pub fn schlick_f90_rgb<T: Real>(f0: V3<T>, f90: V3<T>, v_dot_h: T) -> V3<T> {
    let w = one_minus_pow5(v_dot_h);
    let ch = |a: T, b: T| nan_unless(a.is_finite() & b.is_finite(), lerp_exact(a, b, w));
    V3::new(ch(f0.x, f90.x), ch(f0.y, f90.y), ch(f0.z, f90.z))
}

/// Schlick with the power replaced by a spherical-Gaussian exp2 fit:
/// F = F0 + (1 - F0) 2^((-5.55473 c - 6.98316) c) (Karis 2013, "Real Shading in Unreal Engine
/// 4"). Approximation of [`schlick`], within 0.0037 of it for eta in [1.33, 3]; 1 at c = 0,
/// F0 + (1 - F0) 2^-12.5 at c = 1 (not exactly F0). Domain as [`schlick`].
#[inline]
#[must_use]
pub fn schlick_sg<T: Real>(f0: T, v_dot_h: T) -> T {
    let c = v_dot_h.saturate();
    let w = (c.mul_add(T::splat(-5.55473), T::splat(-6.98316)) * c).exp2();
    nan_unless(in_unit(f0), lerp_exact(f0, T::ONE, w))
}

/// s- and p-polarized reflectances of a dielectric interface: (Rs, Rp) = (r_perp^2, r_par^2)
/// (Fresnel 1823; Born and Wolf, "Principles of Optics", section 1.5).
///
/// `eta` is n_t / n_i as seen from the positive side of the normal. A non-negative
/// `cos_theta_i` means the light arrives from that side (relative index n = eta); a negative
/// one means it arrives from the other side (relative index 1 / eta). With c = |cos_theta_i|
/// and s2 = (1 - c)(1 + c) = sin^2 theta_i, the textbook ratios
/// r_perp = (n_1 c - n_2 cos_t) / (n_1 c + n_2 cos_t) and
/// r_par = (n_2 c - n_1 cos_t) / (n_2 c + n_1 cos_t) are evaluated as:
///
/// - from the positive side, a = c and m = eta^2 - 1, so g2 = a^2 + m = (eta cos_t)^2;
/// - from the other side, a = eta c and m = 1 - eta^2, so g2 = a^2 + m = cos_t^2;
///
/// then, with g = sqrt(g2), r_perp = (a - g) / (a + g) = -m / (a + g)^2 and
/// r_par = (x - y) / (x + y) = (eta^2 - 1) W f / (x + y)^2, where (x, y) = (eta^2 a, g)
/// resp. (eta^2 g, a), f = 1 resp. eta^2 and W = (eta^2 + 1) c^2 - f (zero at Brewster's
/// angle). The factor eta^2 - 1 is formed once from `eta` as given (never from a rounded
/// 1 / eta), so eta = 1 gives exactly 0 at every angle and eta = 1 +- 2^-24 keeps full
/// relative accuracy (the ratios subtract nearly equal numbers there). eta^2, c^2, a, g, the
/// denominators, r_perp, r_par and their squares are carried in double words (about twice
/// the working precision), so that Rs and Rp are rounded once. For eta outside [1/256, 256]
/// the textbook ratios themselves are used, also in double words (no cancellation so far from
/// 1 but at Brewster's angle, where the double words keep it exact), which keeps eta^4 from
/// overflowing and eta^2 from underflowing: the whole finite range is covered (see
/// `extreme_terms` in the source for its scalings near 0 and MAX).
///
/// g2 < 0 is total internal reflection: (1, 1). Domain: eta in (0, MAX], finite; cos_theta_i
/// in [-1, 1] (|cos| above 1 is clamped to 1). Edges: eta = 1 gives (0, 0); c = 0 gives
/// exactly (1, 1) for eta != 1; c = 1 gives ((eta - 1) / (eta + 1))^2 for both. NaN in either
/// input, eta <= 0 and eta = +inf give NaN.
///
/// Accuracy (module docs, "Accuracy"): Rs and Rp within 0.7 ulp of the correctly rounded
/// value (every lane type; max 0.50 found by the oracle's deep search over the whole domain)
/// where a 1-ulp change of the cosine moves them by at most 8 ulps; elsewhere (critical and
/// Brewster's angles) the raw error stays below what one rounding of the cosine explains
/// (raw <= kappa / 2 - 3.3). Cost: both paths
/// run on every lane (no branch on a lane value; they share the root, the quotients and the
/// squares), about 550 flops and seven divisions: 1.9 times the time (scalar) and 2.1 times
/// (f32x8, f64x4) of the previous form, working-precision ratios over double-word
/// denominators, which reached 5.3 ulps in Rs and 6.5 in Rp beyond eta = 256 (x86-64
/// without FMA, process CPU time over 10^7 calls).
#[inline]
#[must_use]
pub fn dielectric_polarized<T: Real>(cos_theta_i: T, eta: T) -> (T, T) {
    let inside = cos_theta_i.simd_lt(T::ZERO);
    let c = cos_theta_i.abs().min(T::ONE);
    let n = eta;

    // Moderate eta, in double-word arithmetic (module docs, "Accuracy"). Both sides share one
    // form: with a = c (m = eta^2 - 1) from the positive side and a = eta c (m = 1 - eta^2)
    // from the other, g2 = a^2 + m is (eta cos_t)^2 resp. cos_t^2 and
    // r_perp = (a - g) / (a + g) = -m / (a + g)^2. For r_par = (x - y) / (x + y) with
    // (x, y) = (eta^2 a, g) resp. (eta^2 g, a), x^2 - y^2 = (eta^2 - 1) W f, where
    // W = (eta^2 + 1) c^2 - f and f = 1 resp. eta^2: the Brewster zero is W's, formed
    // without cancelling rounded terms. The clamp keeps the discarded lanes of the extreme
    // path finite (Veltkamp's split overflows near MAX).
    let nm = n.clamp(T::splat(1.0 / ETA_RATIO_FORM), T::splat(ETA_RATIO_FORM));
    let n2 = Dw::product(nm, nm);
    let n2m1 = n2.add_t(-T::ONE);
    let cc = Dw::product(c, c);
    let n2cc = n2.mul(cc);
    let a = Dw::select(inside, Dw::product(nm, c), Dw::exact(c));
    let a2 = Dw::select(inside, n2cc, cc);
    let m = Dw::select(inside, n2m1.neg(), n2m1);
    let g2 = a2.add(m);
    // Extreme eta: the textbook ratios, with nu = n_t / n_i (eta from the positive side,
    // 1 / eta from the other), r_perp = (p - root) / (p + root) and
    // r_par = (x - root) / (x + root). The square root, the two quotients and the two squares
    // are shared with the moderate path (selected before, not after, to halve their cost).
    let extreme = n.simd_gt(T::splat(ETA_RATIO_FORM)) | n.simd_lt(T::splat(1.0 / ETA_RATIO_FORM));
    let (p_ext, x_ext, rad, big_nu) = extreme_terms(inside, c, n);
    let g = Dw::select(extreme, rad, g2).sqrt();
    // (a + g)^2 as a (a + 2 g) + g2, so that a = 0 gives exactly g2 = m and r_perp = -1.
    let d_perp = a.mul(a.add(g.scale2())).add(g2);
    let f = Dw::select(inside, n2, Dw::exact(T::ONE));
    let w = n2cc.add(cc).add(f.neg());
    let x = n2.mul(Dw::select(inside, g, a));
    let y = Dw::select(inside, a, g);
    let y2 = Dw::select(inside, a2, g2);
    let d_par = x.mul(x.add(y.scale2())).add(y2);
    let r_perp = div_or_zero(
        Dw::select(extreme, p_ext.add(g.neg()), m.neg()),
        Dw::select(extreme, p_ext.add(g), d_perp),
    );
    let r_par = div_or_zero(
        Dw::select(extreme, x_ext.add(g.neg()), n2m1.mul(w).mul(f)),
        Dw::select(extreme, x_ext.add(g), d_par),
    );
    let tir = (extreme & !big_nu & rad.hi.simd_lt(T::ZERO)) | (!extreme & g2.hi.simd_lt(T::ZERO));
    let rs = T::select(tir, T::ONE, r_perp.sq().value().min(T::ONE));
    let rp = T::select(tir, T::ONE, r_par.sq().value().min(T::ONE));
    let ok = valid_eta(eta) & !cos_theta_i.is_nan();
    (nan_unless(ok, rs), nan_unless(ok, rp))
}

/// n / d in double words, 0 where d is 0 (eta = 1 at a cosine whose square underflows: the
/// numerator is 0 there too, and 0 / 0 would be NaN).
#[inline]
fn div_or_zero<T: Real>(n: Dw<T>, d: Dw<T>) -> Dw<T> {
    let ok = !d.hi.simd_eq(T::ZERO);
    let q = n.div(Dw::select(ok, d, Dw::exact(T::ONE)));
    Dw::select(ok, q, Dw::exact(T::ZERO))
}

/// The terms of Fresnel's amplitude ratios for eta outside [1/256, 256] (the extreme path of
/// [`dielectric_polarized`]) in double words: (p, x, rad, nu > 256) with
/// r_perp = (p - sqrt(rad)) / (p + sqrt(rad)), r_par = (x - sqrt(rad)) / (x + sqrt(rad)) and
/// total internal reflection where nu < 1/256 and rad < 0. With nu = n_t / n_i (eta where `inside` is false, 1 / eta where it is true),
/// s2 = (1 - c)(1 + c) and mu = 1 / nu:
///
/// - nu > 256: no total reflection; cos_t = sqrt(1 - s2 mu^2) (within 2^-17 of 1),
///   r_perp = (c mu - cos_t) / (c mu + cos_t), r_par = (nu c - cos_t) / (nu c + cos_t);
/// - nu < 1/256: g = nu cos_t = sqrt(nu^2 - s2) (total reflection where nu^2 < s2),
///   r_perp = (c - g) / (c + g), r_par = (nu^2 c - g) / (nu^2 c + g).
///
/// Neither r_perp nor the denominators cancel (one term is at most 1/256 of the other); the
/// numerators of r_par cancel only at Brewster's angle, exactly formed from double words.
/// Ranges: nu c is capped at 2^(p + 8) (p the significand's bits), where r_par^2 rounds to 1
/// either way; a product with eta above 2^64 (f32) / 2^512 (f64) is formed from eta scaled by
/// that power of two, which Veltkamp's split needs near MAX; for nu < 1/256, nu is raised to
/// 2^-40 (f32) / 2^-100 (f64) at least (below it, only c = 1 escapes total reflection, where
/// Rs = Rp = F0(nu) rounds to 1 regardless). Results below the smallest normal lose bits
/// only in terms far below the last place of r, which is within 1/256 of -1 or 1 there.
#[inline]
fn extreme_terms<T: Real>(inside: T::Mask, c: T, eta: T) -> (Dw<T>, Dw<T>, Dw<T>, T::Mask) {
    let (cap, sc_at, sc_f, nu_lo) = if single::<T>() {
        (pow2(32), pow2(64), pow2(-64), pow2(-40))
    } else {
        (pow2(61), pow2(512), pow2(-512), pow2(-100))
    };
    let one = Dw::exact(T::ONE);
    let s2 = Dw::sum(T::ONE, -c).mul(Dw::sum(T::ONE, c));
    // nu > 256 (from the positive side with eta > 256, or from the other with eta < 1/256).
    let eta_gt1 = eta.simd_gt(T::ONE);
    let big_nu = (inside & !eta_gt1) | (!inside & eta_gt1);
    let scaled = eta.simd_gt(T::splat(sc_at));
    let (sc, unsc) = (
        T::select(scaled, T::splat(sc_f), T::ONE),
        T::select(scaled, T::splat(sc_at), T::ONE),
    );
    let eta_s = eta * sc;
    // One quotient serves three cases: 1 / eta (nu > 256 from the positive side: mu),
    // c / eta (nu > 256 from the other: nu c; both raised by 2^64 (f32) / 2^512 (f64) where
    // eta is below 2^-64 / 2^-512, so that the remainder's product stays above the subnormal
    // range) and 1 / eta^2 (nu < 1/256 from the other: nu^2, eta capped at 1 / nu_lo).
    let up = T::select(eta.simd_lt(T::splat(sc_f)), T::splat(sc_at), T::ONE);
    let e_out = eta.max(T::splat(nu_lo));
    let e_in = eta.min(T::splat(1.0 / nu_lo));
    let num = Dw::exact(T::select(inside & big_nu, c * up, T::ONE));
    let den = Dw::select(
        inside,
        Dw::select(big_nu, Dw::exact(eta * up), Dw::square(e_in)),
        Dw::exact(eta_s),
    );
    let q = num.div(den);
    // nu > 256: mu = 1 / nu and nu c (capped); nu < 1/256: nu^2 (nu raised to nu_lo).
    let mu = Dw::select(inside, Dw::exact(eta), q.scale(sc));
    let c_eta = Dw::product(c, eta_s).scale(unsc);
    let nu_c = Dw::select(inside, q, c_eta);
    let nu_c = Dw::select(
        nu_c.hi.simd_le(T::splat(cap)),
        nu_c,
        Dw::exact(T::splat(cap)),
    );
    let nu2 = Dw::select(inside, q, Dw::square(e_out));
    // The common root: cos_t = sqrt(1 - s2 mu^2) (nu > 256) or g = sqrt(nu^2 - s2).
    let rad = Dw::select(big_nu, one, nu2).add(s2.mul(Dw::select(big_nu, mu.sq(), one)).neg());
    let cd = Dw::exact(c);
    let p = Dw::select(big_nu, mu, one).mul(cd);
    let x = Dw::select(big_nu, nu_c, nu2.mul(cd));
    (p, x, rad, big_nu)
}

/// Exact unpolarized Fresnel reflectance of a dielectric, F = (Rs + Rp) / 2 from
/// [`dielectric_polarized`] (same conventions and domain: a negative cosine means light from
/// the other side, relative index 1 / eta; total internal reflection gives 1; eta = 1 gives
/// 0; NaN and eta outside (0, MAX] give NaN). Within 1.4 ulps of the correctly rounded
/// value (every lane type; max 1.24 found by the oracle's deep search over the whole domain)
/// where a 1-ulp change of the cosine moves F by at most 8 ulps; near the critical cosine the
/// raw error stays below what one rounding of the cosine explains (raw <= kappa / 2 - 2.7 in
/// f32, kappa / 2 - 2.6 in f64; module docs, "Accuracy").
#[inline]
#[must_use]
pub fn dielectric<T: Real>(cos_theta_i: T, eta: T) -> T {
    let (rs, rp) = dielectric_polarized(cos_theta_i, eta);
    T::HALF * (rs + rp)
}

/// Exact unpolarized Fresnel reflectance of a dielectric in working precision, the fast
/// companion of [`dielectric`]: the same F = (Rs + Rp) / 2 (Born and Wolf, "Principles of
/// Optics", section 1.5), in the same cancellation-free arrangement as
/// [`dielectric_polarized`], every quantity rounded in the lane type's own precision (no double
/// words). With c = |cos_theta_i|, s2 = (1 - c)(1 + c):
///
/// - for eta in [1/256, 256]: from the positive side a = c, m = (eta - 1)(eta + 1); from the
///   other a = eta c, m = -(eta - 1)(eta + 1); g2 = a^2 + m (total internal reflection where
///   g2 < 0), g = sqrt(g2), r_perp = -m / (a (a + 2 g) + g2) and
///   r_par = (eta^2 - 1) W f / (x (x + 2 y) + y^2) with (x, y, f) = (eta^2 a, g, 1) resp.
///   (eta^2 g, a, eta^2) and W = (eta^2 + 1) c^2 - f;
/// - beyond (where eta^4 would leave the range), the textbook ratios of the relative index nu
///   (eta from the positive side, 1 / eta from the other): for nu > 256,
///   r_perp = (c / nu - cos_t) / (c / nu + cos_t) and r_par = (nu c - cos_t) / (nu c + cos_t)
///   with cos_t = sqrt(1 - s2 / nu^2) and nu c capped at 2^32 (f32) / 2^61 (f64), where
///   r_par^2 rounds to 1; for nu < 1/256 (raised to 2^-40 / 2^-100 at least: below, only c = 1
///   escapes total reflection, where F rounds to 1 either way), g = sqrt(nu^2 - s2),
///   r_perp = (c - g) / (c + g), r_par = (nu^2 c - g) / (nu^2 c + g).
///
/// m is formed from `eta` as given, so eta = 1 gives 0 at every angle and eta near 1 keeps its
/// relative accuracy. Cost: one square root and two divisions per cosine on the moderate path
/// (a few more on the extreme one, which runs on every lane beside it), about 45 operations,
/// against about 550 and seven divisions for [`dielectric`].
///
/// Domain, edges and bad input exactly as [`dielectric`]: eta in (0, MAX], finite;
/// cos_theta_i in [-1, 1] (a negative cosine means light from the other side; |cos| above 1
/// clamped to 1). Total internal reflection and c = 0 give 1 (eta != 1), eta = 1 gives 0, and
/// every such input gives F in [0, 1]. NaN in either input, eta <= 0 and eta = +inf give NaN.
///
/// Accuracy: max error against [`dielectric`] over cosines of both signs from 0 through 1e-7
/// to 1, eta on a log grid from 1e-3 to 1e6 plus values near 1, near the moderate path's ends
/// and at the ends of the range (subnormal to MAX), ULP where a 1-ULP change of the cosine
/// moves F by at most 8 ULP, plus 2.4 x 10^7 random points (cosines uniform and near 0 and
/// 1, eta log-uniform over [1e-3, 1e3] and near 1): 13 ULP, relative 1.3e-6 (f32); 14 ULP,
/// relative 2.4e-15 (f64); elsewhere (the critical and Brewster's angles) within 1.75 (f32) /
/// 1.83 (f64) of what a 1-ULP change of the cosine moves F by. The same on f32x8 and f64x4,
/// whose lanes equal the scalar results bit for bit (`cargo test --all-features --test kernels
/// fast_variants::dielectric -- --nocapture`, default x86-64 build).
#[inline]
#[must_use]
pub fn dielectric_fast<T: Real>(cos_theta_i: T, eta: T) -> T {
    let inside = cos_theta_i.simd_lt(T::ZERO);
    let c = cos_theta_i.abs().min(T::ONE);
    let s2 = (T::ONE - c) * (T::ONE + c);
    let cc = c * c;
    let two = T::TWO;

    // The moderate path, on eta clamped into its range (the extreme lanes discard it).
    let n = eta.clamp(T::splat(1.0 / ETA_RATIO_FORM), T::splat(ETA_RATIO_FORM));
    let n2 = n * n;
    let n2m1 = (n - T::ONE) * (n + T::ONE);
    let a = T::select(inside, n * c, c);
    let a2 = a * a;
    let m = T::select(inside, -n2m1, n2m1);
    // g2 = a^2 + m. Where total internal reflection is possible (eta < 1 from the positive
    // side, eta > 1 from the other) m < 0 and the sum cancels: there the other form
    // eta^2 - s2 (positive side) resp. 1 - eta^2 s2 (other side) is taken where its larger
    // term is the smaller of the two forms' (near c = 1 with eta far from 1, where c^2 + m
    // would lose c^2's digits); elsewhere both terms are non-negative.
    let lt1 = n.simd_lt(T::ONE);
    let gt1 = n.simd_gt(T::ONE);
    let other_form = T::select(inside, (-n2).mul_add(s2, T::ONE), n2 - s2);
    let other_max = T::select(inside, T::ONE, n2.max(s2));
    let cancels = (inside & gt1) | (!inside & lt1);
    let use_other = cancels & a2.max(-m).simd_gt(other_max);
    let g2 = T::select(use_other, other_form, a2 + m);
    let g = g2.max(T::ZERO).sqrt();
    let d_perp = a.mul_add(two.mul_add(g, a), g2);
    let f = T::select(inside, n2, T::ONE);
    // W = (eta^2 + 1) c^2 - f as eta^2 c^2 - s2 resp. c^2 - eta^2 s2: its one cancellation
    // is Brewster's zero (adding c^2 + s2 = 1 first would cancel near c = 0 and c = 1 too).
    let w = T::select(inside, (-n2).mul_add(s2, cc), n2.mul_add(cc, -s2));
    let x = n2 * T::select(inside, g, a);
    let y = T::select(inside, a, g);
    let y2 = T::select(inside, a2, g2);
    let d_par = x.mul_add(two.mul_add(y, x), y2);
    let tir_moderate = g2.simd_lt(T::ZERO);

    // The extreme path: nu = eta (positive side) or 1 / eta (other side).
    let (cap, nu_lo) = if single::<T>() {
        (pow2(32), pow2(-40))
    } else {
        (pow2(61), pow2(-100))
    };
    let eta_gt1 = eta.simd_gt(T::ONE);
    let big_nu = (inside & !eta_gt1) | (!inside & eta_gt1);
    // mu = 1 / nu where nu > 256: 1 / eta from the positive side, eta from the other.
    let mu = T::select(inside, eta, eta.recip());
    let nu_c = T::select(inside, c / eta, eta * c).min(T::splat(cap));
    let nu = T::select(inside, eta.recip(), eta).max(T::splat(nu_lo));
    let nu2 = nu * nu;
    let rad = T::select(big_nu, (s2 * mu).mul_add(-mu, T::ONE), nu2 - s2);
    let root = rad.max(T::ZERO).sqrt();
    let p = T::select(big_nu, c * mu, c);
    let q = T::select(big_nu, nu_c, nu2 * c);
    let tir_extreme = !big_nu & rad.simd_lt(T::ZERO);

    let extreme =
        eta.simd_gt(T::splat(ETA_RATIO_FORM)) | eta.simd_lt(T::splat(1.0 / ETA_RATIO_FORM));
    let num_perp = T::select(extreme, p - root, -m);
    let den_perp = T::select(extreme, p + root, d_perp);
    let num_par = T::select(extreme, q - root, n2m1 * w * f);
    let den_par = T::select(extreme, q + root, d_par);
    // A zero denominator comes with a zero numerator (eta = 1 at c = 0, or a cosine whose
    // square underflows): the ratio is 0 there.
    let ratio = |num: T, den: T| {
        let zero = den.simd_eq(T::ZERO);
        T::select(zero, T::ZERO, num / T::select(zero, T::ONE, den))
    };
    let (r_perp, r_par) = (ratio(num_perp, den_perp), ratio(num_par, den_par));
    let tir = (extreme & tir_extreme) | (!extreme & tir_moderate);
    let reflectance = (T::HALF * (r_perp * r_perp + r_par * r_par)).min(T::ONE);
    let value = T::select(tir, T::ONE, reflectance);
    nan_unless(valid_eta(eta) & !cos_theta_i.is_nan(), value)
}

/// Exact unpolarized Fresnel reflectance of a conductor with complex relative IOR
/// N = eta + i k (Born and Wolf, section 14.2; the complex form of [`dielectric_polarized`]):
/// with s = sqrt(N^2 - sin^2 theta_i) complex (= N cos_t), r_perp = (c - s) / (c + s),
/// r_par = (N^2 c - s) / (N^2 c + s), F = (|r_perp|^2 + |r_par|^2) / 2.
///
/// Evaluated without the textbook form's cancellation (c - s and N^2 c - s for N near 1) or
/// overflow (|N|^8 for large k): with u = N^2 - 1 and s2 = (1 - c)(1 + c) = sin^2 theta_i,
/// r_perp = -u / (c + s)^2, and r_par = -r_perp (c s - s2) / (c s + s2) (from c^2 + s2 = 1
/// and s^2 + s2 = N^2), so that
///
/// F = |r_perp|^2 A / (A + B), |r_perp|^2 = |u|^2 / |c + s|^4,
/// A = c^2 |s|^2 + s2^2, B = 2 c s2 Re(s)
///
/// (|c s -+ s2|^2 = A -+ B). u, s^2 and s (one Newton step on the exactly formed residual
/// z - s0^2) and the moduli |u|^2 and |c + s|^2 are carried in double words (Dekker products
/// and Knuth sums, without FMA, so every target and lane type rounds alike): the fourth power
/// would otherwise quadruple the roundings of s. A and B are sums of non-negative terms whose
/// roundings reach F damped by B / (A + B) <= 1/2, and no subtraction is left that could
/// cancel, so F near 0 (N near 1) and near 1 (grazing light, large k) keep full relative
/// accuracy. |u|^2 / |c + s|^4 is formed after scaling c + s by the power of two nearest the
/// reciprocal of its larger component (and u by its square; |u| <= |c + s|^2), so that neither
/// overflows nor underflows. Where max(eta, k) exceeds 2^16, N is first divided by
/// max(eta, k) (and A, B by max(c, 1 / max(eta, k))^2); where it is below T::EPSILON^2
/// (f32: 2^-46, f64: 2^-104), N is scaled up to that magnitude, which moves F (within 8 |N|
/// of 1 there) by less than a quarter of an ulp of 1. Where eta = 1 exactly and k is below
/// 2^-40 (f32) / 2^-400 (f64), u = 2 i k - k^2 and c^2 are multiplied by the power of four L
/// nearest 1 / max(2 k, c^2) (and c by sqrt(L)), which leaves |r_perp|^2 unchanged and keeps
/// u, c^2 and their double words' low parts out of the subnormal range (without it, 6.1 ulps
/// at c = 2.2e-23, k = 8e-42 in f32).
///
/// Domain: eta in (0, MAX], k in [0, MAX], both finite: every such pair gives a finite F in
/// [0, 1]; cos_theta_i clamped to [0, 1] (a negative cosine counts as grazing). Edges: k = 0
/// equals [`dielectric`] for the same eta (to rounding, total internal reflection included);
/// c = 0 gives 1; eta = 1, k = 0 gives 0. NaN in any input, eta <= 0, k < 0 and infinite
/// eta or k give NaN.
///
/// On `f32` and `f32x8` all of the above is evaluated in f64 instead (`f32x8` as two `f64x4`
/// halves, lane for lane the scalar operations) and rounded to f32 once: there the inputs'
/// squares are exact and no product of f32 inputs leaves f64's normal range, so neither
/// double words nor scalings are needed. The arrangement is that of [`conductor_fast`]:
/// u = N^2 - 1 from (eta - 1)(eta + 1) - k^2, z = s^2 from whichever form adds the smaller
/// terms, |s|^2 = |z|, and 2 Re(s) = h / w with (h, w) = (sqrt(2) t, 1) where Re z >= 0 and
/// (sqrt(2) |Im z|, t) otherwise, t = sqrt(|z| + |Re z|), so that
/// F = |u|^2 A w^3 / ((|c + s|^2 w)^2 (A + B) w) with both sums multiplied by w: two square
/// roots and one division, every rounding 2^-53 (w and h are scaled by 2^-100 where
/// |z| > 2^200, which keeps |N|^9 finite). F below f32's smallest normal number (N near 1)
/// is rounded from normal numbers, as `beckmann::d`'s is, so no instruction meets a
/// subnormal number.
///
/// Accuracy (module docs, "Accuracy"): within 0.7 ulps (f32, f32x8) / 3.9 ulps (f64, f64x4)
/// of the correctly rounded value where a 1-ulp change of the cosine moves it by at most 8
/// ulps (max 0.50 / 3.69 found by the oracle's deep search over the whole domain; 3.10 for
/// f64 with FMA); elsewhere (k near 0 at the critical angle) the raw error stays below what
/// one rounding of the cosine explains (raw <= kappa / 2 - 3.3 in f32, kappa / 2 - 0.7 in
/// f64). Cost on `f64`, `f64x4`: about 420 flops, 290 more than the same ratios in working
/// precision (fifteen Dekker squares or products, a dozen double-word sums, one double-word
/// quotient); on `f32`, `f32x8`: about 40 f64 operations, two of them square roots and one
/// a division.
#[inline]
#[must_use]
pub fn conductor<T: Real>(cos_theta_i: T, eta: T, k: T) -> T {
    let c = cos_theta_i.saturate();
    let f = T::via_f64([c, eta, k], Conductor, crate::real::sealed::Token::NEW);
    let ok = valid_eta(eta) & k.simd_ge(T::ZERO) & k.simd_le(T::MAX) & !cos_theta_i.is_nan();
    nan_unless(ok, f)
}

/// The F of [`conductor`] for the saturated cosine and eta, k as given (an invalid pair or a
/// NaN cosine gives an unspecified value, which the caller replaces by NaN): double words in
/// f64 and f64x4, one f64 evaluation rounded once in f32 and f32x8.
#[derive(Clone, Copy)]
pub(crate) struct Conductor;

impl crate::real::sealed::Widened<3> for Conductor {
    /// F of N near 1 falls below f32's smallest normal number (F = k^2 / 4 at c = 1, eta = 1).
    const TINY: bool = true;

    #[inline]
    fn native<T: Real>(self, [c, eta, k]: [T; 3]) -> T {
        let s2 = (T::ONE - c) * (T::ONE + c);
        let big = eta.max(k);
        let large = big.simd_gt(T::splat(CONDUCTOR_SCALE_HI));
        let tiny_bound = T::EPSILON * T::EPSILON;
        let tiny = big.simd_lt(tiny_bound);
        let safe_big = T::select(big.simd_gt(T::ZERO), big, T::ONE);
        // N / sigma with sigma = max(eta, k) (large), 1 (moderate) or max(eta, k) / 2^-46 (tiny);
        // m = 1 / sigma where large, else 1 (the tiny case keeps the unit scale).
        let up = tiny_bound / safe_big;
        let (re, im, m) = (
            T::select(large, eta / safe_big, T::select(tiny, eta * up, eta)),
            T::select(large, k / safe_big, T::select(tiny, k * up, k)),
            T::select(large, safe_big.recip(), T::ONE),
        );
        // Exact squares of the scaled inputs; u = N^2 - m^2 (= (N^2 - 1) / sigma^2) in double
        // words, so that N near 1 keeps every digit of the small u.
        let re2 = Dw::square(re);
        let im2 = Dw::square(im);
        let m2 = Dw::square(m);
        let cm = c * m;
        let cm2 = Dw::square(cm);
        let n2_re = re2.add(im2.neg());
        let u_re = n2_re.add(m2.neg());
        let u_im = Dw::product(T::TWO * re, im);
        // z = s^2 = N^2 - s2 m^2, as u + (c m)^2 or as N^2 - (m^2 - (c m)^2), whichever adds the
        // smaller terms (the first for N near 1, the second for small N near normal incidence,
        // where u + c^2 would cancel to nothing).
        let s2m2 = m2.add(cm2.neg());
        // eta = 1 exactly with k below 2^-40 (f32) / 2^-400 (f64): u = 2 i k - k^2 and (c m)^2
        // would reach the subnormal range (their double words' low parts long before), so u is
        // multiplied by L and c by sqrt(L), sqrt(L) the power of two nearest
        // 1 / sqrt(max(2 k, c^2)) (exact scalings; z and s scale by L and sqrt(L), |u|^2 / |c + s|^4
        // not at all, and the parallel factor below divides them out again).
        let small_u = re.simd_eq(T::ONE)
            & m.simd_eq(T::ONE)
            & im.simd_lt(T::splat(if single::<T>() { pow2(-40) } else { pow2(-400) }));
        let sqrt_l = pow2_nearest(
            (T::TWO * im)
                .max(c * c)
                .sqrt()
                .recip()
                .min(T::splat(if single::<T>() { pow2(80) } else { pow2(600) })),
        );
        let sqrt_l = T::select(small_u, sqrt_l, T::ONE);
        let k_l = im * sqrt_l;
        let u_re = Dw::select(small_u, Dw::square(k_l).neg(), u_re);
        let u_im = Dw::select(small_u, Dw::exact(T::TWO * k_l * sqrt_l), u_im);
        let c_l = c * sqrt_l;
        let cm = T::select(small_u, c_l, cm);
        let cm2 = Dw::select(small_u, Dw::square(c_l), cm2);
        let z_re = Dw::select(
            small_u | (u_re.hi.abs() + cm2.hi).simd_le(n2_re.hi.abs() + s2m2.hi),
            u_re.add(cm2),
            n2_re.add(s2m2.neg()),
        );
        // s = sqrt(z): the working-precision root s0, then one Newton step s0 + (z - s0^2) / (2 s0)
        // on the residual, which leaves s to about twice the working precision. The residual is
        // about eps |z| (eps the unit roundoff) and needs only relative accuracy eps: its high
        // parts cancel exactly (Sterbenz) once Re(s0^2)'s own rounding is kept by a Knuth sum.
        let (s0_re, s0_im) = complex_sqrt(z_re.hi, u_im.hi);
        let (sr2, si2) = (Dw::square(s0_re), Dw::square(s0_im));
        let (d, de) = two_sum(sr2.hi, -si2.hi);
        let r_re = ((z_re.hi - d) - de) + ((z_re.lo - sr2.lo) + si2.lo);
        let w = Dw::product(T::TWO * s0_re, s0_im);
        let r_im = (u_im.hi - w.hi) + (u_im.lo - w.lo);
        let s0_abs2 = s0_re.mul_add(s0_re, s0_im * s0_im);
        let has_root = s0_abs2.simd_gt(T::ZERO);
        let den = T::TWO * T::select(has_root, s0_abs2, T::ONE);
        let d_re = T::select(has_root, r_re.mul_add(s0_re, r_im * s0_im) / den, T::ZERO);
        let d_im = T::select(
            has_root,
            r_im.mul_add(s0_re, -(r_re * s0_im)) / den,
            T::ZERO,
        );
        // p = c + s (scaled: c m + s) in double words.
        let (h, l) = two_sum(cm, s0_re);
        let (h, e) = two_sum(h, d_re);
        let p_re = Dw::norm(h, e + l);
        let (h, e) = two_sum(s0_im, d_im);
        let p_im = Dw { hi: h, lo: e };
        // |r_perp|^2 = |u|^2 / |p|^4, after scaling p by the power of two lambda nearest
        // 1 / max(|Re p|, |Im p|) and u by lambda^2 (exact; |u| <= |p|^2, since
        // u = (s - c)(s + c) and Re s >= 0), so that neither fourth power overflows nor underflows.
        let pmax = p_re.hi.abs().max(p_im.hi.abs());
        let lambda = pow2_nearest(pmax).max(T::MIN_POSITIVE).recip();
        let p_re = p_re.scale(lambda);
        let p_im = p_im.scale(lambda);
        let u_re = u_re.scale(lambda).scale(lambda);
        let u_im = u_im.scale(lambda).scale(lambda);
        let u_abs2 = Dw::abs2(u_re, u_im);
        let p_abs2 = Dw::abs2(p_re, p_im);
        let rs = div_or_zero(u_abs2, p_abs2.sq());
        // |r_par|^2 = |r_perp|^2 |c s - s2|^2 / |c s + s2|^2 (r_par = -r_perp (c s - s2) /
        // (c s + s2), from c^2 + s2 = 1 and s^2 + s2 = N^2), so that
        // F = |r_perp|^2 (1 + rho) / 2 = |r_perp|^2 A / (A + B) with A = c^2 |s|^2 + s2^2 and
        // B = 2 c s2 Re(s) (|c s +- s2|^2 = A +- B): two positive sums, whose rounding errors
        // reach F damped by B / (A + B) <= 1/2. In scaled units divided by tau = max(c, m), so
        // that grazing light on a huge N neither underflows nor divides 0 by 0.
        let tau = c.max(m);
        let (ch, s2mh) = (c / tau, s2 * (m / tau));
        let inv_l = sqrt_l.recip();
        let a = (ch * ch).mul_add(s0_abs2 * inv_l * inv_l, s2mh * s2mh);
        let b = T::TWO * ch * s2mh * (s0_re * inv_l);
        let ab = a + b;
        // A > 0 for every valid input (s2 = 1 where c = 0); the guard keeps 0 / 0 out regardless.
        let pos = ab.simd_gt(T::ZERO);
        let q = T::select(pos, a / T::select(pos, ab, T::ONE), T::ONE);
        // |r_perp|^2 q with one rounding (the product's error recovered exactly).
        rs.mul(Dw::exact(q)).value().min(T::ONE)
    }

    #[inline]
    fn wide<W: Real<Scalar = f64>>(self, [c, eta, k]: [W; 3]) -> W {
        // z = N^2 - s2 as u + c^2 or as N^2 - s2, whichever adds the smaller terms; the rest
        // in `ConductorWide::ratio`.
        let p = ConductorWide::new(eta, k);
        let s2 = (W::ONE - c) * (W::ONE + c);
        let c2 = c * c;
        let z_re = W::select(c2.simd_le(p.n2_re), c.mul_add(c, p.u_re), p.n2_re - s2);
        let a = z_re.abs();
        let norm = a.mul_add(a, p.b * p.b).sqrt();
        p.ratio(c, z_re, norm, (norm + a).sqrt())
    }
}

/// 2^-100 where |z| > 2^200 (|N| above about 2^100), else 1: the common factor of h and w in
/// [`ConductorWide`]'s 2 Re(s) = h / w, which keeps w^3 and the ratio's denominator (up to
/// |N|^9) below 2^900.
#[inline]
fn big_root_scale<W: crate::widen::F64Ops>(norm: W) -> W {
    W::select(
        norm.gt(W::splat(1.606_938_044_258_990_3e60)),
        W::splat(7.888_609_052_210_118e-31),
        W::splat(1.0),
    )
}

/// The part of [`Conductor`]'s f64 evaluation that depends on eta and k alone (computed once
/// in a loop with fixed parameters), and two tails: from the cosine and the root s = sqrt(z),
/// z = N^2 - sin^2 theta_i ([`Conductor`]), and from wo.s and |s|^2 of the unnormalized
/// half vector, without the cosine (`cook_torrance::ggx_conductor_local`).
#[derive(Clone, Copy)]
pub(crate) struct ConductorWide<W> {
    /// Re(N^2) = eta^2 - k^2.
    pub(crate) n2_re: W,
    /// Re(N^2) - 1 = (eta - 1)(eta + 1) - k^2 (no cancellation for N near 1).
    pub(crate) u_re: W,
    /// |Im(N^2)| = 2 eta k.
    pub(crate) b: W,
    /// |N^2 - 1|^2.
    u_abs2: W,
    /// Re(N^2) - 1 = eta^2 - k^2 - 1 as an unevaluated sum u_hi + u_lo (to 2^-106 relative):
    /// u_re loses Re(N^2) entirely where |N| is below about 2^-27 (`of_projection`).
    #[cfg_attr(not(all(feature = "ggx", feature = "cook-torrance")), allow(dead_code))]
    u_hi: W,
    #[cfg_attr(not(all(feature = "ggx", feature = "cook-torrance")), allow(dead_code))]
    u_lo: W,
}

impl<W: crate::widen::F64Ops> ConductorWide<W> {
    #[inline]
    pub(crate) fn new(eta: W, k: W) -> Self {
        let one = W::splat(1.0);
        let k2 = k * k;
        let n2_re = eta.mul_add(eta, -k2);
        let u_re = (eta - one).mul_add(eta + one, -k2);
        let u_im = W::splat(2.0) * eta * k;
        // eta^2 and k^2 are exact for f32 inputs; two error-free sums (Knuth's TwoSum) give
        // eta^2 - k^2 - 1 = u_hi + e1 + e2 exactly.
        let two_sum = |a: W, b: W| {
            let s = a + b;
            let bv = s - a;
            (s, (a - (s - bv)) + (b - bv))
        };
        let (s1, e1) = two_sum(eta * eta, -k2);
        let (u_hi, e2) = two_sum(s1, -one);
        let u_lo = e1 + e2;
        Self {
            n2_re,
            u_re,
            b: u_im.abs(),
            u_abs2: u_re.mul_add(u_re, u_im * u_im),
            u_hi,
            u_lo,
        }
    }

    /// F at the cosine c = x / sqrt(y) (saturated to [0, 1]) without forming c: from x = wo.s
    /// and y = |s|^2 of the unnormalized half vector s = wo + wi (`cook_torrance`'s exact rough
    /// conductor), as F = num / (p^2 q) with (num, p, q) returned, all positive, so that the
    /// caller can fold the one division into its own.
    #[cfg(all(feature = "ggx", feature = "cook-torrance"))]
    #[inline]
    pub(crate) fn of_projection(self, x: W, y: W) -> (W, W, W) {
        // F depends on c alone, and c on x / sqrt(y): (x, y) may be scaled by (r, r^2) for any
        // r > 0. r = the bit-pattern seed of 1 / sqrt(y) (within 3.5 %) puts y within 7 % of
        // 1, so that every magnitude below is that of `ratio` with c in [0, 1]; its two
        // roundings move c by 2^-52 at most. Saturation: x >= 0 and x^2 <= y (y := max(y,
        // x^2), which is c = 1 where c would exceed 1).
        let x = x.max(W::splat(0.0));
        let r = y.rsqrt_bits();
        let (x, y) = (x * r, y * (r * r));
        let x2 = x * x;
        let y = y.max(x2);
        // In units of y: s2 y = y - x^2 (exact: Sterbenz), z y = u y + x^2 with Re(u) the
        // exact sum u_hi + u_lo (each multiply-add rounds its own result once, so nothing
        // cancels). The rounding of y and that of x^2 (2^-53 of y each) are those of c^2
        // itself, which `ratio`'s second form N^2 - s2 cannot undo either: c is a rounded
        // quotient there.
        let s2 = y - x2;
        let z_re = self.u_lo.mul_add(y, self.u_hi.mul_add(y, x2));
        // |Im z y|^2 = b^2 y^2 and lambda |Im z y| = (lambda b) y from factors of eta and k
        // alone: lambda = 2^-100 where |u|^2 > 2^400 (|N| above about 2^100), else 1, chosen
        // from |u| rather than from |z y| (within 8 % of |u| there, y being within 7 % of 1)
        // so that a loop with fixed eta and k computes it once.
        let lambda = W::select(
            self.u_abs2.gt(W::splat(2.582_249_878_086_908_6e120)),
            W::splat(7.888_609_052_210_118e-31),
            W::splat(1.0),
        );
        let yy = y * y;
        let norm = z_re.mul_add(z_re, (self.b * self.b) * yy).sqrt();
        let t = (norm + z_re.abs()).sqrt();
        // As `ratio` with c^2 |s|^2 -> x^2 |z y|, s2 -> s2 y, c 2 Re(s) -> x h / w (the powers
        // of y cancel between 2 Re(s) = h / w and c = x / sqrt(y)): the terms of A, A + B and
        // |c + s|^2 gain the factors y^2, y^2 and y, so F = |u|^2 y^2 A w^3 / (p^2 q) with
        // p = |c + s|^2 y w and q = (A + B) y^2 w. Both p and q are linear in t, their
        // coefficients known before the second root: where Re z >= 0 (h = sqrt(2) t, w = 1)
        // p = (x^2 + |z y|) + sqrt(2) x t, q = A y^2 + sqrt(2) x s2 t; elsewhere (h = sqrt(2)
        // |Im z y|, w = t) p = (x^2 + |z y|) t + sqrt(2) x |Im z y| and q = A y^2 t + sqrt(2)
        // x s2 |Im z y|, there with lambda t and lambda |Im z y| in place of t and |Im z y|,
        // which keeps w^3 and p^2 q (up to |N|^9) below 2^900.
        let pos = z_re.ge(W::splat(0.0));
        let xr = W::splat(core::f64::consts::SQRT_2) * x;
        let e = x2 + norm;
        let a_par = x2.mul_add(norm, s2 * s2);
        let xs = xr * s2;
        let im = (lambda * self.b) * y;
        let tl = t * lambda;
        let tt = W::select(pos, t, tl);
        let p = W::select(pos, xr, e).mul_add(tt, W::select(pos, e, xr * im));
        let q = W::select(pos, xs, a_par).mul_add(tt, W::select(pos, a_par, xs * im));
        let w3 = W::select(pos, W::splat(1.0), tl * tl * tl);
        let num = (self.u_abs2 * yy) * (a_par * w3);
        // At c = 0 the ratio is 1 only to rounding: 1, or 0 without an interface (N = 1).
        let no_interface = self.u_abs2.eq(W::splat(0.0));
        let grazing = W::select(no_interface, W::splat(0.0), W::splat(1.0));
        let inside = x.gt(W::splat(0.0));
        (
            W::select(inside, num, grazing),
            W::select(inside, p, W::splat(1.0)),
            W::select(inside, q, W::splat(1.0)),
        )
    }
}

impl<W: Real<Scalar = f64>> ConductorWide<W> {
    /// F from the cosine c in [0, 1], Re z (its sign only), |z| and t = sqrt(|z| + |Re z|).
    #[inline]
    pub(crate) fn ratio(self, c: W, z_re: W, norm: W, t: W) -> W {
        // The arrangement of `conductor_fast` without its scalings: f32 inputs, between 2^-149
        // and 2^128, keep every product below (squares, |u|^2 ~ |N|^4, |c + s|^4 (A + B)
        // ~ |N|^6 c^2) inside f64's normal range, so no power of two is needed. The squares of
        // the inputs are exact, (eta - 1)(eta + 1) and 1 -+ c are exact factors, and every
        // other step rounds once by 2^-53 with no cancellation left (sums of non-negative
        // terms; z = s^2 from whichever form adds the smaller terms; 2 Re(s) without the
        // difference |z| - |Re z| where Re z < 0), so F is within a few dozen units of 2^-53
        // of itself before its one rounding to f32, except near the critical angle of a
        // dielectric-like N, where one rounding of the cosine itself moves F by far more.
        //
        // s = sqrt(z), principal root (Press et al., "Numerical Recipes", section 5.5):
        // |s|^2 = |z|, t = sqrt(|z| + |Re z|) = sqrt(2) sqrt((|z| + |Re z|) / 2), and
        // 2 Re(s) = sqrt(2) t where Re z >= 0, sqrt(2) |Im z| / t otherwise. Written as
        // h / w with (h, w) = (sqrt(2) t, 1) or (sqrt(2) |Im z|, t), so that |c + s|^2 =
        // c (c + 2 Re s) + |s|^2 and A + B = A + c s2 2 Re(s) are multiplied by w and the
        // one division left is the final one: F = |u|^2 A w^3 / ((|c + s|^2 w)^2 (A + B) w).
        let s2 = (W::ONE - c) * (W::ONE + c);
        let c2 = c * c;
        let root2 = W::splat(core::f64::consts::SQRT_2);
        let pos = z_re.simd_ge(W::ZERO);
        // h / w is unchanged by a common factor: 2^-100 where |z| > 2^200 (|N| above about
        // 2^100) keeps the numerator's and the denominator's w^3 (up to |N|^9) below 2^900.
        let lambda = big_root_scale(norm);
        let h = root2 * W::select(pos, t, self.b * lambda);
        let w = W::select(pos, W::ONE, t * lambda);
        let pw = c.mul_add(c.mul_add(w, h), norm * w);
        let a_par = c2.mul_add(norm, s2 * s2);
        let abw = (c * s2).mul_add(h, a_par * w);
        let ratio = (self.u_abs2 * a_par * (w * w * w)) / (pw * pw * abw);
        // At c = 0 the ratio is 1 only to rounding: 1, or 0 without an interface (N = 1).
        let no_interface = self.u_abs2.simd_eq(W::ZERO);
        let grazing = W::select(no_interface, W::ZERO, W::ONE);
        W::select(c.simd_gt(W::ZERO), ratio.min(W::ONE), grazing)
    }
}

/// Exact unpolarized conductor Fresnel in working precision, the fast companion of
/// [`conductor`]: the same F = (|r_perp|^2 + |r_par|^2) / 2 for the complex relative IOR
/// N = eta + i k (Born and Wolf, section 14.2), in the same cancellation-free arrangement,
/// with u = N^2 - 1, s = sqrt(N^2 - sin^2 theta_i) (principal complex root), s2 = (1 - c)(1 + c):
///
/// F = |u|^2 A / (|c + s|^4 (A + B)), A = c^2 |s|^2 + s2^2, B = 2 c s2 Re(s),
/// |c + s|^2 = c (c + 2 Re(s)) + |s|^2, |s|^2 = |N^2 - s2|
///
/// (r_perp = -u / (c + s)^2 as in Lagarde 2013, "Memo on Fresnel equations", and pbrt-v4's
/// `FrComplex`; |r_par|^2 = |r_perp|^2 (A - B) / (A + B); both folded into one ratio), every
/// quantity rounded in working precision: no double words, no Newton step on s. Only |s|^2
/// and Re(s) are needed, and every sum above adds non-negative terms; Re(N^2) - 1 is
/// (eta - 1)(eta + 1) - k^2, so N near 1 keeps its digits. Cost per cosine: two square roots
/// (|s|^2, then Re(s)), two divisions (Re(s) where Re(N^2) < s2, taken alongside the second
/// root, and the final ratio) and about 40 other operations, once the part that depends on
/// eta and k alone (one more division, about 60 operations) is computed, which a loop over
/// cosines with fixed eta and k can do once.
///
/// Scalings, chosen from eta and k alone: N is divided by sigma = max(eta, k) above 2^16 and
/// raised to T::EPSILON^2 below it, as in [`conductor`], A and B then being formed from the
/// scaled s with rho = c sigma in place of c (capped at T::EPSILON^-2, where A / (A + B)
/// already rounds to 1). The others are by powers of two (they round nothing): N^2 - s2
/// before its modulus is squared, and, where |u| < 2^-40 (f32) / 2^-400 (f64), i.e. eta = 1
/// and k tiny, |u| and |c + s|^2 (then between |u| and 4) before they are squared. No square
/// overflows, and none underflows while k is above 2^-124 (f32) / 2^-1017 (f64).
///
/// Domain, edges and bad input exactly as [`conductor`]: eta in (0, MAX], k in [0, MAX], both
/// finite, give a finite F in [0, 1]; cos_theta_i clamped to [0, 1]; c = 0 gives 1 (set
/// there: the ratio is |u|^2 / |s|^4 = 1 only to rounding); eta = 1, k = 0 gives 0 (u = 0), at
/// c = 0 too. NaN in any input, eta <= 0, k < 0 and infinite eta or k give NaN.
///
/// Accuracy: max error against [`conductor`] over cosines from 0 through 1e-7 to 1, eta and k
/// on log grids from 1e-3 to 1e6 plus eta near 1, tiny and huge eta and k (up to 3e38), and
/// eta = 1 with k from 1e-36 to 1e-12 at cosines down to 1e-30, 533 000 points per type:
/// 10 ULP, relative 6.0e-7 (f32); 12 ULP, relative 1.3e-15 (f64), where a 1-ULP change of the
/// cosine moves F by at most 8 ULP; elsewhere (k = 0 near the critical angle) within 0.67
/// (f32) / 1.0 (f64) of that change. The same on f32x8 and f64x4, whose lanes equal the
/// scalar results bit for bit (`cargo test --all-features --test kernels fast_variants:: --
/// --nocapture`, default x86-64 build). Not accurate (but finite, in [0, 1]) for eta = 1
/// exactly with 0 < k < 2^-124 (f32) / 2^-1017 (f64) at cosines up to about a hundred times
/// sqrt(k), where |Im(N^2 - s2)| = 2 k is raised to 2^-123 / 2^-1016: there F = k^2 / (4 c^4)
/// comes out wrong by up to 100% of itself (an absolute error up to 0.016 at c = 2 sqrt(k),
/// falling as c^-4).
#[inline]
#[must_use]
pub fn conductor_fast<T: Real>(cos_theta_i: T, eta: T, k: T) -> T {
    let n = ConductorFast::new(eta, k);
    let c = cos_theta_i.saturate();
    let cm = c * n.m;
    let s2 = (T::ONE - c) * (T::ONE + c);
    // z = s^2 = N^2 - s2 m^2 = u + (c m)^2, from whichever form adds the smaller terms
    // (|u_re| + (c m)^2 against |Re N^2| + s2 m^2): u + (c m)^2 where (c m)^2 <= Re N^2
    // (N near 1 at any angle), else Re N^2 - s2 m^2 (small or mostly imaginary N, where
    // u + (c m)^2 would cancel).
    let z_re = T::select(
        (cm * cm).simd_le(n.n2_re),
        cm.mul_add(cm, n.u_re),
        s2.mul_add(n.neg_m2, n.n2_re),
    );
    n.at(s2, z_re * n.z_up, c)
}

/// The part of [`conductor_fast`] that depends on eta and k alone (a loop over cosines with
/// fixed eta and k computes it once), and the rest as [`ConductorFast::at`], which
/// `cook_torrance::ggx_conductor_local_fast` calls with the squared cosine (wo.s)^2 / |s|^2
/// of the unnormalized half vector s.
#[derive(Clone, Copy)]
pub(crate) struct ConductorFast<T: Real> {
    ok: T::Mask,
    /// 1 / sigma where N is scaled down, else 1.
    pub(crate) m: T,
    sigma: T,
    neg_m2: T,
    /// Re(N^2) in units of m^2.
    n2_re: T,
    /// Re(N^2 - m^2) in units of m^2.
    pub(crate) u_re: T,
    ul_abs2: T,
    ml: T,
    zl_down: T,
    /// 2^(2j - 1), the power of two that scales z before its modulus is squared.
    pub(crate) z_up: T,
    z_down: T,
    b2: T,
    g_num: T,
    g_pos: T,
    tiny_bound: T,
    at_grazing: T,
}

impl<T: Real> ConductorFast<T> {
    /// The quantities of [`conductor_fast`] that depend on eta and k alone.
    #[inline]
    pub(crate) fn new(eta: T, k: T) -> Self {
        // Valid: eta > 0 and k >= 0 (both false for NaN), max(eta, k) finite.
        let big = eta.max(k);
        let ok = eta.simd_gt(T::ZERO) & k.simd_ge(T::ZERO) & big.simd_le(T::MAX);
        // The scaling of `conductor`: N / sigma, m = 1 / sigma, one quotient: 1 / max(eta, k)
        // above 2^16, EPSILON^2 / max(eta, k) below EPSILON^2 (finite for subnormal eta and k),
        // else 1. An invalid eta or k may make these infinite or NaN: F is NaN there regardless.
        let large = big.simd_gt(T::splat(CONDUCTOR_SCALE_HI));
        let tiny_bound = T::EPSILON * T::EPSILON;
        let tiny = big.simd_lt(tiny_bound);
        let n_scale = T::select(tiny, tiny_bound, T::ONE) / T::select(large | tiny, big, T::ONE);
        let (re, im) = (eta * n_scale, k * n_scale);
        let (m, sigma) = (
            T::select(large, n_scale, T::ONE),
            T::select(large, big, T::ONE),
        );
        let neg_m2 = -(m * m);
        let n2_re = re.mul_add(re, -(im * im));
        // u = N^2 - m^2 with (re - m)(re + m): no cancellation for eta near 1.
        let u_re = (re - m).mul_add(re + m, -(im * im));
        let u_im = T::TWO * re * im;
        // Two regimes, told apart by |u| alone, each with its own powers of two (exact scalings):
        // z = s^2 is scaled by 2^(2j - 1) before its modulus is squared, and u and |c + s|^2 by
        // `lift` before they are squared.
        // - |u| >= 2^-40 (f32) / 2^-400 (f64): |z| <= 2^34, so 2^(2j - 1) = 2^27 / 2^475 keeps
        //   every square finite (and parts down to 2^-90 / 2^-986 normal: smaller ones occur only
        //   near the critical angle, where |z| and Re s are negligible against c^2 and s2^2), and
        //   |c + s|^2 >= |u| (u = (s - c m)(s + c m), Re s >= 0) keeps |u|^2 and |c + s|^4 normal
        //   wherever F >= 2^-100 without a lift.
        // - |u| < 2^-40 / 2^-400 (eta = 1 exactly, k below 2^-41 / 2^-401): |z| >= |Im z| = 2k
        //   (about |u|), |z| <= 1 + |u| and |c + s|^2 lies within [|u|, 4 (1 + |u|)], so 2^63 /
        //   2^509 for z and a lift of 2^61 / 2^509 keep every square, and |c + s|^4 (A + B)
        //   (A + B <= 2), finite and normal for k down to 2^-124 / 2^-1017.
        let u_abs2 = u_re.mul_add(u_re, u_im * u_im);
        let (small_u2, [j_hi, j_lo], lift_exp) = if single::<T>() {
            (pow2(-80), [32, 14], 61)
        } else {
            (pow2(-800), [255, 238], 509)
        };
        let lifted = u_abs2.simd_lt(T::splat(small_u2));
        let by = |hi: f64, lo: f64| T::select(lifted, T::splat(hi), T::splat(lo));
        let z_up = by(pow2(2 * j_hi - 1), pow2(2 * j_lo - 1));
        let z_down = by(pow2(1 - 2 * j_hi), pow2(1 - 2 * j_lo));
        let t_down = by(pow2(-j_hi), pow2(-j_lo));
        let lift = by(pow2(lift_exp), 1.0);
        let (ul_re, ul_im) = (u_re * lift, u_im * lift);
        let ul_abs2 = ul_re.mul_add(ul_re, ul_im * ul_im);
        let (ml, zl_down) = (m * lift, z_down * lift);
        // In the second regime |Im z| is raised to 2^-123 / 2^-1016 (as if k were at least
        // 2^-124 / 2^-1017), which keeps |c + s|^4 normal, above 0, even for u = 0.
        let b = (u_im.abs() * z_up).max(by(pow2(if single::<T>() { -60 } else { -507 }), 0.0));
        let b2 = b * b;
        let g_num = (b + b) * t_down;
        let g_pos = T::TWO * t_down;
        // F at c = 0, where the ratio below is |u|^2 / |s|^4 = 1 only to rounding: 1, except for
        // eta = 1, k = 0 (no interface: 0 at every angle, as in `conductor`); NaN for invalid
        // eta or k.
        let no_interface = u_re.simd_eq(T::ZERO) & u_im.simd_eq(T::ZERO);
        let at_grazing = nan_unless(ok, T::select(no_interface, T::ZERO, T::ONE));
        Self {
            ok,
            m,
            sigma,
            neg_m2,
            n2_re,
            u_re,
            ul_abs2,
            ml,
            zl_down,
            z_up,
            z_down,
            b2,
            g_num,
            g_pos,
            tiny_bound,
            at_grazing,
        }
    }

    /// F at the cosine c (in [0, 1], or a few roundings above 1 with s2 as many below 0, as a
    /// caller's unsaturated c^2 = (wo.s)^2 / |s|^2 gives; or NaN), given s2 = 1 - c^2 and
    /// zu = Re(z) 2^(2j - 1),
    /// z = s^2 = N^2 - s2 m^2 (in units of m^2; `z_up` the power of two), each rounded as the
    /// caller chooses: only c m and c sigma read c itself, after the two roots, so that a
    /// caller with c^2 at hand starts the roots before c.
    #[inline]
    pub(crate) fn at(self, s2: T, zu: T, c: T) -> T {
        let Self {
            ok,
            m,
            sigma,
            ul_abs2,
            ml,
            zl_down,
            z_down,
            b2,
            g_num,
            g_pos,
            tiny_bound,
            at_grazing,
            ..
        } = self;
        // s = sqrt(z) (principal root; Press et al., "Numerical Recipes", section 5.5): with
        // a = |Re z|, b = |Im z| scaled by 2^(2j - 1) (above),
        // |s|^2 = |z| = norm 2^(1 - 2j), t = sqrt(norm + a) = sqrt((|z| + a) / 2) 2^j, and
        // 2 Re(s) = 2 t 2^-j for Re z >= 0, b / t = t 2^-j 2 b / (|z| + a) otherwise (no
        // cancellation): 2 Re(s) = g t, g taken alongside the second root rather than after it.
        let a = zu.abs();
        let norm = zu.mul_add(zu, b2).sqrt();
        let sum = norm + a;
        let t = sum.sqrt();
        // sum > 0 wherever Re z < 0: the quotient is only used where it is defined.
        let g = T::select(zu.simd_ge(T::ZERO), g_pos, g_num / sum);
        let s_abs2 = norm * z_down;
        // lift |p|^2 = lift |c m + s|^2 = lift (c m (c m + 2 Re s) + |s|^2).
        let pl_abs2 = (c * ml).mul_add(g.mul_add(t, c * m), norm * zl_down);
        // A = rho^2 |s|^2 + s2^2, B = rho s2 2 Re(s) with s in units of m (rho = c / m = c sigma;
        // where rho is capped, A / (A + B) rounds to 1 regardless).
        let rho = (c * sigma).min(tiny_bound.recip());
        // A = 0 only where s2 = 0 and s = 0 together (normal incidence on an index whose
        // N^2 - 1 rounds to -1, or wo = wi on the horizon): the floor turns the 0 / 0 below
        // into its limit A / (A + B) = 1 (B = 0 there too) and keeps A out of the subnormal
        // range; a normal A is unchanged.
        let a_par = (rho * rho).mul_add(s_abs2, s2 * s2).max(T::MIN_POSITIVE);
        let ab = (rho * s2 * g).mul_add(t, a_par);
        let ratio = (ul_abs2 * a_par) / (pl_abs2 * pl_abs2 * ab);
        // A NaN cosine fails `c <= 0` and reaches F through the ratio.
        T::select(ok & !c.simd_le(T::ZERO), ratio.min(T::ONE), at_grazing)
    }
}

/// A complex index of refraction eta + i k, with its two parts named so that a call site cannot
/// swap them: `ComplexIor { eta, k }`. `C` is a scalar (`f32`, lanes) or a colour `V3<T>` (eta
/// and k per channel, x = r, y = g, z = b), as the full conductor BRDFs take it
/// (`cook_torrance::ggx_conductor_rgb`).
///
/// An argument bundle, not a validated parameter: the kernel it is passed to keeps the
/// crate's rule for invalid values (eta <= 0, k < 0 or NaN give NaN in that channel).
/// Published values are per wavelength; Gulbrandsen 2014 ("Artist Friendly Metallic Fresnel",
/// JCGT 3(4)) lists RGB fits.
///
/// ```
/// use brdf::V3;
/// use brdf::fresnel::{self, ComplexIor};
/// let gold = ComplexIor { eta: V3::new(0.18, 0.42, 1.37), k: V3::new(3.42, 2.35, 1.77) };
/// let f = fresnel::conductor_rgb(1.0_f64, gold.eta, gold.k);
/// assert!(f.x > f.z);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ComplexIor<C> {
    /// The real part: the refractive index n (eta).
    pub eta: C,
    /// The imaginary part: the extinction coefficient k (absorption), k >= 0.
    pub k: C,
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

/// Principal square root of re + i im, without the cancellation of sqrt((|z| - re) / 2) for
/// re > 0 (Press et al., "Numerical Recipes", section 5.5). Where both parts are so small that
/// their squares would lose bits to underflow, |z| is taken as M sqrt(1 + (min / M)^2) with
/// M the larger part, and the root as sqrt(M) sqrt(h).
#[inline]
fn complex_sqrt<T: Real>(re: T, im: T) -> (T, T) {
    let (a, b) = (re.abs(), im.abs());
    let big = a.max(b);
    let norm = re.mul_add(re, im * im).sqrt();
    let t_direct = (T::HALF * (norm + a)).sqrt();
    let safe_big = T::select(big.simd_gt(T::ZERO), big, T::ONE);
    let r = a.min(b) / safe_big;
    let h = T::HALF * (r.mul_add(r, T::ONE).sqrt() + a / safe_big);
    let t_scaled = safe_big.sqrt() * h.sqrt();
    let small = big.simd_lt((T::MIN_POSITIVE / T::EPSILON).sqrt());
    let t = T::select(small & big.simd_gt(T::ZERO), t_scaled, t_direct);
    let safe_t = T::select(t.simd_gt(T::ZERO), t, T::ONE);
    let other = T::select(t.simd_gt(T::ZERO), b / (T::TWO * safe_t), T::ZERO);
    let non_neg = re.simd_ge(T::ZERO);
    let out_re = T::select(non_neg, t, other);
    let out_im_mag = T::select(non_neg, other, t);
    (out_re, out_im_mag.copysign(im))
}

/// 2^e as an f64, exactly, for -1022 <= e <= 1023.
const fn pow2(e: i32) -> f64 {
    f64::from_bits(((1023 + e) as u64) << 52)
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
/// Domain: F0 and tint in [0, 1] (outside, and NaN, give NaN); cosine clamped to [0, 1], NaN
/// gives NaN. tint = 1 is plain Schlick. The result is clamped at 0 (for tint < 1 and small
/// F0 the fitted dip can cross below 0 by a rounding-sized amount).
#[inline]
#[must_use]
pub fn schlick_f82<T: Real>(f0: T, f82_tint: T, cos_theta: T) -> T {
    let ok = in_unit(f0) & in_unit(f82_tint);
    let mu_bar = T::splat(F82_MU);
    let denom = T::splat(F82_MU * libm::pow(1.0 - F82_MU, 6.0));
    let b = schlick(f0, mu_bar) * (T::ONE - f82_tint) / denom;
    let mu = cos_theta.saturate();
    let dip = b * mu * (T::ONE - mu).powi(6);
    nan_unless(ok, (schlick(f0, mu) - dip).max(T::ZERO))
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

/// Gauss-Legendre nodes and weights on [0, 1], `N` points (computed to double precision by
/// Newton iteration on P_N from Tricomi's initial guesses; N points integrate polynomials of
/// degree 2N - 1 exactly). Shared by the Fresnel averages here and `ibl::energy`'s tables.
pub(crate) fn gauss_legendre_01<const N: usize>() -> ([f64; N], [f64; N]) {
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
/// Domain eta in (0, MAX]; F_avg(1) = 0; eta <= 0, +inf and NaN give NaN.
#[must_use]
pub fn average_dielectric(eta: f64) -> f64 {
    if !valid_eta(eta) {
        return f64::NAN;
    }
    let (x, w) = gauss_legendre_01::<24>();
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
/// (`cargo test --test fresnel approximations:: -- --nocapture`). Domain eta in (0, MAX]
/// (eta <= 0, +inf and NaN give NaN); beyond 3 the fit tends to 1 / 1.00071, below 0.5 to
/// 0.997.
#[inline]
#[must_use]
pub fn average_dielectric_fit<T: Real>(eta: T) -> T {
    // (eta - 1) / (4.08567 + 1.00071 eta) divided through by eta, so that eta near MAX does
    // not overflow the denominator.
    let inv = eta.recip();
    let above = (T::ONE - inv) / inv.mul_add(T::splat(4.08567), T::splat(1.00071));
    let below = eta.mul_add(
        eta.mul_add(
            eta.mul_add(T::splat(-0.130607), T::splat(-0.965241)),
            T::splat(0.1014),
        ),
        T::splat(0.997118),
    );
    nan_unless(valid_eta(eta), T::select(eta.simd_ge(T::ONE), above, below))
}
