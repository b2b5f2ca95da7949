//! The bilinearly blended Coons patch of four B-spline boundaries as one B-spline surface.

use nalgebra::{DMatrix, DVector};

use super::bilinear::CoonsPatch;
use crate::bspline::{make_compatible, BSplineCurve, BSplineSurface};
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The Coons patch `x = r_c + r_d − r_cd` (thesis Izrek 4.2, eqs. (4.1)–(4.3)) of the
/// B-spline curves `c1 = x(·,0)`, `c2 = x(·,1)`, `d1 = x(0,·)`, `d2 = x(1,·)` with the corners
/// `corners = [P1, P2, P3, P4]`, as one tensor-product B-spline surface on `[0, 1]²` — the
/// boolean sum of three B-spline surfaces:
///
/// - `r_c = (1 − v) c1(u) + v c2(u)`: `c1`, `c2` made compatible ([`make_compatible`]), the
///   net `[c1 | c2]` of degree `(p, 1)` over knots `(U, [0 0 1 1])`;
/// - `r_d = (1 − u) d1(v) + u d2(v)`: likewise, degree `(1, q)` over `([0 0 1 1], V)`;
/// - `r_cd`: the bilinear patch of the corners, degree `(1, 1)`;
///
/// all three raised to the degrees `(max(p, 1), max(q, 1))` and refined to the union of their
/// knot vectors (each knot with its highest multiplicity), then
/// `P_{i,j} = P^c_{i,j} + P^d_{i,j} − P^{cd}_{i,j}`. This is octave-nurbs' `nrbcoons` (which
/// applies it to homogeneous coefficients). Each curve is first reparametrised affinely onto
/// `[0, 1]` (its knots `(k − a)/(b − a)`; a curve on `[0, 1]` keeps its knots exactly).
///
/// The surface interpolates the four curves when they meet at the corners and the corners
/// are their end points (`P1 = c1(0) = d1(0)`, …); nothing is checked here (the caller has:
/// [`CoonsPatch::to_bspline`] takes the checked corners of a [`CoonsPatch`]).
///
/// # Errors
/// [`Error::InvalidArgument`] for a knot vector that is not clamped (its end knots exactly
/// degree + 1 times), or whose distinct knots become one double on `[0, 1]`;
/// [`Error::ShapeMismatch`] for curves or corners of different dimensions;
/// [`Error::Overflow`] for a control point of the sum whose double overflows; as
/// [`make_compatible`] (degree elevation, knot insertion) otherwise.
pub fn coons_bspline_net<T: Scalar>(
    c1: &BSplineCurve<T>,
    c2: &BSplineCurve<T>,
    d1: &BSplineCurve<T>,
    d2: &BSplineCurve<T>,
    corners: &[DVector<T>; 4],
) -> Result<BSplineSurface<T>> {
    let dim = c1.dim();
    let dims = [c2.dim(), d1.dim(), d2.dim()]
        .into_iter()
        .chain(corners.iter().map(|p| p.len()));
    if dims.into_iter().any(|d| d != dim) {
        return Err(Error::ShapeMismatch {
            what: "Coons patch in B-spline form",
            expected: format!("curves and corners of dimension {dim}"),
            found: "another dimension".into(),
        });
    }
    let cs = make_compatible(&[on_unit_interval("c1", c1)?, on_unit_interval("c2", c2)?])?;
    let ds = make_compatible(&[on_unit_interval("d1", d1)?, on_unit_interval("d2", d2)?])?;
    let linear = vec![T::zero(), T::zero(), T::one(), T::one()];
    let (p, q) = (cs[0].degree(), ds[0].degree());
    let rc = BSplineSurface::new(
        p,
        1,
        cs[0].knots().as_slice().to_vec(),
        linear.clone(),
        (0..dim)
            .map(|k| {
                DMatrix::from_fn(cs[0].control().ncols(), 2, |i, j| {
                    cs[j].control()[(k, i)].clone()
                })
            })
            .collect(),
    )?;
    let rd = BSplineSurface::new(
        1,
        q,
        linear.clone(),
        ds[0].knots().as_slice().to_vec(),
        (0..dim)
            .map(|k| {
                DMatrix::from_fn(2, ds[0].control().ncols(), |i, j| {
                    ds[i].control()[(k, j)].clone()
                })
            })
            .collect(),
    )?;
    let rcd = BSplineSurface::new(
        1,
        1,
        linear.clone(),
        linear,
        (0..dim)
            .map(|k| DMatrix::from_fn(2, 2, |i, j| corners[i + 2 * j][k].clone()))
            .collect(),
    )?;
    let (du, dv) = (p.max(1), q.max(1));
    let parts: Vec<BSplineSurface<T>> = [rc, rd, rcd]
        .iter()
        .map(|s| s.elevate(du - s.degrees().0, dv - s.degrees().1))
        .collect::<Result<_>>()?;
    let ku = crate::bspline::compatible::merged_knots(parts.iter().map(|s| s.knots().0.as_slice()));
    let kv = crate::bspline::compatible::merged_knots(parts.iter().map(|s| s.knots().1.as_slice()));
    let parts: Vec<BSplineSurface<T>> = parts
        .iter()
        .map(|s| {
            s.insert_knots(
                &crate::bspline::compatible::missing_knots(s.knots().0.as_slice(), &ku),
                &crate::bspline::compatible::missing_knots(s.knots().1.as_slice(), &kv),
            )
        })
        .collect::<Result<_>>()?;
    let coords = (0..dim)
        .map(|k| {
            let (a, b, c) = (
                &parts[0].coordinates()[k],
                &parts[1].coordinates()[k],
                &parts[2].coordinates()[k],
            );
            DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| {
                a[(i, j)].clone() + b[(i, j)].clone() - c[(i, j)].clone()
            })
        })
        .collect::<Vec<DMatrix<T>>>();
    crate::error::check_overflow(
        "Coons patch in B-spline form control points",
        coords.iter().flat_map(|m| m.iter()),
    )?;
    BSplineSurface::new(
        du,
        dv,
        parts[0].knots().0.as_slice().to_vec(),
        parts[0].knots().1.as_slice().to_vec(),
        coords,
    )
}

