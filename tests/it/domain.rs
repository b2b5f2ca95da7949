//! Curves and surfaces know their domain (`cagd::param`): every type reports it, `eval`
//! continues the curve outside it and `try_eval` keeps to it — one rule, checked type by type —
//! and the constructions that take curves reparametrise each curve's domain onto `[0, 1]` or
//! refuse it with `Error::UnusableDomain`.
//!
//! Expected values are computed independently of the crate: from the curves' closed forms
//! (the uniform cubic B-spline matrix, Bernstein and hand-derived Cox–de Boor pieces) in exact
//! rationals, or from polynomials the data are known to represent.

use crate::support::{q, Q};

use cagd::bezier::{BezierCurve, BezierPatch, MatrixForm};
use cagd::bspline::{BSplineCurve, BSplineSurface};
use cagd::conversion::CubicForm;
use cagd::coons::{
    BicubicCoonsPatch, BlendingPair, CoonsBoundary, CoonsPatch, CrossDerivatives,
    GeneralizedCoonsPatch, Tolerance, Twist,
};
use cagd::gordon::GordonSurface;
use cagd::hermite::HermiteCubic;
use cagd::interpolation::ParametricInterpolant;
use cagd::lagrange::{Lagrange, LagrangeInterpolant};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::spline::{CubicSpline, EndCondition};
use cagd::surfaces::{CubicMatrixPatch, FergusonPatch, RuledSurface};
use cagd::CurveDeriv;
use cagd::{Curve, Error, FnCurve, OnUnitInterval, SampledCurve, Scalar, Surface};
use nalgebra::{dmatrix, dvector, DMatrix, DVector};
use proptest::prelude::*;

// ------------------------------------------------------------------------------------------
// The Coons patch of four B-spline boundaries, one of them on [0, 4]

/// Control points (columns) from rational coordinates `(n, d)` triples.
fn net<T: Scalar>(points: &[[(i64, i64); 3]]) -> DMatrix<T> {
    DMatrix::from_fn(3, points.len(), |r, c| {
        T::from_ratio(points[c][r].0, points[c][r].1)
    })
}

/// `c1` from (0,0,0) over (1,0,2) to (2,0,0): the uniform cubic B-spline with replicated ends,
/// domain [0, 4]; `c2` the clamped quadratic on (0,2,0), (1,2,1), (2,2,0), domain [0, 1];
/// `d1` the quadratic on the knots 0,0,0,1,2,2,2 over (0,0,0), (0,1,−1), (0,3/2,1/2), (0,2,0),
/// domain [0, 2]; `d2` the line (2,0,0)–(2,2,0), domain [0, 1].
fn b_spline_boundary<T: Scalar>() -> [BSplineCurve<T>; 4] {
    let z = (0, 1);
    let c1 = BSplineCurve::uniform_cubic(
        &net(&[[z, z, z], [(1, 1), z, (2, 1)], [(2, 1), z, z]]),
        true,
    )
    .unwrap();
    let c2 = BSplineCurve::clamped(
        2,
        net(&[
            [z, (2, 1), z],
            [(1, 1), (2, 1), (1, 1)],
            [(2, 1), (2, 1), z],
        ]),
    )
    .unwrap();
    let k = |n: i64| T::from_ratio(n, 1);
    let d1 = BSplineCurve::new(
        2,
        vec![k(0), k(0), k(0), k(1), k(2), k(2), k(2)],
        net(&[
            [z, z, z],
            [z, (1, 1), (-1, 1)],
            [z, (3, 2), (1, 2)],
            [z, (2, 1), z],
        ]),
    )
    .unwrap();
    let d2 = BSplineCurve::clamped(1, net(&[[(2, 1), z, z], [(2, 1), (2, 1), z]])).unwrap();
    [c1, c2, d1, d2]
}

