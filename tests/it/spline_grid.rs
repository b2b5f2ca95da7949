//! Batch evaluation of B-spline, NURBS and interpolating-spline curves and surfaces
//! (`eval_many_into`, `eval_grid_into`, `eval_grid`) against their per-point `eval`.
//!
//! The exact-order curve batches (`eval_many_exact_order_into`, and the interpolating spline's
//! `eval_many_into`) do the same operations as `eval` and must agree bit for bit; the fast
//! curve batches (`eval_many_into` of B-spline and NURBS curves, reciprocals per span) stay
//! within their stated bound of the exact rational value; surfaces sum along `u` first where
//! `eval` sums along `v` first, so they agree to a few `(p + q) ε` times the size of the
//! control net in `f64`. In rationals everything agrees exactly. The data are random:
//! degrees 0…5, non-uniform knots with repeated interior knots (up to a discontinuity),
//! clamped and unclamped knot vectors, parameters at every knot, at and beyond both ends of
//! the domain, sorted and shuffled; NaN and ±∞ are refused by every batch.

use cagd::bspline::{basis_functions, find_span, BSplineCurve, BSplineSurface};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::spline::{CubicSpline, EndCondition};
use cagd::{Curve, Error, Scalar, Surface};
use nalgebra::{DMatrix, DVector};
use num_rational::BigRational as Q;

use cagd_test_support as common;
use common::lcg::Lcg;

/// A random knot vector for `n` control points of degree `p`: clamped or not, non-uniform,
/// interior knots repeated up to `p + 1` times, domain `[u_p, u_n]` of positive length.
fn random_knots(rng: &mut Lcg, p: usize, n: usize, clamped: bool) -> Vec<f64> {
    let total = n + p + 1;
    let (a, b) = (rng.signed() * 2.0, 0.0);
    let b = a + 0.5 + 3.0 * rng.next() + b;
    loop {
        let mut k: Vec<f64> = Vec::with_capacity(total);
        let inner = if clamped { total - 2 * (p + 1) } else { total };
        let mut run = 0;
        for _ in 0..inner {
            // Repeat the previous knot now and then (multiplicity at most p + 1).
            if !k.is_empty() && run < p + 1 && rng.next() < 0.3 {
                k.push(*k.last().unwrap());
                run += 1;
            } else {
                let lo = if clamped { a } else { a - 1.0 };
                let hi = if clamped { b } else { b + 1.0 };
                k.push(lo + (hi - lo) * rng.next());
                run = 1;
            }
        }
        k.sort_by(|x, y| x.partial_cmp(y).unwrap());
        if clamped {
            let mut full = vec![a; p + 1];
            full.extend(k);
            full.extend(std::iter::repeat_n(b, p + 1));
            k = full;
        }
        // Interior multiplicity may have grown by sorting; cap it by skipping such vectors.
        let too_many = k
            .windows(p + 2)
            .enumerate()
            .any(|(i, w)| w[0] == w[p + 1] && i > 0 && i + p + 2 < k.len());
        if k[p] < k[n] && !too_many {
            return k;
        }
    }
}

/// Parameters for a spline over `[lo, hi]` with knots `knots`: every knot, both ends, points
/// beyond both ends, random ones, and (with `specials`) far beyond both ends and the first
/// end once more, out of order; sorted before the specials. (NaN and ±∞ are refused by every
/// batch: [`batches_refuse_non_finite_parameters`].)
fn params_for(rng: &mut Lcg, knots: &[f64], lo: f64, hi: f64, specials: bool) -> Vec<f64> {
    let w = hi - lo;
    let mut ts: Vec<f64> = knots.to_vec();
    ts.extend([
        lo,
        hi,
        lo - 0.25 * w,
        hi + 0.25 * w,
        lo - 1e-300,
        hi + 1e-12,
    ]);
    ts.extend((0..40).map(|_| lo - 0.1 * w + 1.2 * w * rng.next()));
    ts.sort_by(|x, y| x.partial_cmp(y).unwrap());
    if specials {
        ts.extend([hi + 1e3 * w, lo - 1e3 * w, lo]);
    }
    ts
}

/// Bit-for-bit equality, NaN equal to NaN (and `-0.0` to `0.0`).
fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

/// Checks a batch of curve points against `eval` at each parameter, bit for bit.
fn check_curve_bits<C: Curve>(what: &str, c: &C, ts: &[f64]) {
    check_batch_bits(what, c, ts, |ts, out| c.eval_many_into(ts, out));
}

