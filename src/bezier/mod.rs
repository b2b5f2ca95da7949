//! Bézier curves and patches (thesis chapters 2 and 3).
//!
//! - [`BezierCurve`]: a polynomial curve of any degree in any dimension, evaluated by de
//!   Casteljau's algorithm ([`BezierCurve::eval`]), the Bernstein form
//!   ([`BezierCurve::eval_bernstein`]) or the matrix (monomial) form of the course notes
//!   ([`BezierCurve::matrix_form`]); the whole de Casteljau triangle is a
//!   [`DeCasteljauScheme`]. Derivatives are again Bézier curves
//!   ([`BezierCurve::derivative`]); curves can be split ([`BezierCurve::subdivide`]), raised in
//!   degree ([`BezierCurve::elevate`]) and defined over any interval `[a, b]`.
//! - [`BezierPatch`]: a tensor-product patch of degree `(m, n)`, `m ≠ n` allowed, evaluated by
//!   the tensor de Casteljau algorithm ([`BezierPatch::eval`], all levels in a [`PatchScheme`]),
//!   the Bernstein form, or on a whole grid through basis matrices
//!   ([`BezierPatch::try_eval_grid`]). Partial derivatives are patches
//!   ([`BezierPatch::derivative`]); the four boundary curves are [`BezierCurve`]s
//!   ([`BezierPatch::boundary`], [`Edge`]). The bilinear patch (hyperbolic paraboloid) of thesis
//!   §3.1 is [`BezierPatch::bilinear`]. Patches are raised in degree
//!   ([`BezierPatch::elevate`]), split at `u = t` or `v = t` ([`BezierPatch::subdivide`],
//!   [`Direction`]) and integrated ([`BezierPatch::integral`],
//!   [`BezierPatch::antiderivative`]) through their control curves
//!   ([`BezierPatch::control_curves`]).
//!
//! Layouts: a curve's control points are the **columns** of a `d × (n+1)` matrix (the thesis's
//! `3 × (n+1)` control matrices); a patch keeps one `(m+1) × (n+1)` matrix per coordinate, entry
//! `(i, j)` belonging to `b_{i,j}`, `i` along `u`, `j` along `v`, as in the thesis.
//!
//! Everything is generic over [`Scalar`]: the same code runs in `f64` and exactly
//! in `BigRational`.

mod bilinear;
mod bilinear_patch;
mod curve;
mod matrix_form;
mod patch;
mod patch_elevate;
mod patch_integral;
mod patch_subdivide;
mod scheme;

/// The matrices of the matrix form, owned by [`crate::conversion`] and re-exported here beside
/// [`MatrixForm`].
pub use crate::conversion::{bezier_to_monomial_matrix, cubic_bezier_matrix};
pub use bilinear::bilinear_interpolate;
pub use curve::BezierCurve;
pub use matrix_form::MatrixForm;
pub use patch::{BezierPatch, Edge};
pub use patch_subdivide::Direction;
pub use scheme::{DeCasteljauScheme, PatchScheme, PatchStep};

use nalgebra::DMatrix;

use crate::error::{check_finite, Error, Result};
use crate::scalar::Scalar;

/// Checks a list of parameter values: non-empty and finite.
pub(crate) fn check_params<T: Scalar>(what: &'static str, ts: &[T]) -> Result<()> {
    if ts.is_empty() {
        return Err(Error::EmptyGrid {
            what,
            min: 1,
            found: 0,
        });
    }
    crate::error::check_finite_slice(what, ts)
}

/// Checks one parameter value.
pub(crate) fn check_param<T: Scalar>(what: &'static str, t: &T) -> Result<()> {
    check_finite(what, std::iter::once(t))
}

/// The matrix product `a · b` ([`Scalar::mat_mul`]: nalgebra's blocked product for `f64`, the
/// plain triple loop `Σ_k a[i,k] b[k,j]`, `k` ascending, for other scalars).
pub(crate) fn mat_mul<T: Scalar>(a: &DMatrix<T>, b: &DMatrix<T>) -> DMatrix<T> {
    T::mat_mul(a, b)
}

/// Formats one point as `(x, y, z)`, honouring a precision given to the formatter.
pub(crate) fn format_point<'a, T: Scalar>(
    coords: impl IntoIterator<Item = &'a T>,
    precision: Option<usize>,
) -> String {
    let parts: Vec<String> = coords
        .into_iter()
        .map(|x| match precision {
            Some(p) => format!("{x:.p$}"),
            None => format!("{x}"),
        })
        .collect();
    format!("({})", parts.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn mat_mul_agrees_for_both_scalars() {
        let a = DMatrix::from_row_slice(2, 3, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let b = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
        let p = mat_mul(&a, &b);
        assert_eq!(p, DMatrix::from_row_slice(2, 2, &[4.0, 5.0, 10.0, 11.0]));
        let lift = |m: &DMatrix<f64>| m.map(|x| <BigRational as Scalar>::from_f64(x).unwrap());
        let pq = mat_mul(&lift(&a), &lift(&b));
        assert_eq!(pq, lift(&p));
        // Empty inner dimension: a zero matrix, not a panic.
        let e = mat_mul(&DMatrix::<f64>::zeros(2, 0), &DMatrix::<f64>::zeros(0, 3));
        assert_eq!(e, DMatrix::zeros(2, 3));
    }

    #[test]
    fn params_are_checked() {
        assert!(matches!(
            check_params::<f64>("ts", &[]),
            Err(Error::EmptyGrid { found: 0, .. })
        ));
        assert!(matches!(
            check_params("ts", &[0.0, f64::INFINITY]),
            Err(Error::NonFinite { index: 1, .. })
        ));
        assert!(check_params("ts", &[0.0, 1.0]).is_ok());
    }
}
