//! Multiple-scattering energy compensation for GGX with the height-correlated Smith G2: the
//! albedo E(mu, alpha) and its average E_avg(alpha), Kulla and Conty's compensation lobe with
//! its Fresnel term, and the split-sum forms of Turquin and Fdez-Aguera that real-time engines
//! apply to a DFG lookup.
//!
//! A single-scattering microfacet BRDF drops the light that reflects more than once between
//! microfacets: with F = 1, GGX at alpha = 1 returns only 1 - ln 2 = 0.31 of the light at
//! normal incidence (`cargo test --test cook_torrance energy:: -- --nocapture` prints the loss
//! table). The compensations below add the missing energy back as a smooth extra lobe.
//!
//! # The albedo E and its average
//! E(mu, alpha) = integral over the hemisphere of f_ss(wo, wi) cos(theta_i) dwi, with f_ss the
//! GGX Cook-Torrance BRDF D V F of `brdf::cook_torrance` (D: [`crate::ggx::d`]; V: the
//! height-correlated [`crate::ggx::v_correlated`]) and F = 1, mu = cos(theta_o); and
//! E_avg(alpha) = 2 integral_0^1 E(mu, alpha) mu dmu, the albedo under uniform incident light.
//! (E is the sum A + B of the split-sum DFG table of [`super::dfg`], computed here on its own.)
//!
//! [`e_ggx_estimate`] evaluates E by quasi-Monte Carlo: visible normals m of wo drawn with
//! [`crate::sampling::ggx_vndf_spherical_cap`] at Hammersley points, wi the mirror of wo about
//! m, and the estimator f cos / pdf = G2(wo, wi) / G1(wo) = (1 + Lambda(wo)) / (1 +
//! Lambda(wo) + Lambda(wi)) (0 where wi is below the horizon; Heitz 2018, "Sampling the GGX
//! Distribution of Visible Normals", JCGT 7(4)). Its error falls as 1 / samples: about
//! 5e-4 at 1024 samples, 3e-5 to 1e-4 at 16384 and 8e-6 to 2.8e-5 at 65536 against the adaptive cubature of
//! `brdf::integrate::directional_albedo` (`cargo test --features ibl,integrate,cook-torrance
//! --test ibl energy_tables:: -- --nocapture`). [`e_avg_ggx_estimate`] integrates E with
//! 32-point Gauss-Legendre in x = sqrt(mu).
//!
//! E has a shape worth knowing: for F = 1 it is 1 at grazing (mu -> 0: every visible facet
//! reflects above the horizon and Lambda(wo) -> inf makes G2 / G1 -> 1), dips to about 0.89
//! at mu near alpha, and for rough surfaces falls again towards normal incidence (0.31 at
//! alpha = 1, mu = 1). The dip sits at sqrt(mu) ~ sqrt(alpha), which is why the built-in table
//! is uniform in sqrt(mu) and sqrt(alpha) rather than in mu and alpha.
//!
//! # Built-in table and lookups
//! [`E_GGX_TABLE`] holds E on a [`E_TABLE_SIZE`] x [`E_TABLE_SIZE`] (32 x 32) grid and
//! [`E_AVG_GGX_TABLE`] holds E_avg on 32 roughnesses, computed by [`e_table`] and
//! [`e_avg_table`] with 65536 samples (QMC error at most 2.8e-5 against the cubature) and rounded to f32. Grid, for
//! i, j in 0..32: alpha_i = max((i / 31)^2, ALPHA_MIN) (uniform in the perceptual roughness
//! r = sqrt(alpha)) and mu_j = (j / 31)^2 (uniform in sqrt(mu)); `E_GGX_TABLE[32 i + j]` =
//! E(mu_j, alpha_i), `E_AVG_GGX_TABLE[i]` = E_avg(alpha_i). [`e_ggx`] and [`e_avg_ggx`]
//! interpolate them bilinearly (linearly) in (sqrt(mu), sqrt(alpha)): no setup, no allocation.
//! Lookup error against the estimator (`--test ibl energy_tables::`): max abs 0.06 over the
//! whole square, all of it at theta_o > 89 degrees and alpha < 0.002 (the dip narrower than
//! a cell); 0.0016 for theta_o <= 85 degrees; E_avg within 1e-5 at the nodes.
//!
//! # Kulla and Conty's compensation lobe
//! Kulla and Conty 2017, "Revisiting Physically Based Shading at Imageworks" (SIGGRAPH course
//! "Physically Based Shading in Theory and Practice"), after Kelemen and Szirmay-Kalos 2001,
//! "A Microfacet Based Coupled Specular-Matte BRDF Model with Importance Sampling":
//!
//! - f_ms(mu_o, mu_i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)) ([`kulla_conty_lobe`]):
//!   symmetric in its two cosines, hence reciprocal, and its albedo is exactly 1 - E(mu_o), so
//!   f_ss + f_ms has albedo 1 for F = 1 (white furnace);
//! - with Fresnel, the light that bounces k >= 1 more times before leaving is attenuated by
//!   F_avg once more per bounce; summing the series gives the lobe's colour
//!   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) ([`kulla_conty_fresnel`]), which multiplies
//!   f_ms. F_ms / F_avg = F_avg E_avg / (1 - F_avg (1 - E_avg)) falls faster than F_avg, which
//!   saturates coloured metals, as real rough metals are;
//! - F_avg = 2 integral_0^1 F(mu) mu dmu, the cosine-weighted hemispherical average of the
//!   Fresnel term: for Schlick's F0 + (F90 - F0)(1 - mu)^5 it is exactly
//!   F0 + (F90 - F0) / 21 (2 integral (1 - mu)^5 mu dmu = 2 / 42) ([`fresnel_avg_schlick`]);
//!   for a conductor, [`fresnel_avg_conductor`] (quadrature); for a dielectric,
//!   [`crate::fresnel::average_dielectric`] (quadrature) and its fit
//!   [`crate::fresnel::average_dielectric_fit`] (Kulla and Conty's, max abs error 0.0065).
//!
//! [`kulla_conty_ggx`] assembles F_ms f_ms from the built-in table: add it to the
//! single-scattering GGX BRDF. The same formulas are implemented in Blender Cycles
//! (`bsdf_microfacet.h`, with one F_avg cancelled into its albedo scaling), appleseed
//! (`microfacet_energy_compensation_term`), OSPRay and MoonRay.
//!
//! # Split-sum forms (real-time)
//! - Turquin 2019, "Practical multiple scattering compensation for microfacet models"
//!   (eqs. 14 and 16): scale the single-scattering lobe by 1 + F (1 - E(mu_o)) / E(mu_o)
//!   ([`turquin_scale`]). Filament passes F = F0 and E = its DFG table's second channel
//!   (`energyCompensation = 1.0 + f0 * (1.0 / dfg.y - 1.0)`, "Physically Based Rendering in
//!   Filament", section 4.7.2); MaterialX passes F = F_avg (`mx_ggx_energy_compensation`).
//!   With F = 1 the scaled albedo is exactly 1.
//! - Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time Image-based
//!   Lighting" (JCGT 8(1), Listings 1 and 2, with the journal's errata for the F_avg
//!   constant): from the DFG pair (A, B), Ess = A + B, Ems = 1 - Ess, FssEss = F0 A + B,
//!   F_avg = F0 + (1 - F0) / 21, Fms = FssEss F_avg / (1 - Ems F_avg), and the radiance is
//!   FssEss * prefiltered_radiance + Fms Ems * irradiance ([`fdez_aguera`],
//!   [`fdez_aguera_ms`]); a dielectric's diffuse weight is 1 - (FssEss + Fms Ems). Blender
//!   EEVEE applies both terms to the prefiltered radiance, whose sum is
//!   FssEss / (1 - Ems F_avg).
//!
//! # Conventions
//! `alpha` is the GGX width (Walter et al. 2007's alpha_g), never the perceptual roughness
//! r = sqrt(alpha) of a material slider ([`crate::microfacet::alpha_from_perceptual`]). Every
//! mu, `n_dot_v`, `n_dot_l` is a cosine against the shading normal. Bad input follows the
//! crate rule: NaN in any input gives NaN; a parameter outside its documented domain gives
//! NaN; cosines are clamped to [0, 1] and the lobes are 0 below the horizon.

