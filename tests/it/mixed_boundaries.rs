//! Coons patches and Gordon surfaces take any `Curve`: here B-spline, NURBS and Bézier curves
//! mixed in one construction, in f64 and in exact rationals.

use cagd::bezier::BezierCurve;
use cagd::bspline::BSplineCurve;
use cagd::nurbs::NurbsCurve;
use cagd::{CoonsPatch, Curve, GordonSurface, Surface};
use nalgebra::{DMatrix, DVector};
use num_bigint::BigInt;
use num_rational::BigRational;

fn cols(points: &[[f64; 3]]) -> DMatrix<f64> {
    DMatrix::from_fn(3, points.len(), |r, c| points[c][r])
}

fn max_gap(a: &DVector<f64>, b: &DVector<f64>) -> f64 {
    (a - b).amax()
}

/// Four boundary curves of three different kinds meeting at (0,0,0), (1,0,0), (0,1,0), (1,1,0).
fn mixed_boundary() -> [Box<dyn Curve<f64>>; 4] {
    // x(u,0): clamped cubic B-spline with two spans.
    let c1 = BSplineCurve::clamped(
        3,
        cols(&[
            [0.0, 0.0, 0.0],
            [0.2, -0.1, 0.3],
            [0.5, 0.1, 0.4],
            [0.8, 0.0, 0.2],
            [1.0, 0.0, 0.0],
        ]),
    )
    .unwrap();
    // x(u,1): rational quadratic (a conic arc) from (0,1,0) to (1,1,0).
    let c2 = NurbsCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        cols(&[[0.0, 1.0, 0.0], [0.5, 1.5, 0.5], [1.0, 1.0, 0.0]]),
        vec![1.0, 2.0, 1.0],
    )
    .unwrap();
    // x(0,v): cubic Bézier from (0,0,0) to (0,1,0).
    let d1 = BezierCurve::new(cols(&[
        [0.0, 0.0, 0.0],
        [-0.2, 0.3, 0.1],
        [0.1, 0.7, -0.2],
        [0.0, 1.0, 0.0],
    ]))
    .unwrap();
    // x(1,v): quadratic B-spline with an interior knot from (1,0,0) to (1,1,0).
    let d2 = BSplineCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0],
        cols(&[
            [1.0, 0.0, 0.0],
            [1.2, 0.3, 0.1],
            [0.9, 0.8, 0.3],
            [1.0, 1.0, 0.0],
        ]),
    )
    .unwrap();
    [Box::new(c1), Box::new(c2), Box::new(d1), Box::new(d2)]
}

#[test]
fn coons_patch_of_bspline_nurbs_and_bezier_boundaries_interpolates_them() {
    let [c1, c2, d1, d2] = mixed_boundary();
    let reference: [Box<dyn Curve<f64>>; 4] = mixed_boundary();
    let patch = CoonsPatch::new(c1, c2, d1, d2).unwrap();
    let mut worst: f64 = 0.0;
    for k in 0..=40 {
        let s = k as f64 / 40.0;
        worst = worst.max(max_gap(&patch.eval(s, 0.0), &reference[0].eval(s)));
        worst = worst.max(max_gap(&patch.eval(s, 1.0), &reference[1].eval(s)));
        worst = worst.max(max_gap(&patch.eval(0.0, s), &reference[2].eval(s)));
        worst = worst.max(max_gap(&patch.eval(1.0, s), &reference[3].eval(s)));
    }
    assert!(worst <= 4.0 * f64::EPSILON, "boundary gap {worst:e}");
    // An interior point is r_c + r_d − r_cd of the four curves (Izrek 4.2), computed by hand.
    let (u, v) = (0.3, 0.6);
    let rc = reference[0].eval(u) * (1.0 - v) + reference[1].eval(u) * v;
    let rd = reference[2].eval(v) * (1.0 - u) + reference[3].eval(v) * u;
    let corner = |p: [f64; 3]| DVector::from_row_slice(&p);
    let rcd = corner([0.0, 0.0, 0.0]) * ((1.0 - u) * (1.0 - v))
        + corner([1.0, 0.0, 0.0]) * (u * (1.0 - v))
        + corner([0.0, 1.0, 0.0]) * ((1.0 - u) * v)
        + corner([1.0, 1.0, 0.0]) * (u * v);
    let expected = rc + rd - rcd;
    assert!(max_gap(&patch.eval(u, v), &expected) <= 1e-15);
}

#[test]
fn coons_patch_rejects_mixed_boundaries_that_do_not_meet() {
    let [c1, c2, d1, _] = mixed_boundary();
    // A B-spline that starts at (1,0,0.5) instead of the corner (1,0,0).
    let bad = BSplineCurve::clamped(1, cols(&[[1.0, 0.0, 0.5], [1.0, 1.0, 0.0]])).unwrap();
    let d2: Box<dyn Curve<f64>> = Box::new(bad);
    let err = CoonsPatch::new(c1, c2, d1, d2)
        .err()
        .expect("corner mismatch");
    assert!(matches!(err, cagd::Error::CornerMismatch { .. }), "{err:?}");
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// The exact surface s(u, v) = (u, v, u²·v + v) of degree (2, 1).
fn surface(u: &BigRational, v: &BigRational) -> DVector<BigRational> {
    DVector::from_vec(vec![u.clone(), v.clone(), u * u * v + v])
}

#[test]
fn gordon_surface_of_bspline_network_reproduces_a_polynomial_surface_exactly() {
    // Network of s: three curves s(u_i, ·) (linear in v) and two curves s(·, v_j) (quadratic in
    // u), each written as a B-spline with interior knots inserted, so nothing is a plain Bézier.
    let u_nodes = vec![q(0, 1), q(1, 3), q(1, 1)];
    let v_nodes = vec![q(0, 1), q(1, 1)];
    let curves_at_u: Vec<BSplineCurve<BigRational>> = u_nodes
        .iter()
        .map(|u| {
            let control = DMatrix::from_fn(3, 2, |r, c| surface(u, &q(c as i64, 1))[r].clone());
            BSplineCurve::clamped(1, control)
                .unwrap()
                .insert_knots(&[q(1, 2), q(3, 4)])
                .unwrap()
        })
        .collect();
    let curves_at_v: Vec<BSplineCurve<BigRational>> = v_nodes
        .iter()
        .map(|v| {
            // s(u, v) as a quadratic Bézier in u: control points (0, v, v), (1/2, v, v), (1, v, 2v).
            let pts = [
                [q(0, 1), v.clone(), v.clone()],
                [q(1, 2), v.clone(), v.clone()],
                [q(1, 1), v.clone(), v * q(2, 1)],
            ];
            let control = DMatrix::from_fn(3, 3, |r, c| pts[c][r].clone());
            BSplineCurve::clamped(2, control)
                .unwrap()
                .insert_knots(&[q(2, 5)])
                .unwrap()
        })
        .collect();
    let gordon = GordonSurface::new(u_nodes, v_nodes, curves_at_u, curves_at_v).unwrap();
    for (a, b) in [(1, 7), (2, 5), (5, 6), (9, 10)] {
        for (c, d) in [(1, 9), (1, 2), (4, 5)] {
            let (u, v) = (q(a, b), q(c, d));
            assert_eq!(gordon.eval(u.clone(), v.clone()), surface(&u, &v));
        }
    }
}
