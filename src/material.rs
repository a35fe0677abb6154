//! The metallic-roughness material of glTF 2.0, Unreal Engine 4 and Filament: one GGX specular
//! lobe and one Lambertian diffuse lobe, driven by a base colour, a metallic weight and a
//! perceptual roughness; evaluation in RGB and one-sample lobe-selection sampling.
//!
//! # The BRDF
//! With w = (1 - v.h)^5, alpha = roughness^2 (floored at
//! [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN)), D = [`ggx::d`] and V = [`ggx::v_correlated`]
//! (height-correlated Smith visibility G2 / (4 n.v n.l)):
//!
//! ```text
//! F_metal      = base + (1 - base) w                       Schlick, F0 = base colour
//! F_dielectric = F0_d + (F90_d - F0_d) w                   F0_d = 0.04, F90_d = 1 by default
//! F            = (1 - metallic) F_dielectric + metallic F_metal
//!              = Schlick(lerp(F0_d, base, metallic), lerp(F90_d, 1, metallic), v.h)
//! f            = kd base / pi + F D V                       per RGB channel
//! ```
//!
//! and the diffuse weight kd chosen by [`DiffuseCoupling`]:
//!
//! | coupling | kd | used by |
//! |---|---|---|
//! | [`Gltf`](DiffuseCoupling::Gltf) | (1 - metallic)(1 - max_rgb F_dielectric) | glTF 2.0 Appendix B, KHR_materials_specular |
//! | [`OneMinusF`](DiffuseCoupling::OneMinusF) | (1 - metallic)(1 - F), per channel | many engines; glTF 2.0 before its 2021 rewrite (which also scaled base by 0.96) |
//! | [`Additive`](DiffuseCoupling::Additive) | (1 - metallic) | Karis 2013 (UE4), Filament |
//!
//! ## glTF 2.0, Appendix B
//! The specification composes the material as `mix(dielectric_brdf, metal_brdf, metallic)`
//! with `metal_brdf = specular_brdf(alpha) * F_metal` and
//! `dielectric_brdf = mix(diffuse_brdf(base), specular_brdf(alpha), F_dielectric)`. Expanding
//! gives exactly the [`Gltf`](DiffuseCoupling::Gltf) row above: the specular terms combine to
//! F D V with F0 = lerp(0.04, base, metallic), and the diffuse term keeps the weight
//! (1 - metallic)(1 - F_dielectric). The often-quoted combined form with
//! kd = (1 - F)(1 - metallic) ([`OneMinusF`](DiffuseCoupling::OneMinusF)) agrees with it at
//! metallic 0 and 1 only: in between its diffuse term is lower by
//! metallic (1 - metallic) (base - 0.04)(1 - w) base / pi, up to 0.076 at base = 1,
//! metallic = 0.5, v.h = 1 (`cargo test --test material gltf_composition:: -- --nocapture`
//! checks both statements to 4e-15 of D V + base / pi). The specification's own combined
//! listing mixed the two Fresnel terms this way until its 2024 revision, which replaced it
//! with the composition above.
//!
//! ## Energy
//! The white metal (base = 1, metallic = 1, so F = 1) conserves energy but loses the light that
//! scatters more than once between microfacets: its directional albedo is 1 - ln 2 = 0.307 at
//! roughness 1 and normal view (a loss of 0.69), 0.916 at roughness 0.5.
//! No coupling conserves energy for a white dielectric (base = 1, metallic = 0): the diffuse
//! weight uses the Fresnel factor of the half vector, or none, not the energy the specular lobe
//! actually removes. Measured directional albedo:
//! [`Gltf`](DiffuseCoupling::Gltf) and [`OneMinusF`](DiffuseCoupling::OneMinusF) (equal at
//! metallic 0): <= 1 up to 30 degrees, above 1 from about 60 degrees, up to 1.85 at 89 degrees
//! on a smooth surface; a glTF dielectric conserves energy at every angle only for base colours
//! up to 0.087. [`Additive`](DiffuseCoupling::Additive): exactly 1 + the specular albedo, 1.04
//! at normal view and up to 1.92 at 89 degrees (`cargo test --test material energy:: --
//! --nocapture` prints the tables). The glTF specification says as much ("breaks ... energy
//! conservation") and points to Kulla and Conty 2017 for a coupling that conserves it.
//!
//! Every coupling here is reciprocal: v.h = l.h, so kd and F are symmetric in the two
//! directions (`cargo test --test material reciprocity::`).
//!
//! ## Parameters
//! `roughness` is the perceptual roughness r in [0, 1]: glTF's `roughnessFactor` (times the
//! texture's green channel), Unreal Engine 4's material `Roughness`, Filament's
//! `perceptualRoughness`. The GGX kernels take alpha = r^2 ([`alpha_from_perceptual`]), which
//! is what Filament's shader functions call `roughness`: to feed this module from Filament's
//! shading code, pass its perceptual value, not its `roughness`. (Filament also clamps r to
//! at least 0.045 on desktop; this module floors alpha at
//! [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN) = 1e-4, r = 0.01.)
//!
//! [`MetallicRoughness`] validates its parameters once ([`ParamError`] names the one out of
//! range) and evaluates from local-frame directions; the free functions [`metallic_roughness`]
//! and [`gltf`] take dot products (the shader form) and validate nothing (out-of-range
//! parameters give NaN).
//!
//! Sources: The Khronos Group, "glTF 2.0 Specification", Appendix B "BRDF Implementation";
//! "KHR_materials_specular" (ratified extension); Karis 2013, "Real Shading in Unreal Engine 4"
//! (SIGGRAPH course); Guy and Agopian, "Physically Based Rendering in Filament" (Google), sections
//! 4.4 and 4.8; Burley 2012, "Physically-Based Shading at Disney" (alpha = roughness^2).

