//! The argument readers refuse wrong values up front, each with its kind and words, and read
//! arrays column-major, as Octave stores them.

use cagd_octave_pkg::args::{count_of, nonempty_of, real_of, scalar_of, view2_of, REAL_FORM};
use cagd_octave_pkg::{Kind, Real, Value};

use crate::values::real;

#[test]
fn readers_refuse_up_front() {
    let dims = [1usize, 1];
    let two = [2.5];
    let neg = [-1.0];
    let nan = [f64::NAN];
    let half = real(&dims, &two);
    let e = count_of(&half, "N").unwrap_err();
    assert_eq!(
        (e.kind, e.message.as_str()),
        (
            Kind::Value,
            "N: 2.5 is not a non-negative integer; expected a count 0, 1, 2, …"
        )
    );
    let e = count_of(&real(&dims, &neg), "N").unwrap_err();
    assert_eq!(e.kind, Kind::Value);
    let e = scalar_of(&real(&dims, &nan), "u").unwrap_err();
    assert_eq!(e.kind, Kind::NonFinite);
    let e = scalar_of(&Value::Other { class: "int32" }, "u").unwrap_err();
    assert_eq!(
        e.message,
        "u: int32 is not accepted; expected a real scalar"
    );
    let e = real_of(&Value::Struct { fields: vec![] }, "P", REAL_FORM).unwrap_err();
    assert_eq!(e.kind, Kind::Class);
    assert!(e.message.contains("a struct without fields"));
    let empty_dims = [0usize, 3];
    let e = nonempty_of(&real(&empty_dims, &[]), "P", REAL_FORM).unwrap_err();
    assert_eq!(
        (e.kind, e.message.as_str()),
        (Kind::Empty, "P: empty (0×3); expected a real double array")
    );
}

#[test]
fn views_are_column_major() {
    let dims = [2usize, 3];
    let data = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
    let v = view2_of(
        Real {
            dims: &dims,
            data: &data,
        },
        "A",
        REAL_FORM,
    )
    .unwrap();
    assert_eq!(v[[1, 0]], 2.0);
    assert_eq!(v[[0, 2]], 5.0);
}
