//! The parametric tone curves (Hable, Lottes, Uchimura) and extended Reinhard on luminance
//! keep the crate's rule 4 at the edges of their parameters: constructors reject what the
//! kernel cannot evaluate (naming the parameter), and whatever they accept gives a number in
//! [0, 1] for every input, on f32, f64 and lanes. Each case is a reproducer the reference
//! CLI's stability sweep found (`cli/tests/cli/stability.rs`).
#![cfg(feature = "tonemap")]

use brdf::V3;
use brdf::tonemap::{
    self, HableParams, LottesParams, MAX_INPUT, UchimuraParams, reinhard_extended_luminance,
};
use brdf::wide::{f32x8, f64x4};

/// Inputs that reach every part of a curve: black, subnormals, the toe, mid grey, the
/// shoulder, the input clamp and beyond.
const INPUTS: [f64; 12] = [
    0.0,
    1e-45,
    1e-30,
    1e-6,
    0.01,
    0.18,
    0.999_999_94,
    1.0,
    11.2,
    1e4,
    MAX_INPUT,
    f64::MAX,
];

/// Asserts `f` gives a number in [0, 1] at every input, in f64, f32 and both lane types.
fn in_unit_range(
    name: &str,
    f64f: impl Fn(f64) -> f64,
    f32f: impl Fn(f32) -> f32,
    l8: impl Fn(f32x8) -> f32x8,
    l4: impl Fn(f64x4) -> f64x4,
) {
    for x in INPUTS {
        let xs = x as f32;
        let outs = [
            f64f(x),
            f64::from(f32f(xs)),
            f64::from(l8(f32x8::splat(xs)).to_array()[3]),
            l4(f64x4::splat(x)).to_array()[1],
        ];
        for v in outs {
            assert!((0.0..=1.0).contains(&v), "{name}: x = {x:e} gives {v}");
        }
    }
}

#[test]
fn hable_constructor_rejects_a_curve_that_never_reaches_white() {
    // E = F with C = 1: (F - E) A W + B (F C - E) = 0, so F is 0 everywhere and F(x) / F(W)
    // was 0 / 0 = NaN (the sweep's example).
    let err = HableParams::new(1.0, 1.0, 1.0, 1.0, 0.5, 0.5, 1.0, 1.0).unwrap_err();
    assert_eq!(err.param, "e");
    // F(W) < 0: E above both F and F C.
    assert_eq!(
        HableParams::new(0.15, 0.5, 0.1, 0.2, 0.5, 0.3, 11.2, 2.0)
            .unwrap_err()
            .param,
        "e"
    );
    // The Uncharted 2 values stay valid.
    let u = HableParams::UNCHARTED2;
    assert!(HableParams::new(u.a, u.b, u.c, u.d, u.e, u.f, u.white, u.exposure_bias).is_ok());
}

#[test]
fn hable_constructor_rejects_parameters_whose_coefficients_overflow_f64() {
    // A, F and the bias near MAX: F A b^2 overflows f64 (the kernel gave NaN).
    let m = f64::MAX;
    let err = HableParams::new(m, 1.0, 1.0, 1.0, 0.1, m, 1.0, m).unwrap_err();
    assert_eq!(err.param, "white");
}

#[test]
fn hable_accepted_extremes_stay_in_unit_range() {
    // Parameters the constructor accepts, with f32's extremes (MAX, subnormal d, f, white):
    // each gave NaN before (overflowing f32 coefficients, or 0 / 0 at black where the
    // denominator's constant rounded to 0).
    let big = f64::from(f32::MAX);
    let sub = f64::from(f32::from_bits(1));
    let cases = [
        [big, 1.0, 1.0, 1.0, 0.5, 1.0, 1.0, 1.0],
        [1.0, 1.0, 1.0, sub, 0.5, 1.0, 1.0, 1.0],
        [1.0, 1.0, 1.0, 1.0, 1e-44, 1e-40, sub, 1.0],
        [1.0, 1.0, 1.0, 1.0, 0.5, 1.0, sub, 1.0],
        [1.0, 1.0, 1.0, 1.0, 0.5, 1.0, big, big],
        [1e-6, 1e4, 1e-6, 1e4, 1e-6, 1e4, 1e-6, 1e4],
    ];
    for [a, b, c, d, e, f, w, bias] in cases {
        let p = HableParams::new(a, b, c, d, e, f, w, bias).unwrap();
        in_unit_range(
            "hable",
            |x| tonemap::hable(x, &p),
            |x| tonemap::hable(x, &p),
            |x| tonemap::hable(x, &p),
            |x| tonemap::hable(x, &p),
        );
        assert_eq!(
            tonemap::hable(0.0_f32, &p),
            0.0,
            "F(0) = 0 at {a:e}..{bias:e}"
        );
        assert!(tonemap::hable(f32::NAN, &p).is_nan());
    }
}

