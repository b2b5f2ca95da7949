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
    let h = DMatrix::from_fn(d + 1, points.ncols(), |r, c| {
        if r < d {
            weights[c].clone() * points[(r, c)].clone()
        } else {
            weights[c].clone()
        }
    });
    finish_homogeneous(what, h.nrows() - 1, h)
}

/// The cost of a rational point in `d` coordinates from its homogeneous point, whose cost is
/// `homogeneous`: that, and `d` divisions by the weight on numbers twice as large.
/// [`NurbsCurve`]'s and [`NurbsSurface`]'s `point_cost`.
///
/// ```
/// use cagd::cost::Cost;
/// let h = cagd::bspline::curve_point_cost(2, 4, 0, 0, 0);
/// assert_eq!(cagd::nurbs::rational_point_cost(h, 3).ops(), h.ops() + 3);
/// ```
pub fn rational_point_cost(homogeneous: crate::cost::Cost, d: usize) -> crate::cost::Cost {
    homogeneous.and(crate::cost::Cost::new(
        d as u128,
        homogeneous.bits().saturating_mul(2),
    ))
}

/// The homogeneous control points `h` (weights in row `weight_row`) with the weights scaled
/// into a safe range, then checked: a rational curve does not change when all its weights
/// (and weighted points) are multiplied by one factor, so weights whose largest lies outside
/// `[2⁻⁶⁴, 2⁶⁴]` (all 10³⁰⁸, all 5·10⁻³²⁴) are scaled by the power of two that brings it into
/// `[1, 2)` — exactly, bit for bit — before anything is computed with them; weights inside
/// that range are left as given.
///
/// # Errors
/// [`Error::Overflow`] when the weights span more than the range of doubles (the smallest
/// would vanish), or a weighted point `w P` overflows.
pub(crate) fn finish_homogeneous<T: Scalar>(
    what: &'static str,
    weight_row: usize,
    mut h: DMatrix<T>,
) -> Result<DMatrix<T>> {
    if !crate::grid::exact::is_rational::<T>() {
        let largest = h.row(weight_row).iter().map(T::to_f64).fold(0.0, f64::max);
        if largest > 0.0 && !(2f64.powi(-64)..=2f64.powi(64)).contains(&largest) {
            // 2^k with largest · 2^k in [1, 2), applied in two exact halves (2^k alone may
            // overflow: k reaches 1074).
            let k = -(largest.log2().floor() as i32);
            let (a, b) = (k / 2, k - k / 2);
            let (fa, fb) = (T::from_f64(2f64.powi(a)), T::from_f64(2f64.powi(b)));
            if let (Some(fa), Some(fb)) = (fa, fb) {
                h = h.map(|x| x * fa.clone() * fb.clone());
            }
            if let Some(index) = h.row(weight_row).iter().position(|w| w.is_zero()) {
                return Err(Error::Overflow {
                    what,
                    index,
                    value: f64::INFINITY,
                });
            }
        }
    }
    crate::error::check_overflow(what, h.iter())?;
    // The control points themselves, w P / w: a point near 1.8·10³⁰⁸ over a weight below one.
    for (c, column) in h.column_iter().enumerate() {
        let w = column[weight_row].clone();
        for (r, x) in column.iter().enumerate().filter(|(r, _)| *r != weight_row) {
            let value = x.clone() / w.clone();
            if !value.is_finite_value() {
                return Err(Error::Overflow {
                    what: "NURBS control points (weighted point / weight)",
                    index: c * h.nrows() + r,
                    value: value.to_f64(),
                });
            }
        }
    }
    Ok(h)
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
