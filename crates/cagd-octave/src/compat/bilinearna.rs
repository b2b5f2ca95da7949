//! `bilinearna` (thesis appendix B, Algoritem 3).

use ndarray::{Array3, ArrayView2};

use super::tenzor;
use cagd::error::Result;
use cagd::Scalar;

/// One point of the Bézier patch with the packed net `b`: the twin of the thesis's
/// `bilinearna` (appendix B, Algoritem 3), as fixed in `octave_ref/fixed/bilinearna.m`.
///
/// **Original:** `function L = bilinearna(B,u,v,N)`.
///
/// # Layout
/// - `b`: the packed net, `(m+1) × 3(n+1)`, `B(i+1, 3j+1:3j+3) = b_{i,j}` (see [`tenzor`]);
///   `m ≠ n` allowed.
/// - `u`, `v`: the parameters (any finite values; outside `[0, 1]` the patch is extrapolated).
/// - `n`: the original's `N`, used there only for the initial size of a work array; accepted
///   for the sake of the signature and ignored.
/// - result `L`: `1 × 1 × 3`, Octave's `T(1,1,:)`: the point `x(u, v) = b^{m,n}_{0,0}(u, v)`.
///
/// # Bugs of the original fixed here (`octave_ref/BUGS.md`)
/// - **Wrong for `m ≠ n`:** it ran `m` bilinear steps with the `j` loop going to `n − k + 1`.
///   For `m > n` the steps after the `n`-th change nothing; for `m < n` it stops with a row of
///   `n − m + 1` points left; for `m = 0` it returns the zeros its work array started with. The
///   fixed version takes `min(m, n)` bilinear steps and then `|m − n|` linear steps in the
///   direction whose degree remains.
///
/// # Native function
/// [`patch_from_array3`](crate::arrays::patch_from_array3) (after [`tenzor`]) and [`BezierPatch::eval`](cagd::bezier::BezierPatch::eval), the tensor de
/// Casteljau algorithm in the term order of the fixed Octave code (bit for bit equal). Like
/// the Octave function it takes any finite `u`, `v` (outside `[0, 1]` the polynomial
/// continues), where [`BezierPatch::try_eval`](cagd::bezier::BezierPatch::try_eval) would
/// keep to the domain `[0, 1]²`.
///
/// # Errors
/// As [`tenzor`]; [`Error::TooFewPoints`](cagd::Error::TooFewPoints) for an empty net,
/// [`Error::NonFinite`](cagd::Error::NonFinite) for a non-finite `u` or `v`.
///
/// ```
/// use cagd_octave::compat::bilinearna;
/// use ndarray::array;
/// // Degree (1, 2): b_{0,j} = (0, j/2, 0), b_{1,j} = (1, j/2, z_j), z = 0, 2, 0.
/// let b = array![[0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0],
///                [1.0, 0.0, 0.0, 1.0, 0.5, 2.0, 1.0, 1.0, 0.0]];
/// let l = bilinearna(b.view(), 0.5, 0.5, 10)?;
/// assert_eq!(l.dim(), (1, 1, 3));
/// assert_eq!(l.iter().copied().collect::<Vec<_>>(), vec![0.5, 0.5, 0.5]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bilinearna<T: Scalar>(b: ArrayView2<'_, T>, u: T, v: T, n: usize) -> Result<Array3<T>> {
    let _ = n;
    let patch = crate::arrays::patch_from_array3(&tenzor(b)?)?;
    cagd::error::check_finite("bilinearna parameters u, v", [&u, &v])?;
    let point = patch.eval(u, v);
    Ok(Array3::from_shape_fn((1, 1, point.len()), |(_, _, c)| {
        point[c].clone()
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd::Error;
    use ndarray::{array, Array2};

    #[test]
    fn degree_zero_direction_returns_the_point_not_zero() {
        // Degree (0, 1): the original returned zeros(1,1,3).
        let b = array![[1.0, 2.0, 3.0, 3.0, 2.0, 1.0]];
        let l = bilinearna(b.view(), 0.25, 0.5, 2).unwrap();
        assert_eq!(l.iter().copied().collect::<Vec<_>>(), vec![2.0, 2.0, 2.0]);
    }

    #[test]
    fn errors() {
        let b = array![[1.0, 2.0, 3.0]];
        assert!(matches!(
            bilinearna(b.view(), f64::NAN, 0.5, 2),
            Err(Error::NonFinite { .. })
        ));
        assert!(matches!(
            bilinearna(Array2::zeros((0, 3)).view(), 0.5, 0.5, 2),
            Err(Error::TooFewPoints { .. })
        ));
        assert!(matches!(
            bilinearna(Array2::zeros((1, 4)).view(), 0.5, 0.5, 2),
            Err(Error::ShapeMismatch { .. })
        ));
    }
}
