//! GGX and Beckmann D, Lambda, G1, G2 and V stay within their ULP bounds of the correctly rounded
//! result (`oracle/src/bounds.rs`) on f32, f64, f32x8 and f64x4. Print the measured figures
//! with `cargo test -p brdf-oracle --release --test microfacet -- --nocapture`.

/// `ggx::d` against its reference.
#[test]
fn ggx_d_within_bound() {
    brdf_oracle::check("ggx::d");
}

/// `ggx::d_aniso` against its reference.
#[test]
fn ggx_d_aniso_within_bound() {
    brdf_oracle::check("ggx::d_aniso");
}

/// `ggx::lambda` against its reference.
#[test]
fn ggx_lambda_within_bound() {
    brdf_oracle::check("ggx::lambda");
}

/// `ggx::g1` against its reference.
#[test]
fn ggx_g1_within_bound() {
    brdf_oracle::check("ggx::g1");
}

/// `ggx::v_correlated` against its reference.
#[test]
fn ggx_v_correlated_within_bound() {
    brdf_oracle::check("ggx::v_correlated");
}

/// `Ggx::lambda` against its reference.
#[test]
fn ggx_type_lambda_within_bound() {
    brdf_oracle::check("Ggx::lambda");
}

/// `Ggx::g2_correlated` against its reference.
#[test]
fn ggx_type_g2_correlated_within_bound() {
    brdf_oracle::check("Ggx::g2_correlated");
}

/// `Ggx::g2_separable` against its reference.
#[test]
fn ggx_type_g2_separable_within_bound() {
    brdf_oracle::check("Ggx::g2_separable");
}

/// `Ggx::v_correlated` against its reference.
#[test]
fn ggx_type_v_correlated_within_bound() {
    brdf_oracle::check("Ggx::v_correlated");
}

/// `beckmann::d` against its reference.
#[test]
fn beckmann_d_within_bound() {
    brdf_oracle::check("beckmann::d");
}

/// `Beckmann::d` against its reference.
#[test]
fn beckmann_type_d_within_bound() {
    brdf_oracle::check("Beckmann::d");
}

/// `beckmann::lambda` against its reference.
#[test]
fn beckmann_lambda_within_bound() {
    brdf_oracle::check("beckmann::lambda");
}

/// `beckmann::g1` against its reference.
#[test]
fn beckmann_g1_within_bound() {
    brdf_oracle::check("beckmann::g1");
}

/// `Beckmann::lambda` against its reference.
#[test]
fn beckmann_type_lambda_within_bound() {
    brdf_oracle::check("Beckmann::lambda");
}

/// `Beckmann::v_correlated` against its reference.
#[test]
fn beckmann_type_v_correlated_within_bound() {
    brdf_oracle::check("Beckmann::v_correlated");
}
