//! Bézier curves into a buffer: scaling in the number of points (cubic, 10…10⁶) and in the
//! degree (1…20, 10⁵ points), with per-point de Casteljau for comparison.

mod common;
use common::config;

use std::hint::black_box;

use cagd_bench::{cubic_curve, curve_of_degree};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

fn points_scaling(c: &mut Criterion) {
    let curve = cubic_curve();
    let mut g = c.benchmark_group("cubic_curve_points");
    for k in [10, 1_000, 100_000, 1_000_000] {
        let ts = cagd::linspace(0.0, 1.0, k);
        let mut out = vec![0.0; k * 3];
        g.throughput(Throughput::Elements(k as u64));
        g.bench_with_input(BenchmarkId::new("eval_many_into", k), &k, |b, _| {
            b.iter(|| curve.eval_many_into(&ts, black_box(&mut out)).unwrap())
        });
        if k <= 100_000 {
            g.bench_with_input(BenchmarkId::new("de_casteljau_per_point", k), &k, |b, _| {
                b.iter(|| {
                    for (p, &t) in black_box(&mut out).chunks_exact_mut(3).zip(&ts) {
                        p.copy_from_slice(curve.eval(t).as_slice());
                    }
                })
            });
        }
    }
    g.finish();
}

fn degree_scaling(c: &mut Criterion) {
    let k = 100_000;
    let ts = cagd::linspace(0.0, 1.0, k);
    let mut out = vec![0.0; k * 3];
    let mut g = c.benchmark_group("curve_degree_1e5_points");
    g.throughput(Throughput::Elements(k as u64));
    for n in [1, 2, 3, 5, 8, 10, 15, 20] {
        let curve = curve_of_degree(n);
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| curve.eval_many_into(&ts, black_box(&mut out)).unwrap())
        });
    }
    g.finish();
}

criterion_group! { name = benches; config = config(); targets = points_scaling, degree_scaling }
criterion_main!(benches);
