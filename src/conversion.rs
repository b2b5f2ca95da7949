//! Matrix forms of cubics and the conversions between them (the lecture notes "Konverze mezi
//! reprezentacemi", the matrix-form notes §1.2).
//!
//! The lecture notes write every cubic as `x(u) = X M u` with `u = [u³, u², u, 1]ᵀ` (powers
//! **descending**), `X` the `d × 4` geometry matrix (one vector per column) and `M` the
//! `4 × 4` basis matrix whose row `i` holds the coefficients of the `i`-th basis function:
//!
//! | form | geometry `X` | matrix |
//! |---|---|---|
//! | Hermite (Ferguson) | `[x(0) x(1) x'(0) x'(1)]` | [`hermite_matrix`] `M_H` |
//! | Bézier | `[b_0 b_1 b_2 b_3]` | [`bezier_matrix`] `M_B` |
//! | uniform cubic B-spline ("Coons cubic") | `[x_{i−1} x_i x_{i+1} x_{i+2}]` | [`bspline_matrix`] `M_C` |
//!
//! The matrix-form notes write the Bézier matrix for ascending powers `[1, t, t², t³]ᵀ`
//! ([`cubic_bezier_matrix`](crate::bezier::cubic_bezier_matrix)); `M_B` here is that matrix
//! with its columns reversed.
//!
//! Two forms describe the same cubic when `X_F M_F = X_G M_G`, so the geometry converts by
//! `X_G = X_F · M_F M_G⁻¹` — [`conversion_matrix`] computes that product (exactly, in
//! rationals) rather than copying the notes' table. The tests check every entry of the printed
//! table against it: all nine entries are right, read as `X_to = X_from · T` (entry in row
//! "to", column "from"). So is the printed `M_H⁻¹` (its rows are the Hermite data of
//! `u³, u², u, 1`). What the notes get wrong here: the B-spline surface section prints the
//! Bézier matrix as `M_S`; the right `M_S` is `M_C` ([`bspline_matrix`]).

use nalgebra::DMatrix;

use crate::bezier::mat_mul;
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The three cubic forms of the lecture notes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CubicForm {
    /// Hermite / Ferguson: end points and end tangents.
    Hermite,
    /// Bézier: four control points.
    Bezier,
    /// Uniform cubic B-spline segment ("Coons cubic"): four consecutive control points.
    BSpline,
}

fn int_matrix<T: Scalar>(rows: [[i64; 4]; 4], den: i64) -> DMatrix<T> {
    DMatrix::from_fn(4, 4, |i, j| T::from_ratio(rows[i][j], den))
}

/// `M_H` (the lecture notes): rows are `f_1 … f_4`, columns multiply `u³, u², u, 1`.
///
/// ```
/// let m: nalgebra::DMatrix<f64> = cagd::conversion::hermite_matrix();
/// assert_eq!(m.row(2).iter().copied().collect::<Vec<_>>(), vec![1.0, -2.0, 1.0, 0.0]);
/// ```
pub fn hermite_matrix<T: Scalar>() -> DMatrix<T> {
    int_matrix(
        [[2, -3, 0, 1], [-2, 3, 0, 0], [1, -2, 1, 0], [1, -1, 0, 0]],
        1,
    )
}

/// `M_H⁻¹`, computed by [`invert`]. Row `k` holds the Hermite data `[x(0), x(1), x'(0),
/// x'(1)]` of `u^{3−k}`: `[0 1 0 3; 0 1 0 2; 0 1 1 1; 1 1 0 0]`, as the lecture notes print it.
pub fn hermite_matrix_inverse<T: Scalar>() -> DMatrix<T> {
    invert(&hermite_matrix::<T>()).expect("M_H is invertible")
}

/// `M_B` of the lecture notes: `[−1 3 −3 1; 3 −6 3 0; −3 3 0 0; 1 0 0 0]` (rows `B_0^3 … B_3^3`,
/// columns `u³, u², u, 1`).
pub fn bezier_matrix<T: Scalar>() -> DMatrix<T> {
    let m = crate::bezier::cubic_bezier_matrix::<T>();
    DMatrix::from_fn(4, 4, |i, j| m[(i, 3 - j)].clone())
}

