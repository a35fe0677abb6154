//! Transfer functions, gamma, luminance and every tonemap operator over their whole
//! documented domain on f32, f64, f32x8 and f64x4: 0, subnormals, the breakpoints and 40
//! neighbouring floats each side, 1, large values, MAX, +-inf and NaN. Finite where the input
//! is, monotone within each piece, the standard's values at reference points (computed with
//! 300-bit mpmath from IEC 61966-2-1 and BT.709), NaN for NaN input and invalid parameters,
//! lanes bit-identical to scalars.
#![cfg(feature = "tonemap")]
// Reference values are quoted with the digits mpmath printed.
#![allow(clippy::excessive_precision)]

use brdf::color::{self, gamma_decode, gamma_encode, rec709_oetf, srgb_eotf, srgb_oetf};
use brdf::tonemap::{self, HableParams, Operator, UchimuraParams};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

/// Sorted non-negative f32 inputs: 0, subnormals, each breakpoint with 40 neighbours each
/// side, a sweep of [0, 1], large values, MAX.
fn inputs32() -> Vec<f32> {
    let mut v = vec![
        0.0,
        f32::from_bits(1),
        f32::from_bits(1000),
        f32::MIN_POSITIVE,
        1e-30,
    ];
    for b in [0.003_130_8f32, 0.040_45, 0.040_449_936, 0.018, 0.081, 1.0] {
        for d in -40i32..=40 {
            v.push(f32::from_bits((b.to_bits() as i32 + d) as u32));
        }
    }
    v.extend((0..=10_000).map(|i| i as f32 / 10_000.0));
    v.extend([2.0, 100.0, 1e10, 1e30, f32::MAX]);
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

fn inputs64() -> Vec<f64> {
    let mut v = vec![0.0, f64::from_bits(1), f64::MIN_POSITIVE, 1e-300];
    for b in [0.003_130_8f64, 0.040_45, 12.92 * 0.003_130_8, 0.018, 1.0] {
        for d in -40i64..=40 {
            v.push(f64::from_bits((b.to_bits() as i64 + d) as u64));
        }
    }
    v.extend((0..=10_000).map(|i| i as f64 / 10_000.0));
    v.extend([2.0, 100.0, 1e100, 1e300, f64::MAX]);
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

/// The standard's own step: the OETF's power piece at 0.0031308 lies 2.85e-8 below its
/// linear piece (IEC 61966-2-1's rounded constants); nothing else may decrease.
const SRGB_OETF_STEP: f64 = 2.852e-8;

#[test]
fn transfer_functions_are_finite_non_negative_and_monotone_per_piece() {
    fn check(name: &str, xs: &[f64], f: impl Fn(f64) -> f64, allowed_step: f64) -> f64 {
        let mut worst_drop = 0.0f64;
        let mut prev = 0.0;
        for &x in xs {
            let y = f(x);
            assert!(y.is_finite() && y >= 0.0, "{name}({x:e}) = {y}");
            worst_drop = worst_drop.max(prev - y);
            prev = y;
        }
        assert!(worst_drop <= allowed_step, "{name}: drop {worst_drop:e}");
        worst_drop
    }
    let x32: Vec<f64> = inputs32().iter().map(|&x| x as f64).collect();
    let x64 = inputs64();
    let mut lines = Vec::new();
    for (ty, xs) in [("f32", &x32), ("f64", &x64)] {
        let is32 = ty == "f32";
        let f = |g: fn(f32) -> f32, h: fn(f64) -> f64| {
            move |x: f64| if is32 { g(x as f32) as f64 } else { h(x) }
        };
        let d1 = check("srgb_oetf", xs, f(srgb_oetf, srgb_oetf), SRGB_OETF_STEP);
        let d2 = check("srgb_eotf", xs, f(srgb_eotf, srgb_eotf), 0.0);
        let d3 = check("rec709_oetf", xs, f(rec709_oetf, rec709_oetf), 0.0);
        let d4 = check(
            "gamma_encode",
            xs,
            f(|x| gamma_encode(x, 2.2), |x| gamma_encode(x, 2.2)),
            0.0,
        );
        lines.push(format!(
            "{ty}: largest drop oetf {d1:e} (the standard's step), eotf {d2:e}, rec709 {d3:e}, gamma {d4:e}"
        ));
    }
    for l in lines {
        println!("{l}");
    }
}

#[test]
fn transfer_functions_match_the_standards_at_reference_points() {
    // (input, IEC 61966-2-1 / BT.709 value from 300-bit mpmath for the f64 input, the same
    // for the f32 input). Bound: 1 ulp in f32, 4 in f64 (the crate's accuracy target; the
    // measured maxima over 2,300 points are 1 and 3.8).
    type Case = (fn(f64) -> f64, fn(f32) -> f32, f64, f64, f64);
    let cases: [(&str, Case); 8] = [
        (
            "oetf",
            (
                srgb_oetf,
                srgb_oetf,
                0.18,
                0.461_356_129_500_441_6,
                0.461_356_138_049_670_35,
            ),
        ),
        (
            "oetf",
            (
                srgb_oetf,
                srgb_oetf,
                0.003_130_9,
                0.040_451_177_778_598_04,
                0.040_451_177_461_996_477,
            ),
        ),
        (
            "oetf",
            (
                srgb_oetf,
                srgb_oetf,
                0.8,
                0.906_331_753_344_059_5,
                0.906_331_759_312_792_5,
            ),
        ),
        (
            "eotf",
            (
                srgb_eotf,
                srgb_eotf,
                0.5,
                0.214_041_140_482_232_44,
                0.214_041_140_482_232_44,
            ),
        ),
        (
            "eotf",
            (
                srgb_eotf,
                srgb_eotf,
                0.040_46,
                0.003_131_594_552_688_990_4,
                0.003_131_594_684_745_417_3,
            ),
        ),
        (
            "eotf",
            (
                srgb_eotf,
                srgb_eotf,
                0.9,
                0.787_412_289_395_617_1,
                0.787_412_242_216_463,
            ),
        ),
        (
            "rec709",
            (
                rec709_oetf,
                rec709_oetf,
                0.5,
                0.705_515_089_922_121_2,
                0.705_515_089_922_121_2,
            ),
        ),
        (
            "rec709",
            (
                rec709_oetf,
                rec709_oetf,
                0.0181,
                0.081_697_877_417_346_57,
                0.081_697_881_541_053_65,
            ),
        ),
    ];
    let mut worst = (0u64, 0u64);
    for (name, (f64f, f32f, x, want64, want32)) in cases {
        let u64_ = (f64f(x).to_bits() as i64 - want64.to_bits() as i64).unsigned_abs();
        let got32 = f32f(x as f32);
        let u32_ = (got32.to_bits() as i64 - (want32 as f32).to_bits() as i64).unsigned_abs();
        println!("{name}({x}): f64 {u64_} ulp, f32 {u32_} ulp");
        worst = (worst.0.max(u64_), worst.1.max(u32_));
    }
    assert!(worst.0 <= 4 && worst.1 <= 1, "{worst:?}");
    // BT.709's threshold for the value as given: the f32 nearest 0.018 lies below 0.018, so it
    // takes the linear piece, 4.5 L, like the f64 path (not the power piece's 0.0812479).
    assert_eq!(rec709_oetf(0.018f32), (4.5 * 0.018f32 as f64) as f32);
    assert_eq!(rec709_oetf(0.018f64), 4.5 * 0.018);
    // IEC 61966-2-1's breakpoints: linear at and below, power above.
    assert_eq!(srgb_oetf(0.003_130_8f64), 12.92 * 0.003_130_8);
    assert_eq!(srgb_eotf(0.040_45f64), 0.040_45 / 12.92);
    assert!(srgb_eotf(f64::from_bits(0.040_45f64.to_bits() + 1)) > 0.040_45 / 12.92);
}

/// Just above the sRGB OETF's breakpoint, (0.0031308, 0.0031308 + 2.2e-9], the power piece
/// applies: the first 8 floats above it and points spread over that interval, in f32 and f64,
/// within 1 ulp (f32) or 4 (f64) of 1.055 x^(1/2.4) - 0.055 evaluated in f64, and 2.85e-8
/// below the linear piece, never equal to it. Also the Rec.709 OETF's f32 neighbours of 0.018.
#[test]
fn transfer_functions_take_the_standards_piece_next_to_each_breakpoint() {
    let power = |x: f64| 1.055 * x.powf(1.0 / 2.4) - 0.055;
    let b = color::SRGB_OETF_BREAK;
    let mut xs64: Vec<f64> = (1..=8).map(|k| f64::from_bits(b.to_bits() + k)).collect();
    xs64.extend((1..=22).map(|k| b + f64::from(k) * 1e-10));
    for x in xs64 {
        let y = srgb_oetf(x);
        let ulps = (y.to_bits() as i64 - power(x).to_bits() as i64).unsigned_abs();
        // The f64 power piece here is itself a few roundings (the oracle holds srgb_oetf to
        // 2.9 ulp of the exact value): 4 ulp tell the pieces apart by 6 orders of magnitude.
        assert!(
            ulps <= 4,
            "f64 oetf({x:e}) = {y:e}, power piece {:e}",
            power(x)
        );
        assert!(
            12.92 * x - y > 2.8e-8,
            "f64 oetf({x:e}) on the linear piece"
        );
    }
    let b32 = b as f32;
    for k in 1..=8u32 {
        let x = f32::from_bits(b32.to_bits() + k);
        assert!(f64::from(x) > b);
        let y = srgb_oetf(x);
        let want = power(f64::from(x)) as f32;
        let ulps = (y.to_bits() as i64 - want.to_bits() as i64).unsigned_abs();
        assert!(ulps <= 1, "f32 oetf({x:e}) = {y:e}, power piece {want:e}");
    }
    // Below and at the breakpoint (as exact values), the linear piece.
    for k in 0..=8u32 {
        let x = f32::from_bits(b32.to_bits() - k);
        if f64::from(x) <= b {
            assert_eq!(
                srgb_oetf(x),
                (12.92 * f64::from(x)) as f32,
                "f32 oetf({x:e})"
            );
        }
    }
    // Rec.709: 4.5 L up to 0.018 (as an exact value), 1.099 L^0.45 - 0.099 above.
    let r = color::REC709_BREAK as f32;
    for k in -8i32..=8 {
        let x = f32::from_bits((r.to_bits() as i32 + k) as u32);
        let xe = f64::from(x);
        let want = if xe <= color::REC709_BREAK {
            4.5 * xe
        } else {
            1.099 * xe.powf(0.45) - 0.099
        } as f32;
        let ulps = (rec709_oetf(x).to_bits() as i64 - want.to_bits() as i64).unsigned_abs();
        assert!(
            ulps <= 1,
            "f32 rec709({x:e}) = {}, want {want:e}",
            rec709_oetf(x)
        );
    }
}

#[test]
fn nan_is_reported_and_negative_input_is_clamped_on_every_lane_type() {
    fn check<T: Real>() {
        let nan = T::splat(f64::NAN);
        let all_nan = |x: T| {
            (0..T::LANES).all(|i| {
                let v: f64 = x.lane(i).into();
                v.is_nan()
            })
        };
        let all_zero = |x: T| {
            (0..T::LANES).all(|i| {
                let v: f64 = x.lane(i).into();
                v == 0.0
            })
        };
        assert!(all_nan(srgb_oetf(nan)) && all_nan(srgb_eotf(nan)) && all_nan(rec709_oetf(nan)));
        assert!(all_nan(color::srgb_oetf_fast(nan)));
        assert!(
            all_nan(gamma_encode(nan, T::splat(2.2))) && all_nan(gamma_decode(nan, T::splat(2.2)))
        );
        for g in [f64::NAN, 0.0, -2.2, f64::INFINITY] {
            assert!(all_nan(gamma_encode(T::splat(0.5), T::splat(g))));
            assert!(all_nan(gamma_decode(T::splat(0.5), T::splat(g))));
        }
        assert!(all_nan(color::luminance(V3::new(T::ONE, nan, T::ONE))));
        for x in [-1.0, -0.0, -1e-30, -1e30] {
            let x = T::splat(x);
            assert!(all_zero(srgb_oetf(x)) && all_zero(srgb_eotf(x)) && all_zero(rec709_oetf(x)));
            assert!(all_zero(gamma_encode(x, T::splat(2.2))));
        }
        // Infinities are not in the domain (crate docs, "Bad input", rule 5): NaN, not black
        // or +inf.
        for x in [f64::NEG_INFINITY, f64::INFINITY] {
            let x = T::splat(x);
            assert!(all_nan(srgb_oetf(x)) && all_nan(srgb_eotf(x)) && all_nan(rec709_oetf(x)));
            assert!(all_nan(color::srgb_oetf_fast(x)));
            assert!(all_nan(gamma_encode(x, T::splat(2.2))));
            assert!(all_nan(gamma_decode(x, T::splat(2.2))));
        }
        // Finite input never overflows to inf: results beyond the type are capped at MAX.
        for x in [T::MAX, T::splat(1e30)] {
            for y in [
                srgb_eotf(x),
                gamma_decode(x, T::splat(2.2)),
                gamma_encode(x, T::splat(0.1)),
            ] {
                assert!((0..T::LANES).all(|i| {
                    let v: f64 = y.lane(i).into();
                    v.is_finite()
                }));
            }
        }
        // Every operator: NaN channel -> NaN, finite extremes -> [0, 1], invalid params -> NaN.
        let ops = Operator::all();
        for op in ops {
            let out = op.apply(V3::new(nan, T::splat(0.5), T::splat(0.5)));
            assert!(all_nan(out.x), "{op:?}");
            for x in [0.0, 1e-30, 0.18, 1.0, 1e9, 1e30, f64::INFINITY] {
                let x = T::splat(x).min(T::MAX);
                let o = op.apply(V3::new(x, T::splat(0.5), x));
                for c in [o.x, o.y, o.z] {
                    assert!(
                        (0..T::LANES).all(|i| {
                            let v: f64 = c.lane(i).into();
                            (0.0..=1.0).contains(&v)
                        }),
                        "{op:?}"
                    );
                }
            }
        }
        for e in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(all_nan(tonemap::exposure_curve(T::splat(0.5), T::splat(e))));
            assert!(all_nan(tonemap::reinhard_extended(
                T::splat(0.5),
                T::splat(e)
            )));
        }
        // A subnormal white point is valid: 0 stays 0 (no 0 / 0 from w^2 underflowing).
        let sub = T::MIN_POSITIVE * T::EPSILON;
        assert!(all_zero(tonemap::reinhard_extended(T::ZERO, sub)));
        let mut h = HableParams::UNCHARTED2;
        h.white = -1.0;
        assert!(all_nan(tonemap::hable(T::splat(0.5), &h)));
        let mut u = UchimuraParams::GRAN_TURISMO;
        u.contrast = 0.0;
        assert!(all_nan(tonemap::uchimura(T::splat(0.5), &u)));
    }
    check::<f32>();
    check::<f64>();
    check::<f32x8>();
    check::<f64x4>();
}

#[test]
fn lanes_equal_scalars_bit_for_bit() {
    let mut n = 0;
    for x in inputs32() {
        let l = f32x8::splat(x);
        for (a, b) in [
            (srgb_oetf(l).lane(3), srgb_oetf(x)),
            (srgb_eotf(l).lane(4), srgb_eotf(x)),
            (rec709_oetf(l).lane(1), rec709_oetf(x)),
            (
                gamma_encode(l, f32x8::splat(2.2)).lane(0),
                gamma_encode(x, 2.2),
            ),
        ] {
            assert_eq!(a.to_bits(), b.to_bits(), "{x:e}");
            n += 1;
        }
    }
    for x in inputs64() {
        let l = f64x4::splat(x);
        for (a, b) in [
            (srgb_oetf(l).lane(3), srgb_oetf(x)),
            (srgb_eotf(l).lane(2), srgb_eotf(x)),
            (rec709_oetf(l).lane(1), rec709_oetf(x)),
        ] {
            assert_eq!(a.to_bits(), b.to_bits(), "{x:e}");
            n += 1;
        }
    }
    println!("{n} lane results equal their scalars");
}
