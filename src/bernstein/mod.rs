//! Bernstein polynomials (thesis §2.2, Definicija 2.5):
//!
//! ```text
//! B_i^n(t) = C(n, i) · t^i · (1 − t)^(n − i),   i = 0, …, n,
//! ```
//!
//! with `B_i^n ≡ 0` for `i > n`. Everything here is generic over [`Scalar`], so the same code
//! gives `f64` values and exact rational ones.
//!
//! - [`binomial`] is exact at any size ([`BigUint`](num_bigint::BigUint)); [`binomial_scalar`]
//!   gives it in any scalar, exact for rationals and correctly rounded for `f64` (exact
//!   whenever the coefficient is below 2⁵³: up to n = 56 for every k, and much further near
//!   the ends of a row); [`falling_factorial`] and [`power`] are the other integer products of
//!   the basis (`binomial.rs`).
//! - [`bernstein_all`] evaluates a whole degree by the triangular recurrence of Izrek 2.6,
//!   `B_i^n = (1 − t) B_i^{n−1} + t B_{i−1}^{n−1}`. For `t ∈ [0, 1]` every term is a
//!   non-negative multiple of a non-negative number, so there is no cancellation and the values
//!   are accurate to a few units in the last place at any degree (the same reason de Casteljau's
//!   algorithm is stable).
//! - [`bernstein_derivative`] uses `d^r/dt^r B_i^n = n!/(n−r)! · Σ_j (−1)^(r−j) C(r, j)
//!   B_{i−j}^{n−r}`, the basis form of the forward-difference formula of thesis §2.4.
//! - [`elevate`], [`elevate_once`] and [`product`] compute with polynomials in Bernstein form:
//!   degree elevation (thesis §2.3; [`BezierCurve::elevate`](crate::BezierCurve::elevate) and
//!   the Bézier form of a Gordon surface use it) and products (`elevation.rs`).
//!
//! This module is the crate's one owner of binomials, falling factorials, powers and degree
//! elevation.

use nalgebra::DMatrix;

use crate::cost::{polynomial_bits, Cost};
use crate::scalar::Scalar;

mod binomial;
mod elevation;

pub use binomial::{binomial, binomial_f64, binomial_scalar, falling_factorial, power};
pub use elevation::{elevate, elevate_cost, elevate_once, product};

/// One Bernstein polynomial `B_i^n(t) = C(n, i) t^i (1 − t)^(n − i)`; `0` for `i > n`.
///
/// Any `t` is accepted (outside `[0, 1]` the value is the polynomial's value there). The direct
/// formula is accurate to a few units in the last place in `f64` and exact for rationals; if
/// `C(n, i)` does not fit in a double (n above about 1030) the value comes from the
/// triangular recurrence of [`bernstein_all`] instead. A NaN parameter gives NaN.
///
/// ```
/// use cagd::bernstein::bernstein;
/// assert_eq!(bernstein(1, 3, 0.5), 0.375); // 3 · 0.5 · 0.25
/// assert_eq!(bernstein(4, 3, 0.5), 0.0);   // i > n
/// assert_eq!(bernstein(0, 0, 0.7), 1.0);   // B_0^0 ≡ 1
/// ```
///
/// # Panics
/// As [`bernstein_all`], when `C(n, i)` does not fit in a double and the `n + 1` values of the
/// recurrence cannot be held (`n` near `usize::MAX`): a panic naming the size, never an abort.
/// The work is `min(i, n − i)` products for the binomial, `(n+1)²` when the recurrence is
/// needed; in exact arithmetic the numbers grow with `n` (`t^i (1 − t)^(n−i)`): the front ends
/// check the degree against their limits first.
pub fn bernstein<T: Scalar>(i: usize, n: usize, t: T) -> T {
    if i > n {
        return T::zero();
    }
    let c: T = binomial_scalar(n, i);
    if !c.is_finite_value() {
        return bernstein_all(n, t).swap_remove(i);
    }
    let s = T::one() - t.clone();
    c * power(&t, i) * power(&s, n - i)
}

