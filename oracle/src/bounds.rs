//! The per-function ULP bounds, in one table so they are retuned in one place.
//!
//! Each bound is the largest score the deep search found (`crate::hardest`: fresh points and
//! a hill-climb, the worst of them committed and re-measured on every run) plus a margin of
//! 0.3 ULP ([`crate::table::MARGIN`]: fresh points have exceeded a deep search's figure by up
//! to 0.24 ULP), rounded up to the next 0.1 ([`crate::table::suggested_bound`]). The margin is
//! below half an ULP, so one more rounding anywhere in a kernel still breaks the bound at the
//! committed worst point (`tests/harness.rs` proves that by perturbing every result by one
//! rounding). A bound never exceeds the crate's 4 ULP target without a reason in `why`.
//!
//! Ill-conditioned rows score `raw - kappa / 2` (the raw error in ULPs less what one rounding
//! of the input explains, `crate::harness`), so their bound reads "raw <= kappa / 2 + bound".
//! Their score approaches -3.5 for any kernel that rounds its result (half an ulp at kappa
//! just above 8), so their bounds are made from a score of at least -3.55: -3.2 at the lowest.
//!
//! A build with FMA (`-C target-feature=+fma`, where `mul_add` fuses) rounds differently; a
//! row whose FMA figures differ carries them in [`Bound::fma`], and [`bound`] returns the
//! figures of the build it runs in.

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
    /// The figures of a build with FMA, where they differ ([`Bound::fma`]).
    pub with_fma: Option<[f64; 4]>,
}

impl Bound {
    /// This bound with other figures (f32, f64, f32x8, f64x4) for builds with FMA.
    #[must_use]
    pub const fn fma(self, f32: f64, f64: f64, f32x8: f64, f64x4: f64) -> Self {
        Bound {
            with_fma: Some([f32, f64, f32x8, f64x4]),
            ..self
        }
    }

    /// This bound with the reason it exceeds [`TARGET`].
    #[must_use]
    pub const fn why(self, why: &'static str) -> Self {
        Bound { why, ..self }
    }

    /// The figures of the build this binary is (`crate::hardest::build`).
    #[must_use]
    pub fn for_this_build(self) -> Self {
        match self.with_fma {
            Some([f32, f64, f32x8, f64x4]) if cfg!(target_feature = "fma") => Bound {
                f32,
                f64,
                f32x8,
                f64x4,
                ..self
            },
            _ => self,
        }
    }
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
        with_fma: None,
    }
}

