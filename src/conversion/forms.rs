//! The geometry forms the course converts between ([`GeometryForm`]) and their conversion
//! matrices through the Bézier form.

use nalgebra::DMatrix;

use super::{bezier_to_monomial_matrix, conversion_matrix, invert, CubicForm};
use crate::cost::Cost;
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The five geometry forms of a polynomial curve the course converts between (the lecture
/// notes, "Konverze mezi reprezentacemi"; the matrix-form notes' product `P · M`), each a
/// geometry matrix `X` (one column per vector) that describes the curve together with a basis:
///
/// | form | geometry `X` | degree |
/// |---|---|---|
/// | Hermite (Ferguson) | `[x(0) x(1) x'(0) x'(1)]` | cubic |
/// | Bézier | `[b_0 … b_n]` | any |
/// | uniform cubic B-spline segment | `[x_{i−1} x_i x_{i+1} x_{i+2}]` | cubic |
/// | monomial | `[a_0 … a_n]`, `p(t) = Σ a_j t^j` (the matrix-form notes' `P · M`) | any |
/// | algebraic | `[a b c d]` of `u³, u², u, 1` (the lecture notes' `A`, powers descending) | any |
///
/// Two forms describe the same curve when `X_to = X_from · T`; the conversion matrix goes
/// through the Bézier form, `T = T_{from→Bézier} · T_{Bézier→to}`, with the lecture notes'
/// `M_F M_G⁻¹` between the cubic forms ([`conversion_matrix`](crate::conversion::conversion_matrix))
/// and the Bernstein-to-monomial matrix `M` of degree `n` (`M[i, j] = (−1)^{j−i} C(n, j)
/// C(j, i)`, [`bezier_to_monomial_matrix`](crate::conversion::bezier_to_monomial_matrix)) and
/// its inverse for the monomial forms (the algebraic form is the monomial one with its columns
/// reversed).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GeometryForm {
    /// Hermite (Ferguson) cubic: `[x(0) x(1) x'(0) x'(1)]`.
    Hermite,
    /// Bézier control points `b_0 … b_n` (any degree).
    Bezier,
    /// Uniform cubic B-spline segment ("Coons cubic"): `[x_{i−1} x_i x_{i+1} x_{i+2}]`.
    BSpline,
    /// Monomial coefficients `a_0 … a_n` of `1, t, …, t^n`.
    Monomial,
    /// The lecture notes' algebraic form `[a b c d]` of `u³, u², u, 1` (powers descending).
    Algebraic,
}

impl GeometryForm {
    /// The cubic form, for the three forms of the lecture notes' table.
    pub fn cubic(self) -> Option<CubicForm> {
        match self {
            GeometryForm::Hermite => Some(CubicForm::Hermite),
            GeometryForm::Bezier => Some(CubicForm::Bezier),
            GeometryForm::BSpline => Some(CubicForm::BSpline),
            GeometryForm::Monomial | GeometryForm::Algebraic => None,
        }
    }

    /// Whether the form describes cubics only (Hermite and B-spline: 4 columns).
    pub fn is_cubic_only(self) -> bool {
        matches!(self, GeometryForm::Hermite | GeometryForm::BSpline)
    }