use crate::domain::{above_horizon, in_unit, nan_unless, nan_where};
use crate::error::ParamError;
use crate::ggx::{self, Ggx};
use crate::microfacet::{ALPHA_MIN, alpha_ok};
use crate::real::Real;
use crate::sampling::ggx_vndf_spherical_cap;
use crate::vec3::V3;

/// A directional albedo E(mu): the fraction of light a lobe reflects from one direction,
/// integrated over the hemisphere, here with F = 1 ([`e_ggx`], the A + B of a DFG table).
/// A named wrapper, so the energy terms below cannot be passed in each other's place:
/// `turquin_scale(Albedo(e), Reflectance(f0))` compiles, the swapped call does not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Albedo<T>(pub T);

/// The cosine-weighted hemispherical average E_avg = 2 integral_0^1 E(mu) mu dmu of a
/// directional albedo ([`e_avg_ggx`]). A named wrapper, as [`Albedo`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AverageAlbedo<T>(pub T);

/// A Fresnel reflectance: F0, F90, or the hemispherical average F_avg
/// ([`fresnel_avg_schlick`], [`fresnel_avg_conductor`]). A named wrapper, as [`Albedo`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflectance<T>(pub T);

/// Side of the built-in tables: [`E_GGX_TABLE`] is `E_TABLE_SIZE` x `E_TABLE_SIZE`,
/// [`E_AVG_GGX_TABLE`] has `E_TABLE_SIZE` entries (grid in the module docs).
pub const E_TABLE_SIZE: usize = 32;

/// Van der Corput radical inverse in base 2 of `i`: the second Hammersley coordinate.
#[inline]
fn radical_inverse(i: u32) -> f64 {
    f64::from(i.reverse_bits()) * (1.0 / 4_294_967_296.0)
}

/// Directional albedo E(mu, alpha) of GGX Cook-Torrance (height-correlated Smith, F = 1) by
/// quasi-Monte Carlo over `samples` Hammersley points (module docs: visible-normal sampling,
/// estimator G2 / G1; error about 0.5 / samples). Deterministic: the same arguments give the
/// same bits.
///
/// Domain: mu a cosine, clamped to [0, 1]; alpha in [0, +inf) finite (the GGX width, clamped
/// to [ALPHA_MIN, ALPHA_MAX]); `samples` >= 1. NaN for NaN input, alpha < 0 or +inf, and for
/// `samples` = 0. Not a hot-path kernel: 65536 samples take about 3 ms.
#[must_use]
pub fn e_ggx_estimate(mu: f64, alpha: f64, samples: u32) -> f64 {
    if samples == 0 || mu.is_nan() || !alpha_ok(alpha) {
        return f64::NAN;
    }
    let ggx = Ggx::new_unchecked(alpha, alpha);
    let mu = mu.clamp(0.0, 1.0);
    let wo = V3::new(libm::sqrt((1.0 - mu) * (1.0 + mu)), 0.0, mu);
    let lambda_o = ggx::lambda(mu, alpha);
    let n = f64::from(samples);
    let mut sum = 0.0;
    for i in 0..samples {
        let u1 = (f64::from(i) + 0.5) / n;
        let (m, _) = ggx_vndf_spherical_cap(&ggx, wo, u1, radical_inverse(i));
        let wi = wo.mirror(m);
        if wi.z > 0.0 {
            // G2 / G1(wo); at mu = 0 Lambda(wo) is capped at MAX and the ratio is 1, the
            // limit of the grazing view.
            let lambda_i = ggx::lambda(wi.z, alpha);
            sum += if lambda_o >= f64::MAX {
                1.0
            } else {
                (1.0 + lambda_o) / (1.0 + lambda_o + lambda_i)
            };
        }
    }
    sum / n
}

/// Average albedo E_avg(alpha) = 2 integral_0^1 E(mu, alpha) mu dmu, with E from
/// [`e_ggx_estimate`] (`samples` each) at the 32 Gauss-Legendre nodes of x = sqrt(mu)
/// (E_avg = 4 integral_0^1 E(x^2) x^3 dx: the substitution puts nodes into E's dip at
/// small mu). Same domain and edges as [`e_ggx_estimate`]. Deterministic.
#[must_use]
pub fn e_avg_ggx_estimate(alpha: f64, samples: u32) -> f64 {
    let (x, w) = crate::fresnel::gauss_legendre_01::<32>();
    let mut sum = 0.0;
    for k in 0..x.len() {
        let mu = x[k] * x[k];
        sum += w[k] * e_ggx_estimate(mu, alpha, samples) * mu * x[k];
    }
    4.0 * sum
}

/// The grid of the tables: node `k` of `n` as sqrt-coordinate k / (n - 1).
#[inline]
fn node(k: usize, n: usize) -> f64 {
    k as f64 / (n - 1) as f64
}

/// alpha of roughness row `i` of `n`: max((i / (n - 1))^2, ALPHA_MIN).
#[inline]
fn alpha_node(i: usize, n: usize) -> f64 {
    let r = node(i, n);
    (r * r).max(ALPHA_MIN)
}

