//! The Cox–de Boor triangle: every basis function of every degree up to `p` at one parameter
//! (the CAD notes §1.2, the lecture notes "Neuniformní B-spline křivky").
//!
//! ```text
//! N_{i,0}(u) = 1 if u_i ≤ u < u_{i+1}, else 0,
//! N_{i,j}(u) = (u − u_i)/(u_{i+j} − u_i) · N_{i,j−1}(u)
//!            + (u_{i+j+1} − u)/(u_{i+j+1} − u_{i+1}) · N_{i+1,j−1}(u),
//! ```
//!
//! a term with a zero denominator being zero (0/0 := 0), and the last non-empty span closed at
//! the right end of the knot vector, as [`cox_de_boor`](super::cox_de_boor). Level `j` holds
//! `N_{0,j} … N_{m−j−1,j}` for the `m + 1` knots; each level is computed once from the one
//! below, so the triangle costs `O(m p)` operations instead of the recursion's `O(2^p)` per
//! function.

use super::basis::cox_de_boor_unchecked;
use crate::cost::{polynomial_bits, Cost};
use crate::scalar::Scalar;

/// The triangle at `u`: `triangle[j][i] = N_{i,j}(u)` for `j = 0..=p`, `i = 0..m−j` (`m + 1`
/// knots). Needs `p + 1 < knots.len()`.
///
/// ```
/// use cagd::bspline::cox_de_boor_triangle;
/// let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
/// let t = cox_de_boor_triangle(2, &knots, &0.5);
/// assert_eq!(t[0], vec![0.0, 0.0, 1.0, 0.0, 0.0]);
/// assert_eq!(t[1], vec![0.0, 0.5, 0.5, 0.0]);
/// assert_eq!(t[2], vec![0.25, 0.5, 0.25]);
/// ```
pub fn cox_de_boor_triangle<T: Scalar>(p: usize, knots: &[T], u: &T) -> Vec<Vec<T>> {
    let m = knots.len() - 1;
    let mut levels: Vec<Vec<T>> = Vec::with_capacity(p + 1);
    levels.push(
        (0..m)
            .map(|i| cox_de_boor_unchecked(i, 0, knots, u))
            .collect(),
    );
    for j in 1..=p {
        let below = &levels[j - 1];
        let level = (0..m - j)
            .map(|i| {
                let mut value = T::zero();
                let d1 = knots[i + j].clone() - knots[i].clone();
                if !d1.is_zero() {
                    value = value + (u.clone() - knots[i].clone()) / d1 * below[i].clone();
                }
                let d2 = knots[i + j + 1].clone() - knots[i + 1].clone();
                if !d2.is_zero() {
                    value =
                        value + (knots[i + j + 1].clone() - u.clone()) / d2 * below[i + 1].clone();
                }
                value
            })
            .collect();
        levels.push(level);
    }
    levels
}

/// The cost of [`cox_de_boor_triangle`] of degree `p` on `knot_count = m + 1` knots at one
/// parameter of `param_bits` bits: at most `4m` operations per level, `p + 1` levels, on
/// numbers of `p` levels of `(u − u_i)/(u_{i+j} − u_i)`
/// ([`polynomial_bits`]`(p, param_bits + 3 knot_bits, 0)`, as [`basis_cost`](super::basis_cost)).
///
/// ```
/// assert_eq!(cagd::bspline::triangle_cost(2, 6, 0, 0), cagd::cost::Cost::new(60, 2));
/// ```
pub fn triangle_cost(p: usize, knot_count: usize, param_bits: u128, knot_bits: u128) -> Cost {
    let m = knot_count.saturating_sub(1) as u128;
    Cost::new(
        (p as u128 + 1).saturating_mul(m).saturating_mul(4),
        polynomial_bits(p, param_bits.saturating_add(knot_bits.saturating_mul(3)), 0),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_agrees_with_the_recursion() {
        let knots = [0.0, 0.0, 0.25, 0.5, 0.5, 0.75, 1.0, 1.0, 1.0];
        for k in 0..=16 {
            let u = k as f64 / 16.0;
            let t = cox_de_boor_triangle(3, &knots, &u);
            for (j, level) in t.iter().enumerate() {
                for (i, v) in level.iter().enumerate() {
                    assert_eq!(
                        *v,
                        super::super::cox_de_boor(i, j, &knots, &u).unwrap(),
                        "N_{i},{j}({u})"
                    );
                }
            }
        }
    }
}
