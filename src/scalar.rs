//! The number type every rational algorithm of the crate is written over.
//!
//! Bernstein polynomials, de Casteljau, Coons, Gordon/Lagrange and the spline solves only add,
//! subtract, multiply and divide, so the same code runs in `f64` (fast, what Octave does) and
//! in exact rationals ([`BigRational`]), where a worked example from the thesis can be checked
//! to the last digit (Primer 2.4 gives exactly (7/2, 3/2, 3/4)).

use std::fmt::{Debug, Display};
use std::ops::Neg;

use nalgebra::DMatrix;
use num_bigint::{BigInt, BigUint};
use num_rational::BigRational;
use num_traits::{FromPrimitive, Num, Signed, ToPrimitive};

/// A field element: `f64` or an exact rational.
///
/// `from_f64` is exact for rationals (every finite double is a dyadic rational), so data typed
/// as decimals can be lifted into exact arithmetic; use [`Scalar::from_ratio`] for values such
/// as 1/3 that no double holds.
///
/// `Send + Sync` so that large grids can be evaluated on several threads.
pub trait Scalar:
    Clone
    + PartialEq
    + PartialOrd
    + Debug
    + Display
    + Num
    + Neg<Output = Self>
    + Signed
    + Send
    + Sync
    + 'static
{
    /// Whether arithmetic is exact (no rounding): `false` for `f64`, `true` for rationals.
    const EXACT: bool;
    /// The exact value of a finite double; `None` for NaN and ±∞.
    fn from_f64(x: f64) -> Option<Self>;
    /// The value `num / den` (rounded to nearest for `f64`). `den` must not be zero.
    fn from_ratio(num: i64, den: i64) -> Self;
    /// The nearest double.
    fn to_f64(&self) -> f64;
    /// Whether the value is a finite number (always true for rationals).
    fn is_finite_value(&self) -> bool;
    /// The index of the first value of `values` that is not finite (`None` for rationals).
    /// The grid kernels scan every row they write with it, so `f64` answers blocks of values
    /// at once (a test of the exponent bits that the compiler vectorizes) and looks for the
    /// index only in a block that has one.
    ///
    /// ```
    /// use cagd::Scalar;
    /// assert_eq!(f64::first_non_finite(&[1.0, 2.0, f64::INFINITY, f64::NAN]), Some(2));
    /// assert_eq!(f64::first_non_finite(&[f64::MAX; 100]), None);
    /// ```
    fn first_non_finite(values: &[Self]) -> Option<usize>
    where
        Self: Sized,
    {
        values.iter().position(|x| !x.is_finite_value())
    }
    /// Whether every value lies in `[lo, hi]` (a NaN does not). The batch kernels bound a
    /// block of points with it; `f64` tests all the values without stopping early, which the
    /// compiler turns into vector comparisons.
    ///
    /// ```
    /// use cagd::Scalar;
    /// assert!(f64::all_within(&[0.0, 0.5, 1.0], &0.0, &1.0));
    /// assert!(!f64::all_within(&[0.5, 1.5], &0.0, &1.0));
    /// assert!(!f64::all_within(&[0.5, f64::NAN], &0.0, &1.0));
    /// ```
    fn all_within(values: &[Self], lo: &Self, hi: &Self) -> bool
    where
        Self: Sized,
    {
        values.iter().all(|x| lo <= x && x <= hi)
    }
    /// The length of the number in bits, numerator and denominator together (0 for `f64`,
    /// whose cost does not depend on the value). Estimates of exact work weigh each operation
    /// by the size its numbers reach ([`crate::limits::exact_op_cost`], [`crate::cost`]).
    ///
    /// ```
    /// use cagd::Scalar;
    /// use num_rational::BigRational;
    /// assert_eq!(<BigRational as Scalar>::from_ratio(7, 2).bits(), 5);
    /// assert_eq!(0.1f64.bits(), 0);
    /// ```
    fn bits(&self) -> u128 {
        0
    }
    /// `n` as a scalar.
    fn from_usize(n: usize) -> Self {
        Self::from_ratio(n as i64, 1)
    }
    /// A non-negative integer of any size (a binomial coefficient beyond `i64`): exact for
    /// rationals, correctly rounded (`f64::INFINITY` above `f64::MAX`) for `f64`. The default
    /// is exact in any field: Horner's rule in base 2³².
    ///
    /// ```
    /// use cagd::Scalar;
    /// use num_bigint::BigUint;
    /// use num_rational::BigRational;
    /// let big = BigUint::from(3u32).pow(50); // 717897987691852588770249, beyond i64
    /// assert_eq!(<BigRational as Scalar>::from_biguint(&big).to_string(), big.to_string());
    /// assert_eq!(f64::from_biguint(&big), 7.178979876918526e23);
    /// ```
    fn from_biguint(value: &BigUint) -> Self {
        if let Some(small) = value.to_i64() {
            return Self::from_ratio(small, 1);
        }
        let base = Self::from_ratio(1 << 32, 1);
        value
            .to_u32_digits()
            .iter()
            .rev()
            .fold(Self::zero(), |acc, &digit| {
                acc * base.clone() + Self::from_ratio(i64::from(digit), 1)
            })
    }
    /// The matrix product `a · b` (`a.ncols()` must equal `b.nrows()`). The default is the
    /// plain triple loop `Σ_k a[i,k] b[k,j]`, `k` ascending, exact for rationals; `f64`
    /// overrides it with nalgebra's blocked product.
    ///
    /// ```
    /// use cagd::Scalar;
    /// use nalgebra::DMatrix;
    /// let a = DMatrix::from_row_slice(1, 2, &[1.0, 2.0]);
    /// let b = DMatrix::from_row_slice(2, 1, &[3.0, 4.0]);
    /// assert_eq!(f64::mat_mul(&a, &b)[(0, 0)], 11.0);
    /// ```
    fn mat_mul(a: &DMatrix<Self>, b: &DMatrix<Self>) -> DMatrix<Self> {
        let (rows, inner, cols) = (a.nrows(), a.ncols(), b.ncols());
        DMatrix::from_fn(rows, cols, |i, j| {
            (0..inner).fold(Self::zero(), |acc, k| {
                acc + a[(i, k)].clone() * b[(k, j)].clone()
            })
        })
    }
    /// Runs `f`, for `f64` in code compiled for the widest vector instructions the processor
    /// offers (on x86-64: AVX2, when present), chosen at run time with the feature `simd`
    /// (crate `pulp`, a safe dispatch: the crate itself stays free of `unsafe`). The grid
    /// kernels run inside it, so their loops are vectorised four doubles wide instead of
    /// SSE2's two. Only code inlined into `f` benefits: the kernels are `#[inline(always)]`.
    ///
    /// The results do not change: Rust never fuses a multiply and an add into an FMA on its
    /// own, and vector adds and multiplies round exactly like scalar ones. The default (and
    /// the rationals') just calls `f`.
    ///
    /// ```
    /// use cagd::Scalar;
    /// let sum = f64::vectorized(|| (1..=4).map(f64::from).sum::<f64>());
    /// assert_eq!(sum, 10.0);
    /// ```
    #[inline]
    fn vectorized<R>(f: impl FnOnce() -> R) -> R
    where
        Self: Sized,
    {
        f()
    }
}

