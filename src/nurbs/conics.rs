//! Conic sections as rational quadratic curves (the CAD notes §1.3: NURBS express conics exactly).

use nalgebra::DMatrix;

use super::NurbsCurve;
use crate::error::Result;
use crate::scalar::Scalar;

/// The kind of conic a rational quadratic Bézier arc with weights `(1, w, 1)` lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConicKind {
    /// `0 < w < 1`: an ellipse (a circle for suitable control points).
    Ellipse,
    /// `w = 1`: a parabola (the polynomial quadratic Bézier curve).
    Parabola,
    /// `w > 1`: a hyperbola.
    Hyperbola,
}

impl ConicKind {
    /// The kind for the middle weight `w > 0`.
    pub fn of_weight<T: Scalar>(w: &T) -> ConicKind {
        if w < &T::one() {
            ConicKind::Ellipse
        } else if w == &T::one() {
            ConicKind::Parabola
        } else {
            ConicKind::Hyperbola
        }
    }
}

/// The conic arc from `p0` to `p2` tangent to `p0p1` and `p1p2`: the rational quadratic Bézier
/// curve with control points `p0, p1, p2` (columns of `points`, `d × 3`) and weights
/// `(1, w, 1)`, over `[0, 1]`. Its kind is [`ConicKind::of_weight`]; with `p1` at the
/// intersection of the tangents of a circle at `p0` and `p2` and `w = cos(θ/2)` (θ the angle
/// of the arc) it is an exact circular arc. Rational: with rational data it is exact.
///
/// # Errors
/// [`crate::Error::NonPositiveWeight`] unless `w > 0`; [`crate::Error::TooFewControlPoints`]
/// /[`crate::Error::KnotCount`] unless `points` has 3 columns.
///
/// ```
/// use cagd::nurbs::{conic_arc, ConicKind};
/// use nalgebra::DMatrix;
/// use num_rational::BigRational;
/// use cagd::Scalar;
/// // A hyperbolic arc (w = 2 > 1), in exact rationals.
/// let q = |n: i64| BigRational::from_ratio(n, 1);
/// let p = DMatrix::from_column_slice(2, 3, &[q(1), q(0), q(0), q(0), q(0), q(1)]);
/// let c = conic_arc(p, q(2))?;
/// assert_eq!(ConicKind::of_weight(&q(2)), ConicKind::Hyperbola);
/// // At u = 1/2: (1/4·1 + 0)/(1/4 + 2·1/2 + 1/4) = 1/6 in each coordinate.
/// let x = c.try_eval(BigRational::from_ratio(1, 2))?;
/// assert_eq!(x[0], BigRational::from_ratio(1, 6));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn conic_arc<T: Scalar>(points: DMatrix<T>, w: T) -> Result<NurbsCurve<T>> {
    let knots = vec![
        T::zero(),
        T::zero(),
        T::zero(),
        T::one(),
        T::one(),
        T::one(),
    ];
    NurbsCurve::new(2, knots, points, vec![T::one(), w, T::one()])
}
