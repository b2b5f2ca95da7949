//! Derivatives of a Bézier curve on an interval.

use cagd_ops::ops::Derivative;
use cagd_ops::{Context, Params};
use nalgebra::DMatrix;

#[test]
fn on_an_interval_the_derivative_scales_by_its_length() {
    // x(t) = t on [0, 1/2] as the line from 0 to 1/2 on [0, 1/2]: x' = 1, so on the
    // interval the derivative's control points are 2 · Δb = 2 · 1/2 = 1.
    let op = Derivative {
        interval: Some((0.0, 0.5)),
        t: Some(Params::Given(vec![0.25])),
        ..Derivative::new(DMatrix::from_row_slice(1, 2, &[0.0, 0.5]), 1)
    };
    let answer = cagd_ops::execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
    assert_eq!(answer.report.matrix("control").unwrap().as_slice(), &[1.0]);
    assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[1.0]);
}
