//! The worked examples of the course notes (the lecture notes, with the CAD notes and the matrix-form notes), in exact
//! rational arithmetic where the maths is rational.

use cagd::bspline::BSplineCurve;
use cagd::continuity::{c1_free_point, curve_joint, joint};
use cagd::conversion::{
    bezier_matrix, bspline_matrix, conversion_matrix, hermite_matrix, hermite_matrix_inverse,
    CubicForm,
};
use cagd::hermite::HermiteCubic;
use cagd::interpolation::{
    blending_matrix, LagrangePolynomial, ParametricInterpolant, PiecewiseLinear,
};
use cagd::spline::{CubicSpline, EndCondition};
use cagd::surfaces::{CubicMatrixPatch, FergusonPatch, RuledSurface};
use cagd::{BSplineSurface, BezierCurve, BezierPatch, Curve, NurbsCurve, Scalar, Surface};
use nalgebra::{DMatrix, DVector};
use num_rational::BigRational;

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    Q::from_ratio(n, d)
}

fn qi(n: i64) -> Q {
    q(n, 1)
}

fn qm(rows: usize, cols: usize, entries: &[i64], den: i64) -> DMatrix<Q> {
    DMatrix::from_row_slice(
        rows,
        cols,
        &entries.iter().map(|&e| q(e, den)).collect::<Vec<_>>(),
    )
}

fn qv(entries: &[i64]) -> DVector<Q> {
    DVector::from_iterator(entries.len(), entries.iter().map(|&e| qi(e)))
}

/// The lecture notes, case a: points (0,0), (2,1), (4,4), (6,0), tangents (1,1) and (−1,1): x-tangents
/// 1, 31/15, 41/15, −1; y-tangents 1, 48/15, −27/15, 1 (the notes print +27/15).
#[test]
fn lecture_notes_clamped_spline_tangents_exactly() {
    let x = qm(2, 4, &[0, 2, 4, 6, 0, 1, 4, 0], 1);
    let end = EndCondition::Clamped {
        start: qv(&[1, 1]),
        end: qv(&[-1, 1]),
    };
    let s = CubicSpline::interpolate(x.clone(), end).unwrap();
    let t = s.tangents();
    let xs: Vec<Q> = t.row(0).iter().cloned().collect();
    let ys: Vec<Q> = t.row(1).iter().cloned().collect();
    assert_eq!(xs, vec![qi(1), q(31, 15), q(41, 15), qi(-1)]);
    assert_eq!(ys, vec![qi(1), q(48, 15), q(-27, 15), qi(1)]);
    assert_ne!(ys[2], q(27, 15), "the notes' +27/15 is wrong");
    // The notes' inverse matrix times the right-hand side (1, 12, 12, −1) gives x.
    let inv = qm(
        4,
        4,
        &[15, 0, 0, 0, -4, 4, -1, 1, 1, -1, 4, -4, 0, 0, 0, 15],
        15,
    );
    let rhs = DVector::from_vec(vec![qi(1), qi(12), qi(12), qi(-1)]);
    let by_inverse: Vec<Q> = (0..4)
        .map(|i| (0..4).fold(qi(0), |a, j| a + inv[(i, j)].clone() * rhs[j].clone()))
        .collect();
    assert_eq!(by_inverse, xs);
    // It interpolates.
    for k in 0..4 {
        assert_eq!(s.eval(qi(k as i64)), x.column(k).into_owned());
    }
}

/// The natural and closed cases on the same points, exactly: the end conditions hold.
#[test]
fn natural_and_closed_splines_satisfy_their_end_conditions_exactly() {
    let x = qm(2, 4, &[0, 2, 4, 6, 0, 1, 4, 0], 1);
    let n = CubicSpline::interpolate(x.clone(), EndCondition::Natural).unwrap();
    let zero = DVector::from_element(2, qi(0));
    assert_eq!(n.eval_with_derivatives(qi(0))[2], zero);
    assert_eq!(n.eval_with_derivatives(qi(3))[2], zero);
    // Natural, x-coordinate: 2a+b = 6, a+4b+c = 12, b+4c+d = 12, c+2d = 6 → all 2 (a line).
    assert!(n.tangents().row(0).iter().all(|v| *v == qi(2)));
    let c = CubicSpline::interpolate(x.clone(), EndCondition::Closed).unwrap();
    let [p0, d0, s0] = c.eval_with_derivatives(qi(0));
    let [p4, d4, s4] = c.eval_with_derivatives(qi(4));
    assert_eq!((p0, d0, s0), (p4, d4, s4));
}

