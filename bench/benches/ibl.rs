//! Question answered: what does each analytic DFG fit save over reading the split-sum table?
//! Times a bilinear lookup in a 64 x 64 table (`ibl::dfg::lookup`, f32, scalar) against each
//! fit on the same 4096 (NoV, roughness) pairs, on f32 and on f32x8 lanes; the error each fit
//! pays is printed by `cargo test --test ibl dfg_approximations:: -- --nocapture`.
//! Run: `cargo bench -p brdf-bench --bench ibl`.

use brdf::ibl::dfg;
use brdf::wide::f32x8;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

const N: usize = 4096;
const SIDE: usize = 64;

/// (NoV, roughness) pairs spread over (0, 1].
fn inputs() -> Vec<[f32; 2]> {
    (0..N)
        .map(|i| {
            let u = (i as f32 + 0.5) / N as f32;
            [0.02 + 0.98 * u, (13.0 * u) % 1.0]
        })
        .collect()
}

type Fit32 = fn(f32, f32) -> [f32; 2];
type FitX8 = fn(f32x8, f32x8) -> [f32x8; 2];

fn bench(c: &mut Criterion) {
    let xs = inputs();
    let ls: Vec<[f32x8; 2]> = xs
        .chunks_exact(8)
        .map(|c| {
            core::array::from_fn(|k| f32x8::from(core::array::from_fn::<f32, 8, _>(|i| c[i][k])))
        })
        .collect();
    // Timing only: the table's accuracy does not change the cost of reading it.
    let mut table = vec![[0.0_f32; 3]; SIDE * SIDE];
    dfg::table(&mut table, SIDE, SIDE, 64).expect("dimensions match");
    let mut g = c.benchmark_group("dfg");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function(BenchmarkId::new("f32", "table_lookup_64x64"), |b| {
        b.iter(|| {
            xs.iter()
                .map(|x| {
                    let v = dfg::lookup(black_box(&table), SIDE, SIDE, black_box(x[0]), x[1]);
                    v[0] + v[1]
                })
                .sum::<f32>()
        })
    });
    let fits: [(&str, Fit32, FitX8); 4] = [
        ("karis_mobile", dfg::karis_mobile, dfg::karis_mobile),
        ("lazarov", dfg::lazarov, dfg::lazarov),
        (
            "narkowicz_lazarov",
            dfg::narkowicz_lazarov,
            dfg::narkowicz_lazarov,
        ),
        (
            "narkowicz_polynomial",
            dfg::narkowicz_polynomial,
            dfg::narkowicz_polynomial,
        ),
    ];
    for (label, s, l) in fits {
        g.bench_with_input(BenchmarkId::new("f32", label), &xs, |b, xs| {
            b.iter(|| {
                xs.iter()
                    .map(|x| {
                        let v = s(black_box(x[0]), x[1]);
                        v[0] + v[1]
                    })
                    .sum::<f32>()
            })
        });
        g.bench_with_input(BenchmarkId::new("f32x8", label), &ls, |b, ls| {
            b.iter(|| {
                ls.iter().fold(f32x8::ZERO, |acc, x| {
                    let v = l(black_box(x[0]), x[1]);
                    acc + v[0] + v[1]
                })
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
