//! Every `Real` function on `f32x8` / `f64x4` agrees with the scalar (`libm`) path within the
//! ULP bound documented in `src/real.rs`, over the whole domain: zeros, subnormals, normals of
//! every exponent, the largest values, infinities and NaN.

use brdf::Real;
use brdf::wide::{f32x8, f64x4};

/// Distance in units in the last place between two values of one type; 0 when both are NaN or
/// both are the same infinity, u64::MAX when one is NaN and the other is not.
fn ulp32(a: f32, b: f32) -> u64 {
    if a.is_nan() || b.is_nan() {
        return if a.is_nan() && b.is_nan() {
            0
        } else {
            u64::MAX
        };
    }
    let key = |x: f32| {
        let i = x.to_bits() as i32;
        // Map the sign-magnitude bit pattern onto a monotonic integer line.
        (if i < 0 { i32::MIN - i } else { i }) as i64
    };
    (key(a) - key(b)).unsigned_abs()
}

fn ulp64(a: f64, b: f64) -> u64 {
    if a.is_nan() || b.is_nan() {
        return if a.is_nan() && b.is_nan() {
            0
        } else {
            u64::MAX
        };
    }
    let key = |x: f64| {
        let i = x.to_bits() as i64;
        (if i < 0 { i64::MIN - i } else { i }) as i128
    };
    u64::try_from((key(a) - key(b)).unsigned_abs()).unwrap_or(u64::MAX)
}

/// f32 inputs: every 4099th bit pattern of the whole line (positive and negative, normals and
/// subnormals, about 2 million values) plus the special values.
fn inputs32() -> Vec<f32> {
    let mut v: Vec<f32> = (0..=u32::MAX).step_by(4099).map(f32::from_bits).collect();
    v.extend([
        0.0,
        -0.0,
        f32::MIN_POSITIVE,
        f32::MIN_POSITIVE / 2.0,
        1e-45,
        f32::MAX,
        -f32::MAX,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        1.0,
        -1.0,
        0.5,
        core::f32::consts::PI,
    ]);
    // Dense sweep of the range the kernels live in.
    v.extend((0..200_000).map(|i| -10.0 + 20.0 * i as f32 / 200_000.0));
    v
}

/// f64 inputs: every (2^43 + 1)th bit pattern (about 2 million) plus the special values and a
/// dense sweep of [-10, 10].
fn inputs64() -> Vec<f64> {
    let step = (1u64 << 43) + 1;
    let mut v: Vec<f64> = (0..(1u64 << 21))
        .map(|i| f64::from_bits(i.wrapping_mul(step)))
        .collect();
    v.extend([
        0.0,
        -0.0,
        f64::MIN_POSITIVE,
        f64::MIN_POSITIVE / 2.0,
        5e-324,
        f64::MAX,
        -f64::MAX,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        1.0,
        -1.0,
        0.5,
        core::f64::consts::PI,
    ]);
    v.extend((0..200_000).map(|i| -10.0 + 20.0 * i as f64 / 200_000.0));
    v
}

