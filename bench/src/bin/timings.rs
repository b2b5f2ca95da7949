//! Timings of cagd for `compare_octave.sh`: one line per case, `case<TAB>seconds` (the best
//! per-call time over several batches), then the accuracy study of de Casteljau vs. the
//! monomial form as `#`-comment lines.
//!
//! `cargo run --release -p cagd-bench --bin timings [--no-accuracy | --accuracy-only]`

use std::hint::black_box;
use std::time::{Duration, Instant};

use cagd_bench::{
    accuracy_study, bicubic_net, bspline_surface, coons_of, cubic_control, cubic_curve, gordon_of,
    hand_bicubic_grid, hand_cubic_curve, patch, per_point_grid, spline_accuracy_study,
};

/// The best time per call of `f`: batches of at least 30 ms (or one call), seven batches
/// (at most about 2 s in all), the fastest batch's time per call.
fn best_of(mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    f();
    let once = start.elapsed().max(Duration::from_nanos(1));
    let per_batch =
        ((Duration::from_millis(30).as_secs_f64() / once.as_secs_f64()).ceil() as usize).max(1);
    let batches = if once > Duration::from_millis(300) {
        3
    } else {
        7
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

fn report(case: &str, seconds: f64) {
    println!("{case}\t{seconds:.6e}");
}

fn main() {
    let accuracy = !std::env::args().any(|a| a == "--no-accuracy");
    if std::env::args().any(|a| a == "--accuracy-only") {
        print_accuracy();
        return;
    }
    let bicubic = patch(3, 3);

    // Bézier patches (into a buffer), the buffer fill, the hand-specialised kernel.
    for n in [30, 100, 1000] {
        let ts = cagd::linspace(0.0, 1.0, n);
        let mut out = vec![0.0; n * n * 3];
        report(
            &format!("patch_bicubic_N{n}"),
            best_of(|| {
                bicubic
                    .eval_grid_into(&ts, &ts, black_box(&mut out))
                    .unwrap()
            }),
        );
    }
    {
        let ts = cagd::linspace(0.0, 1.0, 1000);
        let mut out = vec![0.0; 1000 * 1000 * 3];
        report(
            "fill_N1000",
            best_of(|| black_box(&mut out).fill(black_box(0.5))),
        );
        let net = bicubic_net(&bicubic);
        report(
            "hand_bicubic_N1000",
            best_of(|| hand_bicubic_grid(&net, &ts, &ts, black_box(&mut out))),
        );
    }
    // B-spline surface: bicubic over a 10 × 10 net (clamped uniform knots, 7 × 7 spans).
    {
        let s = bspline_surface(3, 10);
        for n in [100, 1000] {
            let ts = cagd::linspace(0.0, 1.0, n);
            let mut out = vec![0.0; n * n * 3];
            report(
                &format!("bspline_bicubic_N{n}"),
                best_of(|| s.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap()),
            );
        }
    }
    // Degree (10, 10) on 500 × 500, grid path and per-point de Casteljau (on 100 × 100,
    // reported per 500 × 500 grid).
    {
        let p10 = patch(10, 10);
        let ts = cagd::linspace(0.0, 1.0, 500);
        let mut out = vec![0.0; 500 * 500 * 3];
        report(
            "patch_deg10_N500",
            best_of(|| p10.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap()),
        );
        let small = cagd::linspace(0.0, 1.0, 100);
        let mut out = vec![0.0; 100 * 100 * 3];
        let t = best_of(|| {
            per_point_grid(&small, &small, black_box(&mut out), |u, v| {
                let x = p10.eval(u, v);
                [x[0], x[1], x[2]]
            })
        });
        report("patch_deg10_N500_de_casteljau_per_point", t * 25.0);
    }
    // Curves.
    let curve = cubic_curve();
    for k in [10_000, 1_000_000] {
        let ts = cagd::linspace(0.0, 1.0, k);
        let mut out = vec![0.0; k * 3];
        report(
            &format!("curve_cubic_K{k}"),
            best_of(|| curve.eval_many_into(&ts, black_box(&mut out)).unwrap()),
        );
    }
    {
        let ts = cagd::linspace(0.0, 1.0, 1_000_000);
        let mut out = vec![0.0; ts.len() * 3];
        report(
            "fill_K1000000",
            best_of(|| black_box(&mut out).fill(black_box(0.5))),
        );
        let ctrl = cubic_control(&curve);
        report(
            "hand_curve_cubic_K1000000",
            best_of(|| hand_cubic_curve(&ctrl, &ts, black_box(&mut out))),
        );
    }
    // Coons and Gordon.
    let coons = coons_of(&bicubic);
    let gordon = gordon_of(&bicubic);
    for n in [20, 50, 100, 300, 1000] {
        let ts = cagd::linspace(0.0, 1.0, n);
        let mut out = vec![0.0; n * n * 3];
        report(
            &format!("coons_N{n}"),
            best_of(|| coons.eval_grid_into(&ts, &ts, black_box(&mut out)).unwrap()),
        );
        report(
            &format!("gordon_N{n}"),
            best_of(|| {
                gordon
                    .eval_grid_into(&ts, &ts, black_box(&mut out))
                    .unwrap()
            }),
        );
    }

    if accuracy {
        print_accuracy();
    }
}

/// The accuracy studies, as `#`-comment lines.
fn print_accuracy() {
    println!("# accuracy: max |error| against exact rationals, control values in [-1, 1]");
    println!("# (20 random curves x 50 parameters in [0, 1] per degree)");
    println!("# degree\tde_casteljau\tbasis_rows\tmonomial_form");
    for row in accuracy_study(&[10, 20, 30, 40], 20, 50) {
        println!(
            "# {}\t{:.2e}\t{:.2e}\t{:.2e}",
            row.degree, row.de_casteljau, row.basis_rows, row.monomial
        );
    }
    println!("# B-spline and NURBS curve batches: max |error| against exact rationals,");
    println!("# in units of eps * max |P| (10 random 3-D curves x 50 parameters per degree)");
    println!("# degree\tbspline_fast\tbspline_exact_order\tnurbs_fast\tnurbs_exact_order\tbounds");
    for row in spline_accuracy_study(&[1, 2, 3, 5, 8], 10, 50) {
        println!(
            "# {}\t{:.2}\t{:.2}\t{:.2}\t{:.2}\t{}, {}",
            row.degree,
            row.bspline_fast,
            row.bspline_exact_order,
            row.nurbs_fast,
            row.nurbs_exact_order,
            4 * row.degree + 1,
            7 * row.degree + 3
        );
    }
}
