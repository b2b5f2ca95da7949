//! The bilinearly blended Coons patch (thesis §4.1, Izrek 4.2; notes (5)).

use nalgebra::DVector;

use super::{CoonsBoundary, CoonsPoint, Tolerance};
use crate::cost::{blended, Cost};
use crate::error::Result;
use crate::param::{Curve, Surface};
use crate::scalar::Scalar;

/// The bilinearly blended Coons patch of four boundary curves (Izrek 4.2):
///
/// ```text
/// x(u,v) = r_c(u,v) + r_d(u,v) − r_cd(u,v),
///   r_c  = (1−v) c1(u) + v c2(u)                                   (4.1)
///   r_d  = (1−u) d1(v) + u d2(v)                                   (4.2)
///   r_cd = (1−u)(1−v) P1 + u(1−v) P2 + (1−u)v P3 + uv P4            (4.3)
/// ```
///
/// with `c1 = x(·,0)`, `c2 = x(·,1)`, `d1 = x(0,·)`, `d2 = x(1,·)` over `[0, 1]` and the corners
/// `P1..P4 = x(0,0), x(1,0), x(0,1), x(1,1)` (see the [module docs](super)). It interpolates the
/// four curves: `x(u,0) = c1(u)` because `r_d(u,0) = r_cd(u,0)` when the corners agree. A curve
/// on another domain `[a, b]` is reparametrised onto `[0, 1]` first (so the patch's domain is
/// `[0, 1]²` whatever the curves'), e.g. four B-spline boundaries of which one runs over
/// `[0, 4]`:
///
/// ```
/// use cagd::bspline::BSplineCurve;
/// use cagd::coons::CoonsPatch;
/// use cagd::{Curve, Surface};
/// use nalgebra::DMatrix;
/// let pts = |p: &[[f64; 3]]| DMatrix::from_fn(3, p.len(), |r, c| p[c][r]);
/// // c1: the uniform cubic on [0, 4] through (0,0,0) … (1,0,0); the others on [0, 1].
/// let c1 = BSplineCurve::uniform_cubic(&pts(&[[0.0, 0.0, 0.0], [0.5, 0.0, 1.0], [1.0, 0.0, 0.0]]), true)?;
/// assert_eq!(c1.domain(), (0.0, 4.0));
/// let c2 = BSplineCurve::clamped(1, pts(&[[0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]))?;
/// let d1 = BSplineCurve::clamped(1, pts(&[[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]]))?;
/// let d2 = BSplineCurve::clamped(1, pts(&[[1.0, 0.0, 0.0], [1.0, 1.0, 0.0]]))?;
/// let patch = CoonsPatch::new(c1.clone(), c2, d1, d2)?;
/// assert_eq!(patch.eval(0.5, 0.0), c1.eval(2.0)); // x(u, 0) = c1(4u)
/// # Ok::<(), cagd::Error>(())
/// ```
///
/// The boundary curves may be of any kind implementing [`Curve`] (Bézier, sampled polyline,
/// closure, …; mix kinds with `Box<dyn Curve<T>>`). The sums are formed in the order of the
/// thesis functions `krpaCoons` / `vrednostCoons`, so in `f64` the patch agrees with the
/// (fixed) Octave code to the last bit on the same curve values.
///
/// Checked against the thesis: Primer 4.3's data are compatible (`c2(0) = d1(1) = (0,1,0)`,
/// `c1(1) = d2(0) = (1,0,0)`, `c1(0) = d1(0) = 0`, `c2(1) = d2(1) = (1,1,1)`, which are the
/// `P1..P4` of appendix C) and its printed `r_c`, `r_d`, `r_cd` and `x(0.2, 0.5)` are exactly
/// right (example below). Where the thesis is wrong: the proof of Izrek 4.2 ends with
/// "`x(v,1) = d2(v)`", meaning `x(1,v) = d2(v)`; appendix C's data script for `krpaCoons`
/// assigns `P3` twice (`P3 = [1;1;1]` is meant as `P4`, which is never set) and relies on an
/// undefined `N`; `krpaCoons` itself uses `N` without defining it, and `vrednostCoons` returns
/// nothing (it only displays `T`). The fixed Octave references (`octave_ref/fixed/`) list each
/// fix; on the same curve values this type reproduces them bit for bit.
///
/// # Example: thesis Primer 4.3, exactly
/// ```
/// use cagd::coons::{CoonsPatch, Tolerance};
/// use cagd::FnCurve;
/// use nalgebra::{dvector, DVector};
/// use num_rational::BigRational as Q;
/// type F = fn(Q) -> DVector<Q>;
/// let q = |n: i64, d: i64| Q::new(n.into(), d.into());
/// let c1: F = |u| dvector![u.clone(), Q::from_integer(0.into()), u.clone() - u.clone() * u];
/// let c2: F = |u| dvector![u.clone(), Q::from_integer(1.into()), u];
/// let d1: F = |v| dvector![Q::from_integer(0.into()), v.clone() * v.clone(), v.clone() - v.clone() * v];
/// let d2: F = |v| dvector![Q::from_integer(1.into()), v.clone(), v];
/// let patch = CoonsPatch::with_tolerance(
///     FnCurve::new(3, c1), FnCurve::new(3, c2), FnCurve::new(3, d1), FnCurve::new(3, d2),
///     Tolerance::Exact,
/// ).unwrap();
/// let p = patch.eval_parts(q(1, 5), q(1, 2));
/// assert_eq!(p.rc, dvector![q(1, 5), q(1, 2), q(9, 50)]);   // (0.2, 0.5, 0.18)
/// assert_eq!(p.rd, dvector![q(1, 5), q(3, 10), q(3, 10)]);  // (0.2, 0.3, 0.3)
/// assert_eq!(p.rcd, dvector![q(1, 5), q(1, 2), q(1, 10)]);  // (0.2, 0.5, 0.1)
/// assert_eq!(p.x, dvector![q(1, 5), q(3, 10), q(19, 50)]);  // (0.2, 0.3, 0.38)
/// ```
#[derive(Debug, Clone)]
pub struct CoonsPatch<C, T: Scalar = f64> {
    boundary: CoonsBoundary<C, T>,
}

