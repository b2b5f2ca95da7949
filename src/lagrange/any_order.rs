//! The Lagrange basis of distinct nodes given in any order (the lecture notes' Příklad 1 takes
//! `0, ½, ¼, 1`; the thesis's `Lagrange` takes `x` as given): the barycentric basis
//! ([`Lagrange`]) of the nodes sorted, its values read back in the order given,
//!
//! ```text
//! L_i(t) = Π_{j≠i} (t − t_j) / Π_{j≠i} (t_i − t_j),   i in the order of the nodes given,
//! ```
//!
//! which the order of the nodes does not change: only which value is called `L_i`.

use nalgebra::{DMatrix, DVector};

use super::{check_distinct_nodes, Lagrange};
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The Lagrange basis of distinct nodes in the order given.
///
/// ```
/// use cagd::lagrange::NodesInAnyOrder;
/// let l = NodesInAnyOrder::new(vec![0.0, 0.5, 0.25, 1.0])?;
/// assert!(!l.increasing());
/// // The identity at the nodes, in the order given.
/// assert_eq!(l.basis(&0.25), vec![0.0, 0.0, 1.0, 0.0]);
/// assert_eq!(l.sorted().nodes(), &[0.0, 0.25, 0.5, 1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct NodesInAnyOrder<T: Scalar = f64> {
    sorted: Lagrange<T>,
    /// `order[k]`: the position, in the order given, of the `k`-th smallest node.
    order: Vec<usize>,
}

impl<T: Scalar> NodesInAnyOrder<T> {
    /// The basis of `nodes` (at least one, finite, pairwise distinct, in any order).
    ///
    /// # Errors
    /// See [`check_distinct_nodes`]: [`Error::TooFewPoints`], [`Error::NonFinite`],
    /// [`Error::DuplicateNodes`] naming the first node that repeats an earlier one.
    pub fn new(nodes: Vec<T>) -> Result<Self> {
        check_distinct_nodes("Lagrange nodes", &nodes, 1)?;
        let mut order: Vec<usize> = (0..nodes.len()).collect();
        order.sort_by(|&a, &b| {
            nodes[a]
                .partial_cmp(&nodes[b])
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        let sorted = order.iter().map(|&k| nodes[k].clone()).collect();
        Ok(NodesInAnyOrder {
            sorted: Lagrange::new(sorted)?,
            order,
        })
    }

    /// The basis on the nodes sorted.
    pub fn sorted(&self) -> &Lagrange<T> {
        &self.sorted
    }

    /// Whether the nodes were given in increasing order.
    pub fn increasing(&self) -> bool {
        self.order.iter().enumerate().all(|(k, &j)| k == j)
    }

    /// The smallest and the largest node: the interval the polynomial interpolates on.
    pub fn span(&self) -> (T, T) {
        let n = self.sorted.nodes();
        (n[0].clone(), n[n.len() - 1].clone())
    }

    /// `[L_0(t), …, L_m(t)]` in the order of the nodes given ([`Lagrange::basis`] of the
    /// sorted nodes, read back).
    pub fn basis(&self, t: &T) -> Vec<T> {
        let sorted = self.sorted.basis(t);
        let mut out = sorted.clone();
        for (k, v) in sorted.into_iter().enumerate() {
            out[self.order[k]] = v;
        }
        out
    }

    /// `Σ_i y_i L_i(t)` for values `y_i`, one per column of `values` (d × (m+1)) in the order
    /// of the nodes given.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `values` has one column per node.
    pub fn interpolate(&self, values: &DMatrix<T>, t: &T) -> Result<DVector<T>> {
        let m1 = self.order.len();
        if values.ncols() != m1 {
            return Err(Error::ShapeMismatch {
                what: "Lagrange values",
                expected: format!("{m1} columns (one per node)"),
                found: format!("{} columns", values.ncols()),
            });
        }
        let sorted = DMatrix::from_fn(values.nrows(), m1, |r, k| {
            values[(r, self.order[k])].clone()
        });
        self.sorted.interpolate(&sorted, t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn the_order_given_only_renames_the_basis() {
        let q = |a: i64, b: i64| BigRational::new(a.into(), b.into());
        let given = NodesInAnyOrder::new(vec![q(0, 1), q(1, 2), q(1, 4), q(1, 1)]).unwrap();
        let sorted = Lagrange::new(vec![q(0, 1), q(1, 4), q(1, 2), q(1, 1)]).unwrap();
        let t = q(3, 5);
        let (a, b) = (given.basis(&t), sorted.basis(&t));
        assert_eq!(
            a,
            vec![b[0].clone(), b[2].clone(), b[1].clone(), b[3].clone()]
        );
        // Values follow their nodes: y = 2t at every node gives 2t everywhere.
        let values = DMatrix::from_row_slice(1, 4, &[q(0, 1), q(1, 1), q(1, 2), q(2, 1)]);
        assert_eq!(given.interpolate(&values, &t).unwrap()[0], q(6, 5));
        assert!(NodesInAnyOrder::new(vec![q(0, 1), q(1, 2), q(0, 1)]).is_err());
    }
}
