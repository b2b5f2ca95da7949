//! How one number reads in a message or a step layout: the shortest decimal that reads back
//! to the same double, or a reduced fraction in exact arithmetic.

use cagd::Scalar;

/// Significant digits of a double in readable text (at most 15: every decimal of 15 digits
/// survives the round trip through a double, so no digit shown is round-off).
pub const TEXT_DIGITS: usize = 15;

/// The printed form of one number: shortest round-trip decimal for doubles (exponent form
/// below 1e-5 and from 1e15 on), reduced fraction in exact arithmetic.
///
/// ```
/// use num_rational::BigRational;
/// use cagd_ops::number_text;
/// assert_eq!(number_text(&0.1f64), "0.1");
/// assert_eq!(number_text(&3.0f64), "3");
/// assert_eq!(number_text(&1e-20f64), "1e-20");
/// assert_eq!(number_text(&BigRational::new(31.into(), 15.into())), "31/15");
/// assert_eq!(number_text(&BigRational::new(14.into(), 4.into())), "7/2");
/// ```
pub fn number_text<T: Scalar>(x: &T) -> String {
    if T::EXACT {
        return x.to_string();
    }
    double_text(x.to_f64())
}

/// [`number_text`] of a value rounded to `digits` significant digits first (1 ≤ `digits`
/// ≤ 17; doubles only, fractions are exact and print in full): what readable text prints.
///
/// ```
/// use cagd_ops::number_text_digits;
/// assert_eq!(number_text_digits(&(0.1f64 + 0.2), 15), "0.3");
/// assert_eq!(number_text_digits(&0.6000000000000001f64, 15), "0.6");
/// assert_eq!(number_text_digits(&(2.0f64 / 3.0), 4), "0.6667");
/// assert_eq!(number_text_digits(&-1e-300f64, 15), "-1e-300");
/// ```
pub fn number_text_digits<T: Scalar>(x: &T, digits: usize) -> String {
    if T::EXACT {
        return x.to_string();
    }
    let v = x.to_f64();
    if !v.is_finite() || v == 0.0 {
        return double_text(v);
    }
    let digits = digits.clamp(1, 17);
    let rounded: f64 = format!("{:.*e}", digits - 1, v).parse().unwrap_or(v);
    double_text(rounded)
}

/// The shortest round-trip decimal of a double, in exponent form below 1e-5 and from 1e15 on.
fn double_text(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-5..1e15).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}
