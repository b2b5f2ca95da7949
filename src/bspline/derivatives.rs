//! Derivatives of any order of a B-spline curve (scipy's `BSpline.derivative(nu)` and
//! `BSpline.__call__(x, nu)`).

use super::curve::BSplineCurve;
use super::extrapolate::Extrapolation;
use crate::error::{Error, Result};
use crate::scalar::Scalar;

impl<T: Scalar> BSplineCurve<T> {
    /// The derivative of order `r` as a curve, [`derivative`](Self::derivative) taken `r`
    /// times: degree `p − r`, the knots without the first and the last `r`, control points
    /// `Q^{(k)}_i = (p−k+1)(Q^{(k−1)}_{i+1} − Q^{(k−1)}_i)/(u_{i+p+1} − u_{i+k})`. `r = 0`
    /// is the curve itself.
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] for `r > p`.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// // C(u) = u² on [0, 1] (Bernstein coefficients 0, 0, 1): C'' = 2.
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], DMatrix::from_row_slice(1, 3, &[0.0, 0.0, 1.0]))?;
    /// assert_eq!(c.derivative_of_order(2)?.eval(0.3)[0], 2.0);
    /// assert!(c.derivative_of_order(3).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn derivative_of_order(&self, r: usize) -> Result<Self> {
        if r > self.degree() {
            return Err(Error::DerivativeOrder {
                order: r,
                degree: self.degree(),
            });
        }
        let mut c = self.clone();
        for _ in 0..r {
            c = c.derivative()?;
        }
        Ok(c)
    }

    /// The derivative of order `r` at all parameters `us`, written into `out` (`us.len() × d`
    /// row-major), outside the domain as `extrapolation` says ([`eval_many_extrapolated_into`](Self::eval_many_extrapolated_into)
    /// of [`derivative_of_order`](Self::derivative_of_order)). Above the degree the
    /// derivative is zero (NaN where an extrapolated value is NaN).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · d`.
    ///
    /// ```
    /// use cagd::bspline::{BSplineCurve, Extrapolation};
    /// use nalgebra::DMatrix;
    /// let c = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], DMatrix::from_row_slice(1, 2, &[1.0, 3.0]))?;
    /// let mut out = [0.0; 2];
    /// c.eval_derivative_many_into(1, &[0.5, 2.0], &mut out, &Extrapolation::Continue)?;
    /// assert_eq!(out, [2.0, 2.0]);
    /// c.eval_derivative_many_into(2, &[0.5, 2.0], &mut out, &Extrapolation::Continue)?;
    /// assert_eq!(out, [0.0, 0.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_derivative_many_into(
        &self,
        r: usize,
        us: &[T],
        out: &mut [T],
        extrapolation: &Extrapolation<T>,
    ) -> Result<()> {
        let p = self.degree();
        let curve = self.derivative_of_order(r.min(p))?;
        curve.eval_many_extrapolated_into(us, out, extrapolation)?;
        if r > p {
            // A NaN stays NaN (0 · NaN); every finite value becomes 0.
            for x in out.iter_mut() {
                *x = x.clone() * T::zero();
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;
    use num_rational::BigRational;

    #[test]
    fn cubic_third_derivative_is_piecewise_constant() {
        let r = |a: i64| BigRational::from_integer(a.into());
        let knots = [0, 0, 0, 0, 1, 2, 2, 2, 2].map(r).to_vec();
        let c = BSplineCurve::new(
            3,
            knots,
            DMatrix::from_row_slice(1, 5, &[0, 1, 0, 2, 1].map(r)),
        )
        .unwrap();
        let d3 = c.derivative_of_order(3).unwrap();
        assert_eq!(d3.degree(), 0);
        // On [0, 1] the jump of the 2nd derivative: compare with central differences of exact
        // second derivatives (a linear function on each piece).
        let d2 = c.derivative_of_order(2).unwrap();
        let half = BigRational::new(1.into(), 2.into());
        let slope = (d2.eval(half.clone())[0].clone() - d2.eval(r(0))[0].clone()) / half.clone();
        assert_eq!(d3.eval(half)[0], slope);
        let mut out = vec![r(9); 2];
        c.eval_derivative_many_into(4, &[r(0), r(3)], &mut out, &Extrapolation::Continue)
            .unwrap();
        assert_eq!(out, vec![r(0), r(0)]);
    }
}