#[test]
fn lottes_constructor_rejects_non_finite_b_and_c() {
    // contrast * shoulder = 1e-12: hdr_max^(a d) and mid_in^(a d) round to the same value,
    // b and c divide by their difference (the sweep's example, NaN before).
    let err = LottesParams::new(1e-6, 1e-6, 1.000_001, 0.999_999, 0.999_999_9).unwrap_err();
    assert_eq!(err.param, "shoulder");
    // Contrast or shoulder near MAX, hdr_max near MAX, subnormal mid points.
    for args in [
        [f64::MAX, 1.0, 8.0, 0.18, 0.267],
        [1.6, f64::MAX, 8.0, 0.18, 0.267],
        [1.6, 0.977, f64::MAX, 0.18, 0.267],
        [1.6, 0.977, 8.0, 5e-324, 0.267],
        [1.6, 0.977, 8.0, 0.18, 5e-324],
    ] {
        let [a, d, h, mi, mo] = args;
        assert!(
            LottesParams::new(a, d, h, mi, mo).is_err(),
            "{args:?} accepted"
        );
    }
    // x^contrast would overflow f64 at MAX_INPUT and meet an infinite denominator.
    let err = LottesParams::new(1e4, 1e4, 1e4, 1.0, 0.5).unwrap_err();
    assert_eq!(err.param, "contrast");
    // Lottes' and Filament's curves stay valid.
    assert!(LottesParams::new(1.6, 0.977, 8.0, 0.18, 0.267).is_ok());
    assert!(LottesParams::new(1.55, 1.0, 10.0, 0.18, 0.215).is_ok());
}

#[test]
fn lottes_accepted_extremes_stay_in_unit_range() {
    // Accepted parameters around the sweep's 1e4 / 1e-4 magnitudes.
    let mut accepted = 0;
    let vals = [1e-4, 1e-2, 0.5, 0.999_999, 1.0, 1.000_001, 34.0, 1e4];
    for a in vals {
        for d in vals {
            for h in vals {
                for mi in vals {
                    for mo in [1e-6, 0.5, 0.999_999] {
                        let Ok(p) = LottesParams::new(a, d, h, mi, mo) else {
                            continue;
                        };
                        accepted += 1;
                        for x in INPUTS {
                            let v = tonemap::lottes(x, &p);
                            assert!((0.0..=1.0).contains(&v), "{p:?} at {x:e}: {v}");
                            let v = tonemap::lottes(x as f32, &p);
                            assert!((0.0..=1.0).contains(&v), "{p:?} at {x:e}: {v} (f32)");
                        }
                    }
                }
            }
        }
    }
    // Enough accepted curves for the sweep to mean something (most of the grid is valid).
    assert!(accepted > 500, "{accepted}");
}

#[test]
fn uchimura_shoulder_exponent_cannot_overflow_below_its_start() {
    // linear_start = 0.99999994 (f32 below 1): a S0 / (P - S1) ~ 1e7, exp overflowed while
    // the shoulder's weight was 0, giving 0 * inf = NaN for every input below S0.
    let p = UchimuraParams {
        max_brightness: 1.0,
        contrast: 1.0,
        linear_start: f64::from(0.999_999_94_f32),
        linear_length: 0.4,
        black: 1.33,
        pedestal: 0.0,
    };
    assert_eq!(tonemap::uchimura(0.0, &p), 0.0);
    in_unit_range(
        "uchimura",
        |x| tonemap::uchimura(x, &p),
        |x| tonemap::uchimura(x, &p),
        |x| tonemap::uchimura(x, &p),
        |x| tonemap::uchimura(x, &p),
    );
    assert!(tonemap::uchimura(f64::NAN, &p).is_nan());
}