/// The four boundary curves at the unit parameters `u` (for `c1`, `c2`) and `v` (for `d1`,
/// `d2`), from their closed forms, in exact rationals.
fn boundary_closed_forms(u: &Q, v: &Q) -> [DVector<Q>; 4] {
    let one = q(1, 1);
    let lin = |a: &DVector<Q>, wa: Q, b: &DVector<Q>, wb: Q| a * wa + b * wb;
    let p = |x: i64, y: (i64, i64), z: (i64, i64)| dvector![q(x, 1), q(y.0, y.1), q(z.0, z.1)];
    // c1 on [0, 4] at t = 4u: segment k = ⌊t⌋ (0 ≤ k ≤ 3) blends the replicated points
    // x0 x0 x0 x1 x2 x2 x2 by the uniform cubic B-spline basis (the lecture notes' M_C):
    // [(1−s)³, 3s³ − 6s² + 4, −3s³ + 3s² + 3s + 1, s³]/6, s = t − k.
    let t = u * q(4, 1);
    let k = (0..4).rev().find(|k| t >= q(*k, 1)).unwrap_or(0);
    let s = &t - q(k, 1);
    let (s2, s3) = (&s * &s, &s * &s * &s);
    let b = [
        (&one - &s) * (&one - &s) * (&one - &s),
        &s3 * q(3, 1) - &s2 * q(6, 1) + q(4, 1),
        -&s3 * q(3, 1) + &s2 * q(3, 1) + &s * q(3, 1) + &one,
        s3.clone(),
    ]
    .map(|x| x / q(6, 1));
    let x = [
        p(0, (0, 1), (0, 1)),
        p(1, (0, 1), (2, 1)),
        p(2, (0, 1), (0, 1)),
    ];
    let replicated = [&x[0], &x[0], &x[0], &x[1], &x[2], &x[2], &x[2]];
    let c1 = (0..4).fold(DVector::zeros(3), |acc: DVector<Q>, i| {
        acc + replicated[k as usize + i] * b[i].clone()
    });
    // c2: the quadratic Bézier (Bernstein form) on (0,2,0), (1,2,1), (2,2,0).
    let w = &one - u;
    let c2 = lin(
        &p(0, (2, 1), (0, 1)),
        &w * &w,
        &p(1, (2, 1), (1, 1)),
        u * &w * q(2, 1),
    ) + p(2, (2, 1), (0, 1)) * (u * u);
    // d1 on [0, 2] at t = 2v, on its first span [0, 1]: Cox–de Boor by hand on the knots
    // 0,0,0,1,2,2,2 gives (1 − t)², t(1 − t) + t(2 − t)/2, t²/2.
    let t = v * q(2, 1);
    assert!(t <= one, "the closed form below is that of the first span");
    let n = [
        (&one - &t) * (&one - &t),
        &t * (&one - &t) + &t * (q(2, 1) - &t) / q(2, 1),
        &t * &t / q(2, 1),
    ];
    let d = [
        p(0, (0, 1), (0, 1)),
        p(0, (1, 1), (-1, 1)),
        p(0, (3, 2), (1, 2)),
    ];
    let d1 = (0..3).fold(DVector::zeros(3), |acc: DVector<Q>, i| {
        acc + &d[i] * n[i].clone()
    });
    // d2: the line from (2,0,0) to (2,2,0).
    let d2 = lin(
        &p(2, (0, 1), (0, 1)),
        &one - v,
        &p(2, (2, 1), (0, 1)),
        v.clone(),
    );
    [c1, c2, d1, d2]
}

/// The bilinearly blended Coons patch (Izrek 4.2) from the closed forms.
fn coons_closed_form(u: &Q, v: &Q) -> DVector<Q> {
    let one = q(1, 1);
    let [c1, c2, d1, d2] = boundary_closed_forms(u, v);
    // P1..P4 = c1(0), c1(1), c2(0), c2(1).
    let (z, o) = (q(0, 1), q(1, 1));
    let [c1_0, c2_0, _, _] = boundary_closed_forms(&z, &z);
    let [c1_1, c2_1, _, _] = boundary_closed_forms(&o, &z);
    let p = [c1_0, c1_1, c2_0, c2_1];
    let rc = &c1 * (&one - v) + &c2 * v.clone();
    let rd = &d1 * (&one - u) + &d2 * u.clone();
    let rcd = &p[0] * ((&one - u) * (&one - v))
        + &p[1] * (u * (&one - v))
        + &p[2] * ((&one - u) * v)
        + &p[3] * (u * v);
    rc + rd - rcd
}

#[test]
fn coons_patch_of_four_b_splines_one_on_0_4_gives_the_right_point() {
    let (u, v) = (q(3, 8), q(1, 4));
    let expected = coons_closed_form(&u, &v);
    // By hand: c1(3/2) = (25/48, 0, 23/24), c2(3/8) = (3/4, 2, 15/32), d1(1/2) = (0, 13/16,
    // −9/16), d2(1/4) = (2, 1/2, 0), so x = (37/64, 89/128, 31/64).
    assert_eq!(expected, dvector![q(37, 64), q(89, 128), q(31, 64)]);

    // Exactly, in rationals.
    let [c1, c2, d1, d2] = b_spline_boundary::<Q>();
    assert_eq!(c1.domain(), (q(0, 1), q(4, 1)));
    assert_eq!(d1.domain(), (q(0, 1), q(2, 1)));
    let patch = CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::Exact).unwrap();
    assert_eq!(patch.eval(u.clone(), v.clone()), expected);
    for (a, b) in [
        (q(0, 1), q(0, 1)),
        (q(1, 1), q(1, 2)),
        (q(5, 6), q(1, 3)),
        (q(1, 8), q(1, 2)),
    ] {
        assert_eq!(patch.eval(a.clone(), b.clone()), coons_closed_form(&a, &b));
    }

    // In f64 (the old failure: "boundary curves do not meet at the corners … 9.17e-1").
    let [c1, c2, d1, d2] = b_spline_boundary::<f64>();
    let patch = CoonsPatch::new(c1.clone(), c2, d1, d2).unwrap();
    let x = patch.eval(0.375, 0.25);
    let want = expected.map(|x| x.to_f64());
    assert!((&x - &want).amax() <= 4.0 * f64::EPSILON, "{x} vs {want}");
    assert_eq!(want.as_slice(), &[0.578125, 0.6953125, 0.484375]);
    // The boundary x(u, 0) is c1 over its whole domain: c1(4u).
    for k in 0..=8 {
        let s = k as f64 / 8.0;
        assert!((patch.eval(s, 0.0) - c1.eval(4.0 * s)).amax() <= 4.0 * f64::EPSILON);
    }
    // The grid path reparametrises the same way.
    let mut out = [0.0; 3];
    patch.eval_grid_into(&[0.375], &[0.25], &mut out).unwrap();
    assert!((DVector::from_row_slice(&out) - &want).amax() <= 4.0 * f64::EPSILON);
    let grid = Surface::eval_grid(&patch, &[0.375], &[0.25]);
    assert!((DVector::from_iterator(3, grid.iter().copied()) - &want).amax() <= 4.0 * f64::EPSILON);
}

