//! Question answered: which visible-normal sampler should a renderer use? Times Heitz 2018's
//! GGX VNDF sampler against Dupuy and Benyoub 2023's spherical caps (same distribution), the
//! classic D cos sampling, and the Beckmann VNDF sampler, on f32 and f32x8, each including its
//! pdf. Run: `cargo bench -p brdf-bench --bench sampling`.

use brdf::V3;
use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::sampling;
use brdf::wide::f32x8;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

const N: usize = 4096;

fn bench(c: &mut Criterion) {
    let us: Vec<(f32, f32)> = (0..N)
        .map(|i| {
            (
                ((i * 7919) % N) as f32 / N as f32,
                (i as f32 + 0.5) / N as f32,
            )
        })
        .collect();
    let ls: Vec<(f32x8, f32x8)> = us
        .chunks_exact(8)
        .map(|c| {
            (
                f32x8::from(core::array::from_fn::<f32, 8, _>(|i| c[i].0)),
                f32x8::from(core::array::from_fn::<f32, 8, _>(|i| c[i].1)),
            )
        })
        .collect();
    let g = Ggx::new(0.3f32, 0.5).unwrap();
    let gl = Ggx::new(f32x8::splat(0.3), f32x8::splat(0.5)).unwrap();
    let b = Beckmann::new(0.3f32, 0.5).unwrap();
    let wo = V3::new(0.5f32, 0.3, 0.812);
    let wol = V3::new(f32x8::splat(0.5), f32x8::splat(0.3), f32x8::splat(0.812));
    let mut grp = c.benchmark_group("vndf");
    grp.throughput(Throughput::Elements(N as u64));
    grp.bench_function("f32/ggx heitz 2018", |bn| {
        b_iter(bn, &us, |x, y| sampling::ggx_vndf(&g, wo, x, y).1)
    });
    grp.bench_function("f32/ggx spherical cap", |bn| {
        b_iter(bn, &us, |x, y| {
            sampling::ggx_vndf_spherical_cap(&g, wo, x, y).1
        })
    });
    grp.bench_function("f32/ggx d cos", |bn| {
        b_iter(bn, &us, |x, y| sampling::ggx_d_cos(&g, x, y).1)
    });
    grp.bench_function("f32/beckmann vndf", |bn| {
        b_iter(bn, &us, |x, y| sampling::beckmann_vndf(&b, wo, x, y).1)
    });
    grp.bench_function("f32x8/ggx heitz 2018", |bn| {
        bn.iter(|| {
            ls.iter().fold(f32x8::ZERO, |acc, &(x, y)| {
                acc + sampling::ggx_vndf(&gl, wol, black_box(x), y).1
            })
        })
    });
    grp.bench_function("f32x8/ggx spherical cap", |bn| {
        bn.iter(|| {
            ls.iter().fold(f32x8::ZERO, |acc, &(x, y)| {
                acc + sampling::ggx_vndf_spherical_cap(&gl, wol, black_box(x), y).1
            })
        })
    });
    grp.finish();
}

fn b_iter(bn: &mut criterion::Bencher, us: &[(f32, f32)], f: impl Fn(f32, f32) -> f32) {
    bn.iter(|| us.iter().map(|&(x, y)| f(black_box(x), y)).sum::<f32>())
}

criterion_group!(benches, bench);
criterion_main!(benches);
