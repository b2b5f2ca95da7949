//! Degree elevation of a clamped B-spline curve (the CAD notes §1.2: "explicit formulas for …
//! raising the degree"), by blossoming.
//!
//! The curve of degree `p` is written with degree `q = p + r` over the knot vector in which
//! every distinct knot occurs `r` times more (so the smoothness `C^{p−k}` across a knot of
//! multiplicity `k` is kept: `q − (k + r) = p − k`), as octave-nurbs `nrbdegelev` and Piegl &
//! Tiller's algorithm A5.9 do. Each new control point is a value of the degree-`q` blossom
//! (polar form) of the curve at `q` consecutive new knots:
//!
//! ```text
//! P'_i = F(u'_{i+1}, …, u'_{i+q}),   i = 0, …, n' − 1,
//! ```
//!
//! with `F` the blossom of the polynomial piece on a non-empty span `[u'_k, u'_{k+1}]`,
//! `i ≤ k ≤ i + q`. The blossom of a piece is taken from its Bézier form: the piece's Bézier
//! points are blossom values `f(a, …, a, b, …, b)` of degree `p` (de Boor's algorithm with one
//! argument per level), raised to degree `q` by Bézier degree elevation, and `F` at any
//! arguments is de Casteljau's algorithm with one parameter per level. Everything is rational,
//! so the result is exact in `BigRational`.

use nalgebra::{DMatrix, DVector};

use super::curve::BSplineCurve;
use crate::bezier::BezierCurve;
use crate::cost::{polynomial_bits, Cost};
use crate::error::{Error, Result};
use crate::scalar::Scalar;

impl<T: Scalar> BSplineCurve<T> {
    /// The same curve with degree `q = p + r` (the CAD notes §1.2, "raising the degree"), as
    /// octave-nurbs `nrbdegelev`: every distinct knot occurs `r` times more (so the smoothness
    /// across each knot is kept), and the new control points are values of the curve's
    /// degree-`q` blossom at `q` consecutive new knots, `P'_i = F(u'_{i+1}, …, u'_{i+q})`,
    /// taken from the Bézier form of each piece raised to degree `q`. Exact in rationals.
    /// `r = 0` returns the curve itself.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless the knot vector is clamped (first and last knot
    /// exactly `p + 1` times: the domain is then the whole knot range); [`Error::TooLarge`] for a
    /// degree `p + r` above [`Limits::DEFAULT`](crate::limits::Limits::DEFAULT)`.max_degree`,
    /// or when the estimated work ([`elevate_cost`](Self::elevate_cost), weighed by the size
    /// of exact numbers) exceeds its `max_work` — before anything is computed;
    /// [`Error::Overflow`] for a control point whose double overflows.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// // A clamped quadratic of two spans, raised to a cubic: knots 0,0,0,0, ½,½, 1,1,1,1.
    /// let p = DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], p)?;
    /// let e = c.elevate(1)?;
    /// assert_eq!(e.degree(), 3);
    /// assert_eq!(e.knots().as_slice(), &[0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0]);
    /// let (a, b) = (c.try_eval(0.3)?, e.try_eval(0.3)?);
    /// assert!((a - b).norm() < 1e-14);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn elevate(&self, r: usize) -> Result<Self> {
        let p = self.degree();
        let knots = self.knots().as_slice();
        super::knots::check_clamped("B-spline degree elevation", p, self.knots())?;
        if r == 0 {
            return Ok(self.clone());
        }
        let q = p.saturating_add(r);
        let limits = crate::limits::Limits::DEFAULT;
        limits.check_degree("B-spline degree elevation", q)?;
        crate::checked::point_work::<T>(
            "B-spline degree elevation",
            self.elevate_cost(
                r,
                crate::cost::max_bits(self.control().iter()),
                crate::cost::max_bits(knots),
            ),
        )?;
        let d = self.dim();
        // The new knots: each distinct knot r times more.
        let mut new_knots: Vec<T> = Vec::with_capacity(knots.len() * (r + 1));
        for (k, u) in knots.iter().enumerate() {
            new_knots.push(u.clone());
            if k + 1 == knots.len() || knots[k + 1] != *u {
                new_knots.extend(std::iter::repeat_n(u.clone(), r));
            }
        }
        // The elevated Bézier form of every non-empty span, by its left end.
        let n = self.control().ncols();
        let mut pieces: Vec<(T, T, BezierCurve<T>)> = Vec::new();
        for k in p..n {
            let (a, b) = (knots[k].clone(), knots[k + 1].clone());
            if a == b {
                continue;
            }
            let columns: Vec<DVector<T>> = (0..=p)
                .map(|j| {
                    let args: Vec<T> = std::iter::repeat_n(a.clone(), p - j)
                        .chain(std::iter::repeat_n(b.clone(), j))
                        .collect();
                    self.blossom(k, &args)
                })
                .collect();
            let mut piece = BezierCurve::new_on_interval(
                DMatrix::from_columns(&columns),
                a.clone(),
                b.clone(),
            )?;
            for _ in 0..r {
                piece = piece.elevate();
            }
            pieces.push((a, b, piece));
        }
        let n_new = new_knots.len() - q - 1;
        let mut control = DMatrix::from_element(d, n_new, T::zero());
        for i in 0..n_new {
            let k = (i.max(q)..n_new.min(i + q + 1))
                .find(|&k| new_knots[k] < new_knots[k + 1])
                .ok_or_else(|| Error::InvalidArgument {
                    what: "B-spline degree elevation",
                    message: format!("no non-empty knot span for control point {i}"),
                })?;
            let (a, b, piece) = pieces
                .iter()
                .find(|(a, _, _)| *a == new_knots[k])
                .expect("every non-empty new span is an old one");
            let ts: Vec<T> = new_knots[i + 1..=i + q]
                .iter()
                .map(|x| (x.clone() - a.clone()) / (b.clone() - a.clone()))
                .collect();
            let point = polar_bezier(piece.control(), &ts);
            control.set_column(i, &point);
        }
        crate::error::check_overflow("elevated B-spline control points", control.iter())?;
        BSplineCurve::new(q, new_knots, control)
    }

    /// The cost of [`elevate`](Self::elevate) by `r`, on control points of `control_bits` and
    /// knots of `knot_bits` bits: for each of the `s ≤ n − p` spans the `p + 1` blossoms of its
    /// Bézier form (`p (p+1)/2` combinations each) and their elevation to degree `q = p + r`
    /// ([`bernstein::elevate_cost`](crate::bernstein::elevate_cost) per coordinate), then for
    /// each of the `n + s r` new control points a polar form of degree `q` (`q (q+1)/2`
    /// combinations); a combination of `d`-dimensional points is `3d + 3` operations. The
    /// numbers grow as a polynomial of degree `p + q` in ratios of two knots.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// let c = BSplineCurve::clamped(3, DMatrix::<f64>::zeros(2, 6))?;
    /// // 3 spans, 6 + 3 = 9 new control points of degree 4.
    /// assert_eq!(c.elevate_cost(1, 0, 0).ops(), 3 * (24 * 9 + 2 * 25) + 9 * 10 * 9);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn elevate_cost(&self, r: usize, control_bits: u128, knot_bits: u128) -> Cost {
        let (p, q) = (
            self.degree() as u128,
            self.degree().saturating_add(r) as u128,
        );
        let n = self.control().ncols() as u128;
        let spans = n.saturating_sub(p);
        let combination = 3 * self.dim() as u128 + 3;
        let per_span = ((p + 1) * p * (p + 1) / 2)
            .saturating_mul(combination)
            .saturating_add(
                crate::bernstein::elevate_cost(self.degree(), r, 0)
                    .ops()
                    .saturating_mul(self.dim() as u128),
            );
        let new_points = n.saturating_add(spans.saturating_mul(r as u128));
        let per_point = (q.saturating_mul(q.saturating_add(1)) / 2).saturating_mul(combination);
        Cost::new(
            spans
                .saturating_mul(per_span)
                .saturating_add(new_points.saturating_mul(per_point)),
            polynomial_bits(
                self.degree()
                    .saturating_add(self.degree())
                    .saturating_add(r),
                knot_bits.saturating_mul(2),
                control_bits,
            ),
        )
    }

    /// The blossom of the piece on span `k` (`u_k < u_{k+1}`) at `args` (`p` values): de
    /// Boor's algorithm with argument `args[l−1]` at level `l`,
    /// `d_i^l = (1 − α) d_{i−1}^{l−1} + α d_i^{l−1}`, `α = (x_l − u_i)/(u_{i+p+1−l} − u_i)`.
    fn blossom(&self, k: usize, args: &[T]) -> DVector<T> {
        let p = self.degree();
        let u = self.knots().as_slice();
        let mut pts: Vec<DVector<T>> = (0..=p)
            .map(|j| self.control().column(k - p + j).into_owned())
            .collect();
        for (l, x) in args.iter().enumerate().map(|(l, x)| (l + 1, x)) {
            for j in (l..=p).rev() {
                let i = k - p + j;
                let alpha = (x.clone() - u[i].clone()) / (u[i + p + 1 - l].clone() - u[i].clone());
                pts[j] = combine(&pts[j - 1], &pts[j], &alpha);
            }
        }
        pts[p].clone()
    }
}

