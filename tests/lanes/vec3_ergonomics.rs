//! `V3`'s operators, maps and conversions agree with glam's (an independent implementation of
//! the same component-wise arithmetic) on scalars, give lane by lane the scalar result on
//! `f32x8` and `f64x4`, and round-trip every glam, array and lane-array form exactly.

use crate::common;

use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};
use common::Rng;
use glam::{DVec3, Vec3, Vec3A};

/// Components in [-4, 4], never within 0.25 of 0 (so quotients stay finite and well
/// scaled) and with full 52-bit mantissas (so a rounding difference shows).
fn component(rng: &mut Rng) -> f64 {
    let m = 0.25 + 3.75 * rng.next_f64();
    if rng.next_f64() < 0.5 { -m } else { m }
}

fn dvec(rng: &mut Rng) -> DVec3 {
    DVec3::new(component(rng), component(rng), component(rng))
}

/// Every operator of `V3` applied to (a, b, s), in a fixed order, as plain arrays.
fn ops<T: Real>(a: V3<T>, b: V3<T>, s: T) -> [[T; 3]; 17] {
    let mut add = a;
    add += b;
    let mut sub = a;
    sub -= b;
    let mut mul = a;
    mul *= b;
    let mut mul_s = a;
    mul_s *= s;
    let mut div = a;
    div /= b;
    let mut div_s = a;
    div_s /= s;
    [
        (a + b).into(),
        (a - b).into(),
        (a * b).into(),
        (a * s).into(),
        (a / b).into(),
        (a / s).into(),
        add.into(),
        sub.into(),
        mul.into(),
        mul_s.into(),
        div.into(),
        div_s.into(),
        a.min(b).into(),
        a.max(b).into(),
        a.abs().into(),
        a.zip_map(b, |x, y| x.mul_add(y, s)).into(),
        a.map(|x| x * x - s).into(),
    ]
}

const OP_NAMES: [&str; 17] = [
    "a + b", "a - b", "a * b", "a * s", "a / b", "a / s", "a += b", "a -= b", "a *= b", "a *= s",
    "a /= b", "a /= s", "min", "max", "abs", "zip_map", "map",
];

#[test]
fn scalar_operators_equal_glams_bit_for_bit() {
    // glam's Vec3 / DVec3 operators are component-wise IEEE operations, as ours claim to be:
    // any difference (a division done as a multiplication by 1/s, a swapped operand) shows as
    // a differing bit. min/max agree with glam's on finite, non-NaN input.
    let mut rng = Rng(0x5eed_0001);
    let mut checked = 0;
    for _ in 0..2000 {
        let (ga, gb, gs) = (dvec(&mut rng), dvec(&mut rng), component(&mut rng));
        let expect64: [DVec3; 15] = [
            ga + gb,
            ga - gb,
            ga * gb,
            ga * gs,
            ga / gb,
            ga / gs,
            ga + gb,
            ga - gb,
            ga * gb,
            ga * gs,
            ga / gb,
            ga / gs,
            ga.min(gb),
            ga.max(gb),
            ga.abs(),
        ];
        let got64 = ops(V3::from(ga), V3::from(gb), gs);
        for (i, e) in expect64.iter().enumerate() {
            assert_eq!(
                got64[i],
                e.to_array(),
                "f64 {} for {ga} {gb} {gs}",
                OP_NAMES[i]
            );
        }
        // The scalar on the left.
        assert_eq!(DVec3::from(gs * V3::from(ga)), gs * ga);

        let (fa, fb, fs) = (ga.as_vec3(), gb.as_vec3(), gs as f32);
        let expect32: [Vec3; 15] = [
            fa + fb,
            fa - fb,
            fa * fb,
            fa * fs,
            fa / fb,
            fa / fs,
            fa + fb,
            fa - fb,
            fa * fb,
            fa * fs,
            fa / fb,
            fa / fs,
            fa.min(fb),
            fa.max(fb),
            fa.abs(),
        ];
        let got32 = ops(V3::from(fa), V3::from(fb), fs);
        for (i, e) in expect32.iter().enumerate() {
            assert_eq!(
                got32[i],
                e.to_array(),
                "f32 {} for {fa} {fb} {fs}",
                OP_NAMES[i]
            );
        }
        assert_eq!(Vec3::from(fs * V3::from(fa)), fs * fa);
        checked += 2 * 16;
    }
    println!("scalar V3 operators vs glam: {checked} results, all bit-identical");
}