#[test]
fn every_coons_kind_and_gordon_reparametrise_the_same_boundary() {
    let (u, v) = (q(3, 8), q(1, 4));
    let expected = coons_closed_form(&u, &v);
    let [c1, c2, d1, d2] = b_spline_boundary::<Q>();
    let boundary = CoonsBoundary::new(
        c1.clone(),
        c2.clone(),
        d1.clone(),
        d2.clone(),
        Tolerance::Exact,
    )
    .unwrap();
    // The corners are the ends of the domains.
    assert_eq!(boundary.corners()[1], c1.eval(q(4, 1)));
    assert_eq!(boundary.corners()[2], d1.eval(q(2, 1)));
    let linear = GeneralizedCoonsPatch::from_boundary(
        boundary.clone(),
        BlendingPair::linear(),
        BlendingPair::linear(),
        0.0,
    )
    .unwrap();
    assert_eq!(linear.eval(u.clone(), v.clone()), expected);
    // Given corners are checked against the ends of the domains too.
    let corners = boundary.corners().clone();
    let with_corners = CoonsPatch::with_corners(
        c1.clone(),
        c2.clone(),
        d1.clone(),
        d2.clone(),
        corners,
        Tolerance::Exact,
    )
    .unwrap();
    assert_eq!(with_corners.eval(u.clone(), v.clone()), expected);
    // The partially bicubic patch interpolates the same (reparametrised) boundary.
    let pb =
        GeneralizedCoonsPatch::partially_bicubic(c1.clone(), c2.clone(), d1.clone(), d2.clone())
            .unwrap();
    for k in 0..=4 {
        let s = q(k, 4);
        assert_eq!(pb.eval(s.clone(), q(0, 1)), c1.eval(&s * q(4, 1)));
        assert_eq!(pb.eval(q(0, 1), s.clone()), d1.eval(&s * q(2, 1)));
    }
    // Gordon with nodes {0, 1} is the Coons patch.
    let z = vec![q(0, 1), q(1, 1)];
    let g =
        GordonSurface::with_tolerance(z.clone(), z, vec![d1, d2], vec![c1, c2], Tolerance::Exact)
            .unwrap();
    assert_eq!(g.eval(u, v), expected);
}

// ------------------------------------------------------------------------------------------
// Domains that cannot be reparametrised

type F = fn(f64) -> DVector<f64>;

fn unit_square_edges() -> [F; 4] {
    [
        |u| dvector![u, 0.0],
        |u| dvector![u, 1.0],
        |v| dvector![0.0, v],
        |v| dvector![1.0, v],
    ]
}

