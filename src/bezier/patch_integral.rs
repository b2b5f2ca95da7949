//! Integrals of a tensor-product Bézier patch (the CAD notes §1.1: `∫₀¹ B_i^n = 1/(n+1)`, and
//! the antiderivative of a Bézier curve, [`crate::integral::bezier_antiderivative`], in each
//! direction).

use nalgebra::DVector;

use super::patch::BezierPatch;
use super::patch_subdivide::{net_of_curves, Direction};
use crate::cost::Cost;
use crate::error::{check_overflow, Result};
use crate::integral::{antiderivative_cost, bezier_antiderivative};
use crate::scalar::Scalar;

impl<T: Scalar> BezierPatch<T> {
    /// The antiderivative in one parameter, as a patch over `[0, 1]²`:
    ///
    /// ```text
    /// U:  F(u, v) = ∫₀ᵘ x(s, v) ds,   degree (m + 1, n),   c_{0,j} = 0,  c_{k,j} = 1/(m+1) · Σ_{i<k} b_{i,j},
    /// V:  F(u, v) = ∫₀ᵛ x(u, s) ds,   degree (m, n + 1),   c_{i,0} = 0,  c_{i,l} = 1/(n+1) · Σ_{j<l} b_{i,j}.
    /// ```
    ///
    /// In `u` each column curve ([`control_curves`](Self::control_curves)) is integrated by
    /// [`bezier_antiderivative`] (the partial sums of its control points), since
    /// `∫₀ᵘ Σ_j c_j(s) B_j^n(v) ds = Σ_j (∫₀ᵘ c_j) B_j^n(v)`; in `v` each row curve. Both in turn
    /// give `∫₀ᵘ ∫₀ᵛ x`, a patch of degree `(m + 1, n + 1)` with
    /// `c_{k,l} = Σ_{i<k} Σ_{j<l} b_{i,j} / ((m+1)(n+1))` (the two commute), whose corner
    /// `c_{m+1,n+1}` is [`integral`](Self::integral). Its partial derivative in the same
    /// direction ([`derivative`](Self::derivative)) is the patch again, exactly in rationals.
    ///
    /// # Errors
    /// [`Error::Overflow`](crate::Error::Overflow) for a control point whose double overflows
    /// (the weighted partial sums stay within the largest control point, so only by rounding
    /// next to ±1.8·10³⁰⁸).
    ///
    /// ```
    /// use cagd::bezier::{BezierPatch, Direction};
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // (u, v, uv)
    /// let f = p.antiderivative(Direction::U)?; // (u²/2, uv, u²v/2)
    /// assert_eq!(f.degree(), (2, 1));
    /// assert_eq!(f.eval(1.0, 0.5).as_slice(), &[0.5, 0.5, 0.25]);
    /// assert_eq!(f.derivative(1, 0)?, p);
    /// let g = f.antiderivative(Direction::V)?; // ∫₀ᵘ∫₀ᵛ: (u²v/2, uv²/2, u²v²/4)
    /// assert_eq!(g.eval(1.0, 1.0).as_slice(), p.integral()?.as_slice());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn antiderivative(&self, dir: Direction) -> Result<Self> {
        let controls = self
            .control_curves(dir)
            .iter()
            .map(|c| bezier_antiderivative(c).map(|f| f.control().clone()))
            .collect::<Result<Vec<_>>>()?;
        Ok(BezierPatch::from_valid(net_of_curves(dir, &controls)))
    }

    /// The cost of [`antiderivative`](Self::antiderivative) in `dir` on control points of
    /// `control_bits` bits: one curve antiderivative
    /// ([`integral::antiderivative_cost`](crate::integral::antiderivative_cost)) per control
    /// curve along `dir`.
    ///
    /// ```
    /// use cagd::bezier::{BezierPatch, Direction};
    /// use cagd::integral::antiderivative_cost;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // degree (1, 1), d = 3
    /// assert_eq!(p.antiderivative_cost(Direction::V, 8), antiderivative_cost(2, 3, 1, 8).times(2));
    /// ```
    pub fn antiderivative_cost(&self, dir: Direction, control_bits: u128) -> Cost {
        let (m, n) = self.degree();
        let (along, curves) = match dir {
            Direction::U => (m, n + 1),
            Direction::V => (n, m + 1),
        };
        antiderivative_cost(along + 1, self.dim(), along, control_bits).times(curves as u128)
    }

    /// The definite integral over the domain, one value per coordinate:
    ///
    /// ```text
    /// ∫₀¹ ∫₀¹ x(u, v) du dv = Σ_i Σ_j b_{i,j} ∫₀¹ B_i^m ∫₀¹ B_j^n = 1/((m+1)(n+1)) · Σ_i Σ_j b_{i,j},
    /// ```
    ///
    /// the mean of the control points (`∫₀¹ B_i^n = 1/(n+1)` for every `i`, the CAD notes
    /// §1.1). Each control point is weighed by `1/((m+1)(n+1))` before the sum (`i`, then `j`,
    /// ascending), so that the sum of large control points does not overflow where the mean
    /// does not. Exact in rationals; it is the corner `c_{m+1,n+1}` of the antiderivative in
    /// both directions ([`antiderivative`](Self::antiderivative)).
    ///
    /// # Errors
    /// [`Error::Overflow`](crate::Error::Overflow) for a value whose double overflows.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // (u, v, uv)
    /// assert_eq!(p.integral()?.as_slice(), &[0.5, 0.5, 0.25]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn integral(&self) -> Result<DVector<T>> {
        let (m, n) = self.degree();
        let w = T::one() / (T::from_usize(m + 1) * T::from_usize(n + 1));
        let values = DVector::from_iterator(
            self.dim(),
            self.coordinates().iter().map(|x| {
                let mut sum = T::zero();
                for i in 0..=m {
                    for j in 0..=n {
                        sum = sum + w.clone() * x[(i, j)].clone();
                    }
                }
                sum
            }),
        );
        check_overflow("Bézier patch integral", values.iter())?;
        Ok(values)
    }

    /// The cost of [`integral`](Self::integral): a product and a sum per control point and
    /// coordinate, on numbers of `control_bits` grown by the weight `1/((m+1)(n+1))`.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// use cagd::cost::Cost;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // 4 points, d = 3
    /// assert_eq!(p.integral_cost(10), Cost::new(2 * 4 * 3, 10 + 2 * 3));
    /// ```
    pub fn integral_cost(&self, control_bits: u128) -> Cost {
        let (m, n) = self.degree();
        let points = (m as u128 + 1).saturating_mul(n as u128 + 1);
        let weight = (points + 1).ilog2() as u128 + 1;
        Cost::new(
            points.saturating_mul(2 * self.dim() as u128),
            control_bits.saturating_add(2 * weight),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_integral_of_huge_control_points_does_not_overflow_their_mean() {
        let big = f64::MAX / 2.0;
        let p = BezierPatch::from_net(&[vec![[big], [big]], vec![[big], [big]]]).unwrap();
        assert_eq!(p.integral().unwrap()[0], big);
        // Nor do the antiderivative's weighted partial sums (at most k/(m+1) of the largest).
        let f = p.antiderivative(Direction::V).unwrap();
        assert_eq!(f.control_point(1, 2).unwrap()[0], big);
    }
}