use crate::cook_torrance::half_vector;
use crate::domain::{above_horizon, finite_dirs, in_unit, nan_unless, nan_where};
use crate::error::{ParamError, require};
use crate::ggx::{self, Ggx};
use crate::microfacet::alpha_from_perceptual;
use crate::real::Real;
use crate::sampling;
use crate::shading::{Cosines, ShadingPoint};
use crate::vec3::{V3, any_nonfinite3};

/// F0 of the glTF 2.0 dielectric: ((1.5 - 1) / (1.5 + 1))^2 = 0.04, the index of refraction
/// 1.5 of most dielectrics (glTF 2.0 Appendix B; Karis 2013 and Filament's default
/// reflectance 0.5 give the same value).
pub const GLTF_DIELECTRIC_F0: f64 = 0.04;

/// Smallest probability [`MetallicRoughness::specular_probability`] gives a lobe that is not
/// identically zero. Why 1/16: a one-sample estimator divides by the probability of the lobe it
/// picked, so a lobe that the albedo estimate undervalues (the diffuse lobe seen at grazing
/// angles, whose weight depends on v.h and not on n.v) would otherwise be picked rarely and
/// weighted by up to 1 / P: the floor caps that factor at 16 while costing at most 1/16 of
/// the samples when the estimate is right.
pub const LOBE_PROBABILITY_MIN: f64 = 1.0 / 16.0;

/// The cosine-weighted hemispherical average of (1 - c)^5: integral of (1 - c)^5 2c dc over
/// [0, 1] = 1/21. The diffuse lobe sees v.h spread over its whole hemisphere, so its albedo
/// estimate uses the Fresnel factor at this average instead of at n.v.
pub(crate) const SCHLICK_WEIGHT_AVERAGE: f64 = 1.0 / 21.0;

/// How the diffuse lobe is weighted against the specular one. See the [module docs](self) for
/// the formulas and the energy each one gains or loses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum DiffuseCoupling {
    /// kd = (1 - metallic)(1 - max_rgb F_dielectric(v.h)): glTF 2.0 Appendix B
    /// (`fresnel_mix`), with KHR_materials_specular's `max_value` for a coloured dielectric F0.
    /// Reciprocal; a white dielectric reflects up to 1.85 at grazing view.
    #[default]
    Gltf,
    /// kd = (1 - metallic)(1 - F(v.h)) per channel, F the metallic-mixed Fresnel: the combined
    /// form of many engines. Reciprocal. Equal to
    /// [`Gltf`](DiffuseCoupling::Gltf) at metallic 0 and 1 with an uncoloured specular,
    /// darker in between.
    OneMinusF,
    /// kd = 1 - metallic, no Fresnel weight: Karis 2013 (UE4) and Filament add the two lobes.
    /// Reciprocal; the diffuse lobe ignores the light the specular reflects, so a white
    /// dielectric reflects 1 + the specular albedo (1.04 at normal view, 1.92 at 89 degrees).
    Additive,
}

/// F0 from Filament's reflectance parameter: F0 = 0.16 reflectance^2, so reflectance 0.5 gives
/// 0.04 (IOR 1.5) and 1 gives 0.16 (IOR 2.33, gemstones) (Guy and Agopian, "Physically Based
/// Rendering in Filament", section 4.8.3.2). Domain reflectance in [0, 1]; NaN outside and for
/// NaN.
/// Unreal's `Specular` input s is the linear form F0 = 0.08 s (Karis 2013).
#[inline]
#[must_use]
pub fn f0_from_reflectance<T: Real>(reflectance: T) -> T {
    nan_unless(
        in_unit(reflectance),
        T::splat(0.16) * reflectance * reflectance,
    )
}

/// `(1 - t) a + t b`: exactly a at t = 0 and exactly b at t = 1.
#[inline]
fn lerp<T: Real>(a: T, b: T, t: T) -> T {
    (T::ONE - t) * a + t * b
}

/// Channel-wise product.
#[inline]
fn mul_rgb<T: Real>(a: V3<T>, b: V3<T>) -> V3<T> {
    V3::new(a.x * b.x, a.y * b.y, a.z * b.z)
}

/// Every channel in [0, 1] (false for NaN).
#[inline]
fn in_unit_rgb<T: Real>(c: V3<T>) -> T::Mask {
    in_unit(c.x) & in_unit(c.y) & in_unit(c.z)
}

/// The Schlick weight w = (1 - c)^5 and its complement 1 - w = c (1 + s + s^2 + s^3 + s^4)
/// with s = 1 - c, for c = v.h clamped to [0, 1]. The complement is a sum of positive terms:
/// 1 - (1 - c)^5 evaluated as written loses every digit as c -> 0 (1 - w = 5c + ...), and
/// with it the diffuse weight kd = 1 - F at grazing half vectors (the f32 form stays within
/// the material's 12-ulp bound against f64: `cargo test --test material stability:: --
/// --nocapture`).
#[inline]
pub(crate) fn schlick_weights<T: Real>(c: T) -> (T, T) {
    let c = c.saturate();
    let s = T::ONE - c;
    let s2 = s * s;
    let w = s2 * s2 * s;
    let one_minus_w = c * s.mul_add(s.mul_add(s.mul_add(s + T::ONE, T::ONE), T::ONE), T::ONE);
    (w, one_minus_w)
}

