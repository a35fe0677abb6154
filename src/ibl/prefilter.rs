//! GGX importance samples for prefiltering a radiance cube (the first sum of the split-sum
//! approximation), and the mip level of filtered importance sampling.
//!
//! Karis 2013, "Real Shading in Unreal Engine 4" (SIGGRAPH course notes, p. 4,
//! `PrefilterEnvMap`), prefilters the environment for each roughness by assuming that the
//! normal, the view and the reflection direction coincide, n = v = r. The mip texel of
//! direction r then holds
//!
//! `L_pre(r) = sum_i L(l_i) (n.l_i) / sum_i (n.l_i)`,
//!
//! where the half vectors h_i are drawn from D(h) (n.h) around r and l_i = 2 (v.h_i) h_i - v
//! is v = r reflected about h_i; samples with n.l_i <= 0 get weight 0. The n.l weight is
//! Karis's empirical choice: it is not in the integral, but sharpens the result towards the
//! reference render.
//!
//! What the assumption n = v = r costs: the lobe is always the one seen at normal incidence,
//! rotationally symmetric about r. A surface seen at a grazing angle really reflects a lobe
//! stretched along the plane of incidence and bent towards the normal (the "stretched
//! reflections" on a wet road); the prefiltered cube cannot show it, because one texel serves
//! every (n, v) pair that shares an r.
//!
//! Everything here is in the local frame of r (r = +z): rotate `dir` into world space with
//! [`Frame::from_normal`](crate::frame::Frame::from_normal)`(r).to_world(dir)`. `alpha` is
//! the GGX width as in [`ggx::d`](crate::ggx::d), not perceptual roughness r: alpha = r^2,
//! [`alpha_from_perceptual`](crate::microfacet::alpha_from_perceptual).
//!
//! The sample set is deterministic: sample i of N uses the Hammersley point
//! (radical_inverse_2(i), i / N) ([`hammersley`]; Hammersley and Handscomb 1964, the set
//! Karis's shader uses).
//!
//! ```
//! use brdf::ibl::prefilter;
//! let mut samples = [prefilter::PrefilterSample::default(); 256];
//! let total = prefilter::fill(&mut samples, 0.25);
//! // A constant environment prefilters to itself.
//! let l: f64 = samples.iter().map(|s| 2.0 * s.weight).sum::<f64>() / total;
//! assert!((l - 2.0).abs() < 1e-12);
//! ```

use crate::domain::{above, nan_where};
use crate::ggx::Ggx;
use crate::microfacet::Microfacet;
use crate::real::Real;
use crate::sampling;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

/// One prefilter sample in the local frame of the reflection direction r (= +z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrefilterSample<T> {
    /// The light direction l = 2 (v.h) h - v with v = +z: (2 h.z h.x, 2 h.z h.y,
    /// 2 h.z^2 - 1), a unit vector. May lie below the horizon (then `weight` is 0).
    pub dir: V3<T>,
    /// Karis's weight n.l = max(0, dir.z): 0 for a direction at or below the horizon.
    pub weight: T,
    /// pdf of `dir` with respect to solid angle: D(h) (n.h) / (4 v.h) = D(h) / 4, since
    /// n = v makes n.h = v.h ([`pdf`]). Feed it to [`mip_level`].
    pub pdf: T,
}

impl<T: Real> Default for PrefilterSample<T> {
    /// All zeros (a placeholder to fill a buffer with before [`fill`]).
    fn default() -> Self {
        Self {
            dir: V3::splat(T::ZERO),
            weight: T::ZERO,
            pdf: T::ZERO,
        }
    }
}

/// The Hammersley point i of n in base 2: (radical_inverse_2(i), i / n), where
/// radical_inverse_2 mirrors the 32 bits of i about the binary point (van der Corput).
/// Both coordinates lie in [0, 1) for i < n; exact in f64 (a 32-bit integer over 2^32 and
/// one correctly rounded division). NaN in both for i >= n (n = 0 included).
///
/// Source: Hammersley and Handscomb 1964, "Monte Carlo Methods"; the bit-reversal form is
/// the one of Karis 2013's `Hammersley`.
#[inline]
#[must_use]
pub fn hammersley(i: u32, n: u32) -> (f64, f64) {
    if i >= n {
        return (f64::NAN, f64::NAN);
    }
    let radical = f64::from(i.reverse_bits()) * (1.0 / 4_294_967_296.0);
    (radical, f64::from(i) / f64::from(n))
}