/// Writes E(mu, alpha) into `out` on the grid of the built-in table, sized by the caller:
/// `out[i * n_mu + j]` = [`e_ggx_estimate`]`(mu_j, alpha_i, samples)` with
/// mu_j = (j / (n_mu - 1))^2 and alpha_i = max((i / (n_alpha - 1))^2, ALPHA_MIN).
/// `e_table(out, 32, 32, 65536)` reproduces [`E_GGX_TABLE`]. Deterministic.
///
/// Errors ([`ParamError`], `out` untouched): `n_mu` or `n_alpha` below 2, `samples` = 0,
/// `out.len()` != `n_mu * n_alpha`. Cost: n_mu n_alpha samples visible-normal samples
/// (about 3 s for 32 x 32 x 65536).
pub fn e_table(
    out: &mut [f32],
    n_mu: usize,
    n_alpha: usize,
    samples: u32,
) -> Result<(), ParamError> {
    check_grid(n_mu, "n_mu")?;
    check_grid(n_alpha, "n_alpha")?;
    check_samples(samples)?;
    if n_mu.checked_mul(n_alpha) != Some(out.len()) {
        return Err(ParamError {
            param: "out",
            expected: "length n_mu * n_alpha",
        });
    }
    for (i, row) in out.chunks_exact_mut(n_mu).enumerate() {
        let alpha = alpha_node(i, n_alpha);
        for (j, e) in row.iter_mut().enumerate() {
            let x = node(j, n_mu);
            *e = e_ggx_estimate(x * x, alpha, samples) as f32;
        }
    }
    Ok(())
}

/// Writes E_avg(alpha_i) = [`e_avg_ggx_estimate`]`(alpha_i, samples)` into `out[i]`, with
/// alpha_i = max((i / (out.len() - 1))^2, ALPHA_MIN) (the roughness rows of [`e_table`]).
/// `e_avg_table(out, 65536)` with a 32-entry `out` reproduces [`E_AVG_GGX_TABLE`].
/// Deterministic.
///
/// Errors ([`ParamError`], `out` untouched): `out.len()` below 2, `samples` = 0. Cost: 32
/// albedo estimates per entry.
pub fn e_avg_table(out: &mut [f32], samples: u32) -> Result<(), ParamError> {
    check_grid(out.len(), "out")?;
    check_samples(samples)?;
    let n = out.len();
    for (i, e) in out.iter_mut().enumerate() {
        *e = e_avg_ggx_estimate(alpha_node(i, n), samples) as f32;
    }
    Ok(())
}

fn check_grid(n: usize, param: &'static str) -> Result<(), ParamError> {
    if n < 2 {
        return Err(ParamError {
            param,
            expected: "at least 2 grid points",
        });
    }
    Ok(())
}

fn check_samples(samples: u32) -> Result<(), ParamError> {
    if samples == 0 {
        return Err(ParamError {
            param: "samples",
            expected: ">= 1",
        });
    }
    Ok(())
}

/// Bilinear lookup of the built-in table in (sqrt(mu), sqrt(alpha)), in f64; mu and alpha
/// already checked (NaN only reaches here to be overwritten by the caller).
fn lookup_e(mu: f64, alpha: f64) -> f64 {
    const LAST: f64 = (E_TABLE_SIZE - 1) as f64;
    let x = libm::sqrt(mu.clamp(0.0, 1.0)) * LAST;
    let r = libm::sqrt(alpha.clamp(ALPHA_MIN, 1.0)) * LAST;
    // NaN casts to 0: a valid index whose value the caller discards.
    let j = (x as usize).min(E_TABLE_SIZE - 2);
    let i = (r as usize).min(E_TABLE_SIZE - 2);
    let (fx, fr) = (x - j as f64, r - i as f64);
    let at = |i: usize, j: usize| f64::from(E_GGX_TABLE[i * E_TABLE_SIZE + j]);
    let lo = at(i, j) + fx * (at(i, j + 1) - at(i, j));
    let hi = at(i + 1, j) + fx * (at(i + 1, j + 1) - at(i + 1, j));
    lo + fr * (hi - lo)
}

/// Linear lookup of [`E_AVG_GGX_TABLE`] in sqrt(alpha), in f64.
fn lookup_e_avg(alpha: f64) -> f64 {
    const LAST: f64 = (E_TABLE_SIZE - 1) as f64;
    let r = libm::sqrt(alpha.clamp(ALPHA_MIN, 1.0)) * LAST;
    let i = (r as usize).min(E_TABLE_SIZE - 2);
    let fr = r - i as f64;
    let (a, b) = (
        f64::from(E_AVG_GGX_TABLE[i]),
        f64::from(E_AVG_GGX_TABLE[i + 1]),
    );
    a + fr * (b - a)
}

/// E(mu, alpha) of GGX Cook-Torrance (height-correlated Smith, F = 1) from the built-in
/// [`E_GGX_TABLE`], bilinear in (sqrt(mu), sqrt(alpha)) (module docs). The lookup runs in f64
/// on each lane and is rounded once to the lane type, so every lane equals the scalar result
/// bit for bit.
///
/// Domain: mu a cosine in [-1, 1], clamped to [0, 1]; alpha in [0, +inf) finite, the GGX
/// width (not perceptual roughness). alpha below ALPHA_MIN reads the ALPHA_MIN row; alpha
/// above 1 reads the alpha = 1 row (E keeps falling beyond it: use [`e_ggx_estimate`] for
/// such surfaces). NaN for NaN input, alpha < 0 or +inf. Output in [0.3, 1]. Error: max abs
/// 0.0016 against [`e_ggx_estimate`] for mu >= cos(85 degrees), 0.06 over the whole square
/// (module docs; `cargo test --features ibl,integrate,cook-torrance --test ibl energy_tables::
/// -- --nocapture`).
#[inline]
#[must_use]
pub fn e_ggx<T: Real>(mu: T, alpha: T) -> T {
    let v = T::from_fn(|i| {
        let (m, a): (f64, f64) = (mu.lane(i).into(), alpha.lane(i).into());
        <T::Scalar as Real>::splat(lookup_e(m, a))
    });
    nan_unless(alpha_ok(alpha), nan_where(mu.is_nan(), v))
}

/// E_avg(alpha) = 2 integral_0^1 E(mu, alpha) mu dmu of GGX (height-correlated Smith, F = 1)
/// from the built-in [`E_AVG_GGX_TABLE`], linear in sqrt(alpha); lanes equal scalar bit for
/// bit (as [`e_ggx`]). Domain and edges of alpha as [`e_ggx`]; NaN for NaN, alpha < 0 or
/// +inf. Output in [0.40, 1]: 1 - E_avg is the fraction of uniform light single scattering
/// loses.
#[inline]
#[must_use]
pub fn e_avg_ggx<T: Real>(alpha: T) -> T {
    let v = T::from_fn(|i| {
        let a: f64 = alpha.lane(i).into();
        <T::Scalar as Real>::splat(lookup_e_avg(a))
    });
    nan_unless(alpha_ok(alpha), v)
}