#[test]
fn a_domain_that_cannot_be_mapped_onto_the_unit_interval_is_refused_by_name() {
    let [c1, c2, d1, d2] = unit_square_edges().map(|f| FnCurve::new(2, f));
    let whole_line = FnCurve::new(2, unit_square_edges()[2])
        .with_domain(f64::NEG_INFINITY, f64::INFINITY)
        .unwrap();
    // Coons: the curve is named, with its domain.
    let err = CoonsPatch::new(c1.clone(), c2.clone(), whole_line.clone(), d2.clone()).unwrap_err();
    assert_eq!(
        err,
        Error::UnusableDomain {
            what: "Coons boundary curve d1",
            start: f64::NEG_INFINITY,
            end: f64::INFINITY,
        }
    );
    assert_eq!(
        err.to_string(),
        "Coons boundary curve d1: its domain [-inf, inf] cannot be mapped onto [0, 1] \
         (expected finite ends, start below end)"
    );
    // Not a corner mismatch, whatever the curve's values.
    assert!(!matches!(err, Error::CornerMismatch { .. }));
    let half_line = FnCurve::new(2, unit_square_edges()[0])
        .with_domain(0.0, f64::INFINITY)
        .unwrap();
    assert!(matches!(
        GeneralizedCoonsPatch::partially_bicubic(half_line, c2.clone(), d1.clone(), d2.clone()),
        Err(Error::UnusableDomain { what: "Coons boundary curve c1", start: 0.0, end, .. }) if end == f64::INFINITY
    ));
    // Ruled surfaces.
    assert!(matches!(
        RuledSurface::new(c1.clone(), whole_line.clone()),
        Err(Error::UnusableDomain {
            what: "ruled surface curve ²x",
            ..
        })
    ));
    // Gordon: a single-node interpolant has the one-point domain [1/2, 1/2].
    let constant =
        LagrangeInterpolant::new(Lagrange::new(vec![0.5]).unwrap(), dmatrix![0.0; 0.5]).unwrap();
    assert_eq!(constant.domain(), (0.5, 0.5));
    let line = |a: [f64; 2], b: [f64; 2]| {
        Box::new(BezierCurve::from_points(&[a, b]).unwrap()) as Box<dyn Curve>
    };
    let Err(err) = GordonSurface::new(
        vec![0.0, 1.0],
        vec![0.0, 1.0],
        vec![
            Box::new(constant) as Box<dyn Curve>,
            line([1.0, 0.0], [1.0, 1.0]),
        ],
        vec![line([0.0, 0.0], [1.0, 0.0]), line([0.0, 1.0], [1.0, 1.0])],
    ) else {
        panic!("a one-point domain was accepted")
    };
    assert_eq!(
        err,
        Error::UnusableDomain {
            what: "Gordon curve g(u_i, v)",
            start: 0.5,
            end: 0.5,
        }
    );
    // Cross-boundary curves of the bicubic patch (whose boundary curves need their
    // derivatives: each edge is a line, its derivative the chord).
    let [c1, c2, d1, d2] = unit_square_edges().map(|f| {
        let chord = f(1.0) - f(0.0);
        FnCurve::with_derivative(2, f, move |_: f64| chord.clone())
    });
    let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default()).unwrap();
    let zero: F = |_| dvector![0.0, 0.0];
    let cross = CrossDerivatives {
        du0: FnCurve::with_derivative(2, zero, zero)
            .with_domain(0.0, f64::INFINITY)
            .unwrap(),
        du1: FnCurve::with_derivative(2, zero, zero),
        dv0: FnCurve::with_derivative(2, zero, zero),
        dv1: FnCurve::with_derivative(2, zero, zero),
    };
    assert!(matches!(
        BicubicCoonsPatch::new(boundary, cross, Twist::Zero),
        Err(Error::UnusableDomain {
            what: "cross-boundary curve x_u(0,v)",
            ..
        })
    ));
    // The adaptor itself, and FnCurve's own domain checks.
    assert!(matches!(
        OnUnitInterval::new(whole_line, "that line"),
        Err(Error::UnusableDomain {
            what: "that line",
            ..
        })
    ));
    let f = unit_square_edges()[0];
    assert!(matches!(
        FnCurve::new(2, f).with_domain(1.0, 1.0),
        Err(Error::EmptyInterval { .. })
    ));
    assert!(matches!(
        FnCurve::new(2, f).with_domain(f64::NAN, 1.0),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn bicubic_coons_scales_boundary_tangents_by_the_domain_length() {
    // z = u·v on the unit square; c1 given on [0, 2] as t ↦ (t/2, 0, 0): its own tangent is
    // (1/2, 0, 0), the patch's x_u(u, 0) = (1, 0, 0) = 2 · (1/2, 0, 0).
    let c1 =
        BezierCurve::new_on_interval(dmatrix![0.0, 1.0; 0.0, 0.0; 0.0, 0.0], 0.0, 2.0).unwrap();
    let c2 = BezierCurve::new(dmatrix![0.0, 1.0; 1.0, 1.0; 0.0, 1.0]).unwrap();
    let d1 = BezierCurve::new(dmatrix![0.0, 0.0; 0.0, 1.0; 0.0, 0.0]).unwrap();
    // d2 on [−1, 1]: v ↦ (1, v, v) is s ↦ (1, (s+1)/2, (s+1)/2).
    let d2 =
        BezierCurve::new_on_interval(dmatrix![1.0, 1.0; 0.0, 1.0; 0.0, 1.0], -1.0, 1.0).unwrap();
    assert_eq!(c1.eval_derivative(0.0).as_slice(), &[0.5, 0.0, 0.0]);
    let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default()).unwrap();
    // x_u(0, v) = (1, 0, v), x_u(1, v) = (1, 0, v), x_v(u, 0) = (0, 1, u), x_v(u, 1) = (0, 1, u);
    // x_u(1, ·) given on [0, 4] in its own parameter: t ↦ (1, 0, t/4).
    let cross = CrossDerivatives {
        du0: BezierCurve::new(dmatrix![1.0, 1.0; 0.0, 0.0; 0.0, 1.0]).unwrap(),
        du1: BezierCurve::new_on_interval(dmatrix![1.0, 1.0; 0.0, 0.0; 0.0, 1.0], 0.0, 4.0)
            .unwrap(),
        dv0: BezierCurve::new(dmatrix![0.0, 0.0; 1.0, 1.0; 0.0, 1.0]).unwrap(),
        dv1: BezierCurve::new(dmatrix![0.0, 0.0; 1.0, 1.0; 0.0, 1.0]).unwrap(),
    };
    // The tangent check passes only with c1'(0) scaled by 2 (unscaled it is off by 1/2).
    for twist in [
        Twist::Given(std::array::from_fn(|_| dvector![0.0, 0.0, 1.0])),
        Twist::Gregory,
    ] {
        let patch = BicubicCoonsPatch::new(boundary.clone(), cross.clone(), twist).unwrap();
        for (u, v) in [(0.25, 0.5), (0.75, 0.125), (0.5, 0.5)] {
            assert!(
                (patch.eval(u, v) - dvector![u, v, u * v]).amax() < 1e-15,
                "({u}, {v})"
            );
            let d = patch.eval_partials(u, v).unwrap();
            assert!((d.xu - dvector![1.0, 0.0, v]).amax() < 1e-14);
            assert!((d.xv - dvector![0.0, 1.0, u]).amax() < 1e-14);
        }
    }
}

#[test]
fn gordon_network_of_curves_on_different_domains() {
    // The surface (u, v, uv) cut at u_i = 0, 1/2, 1 and v_j = 0, 1: the curves g(u_i, ·) as
    // lines on [0, 2] in their own parameter, g(·, v_j) as clamped B-splines on [0, 3].
    let at_u: Vec<BezierCurve> = [0.0, 0.5, 1.0]
        .iter()
        .map(|&ui| {
            BezierCurve::new_on_interval(dmatrix![ui, ui; 0.0, 1.0; 0.0, ui], 0.0, 2.0).unwrap()
        })
        .collect();
    let at_v: Vec<BSplineCurve> = [0.0, 1.0]
        .iter()
        .map(|&vj| {
            let k = vec![0.0, 0.0, 1.5, 3.0, 3.0];
            BSplineCurve::new(1, k, dmatrix![0.0, 0.5, 1.0; vj, vj, vj; 0.0, 0.5 * vj, vj]).unwrap()
        })
        .collect();
    let at_u: Vec<Box<dyn Curve>> = at_u
        .into_iter()
        .map(|c| Box::new(c) as Box<dyn Curve>)
        .collect();
    let at_v: Vec<Box<dyn Curve>> = at_v
        .into_iter()
        .map(|c| Box::new(c) as Box<dyn Curve>)
        .collect();
    let g = GordonSurface::new(vec![0.0, 0.5, 1.0], vec![0.0, 1.0], at_u, at_v).unwrap();
    assert_eq!(g.domain(), ((0.0, 1.0), (0.0, 1.0)));
    for (u, v) in [(0.3, 0.7), (0.5, 0.5), (1.0, 0.25), (0.0, 1.0)] {
        assert!(
            (g.eval(u, v) - dvector![u, v, u * v]).amax() < 1e-15,
            "({u}, {v})"
        );
    }
    let mut out = [0.0; 3];
    g.eval_grid_into(&[0.3], &[0.7], &mut out).unwrap();
    assert!((DVector::from_row_slice(&out) - dvector![0.3, 0.7, 0.21]).amax() < 1e-15);
}

#[test]
fn bezier_coons_of_curves_on_other_intervals_converts_exactly() {
    // Bézier boundaries on [2, 6] and [−1, 0]: the exact Bézier patch keeps their control points.
    let on =
        |m: DMatrix<Q>, a: i64, b: i64| BezierCurve::new_on_interval(m, q(a, 1), q(b, 1)).unwrap();
    let m = |rows: [[i64; 3]; 2]| DMatrix::from_fn(2, 3, |r, c| q(rows[r][c], 1));
    let c1 = on(m([[0, 1, 2], [0, -1, 0]]), 2, 6);
    let c2 = on(m([[0, 1, 2], [2, 3, 2]]), -1, 0);
    let d1 = on(m([[0, -1, 0], [0, 1, 2]]), 0, 1);
    let d2 = on(m([[2, 3, 2], [0, 1, 2]]), 2, 6);
    let coons = CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::Exact).unwrap();
    let patch = coons.to_bezier().unwrap();
    for (u, v) in [(q(1, 3), q(3, 4)), (q(0, 1), q(1, 2)), (q(5, 7), q(1, 1))] {
        assert_eq!(patch.eval(u.clone(), v.clone()), coons.eval(u, v));
    }
}