/// Checks the batch `batch` of `c` against `eval` at each parameter, bit for bit.
fn check_batch_bits<C: Curve>(
    what: &str,
    c: &C,
    ts: &[f64],
    batch: impl Fn(&[f64], &mut [f64]) -> Result<(), Error>,
) {
    let d = c.dim();
    let mut out = vec![f64::NAN; ts.len() * d];
    batch(ts, &mut out).unwrap();
    for (t, x) in ts.iter().zip(out.chunks_exact(d)) {
        let e = c.eval(*t);
        assert!(
            x.iter().zip(e.iter()).all(|(a, b)| same(*a, *b)),
            "{what} at t = {t:e}: batch {x:?}, eval {:?}",
            e.as_slice()
        );
    }
}

/// The largest difference between a grid and `eval`, in units of `ε · scale(u, v, eval)`;
/// NaN must match.
fn grid_error<S: Surface>(
    what: &str,
    s: &S,
    us: &[f64],
    vs: &[f64],
    out: &[f64],
    scale: impl Fn(f64, f64, &DVector<f64>) -> f64,
) -> f64 {
    let d = s.dim();
    let mut worst: f64 = 0.0;
    for (a, u) in us.iter().enumerate() {
        for (b, v) in vs.iter().enumerate() {
            let e = s.eval(*u, *v);
            let x = &out[(a * vs.len() + b) * d..][..d];
            for k in 0..d {
                if e[k].is_nan() || x[k].is_nan() {
                    assert!(
                        e[k].is_nan() && x[k].is_nan(),
                        "{what} at ({u:e}, {v:e}): grid {x:?}, eval {:?}",
                        e.as_slice()
                    );
                    continue;
                }
                worst = worst.max((x[k] - e[k]).abs() / (f64::EPSILON * scale(*u, *v, &e)));
            }
        }
    }
    worst
}

/// `Σ_i |N_{i,p}(t)|` over the piece that gives the point at `t`: 1 in the domain (the basis
/// is non-negative and sums to one there), more where an end piece is continued beyond it.
fn basis_magnitude(p: usize, knots: &[f64], t: f64) -> f64 {
    let n = knots.len() - p - 1;
    let s = find_span(p, n, knots, &t.clamp(knots[p], knots[n])).unwrap();
    basis_functions(p, knots, s, &t)
        .unwrap()
        .iter()
        .map(|x| x.abs())
        .sum()
}

fn random_control(rng: &mut Lcg, d: usize, n: usize) -> DMatrix<f64> {
    DMatrix::from_fn(d, n, |_, _| 10.0 * rng.signed())
}

/// The exact-order batches of a B-spline curve and of a NURBS curve against `eval`.
fn check_exact_order_bits(what: &str, c: &BSplineCurve, r: &NurbsCurve, ts: &[f64]) {
    check_batch_bits(&format!("B-spline {what}"), c, ts, |ts, out| {
        c.eval_many_exact_order_into(ts, out)
    });
    check_batch_bits(&format!("NURBS {what}"), r, ts, |ts, out| {
        r.eval_many_exact_order_into(ts, out)
    });
}

#[test]
fn bspline_and_nurbs_exact_order_batches_equal_eval_bit_for_bit() {
    let mut rng = Lcg(11);
    let mut cases = 0;
    for p in 0..=5 {
        for extra in [0, 1, 3, 7] {
            for clamped in [true, false] {
                for d in [1, 2, 3, 4, 6] {
                    let n = p + 1 + extra;
                    let knots = random_knots(&mut rng, p, n, clamped);
                    let c = BSplineCurve::new(p, knots.clone(), random_control(&mut rng, d, n))
                        .unwrap();
                    let (lo, hi) = c.domain();
                    let mut ts = params_for(&mut rng, &knots, lo, hi, true);
                    let weights: Vec<f64> = (0..n).map(|_| 0.25 + 2.0 * rng.next()).collect();
                    let r = NurbsCurve::new(p, knots, c.control().clone(), weights).unwrap();
                    check_exact_order_bits(&format!("p={p} n={n} d={d}"), &c, &r, &ts);
                    rng.shuffle(&mut ts);
                    check_exact_order_bits(&format!("p={p} n={n} d={d} shuffled"), &c, &r, &ts);
                    cases += 1;
                }
            }
        }
    }
    assert_eq!(cases, 6 * 4 * 2 * 5);
}

