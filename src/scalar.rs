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
    /// The exact value of a finite double; `None` for NaN and ±∞.
    fn from_f64(x: f64) -> Option<Self>;
    /// The value `num / den` (rounded to nearest for `f64`). `den` must not be zero.
    fn from_ratio(num: i64, den: i64) -> Self;
    /// The nearest double.
    fn to_f64(&self) -> f64;
    /// Whether the value is a finite number (always true for rationals).
    fn is_finite_value(&self) -> bool;
    /// The size of the number in bits, numerator and denominator together, for the work
    /// estimates of exact arithmetic ([`crate::cost`]); `0` for `f64`, whose operations cost
    /// the same whatever the value.
    ///
    /// ```
    /// use cagd::Scalar;
    /// use num_rational::BigRational;
    /// assert_eq!(0.75f64.size_in_bits(), 0);
    /// assert_eq!(<BigRational as Scalar>::from_ratio(3, 4).size_in_bits(), 2 + 3);
    /// ```
    fn size_in_bits(&self) -> u128 {
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

impl Scalar for BigRational {
    fn from_f64(x: f64) -> Option<Self> {
        <BigRational as FromPrimitive>::from_f64(x)
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        BigRational::new(BigInt::from(num), BigInt::from(den))
    }
    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
    fn is_finite_value(&self) -> bool {
        true
    }
    fn size_in_bits(&self) -> u128 {
        u128::from(self.numer().bits() + self.denom().bits())
    }
}

/// The doubles nearest to `values`, as long as every one is finite: the conversion of an exact
/// result to `f64` (an Octave file, a picture, a mesh) that refuses a value whose exact value
/// is finite but whose double is not (above `f64::MAX` ≈ 1.8·10³⁰⁸ in magnitude), instead of
/// writing `Inf`.
///
/// `values` are counted from 0 in the order given (column-major for matrices and grids taken
/// by `iter()`); `what` names the result.
///
/// # Errors
/// [`Error::Overflow`](crate::Error::Overflow) naming `what` and the index of the first value
/// whose double overflows (`value` is that double, ±∞).
///
/// ```
/// use cagd::scalar::{to_finite_f64, Scalar};
/// use cagd::Error;
/// use num_rational::BigRational;
/// let big = <BigRational as Scalar>::from_f64(1e308).unwrap();
/// let ok = [<BigRational as Scalar>::from_ratio(1, 4), big.clone()];
/// assert_eq!(to_finite_f64("result", &ok)?, vec![0.25, 1e308]);
/// // 5 · 10³⁰⁸ is an exact rational, but no double holds it.
/// let too_big = [big.clone(), big * <BigRational as Scalar>::from_ratio(5, 1)];
/// let err = to_finite_f64("result", &too_big).unwrap_err();
/// assert!(matches!(err, Error::Overflow { what: "result", index: 1, value } if value == f64::INFINITY));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn to_finite_f64<'a, T: Scalar>(
    what: &'static str,
    values: impl IntoIterator<Item = &'a T>,
) -> crate::Result<Vec<f64>> {
    let values = values.into_iter();
    let mut out = Vec::new();
    out.try_reserve(values.size_hint().0)
        .map_err(|_| crate::Error::TooLarge {
            what,
            requested: values.size_hint().0 as u128,
            limit: (isize::MAX as usize / std::mem::size_of::<f64>()) as u128,
            which: crate::limits::Limit::Elements,
        })?;
    for (index, x) in values.enumerate() {
        let value = x.to_f64();
        if !value.is_finite() {
            return Err(crate::Error::Overflow {
                what,
                index,
                value,
            });
        }
        out.push(value);
    }
    Ok(out)
}

