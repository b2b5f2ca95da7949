//! The product form of the Lagrange basis, in the thesis's order of operations.
//!
//! ```text
//! L_i(t) = Π_{j≠i} (t − t_j) / (t_i − t_j)
//! ```

use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// `L_i(t)` as the thesis's product (appendix D, `Lagrange.m` with the product started at one):
/// `v = 1; for j ≠ i: v = (t − t_j)/(t_i − t_j) · v`, in that order, so `f64` values agree
/// with the Octave reference bit for bit. `i` counts from 0 (the Octave code from 1).
///
/// # Errors
/// [`Error::InvalidArgument`] unless `i < nodes.len()`; [`Error::NonFinite`] for a NaN or
/// infinite node or `t`; [`Error::DuplicateNodes`] when a node equals `t_i` (the factor would
/// divide by zero); [`Error::Overflow`] for a value whose double overflows (nodes close
/// together, `t` far away).
///
/// ```
/// use cagd::lagrange::basis_product;
/// let x = [0.0, 0.5, 1.0];
/// assert_eq!(basis_product(&x, 1, &0.25)?, 0.75); // 4t(1 − t)
/// assert!(basis_product(&x, 3, &0.25).is_err());
/// assert!(basis_product(&[0.0, 0.5, 0.5], 1, &0.25).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn basis_product<T: Scalar>(nodes: &[T], i: usize, t: &T) -> Result<T> {
    let Some(ti) = nodes.get(i) else {
        return Err(Error::InvalidArgument {
            what: "Lagrange basis index",
            message: format!("index {i} is not one of the {} nodes", nodes.len()),
        });
    };
    crate::error::check_finite("Lagrange nodes", nodes.iter())?;
    crate::error::check_finite("Lagrange basis parameter", std::iter::once(t))?;
    if let Some(j) = nodes
        .iter()
        .enumerate()
        .position(|(j, x)| j != i && x == ti)
    {
        return Err(Error::DuplicateNodes {
            what: "Lagrange nodes",
            first: i.min(j),
            second: i.max(j),
            value: ti.to_f64(),
        });
    }
    crate::error::finite(
        "Lagrange basis value",
        [basis_product_unchecked(nodes, i, t)],
    )
    .map(|[v]| v)
}

/// [`basis_product`] for nodes already known to be distinct and an index known to be valid
/// (checked when the nodes were given).
pub(crate) fn basis_product_unchecked<T: Scalar>(nodes: &[T], i: usize, t: &T) -> T {
    let mut v = T::one();
    for (j, xj) in nodes.iter().enumerate() {
        if j != i {
            v = (t.clone() - xj.clone()) / (nodes[i].clone() - xj.clone()) * v;
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational as Q;

    #[test]
    fn the_basis_is_one_at_its_node_and_zero_at_the_others() {
        let x: Vec<Q> = [(0, 1), (1, 3), (1, 2), (1, 1)]
            .iter()
            .map(|&(n, d)| Q::from_ratio(n, d))
            .collect();
        for i in 0..x.len() {
            for (k, xk) in x.iter().enumerate() {
                let want = if i == k {
                    Q::from_ratio(1, 1)
                } else {
                    Q::from_ratio(0, 1)
                };
                assert_eq!(basis_product(&x, i, xk).unwrap(), want);
            }
        }
        // One node: the constant 1 (the loop is empty), as in Octave.
        assert_eq!(basis_product(&[0.3], 0, &7.0).unwrap(), 1.0);
    }

    #[test]
    fn the_order_of_operations_is_the_thesis_one() {
        // v = (t − x_j)/(x_i − x_j) · v, j ascending: not the same rounding as multiplying the
        // numerator out first.
        let (x, t) = ([0.1, 0.7, 1.3], 0.45);
        let mut v = 1.0;
        for xj in [0.1, 1.3] {
            v *= (t - xj) / (0.7 - xj); // a product commutes bit for bit
        }
        assert_eq!(basis_product(&x, 1, &t).unwrap().to_bits(), v.to_bits());
    }
}
