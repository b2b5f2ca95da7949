//! NURBS — non-uniform rational B-splines (the CAD notes §1.3, the lecture notes' closing remark).
//!
//! With weights `w_k > 0` the rational basis is
//! `R_{k,p}(u) = w_k N_{k,p}(u) / Σ_j w_j N_{j,p}(u)` (the CAD notes eq. (4)) and a NURBS curve in
//! `ℝ^d` is the central projection onto `x_{d+1} = 1` of the B-spline curve in `ℝ^{d+1}` whose
//! control points are the homogeneous points `(w_k P_k, w_k)` (the CAD notes, last paragraph of
//! §1.3). That is how [`NurbsCurve`] and [`NurbsSurface`] are stored and evaluated, as in
//! octave-nurbs (`nrbmak` takes exactly these homogeneous `coefs`). B-splines (all weights 1)
//! and Bézier curves are special cases; conic sections are exact ([`conic_arc`]).

mod conics;
mod curve;
mod surface;

pub use conics::{conic_arc, ConicKind};
pub use curve::NurbsCurve;
pub use surface::NurbsSurface;

use nalgebra::DMatrix;

use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The homogeneous control points `(w_k P_k, w_k)` of `points` (`d × n`) and `weights`
/// (length `n`, all positive): a `(d + 1) × n` matrix, octave-nurbs' `coefs`.
///
/// # Errors
/// [`Error::ShapeMismatch`] unless there is one weight per point; [`Error::NonFinite`] and
/// [`Error::NonPositiveWeight`] for the first weight that is not finite and positive.
///
/// ```
/// use nalgebra::DMatrix;
/// let p = DMatrix::from_row_slice(1, 2, &[1.0, 3.0]);
/// let h = cagd::nurbs::homogenize("weights", &p, &[2.0, 0.5])?;
/// assert_eq!(h, DMatrix::from_row_slice(2, 2, &[2.0, 1.5, 2.0, 0.5]));
/// assert!(cagd::nurbs::homogenize("weights", &p, &[1.0, 0.0]).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn homogenize<T: Scalar>(
    what: &'static str,
    points: &DMatrix<T>,
    weights: &[T],
) -> Result<DMatrix<T>> {
    if weights.len() != points.ncols() {
        return Err(Error::ShapeMismatch {
            what,
            expected: format!("{} weights (one per control point)", points.ncols()),
            found: format!("{}", weights.len()),
        });
    }
    check_weights(what, weights.iter())?;
    let d = points.nrows();
    Ok(DMatrix::from_fn(d + 1, points.ncols(), |r, c| {
        if r < d {
            weights[c].clone() * points[(r, c)].clone()
        } else {
            weights[c].clone()
        }
    }))
}

/// Every weight finite and positive.
pub(crate) fn check_weights<'a, T: Scalar>(
    what: &'static str,
    weights: impl IntoIterator<Item = &'a T>,
) -> Result<()> {
    for (index, w) in weights.into_iter().enumerate() {
        if !w.is_finite_value() {
            return Err(Error::NonFinite {
                what,
                index,
                value: w.to_f64(),
            });
        }
        if w.partial_cmp(&T::zero()) != Some(std::cmp::Ordering::Greater) {
            return Err(Error::NonPositiveWeight {
                what,
                index,
                value: w.to_f64(),
            });
        }
    }
    Ok(())
}
