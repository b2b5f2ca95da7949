//! `tenzor` (thesis appendix B, Algoritem 4) and its inverse.

use ndarray::{Array2, Array3, ArrayView2, ArrayView3};

use super::{check_finite_array, shape_str};
use cagd::error::{Error, Result};
use cagd::Scalar;

/// The packed net `B` as an `(m+1) × (n+1) × 3` array: the twin of the thesis's `tenzor`
/// (appendix B, Algoritem 4), as fixed in `octave_ref/fixed/tenzor.m`.
///
/// **Original:** `function A=tenzor(B)`.
///
/// # Layout
/// - `b`: `(m+1) × 3(n+1)`, row `k` holds the points `b_{k-1,0}, …, b_{k-1,n}` one after the
///   other as x y z triples: `B(k, 3l-2:3l) = b_{k-1,l-1}` (Octave indices).
/// - result `A`: `(m+1) × (n+1) × 3`, `A(k, l, :) = B(k, 3l-2:3l)`, i.e. `A[[i, j, c]]` is
///   coordinate `c` of `b_{i,j}` — the layout of
///   [`patch_from_array3`](crate::arrays::patch_from_array3) and of the
///   surface grids ([`Surface::eval_grid`](cagd::param::Surface::eval_grid)).
///
/// Empty nets (no rows, or no columns) give empty arrays, as in Octave.
///
/// # Bugs of the original fixed here
/// - With a number of columns that is not a multiple of 3, `n = size(B)(2)/3 - 1` is
///   fractional and the loop `l = 1:n+1` silently drops the trailing columns; here (and in the
///   fixed Octave) that is an error.
/// - `A` was not preallocated (grown element by element); harmless in Octave.
///
/// # Native function
/// None: `tenzor` is a pure layout conversion (values are copied bit for bit).
///
/// # Errors
/// [`Error::ShapeMismatch`] when the number of columns is not a multiple of 3;
/// [`Error::NonFinite`] for a NaN or infinite entry.
///
/// ```
/// use cagd_octave::compat::{tenzor, untenzor};
/// use ndarray::array;
/// // Degree (1, 1): rows b_{0,0} b_{0,1} and b_{1,0} b_{1,1}.
/// let b = array![[0.0, 0.0, 0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 1.0, 1.0, 1.0]];
/// let a = tenzor(b.view())?;
/// assert_eq!(a.dim(), (2, 2, 3));
/// assert_eq!(a.slice(ndarray::s![1, 1, ..]).to_vec(), vec![1.0, 1.0, 1.0]); // b_{1,1}
/// assert_eq!(untenzor(a.view())?, b);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn tenzor<T: Scalar>(b: ArrayView2<'_, T>) -> Result<Array3<T>> {
    if b.ncols() % 3 != 0 {
        return Err(Error::ShapeMismatch {
            what: "tenzor: B",
            expected: "(m+1)×3(n+1): a number of columns divisible by 3".into(),
            found: shape_str(b.shape()),
        });
    }
    check_finite_array("tenzor: B", &b)?;
    let (rows, points) = (b.nrows(), b.ncols() / 3);
    Ok(Array3::from_shape_fn((rows, points, 3), |(k, l, c)| {
        b[[k, 3 * l + c]].clone()
    }))
}

/// The inverse of [`tenzor`]: an `(m+1) × (n+1) × 3` array packed as `(m+1) × 3(n+1)`,
/// `B(k, 3l-2:3l) = A(k, l, :)`. This is how `krpaCoons` and `krpaGordon` hold their result
/// `R` before `P = tenzor(R)`.
///
/// # Errors
/// [`Error::ShapeMismatch`] unless the third dimension is 3; [`Error::NonFinite`] for a NaN
/// or infinite entry.
///
/// ```
/// use cagd_octave::compat::untenzor;
/// let a = ndarray::Array3::from_shape_fn((2, 2, 3), |(i, j, c)| (100 * i + 10 * j + c) as f64);
/// let b = untenzor(a.view())?;
/// assert_eq!(b.row(1).to_vec(), vec![100.0, 101.0, 102.0, 110.0, 111.0, 112.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn untenzor<T: Scalar>(a: ArrayView3<'_, T>) -> Result<Array2<T>> {
    let (rows, points, d) = a.dim();
    if d != 3 {
        return Err(Error::ShapeMismatch {
            what: "untenzor: A",
            expected: "(m+1)×(n+1)×3".into(),
            found: shape_str(a.shape()),
        });
    }
    check_finite_array("untenzor: A", &a)?;
    Ok(Array2::from_shape_fn((rows, 3 * points), |(k, col)| {
        a[[k, col / 3, col % 3]].clone()
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::array;

    #[test]
    fn columns_must_come_in_threes() {
        let b = array![[0.0, 1.0, 2.0, 3.0]];
        assert!(matches!(
            tenzor(b.view()),
            Err(Error::ShapeMismatch {
                what: "tenzor: B",
                ..
            })
        ));
        let a = Array3::<f64>::zeros((2, 2, 2));
        assert!(untenzor(a.view()).is_err());
    }

    #[test]
    fn empty_nets_stay_empty() {
        assert_eq!(
            tenzor(Array2::<f64>::zeros((0, 6)).view()).unwrap().dim(),
            (0, 2, 3)
        );
        assert_eq!(
            tenzor(Array2::<f64>::zeros((2, 0)).view()).unwrap().dim(),
            (2, 0, 3)
        );
    }

    #[test]
    fn round_trip() {
        let b = Array2::from_shape_fn((3, 12), |(i, j)| (i * 12 + j) as f64 - 7.5);
        assert_eq!(untenzor(tenzor(b.view()).unwrap().view()).unwrap(), b);
    }
}