#[test]
fn lane_operators_equal_scalar_operators_lane_by_lane() {
    // Bit-identical: every operator is one IEEE operation per component (mul_add in zip_map
    // is the same instruction on lanes and scalars on one target).
    let mut rng = Rng(0x5eed_0002);
    for _ in 0..500 {
        let a: [DVec3; 8] = core::array::from_fn(|_| dvec(&mut rng));
        let b: [DVec3; 8] = core::array::from_fn(|_| dvec(&mut rng));
        let s: [f64; 8] = core::array::from_fn(|_| component(&mut rng));

        let (a8, b8) = (a.map(|v| v.as_vec3()), b.map(|v| v.as_vec3()));
        let s8 = s.map(|x| x as f32);
        let lanes = ops(V3::from_lanes(a8), V3::from_lanes(b8), f32x8::new(s8));
        let left = f32x8::new(s8) * V3::from_lanes(a8);
        for i in 0..8 {
            let scalar = ops(V3::from(a8[i]), V3::from(b8[i]), s8[i]);
            for (k, op) in OP_NAMES.iter().enumerate() {
                let lane = lanes[k].map(|c| c.lane(i));
                assert_eq!(lane, scalar[k], "f32x8 lane {i}: {op}");
            }
            assert_eq!(
                left.lane(i),
                s8[i] * V3::from(a8[i]),
                "f32x8 lane {i}: s * a"
            );
        }

        let (a4, b4): ([DVec3; 4], [DVec3; 4]) = (
            core::array::from_fn(|i| a[i]),
            core::array::from_fn(|i| b[i]),
        );
        let s4: [f64; 4] = core::array::from_fn(|i| s[i]);
        let lanes = ops(V3::from_lanes(a4), V3::from_lanes(b4), f64x4::new(s4));
        let left = f64x4::new(s4) * V3::from_lanes(a4);
        for i in 0..4 {
            let scalar = ops(V3::from(a4[i]), V3::from(b4[i]), s4[i]);
            for (k, op) in OP_NAMES.iter().enumerate() {
                let lane = lanes[k].map(|c| c.lane(i));
                assert_eq!(lane, scalar[k], "f64x4 lane {i}: {op}");
            }
            assert_eq!(
                left.lane(i),
                s4[i] * V3::from(a4[i]),
                "f64x4 lane {i}: s * a"
            );
        }
    }
}

#[test]
fn min_max_keep_reals_nan_rule_and_elements_propagate_any_nan() {
    // Real::min/max: NaN in self propagates, NaN in the argument is ignored (glam's min
    // would drop either), on every lane type alike.
    let nan = f64::NAN;
    let a = V3::new(nan, 2.0_f64, -1.0);
    let b = V3::new(0.0, nan, 3.0);
    let (mn, mx) = (a.min(b), a.max(b));
    assert!(mn.x.is_nan() && mx.x.is_nan());
    assert_eq!((mn.y, mn.z, mx.y, mx.z), (2.0, -1.0, 2.0, 3.0));
    let lanes = V3::<f32x8>::broadcast(Vec3::new(f32::NAN, 2.0, -1.0))
        .min(V3::<f32x8>::broadcast(Vec3::new(0.0, f32::NAN, 3.0)));
    for i in 0..8 {
        let l = lanes.lane(i);
        assert!(l.x.is_nan() && l.y == 2.0 && l.z == -1.0, "lane {i}: {l:?}");
    }
    // The reductions have no argument to ignore: a NaN in any component gives NaN, so a
    // colour's NaN channel cannot vanish into its peak.
    for i in 0..3 {
        let mut c = [1.0_f64, 5.0, -2.0];
        c[i] = f64::NAN;
        let c = V3::from(c);
        assert!(
            c.max_element().is_nan() && c.min_element().is_nan(),
            "NaN in {i}"
        );
        let l = V3::<f32x8>::broadcast(c.map(|x| x as f32));
        let (mx, mn) = (l.max_element().to_array(), l.min_element().to_array());
        assert!(
            mx.iter().chain(&mn).all(|x| x.is_nan()),
            "lanes, NaN in {i}"
        );
    }
    assert_eq!(V3::new(1.0_f32, 5.0, -2.0).max_element(), 5.0);
    assert_eq!(V3::new(1.0_f32, 5.0, -2.0).min_element(), -2.0);
    let e = V3::<f64x4>::from_lanes([DVec3::new(1.0, 5.0, -2.0); 4]);
    assert_eq!(e.max_element(), f64x4::splat(5.0));
    assert_eq!(e.min_element(), f64x4::splat(-2.0));
}

