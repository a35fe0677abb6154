//! Lanes and precision of the Oren-Nayar family: f32x8 and f64x4 lanes equal the scalar
//! kernels (bit for bit for the qualitative and Fujii forms, which use only IEEE arithmetic;
//! within a stated bound for the full model, whose acos is a polynomial on lanes), and the
//! f32 kernels stay within a stated bound of the f64 kernels on the same inputs.
//!
//! Errors of the full model are measured relative to max(f, rho / pi), Lambert's value for
//! the same albedo: the paper's L1 fit crosses zero (cos(phi) < 0, grazing, large sigma) by
//! cancellation, where no float evaluation has a small error relative to f itself.
//!
//! `cargo test --no-default-features --features diffuse --test diffuse oren_nayar_lanes:: --
//! --nocapture` prints the figures.
#![cfg(feature = "diffuse")]

use crate::common;

use brdf::Real;
use brdf::diffuse::{oren_nayar, oren_nayar_fujii, oren_nayar_full};
use brdf::wide::{f32x8, f64x4};
use common::Rng;

type Inputs = [f64; 6];

fn all3<T: Real>(x: [T; 6]) -> [T; 3] {
    [
        oren_nayar(x[0], x[1], x[2], x[3], x[4]),
        oren_nayar_full(x[0], x[1], x[2], x[3], x[4]),
        oren_nayar_fujii(x[0], x[1], x[2], x[3], x[5]),
    ]
}

/// Physically consistent cosines (min cosine `floor`), rho, sigma, Fujii sigma.
fn random_inputs(rng: &mut Rng, floor: f64) -> Inputs {
    let cv = floor + (1.0 - floor) * rng.next_f64();
    let cl = floor + (1.0 - floor) * rng.next_f64();
    let cp = (2.0 * core::f64::consts::PI * rng.next_f64()).cos();
    let vl = cv * cl + ((1.0 - cv * cv) * (1.0 - cl * cl)).sqrt() * cp;
    [
        cv,
        cl,
        vl,
        rng.next_f64(),
        2.0 * rng.next_f64(),
        rng.next_f64(),
    ]
}

/// |a - b| / max(|b|, rho / pi).
fn scaled(a: f64, b: f64, rho: f64) -> f64 {
    let scale = b.abs().max(rho * core::f64::consts::FRAC_1_PI);
    if a == b { 0.0 } else { (a - b).abs() / scale }
}

fn ulp32(a: f32, b: f32) -> u64 {
    (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
}
fn ulp64(a: f64, b: f64) -> u64 {
    (a.to_bits() as i128 - b.to_bits() as i128).unsigned_abs() as u64
}

#[test]
fn lanes_equal_scalars() {
    let mut rng = Rng(42);
    let (mut u8_, mut u4) = ([0u64; 3], [0u64; 3]);
    let (mut full8, mut full4) = (0.0f64, 0.0f64);
    for _ in 0..20_000 {
        let x: [Inputs; 8] = core::array::from_fn(|_| random_inputs(&mut rng, 1e-4));
        let lanes8 = all3::<f32x8>(core::array::from_fn(|k| {
            f32x8::new(core::array::from_fn(|i| x[i][k] as f32))
        }));
        let lanes4 = all3::<f64x4>(core::array::from_fn(|k| {
            f64x4::new(core::array::from_fn(|i| x[i][k]))
        }));
        for (i, xi) in x.iter().enumerate() {
            let s = all3::<f32>(xi.map(|v| v as f32));
            for m in 0..3 {
                u8_[m] = u8_[m].max(ulp32(lanes8[m].lane(i), s[m]));
            }
            full8 = full8.max(scaled(
                lanes8[1].lane(i).into(),
                s[1].into(),
                xi[3] as f32 as f64,
            ));
        }
        for (i, xi) in x.iter().take(4).enumerate() {
            let s = all3::<f64>(*xi);
            for m in 0..3 {
                u4[m] = u4[m].max(ulp64(lanes4[m].lane(i), s[m]));
            }
            full4 = full4.max(scaled(lanes4[1].lane(i), s[1], xi[3]));
        }
    }
    println!("max ULP lanes vs scalar [qualitative, full, Fujii]: f32x8 {u8_:?}, f64x4 {u4:?}");
    println!(
        "full, |lane - scalar| / max(f, rho/pi): f32x8 {full8:.2e} ({:.0} eps), f64x4 {full4:.2e} ({:.0} eps)",
        full8 / f64::from(f32::EPSILON),
        full4 / f64::EPSILON
    );
    assert_eq!(u8_[0], 0);
    assert_eq!(u8_[2], 0);
    assert_eq!(u4[0], 0);
    assert_eq!(u4[2], 0);
    // The full model's acos differs by <= 1 ULP (f32x8) / 2 ULP (f64x4) on lanes
    // (src/real.rs); tan(beta) ~ 1 / cos(beta) amplifies that near grazing. Bound: 64 eps,
    // a few times the measured maximum.
    assert!(full8 < 64.0 * f64::from(f32::EPSILON), "full f32x8 {full8}");
    assert!(full4 < 64.0 * f64::EPSILON, "full f64x4 {full4}");
}

#[test]
fn f32_kernels_track_f64() {
    let mut rng = Rng(9);
    let mut worst = [0.0f64; 3];
    let floor = 0.01;
    for _ in 0..500_000 {
        // Round the inputs to f32 first, so only the kernels' own rounding is measured.
        let x = random_inputs(&mut rng, floor).map(|v| v as f32);
        let r32 = all3::<f32>(x);
        let r64 = all3::<f64>(x.map(f64::from));
        for m in 0..3 {
            worst[m] = worst[m].max(scaled(f64::from(r32[m]), r64[m], f64::from(x[3])));
        }
    }
    println!(
        "f32 vs f64 max |f32 - f64| / max(f, rho/pi), cosines >= {floor} [qualitative, full, Fujii]: {:?} ({:?} f32 eps)",
        worst.map(|w| format!("{w:.2e}")),
        worst.map(|w| (w / f64::from(f32::EPSILON)).round())
    );
    // s = v.l - (n.v)(n.l) cancels: its absolute error ~ eps is divided by cos(beta) >= 0.01,
    // so the error can reach ~ B eps / cos(beta) ~ 50 eps. Bound 2e-5 (168 eps); measured
    // 3 / 59 / 3 eps (qualitative / full / Fujii).
    for (m, w) in worst.iter().enumerate() {
        assert!(*w < 2e-5, "form {m}: {w}");
    }
}