/// `a (1 - w) + b w` with both weights given (so that 1 - w is accurate).
#[inline]
fn mix2<T: Real>(a: T, b: T, w: T, one_minus_w: T) -> T {
    a.mul_add(one_minus_w, b * w)
}

/// The mixed Fresnel F and the diffuse weight kd for the Schlick weights (w, 1 - w).
///
/// 1 - F is formed from the complements, 1 - F_dielectric = (1 - F0_d)(1 - w) +
/// (1 - F90_d) w and 1 - F_metal = (1 - base)(1 - w), never as 1 - F: F rounds to within an
/// ulp of 1 at grazing half vectors and for F0 near 1, where the subtraction would cancel.
#[inline]
pub(crate) fn fresnel_and_kd<T: Real>(
    weights: (T, T),
    base: V3<T>,
    metallic: T,
    f0_d: V3<T>,
    f90_d: T,
    coupling: DiffuseCoupling,
) -> (V3<T>, V3<T>) {
    fresnel_and_kd_film(weights, base, metallic, f0_d, f90_d, coupling, None)
}

/// A thin film's reflectance replacing the Schlick Fresnel terms of
/// [`fresnel_and_kd_film`] (KHR_materials_iridescence): the factor in [0, 1], the film's RGB
/// reflectance over the dielectric base and over the metal base.
pub(crate) type Film<T> = (T, V3<T>, V3<T>);

/// [`fresnel_and_kd`] with each lobe's Fresnel mixed towards a thin film's reflectance by its
/// factor f (KHR_materials_iridescence, "Implementation Notes"):
/// F_dielectric' = mix(F_dielectric, F_film_d, f), F_metal' = mix(F_metal, F_film_m, f), and
/// the complements alike, mix(1 - F, 1 - F_film, f), so kd follows the coupling's rule from
/// the mixed Fresnel (glTF: 1 - max_rgb F_dielectric', the extension's `rgb_mix`). Where
/// f = 0 each term is selected unmixed: the result is [`fresnel_and_kd`]'s bit for bit.
#[inline]
pub(crate) fn fresnel_and_kd_film<T: Real>(
    (w, one_minus_w): (T, T),
    base: V3<T>,
    metallic: T,
    f0_d: V3<T>,
    f90_d: T,
    coupling: DiffuseCoupling,
    film: Option<Film<T>>,
) -> (V3<T>, V3<T>) {
    let one_minus_m = T::ONE - metallic;
    let channel = |base: T, f0: T, film_d: T, film_m: T| {
        let mut f_dielectric = mix2(f0, f90_d, w, one_minus_w);
        let mut f_metal = mix2(base, T::ONE, w, one_minus_w);
        let mut g_dielectric = mix2(T::ONE - f0, T::ONE - f90_d, w, one_minus_w);
        let mut g_metal = (T::ONE - base) * one_minus_w;
        if let Some((factor, _, _)) = film {
            let off = factor.simd_eq(T::ZERO);
            let mix = |a: T, b: T| T::select(off, a, lerp(a, b, factor));
            f_dielectric = mix(f_dielectric, film_d);
            g_dielectric = mix(g_dielectric, T::ONE - film_d);
            f_metal = mix(f_metal, film_m);
            g_metal = mix(g_metal, T::ONE - film_m);
        }
        (
            lerp(f_dielectric, f_metal, metallic),
            lerp(g_dielectric, g_metal, metallic),
            g_dielectric,
        )
    };
    let (fd, fm) = match film {
        Some((_, d, m)) => (d, m),
        None => (V3::splat(T::ZERO), V3::splat(T::ZERO)),
    };
    let (fx, gx, dx) = channel(base.x, f0_d.x, fd.x, fm.x);
    let (fy, gy, dy) = channel(base.y, f0_d.y, fd.y, fm.y);
    let (fz, gz, dz) = channel(base.z, f0_d.z, fd.z, fm.z);
    let kd = match coupling {
        // 1 - max_rgb F_dielectric = min_rgb (1 - F_dielectric).
        DiffuseCoupling::Gltf => V3::splat(one_minus_m * dx.min(dy).min(dz)),
        DiffuseCoupling::OneMinusF => V3::new(gx, gy, gz) * one_minus_m,
        DiffuseCoupling::Additive => V3::splat(one_minus_m),
    };
    (V3::new(fx, fy, fz), kd)
}

/// The unvalidated kernel: kd base / pi + F D V per channel, 0 below the horizon, NaN for a
/// NaN cosine or where `nan` is set. D is [`ggx::d`], or [`ggx::d_fast`] when `FAST`.
#[allow(clippy::too_many_arguments)]
#[inline]
fn kernel<T: Real, const FAST: bool>(
    n_dot_v: T,
    n_dot_l: T,
    n_dot_h: T,
    v_dot_h: T,
    base: V3<T>,
    metallic: T,
    alpha: T,
    f0_d: V3<T>,
    f90_d: T,
    coupling: DiffuseCoupling,
    nan: T::Mask,
) -> V3<T> {
    let (f, kd) = fresnel_and_kd(
        schlick_weights(v_dot_h),
        base,
        metallic,
        f0_d,
        f90_d,
        coupling,
    );
    // D and V are each finite, but their product overflows where both cosines are subnormal
    // and alpha is at its floor: capped at MAX, as the crate caps every pole.
    let d = if FAST {
        ggx::d_fast(n_dot_h, alpha)
    } else {
        ggx::d(n_dot_h, alpha)
    };
    let dv = (d * ggx::v_correlated(n_dot_v, n_dot_l, alpha)).min(T::MAX);
    let diffuse = mul_rgb(kd, base) * T::FRAC_1_PI;
    // ggx::d turns a NaN n.h into 0 (its horizon select): put the NaN back.
    let nan = nan | n_dot_h.is_nan() | v_dot_h.is_nan();
    let channel = |fc: T, dc: T| {
        let value = above_horizon(n_dot_v, n_dot_l, fc.mul_add(dv, dc).min(T::MAX));
        nan_unless(!nan, value)
    };
    V3::new(
        channel(f.x, diffuse.x),
        channel(f.y, diffuse.y),
        channel(f.z, diffuse.z),
    )
}

