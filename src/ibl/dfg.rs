//! The split-sum DFG term of GGX with height-correlated Smith: its quadrature, a table builder
//! and bilinear lookup, the analytic fits engines ship instead of the table, the split-sum
//! specular and the roughness-to-mip mappings of prefiltered radiance maps.
//!
//! # The split sum
//! Karis 2013 ("Real Shading in Unreal Engine 4", SIGGRAPH course notes) splits the specular
//! image-based lighting integral into a prefiltered radiance map times the directional albedo
//! of the specular lobe. With Schlick's F = F0 + (F90 - F0) Fc, Fc = (1 - v.h)^5, that albedo
//! is linear in F0 and F90:
//!
//! ```text
//! albedo(NoV, alpha) = integral D V F NoL dl = F0 A + F90 B
//! A = integral D V (1 - Fc) NoL dl        B = integral D V Fc NoL dl        E = A + B
//! ```
//!
//! with D the GGX NDF ([`crate::ggx::d`]) and V = G2 / (4 NoV NoL) the height-correlated Smith
//! visibility ([`crate::ggx::v_correlated`]; Heitz 2014; the form of Lagarde and de Rousiers
//! 2014, "Moving Frostbite to PBR", section 4.9, which tabulates the same two terms with
//! F90 = 1). E, the directional albedo with F = 1, is the third channel: the multiple-
//! scattering compensations need it (Kulla and Conty 2017's E(mu); Fdez-Aguera 2019 and
//! Turquin 2019 build theirs from A and B; Filament stores B and E, its `mix(dfg.x, dfg.y, f0)`
//! being (1 - F0) B + F0 E = F0 A + B).
//!
//! # Quadrature
//! [`dfg`] samples the distribution of visible normals (Dupuy and Benyoub 2023's spherical-cap
//! form of Heitz 2018, [`crate::sampling::ggx_vndf_spherical_cap`]) at the points of a
//! centred Hammersley set, reflects the view about each normal, and averages the weight
//! f cos / pdf = G2 / G1(v) = (1 + Lambda(v)) / (1 + Lambda(v) + Lambda(l)) times 1 - Fc or
//! Fc. The weight lies in [0, 1] (sampling D cos instead, as Karis 2013's listing and
//! Filament's `cmgen` do, weights each sample by G2 v.h / (NoV NoH), unbounded at grazing
//! NoV). The horizon cuts the sampled domain, and at grazing views the weight drops from about
//! 1 to 0 across it, so the error falls only like N^-0.8: max error over a 16 x 16 subgrid of
//! the 64 x 64 cells 1.2e-3, 4.1e-4, 1.2e-4, 6.2e-5 at 1024, 4096, 16384, 32768 samples.
//! [`DEFAULT_SAMPLES`] = 32768 meets 1e-4 on every cell of a 64 x 64 table
//! (`cargo test --test ibl dfg_accuracy:: -- --nocapture`).
//!
//! # Table layout
//! [`table`] writes `[A, B, E]` per cell, row-major with n_dot_v along a row: cell
//! `j * n_nov + i` holds NoV = (i + 0.5) / n_nov and perceptual roughness
//! r = (j + 0.5) / n_roughness, alpha = r^2 (cell centres, as a texture sampled with linear
//! filtering expects; Filament's `cmgen` uses the same NoV centres and also stores r, not
//! alpha, along the other axis). [`lookup`] interpolates it bilinearly, clamping to the edge
//! cells' centres as a clamp-to-edge sampler does.
//!
//! # Roughness
//! Every `roughness` here is the perceptual roughness r (glTF's `roughnessFactor`, UE4's
//! `Roughness`, Filament's `perceptualRoughness`), alpha = r^2
//! ([`crate::microfacet::alpha_from_perceptual`]); [`dfg`] alone takes alpha.

use crate::domain::{above, in_unit, nan_unless, nan_where};
use crate::error::ParamError;
use crate::ggx::{self, Ggx};
use crate::real::Real;
use crate::sampling::ggx_vndf_spherical_cap;
use crate::vec3::V3;