/// All Bernstein polynomials of degree `n` at `t`: the vector `[B_0^n(t), …, B_n^n(t)]` of
/// length `n + 1`.
///
/// Built level by level from `B_0^0 = 1` with `B_i^k = (1 − t) B_i^{k−1} + t B_{i−1}^{k−1}`
/// (thesis Izrek 2.6). For `t ∈ [0, 1]` only non-negative terms are ever added, so the result is
/// non-negative and sums to 1 up to rounding (exactly, for rationals).
///
/// ```
/// use cagd::bernstein::bernstein_all;
/// assert_eq!(bernstein_all(3, 0.5), vec![0.125, 0.375, 0.375, 0.125]);
/// assert_eq!(bernstein_all(0, 0.3), vec![1.0]);
///
/// use num_rational::BigRational;
/// use cagd::Scalar;
/// let t = BigRational::from_ratio(1, 3);
/// let b = bernstein_all(2, t);
/// assert_eq!(b[1], BigRational::from_ratio(4, 9)); // 2 · (1/3) · (2/3)
/// ```
///
/// # Panics
/// If `n + 1` values cannot be held (`n` near `usize::MAX`): a panic naming the size, never an
/// abort. Its work is `(n+1)²`: the front ends check the degree against their limits first.
pub fn bernstein_all<T: Scalar>(n: usize, t: T) -> Vec<T> {
    let mut b = crate::grid::filled("Bernstein basis", n.checked_add(1), T::zero());
    bernstein_all_into(&t, &mut b);
    b
}

/// [`bernstein_all`] into a caller-given slice: `out[i] = B_i^n(t)` with `n = out.len() − 1`,
/// the same values bit for bit, without allocating (an empty `out` is left alone).
///
/// ```
/// use cagd::bernstein::bernstein_all_into;
/// let mut b = [0.0; 4];
/// bernstein_all_into(&0.5, &mut b);
/// assert_eq!(b, [0.125, 0.375, 0.375, 0.125]);
/// ```
pub fn bernstein_all_into<T: Scalar>(t: &T, out: &mut [T]) {
    // Exact rationals: the same values from integer products, without the recurrence's gcds.
    if crate::grid::exact::bernstein_row(t, out) {
        return;
    }
    // Low degrees get the loop with its length known at compile time (fully unrolled); the
    // arithmetic, and so every bit of the result, is the same.
    match out.len() {
        0 => {}
        2 => recurrence_fixed::<T, 2>(t, out),
        3 => recurrence_fixed::<T, 3>(t, out),
        4 => recurrence_fixed::<T, 4>(t, out),
        5 => recurrence_fixed::<T, 5>(t, out),
        6 => recurrence_fixed::<T, 6>(t, out),
        _ => recurrence(t, out),
    }
}

#[inline]
fn recurrence_fixed<T: Scalar, const L: usize>(t: &T, out: &mut [T]) {
    if let Ok(fixed) = <&mut [T; L]>::try_from(&mut *out) {
        recurrence(t, fixed);
    } else {
        recurrence(t, out);
    }
}

/// Thesis Izrek 2.6 level by level, in place: `B_0^0 = 1`,
/// `B_i^k = (1 − t) B_i^{k−1} + t B_{i−1}^{k−1}`.
#[inline(always)]
pub(crate) fn recurrence<T: Scalar>(t: &T, out: &mut [T]) {
    let Some((first, _)) = out.split_first_mut() else {
        return;
    };
    *first = T::one();
    let s = T::one() - t.clone();
    for k in 1..out.len() {
        // Left to right: `carry` holds t·B_{i−1}^{k−1} from the previous entry.
        let mut carry = T::zero();
        for bi in out[..k].iter_mut() {
            let old = std::mem::replace(bi, T::zero());
            *bi = carry + s.clone() * old.clone();
            carry = t.clone() * old;
        }
        out[k] = carry;
    }
}

/// The cost of all Bernstein polynomials of degree `n` at one parameter of `param_bits` bits
/// by the triangular recurrence ([`bernstein_all`]): `(n+1)²` operations on numbers of
/// [`polynomial_bits`]`(n, param_bits, 0)` bits.
///
/// ```
/// use cagd::cost::Cost;
/// assert_eq!(cagd::bernstein::basis_cost(3, 2), Cost::new(16, 9));
/// ```
pub fn basis_cost(n: usize, param_bits: u128) -> Cost {
    Cost::new(
        (n as u128 + 1).saturating_pow(2),
        polynomial_bits(n, param_bits, 0),
    )
}

