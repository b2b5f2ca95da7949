//! B-spline, NURBS and interpolating-spline batches: the cubic B-spline curve (10 control
//! points) at 10⁴…10⁶ points; the bicubic B-spline surface (10 × 10 net) on N × N grids,
//! N = 10…2000; the degree (p, p), p = 1…20, on a 500 × 500 grid (24 × 24 net: linear in p);
//! a bicubic NURBS surface on 1000 × 1000; an interpolating cubic spline at 10⁶ points. Each
//! group also times the per-point `eval` (span search, basis and a new vector per point) at
//! one size, for the speed-up.

mod common;
use common::config;

use std::hint::black_box;

use cagd::bspline::{BSplineCurve, BSplineSurface, KnotVector};
use cagd::nurbs::NurbsSurface;
use cagd::spline::{CubicSpline, EndCondition};
use cagd::{Curve, Surface};
use cagd_bench::{bspline_surface, per_point_grid};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use nalgebra::DMatrix;

/// Clamped uniform knots on `[0, 1]` for `n` control points of degree `p`.
fn knots(p: usize, n: usize) -> Vec<f64> {
    KnotVector::<f64>::clamped_uniform(p, n)
        .expect("n ≥ p + 1")
        .as_slice()
        .to_vec()
}

/// The `n × n` net of [`bspline_surface`] (one matrix per coordinate).
fn net(n: usize) -> Vec<DMatrix<f64>> {
    bspline_surface(1, n).coordinates().to_vec()
}

/// The B-spline surface of degree `(p, p)` over the `n × n` net, clamped uniform knots.
fn surface(p: usize, n: usize) -> BSplineSurface {
    bspline_surface(p, n)
}

/// The cubic 3-D B-spline curve with 10 control points on a spiral, clamped uniform knots.
fn cubic_curve() -> BSplineCurve {
    let control = DMatrix::from_fn(3, 10, |k, i| {
        let a = i as f64 * 0.7;
        [a.cos(), a.sin(), i as f64 / 9.0][k]
    });
    BSplineCurve::new(3, knots(3, 10), control).expect("valid curve")
}

/// `Curve::eval` point by point into `out`.
fn per_point_curve(c: &impl Curve, ts: &[f64], out: &mut [f64]) {
    for (p, &t) in out.chunks_exact_mut(3).zip(ts) {
        p.copy_from_slice(c.eval(t).as_slice());
    }
}

fn bspline_curve_points(c: &mut Criterion) {
    let curve = cubic_curve();
    let mut g = c.benchmark_group("bspline_cubic_curve_points");
    for k in [10_000, 100_000, 1_000_000] {
        let ts = cagd::linspace(0.0, 1.0, k);
        let mut out = vec![0.0; k * 3];
        g.throughput(Throughput::Elements(k as u64));
        g.bench_with_input(BenchmarkId::new("eval_many_into", k), &k, |b, _| {
            b.iter(|| curve.eval_many_into(&ts, black_box(&mut out)).unwrap())
        });
        if k == 100_000 {
            g.bench_with_input(BenchmarkId::new("eval_per_point", k), &k, |b, _| {
                b.iter(|| per_point_curve(&curve, &ts, black_box(&mut out)))
            });
        }
    }
    g.finish();
}

/// `eval_grid_into` of `s` on `n × n` grids for every `n` in `sizes`, and per-point `eval` at
/// `n = 100` for the speed-up.
fn surface_grid_group(c: &mut Criterion, name: &str, s: &impl Surface, sizes: &[usize]) {
    let mut g = c.benchmark_group(name);
    for &n in sizes {
        let ts = cagd::linspace(0.0, 1.0, n);
        let mut out = vec![0.0; n * n * 3];
        g.throughput(Throughput::Elements((n * n) as u64));
        g.bench_with_input(BenchmarkId::new("eval_grid_into", n), &n, |b, _| {
            b.iter(|| s.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap())
        });
        if n == 100 {
            g.bench_with_input(BenchmarkId::new("eval_per_point", n), &n, |b, _| {
                b.iter(|| {
                    per_point_grid(&ts, &ts, black_box(&mut out), |u, v| {
                        let x = s.eval(u, v);
                        [x[0], x[1], x[2]]
                    })
                })
            });
        }
    }
    g.finish();
}

fn bspline_surface_grid(c: &mut Criterion) {
    let s = surface(3, 10);
    surface_grid_group(c, "bspline_bicubic_10x10_grid", &s, &[10, 100, 1000, 2000]);
}

fn bspline_degree_scaling(c: &mut Criterion) {
    let n = 500;
    let ts = cagd::linspace(0.0, 1.0, n);
    let mut out = vec![0.0; n * n * 3];
    let mut g = c.benchmark_group("bspline_degree_pp_24x24_grid_500x500");
    g.throughput(Throughput::Elements((n * n) as u64));
    for p in [1, 2, 3, 4, 5, 6, 8, 10, 12, 14, 16, 18, 20] {
        let s = surface(p, 24);
        g.bench_with_input(BenchmarkId::from_parameter(p), &p, |b, _| {
            b.iter(|| s.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap())
        });
    }
    g.finish();
}

fn nurbs_surface_grid(c: &mut Criterion) {
    let w = DMatrix::from_fn(10, 10, |i, j| 1.0 + ((i + 2 * j) % 4) as f64 / 3.0);
    let s = NurbsSurface::new(3, 3, knots(3, 10), knots(3, 10), net(10), w).expect("valid");
    surface_grid_group(c, "nurbs_bicubic_10x10_grid", &s, &[100, 1000]);
}

fn interpolating_spline_points(c: &mut Criterion) {
    // A natural cubic spline through 20 points of a 3-D spiral, parameters 0…19.
    let points = DMatrix::from_fn(3, 20, |k, i| {
        let a = i as f64 * 0.5;
        [a.cos(), a.sin(), i as f64 / 19.0][k]
    });
    let s = CubicSpline::interpolate(points, EndCondition::Natural).expect("valid spline");
    let mut g = c.benchmark_group("interpolating_spline_points");
    for k in [100_000, 1_000_000] {
        let ts = cagd::linspace(0.0, 19.0, k);
        let mut out = vec![0.0; k * 3];
        g.throughput(Throughput::Elements(k as u64));
        g.bench_with_input(BenchmarkId::new("eval_many_into", k), &k, |b, _| {
            b.iter(|| s.eval_many_into(&ts, black_box(&mut out)).unwrap())
        });
        if k == 100_000 {
            g.bench_with_input(BenchmarkId::new("eval_per_point", k), &k, |b, _| {
                b.iter(|| per_point_curve(&s, &ts, black_box(&mut out)))
            });
        }
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bspline_curve_points, bspline_surface_grid, bspline_degree_scaling,
        nurbs_surface_grid, interpolating_spline_points
}
criterion_main!(benches);
