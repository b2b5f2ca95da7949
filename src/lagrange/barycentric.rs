//! The barycentric form of the Lagrange basis (Berrut–Trefethen), which evaluates all `m+1`
//! basis functions in `O(m)` operations after an `O(m²)` set-up and is numerically stable
//! (J.-P. Berrut, L. N. Trefethen, *Barycentric Lagrange interpolation*, SIAM Review 46
//! (2004)):
//!
//! ```text
//! w_i = 1 / Π_{j≠i} (t_i − t_j),       L_i(t) = ℓ(t) · w_i / (t − t_i),   ℓ(t) = Π_j (t − t_j),
//! ```
//!
//! (the first barycentric form; see [`Lagrange::basis`] for why not the second) with
//! `L_i(t_k) = δ_ik` exactly at the nodes.

use nalgebra::{DMatrix, DVector};

use super::check_nodes;
use crate::cost::{polynomial_bits, Cost};
use crate::error::{Error, Result};
use crate::param::Curve;
use crate::scalar::Scalar;

/// An estimate of the Lebesgue constant `Λ = max_t Σ_i |L_i(t)|` of a set of nodes: the
/// factor by which interpolation can amplify errors in the data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LebesgueEstimate {
    /// The largest value of the Lebesgue function found.
    pub value: f64,
    /// Where it was found.
    pub at: f64,
    /// How many points were sampled.
    pub samples: usize,
}

/// The Lagrange basis of a set of distinct nodes, in barycentric form (Berrut–Trefethen).
#[derive(Debug, Clone, PartialEq)]
pub struct Lagrange<T: Scalar = f64> {
    nodes: Vec<T>,
    weights: Vec<T>,
}

impl<T: Scalar> Lagrange<T> {
    /// The basis `L_0, …, L_m` of the nodes `t_0 < … < t_m`, with the barycentric weights
    /// `w_i = 1 / Π_{j≠i} (t_i − t_j)`.
    ///
    /// # Errors
    /// See [`check_nodes`] (at least one node, finite, strictly increasing).
    ///
    /// ```
    /// use cagd::lagrange::Lagrange;
    /// let l = Lagrange::new(vec![0.0, 0.5, 1.0]).unwrap();
    /// assert_eq!(l.weights(), &[2.0, -4.0, 2.0]);
    /// assert_eq!(l.basis(&0.25), vec![0.375, 0.75, -0.125]);
    /// assert_eq!(l.basis(&0.5), vec![0.0, 1.0, 0.0]);
    /// ```
    pub fn new(nodes: Vec<T>) -> Result<Self> {
        check_nodes("Lagrange nodes", &nodes, 1)?;
        let weights = nodes
            .iter()
            .enumerate()
            .map(|(i, ti)| {
                let mut p = T::one();
                for (j, tj) in nodes.iter().enumerate() {
                    if j != i {
                        p = p * (ti.clone() - tj.clone());
                    }
                }
                T::one() / p
            })
            .collect();
        Ok(Lagrange { nodes, weights })
    }

    /// The cost of the set-up ([`new`](Self::new), the weights) for `count = m + 1` nodes:
    /// `(m+1)²` operations on numbers of [`polynomial_bits`]`(m, node_bits, 0)` bits,
    /// `node_bits` the size of the nodes. Known before the set-up, so that a caller can refuse
    /// work it cannot afford before doing any (exact weights of a thousand nodes take minutes).
    ///
    /// ```
    /// use cagd::lagrange::Lagrange;
    /// use cagd::cost::Cost;
    /// assert_eq!(Lagrange::<f64>::weights_cost(3, 3), Cost::new(9, 8));
    /// ```
    pub fn weights_cost(count: usize, node_bits: u128) -> Cost {
        let m1 = count as u128;
        Cost::new(
            m1.saturating_mul(m1),
            polynomial_bits(count.saturating_sub(1), node_bits, 0),
        )
    }

