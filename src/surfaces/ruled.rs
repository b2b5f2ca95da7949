//! The ruled surface between two curves.

use nalgebra::DVector;

use crate::cost::{blended, Cost};
use crate::error::{Error, Result};
use crate::param::{to_domain, usable_domain, Curve, Surface};
use crate::scalar::Scalar;

/// The ruled surface `x(u, v) = (1 − v) ¹x(u) + v ²x(u)`, `u, v ∈ ⟨0, 1⟩` (the lecture notes: the
/// vector `r = ²x(u) − ¹x(u)` slides along `¹x`; with a constant `r` it is a cylinder). Any
/// [`Curve`]s — Hermite, Bézier, B-spline, NURBS, sampled. Its shape depends on how the two
/// curves are parametrised, start points included (as the notes warn). Each curve is
/// reparametrised affinely from its domain `[a, b]` onto `u ∈ [0, 1]`,
/// `¹x(a + (b − a)u)` (see [`crate::param`]), so the rulings join points at the same fraction
/// of the two domains.
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
    /// [`Error::ShapeMismatch`] if the curves have different dimensions,
    /// [`Error::UnusableDomain`] for a curve whose domain is not a finite interval `a < b`.
    pub fn new<T: Scalar>(first: C1, second: C2) -> Result<Self>
    where
        C1: Curve<T>,
        C2: Curve<T>,
    {
        usable_domain("ruled surface curve ¹x", &first)?;
        usable_domain("ruled surface curve ²x", &second)?;
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

    /// `[0, 1]²` (the curves reparametrised onto `[0, 1]`).
    fn domain(&self) -> ((T, T), (T, T)) {
        ((T::zero(), T::one()), (T::zero(), T::one()))
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        let ((a0, a1), (b0, b1)) = (self.first.domain(), self.second.domain());
        let a = self.first.eval(to_domain(&a0, &a1, u.clone()));
        let b = self.second.eval(to_domain(&b0, &b1, u));
        let w = T::one() - v.clone();
        DVector::from_fn(a.len(), |r, _| {
            w.clone() * a[r].clone() + v.clone() * b[r].clone()
        })
    }
}

/// The cost of one point of a ruled surface in `d` coordinates,
/// `x(u, v) = (1 − v) ¹x(u) + v ²x(u)`: the two curves at `u` (`curves`, the cost of each) and
/// about 4 operations per coordinate for the blend, on numbers as large as the curves' values
/// grown by the bits of `u` and `v` (and 2 for `1 − v` and the sum; [`blended`]).
///
/// ```
/// use cagd::cost::Cost;
/// use cagd::surfaces::ruled_point_cost;
/// assert_eq!(ruled_point_cost([Cost::new(5, 10); 2], 3, 4, 6), Cost::new(10 + 12, 10 + 12));
/// ```
pub fn ruled_point_cost(
    curves: impl IntoIterator<Item = Cost>,
    d: usize,
    u_bits: u128,
    v_bits: u128,
) -> Cost {
    blended(
        curves,
        4 * d as u128,
        u_bits.saturating_add(v_bits).saturating_add(2),
    )
}
