//! Degree elevation of a tensor-product Bézier patch: the curve elevation of thesis §2.3 (the
//! CAD notes §1.1) applied to every column and every row of the net.

use nalgebra::DMatrix;

use super::patch::BezierPatch;
use crate::bernstein::{elevate_cost, elevate_once};
use crate::cost::{max_bits, Cost};
use crate::error::{check_overflow, Result};
use crate::limits::Limits;
use crate::scalar::Scalar;

impl<T: Scalar> BezierPatch<T> {
    /// The same patch written with degree `(m + r, n + s)`.
    ///
    /// A patch is `x(u, v) = Σ_j c_j(u) B_j^n(v)` with the column curves `c_j` and
    /// `Σ_i r_i(v) B_i^m(u)` with the row curves `r_i` ([`control_curves`](Self::control_curves)),
    /// so raising the degree in `u` raises every column curve and raising it in `v` every row
    /// curve. One step in `u` and one in `v`
    /// ([`bernstein::elevate_once`](crate::bernstein::elevate_once) on each column or row):
    ///
    /// ```text
    /// b'_{i,j} = i/(m+1) · b_{i−1,j} + (1 − i/(m+1)) · b_{i,j},   i = 0, …, m + 1,
    /// b'_{i,j} = j/(n+1) · b_{i,j−1} + (1 − j/(n+1)) · b_{i,j},   j = 0, …, n + 1,
    /// ```
    ///
    /// (out-of-range terms dropped). The `r` steps in `u` are taken first, then the `s` steps
    /// in `v`; the two commute. After all of them, exactly in rationals,
    ///
    /// ```text
    /// b^{(r,s)}_{k,l} = Σ_i Σ_j  C(m,i) C(r,k−i) / C(m+r,k) · C(n,j) C(s,l−j) / C(n+s,l) · b_{i,j}.
    /// ```
    ///
    /// Every new control point is a convex combination of old ones; the corners stay.
    /// `(0, 0)` gives a copy.
    ///
    /// # Errors
    /// [`Error::TooLarge`](crate::Error::TooLarge) for a degree `m + r` or `n + s` above
    /// [`Limits::DEFAULT`]`.max_degree`, or when the work ([`elevate_cost`](Self::elevate_cost),
    /// weighed by the size of exact numbers) exceeds the default work limit.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // (u, v, uv)
    /// let e = p.elevate(1, 2)?;
    /// assert_eq!(e.degree(), (2, 3));
    /// assert_eq!(e.control_point(1, 0).unwrap().as_slice(), &[0.5, 0.0, 0.0]);
    /// assert_eq!(e.eval(0.5, 0.25), p.eval(0.5, 0.25));
    /// assert!(p.elevate(usize::MAX, 0).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn elevate(&self, r: usize, s: usize) -> Result<Self> {
        let what = "Bézier patch degree elevation";
        let (m, n) = self.degree();
        Limits::DEFAULT.check_degree(what, m.saturating_add(r))?;
        Limits::DEFAULT.check_degree(what, n.saturating_add(s))?;
        let bits = max_bits(self.coordinates().iter().flat_map(|x| x.iter()));
        crate::checked::point_work::<T>(what, self.elevate_cost(r, s, bits))?;
        let coords: Vec<DMatrix<T>> = self
            .coordinates()
            .iter()
            .map(|x| elevate_rows(&elevate_columns(x, r), s))
            .collect();
        check_overflow(
            "elevated Bézier patch control points",
            coords.iter().flat_map(|x| x.iter()),
        )?;
        Ok(BezierPatch::from_valid(coords))
    }

    /// The cost of [`elevate`](Self::elevate) by `(r, s)` on control points of `control_bits`
    /// bits: per coordinate, the `n + 1` columns raised by `r`
    /// ([`bernstein::elevate_cost`](crate::bernstein::elevate_cost)`(m, r, ·)` each), then
    /// the `m + r + 1` rows of the result by `s` (`elevate_cost(n, s, ·)` on the grown numbers).
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// use cagd::bernstein::elevate_cost;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // degree (1, 1), d = 3
    /// let u = elevate_cost(1, 1, 4).times(2);
    /// let v = elevate_cost(1, 2, u.bits()).times(3);
    /// assert_eq!(p.elevate_cost(1, 2, 4), u.and(v).times(3));
    /// ```
    pub fn elevate_cost(&self, r: usize, s: usize, control_bits: u128) -> Cost {
        let (m, n) = self.degree();
        let in_u = elevate_cost(m, r, control_bits).times(n as u128 + 1);
        let in_v = elevate_cost(n, s, in_u.bits()).times((m as u128).saturating_add(r as u128) + 1);
        in_u.and(in_v).times(self.dim() as u128)
    }
}

