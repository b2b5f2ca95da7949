//! The design (collocation) matrix of a B-spline basis and the single B-spline as a curve
//! (scipy's `BSpline.design_matrix` and `BSpline.basis_element`).

use nalgebra::DMatrix;

use super::basis::{basis_functions, extended_span, find_span};
use super::curve::BSplineCurve;
use super::knots::check_knot_slice;
use crate::error::{check_finite, Error, Result};
use crate::scalar::Scalar;

/// The design matrix `A[r, i] = N_{i,p}(x_r)` of the basis of degree `p` over given knots at the
/// parameters `x_0, …`, stored by rows as scipy's CSR: row `r` has its `p + 1` possibly
/// non-zero entries `values[r(p+1) .. (r+1)(p+1)]` in the columns
/// `first_column[r] .. first_column[r] + p` (`first_column[r] = s − p`, `s` the span of `x_r`).
#[derive(Debug, Clone, PartialEq)]
pub struct DesignMatrix<T: Scalar = f64> {
    /// Number of rows (parameters).
    pub rows: usize,
    /// Number of columns (basis functions, `knots − p − 1`).
    pub columns: usize,
    /// The degree `p`: each row holds `p + 1` values.
    pub degree: usize,
    /// The column of the first value of each row.
    pub first_column: Vec<usize>,
    /// The values, `p + 1` per row.
    pub values: Vec<T>,
}

impl<T: Scalar> DesignMatrix<T> {
    /// The dense matrix (`rows × columns`).
    pub fn to_dense(&self) -> DMatrix<T> {
        let mut a = DMatrix::from_element(self.rows, self.columns, T::zero());
        let w = self.degree + 1;
        for (r, first) in self.first_column.iter().enumerate() {
            for k in 0..w {
                a[(r, first + k)] = self.values[r * w + k].clone();
            }
        }
        a
    }
}

/// The design matrix of the degree-`p` basis over `knots` at the parameters `xs`. Inside the
/// domain `[u_p, u_n]` the basis of [`basis_functions`] on the span of [`find_span`]; with
/// `extrapolate` a parameter outside it takes the first or the last piece continued (as
/// [`BSplineCurve::eval`]); without, it is an error.
///
/// # Errors
/// [`Error::KnotCount`] for fewer than `2p + 2` knots; the knot checks of
/// [`BSplineCurve::new`]; [`Error::NonFinite`] for a NaN or infinite parameter;
/// [`Error::ParameterOutOfRange`] outside the domain without `extrapolate`.
///
/// ```
/// use cagd::bspline::design_matrix;
/// let a = design_matrix(1, &[0.0, 0.0, 1.0, 2.0, 2.0], &[0.5, 1.5], false)?;
/// assert_eq!(a.first_column, vec![0, 1]);
/// assert_eq!(a.values, vec![0.5, 0.5, 0.5, 0.5]);
/// assert!(design_matrix(1, &[0.0, 0.0, 1.0, 2.0, 2.0], &[2.5], false).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn design_matrix<T: Scalar>(
    p: usize,
    knots: &[T],
    xs: &[T],
    extrapolate: bool,
) -> Result<DesignMatrix<T>> {
    let what = "design matrix knots";
    // n = len − p − 1 control points, at least p + 1 (checked: p may be any size).
    let n = p
        .checked_add(1)
        .and_then(|q| knots.len().checked_sub(q))
        .filter(|n| *n > p)
        .ok_or(Error::KnotCount {
            what,
            expected: p.saturating_add(1).saturating_mul(2),
            found: knots.len(),
        })?;
    super::knots::KnotVector::new(knots.to_vec())?;
    check_knot_slice(what, p, n, knots)?;
    check_finite("design matrix parameters", xs.iter())?;
    let mut first_column = Vec::with_capacity(xs.len());
    let mut values = Vec::with_capacity(xs.len() * (p + 1));
    for x in xs {
        let span = if extrapolate {
            extended_span(p, n, knots, x).ok_or_else(|| unreachable_non_finite(x))?
        } else {
            find_span(p, n, knots, x)?
        };
        first_column.push(span - p);
        values.extend(basis_functions(p, knots, span, x)?);
    }
    Ok(DesignMatrix {
        rows: xs.len(),
        columns: n,
        degree: p,
        first_column,
        values,
    })
}

