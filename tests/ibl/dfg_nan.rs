//! Bad input of the generic DFG kernels (`ibl::dfg`) on f32, f64, f32x8 and f64x4: NaN in any
//! input gives NaN out, an out-of-domain parameter gives NaN, a view at or below the horizon
//! gives 0, and every lane equals the scalar result for its inputs (bit for bit: the kernels
//! use only lane-exact operations, `exp2` aside, which is within 1 ULP: bound 4 ULP).
#![cfg(feature = "ibl")]

use brdf::ibl::dfg;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

/// A kernel: its name, its number of arguments, and the kernel on a flat argument list.
type Row<T> = (&'static str, usize, Box<dyn Fn(&[T]) -> Vec<T>>);

/// Every kernel as a function of a flat argument list, returning a flat output list.
fn kernels<T: Real>() -> Vec<Row<T>> {
    vec![
        (
            "karis_mobile",
            2,
            Box::new(|x: &[T]| dfg::karis_mobile(x[0], x[1]).to_vec()),
        ),
        (
            "karis_mobile_nonmetal",
            2,
            Box::new(|x: &[T]| vec![dfg::karis_mobile_nonmetal(x[0], x[1])]),
        ),
        (
            "lazarov",
            2,
            Box::new(|x: &[T]| dfg::lazarov(x[0], x[1]).to_vec()),
        ),
        (
            "narkowicz_lazarov",
            2,
            Box::new(|x: &[T]| dfg::narkowicz_lazarov(x[0], x[1]).to_vec()),
        ),
        (
            "narkowicz_polynomial",
            2,
            Box::new(|x: &[T]| dfg::narkowicz_polynomial(x[0], x[1]).to_vec()),
        ),
        (
            "specular",
            9,
            Box::new(|x: &[T]| {
                let v = dfg::specular(
                    V3::new(x[0], x[1], x[2]),
                    V3::new(x[3], x[4], x[5]),
                    x[6],
                    x[7],
                    x[8],
                );
                vec![v.x, v.y, v.z]
            }),
        ),
        (
            "mip_from_roughness_linear",
            2,
            Box::new(|x: &[T]| vec![dfg::mip_from_roughness_linear(x[0], x[1])]),
        ),
        (
            "roughness_from_mip_linear",
            2,
            Box::new(|x: &[T]| vec![dfg::roughness_from_mip_linear(x[0], x[1])]),
        ),
        (
            "lod_from_roughness_filament",
            2,
            Box::new(|x: &[T]| vec![dfg::lod_from_roughness_filament(x[0], x[1])]),
        ),
        (
            "roughness_from_lod_filament",
            2,
            Box::new(|x: &[T]| vec![dfg::roughness_from_lod_filament(x[0], x[1])]),
        ),
        (
            "mip_from_roughness_ue4",
            2,
            Box::new(|x: &[T]| vec![dfg::mip_from_roughness_ue4(x[0], x[1])]),
        ),
        (
            "roughness_from_mip_ue4",
            2,
            Box::new(|x: &[T]| vec![dfg::roughness_from_mip_ue4(x[0], x[1])]),
        ),
    ]
}

/// A valid argument list per kernel (by arity and name).
fn valid(name: &str, n: usize) -> Vec<f64> {
    match name {
        "specular" => vec![0.5, 1.0, 2.0, 0.04, 0.5, 0.9, 1.0, 0.8, 0.1],
        "roughness_from_mip_linear" | "roughness_from_lod_filament" => vec![2.0, 5.0],
        "mip_from_roughness_ue4" | "roughness_from_mip_ue4" => vec![0.5, 7.0],
        _ if n == 2 && name.contains("from") => vec![0.5, 5.0],
        _ => vec![0.5, 0.3],
    }
}

/// Invalid parameters: (argument index, value).
fn invalid(name: &str) -> Vec<(usize, f64)> {
    match name {
        "specular" => vec![(0, -1.0), (3, 1.5), (3, -0.1), (6, 2.0), (6, -0.5)],
        "mip_from_roughness_linear" => vec![(0, -0.1), (0, 1.1), (1, 0.5), (1, f64::INFINITY)],
        "roughness_from_mip_linear" => vec![(0, -1.0), (0, 9.0), (1, 1.0)],
        "lod_from_roughness_filament" => vec![(0, 1.5), (1, -1.0)],
        "roughness_from_lod_filament" => vec![(0, 6.0), (1, 0.0)],
        "mip_from_roughness_ue4" => vec![(0, 1.5), (1, f64::INFINITY)],
        "roughness_from_mip_ue4" => vec![(0, f64::INFINITY)],
        _ => vec![(1, -0.1), (1, 1.1), (1, f64::INFINITY)],
    }
}

fn check<T: Real>(label: &str) {
    let ks = kernels::<T>();
    let scalar = kernels::<f64>();
    for ((name, n, f), (_, _, f64k)) in ks.iter().zip(&scalar) {
        let args = valid(name, *n);
        let lanes: Vec<T> = args.iter().map(|&a| T::splat(a)).collect();
        let out = f(&lanes);
        let reference = f64k(&args);
        for (o, r) in out.iter().zip(&reference) {
            for l in 0..T::LANES {
                let v: f64 = o.lane(l).into();
                assert!(v.is_finite(), "{label} {name}: {v}");
                let tol = if label.starts_with("f32") {
                    1e-5
                } else {
                    1e-14
                } * r.abs().max(1.0);
                assert!((v - r).abs() <= tol, "{label} {name}: {v} vs {r}");
            }
        }
        for i in 0..*n {
            let mut x = lanes.clone();
            x[i] = T::splat(f64::NAN);
            assert!(
                f(&x).iter().any(|o| o.lane(0).into().is_nan()),
                "{label} {name}: NaN in arg {i}"
            );
        }
        for (i, bad) in invalid(name) {
            let mut x = lanes.clone();
            x[i] = T::splat(bad);
            assert!(
                f(&x).iter().any(|o| o.lane(0).into().is_nan()),
                "{label} {name}: arg {i} = {bad}"
            );
        }
        // One NaN lane leaves the others as they were.
        if T::LANES > 1 {
            let mut x = lanes.clone();
            x[0] = T::from_fn(|l| {
                if l == 1 {
                    T::Scalar::splat(f64::NAN)
                } else {
                    lanes[0].lane(l)
                }
            });
            let o2 = f(&x);
            for (a, b) in o2.iter().zip(&out) {
                for l in (0..T::LANES).filter(|&l| l != 1) {
                    let (p, q): (f64, f64) = (a.lane(l).into(), b.lane(l).into());
                    assert!(
                        p.to_bits() == q.to_bits(),
                        "{label} {name}: lane {l} leaked"
                    );
                }
            }
        }
    }
    // The fits: at or below the horizon, 0.
    for nv in [0.0, -0.5] {
        let [a, b] = dfg::karis_mobile(T::splat(nv), T::splat(0.5));
        assert_eq!(a.lane(0).into(), 0.0);
        assert_eq!(b.lane(0).into(), 0.0);
    }
    println!("{label}: NaN, invalid-parameter, horizon and lane checks passed");
}

#[test]
fn nan_in_nan_out_on_every_lane_type() {
    check::<f32>("f32");
    check::<f64>("f64");
    check::<f32x8>("f32x8");
    check::<f64x4>("f64x4");
}

#[test]
fn dfg_quadrature_bad_input() {
    assert!(dfg::dfg(f64::NAN, 0.5, 64).iter().all(|v| v.is_nan()));
    assert!(dfg::dfg(0.5, f64::NAN, 64).iter().all(|v| v.is_nan()));
    assert!(dfg::dfg(0.5, -0.1, 64).iter().all(|v| v.is_nan()));
    assert!(dfg::dfg(0.5, f64::INFINITY, 64).iter().all(|v| v.is_nan()));
    assert!(dfg::dfg(0.5, 0.5, 0).iter().all(|v| v.is_nan()));
    assert_eq!(dfg::dfg(-0.2, 0.5, 64), [0.0; 3]);
    // Extremes of the finite domain stay finite and in [0, 1].
    for alpha in [0.0, 1e-300, 1e4, f64::MAX] {
        for nv in [1e-300, 1e-8, 0.5, 1.0, 2.0] {
            let d = dfg::dfg(nv, alpha, 64);
            assert!(
                d.iter().all(|v| (0.0..=1.0).contains(v)),
                "{nv} {alpha}: {d:?}"
            );
        }
    }
    // Deterministic.
    assert_eq!(dfg::dfg(0.3, 0.2, 999), dfg::dfg(0.3, 0.2, 999));
}
