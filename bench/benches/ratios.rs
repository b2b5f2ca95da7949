//! The benchmark bar of `bench/ratios.sh`: in one run, on one thread and on all threads of the
//! machine, the two floors (the buffer written once; the same multiplications and additions
//! at the vector width, without memory), cagd, and truck-geometry and curvo evaluating point
//! by point (on all threads: their per-point calls under rayon, as a user would write it), for
//! a 1000 × 1000 bicubic grid and 10⁶ points of a cubic 3-D curve; then the B-spline and NURBS
//! batches against the Bézier batch of the same degree and size. Prints the tables and the
//! targets, and exits with status 1 if a target is missed.
//!
//! `cargo bench -p cagd-bench --bench ratios` (a plain `main`, no criterion). Times are the
//! best per-call time of several batches of calls (each batch at least 20 ms).

use std::hint::black_box;
use std::time::{Duration, Instant};

use cagd::{Curve, Surface};
use cagd_bench::{
    arithmetic_floor, arithmetic_floor_all, bicubic_net, bspline_cubic_curve, bspline_surface,
    cubic_control, cubic_curve, fill_floor, fill_floor_all, nurbs_cubic_curve, nurbs_surface, ops,
    patch, store_floor, store_floor_all,
};
use curvo::prelude::{NurbsCurve3D, NurbsSurface3D};
use nalgebra35::Point4;
use rayon::prelude::*;
use rayon::ThreadPool;
use truck_geometry::prelude::{
    BSplineCurve, BSplineSurface, KnotVec, ParametricCurve, ParametricSurface, Point3,
};

/// Targets of the bar.
const FLOOR_TARGET: f64 = 1.5;
const PEER_TARGET: f64 = 50.0;
const PEER_FLOOR_TARGET: f64 = 1.2;
const SPEEDUP_TARGET: f64 = 1.7;
const SPLINE_TARGET: f64 = 2.0;

/// The best time per call of `f` in seconds: batches of at least 20 ms (at least one call),
/// `batches` of them, the fastest batch's time per call.
fn best_of(batches: usize, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    f();
    let once = start.elapsed().max(Duration::from_nanos(1));
    let per_batch = ((0.02 / once.as_secs_f64()).ceil() as usize).max(1);
    let batches = if once > Duration::from_millis(200) {
        batches.min(3)
    } else {
        batches
    };
    let mut best = f64::INFINITY;
    for _ in 0..batches {
        let start = Instant::now();
        for _ in 0..per_batch {
            f();
        }
        best = best.min(start.elapsed().as_secs_f64() / per_batch as f64);
    }
    best
}

fn ms(s: f64) -> String {
    format!("{:.3} ms", s * 1e3)
}

/// One line of the floors-and-peers table.
struct Line {
    case: &'static str,
    threads: usize,
    fill: f64,
    stores: f64,
    arith: f64,
    cagd: f64,
    truck: f64,
    curvo: f64,
}

impl Line {
    fn floor(&self) -> f64 {
        self.fill.max(self.arith)
    }
}

/// The two pools: one thread, and all threads of the machine.
fn pools() -> (ThreadPool, ThreadPool, usize) {
    let all = std::thread::available_parallelism().map_or(1, |n| n.get());
    let build = |n| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .expect("thread pool")
    };
    (build(1), build(all), all)
}

