//! The whole de Boor scheme of one evaluation (the B-spline counterpart of the de Casteljau
//! triangle, thesis §2.1).
//!
//! On the span `s` (`u_s ≤ u < u_{s+1}`) level 0 holds the control points
//! `P_{s−p}, …, P_s`; level `r` holds `d_i^r = (1 − α_i^r) d_{i−1}^{r−1} + α_i^r d_i^{r−1}`,
//! `α_i^r = (u − u_i)/(u_{i+p+1−r} − u_i)`, for `i = s − p + r, …, s`; level `p` is the single
//! point `C(u)`, the value [`BSplineCurve::de_boor`] returns (the same operations).

use nalgebra::{DMatrix, DVector};

use super::basis::find_span;
use super::curve::BSplineCurve;
use crate::error::Result;
use crate::scalar::Scalar;

/// The de Boor scheme at one parameter: the span and the levels.
#[derive(Debug, Clone, PartialEq)]
pub struct DeBoorScheme<T: Scalar = f64> {
    /// The span `s` with `u_s ≤ u < u_{s+1}` (as [`find_span`]).
    pub span: usize,
    /// `levels[r]` is the `d × (p + 1 − r)` matrix of `d_{s−p+r}^r, …, d_s^r`.
    pub levels: Vec<DMatrix<T>>,
    /// `alphas[r − 1]` holds `α_{s−p+r}^r, …, α_s^r` of level `r`.
    pub alphas: Vec<Vec<T>>,
}

impl<T: Scalar> BSplineCurve<T> {
    /// The de Boor scheme at `u`.
    ///
    /// # Errors
    /// [`crate::Error::ParameterOutOfRange`] outside the domain.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// let p = DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], p)?;
    /// let s = c.de_boor_scheme(0.25)?;
    /// assert_eq!(s.span, 2);
    /// assert_eq!(s.alphas[0], vec![0.5, 0.25]);
    /// assert_eq!(s.levels[2].as_slice(), c.de_boor(0.25)?.as_slice());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn de_boor_scheme(&self, u: T) -> Result<DeBoorScheme<T>> {
        let (p, knots) = (self.degree(), self.knots().as_slice());
        let s = find_span(p, self.control().ncols(), knots, &u)?;
        let mut d: Vec<DVector<T>> = (0..=p)
            .map(|j| self.control().column(s - p + j).into_owned())
            .collect();
        let mut levels = vec![DMatrix::from_columns(&d)];
        let mut alphas = Vec::with_capacity(p);
        for r in 1..=p {
            let mut level_alphas = vec![T::zero(); p + 1 - r];
            for j in (r..=p).rev() {
                let i = s - p + j;
                let alpha = (u.clone() - knots[i].clone())
                    / (knots[i + p + 1 - r].clone() - knots[i].clone());
                let one_minus = T::one() - alpha.clone();
                d[j] = DVector::from_fn(d[j].len(), |c, _| {
                    one_minus.clone() * d[j - 1][c].clone() + alpha.clone() * d[j][c].clone()
                });
                level_alphas[j - r] = alpha;
            }
            levels.push(DMatrix::from_columns(&d[r..]));
            alphas.push(level_alphas);
        }
        Ok(DeBoorScheme {
            span: s,
            levels,
            alphas,
        })
    }
}