    /// The cost of the basis at one parameter of `param_bits` bits ([`basis`](Self::basis)):
    /// `4(m+1)` operations, on numbers of `m` factors `(t − t_j)`
    /// ([`polynomial_bits`]`(m, param_bits + node_bits, 0)`).
    ///
    /// ```
    /// use cagd::lagrange::Lagrange;
    /// use cagd::cost::Cost;
    /// assert_eq!(Lagrange::<f64>::basis_cost(3, 2, 3), Cost::new(12, 12));
    /// ```
    pub fn basis_cost(count: usize, param_bits: u128, node_bits: u128) -> Cost {
        Self::interpolation_cost(count, 0, param_bits, node_bits, 0)
    }

    /// The cost of the interpolant of `d`-dimensional values at one parameter
    /// ([`interpolate`](Self::interpolate)): the basis and its combination with the values,
    /// `(4 + 2d)(m+1)` operations, on numbers of
    /// [`polynomial_bits`]`(m, param_bits + node_bits, value_bits)` bits.
    ///
    /// ```
    /// use cagd::lagrange::Lagrange;
    /// use cagd::cost::Cost;
    /// assert_eq!(Lagrange::<f64>::interpolation_cost(3, 2, 2, 3, 10), Cost::new(24, 22));
    /// ```
    pub fn interpolation_cost(
        count: usize,
        d: usize,
        param_bits: u128,
        node_bits: u128,
        value_bits: u128,
    ) -> Cost {
        Cost::new(
            (4 + 2 * d as u128).saturating_mul(count as u128),
            polynomial_bits(
                count.saturating_sub(1),
                param_bits.saturating_add(node_bits),
                value_bits,
            ),
        )
    }

    /// The nodes.
    pub fn nodes(&self) -> &[T] {
        &self.nodes
    }

    /// The barycentric weights `w_i`.
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// The degree `m` (one less than the number of nodes).
    pub fn degree(&self) -> usize {
        self.nodes.len() - 1
    }

    /// `[L_0(t), …, L_m(t)]` by the first barycentric form (the "modified Lagrange formula",
    /// Berrut–Trefethen §3): `ℓ(t) = Π_j (t − t_j)` once, then `L_i(t) = ℓ(t) · w_i/(t − t_i)`,
    /// `O(m)` operations per point; exactly the unit vector at a node.
    ///
    /// Each value carries a relative error of a few `m·ε`, like the product form, and the
    /// formula is backward stable (Higham 2004). The second ("true") barycentric form
    /// `(w_i/(t − t_i)) / Σ_j w_j/(t − t_j)` divides by a sum with cancellation, and its
    /// values can be off by `Λ·ε` relative to the largest one (about 1000 ULPs for six random
    /// nodes on `[−0.1, 1.1]`, see the Octave reference test `octave_lagrange_basis`).
    pub fn basis(&self, t: &T) -> Vec<T> {
        let mut out = vec![T::zero(); self.nodes.len()];
        self.fill_basis(t, &mut out);
        out
    }