/// Samples per cell that keep every entry of a 64 x 64 table within 1e-4 of the exact
/// integrals: measured max error 6.9e-5 (E; A 5.9e-5, B 3.8e-5; RMS 1.2e-5), against a
/// reference converged to 1.3e-5 (`cargo test --test ibl dfg_accuracy:: -- --nocapture`).
/// Cost: about 2 ms per cell, 8 s for the 64 x 64 table on one core.
pub const DEFAULT_SAMPLES: u32 = 32768;

/// Van der Corput radical inverse of `i` in base 2, in [0, 1).
#[inline]
fn radical_inverse(i: u32) -> f64 {
    f64::from(i.reverse_bits()) * (1.0 / 4_294_967_296.0)
}

/// The split-sum terms `[A, B, E]` of GGX with height-correlated Smith at `n_dot_v` and the
/// GGX width `alpha` (not perceptual roughness: alpha = r^2):
/// A = integral D V (1 - Fc) NoL dl, B = integral D V Fc NoL dl, E = A + B, Fc = (1 - v.h)^5
/// (module docs), estimated from `samples` visible normals at the points
/// ((k + 0.5) / n, radical_inverse(k) + 0.5 / n) of a centred Hammersley set.
///
/// Deterministic: the same arguments give the same bits. A, B >= 0 and E <= 1 (every weight
/// lies in [0, 1]); E -> 1 as alpha -> 0 (a mirror reflects everything). Error about
/// N^-0.8 (module docs): with [`DEFAULT_SAMPLES`] within 1e-4 of the exact integrals over the
/// cells of a 64 x 64 table (`tests/ibl/dfg_accuracy.rs`).
///
/// Domain: n_dot_v in [-1, 1] (above 1 clamped to 1; at or below 0 the view is at or below
/// the horizon and every term is 0); alpha in [0, +inf) finite, clamped to [ALPHA_MIN,
/// ALPHA_MAX] as in [`crate::ggx`]; alpha < 0, +inf or NaN, NaN n_dot_v, or `samples` = 0
/// give NaN in all three terms.
#[must_use]
pub fn dfg(n_dot_v: f64, alpha: f64, samples: u32) -> [f64; 3] {
    let nan = [f64::NAN; 3];
    if n_dot_v.is_nan() || samples == 0 {
        return nan;
    }
    let Ok(lobe) = Ggx::isotropic(alpha) else {
        return nan;
    };
    if n_dot_v <= 0.0 {
        return [0.0; 3];
    }
    let c = n_dot_v.min(1.0);
    // sin from (1 - c)(1 + c): no cancellation near the normal.
    let v = V3::new(((1.0 - c) * (1.0 + c)).sqrt(), 0.0, c);
    let lambda_v = ggx::lambda(c, alpha);
    let n = f64::from(samples);
    let offset = 0.5 / n;
    let (mut a, mut b) = (0.0, 0.0);
    for k in 0..samples {
        let u2 = (f64::from(k) + 0.5) / n;
        let u1 = radical_inverse(k) + offset;
        let (m, _) = ggx_vndf_spherical_cap(&lobe, v, u1, u2);
        let v_dot_h = v.dot(m);
        let n_dot_l = 2.0 * v_dot_h * m.z - c;
        if n_dot_l > 0.0 {
            // G2 / G1(v) written with Lambdas: finite for every cosine (Lambda is capped).
            let w = (1.0 + lambda_v) / (1.0 + lambda_v + ggx::lambda(n_dot_l, alpha));
            let fc = (1.0 - v_dot_h.clamp(0.0, 1.0)).powi(5);
            a += w * (1.0 - fc);
            b += w * fc;
        }
    }
    [a / n, b / n, (a + b) / n]
}

