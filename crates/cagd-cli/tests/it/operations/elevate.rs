//! Degree elevation: a clamped B-spline raised as octave-nurbs' `nrbdegelev` raises it, and the
//! work priced by the core (a large Bézier curve allowed, a B-spline of the same size refused).

use cagd_ops::bspline_arg::{BSplineArg, SplineDegree};
use cagd_ops::ops::Elevate;
use cagd_ops::{execute, Context, Kind, Role};
use nalgebra::DMatrix;
use num_rational::BigRational;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

#[test]
fn a_clamped_quadratic_raised_to_a_cubic_as_nrbdegelev() {
    let control = DMatrix::from_row_slice(2, 4, &[0, 1, 3, 4, 0, 2, 2, 0].map(|x| q(x, 1)));
    let knots = [0, 0, 0, 1, 2, 2, 2].map(|x| q(x, 2)).to_vec();
    let op = Elevate {
        bspline: Some(BSplineArg {
            degree: SplineDegree::Degree(2),
            knots: Some(knots),
        }),
        ..Elevate::new(control)
    };
    let answer = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
    let knots = answer.report.matrix("knots").unwrap();
    assert_eq!(
        knots.iter().cloned().collect::<Vec<_>>(),
        [0, 0, 0, 0, 1, 1, 2, 2, 2, 2].map(|x| q(x, 2))
    );
    let control = answer.report.matrix("control").unwrap();
    assert_eq!(
        control.row(0).iter().cloned().collect::<Vec<_>>(),
        [q(0, 1), q(2, 3), q(4, 3), q(8, 3), q(10, 3), q(4, 1)]
    );
}

#[test]
fn elevation_is_priced_by_the_core() {
    let mut cx = Context::new(cagd::Limits::default());
    // A Bézier curve of degree 899 by 99: some 10⁶ operations, allowed.
    let bezier = Elevate {
        by: 99,
        ..Elevate::new(DMatrix::<f64>::zeros(3, 900))
    };
    let answer = execute(&bezier, &mut cx).unwrap();
    assert_eq!(answer.report.matrix("control").unwrap().ncols(), 999);
    // The blossoms of a cubic B-spline of 900 control points by 99: 5.7·10⁹, refused.
    let spline = Elevate {
        bspline: Some(BSplineArg {
            degree: SplineDegree::Degree(3),
            knots: None,
        }),
        ..bezier
    };
    let e = execute(&spline, &mut cx).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::By, Kind::Limit));
}
