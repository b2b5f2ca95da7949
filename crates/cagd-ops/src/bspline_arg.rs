//! A B-spline curve as an argument: its control points, its degree (or, as the lecture notes
//! count, its order `k = p + 1`) and its knots (or the clamped uniform knots on `[0, 1]`). One
//! rule for every request that takes one, worded once.

use cagd::{BSplineCurve, Scalar};
use nalgebra::DMatrix;

use crate::error::{lib, Kind, OpError, Result};
use crate::Role;

/// The form of a B-spline curve's data: `n` control points, degree `p`, `n + p + 1` knots — the
/// one knot-count rule and wording of [`crate::knots::KNOTS_FORM`].
pub const BSPLINE_FORM: &str = crate::knots::KNOTS_FORM;

/// The degree of a B-spline as given: the degree `p`, or the order `k = p + 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SplineDegree {
    /// The degree `p`.
    Degree(usize),
    /// The order `k = p + 1` (`k ≥ 1`).
    Order(usize),
}

impl SplineDegree {
    /// The degree `p`.
    ///
    /// # Errors
    /// [`Kind::Shape`] about [`Role::Order`] for the order `k = 0`.
    ///
    /// ```
    /// use cagd_ops::bspline_arg::SplineDegree;
    /// assert_eq!(SplineDegree::Order(4).degree()?, 3);
    /// assert!(SplineDegree::Order(0).degree().is_err());
    /// # Ok::<(), cagd_ops::OpError>(())
    /// ```
    pub fn degree(self) -> Result<usize> {
        match self {
            SplineDegree::Degree(p) => Ok(p),
            SplineDegree::Order(0) => Err(OpError::new(
                Role::Order,
                Kind::Shape,
                "order k = 0",
                "an order k ≥ 1 (the degree p = k − 1)",
            )),
            SplineDegree::Order(k) => Ok(k - 1),
        }
    }
}

/// A B-spline curve given by its data.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineArg<T> {
    /// The degree (or order).
    pub degree: SplineDegree,
    /// The knots; `None`: clamped uniform on `[0, 1]`.
    pub knots: Option<Vec<T>>,
}

impl<T: Scalar> BSplineArg<T> {
    /// The curve with these control points (the degree already checked against the limits
    /// by the caller).
    ///
    /// # Errors
    /// Given knots are checked first by the one rule of [`crate::knots::check_knots`] (its
    /// errors about [`Role::Knots`] or [`Role::Control`], as every request with knots words
    /// them); then the library's errors about [`Role::Spline`] (non-finite control points,
    /// too few of them for clamped knots), worded with [`BSPLINE_FORM`].
    ///
    /// ```
    /// use cagd_ops::bspline_arg::{BSplineArg, SplineDegree};
    /// let arg = BSplineArg::<f64> { degree: SplineDegree::Degree(3), knots: None };
    /// let e = arg.curve(nalgebra::dmatrix![0.0, 1.0]).unwrap_err();
    /// assert_eq!(e.role, cagd_ops::Role::Spline);
    /// ```
    pub fn curve(&self, control: DMatrix<T>) -> Result<BSplineCurve<T>> {
        let p = self.degree.degree()?;
        if let Some(knots) = &self.knots {
            crate::knots::check_knots(knots, p, control.ncols(), crate::knots::CURVE)?;
        }
        match &self.knots {
            Some(knots) => BSplineCurve::new(p, knots.clone(), control),
            None => BSplineCurve::clamped(p, control),
        }
        .map_err(lib(Role::Spline, BSPLINE_FORM))
    }
}
