//! Lagrange bases (first barycentric form) for 2…21 uniform nodes at 10⁴ parameters: `O(m)`
//! per parameter, into one buffer.

mod common;
use common::config;

use std::hint::black_box;

use cagd::lagrange::{Lagrange, NodePlacement};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

fn basis_rows(c: &mut Criterion) {
    let ts = cagd::linspace(0.0, 1.0, 10_000);
    let mut g = c.benchmark_group("lagrange_basis_1e4_params");
    g.throughput(Throughput::Elements(ts.len() as u64));
    for m in [1, 2, 4, 8, 12, 16, 20] {
        let basis = Lagrange::new(NodePlacement::Uniform.nodes::<f64>(m + 1)).unwrap();
        let mut row = vec![0.0; m + 1];
        g.bench_with_input(BenchmarkId::from_parameter(m), &m, |b, _| {
            b.iter(|| {
                for t in &ts {
                    basis.basis_into(t, black_box(&mut row)).unwrap();
                }
            })
        });
    }
    g.finish();
}

criterion_group! { name = benches; config = config(); targets = basis_rows }
criterion_main!(benches);