/// The lecture notes: Lagrange polynomial through (1,1), (2,2), (3,3), (4,2), (5,1), exactly
/// `3 − 7/6 (x−3)² + 1/6 (x−3)⁴ = x⁴/6 − 2x³ + 47x²/6 − 11x + 6`; and the piecewise-linear
/// interpolant of the same points.
#[test]
fn lecture_notes_lagrange_example() {
    let xs: Vec<Q> = (1..=5).map(qi).collect();
    let ys = vec![qi(1), qi(2), qi(3), qi(2), qi(1)];
    let f = LagrangePolynomial::new(xs.clone(), ys.clone()).unwrap();
    assert_eq!(
        f.coefficients().unwrap(),
        vec![q(1, 6), qi(-2), q(47, 6), qi(-11), qi(6)]
    );
    for (x, y) in xs.iter().zip(&ys) {
        assert_eq!(&f.eval(x.clone()), y);
    }
    assert_eq!(f.eval(q(5, 2)), q(87, 32));
    // Between the nodes the quartic bends away from the data (f(1.5) = 39/32, while the
    // points lie on the line y = x there), the oscillation the notes warn about; the linear
    // interpolant follows the data.
    assert_eq!(f.eval(q(3, 2)), q(39, 32));
    let l = PiecewiseLinear::new(xs, ys).unwrap();
    assert_eq!(l.eval(q(3, 2)), q(3, 2));
    assert_eq!(l.eval(q(7, 2)), q(5, 2));
}

/// The lecture notes' blending matrices for 3 points at (0, ½, 1) and 4 points at (0, ⅓, ⅔, 1).
#[test]
fn lecture_notes_blending_matrices() {
    let g3 = blending_matrix(&[qi(0), q(1, 2), qi(1)]).unwrap();
    assert_eq!(g3, qm(3, 3, &[2, -3, 1, -4, 4, 0, 2, -1, 0], 1));
    let g4 = blending_matrix(&[qi(0), q(1, 3), q(2, 3), qi(1)]).unwrap();
    assert_eq!(
        g4,
        qm(
            4,
            4,
            &[-9, 18, -11, 2, 27, -45, 18, 0, -27, 36, -9, 0, 9, -9, 2, 0],
            2
        )
    );
    // Non-monotone parameters (0, ½, ¼, 1) on collinear, evenly spaced points 0, 1, 2, 3:
    // the curve passes every point, but in the order 0, 2, 1, 3, running back and forth along
    // the line: after x(½) = 1 it falls back to x(¾) = 1/4 before reaching 3.
    let pts = qm(1, 4, &[0, 1, 2, 3], 1);
    let c = ParametricInterpolant::new(pts, vec![qi(0), q(1, 2), q(1, 4), qi(1)]).unwrap();
    assert_eq!(c.eval(q(1, 4))[0], qi(2));
    assert_eq!(c.eval(q(1, 2))[0], qi(1));
    let monotone = ParametricInterpolant::new(
        qm(1, 4, &[0, 1, 2, 3], 1),
        vec![qi(0), q(1, 3), q(2, 3), qi(1)],
    )
    .unwrap();
    assert_eq!(
        monotone.eval(q(1, 5))[0],
        q(3, 5),
        "evenly spaced: x(u) = 3u"
    );
    assert_eq!(c.eval(q(3, 4))[0], q(1, 4));
    assert_eq!(c.eval(qi(1))[0], qi(3));
}

