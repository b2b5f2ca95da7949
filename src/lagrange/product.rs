//! The product form of the Lagrange basis, in the thesis's order of operations.
//!
//! ```text
//! L_i(t) = Π_{j≠i} (t − t_j) / (t_i − t_j)
//! ```

use crate::scalar::Scalar;

/// `L_i(t)` as the thesis's product (appendix D, `Lagrange.m` with the product started at one):
/// `v = 1; for j ≠ i: v = (t − t_j)/(t_i − t_j) · v`, in that order, so `f64` values agree
/// with the Octave reference bit for bit. `i` counts from 0 (the Octave code from 1). Nodes are
/// not checked; `i` must be a valid index.
///
/// ```
/// use cagd::lagrange::basis_product;
/// let x = [0.0, 0.5, 1.0];
/// assert_eq!(basis_product(&x, 1, &0.25), 0.75); // 4t(1 − t)
/// ```
pub fn basis_product<T: Scalar>(nodes: &[T], i: usize, t: &T) -> T {
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
                assert_eq!(basis_product(&x, i, xk), want);
            }
        }
        // One node: the constant 1 (the loop is empty), as in Octave.
        assert_eq!(basis_product(&[0.3], 0, &7.0), 1.0);
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
        assert_eq!(basis_product(&x, 1, &t).to_bits(), v.to_bits());
    }
}
