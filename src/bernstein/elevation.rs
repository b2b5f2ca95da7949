//! Arithmetic on polynomials given by their Bernstein coefficients over `[0, 1]`: degree
//! elevation (thesis §2.3) and the product.
//!
//! A polynomial of degree `n` is `p(t) = Σ_i a_i B_i^n(t)`; the coefficients `a_i` are numbers
//! (one coordinate of a Bézier curve's control points) or anything else a [`Scalar`] holds.

use crate::cost::Cost;
use crate::scalar::Scalar;

use super::binomial::binomial_scalar;

/// The same polynomial written with degree `n + 1` (one step of degree elevation):
///
/// ```text
/// a'_i = i/(n+1) · a_{i−1} + (1 − i/(n+1)) · a_i,   i = 0, …, n + 1,
/// ```
///
/// with the out-of-range terms dropped, so `a'_0 = a_0` and `a'_{n+1} = a_n`. Every new
/// coefficient is a convex combination of two old ones (no cancellation, no binomials).
/// An empty slice stays empty.
///
/// ```
/// use cagd::bernstein::elevate_once;
/// assert_eq!(elevate_once(&[0.0, 3.0]), vec![0.0, 1.5, 3.0]);
/// ```
pub fn elevate_once<T: Scalar>(a: &[T]) -> Vec<T> {
    let Some(last) = a.last() else {
        return Vec::new();
    };
    let m = a.len();
    (0..=m)
        .map(|i| {
            if i == 0 {
                a[0].clone()
            } else if i == m {
                last.clone()
            } else {
                let alpha = T::from_ratio(i as i64, m as i64);
                alpha.clone() * a[i - 1].clone() + (T::one() - alpha) * a[i].clone()
            }
        })
        .collect()
}

/// The same polynomial written with degree `to` (at least its degree `a.len() − 1`):
/// [`elevate_once`] repeated, which gives, exactly in rationals,
///
/// ```text
/// c_k = Σ_i C(r, i) C(to − r, k − i) / C(to, k) · a_i,   r = a.len() − 1.
/// ```
///
/// `to` below the degree returns the coefficients unchanged.
///
/// ```
/// use cagd::bernstein::elevate;
/// use cagd::Scalar;
/// use num_rational::BigRational;
/// let q = |n: i64, d: i64| BigRational::from_ratio(n, d);
/// // t² = Σ_k k(k−1)/12 · B_k^4(t).
/// let e = elevate(&[q(0, 1), q(0, 1), q(1, 1)], 4);
/// assert_eq!(e, vec![q(0, 1), q(0, 1), q(1, 6), q(1, 2), q(1, 1)]);
/// ```
pub fn elevate<T: Scalar>(a: &[T], to: usize) -> Vec<T> {
    let mut c = a.to_vec();
    while c.len() < to + 1 && !c.is_empty() {
        c = elevate_once(&c);
    }
    c
}

/// The cost of raising `n + 1` coefficients (degree `n`) by `r` degrees with [`elevate`]:
/// `r` steps of [`elevate_once`], the step from degree `m` making `m + 2` coefficients of about
/// 5 operations each (the ratio `i/(m+1)`, two products, a sum), `5 Σ_{m=n}^{n+r−1} (m + 2)`
/// operations in all, on numbers that grow by the bits of a denominator `m + 1` (and as much
/// of numerator) at each step: `coefficient_bits + 2r · bits(n + r)`.
///
/// ```
/// use cagd::cost::Cost;
/// // Degree 3 by 2: steps of 5 and 6 coefficients; bits(5) = 3.
/// assert_eq!(cagd::bernstein::elevate_cost(3, 2, 10), Cost::new(55, 10 + 2 * 2 * 3));
/// ```
pub fn elevate_cost(n: usize, r: usize, coefficient_bits: u128) -> Cost {
    let (n, r) = (n as u128, r as u128);
    // Σ_{m=n}^{n+r−1} (m + 2) = r (n + 2) + r (r − 1) / 2.
    let coefficients = r
        .saturating_mul(n + 2)
        .saturating_add(r.saturating_mul(r.saturating_sub(1)) / 2);
    let top = n.saturating_add(r);
    let bits = u128::from(u128::BITS - top.leading_zeros());
    Cost::new(
        coefficients.saturating_mul(5),
        coefficient_bits.saturating_add(r.saturating_mul(2 * bits)),
    )
}