/// The lecture notes' matrices and the conversion table, every entry, exactly.
#[test]
fn lecture_notes_matrices_and_conversion_table() {
    assert_eq!(
        hermite_matrix::<Q>(),
        qm(
            4,
            4,
            &[2, -3, 0, 1, -2, 3, 0, 0, 1, -2, 1, 0, 1, -1, 0, 0],
            1
        )
    );
    assert_eq!(
        hermite_matrix_inverse::<Q>(),
        qm(4, 4, &[0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 1, 1, 1, 1, 0, 0], 1)
    );
    assert_eq!(
        bezier_matrix::<Q>(),
        qm(
            4,
            4,
            &[-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0],
            1
        )
    );
    assert_eq!(
        bspline_matrix::<Q>(),
        qm(
            4,
            4,
            &[-1, 3, -3, 1, 3, -6, 0, 4, -3, 3, 3, 1, 1, 0, 0, 0],
            6
        )
    );
    // M_BH M_H = M_B.
    let m_bh = qm(4, 4, &[1, 0, -3, 0, 0, 0, 3, 0, 0, 0, 0, -3, 0, 1, 0, 3], 1);
    assert_eq!(
        conversion_matrix::<Q>(CubicForm::Bezier, CubicForm::Hermite),
        m_bh
    );
    // The table, entry (row "to", column "from"), as printed.
    use CubicForm::*;
    let table = [
        (
            Hermite,
            BSpline,
            qm(4, 4, &[1, 0, -3, 0, 4, 1, 0, -3, 1, 4, 3, 0, 0, 1, 0, 3], 6),
        ),
        (
            Bezier,
            Hermite,
            qm(4, 4, &[3, 3, 0, 0, 0, 0, 3, 3, 0, 1, 0, 0, 0, 0, -1, 0], 3),
        ),
        (
            Bezier,
            BSpline,
            qm(4, 4, &[1, 0, 0, 0, 4, 4, 2, 1, 1, 2, 4, 4, 0, 0, 0, 1], 6),
        ),
        (
            BSpline,
            Hermite,
            qm(
                4,
                4,
                &[-3, 6, -3, 6, 6, -3, 6, -3, -7, 2, -1, 2, -2, 1, -2, 7],
                3,
            ),
        ),
        (
            BSpline,
            Bezier,
            qm(
                4,
                4,
                &[6, 0, 0, 0, -7, 2, -1, 2, 2, -1, 2, -7, 0, 0, 0, 6],
                1,
            ),
        ),
    ];
    for (to, from, printed) in table {
        assert_eq!(
            conversion_matrix::<Q>(from, to),
            printed,
            "to {to:?} from {from:?}"
        );
    }
    for f in [Hermite, Bezier, BSpline] {
        assert_eq!(conversion_matrix::<Q>(f, f), DMatrix::identity(4, 4));
    }
    // The notes' M_S for the B-spline surface is M_B, which is not M_C.
    assert_ne!(bezier_matrix::<Q>(), bspline_matrix::<Q>());
}

/// The lecture notes' C1 example: x_C = (x, y, z) with x = 3 + k, y = 4 − 2k, z = 3 + 3k.
#[test]
fn lecture_notes_c1_free_point() {
    let (xa, xb, xd) = (qv(&[2, 3, 4]), qv(&[3, 1, 5]), qv(&[3, 4, 3]));
    let (xe, xf, xg) = (qv(&[2, 6, 0]), qv(&[5, 7, 5]), qv(&[5, 2, 3]));
    let (p, dir) = c1_free_point(&xd, &xe).unwrap();
    assert_eq!((p.clone(), dir.clone()), (qv(&[3, 4, 3]), qv(&[1, -2, 3])));
    let second = BezierCurve::new(DMatrix::from_columns(&[xd.clone(), xe, xf, xg])).unwrap();
    for (k, expect_c1) in [(qi(1), true), (q(1, 2), false), (qi(3), false)] {
        let xc = DVector::from_fn(3, |r, _| p[r].clone() + k.clone() * dir[r].clone());
        let first = BezierCurve::new(DMatrix::from_columns(&[
            xa.clone(),
            xb.clone(),
            xc,
            xd.clone(),
        ]))
        .unwrap();
        let j = curve_joint(&first, qi(1), &second, qi(0), qi(0)).unwrap();
        assert!(j.c0 && j.g1, "k = {k}");
        assert_eq!(j.c1, expect_c1, "k = {k}");
    }
    // k < 0 reverses the tangent: not even G1.
    let xc = DVector::from_fn(3, |r, _| p[r].clone() - dir[r].clone());
    let first = BezierCurve::new(DMatrix::from_columns(&[xa, xb, xc, xd])).unwrap();
    let j = curve_joint(&first, qi(1), &second, qi(0), qi(0)).unwrap();
    assert!(j.c0 && !j.g1 && !j.c1);
    let far = joint(
        (&qv(&[0, 0]), &qv(&[1, 0])),
        (&qv(&[0, 1]), &qv(&[1, 0])),
        qi(0),
    )
    .unwrap();
    assert!(!far.c0 && !far.g1);
}

