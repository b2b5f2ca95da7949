//! Bilinear Coons patches (four cubic Bézier boundaries) and Gordon surfaces (5 × 5 network of
//! cubic Bézier curves) on N × N grids, N = 10…2000, next to the bicubic Bézier patch they
//! come from on the same grids.

mod common;
use common::config;

use std::hint::black_box;

use cagd::Surface;
use cagd_bench::{coons_of, gordon_of, patch};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

fn coons_gordon(c: &mut Criterion) {
    let p = patch(3, 3);
    let coons = coons_of(&p);
    let gordon = gordon_of(&p);
    let mut g = c.benchmark_group("coons_gordon_grid");
    for n in [10, 100, 500, 1000, 2000] {
        let ts = cagd::linspace(0.0, 1.0, n);
        let mut out = vec![0.0; n * n * 3];
        g.throughput(Throughput::Elements((n * n) as u64));
        let surfaces: [(&str, &dyn Surface); 3] = [
            ("bezier_bicubic", &p),
            ("coons_bilinear", &coons),
            ("gordon_5x5_cubic", &gordon),
        ];
        for (name, s) in surfaces {
            g.bench_with_input(BenchmarkId::new(name, n), &n, |b, _| {
                b.iter(|| s.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap())
            });
        }
    }
    g.finish();
}

criterion_group! { name = benches; config = config(); targets = coons_gordon }
criterion_main!(benches);
