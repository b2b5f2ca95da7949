//! Bad input to the Bézier core returns the specific `Error` variant, with its data, and never
//! panics.

use cagd::bezier::{bilinear_interpolate, BezierCurve, BezierPatch, MatrixForm};
use cagd::Error;
use nalgebra::DMatrix;

fn cubic() -> BezierCurve {
    BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]).unwrap()
}

fn patch_2_5() -> BezierPatch {
    let coords = (0..3)
        .map(|k| DMatrix::from_fn(3, 6, |i, j| (i * 6 + j + k) as f64))
        .collect();
    BezierPatch::new(coords).unwrap()
}

// --- no control points -----------------------------------------------------------------------

#[test]
fn curve_without_control_points() {
    assert_eq!(
        BezierCurve::new(DMatrix::<f64>::zeros(3, 0)),
        Err(Error::TooFewPoints {
            what: "Bézier curve control points",
            min: 1,
            found: 0
        })
    );
    let none: &[[f64; 2]] = &[];
    assert!(matches!(
        BezierCurve::from_points(none),
        Err(Error::TooFewPoints {
            min: 1,
            found: 0,
            ..
        })
    ));
    assert!(matches!(
        MatrixForm::from_coefficients(DMatrix::<f64>::zeros(2, 0)),
        Err(Error::TooFewPoints { found: 0, .. })
    ));
}

#[test]
fn curve_without_coordinates() {
    assert!(matches!(
        BezierCurve::new(DMatrix::<f64>::zeros(0, 3)),
        Err(Error::ShapeMismatch { .. })
    ));
    let empty_points: &[Vec<f64>] = &[vec![], vec![]];
    assert!(matches!(
        BezierCurve::from_points(empty_points),
        Err(Error::ShapeMismatch { .. })
    ));
}