/// Kulla and Conty's multiple-scattering lobe (after Kelemen and Szirmay-Kalos 2001):
/// f_ms = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)), without Fresnel (multiply by
/// [`kulla_conty_fresnel`]). Symmetric in `e_o` and `e_i`, so the lobe is reciprocal; its
/// albedo for a view with albedo E(mu_o) is exactly 1 - E(mu_o) when E_avg is the average of
/// the same E.
///
/// Arguments: `e_o` = E(n.v), `e_i` = E(n.l), `e_avg` = E_avg, each in [0, 1] (from
/// [`e_ggx`] and [`e_avg_ggx`] or a caller's own table); outside, or NaN, gives NaN.
/// e_avg = 1 (a mirror, where E = 1 everywhere) gives 0, as do e_o = 1 or e_i = 1; capped at
/// the largest finite value when 1 - e_avg is tiny and the numerator is not (inconsistent
/// tables). Source: Kulla and Conty 2017, "Revisiting Physically Based Shading at
/// Imageworks".
#[inline]
#[must_use]
pub fn kulla_conty_lobe<T: Real>(e_o: Albedo<T>, e_i: Albedo<T>, e_avg: AverageAlbedo<T>) -> T {
    let (e_o, e_i, e_avg) = (e_o.0, e_i.0, e_avg.0);
    let num = (T::ONE - e_o) * (T::ONE - e_i);
    let den = T::PI * (T::ONE - e_avg);
    let v = T::select(
        den.simd_gt(T::ZERO) & num.simd_gt(T::ZERO),
        (num / den).min(T::MAX),
        T::ZERO,
    );
    nan_unless(in_unit(e_o) & in_unit(e_i) & in_unit(e_avg), v)
}

/// Kulla and Conty's Fresnel term of the multiple-scattering lobe:
/// F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), the sum over k >= 1 further bounces of
/// F_avg^(k+1) E_avg (1 - E_avg)^k, divided by the lobe's albedo 1 - E_avg. 1 for F_avg = 1;
/// F_ms / F_avg < F_avg for F_avg < 1 (the added light is more saturated than the single
/// scattering).
///
/// Arguments: `f_avg` = 2 integral F mu dmu ([`fresnel_avg_schlick`],
/// [`fresnel_avg_conductor`], [`crate::fresnel::average_dielectric`]) and `e_avg`
/// ([`e_avg_ggx`]), both in [0, 1]; outside, or NaN, gives NaN. At F_avg = 1, E_avg = 0 (0 /
/// 0) it returns the F_avg = 1 limit 1. Source: Kulla and Conty 2017, "Revisiting Physically
/// Based Shading at Imageworks", slide "Fresnel".
#[inline]
#[must_use]
pub fn kulla_conty_fresnel<T: Real>(f_avg: Reflectance<T>, e_avg: AverageAlbedo<T>) -> T {
    let (f_avg, e_avg) = (f_avg.0, e_avg.0);
    let den = T::ONE - f_avg * (T::ONE - e_avg);
    let v = T::select(den.simd_gt(T::ZERO), f_avg * f_avg * e_avg / den, T::ONE);
    // F_ms <= F_avg <= 1, but at F_avg = 1 the quotient E_avg / (1 - (1 - E_avg)) rounds up to
    // 1 + 1e-13 for small E_avg: the cap keeps it in [0, 1] (NaN passes through Real::min).
    nan_unless(in_unit(f_avg) & in_unit(e_avg), v.min(T::ONE))
}

/// Hemispherical average of Schlick's Fresnel F0 + (F90 - F0)(1 - mu)^5:
/// F_avg = 2 integral_0^1 F(mu) mu dmu = F0 + (F90 - F0) / 21, exact (2 integral (1 - mu)^5 mu
/// dmu = 1/21). F90 = 1 for the classic form (Fdez-Aguera 2019's F0 + (1 - F0) / 21); MaterialX
/// uses the F90 form. Domain: F0 and F90 in [0, 1]; outside, or NaN, gives NaN.
#[inline]
#[must_use]
pub fn fresnel_avg_schlick<T: Real>(f0: T, f90: T) -> T {
    let v = (f90 - f0).mul_add(T::splat(1.0 / 21.0), f0);
    nan_unless(in_unit(f0) & in_unit(f90), v)
}

/// Hemispherical average F_avg = 2 integral_0^1 F(mu) mu dmu of the exact conductor Fresnel
/// term [`crate::fresnel::conductor`] of complex IOR eta + i k, by 32-point Gauss-Legendre
/// quadrature (F is smooth in mu for a conductor: the result is within 1e-12 of the integral),
/// capped at 1: where F is 1 at every angle (eta or k near 0 or MAX) the rounded weights sum
/// to 1 + 2^-52. Domain: eta in (0, MAX], k in [0, MAX]; NaN outside or for NaN. Not a
/// hot-path kernel (32 Fresnel evaluations); per channel for RGB.
#[must_use]
pub fn fresnel_avg_conductor(eta: f64, k: f64) -> f64 {
    let (x, w) = crate::fresnel::gauss_legendre_01::<32>();
    let mut sum = 0.0;
    for i in 0..x.len() {
        sum += w[i] * crate::fresnel::conductor(x[i], eta, k) * x[i];
    }
    let avg = 2.0 * sum;
    // Not f64::min, which would turn a NaN average into 1.
    if avg > 1.0 { 1.0 } else { avg }
}

/// Kulla and Conty's multiple-scattering term of GGX from the built-in tables:
/// F_ms(f_avg, E_avg(alpha)) f_ms(E(n.v), E(n.l), E_avg(alpha)) ([`kulla_conty_fresnel`],
/// [`kulla_conty_lobe`], [`e_ggx`], [`e_avg_ggx`]). Add it to the single-scattering BRDF
/// (`brdf::cook_torrance`'s D V F); like it, the value is the BRDF, not multiplied by n.l.
/// Reciprocal (symmetric in the two cosines).
///
/// Domain: cosines in [-1, 1] (clamped; 0 where n.v <= 0 or n.l <= 0); alpha as [`e_ggx`];
/// `f_avg` in [0, 1] (F_avg of the Fresnel term the single scattering uses). NaN for NaN in
/// any input, alpha < 0 or +inf, f_avg outside [0, 1]. With f_avg = 1 the sum has albedo
/// in [0.9995, 1.0006] for alpha in [0, 1] and theta_o <= 85 degrees
/// (`cargo test --features ibl,integrate,cook-torrance --test ibl energy_furnace:: --
/// --nocapture`).
#[inline]
#[must_use]
pub fn kulla_conty_ggx<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T, f_avg: T) -> T {
    let e_avg = e_avg_ggx(alpha);
    let lobe = kulla_conty_lobe(
        Albedo(e_ggx(n_dot_v, alpha)),
        Albedo(e_ggx(n_dot_l, alpha)),
        AverageAlbedo(e_avg),
    );
    let v = kulla_conty_fresnel(Reflectance(f_avg), AverageAlbedo(e_avg)) * lobe;
    // An invalid alpha or f_avg gives NaN below the horizon too (the crate's bad-input rule).
    let params_ok = e_avg.simd_ge(T::ZERO) & in_unit(f_avg);
    nan_unless(params_ok, above_horizon(n_dot_v, n_dot_l, v))
}