#[test]
fn inherent_eval_many_is_try_eval_and_refuses_parameters_outside_the_domain() {
    let mut rng = Lcg(5);
    let knots = vec![0.0, 0.0, 0.0, 0.25, 0.25, 0.7, 1.0, 1.0, 1.0];
    let c = BSplineCurve::new(2, knots.clone(), random_control(&mut rng, 3, 6)).unwrap();
    let ts = params_for(&mut rng, &knots, 0.0, 1.0, false);
    let inside: Vec<f64> = ts
        .iter()
        .copied()
        .filter(|t| (0.0..=1.0).contains(t))
        .collect();
    let m = c.eval_many(&inside).unwrap();
    for (k, t) in inside.iter().enumerate() {
        assert_eq!(m.column(k), c.try_eval(*t).unwrap(), "t = {t}");
    }
    let r = NurbsCurve::from_bspline(&c);
    let mut out = vec![7.0; 3 * 3];
    for bad in [1.5, -1e-300, f64::NAN, f64::INFINITY] {
        let us = [0.5, bad, 0.25];
        for err in [
            c.eval_many(&us).unwrap_err(),
            c.try_eval_many_into(&us, &mut out).unwrap_err(),
            r.try_eval_many_into(&us, &mut out).unwrap_err(),
        ] {
            // Finite parameters outside the domain are out of range; NaN and ±∞ are refused
            // as non-finite (the rule of cagd::param).
            if bad.is_finite() {
                assert!(
                    matches!(
                        err,
                        Error::ParameterOutOfRange {
                            min: 0.0,
                            max: 1.0,
                            ..
                        }
                    ),
                    "{bad}: {err:?}"
                );
            } else {
                assert!(matches!(err, Error::NonFinite { .. }), "{bad}: {err:?}");
            }
        }
        assert_eq!(out, vec![7.0; 9], "nothing is written on error");
    }
    r.try_eval_many_into(&[0.0, 0.3, 1.0], &mut out).unwrap();
    for (k, t) in [0.0, 0.3, 1.0].iter().enumerate() {
        assert_eq!(&out[3 * k..3 * k + 3], r.try_eval(*t).unwrap().as_slice());
    }
}

#[test]
fn bspline_and_nurbs_surface_grids_agree_with_eval() {
    let mut rng = Lcg(23);
    let mut worst_b: f64 = 0.0;
    let mut worst_n: f64 = 0.0;
    for (p, q) in [
        (0, 0),
        (0, 3),
        (1, 1),
        (2, 1),
        (1, 4),
        (3, 3),
        (2, 5),
        (5, 2),
        (4, 4),
        (5, 5),
    ] {
        for (clamped, d) in [(true, 1), (false, 3), (true, 3), (false, 5)] {
            let (nu, nv) = (p + 1 + rng.below(6), q + 1 + rng.below(6));
            let ku = random_knots(&mut rng, p, nu, clamped);
            let kv = random_knots(&mut rng, q, nv, !clamped);
            let coords: Vec<DMatrix<f64>> = (0..d)
                .map(|_| DMatrix::from_fn(nu, nv, |_, _| 10.0 * rng.signed()))
                .collect();
            let scale = coords.iter().map(|c| c.amax()).fold(0.0, f64::max);
            let s = BSplineSurface::new(p, q, ku.clone(), kv.clone(), coords.clone()).unwrap();
            let ((a, b), (c, e)) = s.domain();
            let mut us = params_for(&mut rng, &ku, a, b, true);
            let mut vs = params_for(&mut rng, &kv, c, e, true);
            if rng.next() < 0.5 {
                rng.shuffle(&mut us);
                rng.shuffle(&mut vs);
            }
            let mut out = vec![f64::NAN; us.len() * vs.len() * d];
            s.eval_grid_into(&us, &vs, &mut out).unwrap();
            let what = format!("B-spline ({p},{q}) d={d}");
            let inside = |u: f64, v: f64| (a..=b).contains(&u) && (c..=e).contains(&v);
            // Beyond the domain the end pieces continue; their basis values are no longer a
            // partition of unity, and the error grows with Σ|N_i(u)| · Σ|N_j(v)|.
            let magnitude =
                |u: f64, v: f64| basis_magnitude(p, &ku, u) * basis_magnitude(q, &kv, v);
            let err = grid_error(&what, &s, &us, &vs, &out, |u, v, _| {
                if inside(u, v) {
                    scale
                } else {
                    scale * magnitude(u, v)
                }
            });
            // Non-negative weights summing to one in both directions.
            assert!(err <= 2.0 * (p + q + 2) as f64, "{what}: {err} ε·scale");
            worst_b = worst_b.max(err);
            // The Array3 path and the trait's eval_grid_into are the same computation.
            let g = Surface::eval_grid(&s, &us, &vs);
            assert!(g.iter().zip(&out).all(|(x, y)| same(*x, *y)), "{what}");
            let mut again = vec![0.0; out.len()];
            Surface::eval_grid_into(&s, &us, &vs, &mut again).unwrap();
            assert!(again.iter().zip(&out).all(|(x, y)| same(*x, *y)), "{what}");

            // NURBS: weights in [0.5, 2]; the homogeneous error ~ ε·max|w P| is divided by a
            // weight ≥ 0.5.
            let w = DMatrix::from_fn(nu, nv, |_, _| 0.5 + 1.5 * rng.next());
            let r = NurbsSurface::new(p, q, ku.clone(), kv.clone(), coords, w.clone()).unwrap();
            let mut out = vec![f64::NAN; us.len() * vs.len() * d];
            r.eval_grid_into(&us, &vs, &mut out).unwrap();
            let what = format!("NURBS ({p},{q}) d={d}");
            // Beyond the domain: the homogeneous sums err by 2(p+q+2) ε Σ|N|Σ|N| max|wP| (and
            // max|w| for the weight), and dividing by the weight h_w(u, v) — no longer at least
            // min w there — amplifies that to (max|wP| + |x| max|w|) / |h_w|.
            let max_wp = r
                .homogeneous()
                .coordinates()
                .iter()
                .take(d)
                .map(|c| c.amax())
                .fold(0.0, f64::max);
            let max_w = w.amax();
            let err = grid_error(&what, &r, &us, &vs, &out, |u, v, x| {
                if inside(u, v) {
                    scale
                } else {
                    let h = r.homogeneous().eval(u, v);
                    magnitude(u, v) * (max_wp + x.amax() * max_w) / (8.0 * h[d].abs())
                }
            });
            assert!(err <= 16.0 * (p + q + 2) as f64, "{what}: {err} ε·scale");
            worst_n = worst_n.max(err);
            let g = Surface::eval_grid(&r, &us, &vs);
            assert!(g.iter().zip(&out).all(|(x, y)| same(*x, *y)), "{what}");
        }
    }
    println!("worst: B-spline {worst_b:.2} ε·scale, NURBS {worst_n:.2} ε·scale");
}

