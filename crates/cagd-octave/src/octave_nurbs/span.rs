//! Knot spans as octave-nurbs finds them: `findspan.m`, and the search of its compiled
//! `bspeval` (which `nrbeval` calls).

use super::error::{NurbsError, Result};

/// `Ok` unless `u` lies outside `[U(1), U(end)]`, which octave-nurbs' compiled evaluators
/// refuse ("Value … is outside the knot span"); NaN passes, as there.
///
/// # Errors
/// [`NurbsError::OutsideKnots`].
pub fn check_in_knots(what: &'static str, u: f64, knots: &[f64]) -> Result<()> {
    let (Some(&min), Some(&max)) = (knots.first(), knots.last()) else {
        return Err(NurbsError::Index {
            what: "knot vector",
            index: 1,
            bound: 0,
        });
    };
    if u > max || u < min {
        return Err(NurbsError::OutsideKnots {
            what,
            value: u,
            min,
            max,
        });
    }
    Ok(())
}

/// The span of `u` as octave-nurbs' compiled `bspeval` finds it for `nc` control points: the
/// number of the knots `U_1, …, U_{nc−1}` (0-based) that are `≤ u`, counted from the start up
/// to the first larger one (a linear search there; here a binary search when `sorted`, which
/// gives the same count). So `s ≤ nc − 1` always: a parameter past the last domain knot
/// belongs to the last span, and at `u = U(end)` of a clamped knot vector `s = nc − 1`. NaN
/// gives `0`.
///
/// `knots` must hold at least `nc` entries (they do whenever `nk = nc + d + 1`).
pub fn eval_span(nc: usize, knots: &[f64], u: f64, sorted: bool) -> usize {
    let n = nc.saturating_sub(1);
    if sorted {
        return knots[1..=n].partition_point(|&k| k <= u);
    }
    let mut s = 0;
    while s < n && knots[s + 1] <= u {
        s += 1;
    }
    s
}

/// Whether the knots never decrease.
pub fn is_sorted(knots: &[f64]) -> bool {
    knots.windows(2).all(|w| w[0] <= w[1])
}

/// octave-nurbs' `findspan (n, p, u, U)` (its `.m` file, which `bspkntins`, `bspinterpcrv` and
/// `bspinterpsurf` call): for each `u(j)`, `n` when `u(j) = U(n+2)`, otherwise the last
/// (0-based) index `k` with `U(k) ≤ u(j)`. The degree `p` is not used and the number of
/// knots is not checked against `n`. Returns the spans in the order of `u` (the caller keeps
/// `u`'s size).
///
/// # Errors
/// As octave-nurbs: [`NurbsError::Refused`] ("Some value is outside the knot span") when the
/// largest or smallest non-NaN `u` lies outside `[U(1), U(end)]`; [`NurbsError::Index`] when
/// `U(n+2)` does not exist or `n + 2` is not a positive integer (only asked for when `u` is
/// not empty); [`NurbsError::Refused`] for a NaN `u(j)` (no knot is `≤ NaN`).
///
/// ```
/// use cagd_octave::octave_nurbs::findspan;
/// let knots = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
/// assert_eq!(findspan(3.0, &[0.0, 0.25, 0.5, 1.0], &knots)?, vec![2.0, 2.0, 3.0, 3.0]);
/// // n is not checked against the knots (bspinterpcrv relies on it):
/// assert_eq!(findspan(4.0, &[0.5], &knots)?, vec![3.0]);
/// assert!(findspan(3.0, &[1.5], &knots).is_err());
/// # Ok::<(), cagd_octave::octave_nurbs::NurbsError>(())
/// ```
pub fn findspan(n: f64, u: &[f64], knots: &[f64]) -> Result<Vec<f64>> {
    let max = u.iter().copied().filter(|x| !x.is_nan()).reduce(f64::max);
    let min = u.iter().copied().filter(|x| !x.is_nan()).reduce(f64::min);
    // `U(end)` is read even for an empty `u`.
    let (Some(&first), Some(&last)) = (knots.first(), knots.last()) else {
        return Err(NurbsError::Index {
            what: "U",
            index: 0,
            bound: 0,
        });
    };
    {
        if max.is_some_and(|m| m > last) || min.is_some_and(|m| m < first) {
            return Err(NurbsError::refused(
                "u",
                "a value is outside the knots (octave-nurbs: \"Some value is outside the knot span\")",
            ));
        }
    }
    let mut out = Vec::with_capacity(u.len());
    for &x in u {
        let end = knot_at(knots, n + 2.0)?;
        if x == end {
            out.push(n);
            continue;
        }
        match knots.iter().rposition(|&k| x >= k) {
            Some(k) => out.push(k as f64),
            None => {
                return Err(NurbsError::refused(
                    "u",
                    format!("no knot is ≤ {x} (octave-nurbs fails on a NaN parameter)"),
                ))
            }
        }
    }
    Ok(out)
}

/// `U(i)` with Octave's 1-based indexing and its index errors.
fn knot_at(knots: &[f64], i: f64) -> Result<f64> {
    if i.fract() != 0.0 || i < 1.0 || i.is_nan() {
        return Err(NurbsError::refused(
            "n",
            format!("U(n+2) = U({i}): octave-nurbs indexes the knots with n + 2, which must be an integer from 1"),
        ));
    }
    knots.get(i as usize - 1).copied().ok_or(NurbsError::Index {
        what: "U (at n + 2)",
        index: i as i64,
        bound: knots.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eval_span_counts_knots_up_to_u() {
        // nrbmak([0 1 3 4 5; 0 2 2 0 1], [0 0 0 .4 .4 .4 1 1]): nc = 5; octave-nurbs gives NaN
        // from 0.4 on, the span 4 = [0.4, 0.4] being empty.
        let k = [0.0, 0.0, 0.0, 0.4, 0.4, 0.4, 1.0, 1.0];
        for sorted in [true, false] {
            assert_eq!(eval_span(5, &k, 0.2, sorted), 2);
            assert_eq!(eval_span(5, &k, 0.4, sorted), 4);
            assert_eq!(eval_span(5, &k, 0.7, sorted), 4);
            assert_eq!(eval_span(5, &k, 1.0, sorted), 4);
            assert_eq!(eval_span(5, &k, f64::NAN, sorted), 0);
        }
    }

    #[test]
    fn findspan_as_octave_nurbs() {
        // Values of octave-nurbs 1.4.3 (probe of 2026-11-25).
        let k = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
        assert_eq!(findspan(5.0, &[0.5], &k).unwrap(), vec![3.0]);
        assert_eq!(findspan(5.0, &[1.0], &k).unwrap(), vec![5.0]);
        assert_eq!(findspan(-1.0, &[0.5], &k).unwrap(), vec![3.0]);
        assert!(findspan(-2.0, &[0.5], &k).is_err());
        assert!(findspan(2.5, &[0.5], &k).is_err());
        assert!(findspan(3.0, &[f64::NAN, 0.5], &k).is_err());
        assert!(findspan(3.0, &[f64::INFINITY], &k).is_err());
        assert_eq!(findspan(3.0, &[], &k).unwrap(), Vec::<f64>::new());
        assert_eq!(findspan(9.0, &[], &k).unwrap(), Vec::<f64>::new());
    }
}
