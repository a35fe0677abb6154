//! Bad and extreme input to the metallic-roughness material: finite, non-negative output over
//! the whole documented domain (roughness and metallic 0 and 1, grazing and horizon
//! directions), NaN in each input gives NaN on f32, f64, f32x8 and f64x4, out-of-domain
//! parameters give NaN from the free functions and a named `ParamError` from the
//! constructors, lanes equal scalars bit for bit, and f32 stays within a stated relative
//! bound of f64.
#![cfg(feature = "material")]

use brdf::Cosines;
use brdf::material::{self, DiffuseCoupling, MetallicRoughness};
use brdf::wide::{f32x8, f64x4};
use brdf::{Mask, Real, V3};
use proptest::prelude::*;

use crate::common;
use common::Rng;

const COUPLINGS: [DiffuseCoupling; 3] = [
    DiffuseCoupling::Gltf,
    DiffuseCoupling::OneMinusF,
    DiffuseCoupling::Additive,
];

/// The free function's ten inputs, in order: n.v, n.l, n.h, v.h, base r, g, b, metallic,
/// roughness, dielectric F0.
type Inputs = [f64; 10];

fn free<T: Real>(x: Inputs, c: DiffuseCoupling) -> V3<T> {
    let s = |i: usize| T::splat(x[i]);
    material::metallic_roughness(
        Cosines {
            n_dot_v: s(0),
            n_dot_l: s(1),
            n_dot_h: s(2),
            v_dot_h: s(3),
        },
        V3::new(s(4), s(5), s(6)),
        s(7),
        s(8),
        s(9),
        c,
    )
}

/// Every lane of every channel is NaN.
fn all_nan<T: Real>(v: V3<T>) -> bool {
    v.x.is_nan().all() && v.y.is_nan().all() && v.z.is_nan().all()
}

const VALID: Inputs = [0.7, 0.5, 0.9, 0.8, 0.9, 0.5, 0.2, 0.3, 0.4, 0.04];

#[test]
fn nan_in_any_input_gives_nan_on_every_type() {
    for c in COUPLINGS {
        assert!(!all_nan(free::<f64>(VALID, c)));
        for i in 0..10 {
            let mut x = VALID;
            x[i] = f64::NAN;
            assert!(all_nan(free::<f32>(x, c)), "f32, input {i}, {c:?}");
            assert!(all_nan(free::<f64>(x, c)), "f64, input {i}, {c:?}");
            assert!(all_nan(free::<f32x8>(x, c)), "f32x8, input {i}, {c:?}");
            assert!(all_nan(free::<f64x4>(x, c)), "f64x4, input {i}, {c:?}");
            // Also below the horizon: a NaN is never hidden by the horizon's 0.
            x[1] = if i == 1 { f64::NAN } else { -0.5 };
            assert!(
                all_nan(free::<f64>(x, c)),
                "f64 below the horizon, input {i}"
            );
        }
    }
    // The vector entry point: a NaN component of either direction.
    let m = MetallicRoughness::new(V3::splat(0.5), 0.5, 0.5).unwrap();
    let (wo, wi) = (V3::new(0.0, 0.6, 0.8), V3::new(0.6, 0.0, 0.8));
    for k in 0..6 {
        let (mut o, mut i) = ([wo.x, wo.y, wo.z], [wi.x, wi.y, wi.z]);
        if k < 3 {
            o[k] = f64::NAN
        } else {
            i[k - 3] = f64::NAN
        }
        let f = m.eval(V3::new(o[0], o[1], o[2]), V3::new(i[0], i[1], i[2]));
        assert!(all_nan(f), "eval, component {k}: {f:?}");
    }
    // specular_probability and pdf of a NaN view.
    assert!(m.specular_probability(V3::new(0.0, 0.0, f64::NAN)).is_nan());
    assert!(m.pdf(V3::new(0.0, 0.0, f64::NAN), wi).is_nan());
}

