//! A tensor-product Bézier patch split in two along one parameter (thesis §2.1 applied to
//! the control curves of the net, §3.4), and the control curves themselves.

use nalgebra::DMatrix;

use super::check_param;
use super::curve::BezierCurve;
use super::patch::BezierPatch;
use crate::cost::{polynomial_bits, Cost};
use crate::error::{check_overflow, Error, Result};
use crate::scalar::Scalar;

/// One of the two parameters of a patch over `[0, 1]²`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Direction {
    /// The first parameter `u` (the index `i` of `b_{i,j}`, degree `m`).
    U,
    /// The second parameter `v` (the index `j` of `b_{i,j}`, degree `n`).
    V,
}

impl<T: Scalar> BezierPatch<T> {
    /// The control curves of the net along `dir`, as Bézier curves over `[0, 1]`.
    ///
    /// Along [`Direction::U`]: the `n + 1` curves `c_j(u) = Σ_i b_{i,j} B_i^m(u)`, control points
    /// the columns `b_{0,j}, …, b_{m,j}` of the net, so that `x(u, v) = Σ_j c_j(u) B_j^n(v)`
    /// (eq. (3.5) summed over `i` first). Along [`Direction::V`]: the `m + 1` curves
    /// `r_i(v) = Σ_j b_{i,j} B_j^n(v)` of the rows, `x(u, v) = Σ_i r_i(v) B_i^m(u)`. The first
    /// and last are boundary curves ([`boundary`](Self::boundary)).
    ///
    /// ```
    /// use cagd::bezier::{BezierPatch, Direction, Edge};
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // (u, v, uv)
    /// let cols = p.control_curves(Direction::U);
    /// assert_eq!(cols.len(), 2);
    /// assert_eq!(cols[0], p.boundary(Edge::V0));
    /// assert_eq!(cols[1].eval(0.5).as_slice(), &[0.5, 1.0, 0.5]); // x(½, 1)
    /// ```
    pub fn control_curves(&self, dir: Direction) -> Vec<BezierCurve<T>> {
        let (m, n) = self.degree();
        let d = self.dim();
        let x = self.coordinates();
        match dir {
            Direction::U => (0..=n)
                .map(|j| DMatrix::from_fn(d, m + 1, |k, i| x[k][(i, j)].clone()))
                .map(|c| BezierCurve::from_valid(c, T::zero(), T::one()))
                .collect(),
            Direction::V => (0..=m)
                .map(|i| DMatrix::from_fn(d, n + 1, |k, j| x[k][(i, j)].clone()))
                .map(|c| BezierCurve::from_valid(c, T::zero(), T::one()))
                .collect(),
        }
    }