#[test]
fn batches_refuse_non_finite_parameters() {
    // `eval` is total (a NaN parameter gives NaNs); the batches return `Result` and refuse it,
    // as every `Result`-returning function of the crate does.
    let k = vec![0.0, 0.0, 0.5, 1.0, 1.0];
    let coords = vec![DMatrix::from_fn(3, 3, |i, j| (i + 2 * j) as f64 + 1.0)];
    let s = BSplineSurface::new(1, 1, k.clone(), k.clone(), coords.clone()).unwrap();
    let r = NurbsSurface::new(
        1,
        1,
        k.clone(),
        k.clone(),
        coords,
        DMatrix::from_element(3, 3, 1.0),
    )
    .unwrap();
    let c = BSplineCurve::new(
        1,
        k.clone(),
        DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 3.0]),
    )
    .unwrap();
    let n = NurbsCurve::new(
        1,
        k,
        DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 3.0]),
        vec![1.0; 3],
    )
    .unwrap();
    for (u, v) in [(f64::NAN, 0.5), (0.5, f64::INFINITY), (0.25, 0.75)] {
        let e = s.eval(u, v);
        assert_eq!(
            !(u.is_finite() && v.is_finite()),
            e[0].is_nan(),
            "({u}, {v})"
        );
        let mut out = [0.0];
        let (grid, nurbs) = (
            s.eval_grid_into(&[u], &[v], &mut out),
            r.eval_grid_into(&[u], &[v], &mut out),
        );
        let mut point = [0.0];
        let batches = [
            c.eval_many_into(&[u], &mut point),
            c.eval_many_exact_order_into(&[u], &mut point),
            n.eval_many_into(&[u], &mut point),
            n.eval_many_exact_order_into(&[u], &mut point),
        ];
        if u.is_finite() && v.is_finite() {
            assert!(grid.is_ok() && nurbs.is_ok() && batches.iter().all(Result::is_ok));
        } else {
            assert!(
                matches!(grid, Err(Error::NonFinite { .. })),
                "({u}, {v}): {grid:?}"
            );
            assert!(
                matches!(nurbs, Err(Error::NonFinite { .. })),
                "({u}, {v}): {nurbs:?}"
            );
            if !u.is_finite() {
                for b in batches {
                    assert!(matches!(b, Err(Error::NonFinite { .. })), "{u}: {b:?}");
                }
            }
        }
    }
}

