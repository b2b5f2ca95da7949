//! Exact numbers in and out: decimals read as the rationals they write (`0.2` is 1/5), and
//! exact results written as doubles without letting one overflow to `Inf` unnoticed.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Num;

use crate::scalar::Scalar;

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
/// use cagd::exact::to_finite_f64;
/// use cagd::Scalar;
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
            return Err(crate::Error::Overflow { what, index, value });
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
/// use cagd::exact::rational_from_decimal;
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
            (
                &text[..pos],
                e.parse::<i64>().map_err(|_| too_large(u128::MAX))?,
            )
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
                matches!(
                    rational_from_decimal(bad),
                    Err(Error::InvalidArgument { .. })
                ),
                "{bad}"
            );
        }
        // Exponents whose powers of ten would take minutes are refused before any work,
        // also where the digits after the point push the scale past i32.
        for huge in [
            "1e999999999",
            "1e-999999999",
            "1e99999999999999999999999",
            "0.5e-2147483648",
        ] {
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
}
