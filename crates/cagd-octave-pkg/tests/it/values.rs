//! Octave's values as the package receives them, shared by the test modules.

use cagd_octave_pkg::{Real, Value};

/// A real array of size `dims` holding `data` (column-major, as Octave stores it).
pub fn real<'a>(dims: &'a [usize], data: &'a [f64]) -> Value<'a> {
    Value::Real(Real { dims, data })
}

/// The structure octave-nurbs' `nrbmak` makes: the field `form` ("B-NURBS"), then `fields`.
pub fn nrbmak<'a>(fields: impl IntoIterator<Item = (&'a str, Value<'a>)>) -> Value<'a> {
    let form = Value::Char {
        dims: &[1, 7],
        bytes: b"B-NURBS",
    };
    Value::Struct {
        fields: std::iter::once(("form", form)).chain(fields).collect(),
    }
}