/// The `r`-th derivative of `B_i^n` at `t`.
///
/// ```text
/// d^r/dt^r B_i^n(t) = n!/(n−r)! · Σ_{j=0..r} (−1)^(r−j) C(r, j) B_{i−j}^{n−r}(t)
/// ```
///
/// (for `r = 1` this is thesis eq. (2.4), `n (B_{i−1}^{n−1} − B_i^{n−1})`). For `r > n` the
/// derivative of a polynomial of degree `n` is identically zero, and so is the result; `i > n`
/// also gives zero.
///
/// ```
/// use cagd::bernstein::bernstein_derivative;
/// // B_1^2(t) = 2t(1−t): first derivative 2 − 4t, second −4, third 0.
/// assert_eq!(bernstein_derivative(1, 2, 1, 0.25), 1.0);
/// assert_eq!(bernstein_derivative(1, 2, 2, 0.25), -4.0);
/// assert_eq!(bernstein_derivative(1, 2, 3, 0.25), 0.0);
/// // r = 0 is the polynomial itself.
/// assert_eq!(bernstein_derivative(1, 2, 0, 0.25), 0.375);
/// ```
///
/// # Panics
/// As [`bernstein_all`] of degree `n − r`: if its `n − r + 1` values cannot be held, a panic
/// naming the size, never an abort. The work is `(n − r + 1)² + r` operations: the front ends
/// check the degree against their limits first.
pub fn bernstein_derivative<T: Scalar>(i: usize, n: usize, r: usize, t: T) -> T {
    if i > n || r > n {
        return T::zero();
    }
    let lower = bernstein_all(n - r, t);
    let mut sum = T::zero();
    for j in 0..=r.min(i) {
        let k = i - j;
        if k > n - r {
            continue;
        }
        let term = binomial_scalar::<T>(r, j) * lower[k].clone();
        if (r - j) % 2 == 0 {
            sum = sum + term;
        } else {
            sum = sum - term;
        }
    }
    falling_factorial::<T>(n, r) * sum
}

/// All `r`-th derivatives `[d^r B_0^n(t), …, d^r B_n^n(t)]` (length `n + 1`; all zero when
/// `r > n`). See [`bernstein_derivative`] for the formula.
///
/// ```
/// use cagd::bernstein::bernstein_derivative_all;
/// // Derivatives of a partition of unity sum to zero.
/// let d = bernstein_derivative_all(4, 2, 0.3);
/// assert!(d.iter().sum::<f64>().abs() < 1e-12);
/// ```
///
/// # Panics
/// If the `n + 1` values cannot be held (`n` near `usize::MAX`): a panic naming the size,
/// never an abort. The work is `(n + 1)(r + 1) + (n − r + 1)²` operations: the front ends check
/// the degree against their limits first.
pub fn bernstein_derivative_all<T: Scalar>(n: usize, r: usize, t: T) -> Vec<T> {
    if r > n {
        return crate::grid::filled("Bernstein derivatives", n.checked_add(1), T::zero());
    }
    let lower = bernstein_all(n - r, t);
    let factor = falling_factorial::<T>(n, r);
    let signed: Vec<T> = (0..=r)
        .map(|j| {
            let c = binomial_scalar::<T>(r, j);
            if (r - j) % 2 == 0 {
                c
            } else {
                -c
            }
        })
        .collect();
    let mut out = crate::grid::filled("Bernstein derivatives", n.checked_add(1), T::zero());
    for (i, slot) in out.iter_mut().enumerate() {
        let mut sum = T::zero();
        for (j, c) in signed.iter().enumerate().take(i + 1) {
            let k = i - j;
            if k <= n - r {
                sum = sum + c.clone() * lower[k].clone();
            }
        }
        *slot = factor.clone() * sum;
    }
    out
}