impl Scalar for f64 {
    const EXACT: bool = false;
    #[inline]
    fn from_f64(x: f64) -> Option<Self> {
        x.is_finite().then_some(x)
    }
    #[inline]
    fn from_ratio(num: i64, den: i64) -> Self {
        num as f64 / den as f64
    }
    #[inline]
    fn to_f64(&self) -> f64 {
        *self
    }
    #[inline]
    fn is_finite_value(&self) -> bool {
        self.is_finite()
    }
    fn first_non_finite(values: &[f64]) -> Option<usize> {
        // With the widest vectors of the processor (`vectorized`): a row just written is
        // scanned at about ten values a nanosecond.
        Self::vectorized(|| first_non_finite_f64(values))
    }
    #[inline]
    fn all_within(values: &[f64], lo: &f64, hi: &f64) -> bool {
        values.iter().fold(true, |ok, x| ok & (lo <= x) & (x <= hi))
    }
    #[inline]
    fn from_usize(n: usize) -> Self {
        n as f64
    }
    /// One correctly rounded conversion (a rounding per digit of Horner's rule would drift).
    fn from_biguint(value: &BigUint) -> Self {
        match value.to_i64() {
            Some(small) => small as f64,
            None => ToPrimitive::to_f64(value).unwrap_or(f64::INFINITY),
        }
    }
    fn mat_mul(a: &DMatrix<Self>, b: &DMatrix<Self>) -> DMatrix<Self> {
        a * b
    }
    #[cfg(feature = "simd")]
    #[inline]
    fn vectorized<R>(f: impl FnOnce() -> R) -> R {
        pulp::Arch::new().dispatch(f)
    }
}

/// The index of the first NaN or ±∞ of `values`, a block of 256 at a time: `0 · x` is ±0 for a
/// finite `x` and NaN otherwise, and eight sums of it side by side (which the compiler turns into
/// vector additions) are 0 unless the block holds one.
#[inline(always)]
fn first_non_finite_f64(values: &[f64]) -> Option<usize> {
    const BLOCK: usize = 256;
    values.chunks(BLOCK).enumerate().find_map(|(k, block)| {
        let mut lanes = [0.0f64; 8];
        let mut eights = block.chunks_exact(8);
        for eight in &mut eights {
            for (lane, x) in lanes.iter_mut().zip(eight) {
                *lane += x * 0.0;
            }
        }
        let rest: f64 = eights.remainder().iter().map(|x| x * 0.0).sum();
        if lanes.iter().sum::<f64>() + rest == 0.0 {
            return None;
        }
        block
            .iter()
            .position(|x| !x.is_finite())
            .map(|i| k * BLOCK + i)
    })
}

impl Scalar for BigRational {
    const EXACT: bool = true;
    fn bits(&self) -> u128 {
        u128::from(self.numer().bits() + self.denom().bits())
    }
    fn from_f64(x: f64) -> Option<Self> {
        <BigRational as FromPrimitive>::from_f64(x)
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        // Reduced in machine integers first (no big-integer gcd); i128 holds -i64::MIN.
        let (mut n, mut d) = (i128::from(num), i128::from(den));
        if d == 0 {
            return BigRational::new(BigInt::from(num), BigInt::from(den)); // its own panic
        }
        let g = num_integer::Integer::gcd(&n, &d);
        (n, d) = (n / g, d / g);
        if d < 0 {
            (n, d) = (-n, -d);
        }
        BigRational::new_raw(BigInt::from(n), BigInt::from(d))
    }
    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
    fn is_finite_value(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f64_lift_is_exact() {
        let r = <BigRational as Scalar>::from_f64(0.5).unwrap();
        assert_eq!(r, BigRational::from_ratio(1, 2));
        assert!(<BigRational as Scalar>::from_f64(f64::NAN).is_none());
    }
}