/// pdf (solid angle) of a prefilter direction `dir` (local frame of r = n = v = +z):
/// D(h) / 4 with h = normalize(dir + z) (Walter et al. 2007 eq. 14 with n.h = v.h).
/// Integrates to 1 over the sphere. D is evaluated on the vector h
/// ([`Microfacet::d`]), not on n.h: near the peak of a
/// narrow lobe 1 - (n.h)^2 would cancel (in f32, 1e-5 relative error of the pdf at
/// alpha = 0.05). 0 at dir = -z (h horizontal) and for the zero vector (no direction); NaN for
/// NaN in any input, an infinite component of dir or an alpha outside
/// [0, +inf) finite (alpha clamped to [ALPHA_MIN, ALPHA_MAX] as in [`ggx::d`](crate::ggx::d)).
#[inline]
#[must_use]
pub fn pdf<T: Real>(dir: V3<T>, alpha: T) -> T {
    // dir = -z has no half vector; any horizontal one has D = 0, the limit from most sides.
    let h = V3::new(dir.x, dir.y, T::ONE + dir.z).normalize_or(V3::new(T::ONE, T::ZERO, T::ZERO));
    let d = Ggx::new_unchecked(alpha, alpha).d(h);
    // A zero-length dir is no direction: pdf 0 (its h would be +z, the peak).
    let d = T::select(crate::vec3::is_zero3(dir), T::ZERO, d);
    nan_where(any_nonfinite3(dir), d * T::splat(0.25))
}

/// The prefilter sample drawn from the uniform pair (u1, u2): the half vector h from D(h) n.h
/// ([`sampling::ggx_d_cos`]: cos(theta_h) = sqrt((1 - u1) / (1 + (alpha^2 - 1) u1)),
/// phi_h = 2 pi u2, up to a half turn about z), reflected to l = 2 h.z h - z, with weight
/// max(0, l.z) and pdf D(h) / 4.
///
/// u outside [0, 1) is clamped into it. NaN in u1, u2 or alpha, or alpha outside [0, +inf)
/// finite, gives a NaN direction, weight and pdf.
#[inline]
#[must_use]
pub fn sample_from<T: Real>(u1: T, u2: T, alpha: T) -> PrefilterSample<T> {
    let (h, _) = sampling::ggx_d_cos(&Ggx::new_unchecked(alpha, alpha), u1, u2);
    let two_hz = T::TWO * h.z;
    let dir = V3::new(two_hz * h.x, two_hz * h.y, two_hz.mul_add(h.z, -T::ONE));
    // D(h) / 4 on the vector h, which never divides by a small cosine (the sampler's own pdf
    // D(h) h.z would need / (4 h.z)), and never forms 1 - h.z^2 (see [`pdf`]).
    let pdf = nan_where(
        any_nonfinite3(h),
        Ggx::new_unchecked(alpha, alpha).d(h) * T::splat(0.25),
    );
    PrefilterSample {
        dir,
        weight: above(dir.z, dir.z),
        pdf,
    }
}

/// Prefilter sample `i` of `n` for GGX width `alpha`: [`sample_from`] at the Hammersley point
/// ([`hammersley`]`(i, n)`: u1 = radical_inverse_2(i) picks theta_h, u2 = i / n picks phi_h,
/// as in Karis 2013). Deterministic: the same (i, n, alpha) gives the same bits.
/// i >= n gives a NaN sample.
#[inline]
#[must_use]
pub fn sample<T: Real>(i: u32, n: u32, alpha: T) -> PrefilterSample<T> {
    let (u1, u2) = hammersley(i, n);
    sample_from(T::splat(u1), T::splat(u2), alpha)
}