/// Worst ULP distance of `lane(x)` against `scalar(x)` over the inputs kept by `domain`.
fn worst32(
    domain: impl Fn(f32) -> bool,
    lane: impl Fn(f32x8) -> f32x8,
    scalar: impl Fn(f32) -> f32,
) -> (u64, f32) {
    let xs: Vec<f32> = inputs32().into_iter().filter(|&x| domain(x)).collect();
    let mut worst = (0, 0.0);
    for chunk in xs.chunks(8) {
        let v = f32x8::from_fn(|i| chunk[i % chunk.len()]);
        let r = lane(v).to_array();
        for (i, &x) in chunk.iter().enumerate() {
            let d = ulp32(r[i], scalar(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
    }
    worst
}

fn worst64(
    domain: impl Fn(f64) -> bool,
    lane: impl Fn(f64x4) -> f64x4,
    scalar: impl Fn(f64) -> f64,
) -> (u64, f64) {
    let xs: Vec<f64> = inputs64().into_iter().filter(|&x| domain(x)).collect();
    let mut worst = (0, 0.0);
    for chunk in xs.chunks(4) {
        let v = f64x4::from_fn(|i| chunk[i % chunk.len()]);
        let r = lane(v).to_array();
        for (i, &x) in chunk.iter().enumerate() {
            let d = ulp64(r[i], scalar(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
    }
    worst
}

macro_rules! unary_bound_test {
    ($name:ident, $method:ident, $bound32:expr, $bound64:expr, $domain:expr) => {
        #[test]
        fn $name() {
            let domain = $domain;
            let (u32_, x32) = worst32(
                |x| domain(x as f64),
                |v| Real::$method(v),
                |x| Real::$method(x),
            );
            let (u64_, x64) = worst64(domain, |v| Real::$method(v), |x| Real::$method(x));
            println!(
                "{}: f32x8 max {} ULP (at {:e}), f64x4 max {} ULP (at {:e})",
                stringify!($method),
                u32_,
                x32,
                u64_,
                x64
            );
            assert!(
                u32_ <= $bound32,
                "f32x8 {}: {} ULP at {:e}",
                stringify!($method),
                u32_,
                x32
            );
            assert!(
                u64_ <= $bound64,
                "f64x4 {}: {} ULP at {:e}",
                stringify!($method),
                u64_,
                x64
            );
        }
    };
}

fn everywhere(_: f64) -> bool {
    true
}

unary_bound_test!(sqrt_is_exact, sqrt, 0, 0, everywhere);
unary_bound_test!(recip_is_exact, recip, 0, 0, everywhere);
unary_bound_test!(abs_is_exact, abs, 0, 0, everywhere);
unary_bound_test!(floor_is_exact, floor, 0, 0, everywhere);
unary_bound_test!(exp_within_bound, exp, 1, 2, everywhere);
unary_bound_test!(exp2_within_bound, exp2, 1, 0, everywhere);
unary_bound_test!(ln_within_bound, ln, 1, 1, everywhere);
unary_bound_test!(erf_is_exact, erf, 0, 0, everywhere);
unary_bound_test!(erfc_is_exact, erfc, 0, 0, everywhere);
unary_bound_test!(tan_is_exact, tan, 0, 0, everywhere);
unary_bound_test!(sin_within_bound, sin, 1, 1, everywhere);
unary_bound_test!(cos_within_bound, cos, 1, 1, everywhere);
unary_bound_test!(atan_within_bound, atan, 3, 1, everywhere);
unary_bound_test!(acos_within_bound, acos, 1, 2, everywhere);
unary_bound_test!(asin_within_bound, asin, 2, 2, everywhere);

/// Binary functions: the second argument from a fixed set spanning signs, magnitudes and
/// specials.
const SECOND: [f64; 14] = [
    0.0,
    -0.0,
    1e-30,
    0.5,
    1.0,
    -1.0,
    2.0,
    5.0,
    -3.7,
    1e4,
    1e30,
    f64::INFINITY,
    -f64::INFINITY,
    f64::NAN,
];

macro_rules! binary_bound_test {
    ($name:ident, $method:ident, $bound32:expr, $bound64:expr) => {
        #[test]
        fn $name() {
            let mut w32 = (0u64, 0.0f32, 0.0f32);
            let mut w64 = (0u64, 0.0f64, 0.0f64);
            for y in SECOND {
                let (u, x) = worst32(
                    |_| true,
                    |v| Real::$method(v, f32x8::splat(y as f32)),
                    |x| Real::$method(x, y as f32),
                );
                if u > w32.0 {
                    w32 = (u, x, y as f32);
                }
                let (u, x) = worst64(
                    |_| true,
                    |v| Real::$method(v, f64x4::splat(y)),
                    |x| Real::$method(x, y),
                );
                if u > w64.0 {
                    w64 = (u, x, y);
                }
            }
            println!(
                "{}: f32x8 max {:?}, f64x4 max {:?}",
                stringify!($method),
                w32,
                w64
            );
            assert!(
                w32.0 <= $bound32,
                "f32x8 {}: {:?}",
                stringify!($method),
                w32
            );
            assert!(
                w64.0 <= $bound64,
                "f64x4 {}: {:?}",
                stringify!($method),
                w64
            );
        }
    };
}

binary_bound_test!(atan2_within_bound, atan2, 3, 2);
binary_bound_test!(pow_is_exact, pow, 0, 0);
binary_bound_test!(min_is_exact, min, 0, 0);
binary_bound_test!(max_is_exact, max, 0, 0);
binary_bound_test!(copysign_is_exact, copysign, 0, 0);

#[test]
fn mul_add_matches_scalar_exactly() {
    let xs = inputs32();
    for w in xs.windows(3).step_by(997) {
        let (a, b, c) = (w[0], w[1], w[2]);
        let lane = f32x8::splat(a)
            .mul_add(f32x8::splat(b), f32x8::splat(c))
            .lane(0);
        assert_eq!(ulp32(lane, Real::mul_add(a, b, c)), 0, "{a} {b} {c}");
    }
}

#[test]
fn select_and_masks_agree_lane_by_lane() {
    let a = f32x8::from_fn(|i| i as f32 - 3.5);
    let b = f32x8::splat(0.0);
    let m = a.simd_gt(b);
    let s = f32x8::select(m, a, -a);
    for i in 0..8 {
        let x = a.lane(i);
        assert_eq!(s.lane(i), if x > 0.0 { x } else { -x });
    }
    assert!(brdf::Mask::any(m) && !brdf::Mask::all(m));
    // NaN compares false in every lane, as on the scalar path.
    let n = f32x8::splat(f32::NAN);
    assert!(!brdf::Mask::any(n.simd_lt(b) | n.simd_ge(b) | n.simd_eq(n)));
    assert!(brdf::Mask::all(n.is_nan()) && !brdf::Mask::any(n.is_finite()));
}

#[test]
fn clamp_propagates_nan_identically() {
    let nan = f64::NAN;
    assert!(Real::clamp(nan, 0.0, 1.0).is_nan());
    assert!(
        Real::clamp(f64x4::splat(nan), f64x4::splat(0.0), f64x4::splat(1.0))
            .lane(2)
            .is_nan()
    );
    assert_eq!(Real::max(1.0_f32, f32::NAN), 1.0);
    assert_eq!(
        Real::max(f32x8::splat(1.0), f32x8::splat(f32::NAN)).lane(0),
        1.0
    );
}
