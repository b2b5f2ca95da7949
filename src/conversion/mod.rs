//! Matrix forms of polynomial curves and the conversions between them (the lecture notes
//! "Konverze mezi reprezentacemi", the matrix-form notes §1.2). This module is the crate's one
//! owner of matrix forms, one file each:
//!
//! - `cubic.rs`: the lecture notes' three cubic forms ([`CubicForm`]) and their basis matrices;
//! - `monomial.rs`: Bézier ↔ monomial matrices of any degree ([`bezier_to_monomial_matrix`],
//!   [`monomial_to_bezier_matrix`]), the matrix form of
//!   [`MatrixForm`](crate::bezier::MatrixForm);
//! - `forms.rs`: the five geometry forms the course converts between ([`GeometryForm`],
//!   [`form_conversion`]), through the Bézier form;
//! - `invert.rs`: [`invert`], exact in rationals.
//!
//! **One power order.** Every matrix here multiplies **ascending** powers: row `i` of a basis
//! matrix `M` holds the coefficients of the `i`-th basis function, column `p` multiplies
//! `t^p`, and a curve with geometry `X` (`d × (n+1)`, one vector per column) is
//! `X · M · [1, t, …, t^n]ᵀ`. The sources print both orders, and their matrices are kept as
//! documented views:
//!
//! | source | powers | views |
//! |---|---|---|
//! | the matrix-form notes | ascending `[1, t, t², t³]ᵀ` | [`cubic_bezier_matrix`] (the matrix itself) |
//! | the lecture notes | descending `[u³, u², u, 1]ᵀ` | [`hermite_matrix`], [`bezier_matrix`], [`bspline_matrix`], [`hermite_matrix_inverse`], [`CubicForm::lecture_notes_matrix`] (columns reversed) |
//!
//! | form | geometry `X` | lecture notes' matrix |
//! |---|---|---|
//! | Hermite (Ferguson) | `[x(0) x(1) x'(0) x'(1)]` | [`hermite_matrix`] `M_H` |
//! | Bézier | `[b_0 b_1 b_2 b_3]` | [`bezier_matrix`] `M_B` |
//! | uniform cubic B-spline ("Coons cubic") | `[x_{i−1} x_i x_{i+1} x_{i+2}]` | [`bspline_matrix`] `M_C` |
//!
//! Two forms describe the same cubic when `X_F M_F = X_G M_G`, so the geometry converts by
//! `X_G = X_F · M_F M_G⁻¹` — [`conversion_matrix`] computes that product (exactly, in
//! rationals) rather than copying the notes' table; it does not depend on the power order. The
//! tests check every entry of the printed table against it: all nine entries are right, read as
//! `X_to = X_from · T` (entry in row "to", column "from"). So is the printed `M_H⁻¹` (its rows
//! are the Hermite data of `u³, u², u, 1`). What the notes get wrong here: the B-spline surface
//! section prints the Bézier matrix as `M_S`; the right `M_S` is `M_C` ([`bspline_matrix`]).

use nalgebra::DMatrix;

use crate::scalar::Scalar;

mod cubic;
mod forms;
mod invert;
mod monomial;

pub use cubic::{bezier_matrix, bspline_matrix, hermite_matrix, hermite_matrix_inverse, CubicForm};
pub use forms::{form_conversion, form_conversion_cost, GeometryForm};
pub use invert::invert;
pub use monomial::{bezier_to_monomial_matrix, cubic_bezier_matrix, monomial_to_bezier_matrix};

/// The matrix `T = M_from · M_to⁻¹` with `X_to = X_from · T`: it converts the geometry of a
/// cubic from one form to another without changing the curve. Exact in rationals.
///
/// `T` is the same for any order of the powers (reordering the columns of both matrices
/// cancels); it is computed from the lecture notes' matrices
/// ([`CubicForm::lecture_notes_matrix`]), whose column order gives [`invert`]'s partial
/// pivoting the elimination that keeps the `f64` conversions between Hermite and Bézier form
/// exact (the ascending order would not: `Hermite → Hermite` would come out a few units in the
/// last place off the identity).
///
/// ```
/// use cagd::conversion::{conversion_matrix, CubicForm};
/// use num_rational::BigRational;
/// let t: nalgebra::DMatrix<BigRational> = conversion_matrix(CubicForm::Bezier, CubicForm::Hermite);
/// // x'(0) = 3(b_1 − b_0): column 2 is (−3, 3, 0, 0).
/// let col: Vec<i64> = t.column(2).iter().map(|x| x.to_integer().try_into().unwrap()).collect();
/// assert_eq!(col, vec![-3, 3, 0, 0]);
/// ```
pub fn conversion_matrix<T: Scalar>(from: CubicForm, to: CubicForm) -> DMatrix<T> {
    let inv = invert(&to.lecture_notes_matrix::<T>()).expect("basis matrices are invertible");
    T::mat_mul(&from.lecture_notes_matrix::<T>(), &inv)
}

/// The geometry `X_to = X_from · conversion_matrix(from, to)` (`d × 4` in, `d × 4` out).
///
/// # Errors
/// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) unless `geometry` has 4 columns.
pub fn convert<T: Scalar>(
    geometry: &DMatrix<T>,
    from: CubicForm,
    to: CubicForm,
) -> crate::Result<DMatrix<T>> {
    if geometry.ncols() != 4 {
        return Err(crate::Error::ShapeMismatch {
            what: "cubic geometry",
            expected: "4 columns (one per point or tangent of the cubic)".into(),
            found: format!("{} × {}", geometry.nrows(), geometry.ncols()),
        });
    }
    Ok(T::mat_mul(geometry, &conversion_matrix(from, to)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_and_bezier_conversions_are_exact_in_f64() {
        use CubicForm::{Bezier, Hermite};
        for f in [Hermite, Bezier] {
            assert_eq!(
                conversion_matrix::<f64>(f, f),
                DMatrix::identity(4, 4),
                "{f:?}"
            );
        }
        let to_hermite = DMatrix::from_row_slice(
            4,
            4,
            &[
                1.0, 0.0, -3.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, -3.0, 0.0, 1.0, 0.0, 3.0,
            ],
        );
        assert_eq!(conversion_matrix::<f64>(Bezier, Hermite), to_hermite);
        let back = conversion_matrix::<f64>(Hermite, Bezier);
        assert_eq!(
            back.column(1).iter().copied().collect::<Vec<_>>(),
            vec![1.0, 0.0, 1.0 / 3.0, 0.0]
        );
    }
}