/// The metallic-roughness BRDF from dot products (the shader form): RGB
/// f = kd base_color / pi + F D V with F = Schlick(lerp(F0_d, base_color, metallic), v.h),
/// D = [`ggx::d`], V = [`ggx::v_correlated`], alpha = [`alpha_from_perceptual`]`(roughness)`,
/// and kd from `coupling` (see the [module docs](self)). F90 of the dielectric is 1; use
/// [`MetallicRoughness`] for KHR_materials_specular's coloured F0 and F90.
///
/// Arguments: the shading point's [`Cosines`] (n.v, n.l, n.h and v.h of unit vectors, from
/// [`Cosines::from_world`], a [`ShadingPoint`] or a struct literal); `base_color` with each
/// channel in [0, 1]; `metallic` in [0, 1]; perceptual `roughness` in [0, 1] (glTF's
/// `roughnessFactor`, not alpha: alpha = roughness^2 is formed here);
/// `dielectric_f0` in [0, 1] (0.04 = [`GLTF_DIELECTRIC_F0`] for glTF, [`f0_from_reflectance`]
/// for Filament, [`fresnel::f0_from_ior`](crate::fresnel::f0_from_ior) from an IOR).
///
/// Edges: 0 where n.v <= 0 or n.l <= 0; NaN where any input is NaN or any parameter lies
/// outside its domain (in every case, above or below the horizon); n.h and v.h are clamped
/// to [0, 1] (n.h <= 0 gives D = 0). Roughness 0 is the floored alpha
/// [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN), finite everywhere: where both cosines are
/// near 0 (subnormal in f32) D V and f are capped at the largest finite value, never inf
/// (`cargo test --test material stability:: -- --nocapture` sweeps the parameter extremes).
///
/// Accuracy: f32 within 12 ulps (relative) of f64 on the same inputs, 5.6 measured over
/// cosines down to 1e-4; 1 - F is formed from complements, so grazing half vectors and F0
/// near 1 lose nothing to cancellation (`cargo test --test material stability:: -- --nocapture`).
///
/// Sources: glTF 2.0 Appendix B; Karis 2013, "Real Shading in Unreal Engine 4"; Guy and
/// Agopian, "Physically Based Rendering in Filament", section 4.6 (`BRDF` listing).
#[allow(clippy::too_many_arguments)]
#[inline]
#[must_use]
pub fn metallic_roughness<T: Real>(
    c: Cosines<T>,
    base_color: V3<T>,
    metallic: T,
    roughness: T,
    dielectric_f0: T,
    coupling: DiffuseCoupling,
) -> V3<T> {
    free_kernel::<T, false>(c, base_color, metallic, roughness, dielectric_f0, coupling)
}

/// [`metallic_roughness`] and [`metallic_roughness_fast`]: the parameter checks and the kernel.
#[inline]
fn free_kernel<T: Real, const FAST: bool>(
    c: Cosines<T>,
    base_color: V3<T>,
    metallic: T,
    roughness: T,
    dielectric_f0: T,
    coupling: DiffuseCoupling,
) -> V3<T> {
    let ok =
        in_unit_rgb(base_color) & in_unit(metallic) & in_unit(roughness) & in_unit(dielectric_f0);
    let f = kernel::<T, FAST>(
        c.n_dot_v,
        c.n_dot_l,
        c.n_dot_h,
        c.v_dot_h,
        base_color,
        metallic,
        alpha_from_perceptual(roughness),
        V3::splat(dielectric_f0),
        T::ONE,
        coupling,
        c.n_dot_v.is_nan(),
    );
    V3::new(
        nan_unless(ok, f.x),
        nan_unless(ok, f.y),
        nan_unless(ok, f.z),
    )
}

/// The glTF 2.0 metallic-roughness BRDF exactly as Appendix B composes it,
/// `mix(dielectric_brdf, metal_brdf, metallic)` with F0 = 0.04 (IOR 1.5): [`metallic_roughness`]
/// with [`GLTF_DIELECTRIC_F0`] and [`DiffuseCoupling::Gltf`]. Same domain and edges;
/// `roughness` is the material's `roughnessFactor` (perceptual, alpha = roughness^2 inside,
/// [`alpha_from_perceptual`]).
///
/// Source: The Khronos Group, "glTF 2.0 Specification", Appendix B "BRDF Implementation".
#[inline]
#[must_use]
pub fn gltf<T: Real>(c: Cosines<T>, base_color: V3<T>, metallic: T, roughness: T) -> V3<T> {
    metallic_roughness(
        c,
        base_color,
        metallic,
        roughness,
        T::splat(GLTF_DIELECTRIC_F0),
        DiffuseCoupling::Gltf,
    )
}