#[test]
fn large_batches_on_threads_agree_with_eval() {
    // Above the parallel threshold of the grid driver: several blocks on several threads.
    let mut rng = Lcg(99);
    let knots = random_knots(&mut rng, 3, 12, true);
    let c = BSplineCurve::new(3, knots.clone(), random_control(&mut rng, 3, 12)).unwrap();
    let ts: Vec<f64> = (0..40_000)
        .map(|_| rng.signed() * 0.1 + rng.next())
        .collect();
    let weights: Vec<f64> = (0..12).map(|_| 0.5 + rng.next()).collect();
    let r = NurbsCurve::new(3, knots.clone(), c.control().clone(), weights).unwrap();
    check_exact_order_bits("40 000 points", &c, &r, &ts);
    // The fast batch: on threads, the same values as the same parameters in small batches.
    for curve in [&c as &dyn Curve, &r as &dyn Curve] {
        let mut all = vec![f64::NAN; ts.len() * 3];
        curve.eval_many_into(&ts, &mut all).unwrap();
        for (k, chunk) in ts.chunks(7).enumerate() {
            let mut part = vec![f64::NAN; chunk.len() * 3];
            curve.eval_many_into(chunk, &mut part).unwrap();
            assert_eq!(&all[k * 21..k * 21 + part.len()], &part[..]);
        }
    }

    let coords: Vec<DMatrix<f64>> = (0..3)
        .map(|_| DMatrix::from_fn(12, 9, |_, _| rng.signed()))
        .collect();
    let kv = random_knots(&mut rng, 2, 9, false);
    let s = BSplineSurface::new(3, 2, knots, kv, coords).unwrap();
    let ((a, b), (c0, c1)) = s.domain();
    let us: Vec<f64> = (0..150).map(|i| a + (b - a) * i as f64 / 149.0).collect();
    let vs: Vec<f64> = (0..1000)
        .map(|i| c0 + (c1 - c0) * i as f64 / 999.0)
        .collect();
    let mut out = vec![f64::NAN; us.len() * vs.len() * 3];
    s.eval_grid_into(&us, &vs, &mut out).unwrap();
    // Rows of a large grid are the rows of one-row grids (the same arithmetic per row).
    for a in [0, 1, 77, 149] {
        let mut row = vec![f64::NAN; vs.len() * 3];
        s.eval_grid_into(&us[a..a + 1], &vs, &mut row).unwrap();
        assert_eq!(&out[a * vs.len() * 3..(a + 1) * vs.len() * 3], &row[..]);
    }
    let err = grid_error(
        "large surface",
        &s,
        &us[..20],
        &vs,
        &out[..20 * 3000],
        |_, _, _| 1.0,
    );
    assert!(err <= 20.0, "{err}");
}

fn random_spline(rng: &mut Lcg, m: usize, d: usize, end: usize) -> CubicSpline {
    let closed = end == 2;
    let np = m + usize::from(closed);
    let mut t = 0.0;
    let params: Vec<f64> = (0..np)
        .map(|_| {
            t += 0.1 + 2.0 * rng.next();
            t - 1.0
        })
        .collect();
    let points = random_control(rng, d, m);
    let end = match end {
        0 => EndCondition::Clamped {
            start: DVector::from_fn(d, |_, _| rng.signed()),
            end: DVector::from_fn(d, |_, _| rng.signed()),
        },
        1 => EndCondition::Natural,
        _ => EndCondition::Closed,
    };
    CubicSpline::interpolate_with_params(points, params, end).unwrap()
}

#[test]
fn spline_batches_equal_eval_bit_for_bit() {
    let mut rng = Lcg(3);
    for m in [2, 3, 4, 7, 20] {
        for d in [1, 2, 3, 5] {
            for end in 0..3 {
                if end == 2 && m < 3 {
                    continue;
                }
                let s = random_spline(&mut rng, m, d, end);
                let t = s.params();
                let (lo, hi) = (t[0], t[t.len() - 1]);
                let mut ts = params_for(&mut rng, t, lo, hi, true);
                let what = format!("spline m={m} d={d} end={end}");
                check_curve_bits(&what, &s, &ts);
                rng.shuffle(&mut ts);
                check_curve_bits(&format!("{what} shuffled"), &s, &ts);
                let mat = s.eval_many(&ts);
                for (k, t) in ts.iter().enumerate() {
                    let e = s.eval(*t);
                    assert!(mat
                        .column(k)
                        .iter()
                        .zip(e.iter())
                        .all(|(a, b)| same(*a, *b)));
                }
            }
        }
    }
    // Many points: threads.
    let s = random_spline(&mut rng, 30, 3, 1);
    let ts: Vec<f64> = (0..50_000).map(|_| 70.0 * rng.next() - 5.0).collect();
    check_curve_bits("spline 50 000 points", &s, &ts);
}

