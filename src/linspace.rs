//! `linspace` exactly as GNU Octave 7 computes it.
//!
//! The thesis samples every curve and patch at `linspace(0,1,N)`. To reproduce its numbers to
//! the last bit we must produce the very same doubles. Octave 7 (liboctave `linspace`) does not
//! compute `a + i*(b-a)/(n-1)` for every `i`: it sets both end points exactly, fills the vector
//! symmetrically from both ends (`a + i*δ` from the left, `b - i*δ` from the right, with
//! `δ = (b-a)/(n-1)`), and sets the middle element of an odd-length vector to `(a+b)/2` (or to
//! exactly `0` when `a == -b`). `linspace(a, b, 1)` is `[b]`, and `n < 1` gives an empty vector.
//! The test `tests/it/octave_reference.rs` checks this against Octave's own output for n = 1…200.

use crate::scalar::Scalar;

/// `n` points from `a` to `b`, bit for bit as Octave 7's `linspace(a, b, n)`.
///
/// ```
/// let t = cagd::linspace(0.0, 1.0, 5);
/// assert_eq!(t, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
/// assert_eq!(cagd::linspace(0.0, 1.0, 1), vec![1.0]);
/// assert!(cagd::linspace(0.0, 1.0, 0).is_empty());
/// ```
///
/// Like Octave, any ends are taken: NaN or ±∞ ends, or ends whose difference overflows
/// (`−10³⁰⁸, 10³⁰⁸`), give NaNs where Octave gives them; [`try_linspace`] refuses them.
///
/// # Panics
/// When `n` numbers cannot be allocated (`1 << 40`, say: a panic naming the size, never an
/// abort); [`try_linspace`] refuses such an `n` instead. The front ends check `n` against
/// their `max_samples` before they call it.
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    match fill(a, b, n) {
        Ok(v) => v,
        Err(e) => panic!("{e}"),
    }
}

/// [`linspace`] for ends and counts from anywhere: the same numbers, or an error.
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite end;
/// [`Error::Overflow`](crate::Error::Overflow) when `b − a` overflows (and the samples would
/// hold NaNs); [`Error::TooLarge`](crate::Error::TooLarge) for an `n` whose numbers cannot be
/// allocated (`usize::MAX`, say).
///
/// ```
/// assert_eq!(cagd::linspace::try_linspace(0.0, 1.0, 3)?, vec![0.0, 0.5, 1.0]);
/// assert!(cagd::linspace::try_linspace(0.0, 1.0, usize::MAX).is_err());
/// assert!(cagd::linspace::try_linspace(f64::NAN, 1.0, 5).is_err());
/// assert!(cagd::linspace::try_linspace(-1e308, 1e308, 5).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn try_linspace(a: f64, b: f64, n: usize) -> crate::Result<Vec<f64>> {
    crate::error::check_finite("linspace ends", [&a, &b])?;
    if n > 2 && !(b - a).is_finite() {
        return Err(crate::Error::Overflow {
            what: "linspace step (b − a)/(n − 1)",
            index: 0,
            value: b - a,
        });
    }
    let out = fill(a, b, n)?;
    crate::error::check_overflow("linspace samples", out.iter())?;
    Ok(out)
}

/// The samples of [`linspace`], Octave's arithmetic (NaNs where its step overflows).
fn fill(a: f64, b: f64, n: usize) -> crate::Result<Vec<f64>> {
    let mut out = crate::grid::try_filled("linspace samples", n, 0.0)?;
    match n {
        0 => return Ok(out),
        1 => {
            out[0] = b;
            return Ok(out);
        }
        _ => {}
    }
    if a == b {
        out.fill(b);
        return Ok(out);
    }
    out[0] = a;
    out[n - 1] = b;
    let mut delta = (b - a) / (n - 1) as f64;
    let delta_is_nan = delta.is_infinite();
    if delta_is_nan {
        delta = f64::NAN;
    }
    let half = n / 2;
    for i in 1..half {
        out[i] = a + i as f64 * delta;
        out[n - 1 - i] = b - i as f64 * delta;
    }
    if n % 2 == 1 {
        out[half] = if a == -b {
            0.0
        } else if !delta_is_nan {
            (a + b) / 2.0
        } else {
            a + half as f64 * delta
        };
    }
    Ok(out)
}