#[test]
fn out_of_domain_parameters_give_nan_from_the_free_functions() {
    let bad: [(usize, f64); 10] = [
        (4, -0.1),
        (5, 1.5),
        (6, f64::INFINITY),
        (7, -1e-9),
        (7, 1.0 + 1e-6),
        (8, -0.5),
        (8, 2.0),
        (9, 1.1),
        (9, -0.04),
        (9, f64::NEG_INFINITY),
    ];
    for c in COUPLINGS {
        for (i, v) in bad {
            let mut x = VALID;
            x[i] = v;
            assert!(all_nan(free::<f64>(x, c)), "input {i} = {v}");
            assert!(all_nan(free::<f32x8>(x, c)), "f32x8 input {i} = {v}");
            x[0] = -0.3; // below the horizon too
            assert!(all_nan(free::<f64>(x, c)), "below horizon, input {i} = {v}");
        }
    }
    let g = material::gltf(
        Cosines {
            n_dot_v: 0.5,
            n_dot_l: 0.5,
            n_dot_h: 0.9,
            v_dot_h: 0.9,
        },
        V3::splat(0.5),
        1.2,
        0.5,
    );
    assert!(all_nan(g));
}

#[test]
fn constructors_name_the_parameter_they_reject() {
    let ok = || MetallicRoughness::new(V3::splat(0.5), 0.5, 0.5).unwrap();
    let cases: [(&str, Result<MetallicRoughness<f64>, brdf::ParamError>); 14] = [
        (
            "base_color",
            MetallicRoughness::new(V3::new(0.5, 1.01, 0.5), 0.5, 0.5),
        ),
        (
            "base_color",
            MetallicRoughness::new(V3::new(0.5, 0.5, f64::NAN), 0.5, 0.5),
        ),
        (
            "base_color",
            MetallicRoughness::new(V3::new(-0.0001, 0.5, 0.5), 0.5, 0.5),
        ),
        (
            "metallic",
            MetallicRoughness::new(V3::splat(0.5), -0.1, 0.5),
        ),
        (
            "metallic",
            MetallicRoughness::new(V3::splat(0.5), f64::NAN, 0.5),
        ),
        (
            "roughness",
            MetallicRoughness::new(V3::splat(0.5), 0.5, 1.5),
        ),
        (
            "roughness",
            MetallicRoughness::new(V3::splat(0.5), 0.5, f64::NAN),
        ),
        ("ior", ok().with_ior(0.99)),
        ("ior", ok().with_ior(f64::INFINITY)),
        ("dielectric_f0", ok().with_dielectric_f0(1.01)),
        ("reflectance", ok().with_reflectance(-0.2)),
        ("specular", ok().with_specular(1.2, V3::splat(1.0))),
        (
            "specular_color",
            ok().with_specular(0.5, V3::new(1.0, -1.0, 1.0)),
        ),
        (
            "specular_color",
            ok().with_specular(0.5, V3::new(1.0, 1.0, f64::INFINITY)),
        ),
    ];
    for (name, r) in cases {
        let e = r.expect_err(name);
        assert_eq!(e.param, name, "{e}");
        println!("{e}");
    }
    // One bad lane rejects the whole vector.
    let lanes = f32x8::from_fn(|i| if i == 5 { 1.5 } else { 0.5 });
    let e = MetallicRoughness::new(V3::splat(f32x8::splat(0.5)), lanes, f32x8::splat(0.5));
    assert_eq!(e.unwrap_err().param, "metallic");
    // The documented ends are accepted.
    for (b, m, r) in [(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)] {
        let p = MetallicRoughness::new(V3::splat(b), m, r).unwrap();
        p.with_ior(1.0).unwrap().with_ior(f64::MAX).unwrap();
        p.with_specular(0.0, V3::splat(0.0)).unwrap();
        p.with_specular(1.0, V3::splat(f64::MAX)).unwrap();
        p.with_dielectric_f0(0.0)
            .unwrap()
            .with_dielectric_f0(1.0)
            .unwrap();
    }
}