/// The working-precision tier of [`metallic_roughness`]: the same BRDF, domain, edges and bad
/// input, with [`ggx::d_fast`] in place of the correctly rounded [`ggx::d`] (V, F and the
/// diffuse weight are the same code). What a renderer evaluating millions of shading points on
/// lanes wants: the exact tier's D alone costs about 150 extra flops per evaluation.
///
/// Accuracy against [`metallic_roughness`] on the same inputs, per channel: within 12 ULP,
/// relative 7e-7 (f32) / 1.4e-15 (f64): D's relative error against [`ggx::d`] (5.3e-7 /
/// 9.1e-16, see [`ggx::d_fast`]) reaches f scaled by the specular share of f (at most 1),
/// plus one rounding of each tier. Measured over 3 million random points (cosines from 1e-6
/// to 1, base colour, metallic, roughness and F0 including 0 and 1) and the three couplings:
/// 9 ULP, relative 5.9e-7 (f32); 8 ULP, relative 1.1e-15 (f64). Lanes equal the scalar
/// results bit for bit (`BRDF_FAST_TIER_POINTS=3000000 cargo test --all-features --test
/// material fast_tier:: -- --nocapture`; 200 000 points by default).
///
/// Sources: as [`metallic_roughness`]; D as Filament's `D_GGX` (Guy and Agopian,
/// "Physically Based Rendering in Filament", section 4.4).
#[allow(clippy::too_many_arguments)]
#[inline]
#[must_use]
pub fn metallic_roughness_fast<T: Real>(
    c: Cosines<T>,
    base_color: V3<T>,
    metallic: T,
    roughness: T,
    dielectric_f0: T,
    coupling: DiffuseCoupling,
) -> V3<T> {
    free_kernel::<T, true>(c, base_color, metallic, roughness, dielectric_f0, coupling)
}

/// The working-precision tier of [`gltf`]: [`metallic_roughness_fast`] with
/// [`GLTF_DIELECTRIC_F0`] and [`DiffuseCoupling::Gltf`]. Same domain and edges; within 12 ULP
/// of [`gltf`] per channel (see [`metallic_roughness_fast`]).
///
/// Source: The Khronos Group, "glTF 2.0 Specification", Appendix B "BRDF Implementation".
#[inline]
#[must_use]
pub fn gltf_fast<T: Real>(c: Cosines<T>, base_color: V3<T>, metallic: T, roughness: T) -> V3<T> {
    metallic_roughness_fast(
        c,
        base_color,
        metallic,
        roughness,
        T::splat(GLTF_DIELECTRIC_F0),
        DiffuseCoupling::Gltf,
    )
}

/// Validated metallic-roughness material parameters, with evaluation and sampling on
/// local-frame directions (normal = +z, both directions pointing away from the surface).
///
/// Built by [`MetallicRoughness::new`] with the glTF 2.0 defaults (IOR 1.5, specular factor
/// and colour 1, [`DiffuseCoupling::Gltf`]) and adjusted by the `with_*` methods, each of
/// which validates its own argument:
///
/// ```
/// use brdf::V3;
/// use brdf::material::{DiffuseCoupling, MetallicRoughness};
///
/// let gold = MetallicRoughness::new(V3::new(1.0, 0.766, 0.336), 1.0, 0.3)?;
/// let plastic = MetallicRoughness::new(V3::new(0.8, 0.1, 0.1), 0.0, 0.5)?
///     .with_reflectance(0.5)? // Filament: F0 = 0.16 * 0.5^2 = 0.04
///     .with_coupling(DiffuseCoupling::Additive);
/// let (wo, wi) = (V3::new(0.0, 0.6, 0.8), V3::new(0.0, -0.6, 0.8));
/// let rgb = plastic.eval(wo, wi);
/// assert!(rgb.x > rgb.y);
/// assert!(MetallicRoughness::new(V3::splat(1.2), 0.0, 0.5).is_err());
/// # let _ = gold;
/// # Ok::<(), brdf::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MetallicRoughness<T> {
    base_color: V3<T>,
    metallic: T,
    roughness: T,
    alpha: T,
    ior_f0: T,
    specular: T,
    specular_color: V3<T>,
    coupling: DiffuseCoupling,
}

impl<T: Real> MetallicRoughness<T> {
    /// A glTF 2.0 material: `base_color` with each channel in [0, 1] (linear RGB), `metallic`
    /// in [0, 1], perceptual `roughness` in [0, 1] (glTF's `roughnessFactor`, Unreal Engine 4's
    /// `Roughness`; alpha = roughness^2 by [`alpha_from_perceptual`], floored at
    /// [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN)), dielectric F0 = 0.04 (IOR 1.5), no
    /// KHR_materials_specular adjustment, [`DiffuseCoupling::Gltf`]. A value outside its domain
    /// in any lane (NaN included) is a [`ParamError`] naming `base_color`, `metallic` or
    /// `roughness`.
    pub fn new(base_color: V3<T>, metallic: T, roughness: T) -> Result<Self, ParamError> {
        require::<T>(
            in_unit_rgb(base_color),
            "base_color",
            "each channel in [0, 1]",
        )?;
        require::<T>(in_unit(metallic), "metallic", "in [0, 1]")?;
        require::<T>(in_unit(roughness), "roughness", "in [0, 1]")?;
        Ok(Self {
            base_color,
            metallic,
            roughness,
            alpha: alpha_from_perceptual(roughness),
            ior_f0: T::splat(GLTF_DIELECTRIC_F0),
            specular: T::ONE,
            specular_color: V3::splat(T::ONE),
            coupling: DiffuseCoupling::Gltf,
        })
    }

