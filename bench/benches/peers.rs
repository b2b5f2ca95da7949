//! Side by side, in one run: a 1000 × 1000 bicubic grid and 10⁶ points of a cubic 3-D curve,
//! written into the same buffer by: filling the buffer once (the memory floor), cagd, a
//! hand-specialised f64 kernel, truck-geometry (`BSplineSurface::subs` / `BSplineCurve::subs`
//! per point) and curvo (`point_at` per point), all on the same control points — every group
//! twice, on a rayon pool of one thread (`…/1_thread`) and of all threads (`…/N_threads`: cagd
//! and the hand kernel split rows as they do, the peers' per-point calls run under rayon as a
//! user would write it). The floors and the targets: `bash bench/ratios.sh`.

mod common;
use common::config;

use std::hint::black_box;

use cagd_bench::{
    bicubic_net, cubic_control, cubic_curve, hand_bicubic_grid, hand_cubic_curve, patch,
    per_point_grid,
};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use curvo::prelude::{NurbsCurve3D, NurbsSurface3D};
use nalgebra35::Point4;
use rayon::prelude::*;
use truck_geometry::prelude::{
    BSplineCurve, BSplineSurface, KnotVec, ParametricCurve, ParametricSurface, Point3,
};

/// The pools the groups run on: one thread and all threads, with their names.
fn pools() -> Vec<(rayon::ThreadPool, String)> {
    let all = std::thread::available_parallelism().map_or(1, |n| n.get());
    [1, all]
        .into_iter()
        .map(|n| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .expect("thread pool");
            let name = if n == 1 {
                "1_thread".to_string()
            } else {
                format!("{n}_threads")
            };
            (pool, name)
        })
        .collect()
}

fn bicubic_1000(c: &mut Criterion) {
    let p = patch(3, 3);
    let net = bicubic_net(&p);
    let n = 1000;
    let ts = cagd::linspace(0.0, 1.0, n);
    let mut out = vec![0.0; n * n * 3];
    let truck = BSplineSurface::new(
        (KnotVec::bezier_knot(3), KnotVec::bezier_knot(3)),
        net.iter()
            .map(|row| row.iter().map(|b| Point3::new(b[0], b[1], b[2])).collect())
            .collect(),
    );
    let bezier_knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let curvo = NurbsSurface3D::<f64>::new(
        3,
        3,
        bezier_knots.clone(),
        bezier_knots,
        net.iter()
            .map(|row| {
                row.iter()
                    .map(|b| Point4::new(b[0], b[1], b[2], 1.0))
                    .collect()
            })
            .collect(),
    );
    // The peers agree with cagd (same surface).
    let x = p.eval(0.3, 0.7);
    let t = truck.subs(0.3, 0.7);
    let q = curvo.point_at(0.3, 0.7);
    assert!((t.x - x[0]).abs() + (t.y - x[1]).abs() + (t.z - x[2]).abs() < 1e-12);
    assert!((q.x - x[0]).abs() + (q.y - x[1]).abs() + (q.z - x[2]).abs() < 1e-12);

    for (pool, threads) in pools() {
        let parallel = pool.current_num_threads() > 1;
        // The peers per point, row by row; on several threads the rows under rayon.
        let per_point = |out: &mut [f64], f: &(dyn Fn(f64, f64) -> [f64; 3] + Sync)| {
            if parallel {
                out.par_chunks_mut(n * 3).zip(&ts).for_each(|(row, &u)| {
                    per_point_grid(&[u], &ts, row, f);
                });
            } else {
                per_point_grid(&ts, &ts, out, f);
            }
        };
        let mut g = c.benchmark_group(format!("bicubic_grid_1000x1000/{threads}"));
        g.throughput(Throughput::Elements((n * n) as u64));
        {
            g.bench_function("fill_buffer", |b| {
                b.iter(|| pool.install(|| cagd_bench::fill_floor_all(black_box(&mut out))))
            });
            g.bench_function("cagd_eval_grid_into", |b| {
                b.iter(|| pool.install(|| p.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap()))
            });
            g.bench_function("hand_specialised_f64", |b| {
                b.iter(|| pool.install(|| hand_bicubic_grid(&net, &ts, &ts, black_box(&mut out))))
            });
            g.bench_function("truck_subs_per_point", |b| {
                b.iter(|| {
                    pool.install(|| {
                        per_point(black_box(&mut out), &|u, v| {
                            let q = truck.subs(u, v);
                            [q.x, q.y, q.z]
                        })
                    })
                })
            });
            g.bench_function("curvo_point_at_per_point", |b| {
                b.iter(|| {
                    pool.install(|| {
                        per_point(black_box(&mut out), &|u, v| {
                            let q = curvo.point_at(u, v);
                            [q.x, q.y, q.z]
                        })
                    })
                })
            });
        }
        g.finish();
    }
}

