//! Bernstein polynomials (thesis §2.2, Definicija 2.5):
//!
//! ```text
//! B_i^n(t) = C(n, i) · t^i · (1 − t)^(n − i),   i = 0, …, n,
//! ```
//!
//! with `B_i^n ≡ 0` for `i > n`. Everything here is generic over [`Scalar`], so the same code
//! gives `f64` values and exact rational ones.
//!
//! - [`binomial`] is exact at any size ([`BigUint`]); [`binomial_f64`] is the fast path, exact
//!   whenever the coefficient is below 2⁵³ (up to n = 56 for every k, and much further near the
//!   ends of a row).
//! - [`bernstein_all`] evaluates a whole degree by the triangular recurrence of Izrek 2.6,
//!   `B_i^n = (1 − t) B_i^{n−1} + t B_{i−1}^{n−1}`. For `t ∈ [0, 1]` every term is a
//!   non-negative multiple of a non-negative number, so there is no cancellation and the values
//!   are accurate to a few units in the last place at any degree (the same reason de Casteljau's
//!   algorithm is stable).
//! - [`bernstein_derivative`] uses `d^r/dt^r B_i^n = n!/(n−r)! · Σ_j (−1)^(r−j) C(r, j)
//!   B_{i−j}^{n−r}`, the basis form of the forward-difference formula of thesis §2.4.

use std::any::Any;

use nalgebra::DMatrix;
use num_bigint::BigUint;
use num_traits::{One, ToPrimitive, Zero};

use crate::scalar::Scalar;

/// The binomial coefficient `C(n, k) = n! / (k! (n − k)!)`, exactly; `0` when `k > n`
/// (thesis Definicija 2.5).
///
/// Computed by the multiplicative formula `C(n, k) = Π_{i=1..k} (n − k + i) / i`, where every
/// partial product is itself a binomial coefficient, so each division is exact.
///
/// ```
/// use cagd::bernstein::binomial;
/// use num_bigint::BigUint;
/// assert_eq!(binomial(5, 2), BigUint::from(10u32));
/// assert_eq!(binomial(3, 4), BigUint::from(0u32));
/// // Far beyond what a double holds exactly: C(100, 50).
/// assert_eq!(
///     binomial(100, 50).to_string(),
///     "100891344545564193334812497256"
/// );
/// ```
pub fn binomial(n: usize, k: usize) -> BigUint {
    if k > n {
        return BigUint::zero();
    }
    let k = k.min(n - k);
    let mut c = BigUint::one();
    for i in 1..=k {
        c *= BigUint::from(n - k + i);
        c /= BigUint::from(i);
    }
    c
}

/// `C(n, k)` as the nearest `f64`; exact whenever the coefficient is below 2⁵³.
///
/// Uses 128-bit integers while the partial products fit (the coefficient is then computed
/// exactly and rounded once) and falls back to the exact [`binomial`] beyond. Coefficients above
/// `f64::MAX` (from about `n = 1030` on, in the middle of the row) give `f64::INFINITY`.
///
/// ```
/// use cagd::bernstein::binomial_f64;
/// assert_eq!(binomial_f64(4, 2), 6.0);
/// assert_eq!(binomial_f64(56, 28), 7648690600760440.0); // exact: below 2^53
/// assert_eq!(binomial_f64(2, 3), 0.0);
/// ```
pub fn binomial_f64(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    let mut c: u128 = 1;
    for i in 1..=k {
        match c.checked_mul((n - k + i) as u128) {
            Some(p) => c = p / i as u128,
            None => return binomial(n, k).to_f64().unwrap_or(f64::INFINITY),
        }
    }
    c as f64
}

/// A non-negative integer held in a [`BigUint`], as a scalar: exact for rationals, correctly
/// rounded for `f64`.
pub(crate) fn scalar_from_biguint<T: Scalar>(value: &BigUint) -> T {
    if let Some(small) = value.to_i64() {
        return T::from_ratio(small, 1);
    }
    // For f64, one correctly rounded conversion beats Horner's rule with a rounding per digit.
    if std::any::TypeId::of::<T>() == std::any::TypeId::of::<f64>() {
        let boxed: Box<dyn Any> = Box::new(value.to_f64().unwrap_or(f64::INFINITY));
        if let Ok(x) = boxed.downcast::<T>() {
            return *x;
        }
    }
    // Exact for rationals: Horner's rule in base 2^32.
    let base = T::from_ratio(1 << 32, 1);
    value
        .to_u32_digits()
        .iter()
        .rev()
        .fold(T::zero(), |acc, &digit| {
            acc * base.clone() + T::from_ratio(i64::from(digit), 1)
        })
}