/// The curve `name` with its knots mapped affinely onto `[0, 1]` (unchanged when its domain is
/// `[0, 1]`). In doubles the map rounds: two distinct knots that become one double (an interior
/// knot of a domain like `[−1.5·10³⁰⁸, 3]` becomes 1) would change the curve, and are refused.
fn on_unit_interval<T: Scalar>(name: &str, c: &BSplineCurve<T>) -> Result<BSplineCurve<T>> {
    let (a, b) = c.domain();
    if a == T::zero() && b == T::one() {
        return Ok(c.clone());
    }
    let given = c.knots().as_slice();
    let knots: Vec<T> = given
        .iter()
        .map(|k| (k.clone() - a.clone()) / (b.clone() - a.clone()))
        .collect();
    if let Some(i) = (1..given.len()).find(|&i| given[i - 1] < given[i] && knots[i - 1] >= knots[i])
    {
        return Err(Error::InvalidArgument {
            what: "Coons patch in B-spline form",
            message: format!(
                "boundary {name}: the knots {:?} and {:?} become the same double {:?} when its domain [{:?}, {:?}] is mapped onto [0, 1]",
                given[i - 1].to_f64(),
                given[i].to_f64(),
                knots[i].to_f64(),
                a.to_f64(),
                b.to_f64()
            ),
        });
    }
    BSplineCurve::new(c.degree(), knots, c.control().clone())
}

impl<T: Scalar> CoonsPatch<BSplineCurve<T>, T> {
    /// The Coons patch of four B-spline curves, exactly, as one B-spline surface on
    /// `[0, 1]²` ([`coons_bspline_net`] with the patch's corners `P1..P4`), as octave-nurbs'
    /// `nrbcoons` builds it.
    ///
    /// # Errors
    /// As [`coons_bspline_net`]: a boundary whose knot vector is not clamped, whose knots
    /// cannot be mapped onto `[0, 1]` in doubles, or a control point that overflows.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use cagd::coons::CoonsPatch;
    /// use cagd::Surface;
    /// use nalgebra::DMatrix;
    /// let k2 = vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    /// let line = |a: [f64; 2], b: [f64; 2]| {
    ///     BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], DMatrix::from_column_slice(2, 2, &[a[0], a[1], b[0], b[1]]))
    /// };
    /// let c1 = BSplineCurve::new(2, k2, DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 0.3, -0.2, 0.7, 0.2, 1.0, 0.0]))?;
    /// let coons = CoonsPatch::new(c1, line([0.0, 1.0], [1.0, 1.0])?, line([0.0, 0.0], [0.0, 1.0])?, line([1.0, 0.0], [1.0, 1.0])?)?;
    /// let s = coons.to_bspline()?;
    /// assert_eq!(s.degrees(), (2, 1));
    /// assert!((s.try_eval(0.3, 0.6)? - coons.eval(0.3, 0.6)).amax() < 1e-15);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn to_bspline(&self) -> Result<BSplineSurface<T>> {
        let (c1, c2, d1, d2) = self.boundary().curves();
        coons_bspline_net(c1, c2, d1, d2, self.boundary().corners())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::param::Surface;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::from_ratio(n, d)
    }

    fn curve(p: usize, interior: &[(i64, i64)], points: &[[i64; 3]]) -> BSplineCurve<BigRational> {
        let mut knots = vec![q(0, 1); p + 1];
        knots.extend(interior.iter().map(|&(n, d)| q(n, d)));
        knots.extend(std::iter::repeat_n(q(1, 1), p + 1));
        let control = DMatrix::from_fn(3, points.len(), |r, c| q(points[c][r], 1));
        BSplineCurve::new(p, knots, control).unwrap()
    }

    #[test]
    fn the_boolean_sum_is_the_coons_patch_exactly() {
        // Corners (0,0,0), (4,0,1), (0,3,2), (4,3,0); curves of degrees 2, 3, 1, 2.
        let c1 = curve(2, &[(1, 3)], &[[0, 0, 0], [1, -1, 2], [3, 1, 1], [4, 0, 1]]);
        let c2 = curve(3, &[], &[[0, 3, 2], [1, 4, 0], [3, 2, 1], [4, 3, 0]]);
        let d1 = curve(1, &[(1, 2)], &[[0, 0, 0], [-1, 1, 1], [0, 3, 2]]);
        let d2 = curve(
            2,
            &[(1, 4), (3, 4)],
            &[[4, 0, 1], [5, 1, 0], [3, 2, 2], [4, 2, 1], [4, 3, 0]],
        );
        let coons = CoonsPatch::new(c1, c2, d1, d2).unwrap();
        let s = coons.to_bspline().unwrap();
        assert_eq!(s.degrees(), (3, 2));
        for (i, j) in [(0, 0), (1, 5), (2, 2), (5, 1), (6, 6), (3, 4)] {
            let (u, v) = (q(i, 6), q(j, 6));
            assert_eq!(s.try_eval(u.clone(), v.clone()).unwrap(), coons.eval(u, v));
        }
    }
}