/// Checks a table's dimensions against its buffer.
fn check_dims(len: usize, n_nov: usize, n_roughness: usize) -> Result<(), ParamError> {
    if n_nov == 0 || n_roughness == 0 {
        return Err(ParamError {
            param: "n_nov, n_roughness",
            expected: ">= 1",
        });
    }
    if n_nov.checked_mul(n_roughness) != Some(len) {
        return Err(ParamError {
            param: "out",
            expected: "a slice of n_nov * n_roughness cells",
        });
    }
    Ok(())
}

/// Fills `out` with the DFG table: cell `j * n_nov + i` = [`dfg`]`(NoV, r^2, samples)` as
/// `[A, B, E]` in f32, with NoV = (i + 0.5) / n_nov and perceptual roughness
/// r = (j + 0.5) / n_roughness (module docs, "Table layout").
///
/// Errors: `n_nov` or `n_roughness` = 0, `out.len() != n_nov * n_roughness`, or `samples` = 0
/// return [`ParamError`] and leave `out` untouched. Cost: n_nov n_roughness samples
/// evaluations (64 x 64 at [`DEFAULT_SAMPLES`]: about 8 s on one core).
pub fn table(
    out: &mut [[f32; 3]],
    n_nov: usize,
    n_roughness: usize,
    samples: u32,
) -> Result<(), ParamError> {
    fill(out, n_nov, n_roughness, samples, |t| t)
}

/// The cells of a DFG table: each [`dfg`] at its cell centre (module docs, "Table layout"),
/// its `[A, B, E]` kept by `pick` and stored in f32; the dimension and sample checks of
/// [`table`].
fn fill<const N: usize>(
    out: &mut [[f32; N]],
    n_nov: usize,
    n_roughness: usize,
    samples: u32,
    pick: impl Fn([f64; 3]) -> [f64; N],
) -> Result<(), ParamError> {
    check_dims(out.len(), n_nov, n_roughness)?;
    if samples == 0 {
        return Err(ParamError {
            param: "samples",
            expected: ">= 1",
        });
    }
    for (idx, cell) in out.iter_mut().enumerate() {
        let (i, j) = (idx % n_nov, idx / n_nov);
        let n_dot_v = (i as f64 + 0.5) / n_nov as f64;
        let r = (j as f64 + 0.5) / n_roughness as f64;
        *cell = pick(dfg(n_dot_v, r * r, samples)).map(|x| x as f32);
    }
    Ok(())
}

/// Fills `out` with the DFG table in Filament's two channels, `[B, E]` per cell (B = F0's
/// complement weight, E = A + B the albedo with F = 1; module docs, "The split sum"), the
/// layout of Filament's `cmgen` multiple-scattering table that its shaders read as
/// `dfg.x`, `dfg.y` and combine with [`specular_filament`] (Filament's `specularDFG`,
/// mix(dfg.x, dfg.y, F0), and its energy compensation 1 + F0 (1 / dfg.y - 1); Romain
/// Guy and Mathias Agopian, "Physically Based Rendering in Filament", sections 5.3.4.3 and
/// 4.7.2). Same cells, order and errors as [`table`], whose B and E it holds bit for bit.
pub fn table_filament(
    out: &mut [[f32; 2]],
    n_nov: usize,
    n_roughness: usize,
    samples: u32,
) -> Result<(), ParamError> {
    fill(out, n_nov, n_roughness, samples, |[_, b, e]| [b, e])
}