/// The `n` samples `sample(0, n, alpha)`, ..., `sample(n - 1, n, alpha)`, without allocating.
pub fn samples<T: Real>(n: u32, alpha: T) -> impl Iterator<Item = PrefilterSample<T>> {
    (0..n).map(move |i| sample(i, n, alpha))
}

/// Writes `sample(i, N, alpha)` into `out[i]` with N = `out.len()` and returns the sum of the
/// weights, sum_i max(0, n.l_i): the normalisation a prefilter divides by (Karis 2013's
/// `TotalWeight`), so that L_pre = sum_i L(l_i) weight_i / total. The total is > 0 for every
/// N >= 1 (sample 0 has u1 = 0, hence h = l = +z and weight 1). Entries past index
/// u32::MAX - 1 are NaN samples; an empty slice returns 0.
pub fn fill<T: Real>(out: &mut [PrefilterSample<T>], alpha: T) -> T {
    let n = u32::try_from(out.len()).unwrap_or(u32::MAX);
    let mut total = T::ZERO;
    for (i, slot) in out.iter_mut().enumerate() {
        let i = u32::try_from(i).unwrap_or(u32::MAX);
        *slot = sample(i, n, alpha);
        total += slot.weight;
    }
    total
}

/// log2(6 / (4 pi)) = log2(3 / (2 pi)): the cube's mean texel solid angle 4 pi / (6 w^2)
/// without w.
const LOG2_3_OVER_2PI: f64 = -1.066_533_628_751_162_6;

/// Mip level for a sample of density `pdf` in filtered importance sampling (Krivanek and
/// Colbert 2008, "Real-time Shading with Filtered Importance Sampling", EGSR; also Colbert
/// and Krivanek 2007, GPU Gems 3 ch. 20, section 20.4 "Mipmap Filtered Samples"):
///
/// lod = max(0, 0.5 log2(Omega_s / Omega_p) + 1),
/// Omega_s = 1 / (N pdf) (the solid angle one of the N samples stands for),
/// Omega_p = 4 pi / (6 w^2) (a texel of a cube with w x w faces, averaged over the sphere).
///
/// The 0.5 turns a solid-angle ratio into a texel-width ratio (each mip halves the width);
/// the +1 is the one-level bias of the source, which trades a little blur for less noise.
/// Engines port it as written (Sascha Willems' Vulkan PBR prefilter shader keeps the + 1,
/// LearnOpenGL's drops it). Omega_p is a mean: texels at a face's corners subtend
/// 3^1.5 = 5.2 times less than at its centre, so the level is about 1.2 too low there.
///
/// Evaluated as log2(w) + 0.5 (log2(3 / (2 pi)) - log2(N) - log2(pdf)) + 1, which never
/// forms w^2 or N pdf (no overflow for any finite w, N, pdf). Domain: pdf >= 0 finite (a
/// pdf of `T::MAX` gives level 0; +inf is out of every domain, crate docs "Bad input", rule
/// 5), `sample_count` N >= 1 finite, `face_size` w >= 1 finite (texels), all
/// floats so the function runs on lanes; the caller clamps the result to its mip count.
/// pdf = 0 gives the largest finite value (an infinitely coarse level). NaN for NaN input or
/// any argument outside its domain.
#[inline]
#[must_use]
pub fn mip_level<T: Real>(pdf: T, sample_count: T, face_size: T) -> T {
    let log2 = |x: T| x.ln() * T::splat(core::f64::consts::LOG2_E);
    let lod = log2(face_size)
        + T::HALF * (T::splat(LOG2_3_OVER_2PI) - log2(sample_count) - log2(pdf))
        + T::ONE;
    let ok = pdf.simd_ge(T::ZERO)
        & pdf.simd_lt(T::INFINITY)
        & sample_count.simd_ge(T::ONE)
        & sample_count.is_finite()
        & face_size.simd_ge(T::ONE)
        & face_size.is_finite();
    crate::domain::nan_unless(ok, lod.max(T::ZERO).min(T::MAX))
}
