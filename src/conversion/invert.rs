//! The inverse of a small square matrix, exact in rationals.

use nalgebra::DMatrix;

use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The inverse of a square matrix by Gauss–Jordan elimination with partial pivoting (largest
/// absolute value in the column), generic so that it is exact in rationals.
///
/// # Errors
/// [`Error::ShapeMismatch`] for a non-square matrix, [`Error::NonFinite`] for a NaN or
/// infinite entry, [`Error::Singular`] for a singular one, [`Error::TooLarge`] when the `n³`
/// operations (weighed by the size of exact numbers) exceed the default work limit,
/// [`Error::Overflow`] for an entry of the inverse whose double overflows (a nearly singular
/// matrix).
pub fn invert<T: Scalar>(m: &DMatrix<T>) -> Result<DMatrix<T>> {
    let n = m.nrows();
    if m.ncols() != n {
        return Err(Error::ShapeMismatch {
            what: "matrix to invert",
            expected: "a square matrix".into(),
            found: format!("{} × {}", n, m.ncols()),
        });
    }
    crate::error::check_finite("matrix to invert", m.iter())?;
    let size = n as u128;
    crate::checked::point_work::<T>(
        "matrix inverse",
        crate::cost::Cost::new(size.saturating_pow(3).saturating_mul(4), 0)
            .grown(size.saturating_mul(crate::cost::max_bits(m.iter()).saturating_add(1))),
    )?;
    let mut a = m.clone();
    let mut inv = DMatrix::from_fn(n, n, |i, j| if i == j { T::one() } else { T::zero() });
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| {
                a[(i, col)]
                    .abs()
                    .partial_cmp(&a[(j, col)].abs())
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .expect("non-empty range");
        if a[(pivot, col)].is_zero() {
            return Err(Error::Singular {
                what: "matrix to invert",
                reason: format!("no pivot in column {col}"),
            });
        }
        a.swap_rows(col, pivot);
        inv.swap_rows(col, pivot);
        let p = a[(col, col)].clone();
        for j in 0..n {
            a[(col, j)] = a[(col, j)].clone() / p.clone();
            inv[(col, j)] = inv[(col, j)].clone() / p.clone();
        }
        for i in 0..n {
            if i == col || a[(i, col)].is_zero() {
                continue;
            }
            let f = a[(i, col)].clone();
            for j in 0..n {
                a[(i, j)] = a[(i, j)].clone() - f.clone() * a[(col, j)].clone();
                inv[(i, j)] = inv[(i, j)].clone() - f.clone() * inv[(col, j)].clone();
            }
        }
    }
    crate::error::check_overflow("inverse matrix", inv.iter())?;
    Ok(inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_or_a_named_error() {
        let m = DMatrix::from_row_slice(2, 2, &[0.0, 2.0, 4.0, 0.0]);
        assert_eq!(
            invert(&m).unwrap(),
            DMatrix::from_row_slice(2, 2, &[0.0, 0.25, 0.5, 0.0])
        );
        assert!(matches!(
            invert(&DMatrix::<f64>::zeros(2, 2)),
            Err(Error::Singular { .. })
        ));
        assert!(matches!(
            invert(&DMatrix::<f64>::zeros(2, 3)),
            Err(Error::ShapeMismatch { .. })
        ));
    }
}
