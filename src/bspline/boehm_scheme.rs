//! Boehm's knot insertion step by step (the CAD notes §1.2 "adding a knot"; Piegl & Tiller
//! A5.1), the counterpart of the de Boor scheme for refinement.
//!
//! Inserting `u` into the span `[u_k, u_{k+1})` of a degree-`p` curve replaces the control
//! points `P_{k−p+1} … P_k` by
//!
//! ```text
//! Q_i = (1 − α_i) P_{i−1} + α_i P_i,   α_i = (u − u_i)/(u_{i+p} − u_i),   i = k−p+1, …, k,
//! ```
//!
//! and keeps the others; the curve does not change. A NURBS curve does this to its homogeneous
//! points `(w P, w)`.

use super::basis::find_span;
use super::curve::BSplineCurve;
use crate::cost::{polynomial_bits, Cost};
use crate::error::{check_finite, Result};
use crate::scalar::Scalar;

/// One insertion of Boehm's algorithm: the knot, its span, the `α_i` and the curve after it.
#[derive(Debug, Clone, PartialEq)]
pub struct BoehmStep<T: Scalar = f64> {
    /// The knot `u` inserted.
    pub knot: T,
    /// The span `k` with `u_k ≤ u < u_{k+1}` (as [`find_span`]) before the insertion.
    pub span: usize,
    /// `α_{k−p+1}, …, α_k`.
    pub alphas: Vec<T>,
    /// The curve with `u` inserted (its control points are the new polygon).
    pub curve: BSplineCurve<T>,
}

impl<T: Scalar> BSplineCurve<T> {
    /// Boehm's algorithm inserting `us` one after the other, in the order given: each step's
    /// span, `α_i` and refined curve.
    ///
    /// # Errors
    /// As [`insert_knots`](Self::insert_knots): [`crate::Error::NonFinite`],
    /// [`crate::Error::ParameterOutOfRange`] for a knot not strictly inside the domain,
    /// [`crate::Error::InvalidArgument`] for a knot that would occur more than `p + 1` times.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// // The quadratic on (0,0), (1,2), (3,2), (4,0), knots 0,0,0,½,1,1,1: u = ¼ lies in
    /// // span 2, α_1 = (¼ − u_1)/(u_3 − u_1) = ½, α_2 = (¼ − u_2)/(u_4 − u_2) = ¼.
    /// let p = DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], p)?;
    /// let steps = c.boehm_scheme(&[0.25])?;
    /// assert_eq!(steps[0].span, 2);
    /// assert_eq!(steps[0].alphas, vec![0.5, 0.25]);
    /// assert_eq!(steps[0].curve.control().ncols(), 5);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn boehm_scheme(&self, us: &[T]) -> Result<Vec<BoehmStep<T>>> {
        check_finite("inserted knots", us.iter())?;
        let mut steps: Vec<BoehmStep<T>> = Vec::with_capacity(us.len());
        for u in us {
            let current = steps.last().map_or(self, |s| &s.curve);
            let next = current.insert_knot(u.clone())?;
            let p = current.degree();
            let knots = current.knots().as_slice();
            let k = find_span(p, current.control().ncols(), knots, u)?;
            let alphas = (k + 1 - p..=k)
                .map(|i| (u.clone() - knots[i].clone()) / (knots[i + p].clone() - knots[i].clone()))
                .collect();
            steps.push(BoehmStep {
                knot: u.clone(),
                span: k,
                alphas,
                curve: next,
            });
        }
        Ok(steps)
    }

    /// The cost of inserting `count` knots of `inserted_bits` bits
    /// ([`insert_knots`](Self::insert_knots), or [`boehm_scheme`](Self::boehm_scheme)): per
    /// knot `(p + 1)(d + 1)` combinations and a copy of the `n + count` control points, on
    /// numbers that grow by the bits of the knot inserted (and its `α`) at each insertion.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use cagd::cost::Cost;
    /// use nalgebra::DMatrix;
    /// let c = BSplineCurve::clamped(2, DMatrix::from_row_slice(1, 4, &[0.0, 1.0, 2.0, 3.0]))?;
    /// // 2 knots: 2 · (3 · 2 + 6 · 2) operations.
    /// assert_eq!(c.insertion_cost(2, 0), Cost::new(36, 4));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn insertion_cost(&self, count: usize, inserted_bits: u128) -> Cost {
        let (p1, d1) = (self.degree() as u128 + 1, self.dim() as u128 + 1);
        let r = count as u128;
        let total = (self.control().ncols() as u128).saturating_add(r);
        let knot_bits = crate::cost::max_bits(self.knots().as_slice());
        let control_bits = crate::cost::max_bits(self.control().iter());
        Cost::new(
            r.saturating_mul(p1 * d1 + total.saturating_mul(d1)),
            polynomial_bits(
                count.saturating_mul(2),
                inserted_bits,
                control_bits.saturating_add(knot_bits.saturating_mul(2)),
            ),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;
    use num_rational::BigRational;

    #[test]
    fn the_steps_end_where_insert_knots_ends() {
        let q = |a: i64, b: i64| BigRational::new(a.into(), b.into());
        let p = DMatrix::from_row_slice(2, 4, &[0, 1, 3, 4, 0, 2, 2, 0].map(|x| q(x, 1)));
        let c = BSplineCurve::new(2, [0, 0, 0, 1, 2, 2, 2].map(|x| q(x, 2)).to_vec(), p).unwrap();
        let us = [q(3, 4), q(1, 4), q(3, 4)];
        let steps = c.boehm_scheme(&us).unwrap();
        assert_eq!(steps.len(), 3);
        assert_eq!(steps[2].curve, c.insert_knots(&us).unwrap());
        // u = 3/4 in span 3 of 0,0,0,1/2,1,1,1: α_2 = (3/4 − 0)/(1 − 0), α_3 = (3/4 − 1/2)/(1 − 1/2).
        assert_eq!(steps[0].alphas, vec![q(3, 4), q(1, 2)]);
        assert!(c.boehm_scheme(&[q(1, 1)]).is_err());
    }
}