fn q(n: i64, d: i64) -> Q {
    <Q as Scalar>::from_ratio(n, d)
}

#[test]
fn batches_are_exact_in_rationals() {
    // Knots with a double interior knot, non-uniform; parameters at knots, ends, beyond.
    let ku = vec![
        q(0, 1),
        q(0, 1),
        q(0, 1),
        q(1, 3),
        q(1, 3),
        q(3, 4),
        q(1, 1),
        q(1, 1),
        q(1, 1),
    ];
    let kv = vec![
        q(-1, 1),
        q(-1, 2),
        q(0, 1),
        q(1, 5),
        q(1, 2),
        q(2, 1),
        q(3, 1),
    ];
    let ts = [
        q(-1, 2),
        q(0, 1),
        q(1, 7),
        q(1, 3),
        q(1, 2),
        q(3, 4),
        q(9, 10),
        q(1, 1),
        q(2, 1),
    ];
    let vs = [
        q(-3, 1),
        q(0, 1),
        q(1, 10),
        q(1, 5),
        q(1, 3),
        q(1, 2),
        q(7, 5),
        q(9, 2),
    ];
    let val =
        |i: usize, j: usize, k: usize| q(((i * 7 + j * 3 + k * 5) % 11) as i64 - 5, 1 + k as i64);
    let control = DMatrix::from_fn(3, 6, |k, i| val(i, 0, k));
    let c = BSplineCurve::new(2, ku.clone(), control.clone()).unwrap();
    let weights: Vec<Q> = (0..6).map(|i| q(1 + (i as i64 % 3), 2)).collect();
    let r = NurbsCurve::new(2, ku.clone(), control, weights).unwrap();
    let mut out = vec![q(0, 1); ts.len() * 3];
    for curve in [&c as &dyn Curve<Q>, &r as &dyn Curve<Q>] {
        curve.eval_many_into(&ts, &mut out).unwrap();
        for (t, x) in ts.iter().zip(out.chunks_exact(3)) {
            assert_eq!(x, curve.eval(t.clone()).as_slice(), "t = {t}");
        }
    }
    // Surfaces: B-spline of degrees (2, 2) with unclamped v knots (domain [0, 1/2]); NURBS of
    // degrees (2, 3), clamped single-span v knots.
    let coords: Vec<DMatrix<Q>> = (0..2)
        .map(|k| DMatrix::from_fn(6, 4, |i, j| val(i, j, k)))
        .collect();
    let s = BSplineSurface::new(2, 2, ku.clone(), kv, coords.clone()).unwrap();
    let kv2 = vec![
        q(0, 1),
        q(0, 1),
        q(0, 1),
        q(0, 1),
        q(1, 1),
        q(1, 1),
        q(1, 1),
        q(1, 1),
    ];
    let w = DMatrix::from_fn(6, 4, |i, j| q(1 + ((i + j) as i64 % 4), 3));
    let n = NurbsSurface::new(2, 3, ku, kv2, coords, w).unwrap();
    let mut out = vec![q(0, 1); ts.len() * vs.len() * 2];
    for surf in [&s as &dyn Surface<Q>, &n as &dyn Surface<Q>] {
        surf.eval_grid_into(&ts, &vs, &mut out).unwrap();
        for (a, u) in ts.iter().enumerate() {
            for (b, v) in vs.iter().enumerate() {
                let x = &out[(a * vs.len() + b) * 2..][..2];
                assert_eq!(x, surf.eval(u.clone(), v.clone()).as_slice(), "({u}, {v})");
            }
        }
    }
    // Interpolating spline, clamped, exact.
    let pts = DMatrix::from_fn(2, 4, |k, i| val(i, 1, k));
    let end = EndCondition::Clamped {
        start: DVector::from_vec(vec![q(1, 1), q(1, 1)]),
        end: DVector::from_vec(vec![q(-1, 1), q(1, 2)]),
    };
    let sp = CubicSpline::interpolate(pts, end).unwrap();
    let ts = [
        q(-1, 2),
        q(0, 1),
        q(1, 3),
        q(1, 1),
        q(5, 2),
        q(3, 1),
        q(4, 1),
    ];
    let mut out = vec![q(0, 1); ts.len() * 2];
    sp.eval_many_into(&ts, &mut out).unwrap();
    for (t, x) in ts.iter().zip(out.chunks_exact(2)) {
        assert_eq!(x, sp.eval(t.clone()).as_slice(), "t = {t}");
    }
}

