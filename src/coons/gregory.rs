//! Gregory's square: a variable twist for incompatible twist data (thesis §4.4).

use nalgebra::DVector;

use super::Corner;
use crate::error::{check_finite, Error, Result};
use crate::scalar::Scalar;

/// The variable twists of Gregory's square (thesis §4.4).
///
/// At a corner `(i, j)` of the parameter square the data of a bicubically blended patch give
/// two twists that need not agree (eqs. (4.6), (4.7)):
/// `a = ∂/∂v x_u(i, v)` at `v = j` (the derivative of the cross-boundary curve `x_u(i, ·)`) and
/// `b = ∂/∂u x_v(u, j)` at `u = i`. Gregory replaces the constant twist by the rational blend
///
/// ```text
/// T_ij(u, v) = (|u − i| a + |v − j| b) / (|u − i| + |v − j|),
/// ```
///
/// which is `b` on the edge `u = i` and `a` on the edge `v = j` — exactly what the
/// cross-boundary derivative along each of those edges needs, so the patch interpolates the
/// incompatible data edge by edge.
///
/// The thesis prints the four cases as
/// `x_uv(0,0) = (u a + v b)/(u + v)`, `x_uv(0,1) = (−u a + (v−1) b)/(−u + v − 1)`,
/// `x_uv(1,0) = ((1−u) a + v b)/(1 − u + v)`, `x_uv(1,1) = ((u−1) a + (v−1) b)/(u − 1 + v − 1)`.
/// These were checked and are correct: each is the formula above with numerator and
/// denominator multiplied by −1 where the printed version uses `u − 1` or `v − 1`. What the
/// thesis leaves open is the corner itself, where the quotient is `0/0` and the limit depends
/// on the direction of approach; there we take the limit along the diagonal, `(a + b)/2`. In
/// the patch the twist is multiplied by `H1³` or `H2³` in both parameters, which vanish at the
/// corner, so the surface and its first derivatives do not depend on that choice.
///
/// ```
/// use cagd::coons::{Corner, GregoryTwist};
/// use nalgebra::dvector;
/// let a = dvector![1.0];
/// let b = dvector![3.0];
/// let g = GregoryTwist::new([a.clone(), a.clone(), a.clone(), a], [b.clone(), b.clone(), b.clone(), b])?;
/// assert_eq!(g.eval(Corner::U0V0, &0.0, &0.5), dvector![3.0]); // on u = 0: b
/// assert_eq!(g.eval(Corner::U0V0, &0.5, &0.0), dvector![1.0]); // on v = 0: a
/// assert_eq!(g.eval(Corner::U0V0, &0.0, &0.0), dvector![2.0]); // the corner: (a + b)/2
/// assert_eq!(g.eval(Corner::U1V1, &1.0, &0.5), dvector![3.0]); // on u = 1: b
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct GregoryTwist<T: Scalar = f64> {
    along_v: [DVector<T>; 4],
    along_u: [DVector<T>; 4],
}

impl<T: Scalar> GregoryTwist<T> {
    /// The Gregory twists from `a = ∂/∂v x_u` and `b = ∂/∂u x_v` at the corners, each array in
    /// the order `P1..P4` = `(0,0), (1,0), (0,1), (1,1)` (see [`Corner`]).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless the eight vectors have one dimension (the blend combines
    /// `a` and `b` coordinate by coordinate); [`Error::NonFinite`] for a NaN or infinite
    /// coordinate.
    pub fn new(along_v: [DVector<T>; 4], along_u: [DVector<T>; 4]) -> Result<Self> {
        let dim = along_v[0].len();
        let all = along_v.iter().chain(along_u.iter());
        if let Some((k, v)) = all.clone().enumerate().find(|(_, v)| v.len() != dim) {
            return Err(Error::ShapeMismatch {
                what: "Gregory twists",
                expected: format!("vectors of dimension {dim} (that of a at P1)"),
                found: format!(
                    "dimension {} for {} at P{}",
                    v.len(),
                    if k < 4 { "a" } else { "b" },
                    k % 4 + 1
                ),
            });
        }
        check_finite("Gregory twists", all.flat_map(|v| v.iter()))?;
        Ok(GregoryTwist { along_v, along_u })
    }

    /// `a = ∂/∂v x_u` at the corners (order `P1..P4`).
    pub fn along_v(&self) -> &[DVector<T>; 4] {
        &self.along_v
    }

    /// `b = ∂/∂u x_v` at the corners (order `P1..P4`).
    pub fn along_u(&self) -> &[DVector<T>; 4] {
        &self.along_u
    }

    /// Distances `(|u − i|, |v − j|)` to the two edges through the corner.
    fn distances(corner: Corner, u: &T, v: &T) -> (T, T) {
        let (i, j) = corner.uv();
        let du = if i == 0 {
            u.clone()
        } else {
            T::one() - u.clone()
        };
        let dv = if j == 0 {
            v.clone()
        } else {
            T::one() - v.clone()
        };
        (du, dv)
    }

    /// The twist `T_ij(u, v)` for the corner `(i, j)`; `(a + b)/2` at the corner itself.
    pub fn eval(&self, corner: Corner, u: &T, v: &T) -> DVector<T> {
        let k = corner.index();
        let (a, b) = (&self.along_v[k], &self.along_u[k]);
        let (du, dv) = Self::distances(corner, u, v);
        let den = du.clone() + dv.clone();
        if den.is_zero() {
            let two = T::from_usize(2);
            return a.zip_map(b, |x, y| (x + y) / two.clone());
        }
        a.zip_map(b, |x, y| (du.clone() * x + dv.clone() * y) / den.clone())
    }

    /// The partial derivatives `(∂T_ij/∂u, ∂T_ij/∂v)`:
    /// `∂u T = ±|v − j| (a − b)/(|u − i| + |v − j|)²`, `∂v T = ±|u − i| (b − a)/(…)²`, the sign
    /// `+` at `i = 0` (resp. `j = 0`). They are unbounded at the corner, where the patch
    /// multiplies them by a vanishing Hermite factor; there both are returned as zero, the value
    /// of that product.
    pub fn derivatives(&self, corner: Corner, u: &T, v: &T) -> (DVector<T>, DVector<T>) {
        let k = corner.index();
        let (a, b) = (&self.along_v[k], &self.along_u[k]);
        let (i, j) = corner.uv();
        let (du, dv) = Self::distances(corner, u, v);
        let den = du.clone() + dv.clone();
        if den.is_zero() {
            let z = DVector::from_element(a.len(), T::zero());
            return (z.clone(), z);
        }
        let den2 = den.clone() * den;
        let su = if i == 0 { T::one() } else { -T::one() };
        let sv = if j == 0 { T::one() } else { -T::one() };
        let diff = a.zip_map(b, |x, y| x - y);
        let cu = su * dv / den2.clone();
        let cv = -(sv * du / den2);
        (diff.map(|x| cu.clone() * x), diff.map(|x| cv.clone() * x))
    }
}
