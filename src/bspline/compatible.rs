//! Compatible B-spline curves: one degree and one knot vector for several curves, so that
//! their control points can be combined point by point (ruled, Coons and Gordon surfaces in
//! B-spline form; Piegl & Tiller §10.3, octave-nurbs' `nrbruled` and `nrbcoons`).

use super::curve::BSplineCurve;
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The curves, unchanged in shape, over one degree and one knot vector: each raised to the
/// highest degree `p = max p_i` ([`BSplineCurve::elevate`]), then given the knots it lacks
/// ([`BSplineCurve::insert_knots`]) so that every distinct knot `x` occurs
/// `max_i m_i(x)` times in each (`m_i(x)`: its multiplicity in curve `i` after elevation).
/// Exact in rationals.
///
/// # Errors
/// [`Error::InvalidArgument`] for no curve, curves of different dimensions or domains, or a
/// knot vector that is not clamped, its first and last knots exactly degree + 1 times each
/// (degree elevation and the shared end knots need it).
///
/// ```
/// use cagd::bspline::{make_compatible, BSplineCurve};
/// use nalgebra::DMatrix;
/// let line = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], DMatrix::from_row_slice(1, 2, &[0.0, 1.0]))?;
/// let quad = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
///     DMatrix::from_row_slice(1, 4, &[0.0, 1.0, 2.0, 1.0]))?;
/// let c = make_compatible(&[line.clone(), quad])?;
/// assert_eq!(c[0].degree(), 2);
/// assert_eq!(c[0].knots().as_slice(), c[1].knots().as_slice());
/// assert!((c[0].try_eval(0.3)? - line.try_eval(0.3)?).norm() < 1e-15);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn make_compatible<T: Scalar>(curves: &[BSplineCurve<T>]) -> Result<Vec<BSplineCurve<T>>> {
    let what = "compatible B-spline curves";
    let first = curves.first().ok_or_else(|| Error::InvalidArgument {
        what,
        message: "no curve".into(),
    })?;
    for (k, c) in curves.iter().enumerate() {
        if c.dim() != first.dim() || c.domain() != first.domain() {
            return Err(Error::InvalidArgument {
                what,
                message: format!("curve {k} has another dimension or domain than curve 0"),
            });
        }
        super::knots::check_clamped(what, c.degree(), c.knots()).map_err(|e| match e {
            Error::InvalidArgument { what, message } => Error::InvalidArgument {
                what,
                message: format!("curve {k}: {message}"),
            },
            other => other,
        })?;
    }
    let p = curves.iter().map(BSplineCurve::degree).max().unwrap_or(0);
    let raised: Vec<BSplineCurve<T>> = curves
        .iter()
        .map(|c| c.elevate(p - c.degree()))
        .collect::<Result<_>>()?;
    let merged = merged_knots(raised.iter().map(|c| c.knots().as_slice()));
    raised
        .iter()
        .map(|c| c.insert_knots(&missing_knots(c.knots().as_slice(), &merged)))
        .collect()
}

/// Every distinct knot of the vectors with its highest multiplicity, in increasing order.
pub(crate) fn merged_knots<'k, T: Scalar + 'k>(
    vectors: impl IntoIterator<Item = &'k [T]>,
) -> Vec<(T, usize)> {
    let mut merged: Vec<(T, usize)> = Vec::new();
    for v in vectors {
        let mut k = 0;
        while k < v.len() {
            let x = &v[k];
            let m = v[k..].iter().take_while(|y| *y == x).count();
            match merged.iter_mut().find(|(y, _)| y == x) {
                Some(entry) => entry.1 = entry.1.max(m),
                None => merged.push((x.clone(), m)),
            }
            k += m;
        }
    }
    merged.sort_by(|a, b| a.0.partial_cmp(&b.0).expect("finite knots"));
    merged
}

/// The knots `knots` lacks to reach the multiplicities of `merged`, in increasing order.
pub(crate) fn missing_knots<T: Scalar>(knots: &[T], merged: &[(T, usize)]) -> Vec<T> {
    let mut out = Vec::new();
    for (x, m) in merged {
        let have = knots.iter().filter(|y| *y == x).count();
        out.extend(std::iter::repeat_n(x.clone(), m.saturating_sub(have)));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::from_ratio(n, d)
    }

    #[test]
    fn compatible_curves_keep_their_shape_exactly() {
        let a = BSplineCurve::new(
            1,
            vec![q(0, 1), q(0, 1), q(1, 3), q(1, 1), q(1, 1)],
            DMatrix::from_fn(2, 3, |r, c| q((r * 3 + c) as i64, 1)),
        )
        .unwrap();
        let b = BSplineCurve::new(
            3,
            vec![
                q(0, 1),
                q(0, 1),
                q(0, 1),
                q(0, 1),
                q(1, 2),
                q(1, 1),
                q(1, 1),
                q(1, 1),
                q(1, 1),
            ],
            DMatrix::from_fn(2, 5, |r, c| q((c * c) as i64 - r as i64, 2)),
        )
        .unwrap();
        let c = make_compatible(&[a.clone(), b.clone()]).unwrap();
        assert_eq!(c[0].knots(), c[1].knots());
        // 0 and 1 four times, 1/3 three times (a's knot raised twice), 1/2 once.
        assert_eq!(c[0].knots().multiplicity(&q(1, 3)), 3);
        assert_eq!(c[0].knots().multiplicity(&q(1, 2)), 1);
        for k in 0..=12 {
            let t = q(k, 12);
            assert_eq!(
                c[0].try_eval(t.clone()).unwrap(),
                a.try_eval(t.clone()).unwrap()
            );
            assert_eq!(c[1].try_eval(t.clone()).unwrap(), b.try_eval(t).unwrap());
        }
    }

    #[test]
    fn different_domains_are_refused() {
        let a = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], DMatrix::zeros(1, 2)).unwrap();
        let b = BSplineCurve::new(1, vec![0.0, 0.0, 2.0, 2.0], DMatrix::zeros(1, 2)).unwrap();
        assert!(make_compatible(&[a, b]).is_err());
    }
}