    /// The dielectric's F0 from its index of refraction: F0 = ((ior - 1) / (ior + 1))^2
    /// (KHR_materials_ior with the outside medium air). `ior` finite and >= 1, else
    /// [`ParamError`] (`"ior"`). KHR_materials_ior's special value 0 (F0 = 1, used to convert
    /// specular-glossiness materials) is [`with_dielectric_f0`](Self::with_dielectric_f0)`(1)`.
    pub fn with_ior(self, ior: T) -> Result<Self, ParamError> {
        require::<T>(
            ior.simd_ge(T::ONE) & ior.is_finite(),
            "ior",
            "finite and >= 1",
        )?;
        Ok(Self {
            ior_f0: crate::fresnel::f0_from_ior(ior),
            ..self
        })
    }

    /// The dielectric's F0 given directly, in [0, 1], else [`ParamError`]
    /// (`"dielectric_f0"`). Unreal's `Specular` input s is F0 = 0.08 s (Karis 2013).
    pub fn with_dielectric_f0(self, f0: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(f0), "dielectric_f0", "in [0, 1]")?;
        Ok(Self { ior_f0: f0, ..self })
    }

    /// The dielectric's F0 from Filament's reflectance in [0, 1], else [`ParamError`]
    /// (`"reflectance"`): F0 = 0.16 reflectance^2 ([`f0_from_reflectance`]). Filament's full
    /// F0, 0.16 reflectance^2 (1 - metallic) + base_color metallic, is what
    /// [`eval`](Self::eval) computes from it.
    pub fn with_reflectance(self, reflectance: T) -> Result<Self, ParamError> {
        require::<T>(in_unit(reflectance), "reflectance", "in [0, 1]")?;
        Ok(Self {
            ior_f0: f0_from_reflectance(reflectance),
            ..self
        })
    }

    /// KHR_materials_specular: the dielectric's F0 becomes
    /// min(F0_ior specular_color, 1) specular per channel and its F90 becomes `specular`; the
    /// metal is unchanged. `specular` in [0, 1] (`"specular"`), `specular_color` with each
    /// channel finite and >= 0 (`"specular_color"`): the extension allows colours above 1 so
    /// that F0 can exceed the IOR's, the min(., 1) keeps it a reflectance.
    ///
    /// With [`DiffuseCoupling::Gltf`] the diffuse weight is 1 - max_rgb(F_dielectric), the
    /// extension's `max_value`.
    ///
    /// Source: The Khronos Group, "KHR_materials_specular" (ratified), section
    /// "Implementation".
    pub fn with_specular(self, specular: T, specular_color: V3<T>) -> Result<Self, ParamError> {
        require::<T>(in_unit(specular), "specular", "in [0, 1]")?;
        let ok = |c: T| c.simd_ge(T::ZERO) & c.is_finite();
        require::<T>(
            ok(specular_color.x) & ok(specular_color.y) & ok(specular_color.z),
            "specular_color",
            "each channel finite and >= 0",
        )?;
        Ok(Self {
            specular,
            specular_color,
            ..self
        })
    }

    /// The same material with another diffuse coupling.
    #[must_use]
    pub fn with_coupling(self, coupling: DiffuseCoupling) -> Self {
        Self { coupling, ..self }
    }

    /// The base colour.
    #[inline]
    #[must_use]
    pub fn base_color(&self) -> V3<T> {
        self.base_color
    }

    /// The metallic weight.
    #[inline]
    #[must_use]
    pub fn metallic(&self) -> T {
        self.metallic
    }

    /// The perceptual roughness r, as given (alpha = r^2 is [`alpha`](Self::alpha)).
    #[inline]
    #[must_use]
    pub fn roughness(&self) -> T {
        self.roughness
    }

    /// The GGX alpha the kernels use: roughness^2 ([`alpha_from_perceptual`]), floored at
    /// [`ALPHA_MIN`](crate::microfacet::ALPHA_MIN): the value to pass to [`ggx::d`] and
    /// [`ggx::v_correlated`], and Filament's shader `roughness`.
    #[inline]
    #[must_use]
    pub fn alpha(&self) -> T {
        self.alpha
    }

    /// The dielectric's F0 per channel: min(F0_ior specular_color, 1) specular (0.04 for the
    /// glTF defaults).
    #[inline]
    #[must_use]
    pub fn dielectric_f0(&self) -> V3<T> {
        let c = |s: T| (self.ior_f0 * s).min(T::ONE) * self.specular;
        V3::new(
            c(self.specular_color.x),
            c(self.specular_color.y),
            c(self.specular_color.z),
        )
    }

    /// The dielectric's F90: the specular factor (1 for the glTF defaults).
    #[inline]
    #[must_use]
    pub fn dielectric_f90(&self) -> T {
        self.specular
    }

    /// The diffuse coupling.
    #[inline]
    #[must_use]
    pub fn coupling(&self) -> DiffuseCoupling {
        self.coupling
    }

    /// The BRDF f(wo, wi) in RGB (not multiplied by the cosine): the formula of the
    /// [module docs](self) with h = normalize(wo + wi). 0 where wo.z <= 0 or wi.z <= 0; NaN
    /// where a component of wo or wi is NaN or infinite.
    #[inline]
    #[must_use]
    pub fn eval(&self, wo: V3<T>, wi: V3<T>) -> V3<T> {
        self.eval_tier::<false>(wo, wi)
    }

    /// [`eval`](Self::eval) in the working-precision tier ([`metallic_roughness_fast`]'s D):
    /// the same BRDF, edges and bad input, within 12 ULP of [`eval`](Self::eval) per channel
    /// (see [`metallic_roughness_fast`]).
    #[inline]
    #[must_use]
    pub fn eval_fast(&self, wo: V3<T>, wi: V3<T>) -> V3<T> {
        self.eval_tier::<true>(wo, wi)
    }

    /// [`eval`](Self::eval) or, when `FAST`, [`eval_fast`](Self::eval_fast).
    #[inline]
    fn eval_tier<const FAST: bool>(&self, wo: V3<T>, wi: V3<T>) -> V3<T> {
        let (h, v_dot_h) = half_vector(wo, wi);
        kernel::<T, FAST>(
            wo.z,
            wi.z,
            h.z,
            v_dot_h,
            self.base_color,
            self.metallic,
            self.alpha,
            self.dielectric_f0(),
            self.dielectric_f90(),
            self.coupling,
            // A NaN tangent component would vanish in the half vector's normalization
            // fallback, an infinite one normalize to a plausible axis (rules 1 and 5).
            any_nonfinite3(wo) | any_nonfinite3(wi),
        )
    }

    /// The isotropic GGX of the specular lobe.
    #[inline]
    fn ggx(&self) -> Ggx<T> {
        Ggx::new_unchecked(self.alpha, self.alpha)
    }

    /// Probability of sampling the specular lobe for the view `wo`: P = S / (S + D), the
    /// lobes' estimated albedos, then kept in [1/16, 15/16] ([`LOBE_PROBABILITY_MIN`]) unless
    /// a lobe is identically zero (P = 1 without diffuse, 0 without specular).
    ///
    /// S = the mean over channels of the mixed Fresnel F at n.v (the specular lobe's albedo for
    /// a smooth surface, ignoring the shadowing loss of rough ones). D = the mean over channels
    /// of kd base_color, with kd evaluated at the Schlick weight 1/21, the cosine-weighted
    /// hemispherical average of (1 - c)^5: the diffuse lobe sees v.h spread over its whole
    /// hemisphere, not n.v, so at grazing view its weight stays near its average while F(n.v)
    /// goes to 1. NaN where a component of wo is NaN or infinite.
    #[inline]
    #[must_use]
    pub fn specular_probability(&self, wo: V3<T>) -> T {
        let (f0_d, f90_d) = (self.dielectric_f0(), self.dielectric_f90());
        let mean = |c: V3<T>| (c.x + c.y + c.z) * T::splat(1.0 / 3.0);
        let (f, _) = fresnel_and_kd(
            schlick_weights(wo.z),
            self.base_color,
            self.metallic,
            f0_d,
            f90_d,
            self.coupling,
        );
        let (_, kd) = fresnel_and_kd(
            (
                T::splat(SCHLICK_WEIGHT_AVERAGE),
                T::splat(1.0 - SCHLICK_WEIGHT_AVERAGE),
            ),
            self.base_color,
            self.metallic,
            f0_d,
            f90_d,
            self.coupling,
        );
        let s = mean(f);
        let d = mean(mul_rgb(kd, self.base_color));
        let lo = T::splat(LOBE_PROBABILITY_MIN);
        let p = (s / (s + d)).clamp(lo, T::ONE - lo);
        // The specular lobe vanishes only for a non-metal with specular factor 0 (F90_d = 0
        // forces F0_d = 0); the diffuse lobe exactly where D = 0.
        let no_specular = self.metallic.simd_eq(T::ZERO) & f90_d.simd_eq(T::ZERO);
        let p = T::select(d.simd_eq(T::ZERO), T::ONE, p);
        let p = T::select(no_specular, T::ZERO, p);
        // The selects above would turn a NaN view into a plausible probability, and only wo.z
        // reaches them: a NaN in any component of wo gives NaN.
        nan_where(any_nonfinite3(wo), p)
    }

    /// The one-sample MIS pdf (solid angle) of [`sample`](Self::sample):
    /// pdf = P p_spec(wi) + (1 - P) p_diff(wi), with
    /// P = [`specular_probability`](Self::specular_probability),
    /// p_spec = D_wo(h) / (4 wo.h) for h = normalize(wo + wi) (GGX visible normals,
    /// [`sampling::visible_normal_pdf`] and [`sampling::reflect_pdf`]) and
    /// p_diff = max(0, wi.z) / pi.
    ///
    /// wi below the horizon: p_diff = 0 but p_spec is the density of the reflected visible
    /// normals there, so pdf integrates to 1 over the whole sphere and to
    /// 1 - P x (the fraction of specular samples reflected below the horizon) over the upper
    /// hemisphere (`cargo test --test material sampling:: -- --nocapture` prints both).
    ///
    /// A zero-length wo or wi is no direction: pdf 0 (so [`sample`](Self::sample) of a zero
    /// wo returns a finite direction with pdf 0, and [`sample_weighted`](Self::sample_weighted)
    /// weight 0). A NaN or infinite component of wo or wi gives NaN.
    #[inline]
    #[must_use]
    pub fn pdf(&self, wo: V3<T>, wi: V3<T>) -> T {
        let p = self.specular_probability(wo);
        let h = (wo + wi).normalize_or(V3::unit_z());
        let ggx = self.ggx();
        let p_spec = sampling::reflect_pdf(sampling::visible_normal_pdf(&ggx, wo, h), wo.dot(h));
        let p_diff = sampling::cosine_hemisphere_pdf(wi);
        // A zero-length wo or wi is no direction: pdf 0 (without this, 0 / 0 in P for wo and a
        // specular density about h = wo for wi).
        let zero = crate::vec3::is_zero3(wo) | crate::vec3::is_zero3(wi);
        let pdf = T::select(zero, T::ZERO, lerp(p_diff, p_spec, p));
        finite_dirs(wo, wi, pdf)
    }

    /// Draws wi for the view `wo` by one-sample lobe selection and returns (wi, pdf) with pdf
    /// = [`pdf`](Self::pdf)(wo, wi).
    ///
    /// `u1` picks the lobe and is then reused: u1 < P selects the specular lobe and passes
    /// u1 / P on, otherwise (u1 - P) / (1 - P) goes to the diffuse lobe, so each lobe still gets
    /// a uniform number in [0, 1) and a stratified or low-discrepancy u1 stays stratified
    /// within each lobe (at the cost of log2(1 / P) bits of u1's precision). Specular: a GGX
    /// visible normal m ([`sampling::ggx_vndf`], Heitz 2018) and wi = reflect(wo, m).
    /// Diffuse: [`sampling::cosine_hemisphere`].
    ///
    /// A specular wi can fall below the horizon (a visible normal tilted far from the normal
    /// reflects a grazing view downwards). It is returned as drawn, with its true pdf > 0;
    /// [`eval`](Self::eval) is 0 there, so its weight is 0 and the path ends (pbrt-v4 returns
    /// no sample in that case, which is the same estimator). wo at or below the horizon: the
    /// BRDF is 0 and every weight is 0. A NaN or infinite component of wo, or a NaN u1 or u2, gives a
    /// NaN direction and pdf.
    #[inline]
    #[must_use]
    pub fn sample(&self, wo: V3<T>, u1: T, u2: T) -> (V3<T>, T) {
        let p = self.specular_probability(wo);
        // u1 = 1 (outside [0, 1), but common) would select neither lobe when P = 1 and divide
        // 0 by 0 when P = 0: clamp it below 1 first, as the samplers do.
        let u1 = u1.clamp(T::ZERO, T::ONE - T::EPSILON * T::HALF);
        let specular = u1.simd_lt(p);
        let u_spec = u1 / p;
        let u_diff = (u1 - p) / (T::ONE - p);
        let u = T::select(specular, u_spec, u_diff);
        let (m, _) = sampling::ggx_vndf(&self.ggx(), wo, u, u2);
        let (wi_diff, _) = sampling::cosine_hemisphere(u, u2);
        let wi = V3::select(specular, wo.mirror(m), wi_diff);
        // A diffuse wi does not depend on wo: a NaN view must still give a NaN direction.
        let bad = any_nonfinite3(wo);
        let nan = T::splat(f64::NAN);
        let wi = V3::new(
            T::select(bad, nan, wi.x),
            T::select(bad, nan, wi.y),
            T::select(bad, nan, wi.z),
        );
        (wi, self.pdf(wo, wi))
    }

    /// [`sample`](Self::sample) with the Monte Carlo weight: (wi, pdf, f(wo, wi) wi.z / pdf)
    /// in RGB, the weight 0 where the pdf or the BRDF is 0 (wi below the horizon).
    #[inline]
    #[must_use]
    pub fn sample_weighted(&self, wo: V3<T>, u1: T, u2: T) -> (V3<T>, T, V3<T>) {
        let (wi, pdf) = self.sample(wo, u1, u2);
        let f = self.eval(wo, wi);
        let positive = pdf.simd_gt(T::ZERO);
        let scale = T::select(positive, wi.z.max(T::ZERO) / pdf, T::ZERO);
        (wi, pdf, f * scale)
    }

    /// [`eval`](Self::eval) from world space: f(v, l) for the shading point `sp` (its normal
    /// and view direction, [`ShadingPoint::new`], built once per pixel) and the world-space
    /// unit light direction `l`. Equal to `self.eval(sp.wo(), sp.local(l))`.
    ///
    /// ```
    /// use brdf::V3;
    /// use brdf::material::MetallicRoughness;
    /// use brdf::shading::ShadingPoint;
    ///
    /// let m = MetallicRoughness::new(V3::new(0.9, 0.6, 0.2), 1.0, 0.4)?;
    /// let (n, v) = (V3::new(0.0, 0.6, 0.8), V3::new(0.0, 0.0, 1.0));
    /// let sp = ShadingPoint::new(n, v);
    /// let l = V3::new(0.0, 0.96, 0.28); // the mirror direction of v about n
    /// let rgb: V3<f64> = m.eval_world(&sp, l) * n.dot(l);
    /// assert!(rgb.x > rgb.z && rgb.z > 0.0);
    /// # Ok::<(), brdf::ParamError>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn eval_world(&self, sp: &ShadingPoint<T>, l: V3<T>) -> V3<T> {
        self.eval(sp.wo(), sp.local(l))
    }

    /// [`pdf`](Self::pdf) from world space: the solid-angle pdf of drawing the world-space
    /// direction `l` at the shading point `sp` with [`sample_world`](Self::sample_world).
    #[inline]
    #[must_use]
    pub fn pdf_world(&self, sp: &ShadingPoint<T>, l: V3<T>) -> T {
        self.pdf(sp.wo(), sp.local(l))
    }

    /// [`sample`](Self::sample) in world space: (l, pdf) with l the drawn world-space
    /// direction, `sp.world(wi)` of the local sample.
    #[inline]
    #[must_use]
    pub fn sample_world(&self, sp: &ShadingPoint<T>, u1: T, u2: T) -> (V3<T>, T) {
        let (wi, pdf) = self.sample(sp.wo(), u1, u2);
        (sp.world(wi), pdf)
    }

    /// [`sample_weighted`](Self::sample_weighted) in world space: (l, pdf, f(v, l) n.l / pdf)
    /// with l in world space.
    #[inline]
    #[must_use]
    pub fn sample_weighted_world(&self, sp: &ShadingPoint<T>, u1: T, u2: T) -> (V3<T>, T, V3<T>) {
        let (wi, pdf, w) = self.sample_weighted(sp.wo(), u1, u2);
        (sp.world(wi), pdf, w)
    }
}
