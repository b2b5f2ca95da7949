//! What a B-spline curve is outside its domain `[u_p, u_n]`: its end pieces continued, a fixed
//! value (scipy's `extrapolate=False` gives NaN), or the curve repeated periodically (scipy's
//! `extrapolate='periodic'`).

use super::curve::BSplineCurve;
use crate::error::Result;
use crate::scalar::Scalar;

/// The value of a B-spline curve outside its domain `[u_p, u_n]`.
#[derive(Debug, Clone, PartialEq)]
pub enum Extrapolation<T> {
    /// The first and the last polynomial pieces continue (the rule of
    /// [`crate::param`]: [`BSplineCurve::eval`]).
    Continue,
    /// Every coordinate is this value (NaN in scipy's `extrapolate=False`); integrals are taken
    /// over the part of the interval inside the domain.
    Outside(T),
    /// The curve repeats with period `u_n − u_p`: `C(u) = C(u_p + (u − u_p) mod (u_n − u_p))`.
    Periodic,
}

/// The largest integer `≤ x`, in `T`: exact for rationals, the double's `floor` otherwise (NaN
/// and ±∞ stay as they are). No loop: a double such as `10³⁰⁰`, where `k + 1 = k`, or a
/// rational far beyond the range of doubles is floored in one step.
pub(crate) fn floor<T: Scalar>(x: &T) -> T {
    if let Some(q) = (x as &dyn std::any::Any).downcast_ref::<num_rational::BigRational>() {
        let floored: Box<dyn std::any::Any> = Box::new(q.floor());
        if let Ok(k) = floored.downcast::<T>() {
            return *k;
        }
    }
    T::from_f64(x.to_f64().floor()).unwrap_or_else(|| x.clone())
}

/// `u` wrapped into `[lo, hi)`: `lo + (u − lo) mod (hi − lo)` (scipy's periodic parameter).
///
/// ```
/// use cagd::bspline::wrap_periodic;
/// assert_eq!(wrap_periodic(7.5, &1.0, &3.0), 1.5);
/// assert_eq!(wrap_periodic(-0.5, &1.0, &3.0), 1.5);
/// assert_eq!(wrap_periodic(3.0, &1.0, &3.0), 1.0);
/// ```
pub fn wrap_periodic<T: Scalar>(u: T, lo: &T, hi: &T) -> T {
    let period = hi.clone() - lo.clone();
    let offset = u - lo.clone();
    let k = floor(&(offset.clone() / period.clone()));
    let wrapped = lo.clone() + offset - k * period;
    // Rounding in f64 may land on `hi` itself, or (for `u` far beyond the period, where
    // `lo + offset` loses `lo`) below `lo`.
    if &wrapped >= hi || &wrapped < lo {
        lo.clone()
    } else {
        wrapped
    }
}

impl<T: Scalar> BSplineCurve<T> {
    /// The points at all parameters `us` written into `out` (`us.len() × d` row-major, as
    /// [`eval_many_into`](Self::eval_many_into)), outside the domain as `extrapolation` says.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) unless `out.len() == us.len() · d`;
    /// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or ±∞ parameter, as
    /// [`eval_many_into`](Self::eval_many_into) (scipy's "NaN in, NaN out" is the Python
    /// front end's translation).
    ///
    /// ```
    /// use cagd::bspline::{BSplineCurve, Extrapolation};
    /// use nalgebra::DMatrix;
    /// let c = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], DMatrix::from_row_slice(1, 2, &[0.0, 1.0]))?;
    /// let mut out = [0.0; 3];
    /// c.eval_many_extrapolated_into(&[0.5, 1.5, -0.75], &mut out, &Extrapolation::Periodic)?;
    /// assert_eq!(out, [0.5, 0.5, 0.25]);
    /// c.eval_many_extrapolated_into(&[0.5, 1.5, -0.75], &mut out, &Extrapolation::Outside(f64::NAN))?;
    /// assert!(out[0] == 0.5 && out[1].is_nan() && out[2].is_nan());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_many_extrapolated_into(
        &self,
        us: &[T],
        out: &mut [T],
        extrapolation: &Extrapolation<T>,
    ) -> Result<()> {
        let (lo, hi) = self.domain();
        match extrapolation {
            Extrapolation::Continue => self.eval_many_into(us, out),
            Extrapolation::Periodic => {
                let wrapped: Vec<T> = us
                    .iter()
                    .map(|u| {
                        if u.is_finite_value() {
                            wrap_periodic(u.clone(), &lo, &hi)
                        } else {
                            u.clone()
                        }
                    })
                    .collect();
                self.eval_many_into(&wrapped, out)
            }
            Extrapolation::Outside(value) => {
                self.eval_many_into(us, out)?;
                let d = self.dim();
                for (u, point) in us.iter().zip(out.chunks_mut(d)) {
                    if u.is_finite_value() && (u < &lo || u > &hi) {
                        point.fill(value.clone());
                    }
                }
                Ok(())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn floor_is_exact_for_rationals() {
        let r = |a: i64, b: i64| BigRational::new(a.into(), b.into());
        assert_eq!(floor(&r(-1, 3)), r(-1, 1));
        assert_eq!(floor(&r(7, 1)), r(7, 1));
        // Just below an integer: the double rounds to it, the correction does not.
        let below = r(1, 1) - BigRational::new(1.into(), num_bigint::BigInt::from(10).pow(30));
        assert_eq!(floor(&below), r(0, 1));
        assert_eq!(wrap_periodic(r(22, 3), &r(1, 1), &r(3, 1)), r(4, 3));
    }
}
