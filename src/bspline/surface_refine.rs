//! Degree elevation and knot insertion of tensor-product B-spline surfaces, one direction at
//! a time: along `u` the surface is the B-spline curve whose control points are the columns
//! `(P_{i,0}, …, P_{i,nv−1})` of the net stacked (all coordinates), so the curve algorithms
//! apply unchanged (Piegl & Tiller §5.5).

use nalgebra::DMatrix;

use super::curve::BSplineCurve;
use super::surface::BSplineSurface;
use crate::error::Result;
use crate::scalar::Scalar;

impl<T: Scalar> BSplineSurface<T> {
    /// The net along `u` as one curve: control point `i` holds `P_{i,j}` for every `j` and
    /// coordinate (`d · nv` numbers).
    fn along_u(&self) -> Result<BSplineCurve<T>> {
        let coords = self.coordinates();
        let (nu, nv) = coords[0].shape();
        let d = coords.len();
        let control = DMatrix::from_fn(d * nv, nu, |r, i| coords[r % d][(i, r / d)].clone());
        BSplineCurve::new(
            self.degrees().0,
            self.knots().0.as_slice().to_vec(),
            control,
        )
    }

    /// The net along `v` as one curve (`d · nu` numbers per control point).
    fn along_v(&self) -> Result<BSplineCurve<T>> {
        let coords = self.coordinates();
        let (nu, nv) = coords[0].shape();
        let d = coords.len();
        let control = DMatrix::from_fn(d * nu, nv, |r, j| coords[r % d][(r / d, j)].clone());
        BSplineCurve::new(
            self.degrees().1,
            self.knots().1.as_slice().to_vec(),
            control,
        )
    }

    /// The surface with the `u` direction replaced by `curve` (from [`along_u`](Self::along_u)).
    fn with_u(&self, curve: &BSplineCurve<T>) -> Result<Self> {
        let d = self.coordinates().len();
        let nv = self.coordinates()[0].ncols();
        let c = curve.control();
        let coords = (0..d)
            .map(|k| DMatrix::from_fn(c.ncols(), nv, |i, j| c[(k + d * j, i)].clone()))
            .collect();
        BSplineSurface::new(
            curve.degree(),
            self.degrees().1,
            curve.knots().as_slice().to_vec(),
            self.knots().1.as_slice().to_vec(),
            coords,
        )
    }

    /// The surface with the `v` direction replaced by `curve` (from [`along_v`](Self::along_v)).
    fn with_v(&self, curve: &BSplineCurve<T>) -> Result<Self> {
        let d = self.coordinates().len();
        let nu = self.coordinates()[0].nrows();
        let c = curve.control();
        let coords = (0..d)
            .map(|k| DMatrix::from_fn(nu, c.ncols(), |i, j| c[(k + d * i, j)].clone()))
            .collect();
        BSplineSurface::new(
            self.degrees().0,
            curve.degree(),
            self.knots().0.as_slice().to_vec(),
            curve.knots().as_slice().to_vec(),
            coords,
        )
    }

    /// The same surface with its degrees raised by `(ru, rv)`
    /// ([`BSplineCurve::elevate`] along each direction). Exact in rationals.
    ///
    /// # Errors
    /// [`crate::Error::InvalidArgument`] for a direction to raise whose knots are not clamped.
    ///
    /// ```
    /// use cagd::bspline::BSplineSurface;
    /// use nalgebra::DMatrix;
    /// let z = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 1.0, 3.0]);
    /// let s = BSplineSurface::new(1, 1, vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 0.0, 1.0, 1.0], vec![z])?;
    /// let e = s.elevate(1, 2)?;
    /// assert_eq!(e.degrees(), (2, 3));
    /// assert!((e.try_eval(0.3, 0.7)?[0] - s.try_eval(0.3, 0.7)?[0]).abs() < 1e-15);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn elevate(&self, ru: usize, rv: usize) -> Result<Self> {
        let mut s = self.clone();
        if ru > 0 {
            s = s.with_u(&s.along_u()?.elevate(ru)?)?;
        }
        if rv > 0 {
            s = s.with_v(&s.along_v()?.elevate(rv)?)?;
        }
        Ok(s)
    }

    /// The same surface over refined knot vectors: `us` inserted along `u`, `vs` along `v`
    /// ([`BSplineCurve::insert_knots`]). Exact in rationals.
    ///
    /// # Errors
    /// As [`BSplineCurve::insert_knots`]: a knot not strictly inside its domain, or one that
    /// would occur more than degree + 1 times.
    pub fn insert_knots(&self, us: &[T], vs: &[T]) -> Result<Self> {
        let mut s = self.clone();
        if !us.is_empty() {
            s = s.with_u(&s.along_u()?.insert_knots(us)?)?;
        }
        if !vs.is_empty() {
            s = s.with_v(&s.along_v()?.insert_knots(vs)?)?;
        }
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::from_ratio(n, d)
    }

    #[test]
    fn refinement_keeps_the_surface_exactly() {
        let ku = vec![
            q(0, 1),
            q(0, 1),
            q(0, 1),
            q(1, 2),
            q(1, 1),
            q(1, 1),
            q(1, 1),
        ];
        let kv = vec![q(0, 1), q(0, 1), q(1, 1), q(1, 1)];
        let coords = (0..3)
            .map(|k| DMatrix::from_fn(4, 2, |i, j| q((7 * i + 3 * j + k) as i64 % 5, 1 + k as i64)))
            .collect();
        let s = BSplineSurface::new(2, 1, ku, kv, coords).unwrap();
        let r = s
            .elevate(1, 2)
            .unwrap()
            .insert_knots(&[q(1, 3)], &[q(1, 4), q(1, 4)])
            .unwrap();
        assert_eq!(r.degrees(), (3, 3));
        for (i, j) in [(0, 0), (1, 3), (2, 5), (5, 1), (6, 6)] {
            let (u, v) = (q(i, 6), q(j, 6));
            assert_eq!(
                r.try_eval(u.clone(), v.clone()).unwrap(),
                s.try_eval(u, v).unwrap()
            );
        }
    }
}
