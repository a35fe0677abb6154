//! sRGB and Rec.709 transfer functions: exact round trips of every 8- and 16-bit code, 1-ulp
//! round trips over a dense sweep, reference values, and bad-input handling.
#![cfg(feature = "tonemap")]

use brdf::color::{self, srgb_eotf, srgb_oetf};
use brdf::wide::f32x8;
use brdf::{Real, V3};

#[test]
fn every_8_and_16_bit_code_round_trips_exactly() {
    for bits in [8u32, 16] {
        let max = ((1u32 << bits) - 1) as f64;
        for code in 0..=(1u32 << bits) - 1 {
            let x = code as f64 / max;
            let back64 = (srgb_oetf(srgb_eotf(x)) * max).round() as u32;
            let back32 = (srgb_oetf(srgb_eotf(x as f32)) as f64 * max).round() as u32;
            assert_eq!(back64, code, "f64 {bits}-bit code {code}");
            assert_eq!(back32, code, "f32 {bits}-bit code {code}");
        }
    }
}

fn ulp_distance32(a: f32, b: f32) -> u32 {
    (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs() as u32
}

#[test]
fn oetf_of_eotf_is_within_one_ulp_over_a_dense_sweep() {
    let mut worst64 = 0u64;
    let mut worst32 = 0u32;
    for i in 0..=1_000_000 {
        let x = i as f64 / 1e6;
        // IEC 61966-2-1's pieces leave a seam: (12.92 * 0.0031308, 0.04045] decodes on the
        // linear piece and re-encodes on the power piece, 2.85e-8 lower (color::srgb_oetf).
        if x > 12.92 * 0.003_130_8 && x <= color::SRGB_EOTF_BREAK {
            continue;
        }
        let y = srgb_oetf(srgb_eotf(x));
        worst64 = worst64.max((y.to_bits() as i64 - x.to_bits() as i64).unsigned_abs());
        let x32 = x as f32;
        worst32 = worst32.max(ulp_distance32(srgb_oetf(srgb_eotf(x32)), x32));
    }
    println!("sRGB round trip: f64 max {worst64} ulp, f32 max {worst32} ulp");
    // f32 (and f32x8, which evaluates the same per-lane f64 code): 1 ulp, issue 4's target.
    // f64: 2 ulps on 410 of the million points (957k exact), near x = 0.0497, where EOTF(x)
    // sits at the bottom of its binade: even a correctly rounded EOTF moves x by up to 0.7 ulp
    // there, and libm's pow adds its own rounding. Only a double-word pow would remove it.
    assert!(worst32 <= 1, "f32 round trip {worst32} ulp");
    assert!(worst64 <= 2, "f64 round trip {worst64} ulp");
}

#[test]
fn reference_values() {
    // IEC 61966-2-1: mid-level 0.5 encoded is 21.4% linear; 18% grey encodes to 0.4614.
    assert!((srgb_eotf(0.5) - 0.214_041_140_482_232_5).abs() < 1e-15);
    assert!((srgb_oetf(0.18) - 0.461_356_129_500_441_9).abs() < 1e-15);
    assert_eq!(srgb_oetf(0.0), 0.0);
    assert!((srgb_oetf(1.0) - 1.0).abs() < 1e-15);
    // The two pieces meet at the breakpoints (the standard's rounded constants leave a gap
    // below 1e-7, invisible at 16 bits).
    assert!((0.003_130_8 * 12.92 - (1.055 * 0.003_130_8f64.powf(1.0 / 2.4) - 0.055)).abs() < 1e-7);
    // Rec.709: 4.5 L below 0.018, 1.099 L^0.45 - 0.099 above; 1 -> 1.
    assert!((color::rec709_oetf(1.0) - 1.0).abs() < 1e-15);
    assert!((color::rec709_oetf(0.01) - 0.045).abs() < 1e-16);
    assert!((color::gamma_decode(color::gamma_encode(0.3, 2.2), 2.2) - 0.3).abs() < 1e-15);
    // Luminance weights sum to 1: white has luminance 1.
    assert!((color::luminance(V3::splat(1.0)) - 1.0).abs() < 1e-15);
}

#[test]
fn bad_input_gives_black_on_scalars_and_lanes() {
    // NaN is reported, not clamped.
    assert!(srgb_oetf(f32::NAN).is_nan() && srgb_eotf(f32::NAN).is_nan());
    assert!(color::rec709_oetf(f32::NAN).is_nan());
    assert!(srgb_oetf(f32x8::splat(f32::NAN)).lane(3).is_nan());
    for x in [-1.0, -0.0, -f32::MAX] {
        assert_eq!(srgb_oetf(x), 0.0);
        assert_eq!(srgb_eotf(x), 0.0);
        assert_eq!(color::rec709_oetf(x), 0.0);
        assert_eq!(srgb_oetf(f32x8::splat(x)).lane(3), 0.0);
    }
    // An infinite signal is an overflow upstream: reported, not clamped (rule 5).
    for x in [f32::NEG_INFINITY, f32::INFINITY] {
        assert!(srgb_oetf(x).is_nan() && srgb_eotf(x).is_nan());
        assert!(color::rec709_oetf(x).is_nan());
        assert!(srgb_oetf(f32x8::splat(x)).lane(3).is_nan());
    }
    for i in 0..=1000 {
        let x = i as f32 / 1000.0;
        assert_eq!(srgb_oetf(f32x8::splat(x)).lane(0), srgb_oetf(x));
        assert_eq!(srgb_eotf(f32x8::splat(x)).lane(7), srgb_eotf(x));
    }
}