#[test]
fn uchimura_parameters_near_the_largest_float_stay_in_unit_range() {
    // Each gave NaN: (x / m)^c overflowing for a tiny m (toe weight 0), the linear section or
    // the shoulder overflowing and meeting another infinity in the blend, or the
    // exponent's factor overflowing to -inf (times 0 at x = S0).
    let big = f64::from(f32::MAX);
    let tiny = f64::from(f32::from_bits(1));
    let cases = [
        [1.0, 1.0, tiny, 0.4, 1e4, 0.0],
        [1.0, 1.0, 1e-4, 0.4, big, big],
        [big, big, 1.0, 0.999_999, 1.0, -big],
        [big, 1e4, 1e-4, 0.999_999, 1.33, 0.0],
        [1e4, big, 0.999_999_9, 1e-6, 1e-6, 1.0],
        [1e-4, 1e-4, 1e4, 1.000_001, 1e4, -big],
    ];
    for [pm, a, m, l, c, b] in cases {
        let p = UchimuraParams {
            max_brightness: pm,
            contrast: a,
            linear_start: m,
            linear_length: l,
            black: c,
            pedestal: b,
        };
        assert!(m + a * ((pm - m) * l / a) < pm, "{p:?} outside the domain");
        in_unit_range(
            "uchimura",
            |x| tonemap::uchimura(x, &p),
            |x| tonemap::uchimura(x, &p),
            |x| tonemap::uchimura(x, &p),
            |x| tonemap::uchimura(x, &p),
        );
    }
}

#[test]
fn uchimura_gran_turismo_values_are_unchanged_by_the_guards() {
    // Values of the unguarded formula (toe, linear section, shoulder), rounded once.
    let p = UchimuraParams::GRAN_TURISMO;
    let (pm, a, m, l, c) = (1.0_f64, 1.0_f64, 0.22_f64, 0.4_f64, 1.33_f64);
    let l0 = (pm - m) * l / a;
    let (s0, s1) = (m + l0, m + a * l0);
    let cp = -(a * pm / (pm - s1)) / pm;
    for x in [0.05, 0.2, 0.3, 0.6, 2.0, 10.0] {
        let t = (x / m).clamp(0.0, 1.0);
        let smooth = t * t * (3.0 - 2.0 * t);
        let w2 = if x >= s0 { 1.0 } else { 0.0 };
        let want = (m * (x / m).powf(c)) * (1.0 - smooth)
            + (a * (x - m) + m) * (smooth - w2)
            + (pm - (pm - s1) * (cp * (x - s0)).exp()) * w2;
        let got = tonemap::uchimura(x, &p);
        // powf and exp are libm's and std's: a few ulps apart at most.
        assert!(
            (got - want.clamp(0.0, 1.0)).abs() < 1e-15,
            "x = {x}: {got} vs {want}"
        );
    }
}

#[test]
fn reinhard_extended_luminance_tiny_white_keeps_zero_channels_at_zero() {
    // L / w / w overflows to +inf for w = 1e-30 in f32; the zero channels gave 0 * inf = NaN.
    let w = 1e-30_f32;
    let out = reinhard_extended_luminance(V3::new(1.0_f32, 0.0, 0.0), w);
    assert_eq!((out.x, out.y, out.z), (1.0, 0.0, 0.0));
    let out = reinhard_extended_luminance(V3::new(1.0_f64, 0.0, 0.0), 1e-300);
    assert_eq!((out.x, out.y, out.z), (1.0, 0.0, 0.0));
    let l = reinhard_extended_luminance(
        V3::new(f32x8::splat(1.0), f32x8::splat(0.0), f32x8::splat(0.5)),
        f32x8::splat(w),
    );
    assert_eq!(l.y.to_array(), [0.0; 8]);
    assert_eq!(l.z.to_array(), [1.0; 8]);
    // Below the cap nothing changes: w = 4 at L = 1 is (1 + 1/16) / 2 per unit channel.
    let out = reinhard_extended_luminance(V3::new(1.0_f64, 1.0, 1.0), 4.0);
    assert_eq!(out.x, 1.0 * (1.0 + 1.0 / 4.0 / 4.0) / 2.0);
    // A NaN channel still reaches every channel.
    let out = reinhard_extended_luminance(V3::new(1.0_f32, f32::NAN, 0.0), w);
    assert!(out.x.is_nan() && out.z.is_nan());
}