#[test]
fn conversions_round_trip_exactly() {
    let mut rng = Rng(0x5eed_0003);
    for _ in 0..200 {
        let d = dvec(&mut rng);
        let f = d.as_vec3();
        // Scalar glam types and arrays, both ways.
        assert_eq!(DVec3::from(V3::from(d)), d);
        assert_eq!(Vec3::from(V3::from(f)), f);
        assert_eq!(Vec3A::from(V3::from(Vec3A::from(f))), Vec3A::from(f));
        assert_eq!(V3::from(Vec3A::from(f)), V3::from(f));
        assert_eq!(<[f64; 3]>::from(V3::from(d.to_array())), d.to_array());
        assert_eq!(V3::from(f).to_array(), f.to_array());
        let into: Vec3A = V3::from(f).into();
        assert_eq!(Vec3::from(into), f);
    }

    // Lane arrays of every accepted kind, both ways; lane i is element i.
    let f8: [Vec3; 8] = core::array::from_fn(|i| Vec3::new(i as f32, -(i as f32), 0.5 * i as f32));
    let l = V3::from_lanes(f8);
    assert_eq!(l.to_lanes(), f8);
    assert_eq!(V3::from_lanes(f8.map(Vec3A::from)), l);
    assert_eq!(V3::from_lanes(f8.map(V3::from)), l);
    assert_eq!(V3::from_lanes(f8.map(|v| v.to_array())), l);
    assert_eq!(<[Vec3A; 8]>::from(l), f8.map(Vec3A::from));
    assert_eq!(<[V3<f32>; 8]>::from(l), f8.map(V3::from));
    assert_eq!(<[[f32; 3]; 8]>::from(l), f8.map(|v| v.to_array()));
    for (i, v) in f8.iter().enumerate() {
        assert_eq!(Vec3::from(l.lane(i)), *v);
    }

    let d4: [DVec3; 4] = core::array::from_fn(|i| DVec3::new(0.1 * i as f64, 1.0, -(i as f64)));
    let l = V3::from_lanes(d4);
    assert_eq!(l.to_lanes(), d4);
    assert_eq!(V3::from_lanes(d4.map(V3::from)), l);
    assert_eq!(V3::from_lanes(d4.map(|v| v.to_array())), l);
    assert_eq!(<[V3<f64>; 4]>::from(l), d4.map(V3::from));
    assert_eq!(<[[f64; 3]; 4]>::from(l), d4.map(|v| v.to_array()));
}

#[test]
fn broadcast_puts_one_vector_in_every_lane_and_splat_one_value_in_every_component() {
    let v = Vec3::new(0.25, -0.5, 0.75);
    let b = V3::<f32x8>::broadcast(v);
    assert_eq!(b, V3::from_lanes([v; 8]));
    assert_eq!(V3::<f32x8>::broadcast(Vec3A::from(v)), b);
    assert_eq!(V3::<f32x8>::broadcast(V3::from(v)), b);
    for i in 0..8 {
        assert_eq!(Vec3::from(b.lane(i)), v);
    }
    let d = DVec3::new(0.1, 0.2, 0.3);
    assert_eq!(V3::<f64x4>::broadcast(d), V3::from_lanes([d; 4]));
    // On scalar types broadcast is the plain conversion.
    assert_eq!(V3::<f32>::broadcast(v), V3::from(v));
    assert_eq!(V3::<f64>::broadcast(d), V3::from(d));
    // splat: three equal components (of a scalar or of a lane value).
    assert_eq!(V3::splat(0.5_f32), V3::new(0.5, 0.5, 0.5));
    let s = V3::splat(f32x8::new([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]));
    assert_eq!(s.lane(2), V3::splat(3.0));
}

#[test]
fn mirror_is_glams_reflect_of_the_negated_direction() {
    // glam's reflect takes a direction towards the surface; ours both away. v.mirror(n) and
    // (-v).reflect(n) are the same formula summed in a different order, so they agree to a
    // few ulps of |v| (bound: 4 eps; measured figure printed).
    let mut rng = Rng(0x5eed_0004);
    let (mut worst, mut angle, mut length): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for _ in 0..5000 {
        let n = dvec(&mut rng).normalize();
        let v = dvec(&mut rng).normalize();
        let ours = DVec3::from(V3::from(v).mirror(V3::from(n)));
        let glams = (-v).reflect(n);
        worst = worst.max((ours - glams).abs().max_element() / f64::EPSILON);
        // Same angle with the normal, same length: a mirror, not a rotation (or a sign flip,
        // which would give -v.n).
        angle = angle.max((ours.dot(n) - v.dot(n)).abs() / f64::EPSILON);
        length = length.max((ours.length() - 1.0).abs() / f64::EPSILON);
    }
    println!(
        "unit v, n (f64): |v.mirror(n) - (-v).reflect(n)| <= {worst:.2} eps, \
         |r.n - v.n| <= {angle:.2} eps, ||r| - 1| <= {length:.2} eps"
    );
    // Each component of 2 (v.n) n - v carries about 3 roundings of quantities up to 2 in
    // size, and a dot or a length of the result three more: 8 eps bounds all three.
    assert!(
        worst <= 8.0,
        "mirror differs from glam's reflect(-v) by {worst} eps"
    );
    assert!(
        angle <= 8.0,
        "mirror changes the angle with n by {angle} eps"
    );
    assert!(length <= 8.0, "mirror changes the length by {length} eps");
    // Lanes equal scalars.
    let v = V3::<f32x8>::broadcast(Vec3::new(0.6, 0.0, 0.8));
    assert_eq!(v.mirror(V3::unit_z()).lane(7), V3::new(-0.6, 0.0, 0.8));
}

