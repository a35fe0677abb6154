//! The diffuse and Phong lobes stay within their ULP bounds of the correctly rounded
//! result (`oracle/src/bounds.rs`) on f32, f64, f32x8 and f64x4. Print the measured figures
//! with `cargo test -p brdf-oracle --release --test lobes -- --nocapture`.

/// `diffuse::lambert` against its reference.
#[test]
fn diffuse_lambert_within_bound() {
    brdf_oracle::check("diffuse::lambert");
}

/// `diffuse::oren_nayar` against its reference.
#[test]
fn diffuse_oren_nayar_within_bound() {
    brdf_oracle::check("diffuse::oren_nayar");
}

/// `diffuse::burley` against its reference.
#[test]
fn diffuse_burley_within_bound() {
    brdf_oracle::check("diffuse::burley");
}

/// `phong::normalized` against its reference.
#[test]
fn phong_normalized_within_bound() {
    brdf_oracle::check("phong::normalized");
}

/// `phong::blinn_phong_normalized` against its reference.
#[test]
fn phong_blinn_phong_normalized_within_bound() {
    brdf_oracle::check("phong::blinn_phong_normalized");
}

/// `diffuse::burley_renormalized` against its reference.
#[test]
fn diffuse_burley_renormalized_within_bound() {
    brdf_oracle::check("diffuse::burley_renormalized");
}

/// `diffuse::oren_nayar_full` against its reference.
#[test]
fn diffuse_oren_nayar_full_within_bound() {
    brdf_oracle::check("diffuse::oren_nayar_full");
}

/// `diffuse::oren_nayar_fujii` against its reference.
#[test]
fn diffuse_oren_nayar_fujii_within_bound() {
    brdf_oracle::check("diffuse::oren_nayar_fujii");
}

/// `diffuse::eon` against its reference.
#[test]
fn diffuse_eon_within_bound() {
    brdf_oracle::check("diffuse::eon");
}

/// `phong::modified` against its reference.
#[test]
fn phong_modified_within_bound() {
    brdf_oracle::check("phong::modified");
}

/// `phong::blinn_phong` against its reference.
#[test]
fn phong_blinn_phong_within_bound() {
    brdf_oracle::check("phong::blinn_phong");
}

/// `phong::blinn_phong_normalization_exact` against its reference.
#[test]
fn phong_blinn_phong_normalization_exact_within_bound() {
    brdf_oracle::check("phong::blinn_phong_normalization_exact");
}

/// `diffuse::oren_nayar_full` where it is ill-conditioned, scored against its conditioning.
#[test]
fn diffuse_oren_nayar_full_ill_conditioned_within_bound() {
    brdf_oracle::check("diffuse::oren_nayar_full (ill-conditioned)");
}