#[test]
fn below_the_horizon_is_black() {
    for c in COUPLINGS {
        for (nv, nl) in [
            (0.0, 0.5),
            (0.5, 0.0),
            (-0.5, 0.5),
            (0.5, -1e-9),
            (-1.0, -1.0),
        ] {
            let mut x = VALID;
            (x[0], x[1]) = (nv, nl);
            assert_eq!(free::<f64>(x, c), V3::splat(0.0));
            assert_eq!(free::<f32>(x, c), V3::splat(0.0));
        }
    }
    let m = MetallicRoughness::new(V3::splat(1.0), 0.0, 0.0).unwrap();
    let (up, down) = (V3::new(0.0, 0.6, 0.8), V3::new(0.0, 0.6, -0.8));
    assert_eq!(m.eval(up, down), V3::splat(0.0));
    assert_eq!(m.eval(down, up), V3::splat(0.0));
    assert_eq!(m.eval(down, V3::new(0.0, -0.6, 0.8)), V3::splat(0.0));
}

/// A unit direction with the given cosine and azimuth.
fn dir(c: f64, phi: f64) -> V3<f64> {
    let s = ((1.0 - c) * (1.0 + c)).max(0.0).sqrt();
    V3::new(s * phi.cos(), s * phi.sin(), c)
}

fn edge_or(
    range: core::ops::RangeInclusive<f64>,
    edges: &'static [f64],
) -> impl Strategy<Value = f64> {
    prop_oneof![range, proptest::sample::select(edges)]
}

fn cosine() -> impl Strategy<Value = f64> {
    edge_or(0.0..=1.0, &[0.0, 1e-7, 1e-4, 0.999_999_9, 1.0])
}

fn unit() -> impl Strategy<Value = f64> {
    edge_or(0.0..=1.0, &[0.0, 1.0])
}

fn finite_non_negative<T: Real + Into<f64>>(v: V3<T>) -> bool
where
    T::Scalar: Into<f64>,
{
    [v.x, v.y, v.z].into_iter().all(|c| {
        let c: f64 = c.into();
        c.is_finite() && c >= 0.0
    })
}

proptest! {
    #![proptest_config(common::proptest_cases(4000))]

    #[test]
    fn free_function_is_finite_and_non_negative(
        nv in cosine(), nl in cosine(), nh in cosine(), vh in cosine(),
        r in unit(), g in unit(), b in unit(), metallic in unit(), roughness in unit(),
        f0 in unit(), c in 0usize..3,
    ) {
        let x = [nv, nl, nh, vh, r, g, b, metallic, roughness, f0];
        prop_assert!(finite_non_negative(free::<f64>(x, COUPLINGS[c])), "{x:?}");
        prop_assert!(finite_non_negative(free::<f32>(x, COUPLINGS[c])), "{x:?}");
    }

    #[test]
    fn eval_and_sampler_are_finite_and_non_negative(
        co in cosine(), ci in cosine(), po in 0.0..6.3f64, pi in 0.0..6.3f64,
        r in unit(), g in unit(), b in unit(), metallic in unit(), roughness in unit(),
        specular in unit(), color in edge_or(0.0..=1e3, &[0.0, 1.0, 1e30]),
        u1 in edge_or(0.0..=1.0, &[0.0, 1.0]), u2 in edge_or(0.0..=1.0, &[0.0, 1.0]),
        c in 0usize..3,
    ) {
        let m = MetallicRoughness::new(V3::new(r, g, b), metallic, roughness)
            .unwrap()
            .with_specular(specular, V3::new(color, 1.0, 0.5))
            .unwrap()
            .with_coupling(COUPLINGS[c]);
        let (wo, wi) = (dir(co, po), dir(ci, pi));
        prop_assert!(finite_non_negative(m.eval(wo, wi)));
        let pdf = m.pdf(wo, wi);
        prop_assert!(pdf.is_finite() && pdf >= 0.0, "{pdf}");
        let (wi, pdf, weight) = m.sample_weighted(wo, u1, u2);
        prop_assert!((wi.length() - 1.0).abs() < 1e-9, "{wi:?}");
        prop_assert!(pdf.is_finite() && pdf >= 0.0, "{pdf}");
        prop_assert!(finite_non_negative(weight), "{weight:?}");
        let p = m.specular_probability(wo);
        prop_assert!((0.0..=1.0).contains(&p));
    }
}