/// Parses an exact decimal such as `"0.2"` or `"-3.25e-1"` into a rational (so that `0.2` means
/// 1/5, not the nearest double).
///
/// The work grows with the exponent (`1e-1000000` is a fraction with a million-digit
/// denominator), so an exponent beyond [`Limits::DEFAULT`](crate::limits::Limits::DEFAULT)`.max_expression_bytes`
/// (a decimal exponent `e` stands for `|e|` written digits) is refused before anything is
/// computed.
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) if the text is not a plain decimal
/// number (digits with at most one point, an optional sign and an optional exponent);
/// [`Error::TooLarge`](crate::Error::TooLarge) (limit `ExpressionBytes`) for an exponent beyond
/// the limit.
///
/// ```
/// use cagd::scalar::rational_from_decimal;
/// use num_rational::BigRational;
/// assert_eq!(rational_from_decimal("-3.25e-1")?, BigRational::new((-13).into(), 40.into()));
/// assert!(matches!(rational_from_decimal("1e999999999"), Err(cagd::Error::TooLarge { .. })));
/// assert!(matches!(rational_from_decimal("0x10"), Err(cagd::Error::InvalidArgument { .. })));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn rational_from_decimal(text: &str) -> crate::Result<BigRational> {
    use crate::error::Error;
    let text = text.trim();
    let not_decimal = || {
        let shown: String = text.chars().take(40).collect();
        let more = if text.chars().count() > 40 { "…" } else { "" };
        Error::InvalidArgument {
            what: "decimal number",
            message: format!(
                "expected a plain decimal number such as 0.2 or -3.25e-1, got {shown:?}{more}"
            ),
        }
    };
    let limit = crate::limits::Limits::DEFAULT.max_expression_bytes;
    let too_large = |requested: u128| Error::TooLarge {
        what: "decimal exponent",
        requested,
        limit: limit as u128,
        which: crate::limits::Limit::ExpressionBytes,
    };
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(pos) => {
            let e = &text[pos + 1..];
            let digits = e.strip_prefix(['+', '-']).unwrap_or(e);
            if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
                return Err(not_decimal());
            }
            // All digits: a parse failure is an exponent beyond i64.
            (&text[..pos], e.parse::<i64>().map_err(|_| too_large(u128::MAX))?)
        }
        None => (text, 0),
    };
    let (negative, digits) = match mantissa.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = match digits.find('.') {
        Some(pos) => (&digits[..pos], &digits[pos + 1..]),
        None => (digits, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return Err(not_decimal());
    }
    if !int_part
        .bytes()
        .chain(frac_part.bytes())
        .all(|b| b.is_ascii_digit())
    {
        return Err(not_decimal());
    }
    let scale = i128::from(exponent) - frac_part.len() as i128;
    if scale.unsigned_abs() > limit as u128 {
        return Err(too_large(scale.unsigned_abs()));
    }
    let all_digits = format!("{int_part}{frac_part}");
    let mantissa = BigInt::from_str_radix(&all_digits, 10).map_err(|_| not_decimal())?;
    // One power of ten and one gcd (BigRational::new), not a gcd per factor of ten.
    let power = num_traits::pow(BigInt::from(10), scale.unsigned_abs() as usize);
    let value = if scale >= 0 {
        BigRational::from_integer(mantissa * power)
    } else {
        BigRational::new(mantissa, power)
    };
    Ok(if negative { -value } else { value })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;

    #[test]
    fn decimal_is_exact() {
        assert_eq!(
            rational_from_decimal("0.2"),
            Ok(BigRational::from_ratio(1, 5))
        );
        assert_eq!(
            rational_from_decimal("-3.25e-1"),
            Ok(BigRational::from_ratio(-13, 40))
        );
        assert_eq!(
            rational_from_decimal("12e2"),
            Ok(BigRational::from_ratio(1200, 1))
        );
        for bad in ["abc", ".", "1e", "1e+", "--1", "1.2.3", "1e1.5", ""] {
            assert!(
                matches!(rational_from_decimal(bad), Err(Error::InvalidArgument { .. })),
                "{bad}"
            );
        }
        // Exponents whose powers of ten would take minutes are refused before any work,
        // also where the digits after the point push the scale past i32.
        for huge in ["1e999999999", "1e-999999999", "1e99999999999999999999999", "0.5e-2147483648"] {
            assert!(
                matches!(rational_from_decimal(huge), Err(Error::TooLarge { .. })),
                "{huge}"
            );
        }
        assert_eq!(
            rational_from_decimal("1e-300").unwrap(),
            BigRational::new(1.into(), num_traits::pow(BigInt::from(10), 300))
        );
    }

    #[test]
    fn f64_lift_is_exact() {
        let r = <BigRational as Scalar>::from_f64(0.5).unwrap();
        assert_eq!(r, BigRational::from_ratio(1, 2));
        assert!(<BigRational as Scalar>::from_f64(f64::NAN).is_none());
    }
}
