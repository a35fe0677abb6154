//! Question answered: what does each approximation save over the exact form it replaces?
//! Each group times the exact kernel and its approximations on the same 4096 inputs, on f32
//! and on f32x8 lanes; the ratio of their times is the speed-up, and the error each one pays
//! for it is measured by the tests named in its doc comment (`cargo test --test microfacet
//! --test fresnel approximations:: -- --nocapture`). Run: `cargo bench -p brdf-bench --bench approximations`.

use brdf::wide::f32x8;
use brdf::{beckmann, fresnel, ggx};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

const N: usize = 4096;

/// (cos_v, cos_l, alpha) triples spread over (0, 1].
fn inputs() -> Vec<[f32; 3]> {
    (0..N)
        .map(|i| {
            let u = (i as f32 + 0.5) / N as f32;
            [
                0.02 + 0.98 * u,
                1.0 - 0.97 * ((7.0 * u) % 1.0),
                0.02 + 0.98 * ((13.0 * u) % 1.0),
            ]
        })
        .collect()
}

fn lanes(xs: &[[f32; 3]]) -> Vec<[f32x8; 3]> {
    xs.chunks_exact(8)
        .map(|c| {
            core::array::from_fn(|k| f32x8::from(core::array::from_fn::<f32, 8, _>(|i| c[i][k])))
        })
        .collect()
}

type Kernel32 = fn(f32, f32, f32) -> f32;
type KernelX8 = fn(f32x8, f32x8, f32x8) -> f32x8;

fn group(c: &mut Criterion, name: &str, kernels: &[(&str, Kernel32, KernelX8)]) {
    let xs = inputs();
    let ls = lanes(&xs);
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(N as u64));
    for (label, s, l) in kernels {
        g.bench_with_input(BenchmarkId::new("f32", label), &xs, |b, xs| {
            b.iter(|| {
                xs.iter()
                    .map(|x| s(black_box(x[0]), x[1], x[2]))
                    .sum::<f32>()
            })
        });
        g.bench_with_input(BenchmarkId::new("f32x8", label), &ls, |b, ls| {
            b.iter(|| {
                ls.iter()
                    .fold(f32x8::ZERO, |acc, x| acc + l(black_box(x[0]), x[1], x[2]))
            })
        });
    }
    g.finish();
}

fn smith(c: &mut Criterion) {
    group(
        c,
        "ggx_visibility",
        &[
            (
                "exact v_correlated",
                |v, l, a| ggx::v_correlated(v, l, a),
                |v, l, a| ggx::v_correlated(v, l, a),
            ),
            (
                "hammon",
                |v, l, a| ggx::v_correlated_hammon(v, l, a),
                |v, l, a| ggx::v_correlated_hammon(v, l, a),
            ),
            (
                "filament fast",
                |v, l, a| ggx::v_correlated_fast(v, l, a),
                |v, l, a| ggx::v_correlated_fast(v, l, a),
            ),
            (
                "schlick k=alpha/2",
                |v, l, a| ggx::v_schlick(v, l, a * 0.5),
                |v, l, a| ggx::v_schlick(v, l, a * f32x8::splat(0.5)),
            ),
        ],
    );
    group(
        c,
        "beckmann_lambda",
        &[
            (
                "exact (erfc)",
                |v, _, a| beckmann::lambda(v, a),
                |v, _, a| beckmann::lambda(v, a),
            ),
            (
                "walter rational",
                |v, _, a| beckmann::lambda_walter(v, a),
                |v, _, a| beckmann::lambda_walter(v, a),
            ),
        ],
    );
    group(
        c,
        "ndf",
        &[
            ("ggx d", |h, _, a| ggx::d(h, a), |h, _, a| ggx::d(h, a)),
            (
                "beckmann d",
                |h, _, a| beckmann::d(h, a),
                |h, _, a| beckmann::d(h, a),
            ),
        ],
    );
}

fn fresnel_terms(c: &mut Criterion) {
    group(
        c,
        "fresnel",
        &[
            (
                "exact dielectric",
                |c, _, a| fresnel::dielectric(c, 1.0 + a),
                |c, _, a| fresnel::dielectric(c, f32x8::splat(1.0) + a),
            ),
            (
                "schlick",
                |c, _, a| fresnel::schlick(a * 0.1, c),
                |c, _, a| fresnel::schlick(a * f32x8::splat(0.1), c),
            ),
            (
                "schlick sg",
                |c, _, a| fresnel::schlick_sg(a * 0.1, c),
                |c, _, a| fresnel::schlick_sg(a * f32x8::splat(0.1), c),
            ),
            (
                "exact conductor",
                |c, l, a| fresnel::conductor(c, a, 3.0 * l),
                |c, l, a| fresnel::conductor(c, a, f32x8::splat(3.0) * l),
            ),
        ],
    );
}

criterion_group!(benches, smith, fresnel_terms);
criterion_main!(benches);