/// Bilinear interpolation of a [`table`] at (`n_dot_v`, perceptual `roughness`), as a texture
/// sampler with linear filtering and clamp-to-edge addressing reads it: coordinates
/// x = NoV n_nov - 0.5 and y = r n_roughness - 0.5, clamped to the edge cells' centres.
///
/// Domain: n_dot_v in [-1, 1] (above 1 clamped to 1; at or below 0, below the horizon, every
/// term is 0); roughness in [0, 1] (the table's range). NaN input, roughness outside [0, 1],
/// or a table whose length is not `n_nov * n_roughness` (or a zero dimension) give NaN in all
/// three terms; nothing panics.
#[must_use]
pub fn lookup(
    table: &[[f32; 3]],
    n_nov: usize,
    n_roughness: usize,
    n_dot_v: f32,
    roughness: f32,
) -> [f32; 3] {
    let nan = [f32::NAN; 3];
    if check_dims(table.len(), n_nov, n_roughness).is_err()
        || n_dot_v.is_nan()
        || !(0.0..=1.0).contains(&roughness)
    {
        return nan;
    }
    if n_dot_v <= 0.0 {
        return [0.0; 3];
    }
    let axis = |x: f32, n: usize| {
        let t = (x * n as f32 - 0.5).clamp(0.0, (n - 1) as f32);
        // t is finite and in [0, n - 1]: the cast cannot wrap.
        let i0 = t as usize;
        let i1 = (i0 + 1).min(n - 1);
        (i0, i1, t - i0 as f32)
    };
    let (i0, i1, tx) = axis(n_dot_v.min(1.0), n_nov);
    let (j0, j1, ty) = axis(roughness, n_roughness);
    let at = |i: usize, j: usize| table[j * n_nov + i];
    let (c00, c10, c01, c11) = (at(i0, j0), at(i1, j0), at(i0, j1), at(i1, j1));
    core::array::from_fn(|k| {
        let lo = c00[k] + (c10[k] - c00[k]) * tx;
        let hi = c01[k] + (c11[k] - c01[k]) * tx;
        lo + (hi - lo) * ty
    })
}

/// NaN unless `n_dot_v` is not NaN and `roughness` lies in [0, 1]; 0 at or below the horizon.
#[inline]
fn fit_guard<T: Real>(n_dot_v: T, roughness: T, v: T) -> T {
    nan_unless(in_unit(roughness), above(n_dot_v, v))
}

/// Karis 2014's analytic fit of the split-sum terms `[A, B]` ("Physically Based Shading on
/// Mobile", Unreal Engine blog; UE4's `EnvBRDFApprox`), from the perceptual `roughness` r
/// (UE4's `Roughness`, alpha = r^2):
///
/// ```text
/// (rx, ry, rz, rw) = r (-1, -0.0275, -0.572, 0.022) + (1, 0.0425, 1.04, -0.04)
/// a004 = min(rx^2, 2^(-9.28 NoV)) rx + ry
/// A = -1.04 a004 + rz        B = 1.04 a004 + rw
/// ```
///
/// Specular albedo F0 A + F90 B (UE4 takes F90 = saturate(50 F0.g): [`specular`]). Fitted to
/// UE4's table (GGX, Schlick-Smith G with k = alpha / 2), so it differs from the
/// height-correlated table by its fit error plus that model difference: max and RMS error
/// against a 64 x 64 [`table`] in `cargo test --test ibl dfg_approximations:: -- --nocapture`.
/// B goes slightly negative (-0.0024 at r = 1, NoV = 1) as in the source.
///
/// Domain: n_dot_v in [-1, 1] (above 1 clamped to 1; at or below 0, both terms 0); roughness
/// in [0, 1], else NaN; NaN in either gives NaN.
#[inline]
#[must_use]
pub fn karis_mobile<T: Real>(n_dot_v: T, roughness: T) -> [T; 2] {
    let nv = n_dot_v.min(T::ONE);
    let rx = T::ONE - roughness;
    let ry = roughness.mul_add(T::splat(-0.0275), T::splat(0.0425));
    let rz = roughness.mul_add(T::splat(-0.572), T::splat(1.04));
    let rw = roughness.mul_add(T::splat(0.022), T::splat(-0.04));
    let a004 = (rx * rx).min((T::splat(-9.28) * nv).exp2()).mul_add(rx, ry);
    let a = a004.mul_add(T::splat(-1.04), rz);
    let b = a004.mul_add(T::splat(1.04), rw);
    [
        fit_guard(n_dot_v, roughness, a),
        fit_guard(n_dot_v, roughness, b),
    ]
}