#[test]
fn buffers_of_the_wrong_length_are_shape_errors() {
    let mut rng = Lcg(1);
    let k = vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    let c = BSplineCurve::new(2, k.clone(), random_control(&mut rng, 3, 4)).unwrap();
    let r = NurbsCurve::from_bspline(&c);
    let coords = vec![DMatrix::from_fn(4, 4, |i, j| (i * j) as f64); 3];
    let s = BSplineSurface::new(2, 2, k.clone(), k.clone(), coords.clone()).unwrap();
    let n =
        NurbsSurface::new(2, 2, k.clone(), k, coords, DMatrix::from_element(4, 4, 1.0)).unwrap();
    let sp =
        CubicSpline::interpolate(random_control(&mut rng, 3, 5), EndCondition::Natural).unwrap();
    let ts = [0.0, 0.5];
    for len in [0, 5, 7, 100] {
        let mut out = vec![0.0; len];
        let errors = [
            c.eval_many_into(&ts, &mut out),
            c.try_eval_many_into(&ts, &mut out),
            Curve::eval_many_into(&c, &ts, &mut out),
            r.eval_many_into(&ts, &mut out),
            r.try_eval_many_into(&ts, &mut out),
            Curve::eval_many_into(&r, &ts, &mut out),
            sp.eval_many_into(&ts, &mut out),
            Curve::eval_many_into(&sp, &ts, &mut out),
            s.eval_grid_into(&ts, &ts, &mut out),
            Surface::eval_grid_into(&s, &ts, &ts, &mut out),
            n.eval_grid_into(&ts, &ts, &mut out),
            Surface::eval_grid_into(&n, &ts, &ts, &mut out),
        ];
        for (i, e) in errors.into_iter().enumerate() {
            assert!(
                matches!(e, Err(Error::ShapeMismatch { .. })),
                "case {i}, length {len}: {e:?}"
            );
        }
    }
    // Empty parameter lists: nothing to write, no error.
    c.eval_many_into(&[], &mut []).unwrap();
    s.eval_grid_into(&[], &ts, &mut []).unwrap();
    n.eval_grid_into(&ts, &[], &mut []).unwrap();
    sp.eval_many_into(&[], &mut []).unwrap();
}

/// `Σ_i Ñ_i(u)`: the triangular scheme of the batch run on `|u − u_{s+1−j}|` and
/// `|u_{s+j} − u|` in exact rationals, on the span whose piece continues to `u`. On the domain
/// every quantity is non-negative and the sum is 1; outside it the rounding errors of the
/// continued piece are bounded by this sum instead.
fn absolute_basis_sum(p: usize, knots: &[f64], u: f64) -> f64 {
    let n = knots.len() - p - 1;
    let (lo, hi) = (knots[p], knots[n]);
    let s = find_span(p, n, knots, &u.clamp(lo, hi)).unwrap();
    let k = |i: usize| Q::from_f64(knots[i]).unwrap();
    let uq = Q::from_f64(u).unwrap();
    let abs = |x: Q| if x < Q::from_integer(0.into()) { -x } else { x };
    let mut nb = vec![Q::from_integer(1.into())];
    for j in 1..=p {
        let mut next = vec![Q::from_integer(0.into()); j + 1];
        for r in 0..j {
            let t = nb[r].clone() / (k(s + r + 1) - k(s + r + 1 - j));
            next[r] += abs(k(s + r + 1) - uq.clone()) * t.clone();
            next[r + 1] += abs(uq.clone() - k(s + r + 1 - j)) * t;
        }
        nb = next;
    }
    Scalar::to_f64(&nb.into_iter().fold(Q::from_integer(0.into()), |a, b| a + b))
}

