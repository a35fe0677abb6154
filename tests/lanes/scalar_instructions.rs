//! The scalar `Real::mul_add` and `Real::sqrt` keep their definitions now that they compile to
//! single instructions: `mul_add` is the correctly rounded a b + c (one rounding) on targets
//! with FMA and `a * b + c` (two roundings) elsewhere, on f32 and f64, and agrees with the lanes
//! on the same target; `sqrt` is the correctly rounded square root (`libm`'s) bit for bit.
//! `cargo test --test lanes scalar_instructions:: -- --nocapture` prints which form this build has.

use brdf::Real;
use brdf::wide::{f32x8, f64x4};

/// Whether this build fuses (x86 with FMA, aarch64 with NEON).
const FUSED: bool = cfg!(any(
    target_feature = "fma",
    all(target_arch = "aarch64", target_feature = "neon")
));

/// Operands whose product needs more than the working precision, so that one and two
/// roundings differ, plus ordinary and special values.
fn triples32() -> Vec<(f32, f32, f32)> {
    let mut v = vec![
        (1.0 + f32::EPSILON, 1.0 - f32::EPSILON, -1.0),
        (0.1, 10.0, -1.0),
        (3.0, 1.0 / 3.0, -1.0),
        (1e30, 1e10, -f32::MAX),
        (0.0, 0.0, -0.0),
        (f32::NAN, 1.0, 1.0),
        (f32::INFINITY, 0.0, 1.0),
    ];
    let mut x = 0.123_456_79f32;
    for _ in 0..2000 {
        x = (x * 3.712_345 + 0.318_271).fract();
        v.push((x * 7.3 - 3.1, x * x * 11.0 + 0.5, -(x * 2.9)));
    }
    v
}

fn triples64() -> Vec<(f64, f64, f64)> {
    let mut v = vec![
        (1.0 + f64::EPSILON, 1.0 - f64::EPSILON, -1.0),
        (0.1, 10.0, -1.0),
        (3.0, 1.0 / 3.0, -1.0),
        (0.0, 0.0, -0.0),
        (f64::NAN, 1.0, 1.0),
    ];
    let mut x = 0.123_456_789f64;
    for _ in 0..2000 {
        x = (x * 3.712_345 + 0.318_271).fract();
        v.push((x * 7.3 - 3.1, x * x * 11.0 + 0.5, -(x * 2.9)));
    }
    v
}

fn same32(a: f32, b: f32) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

fn same64(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[test]
fn scalar_mul_add_is_fused_exactly_where_the_target_has_fma() {
    println!(
        "this build: mul_add {}",
        if FUSED { "fused" } else { "two roundings" }
    );
    let mut differ = 0;
    for (a, b, c) in triples32() {
        let got = Real::mul_add(a, b, c);
        let fused = libm::fmaf(a, b, c);
        let plain = a * b + c;
        differ += usize::from(!same32(fused, plain));
        let want = if FUSED { fused } else { plain };
        assert!(same32(got, want), "f32 {a} {b} {c}: {got} vs {want}");
        let lanes = Real::mul_add(f32x8::splat(a), f32x8::splat(b), f32x8::splat(c));
        assert!(same32(lanes.lane(3), got), "f32x8 {a} {b} {c}");
    }
    for (a, b, c) in triples64() {
        let got = Real::mul_add(a, b, c);
        let want = if FUSED { libm::fma(a, b, c) } else { a * b + c };
        assert!(same64(got, want), "f64 {a} {b} {c}: {got} vs {want}");
        let lanes = Real::mul_add(f64x4::splat(a), f64x4::splat(b), f64x4::splat(c));
        assert!(same64(lanes.lane(2), got), "f64x4 {a} {b} {c}");
    }
    // The operands are chosen so that the two forms tell apart: the test can see a change.
    println!("f32 operands where fused and unfused differ: {differ}");
    assert!(differ > 100, "only {differ} discriminating operands");
}

#[test]
fn scalar_sqrt_is_the_correctly_rounded_root() {
    let mut x = 1e-40f32;
    while x < 1e38 {
        assert!(same32(Real::sqrt(x), libm::sqrtf(x)), "f32 sqrt({x})");
        x *= 1.37;
    }
    for x in [
        0.0f32,
        -0.0,
        -1.0,
        f32::INFINITY,
        f32::NAN,
        f32::from_bits(1),
    ] {
        assert!(same32(Real::sqrt(x), libm::sqrtf(x)), "f32 sqrt({x})");
    }
    let mut y = 1e-300f64;
    while y < 1e300 {
        assert!(same64(Real::sqrt(y), libm::sqrt(y)), "f64 sqrt({y})");
        y *= 1.37;
    }
    for y in [
        0.0f64,
        -0.0,
        -1.0,
        f64::INFINITY,
        f64::NAN,
        f64::from_bits(1),
    ] {
        assert!(same64(Real::sqrt(y), libm::sqrt(y)), "f64 sqrt({y})");
    }
}