    /// [`basis`](Self::basis) into a caller-given slice of length `m + 1` (the same values bit
    /// for bit, no allocation).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len()` is the number of nodes.
    ///
    /// ```
    /// use cagd::lagrange::Lagrange;
    /// let l = Lagrange::new(vec![0.0, 0.5, 1.0])?;
    /// let mut row = [0.0; 3];
    /// l.basis_into(&0.25, &mut row)?;
    /// assert_eq!(row, [0.375, 0.75, -0.125]);
    /// assert!(l.basis_into(&0.25, &mut [0.0; 2]).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn basis_into(&self, t: &T, out: &mut [T]) -> Result<()> {
        crate::grid::check_len("Lagrange basis values", self.nodes.len(), out)?;
        self.fill_basis(t, out);
        Ok(())
    }

    /// The basis at `t` into `out` (of length `m + 1`).
    pub(crate) fn fill_basis(&self, t: &T, out: &mut [T]) {
        if let Some(k) = self.nodes.iter().position(|x| x == t) {
            out.iter_mut().for_each(|o| *o = T::zero());
            out[k] = T::one();
            return;
        }
        let ell = self
            .nodes
            .iter()
            .fold(T::one(), |p, x| p * (t.clone() - x.clone()));
        for ((o, x), w) in out.iter_mut().zip(&self.nodes).zip(&self.weights) {
            *o = ell.clone() * (w.clone() / (t.clone() - x.clone()));
        }
    }

    /// `Σ_i y_i L_i(t)` for values `y_i` (one per column of `values`, d × (m+1)).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `values` has one column per node.
    pub fn interpolate(&self, values: &DMatrix<T>, t: &T) -> Result<DVector<T>> {
        self.check_values(values)?;
        Ok(self.combine(values, &self.basis(t)))
    }

    fn check_values(&self, values: &DMatrix<T>) -> Result<()> {
        if values.ncols() != self.nodes.len() {
            return Err(Error::ShapeMismatch {
                what: "Lagrange values",
                expected: format!("{} columns (one per node)", self.nodes.len()),
                found: format!("{} columns", values.ncols()),
            });
        }
        Ok(())
    }

    fn combine(&self, values: &DMatrix<T>, basis: &[T]) -> DVector<T> {
        DVector::from_fn(values.nrows(), |k, _| {
            basis.iter().enumerate().fold(T::zero(), |acc, (i, l)| {
                acc + l.clone() * values[(k, i)].clone()
            })
        })
    }

    /// The Lebesgue function `Σ_i |L_i(t)|` (in `f64`).
    pub fn lebesgue_function(&self, t: &T) -> f64 {
        self.basis(t).iter().map(|l| l.to_f64().abs()).sum()
    }

    /// Estimates the Lebesgue constant on `[a, b]` by sampling the Lebesgue function at
    /// `samples` equispaced points (at least 2), evaluated in `f64`.
    ///
    /// ```
    /// use cagd::lagrange::{Lagrange, NodePlacement};
    /// let uniform = Lagrange::new(NodePlacement::Uniform.nodes::<f64>(11)).unwrap();
    /// let chebyshev = Lagrange::new(NodePlacement::Chebyshev.nodes::<f64>(11)).unwrap();
    /// let (lu, lc) = (uniform.lebesgue_constant(0.0, 1.0, 10001), chebyshev.lebesgue_constant(0.0, 1.0, 10001));
    /// assert!(lu.value > 29.0 && lu.value < 30.0); // 29.89…
    /// assert!(lc.value < 2.5);                     // 2.4…
    /// ```
    pub fn lebesgue_constant(&self, a: f64, b: f64, samples: usize) -> LebesgueEstimate {
        let samples = samples.max(2);
        let nodes: Vec<f64> = self.nodes.iter().map(|t| t.to_f64()).collect();
        let f64_basis = Lagrange::<f64> {
            weights: self.weights.iter().map(|w| w.to_f64()).collect(),
            nodes,
        };
        let mut best = LebesgueEstimate {
            value: 0.0,
            at: a,
            samples,
        };
        for t in crate::linspace(a, b, samples) {
            let value = f64_basis.lebesgue_function(&t);
            if value > best.value {
                best.value = value;
                best.at = t;
            }
        }
        best
    }
}

/// The polynomial `p(t) = Σ_i y_i L_i(t)` through the points `y_i` (columns of a d × (m+1)
/// matrix) at the nodes of a [`Lagrange`] basis, as a [`Curve`] with derivative.
///
/// The derivative uses the barycentric differentiation formulas (Berrut–Trefethen §9):
/// off the nodes `p'(t) = Σ_j (w_j/(t−t_j)) (p(t) − y_j)/(t − t_j) / Σ_j (w_j/(t−t_j))`, at a
/// node `p'(t_k) = Σ_{j≠k} D_kj (y_j − y_k)` with `D_kj = (w_j/w_k)/(t_k − t_j)`.
///
/// ```
/// use cagd::lagrange::{Lagrange, LagrangeInterpolant};
/// use cagd::{Curve, CurveDeriv};
/// use nalgebra::{dmatrix, dvector};
/// // p(t) = t² through (0, 0), (1/2, 1/4), (1, 1).
/// let p = LagrangeInterpolant::new(Lagrange::new(vec![0.0, 0.5, 1.0]).unwrap(), dmatrix![0.0, 0.25, 1.0]).unwrap();
/// assert_eq!(p.eval(0.25), dvector![0.0625]);
/// assert_eq!(p.eval_derivative(0.5), dvector![1.0]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct LagrangeInterpolant<T: Scalar = f64> {
    basis: Lagrange<T>,
    values: DMatrix<T>,
}