#[test]
fn lanes_equal_scalars_bit_for_bit() {
    let mut rng = Rng(0x1a7e);
    for _ in 0..2_000 {
        let x: Vec<[f64; 10]> = (0..8)
            .map(|_| {
                let mut x = [0.0; 10];
                for v in x.iter_mut() {
                    *v = rng.next_f64();
                }
                x[0] -= 0.1; // some below the horizon
                x
            })
            .collect();
        for c in COUPLINGS {
            let lane8 = |k: usize| f32x8::from_fn(|i| x[i][k] as f32);
            let lane4 = |k: usize| f64x4::from_fn(|i| x[i][k]);
            let v8 = material::metallic_roughness(
                Cosines {
                    n_dot_v: lane8(0),
                    n_dot_l: lane8(1),
                    n_dot_h: lane8(2),
                    v_dot_h: lane8(3),
                },
                V3::new(lane8(4), lane8(5), lane8(6)),
                lane8(7),
                lane8(8),
                lane8(9),
                c,
            );
            let v4 = material::metallic_roughness(
                Cosines {
                    n_dot_v: lane4(0),
                    n_dot_l: lane4(1),
                    n_dot_h: lane4(2),
                    v_dot_h: lane4(3),
                },
                V3::new(lane4(4), lane4(5), lane4(6)),
                lane4(7),
                lane4(8),
                lane4(9),
                c,
            );
            for (i, xi) in x.iter().enumerate() {
                let x32: Vec<f64> = xi.iter().map(|v| *v as f32 as f64).collect();
                assert_eq!(v8.lane(i), free::<f32>(x32.try_into().unwrap(), c));
                if i < 4 {
                    assert_eq!(v4.lane(i), free::<f64>(*xi, c));
                }
            }
        }
    }
}

#[test]
fn f32_is_within_its_stated_bound_of_f64() {
    // Same inputs (f32 values, widened), f32 kernel against f64 kernel; relative to the f64
    // value, over roughness in [0, 1] and cosines down to 1e-4.
    let mut rng = Rng(0xf32f);
    let mut worst: f64 = 0.0;
    for i in 0..200_000 {
        let mut x = [0.0f64; 10];
        for v in x.iter_mut() {
            *v = rng.next_f64() as f32 as f64;
        }
        for v in x.iter_mut().take(2) {
            *v = v.max(1e-4) as f32 as f64;
        }
        let c = COUPLINGS[i % 3];
        let (a, b) = (free::<f32>(x, c), free::<f64>(x, c));
        for (a, b) in [(a.x, b.x), (a.y, b.y), (a.z, b.z)] {
            worst = worst.max((a as f64 - b).abs() / b.abs().max(f64::MIN_POSITIVE));
        }
    }
    let ulps = worst / f32::EPSILON as f64;
    println!("f32 vs f64: max relative difference {worst:.2e} ({ulps:.1} f32 ulps)");
    // D within 5 ulps, V within 2 and the Fresnel mix within 5 (src/ggx.rs, src/fresnel.rs):
    // 12 ulps. The diffuse weight's complement form matters here: 1 - F written as such
    // measured 946 ulps (at v.h = 4e-4).
    assert!(ulps <= 12.0, "{ulps} ulps");
}

/// A unit direction of cosine `c` at azimuth `phi`, in the lane type.
fn dir_t<T: Real>(c: f64, phi: f64) -> V3<T> {
    let s = ((1.0 - c) * (1.0 + c)).max(0.0).sqrt();
    V3::new(
        T::splat(s * phi.cos()),
        T::splat(s * phi.sin()),
        T::splat(c),
    )
}

