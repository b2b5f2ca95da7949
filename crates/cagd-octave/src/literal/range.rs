//! Octave's colon ranges `base:increment:limit`, element for element.
//!
//! Octave (liboctave `Range.cc`, version 7) does not step `x += increment`. It first counts the
//! elements with a *tolerant* floor (Hagerty's FL5 with tolerance 3ε) of
//! `(limit − base + increment) / increment`, corrects the count by one if the element it would
//! stop on lies within 3ε (relative) of the limit, and then computes element `i` as
//! `base + i·increment`, except the last one, which is `base + (n−1)·increment` clamped to the
//! limit (so `0:0.1:0.3` ends in exactly `0.3`, not `0.30000000000000004`) and rounded when
//! every element is an integer. [`octave_range`] reproduces that to the bit; the test file
//! `crates/cagd-octave/tests/it/literal.rs` holds values printed by Octave itself.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Why a range cannot be built.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum RangeError {
    /// More than the allowed number of elements (the count, saturated).
    TooLarge(u128),
}

/// Octave's tolerant floor (`xtfloor`, Hagerty's FL5 function).
fn tolerant_floor(x: f64, ct: f64) -> f64 {
    let q = if x < 0.0 { 1.0 - ct } else { 1.0 };
    let rmax = q / (2.0 - ct);
    let mut t1 = 1.0 + x.floor();
    t1 = (ct / q) * t1.abs();
    t1 = t1.min(rmax);
    t1 = t1.max(ct);
    t1 = (x + t1).floor();
    if x <= 0.0 || (t1 - x) < rmax {
        t1
    } else {
        t1 - 1.0
    }
}

/// Octave's tolerant equality (`xteq`).
fn tolerant_eq(u: f64, v: f64, ct: f64) -> bool {
    (u - v).abs() < u.abs().max(v.abs()) * ct
}

/// The elements of `base:increment:limit` exactly as Octave 7 computes them, for finite
/// arguments.
///
/// At most `max` elements are produced; a longer range is an error before anything is
/// allocated.
pub(crate) fn octave_range(
    base: f64,
    increment: f64,
    limit: f64,
    max: usize,
) -> Result<Vec<f64>, RangeError> {
    if increment == 0.0 || (limit < base && increment > 0.0) || (limit > base && increment < 0.0) {
        return Ok(Vec::new());
    }
    if (limit <= base && base + increment < limit) || (limit >= base && base + increment > limit) {
        return Ok(vec![base]);
    }
    let ct = 3.0 * f64::EPSILON;
    let tmp = tolerant_floor((limit - base + increment) / increment, ct);
    if !tmp.is_finite() || tmp > (max as f64) + 2.0 {
        return Err(RangeError::TooLarge(if tmp.is_finite() {
            tmp as u128
        } else {
            u128::MAX
        }));
    }
    let mut n = if tmp > 0.0 { tmp as i64 } else { 0 };
    if !tolerant_eq(base + (n - 1) as f64 * increment, limit, ct) {
        if tolerant_eq(base + (n - 2) as f64 * increment, limit, ct) {
            n -= 1;
        } else if tolerant_eq(base + n as f64 * increment, limit, ct) {
            n += 1;
        }
    }
    let n = n.max(0) as usize;
    if n > max {
        return Err(RangeError::TooLarge(n as u128));
    }
    if n == 0 {
        return Ok(Vec::new());
    }
    let mut out: Vec<f64> = Vec::new();
    // `max` may be a limit raised past the machine's memory: reserve, never abort.
    out.try_reserve_exact(n)
        .map_err(|_| RangeError::TooLarge(n as u128))?;
    out.extend((0..n).map(|i| base + i as f64 * increment));
    if n > 1 {
        let mut last = base + (n - 1) as f64 * increment;
        if (increment > 0.0 && last >= limit) || (increment < 0.0 && last <= limit) {
            last = limit;
        }
        let is_int = |x: f64| x.abs() < 9.2e18 && x.round() == x;
        if is_int(base) && is_int(increment) {
            last = last.round();
        }
        out[n - 1] = last;
    }
    Ok(out)
}

/// The exact range `base, base + increment, …` up to `limit` (no rounding anywhere):
/// `floor((limit − base)/increment) + 1` elements.
pub(crate) fn exact_range(
    base: &BigRational,
    increment: &BigRational,
    limit: &BigRational,
    max: usize,
) -> Result<Vec<BigRational>, RangeError> {
    if increment.is_zero()
        || (limit < base && increment.is_positive())
        || (limit > base && increment.is_negative())
    {
        return Ok(Vec::new());
    }
    let steps = ((limit - base) / increment).floor().to_integer();
    let count = steps + BigInt::one();
    let Some(n) = count.to_usize().filter(|&n| n <= max) else {
        return Err(RangeError::TooLarge(count.to_u128().unwrap_or(u128::MAX)));
    };
    let mut out = Vec::new();
    out.try_reserve_exact(n)
        .map_err(|_| RangeError::TooLarge(n as u128))?;
    let mut x = base.clone();
    for _ in 0..n {
        out.push(x.clone());
        x += increment;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn last_element_is_clamped_to_the_limit() {
        let r = octave_range(0.0, 0.1, 0.3, 100).unwrap();
        assert_eq!(r, vec![0.0, 0.1, 0.2, 0.3]);
        // Plain stepping would give 3*0.1 = 0.30000000000000004.
        assert_ne!(3.0 * 0.1, 0.3);
    }

    #[test]
    fn empty_and_single() {
        assert!(octave_range(1.0, 1.0, 0.0, 10).unwrap().is_empty());
        assert!(octave_range(0.0, 0.0, 1.0, 10).unwrap().is_empty());
        assert_eq!(octave_range(0.0, 5.0, 1.0, 10).unwrap(), vec![0.0]);
        assert!(octave_range(0.0, 1.0, 1e12, 1000).is_err());
    }
}