/// The Bernstein basis matrix: row `k` is `[B_0^n(ts[k]), …, B_n^n(ts[k])]`, so the result is
/// `ts.len() × (n + 1)` (rows = parameters, columns = basis functions).
///
/// Multiplying it by a column of control values evaluates a Bézier function at every
/// parameter at once; a patch on a grid is `B_u · P · B_vᵀ` per coordinate. An empty `ts`
/// gives a `0 × (n + 1)` matrix.
///
/// ```
/// use cagd::bernstein::basis_matrix;
/// let b = basis_matrix(2, &[0.0, 0.5, 1.0]);
/// assert_eq!(b.shape(), (3, 3));
/// assert_eq!(b.row(1).iter().copied().collect::<Vec<_>>(), vec![0.25, 0.5, 0.25]);
/// assert_eq!(b[(2, 2)], 1.0);
/// ```
///
/// # Panics
/// If the `ts.len() × (n + 1)` values cannot be held: a panic naming the size, never an abort.
pub fn basis_matrix<T: Scalar>(n: usize, ts: &[T]) -> DMatrix<T> {
    let cols = n
        .checked_add(1)
        .expect("Bernstein basis matrix: n + 1 basis functions overflow usize");
    let data = crate::grid::filled(
        "Bernstein basis matrix",
        ts.len().checked_mul(cols),
        T::zero(),
    );
    let mut m = DMatrix::from_vec(ts.len(), cols, data);
    for (k, t) in ts.iter().enumerate() {
        for (i, b) in bernstein_all(n, t.clone()).into_iter().enumerate() {
            m[(k, i)] = b;
        }
    }
    m
}

/// The matrix of `r`-th derivatives of the basis: row `k` is
/// `[d^r B_0^n(ts[k]), …, d^r B_n^n(ts[k])]` (`ts.len() × (n + 1)`).
///
/// ```
/// use cagd::bernstein::basis_derivative_matrix;
/// let d = basis_derivative_matrix(1, 1, &[0.2]);
/// assert_eq!((d[(0, 0)], d[(0, 1)]), (-1.0, 1.0));
/// ```
///
/// # Panics
/// If the `ts.len() × (n + 1)` values cannot be held: a panic naming the size, never an abort.
pub fn basis_derivative_matrix<T: Scalar>(n: usize, r: usize, ts: &[T]) -> DMatrix<T> {
    let cols = n
        .checked_add(1)
        .expect("Bernstein derivative matrix: n + 1 basis functions overflow usize");
    let data = crate::grid::filled(
        "Bernstein derivative matrix",
        ts.len().checked_mul(cols),
        T::zero(),
    );
    let mut m = DMatrix::from_vec(ts.len(), cols, data);
    for (k, t) in ts.iter().enumerate() {
        for (i, b) in bernstein_derivative_all(n, r, t.clone())
            .into_iter()
            .enumerate()
        {
            m[(k, i)] = b;
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        <BigRational as Scalar>::from_ratio(n, d)
    }

    #[test]
    fn basis_cost_counts_the_recurrence() {
        // The recurrence does k multiplications and additions at level k: below (n+1)².
        assert_eq!(basis_cost(0, 5).ops(), 1);
        assert_eq!(basis_cost(10, 0), Cost::new(121, 10));
        assert_eq!(basis_cost(10, 7).bits(), 80);
    }

    #[test]
    fn bernstein_matches_recurrence_exactly_in_rationals() {
        for n in 0..12 {
            let t = q(2, 7);
            let all = bernstein_all(n, t.clone());
            for (i, b) in all.iter().enumerate() {
                assert_eq!(*b, bernstein(i, n, t.clone()));
            }
        }
    }

    #[test]
    fn high_degree_f64_falls_back_to_recurrence() {
        // C(1100, 550) overflows a double; the recurrence still gives a finite tiny value.
        let b = bernstein(550, 1100, 0.5);
        assert!(b.is_finite() && b > 0.0 && b < 0.03);
        let all = bernstein_all(1100, 0.5);
        assert_eq!(b, all[550]);
    }

    #[test]
    fn derivative_formula_in_rationals() {
        // B_2^4(t) = 6 t^2 (1-t)^2; B'' = 12 - 72 t + 72 t^2; at t = 1/3: 12 - 24 + 8 = -4.
        assert_eq!(bernstein_derivative(2, 4, 2, q(1, 3)), q(-4, 1));
        let all = bernstein_derivative_all(4, 2, q(1, 3));
        assert_eq!(all[2], q(-4, 1));
        for (i, d) in all.iter().enumerate() {
            assert_eq!(*d, bernstein_derivative(i, 4, 2, q(1, 3)));
        }
        // Fourth derivative of 6 t^2 (1-t)^2 = 6 t^4 + … is 144.
        assert_eq!(bernstein_derivative(2, 4, 4, q(5, 9)), q(144, 1));
    }
}
