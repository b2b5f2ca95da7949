//! Conversions between the cubic forms: Bézier points as monomial coefficients, a wrong size
//! refused about the geometry.

use cagd::conversion::GeometryForm;
use cagd_ops::ops::Convert;
use cagd_ops::{execute, Context, Kind, Role};
use nalgebra::DMatrix;
use num_rational::BigRational;

fn m(rows: usize, values: &[i64]) -> DMatrix<BigRational> {
    let values: Vec<BigRational> = values
        .iter()
        .map(|&x| BigRational::from_integer(x.into()))
        .collect();
    DMatrix::from_row_slice(rows, values.len() / rows, &values)
}

#[test]
fn bezier_points_as_monomial_coefficients_the_matrix_form_notes_p_times_m() {
    // b = (0,0), (1,1), (2,0), (3,1): x = 3t, y = 3t − 6t² + 4t³.
    let op = Convert::new(
        m(2, &[0, 1, 2, 3, 0, 1, 0, 1]),
        GeometryForm::Bezier,
        GeometryForm::Monomial,
    );
    let answer = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
    assert_eq!(
        answer.report.matrix("result").unwrap(),
        &m(2, &[0, 3, 0, 0, 0, 3, -6, 4])
    );
}

#[test]
fn a_cubic_form_of_three_columns_is_refused_about_the_geometry() {
    let op = Convert::new(
        m(1, &[1, 2, 3]),
        GeometryForm::Hermite,
        GeometryForm::Bezier,
    );
    let e = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::Control, Kind::Shape));
    assert_eq!(e.problem, "3 column(s) for the hermite form");
}