/// [`kulla_conty_ggx`] for an RGB F_avg (x = r, y = g, z = b): the lobe is evaluated once and
/// scaled by each channel's F_ms; each channel equals [`kulla_conty_ggx`] with that channel's
/// f_avg bit for bit. Domain and edges as [`kulla_conty_ggx`], per channel for f_avg.
#[inline]
#[must_use]
pub fn kulla_conty_ggx_rgb<T: Real>(n_dot_v: T, n_dot_l: T, alpha: T, f_avg: V3<T>) -> V3<T> {
    let e_avg = e_avg_ggx(alpha);
    let lobe = kulla_conty_lobe(
        Albedo(e_ggx(n_dot_v, alpha)),
        Albedo(e_ggx(n_dot_l, alpha)),
        AverageAlbedo(e_avg),
    );
    let ch = |f: T| {
        let fms = kulla_conty_fresnel(Reflectance(f), AverageAlbedo(e_avg));
        let v = above_horizon(n_dot_v, n_dot_l, fms * lobe);
        // An invalid alpha or f_avg gives NaN below the horizon too.
        nan_unless(e_avg.simd_ge(T::ZERO) & in_unit(f), v)
    };
    V3::new(ch(f_avg.x), ch(f_avg.y), ch(f_avg.z))
}

/// Turquin's energy-compensation factor 1 + F (1 - E) / E that scales the single-scattering
/// specular lobe (Turquin 2019, "Practical multiple scattering compensation for microfacet
/// models", eqs. 14 and 16). `e` = E(n.v) (the single-scattering albedo with F = 1: [`e_ggx`],
/// or A + B of a DFG table; Filament's `dfg.y`); `f` = F0 (Filament:
/// `1.0 + f0 * (1.0 / dfg.y - 1.0)`) or F_avg (MaterialX). With f = 1 the scaled lobe's albedo
/// E (1 + (1 - E) / E) is exactly 1. Not reciprocal (it depends on n.v only), which the
/// split-sum of image-based lighting does not need.
///
/// Domain: e in (0, 1], f in [0, 1]; e <= 0 or > 1, f outside [0, 1], and NaN give NaN.
/// Output in [1, 1 / e], capped at the largest finite value (e below 1 / MAX); f = 0 gives
/// exactly 1 for every e.
///
/// The two arguments are wrapped so that they cannot be swapped (swapped, the call used to
/// return a plausible 1):
///
/// ```
/// use brdf::ibl::energy::{Albedo, Reflectance, e_ggx, turquin_scale};
/// let e = e_ggx(1.0_f64, 1.0); // alpha = 1, normal incidence: E = 0.307
/// let s = turquin_scale(Albedo(e), Reflectance(1.0));
/// assert!((e * s - 1.0).abs() < 1e-12); // the compensated albedo of a white lobe is 1
/// ```
///
/// ```compile_fail
/// use brdf::ibl::energy::{Albedo, Reflectance, turquin_scale};
/// let s = turquin_scale(Reflectance(1.0_f64), Albedo(0.307)); // does not compile
/// ```
///
/// ```compile_fail
/// use brdf::ibl::energy::turquin_scale;
/// let s = turquin_scale(1.0_f64, 0.307); // neither do bare floats
/// ```
#[inline]
#[must_use]
pub fn turquin_scale<T: Real>(e: Albedo<T>, f: Reflectance<T>) -> T {
    let (e, f) = (e.0, f.0);
    let ok = e.simd_gt(T::ZERO) & e.simd_le(T::ONE) & in_unit(f);
    // (1 - e) / e overflows to +inf for e below 1 / MAX; capped first, so f = 0 gives
    // 0 * MAX + 1 = 1 instead of 0 * inf = NaN.
    let v = f.mul_add(((T::ONE - e) / e).min(T::MAX), T::ONE);
    nan_unless(ok, v.min(T::MAX))
}

/// Fdez-Aguera's multiple-scattering term Fms Ems of the split sum (Fdez-Aguera 2019, "A
/// Multiple-Scattering Microfacet Model for Real-Time Image-based Lighting", JCGT 8(1),
/// Listing 1): Ems = 1 - Ess, Fms = FssEss F_avg / (1 - Ems F_avg), returned as Fms Ems, the
/// weight of the cosine-weighted irradiance (FssEss weighs the prefiltered radiance).
///
/// Arguments: `fss_ess` = the single-scattering albedo with Fresnel (F0 A + B of a DFG
/// table), `e_ss` = Ess = A + B, `f_avg` ([`fresnel_avg_schlick`]); all in [0, 1], else NaN.
/// With f_avg = 1 and fss_ess = e_ss the total fss_ess + Fms Ems is exactly 1. At Ess = 0 and
/// F_avg = 1 (0 / 0) it returns 0.
#[inline]
#[must_use]
pub fn fdez_aguera_ms<T: Real>(fss_ess: T, e_ss: Albedo<T>, f_avg: Reflectance<T>) -> T {
    let (e_ss, f_avg) = (e_ss.0, f_avg.0);
    let e_ms = T::ONE - e_ss;
    let den = T::ONE - e_ms * f_avg;
    let v = T::select(den.simd_gt(T::ZERO), fss_ess * f_avg * e_ms / den, T::ZERO);
    nan_unless(in_unit(fss_ess) & in_unit(e_ss) & in_unit(f_avg), v)
}