// ------------------------------------------------------------------------------------------
// One rule for eval and try_eval, type by type

/// Checks the rule of `cagd::param` on a curve: its domain; `try_eval` = `eval` bit for bit in
/// the domain (ends included); `ParameterOutOfRange` (naming the domain) just outside it,
/// `NonFinite` for NaN and ±∞; and `eval` outside the domain equal to the continued curve,
/// given as `(t, value)` pairs computed independently.
fn check_curve<C: Curve + ?Sized>(
    what: &str,
    c: &C,
    domain: (f64, f64),
    outside: &[(f64, DVector<f64>)],
) {
    let (a, b) = domain;
    assert_eq!(c.domain(), domain, "{what}: domain");
    for t in [a, 0.5 * (a + b), b] {
        assert_eq!(
            c.try_eval(t).unwrap(),
            c.eval(t),
            "{what}: try_eval = eval at {t}"
        );
    }
    let w = (b - a).max(1.0);
    for t in [a - 0.25 * w, b + 0.25 * w] {
        match c.try_eval(t) {
            Err(Error::ParameterOutOfRange {
                value, min, max, ..
            }) => {
                assert_eq!((value, min, max), (t, a, b), "{what}");
            }
            other => panic!("{what}: try_eval({t}) = {other:?}"),
        }
    }
    for t in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(
            matches!(c.try_eval(t), Err(Error::NonFinite { .. })),
            "{what}: {t}"
        );
    }
    for (t, x) in outside {
        assert!(*t < a || *t > b, "{what}: {t} is not outside");
        let e = c.eval(*t);
        assert!(
            (&e - x).amax() <= 1e-12 * x.amax().max(1.0),
            "{what}: eval({t}) = {e}, want {x}"
        );
    }
}

/// [`check_curve`] for surfaces, in both parameters.
fn check_surface<S: Surface + ?Sized>(what: &str, s: &S, outside: &[((f64, f64), DVector<f64>)]) {
    let unit = (0.0, 1.0);
    assert_eq!(s.domain(), (unit, unit), "{what}: domain");
    for (u, v) in [(0.0, 0.0), (1.0, 0.5), (0.25, 1.0)] {
        assert_eq!(
            s.try_eval(u, v).unwrap(),
            s.eval(u, v),
            "{what}: ({u}, {v})"
        );
    }
    for (u, v) in [(-0.25, 0.5), (0.5, 1.25)] {
        assert!(
            matches!(
                s.try_eval(u, v),
                Err(Error::ParameterOutOfRange {
                    min: 0.0,
                    max: 1.0,
                    ..
                })
            ),
            "{what}: ({u}, {v})"
        );
    }
    for (u, v) in [(f64::NAN, 0.5), (0.5, f64::INFINITY)] {
        assert!(
            matches!(s.try_eval(u, v), Err(Error::NonFinite { .. })),
            "{what}"
        );
    }
    for ((u, v), x) in outside {
        let e = s.eval(*u, *v);
        assert!(
            (&e - x).amax() <= 1e-12 * x.amax().max(1.0),
            "{what}: eval({u}, {v}) = {e}, want {x}"
        );
    }
}

