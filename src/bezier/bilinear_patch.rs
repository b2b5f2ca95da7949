//! The bilinear patch (thesis §3.1): a Bézier patch of degree (1, 1) from its four corners.

use nalgebra::DMatrix;

use super::bilinear::check_corners;
use super::patch::BezierPatch;
use crate::error::Result;
use crate::scalar::Scalar;

impl<T: Scalar> BezierPatch<T> {
    /// The bilinear patch (degree (1, 1)) through the corners `b00 = x(0,0)`, `b01 = x(0,1)`,
    /// `b10 = x(1,0)`, `b11 = x(1,1)` — the hyperbolic paraboloid of thesis §3.1, eq. (3.1).
    /// The argument order is the reading order of the matrix in eq. (3.2).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) if the corners differ in dimension (or are empty);
    /// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite coordinate.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p = BezierPatch::bilinear(&[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0], &[1.0, 0.0, 0.0], &[1.0, 1.0, 1.0])?;
    /// assert_eq!(p.degree(), (1, 1));
    /// assert_eq!(p.eval(0.25, 0.5).as_slice(), &[0.25, 0.5, 0.125]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn bilinear(b00: &[T], b01: &[T], b10: &[T], b11: &[T]) -> Result<Self> {
        check_corners(b00, b01, b10, b11)?;
        let coords = (0..b00.len())
            .map(|c| {
                DMatrix::from_row_slice(
                    2,
                    2,
                    &[
                        b00[c].clone(),
                        b01[c].clone(),
                        b10[c].clone(),
                        b11[c].clone(),
                    ],
                )
            })
            .collect();
        Ok(BezierPatch::from_valid(coords))
    }

    /// The hyperbolic paraboloid `z = xy` over the unit square as a bilinear patch: corners
    /// `(0,0,0)`, `(0,1,0)`, `(1,0,0)`, `(1,1,1)`, so `x(u, v) = (u, v, uv)` (thesis Slika 2).
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    /// assert_eq!(p.eval(0.5, 0.25).as_slice(), &[0.5, 0.25, 0.125]);
    /// ```
    pub fn hyperbolic_paraboloid() -> Self {
        let (o, l) = (T::zero(), T::one());
        let corner = |x: &T, y: &T, z: &T| [x.clone(), y.clone(), z.clone()];
        let coords = (0..3)
            .map(|c| {
                let pts = [
                    corner(&o, &o, &o),
                    corner(&o, &l, &o),
                    corner(&l, &o, &o),
                    corner(&l, &l, &l),
                ];
                DMatrix::from_row_slice(
                    2,
                    2,
                    &[
                        pts[0][c].clone(),
                        pts[1][c].clone(),
                        pts[2][c].clone(),
                        pts[3][c].clone(),
                    ],
                )
            })
            .collect();
        BezierPatch::from_valid(coords)
    }
}
