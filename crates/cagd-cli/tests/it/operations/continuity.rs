//! The continuity of two Bézier curves at their joint, with the free point of the lecture notes.

use cagd_ops::ops::Continuity;
use cagd_ops::{execute, Context, Kind, Role, Value};
use nalgebra::DMatrix;
use num_rational::BigRational;

fn m(rows: usize, values: &[i64]) -> DMatrix<BigRational> {
    DMatrix::from_row_slice(
        rows,
        values.len() / rows,
        &values
            .iter()
            .map(|&x| BigRational::from_integer(x.into()))
            .collect::<Vec<_>>(),
    )
}

#[test]
fn the_lecture_notes_free_point_makes_the_joint_c1_not_c2() {
    let first = m(3, &[2, 3, 3, 3, 1, 4, 3, 4, 3]);
    let second = m(3, &[3, 2, 5, 5, 4, 6, 7, 2, 3, 0, 5, 3]);
    let op = Continuity {
        free_point: true,
        ..Continuity::new(first, second)
    };
    let answer = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
    let Some(Value::Text(line)) = answer.report.get("free_point") else {
        panic!("no line");
    };
    assert!(line.contains("x = 3 + k, y = 4 - 2k, z = 3 + 3k"), "{line}");
    let Some(Value::Text(verdict)) = answer.report.get("verdict") else {
        panic!("no verdict");
    };
    assert!(
        verdict.starts_with("C0: yes") && verdict.contains("C1: yes") && verdict.contains("C2: no"),
        "{verdict}"
    );
}

#[test]
fn a_factor_without_the_free_point_is_refused() {
    let op = Continuity {
        k: Some(BigRational::from_integer(2.into())),
        ..Continuity::new(m(1, &[0, 1]), m(1, &[1, 2]))
    };
    let e = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::Factor, Kind::Usage));
}