impl<T: Scalar, C: Curve<T>> CoonsPatch<C, T> {
    /// The Coons patch of `c1 = x(·,0)`, `c2 = x(·,1)`, `d1 = x(0,·)`, `d2 = x(1,·)`, corners
    /// checked with the default tolerance (relative `1e-10`, see [`Tolerance`]) and taken from
    /// `c1`, `c2`.
    ///
    /// # Errors
    /// See [`CoonsBoundary::new`]: curves of different dimensions, a domain that cannot be
    /// reparametrised onto `[0, 1]` ([`crate::Error::UnusableDomain`]), non-finite corners,
    /// and [`crate::Error::CornerMismatch`] naming every corner where the curves disagree.
    pub fn new(c1: C, c2: C, d1: C, d2: C) -> Result<Self> {
        Self::with_tolerance(c1, c2, d1, d2, Tolerance::default())
    }

    /// [`CoonsPatch::new`] with a chosen corner tolerance.
    ///
    /// # Errors
    /// As [`CoonsPatch::new`].
    pub fn with_tolerance(c1: C, c2: C, d1: C, d2: C, tolerance: Tolerance) -> Result<Self> {
        Ok(CoonsPatch {
            boundary: CoonsBoundary::new(c1, c2, d1, d2, tolerance)?,
        })
    }

    /// The Coons patch with the corner points `P1..P4 = x(0,0), x(1,0), x(0,1), x(1,1)` given,
    /// as in the thesis function `krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)`.
    ///
    /// # Errors
    /// As [`CoonsBoundary::with_corners`].
    pub fn with_corners(
        c1: C,
        c2: C,
        d1: C,
        d2: C,
        corners: [DVector<T>; 4],
        tolerance: Tolerance,
    ) -> Result<Self> {
        Ok(CoonsPatch {
            boundary: CoonsBoundary::with_corners(c1, c2, d1, d2, corners, tolerance)?,
        })
    }

    /// The patch of an already checked boundary.
    pub fn from_boundary(boundary: CoonsBoundary<C, T>) -> Self {
        CoonsPatch { boundary }
    }

