//! EON's multiple-scattering albedo rho_ms stays in [0, rho] and is exactly 1 at rho = 1 for
//! every sigma, as documented, on f32, f64 and lanes (the reference CLI's stability sweep
//! found 1 + 1 ULP at rho = 1, sigma = 1e-6: `cli/tests/cli/stability.rs`).
#![cfg(feature = "diffuse")]

use brdf::diffuse::eon_multiscatter_albedo;
use brdf::wide::{f32x8, f64x4};

/// Sigmas from 0 to 1, dense near 0 where the rounding showed.
fn sigmas() -> Vec<f64> {
    let mut s: Vec<f64> = (0..=1000).map(|i| f64::from(i) / 1000.0).collect();
    s.extend([
        1e-6,
        1e-7,
        1e-5,
        2e-6,
        3e-6,
        f64::MIN_POSITIVE,
        5e-324,
        0.999_999,
    ]);
    s
}

#[test]
fn eon_multiscatter_albedo_is_exactly_one_at_rho_one() {
    for sigma in sigmas() {
        assert_eq!(
            eon_multiscatter_albedo(1.0_f64, sigma),
            1.0,
            "f64, sigma = {sigma:e}"
        );
        let s32 = sigma as f32;
        assert_eq!(
            eon_multiscatter_albedo(1.0_f32, s32),
            1.0,
            "f32, sigma = {sigma:e}"
        );
        let l8 = eon_multiscatter_albedo(f32x8::splat(1.0), f32x8::splat(s32));
        assert_eq!(l8.to_array(), [1.0; 8], "f32x8, sigma = {sigma:e}");
        let l4 = eon_multiscatter_albedo(f64x4::splat(1.0), f64x4::splat(sigma));
        assert_eq!(l4.to_array(), [1.0; 4], "f64x4, sigma = {sigma:e}");
    }
}

#[test]
fn eon_multiscatter_albedo_lies_in_zero_to_rho() {
    for sigma in sigmas() {
        for i in 0..=200 {
            let rho = f64::from(i) / 200.0;
            let v = eon_multiscatter_albedo(rho, sigma);
            assert!((0.0..=rho).contains(&v), "rho {rho}, sigma {sigma:e}: {v}");
            let (r32, s32) = (rho as f32, sigma as f32);
            let v = eon_multiscatter_albedo(r32, s32);
            assert!(
                (0.0..=r32).contains(&v),
                "f32 rho {rho}, sigma {sigma:e}: {v}"
            );
        }
    }
    // NaN still propagates, and rho^2 at sigma = 0 is unchanged.
    assert!(eon_multiscatter_albedo(f32::NAN, 0.5).is_nan());
    assert!(eon_multiscatter_albedo(0.5_f32, f32::NAN).is_nan());
    assert_eq!(eon_multiscatter_albedo(0.5_f64, 0.0), 0.25);
}