#[test]
fn from_f64_is_real_splat_and_wides_splat_of_the_rounded_value() {
    for x in [0.1, 0.5, 1.0 / 3.0, 1e-40, 3.4e38, f64::NAN] {
        let a = <f32x8 as Real>::splat(x);
        let b = f32x8::from_f64(x);
        let c = f32x8::splat(x as f32);
        assert_eq!(
            a.to_array().map(f32::to_bits),
            b.to_array().map(f32::to_bits)
        );
        assert_eq!(
            b.to_array().map(f32::to_bits),
            c.to_array().map(f32::to_bits)
        );
        assert_eq!(
            f64x4::from_f64(x).to_array().map(f64::to_bits),
            [x.to_bits(); 4]
        );
        assert_eq!(f32::from_f64(x).to_bits(), (x as f32).to_bits());
        assert_eq!(f64::from_f64(x).to_bits(), x.to_bits());
    }
}

/// `V3::normalize` against the f64 unit vector of the same f32 components, over magnitudes
/// from the subnormals to the largest finite f32 (where `normalize_or` falls back): the
/// largest error of a component in ULPs of its own binade (components above 1e-6) and in
/// eps absolute.
#[test]
fn normalize_is_accurate_from_subnormal_to_max() {
    let mut state = 0x1234_5678_9abc_def0_u64;
    let mut unit = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut worst_ulp, mut worst_abs) = (0.0f64, 0.0f64);
    for i in 0..400_000 {
        // A random direction scaled by 2^e, e across the whole f32 range.
        let e = -149.0 + 277.0 * unit();
        let d = [unit() - 0.5, unit() - 0.5, unit() - 0.5];
        let scale = 2f64.powf(e);
        let v = V3::new(
            (d[0] * scale) as f32,
            (d[1] * scale) as f32,
            (d[2] * scale) as f32,
        );
        if !(v.x.is_finite() && v.y.is_finite() && v.z.is_finite()) {
            continue;
        }
        let n = v.normalize();
        let w = [f64::from(v.x), f64::from(v.y), f64::from(v.z)];
        let len = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
        if len == 0.0 {
            assert_eq!(n, V3::splat(0.0), "zero at {i}");
            continue;
        }
        for (got, x) in [n.x, n.y, n.z].into_iter().zip(w) {
            let exact = x / len;
            let abs = (f64::from(got) - exact).abs();
            worst_abs = worst_abs.max(abs / f64::from(f32::EPSILON));
            if exact.abs() > 1e-6 {
                let ulp = f64::from(f32::EPSILON) * 2f64.powi(exact.abs().log2().floor() as i32);
                worst_ulp = worst_ulp.max(abs / ulp);
            }
        }
    }
    println!("V3::normalize f32: max {worst_ulp:.2} ULP (own binade), {worst_abs:.2} eps absolute");
    // The bound of the error analysis in the method's docs: five roundings of 2^-24.
    assert!(
        worst_ulp <= 5.0 && worst_abs <= 2.5,
        "{worst_ulp} ULP, {worst_abs} eps"
    );
    // Where normalize_or gives up (|v|^2 overflows or underflows), normalize does not.
    let big = V3::new(3.0 * 2f32.powi(100), -4.0 * 2f32.powi(100), 0.0);
    assert_eq!(big.normalize(), V3::new(0.6, -0.8, 0.0));
    let tiny = V3::new(3.0e-44_f32, 4.0e-44, 0.0);
    assert!((tiny.normalize().length() - 1.0).abs() < 1e-6);
    assert!(V3::new(f32::NAN, 0.0, 1.0).normalize().x.is_nan());
    assert!(V3::new(f32::INFINITY, 0.0, 1.0).normalize().x.is_nan());
}