#[test]
fn every_curve_type_follows_the_one_rule() {
    // Bézier t ↦ (t, t²) on [0, 1] and on [2, 6] (t = (u − 2)/4).
    let parabola = BezierCurve::new(dmatrix![0.0, 0.5, 1.0; 0.0, 0.0, 1.0]).unwrap();
    check_curve(
        "Bézier",
        &parabola,
        (0.0, 1.0),
        &[(2.0, dvector![2.0, 4.0]), (-1.0, dvector![-1.0, 1.0])],
    );
    let wide = parabola.clone().with_interval(2.0, 6.0).unwrap();
    check_curve(
        "Bézier on [2, 6]",
        &wide,
        (2.0, 6.0),
        &[(10.0, dvector![2.0, 4.0])],
    );
    // Its matrix form, and a monomial form given directly.
    check_curve(
        "matrix form",
        &wide.matrix_form(),
        (2.0, 6.0),
        &[(10.0, dvector![2.0, 4.0])],
    );
    let monomial = MatrixForm::from_coefficients(dmatrix![0.0, 1.0, 0.0; 0.0, 0.0, 1.0]).unwrap();
    check_curve(
        "monomial form",
        &monomial,
        (0.0, 1.0),
        &[(3.0, dvector![3.0, 9.0])],
    );

    // B-spline (u, u²) on the knots 0,0,0,1/2,1,1,1 (Greville abscissae 0, 1/4, 3/4, 1 for u;
    // 0, 0, 1/2, 1 for u² by inserting 1/2 into the Bézier 0, 0, 1): both pieces are the one
    // parabola, so the continued end pieces are too.
    let knots = vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    let control = dmatrix![0.0, 0.25, 0.75, 1.0; 0.0, 0.0, 0.5, 1.0];
    let bs = BSplineCurve::new(2, knots.clone(), control.clone()).unwrap();
    check_curve(
        "B-spline",
        &bs,
        (0.0, 1.0),
        &[(2.0, dvector![2.0, 4.0]), (-1.5, dvector![-1.5, 2.25])],
    );
    // Its derivative continues too: (1, 2u).
    assert!((CurveDeriv::eval_derivative(&bs, 2.0) - dvector![1.0, 4.0]).amax() < 1e-12);
    let uniform = BSplineCurve::uniform_cubic(&dmatrix![0.0, 1.0, 2.0], true).unwrap();
    check_curve("uniform cubic B-spline", &uniform, (0.0, 4.0), &[]);
    // NURBS with unit weights: the same parabola; the rational quarter circle (weights 1, √½,
    // 1) continued stays on the unit circle.
    let nurbs = NurbsCurve::new(2, knots, control, vec![1.0; 4]).unwrap();
    check_curve("NURBS", &nurbs, (0.0, 1.0), &[(2.0, dvector![2.0, 4.0])]);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let arc = NurbsCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        dmatrix![1.0, 1.0, 0.0; 0.0, 1.0, 1.0],
        vec![1.0, h, 1.0],
    )
    .unwrap();
    check_curve("NURBS arc", &arc, (0.0, 1.0), &[]);
    for t in [1.5, 2.0, -0.5] {
        assert!((arc.eval(t).norm() - 1.0).abs() < 1e-14, "{t}");
    }
    // Sampled: the end segments continue.
    let sampled =
        SampledCurve::new(vec![0.0, 1.0, 3.0], dmatrix![0.0, 1.0, 3.0; 0.0, 1.0, 5.0]).unwrap();
    check_curve(
        "sampled",
        &sampled,
        (0.0, 3.0),
        &[(4.0, dvector![4.0, 7.0]), (-1.0, dvector![-1.0, -1.0])],
    );
    // Closures: [0, 1] by default, or the domain given; the closure is the formula.
    let f: F = |t| dvector![t, t * t];
    check_curve(
        "FnCurve",
        &FnCurve::new(2, f),
        (0.0, 1.0),
        &[(2.0, dvector![2.0, 4.0])],
    );
    let g = FnCurve::new(2, f).with_domain(-1.0, 2.0).unwrap();
    check_curve(
        "FnCurve on [−1, 2]",
        &g,
        (-1.0, 2.0),
        &[(3.0, dvector![3.0, 9.0])],
    );
    // Hermite: x(0) = 0, x(1) = 1, x'(0) = 0, x'(1) = 3 is u³.
    let v1 = |x: f64| dvector![x];
    let cubic = HermiteCubic::new(v1(0.0), v1(1.0), v1(0.0), v1(3.0)).unwrap();
    check_curve(
        "Hermite",
        &cubic,
        (0.0, 1.0),
        &[(2.0, v1(8.0)), (-1.0, v1(-1.0))],
    );
    // Clamped cubic spline through t³ at 0, 1, 2 with the end tangents 0, 12: t³ itself.
    let spline = CubicSpline::interpolate_with_params(
        dmatrix![0.0, 1.0, 8.0],
        vec![0.0, 1.0, 2.0],
        EndCondition::Clamped {
            start: v1(0.0),
            end: v1(12.0),
        },
    )
    .unwrap();
    check_curve(
        "cubic spline",
        &spline,
        (0.0, 2.0),
        &[(3.0, v1(27.0)), (-1.0, v1(-1.0))],
    );
    // Lagrange: t² through 0, 1/2, 1; parametric interpolation of t³ at unordered parameters.
    let lagrange = LagrangeInterpolant::new(
        Lagrange::new(vec![0.0, 0.5, 1.0]).unwrap(),
        dmatrix![0.0, 0.25, 1.0],
    )
    .unwrap();
    check_curve("Lagrange", &lagrange, (0.0, 1.0), &[(2.0, v1(4.0))]);
    let params = vec![0.0, 0.5, 0.25, 1.0];
    let cube = DMatrix::from_fn(1, 4, |_, k| params[k] * params[k] * params[k]);
    let parametric = ParametricInterpolant::new(cube, params).unwrap();
    check_curve(
        "parametric interpolant",
        &parametric,
        (0.0, 1.0),
        &[(2.0, v1(8.0))],
    );
    // The unit view of the B-spline on [0, 4], references and boxes.
    let unit = OnUnitInterval::new(&uniform, "uniform").unwrap();
    check_curve("unit view", &unit, (0.0, 1.0), &[(1.25, uniform.eval(5.0))]);
    check_curve("&C", &&bs, (0.0, 1.0), &[(2.0, dvector![2.0, 4.0])]);
    let boxed: Box<dyn Curve> = Box::new(wide);
    check_curve(
        "Box<dyn Curve>",
        &boxed,
        (2.0, 6.0),
        &[(10.0, dvector![2.0, 4.0])],
    );
}

