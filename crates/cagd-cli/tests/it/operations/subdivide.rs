//! Subdivision: the halves of thesis Primer 2.4 are the edges of de Casteljau's scheme, and a
//! split at an end is refused about `t`.

use cagd_ops::ops::Subdivide;
use cagd_ops::{execute, Context, Kind, Role, Value};
use nalgebra::DMatrix;
use num_rational::BigRational;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn primer_2_4() -> DMatrix<BigRational> {
    DMatrix::from_row_slice(3, 4, &[0, 0, 8, 4, 0, 2, 2, 0, 0, 2, 0, 0].map(|x| q(x, 1)))
}

#[test]
fn primer_2_4_halves_are_the_edges_of_the_scheme() {
    let op = Subdivide {
        t: Some(q(1, 2)),
        steps: true,
        ..Subdivide::new(primer_2_4())
    };
    let answer = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
    let left = answer.report.matrix("left").unwrap();
    let right = answer.report.matrix("right").unwrap();
    assert_eq!(
        left.column(2).iter().cloned().collect::<Vec<_>>(),
        [q(2, 1), q(3, 2), q(1, 1)]
    );
    assert_eq!(left.column(3), right.column(0));
    assert_eq!(
        right.column(3).iter().cloned().collect::<Vec<_>>(),
        [q(4, 1), q(0, 1), q(0, 1)]
    );
    let Some(Value::Shown { text, .. }) = answer.report.get("scheme") else {
        panic!("no scheme");
    };
    assert!(text.contains("LR(7/2, 3/2, 3/4)"), "{text}");
}

#[test]
fn a_split_at_an_end_is_refused_about_t() {
    let op = Subdivide {
        t: Some(q(1, 1)),
        ..Subdivide::new(primer_2_4())
    };
    let e = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::T, Kind::Value));
    assert!(matches!(
        e.source.as_deref(),
        Some(cagd::Error::EmptyInterval { .. })
    ));
}
