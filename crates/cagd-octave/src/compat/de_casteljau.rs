//! `deCasteljau` (thesis appendix A, Algoritem 1).

use ndarray::{Array2, ArrayView2};

use super::{check_finite_array, from_dmatrix, samples, to_dmatrix};
use crate::literal::LiteralScalar;
use cagd::bezier::BezierCurve;
use cagd::error::Result;

/// The Bézier curve with control points `kontrolne_t` sampled at `linspace(0,1,N)`: the twin
/// of the thesis's `deCasteljau` (appendix A, Algoritem 1), as fixed in
/// `octave_ref/fixed/deCasteljau.m`.
///
/// **Original:** `function deCasteljau(kontrolneT,N)` — no output; it plots the curve and the
/// control polygon. **Fixed Octave:** `T = deCasteljau(kontrolneT, N)`.
///
/// # Layout
/// - `kontrolne_t`: `d × (n+1)`, one control point per **column** (row 1 = x, row 2 = y, …);
///   any dimension `d ≥ 1` and degree `n ≥ 0`.
/// - `n`: the number of samples `N`; the curve is evaluated at `t = linspace(0,1,N)`
///   (Octave's own points, see [`linspace`](super::linspace)).
/// - result `T`: `d × N`, column `k` = the point at `t(k)`.
///
/// The original plots the curve and the control polygon: the curve is `T`, the polygon is
/// `kontrolne_t` itself (unchanged; the original plotted its own overwritten copy).
///
/// # Bugs of the original fixed here (`octave_ref/BUGS.md`)
/// - **Rows for points:** it interpolated the ROWS `kontrolneT(i,:)` (the coordinates) instead
///   of the columns (the points), over `j = 1:m` levels with `m` the number of rows; with more
///   control points than coordinates Octave stops with `kontrolneT(4,_): out of bound 3`.
/// - **In-place overwrite:** it overwrote `kontrolneT` itself, so every parameter after the
///   first started from the previous parameter's scheme, and the "control polygon" it plotted
///   afterwards was that scheme.
/// - **Dimension fixed at 3:** `T = zeros(3,N)`; plane curves fail to fit into `T`.
/// - It returned nothing.
///
/// # Native function
/// [`BezierCurve::new`] and [`BezierCurve::eval_many`] (de Casteljau in the operation order of
/// the fixed Octave code, `(1-t)*b_i + t*b_(i+1)`, so the values agree bit for bit).
///
/// # Errors
/// [`Error::TooFewPoints`](cagd::Error::TooFewPoints) for no columns,
/// [`Error::ShapeMismatch`](cagd::Error::ShapeMismatch) for no rows,
/// [`Error::NonFinite`](cagd::Error::NonFinite) for a NaN or infinite coordinate. `N = 0`
/// gives a `d × 0` array, as Octave does.
///
/// ```
/// use cagd_octave::compat::de_casteljau;
/// use ndarray::array;
/// // Thesis Primer 2.4: b0 = (0,0,0), b1 = (0,2,2), b2 = (8,2,0), b3 = (4,0,0) as columns.
/// let p = array![[0.0, 0.0, 8.0, 4.0], [0.0, 2.0, 2.0, 0.0], [0.0, 2.0, 0.0, 0.0]];
/// let t = de_casteljau(p.view(), 3)?;
/// assert_eq!(t.column(1).to_vec(), vec![3.5, 1.5, 0.75]); // b(1/2)
/// assert_eq!(t.column(2).to_vec(), vec![4.0, 0.0, 0.0]);  // b(1) = b3
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn de_casteljau<T: LiteralScalar>(
    kontrolne_t: ArrayView2<'_, T>,
    n: usize,
) -> Result<Array2<T>> {
    check_finite_array("de_casteljau: kontrolneT", &kontrolne_t)?;
    let curve = BezierCurve::new(to_dmatrix(&kontrolne_t))?;
    if n == 0 {
        return Ok(Array2::zeros((curve.dim(), 0)));
    }
    Ok(from_dmatrix(&curve.eval_many(&samples::<T>(n))?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd::Error;
    use ndarray::array;

    #[test]
    fn shapes_and_errors() {
        let p = array![[0.0, 1.0], [2.0, 3.0]];
        assert_eq!(de_casteljau(p.view(), 0).unwrap().dim(), (2, 0));
        // N = 1: linspace(0,1,1) = [1], the last control point.
        assert_eq!(de_casteljau(p.view(), 1).unwrap(), array![[1.0], [3.0]]);
        let empty = Array2::<f64>::zeros((3, 0));
        assert!(matches!(
            de_casteljau(empty.view(), 4),
            Err(Error::TooFewPoints { .. })
        ));
        let bad = array![[0.0, f64::NAN]];
        assert!(matches!(
            de_casteljau(bad.view(), 4),
            Err(Error::NonFinite { index: 1, .. })
        ));
    }
}