/// The lecture notes' Bézier example x0 = (2,3), x1 = (3,5), x2 = (4,7) or (4,1), x3 = (5,3), and
/// the Hermite form with x'_1 = 3(x1 − x0), x'_2 = 3(x3 − x2).
#[test]
fn lecture_notes_bezier_hermite_equivalence() {
    for x2 in [[4, 7], [4, 1]] {
        let b = BezierCurve::new(qm(2, 4, &[2, 3, x2[0], 5, 3, 5, x2[1], 3], 1)).unwrap();
        let h = HermiteCubic::from_bezier(&b).unwrap();
        assert_eq!(h.geometry().column(2).into_owned(), qv(&[3, 6]));
        assert_eq!(
            h.geometry().column(3).into_owned(),
            qv(&[3, 3 * (3 - x2[1])])
        );
        for k in 0..=8 {
            let u = q(k, 8);
            assert_eq!(h.eval(u.clone()), b.eval(u));
        }
        assert_eq!(h.to_bezier().unwrap(), b);
    }
    // Tangent scaling by q keeps the end points and end directions.
    let h = HermiteCubic::new(qv(&[0, 0]), qv(&[4, 0]), qv(&[1, 2]), qv(&[1, -2])).unwrap();
    let h3 = h.scaled_tangents(qi(3)).unwrap();
    assert_eq!(h3.eval(qi(0)), h.eval(qi(0)));
    assert_eq!(h3.eval_derivative(qi(1)), qv(&[3, -6]));
    assert_ne!(h3.eval(q(1, 2)), h.eval(q(1, 2)));
}

/// The uniform cubic B-spline of the lecture notes with replicated end points equals its segment-wise
/// matrix form `X_C M_C u`, and starts and ends at the end points.
#[test]
fn uniform_cubic_bspline_is_the_coons_cubic() {
    let pts = qm(2, 5, &[0, 1, 3, 4, 6, 0, 2, 2, -1, 0], 1);
    let c = BSplineCurve::uniform_cubic(&pts, true).unwrap();
    let (a, b) = c.domain();
    assert_eq!((a.clone(), b.clone()), (qi(0), qi(6)));
    assert_eq!(c.try_eval(a).unwrap(), pts.column(0).into_owned());
    assert_eq!(c.try_eval(b).unwrap(), pts.column(4).into_owned());
    let m = bspline_matrix::<Q>();
    for seg in 0..6usize {
        let x_c = DMatrix::from_fn(2, 4, |r, j| c.control()[(r, seg + j)].clone());
        for k in 0..=4 {
            let u = q(k, 4);
            let powers = DVector::from_vec(vec![
                u.clone() * u.clone() * u.clone(),
                u.clone() * u.clone(),
                u.clone(),
                qi(1),
            ]);
            let f = DVector::from_fn(4, |i, _| {
                (0..4).fold(qi(0), |s, j| s + m[(i, j)].clone() * powers[j].clone())
            });
            let by_matrix = DVector::from_fn(2, |r, _| {
                (0..4).fold(qi(0), |s, j| s + x_c[(r, j)].clone() * f[j].clone())
            });
            assert_eq!(
                c.try_eval(qi(seg as i64) + u).unwrap(),
                by_matrix,
                "segment {seg}"
            );
        }
    }
}

