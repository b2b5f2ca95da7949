//! One batch kernel of cagd run a fixed number of times, for instruction counts that do not
//! depend on the machine's load (`valgrind --tool=callgrind`) and for profiles:
//!
//! ```text
//! RAYON_NUM_THREADS=1 valgrind --tool=callgrind target/release/kernels CASE ITERATIONS
//! ```
//!
//! The instructions of one call are the difference between two runs with different
//! `ITERATIONS`, divided by the difference. `kernels list` prints the cases. With the
//! environment variable `KERNELS_TIME` set, the best time of one call is printed too.

use std::hint::black_box;

use cagd_bench::{
    arithmetic_floor, bspline_cubic_curve, bspline_surface, cubic_curve, nurbs_cubic_curve,
    nurbs_surface, ops, patch, store_floor,
};

const CASES: &[&str] = &[
    "fill_grid",
    "bezier_patch",
    "bspline_surface",
    "nurbs_surface",
    "fill_curve",
    "bezier_curve",
    "bspline_curve",
    "nurbs_curve",
    "store_grid",
    "arith_bicubic",
    "arith_cubic",
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let case = args.first().map(String::as_str).unwrap_or("list");
    let iterations: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1);
    let n = 1000;
    let k = 1_000_000;
    let grid_ts = cagd::linspace(0.0, 1.0, n);
    let curve_ts = cagd::linspace(0.0, 1.0, k);
    let mut grid = vec![0.0; n * n * 3];
    let mut points = vec![0.0; k * 3];
    let bicubic = patch(3, 3);
    let bs = bspline_surface(3, 10);
    let ns = nurbs_surface(3, 10);
    let bc = cubic_curve();
    let sc = bspline_cubic_curve();
    let nc = nurbs_cubic_curve();
    let timed = std::env::var_os("KERNELS_TIME").is_some();
    let mut best = f64::INFINITY;
    for _ in 0..iterations {
        let start = std::time::Instant::now();
        match case {
            "fill_grid" => black_box(&mut grid).fill(black_box(0.5)),
            "bezier_patch" => bicubic
                .eval_grid_into(&grid_ts, &grid_ts, &mut grid)
                .unwrap(),
            "bspline_surface" => bs.eval_grid_into(&grid_ts, &grid_ts, &mut grid).unwrap(),
            "nurbs_surface" => ns.eval_grid_into(&grid_ts, &grid_ts, &mut grid).unwrap(),
            "fill_curve" => black_box(&mut points).fill(black_box(0.5)),
            "bezier_curve" => bc.eval_many_into(&curve_ts, &mut points).unwrap(),
            "bspline_curve" => sc.eval_many_into(&curve_ts, &mut points).unwrap(),
            "nurbs_curve" => nc.eval_many_into(&curve_ts, &mut points).unwrap(),
            "store_grid" => store_floor(&mut grid),
            "arith_bicubic" => {
                black_box(arithmetic_floor::<{ ops::BICUBIC.0 }, { ops::BICUBIC.1 }>(
                    n * n,
                ));
            }
            "arith_cubic" => {
                black_box(arithmetic_floor::<
                    { ops::CUBIC_CURVE.0 },
                    { ops::CUBIC_CURVE.1 },
                >(k));
            }
            _ => {
                println!("cases: {}", CASES.join(" "));
                return;
            }
        }
        black_box(&mut grid);
        black_box(&mut points);
        best = best.min(start.elapsed().as_secs_f64());
    }
    if timed {
        println!("{case}\t{:.3} ms (best of {iterations})", best * 1e3);
    }
}