    /// The patch on the grid `us × vs` written into `out`, row by row:
    /// `out[(a·nv + b)·d + c]` is coordinate `c` of `x(us[a], vs[b])` (`(nu, nv, d)` row-major,
    /// see [`crate::grid`]).
    ///
    /// Each boundary curve is evaluated once per grid line, through
    /// [`Curve::eval_many_into`] (for Bézier curves the basis-row path, no allocation per
    /// point). The formula is regrouped per row `u = us[a]`:
    ///
    /// ```text
    /// x(u, v) = (1−v) e1(u) + v e2(u) + (1−u) d1(v) + u d2(v),
    ///   e1(u) = c1(u) − (1−u) P1 − u P2,   e2(u) = c2(u) − (1−u) P3 − u P4,
    /// ```
    ///
    /// (the same polynomial as `r_c + r_d − r_cd`), so each point costs `4d` multiply-adds and
    /// no allocation; large grids are split by rows over all cores. The `f64` values agree with
    /// [`Surface::eval`] to a few ULPs of the coordinates' magnitude (not bit for bit, the
    /// order of the terms being different) and exactly for rationals. For the thesis's term
    /// order use [`Surface::eval_grid`].
    ///
    /// # Errors
    /// [`crate::Error::ShapeMismatch`] unless `out.len() == us.len() · vs.len() · d` (or if a
    /// curve returns points of another dimension).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use cagd::coons::CoonsPatch;
    /// let line = |p: [f64; 3], q: [f64; 3]| BezierCurve::from_points(&[p, q]).unwrap();
    /// let (p1, p2, p3, p4) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 1.0]);
    /// let patch = CoonsPatch::new(line(p1, p2), line(p3, p4), line(p1, p3), line(p2, p4))?;
    /// let mut out = vec![0.0; 2 * 1 * 3];
    /// patch.eval_grid_into(&[0.5, 1.0], &[0.5], &mut out)?;
    /// assert_eq!(out, [0.5, 0.5, 0.25, 1.0, 0.5, 0.5]); // the bilinear patch (u, v, uv)
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        let d = self.boundary.dim();
        let len = crate::grid::grid_len("Coons patch grid", &[us.len(), vs.len(), d])?;
        crate::grid::check_len("Coons patch grid buffer", len, out)?;
        crate::error::check_finite("Coons patch grid parameters", us.iter().chain(vs))?;
        if len == 0 {
            return Ok(());
        }
        let [c1, c2, d1, d2] = self.boundary.unit_curves();
        let [p1, p2, p3, p4] = self.boundary.corners();
        // e[a] = [e1(us[a]), e2(us[a])], 2d values per row; g[b] = [1 − v, v].
        let mut e = vec![T::zero(); 2 * us.len() * d];
        let mut samples = vec![T::zero(); us.len() * d];
        for (curve, (first, second), offset) in [(&c1, (p1, p2), 0), (&c2, (p3, p4), d)] {
            curve.eval_many_into(us, &mut samples)?;
            for ((u, x), ea) in us
                .iter()
                .zip(samples.chunks_exact(d))
                .zip(e.chunks_exact_mut(2 * d))
            {
                let s = T::one() - u.clone();
                for k in 0..d {
                    ea[offset + k] =
                        x[k].clone() - s.clone() * first[k].clone() - u.clone() * second[k].clone();
                }
            }
        }
        // dd = [d1(vs[0]), …, d1(vs[nv−1]), d2(vs[0]), …]: one grid row of each.
        let row_len = vs.len() * d;
        let mut dd = vec![T::zero(); 2 * row_len];
        let (dd1, dd2) = dd.split_at_mut(row_len);
        d1.eval_many_into(vs, dd1)?;
        d2.eval_many_into(vs, dd2)?;
        let g = crate::grid::rows_of(vs, 2, |v, w| {
            w[0] = T::one() - v.clone();
            w[1] = v.clone();
        });
        let work = out.len().saturating_mul(4);
        crate::grid::for_each_row(
            "Coons patch grid",
            out,
            vs.len() * d,
            work,
            || (),
            |_, a, row| {
                let u = &us[a];
                let f = [T::one() - u.clone(), u.clone()];
                let ea = &e[a * 2 * d..(a + 1) * 2 * d];
                crate::grid::blend_row(&g, 2, ea, &f, &dd, row);
            },
        )
    }

    /// The point `x(u, v)` with its parts `r_c`, `r_d`, `r_cd` (thesis `vrednostCoons`).
    pub fn eval_parts(&self, u: T, v: T) -> CoonsPoint<T> {
        let f = (T::one() - u.clone(), u.clone());
        let g = (T::one() - v.clone(), v.clone());
        self.boundary.blend(&u, &v, &f, &g)
    }
}

impl<T: Scalar, C> CoonsPatch<C, T> {
    /// The checked boundary curves and corners.
    pub fn boundary(&self) -> &CoonsBoundary<C, T> {
        &self.boundary
    }

    /// The corner points `[P1, P2, P3, P4] = [x(0,0), x(1,0), x(0,1), x(1,1)]`.
    pub fn corners(&self) -> &[DVector<T>; 4] {
        self.boundary.corners()
    }
}

impl<T: Scalar, C: Curve<T>> Surface<T> for CoonsPatch<C, T> {
    fn dim(&self) -> usize {
        self.boundary.dim()
    }

    /// `[0, 1]²` (the boundary curves reparametrised onto `[0, 1]`).
    fn domain(&self) -> ((T, T), (T, T)) {
        ((T::zero(), T::one()), (T::zero(), T::one()))
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        self.eval_parts(u, v).x
    }