/// Bicubic patches in matrix form: Bézier (the matrix-form notes §2.2, 004) equals `BezierPatch`; the
/// uniform B-spline form (the right `M_S = M_C`) equals `BSplineSurface` on one span; the
/// Ferguson patch with corner data from a Bézier patch reproduces it.
#[test]
fn matrix_form_patches() {
    let net: Vec<DMatrix<Q>> = (0..3)
        .map(|k| DMatrix::from_fn(4, 4, |i, j| qi(((i * 7 + j * 3 + k * 5) % 11) as i64 - 5)))
        .collect();
    let bez = BezierPatch::new(net.clone()).unwrap();
    let mb = CubicMatrixPatch::new(CubicForm::Bezier, net.clone()).unwrap();
    let knots: Vec<Q> = (-3..=4).map(qi).collect();
    let bs = BSplineSurface::new(3, 3, knots.clone(), knots, net.clone()).unwrap();
    let mc = CubicMatrixPatch::new(CubicForm::BSpline, net.clone()).unwrap();
    // The notes' M_S (= M_B) does not give the B-spline surface.
    let (u0, v0) = (q(1, 3), q(3, 4));
    assert_ne!(
        Surface::eval(&bs, u0.clone(), v0.clone()),
        Surface::eval(&mb, u0, v0)
    );
    let d = |r, s| bez.derivative(r, s).unwrap();
    let (du, dv, duv) = (d(1, 0), d(0, 1), d(1, 1));
    let corner = |p: &BezierPatch<Q>, i: i64, j: i64| p.eval(qi(i), qi(j));
    let grid = |p: &BezierPatch<Q>| {
        [
            [corner(p, 0, 0), corner(p, 0, 1)],
            [corner(p, 1, 0), corner(p, 1, 1)],
        ]
    };
    let fer = FergusonPatch::new(&grid(&bez), &grid(&du), &grid(&dv), &grid(&duv)).unwrap();
    for i in 0..=3 {
        for j in 0..=3 {
            let (u, v) = (q(i, 3), q(j, 3));
            let expect = bez.eval(u.clone(), v.clone());
            assert_eq!(Surface::eval(&mb, u.clone(), v.clone()), expect);
            assert_eq!(Surface::eval(&fer, u.clone(), v.clone()), expect);
            assert_eq!(
                Surface::eval(&mc, u.clone(), v.clone()),
                bs.try_eval(u, v).unwrap()
            );
        }
    }
}

/// The lecture notes' ruled surface between two curves of different kinds (B-spline and NURBS), and a
/// cylinder (constant ruling vector).
#[test]
fn ruled_surfaces_take_any_curves() {
    let a = BSplineCurve::clamped(
        2,
        DMatrix::from_column_slice(
            3,
            4,
            &[0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 2.0, 0.0, 1.0, 3.0, 0.0, 0.0],
        ),
    )
    .unwrap();
    let circle = NurbsCurve::arc(1.0, &[1.5, 2.0, 1.0], 0.0, std::f64::consts::PI).unwrap();
    let s = RuledSurface::new(&a, &circle).unwrap();
    for k in 0..=4 {
        let u = k as f64 / 4.0;
        assert_eq!(s.eval(u, 0.0), a.eval(u));
        assert!((s.eval(u, 1.0) - Curve::eval(&circle, u)).norm() < 1e-15);
        let mid = s.eval(u, 0.5);
        assert!((mid - (a.eval(u) + Curve::eval(&circle, u)) * 0.5).norm() < 1e-15);
    }
    // Cylinder: the second curve is the first shifted by r.
    let shifted = BSplineCurve::clamped(
        2,
        a.control().map(|x| x) + DMatrix::from_fn(3, 4, |r, _| [0.0, 0.0, 2.0][r]),
    )
    .unwrap();
    let cyl = RuledSurface::new(&a, &shifted).unwrap();
    assert_eq!(
        cyl.eval(0.3, 0.5) - a.eval(0.3),
        DVector::from_vec(vec![0.0, 0.0, 1.0])
    );
}

/// NURBS conics in exact rationals: a quarter circle with rational control points needs the
/// irrational weight √2/2, but the rational parametrisation of the circle
/// `((1 − t²)/(1 + t²), 2t/(1 + t²))` is the conic arc with weights (1, 1, 2) over control
/// points (1,0), (1,1), (0,1)… checked here on exact points of the unit circle.
#[test]
fn exact_rational_circle_points() {
    // Quadratic rational Bézier with P0 = (1,0), P1 = (1,1), P2 = (0,1) and weights
    // (1, 1, 2) is (1 − t², 2t)/(1 + t²): every point lies on the unit circle exactly.
    let p = DMatrix::from_column_slice(2, 3, &[qi(1), qi(0), qi(1), qi(1), qi(0), qi(1)]);
    let c = cagd::nurbs::NurbsCurve::new(
        2,
        vec![qi(0), qi(0), qi(0), qi(1), qi(1), qi(1)],
        p,
        vec![qi(1), qi(1), qi(2)],
    )
    .unwrap();
    for k in 0..=10 {
        let x = c.try_eval(q(k, 10)).unwrap();
        assert_eq!(
            x[0].clone() * x[0].clone() + x[1].clone() * x[1].clone(),
            qi(1),
            "t = {k}/10"
        );
    }
    let _ = <Q as Scalar>::from_usize(0);
}
