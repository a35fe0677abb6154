//! Bad and extreme input for the Phong family, on f32, f64, f32x8 and f64x4:
//! - exponents over the whole documented domain, 0 to `T::MAX`, with cosines at 0, subnormal,
//!   grazing, 1, rounded above 1 and negative: finite and non-negative, never NaN;
//! - documented edge values: the n = 0 step, the classic model's floored divisor;
//! - a NaN in any input gives NaN (below the horizon too); parameters outside the domain give
//!   NaN from the free functions and `ParamError` from the constructors;
//! - lanes equal scalars bit for bit; f32 within a stated, printed bound of f64;
//! - proptest: finite and non-negative over the domain, exponent 0 and 10^4 included.
#![cfg(feature = "phong")]

use crate::common;
use brdf::phong::{
    self, ApproxNormalizedBlinnPhong, BlinnPhong, ClassicPhong, ModifiedPhong,
    NormalizedBlinnPhong, NormalizedPhong, PhongDiffuseSpecular,
};
use brdf::wide::{f32x8, f64x4};
use brdf::{ParamError, Real, V3};
use proptest::prelude::*;

/// Arguments: (n_dot_v, n_dot_l, lobe cosine r_dot_l or n_dot_h, kd, ks, exponent).
type Args = [f64; 6];
type Kernel<T> = (&'static str, fn(&[T; 6]) -> T);

/// Every free function, on a common argument array (kd is read only by `diffuse_specular`).
fn kernels<T: Real>() -> Vec<Kernel<T>> {
    vec![
        ("classic", |a| phong::classic(a[0], a[1], a[2], a[4], a[5])),
        ("modified", |a| {
            phong::modified(a[0], a[1], a[2], a[4], a[5])
        }),
        ("normalized", |a| {
            phong::normalized(a[0], a[1], a[2], a[4], a[5])
        }),
        ("diffuse_specular", |a| {
            phong::diffuse_specular(a[0], a[1], a[2], a[3], a[4], a[5])
        }),
        ("blinn_phong", |a| {
            phong::blinn_phong(a[0], a[1], a[2], a[4], a[5])
        }),
        ("blinn_phong_normalized", |a| {
            phong::blinn_phong_normalized(a[0], a[1], a[2], a[4], a[5])
        }),
        ("blinn_phong_normalized_approx", |a| {
            phong::blinn_phong_normalized_approx(a[0], a[1], a[2], a[4], a[5])
        }),
        ("blinn_phong_ndf", |a| phong::blinn_phong_ndf(a[2], a[5])),
        ("phong_normalization", |a| phong::phong_normalization(a[5])),
        ("blinn_phong_normalization_exact", |a| {
            phong::blinn_phong_normalization_exact(a[5])
        }),
        ("blinn_phong_normalization_approx", |a| {
            phong::blinn_phong_normalization_approx(a[5])
        }),
    ]
}

/// Which argument positions each kernel reads (the NaN test poisons only those).
fn reads(name: &str) -> &'static [usize] {
    match name {
        "diffuse_specular" => &[0, 1, 2, 3, 4, 5],
        "blinn_phong_ndf" => &[2, 5],
        n if n.contains("normalization") => &[5],
        _ => &[0, 1, 2, 4, 5],
    }
}

fn splat<T: Real>(a: &Args) -> [T; 6] {
    a.map(T::splat)
}

/// Exponents over the whole domain of the lane type: 0, every 5th power of two from the
/// smallest subnormal to the largest, 0.5, 1, 10^4, 1.8e19 (where (n + 2)(n + 4) would
/// overflow f32) and `MAX`.
fn exponents<T: Real>() -> Vec<f64> {
    let max: f64 = T::MAX.lane(0).into();
    let (lo, hi) = if max > 1e300 {
        (-1074, 1023)
    } else {
        (-149, 127)
    };
    let mut v: Vec<f64> = (lo..=hi).step_by(5).map(|k| 2f64.powi(k)).collect();
    v.extend([0.0, 0.5, 1.0, 1e4, 1.8e19, max]);
    v
}

