//! Question answered: how much faster is one generic kernel on `f32x8` lanes than on scalar
//! `f32`, and what do the lane transcendentals cost (the `wide` polynomials against the
//! per-lane `libm` fallbacks)?
//!
//! Run: `cargo bench -p brdf-bench --bench lanes`. Compare the `elem/s` of the `scalar` and `f32x8` rows of
//! one group: their ratio is the SIMD speed-up on this machine (without `-C target-cpu`, x86-64
//! lanes are two SSE halves; with AVX2 they are one register).

use brdf::wide::f32x8;
use brdf::{Real, V3};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

const N: usize = 4096;

/// A representative shading kernel: GGX D, height-correlated Smith V and Schlick F, written
/// here against `Real` only, so the benchmark measures the lane abstraction, not a module.
#[inline]
fn specular<T: Real>(n_dot_h: T, n_dot_v: T, n_dot_l: T, v_dot_h: T, alpha: T) -> T {
    let a2 = alpha * alpha;
    let t = (n_dot_h * n_dot_h).mul_add(a2 - T::ONE, T::ONE);
    let d = a2 / (T::PI * t * t);
    let gv = n_dot_l * (n_dot_v * n_dot_v * (T::ONE - a2) + a2).sqrt();
    let gl = n_dot_v * (n_dot_l * n_dot_l * (T::ONE - a2) + a2).sqrt();
    let v = T::HALF / (gv + gl).max(T::MIN_POSITIVE);
    let f0 = T::splat(0.04);
    let f = f0 + (T::ONE - f0) * (T::ONE - v_dot_h).powi(5);
    d * v * f
}

fn inputs() -> Vec<[f32; 5]> {
    (0..N)
        .map(|i| {
            let u = (i as f32 + 0.5) / N as f32;
            [
                0.5 + 0.5 * u,
                0.2 + 0.8 * u,
                1.0 - 0.7 * u,
                0.3 + 0.6 * u,
                0.05 + 0.9 * u,
            ]
        })
        .collect()
}

fn bench_kernel(c: &mut Criterion) {
    let xs = inputs();
    let lanes: Vec<[f32x8; 5]> = xs
        .chunks_exact(8)
        .map(|ch| core::array::from_fn(|k| f32x8::from_fn(|i| ch[i][k])))
        .collect();
    let mut g = c.benchmark_group("ggx_specular");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("scalar", |b| {
        b.iter(|| {
            xs.iter()
                .map(|x| specular(x[0], x[1], x[2], x[3], x[4]))
                .sum::<f32>()
        })
    });
    g.bench_function("f32x8", |b| {
        b.iter(|| {
            lanes.iter().fold(f32x8::ZERO, |acc, x| {
                acc + specular(x[0], x[1], x[2], x[3], x[4])
            })
        })
    });
    g.finish();
}

fn bench_transcendentals(c: &mut Criterion) {
    let xs: Vec<f32> = (0..N).map(|i| 0.01 + 4.0 * i as f32 / N as f32).collect();
    let lanes: Vec<f32x8> = xs
        .chunks_exact(8)
        .map(|ch| f32x8::from_fn(|i| ch[i]))
        .collect();
    let mut g = c.benchmark_group("transcendentals");
    g.throughput(Throughput::Elements(N as u64));
    type F32Fn = fn(f32) -> f32;
    type LaneFn = fn(f32x8) -> f32x8;
    let cases: [(&str, F32Fn, LaneFn); 5] = [
        ("exp", Real::exp, Real::exp),
        ("ln", Real::ln, Real::ln),
        ("sin", Real::sin, Real::sin),
        ("erf (libm per lane)", Real::erf, Real::erf),
        (
            "pow (libm per lane)",
            |x| Real::pow(x, 2.5),
            |x| Real::pow(x, f32x8::splat(2.5)),
        ),
    ];
    for (name, s, l) in cases {
        g.bench_with_input(BenchmarkId::new("scalar", name), &xs, |b, xs| {
            b.iter(|| xs.iter().map(|&x| s(black_box(x))).sum::<f32>())
        });
        g.bench_with_input(BenchmarkId::new("f32x8", name), &lanes, |b, ls| {
            b.iter(|| ls.iter().fold(f32x8::ZERO, |acc, &x| acc + l(black_box(x))))
        });
    }
    g.finish();
}

/// Directions through the structure-of-arrays vector: the transpose cost of `V3::from_lanes`.
fn bench_soa(c: &mut Criterion) {
    let dirs: Vec<glam::Vec3> = (0..N)
        .map(|i| glam::Vec3::new(i as f32, 1.0, 2.0).normalize())
        .collect();
    let mut g = c.benchmark_group("soa_dot");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("scalar", |b| {
        b.iter(|| {
            dirs.iter()
                .map(|&d| V3::from(d).dot(V3::unit_z()))
                .sum::<f32>()
        })
    });
    g.bench_function("f32x8", |b| {
        b.iter(|| {
            dirs.chunks_exact(8).fold(f32x8::ZERO, |acc, ch| {
                let v = V3::<f32x8>::from_lanes(core::array::from_fn(|i| ch[i]));
                acc + v.dot(V3::unit_z())
            })
        })
    });
    g.finish();
}

criterion_group!(benches, bench_kernel, bench_transcendentals, bench_soa);
criterion_main!(benches);
