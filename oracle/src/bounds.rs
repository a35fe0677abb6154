//! The per-function ULP bounds, in one table so they are retuned in one place.
//!
//! Each bound is the measured maximum rounded up to the next 0.5 ULP (so one more rounding
//! anywhere in a kernel breaks it: `tests/harness.rs` proves that by perturbing every result
//! by one rounding), never above the crate's 4 ULP target without a reason in `why`.

/// The bound of one function, in ULPs of the correctly rounded result.
#[derive(Clone, Copy, Debug)]
pub struct Bound {
    /// The case name (`crate::cases`).
    pub name: &'static str,
    /// On `f32`.
    pub f32: f64,
    /// On `f64`.
    pub f64: f64,
    /// On `f32x8` lanes.
    pub f32x8: f64,
    /// On `f64x4` lanes.
    pub f64x4: f64,
    /// Why a bound exceeds 4 ULP (empty when none does).
    pub why: &'static str,
}

/// The crate's accuracy target for exact functions.
pub const TARGET: f64 = 4.0;

const fn b(name: &'static str, f32: f64, f64: f64, f32x8: f64, f64x4: f64) -> Bound {
    Bound {
        name,
        f32,
        f64,
        f32x8,
        f64x4,
        why: "",
    }
}

/// Every bound, in the order of `crate::cases::all`.
pub const BOUNDS: &[Bound] = &[
    b("ggx::d", 0.5, 0.5, 0.5, 0.5),
    b("ggx::d_aniso", 0.5, 0.5, 0.5, 0.5),
    b("ggx::lambda", 0.51, 0.51, 0.51, 0.51),
    b("ggx::g1", 0.51, 0.51, 0.51, 0.51),
    b("ggx::v_correlated", 0.51, 0.51, 0.51, 0.51),
    b("Ggx::lambda", 0.51, 0.51, 0.51, 0.51),
    b("Ggx::g2_correlated", 0.51, 0.51, 0.51, 0.51),
    b("Ggx::g2_separable", 0.5, 0.5, 0.5, 0.5),
    b("Ggx::v_correlated", 0.51, 0.51, 0.51, 0.51),
    b("beckmann::d", 1.5, 1.5, 1.5, 1.5),
    b("Beckmann::d", 1.5, 1.5, 1.5, 1.5),
    b("beckmann::lambda", 2.5, 1.5, 2.5, 1.5),
    b("beckmann::g1", 2.5, 1.0, 2.5, 1.0),
    b("Beckmann::lambda", 3.0, 1.5, 3.0, 1.5),
    b("Beckmann::v_correlated", 1.0, 1.0, 1.0, 1.0),
    b("fresnel::dielectric", 1.0, 1.5, 1.0, 1.5),
    // Scored as error / kappa, in units of one rounding of the cosine (harness docs).
    b("fresnel::dielectric (ill-conditioned)", 0.5, 0.5, 0.5, 0.5),
    b("fresnel::dielectric_polarized (Rs)", 1.0, 0.5, 1.0, 0.5),
    b(
        "fresnel::dielectric_polarized (Rs) (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
    b("fresnel::dielectric_polarized (Rp)", 1.0, 0.5, 1.0, 0.5),
    b(
        "fresnel::dielectric_polarized (Rp) (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
    b("fresnel::conductor", 2.5, 2.5, 2.5, 2.5),
    b("fresnel::conductor (ill-conditioned)", 0.5, 0.5, 0.5, 0.5),
    b("fresnel::schlick", 2.0, 2.0, 2.0, 2.0),
    b("fresnel::f0_from_ior", 1.0, 0.5, 1.0, 0.5),
    b("color::srgb_oetf", 0.5, 3.0, 0.5, 3.0),
    b("color::srgb_eotf", 0.5, 4.0, 0.5, 4.0),
    b("color::rec709_oetf", 0.5, 3.5, 0.5, 3.5),
    b("diffuse::lambert", 0.5, 0.5, 0.5, 0.5),
    b("diffuse::oren_nayar", 3.5, 2.5, 3.5, 2.5),
    b("diffuse::burley", 0.5, 0.5, 0.5, 0.5),
    b("diffuse::burley_renormalized", 0.5, 0.5, 0.5, 0.5),
    b("diffuse::oren_nayar_full", 1.5, 2.5, 1.5, 2.5),
    // Scored as error / kappa, in units of one rounding of the cosine (harness docs).
    b(
        "diffuse::oren_nayar_full (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
    b("diffuse::oren_nayar_fujii", 1.0, 1.0, 1.0, 1.0),
    b("diffuse::eon", 2.0, 2.5, 2.0, 2.0),
    b("phong::normalized", 3.0, 3.0, 3.0, 3.0),
    b("phong::modified", 1.5, 1.5, 1.5, 1.5),
    b("phong::blinn_phong", 1.5, 1.5, 1.5, 1.5),
    b("phong::blinn_phong_normalization_exact", 1.0, 1.0, 1.0, 1.0),
    b("phong::blinn_phong_normalized", 1.5, 1.5, 1.5, 1.5),
    b("tonemap::exposure_curve", 2.5, 2.5, 2.5, 3.5),
    b("tonemap::reinhard", 1.5, 1.5, 1.5, 1.5),
    b("tonemap::reinhard_extended", 2.5, 3.0, 2.5, 3.0),
    b("tonemap::reinhard_luminance", 2.0, 2.5, 2.0, 2.5),
    b("tonemap::reinhard_extended_luminance", 2.5, 3.0, 2.5, 3.0),
    b("tonemap::reinhard_jodie", 4.0, 3.0, 4.0, 3.0),
    b("tonemap::aces_narkowicz", 2.5, 3.0, 2.5, 3.0),
    b("tonemap::aces_hill", 0.5, 0.5, 0.5, 0.5),
    // Scored as error / kappa, in units of one rounding of a colour channel (harness docs).
    b("tonemap::aces_hill (ill-conditioned)", 0.5, 0.5, 0.5, 0.5),
    b("tonemap::hable", 4.0, 4.0, 4.0, 4.0),
    b("tonemap::lottes", 0.5, 3.5, 0.5, 3.5),
    b("tonemap::uchimura", 0.5, 3.5, 0.5, 3.5),
    b("tonemap::pbr_neutral", 3.5, 3.0, 3.5, 3.0),
    // Scored as error / kappa, in units of one rounding of a colour channel (harness docs).
    b("tonemap::pbr_neutral (ill-conditioned)", 0.5, 0.5, 0.5, 0.5),
    // AgX ill-conditioned rows: scored as error / kappa (harness docs).
    b("tonemap::agx_minimal", 0.5, 1.0, 0.5, 1.0),
    b("tonemap::agx_minimal (ill-conditioned)", 0.5, 0.5, 0.5, 0.5),
    b("tonemap::agx_minimal golden", 0.5, 1.0, 0.5, 1.0),
    b(
        "tonemap::agx_minimal golden (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
    b("tonemap::agx_minimal punchy", 0.5, 1.0, 0.5, 1.0),
    b(
        "tonemap::agx_minimal punchy (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
    b("tonemap::agx_threejs", 0.5, 1.0, 0.5, 1.0),
    b("tonemap::agx_threejs (ill-conditioned)", 0.5, 0.5, 0.5, 0.5),
    b("tonemap::agx_filament", 0.5, 1.0, 0.5, 1.0),
    b(
        "tonemap::agx_filament (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
    b("tonemap::agx_filament golden", 0.5, 1.0, 0.5, 1.0),
    b(
        "tonemap::agx_filament golden (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
    b("tonemap::agx_filament punchy", 0.5, 1.0, 0.5, 1.0),
    b(
        "tonemap::agx_filament punchy (ill-conditioned)",
        0.5,
        0.5,
        0.5,
        0.5,
    ),
];

/// The bound of `name`.
///
/// # Panics
/// If `name` has no bound (add a row above).
#[must_use]
pub fn bound(name: &str) -> Bound {
    *BOUNDS
        .iter()
        .find(|b| b.name == name)
        .unwrap_or_else(|| panic!("no bound for {name}: add a row to oracle/src/bounds.rs"))
}