/// Cosines at and near every edge: 0, subnormal, smallest normal, grazing, 1, rounded above 1
/// (a unit dot product can round there), negative.
fn cosines<T: Real>() -> Vec<f64> {
    let min: f64 = T::MIN_POSITIVE.lane(0).into();
    vec![
        0.0,
        min * 0.5,
        min,
        1e-7,
        1e-3,
        0.5,
        1.0 - 1e-7,
        1.0,
        1.0 + 1e-6,
        -1e-7,
        -0.5,
    ]
}

fn finite_non_negative_over_the_domain<T: Real>(label: &str) {
    let (mut count, mut largest) = (0u64, 0.0f64);
    for n in exponents::<T>() {
        for &cv in &cosines::<T>() {
            for &cl in &cosines::<T>() {
                for &c in &cosines::<T>() {
                    for (kd, ks) in [(0.0, 1.0), (0.5, 0.5), (1.0, 0.0), (0.0, 0.0)] {
                        let a = splat::<T>(&[cv, cl, c, kd, ks, n]);
                        for (name, k) in kernels::<T>() {
                            let v: f64 = k(&a).lane(0).into();
                            assert!(
                                v.is_finite() && v >= 0.0,
                                "{label} {name}({cv}, {cl}, {c}, kd {kd}, ks {ks}, n {n}) = {v}"
                            );
                            largest = largest.max(v);
                            count += 1;
                        }
                    }
                }
            }
        }
    }
    println!(
        "{label}: {count} evaluations, exponents 0 to MAX, all finite and >= 0; largest {largest:.3e}"
    );
}

#[test]
fn finite_and_non_negative_up_to_the_largest_exponent_f32() {
    finite_non_negative_over_the_domain::<f32>("f32");
}

#[test]
fn finite_and_non_negative_up_to_the_largest_exponent_f64() {
    finite_non_negative_over_the_domain::<f64>("f64");
}

#[test]
fn documented_edge_values() {
    let pi = core::f64::consts::PI;
    // n = 0 is the limit n -> 0+: a step, 1 inside the lobe, 0 outside (not 0^0 = 1).
    assert_eq!(phong::normalized(0.5, 0.5, 0.3, 1.0, 0.0), 1.0 / pi);
    assert_eq!(phong::normalized(0.5, 0.5, 0.0, 1.0, 0.0), 0.0);
    assert_eq!(phong::normalized(0.5, 0.5, -0.3, 1.0, 0.0), 0.0);
    assert_eq!(phong::modified(0.5, 0.5, -0.3, 1.0, 0.0), 0.0);
    // Blinn-Phong at n = 0 is Lambert.
    assert_eq!(
        phong::blinn_phong_normalized(0.5, 0.2, 0.7, 1.0, 0.0),
        1.0 / pi
    );
    assert_eq!(phong::blinn_phong_normalization_exact(0.0), 1.0 / pi);
    // A lobe cosine rounded above 1 is clamped: no (1 + e)^n overflow.
    assert_eq!(
        phong::normalized(1.0, 1.0, 1.0 + 1e-6, 1.0, 1e4),
        phong::phong_normalization(1e4)
    );
    // Classic Phong: the divisor is floored at MIN_POSITIVE, so a subnormal n.l gives
    // ks / MIN_POSITIVE, finite.
    let v = phong::classic(1e-45_f32, 1e-45, 1.0, 1.0, 2.0);
    println!("classic(f32, n.l = 1e-45, r.l = 1) = {v:e}");
    assert_eq!(v, 1.0 / f32::MIN_POSITIVE);
    // Below or at the horizon: 0.
    for (cv, cl) in [(0.0, 0.5), (0.5, 0.0), (-0.5, 0.5), (0.5, -1e-30)] {
        for (name, k) in kernels::<f64>().into_iter().take(7) {
            assert_eq!(k(&[cv, cl, 0.9, 0.0, 1.0, 10.0]), 0.0, "{name} {cv} {cl}");
        }
    }
    // The peak at the largest exponent is finite: (n + 2) / (2 pi) at n = MAX.
    let p = phong::normalized(1.0, 1.0, 1.0, 1.0, f32::MAX);
    let q = phong::blinn_phong_normalized(1.0, 1.0, 1.0, 1.0, f32::MAX);
    println!("f32 peaks at n = f32::MAX: normalized Phong {p:e}, exact Blinn-Phong {q:e}");
    assert!(p.is_finite() && q.is_finite());
    // Eval with wo = -wi (one below the horizon): 0, not 0 / 0.
    let w = V3::new(0.6, 0.0, 0.8);
    let m = NormalizedBlinnPhong::new(1.0, 10.0).unwrap();
    assert_eq!(m.eval(w, -w), 0.0);
    assert_eq!(m.eval(-w, w), 0.0);
}