/// [`try_linspace`] in any scalar: Octave's doubles for `f64` (bit for bit), exact steps
/// `a + i (b − a)/(n − 1)` in rationals (the ends exactly `a` and `b`).
///
/// # Errors
/// As [`try_linspace`]: [`Error::TooLarge`](crate::Error::TooLarge) for a count that cannot
/// be allocated; [`Error::NonFinite`](crate::Error::NonFinite) for a non-finite end.
///
/// ```
/// use cagd::Scalar;
/// use num_rational::BigRational;
/// let third = |k| <BigRational as Scalar>::from_ratio(k, 3);
/// assert_eq!(cagd::linspace::linspace_in(&third(0), &third(3), 4)?, vec![third(0), third(1), third(2), third(3)]);
/// assert_eq!(cagd::linspace::linspace_in(&0.0, &1.0, 3)?, vec![0.0, 0.5, 1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn linspace_in<T: Scalar>(a: &T, b: &T, n: usize) -> crate::Result<Vec<T>> {
    for (index, x) in [a, b].into_iter().enumerate() {
        if !x.is_finite_value() {
            return Err(crate::Error::NonFinite {
                what: "linspace ends",
                index,
                value: x.to_f64(),
            });
        }
    }
    if !T::EXACT {
        return try_linspace(a.to_f64(), b.to_f64(), n)?
            .into_iter()
            .map(|x| {
                T::from_f64(x).ok_or(crate::Error::NonFinite {
                    what: "linspace samples",
                    index: 0,
                    value: x,
                })
            })
            .collect();
    }
    let mut out = crate::grid::try_filled("linspace samples", n, b.clone())?;
    if n > 1 {
        // a + (b − a)·i/(n − 1), the fraction i/(n − 1) reduced in machine integers: on [0, 1]
        // (the usual case) no big-number arithmetic but the fraction's own.
        let span = b.clone() - a.clone();
        let (from_zero, unit) = (a.is_zero(), span == T::one());
        let last = i64::try_from(n - 1).map_err(|_| crate::Error::TooLarge {
            what: "linspace samples",
            requested: n as u128,
            limit: i64::MAX as u128,
            which: crate::limits::Limit::Samples,
        })?;
        for (i, x) in (0..last).zip(out.iter_mut()) {
            let f = T::from_ratio(i, last);
            let f = if unit { f } else { span.clone() * f };
            *x = if from_zero { f } else { a.clone() + f };
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::linspace;

    /// Exact samples are `a + i (b − a)/(n − 1)` for any rational ends (start at zero or
    /// not, a span of one or not, decreasing), checked against that formula term by term.
    #[test]
    fn exact_samples_are_the_formula() {
        use crate::Scalar;
        use num_rational::BigRational;
        let q = |n, d| <BigRational as Scalar>::from_ratio(n, d);
        for (a, b) in [
            (q(0, 1), q(1, 1)),
            (q(-1, 3), q(2, 1)),
            (q(5, 7), q(-3, 4)),
            (q(1, 2), q(3, 2)),
            (q(0, 1), q(7, 3)),
        ] {
            for n in [2usize, 3, 8, 13] {
                let got = super::linspace_in(&a, &b, n).unwrap();
                for (i, x) in got.iter().enumerate() {
                    let want = a.clone() + (b.clone() - a.clone()) * q(i as i64, n as i64 - 1);
                    assert_eq!(*x, want, "a = {a}, b = {b}, n = {n}, i = {i}");
                }
            }
        }
        // Reduced like any other rational: 2/4 is 1/2, and a negative denominator is moved up.
        assert_eq!(q(2, 4), q(1, 2));
        assert_eq!(q(3, -6), q(-1, 2));
        assert_eq!(q(i64::MIN, -1).to_string(), "9223372036854775808");
    }

    #[test]
    fn ends_are_exact() {
        for n in 2..50 {
            let t = linspace(0.0, 1.0, n);
            assert_eq!(t[0], 0.0);
            assert_eq!(t[n - 1], 1.0);
            assert!(t.windows(2).all(|w| w[0] < w[1]));
        }
    }

    #[test]
    fn symmetric_about_the_middle() {
        // Filling from both ends makes linspace(-1,1,n) exactly antisymmetric.
        let t = linspace(-1.0, 1.0, 11);
        for i in 0..11 {
            assert_eq!(t[i], -t[10 - i]);
        }
        assert_eq!(t[5], 0.0);
    }
}
