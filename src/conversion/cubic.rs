//! The three cubic forms of the lecture notes — Hermite (Ferguson), Bézier, uniform cubic
//! B-spline — as basis matrices, and the lecture notes' printed views of them.

use nalgebra::DMatrix;

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

/// A basis matrix with its columns reversed: ascending powers `[1, u, u², u³]` to the lecture
/// notes' descending `[u³, u², u, 1]` and back.
fn reversed_columns<T: Scalar>(m: &DMatrix<T>) -> DMatrix<T> {
    let n = m.ncols();
    DMatrix::from_fn(m.nrows(), n, |i, j| m[(i, n - 1 - j)].clone())
}

impl CubicForm {
    /// The basis matrix `M` of the form in the crate's power order, **ascending**: row `i`
    /// holds the coefficients of the `i`-th basis function, column `p` multiplies `u^p`, so a
    /// cubic with geometry `X` (`d × 4`, one vector per column) is `X · M · [1, u, u², u³]ᵀ`.
    ///
    /// | form | geometry `X` | `M` (rows) |
    /// |---|---|---|
    /// | `Hermite` | `[x(0) x(1) x'(0) x'(1)]` | `1 − 3u² + 2u³`, `3u² − 2u³`, `u − 2u² + u³`, `−u² + u³` |
    /// | `Bezier` | `[b_0 b_1 b_2 b_3]` | [`bezier_to_monomial_matrix`](super::bezier_to_monomial_matrix)`(3)`: `B_0³ … B_3³` |
    /// | `BSpline` | `[x_{i−1} x_i x_{i+1} x_{i+2}]` | `(1 − u)³/6`, `(4 − 6u² + 3u³)/6`, `(1 + 3u + 3u² − 3u³)/6`, `u³/6` |
    ///
    /// ```
    /// use cagd::conversion::CubicForm;
    /// let m: nalgebra::DMatrix<f64> = CubicForm::Hermite.matrix();
    /// assert_eq!(m.row(0).iter().copied().collect::<Vec<_>>(), vec![1.0, 0.0, -3.0, 2.0]);
    /// ```
    pub fn matrix<T: Scalar>(self) -> DMatrix<T> {
        match self {
            CubicForm::Hermite => int_matrix(
                [[1, 0, -3, 2], [0, 0, 3, -2], [0, 1, -2, 1], [0, 0, -1, 1]],
                1,
            ),
            CubicForm::Bezier => super::monomial::cubic_bezier_matrix(),
            CubicForm::BSpline => int_matrix(
                [[1, -3, 3, -1], [4, 0, -6, 3], [1, 3, 3, -3], [0, 0, 0, 1]],
                6,
            ),
        }
    }

    /// The basis matrix as the lecture notes print it, for descending powers
    /// `u = [u³, u², u, 1]ᵀ` (`x(u) = X M u`): [`CubicForm::matrix`] with its columns reversed.
    ///
    /// ```
    /// use cagd::conversion::CubicForm;
    /// let m: nalgebra::DMatrix<f64> = CubicForm::Hermite.lecture_notes_matrix();
    /// assert_eq!(m.row(0).iter().copied().collect::<Vec<_>>(), vec![2.0, -3.0, 0.0, 1.0]);
    /// ```
    pub fn lecture_notes_matrix<T: Scalar>(self) -> DMatrix<T> {
        reversed_columns(&self.matrix::<T>())
    }

    /// The four basis functions at `u`, `M · [1, u, u², u³]ᵀ` (the matrix form of the lecture
    /// notes and of the matrix-form notes, evaluated as printed: each row times the powers, the
    /// highest power first).
    ///
    /// ```
    /// use cagd::conversion::CubicForm;
    /// assert_eq!(CubicForm::Bezier.basis(&0.5), [0.125, 0.375, 0.375, 0.125]);
    /// ```
    pub fn basis<T: Scalar>(self, u: &T) -> [T; 4] {
        let m = self.matrix::<T>();
        let powers = [
            T::one(),
            u.clone(),
            u.clone() * u.clone(),
            u.clone() * u.clone() * u.clone(),
        ];
        std::array::from_fn(|i| {
            (0..4).rev().fold(T::zero(), |acc, p| {
                acc + m[(i, p)].clone() * powers[p].clone()
            })
        })
    }
}

/// `M_H` as the lecture notes print it (rows `f_1 … f_4`, columns `u³, u², u, 1`): the view
/// [`CubicForm::lecture_notes_matrix`] of [`CubicForm::Hermite`].
///
/// ```
/// let m: nalgebra::DMatrix<f64> = cagd::conversion::hermite_matrix();
/// assert_eq!(m.row(2).iter().copied().collect::<Vec<_>>(), vec![1.0, -2.0, 1.0, 0.0]);
/// ```
pub fn hermite_matrix<T: Scalar>() -> DMatrix<T> {
    CubicForm::Hermite.lecture_notes_matrix()
}

/// `M_H⁻¹` as the lecture notes print it, the inverse ([`super::invert`]) of [`hermite_matrix`]:
/// row `k` holds the Hermite data `[x(0), x(1), x'(0), x'(1)]` of `u^{3−k}`,
/// `[0 1 0 3; 0 1 0 2; 0 1 1 1; 1 1 0 0]`.
pub fn hermite_matrix_inverse<T: Scalar>() -> DMatrix<T> {
    super::invert(&hermite_matrix::<T>()).expect("M_H is invertible")
}

/// `M_B` as the lecture notes print it: `[−1 3 −3 1; 3 −6 3 0; −3 3 0 0; 1 0 0 0]` (rows
/// `B_0^3 … B_3^3`, columns `u³, u², u, 1`) — the matrix-form notes'
/// [`cubic_bezier_matrix`](super::cubic_bezier_matrix) with its columns reversed.
pub fn bezier_matrix<T: Scalar>() -> DMatrix<T> {
    CubicForm::Bezier.lecture_notes_matrix()
}

/// `M_C` as the lecture notes print it, the uniform cubic B-spline ("Coons cubic"):
/// `1/6 · [−1 3 −3 1; 3 −6 0 4; −3 3 3 1; 1 0 0 0]`. Its rows are the four uniform B-spline
/// pieces `(1 − u)³/6`, `(3u³ − 6u² + 4)/6`, `(−3u³ + 3u² + 3u + 1)/6`, `u³/6`, which sum to 1.
/// This is also the right `M_S` for the "Coons B-spline surface" `vᵀ M_Sᵀ X_S M_S u`; the
/// lecture notes print `M_B` there by mistake.
pub fn bspline_matrix<T: Scalar>() -> DMatrix<T> {
    CubicForm::BSpline.lecture_notes_matrix()
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
    }

    #[test]
    fn the_views_reverse_the_columns_and_the_bases_sum_as_they_should() {
        for form in [CubicForm::Hermite, CubicForm::Bezier, CubicForm::BSpline] {
            let m: DMatrix<BigRational> = form.matrix();
            assert_eq!(reversed_columns(&form.lecture_notes_matrix()), m);
            let u = BigRational::new(2.into(), 7.into());
            let b = form.basis(&u);
            for (i, bi) in b.iter().enumerate() {
                let horner = (0..4)
                    .rev()
                    .fold(BigRational::from_integer(0.into()), |acc, p| {
                        acc * u.clone() + m[(i, p)].clone()
                    });
                assert_eq!(*bi, horner);
            }
        }
        // Bézier and B-spline bases are partitions of unity.
        for form in [CubicForm::Bezier, CubicForm::BSpline] {
            assert!((form.basis(&0.3).iter().sum::<f64>() - 1.0).abs() < 1e-15);
        }
    }
}