/// `M_C` of the lecture notes, the uniform cubic B-spline ("Coons cubic"):
/// `1/6 · [−1 3 −3 1; 3 −6 0 4; −3 3 3 1; 1 0 0 0]`. Its rows are the four uniform B-spline
/// pieces `(1 − u)³/6`, `(3u³ − 6u² + 4)/6`, `(−3u³ + 3u² + 3u + 1)/6`, `u³/6`, which sum to 1.
/// This is also the right `M_S` for the "Coons B-spline surface" `vᵀ M_Sᵀ X_S M_S u`; the lecture notes
/// prints `M_B` there by mistake.
pub fn bspline_matrix<T: Scalar>() -> DMatrix<T> {
    int_matrix(
        [[-1, 3, -3, 1], [3, -6, 0, 4], [-3, 3, 3, 1], [1, 0, 0, 0]],
        6,
    )
}

/// The basis matrix of a form.
pub fn basis_matrix<T: Scalar>(form: CubicForm) -> DMatrix<T> {
    match form {
        CubicForm::Hermite => hermite_matrix(),
        CubicForm::Bezier => bezier_matrix(),
        CubicForm::BSpline => bspline_matrix(),
    }
}

/// The matrix `T = M_from · M_to⁻¹` with `X_to = X_from · T`: it converts the geometry of a
/// cubic from one form to another without changing the curve. Exact in rationals.
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
    let inv = invert(&basis_matrix::<T>(to)).expect("basis matrices are invertible");
    mat_mul(&basis_matrix::<T>(from), &inv)
}

/// The geometry `X_to = X_from · conversion_matrix(from, to)` (`d × 4` in, `d × 4` out).
/// `geometry` must have 4 columns.
pub fn convert<T: Scalar>(geometry: &DMatrix<T>, from: CubicForm, to: CubicForm) -> DMatrix<T> {
    mat_mul(geometry, &conversion_matrix(from, to))
}

/// The inverse of a square matrix by Gauss–Jordan elimination with partial pivoting (largest
/// absolute value in the column), generic so that it is exact in rationals.
///
/// # Errors
/// [`Error::ShapeMismatch`] for a non-square matrix, [`Error::Singular`] for a singular one.
pub fn invert<T: Scalar>(m: &DMatrix<T>) -> Result<DMatrix<T>> {
    let n = m.nrows();
    if m.ncols() != n {
        return Err(Error::ShapeMismatch {
            what: "matrix to invert",
            expected: "a square matrix".into(),
            found: format!("{} × {}", n, m.ncols()),
        });
    }
    let mut a = m.clone();
    let mut inv = DMatrix::from_fn(n, n, |i, j| if i == j { T::one() } else { T::zero() });
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| {
                a[(i, col)]
                    .abs()
                    .partial_cmp(&a[(j, col)].abs())
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .expect("non-empty range");
        if a[(pivot, col)].is_zero() {
            return Err(Error::Singular {
                what: "matrix to invert",
                reason: format!("no pivot in column {col}"),
            });
        }
        a.swap_rows(col, pivot);
        inv.swap_rows(col, pivot);
        let p = a[(col, col)].clone();
        for j in 0..n {
            a[(col, j)] = a[(col, j)].clone() / p.clone();
            inv[(col, j)] = inv[(col, j)].clone() / p.clone();
        }
        for i in 0..n {
            if i == col || a[(i, col)].is_zero() {
                continue;
            }
            let f = a[(i, col)].clone();
            for j in 0..n {
                a[(i, j)] = a[(i, j)].clone() - f.clone() * a[(col, j)].clone();
                inv[(i, j)] = inv[(i, j)].clone() - f.clone() * inv[(col, j)].clone();
            }
        }
    }
    Ok(inv)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn inverse_of_m_h_is_as_printed() {
        let inv: DMatrix<BigRational> = hermite_matrix_inverse();
        let printed: DMatrix<BigRational> =
            int_matrix([[0, 1, 0, 3], [0, 1, 0, 2], [0, 1, 1, 1], [1, 1, 0, 0]], 1);
        assert_eq!(inv, printed);
        assert!(matches!(
            invert(&DMatrix::<f64>::zeros(2, 2)),
            Err(Error::Singular { .. })
        ));
    }
}
