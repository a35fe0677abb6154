//! `batch::par_run` (feature `rayon`) against `batch::run`: the same results bit for bit for
//! every length (empty, one chunk, one element past a chunk, many chunks with a ragged tail),
//! on `f32x8`, `f64x4` and scalars, several inputs and outputs; the same errors for slices of
//! different lengths, with nothing written.
#![cfg(all(feature = "rayon", feature = "ggx"))]

use brdf::batch::{self, PAR_CHUNK};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, ggx};

use crate::common::Rng;

fn data(n: usize, seed: u64) -> (Vec<f64>, Vec<f64>) {
    let mut rng = Rng(seed);
    let c = (0..n).map(|_| 2.0 * rng.next_f64() - 0.5).collect();
    let a = (0..n).map(|_| rng.next_f64()).collect();
    (c, a)
}

/// D and Lambda of two input slices: two outputs.
fn kernel<T: Real>([c, a]: [T; 2]) -> [T; 2] {
    [ggx::d(c, a), ggx::lambda(c, a)]
}

#[test]
fn par_run_equals_run_bit_for_bit() {
    for n in [
        0,
        1,
        7,
        PAR_CHUNK,
        PAR_CHUNK + 1,
        5 * PAR_CHUNK + 13,
        40 * PAR_CHUNK + 3,
    ] {
        let (c, a) = data(n, n as u64 + 1);
        let (c32, a32): (Vec<f32>, Vec<f32>) = (
            c.iter().map(|&x| x as f32).collect(),
            a.iter().map(|&x| x as f32).collect(),
        );
        // f32x8
        let (mut p0, mut p1, mut r0, mut r1) =
            (vec![0f32; n], vec![0f32; n], vec![0f32; n], vec![0f32; n]);
        assert_eq!(
            batch::par_run_f32([&c32, &a32], [&mut p0, &mut p1], kernel::<f32x8>),
            Ok(n)
        );
        assert_eq!(
            batch::run_f32([&c32, &a32], [&mut r0, &mut r1], kernel::<f32x8>),
            Ok(n)
        );
        assert!(
            p0.iter().zip(&r0).all(|(x, y)| x.to_bits() == y.to_bits()),
            "f32x8, n = {n}"
        );
        assert!(
            p1.iter().zip(&r1).all(|(x, y)| x.to_bits() == y.to_bits()),
            "f32x8, n = {n}"
        );
        // f64x4
        let (mut p0, mut p1, mut r0, mut r1) =
            (vec![0f64; n], vec![0f64; n], vec![0f64; n], vec![0f64; n]);
        assert_eq!(
            batch::par_run_f64([&c, &a], [&mut p0, &mut p1], kernel::<f64x4>),
            Ok(n)
        );
        assert_eq!(
            batch::run_f64([&c, &a], [&mut r0, &mut r1], kernel::<f64x4>),
            Ok(n)
        );
        assert!(
            p0.iter().zip(&r0).all(|(x, y)| x.to_bits() == y.to_bits()),
            "f64x4, n = {n}"
        );
        assert!(
            p1.iter().zip(&r1).all(|(x, y)| x.to_bits() == y.to_bits()),
            "f64x4, n = {n}"
        );
        // Scalar f64, and each element against the kernel called on it alone.
        let mut p0 = vec![0f64; n];
        let mut p1 = vec![0f64; n];
        assert_eq!(
            batch::par_run::<f64, 2, 2>([&c, &a], [&mut p0, &mut p1], kernel::<f64>),
            Ok(n)
        );
        for i in 0..n {
            let [d, l] = kernel::<f64>([c[i], a[i]]);
            assert_eq!(
                (p0[i].to_bits(), p1[i].to_bits()),
                (d.to_bits(), l.to_bits())
            );
        }
    }
}

#[test]
fn par_run_rejects_slices_of_different_lengths_and_writes_nothing() {
    let n = 3 * PAR_CHUNK;
    let (c, a) = data(n, 9);
    let short = &a[..n - 1];
    let mut out = vec![-1.0f64; n];
    let e = batch::par_run_f64([&c, short], [&mut out], |[x, y]: [f64x4; 2]| [x + y]);
    assert_eq!(
        e,
        batch::run_f64([&c, short], [&mut out], |[x, y]: [f64x4; 2]| [x + y])
    );
    assert!(e.is_err());
    assert!(out.iter().all(|&x| x == -1.0));
    let mut short_out = vec![-1.0f64; n - 1];
    let e = batch::par_run_f64([&c, &a], [&mut short_out], |[x, y]: [f64x4; 2]| [x + y]);
    assert!(e.is_err());
    assert!(short_out.iter().all(|&x| x == -1.0));
}

#[test]
fn par_run_uses_the_enclosing_pool() {
    // A one-thread pool: the same results (the chunks run one after another).
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let n = 4 * PAR_CHUNK + 5;
    let (c, a) = data(n, 3);
    let (mut p, mut r) = (vec![0f64; n], vec![0f64; n]);
    pool.install(|| batch::par_run_f64([&c, &a], [&mut p], |[x, y]: [f64x4; 2]| [ggx::d(x, y)]))
        .unwrap();
    batch::run_f64([&c, &a], [&mut r], |[x, y]: [f64x4; 2]| [ggx::d(x, y)]).unwrap();
    assert!(p.iter().zip(&r).all(|(x, y)| x.to_bits() == y.to_bits()));
}