/// Fdez-Aguera's split-sum specular from a DFG pair (A, B) and F0 (Listing 1): returns
/// (FssEss, Fms Ems) with FssEss = F0 A + B, Ess = A + B, F_avg = F0 + (1 - F0) / 21 and
/// Fms Ems from [`fdez_aguera_ms`]. The specular radiance is FssEss * prefiltered_radiance +
/// Fms Ems * irradiance; a dielectric's diffuse weight is 1 - (FssEss + Fms Ems) (Listing 2).
///
/// Domain: a, b >= 0 with a + b <= 1 (the DFG table of GGX, A: the F0 scale, B: the bias), F0
/// in [0, 1]; otherwise, or NaN, both outputs are NaN. With F0 = 1 the two sum to exactly
/// A + B + (1 - A - B) = 1.
#[inline]
#[must_use]
pub fn fdez_aguera<T: Real>(a: T, b: T, f0: T) -> (T, T) {
    let ok = a.simd_ge(T::ZERO) & b.simd_ge(T::ZERO) & (a + b).simd_le(T::ONE) & in_unit(f0);
    let fss_ess = nan_unless(ok, f0.mul_add(a, b));
    let e_ss = a + b;
    let ms = fdez_aguera_ms(
        fss_ess,
        Albedo(e_ss),
        Reflectance(fresnel_avg_schlick(f0, T::ONE)),
    );
    (fss_ess, nan_unless(ok, ms))
}

