//! `Lagrange` (thesis appendix D, Algoritem 8).

use ndarray::{Array, ArrayView, ArrayView2, Dimension};

use super::{check_finite_array, shape_str};
use cagd::error::{Error, Result};
use cagd::lagrange::{basis_product, check_distinct_nodes};
use cagd::Scalar;

/// The Lagrange basis polynomial `L_m` of the nodes `x` at every parameter of `u`: the twin of
/// the thesis's `Lagrange` (appendix D, Algoritem 8), as fixed in `octave_ref/fixed/Lagrange.m`.
///
/// **Original:** `function v = Lagrange(x,m,u)`.
///
/// ```text
/// L_m(u) = Π_{j ≠ m} (u − x(j)) / (x(m) − x(j))      (Octave indices, m = 1..n)
/// ```
///
/// # Layout
/// - `x`: the nodes, a `1 × n` row (as appendix D writes `x = [0 0.5 1]`) or an `n × 1`
///   column; distinct, in any order.
/// - `m`: the index of the basis polynomial, from 1 as in Octave (the thesis's description calls
///   it the degree; it is not).
/// - `u`: an array of parameters of any shape.
/// - result `v`: the shape of `u`, `v[k] = L_m(u[k])`.
///
/// # Bugs of the original fixed here (`octave_ref/BUGS.md`)
/// - **Always 0:** the product started at `v = zeros(size(u))`, so every factor multiplied zero;
///   even `L_m(x(m))`, which must be 1, came out 0, and every Gordon surface built on it was
///   identically zero. The fixed product starts at one.
///
/// # Native function
/// [`cagd::lagrange::basis_product`], the same product in the same order
/// (`v = (u − x(j)) / (x(m) − x(j)) · v`, `j` ascending), bit for bit equal to the fixed Octave.
///
/// # Errors
/// [`Error::ShapeMismatch`] unless `x` is a non-empty row or column;
/// [`Error::InvalidArgument`] for `m = 0` or `m > n` (Octave: index out of bound);
/// [`Error::DuplicateNodes`] for two equal nodes (Octave would divide by zero and return
/// `Inf`/`NaN`); [`Error::NonFinite`] for a NaN or infinite node or parameter.
///
/// ```
/// use cagd_octave::compat::lagrange;
/// use ndarray::array;
/// let x = array![[0.0, 0.5, 1.0]];
/// let u = array![[0.0, 0.25, 0.5, 1.0]];
/// // L_2 = 4u(1 − u): 1 at its node, 0 at the others.
/// assert_eq!(lagrange(x.view(), 2, u.view())?, array![[0.0, 0.75, 1.0, 0.0]]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn lagrange<T: Scalar, D: Dimension>(
    x: ArrayView2<'_, T>,
    m: usize,
    u: ArrayView<'_, T, D>,
) -> Result<Array<T, D>> {
    let nodes = node_vector("lagrange: x", &x)?;
    if m == 0 || m > nodes.len() {
        return Err(Error::InvalidArgument {
            what: "lagrange: m",
            message: format!(
                "expected the index of a node, 1 ≤ m ≤ {}, got {m}",
                nodes.len()
            ),
        });
    }
    check_finite_array("lagrange: u", &u)?;
    // The nodes are distinct (node_vector) and 1 ≤ m ≤ their count: the product is defined.
    let mut out = u.to_owned();
    for (o, t) in out.iter_mut().zip(u.iter()) {
        *o = basis_product(&nodes, m - 1, t)?;
    }
    Ok(out)
}

/// A non-empty row or column of finite, pairwise distinct nodes, in Octave's order (the
/// library's one node check, [`check_distinct_nodes`]).
pub(crate) fn node_vector<T: Scalar>(what: &'static str, x: &ArrayView2<'_, T>) -> Result<Vec<T>> {
    if x.is_empty() || (x.nrows() != 1 && x.ncols() != 1) {
        return Err(Error::ShapeMismatch {
            what,
            expected: "a 1×n row or n×1 column of nodes (n ≥ 1)".into(),
            found: shape_str(x.shape()),
        });
    }
    check_finite_array(what, x)?;
    let nodes: Vec<T> = x.iter().cloned().collect();
    check_distinct_nodes(what, &nodes, 1)?;
    Ok(nodes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::{array, Array3};

    #[test]
    fn any_shape_any_order() {
        // Unsorted column of nodes; a 3-D array of parameters keeps its shape.
        let x = array![[1.0], [0.0], [0.5]];
        let u = Array3::from_shape_fn((2, 2, 2), |(i, j, k)| (i + 2 * j + 4 * k) as f64 / 8.0);
        let v = lagrange(x.view(), 2, u.view()).unwrap();
        assert_eq!(v.dim(), (2, 2, 2));
        for (t, l) in u.iter().zip(v.iter()) {
            let exact = (t - 1.0) * (t - 0.5) / ((0.0 - 1.0) * (0.0 - 0.5));
            assert!((l - exact).abs() < 1e-15, "L({t}) = {l}, expected {exact}");
        }
    }

    #[test]
    fn errors() {
        let x = array![[0.0, 0.5, 1.0]];
        let u = array![0.5];
        assert!(matches!(
            lagrange(x.view(), 0, u.view()),
            Err(Error::InvalidArgument { .. })
        ));
        assert!(matches!(
            lagrange(x.view(), 4, u.view()),
            Err(Error::InvalidArgument { .. })
        ));
        let dup = array![[0.0, 0.5, 0.0]];
        assert!(matches!(
            lagrange(dup.view(), 1, u.view()),
            Err(Error::DuplicateNodes {
                first: 0,
                second: 2,
                ..
            })
        ));
        let square = array![[0.0, 1.0], [2.0, 3.0]];
        assert!(matches!(
            lagrange(square.view(), 1, u.view()),
            Err(Error::ShapeMismatch { .. })
        ));
        assert!(matches!(
            lagrange(x.view(), 1, array![f64::NAN].view()),
            Err(Error::NonFinite { .. })
        ));
        // One node: the constant 1, as in Octave (the loop is empty).
        assert_eq!(
            lagrange(array![[0.3]].view(), 1, u.view()).unwrap(),
            array![1.0]
        );
    }
}
