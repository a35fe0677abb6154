//! `batch::run` over slices equals the kernel evaluated element by element, for every length
//! (full groups and every tail length), on f32x8, f64x4 and scalars, with several inputs and
//! outputs; mismatched lengths are an error that writes nothing.
#![cfg(all(feature = "ggx", feature = "fresnel"))]

use brdf::wide::{f32x8, f64x4};
use brdf::{batch, fresnel, ggx};

fn inputs(n: usize) -> (Vec<f32>, Vec<f32>) {
    let c = (0..n).map(|i| ((i * 37 % 101) as f32) / 100.0).collect();
    let a = (0..n)
        .map(|i| 0.05 + ((i * 13 % 17) as f32) / 20.0)
        .collect();
    (c, a)
}

#[test]
fn every_length_matches_the_scalar_kernel_bit_for_bit_on_f32x8() {
    for n in 0..=67 {
        let (c, a) = inputs(n);
        let mut d = vec![f32::NAN; n];
        let done = batch::run_f32([&c, &a], [&mut d], |[c, a]| [ggx::d(c, a)]).unwrap();
        assert_eq!(done, n);
        for i in 0..n {
            // The lane D is the scalar D to within the lane functions' bound; here both are
            // compensated and rounded once, so equal.
            let want = ggx::d(c[i], a[i]);
            assert_eq!(d[i].to_bits(), want.to_bits(), "n {n} element {i}");
        }
    }
}

#[test]
fn several_inputs_and_outputs_and_f64_lanes() {
    let n = 1003;
    let cos: Vec<f64> = (0..n).map(|i| (i as f64 + 0.5) / n as f64).collect();
    let eta: Vec<f64> = (0..n).map(|i| 0.2 + (i % 7) as f64 * 0.3).collect();
    let k: Vec<f64> = (0..n).map(|i| 1.0 + (i % 5) as f64).collect();
    let (mut f, mut one_minus) = (vec![0.0; n], vec![0.0; n]);
    batch::run_f64([&cos, &eta, &k], [&mut f, &mut one_minus], |[c, e, k]| {
        let r = fresnel::conductor(c, e, k);
        [r, f64x4::ONE - r]
    })
    .unwrap();
    for i in 0..n {
        let want = fresnel::conductor(cos[i], eta[i], k[i]);
        assert_eq!(f[i], want, "element {i}");
        assert_eq!(one_minus[i], 1.0 - want, "element {i}");
    }
}

#[test]
fn scalar_lanes_run_the_same_kernel() {
    let (c, a) = inputs(50);
    let (mut lanes, mut scalar) = (vec![0.0; 50], vec![0.0; 50]);
    batch::run::<f32x8, 2, 1>([&c, &a], [&mut lanes], |[c, a]| [ggx::d(c, a)]).unwrap();
    batch::run::<f32, 2, 1>([&c, &a], [&mut scalar], |[c, a]| [ggx::d(c, a)]).unwrap();
    assert_eq!(lanes, scalar);
}

/// The tail's padding lanes repeat the last element: a kernel never sees a value the caller
/// did not give (here, one that would turn NaN).
#[test]
fn the_tail_pads_with_the_callers_own_values() {
    let x = [1.0f32, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0];
    let mut seen_min = f32::INFINITY;
    let mut out = [0.0f32; 10];
    batch::run_f32([&x], [&mut out], |[v]| {
        seen_min = v.to_array().iter().fold(seen_min, |m, &x| m.min(x));
        [v.sqrt()]
    })
    .unwrap();
    assert_eq!(seen_min, 1.0);
    for (o, v) in out.iter().zip(x) {
        assert_eq!(*o, v.sqrt());
    }
}

#[test]
fn mismatched_lengths_are_an_error_and_write_nothing() {
    let a = [0.5f32; 9];
    let b = [0.5f32; 8];
    let mut out = [7.0f32; 9];
    let err = batch::run_f32([&a, &b], [&mut out], |[x, y]| [x * y]).unwrap_err();
    assert_eq!(err.param, "inputs");
    assert!(out.iter().all(|&v| v == 7.0));
    let mut short = [7.0f32; 8];
    let err = batch::run_f32([&a], [&mut short], |[x]| [x]).unwrap_err();
    assert_eq!(err.param, "outputs");
    assert!(short.iter().all(|&v| v == 7.0));
    // No slices at all: nothing to do.
    assert_eq!(batch::run_f32::<0, 0>([], [], |[]| []), Ok(0));
}

/// NaN in one element stays in that element (lanes do not interact).
#[test]
fn a_nan_element_stays_in_its_element() {
    let (mut c, a) = inputs(20);
    c[11] = f32::NAN;
    let mut d = vec![0.0; 20];
    batch::run_f32([&c, &a], [&mut d], |[c, a]| [ggx::d(c, a)]).unwrap();
    for (i, v) in d.iter().enumerate() {
        assert_eq!(v.is_nan(), i == 11, "element {i}");
    }
}
