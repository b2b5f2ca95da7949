//! Bad input to the course constructions gives typed errors, never a panic.

use cagd::bspline::{find_span, BSplineCurve, BSplineSurface, KnotVector};
use cagd::interpolation::{blending_matrix, LagrangePolynomial, PiecewiseLinear};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::spline::{CubicSpline, EndCondition};
use cagd::{Error, HermiteCubic};
use nalgebra::{DMatrix, DVector};

fn pts(d: usize, n: usize) -> DMatrix<f64> {
    DMatrix::from_fn(d, n, |r, c| (r * 3 + c) as f64)
}

#[test]
fn decreasing_knots() {
    let e = BSplineCurve::new(1, vec![0.0, 0.0, 0.7, 0.5, 1.0, 1.0], pts(2, 4)).unwrap_err();
    assert_eq!(
        e,
        Error::DecreasingKnots {
            what: "knot vector",
            index: 3,
            previous: 0.7,
            next: 0.5
        }
    );
    assert!(matches!(
        KnotVector::new(vec![1.0, 0.0]),
        Err(Error::DecreasingKnots { index: 1, .. })
    ));
    assert!(matches!(
        BSplineSurface::new(
            1,
            1,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 1.0, 0.5, 1.0],
            vec![DMatrix::zeros(2, 2)]
        ),
        Err(Error::DecreasingKnots { index: 2, .. })
    ));
    assert!(matches!(
        KnotVector::new(vec![0.0, f64::NAN]),
        Err(Error::NonFinite { index: 1, .. })
    ));
}

#[test]
fn too_few_control_points_for_the_degree() {
    let e = BSplineCurve::clamped(3, pts(2, 3)).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooFewControlPoints {
                degree: 3,
                min: 4,
                found: 3,
                ..
            }
        ),
        "{e:?}"
    );
    let e = BSplineCurve::new(2, vec![0.0, 0.0, 1.0, 1.0], pts(2, 2)).unwrap_err();
    assert!(matches!(
        e,
        Error::TooFewControlPoints {
            degree: 2,
            min: 3,
            found: 2,
            ..
        }
    ));
    assert!(matches!(
        BSplineCurve::uniform_cubic(&pts(2, 3), false),
        Err(Error::TooFewControlPoints { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(2, vec![0.0; 4], pts(2, 1), vec![1.0]),
        Err(Error::TooFewControlPoints { .. })
    ));
}

#[test]
fn wrong_knot_count_and_empty_domain() {
    let e = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], pts(2, 3)).unwrap_err();
    assert_eq!(
        e,
        Error::KnotCount {
            what: "B-spline curve",
            expected: 5,
            found: 4
        }
    );
    let e = BSplineCurve::new(1, vec![0.0, 1.0, 1.0, 1.0, 2.0], pts(2, 3)).unwrap_err();
    assert!(matches!(e, Error::EmptyInterval { .. }), "{e:?}");
}

#[test]
fn zero_or_negative_weights() {
    let k = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    for (w, index) in [(vec![1.0, 0.0, 1.0], 1), (vec![-1.0, 1.0, 1.0], 0)] {
        let e = NurbsCurve::new(2, k.clone(), pts(2, 3), w.clone()).unwrap_err();
        assert_eq!(
            e,
            Error::NonPositiveWeight {
                what: "NURBS curve weights",
                index,
                value: w[index]
            }
        );
    }
    assert!(matches!(
        NurbsCurve::new(2, k.clone(), pts(2, 3), vec![1.0, 1.0]),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(matches!(
        cagd::nurbs::conic_arc(pts(2, 3), 0.0),
        Err(Error::NonPositiveWeight { .. })
    ));
    let kk = vec![0.0, 0.0, 1.0, 1.0];
    let w = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, -2.0]);
    assert!(matches!(
        NurbsSurface::new(1, 1, kk.clone(), kk, vec![DMatrix::zeros(2, 2)], w),
        Err(Error::NonPositiveWeight { index: 3, value, .. }) if value == -2.0
    ));
    assert!(matches!(
        NurbsCurve::arc(-1.0, &[0.0, 0.0], 0.0, 1.0),
        Err(Error::InvalidArgument { .. })
    ));
    // More than one full turn: nrbcirc's weights would turn negative (found by proptest).
    assert!(matches!(
        NurbsCurve::arc(0.1, &[0.0, 0.0], -6.079064392945602, 6.8378250569240775),
        Err(Error::InvalidArgument {
            what: "circular arc",
            ..
        })
    ));
    assert!(NurbsCurve::arc(1.0, &[0.0, 0.0], 1.0, 1.0 + 2.0 * std::f64::consts::PI).is_ok());
}