/// Karis 2014's non-metal shortcut (UE4's `EnvBRDFApproxNonmetal`): the specular albedo of
/// [`karis_mobile`] at F0 = 0.04, F90 = 1, folded into one term,
/// 0.04 A + B = min(rx^2, 2^(-9.28 NoV)) rx + ry with rx = 1 - r, ry = 0.0425 - 0.0275 r
/// (that is a004: 0.04 A + B = 0.9984 a004 + 0.0016 - 0.00088 r, within 0.0016 of it).
/// Same domain as [`karis_mobile`]; its error against 0.04 A + B of the [`table`] is printed by
/// `cargo test --test ibl dfg_approximations:: -- --nocapture`.
#[inline]
#[must_use]
pub fn karis_mobile_nonmetal<T: Real>(n_dot_v: T, roughness: T) -> T {
    let nv = n_dot_v.min(T::ONE);
    let rx = T::ONE - roughness;
    let ry = roughness.mul_add(T::splat(-0.0275), T::splat(0.0425));
    let v = (rx * rx).min((T::splat(-9.28) * nv).exp2()).mul_add(rx, ry);
    fit_guard(n_dot_v, roughness, v)
}

/// Lazarov 2013's environment BRDF ("Getting More Physical in Call of Duty: Black Ops II",
/// SIGGRAPH course notes), as `[A, B]`, from gloss g = 1 - r:
///
/// ```text
/// t = g (1/0.96, 0.475, (0.0275 - 0.25 0.04)/0.96, 0.25) + (0, 0, (0.015 - 0.75 0.04)/0.96, 0.75)
/// a0 = t.x min(t.y, 2^(-9.28 NoV)) + t.z        a1 = t.w
/// A = a1 - a0        B = a0
/// ```
///
/// The source returns saturate(a0 + F0 (a1 - a0)) = saturate(F0 A + B). Fitted for Black
/// Ops II's normalized Blinn-Phong lobe, not GGX: its error against the GGX [`table`] is
/// mostly that model difference, and Karis 2014 reworked its form for GGX
/// ([`karis_mobile`]). How gloss relates to perceptual roughness is the engine's choice;
/// g = 1 - r is the mapping engines porting it use. Same domain as [`karis_mobile`].
#[inline]
#[must_use]
pub fn lazarov<T: Real>(n_dot_v: T, roughness: T) -> [T; 2] {
    let nv = n_dot_v.min(T::ONE);
    let g = T::ONE - roughness;
    let tx = g * T::splat(1.0 / 0.96);
    let ty = g * T::splat(0.475);
    let tz = g.mul_add(
        T::splat((0.0275 - 0.25 * 0.04) / 0.96),
        T::splat((0.015 - 0.75 * 0.04) / 0.96),
    );
    let tw = g.mul_add(T::splat(0.25), T::splat(0.75));
    let a0 = tx.mul_add(ty.min((T::splat(-9.28) * nv).exp2()), tz);
    [
        fit_guard(n_dot_v, roughness, tw - a0),
        fit_guard(n_dot_v, roughness, a0),
    ]
}

/// Narkowicz 2014's refit of [`lazarov`]'s form to GGX ("Analytical DFG Term for IBL", blog
/// post, `EnvDFGLazarov`), as `[A, B]` = [scale, bias], from gloss g = 1 - r:
///
/// ```text
/// t = g (0.5745, 1.548, -0.02397, 1.301) + (0.5753, -0.2511, -0.02066, 0.4755)
/// B = saturate(t.x min(t.y, 2^(-7.672 NoV)) + t.z)        A = saturate(t.w) - B
/// ```
///
/// The post multiplies B by saturate(50 F0.g) as UE4 does (F90 of [`specular`]). Its gloss
/// convention is not stated with the code; g = 1 - r is the one ports use, and the test
/// prints the error under g = 1 - r. Same domain as [`karis_mobile`].
#[inline]
#[must_use]
pub fn narkowicz_lazarov<T: Real>(n_dot_v: T, roughness: T) -> [T; 2] {
    let nv = n_dot_v.min(T::ONE);
    let g = T::ONE - roughness;
    let tx = g.mul_add(T::splat(0.5745), T::splat(0.5753));
    let ty = g.mul_add(T::splat(1.548), T::splat(-0.2511));
    let tz = g.mul_add(T::splat(-0.02397), T::splat(-0.02066));
    let tw = g.mul_add(T::splat(1.301), T::splat(0.4755));
    let bias = tx
        .mul_add(ty.min((T::splat(-7.672) * nv).exp2()), tz)
        .saturate();
    let delta = tw.saturate();
    [
        fit_guard(n_dot_v, roughness, delta - bias),
        fit_guard(n_dot_v, roughness, bias),
    ]
}