#[test]
fn patch_without_control_points() {
    assert!(matches!(
        BezierPatch::<f64>::new(vec![]),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(matches!(
        BezierPatch::new(vec![DMatrix::<f64>::zeros(0, 3)]),
        Err(Error::TooFewPoints { found: 0, .. })
    ));
    let no_rows: &[Vec<[f64; 3]>] = &[];
    assert!(matches!(
        BezierPatch::from_net(no_rows),
        Err(Error::TooFewPoints { found: 0, .. })
    ));
    let empty_row: &[Vec<[f64; 3]>] = &[vec![]];
    assert!(matches!(
        BezierPatch::from_net(empty_row),
        Err(Error::TooFewPoints { found: 0, .. })
    ));
    assert!(matches!(
        BezierPatch::from_grid(&cagd::grid::PointGrid::<f64>::from_elem((0, 2, 3), 0.0)),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        BezierPatch::from_grid(&cagd::grid::PointGrid::<f64>::from_elem((2, 2, 0), 0.0)),
        Err(Error::ShapeMismatch { .. })
    ));
}

// --- ragged input ----------------------------------------------------------------------------

#[test]
fn ragged_curve_points() {
    let err = BezierCurve::from_points(&[vec![0.0, 0.0, 0.0], vec![1.0, 1.0], vec![2.0, 0.0, 1.0]])
        .unwrap_err();
    match err {
        Error::ShapeMismatch {
            what,
            expected,
            found,
        } => {
            assert_eq!(what, "Bézier curve control points");
            assert!(expected.contains('3'), "{expected}");
            assert!(found.contains("point 1"), "{found}");
        }
        other => panic!("expected ShapeMismatch, got {other:?}"),
    }
}

#[test]
fn ragged_patch_nets() {
    // Rows of different lengths.
    let net = vec![vec![[0.0, 0.0], [0.0, 1.0]], vec![[1.0, 0.0]]];
    let err = BezierPatch::from_net(&net).unwrap_err();
    assert!(
        matches!(&err, Error::ShapeMismatch { found, .. } if found.contains("row 1")),
        "{err:?}"
    );
    // Points of different dimensions.
    let net = vec![
        vec![vec![0.0, 0.0], vec![0.0, 1.0]],
        vec![vec![1.0, 0.0], vec![1.0]],
    ];
    let err = BezierPatch::from_net(&net).unwrap_err();
    assert!(
        matches!(&err, Error::ShapeMismatch { found, .. } if found.contains("(1, 1)")),
        "{err:?}"
    );
    // Coordinate matrices of different shapes.
    let err =
        BezierPatch::new(vec![DMatrix::<f64>::zeros(2, 3), DMatrix::zeros(3, 2)]).unwrap_err();
    assert!(
        matches!(&err, Error::ShapeMismatch { found, .. } if found.contains("coordinate 1")),
        "{err:?}"
    );
    // Bilinear corners of different dimensions.
    assert!(matches!(
        BezierPatch::bilinear(&[0.0, 0.0], &[0.0, 1.0, 0.0], &[1.0, 0.0], &[1.0, 1.0]),
        Err(Error::ShapeMismatch {
            what: "bilinear corner b01",
            ..
        })
    ));
    assert!(matches!(
        bilinear_interpolate(&[0.0], &[0.0], &[1.0], &[], 0.5, 0.5),
        Err(Error::ShapeMismatch {
            what: "bilinear corner b11",
            ..
        })
    ));
}

// --- NaN / Inf -------------------------------------------------------------------------------

#[test]
fn non_finite_curve_coordinates() {
    let mut control = DMatrix::from_element(2, 3, 1.0);
    control[(1, 2)] = f64::NAN;
    match BezierCurve::new(control).unwrap_err() {
        Error::NonFinite { index, value, .. } => {
            assert_eq!(index, 5); // column-major, as Octave counts
            assert!(value.is_nan());
        }
        other => panic!("expected NonFinite, got {other:?}"),
    }
    let err = BezierCurve::from_points(&[[0.0, 0.0], [f64::INFINITY, 1.0]]).unwrap_err();
    assert_eq!(
        err,
        Error::NonFinite {
            what: "Bézier curve control points",
            index: 2,
            value: f64::INFINITY
        }
    );
    assert!(matches!(
        BezierCurve::from_points(&[[f64::NEG_INFINITY]]),
        Err(Error::NonFinite { index: 0, .. })
    ));
}

#[test]
fn non_finite_patch_coordinates() {
    let net = vec![
        vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        vec![[1.0, 0.0, 0.0], [1.0, 1.0, f64::NAN]],
    ];
    assert!(matches!(
        BezierPatch::from_net(&net),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        BezierPatch::bilinear(&[0.0], &[f64::INFINITY], &[1.0], &[1.0]),
        Err(Error::NonFinite {
            what: "bilinear corner b01",
            ..
        })
    ));
}

#[test]
fn non_finite_parameters() {
    let c = cubic();
    assert!(matches!(c.try_eval(f64::NAN), Err(Error::NonFinite { .. })));
    assert!(matches!(
        c.eval_many(&[0.0, 0.5, f64::INFINITY]),
        Err(Error::NonFinite { index: 2, .. })
    ));
    assert!(matches!(
        c.subdivide(f64::NAN),
        Err(Error::NonFinite { .. })
    ));
    let p = patch_2_5();
    assert!(matches!(
        p.try_eval(0.5, f64::NAN),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        p.try_eval_grid(&[0.0, f64::NAN], &[0.5]),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        bilinear_interpolate(&[0.0], &[0.0], &[1.0], &[1.0], f64::INFINITY, 0.5),
        Err(Error::NonFinite { .. })
    ));
    // The unchecked evaluators do not panic: NaN in, NaN out.
    assert!(c.eval(f64::NAN).iter().all(|x| x.is_nan()));
    assert!(p.eval(f64::NAN, 0.5).iter().all(|x| x.is_nan()));
}

// --- derivative order above the degree -------------------------------------------------------

#[test]
fn derivative_order_above_degree() {
    assert_eq!(
        cubic().derivative(4),
        Err(Error::DerivativeOrder {
            order: 4,
            degree: 3
        })
    );
    assert!(cubic().derivative(3).is_ok());
    let point = BezierCurve::from_points(&[[1.0, 2.0]]).unwrap();
    assert_eq!(
        point.hodograph(),
        Err(Error::DerivativeOrder {
            order: 1,
            degree: 0
        })
    );
    let p = patch_2_5();
    assert_eq!(
        p.derivative(3, 0),
        Err(Error::DerivativeOrder {
            order: 3,
            degree: 2
        })
    );
    assert_eq!(
        p.derivative(0, 6),
        Err(Error::DerivativeOrder {
            order: 6,
            degree: 5
        })
    );
    assert!(p.derivative(2, 5).is_ok());
    let flat = BezierPatch::new(vec![DMatrix::from_element(1, 4, 1.0)]).unwrap();
    assert_eq!(
        flat.twist(),
        Err(Error::DerivativeOrder {
            order: 1,
            degree: 0
        })
    );
}

// --- empty parameter lists and grids ---------------------------------------------------------

#[test]
fn empty_parameter_lists() {
    assert_eq!(
        cubic().eval_many(&[]),
        Err(Error::EmptyGrid {
            what: "Bézier curve parameters",
            min: 1,
            found: 0
        })
    );
    let p = patch_2_5();
    assert_eq!(
        p.try_eval_grid(&[], &[0.5]),
        Err(Error::EmptyGrid {
            what: "Bézier patch u grid",
            min: 1,
            found: 0
        })
    );
    assert_eq!(
        p.try_eval_grid(&[0.5], &[]),
        Err(Error::EmptyGrid {
            what: "Bézier patch v grid",
            min: 1,
            found: 0
        })
    );
}

// --- bad intervals ---------------------------------------------------------------------------

#[test]
fn degenerate_intervals() {
    let control = DMatrix::from_element(2, 3, 1.0);
    assert_eq!(
        BezierCurve::new_on_interval(control.clone(), 1.0, 1.0),
        Err(Error::EmptyInterval {
            what: "Bézier curve interval",
            a: 1.0,
            b: 1.0
        })
    );
    assert!(matches!(
        BezierCurve::new_on_interval(control.clone(), 2.0, -1.0),
        Err(Error::EmptyInterval { a, b, .. }) if a == 2.0 && b == -1.0
    ));
    assert!(matches!(
        BezierCurve::new_on_interval(control, f64::NAN, 1.0),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        cubic().with_interval(0.0, f64::INFINITY),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        cubic().with_interval(3.0, 3.0),
        Err(Error::EmptyInterval { .. })
    ));
    // Subdividing at an end (or outside) would leave an empty half.
    let c = cubic().with_interval(1.0, 2.0).unwrap();
    assert!(matches!(
        c.subdivide(1.0),
        Err(Error::EmptyInterval { a, b, .. }) if a == 1.0 && b == 1.0
    ));
    assert!(matches!(
        c.subdivide(2.5),
        Err(Error::EmptyInterval { a, b, .. }) if a == 2.5 && b == 2.0
    ));
}

#[test]
fn error_messages_name_the_problem() {
    let err = cubic().derivative(7).unwrap_err();
    assert_eq!(err.to_string(), "derivative order 7 exceeds the degree 3");
    let err = cubic().eval_many(&[]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "Bézier curve parameters: expected at least 1 parameter value(s), got 0"
    );
}
