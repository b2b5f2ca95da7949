//! Bernstein ↔ monomial matrices of any degree (the matrix-form notes §1.2): the matrix form of
//! a Bézier curve, `p(t) = P · M · [1, t, …, t^n]ᵀ`.

use nalgebra::DMatrix;

use crate::bernstein::binomial_scalar;
use crate::scalar::Scalar;

/// The Bézier-to-monomial matrix of degree `n`, `(n+1) × (n+1)`: row `i` holds the coefficients
/// of `1, t, …, t^n` in `B_i^n(t)` (ascending powers, the crate's one order):
///
/// ```text
/// M[i, j] = (−1)^(j−i) C(n, j) C(j, i)   for j ≥ i,   0 below the diagonal.
/// ```
///
/// A curve with control points `P` (columns) is `P · M · [1, t, …, t^n]ᵀ`.
///
/// ```
/// use cagd::conversion::bezier_to_monomial_matrix;
/// use nalgebra::DMatrix;
/// // B_0^2 = 1 − 2t + t², B_1^2 = 2t − 2t², B_2^2 = t².
/// let m: DMatrix<f64> = bezier_to_monomial_matrix(2);
/// assert_eq!(m, DMatrix::from_row_slice(3, 3, &[1.0, -2.0, 1.0, 0.0, 2.0, -2.0, 0.0, 0.0, 1.0]));
/// ```
pub fn bezier_to_monomial_matrix<T: Scalar>(n: usize) -> DMatrix<T> {
    DMatrix::from_fn(n + 1, n + 1, |i, j| {
        if j < i {
            T::zero()
        } else {
            let c = binomial_scalar::<T>(n, j) * binomial_scalar::<T>(j, i);
            if (j - i) % 2 == 0 {
                c
            } else {
                -c
            }
        }
    })
}

/// The inverse of [`bezier_to_monomial_matrix`]: row `j` holds the Bézier points of `t^j`,
///
/// ```text
/// M⁻¹[j, i] = C(i, j) / C(n, j)   for j ≤ i,   0 otherwise,
/// ```
///
/// so monomial coefficients `A` (columns, `t^j` in column `j`) have the Bézier points
/// `A · M⁻¹`, `b_i = Σ_{j ≤ i} C(i, j) / C(n, j) · a_j`.
///
/// ```
/// use cagd::conversion::monomial_to_bezier_matrix;
/// use nalgebra::DMatrix;
/// // t² has Bézier points 0, 0, 1; t has 0, 1/2, 1.
/// let m: DMatrix<f64> = monomial_to_bezier_matrix(2);
/// assert_eq!(m.row(2).iter().copied().collect::<Vec<_>>(), vec![0.0, 0.0, 1.0]);
/// assert_eq!(m.row(1).iter().copied().collect::<Vec<_>>(), vec![0.0, 0.5, 1.0]);
/// ```
pub fn monomial_to_bezier_matrix<T: Scalar>(n: usize) -> DMatrix<T> {
    DMatrix::from_fn(n + 1, n + 1, |j, i| {
        if j > i {
            T::zero()
        } else {
            binomial_scalar::<T>(i, j) / binomial_scalar::<T>(n, j)
        }
    })
}

/// The cubic Bézier matrix `M_B` as the matrix-form notes print it (§1.2), for ascending
/// powers `[1, t, t², t³]ᵀ` — the crate's own order, so this is
/// [`bezier_to_monomial_matrix`]`(3)` itself:
///
/// ```text
/// [1 −3  3 −1]
/// [0  3 −6  3]
/// [0  0  3 −3]
/// [0  0  0  1]
/// ```
///
/// (the notes print it correctly; their parametric form `p(t) = 0p_0B_0^3(t) + …` has a stray
/// `0` in front of `p_0`). The lecture notes print the same matrix for descending powers:
/// [`bezier_matrix`](super::bezier_matrix).
///
/// ```
/// use cagd::conversion::cubic_bezier_matrix;
/// let m: nalgebra::DMatrix<f64> = cubic_bezier_matrix();
/// assert_eq!(m.row(1).iter().copied().collect::<Vec<_>>(), vec![0.0, 3.0, -6.0, 3.0]);
/// ```
pub fn cubic_bezier_matrix<T: Scalar>() -> DMatrix<T> {
    bezier_to_monomial_matrix(3)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn the_two_matrices_are_inverse_in_rationals() {
        for n in 0..9 {
            let m = bezier_to_monomial_matrix::<BigRational>(n);
            let inv = monomial_to_bezier_matrix::<BigRational>(n);
            assert_eq!(
                BigRational::mat_mul(&m, &inv),
                DMatrix::identity(n + 1, n + 1),
                "n = {n}"
            );
        }
    }
}