/// Narkowicz 2014's polynomial fit for GGX ("Analytical DFG Term for IBL", blog post,
/// `EnvDFGPolynomial`), as `[A, B]` = [delta - bias, bias], with x = gloss = 1 - r, y = NoV:
///
/// ```text
/// bias  = saturate(min(-0.1688 x + 1.895 x^2, 0.9903 - 4.853 y + 8.404 y^2 - 5.069 y^3))
/// delta = saturate(0.6045 + 1.699 x - 0.5228 y - 3.603 x^2 + 1.404 x y + 0.1939 y^2
///                  + 2.661 x^3)
/// ```
///
/// As [`narkowicz_lazarov`], the post scales B by saturate(50 F0.g) and leaves the gloss
/// convention to the code's callers (g = 1 - r here). Same domain as [`karis_mobile`].
#[inline]
#[must_use]
pub fn narkowicz_polynomial<T: Real>(n_dot_v: T, roughness: T) -> [T; 2] {
    let y = n_dot_v.min(T::ONE);
    let x = T::ONE - roughness;
    let s = T::splat;
    let bias_x = x * x.mul_add(s(1.895), s(-0.1688));
    let bias_y = y.mul_add(
        y.mul_add(y.mul_add(s(-5.069), s(8.404)), s(-4.853)),
        s(0.9903),
    );
    let bias = bias_x.min(bias_y).saturate();
    let delta = (s(0.6045)
        + x.mul_add(s(1.699), y * s(-0.5228))
        + x * x.mul_add(x.mul_add(s(2.661), s(-3.603)), y * s(1.404))
        + y * y * s(0.1939))
    .saturate();
    [
        fit_guard(n_dot_v, roughness, delta - bias),
        fit_guard(n_dot_v, roughness, bias),
    ]
}

/// The split-sum specular radiance: prefiltered (F0 A + F90 B) per channel (Karis 2013,
/// "Real Shading in Unreal Engine 4", the split-sum approximation; Lagarde and de Rousiers
/// 2014, "Moving Frostbite to PBR", section 4.9.2, with F90 as a parameter).
///
/// `prefiltered`: the radiance map read along the reflected (or dominant) direction at the
/// mip of the roughness ([`mip_from_roughness_linear`] and its siblings); `f0`: Schlick's
/// reflectance at normal incidence; `f90`: at grazing (1 for every real material; UE4 uses
/// saturate(50 F0.g) to let F0 below 0.02 switch specular off); `a`, `b`: the DFG terms of
/// [`dfg`], [`lookup`] or a fit.
///
/// Domain: prefiltered >= 0 (radiance) and finite; f0 components and f90 in [0, 1]; a, b
/// finite (a fit may give a B slightly below 0). A negative or infinite radiance or f0 / f90
/// outside [0, 1] give NaN in every channel (f0's own channel for f0, the radiance's own
/// channel for the radiance); NaN or an infinite a or b gives NaN (rule 5);
/// F0 A + F90 B and the result are clamped to [-MAX, MAX] (a negative B can make the result
/// negative: it is a radiance estimate, not clamped at 0), so finite input gives finite
/// output.
#[inline]
#[must_use]
pub fn specular<T: Real>(prefiltered: V3<T>, f0: V3<T>, f90: T, a: T, b: T) -> V3<T> {
    let fb = f90 * b;
    let f90_ok = in_unit(f90);
    // Capped on both sides, twice: F0 A + F90 B itself can overflow (a and b near +-MAX),
    // and a zero radiance would then give 0 * inf = NaN; a fit's B < 0 makes it negative, so
    // the -MAX side matters as much as the +MAX one.
    let cap = |v: T| v.clamp(-T::MAX, T::MAX);
    // An infinite a, b or radiance would be capped to a plausible +-MAX (rule 5: NaN).
    let ok = f90_ok & a.is_finite() & b.is_finite();
    prefiltered.zip_map(f0, |l, f| {
        let v = cap(l * cap(f.mul_add(a, fb)));
        nan_unless(
            ok & in_unit(f) & l.simd_ge(T::ZERO) & l.simd_lt(T::INFINITY),
            v,
        )
    })
}

