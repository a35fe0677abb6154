//! The SH9 kernels keep the crate's bad-input rule on f32, f64, f32x8 and f64x4: NaN in a
//! direction component gives NaN in every basis function and every channel of `eval` and
//! `irradiance`; the quadratures return NaN for a NaN or zero normal and for order 0; lanes
//! equal scalars bit for bit (the kernels are sums of products, no transcendental).
#![cfg(feature = "ibl")]

use brdf::ibl::irradiance::{self, Sh9, project, sh9_basis};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

fn env(d: V3<f64>) -> V3<f64> {
    V3::new(1.0 + d.z, 0.5 + 0.2 * d.x * d.y, 2.0 - d.y)
}

fn check<T: Real>(name: &str, sh: &Sh9<f64>) {
    let sh = Sh9::<T>::splat_from(sh);
    let nan = T::splat(f64::NAN);
    let (a, b) = (T::splat(0.6), T::splat(0.8));
    for (k, d) in [V3::new(nan, a, b), V3::new(a, nan, b), V3::new(a, b, nan)]
        .into_iter()
        .enumerate()
    {
        let all = |v: V3<T>| {
            (0..T::LANES).all(|i| {
                let l = v.lane(i);
                l.x.is_nan() && l.y.is_nan() && l.z.is_nan()
            })
        };
        assert!(all(sh.eval(d)), "{name}: eval, NaN component {k}");
        assert!(
            all(sh.irradiance(d)),
            "{name}: irradiance, NaN component {k}"
        );
        for y in sh9_basis(d) {
            assert!(
                (0..T::LANES).all(|i| y.lane(i).is_nan()),
                "{name}: basis {k}"
            );
        }
    }
    // Finite unit directions give finite values.
    let e = sh.irradiance(V3::new(T::ZERO, a, b));
    assert!((0..T::LANES).all(|i| e.lane(i).x.is_finite()));
}

#[test]
fn sh9_nan_in_gives_nan_out_on_every_type() {
    let sh = project(env, 8);
    check::<f32>("f32", &sh);
    check::<f64>("f64", &sh);
    check::<f32x8>("f32x8", &sh);
    check::<f64x4>("f64x4", &sh);
    let mut acc = Sh9::<f64>::zero();
    acc.add(V3::new(f64::NAN, 0.0, 1.0), V3::splat(1.0), 0.1);
    assert!(acc.coeffs().iter().all(|c| c.x.is_nan()));
    let nan_sh = Sh9::from_coeffs([V3::splat(f64::NAN); 9]);
    assert!(nan_sh.irradiance(V3::new(0.0, 0.0, 1.0)).x.is_nan());
}

#[test]
fn quadratures_return_nan_for_bad_normals_and_order_zero() {
    let mut calls = 0;
    for n in [
        V3::new(f64::NAN, 0.0, 1.0),
        V3::splat(0.0),
        V3::new(0.0, f64::INFINITY, 1.0),
    ] {
        let e = irradiance::irradiance(
            n,
            |d| {
                calls += 1;
                env(d)
            },
            8,
        );
        assert!(e.x.is_nan() && e.y.is_nan() && e.z.is_nan(), "{n:?}");
    }
    assert!(
        irradiance::irradiance(V3::new(0.0, 0.0, 1.0), env, 0)
            .x
            .is_nan()
    );
    assert!(project(env, 0).coeffs().iter().all(|c| c.x.is_nan()));
    assert_eq!(calls, 0);
    // A non-unit normal is normalised.
    let a = irradiance::irradiance(V3::new(0.0, 0.0, 3.0), env, 8);
    let b = irradiance::irradiance(V3::new(0.0, 0.0, 1.0), env, 8);
    assert_eq!(a, b);
}

#[test]
fn sh9_lanes_equal_scalars() {
    let sh = project(env, 8);
    let (s32, s64) = (Sh9::<f32>::splat_from(&sh), Sh9::<f64>::splat_from(&sh));
    let (l8, l4) = (Sh9::<f32x8>::splat_from(&sh), Sh9::<f64x4>::splat_from(&sh));
    let dirs: Vec<V3<f64>> = (0..8)
        .map(|i| {
            let t = f64::from(i) * 0.7;
            V3::new(
                t.sin() * 0.6,
                t.cos() * 0.6,
                0.8 * if i % 2 == 0 { 1.0 } else { -1.0 },
            )
        })
        .collect();
    let d8 = V3::new(
        f32x8::from_fn(|i| dirs[i].x as f32),
        f32x8::from_fn(|i| dirs[i].y as f32),
        f32x8::from_fn(|i| dirs[i].z as f32),
    );
    let d4 = V3::new(
        f64x4::from_fn(|i| dirs[i].x),
        f64x4::from_fn(|i| dirs[i].y),
        f64x4::from_fn(|i| dirs[i].z),
    );
    let (e8, i8) = (l8.eval(d8), l8.irradiance(d8));
    let (e4, i4) = (l4.eval(d4), l4.irradiance(d4));
    for (i, di) in dirs.iter().enumerate() {
        let d = V3::new(di.x as f32, di.y as f32, di.z as f32);
        assert_eq!(e8.lane(i), s32.eval(d), "f32x8 eval lane {i}");
        assert_eq!(i8.lane(i), s32.irradiance(d), "f32x8 irradiance lane {i}");
    }
    for (i, &di) in dirs.iter().take(4).enumerate() {
        assert_eq!(e4.lane(i), s64.eval(di), "f64x4 eval lane {i}");
        assert_eq!(i4.lane(i), s64.irradiance(di), "f64x4 irradiance lane {i}");
    }
}
