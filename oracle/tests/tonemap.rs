//! The tonemapping operators stay within their ULP bounds of the correctly rounded result of
//! their published formulas (`oracle/src/bounds.rs`) on f32, f64, f32x8 and f64x4; where a
//! 1-ulp change of one colour channel moves the exact result by more than
//! `harness::KAPPA_MAX` ulps, the `(ill-conditioned)` rows bound the error in units of that
//! change. Print the measured figures with
//! `cargo test -p brdf-oracle --release --test tonemap -- --nocapture`.

/// `tonemap::exposure_curve` against its reference.
#[test]
fn tonemap_exposure_curve_within_bound() {
    brdf_oracle::check("tonemap::exposure_curve");
}

/// `tonemap::reinhard` against its reference.
#[test]
fn tonemap_reinhard_within_bound() {
    brdf_oracle::check("tonemap::reinhard");
}

/// `tonemap::reinhard_extended` against its reference.
#[test]
fn tonemap_reinhard_extended_within_bound() {
    brdf_oracle::check("tonemap::reinhard_extended");
}

/// `tonemap::reinhard_luminance` against its reference.
#[test]
fn tonemap_reinhard_luminance_within_bound() {
    brdf_oracle::check("tonemap::reinhard_luminance");
}

/// `tonemap::reinhard_extended_luminance` against its reference.
#[test]
fn tonemap_reinhard_extended_luminance_within_bound() {
    brdf_oracle::check("tonemap::reinhard_extended_luminance");
}

/// `tonemap::reinhard_jodie` against its reference.
#[test]
fn tonemap_reinhard_jodie_within_bound() {
    brdf_oracle::check("tonemap::reinhard_jodie");
}

/// `tonemap::aces_narkowicz` against its reference.
#[test]
fn tonemap_aces_narkowicz_within_bound() {
    brdf_oracle::check("tonemap::aces_narkowicz");
}

/// `tonemap::aces_hill` against its reference.
#[test]
fn tonemap_aces_hill_within_bound() {
    brdf_oracle::check("tonemap::aces_hill");
}

/// `tonemap::aces_hill` where ill-conditioned (the fit's root, the output matrix's
/// cancellations).
#[test]
fn tonemap_aces_hill_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::aces_hill (ill-conditioned)");
}

/// `tonemap::hable` against its reference.
#[test]
fn tonemap_hable_within_bound() {
    brdf_oracle::check("tonemap::hable");
}

/// `tonemap::lottes` against its reference.
#[test]
fn tonemap_lottes_within_bound() {
    brdf_oracle::check("tonemap::lottes");
}

/// `tonemap::uchimura` against its reference.
#[test]
fn tonemap_uchimura_within_bound() {
    brdf_oracle::check("tonemap::uchimura");
}

/// `tonemap::pbr_neutral` against its reference.
#[test]
fn tonemap_pbr_neutral_within_bound() {
    brdf_oracle::check("tonemap::pbr_neutral");
}

/// `tonemap::pbr_neutral` where ill-conditioned (a channel within a few ulps of the darkest,
/// the peak just above the compression start).
#[test]
fn tonemap_pbr_neutral_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::pbr_neutral (ill-conditioned)");
}

/// `tonemap::agx_minimal` against its reference.
#[test]
fn tonemap_agx_minimal_within_bound() {
    brdf_oracle::check("tonemap::agx_minimal");
}

/// `tonemap::agx_minimal` where ill-conditioned (the outset's cancellations).
#[test]
fn tonemap_agx_minimal_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::agx_minimal (ill-conditioned)");
}

/// `tonemap::agx_minimal golden` against its reference.
#[test]
fn tonemap_agx_minimal_golden_within_bound() {
    brdf_oracle::check("tonemap::agx_minimal golden");
}

/// `tonemap::agx_minimal golden` where ill-conditioned (the outset's cancellations).
#[test]
fn tonemap_agx_minimal_golden_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::agx_minimal golden (ill-conditioned)");
}

/// `tonemap::agx_minimal punchy` against its reference.
#[test]
fn tonemap_agx_minimal_punchy_within_bound() {
    brdf_oracle::check("tonemap::agx_minimal punchy");
}

/// `tonemap::agx_minimal punchy` where ill-conditioned (the outset's cancellations).
#[test]
fn tonemap_agx_minimal_punchy_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::agx_minimal punchy (ill-conditioned)");
}

/// `tonemap::agx_threejs` against its reference.
#[test]
fn tonemap_agx_threejs_within_bound() {
    brdf_oracle::check("tonemap::agx_threejs");
}

/// `tonemap::agx_threejs` where ill-conditioned (the outset's cancellations).
#[test]
fn tonemap_agx_threejs_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::agx_threejs (ill-conditioned)");
}

/// `tonemap::agx_filament` against its reference.
#[test]
fn tonemap_agx_filament_within_bound() {
    brdf_oracle::check("tonemap::agx_filament");
}

/// `tonemap::agx_filament` where ill-conditioned (the outset's cancellations).
#[test]
fn tonemap_agx_filament_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::agx_filament (ill-conditioned)");
}

/// `tonemap::agx_filament golden` against its reference.
#[test]
fn tonemap_agx_filament_golden_within_bound() {
    brdf_oracle::check("tonemap::agx_filament golden");
}

/// `tonemap::agx_filament golden` where ill-conditioned (the outset's cancellations).
#[test]
fn tonemap_agx_filament_golden_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::agx_filament golden (ill-conditioned)");
}

/// `tonemap::agx_filament punchy` against its reference.
#[test]
fn tonemap_agx_filament_punchy_within_bound() {
    brdf_oracle::check("tonemap::agx_filament punchy");
}

/// `tonemap::agx_filament punchy` where ill-conditioned (the outset's cancellations).
#[test]
fn tonemap_agx_filament_punchy_ill_conditioned_within_bound() {
    brdf_oracle::check("tonemap::agx_filament punchy (ill-conditioned)");
}