fn bicubic(pool: &ThreadPool, threads: usize, batches: usize) -> Line {
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
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let curvo = NurbsSurface3D::<f64>::new(
        3,
        3,
        knots.clone(),
        knots,
        net.iter()
            .map(|row| {
                row.iter()
                    .map(|b| Point4::new(b[0], b[1], b[2], 1.0))
                    .collect()
            })
            .collect(),
    );
    let x = p.eval(0.3, 0.7);
    let (t, q) = (truck.subs(0.3, 0.7), curvo.point_at(0.3, 0.7));
    assert!((t.x - x[0]).abs() + (t.y - x[1]).abs() + (t.z - x[2]).abs() < 1e-12);
    assert!((q.x - x[0]).abs() + (q.y - x[1]).abs() + (q.z - x[2]).abs() < 1e-12);
    // Per point, row by row; on all threads the rows under rayon.
    let per_point = |out: &mut [f64], f: &(dyn Fn(f64, f64) -> [f64; 3] + Sync)| {
        let row = |(r, &u): (&mut [f64], &f64)| {
            for (x, &v) in r.chunks_exact_mut(3).zip(&ts) {
                x.copy_from_slice(&f(u, v));
            }
        };
        if threads == 1 {
            out.chunks_mut(n * 3).zip(&ts).for_each(row);
        } else {
            out.par_chunks_mut(n * 3).zip(&ts).for_each(row);
        }
    };
    let (m, a) = ops::BICUBIC;
    assert_eq!((m, a), (12, 9));
    pool.install(|| Line {
        case: "bicubic 1000²",
        threads,
        fill: best_of(batches, || {
            if threads == 1 {
                fill_floor(&mut out)
            } else {
                fill_floor_all(&mut out)
            }
        }),
        stores: best_of(batches, || {
            if threads == 1 {
                store_floor(&mut out)
            } else {
                store_floor_all(&mut out)
            }
        }),
        arith: best_of(batches, || {
            black_box(if threads == 1 {
                arithmetic_floor::<12, 9>(n * n)
            } else {
                arithmetic_floor_all::<12, 9>(n * n)
            });
        }),
        cagd: best_of(batches, || {
            p.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap()
        }),
        truck: best_of(batches, || {
            per_point(&mut out, &|u, v| {
                let q = truck.subs(u, v);
                [q.x, q.y, q.z]
            })
        }),
        curvo: best_of(batches, || {
            per_point(&mut out, &|u, v| {
                let q = curvo.point_at(u, v);
                [q.x, q.y, q.z]
            })
        }),
    })
}

fn cubic(pool: &ThreadPool, threads: usize, batches: usize) -> Line {
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
    // Per point; on all threads every point a rayon item (rayon splits them adaptively).
    let per_point = |out: &mut [f64], f: &(dyn Fn(f64) -> [f64; 3] + Sync)| {
        if threads == 1 {
            for (x, &t) in out.chunks_exact_mut(3).zip(&ts) {
                x.copy_from_slice(&f(t));
            }
        } else {
            out.par_chunks_mut(3)
                .zip(&ts)
                .for_each(|(x, &t)| x.copy_from_slice(&f(t)));
        }
    };
    let (m, a) = ops::CUBIC_CURVE;
    assert_eq!((m, a), (22, 10));
    pool.install(|| Line {
        case: "cubic curve 10⁶",
        threads,
        fill: best_of(batches, || {
            if threads == 1 {
                fill_floor(&mut out)
            } else {
                fill_floor_all(&mut out)
            }
        }),
        stores: best_of(batches, || {
            if threads == 1 {
                store_floor(&mut out)
            } else {
                store_floor_all(&mut out)
            }
        }),
        arith: best_of(batches, || {
            black_box(if threads == 1 {
                arithmetic_floor::<22, 10>(k)
            } else {
                arithmetic_floor_all::<22, 10>(k)
            });
        }),
        cagd: best_of(batches, || {
            curve.eval_many_into(&ts, black_box(&mut out)).unwrap()
        }),
        truck: best_of(batches, || {
            per_point(&mut out, &|t| {
                let q = truck.subs(t);
                [q.x, q.y, q.z]
            })
        }),
        curvo: best_of(batches, || {
            per_point(&mut out, &|t| {
                let q = curvo.point_at(t);
                [q.x, q.y, q.z]
            })
        }),
    })
}

/// One line of the spline table: Bézier, B-spline and NURBS batches of the same degree and
/// size, and the B-spline exact-order curve batch.
struct SplineLine {
    case: &'static str,
    threads: usize,
    bezier: f64,
    bspline: f64,
    nurbs: f64,
    exact_order: Option<(f64, f64)>,
}