/// Every column of `x` raised `r` degrees.
fn elevate_columns<T: Scalar>(x: &DMatrix<T>, r: usize) -> DMatrix<T> {
    let columns: Vec<Vec<T>> = x
        .column_iter()
        .map(|c| raised(c.iter().cloned().collect(), r))
        .collect();
    let rows = columns.first().map_or(0, Vec::len);
    DMatrix::from_fn(rows, columns.len(), |i, j| columns[j][i].clone())
}

/// Every row of `x` raised `s` degrees.
fn elevate_rows<T: Scalar>(x: &DMatrix<T>, s: usize) -> DMatrix<T> {
    let rows: Vec<Vec<T>> = x
        .row_iter()
        .map(|r| raised(r.iter().cloned().collect(), s))
        .collect();
    let cols = rows.first().map_or(0, Vec::len);
    DMatrix::from_fn(rows.len(), cols, |i, j| rows[i][j].clone())
}

/// Bernstein coefficients raised `times` degrees, one step at a time.
fn raised<T: Scalar>(mut a: Vec<T>, times: usize) -> Vec<T> {
    for _ in 0..times {
        a = elevate_once(&a);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bernstein::binomial_scalar;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        <BigRational as Scalar>::from_ratio(n, d)
    }

    /// The closed form of the doc comment, term by term.
    fn closed_form(b: &DMatrix<BigRational>, r: usize, s: usize) -> DMatrix<BigRational> {
        let (m, n) = (b.nrows() - 1, b.ncols() - 1);
        let w = |deg: usize, by: usize, i: usize, k: usize| -> BigRational {
            if k < i || k - i > by {
                return q(0, 1);
            }
            binomial_scalar::<BigRational>(deg, i) * binomial_scalar::<BigRational>(by, k - i)
                / binomial_scalar::<BigRational>(deg + by, k)
        };
        DMatrix::from_fn(m + r + 1, n + s + 1, |k, l| {
            let mut sum = q(0, 1);
            for i in 0..=m {
                for j in 0..=n {
                    sum += w(m, r, i, k) * w(n, s, j, l) * b[(i, j)].clone();
                }
            }
            sum
        })
    }

    #[test]
    fn stepwise_elevation_is_the_closed_form() {
        let b = DMatrix::from_fn(3, 2, |i, j| q((i * 5 + j * 3) as i64 - 4, 1 + j as i64));
        let p = BezierPatch::new(vec![b.clone()]).unwrap();
        for (r, s) in [(0, 0), (1, 0), (0, 2), (2, 3), (4, 1)] {
            let e = p.elevate(r, s).unwrap();
            assert_eq!(e.coordinates()[0], closed_form(&b, r, s), "({r}, {s})");
        }
    }

    #[test]
    fn elevation_is_limited_by_degree_and_work() {
        let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
        assert!(matches!(
            p.elevate(0, usize::MAX),
            Err(crate::Error::TooLarge { .. })
        ));
        // Degree 999 in both directions: some 7.5·10⁹ operations, refused before any work.
        assert!(p.elevate_cost(998, 998, 0).ops() > 7_000_000_000);
        assert!(matches!(
            p.elevate(998, 998),
            Err(crate::Error::TooLarge {
                which: crate::limits::Limit::Work,
                ..
            })
        ));
    }
}