#[test]
fn parameter_outside_the_knot_span() {
    let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 2.0, 2.0, 2.0], pts(2, 4)).unwrap();
    for u in [-0.1, 2.5] {
        assert!(
            matches!(c.try_eval(u), Err(Error::ParameterOutOfRange { min, max, .. }) if min == 0.0 && max == 2.0),
            "{u}"
        );
        assert!(c.de_boor(u).is_err());
    }
    // A NaN parameter is refused as every non-finite parameter is (the rule of cagd::param).
    assert!(matches!(c.try_eval(f64::NAN), Err(Error::NonFinite { .. })));
    assert!(c.de_boor(f64::NAN).is_err());
    assert!(matches!(
        find_span(1, 2, &[0.0, 1.0, 2.0, 3.0], &0.5),
        Err(Error::ParameterOutOfRange { .. })
    ));
    assert!(matches!(
        c.insert_knot(2.0),
        Err(Error::ParameterOutOfRange { .. })
    ));
    assert!(matches!(
        c.insert_knots(&[1.0, 1.0, 1.0, 1.0]),
        Err(Error::InvalidArgument { .. })
    ));
    let h = NurbsCurve::from_bspline(&c);
    assert!(matches!(
        h.try_eval(3.0),
        Err(Error::ParameterOutOfRange { .. })
    ));
    // The Curve trait continues the last polynomial piece instead (the rule of cagd::param).
    // On the span [1/2, 2] of the knots 0,0,0,1/2,2,2,2 the basis is (2−u)²/3,
    // (2−u)(u/3 + (u − 1/2)/(9/4)), ((u − 1/2)/(3/2))²: at u = 5 that is 3, −11, 9, so the
    // point is 3·(1,4) − 11·(2,5) + 9·(3,6) = (8, 11).
    use cagd::Curve;
    let far = Curve::eval(&c, 5.0);
    assert!((far - nalgebra::dvector![8.0, 11.0]).amax() < 1e-12);
    assert!(Curve::eval(&c, f64::NAN).iter().all(|x| x.is_nan()));
    let s = BSplineSurface::clamped(1, 1, vec![DMatrix::zeros(2, 2)]).unwrap();
    assert!(matches!(
        s.try_eval(0.5, 1.5),
        Err(Error::ParameterOutOfRange { .. })
    ));
    assert!(matches!(
        BSplineCurve::new(0, vec![0.0, 1.0], pts(1, 1))
            .unwrap()
            .derivative(),
        Err(Error::DerivativeOrder { .. })
    ));
}

#[test]
fn too_few_spline_points() {
    let two = pts(2, 2);
    assert!(CubicSpline::interpolate(two.clone(), EndCondition::Natural).is_ok());
    let e = CubicSpline::interpolate(pts(2, 1), EndCondition::Natural).unwrap_err();
    assert_eq!(
        e,
        Error::TooFewPoints {
            what: "interpolating spline",
            min: 2,
            found: 1
        }
    );
    let e = CubicSpline::interpolate(two, EndCondition::Closed).unwrap_err();
    assert_eq!(
        e,
        Error::TooFewPoints {
            what: "interpolating spline",
            min: 3,
            found: 2
        }
    );
    assert!(CubicSpline::interpolate(pts(2, 3), EndCondition::Closed).is_ok());
    let clamped = EndCondition::Clamped {
        start: DVector::zeros(3),
        end: DVector::zeros(2),
    };
    assert!(matches!(
        CubicSpline::interpolate(pts(2, 3), clamped),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(matches!(
        CubicSpline::interpolate_with_params(pts(2, 3), vec![0.0, 1.0, 1.0], EndCondition::Natural),
        Err(Error::InvalidArgument { .. })
    ));
    assert!(matches!(
        CubicSpline::interpolate_with_params(pts(2, 3), vec![0.0, 1.0], EndCondition::Natural),
        Err(Error::ShapeMismatch { .. })
    ));
}

#[test]
fn interpolation_and_hermite_errors() {
    // Repeated nodes are `DuplicateNodes` (naming both), as everywhere else the Lagrange basis
    // is used: the lecture notes' interpolation shares the node check of `cagd::lagrange`.
    assert!(matches!(
        LagrangePolynomial::new(vec![1.0, 1.0], vec![0.0, 1.0]),
        Err(Error::DuplicateNodes {
            first: 0,
            second: 1,
            ..
        })
    ));
    assert!(matches!(
        LagrangePolynomial::new(vec![1.0], vec![0.0, 1.0]),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(matches!(
        blending_matrix(&[0.0, 0.5, 0.5]),
        Err(Error::DuplicateNodes {
            first: 1,
            second: 2,
            ..
        })
    ));
    assert!(matches!(
        PiecewiseLinear::new(vec![0.0], vec![1.0]),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        HermiteCubic::from_geometry(DMatrix::<f64>::zeros(2, 3)),
        Err(Error::ShapeMismatch { .. })
    ));
    let bez = cagd::BezierCurve::from_points(&[[0.0], [1.0], [2.0]]).unwrap();
    assert!(matches!(
        HermiteCubic::from_bezier(&bez),
        Err(Error::InvalidArgument { .. })
    ));
}
