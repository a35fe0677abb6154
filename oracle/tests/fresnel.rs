//! Dielectric (both sides, polarized), conductor, Schlick and F0 stay within their ULP bounds
//! of the correctly rounded result (`oracle/src/bounds.rs`) on f32, f64, f32x8 and f64x4;
//! where a 1-ulp change of the cosine moves the exact result by more than
//! `harness::KAPPA_MAX` ulps, the `(ill-conditioned)` rows bound the error in units of that
//! change. Print the measured figures with
//! `cargo test -p brdf-oracle --release --test fresnel -- --nocapture`.

/// `fresnel::dielectric` against its reference.
#[test]
fn fresnel_dielectric_within_bound() {
    brdf_oracle::check("fresnel::dielectric");
}

/// `fresnel::dielectric` where ill-conditioned (the critical angle).
#[test]
fn fresnel_dielectric_ill_conditioned_within_bound() {
    brdf_oracle::check("fresnel::dielectric (ill-conditioned)");
}

/// `fresnel::dielectric_polarized (Rs)` against its reference.
#[test]
fn fresnel_dielectric_polarized_rs_within_bound() {
    brdf_oracle::check("fresnel::dielectric_polarized (Rs)");
}

/// `fresnel::dielectric_polarized (Rs)` where ill-conditioned (the critical angle).
#[test]
fn fresnel_dielectric_polarized_rs_ill_conditioned_within_bound() {
    brdf_oracle::check("fresnel::dielectric_polarized (Rs) (ill-conditioned)");
}

/// `fresnel::dielectric_polarized (Rp)` against its reference.
#[test]
fn fresnel_dielectric_polarized_rp_within_bound() {
    brdf_oracle::check("fresnel::dielectric_polarized (Rp)");
}

/// `fresnel::dielectric_polarized (Rp)` where ill-conditioned (the critical angle and
/// Brewster's angle).
#[test]
fn fresnel_dielectric_polarized_rp_ill_conditioned_within_bound() {
    brdf_oracle::check("fresnel::dielectric_polarized (Rp) (ill-conditioned)");
}

/// `fresnel::conductor` against its reference.
#[test]
fn fresnel_conductor_within_bound() {
    brdf_oracle::check("fresnel::conductor");
}

/// `fresnel::conductor` where ill-conditioned (k = 0 at the critical angle).
#[test]
fn fresnel_conductor_ill_conditioned_within_bound() {
    brdf_oracle::check("fresnel::conductor (ill-conditioned)");
}

/// `fresnel::schlick` against its reference.
#[test]
fn fresnel_schlick_within_bound() {
    brdf_oracle::check("fresnel::schlick");
}

/// `fresnel::f0_from_ior` against its reference.
#[test]
fn fresnel_f0_from_ior_within_bound() {
    brdf_oracle::check("fresnel::f0_from_ior");
}