#[test]
fn every_surface_type_follows_the_one_rule() {
    // Everything below is the hyperbolic paraboloid (u, v, uv) (or its z), continued outside.
    let hp = |u: f64, v: f64| dvector![u, v, u * v];
    let far = [((2.0, -1.0), hp(2.0, -1.0)), ((-0.5, 3.0), hp(-0.5, 3.0))];
    check_surface(
        "Bézier patch",
        &BezierPatch::<f64>::hyperbolic_paraboloid(),
        &far,
    );
    let k = vec![0.0, 0.0, 1.0, 1.0];
    let coords = vec![
        dmatrix![0.0, 0.0; 1.0, 1.0],
        dmatrix![0.0, 1.0; 0.0, 1.0],
        dmatrix![0.0, 0.0; 0.0, 1.0],
    ];
    let bs = BSplineSurface::new(1, 1, k.clone(), k.clone(), coords.clone()).unwrap();
    check_surface("B-spline surface", &bs, &far);
    let ns =
        NurbsSurface::new(1, 1, k.clone(), k, coords, DMatrix::from_element(2, 2, 1.0)).unwrap();
    check_surface("NURBS surface", &ns, &far);
    // Coons, generalized, bicubic, Gordon and ruled surfaces of its boundary lines: they
    // reproduce the bilinear surface, and continue it.
    let line = |a: [f64; 3], b: [f64; 3]| BezierCurve::from_points(&[a, b]).unwrap();
    let (p1, p2, p3, p4) = (
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 1.0],
    );
    let edges = || (line(p1, p2), line(p3, p4), line(p1, p3), line(p2, p4));
    let (c1, c2, d1, d2) = edges();
    check_surface("Coons", &CoonsPatch::new(c1, c2, d1, d2).unwrap(), &far);
    let (c1, c2, d1, d2) = edges();
    let generalized = GeneralizedCoonsPatch::new(
        c1,
        c2,
        d1,
        d2,
        BlendingPair::linear(),
        BlendingPair::linear(),
    )
    .unwrap();
    check_surface("generalized Coons", &generalized, &far);
    let (c1, c2, d1, d2) = edges();
    let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default()).unwrap();
    let cross = CrossDerivatives {
        du0: line([1.0, 0.0, 0.0], [1.0, 0.0, 1.0]),
        du1: line([1.0, 0.0, 0.0], [1.0, 0.0, 1.0]),
        dv0: line([0.0, 1.0, 0.0], [0.0, 1.0, 1.0]),
        dv1: line([0.0, 1.0, 0.0], [0.0, 1.0, 1.0]),
    };
    let twist = Twist::Given(std::array::from_fn(|_| dvector![0.0, 0.0, 1.0]));
    let bicubic = BicubicCoonsPatch::new(boundary, cross, twist).unwrap();
    check_surface("bicubic Coons", &bicubic, &far);
    let (c1, c2, d1, d2) = edges();
    let z = vec![0.0, 1.0];
    let gordon = GordonSurface::new(z.clone(), z, vec![d1, d2], vec![c1, c2]).unwrap();
    check_surface("Gordon", &gordon, &far);
    // The ruled surface between c1 and c2, with c2 given on [−1, 1]: x(u, v) = (u, v, uv).
    let (c1, c2, _, _) = edges();
    let c2 = c2.with_interval(-1.0, 1.0).unwrap();
    check_surface("ruled", &RuledSurface::new(c1, c2).unwrap(), &far);
    // Ferguson (Hermite bicubic) data of the same surface, and its Bézier bicubic net.
    let v = |x: f64, y: f64, z: f64| dvector![x, y, z];
    let x = [
        [v(0., 0., 0.), v(0., 1., 0.)],
        [v(1., 0., 0.), v(1., 1., 1.)],
    ];
    let du = [
        [v(1., 0., 0.), v(1., 0., 1.)],
        [v(1., 0., 0.), v(1., 0., 1.)],
    ];
    let dv = [
        [v(0., 1., 0.), v(0., 1., 0.)],
        [v(0., 1., 1.), v(0., 1., 1.)],
    ];
    let tw = [
        [v(0., 0., 1.), v(0., 0., 1.)],
        [v(0., 0., 1.), v(0., 0., 1.)],
    ];
    check_surface(
        "Ferguson",
        &FergusonPatch::new(&x, &du, &dv, &tw).unwrap(),
        &far,
    );
    let third = |i: usize| i as f64 / 3.0;
    let bezier_net = vec![
        DMatrix::from_fn(4, 4, |i, _| third(i)),
        DMatrix::from_fn(4, 4, |_, j| third(j)),
        DMatrix::from_fn(4, 4, |i, j| third(i) * third(j)),
    ];
    let matrix_patch = CubicMatrixPatch::new(CubicForm::Bezier, bezier_net).unwrap();
    check_surface("bicubic matrix patch", &matrix_patch, &far);
}