/// E(mu, alpha) of GGX with the height-correlated Smith G2 and F = 1 on the grid of the
/// module docs: `E_GGX_TABLE[32 i + j]` = E(mu_j = (j / 31)^2, alpha_i = max((i / 31)^2,
/// ALPHA_MIN)), from `e_table(out, 32, 32, 65536)` rounded to f32 (QMC error at most 2.8e-5;
/// `tests/ibl/energy_tables.rs` regenerates it). Row-major in alpha: a 32 x 32 texture with mu
/// along u and alpha along v, for a renderer that uploads it.
#[rustfmt::skip]
pub static E_GGX_TABLE: [f32; E_TABLE_SIZE * E_TABLE_SIZE] = [
    1.0, 0.99463105, 0.99969834, 0.99995184, 0.99997574, 0.9999958, 0.9999982, 0.99999905, 0.99999946, 0.99999964, 0.99999976, 0.9999998, 0.9999999, 0.99999994, 0.99999994, 0.99999994, 0.99999994, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    1.0, 0.89206547, 0.96454036, 0.99271005, 0.997853, 0.9991388, 0.9995876, 0.99979866, 0.9998748, 0.9999158, 0.99995965, 0.9999679, 0.99997294, 0.9999763, 0.9999785, 0.9999801, 0.9999952, 0.99999726, 0.9999979, 0.99999833, 0.9999987, 0.999999, 0.9999992, 0.9999994, 0.9999995, 0.99999964, 0.9999997, 0.9999998, 0.9999999, 0.99999994, 0.99999994, 1.0,
    1.0, 0.95257455, 0.89205986, 0.9222191, 0.96453774, 0.98465484, 0.99271035, 0.99618787, 0.9978526, 0.99869174, 0.9991376, 0.9994075, 0.9995915, 0.99970704, 0.9998027, 0.9998327, 0.99987954, 0.999895, 0.999923, 0.99994284, 0.9999635, 0.9999684, 0.9999719, 0.9999747, 0.999977, 0.99997884, 0.99998033, 0.9999815, 0.99998254, 0.99998343, 0.99999934, 0.99998474,
    1.0, 0.9774627, 0.925066, 0.89201283, 0.90595424, 0.93861645, 0.96450096, 0.9798047, 0.9881602, 0.99268776, 0.99531156, 0.996863, 0.99782276, 0.9984153, 0.99882054, 0.9991128, 0.9993255, 0.9994352, 0.99954945, 0.999632, 0.99970216, 0.99976283, 0.99978, 0.99979573, 0.99983734, 0.9998467, 0.99983996, 0.9998752, 0.99988186, 0.99988633, 0.9999051, 0.99992293,
    1.0, 0.9870372, 0.95244896, 0.912646, 0.8918472, 0.8990171, 0.9219925, 0.94600236, 0.9643582, 0.97665024, 0.98446834, 0.9893918, 0.9925701, 0.9946565, 0.996061, 0.9969972, 0.9976899, 0.9981633, 0.9985398, 0.99879974, 0.99899507, 0.9991647, 0.9992854, 0.99938333, 0.99945974, 0.9995221, 0.99957824, 0.9996102, 0.9996487, 0.99965584, 0.99971807, 0.999722,
    1.0, 0.9915687, 0.96798724, 0.93550855, 0.90598357, 0.8914952, 0.895382, 0.9116289, 0.93167216, 0.9498585, 0.9640401, 0.9743119, 0.98148054, 0.98646235, 0.98991597, 0.9923435, 0.9940671, 0.9953399, 0.9962659, 0.9969389, 0.99748343, 0.99787, 0.99818975, 0.99844444, 0.99864906, 0.99877906, 0.99890447, 0.99900794, 0.99911577, 0.99918836, 0.9992451, 0.99930394,
    1.0, 0.9940311, 0.9770257, 0.9518345, 0.92413956, 0.90169144, 0.89085644, 0.8929768, 0.9047228, 0.92096364, 0.93749624, 0.951913, 0.9634939, 0.97230995, 0.97889984, 0.9837275, 0.98730975, 0.9899367, 0.9919041, 0.9933973, 0.99453235, 0.99541754, 0.9960998, 0.9966314, 0.9970448, 0.99741006, 0.99769014, 0.99790275, 0.99810135, 0.99830025, 0.9984164, 0.9985205,
    1.0, 0.9954856, 0.9825628, 0.9627815, 0.93910515, 0.91596746, 0.8983751, 0.8898127, 0.890886, 0.899591, 0.9126876, 0.92714846, 0.9408762, 0.9527935, 0.9625714, 0.9703358, 0.9763766, 0.9810452, 0.9846277, 0.98737746, 0.9895088, 0.99121135, 0.9925206, 0.9935234, 0.99437803, 0.99505734, 0.99559844, 0.9960268, 0.99641275, 0.996734, 0.9969584, 0.9971909,
    1.0, 0.9963862, 0.9860999, 0.9701409, 0.9502018, 0.92887855, 0.9095021, 0.8952731, 0.88822407, 0.8886334, 0.8951989, 0.9057981, 0.91826314, 0.9308734, 0.94251716, 0.95266867, 0.96117485, 0.96811825, 0.97372085, 0.9781826, 0.98173255, 0.9845556, 0.9868269, 0.9886485, 0.99009705, 0.991277, 0.99224013, 0.9930599, 0.9937029, 0.99423105, 0.9946889, 0.9950795,
    1.0, 0.99695975, 0.9884107, 0.97512, 0.9581615, 0.93914396, 0.92021245, 0.903774, 0.891937, 0.885932, 0.8858796, 0.8908881, 0.89952284, 0.91021, 0.9215728, 0.9326091, 0.94270635, 0.9515735, 0.95913655, 0.9654555, 0.97068465, 0.97496873, 0.9784779, 0.98134124, 0.98367614, 0.9856058, 0.9871712, 0.988509, 0.9895883, 0.9904873, 0.99125075, 0.9918914,
    1.0, 0.9973229, 0.9899249, 0.97848666, 0.9637615, 0.9468335, 0.9291097, 0.9123, 0.89813805, 0.8880331, 0.8827581, 0.8823502, 0.88619274, 0.89327043, 0.90241706, 0.9125502, 0.92282164, 0.93259794, 0.94152445, 0.949428, 0.95627743, 0.96211815, 0.9670543, 0.9711708, 0.97463983, 0.9775301, 0.9799277, 0.98194873, 0.98363024, 0.98505914, 0.98624927, 0.98726875,
    1.0, 0.9975412, 0.9908963, 0.980722, 0.96761966, 0.9523649, 0.93594384, 0.9195597, 0.9045318, 0.89211226, 0.8832678, 0.87849987, 0.8778038, 0.8807308, 0.8865434, 0.8943751, 0.90337247, 0.91280794, 0.92210865, 0.9308961, 0.9389365, 0.94611096, 0.9524166, 0.957887, 0.9625745, 0.96660006, 0.9700174, 0.9729084, 0.9753822, 0.97748214, 0.9792692, 0.9807918,
    1.0, 0.99765486, 0.99147564, 0.982133, 0.9701569, 0.95615566, 0.9408544, 0.9251306, 0.90997326, 0.8964009, 0.8853124, 0.87738776, 0.8729521, 0.8719926, 0.8741687, 0.8789353, 0.8856338, 0.8935878, 0.9021892, 0.9109296, 0.91944176, 0.927449, 0.93480897, 0.94143444, 0.9473352, 0.95251226, 0.9570304, 0.960957, 0.9643463, 0.96727633, 0.9698071, 0.97198975,
    1.0, 0.99769026, 0.9917611, 0.98291874, 0.97167647, 0.9585442, 0.9440981, 0.9290008, 0.9140039, 0.8999056, 0.8874828, 0.87740093, 0.87013155, 0.8658972, 0.86467236, 0.8662042, 0.8700767, 0.8757788, 0.88278127, 0.89057827, 0.8987165, 0.9068534, 0.9147102, 0.92211616, 0.9289566, 0.9351683, 0.94075084, 0.9457304, 0.9501258, 0.9539952, 0.9573925, 0.96036226,
    1.0, 0.99766433, 0.9918148, 0.98322034, 0.9723934, 0.9597977, 0.9459204, 0.93129134, 0.9165002, 0.90217173, 0.8889465, 0.8774159, 0.8680691, 0.86124295, 0.8570953, 0.85559106, 0.8565405, 0.8596185, 0.8644338, 0.8705566, 0.8775636, 0.8850852, 0.8927812, 0.90040416, 0.9077529, 0.91468906, 0.92113245, 0.927042, 0.9324111, 0.93723726, 0.94156104, 0.9454142,
    1.0, 0.99758863, 0.99168193, 0.98312956, 0.97246027, 0.9601194, 0.9465415, 0.93217784, 0.9175081, 0.90303236, 0.88927215, 0.876731, 0.86586076, 0.857028, 0.8504725, 0.8463043, 0.84449303, 0.84488475, 0.84723306, 0.85122734, 0.8565234, 0.86277115, 0.86965084, 0.8768645, 0.8841669, 0.89136463, 0.89830476, 0.90488654, 0.911043, 0.9167325, 0.9219536, 0.92670095,
    1.0, 0.9974714, 0.9913976, 0.9827148, 0.9719868, 0.95965916, 0.946138, 0.93182653, 0.91712976, 0.90247136, 0.8882737, 0.87495834, 0.8629239, 0.85251606, 0.84400636, 0.8375694, 0.8332843, 0.8311193, 0.8309593, 0.8326046, 0.8358151, 0.8403095, 0.84580326, 0.8520197, 0.8586997, 0.86561424, 0.8725787, 0.8794344, 0.88606566, 0.8923818, 0.8983317, 0.9038804,
    1.0, 0.9973186, 0.99098355, 0.9820291, 0.9710626, 0.9585384, 0.9448545, 0.930389, 0.9155003, 0.9005545, 0.88590705, 0.8719137, 0.8589159, 0.84721977, 0.8370937, 0.82873696, 0.8222843, 0.81778365, 0.8152135, 0.81447715, 0.81542015, 0.8178563, 0.8215539, 0.8262799, 0.83180326, 0.83789635, 0.84435487, 0.85099345, 0.8576696, 0.8642489, 0.87063754, 0.87676376,
    1.0, 0.99713457, 0.99045664, 0.9811109, 0.96974766, 0.95684606, 0.94280744, 0.9279941, 0.91274446, 0.897378, 0.88220954, 0.86754125, 0.853664, 0.8408485, 0.8293386, 0.81932926, 0.8109797, 0.80438083, 0.7995716, 0.7965285, 0.7951777, 0.7953985, 0.79703873, 0.7999179, 0.80384564, 0.80862415, 0.81406194, 0.8199708, 0.82619417, 0.8325789, 0.83900225, 0.8453559,
    1.0, 0.99692285, 0.98983145, 0.9799887, 0.96809506, 0.9546576, 0.9400914, 0.924759, 0.90897745, 0.89304966, 0.87725675, 0.86186135, 0.84711677, 0.8332587, 0.8204993, 0.80902386, 0.79898775, 0.7905036, 0.78364, 0.7784223, 0.7748316, 0.7728096, 0.7722642, 0.7730705, 0.7750877, 0.77816105, 0.7821249, 0.78682035, 0.79208416, 0.79777074, 0.803744, 0.80987793,
    1.0, 0.996686, 0.9891181, 0.9786852, 0.9661403, 0.9520305, 0.9367881, 0.920775, 0.90431046, 0.8876804, 0.87114376, 0.85493916, 0.83929044, 0.8244028, 0.81046206, 0.7976349, 0.7860624, 0.77586186, 0.7671145, 0.7598694, 0.75414485, 0.7499254, 0.7471643, 0.7457894, 0.7457015, 0.7467928, 0.74893606, 0.75199884, 0.7558455, 0.76034063, 0.76535535, 0.77076447,
    1.0, 0.9964262, 0.9883248, 0.97721595, 0.96391976, 0.9490165, 0.93296397, 0.91613036, 0.89883965, 0.8813713, 0.86397207, 0.84686464, 0.830247, 0.81430346, 0.79919845, 0.78507715, 0.7720669, 0.76027393, 0.74978155, 0.74065125, 0.73291844, 0.72659093, 0.7216561, 0.7180772, 0.71579814, 0.7147438, 0.714825, 0.7159464, 0.7179974, 0.72087234, 0.72445494, 0.72863704,
    1.0, 0.9961453, 0.9874592, 0.97559875, 0.9614566, 0.9456545, 0.92867017, 0.9108926, 0.89265084, 0.87422025, 0.8558448, 0.8377329, 0.82007295, 0.8030276, 0.78674364, 0.7713503, 0.7569559, 0.74365854, 0.73153144, 0.7206368, 0.7110168, 0.7026931, 0.6956702, 0.6899344, 0.6854576, 0.6821938, 0.6800865, 0.67906857, 0.67906195, 0.679983, 0.6817448, 0.68425626,
    1.0, 0.9958447, 0.98652637, 0.97384834, 0.95877963, 0.94197965, 0.9239608, 0.90512717, 0.88581854, 0.86631596, 0.8468576, 0.8276505, 0.8088685, 0.79066545, 0.77317303, 0.7565029, 0.7407527, 0.7260046, 0.7123265, 0.69977146, 0.6883802, 0.6781758, 0.6691733, 0.6613714, 0.65475696, 0.64930534, 0.64498156, 0.6417408, 0.63952935, 0.6382903, 0.63795716, 0.63846195,
    1.0, 0.9955258, 0.9855321, 0.9719769, 0.95590544, 0.938024, 0.9188768, 0.8988912, 0.87841785, 0.85774225, 0.83710825, 0.8167183, 0.796742, 0.77732426, 0.7585829, 0.74062365, 0.7235295, 0.70736957, 0.6922027, 0.6780717, 0.6650118, 0.6530465, 0.64218664, 0.63243777, 0.62379247, 0.61623764, 0.609751, 0.60430276, 0.5998577, 0.59637517, 0.59380877, 0.5921097,
    1.0, 0.9951896, 0.98448074, 0.9699948, 0.95285064, 0.9338139, 0.9134568, 0.89223427, 0.8705063, 0.8485746, 0.8266833, 0.8050365, 0.7838, 0.763114, 0.7430911, 0.7238252, 0.70539045, 0.6878468, 0.671241, 0.65561086, 0.6409796, 0.6273652, 0.6147771, 0.60321593, 0.5926792, 0.5831535, 0.5746242, 0.56706786, 0.56046057, 0.5547715, 0.5499678, 0.5460134,
    1.0, 0.99483716, 0.9833764, 0.96790814, 0.94963485, 0.9293733, 0.9077357, 0.88519996, 0.86214566, 0.83888465, 0.81566817, 0.79269934, 0.77015, 0.74815273, 0.72681737, 0.7062311, 0.686461, 0.6675581, 0.6495616, 0.63249946, 0.6163883, 0.6012384, 0.58705306, 0.5738285, 0.5615578, 0.55022794, 0.53982383, 0.53032464, 0.52170837, 0.5139505, 0.50702435, 0.50090027,
    1.0, 0.9944694, 0.9822227, 0.96572655, 0.94626826, 0.9247236, 0.901743, 0.8778309, 0.8533889, 0.8287366, 0.8041368, 0.77979964, 0.7558931, 0.7325521, 0.7098852, 0.687972, 0.66687596, 0.64664215, 0.6273028, 0.6088777, 0.59137714, 0.57480454, 0.5591559, 0.5444217, 0.5305909, 0.51764596, 0.505568, 0.49433517, 0.48392525, 0.47431317, 0.46547365, 0.45738035,
    1.0, 0.9940871, 0.9810227, 0.9634568, 0.94276583, 0.91988474, 0.89550817, 0.8701665, 0.8442822, 0.818191, 0.792165, 0.76641935, 0.7411273, 0.7164234, 0.6924143, 0.66917884, 0.64677554, 0.62524617, 0.604616, 0.5849003, 0.56610364, 0.54822177, 0.5312462, 0.51516265, 0.49995178, 0.48559302, 0.47206303, 0.45933592, 0.4473862, 0.43618712, 0.42571145, 0.41593203,
    1.0, 0.99369097, 0.9797795, 0.9611046, 0.93913764, 0.9148759, 0.88905597, 0.8622391, 0.8348708, 0.8073034, 0.77981776, 0.75263953, 0.7259439, 0.699869, 0.67452043, 0.64997727, 0.626296, 0.60351384, 0.58165365, 0.5607253, 0.5407295, 0.5216577, 0.5034953, 0.48622277, 0.46981743, 0.45425263, 0.4395009, 0.42553303, 0.41231954, 0.39982915, 0.3880329, 0.37690046,
    1.0, 0.99328166, 0.9784957, 0.958676, 0.9353953, 0.90971273, 0.88240945, 0.8540812, 0.82519627, 0.7961241, 0.7671587, 0.73853254, 0.7104277, 0.68298566, 0.656313, 0.63048893, 0.60556847, 0.5815874, 0.558566, 0.536511, 0.5154191, 0.49527863, 0.47607136, 0.45777348, 0.4403584, 0.4237958, 0.40805453, 0.3931015, 0.37890345, 0.3654269, 0.35263875, 0.34050617,
    1.0, 0.99285984, 0.9771738, 0.9561776, 0.9315473, 0.9044098, 0.87559104, 0.84572214, 0.8152957, 0.78470033, 0.75424314, 0.7241659, 0.6946576, 0.66586345, 0.63789284, 0.61082524, 0.5847158, 0.5595993, 0.53549397, 0.5124048, 0.49032587, 0.4692427, 0.4491342, 0.42997408, 0.41173238, 0.39437628, 0.37787133, 0.36218187, 0.3472719, 0.33310533, 0.3196465, 0.30686045,
];

/// E_avg(alpha_i) = 2 integral_0^1 E(mu, alpha_i) mu dmu for alpha_i = max((i / 31)^2,
/// ALPHA_MIN), from `e_avg_table(out, 65536)` rounded to f32 (error about 3e-5;
/// `tests/ibl/energy_tables.rs` regenerates it).
#[rustfmt::skip]
pub static E_AVG_GGX_TABLE: [f32; E_TABLE_SIZE] = [
    0.99999994, 0.99999326, 0.99990606, 0.9995473, 0.99873483, 0.997204, 0.9947042, 0.9909925, 0.9858137, 0.9789392, 0.970167, 0.95932937, 0.94628525, 0.9309446, 0.9132544, 0.8932162, 0.87088096, 0.84635234, 0.8197813, 0.79136765, 0.76135194, 0.7300091, 0.697638, 0.6645539, 0.63107556, 0.59751594, 0.56417245, 0.5313187, 0.4991982, 0.46802017, 0.4379573, 0.40914473,
];