fn splines(pool: &ThreadPool, threads: usize, batches: usize) -> [SplineLine; 2] {
    let n = 1000;
    let grid_ts = cagd::linspace(0.0, 1.0, n);
    let mut grid = vec![0.0; n * n * 3];
    let k = 1_000_000;
    let ts = cagd::linspace(0.0, 1.0, k);
    let mut points = vec![0.0; k * 3];
    let (bp, bs, ns) = (patch(3, 3), bspline_surface(3, 10), nurbs_surface(3, 10));
    let (bc, sc, nc) = (cubic_curve(), bspline_cubic_curve(), nurbs_cubic_curve());
    pool.install(|| {
        let mut grid_time = |s: &dyn Surface| {
            best_of(batches, || {
                s.eval_grid_into(&grid_ts, &grid_ts, black_box(&mut grid))
                    .unwrap()
            })
        };
        let surfaces = SplineLine {
            case: "bicubic surface 1000²",
            threads,
            bezier: grid_time(&bp),
            bspline: grid_time(&bs),
            nurbs: grid_time(&ns),
            exact_order: None,
        };
        let mut curve_time = |c: &dyn Curve| {
            best_of(batches, || {
                c.eval_many_into(&ts, black_box(&mut points)).unwrap()
            })
        };
        let (bezier, bspline, nurbs) = (curve_time(&bc), curve_time(&sc), curve_time(&nc));
        let exact_b = best_of(batches, || {
            sc.eval_many_exact_order_into(&ts, black_box(&mut points))
                .unwrap()
        });
        let exact_n = best_of(batches, || {
            nc.eval_many_exact_order_into(&ts, black_box(&mut points))
                .unwrap()
        });
        [
            surfaces,
            SplineLine {
                case: "cubic curve 10⁶",
                threads,
                bezier,
                bspline,
                nurbs,
                exact_order: Some((exact_b, exact_n)),
            },
        ]
    })
}

/// A target and whether it is met.
struct Check {
    what: String,
    met: bool,
}

