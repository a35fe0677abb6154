//! The sRGB and Rec.709 transfer functions stay within their ULP bounds of the correctly rounded
//! result (`oracle/src/bounds.rs`) on f32, f64, f32x8 and f64x4. Print the measured figures
//! with `cargo test -p brdf-oracle --release --test color -- --nocapture`.

/// `color::srgb_oetf` against its reference.
#[test]
fn color_srgb_oetf_within_bound() {
    brdf_oracle::check("color::srgb_oetf");
}

/// `color::srgb_eotf` against its reference.
#[test]
fn color_srgb_eotf_within_bound() {
    brdf_oracle::check("color::srgb_eotf");
}

/// `color::rec709_oetf` against its reference.
#[test]
fn color_rec709_oetf_within_bound() {
    brdf_oracle::check("color::rec709_oetf");
}