/// The split-sum specular radiance from Filament's two DFG channels ([`table_filament`]:
/// x = B, y = E = A + B): prefiltered mix(x, y, F0) = prefiltered (x + F0 (y - x)) per
/// channel, which is prefiltered (F0 A + B), [`specular`] with F90 = 1 (Filament's
/// `specularDFG` in `light_indirect.fs`; Guy and Agopian, "Physically Based Rendering in
/// Filament", section 5.3.4.3).
///
/// Domain: prefiltered >= 0 and finite; f0 components in [0, 1]; x, y finite. A negative or
/// infinite radiance or f0 outside [0, 1] give NaN in its channel; NaN or an infinite x or y
/// give NaN in every channel; the mix and the result are clamped to [-MAX, MAX], so finite
/// input gives finite output.
#[inline]
#[must_use]
pub fn specular_filament<T: Real>(prefiltered: V3<T>, f0: V3<T>, dfg_x: T, dfg_y: T) -> V3<T> {
    let cap = |v: T| v.clamp(-T::MAX, T::MAX);
    let diff = cap(dfg_y - dfg_x);
    let ok = dfg_x.is_finite() & dfg_y.is_finite();
    prefiltered.zip_map(f0, |l, f| {
        let v = cap(l * cap(f.mul_add(diff, dfg_x)));
        nan_unless(
            ok & in_unit(f) & l.simd_ge(T::ZERO) & l.simd_lt(T::INFINITY),
            v,
        )
    })
}

/// True where `n` is a finite count >= `lo` (false for NaN).
#[inline]
fn count_ok<T: Real>(n: T, lo: f64) -> T::Mask {
    n.simd_ge(T::splat(lo)) & n.simd_lt(T::INFINITY)
}

/// The linear roughness-to-mip mapping, mip = r (n_mips - 1): mip 0 holds the mirror (r = 0),
/// the last mip r = 1. It assumes mip k was prefiltered with GGX of perceptual roughness
/// k / (n_mips - 1) (Karis 2013's prefiltering, read back this way by LearnOpenGL, bevy and
/// many engines), whatever the mip's resolution.
///
/// Domain: r in [0, 1] (else NaN); n_mips >= 1 and finite (else NaN); NaN in gives NaN.
#[inline]
#[must_use]
pub fn mip_from_roughness_linear<T: Real>(roughness: T, n_mips: T) -> T {
    nan_unless(
        in_unit(roughness) & count_ok(n_mips, 1.0),
        roughness * (n_mips - T::ONE),
    )
}

/// Inverse of [`mip_from_roughness_linear`]: r = mip / (n_mips - 1), the roughness to
/// prefilter mip `mip` with. Domain: n_mips > 1 and finite, mip in [0, n_mips - 1]; else NaN.
#[inline]
#[must_use]
pub fn roughness_from_mip_linear<T: Real>(mip: T, n_mips: T) -> T {
    let top = n_mips - T::ONE;
    let ok = n_mips.simd_gt(T::ONE) & n_mips.simd_lt(T::INFINITY);
    nan_unless(ok & mip.simd_ge(T::ZERO) & mip.simd_le(top), mip / top)
}