// ------------------------------------------------------------------------------------------
// Reparametrisation keeps corners and boundaries interpolated (exactly, in rationals)

fn coordinate() -> impl Strategy<Value = Q> {
    (-32i64..=32).prop_map(|n| q(n, 4))
}

fn point() -> impl Strategy<Value = DVector<Q>> {
    proptest::collection::vec(coordinate(), 3).prop_map(DVector::from_vec)
}

/// An interval `[a, b]` with integer ends, `a < b`.
fn interval() -> impl Strategy<Value = (Q, Q)> {
    (-5i64..=5, 1i64..=6).prop_map(|(a, w)| (q(a, 1), q(a + w, 1)))
}

/// A Bézier curve from `p` to `r` on `[a, b]` with up to two random inner control points.
fn bezier_between(
    p: DVector<Q>,
    r: DVector<Q>,
    inner: Vec<DVector<Q>>,
    (a, b): (Q, Q),
) -> Box<dyn Curve<Q>> {
    let mut points = vec![p];
    points.extend(inner);
    points.push(r);
    let m = DMatrix::from_fn(3, points.len(), |row, col| points[col][row].clone());
    Box::new(BezierCurve::new_on_interval(m, a, b).unwrap())
}

/// The uniform cubic B-spline with replicated ends from `p` over `inner` to `r` (domain
/// `[0, inner.len() + 1]`).
fn uniform_between(p: DVector<Q>, r: DVector<Q>, inner: Vec<DVector<Q>>) -> Box<dyn Curve<Q>> {
    let mut points = vec![p];
    points.extend(inner);
    points.push(r);
    let m = DMatrix::from_fn(3, points.len(), |row, col| points[col][row].clone());
    Box::new(BSplineCurve::uniform_cubic(&m, true).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn reparametrised_boundaries_are_interpolated(
        corners in proptest::collection::vec(point(), 4),
        inner in proptest::collection::vec(proptest::collection::vec(point(), 0..=2), 4),
        intervals in proptest::collection::vec(interval(), 4),
        b_spline_c1 in any::<bool>(),
    ) {
        let p = |k: usize| corners[k].clone();
        let c1 = if b_spline_c1 {
            uniform_between(p(0), p(1), inner[0].clone())
        } else {
            bezier_between(p(0), p(1), inner[0].clone(), intervals[0].clone())
        };
        let curves = [
            c1,
            bezier_between(p(2), p(3), inner[1].clone(), intervals[1].clone()),
            bezier_between(p(0), p(2), inner[2].clone(), intervals[2].clone()),
            bezier_between(p(1), p(3), inner[3].clone(), intervals[3].clone()),
        ];
        // The curves' own parameter of the unit parameter s: a + (b − a)s.
        let at = |c: &dyn Curve<Q>, s: &Q| {
            let (a, b) = c.domain();
            c.eval(a.clone() + (b - a) * s.clone())
        };
        let [c1, c2, d1, d2] = curves;
        let expected = |s: &Q| [at(&*c1, s), at(&*c2, s), at(&*d1, s), at(&*d2, s)];
        let samples: Vec<Q> = (0..=6).map(|k| q(k, 6)).collect();
        let want: Vec<_> = samples.iter().map(expected).collect();
        let patch = CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::Exact).unwrap();
        let (zero, one) = (q(0, 1), q(1, 1));
        prop_assert_eq!(patch.eval(zero.clone(), zero.clone()), p(0));
        prop_assert_eq!(patch.eval(one.clone(), zero.clone()), p(1));
        prop_assert_eq!(patch.eval(zero.clone(), one.clone()), p(2));
        prop_assert_eq!(patch.eval(one.clone(), one.clone()), p(3));
        for (s, [c1s, c2s, d1s, d2s]) in samples.iter().zip(&want) {
            prop_assert_eq!(&patch.eval(s.clone(), zero.clone()), c1s);
            prop_assert_eq!(&patch.eval(s.clone(), one.clone()), c2s);
            prop_assert_eq!(&patch.eval(zero.clone(), s.clone()), d1s);
            prop_assert_eq!(&patch.eval(one.clone(), s.clone()), d2s);
        }
        // The grid path, along the edge v = 0.
        let mut out = vec![q(0, 1); samples.len() * 3];
        patch.eval_grid_into(&samples, &[zero], &mut out).unwrap();
        for (k, [c1s, ..]) in want.iter().enumerate() {
            prop_assert_eq!(&out[3 * k..3 * k + 3], c1s.as_slice());
        }
    }
}