/// The largest `|batch − exact| / (ε · max |P| · scale(t))` of the fast batch of a curve over
/// the parameters `ts`, the exact value from the same curve in rationals at the same
/// parameter (the end pieces continue outside the domain); a NaN or infinite parameter must
/// give NaNs.
fn fast_batch_error(
    fast: &dyn Curve,
    exact: &dyn Curve<Q>,
    ts: &[f64],
    max_p: f64,
    scale: &dyn Fn(f64) -> f64,
) -> f64 {
    let d = fast.dim();
    let mut out = vec![0.0; ts.len() * d];
    fast.eval_many_into(ts, &mut out).unwrap();
    let mut worst: f64 = 0.0;
    for (t, x) in ts.iter().zip(out.chunks_exact(d)) {
        let e = exact.eval(Q::from_f64(*t).unwrap());
        for (a, b) in x.iter().zip(e.iter()) {
            let diff = Scalar::to_f64(&(Q::from_f64(*a).unwrap() - b.clone())).abs();
            worst = worst.max(diff / (f64::EPSILON * max_p * scale(*t)));
        }
    }
    worst
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(40))]

    /// The fast batches (reciprocals of the knot differences per span) against exact rational
    /// arithmetic: on the domain B-spline within `(4p + 1) ε · max |P_i|`, NURBS within
    /// `(7p + 3) ε · max |P_k|` (the bounds of `BSplineCurve::eval_many_into` and
    /// `NurbsCurve::eval_many_into`); beyond the domain (the end pieces continued) B-spline
    /// within `(4p + 1) ε · max |P_i| · Σ Ñ_i(u)` ([`absolute_basis_sum`]); for degrees 0…7
    /// (the four-lane kernels and the general one), clamped and unclamped knots with repeated
    /// knots, parameters at every knot, near and far beyond the domain;
    /// shuffled, the same points bit for bit.
    #[test]
    fn fast_curve_batches_are_within_the_bound_of_exact_rationals(
        seed in proptest::prelude::any::<u64>(),
        p in 0usize..=7,
        extra in 0usize..6,
        d in 1usize..=4,
        clamped in proptest::prelude::any::<bool>(),
    ) {
        let mut rng = Lcg(seed | 1);
        let n = p + 1 + extra;
        let knots = random_knots(&mut rng, p, n, clamped);
        let control = random_control(&mut rng, d, n);
        let weights: Vec<f64> = (0..n).map(|_| 0.25 + 4.0 * rng.next()).collect();
        let c = BSplineCurve::new(p, knots.clone(), control.clone()).unwrap();
        let r = NurbsCurve::new(p, knots.clone(), control.clone(), weights.clone()).unwrap();
        let lift = |v: &[f64]| v.iter().map(|x| Q::from_f64(*x).unwrap()).collect::<Vec<Q>>();
        let control_q = DMatrix::from_iterator(d, n, lift(control.as_slice()));
        let cq = BSplineCurve::new(p, lift(&knots), control_q.clone()).unwrap();
        let rq = NurbsCurve::new(p, lift(&knots), control_q, lift(&weights)).unwrap();
        let domain = c.domain();
        let mut ts = params_for(&mut rng, &knots, domain.0, domain.1, true);
        ts.truncate(30);
        ts.push(domain.1);
        let max_p = control.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let beyond = |t: f64| {
            if (domain.0..=domain.1).contains(&t) {
                1.0
            } else {
                absolute_basis_sum(p, &knots, t)
            }
        };
        let inside: Vec<f64> = ts
            .iter()
            .copied()
            .filter(|t| (domain.0..=domain.1).contains(t))
            .collect();
        let b = fast_batch_error(&c, &cq, &ts, max_p, &beyond);
        proptest::prop_assert!(b <= (4 * p + 1) as f64, "B-spline p={} d={}: {} ε", p, d, b);
        let w = fast_batch_error(&r, &rq, &inside, max_p, &|_| 1.0);
        proptest::prop_assert!(w <= (7 * p + 3) as f64, "NURBS p={} d={}: {} ε", p, d, w);
        // Shuffled, every point is the one of the sorted batch, bit for bit: a point does not
        // depend on the other parameters of the batch.
        let mut order: Vec<usize> = (0..ts.len()).collect();
        rng.shuffle(&mut order);
        let shuffled: Vec<f64> = order.iter().map(|&i| ts[i]).collect();
        for curve in [&c as &dyn Curve, &r] {
            let batch = |ts: &[f64]| {
                let mut out = vec![0.0; ts.len() * d];
                curve.eval_many_into(ts, &mut out).unwrap();
                out
            };
            let (a, z) = (batch(&ts), batch(&shuffled));
            for (k, &i) in order.iter().enumerate() {
                for j in 0..d {
                    proptest::prop_assert!(same(z[k * d + j], a[i * d + j]), "t = {}", ts[i]);
                }
            }
        }
    }
}
