//! Bézier patch grids: scaling in the grid size (bicubic, N = 10…2000), in the degree
//! ((m, m), m = 1…20, on 500 × 500: linear in m), and the grid path against per-point tensor
//! de Casteljau at degree (10, 10).

mod common;
use common::config;

use std::hint::black_box;

use cagd::bezier::BezierPatch;
use cagd_bench::{patch, per_point_grid};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

fn grid(p: &BezierPatch, n: usize) -> (Vec<f64>, Vec<f64>) {
    (cagd::linspace(0.0, 1.0, n), vec![0.0; n * n * p.dim()])
}

fn bicubic_scaling(c: &mut Criterion) {
    let p = patch(3, 3);
    let mut g = c.benchmark_group("bicubic_grid_scaling");
    for n in [10, 100, 500, 1000, 2000] {
        let (ts, mut out) = grid(&p, n);
        g.throughput(Throughput::Elements((n * n) as u64));
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| p.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap())
        });
    }
    g.finish();
}

fn degree_scaling(c: &mut Criterion) {
    let mut g = c.benchmark_group("degree_mm_grid_500x500");
    g.throughput(Throughput::Elements(500 * 500));
    for m in [1, 2, 3, 4, 5, 6, 8, 10, 12, 14, 16, 18, 20] {
        let p = patch(m, m);
        let (ts, mut out) = grid(&p, 500);
        g.bench_with_input(BenchmarkId::from_parameter(m), &m, |b, _| {
            b.iter(|| p.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap())
        });
    }
    g.finish();
}

fn degree10_vs_de_casteljau(c: &mut Criterion) {
    let p = patch(10, 10);
    let (ts, mut out) = grid(&p, 100);
    let mut g = c.benchmark_group("degree_10_grid_100x100");
    g.throughput(Throughput::Elements(100 * 100));
    g.bench_function("eval_grid_into", |b| {
        b.iter(|| p.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap())
    });
    g.bench_function("de_casteljau_per_point", |b| {
        b.iter(|| {
            per_point_grid(&ts, &ts, black_box(&mut out), |u, v| {
                let x = p.eval(u, v);
                [x[0], x[1], x[2]]
            })
        })
    });
    g.finish();
}

criterion_group! { name = benches; config = config(); targets = bicubic_scaling, degree_scaling, degree10_vs_de_casteljau }
criterion_main!(benches);