/// Filament's roughness-to-lod mapping, lod = L r (2 - r) with L the level prefiltered for
/// r = 1 (Filament's `iblRoughnessOneLevel`; `perceptualRoughnessToLod` in
/// `shaders/src/surface_light_indirect.fs` of google/filament). A quadratic fit of
/// log2(r) + L for L = 4, found to work for a 256-texel cube with 5 levels. It assumes level
/// k was prefiltered with r = [`roughness_from_lod_filament`]`(k, L)`, as Filament's `cmgen`
/// and `IBLPrefilterContext` do, so mips concentrate on low roughness.
///
/// Domain: r in [0, 1] (else NaN); L >= 0 and finite (else NaN); NaN in gives NaN.
#[inline]
#[must_use]
pub fn lod_from_roughness_filament<T: Real>(roughness: T, roughness_one_level: T) -> T {
    nan_unless(
        in_unit(roughness) & count_ok(roughness_one_level, 0.0),
        roughness_one_level * roughness * (T::TWO - roughness),
    )
}

/// Inverse of [`lod_from_roughness_filament`] (Filament's `lodToPerceptualRoughness`):
/// r = 1 - sqrt(1 - lod / L). Domain: L > 0 and finite, lod in [0, L]; else NaN.
#[inline]
#[must_use]
pub fn roughness_from_lod_filament<T: Real>(lod: T, roughness_one_level: T) -> T {
    let l = roughness_one_level;
    let ok = l.simd_gt(T::ZERO) & l.simd_lt(T::INFINITY) & lod.simd_ge(T::ZERO) & lod.simd_le(l);
    nan_unless(ok, T::ONE - (T::ONE - lod / l).sqrt_nonneg())
}

/// Unreal Engine 4's roughness-to-mip mapping (`ComputeReflectionCaptureMipFromRoughness`,
/// `Engine/Shaders/Private/ReflectionEnvironmentShared.ush`):
/// mip = M - 1 - (1 - 1.2 log2(max(r, 0.001))), M = UE4's `ReflectionCubemapMaxMip`. Each
/// halving of r moves 1.2 mips towards the sharp end, independent of the cube's size, and
/// r = 1 sits at mip M - 2: more mips only add sharper levels. It assumes each mip was
/// prefiltered with r = [`roughness_from_mip_ue4`]`(mip, M)`. The result is not clamped
/// (below 0 for small r on small cubes; the sampler clamps).
///
/// Domain: r in [0, 1] (else NaN; below 0.001 the source's floor applies); M finite (else
/// NaN); NaN in gives NaN.
#[inline]
#[must_use]
pub fn mip_from_roughness_ue4<T: Real>(roughness: T, cubemap_max_mip: T) -> T {
    let log2_r = roughness.max(T::splat(0.001)).ln() * T::splat(core::f64::consts::LOG2_E);
    let level_from_1x1 = T::splat(-1.2).mul_add(log2_r, T::ONE);
    let ok = in_unit(roughness) & cubemap_max_mip.is_finite();
    nan_unless(ok, cubemap_max_mip - T::ONE - level_from_1x1)
}

/// Inverse of [`mip_from_roughness_ue4`] (UE4's `ComputeReflectionCaptureRoughnessFromMip`):
/// r = 2^((1 - (M - 1 - mip)) / 1.2). Domain: mip and M finite (else NaN); mips past r = 1
/// give r > 1, as in the source.
#[inline]
#[must_use]
pub fn roughness_from_mip_ue4<T: Real>(mip: T, cubemap_max_mip: T) -> T {
    let level_from_1x1 = cubemap_max_mip - T::ONE - mip;
    let r = ((T::ONE - level_from_1x1) * T::splat(1.0 / 1.2)).exp2();
    nan_where(
        !(mip.is_finite() & cubemap_max_mip.is_finite()),
        r.min(T::MAX),
    )
}
