//! The Bernstein form of the Lagrange basis: `L_i(t) = Σ_k c_ik B_k^d(t)` on `[0, 1]`, the
//! blending functions of a Gordon surface of Bézier curves written as one Bézier patch.

use crate::bernstein::{elevate, product};
use crate::error::Result;
use crate::limits::Limits;
use crate::scalar::Scalar;

/// The Bernstein coefficients, at degree `to ≥ m` (`m + 1 = nodes.len()`), of the Lagrange
/// basis `L_0, …, L_m` of `nodes` (row `i` holds `L_i`, `to + 1` coefficients). Nodes are not
/// checked for order (repeated ones give non-finite values, an error).
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite node;
/// [`Error::TooLarge`](crate::Error::TooLarge) for a degree (`to`, or the number of nodes)
/// above [`Limits::DEFAULT`]`.max_degree`; [`Error::Overflow`](crate::Error::Overflow) for a
/// coefficient whose double overflows (nodes close together, or repeated).
///
/// Each `L_i` is the product of the linear factors `(t − t_j)/(t_i − t_j)`, `j ≠ i`, whose
/// Bernstein coefficients are `[−t_j, 1 − t_j]/(t_i − t_j)`
/// ([`bernstein::product`](crate::bernstein::product)), elevated to degree `to`
/// ([`bernstein::elevate`](crate::bernstein::elevate)). Exact in rationals.
///
/// ```
/// use cagd::lagrange::bernstein_coefficients;
/// // The basis of {0, 1} is 1 − t = B_0^1 and t = B_1^1; at degree 2: [1, 1/2, 0], [0, 1/2, 1].
/// let c = bernstein_coefficients(&[0.0, 1.0], 2)?;
/// assert_eq!(c, vec![vec![1.0, 0.5, 0.0], vec![0.0, 0.5, 1.0]]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bernstein_coefficients<T: Scalar>(nodes: &[T], to: usize) -> Result<Vec<Vec<T>>> {
    crate::error::check_finite("Lagrange nodes", nodes.iter())?;
    Limits::DEFAULT.check_degree("Lagrange basis in Bernstein form", to.max(nodes.len()))?;
    let rows = nodes
        .iter()
        .enumerate()
        .map(|(i, ti)| {
            let mut poly = vec![T::one()];
            for (j, tj) in nodes.iter().enumerate() {
                if j != i {
                    let den = ti.clone() - tj.clone();
                    let factor = [-tj.clone() / den.clone(), (T::one() - tj.clone()) / den];
                    poly = product(&poly, &factor);
                }
            }
            elevate(&poly, to)
        })
        .collect::<Result<Vec<Vec<T>>>>()?;
    crate::error::check_overflow("Lagrange basis in Bernstein form", rows.iter().flatten())?;
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bernstein::bernstein_all;
    use crate::lagrange::Lagrange;
    use num_rational::BigRational as Q;

    #[test]
    fn lagrange_basis_in_bernstein_form_is_the_basis() {
        let q = |n: i64, d: i64| <Q as Scalar>::from_ratio(n, d);
        let nodes = [q(-1, 2), q(0, 1), q(2, 3), q(1, 1)];
        let basis = Lagrange::new(nodes.to_vec()).unwrap();
        let coeffs = bernstein_coefficients(&nodes, 5).unwrap();
        for t in [q(1, 7), q(1, 2), q(9, 10), q(-1, 3)] {
            let want = basis.basis(&t);
            let b = bernstein_all(5, t.clone());
            for (i, c) in coeffs.iter().enumerate() {
                let value = c
                    .iter()
                    .zip(&b)
                    .fold(q(0, 1), |acc, (ck, bk)| acc + ck.clone() * bk.clone());
                assert_eq!(value, want[i]);
            }
        }
    }
}
