//! Binomial coefficients and the other integer products of the Bernstein basis: falling
//! factorials (the factor of a derivative) and powers.
//!
//! The one binomial of the crate: [`binomial`] exactly, [`binomial_scalar`] in any
//! [`Scalar`] (exact for rationals, correctly rounded for `f64`), [`binomial_f64`] its `f64`
//! instance. All come from the multiplicative formula
//!
//! ```text
//! C(n, k) = Π_{i=1..k} (n − k + i) / i,
//! ```
//!
//! whose partial products are themselves binomial coefficients, so every division is exact.

use num_bigint::BigUint;
use num_traits::One;

use crate::scalar::Scalar;

/// `C(n, k)` in 128-bit integers, or `None` when a partial product does not fit (the
/// coefficient is then computed in [`BigUint`]). `Some(0)` for `k > n`.
fn binomial_u128(n: usize, k: usize) -> Option<u128> {
    if k > n {
        return Some(0);
    }
    let k = k.min(n - k);
    let mut c: u128 = 1;
    for i in 1..=k {
        c = c.checked_mul((n - k + i) as u128)? / i as u128;
    }
    Some(c)
}

/// The binomial coefficient `C(n, k) = n! / (k! (n − k)!)`, exactly; `0` when `k > n`
/// (thesis Definicija 2.5).
///
/// Computed by the multiplicative formula `C(n, k) = Π_{i=1..k} (n − k + i) / i`, where every
/// partial product is itself a binomial coefficient, so each division is exact (in 128-bit
/// integers while they hold the partial products, in [`BigUint`] beyond).
///
/// The work is `min(k, n − k)` products of numbers growing to about `min(k, n − k) · log₂ n`
/// bits — quadratic in that size: the crate asks for it at degrees its limits bound (at most
/// `Limits::max_degree`); a caller passing `n = 10⁹, k = n/2` waits for hours.
///
/// # Panics
/// Never on its arguments; the big integer it builds is allocated as it grows, so a size no
/// machine holds would end the process — long after the hours above. Bound `n` first (the
/// front ends check the degree against their limits).
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
    if let Some(c) = binomial_u128(n, k) {
        return BigUint::from(c);
    }
    let k = k.min(n - k);
    let mut c = BigUint::one();
    for i in 1..=k {
        c *= BigUint::from(n - k + i);
        c /= BigUint::from(i);
    }
    c
}

/// `C(n, k)` as a scalar: exact for rationals, the nearest double for `f64` (the exact
/// integer rounded once, [`Scalar::from_biguint`]); `0` when `k > n`.
///
/// ```
/// use cagd::bernstein::binomial_scalar;
/// use num_rational::BigRational;
/// assert_eq!(binomial_scalar::<f64>(30, 15), 155117520.0);
/// let c: BigRational = binomial_scalar(100, 50);
/// assert_eq!(c.to_string(), "100891344545564193334812497256");
/// ```
///
/// # Panics
/// Never on its arguments; in exact arithmetic its work and memory are those of [`binomial`]
/// (a double is answered at once: infinite beyond about `n = 1030`).
pub fn binomial_scalar<T: Scalar>(n: usize, k: usize) -> T {
    if !crate::grid::exact::is_rational::<T>() && k <= n && k.min(n - k) > 1030 {
        // Above f64::MAX (as binomial_f64), at once rather than after min(k, n − k) big
        // products: a double is infinite there.
        return T::from_f64(f64::MAX).map_or_else(T::zero, |m| m.clone() + m);
    }
    match binomial_u128(n, k) {
        Some(c) => match i64::try_from(c) {
            Ok(small) => T::from_ratio(small, 1),
            Err(_) => T::from_biguint(&BigUint::from(c)),
        },
        None => T::from_biguint(&binomial(n, k)),
    }
}

/// `C(n, k)` as the nearest `f64` ([`binomial_scalar`] in `f64`); exact whenever the
/// coefficient is below 2⁵³. Coefficients above `f64::MAX` (from about `n = 1030` on, in the
/// middle of the row) give `f64::INFINITY`.
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
    // C(n, m), m = min(k, n − k) > 1030 and n ≥ 2m, is at least C(2062, 1031) > f64::MAX:
    // answered at once instead of after min(k, n − k) products (2⁶³ for n = usize::MAX).
    if k.min(n - k) > 1030 {
        return f64::INFINITY;
    }
    binomial_scalar(n, k)
}

/// The falling factorial `n (n − 1) ⋯ (n − r + 1) = n!/(n − r)!` as a scalar (`1` for
/// `r = 0`, `0` for `r > n`), the factor of the r-th derivative of a degree-n Bézier curve
/// (thesis §2.4).
///
/// ```
/// use cagd::bernstein::falling_factorial;
/// assert_eq!(falling_factorial::<f64>(5, 2), 20.0);
/// assert_eq!(falling_factorial::<f64>(3, 0), 1.0);
/// ```
///
/// # Panics
/// Never on its arguments. A double stops at the first infinite product (at most a few hundred
/// factors); in exact arithmetic it is `r` products of a number growing to about `r log₂ n`
/// bits: bound `r` first (the front ends check the degree against their limits).
pub fn falling_factorial<T: Scalar>(n: usize, r: usize) -> T {
    if r > n {
        // One of the factors is n − n = 0.
        return T::zero();
    }
    let mut acc = T::one();
    for k in 0..r {
        acc = acc * T::from_usize(n - k);
        if !acc.is_finite_value() {
            // Every further factor is at least 1: a double stays infinite (not r steps).
            break;
        }
    }
    acc
}

/// `x^k` by repeated squaring.
///
/// ```
/// assert_eq!(cagd::bernstein::power(&0.5, 3), 0.125);
/// ```
///
/// # Panics
/// Never on its arguments. A double takes `log₂ k` squarings; an exact `x` of `b` bits gives a
/// number of `k·b` bits, allocated as it grows: bound `k` first (the crate calls it with
/// degrees its limits bound).
pub fn power<T: Scalar>(x: &T, k: usize) -> T {
    num_traits::pow(x.clone(), k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    use num_traits::{ToPrimitive, Zero};

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
    fn every_size_rounds_once_and_rationals_are_exact() {
        // Through i64, through u128 beyond i64, and through BigUint beyond u128.
        for (n, k) in [(60, 30), (70, 35), (120, 60), (130, 65), (300, 150)] {
            let exact = binomial(n, k);
            assert_eq!(binomial_f64(n, k), exact.to_f64().unwrap(), "C({n},{k})");
            let q: BigRational = binomial_scalar(n, k);
            assert_eq!(q.to_string(), exact.to_string(), "C({n},{k})");
        }
        assert!(i64::try_from(binomial_u128(60, 30).unwrap()).is_ok());
        assert!(i64::try_from(binomial_u128(120, 60).unwrap()).is_err());
        assert!(binomial_u128(130, 65).is_none());
    }

    #[test]
    fn binomial_past_the_row_is_zero_in_every_form() {
        assert_eq!(binomial(3, 4), BigUint::zero());
        assert_eq!(binomial_scalar::<BigRational>(3, 4), BigRational::zero());
        assert_eq!(binomial_f64(0, 1), 0.0);
    }

    #[test]
    fn falling_factorial_values() {
        assert_eq!(falling_factorial::<f64>(5, 0), 1.0);
        assert_eq!(falling_factorial::<f64>(5, 2), 20.0);
        assert_eq!(falling_factorial::<f64>(5, 5), 120.0);
        assert_eq!(falling_factorial::<f64>(2, 3), 0.0);
    }
}