    /// [`eval`](Surface::eval) on `[0, 1]²`, each boundary curve through its own `try_eval`
    /// (its work bounded, its point checked: a curve returning a point of another dimension
    /// is an [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) naming it), the point
    /// checked for overflow.
    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let f = (T::one() - u.clone(), u.clone());
        let g = (T::one() - v.clone(), v.clone());
        self.boundary.try_blend(&u, &v, &f, &g)
    }

    /// The patch on the grid `us × vs`, shape `(us.len(), vs.len(), d)` (the layout of the
    /// thesis's `P = tenzor(R)` in `krpaCoons`). Each boundary curve is evaluated once per grid
    /// line, not once per point.
    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        CoonsPatch::eval_grid_into(self, us, vs, out)
    }

    fn eval_grid(&self, us: &[T], vs: &[T]) -> crate::grid::PointGrid<T> {
        let f: Vec<_> = us
            .iter()
            .map(|u| (T::one() - u.clone(), u.clone()))
            .collect();
        let g: Vec<_> = vs
            .iter()
            .map(|v| (T::one() - v.clone(), v.clone()))
            .collect();
        self.boundary.blend_grid(us, vs, &f, &g)
    }
}

impl<T: Scalar> CoonsPatch<crate::bezier::BezierCurve<T>, T> {
    /// The Coons patch of four Bézier curves, exactly, as one tensor-product Bézier patch of
    /// degree `(max(1, deg c1, deg c2), max(1, deg d1, deg d2))`: the Gordon surface with nodes
    /// `{0, 1}` in both directions (its Lagrange basis is `1 − t, t`), see
    /// [`crate::gordon::GordonSurface::to_bezier`]. The corners used are the patch's `P1..P4`.
    /// A curve on another interval `[a, b]` enters reparametrised onto `[0, 1]`, which keeps
    /// its control points.
    ///
    /// # Errors
    /// [`crate::Error::NonFinite`] if a control point overflows in `f64`.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use cagd::coons::CoonsPatch;
    /// use cagd::Surface;
    /// use nalgebra::dmatrix;
    /// let c1 = BezierCurve::new(dmatrix![0.0, 0.5, 1.0; 0.0, -0.5, 0.0]).unwrap();
    /// let c2 = BezierCurve::new(dmatrix![0.0, 1.0; 1.0, 1.0]).unwrap();
    /// let d1 = BezierCurve::new(dmatrix![0.0, 0.0; 0.0, 1.0]).unwrap();
    /// let d2 = BezierCurve::new(dmatrix![1.0, 1.0; 0.0, 1.0]).unwrap();
    /// let coons = CoonsPatch::new(c1, c2, d1, d2).unwrap();
    /// let patch = coons.to_bezier().unwrap();
    /// assert_eq!(patch.degree(), (2, 1));
    /// assert!((patch.eval(0.3, 0.6) - coons.eval(0.3, 0.6)).amax() < 1e-15);
    /// ```
    pub fn to_bezier(&self) -> Result<crate::bezier::BezierPatch<T>> {
        let (c1, c2, d1, d2) = self.boundary.curves();
        let p = self.boundary.corners();
        let nodes = [T::zero(), T::one()];
        crate::gordon::gordon_bezier_net(
            &nodes,
            &nodes,
            &[d1.clone(), d2.clone()],
            &[c1.clone(), c2.clone()],
            &[
                vec![p[0].clone(), p[2].clone()],
                vec![p[1].clone(), p[3].clone()],
            ],
        )
    }
}

/// The cost of one point of a bilinearly blended Coons patch in `d` coordinates,
/// `x = r_c + r_d − r_cd`: the four boundary curves at their parameters (`curves`, the cost of
/// each: `c1`, `c2` at `u`, `d1`, `d2` at `v`) and about 16 operations per coordinate for the
/// blend, on numbers as large as the curves' values grown by the bits of `u` and `v` (and 2 for
/// `1 − u`, `1 − v`; [`blended`](crate::cost::blended)).
///
/// ```
/// use cagd::coons::coons_point_cost;
/// use cagd::cost::Cost;
/// let line = Cost::new(3, 10);
/// assert_eq!(coons_point_cost([line; 4], 3, 4, 5), Cost::new(12 + 48, 10 + 11));
/// ```
pub fn coons_point_cost(
    curves: impl IntoIterator<Item = Cost>,
    d: usize,
    u_bits: u128,
    v_bits: u128,
) -> Cost {
    blended(
        curves,
        16 * d as u128,
        u_bits.saturating_add(v_bits).saturating_add(2),
    )
}

#[cfg(test)]
mod cost_tests {
    use super::*;

    #[test]
    fn the_blend_adds_to_the_curves_and_grows_their_largest_value() {
        let curves = [
            Cost::new(10, 5),
            Cost::new(20, 50),
            Cost::new(1, 0),
            Cost::new(1, 0),
        ];
        assert_eq!(coons_point_cost(curves, 2, 0, 0), Cost::new(32 + 32, 52));
        assert_eq!(coons_point_cost(curves, 2, 7, 8).bits(), 50 + 17);
    }
}
