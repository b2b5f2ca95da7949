//! The power (monomial) form of the Lagrange basis: the coefficients of
//! `L_i(t) = Π_{j≠i} (t − t_j)/(t_i − t_j)` multiplied out.
//!
//! Coefficients are listed in the crate's one power order, **ascending** (`c[p]` multiplies
//! `t^p`, as in [`crate::conversion`]); the lecture notes' blending matrix and Octave's
//! `polyfit` print them highest power first
//! ([`blending_matrix`](crate::interpolation::blending_matrix) and
//! [`LagrangePolynomial::coefficients`](crate::interpolation::LagrangePolynomial::coefficients)
//! are those views).

use crate::cost::Cost;
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The coefficients of `L_i` in ascending powers: `L_i(t) = Σ_p c[p] t^p`, `p = 0..m`
/// (`m + 1 = nodes.len()`), exact in rationals. Nodes are not checked for order or
/// repeats (a repeat divides by zero: an error).
///
/// The numerator `Π_{j≠i} (t − t_j)` is multiplied out factor by factor (`j` ascending), then
/// divided by `Π_{j≠i} (t_i − t_j)`.
///
/// # Errors
/// [`Error::InvalidArgument`] unless `i < nodes.len()`; [`Error::NonFinite`] for a NaN or
/// infinite node; [`Error::TooLarge`] when the `m²` operations (weighed by the size of exact
/// numbers) exceed the default work limit; [`Error::Overflow`] for a coefficient whose double
/// overflows (repeated or close nodes, many nodes).
///
/// ```
/// use cagd::lagrange::power_coefficients;
/// // L_1 of [0, 1/2, 1] is 4t − 4t².
/// assert_eq!(power_coefficients(&[0.0, 0.5, 1.0], 1)?, vec![0.0, 4.0, -4.0]);
/// assert!(power_coefficients(&[0.0, 0.5, 1.0], 3).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn power_coefficients<T: Scalar>(nodes: &[T], i: usize) -> Result<Vec<T>> {
    if i >= nodes.len() {
        return Err(Error::InvalidArgument {
            what: "Lagrange basis index",
            message: format!("index {i} is not one of the {} nodes", nodes.len()),
        });
    }
    crate::error::check_finite("Lagrange nodes", nodes.iter())?;
    let m = nodes.len() as u128;
    crate::checked::point_work::<T>(
        "Lagrange basis in power form",
        Cost::new(m.saturating_mul(m).saturating_mul(3), 0).grown(crate::cost::polynomial_bits(
            nodes.len(),
            0,
            crate::cost::max_bits(nodes),
        )),
    )?;
    let c = power_coefficients_unchecked(nodes, i);
    crate::error::check_overflow("Lagrange basis in power form", c.iter())?;
    Ok(c)
}

/// [`power_coefficients`] for a valid index, without checks.
pub(crate) fn power_coefficients_unchecked<T: Scalar>(nodes: &[T], i: usize) -> Vec<T> {
    let mut poly = vec![T::one()];
    let mut denom = T::one();
    for (j, xj) in nodes.iter().enumerate() {
        if j == i {
            continue;
        }
        // poly · (t − t_j). Each new coefficient is formed as `(0 − c_p t_j) + c_{p−1}`, the
        // highest power first, which fixes every rounding (and sign of zero) in `f64`.
        let mut next = vec![T::zero(); poly.len() + 1];
        for (p, c) in poly.iter().enumerate().rev() {
            next[p + 1] = next[p + 1].clone() + c.clone();
            next[p] = next[p].clone() - c.clone() * xj.clone();
        }
        poly = next;
        denom = denom * (nodes[i].clone() - xj.clone());
    }
    poly.into_iter().map(|c| c / denom.clone()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lagrange::basis_product;
    use num_rational::BigRational as Q;

    #[test]
    fn the_coefficients_are_the_basis() {
        let q = |n: i64, d: i64| <Q as Scalar>::from_ratio(n, d);
        let x = [q(-1, 2), q(0, 1), q(2, 3), q(1, 1)];
        for i in 0..x.len() {
            let c = power_coefficients(&x, i).unwrap();
            assert_eq!(c.len(), 4);
            for t in [q(1, 7), q(5, 3), q(-2, 1)] {
                let horner = c
                    .iter()
                    .rev()
                    .fold(q(0, 1), |acc, ck| acc * t.clone() + ck.clone());
                assert_eq!(horner, basis_product(&x, i, &t).unwrap());
            }
        }
        assert_eq!(power_coefficients(&[0.25], 0).unwrap(), vec![1.0]);
    }
}