/// The Bernstein coefficients of the product of two polynomials given by their Bernstein
/// coefficients (degrees `p = a.len() − 1`, `q = b.len() − 1`, both at least 0):
///
/// ```text
/// c_k = Σ_{i+j=k} C(p, i) C(q, j) / C(p + q, k) · a_i b_j,   k = 0, …, p + q.
/// ```
///
/// ```
/// use cagd::bernstein::product;
/// // t · t = t²: [0, 1] times [0, 1] is [0, 0, 1].
/// assert_eq!(product(&[0.0, 1.0], &[0.0, 1.0]), vec![0.0, 0.0, 1.0]);
/// ```
pub fn product<T: Scalar>(a: &[T], b: &[T]) -> Vec<T> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let (p, q) = (a.len() - 1, b.len() - 1);
    (0..=p + q)
        .map(|k| {
            let sum = (k.saturating_sub(q)..=k.min(p)).fold(T::zero(), |sum, i| {
                let j = k - i;
                sum + binomial_scalar::<T>(p, i)
                    * binomial_scalar::<T>(q, j)
                    * a[i].clone()
                    * b[j].clone()
            });
            sum / binomial_scalar::<T>(p + q, k)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational as Q;

    fn q(n: i64, d: i64) -> Q {
        <Q as Scalar>::from_ratio(n, d)
    }

    /// Evaluates Bernstein coefficients at `t` by the definition.
    fn eval(c: &[Q], t: &Q) -> Q {
        let n = c.len() - 1;
        c.iter().enumerate().fold(q(0, 1), |acc, (i, ci)| {
            let mut b: Q = binomial_scalar(n, i);
            for _ in 0..i {
                b *= t.clone();
            }
            for _ in i..n {
                b *= q(1, 1) - t.clone();
            }
            acc + b * ci.clone()
        })
    }

    #[test]
    fn product_and_elevation_keep_the_polynomial() {
        let a = [q(1, 2), q(-3, 1), q(2, 5)];
        let b = [q(7, 3), q(0, 1)];
        let c = product(&a, &b);
        let e = elevate(&a, 5);
        assert_eq!((c.len(), e.len()), (4, 6));
        for t in [q(0, 1), q(1, 3), q(4, 5), q(1, 1), q(3, 2)] {
            assert_eq!(eval(&c, &t), eval(&a, &t) * eval(&b, &t));
            assert_eq!(eval(&e, &t), eval(&a, &t));
        }
    }

    #[test]
    fn repeated_steps_are_the_closed_formula() {
        let a = [q(1, 2), q(-3, 1), q(2, 5), q(9, 7)];
        let (r, to) = (3, 7);
        let e = elevate(&a, to);
        for (k, ek) in e.iter().enumerate() {
            let closed = (k.saturating_sub(to - r)..=k.min(r)).fold(q(0, 1), |s, i| {
                s + binomial_scalar::<Q>(r, i) * binomial_scalar::<Q>(to - r, k - i) * a[i].clone()
            }) / binomial_scalar::<Q>(to, k);
            assert_eq!(*ek, closed, "c_{k}");
        }
    }

    #[test]
    fn degenerate_inputs() {
        assert_eq!(elevate(&[2.0], 0), vec![2.0]);
        assert_eq!(elevate(&[2.0], 3), vec![2.0; 4]);
        assert_eq!(elevate(&[1.0, 2.0, 3.0], 1), vec![1.0, 2.0, 3.0]);
        assert!(elevate::<f64>(&[], 3).is_empty());
        assert!(product::<f64>(&[], &[1.0]).is_empty());
    }
}
