//! Bernstein polynomials: one of them at an exact parameter, an index above the degree refused.

use cagd_ops::ops::Bernstein;
use cagd_ops::{execute, Context, Kind, Params, Role};
use num_rational::BigRational;

#[test]
fn one_polynomial_and_an_index_above_the_degree() {
    // B_1^3(1/3) = 3 · 1/3 · (2/3)² = 4/9.
    let op = Bernstein {
        index: Some(1),
        t: Params::Given(vec![BigRational::new(1.into(), 3.into())]),
        ..Bernstein::new(3)
    };
    let mut cx = Context::new(cagd::Limits::default());
    let answer = execute(&op, &mut cx).unwrap();
    assert_eq!(
        answer.report.matrix("result").unwrap()[0],
        BigRational::new(4.into(), 9.into())
    );
    let e = execute(
        &Bernstein {
            index: Some(4),
            ..op
        },
        &mut cx,
    )
    .unwrap_err();
    assert_eq!((e.role, e.kind), (Role::Index, Kind::Shape));
}