/// Each kernel, each argument NaN in turn, above and below the horizon, on one lane type.
fn nan_in_each_input<T: Real>(label: &str) {
    let bases: [Args; 2] = [
        [0.7, 0.6, 0.9, 0.3, 0.6, 20.0],
        [-0.7, 0.6, 0.9, 0.3, 0.6, 0.0],
    ];
    let mut checked = 0;
    for base in bases {
        for (name, k) in kernels::<T>() {
            for &i in reads(name) {
                let mut a = splat::<T>(&base);
                a[i] = T::splat(f64::NAN);
                let v = k(&a);
                for l in 0..T::LANES {
                    let x: f64 = v.lane(l).into();
                    assert!(x.is_nan(), "{label} {name}: NaN in argument {i} gave {x}");
                }
                checked += 1;
            }
        }
    }
    println!("{label}: {checked} (kernel, argument) pairs give NaN for a NaN argument");
}

#[test]
fn nan_in_any_input_gives_nan_on_every_lane_type() {
    nan_in_each_input::<f32>("f32");
    nan_in_each_input::<f64>("f64");
    nan_in_each_input::<f32x8>("f32x8");
    nan_in_each_input::<f64x4>("f64x4");
}

/// The `eval` of every type, as (name, closure) on local vectors.
type Eval<T> = Box<dyn Fn(V3<T>, V3<T>) -> T>;
fn evals<T: Real>(ks: f64, n: f64) -> Vec<(&'static str, Eval<T>)> {
    let (ks, n) = (T::splat(ks), T::splat(n));
    let kd = T::splat(0.1);
    let c = ClassicPhong::new(ks, n).unwrap();
    let m = ModifiedPhong::new(ks, n).unwrap();
    let z = NormalizedPhong::new(ks, n).unwrap();
    let d = PhongDiffuseSpecular::new(kd, ks * T::splat(0.9), n).unwrap();
    let b = BlinnPhong::new(ks, n).unwrap();
    let e = NormalizedBlinnPhong::new(ks, n).unwrap();
    let a = ApproxNormalizedBlinnPhong::new(ks, n).unwrap();
    vec![
        ("ClassicPhong", Box::new(move |o, i| c.eval(o, i))),
        ("ModifiedPhong", Box::new(move |o, i| m.eval(o, i))),
        ("NormalizedPhong", Box::new(move |o, i| z.eval(o, i))),
        ("PhongDiffuseSpecular", Box::new(move |o, i| d.eval(o, i))),
        ("BlinnPhong", Box::new(move |o, i| b.eval(o, i))),
        ("NormalizedBlinnPhong", Box::new(move |o, i| e.eval(o, i))),
        (
            "ApproxNormalizedBlinnPhong",
            Box::new(move |o, i| a.eval(o, i)),
        ),
    ]
}

fn nan_in_each_component<T: Real>(label: &str) {
    let wo = [0.36, 0.48, 0.8];
    let wi = [-0.6, 0.0, 0.8];
    for (name, f) in evals::<T>(0.8, 50.0) {
        for i in 0..6 {
            let mut c = [wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]];
            c[i] = f64::NAN;
            let v = |a: f64, b: f64, d: f64| V3::new(T::splat(a), T::splat(b), T::splat(d));
            let x: f64 = f(v(c[0], c[1], c[2]), v(c[3], c[4], c[5])).lane(0).into();
            assert!(
                x.is_nan(),
                "{label} {name}.eval: NaN in component {i} gave {x}"
            );
        }
    }
}

