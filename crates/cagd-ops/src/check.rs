//! Checks every request makes of its numbers before anything else, worded once: a front end
//! passes its values as they came (an Octave array, the page's numbers, a Python array) and
//! never checks them itself, so the same bad value reads the same everywhere.

use cagd::Scalar;
use nalgebra::DMatrix;

use crate::error::{Kind, OpError, Result};
use crate::number_text;
use crate::Role;

/// The words of a non-finite value: `value K is not finite (NaN)`, `K` counted from 1 in
/// Octave's (column-major) order.
///
/// ```
/// use cagd_ops::{check::finite, Kind, Role};
/// let e = finite(Role::Weights, &[1.0, f64::NAN]).unwrap_err();
/// assert_eq!((e.kind, e.problem.as_str()), (Kind::NonFinite, "value 2 is not finite (NaN)"));
/// ```
///
/// # Errors
/// [`Kind::NonFinite`] about `role` for the first NaN or ±Inf.
pub fn finite<'a, T: Scalar>(role: Role, values: impl IntoIterator<Item = &'a T>) -> Result<()> {
    match non_finite(values) {
        None => Ok(()),
        Some((problem, expected)) => Err(OpError::new(role, Kind::NonFinite, problem, expected)),
    }
}

/// The words of [`finite`] for the first NaN or ±Inf of `values`, if any: a front end that
/// reads numbers before any request (an Octave argument of a thesis function) refuses them
/// with these words under its own name.
pub fn non_finite<'a, T: Scalar>(
    values: impl IntoIterator<Item = &'a T>,
) -> Option<(String, &'static str)> {
    values
        .into_iter()
        .enumerate()
        .find(|(_, x)| !x.is_finite_value())
        .map(|(k, x)| not_finite_at(k, x))
}

/// The words of [`non_finite`] for the value `x` at `index` (from 0), for a front end that
/// meets it while reading values one by one (a Python object array read as fractions).
///
/// ```
/// let (problem, expected) = cagd_ops::check::not_finite_at(1, &f64::INFINITY);
/// assert_eq!(format!("{problem}; expected {expected}"), "value 2 is not finite (inf); expected finite numbers");
/// ```
pub fn not_finite_at<T: Scalar>(index: usize, x: &T) -> (String, &'static str) {
    (
        format!("value {} is not finite ({})", index + 1, number_text(x)),
        "finite numbers",
    )
}

/// [`finite`] for a matrix (column-major, as Octave counts).
///
/// # Errors
/// As [`finite`].
pub fn finite_matrix<T: Scalar>(role: Role, m: &DMatrix<T>) -> Result<()> {
    finite(role, m.iter())
}

/// Points as the columns of a matrix: at least `min` of them, with at least one coordinate.
///
/// # Errors
/// [`Kind::Shape`] about `role`; [`Kind::NonFinite`].
pub fn points<T: Scalar>(role: Role, m: &DMatrix<T>, min: usize, what: &str) -> Result<()> {
    if m.nrows() == 0 || m.ncols() < min {
        return Err(OpError::new(
            role,
            Kind::Shape,
            format!("{} × {} {what}", m.nrows(), m.ncols()),
            format!("at least {min} {what}, one point of at least one coordinate per column"),
        ));
    }
    finite_matrix(role, m)
}