/// The parameters were checked finite: `extended_span` finds a span for each.
fn unreachable_non_finite<T: Scalar>(x: &T) -> Error {
    Error::NonFinite {
        what: "design matrix parameters",
        index: 0,
        value: x.to_f64(),
    }
}

impl<T: Scalar> BSplineCurve<T> {
    /// The single B-spline `N_{0,k}` of degree `k = len − 2` over the knots `t_0 ≤ … ≤ t_{k+1}`
    /// as a curve whose domain is `[t_0, t_{k+1}]` (scipy's `BSpline.basis_element`): the
    /// knots padded with `k` knots `t_0 − 1` in front and `k` knots `t_{k+1} + 1` behind, the
    /// control points zero but the `(k+1)`-th, which is one. Zero outside `[t_0, t_{k+1}]`
    /// as far as the padding reaches.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 knots; as [`new`](Self::new).
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// let hat = BSplineCurve::basis_element(&[0.0, 1.0, 2.0])?; // degree 1
    /// assert_eq!(hat.eval(0.5)[0], 0.5);
    /// assert_eq!(hat.eval(1.0)[0], 1.0);
    /// assert_eq!(hat.domain(), (0.0, 2.0));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn basis_element(knots: &[T]) -> Result<Self> {
        if knots.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "basis element knots",
                min: 2,
                found: knots.len(),
            });
        }
        check_finite("basis element knots", knots.iter())?;
        let k = knots.len() - 2;
        let (first, last) = (knots[0].clone(), knots[k + 1].clone());
        let mut padded = vec![first - T::one(); k];
        padded.extend_from_slice(knots);
        padded.extend(std::iter::repeat_n(last + T::one(), k));
        let n = padded.len() - k - 1;
        let mut control = DMatrix::from_element(1, n, T::zero());
        control[(0, k)] = T::one();
        Self::new(k, padded, control)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn rows_sum_to_one_and_match_the_curve() {
        let r = |a: i64, b: i64| BigRational::new(a.into(), b.into());
        let knots = [0, 0, 0, 1, 3, 4, 4, 4].map(|k| r(k, 1)).to_vec();
        let xs = [r(0, 1), r(1, 2), r(3, 1), r(4, 1), r(-1, 2), r(9, 2)];
        let a = design_matrix(2, &knots, &xs, true).unwrap();
        assert_eq!((a.rows, a.columns), (6, 5));
        let dense = a.to_dense();
        for row in dense.row_iter() {
            assert_eq!(row.iter().cloned().sum::<BigRational>(), r(1, 1));
        }
        // A · c is the curve with control points c.
        let c = [3, -1, 4, 1, -5].map(|x| r(x, 1));
        let curve = BSplineCurve::new(2, knots.clone(), DMatrix::from_row_slice(1, 5, &c)).unwrap();
        let ac = &dense * nalgebra::DVector::from_row_slice(&c);
        for (x, y) in xs.iter().zip(ac.iter()) {
            assert_eq!(&curve.eval(x.clone())[0], y);
        }
        assert!(matches!(
            design_matrix(2, &knots, &[r(-1, 2)], false),
            Err(Error::ParameterOutOfRange { .. })
        ));
        assert!(matches!(
            design_matrix(4, &knots, &[r(1, 2)], false),
            Err(Error::KnotCount { .. })
        ));
    }

    #[test]
    fn basis_element_is_the_cubic_bell() {
        // The uniform cubic B-spline on 0..4 is 1/6 at 1 and 2/3 at 2.
        let b = BSplineCurve::basis_element(&[0.0, 1.0, 2.0, 3.0, 4.0]).unwrap();
        assert_eq!(b.degree(), 3);
        assert!((b.eval(1.0)[0] - 1.0 / 6.0).abs() < 1e-15);
        assert!((b.eval(2.0)[0] - 2.0 / 3.0).abs() < 1e-15);
        assert_eq!(b.eval(0.0)[0], 0.0);
    }
}