/// `(1 − t) a + t b`, coordinate by coordinate.
fn combine<T: Scalar>(a: &DVector<T>, b: &DVector<T>, t: &T) -> DVector<T> {
    let s = T::one() - t.clone();
    DVector::from_fn(a.len(), |r, _| {
        s.clone() * a[r].clone() + t.clone() * b[r].clone()
    })
}

/// The polar form of a Bézier curve (control points as columns, over `[0, 1]`) at `ts`, one
/// parameter per de Casteljau level.
fn polar_bezier<T: Scalar>(control: &DMatrix<T>, ts: &[T]) -> DVector<T> {
    let mut level: Vec<DVector<T>> = control.column_iter().map(|c| c.into_owned()).collect();
    for t in ts {
        level = level.windows(2).map(|w| combine(&w[0], &w[1], t)).collect();
    }
    level[0].clone()
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::from_ratio(n, d)
    }

    #[test]
    fn elevation_keeps_the_curve_exactly() {
        let control = DMatrix::from_fn(2, 6, |r, c| {
            q((3 * c as i64 + 5 * r as i64) % 7, 1 + r as i64)
        });
        let knots = vec![
            q(0, 1),
            q(0, 1),
            q(0, 1),
            q(1, 4),
            q(1, 2),
            q(1, 2),
            q(1, 1),
            q(1, 1),
            q(1, 1),
        ];
        let c = BSplineCurve::new(2, knots, control).unwrap();
        for r in 1..4 {
            let e = c.elevate(r).unwrap();
            assert_eq!(e.degree(), 2 + r);
            assert_eq!(e.knots().multiplicity(&q(1, 2)), 2 + r);
            for k in 0..=20 {
                let t = q(k, 20);
                assert_eq!(c.try_eval(t.clone()).unwrap(), e.try_eval(t).unwrap());
            }
        }
    }

    #[test]
    fn unclamped_knots_are_refused() {
        let c = BSplineCurve::new(
            1,
            vec![0.0, 1.0, 2.0, 3.0],
            DMatrix::from_column_slice(1, 2, &[0.0, 1.0]),
        )
        .unwrap();
        assert!(matches!(c.elevate(1), Err(Error::InvalidArgument { .. })));
    }
}
