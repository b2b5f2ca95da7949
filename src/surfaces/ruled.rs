//! The ruled surface between two curves.

use nalgebra::DVector;

use crate::error::{Error, Result};
use crate::param::{Curve, Surface};
use crate::scalar::Scalar;

/// The ruled surface `x(u, v) = (1 − v) ¹x(u) + v ²x(u)`, `u, v ∈ ⟨0, 1⟩` (the lecture notes: the
/// vector `r = ²x(u) − ¹x(u)` slides along `¹x`; with a constant `r` it is a cylinder). Any
/// [`Curve`]s — Hermite, Bézier, B-spline, NURBS, sampled. Its shape depends on how the two
/// curves are parametrised, start points included (as the notes warn).
///
/// ```
/// use cagd::surfaces::RuledSurface;
/// use cagd::{BezierCurve, Surface};
/// let a = BezierCurve::from_points(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])?;
/// let b = BezierCurve::from_points(&[[0.0, 1.0, 1.0], [1.0, 1.0, 1.0]])?;
/// let s = RuledSurface::new(a, b)?;
/// assert_eq!(s.eval(0.5, 0.25).as_slice(), &[0.5, 0.25, 0.25]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct RuledSurface<C1, C2> {
    first: C1,
    second: C2,
}

impl<C1, C2> RuledSurface<C1, C2> {
    /// The surface between `first` (`v = 0`) and `second` (`v = 1`).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] if the curves have different dimensions.
    pub fn new<T: Scalar>(first: C1, second: C2) -> Result<Self>
    where
        C1: Curve<T>,
        C2: Curve<T>,
    {
        if first.dim() != second.dim() {
            return Err(Error::ShapeMismatch {
                what: "ruled surface",
                expected: format!("curves of dimension {}", first.dim()),
                found: format!("dimension {}", second.dim()),
            });
        }
        Ok(RuledSurface { first, second })
    }

    /// The curves `(¹x, ²x)`.
    pub fn curves(&self) -> (&C1, &C2) {
        (&self.first, &self.second)
    }
}

impl<T: Scalar, C1: Curve<T>, C2: Curve<T>> Surface<T> for RuledSurface<C1, C2> {
    fn dim(&self) -> usize {
        self.first.dim()
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        let a = self.first.eval(u.clone());
        let b = self.second.eval(u);
        let w = T::one() - v.clone();
        DVector::from_fn(a.len(), |r, _| {
            w.clone() * a[r].clone() + v.clone() * b[r].clone()
        })
    }
}
