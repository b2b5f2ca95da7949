//! Bernstein ↔ monomial matrices of any degree (the matrix-form notes §1.2): the matrix form of
//! a Bézier curve, `p(t) = P · M · [1, t, …, t^n]ᵀ`.

use nalgebra::DMatrix;

use num_bigint::BigUint;
use num_traits::One;

use crate::error::{check_overflow, Result};
use crate::limits::Limits;
use crate::scalar::Scalar;

/// The Bézier-to-monomial matrix of degree `n`, `(n+1) × (n+1)`: row `i` holds the coefficients
/// of `1, t, …, t^n` in `B_i^n(t)` (ascending powers, the crate's one order):
///
/// ```text
/// M[i, j] = (−1)^(j−i) C(n, j) C(j, i)   for j ≥ i,   0 below the diagonal.
/// ```
///
/// A curve with control points `P` (columns) is `P · M · [1, t, …, t^n]ᵀ`. The binomials come
/// from Pascal's triangle, one row per column (`O(n²)` additions of exact integers, each
/// binomial then rounded once), so the matrix of degree 1000 takes milliseconds.
///
/// # Errors
/// [`Error::TooLarge`](crate::Error::TooLarge) for `n` above [`Limits::DEFAULT`]`.max_degree` (the matrix has
/// `(n+1)²` entries); [`Error::Overflow`](crate::Error::Overflow) in `f64` when an entry exceeds the range of doubles
/// (entries reach about `3^n`: beyond the range of doubles from degree 653 on).
///
/// ```
/// use cagd::conversion::bezier_to_monomial_matrix;
/// use nalgebra::DMatrix;
/// // B_0^2 = 1 − 2t + t², B_1^2 = 2t − 2t², B_2^2 = t².
/// let m: DMatrix<f64> = bezier_to_monomial_matrix(2)?;
/// assert_eq!(m, DMatrix::from_row_slice(3, 3, &[1.0, -2.0, 1.0, 0.0, 2.0, -2.0, 0.0, 0.0, 1.0]));
/// assert!(matches!(bezier_to_monomial_matrix::<f64>(700), Err(cagd::Error::Overflow { .. })));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bezier_to_monomial_matrix<T: Scalar>(n: usize) -> Result<DMatrix<T>> {
    let mut m = square("Bézier-to-monomial matrix", n)?;
    let top = pascal_row(n)
        .iter()
        .map(T::from_biguint)
        .collect::<Vec<T>>();
    for (j, row) in PascalRows::new().take(n + 1).enumerate() {
        for (i, c) in row.iter().enumerate() {
            let c = top[j].clone() * T::from_biguint(c);
            m[(i, j)] = if (j - i) % 2 == 0 { c } else { -c };
        }
    }
    check_overflow("Bézier-to-monomial matrix", m.iter())?;
    Ok(m)
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
/// # Errors
/// As [`bezier_to_monomial_matrix`] (in `f64`, `C(n, j)` itself overflows from degree 1030
/// on).
///
/// ```
/// use cagd::conversion::monomial_to_bezier_matrix;
/// use nalgebra::DMatrix;
/// // t² has Bézier points 0, 0, 1; t has 0, 1/2, 1.
/// let m: DMatrix<f64> = monomial_to_bezier_matrix(2)?;
/// assert_eq!(m.row(2).iter().copied().collect::<Vec<_>>(), vec![0.0, 0.0, 1.0]);
/// assert_eq!(m.row(1).iter().copied().collect::<Vec<_>>(), vec![0.0, 0.5, 1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn monomial_to_bezier_matrix<T: Scalar>(n: usize) -> Result<DMatrix<T>> {
    let mut m = square("monomial-to-Bézier matrix", n)?;
    let top = pascal_row(n)
        .iter()
        .map(T::from_biguint)
        .collect::<Vec<T>>();
    check_overflow("monomial-to-Bézier matrix", top.iter())?;
    for (i, row) in PascalRows::new().take(n + 1).enumerate() {
        for (j, c) in row.iter().enumerate() {
            m[(j, i)] = T::from_biguint(c) / top[j].clone();
        }
    }
    check_overflow("monomial-to-Bézier matrix", m.iter())?;
    Ok(m)
}

/// A zero `(n+1) × (n+1)` matrix, for `n` up to [`Limits::DEFAULT`]`.max_degree`.
fn square<T: Scalar>(what: &'static str, n: usize) -> Result<DMatrix<T>> {
    Limits::DEFAULT.check_degree(what, n)?;
    let len = crate::grid::grid_len(what, &[n + 1, n + 1])?;
    let zeros = crate::grid::try_filled(what, len, T::zero())?;
    Ok(DMatrix::from_vec(n + 1, n + 1, zeros))
}

/// Row `n` of Pascal's triangle, `C(n, 0), …, C(n, n)`.
fn pascal_row(n: usize) -> Vec<BigUint> {
    PascalRows::new().nth(n).unwrap_or_default()
}

/// The rows of Pascal's triangle, `[1], [1, 1], [1, 2, 1], …`, each from the one before by
/// additions (exact, `O(n)` per row).
struct PascalRows {
    row: Vec<BigUint>,
}

impl PascalRows {
    fn new() -> Self {
        PascalRows { row: Vec::new() }
    }
}

impl Iterator for PascalRows {
    type Item = Vec<BigUint>;
    fn next(&mut self) -> Option<Vec<BigUint>> {
        let mut next = Vec::with_capacity(self.row.len() + 1);
        next.push(BigUint::one());
        for w in self.row.windows(2) {
            next.push(&w[0] + &w[1]);
        }
        if !self.row.is_empty() {
            next.push(BigUint::one());
        }
        self.row = next.clone();
        Some(next)
    }
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
    bezier_to_monomial_matrix(3).expect("degree 3 is within every limit and the range of doubles")
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn the_two_matrices_are_inverse_in_rationals() {
        for n in 0..9 {
            let m = bezier_to_monomial_matrix::<BigRational>(n).unwrap();
            let inv = monomial_to_bezier_matrix::<BigRational>(n).unwrap();
            assert_eq!(
                BigRational::mat_mul(&m, &inv),
                DMatrix::identity(n + 1, n + 1),
                "n = {n}"
            );
        }
    }

    #[test]
    fn entries_are_the_binomial_products_and_overflow_is_an_error() {
        use crate::bernstein::binomial_scalar;
        for n in [0, 1, 7, 60, 130] {
            let m = bezier_to_monomial_matrix::<f64>(n).unwrap();
            let inv = monomial_to_bezier_matrix::<f64>(n).unwrap();
            for i in 0..=n {
                for j in i..=n {
                    let c = binomial_scalar::<f64>(n, j) * binomial_scalar::<f64>(j, i);
                    assert_eq!(m[(i, j)], if (j - i) % 2 == 0 { c } else { -c });
                    let q = binomial_scalar::<f64>(j, i) / binomial_scalar::<f64>(n, i);
                    assert_eq!(inv[(i, j)], q, "n = {n}, ({i}, {j})");
                }
            }
        }
        assert!(matches!(
            bezier_to_monomial_matrix::<f64>(1100),
            Err(crate::Error::TooLarge { .. })
        ));
        assert!(matches!(
            bezier_to_monomial_matrix::<f64>(700),
            Err(crate::Error::Overflow { .. })
        ));
        // Exactly, degree 1000 is allowed and fast.
        let m = bezier_to_monomial_matrix::<BigRational>(200).unwrap();
        assert_eq!(m[(0, 200)], BigRational::from_integer(1.into()));
    }
}