/// `C(n, k)` as a scalar (exact for rationals, nearest double for `f64`).
pub(crate) fn binomial_scalar<T: Scalar>(n: usize, k: usize) -> T {
    if std::any::TypeId::of::<T>() == std::any::TypeId::of::<f64>() {
        let boxed: Box<dyn Any> = Box::new(binomial_f64(n, k));
        if let Ok(x) = boxed.downcast::<T>() {
            return *x;
        }
    }
    scalar_from_biguint(&binomial(n, k))
}

/// The falling factorial `n (n − 1) ⋯ (n − r + 1) = n!/(n − r)!` as a scalar (`1` for `r = 0`),
/// the factor of the r-th derivative of a degree-n Bézier curve (thesis §2.4).
pub(crate) fn falling_factorial<T: Scalar>(n: usize, r: usize) -> T {
    (0..r.min(n + 1)).fold(T::one(), |acc, k| acc * T::from_usize(n - k))
}

/// `x^k` by repeated squaring.
pub(crate) fn power<T: Scalar>(x: &T, k: usize) -> T {
    num_traits::pow(x.clone(), k)
}

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
pub fn bernstein_all<T: Scalar>(n: usize, t: T) -> Vec<T> {
    let mut b = vec![T::zero(); n + 1];
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
pub fn bernstein_derivative_all<T: Scalar>(n: usize, r: usize, t: T) -> Vec<T> {
    if r > n {
        return vec![T::zero(); n + 1];
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
    (0..=n)
        .map(|i| {
            let mut sum = T::zero();
            for (j, c) in signed.iter().enumerate().take(i + 1) {
                let k = i - j;
                if k <= n - r {
                    sum = sum + c.clone() * lower[k].clone();
                }
            }
            factor.clone() * sum
        })
        .collect()
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
pub fn basis_matrix<T: Scalar>(n: usize, ts: &[T]) -> DMatrix<T> {
    let mut m = DMatrix::from_element(ts.len(), n + 1, T::zero());
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
pub fn basis_derivative_matrix<T: Scalar>(n: usize, r: usize, ts: &[T]) -> DMatrix<T> {
    let mut m = DMatrix::from_element(ts.len(), n + 1, T::zero());
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
    fn binomial_rows_sum_to_powers_of_two() {
        for n in 0..70usize {
            let sum = (0..=n).fold(BigUint::zero(), |acc, k| acc + binomial(n, k));
            assert_eq!(sum, BigUint::one() << n);
        }
    }

    #[test]
    fn binomial_f64_is_exact_below_2_pow_53() {
        for n in 0..=200usize {
            for k in 0..=n {
                let exact = binomial(n, k);
                if exact < (BigUint::one() << 53) {
                    assert_eq!(binomial_f64(n, k), exact.to_f64().unwrap(), "C({n},{k})");
                }
            }
        }
        // Rounded once, correctly, beyond: C(200, 100) ≈ 9.0548514656103281e58.
        let big = binomial(200, 100).to_f64().unwrap();
        assert_eq!(binomial_f64(200, 100), big);
        assert!(binomial_f64(2000, 1000).is_infinite());
    }

    #[test]
    fn scalar_conversion_of_large_binomials_is_exact_for_rationals() {
        let c = binomial(100, 50);
        let r: BigRational = scalar_from_biguint(&c);
        assert_eq!(r.to_string(), "100891344545564193334812497256");
        let f: f64 = scalar_from_biguint(&c);
        assert_eq!(f, c.to_f64().unwrap());
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

    #[test]
    fn falling_factorial_values() {
        assert_eq!(falling_factorial::<f64>(5, 0), 1.0);
        assert_eq!(falling_factorial::<f64>(5, 2), 20.0);
        assert_eq!(falling_factorial::<f64>(5, 5), 120.0);
    }
}
