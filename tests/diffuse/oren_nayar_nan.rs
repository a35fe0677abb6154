//! Bad input to the Oren-Nayar family: a NaN in any input gives NaN on f32, f64, f32x8 and
//! f64x4 (also at the poles and the horizon, where a guard could swallow it); rho outside
//! [0, 1] or a negative, infinite or NaN sigma (Fujii: sigma outside [0, 1]) gives NaN from the
//! free functions and `ParamError` from the constructors.
#![cfg(feature = "diffuse")]

use brdf::Real;
use brdf::diffuse::{
    OrenNayar, OrenNayarFujii, OrenNayarFull, oren_nayar, oren_nayar_a, oren_nayar_b,
    oren_nayar_fujii, oren_nayar_full,
};
use brdf::wide::{f32x8, f64x4};

fn all3<T: Real>(x: [T; 5]) -> [T; 3] {
    [
        oren_nayar(x[0], x[1], x[2], x[3], x[4]),
        oren_nayar_full(x[0], x[1], x[2], x[3], x[4]),
        oren_nayar_fujii(x[0], x[1], x[2], x[3], x[4]),
    ]
}

fn is_nan<T: Real>(x: T) -> bool {
    (0..T::LANES).all(|i| {
        let v: f64 = x.lane(i).into();
        v.is_nan()
    })
}

/// Valid points: generic, at the pole (n.v = 1), both grazing, and below the horizon.
const POINTS: [[f64; 5]; 4] = [
    [0.6, 0.7, 0.5, 0.5, 0.4],
    [1.0, 0.7, 0.7, 0.5, 0.4],
    [1e-9, 1e-9, -0.9, 1.0, 1.0],
    [-0.5, 0.7, 0.1, 0.5, 0.4],
];

fn check<T: Real>() -> usize {
    let mut n = 0;
    for p in POINTS {
        for k in 0..5 {
            let mut x = p.map(T::splat);
            x[k] = T::splat(f64::NAN);
            for (form, f) in all3(x).into_iter().enumerate() {
                assert!(
                    is_nan(f),
                    "form {form}, NaN at input {k}, point {p:?}: {f:?}"
                );
                n += 1;
            }
        }
        for (k, bad) in [
            (3, -0.1),
            (3, 1.1),
            (3, f64::INFINITY),
            (4, -1e-9),
            (4, f64::INFINITY),
        ] {
            let mut x = p.map(T::splat);
            x[k] = T::splat(bad);
            for (form, f) in all3(x).into_iter().enumerate() {
                assert!(
                    is_nan(f),
                    "form {form}, input {k} = {bad}, point {p:?}: {f:?}"
                );
                n += 1;
            }
        }
        // Fujii's sigma is bounded by 1; the other forms accept it.
        let mut x = p.map(T::splat);
        x[4] = T::splat(1.5);
        let f = all3(x);
        assert!(is_nan(f[2]), "Fujii sigma 1.5: {:?}", f[2]);
        assert!(!is_nan(f[0]) && !is_nan(f[1]));
    }
    for s in [-1.0, f64::INFINITY, f64::NAN] {
        assert!(is_nan(oren_nayar_a(T::splat(s))) && is_nan(oren_nayar_b(T::splat(s))));
    }
    n
}

#[test]
fn nan_and_out_of_domain_inputs_give_nan() {
    let n = check::<f32>() + check::<f64>() + check::<f32x8>() + check::<f64x4>();
    println!("{n} NaN checks");
}

#[test]
fn constructors_reject_out_of_domain_parameters() {
    for (rho, sigma) in [
        (-0.1, 0.5),
        (1.1, 0.5),
        (f64::NAN, 0.5),
        (0.5, -0.1),
        (0.5, f64::INFINITY),
        (0.5, f64::NAN),
    ] {
        assert!(OrenNayar::new(rho, sigma).is_err());
        assert!(OrenNayarFull::new(rho, sigma).is_err());
        assert!(OrenNayarFujii::new(rho, sigma).is_err());
        assert!(OrenNayar::new(rho as f32, sigma as f32).is_err());
    }
    assert!(OrenNayarFujii::new(0.5, 1.0 + 1e-12).is_err());
    assert!(OrenNayar::new(0.5, f64::MAX).is_ok());
    assert!(OrenNayarFull::new(1.0, 0.0).is_ok());
    assert!(OrenNayarFujii::new(0.0, 1.0).is_ok());
    // One bad lane rejects the whole vector.
    let sigma = f32x8::new([0.1, 0.2, 0.3, -0.4, 0.5, 0.6, 0.7, 0.8]);
    let e = OrenNayar::new(f32x8::splat(0.5), sigma).unwrap_err();
    assert_eq!(e.param, "sigma");
    assert!(OrenNayarFull::new(f32x8::splat(0.5), sigma).is_err());
    assert!(OrenNayarFujii::new(f32x8::splat(0.5), sigma).is_err());
}