/// Every bound, in the order of `crate::cases::all`.
pub const BOUNDS: &[Bound] = &[
    b("ggx::d", 0.9, 0.8, 0.9, 0.8),
    b("ggx::d_aniso", 0.9, 0.8, 0.9, 0.8),
    b("ggx::lambda", 0.8, 0.8, 0.8, 0.8),
    b("ggx::g1", 0.8, 0.8, 0.8, 0.8),
    b("ggx::v_correlated", 0.8, 0.8, 0.8, 0.8),
    b("Ggx::lambda", 0.9, 0.8, 0.9, 0.8),
    b("Ggx::g2_correlated", 0.9, 0.8, 0.9, 0.8),
    b("Ggx::g2_separable", 0.9, 0.8, 0.9, 0.8),
    b("Ggx::v_correlated", 0.9, 0.8, 0.9, 0.8),
    b("beckmann::d", 0.9, 1.9, 0.9, 2.3),
    b("Beckmann::d", 1.8, 1.9, 2.0, 2.5),
    b("beckmann::lambda", 2.6, 2.1, 2.6, 2.5),
    b("beckmann::g1", 3.5, 2.8, 3.5, 2.8),
    b("Beckmann::lambda", 3.4, 2.0, 3.4, 2.6),
    b("Beckmann::v_correlated", 1.3, 1.3, 1.3, 1.3),
    b("fresnel::dielectric", 1.6, 1.6, 1.6, 1.6),
    b(
        "fresnel::dielectric (ill-conditioned)",
        -2.5,
        -2.4,
        -2.5,
        -2.4,
    ),
    b("fresnel::dielectric_polarized (Rs)", 0.9, 0.8, 0.9, 0.8),
    b(
        "fresnel::dielectric_polarized (Rs) (ill-conditioned)",
        -3.2,
        -3.2,
        -3.2,
        -3.2,
    ),
    b("fresnel::dielectric_polarized (Rp)", 0.9, 0.8, 0.9, 0.8),
    b(
        "fresnel::dielectric_polarized (Rp) (ill-conditioned)",
        -3.2,
        -3.2,
        -3.2,
        -3.2,
    ),
    b("fresnel::conductor", 0.8, 4.0, 0.8, 4.0).fma(0.8, 3.4, 0.8, 3.4),
    b(
        "fresnel::conductor (ill-conditioned)",
        -3.2,
        -0.6,
        -3.2,
        -0.6,
    ),
    b("fresnel::schlick", 3.6, 3.6, 3.6, 3.6),
    b("fresnel::f0_from_ior", 0.9, 0.8, 0.9, 0.8),
    b("color::srgb_oetf", 0.8, 2.9, 0.8, 2.9),
    b("color::srgb_eotf", 0.8, 2.6, 0.8, 2.6),
    b("color::rec709_oetf", 0.8, 3.8, 0.8, 3.8),
    b("diffuse::lambert", 0.8, 0.8, 0.8, 0.8),
    b("diffuse::oren_nayar", 2.5, 2.9, 2.5, 2.9),
    b("diffuse::burley", 0.9, 0.8, 0.9, 0.8),
    b("diffuse::burley_renormalized", 0.9, 0.8, 0.9, 0.8),
    b("diffuse::oren_nayar_full", 0.9, 0.8, 0.9, 0.8),
    b(
        "diffuse::oren_nayar_full (ill-conditioned)",
        -3.2,
        -3.2,
        -3.2,
        -3.2,
    ),
    b("diffuse::oren_nayar_fujii", 1.3, 1.3, 1.3, 1.3),
    b("diffuse::eon", 1.5, 1.5, 1.6, 1.5),
    b("phong::normalized", 2.1, 2.0, 2.1, 2.0),
    b("phong::modified", 1.8, 1.8, 1.8, 1.8),
    b("phong::blinn_phong", 1.8, 1.8, 1.8, 1.8),
    b("phong::blinn_phong_normalization_exact", 1.2, 1.2, 1.2, 1.2),
    b("phong::blinn_phong_normalized", 2.2, 2.0, 2.2, 2.0),
    b("tonemap::exposure_curve", 0.8, 1.6, 0.8, 1.6),
    b("tonemap::reinhard", 1.8, 1.8, 1.8, 1.8),
    b("tonemap::reinhard_extended", 0.9, 0.8, 0.9, 0.8),
    b("tonemap::reinhard_luminance", 0.9, 0.8, 0.9, 0.8),
    b("tonemap::reinhard_extended_luminance", 0.9, 0.8, 0.9, 0.8),
    b("tonemap::reinhard_jodie", 0.9, 0.8, 0.9, 0.8),
    b("tonemap::aces_narkowicz", 0.8, 0.8, 0.8, 0.8),
    b("tonemap::aces_hill", 0.8, 0.8, 0.8, 0.8),
    b(
        "tonemap::aces_hill (ill-conditioned)",
        -3.2,
        -3.2,
        -3.2,
        -3.2,
    ),
    b("tonemap::hable", 0.8, 0.8, 0.8, 0.8),
    b("tonemap::lottes", 0.8, 4.0, 0.8, 4.0),
    b("tonemap::uchimura", 0.8, 3.9, 0.8, 3.9),
    b("tonemap::pbr_neutral", 0.9, 0.8, 0.9, 0.8),
    b(
        "tonemap::pbr_neutral (ill-conditioned)",
        -3.2,
        -3.2,
        -3.2,
        -3.2,
    ),
    b("tonemap::agx_minimal", 0.9, 0.9, 0.9, 0.9),
    b(
        "tonemap::agx_minimal (ill-conditioned)",
        -3.2,
        -3.1,
        -3.2,
        -3.1,
    ),
    b("tonemap::agx_minimal golden", 0.9, 0.9, 0.9, 0.9),
    b(
        "tonemap::agx_minimal golden (ill-conditioned)",
        -3.2,
        -3.2,
        -3.2,
        -3.2,
    ),
    b("tonemap::agx_minimal punchy", 0.9, 1.1, 0.9, 1.1),
    b(
        "tonemap::agx_minimal punchy (ill-conditioned)",
        -3.2,
        -3.0,
        -3.2,
        -3.0,
    ),
    b("tonemap::agx_threejs", 0.8, 1.1, 0.8, 1.1),
    b(
        "tonemap::agx_threejs (ill-conditioned)",
        -3.2,
        -3.1,
        -3.2,
        -3.1,
    ),
    b("tonemap::agx_filament", 0.8, 0.9, 0.8, 0.9),
    b(
        "tonemap::agx_filament (ill-conditioned)",
        -3.2,
        -3.1,
        -3.2,
        -3.1,
    ),
    b("tonemap::agx_filament golden", 0.8, 1.0, 0.8, 1.0),
    b(
        "tonemap::agx_filament golden (ill-conditioned)",
        -3.2,
        -3.1,
        -3.2,
        -3.1,
    ),
    b("tonemap::agx_filament punchy", 0.9, 1.0, 0.9, 1.0),
    b(
        "tonemap::agx_filament punchy (ill-conditioned)",
        -3.2,
        -3.0,
        -3.2,
        -3.0,
    ),
];

/// The bound of `name` in the build this binary is ([`Bound::for_this_build`]).
///
/// # Panics
/// If `name` has no bound (add a row above).
#[must_use]
pub fn bound(name: &str) -> Bound {
    BOUNDS
        .iter()
        .copied()
        .find(|b| b.name == name)
        .unwrap_or_else(|| panic!("no bound for {name}: add a row to oracle/src/bounds.rs"))
        .for_this_build()
}
