//! Property tests for the course material: the invariants the CAD notes and the lecture notes state.

use cagd::bspline::{basis_all, BSplineCurve};
use cagd::conversion::{convert, CubicForm};
use cagd::spline::{CubicSpline, EndCondition};
use cagd::{BezierCurve, HermiteCubic, NurbsCurve, Scalar};
use nalgebra::{DMatrix, DVector};
use num_rational::BigRational;
use proptest::prelude::*;

/// A clamped knot vector of degree p with `n` control points and random interior knots
/// (possibly repeated, at most p times).
fn clamped_knots(p: usize, n: usize) -> impl Strategy<Value = Vec<f64>> {
    let interior = n - p - 1;
    proptest::collection::vec(0usize..8, interior).prop_map(move |mut ks| {
        ks.sort_unstable();
        let mut knots = vec![0.0; p + 1];
        // Cap the multiplicity at p.
        let mut out: Vec<f64> = Vec::new();
        for k in ks {
            let v = (k + 1) as f64 / 9.0;
            if out.iter().filter(|x| **x == v).count() < p {
                out.push(v);
            } else {
                out.push(v + 1.0 / 100.0);
            }
        }
        out.sort_by(|a, b| a.total_cmp(b));
        knots.extend(out);
        knots.extend(std::iter::repeat_n(1.0, p + 1));
        knots
    })
}