impl<T: Scalar> LagrangeInterpolant<T> {
    /// The interpolant of `values` (d × (m+1), one point per column) at the nodes of `basis`.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless there is one column per node; [`Error::NonFinite`].
    pub fn new(basis: Lagrange<T>, values: DMatrix<T>) -> Result<Self> {
        basis.check_values(&values)?;
        crate::error::check_finite("Lagrange values", values.iter())?;
        Ok(LagrangeInterpolant { basis, values })
    }

    /// The basis.
    pub fn basis(&self) -> &Lagrange<T> {
        &self.basis
    }

    /// The interpolated values, one per column.
    pub fn values(&self) -> &DMatrix<T> {
        &self.values
    }
}

impl<T: Scalar> Curve<T> for LagrangeInterpolant<T> {
    fn dim(&self) -> usize {
        self.values.nrows()
    }

    /// From the first to the last node (the polynomial continues outside).
    fn domain(&self) -> (T, T) {
        let nodes = self.basis.nodes();
        (nodes[0].clone(), nodes[nodes.len() - 1].clone())
    }

    fn eval(&self, t: T) -> DVector<T> {
        self.basis.combine(&self.values, &self.basis.basis(&t))
    }

    /// [`Lagrange::interpolation_cost`] on the interpolant's own nodes and values.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        Lagrange::<T>::interpolation_cost(
            self.basis.nodes.len(),
            self.values.nrows(),
            param_bits,
            crate::cost::max_bits(&self.basis.nodes),
            crate::cost::max_bits(self.values.iter()),
        )
    }
}

impl<T: Scalar> crate::param::CurveDeriv<T> for LagrangeInterpolant<T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        let (x, w, y) = (&self.basis.nodes, &self.basis.weights, &self.values);
        let d = y.nrows();
        if let Some(k) = x.iter().position(|xk| *xk == t) {
            let mut out = DVector::from_element(d, T::zero());
            for j in (0..x.len()).filter(|&j| j != k) {
                let dkj = w[j].clone() / w[k].clone() / (x[k].clone() - x[j].clone());
                for r in 0..d {
                    out[r] = out[r].clone() + dkj.clone() * (y[(r, j)].clone() - y[(r, k)].clone());
                }
            }
            return out;
        }
        let p = self.eval(t.clone());
        let mut num = DVector::from_element(d, T::zero());
        let mut den = T::zero();
        for j in 0..x.len() {
            let h = t.clone() - x[j].clone();
            let q = w[j].clone() / h.clone();
            den = den + q.clone();
            for r in 0..d {
                num[r] =
                    num[r].clone() + q.clone() * (p[r].clone() - y[(r, j)].clone()) / h.clone();
            }
        }
        num.map(|v| v / den.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn costs_of_the_set_up_the_basis_and_the_interpolant() {
        assert_eq!(Lagrange::<f64>::weights_cost(5, 0), Cost::new(25, 4));
        assert_eq!(Lagrange::<f64>::basis_cost(5, 3, 2), Cost::new(20, 4 * 6));
        assert_eq!(
            Lagrange::<f64>::interpolation_cost(5, 0, 3, 2, 0),
            Lagrange::<f64>::basis_cost(5, 3, 2)
        );
        assert_eq!(
            Lagrange::<f64>::interpolation_cost(5, 3, 3, 2, 9),
            Cost::new(50, 24 + 9)
        );
    }
}