fn main() {
    // `cargo bench` passes `--bench`; `--quick` runs fewer batches.
    let quick = std::env::args().any(|a| a == "--quick");
    let batches = if quick { 3 } else { 7 };
    let (one, all, cores) = pools();
    let mut lines = Vec::new();
    for (pool, threads) in [(&one, 1), (&all, cores)] {
        lines.push(bicubic(pool, threads, batches));
        lines.push(cubic(pool, threads, batches));
    }
    lines.sort_by_key(|l| (l.case, l.threads));
    let mut spline_lines = Vec::new();
    for (pool, threads) in [(&one, 1), (&all, cores)] {
        spline_lines.extend(splines(pool, threads, batches));
    }

    println!("Floors, cagd and the peers (best time per call; floor = the higher of fill and");
    println!("arithmetic; the peers per point; on {cores} threads the peers' calls under rayon):");
    println!();
    println!(
        "| case | threads | fill | stores | arithmetic | cagd | cagd / floor | truck | truck / cagd | curvo | curvo / cagd |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for l in &lines {
        println!(
            "| {} | {} | {} | {} | {} | **{}** | {:.2}× | {} | {:.0}× | {} | {:.0}× |",
            l.case,
            l.threads,
            ms(l.fill),
            ms(l.stores),
            ms(l.arith),
            ms(l.cagd),
            l.cagd / l.floor(),
            ms(l.truck),
            l.truck / l.cagd,
            ms(l.curvo),
            l.curvo / l.cagd,
        );
    }
    println!();
    println!("B-spline and NURBS batches against the Bézier batch of the same degree and size");
    println!("(bicubic 10 × 10 nets, 7 × 7 spans; cubic curves with 10 control points, 7 spans):");
    println!();
    println!(
        "| case | threads | Bézier | B-spline | B-spline / Bézier | NURBS | NURBS / Bézier | exact order (B-spline, NURBS) |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for l in &spline_lines {
        let exact = l
            .exact_order
            .map_or("—".to_string(), |(b, n)| format!("{}, {}", ms(b), ms(n)));
        println!(
            "| {} | {} | {} | {} | {:.2}× | {} | {:.2}× | {} |",
            l.case,
            l.threads,
            ms(l.bezier),
            ms(l.bspline),
            l.bspline / l.bezier,
            ms(l.nurbs),
            l.nurbs / l.bezier,
            exact
        );
    }

    // The targets.
    let mut checks = Vec::new();
    for l in lines.iter().filter(|l| l.threads == 1) {
        checks.push(Check {
            what: format!(
                "{}, 1 thread: cagd within {FLOOR_TARGET}× of the higher floor ({:.2}×)",
                l.case,
                l.cagd / l.floor()
            ),
            met: l.cagd <= FLOOR_TARGET * l.floor(),
        });
        for (peer, t) in [("truck", l.truck), ("curvo", l.curvo)] {
            // Where 50× the peer's speed lies beyond the floors, within 1.2× of the floor.
            let reachable = t / PEER_TARGET >= l.floor();
            let met = if reachable {
                t / l.cagd >= PEER_TARGET
            } else {
                t / l.cagd >= PEER_TARGET || l.cagd <= PEER_FLOOR_TARGET * l.floor()
            };
            checks.push(Check {
                what: format!(
                    "{}, 1 thread vs 1 thread: ≥ {PEER_TARGET}× {peer} ({:.0}×){}",
                    l.case,
                    t / l.cagd,
                    if reachable {
                        String::new()
                    } else {
                        format!(
                            " or, 50× being beyond the floor, within {PEER_FLOOR_TARGET}× of it ({:.2}×)",
                            l.cagd / l.floor()
                        )
                    }
                ),
                met,
            });
        }
    }
    if cores > 1 {
        for case in ["bicubic 1000²", "cubic curve 10⁶"] {
            let single = lines.iter().find(|l| l.case == case && l.threads == 1);
            let multi = lines.iter().find(|l| l.case == case && l.threads == cores);
            if let (Some(s), Some(m)) = (single, multi) {
                let speedup = s.cagd / m.cagd;
                // Where the all-core floor itself forbids 1.7×, within 1.5× of that floor.
                let allowed = s.cagd / m.floor() >= SPEEDUP_TARGET;
                let met =
                    speedup >= SPEEDUP_TARGET || (!allowed && m.cagd <= FLOOR_TARGET * m.floor());
                checks.push(Check {
                    what: format!(
                        "{case}: {cores} threads ≥ {SPEEDUP_TARGET}× faster than 1 ({speedup:.2}×){}",
                        if allowed {
                            String::new()
                        } else {
                            format!(
                                "; the {cores}-thread floor allows only {:.2}×, cagd is {:.2}× of it",
                                s.cagd / m.floor(),
                                m.cagd / m.floor()
                            )
                        }
                    ),
                    met,
                });
            }
        }
    }
    for l in spline_lines.iter().filter(|l| l.threads == 1) {
        for (what, t) in [("B-spline", l.bspline), ("NURBS", l.nurbs)] {
            checks.push(Check {
                what: format!(
                    "{}, 1 thread: {what} within {SPLINE_TARGET}× of Bézier ({:.2}×)",
                    l.case,
                    t / l.bezier
                ),
                met: t <= SPLINE_TARGET * l.bezier,
            });
        }
    }
    println!();
    println!("Targets:");
    for c in &checks {
        println!("- [{}] {}", if c.met { "met" } else { "MISSED" }, c.what);
    }
    let missed = checks.iter().filter(|c| !c.met).count();
    if missed > 0 {
        println!();
        println!("{missed} target(s) missed");
        std::process::exit(1);
    }
}
