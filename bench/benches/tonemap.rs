//! Question answered: what does each tonemapping operator cost per pixel, on f32 and on f32x8
//! lanes? Run: `cargo bench -p brdf-bench --bench tonemap`. Ratios between rows of one run are the figures
//! to quote (the machine is shared).

use brdf::tonemap::Operator;
use brdf::wide::f32x8;
use brdf::{Real, V3};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

const N: usize = 4096;

fn bench(c: &mut Criterion) {
    let px: Vec<V3<f32>> = (0..N)
        .map(|i| {
            let t = (i as f32 + 0.5) / N as f32;
            V3::new(16.0 * t * t, 4.0 * t, 0.5 + 8.0 * ((7.0 * t) % 1.0))
        })
        .collect();
    let lanes: Vec<V3<f32x8>> = px
        .chunks_exact(8)
        .map(|ch| {
            V3::new(
                f32x8::from_fn(|i| ch[i].x),
                f32x8::from_fn(|i| ch[i].y),
                f32x8::from_fn(|i| ch[i].z),
            )
        })
        .collect();
    let mut g = c.benchmark_group("tonemap");
    g.throughput(Throughput::Elements(N as u64));
    for (i, op) in Operator::all().into_iter().enumerate() {
        // AgX variants with different looks share a variant name: the index keeps IDs unique.
        let name = format!(
            "{i:02} {}",
            format!("{op:?}").split('(').next().unwrap_or("op")
        );
        g.bench_with_input(BenchmarkId::new("f32", &name), &px, |b, px| {
            b.iter(|| px.iter().map(|&p| op.apply(black_box(p)).y).sum::<f32>())
        });
        g.bench_with_input(BenchmarkId::new("f32x8", &name), &lanes, |b, ls| {
            b.iter(|| {
                ls.iter()
                    .fold(f32x8::ZERO, |acc, &p| acc + op.apply(black_box(p)).y)
            })
        });
    }
    g.finish();
}

/// The refined sRGB pair (per-lane f64, two pows in the OETF) against the single-pow form.
fn transfer(c: &mut Criterion) {
    let xs: Vec<f32> = (0..N).map(|i| (i as f32 + 0.5) / N as f32).collect();
    let ls: Vec<f32x8> = xs
        .chunks_exact(8)
        .map(|ch| f32x8::from_fn(|i| ch[i]))
        .collect();
    let mut g = c.benchmark_group("srgb");
    g.throughput(Throughput::Elements(N as u64));
    type F = fn(f32) -> f32;
    type L = fn(f32x8) -> f32x8;
    let cases: [(&str, F, L); 3] = [
        (
            "oetf (refined)",
            brdf::color::srgb_oetf,
            brdf::color::srgb_oetf,
        ),
        (
            "oetf_fast",
            brdf::color::srgb_oetf_fast,
            brdf::color::srgb_oetf_fast,
        ),
        ("eotf", brdf::color::srgb_eotf, brdf::color::srgb_eotf),
    ];
    for (name, s, l) in cases {
        g.bench_with_input(BenchmarkId::new("f32", name), &xs, |b, xs| {
            b.iter(|| xs.iter().map(|&x| s(black_box(x))).sum::<f32>())
        });
        g.bench_with_input(BenchmarkId::new("f32x8", name), &ls, |b, ls| {
            b.iter(|| ls.iter().fold(f32x8::ZERO, |acc, &x| acc + l(black_box(x))))
        });
    }
    g.finish();
}

criterion_group!(benches, bench, transfer);
criterion_main!(benches);