#[test]
fn nan_in_any_direction_component_gives_nan_from_eval() {
    nan_in_each_component::<f32>("f32");
    nan_in_each_component::<f64>("f64");
    nan_in_each_component::<f32x8>("f32x8");
    nan_in_each_component::<f64x4>("f64x4");
}

#[test]
fn invalid_parameters_give_nan_and_param_error() {
    let bad_ks = [-0.1, 1.1, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
    let bad_n = [-1.0, -1e-300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
    // Free functions: NaN, above and below the horizon.
    for cv in [0.7, -0.7] {
        for (name, k) in kernels::<f64>() {
            let r = reads(name);
            let mut cases = Vec::new();
            if r.contains(&4) {
                cases.extend(bad_ks.iter().map(|&ks| [cv, 0.6, 0.9, 0.0, ks, 10.0]));
            }
            if r.contains(&3) {
                cases.extend(bad_ks.iter().map(|&kd| [cv, 0.6, 0.9, kd, 0.0, 10.0]));
                cases.push([cv, 0.6, 0.9, 0.6, 0.6, 10.0]);
            }
            cases.extend(bad_n.iter().map(|&n| [cv, 0.6, 0.9, 0.0, 0.5, n]));
            for a in cases {
                assert!(k(&a).is_nan(), "{name}({a:?}) = {}", k(&a));
            }
        }
    }
    // Constructors: Err naming the parameter.
    let p = |r: Result<(), ParamError>| r.unwrap_err().param;
    for ks in bad_ks {
        assert_eq!(p(ClassicPhong::new(ks, 1.0).map(drop)), "ks");
        assert_eq!(p(ModifiedPhong::new(ks, 1.0).map(drop)), "ks");
        assert_eq!(p(NormalizedPhong::new(ks, 1.0).map(drop)), "ks");
        assert_eq!(p(BlinnPhong::new(ks, 1.0).map(drop)), "ks");
        assert_eq!(p(NormalizedBlinnPhong::new(ks, 1.0).map(drop)), "ks");
        assert_eq!(p(ApproxNormalizedBlinnPhong::new(ks, 1.0).map(drop)), "ks");
        assert_eq!(p(PhongDiffuseSpecular::new(0.0, ks, 1.0).map(drop)), "ks");
        assert_eq!(p(PhongDiffuseSpecular::new(ks, 0.0, 1.0).map(drop)), "kd");
    }
    for n in bad_n {
        assert_eq!(p(NormalizedPhong::new(0.5, n).map(drop)), "exponent");
        assert_eq!(p(ClassicPhong::new(0.5, n).map(drop)), "exponent");
        assert_eq!(p(NormalizedBlinnPhong::new(0.5, n).map(drop)), "exponent");
        assert_eq!(
            p(PhongDiffuseSpecular::new(0.1, 0.5, n).map(drop)),
            "exponent"
        );
    }
    assert_eq!(
        p(PhongDiffuseSpecular::new(0.6, 0.6, 1.0).map(drop)),
        "kd + ks"
    );
    // kd = 1 - ks in the lane type is accepted (one rounding of the sum tolerated).
    for ks in [0.1_f32, 0.3, 0.7, 0.9] {
        assert!(PhongDiffuseSpecular::new(1.0 - ks, ks, 1.0).is_ok(), "{ks}");
    }
    assert!(NormalizedPhong::new(1.0, f64::MAX).is_ok());
    assert!(NormalizedPhong::new(0.0, 0.0).is_ok());
    // One bad lane rejects the whole lane value.
    let ks = f32x8::new([0.5, 0.5, 0.5, 1.5, 0.5, 0.5, 0.5, 0.5]);
    assert_eq!(
        NormalizedPhong::new(ks, f32x8::splat(4.0))
            .unwrap_err()
            .param,
        "ks"
    );
    let n = f64x4::new([1.0, 2.0, f64::NAN, 4.0]);
    assert_eq!(
        NormalizedBlinnPhong::new(f64x4::splat(0.5), n)
            .unwrap_err()
            .param,
        "exponent"
    );
}

/// A deterministic stream of arguments across the domain (SplitMix64).
fn random_args(count: usize) -> Vec<Args> {
    let mut s = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = move || {
        s = s.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|_| {
            let ks = next();
            // Exponents log-uniform over [1e-3, 1e4], with exact 0 now and then.
            let n = if next() < 0.05 {
                0.0
            } else {
                10f64.powf(7.0 * next() - 3.0)
            };
            [
                next() * 1.2 - 0.1,
                next() * 1.2 - 0.1,
                1.0 - next() * next() * 1.1,
                (1.0 - ks) * next(),
                ks,
                n,
            ]
        })
        .collect()
}

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[test]
fn lanes_equal_scalars_bit_for_bit() {
    let args = random_args(4000);
    let k32 = kernels::<f32>();
    let k64 = kernels::<f64>();
    let (k32x8, k64x4) = (kernels::<f32x8>(), kernels::<f64x4>());
    for (j, (name, _)) in k32.iter().enumerate() {
        for chunk in args.chunks_exact(8) {
            let lanes: [f32x8; 6] =
                core::array::from_fn(|i| f32x8::from_fn(|l| chunk[l][i] as f32));
            let v = (k32x8[j].1)(&lanes);
            for (l, a) in chunk.iter().enumerate() {
                let s = (k32[j].1)(&a.map(|x| x as f32));
                assert!(
                    same(v.lane(l) as f64, s as f64),
                    "{name} f32x8 lane {l}: {a:?}"
                );
            }
        }
        for chunk in args.chunks_exact(4) {
            let lanes: [f64x4; 6] = core::array::from_fn(|i| f64x4::from_fn(|l| chunk[l][i]));
            let v = (k64x4[j].1)(&lanes);
            for (l, a) in chunk.iter().enumerate() {
                assert!(
                    same(v.lane(l), (k64[j].1)(a)),
                    "{name} f64x4 lane {l}: {a:?}"
                );
            }
        }
    }
    // Through eval, with directions from the same stream.
    let dir = |a: f64, b: f64| {
        let z: f64 = a.clamp(1e-4, 1.0);
        let r = (1.0 - z * z).sqrt();
        let phi = b * core::f64::consts::TAU;
        glam::DVec3::new(r * phi.cos(), r * phi.sin(), z)
    };
    for n in [0.0, 1.0, 37.5, 1e4] {
        let e8 = evals::<f32x8>(0.7, n);
        let e1 = evals::<f32>(0.7, n);
        for chunk in args.chunks_exact(8) {
            let wo: [glam::Vec3; 8] =
                core::array::from_fn(|l| dir(chunk[l][0], chunk[l][3]).as_vec3());
            let wi: [glam::Vec3; 8] =
                core::array::from_fn(|l| dir(chunk[l][1], chunk[l][2]).as_vec3());
            for ((name, f8), (_, f1)) in e8.iter().zip(&e1) {
                let v = f8(V3::<f32x8>::from_lanes(wo), V3::<f32x8>::from_lanes(wi));
                for l in 0..8 {
                    let s = f1(V3::from(wo[l]), V3::from(wi[l]));
                    assert!(same(v.lane(l) as f64, s as f64), "{name}.eval lane {l}");
                }
            }
        }
    }
    println!(
        "lanes: {} argument sets per kernel, f32x8 and f64x4 bit-identical to scalars",
        args.len()
    );
}

/// f32 against f64 on identical inputs, relative to the f64 value in units of f32::EPSILON.
/// Every kernel is a `powf` (libm, within 1 ulp) times at most four correctly rounded
/// operations (the exact Blinn-Phong factor adds a second `powf` whose exponent n / 2 is
/// exact), so a few epsilon is what correct code gives; 4 epsilon is the bound the module docs
/// state. It holds where the lobe max(0, c)^n itself is a normal f32: below f32::MIN_POSITIVE
/// the lobe is subnormal, with an absolute error of one subnormal step (2^-149), which the
/// normalization or the classic 1 / (n.l) then scales up, plus one more step if the result is
/// subnormal too; there the bound is 4 eps |f| + 2^-149 (|f| / c^n + 1).
const F32_BOUND_EPS: f64 = 4.0;

#[test]
fn f32_within_its_stated_bound_of_f64() {
    let args = random_args(200_000);
    let k32 = kernels::<f32>();
    let k64 = kernels::<f64>();
    let eps = f32::EPSILON as f64;
    let tiny = 2f64.powi(-149);
    for (j, (name, _)) in k32.iter().enumerate() {
        let (mut worst, mut at, mut subnormal_lobes) = (0.0f64, [0.0; 6], 0);
        for a in &args {
            let a32 = a.map(|x| x as f32);
            let a64 = a32.map(f64::from);
            let (x32, x64) = ((k32[j].1)(&a32), (k64[j].1)(&a64));
            let err = (x32 as f64 - x64).abs();
            let lobe = if a64[2] > 0.0 {
                a64[2].min(1.0).powf(a64[5])
            } else {
                0.0
            };
            if lobe > 0.0 && lobe < f32::MIN_POSITIVE as f64 && reads(name).contains(&2) {
                subnormal_lobes += 1;
                let allowed = F32_BOUND_EPS * eps * x64.abs() + tiny * (x64.abs() / lobe + 1.0);
                assert!(err <= allowed, "{name} {a64:?}: {x32} vs {x64}");
                continue;
            }
            // A result below f32's normal range (ks = 0 aside, a tiny ks) is compared absolutely.
            if x64.abs() < f32::MIN_POSITIVE as f64 {
                assert!(err <= f32::MIN_POSITIVE as f64, "{name} {a64:?}");
                continue;
            }
            let e = err / x64.abs() / eps;
            if e > worst {
                (worst, at) = (e, a64);
            }
        }
        println!(
            "{name}: f32 vs f64 worst {worst:.2} eps at {at:?} ({subnormal_lobes} subnormal-lobe samples checked absolutely)"
        );
        assert!(worst <= F32_BOUND_EPS, "{name}: {worst} eps at {at:?}");
    }
}

proptest! {
    #![proptest_config(common::proptest_cases(2000))]

    #[test]
    fn finite_and_non_negative_across_the_domain(
        ox in -1.0..1.0f64, oy in -1.0..1.0f64, oz in prop_oneof![Just(0.0), Just(1e-9), 0.0..1.0f64, Just(1.0)],
        ix in -1.0..1.0f64, iy in -1.0..1.0f64, iz in prop_oneof![Just(0.0), Just(1e-9), 0.0..1.0f64, Just(1.0)],
        ks in prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64],
        kd_frac in 0.0..=1.0f64,
        n in prop_oneof![Just(0.0), Just(1e4), 0.0..1e4f64, Just(f32::MAX as f64)],
    ) {
        let unit = |x: f64, y: f64, z: f64| {
            let t = (x * x + y * y).sqrt().max(1e-300);
            let r = (1.0 - z * z).sqrt();
            if t < 1e-12 { glam::DVec3::Z } else { glam::DVec3::new(x / t * r, y / t * r, z) }
        };
        let (wo, wi) = (unit(ox, oy, oz), unit(ix, iy, iz));
        for (name, f) in evals::<f64>(ks, n) {
            let v = f(V3::from(wo), V3::from(wi));
            prop_assert!(v.is_finite() && v >= 0.0, "{} f64 {:?} {:?} = {}", name, wo, wi, v);
        }
        for (name, f) in evals::<f32>(ks, n) {
            let v = f(V3::from(wo.as_vec3()), V3::from(wi.as_vec3()));
            prop_assert!(v.is_finite() && v >= 0.0, "{} f32 {:?} {:?} = {}", name, wo, wi, v);
        }
        let kd = (1.0 - ks) * kd_frac;
        let c = wo.z * wi.z - wo.x * wi.x - wo.y * wi.y;
        let h = (wo + wi).normalize_or_zero().z;
        for (name, k) in kernels::<f64>() {
            let lobe = if name.starts_with("blinn") { h } else { c };
            let v = k(&[wo.z, wi.z, lobe, kd, ks, n]);
            prop_assert!(v.is_finite() && v >= 0.0, "{} = {}", name, v);
        }
    }
}
