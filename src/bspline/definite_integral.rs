//! The definite integral of a B-spline curve over any interval, with the curve outside its
//! domain continued, zero or periodic (scipy's `BSpline.integrate`); the antiderivative it
//! uses is [`crate::integral::bspline_antiderivative`].

use nalgebra::DVector;

use super::curve::BSplineCurve;
use super::extrapolate::{wrap_periodic, Extrapolation};
use crate::error::{check_finite, Result};
use crate::scalar::Scalar;

impl<T: Scalar> BSplineCurve<T> {
    /// The definite integral `∫_a^b C(u) du` (a point of the curve's dimension), with the curve
    /// outside its domain `[u_p, u_n]` taken as `extrapolation` says (scipy's
    /// `BSpline.integrate`):
    /// - [`Extrapolation::Continue`]: the end pieces continued, `F(b) − F(a)` with `F` the
    ///   [`bspline_antiderivative`](crate::integral::bspline_antiderivative);
    /// - [`Extrapolation::Outside`]: zero outside — `a` and `b` clipped to the domain;
    /// - [`Extrapolation::Periodic`]: the curve repeated with period `L = u_n − u_p`: with
    ///   `b − a = kL + r` (`0 ≤ r < L`) the integral is `k ∫_{u_p}^{u_n} C` plus the integral
    ///   over `[a', a' + r]`, `a'` the parameter `a` wrapped into the domain, split at `u_n`.
    ///
    /// For `b < a` it is `−∫_b^a`. Rational: exact in `BigRational`.
    ///
    /// # Errors
    /// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite bound.
    ///
    /// ```
    /// use cagd::bspline::{BSplineCurve, Extrapolation};
    /// use nalgebra::DMatrix;
    /// // C(u) = u on [0, 1] (a clamped line), continued as u beyond it.
    /// let c = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], DMatrix::from_row_slice(1, 2, &[0.0, 1.0]))?;
    /// assert_eq!(c.integral(0.0, 2.0, Extrapolation::Continue)?[0], 2.0);
    /// assert_eq!(c.integral(0.0, 2.0, Extrapolation::Outside(0.0))?[0], 0.5);
    /// assert_eq!(c.integral(0.0, 2.0, Extrapolation::Periodic)?[0], 1.0);
    /// assert_eq!(c.integral(1.0, 0.0, Extrapolation::Continue)?[0], -0.5);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn integral(&self, a: T, b: T, extrapolation: Extrapolation<T>) -> Result<DVector<T>> {
        check_finite("integration bounds", [&a, &b])?;
        if b < a {
            return Ok(self.integral(b, a, extrapolation)?.map(|x| -x));
        }
        let f = crate::integral::bspline_antiderivative(self)?;
        let (lo, hi) = self.domain();
        let between = |x: T, y: T| {
            let (fx, fy) = (f.eval(x), f.eval(y));
            DVector::from_iterator(
                fx.len(),
                fy.iter().zip(fx.iter()).map(|(b, a)| b.clone() - a.clone()),
            )
        };
        let add = |a: DVector<T>, b: DVector<T>| {
            DVector::from_iterator(
                a.len(),
                a.iter().zip(b.iter()).map(|(x, y)| x.clone() + y.clone()),
            )
        };
        Ok(match extrapolation {
            Extrapolation::Continue => between(a, b),
            Extrapolation::Outside(_) => {
                let clip = |x: T| {
                    if x < lo {
                        lo.clone()
                    } else if x > hi {
                        hi.clone()
                    } else {
                        x
                    }
                };
                between(clip(a), clip(b))
            }
            Extrapolation::Periodic => {
                let period = hi.clone() - lo.clone();
                let whole = (b.clone() - a.clone()) / period.clone();
                let k = super::extrapolate::floor(&whole);
                let rest = b - a.clone() - k.clone() * period.clone();
                let whole_periods = between(lo.clone(), hi.clone()).map(|x| x * k.clone());
                let start = wrap_periodic(a, &lo, &hi);
                let end = start.clone() + rest;
                let part = if end <= hi {
                    between(start, end)
                } else {
                    let over = end - hi.clone();
                    add(
                        between(start, hi.clone()),
                        between(lo.clone(), lo.clone() + over),
                    )
                };
                add(whole_periods, part)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;
    use num_rational::BigRational;

    fn r(a: i64, b: i64) -> BigRational {
        BigRational::new(a.into(), b.into())
    }

    /// A cubic over non-uniform knots with a double knot, exactly.
    fn cubic() -> BSplineCurve<BigRational> {
        let knots = [0, 0, 0, 0, 1, 3, 3, 4, 6, 6, 6, 6]
            .map(|k| r(k, 1))
            .to_vec();
        let c = [1, -2, 5, 3, 0, 7, 2, 4].map(|x| r(x, 2));
        BSplineCurve::new(3, knots, DMatrix::from_row_slice(1, 8, &c)).unwrap()
    }

    #[test]
    fn integral_matches_simpson_on_each_piece() {
        // On each polynomial piece (degree 3), Simpson's rule is exact.
        let c = cubic();
        let knots = [0, 1, 3, 4, 6];
        let mut total = r(0, 1);
        for w in knots.windows(2) {
            let (a, b) = (r(w[0], 1), r(w[1], 1));
            let m = (a.clone() + b.clone()) / r(2, 1);
            let simpson = (b.clone() - a.clone()) / r(6, 1)
                * (c.eval(a.clone())[0].clone()
                    + r(4, 1) * c.eval(m)[0].clone()
                    + c.eval(b.clone())[0].clone());
            assert_eq!(
                c.integral(a, b, Extrapolation::Continue).unwrap()[0],
                simpson
            );
            total += simpson;
        }
        assert_eq!(
            c.integral(r(0, 1), r(6, 1), Extrapolation::Continue)
                .unwrap()[0],
            total
        );
        let from_one = c
            .integral(r(1, 1), r(6, 1), Extrapolation::Continue)
            .unwrap()[0]
            .clone();
        let to_four = c
            .integral(r(0, 1), r(4, 1), Extrapolation::Continue)
            .unwrap()[0]
            .clone();
        let periodic = c
            .integral(r(1, 1), r(22, 1), Extrapolation::Periodic)
            .unwrap()[0]
            .clone();
        // [1, 22] = [1, 6] + 2 periods [6, 18] + [18, 22] ≅ [0, 4].
        assert_eq!(periodic, from_one + r(2, 1) * total + to_four);
    }

    #[test]
    fn scipy_numbers() {
        // scipy 1.17: BSpline([0,0,0,1,2,3,3,3], [1,3,2,-1,4], 2).antiderivative().c starts
        // 0, 1/3, 7/3, 13/3, 11/3, 5 (then repeats 5), and integrate(0.5, 2.5) = 37/12.
        let knots = [0, 0, 0, 1, 2, 3, 3, 3].map(|k| r(k, 1)).to_vec();
        let c = [1, 3, 2, -1, 4].map(|x| r(x, 1));
        let s = BSplineCurve::new(2, knots, DMatrix::from_row_slice(1, 5, &c)).unwrap();
        let f = crate::integral::bspline_antiderivative(&s).unwrap();
        let want = [r(0, 1), r(1, 3), r(7, 3), r(13, 3), r(11, 3), r(5, 1)];
        assert_eq!(f.control().iter().cloned().collect::<Vec<_>>(), want);
        let i = s
            .integral(r(1, 2), r(5, 2), Extrapolation::Continue)
            .unwrap();
        assert_eq!(i[0], r(37, 12));
    }
}