    /// Splits the patch at `u = t` ([`Direction::U`]) or `v = t` ([`Direction::V`]) into two
    /// patches over `[0, 1]²`, each reparametrised onto the unit square:
    ///
    /// ```text
    /// U:  first(s, v) = x(t·s, v),   second(s, v) = x(t + (1 − t)·s, v),
    /// V:  first(u, s) = x(u, t·s),   second(u, s) = x(u, t + (1 − t)·s).
    /// ```
    ///
    /// Each control curve along `dir` ([`control_curves`](Self::control_curves)) is split by
    /// its de Casteljau scheme at `t`, as [`BezierCurve::subdivide`]: in `u`, column `j` of the
    /// first net is the diagonal `b_{0,j}^0, b_{0,j}^1, …, b_{0,j}^m` of the scheme of
    /// `b_{0,j}, …, b_{m,j}`, column `j` of the second its last row
    /// `b_{0,j}^m, b_{1,j}^{m−1}, …, b_{m,j}^0` (thesis §3.4: a curve of constant `v` has the
    /// control points `Σ_j b_{i,j} B_j^n(v)`, and splitting commutes with that sum). The two
    /// nets share the row `i = m` / `i = 0` (the curve `x(t, ·)`). In exact rationals the
    /// identities hold exactly.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite `t`; [`Error::EmptyInterval`] unless
    /// `0 < t < 1` (one part would be empty); [`Error::Overflow`] for a control point whose
    /// double overflows.
    ///
    /// ```
    /// use cagd::bezier::{BezierPatch, Direction};
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // (u, v, uv)
    /// let (first, second) = p.subdivide(Direction::U, 0.5)?;
    /// assert_eq!(first.eval(0.5, 0.5), p.eval(0.25, 0.5));
    /// assert_eq!(second.eval(0.5, 0.5), p.eval(0.75, 0.5));
    /// assert_eq!(first.control_point(1, 1).unwrap().as_slice(), &[0.5, 1.0, 0.5]);
    /// assert!(p.subdivide(Direction::V, 1.0).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn subdivide(&self, dir: Direction, t: T) -> Result<(Self, Self)> {
        let what = match dir {
            Direction::U => "Bézier patch subdivision parameter u",
            Direction::V => "Bézier patch subdivision parameter v",
        };
        check_param(what, &t)?;
        if t <= T::zero() || t >= T::one() {
            return Err(Error::EmptyInterval {
                what: match (dir, t <= T::zero()) {
                    (Direction::U, true) => "first part of a Bézier patch subdivided in u",
                    (Direction::U, false) => "second part of a Bézier patch subdivided in u",
                    (Direction::V, true) => "first part of a Bézier patch subdivided in v",
                    (Direction::V, false) => "second part of a Bézier patch subdivided in v",
                },
                a: if t <= T::zero() { 0.0 } else { t.to_f64() },
                b: if t <= T::zero() { t.to_f64() } else { 1.0 },
            });
        }
        let (mut first, mut second) = (Vec::new(), Vec::new());
        for curve in self.control_curves(dir) {
            let scheme = curve.scheme(t.clone());
            first.push(scheme.left_control());
            second.push(scheme.right_control());
        }
        let (first, second) = (net_of_curves(dir, &first), net_of_curves(dir, &second));
        check_overflow(
            "subdivided Bézier patch control points",
            first.iter().chain(&second).flat_map(|x| x.iter()),
        )?;
        Ok((
            BezierPatch::from_valid(first),
            BezierPatch::from_valid(second),
        ))
    }

    /// The cost of [`subdivide`](Self::subdivide) at a parameter of `param_bits` bits: one de
    /// Casteljau scheme per control curve along `dir` ([`BezierCurve::eval_cost`]: `d (k+1)²`
    /// operations for degree `k` in `dir`), as many curves as the net has in the other
    /// direction.
    ///
    /// ```
    /// use cagd::bezier::{BezierPatch, Direction};
    /// use cagd::cost::Cost;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // degree (1, 1), d = 3
    /// assert_eq!(p.subdivide_cost(Direction::U, 2, 5), Cost::new(2 * 3 * 4, 5 + 3));
    /// ```
    pub fn subdivide_cost(&self, dir: Direction, param_bits: u128, control_bits: u128) -> Cost {
        let (m, n) = self.degree();
        let (along, curves) = match dir {
            Direction::U => (m, n + 1),
            Direction::V => (n, m + 1),
        };
        let per_curve = (self.dim() as u128).saturating_mul((along as u128 + 1).saturating_pow(2));
        Cost::new(
            per_curve.saturating_mul(curves as u128),
            polynomial_bits(along, param_bits, control_bits),
        )
    }
}

/// The coordinate matrices of a net whose control curves along `dir` have the control
/// points `controls` (each `d × (k + 1)`, all the same shape): the inverse of
/// [`BezierPatch::control_curves`].
pub(crate) fn net_of_curves<T: Scalar>(dir: Direction, controls: &[DMatrix<T>]) -> Vec<DMatrix<T>> {
    let (d, along) = controls.first().map_or((0, 0), |c| c.shape());
    let across = controls.len();
    (0..d)
        .map(|k| match dir {
            Direction::U => DMatrix::from_fn(along, across, |i, j| controls[j][(k, i)].clone()),
            Direction::V => DMatrix::from_fn(across, along, |i, j| controls[i][(k, j)].clone()),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        <BigRational as Scalar>::from_ratio(n, d)
    }

    #[test]
    fn control_curves_rebuild_the_net() {
        let p = BezierPatch::<BigRational>::from_net(&[
            vec![[q(0, 1), q(1, 2)], [q(3, 1), q(-1, 1)], [q(2, 3), q(5, 1)]],
            vec![[q(7, 2), q(0, 1)], [q(1, 1), q(1, 1)], [q(-4, 1), q(2, 1)]],
        ])
        .unwrap();
        for dir in [Direction::U, Direction::V] {
            let controls: Vec<_> = p
                .control_curves(dir)
                .iter()
                .map(|c| c.control().clone())
                .collect();
            assert_eq!(net_of_curves(dir, &controls), p.coordinates());
        }
        assert_eq!(p.control_curves(Direction::U).len(), 3);
        assert_eq!(p.control_curves(Direction::V).len(), 2);
    }

    #[test]
    fn a_split_at_an_end_or_outside_is_refused() {
        let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
        for (dir, t) in [
            (Direction::U, 0.0),
            (Direction::U, 1.0),
            (Direction::V, -0.5),
            (Direction::V, 2.0),
        ] {
            assert!(
                matches!(p.subdivide(dir, t), Err(Error::EmptyInterval { .. })),
                "{dir:?} {t}"
            );
        }
        assert!(matches!(
            p.subdivide(Direction::U, f64::NAN),
            Err(Error::NonFinite { .. })
        ));
    }
}