/// The documented extremes of every parameter at once, through `eval`, `pdf` and
/// `sample_weighted`: roughness 0 (alpha floored at ALPHA_MIN) to 1, IOR 1 (F0 = 0) and the
/// largest finite float (F0 -> 1), specular factor 0 and 1 with the specular colour at the
/// largest finite float, cosines down to the smallest subnormal and at or below the horizon,
/// uniform samples 0 and 1. Every value must be finite and the pdf and BRDF non-negative.
fn sweep_parameter_extremes<T: Real>(ty: &str) -> (usize, usize) {
    let s = T::splat;
    let cos = [
        1e-45, 1e-38, 1e-30, 1e-20, 1e-10, 1e-7, 1e-4, 0.01, 0.5, 0.999_999, 1.0, 0.0, -0.3,
    ];
    let (mut bad, mut n) = (0, 0);
    for r in [0.0, 1e-30, 1e-7, 1e-3, 0.01, 0.5, 1.0] {
        for m in [0.0, 0.5, 1.0] {
            for b in [0.0, 1e-30, 0.5, 1.0] {
                let base = MetallicRoughness::new(V3::splat(s(b)), s(m), s(r)).unwrap();
                let mats = [
                    base,
                    base.with_ior(s(1.0)).unwrap(),
                    base.with_ior(T::MAX).unwrap(),
                    base.with_specular(T::ZERO, V3::splat(T::MAX)).unwrap(),
                    base.with_specular(T::ONE, V3::splat(T::MAX))
                        .unwrap()
                        .with_coupling(DiffuseCoupling::OneMinusF),
                ];
                for mat in mats {
                    for co in cos {
                        for ci in cos {
                            for phi in [0.0, 1.0, core::f64::consts::PI] {
                                let (wo, wi) = (dir_t::<T>(co, 0.3), dir_t::<T>(ci, 0.3 + phi));
                                let (f, p) = (mat.eval(wo, wi), mat.pdf(wo, wi));
                                n += 1;
                                let v: [f64; 4] =
                                    [f.x.into_f64(), f.y.into_f64(), f.z.into_f64(), p.into_f64()];
                                if v.iter().any(|x| !x.is_finite() || *x < 0.0) {
                                    bad += 1;
                                    println!("{ty}: r {r} m {m} b {b} cos {co} {ci}: {v:?}");
                                }
                            }
                        }
                        for u1 in [0.0, 0.3, 0.999_999, 1.0] {
                            for u2 in [0.0, 0.5, 1.0] {
                                let (wi, pdf, w) =
                                    mat.sample_weighted(dir_t::<T>(co, 0.3), s(u1), s(u2));
                                n += 1;
                                let v =
                                    [wi.x, wi.y, wi.z, pdf, w.x, w.y, w.z].map(|x| x.into_f64());
                                if v.iter().any(|x| !x.is_finite()) || v[3] < 0.0 {
                                    bad += 1;
                                    println!(
                                        "{ty}: sample r {r} m {m} b {b} cos {co} u {u1} {u2}: {v:?}"
                                    );
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    (bad, n)
}

/// Lane 0 as f64 (all lanes hold the same input here).
trait IntoF64 {
    fn into_f64(self) -> f64;
}

impl<T: Real> IntoF64 for T {
    fn into_f64(self) -> f64 {
        self.lane(0).into()
    }
}

#[test]
fn eval_pdf_and_sample_are_finite_at_every_parameter_extreme() {
    for (ty, (bad, n)) in [
        ("f32", sweep_parameter_extremes::<f32>("f32")),
        ("f64", sweep_parameter_extremes::<f64>("f64")),
    ] {
        println!("{ty}: {n} evaluations at the parameter extremes, {bad} not finite or negative");
        assert_eq!(bad, 0, "{ty}");
    }
}