    /// The form's name (`"hermite"`, `"bezier"`, `"bspline"`, `"monomial"`, `"algebraic"`).
    pub fn name(self) -> &'static str {
        match self {
            GeometryForm::Hermite => "hermite",
            GeometryForm::Bezier => "bezier",
            GeometryForm::BSpline => "bspline",
            GeometryForm::Monomial => "monomial",
            GeometryForm::Algebraic => "algebraic",
        }
    }

    /// `T` with `X_Bézier = X_self · T`, for a geometry of `k ≥ 1` columns (`k = 4` for the
    /// cubic-only forms).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for `k = 0`, or `k ≠ 4` in a cubic-only form;
    /// [`Error::TooLarge`] for a degree `k − 1` above
    /// [`Limits::DEFAULT`](crate::limits::Limits::DEFAULT)`.max_degree` (the matrix has `k²`
    /// entries).
    ///
    /// ```
    /// use cagd::conversion::GeometryForm;
    /// // p(t) = t: monomial [0 1], Bézier points 0, 1.
    /// let t = GeometryForm::Monomial.to_bezier::<f64>(2)?;
    /// assert_eq!(t.as_slice(), &[1.0, 0.0, 1.0, 1.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn to_bezier<T: Scalar>(self, k: usize) -> Result<DMatrix<T>> {
        self.check_columns(k)?;
        Ok(match self {
            GeometryForm::Bezier => identity(k),
            GeometryForm::Hermite | GeometryForm::BSpline => {
                conversion_matrix(self.cubic().unwrap_or(CubicForm::Bezier), CubicForm::Bezier)
            }
            GeometryForm::Monomial => invert(&bezier_to_monomial_matrix::<T>(k - 1)?)?,
            GeometryForm::Algebraic => T::mat_mul(
                &reversal(k),
                &invert(&bezier_to_monomial_matrix::<T>(k - 1)?)?,
            ),
        })
    }

    /// `T` with `X_self = X_Bézier · T`, for a geometry of `k ≥ 1` columns.
    ///
    /// # Errors
    /// As [`to_bezier`](Self::to_bezier).
    ///
    /// ```
    /// use cagd::conversion::GeometryForm;
    /// // The Bézier points 0, 1 of p(t) = t: algebraic [1 0] (t¹, t⁰).
    /// let t = GeometryForm::Algebraic.from_bezier::<f64>(2)?;
    /// let x = nalgebra::dmatrix![0.0, 1.0] * t;
    /// assert_eq!(x.as_slice(), &[1.0, 0.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn from_bezier<T: Scalar>(self, k: usize) -> Result<DMatrix<T>> {
        self.check_columns(k)?;
        Ok(match self {
            GeometryForm::Bezier => identity(k),
            GeometryForm::Hermite | GeometryForm::BSpline => {
                conversion_matrix(CubicForm::Bezier, self.cubic().unwrap_or(CubicForm::Bezier))
            }
            GeometryForm::Monomial => bezier_to_monomial_matrix::<T>(k - 1)?,
            GeometryForm::Algebraic => {
                T::mat_mul(&bezier_to_monomial_matrix::<T>(k - 1)?, &reversal(k))
            }
        })
    }

    fn check_columns(self, k: usize) -> Result<()> {
        if k > 0 {
            // k × k matrices of a polynomial of degree k − 1: bounded before they are built.
            crate::limits::Limits::DEFAULT.check_degree("geometry form conversion", k - 1)?;
        }
        if k == 0 || (self.is_cubic_only() && k != 4) {
            return Err(Error::ShapeMismatch {
                what: "geometry",
                expected: if self.is_cubic_only() {
                    format!("4 columns for the {} form (a cubic)", self.name())
                } else {
                    "at least one column".into()
                },
                found: format!("{k} columns"),
            });
        }
        Ok(())
    }
}

/// The matrix `T` with `X_to = X_from · T` for a geometry of `k` columns:
/// `T = T_{from→Bézier} · T_{Bézier→to}`, with the two factors. Exact in rationals.
///
/// # Errors
/// [`Error::ShapeMismatch`] for `k = 0` or `k ≠ 4` with a cubic-only form; [`Error::TooLarge`]
/// for a degree `k − 1` above [`Limits::DEFAULT`](crate::limits::Limits::DEFAULT)`.max_degree`.
///
/// ```
/// use cagd::conversion::{form_conversion, GeometryForm};
/// use num_rational::BigRational;
/// // The Bézier points of a quadratic as monomial coefficients: M of degree 2.
/// let (t, _, _) = form_conversion::<BigRational>(GeometryForm::Bezier, GeometryForm::Monomial, 3)?;
/// assert_eq!(t[(0, 1)], BigRational::from_integer((-2).into()));
/// # Ok::<(), cagd::Error>(())
/// ```
#[allow(clippy::type_complexity)]
pub fn form_conversion<T: Scalar>(
    from: GeometryForm,
    to: GeometryForm,
    k: usize,
) -> Result<(DMatrix<T>, DMatrix<T>, DMatrix<T>)> {
    let into = from.to_bezier::<T>(k)?;
    let out = to.from_bezier::<T>(k)?;
    let t = T::mat_mul(&into, &out);
    Ok((t, into, out))
}