fn curve_strategy() -> impl Strategy<Value = BSplineCurve> {
    (1usize..=4, 0usize..4)
        .prop_flat_map(|(p, extra)| {
            let n = p + 1 + extra;
            (
                Just(p),
                clamped_knots(p, n),
                proptest::collection::vec(-10.0f64..10.0, 2 * n),
            )
        })
        .prop_map(|(p, knots, c)| {
            let n = c.len() / 2;
            BSplineCurve::new(p, knots, DMatrix::from_column_slice(2, n, &c)).unwrap()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// The CAD notes: Σ N_{k,p} = 1 and N_{k,p} ≥ 0; the CAD notes: supp N_{k,p} ⊂ [ξ_k, ξ_{k+p+1}].
    #[test]
    fn partition_of_unity_and_local_support(c in curve_strategy(), t in 0.0f64..=1.0) {
        let p = c.degree();
        let knots = c.knots().as_slice();
        let n = c.control().ncols();
        let b = basis_all(p, n, knots, &t).unwrap();
        let sum: f64 = b.iter().sum();
        prop_assert!((sum - 1.0).abs() < 1e-14, "sum {sum}");
        for (k, v) in b.iter().enumerate() {
            prop_assert!(*v >= 0.0);
            if t < knots[k] || t > knots[k + p + 1] {
                prop_assert_eq!(*v, 0.0, "N_{},{} at {} outside its support", k, p, t);
            }
        }
        // Local support of the curve: moving control point k changes C only on its support.
        let k = n / 2;
        let mut moved = c.control().clone();
        moved[(0, k)] += 5.0;
        let c2 = BSplineCurve::new(p, knots.to_vec(), moved).unwrap();
        let delta = (c2.try_eval(t).unwrap() - c.try_eval(t).unwrap()).norm();
        if t < knots[k] || t > knots[k + p + 1] {
            prop_assert_eq!(delta, 0.0);
        } else {
            prop_assert!((delta - 5.0 * b[k]).abs() < 1e-12);
        }
    }

    /// Knot insertion does not change the curve.
    #[test]
    fn knot_insertion_keeps_the_curve(c in curve_strategy(), ins in proptest::collection::vec(0.01f64..0.99, 1..4), t in 0.0f64..=1.0) {
        let refined = match c.insert_knots(&ins) {
            Ok(r) => r,
            Err(_) => return Ok(()), // a knot that would exceed multiplicity p + 1
        };
        prop_assert_eq!(refined.control().ncols(), c.control().ncols() + ins.len());
        let d = (refined.try_eval(t).unwrap() - c.try_eval(t).unwrap()).norm();
        prop_assert!(d < 1e-12, "moved by {d}");
    }

    /// A Bézier curve is the B-spline with clamped knots of one span.
    #[test]
    fn bezier_is_a_one_span_bspline(ctrl in proptest::collection::vec(-10.0f64..10.0, 2..=14), t in 0.0f64..=1.0) {
        let n = ctrl.len() / 2;
        let bez = BezierCurve::new(DMatrix::from_column_slice(2, n, &ctrl[..2 * n])).unwrap();
        let bs = BSplineCurve::from_bezier(&bez);
        let clamped = BSplineCurve::clamped(n - 1, bez.control().clone()).unwrap();
        prop_assert_eq!(&bs, &clamped);
        prop_assert!((bs.try_eval(t).unwrap() - bez.eval(t)).norm() < 1e-13);
        prop_assert!((bs.de_boor(t).unwrap() - bez.eval(t)).norm() < 1e-13);
    }

    /// nrbcirc-style arcs lie on their circle to round-off; more than a full turn is refused.
    #[test]
    fn nurbs_circle_points_at_distance_r(r in 0.1f64..100.0, cx in -50.0f64..50.0, cy in -50.0f64..50.0,
                                         s in -7.0f64..7.0, sweep in -std::f64::consts::TAU..=std::f64::consts::TAU, t in 0.0f64..=1.0) {
        let c = NurbsCurve::arc(r, &[cx, cy], s, s + sweep).unwrap();
        let x = c.try_eval(t).unwrap();
        let dist = ((x[0] - cx).powi(2) + (x[1] - cy).powi(2)).sqrt();
        prop_assert!((dist - r).abs() <= 1e-14 * (r + cx.abs() + cy.abs()), "distance {dist} vs {r}");
    }

    /// The spline interpolates its points and is C2 at every joint (f64, tolerance), for all
    /// three end conditions and random increasing parameters.
    #[test]
    fn spline_interpolates_with_c2_joints(pts in proptest::collection::vec(-10.0f64..10.0, 6..=24),
                                          steps in proptest::collection::vec(0.2f64..2.0, 13),
                                          which in 0usize..3) {
        let m = pts.len() / 2;
        let x = DMatrix::from_column_slice(2, m, &pts[..2 * m]);
        let closed = which == 2;
        let np = m + usize::from(closed);
        let mut t = vec![0.0];
        for k in 0..np - 1 { t.push(t[k] + steps[k]); }
        let end = match which {
            0 => EndCondition::Clamped { start: DVector::from_vec(vec![1.0, -1.0]), end: DVector::from_vec(vec![0.5, 2.0]) },
            1 => EndCondition::Natural,
            _ => EndCondition::Closed,
        };
        let s = CubicSpline::interpolate_with_params(x.clone(), t.clone(), end).unwrap();
        for (k, tk) in t.iter().enumerate().take(m) {
            prop_assert!((s.eval(*tk) - x.column(k)).norm() < 1e-12);
        }
        let scale = 1.0 + s.tangents().amax() / steps.iter().cloned().fold(f64::INFINITY, f64::min);
        for k in 1..np - 1 {
            // Left limit from segment k−1 at its end, right value from segment k.
            let left = s.segment(k - 1).unwrap();
            let right = s.segment(k).unwrap();
            let (hl, hr) = (t[k] - t[k - 1], t[k + 1] - t[k]);
            let d2l = left.eval_second_derivative(1.0) / (hl * hl);
            let d2r = right.eval_second_derivative(0.0) / (hr * hr);
            prop_assert!((d2l - d2r).norm() < 1e-9 * scale * scale, "joint {k}");
            let d1l = left.eval_derivative(1.0) / hl;
            let d1r = right.eval_derivative(0.0) / hr;
            prop_assert!((d1l - d1r).norm() < 1e-12 * scale);
        }
    }

    /// Hermite → Bézier → Hermite (and through the B-spline form) is the identity, exactly.
    #[test]
    fn conversions_round_trip_exactly(g in proptest::collection::vec(-1000i64..1000, 12), den in 1i64..50) {
        let q = |n: i64| BigRational::from_ratio(n, den);
        let geo = DMatrix::from_fn(3, 4, |r, c| q(g[r * 4 + c]));
        let h = HermiteCubic::from_geometry(geo.clone()).unwrap();
        let b = h.to_bezier().unwrap();
        let back = HermiteCubic::from_bezier(&b).unwrap();
        prop_assert_eq!(back.geometry(), &geo);
        let via_s = convert(&convert(&geo, CubicForm::Hermite, CubicForm::BSpline).unwrap(), CubicForm::BSpline, CubicForm::Bezier).unwrap();
        prop_assert_eq!(&via_s, b.control());
        // The same curve at a few parameters.
        for k in 0..=4 {
            let u = BigRational::from_ratio(k, 4);
            prop_assert_eq!(h.eval(u.clone()), b.eval(u));
        }
        let _ = <BigRational as Scalar>::from_usize(0);
    }
}

/// The spline solves run exactly in rationals: C2 at every joint, with equality.
#[test]
fn exact_spline_is_c2_everywhere() {
    let q = |n: i64, d: i64| BigRational::from_ratio(n, d);
    let x = DMatrix::from_fn(2, 6, |r, c| {
        q(((r * 5 + c * 7) % 9) as i64 - 4, 1 + c as i64)
    });
    let t: Vec<BigRational> = [0, 1, 3, 4, 7, 8, 10].iter().map(|&k| q(k, 2)).collect();
    for end in [EndCondition::Natural, EndCondition::Closed] {
        let closed = end == EndCondition::Closed;
        let tt = if closed { t.clone() } else { t[..6].to_vec() };
        let s = CubicSpline::interpolate_with_params(x.clone(), tt.clone(), end).unwrap();
        for k in 1..tt.len() - 1 {
            let (l, r) = (s.segment(k - 1).unwrap(), s.segment(k).unwrap());
            let (hl, hr) = (
                tt[k].clone() - tt[k - 1].clone(),
                tt[k + 1].clone() - tt[k].clone(),
            );
            let d2l = l
                .eval_second_derivative(q(1, 1))
                .map(|v| v / (hl.clone() * hl.clone()));
            let d2r = r
                .eval_second_derivative(q(0, 1))
                .map(|v| v / (hr.clone() * hr.clone()));
            assert_eq!(d2l, d2r, "joint {k}");
        }
        if closed {
            let [a0, a1, a2] = s.eval_with_derivatives(t[0].clone());
            let [b0, b1, b2] = s.eval_with_derivatives(t[6].clone());
            assert_eq!((a0, a1, a2), (b0, b1, b2));
        }
    }
}