fn cubic_curve_1e6(c: &mut Criterion) {
    let curve = cubic_curve();
    let ctrl = cubic_control(&curve);
    let k = 1_000_000;
    let ts = cagd::linspace(0.0, 1.0, k);
    let mut out = vec![0.0; k * 3];
    let truck = BSplineCurve::new(
        KnotVec::bezier_knot(3),
        ctrl.iter().map(|b| Point3::new(b[0], b[1], b[2])).collect(),
    );
    let curvo = NurbsCurve3D::<f64>::try_new(
        3,
        ctrl.iter()
            .map(|b| Point4::new(b[0], b[1], b[2], 1.0))
            .collect(),
        vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
    )
    .unwrap();
    let x = curve.eval(0.3);
    let (t, q) = (truck.subs(0.3), curvo.point_at(0.3));
    assert!((t.x - x[0]).abs() + (t.y - x[1]).abs() + (t.z - x[2]).abs() < 1e-12);
    assert!((q.x - x[0]).abs() + (q.y - x[1]).abs() + (q.z - x[2]).abs() < 1e-12);

    for (pool, threads) in pools() {
        let parallel = pool.current_num_threads() > 1;
        // Per point; on several threads every point a rayon item.
        let each = |out: &mut [f64], f: &(dyn Fn(f64) -> [f64; 3] + Sync)| {
            if parallel {
                out.par_chunks_mut(3)
                    .zip(&ts)
                    .for_each(|(p, &t)| p.copy_from_slice(&f(t)));
            } else {
                for (p, &t) in out.chunks_exact_mut(3).zip(&ts) {
                    p.copy_from_slice(&f(t));
                }
            }
        };
        let mut g = c.benchmark_group(format!("cubic_curve_1e6_points/{threads}"));
        g.throughput(Throughput::Elements(k as u64));
        {
            g.bench_function("fill_buffer", |b| {
                b.iter(|| pool.install(|| cagd_bench::fill_floor_all(black_box(&mut out))))
            });
            g.bench_function("cagd_eval_many_into", |b| {
                b.iter(|| pool.install(|| curve.eval_many_into(&ts, black_box(&mut out)).unwrap()))
            });
            g.bench_function("hand_specialised_f64", |b| {
                b.iter(|| pool.install(|| hand_cubic_curve(&ctrl, &ts, black_box(&mut out))))
            });
            g.bench_function("cagd_de_casteljau_per_point", |b| {
                b.iter(|| {
                    pool.install(|| {
                        each(black_box(&mut out), &|t| {
                            let x = curve.eval(t);
                            [x[0], x[1], x[2]]
                        })
                    })
                })
            });
            g.bench_function("truck_subs_per_point", |b| {
                b.iter(|| {
                    pool.install(|| {
                        each(black_box(&mut out), &|t| {
                            let q = truck.subs(t);
                            [q.x, q.y, q.z]
                        })
                    })
                })
            });
            g.bench_function("curvo_point_at_per_point", |b| {
                b.iter(|| {
                    pool.install(|| {
                        each(black_box(&mut out), &|t| {
                            let q = curvo.point_at(t);
                            [q.x, q.y, q.z]
                        })
                    })
                })
            });
        }
        g.finish();
    }
}

criterion_group! { name = benches; config = config(); targets = bicubic_1000, cubic_curve_1e6 }
criterion_main!(benches);