/// The cost of [`form_conversion`] for a geometry of `k` columns and `d` rows, and of the
/// product `X · T`: products of `k × k` matrices, the inverse of `M` and the geometry times
/// `T`, `4k³ + 2dk²` operations on numbers of the binomials' size (about `2k` bits) over the
/// geometry's `geometry_bits`.
///
/// ```
/// use cagd::cost::Cost;
/// assert_eq!(cagd::conversion::form_conversion_cost(4, 2, 10), Cost::new(4 * 64 + 2 * 2 * 16, 26));
/// ```
pub fn form_conversion_cost(k: usize, d: usize, geometry_bits: u128) -> Cost {
    let k = k as u128;
    Cost::new(
        k.saturating_mul(k)
            .saturating_mul(k)
            .saturating_mul(4)
            .saturating_add((2 * d as u128).saturating_mul(k).saturating_mul(k)),
        geometry_bits.saturating_add(2 * k + 8),
    )
}

/// The `k × k` identity.
fn identity<T: Scalar>(k: usize) -> DMatrix<T> {
    DMatrix::from_fn(k, k, |i, j| if i == j { T::one() } else { T::zero() })
}

/// The `k × k` matrix reversing the order of columns.
fn reversal<T: Scalar>(k: usize) -> DMatrix<T> {
    DMatrix::from_fn(
        k,
        k,
        |i, j| if i + j + 1 == k { T::one() } else { T::zero() },
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(n: i64) -> BigRational {
        BigRational::from_integer(n.into())
    }

    #[test]
    fn every_form_round_trips_through_the_bezier_form_exactly() {
        use GeometryForm::*;
        for form in [Hermite, Bezier, BSpline, Monomial, Algebraic] {
            let there = form.to_bezier::<BigRational>(4).unwrap();
            let back = form.from_bezier::<BigRational>(4).unwrap();
            assert_eq!(
                BigRational::mat_mul(&there, &back),
                identity::<BigRational>(4),
                "{form:?}"
            );
        }
    }

    #[test]
    fn the_matrix_form_notes_p_times_m() {
        // b = (0, 1, 2, 3) in x is p(t) = 3t: monomial [0 3 0 0], algebraic [0 0 3 0].
        let x = DMatrix::from_row_slice(1, 4, &[q(0), q(1), q(2), q(3)]);
        let (t, _, _) =
            form_conversion::<BigRational>(GeometryForm::Bezier, GeometryForm::Monomial, 4)
                .unwrap();
        assert_eq!(
            BigRational::mat_mul(&x, &t).as_slice(),
            &[q(0), q(3), q(0), q(0)]
        );
        let (t, _, _) =
            form_conversion::<BigRational>(GeometryForm::Bezier, GeometryForm::Algebraic, 4)
                .unwrap();
        assert_eq!(
            BigRational::mat_mul(&x, &t).as_slice(),
            &[q(0), q(0), q(3), q(0)]
        );
    }

    #[test]
    fn cubic_only_forms_refuse_other_sizes() {
        assert!(matches!(
            GeometryForm::Hermite.to_bezier::<f64>(3),
            Err(Error::ShapeMismatch { .. })
        ));
        assert!(GeometryForm::Monomial.to_bezier::<f64>(3).is_ok());
        assert!(GeometryForm::Bezier.from_bezier::<f64>(0).is_err());
    }
}
