//! B-spline curves (the CAD notes eq. (3), the lecture notes "B-spline křivky").

use nalgebra::{DMatrix, DVector};

use super::basis::{
    basis_all, basis_values, check_in_domain, curve_point_cost, extended_span, span_of,
};
use super::batch::curve_points_fast_into;
use super::grid::curve_points_into;
use super::knots::{check_knots, KnotVector};
use crate::bezier::BezierCurve;
use crate::error::{check_finite, Error, Result};
use crate::param::Curve;
use crate::scalar::Scalar;

/// A B-spline curve `C(u) = Σ_{i=0}^{n−1} P_i N_{i,p}(u)`, `u ∈ [u_p, u_n]`
/// (the CAD notes eq. (3); the lecture notes number the order `k = p + 1`).
///
/// **Layout:** the control points `P_0, …, P_{n−1}` are the columns of a `d × n` matrix (as
/// for [`BezierCurve`] and octave-nurbs `coefs`), the knots `u_0 ≤ … ≤ u_{n+p}` a
/// [`KnotVector`] of length `n + p + 1`.
///
/// **Evaluation** ([`try_eval`](Self::try_eval), [`eval`](Self::eval)) sums the `p + 1`
/// non-zero terms `N_{s−p+i,p}(u) P_{s−p+i}` of the span `s`, `i` ascending, exactly as
/// octave-nurbs `bspeval`; [`de_boor`](Self::de_boor) runs de Boor's algorithm (the same
/// point). The domain is `[u_p, u_n]` (the rule of [`crate::param`]): outside it `try_eval`
/// returns [`Error::ParameterOutOfRange`] (and [`Error::NonFinite`] for NaN or ±∞), while
/// `eval` continues the first or the last polynomial piece (a NaN or infinite parameter gives
/// a point of NaNs).
///
/// ```
/// use cagd::bspline::BSplineCurve;
/// use nalgebra::DMatrix;
/// // A clamped quadratic through (0,0), (1,2), (3,2), (4,0): interpolates its end points.
/// let p = DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
/// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], p)?;
/// assert_eq!(c.try_eval(0.0)?.as_slice(), &[0.0, 0.0]);
/// assert_eq!(c.try_eval(1.0)?.as_slice(), &[4.0, 0.0]);
/// assert_eq!(c.try_eval(0.5)?.as_slice(), &[2.0, 2.0]);
/// assert!(c.try_eval(1.5).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<T: Scalar = f64> {
    degree: usize,
    knots: KnotVector<T>,
    control: DMatrix<T>,
}

impl<T: Scalar> BSplineCurve<T> {
    /// The curve of degree `degree` with the given knots and control points (columns).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for control points with no coordinates; [`Error::NonFinite`];
    /// [`Error::DecreasingKnots`]; [`Error::TooFewControlPoints`] for fewer than `degree + 1`
    /// control points; [`Error::KnotCount`] unless there are `n + degree + 1` knots;
    /// [`Error::EmptyInterval`] if the domain `[u_p, u_n]` is a single point.
    pub fn new(degree: usize, knots: Vec<T>, control: DMatrix<T>) -> Result<Self> {
        let what = "B-spline curve";
        if control.nrows() == 0 {
            return Err(Error::ShapeMismatch {
                what,
                expected: "at least one coordinate row".into(),
                found: "0 rows".into(),
            });
        }
        check_finite("B-spline control points", control.iter())?;
        let knots = KnotVector::new(knots)?;
        check_knots(what, degree, control.ncols(), &knots)?;
        Ok(BSplineCurve {
            degree,
            knots,
            control,
        })
    }

    /// The curve with clamped uniform knots on `[0, 1]` ([`KnotVector::clamped_uniform`]): it
    /// starts at the first and ends at the last control point.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn clamped(degree: usize, control: DMatrix<T>) -> Result<Self> {
        let knots = KnotVector::<T>::clamped_uniform(degree, control.ncols())?;
        Self::new(degree, knots.as_slice().to_vec(), control)
    }

    /// The uniform cubic B-spline of the lecture notes ("Coons cubic", `x(u) = X_C M_C u` on each
    /// segment, see [`crate::conversion::bspline_matrix`]) over the points `x_0, …, x_n`
    /// (columns). With `replicate_ends` the end points are repeated as the notes do to "start"
    /// and "finish" the curve — the segments use `[x_0 x_0 x_0 x_1]`, `[x_0 x_0 x_1 x_2]`, …,
    /// `[x_{n−1} x_n x_n x_n]` — so the curve starts at `x_0` and ends at `x_n`. Segment `k`
    /// runs over `u ∈ [k, k + 1]` (knots [`KnotVector::uniform`]).
    ///
    /// # Errors
    /// [`Error::TooFewControlPoints`] for fewer than 4 points without replication (1 with);
    /// as [`new`](Self::new) otherwise.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// let x = DMatrix::from_column_slice(2, 3, &[0.0, 0.0, 6.0, 6.0, 12.0, 0.0]);
    /// let c = BSplineCurve::uniform_cubic(&x, true)?;
    /// let (a, b) = c.domain();
    /// assert_eq!((a, b), (0.0, 4.0));
    /// assert_eq!(c.try_eval(a)?.as_slice(), &[0.0, 0.0]);
    /// assert_eq!(c.try_eval(b)?.as_slice(), &[12.0, 0.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn uniform_cubic(points: &DMatrix<T>, replicate_ends: bool) -> Result<Self> {
        let control = if replicate_ends && points.ncols() > 0 {
            let n = points.ncols();
            let idx: Vec<usize> = [0, 0]
                .into_iter()
                .chain(0..n)
                .chain([n - 1, n - 1])
                .collect();
            DMatrix::from_fn(points.nrows(), idx.len(), |r, c| {
                points[(r, idx[c])].clone()
            })
        } else {
            points.clone()
        };
        let knots = KnotVector::<T>::uniform(3, control.ncols())?;
        Self::new(3, knots.as_slice().to_vec(), control)
    }

    /// The Bézier curve as a B-spline of one span: knots `a` (`n + 1` times), `b` (`n + 1`
    /// times) for a curve over `[a, b]`.
    pub fn from_bezier(curve: &BezierCurve<T>) -> Self {
        let n = curve.degree();
        let (a, b) = curve.interval();
        let mut knots = vec![a.clone(); n + 1];
        knots.extend(std::iter::repeat_n(b.clone(), n + 1));
        BSplineCurve {
            degree: n,
            // a < b with b − a and its reciprocal finite: the interval's own check.
            knots: KnotVector::from_valid(knots),
            control: curve.control().clone(),
        }
    }

    /// The degree `p`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The dimension `d` of the points.
    pub fn dim(&self) -> usize {
        self.control.nrows()
    }

    /// The control points, one per column (`d × n`).
    pub fn control(&self) -> &DMatrix<T> {
        &self.control
    }

    /// The knot vector.
    pub fn knots(&self) -> &KnotVector<T> {
        &self.knots
    }

    /// The domain `[u_p, u_n]`.
    pub fn domain(&self) -> (T, T) {
        self.knots.domain(self.degree)
    }

    /// The values `N_{0,p}(u), …, N_{n−1,p}(u)` of all basis functions.
    ///
    /// # Errors
    /// [`Error::ParameterOutOfRange`] outside the domain.
    pub fn basis(&self, u: &T) -> Result<Vec<T>> {
        basis_all(self.degree, self.control.ncols(), self.knots.as_slice(), u)
    }

    /// The point `C(u)` for `u` in the domain (see the type's documentation for the operation
    /// order): [`eval`](Self::eval)'s value, bit for bit.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for NaN or ±∞, [`Error::ParameterOutOfRange`] outside the domain,
    /// [`Error::TooLarge`] when one point's work ([`curve_point_cost`]) exceeds the default
    /// limit, [`Error::Overflow`] for a point whose double overflows.
    pub fn try_eval(&self, u: T) -> Result<DVector<T>> {
        let (p, knots) = (self.degree, self.knots.as_slice());
        let s = span_of(p, self.control.ncols(), knots, &u)?;
        self.check_point_work(u.bits())?;
        let n = basis_values(p, knots, s, &u);
        crate::checked::point(
            "B-spline curve point",
            self.dim(),
            combine(&self.control, s - p, &n),
        )
    }

    /// One point's work ([`curve_point_cost`]) at a parameter of `param_bits` bits against
    /// the default limit ([`crate::checked::point_work`]).
    fn check_point_work(&self, param_bits: u128) -> Result<()> {
        let cost = curve_point_cost(
            self.degree,
            self.dim(),
            param_bits,
            crate::cost::max_bits(self.knots.as_slice()),
            crate::cost::max_bits(self.control.iter()),
        );
        crate::checked::point_work::<T>("B-spline curve point", cost)
    }

    /// The point `C(u)` for any `u`: inside the domain [`try_eval`](Self::try_eval)'s value;
    /// below (above) it the polynomial of the first (last) non-empty span continued, by the
    /// same operations with that span; for NaN or ±∞ a point of NaNs.
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// // The clamped quadratic on (0,0), (1,2), (3,2), (4,0): on its last span [1/2, 1] the
    /// // basis is 2(1−u)², 2(1−u)(3u−1), (2u−1)²; at u = 3/2 that is 1/2, −7/2, 4, so (6, −6).
    /// let p = DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], p)?;
    /// assert_eq!(c.eval(1.0), c.try_eval(1.0)?);
    /// assert_eq!(c.eval(1.5).as_slice(), &[6.0, -6.0]);
    /// assert!(c.try_eval(1.5).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval(&self, u: T) -> DVector<T> {
        let (p, knots) = (self.degree, self.knots.as_slice());
        match extended_span(p, self.control.ncols(), knots, &u) {
            Some(s) => {
                let n = basis_values(p, knots, s, &u);
                combine(&self.control, s - p, &n)
            }
            None => DVector::from_element(self.dim(), u.clone() - u),
        }
    }

    /// The point `C(u)` by de Boor's algorithm: the `p + 1` control points of the span are
    /// blended pairwise `p` times, `d_i ← (1 − α_i) d_{i−1} + α_i d_i` with
    /// `α_i = (u − u_i)/(u_{i+p+1−r} − u_i)`.
    ///
    /// # Errors
    /// [`Error::ParameterOutOfRange`] outside the domain.
    pub fn de_boor(&self, u: T) -> Result<DVector<T>> {
        let (p, knots) = (self.degree, self.knots.as_slice());
        let s = span_of(p, self.control.ncols(), knots, &u)?;
        self.check_point_work(u.bits())?;
        let mut d: Vec<DVector<T>> = (0..=p)
            .map(|j| self.control.column(s - p + j).into_owned())
            .collect();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = s - p + j;
                let alpha = (u.clone() - knots[i].clone())
                    / (knots[i + p + 1 - r].clone() - knots[i].clone());
                let one_minus = T::one() - alpha.clone();
                d[j] = blend(&d[j - 1], one_minus, &d[j], alpha);
            }
        }
        crate::checked::point(
            "B-spline curve point (de Boor)",
            self.dim(),
            d.swap_remove(p),
        )
    }

    /// The points at the parameters `us`, one per column (`d × us.len()`), by
    /// [`try_eval_many_into`](Self::try_eval_many_into) (the values of
    /// [`try_eval`](Self::try_eval), bit for bit).
    ///
    /// # Errors
    /// [`Error::NonFinite`] or [`Error::ParameterOutOfRange`] for a parameter outside the
    /// domain.
    pub fn eval_many(&self, us: &[T]) -> Result<DMatrix<T>> {
        let len = crate::grid::grid_len("B-spline curve points", &[us.len(), self.dim()])?;
        let zeros = crate::grid::try_filled("B-spline curve points", len, T::zero())?;
        let mut out = DMatrix::from_vec(self.dim(), us.len(), zeros);
        self.try_eval_many_into(us, out.as_mut_slice())?;
        Ok(out)
    }

    /// The points at all parameters `us` written into `out`, one after the other:
    /// `out[k·d + c]` is coordinate `c` of `C(us[k])` (`us.len() × d` row-major, which is the
    /// storage of the `d × us.len()` matrix of [`eval_many`](Self::eval_many); see
    /// [`crate::grid`]). As [`eval`](Self::eval), outside the domain `[u_p, u_n]` the end
    /// pieces continue; a NaN or infinite parameter is refused.
    ///
    /// The fast batch: per parameter the knot span `s` (the previous parameter's span or the
    /// next one is tried first, so sorted parameters cost `O(1)`; otherwise a binary search),
    /// the `p + 1` non-zero basis values by the triangular scheme of [`basis_functions`](super::basis_functions) with
    /// its divisions by knot differences replaced by products with their reciprocals,
    /// computed once per span, then `Σ_{i=0}^{p} N_{s−p+i,p}(u) P_{s−p+i}`: `O(p² + p·d)`
    /// multiplications and additions and no division per point, the parameters of one span
    /// four at a time in vector registers. Nothing is allocated per point and long batches
    /// are split over all cores.
    ///
    /// Accuracy: `|C_batch(u) − C(u)| ≤ (4p + 1) ε · max_i |P_i|` on the domain (every
    /// quantity of the scheme is non-negative, so relative roundings add up; derivation, and
    /// the bound of the continued end pieces beyond the domain, in the module docs of the
    /// kernel), exact for rationals. For the operations of
    /// [`try_eval`](Self::try_eval) and octave-nurbs `bspeval`, bit for bit, use
    /// [`eval_many_exact_order_into`](Self::eval_many_exact_order_into).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · d`; [`Error::NonFinite`] for a
    /// NaN or infinite parameter; [`Error::TooLarge`] when one point's work exceeds the default
    /// limit; [`Error::Overflow`] for a point whose double overflows (the buffer is written all
    /// the same).
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// let p = DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], p)?;
    /// let mut out = [0.0; 6];
    /// c.eval_many_into(&[0.0, 0.5, 1.5], &mut out)?; // 1.5: the last piece continued
    /// assert_eq!(out, [0.0, 0.0, 2.0, 2.0, 6.0, -6.0]);
    /// assert!(c.eval_many_into(&[0.5], &mut out).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_many_into(&self, us: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("B-spline curve points", &[us.len(), d])?;
        crate::grid::check_len("B-spline curve point buffer", len, out)?;
        self.check_point_work(crate::cost::max_bits(us))?;
        let (p, knots) = (self.degree, self.knots.as_slice());
        // A NaN or infinite parameter gives a point of NaNs, which the scan of its block finds:
        // only then are the parameters looked at (one pass fewer over a large batch).
        curve_points_fast_into(p, knots, self.control.as_slice(), d, false, us, out).map_err(|e| {
            crate::error::check_finite_slice("B-spline curve parameters", us)
                .err()
                .unwrap_or(e)
        })
    }

    /// [`eval_many_into`](Self::eval_many_into) in the exact order of
    /// [`try_eval`](Self::try_eval): per parameter the span, the basis by the triangular
    /// scheme of [`basis_functions`](super::basis_functions) with its divisions, in the operation order of
    /// octave-nurbs `basisfun`, then the sum from zero, `i` ascending — the values of
    /// `try_eval` (and of `bspeval`) bit for bit, at about three times the cost of the fast
    /// batch for cubics. Outside the domain the end pieces continue, as in `eval` and
    /// `eval_many_into`.
    ///
    /// # Errors
    /// As [`eval_many_into`](Self::eval_many_into).
    ///
    /// ```
    /// use cagd::bspline::BSplineCurve;
    /// use nalgebra::DMatrix;
    /// let p = DMatrix::from_column_slice(1, 4, &[0.0, 3.0, -1.0, 2.0]);
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.3, 1.0, 1.0, 1.0], p)?;
    /// let ts = [0.1, 0.2, 0.7, 0.9];
    /// let mut out = [0.0; 4];
    /// c.eval_many_exact_order_into(&ts, &mut out)?;
    /// for (t, x) in ts.iter().zip(out) {
    ///     assert_eq!(c.try_eval(*t)?[0], x);
    /// }
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_many_exact_order_into(&self, us: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("B-spline curve points", &[us.len(), d])?;
        crate::grid::check_len("B-spline curve point buffer", len, out)?;
        crate::error::check_finite_slice("B-spline curve parameters", us)?;
        self.check_point_work(crate::cost::max_bits(us))?;
        let (p, knots) = (self.degree, self.knots.as_slice());
        curve_points_into(p, knots, self.control.as_slice(), d, false, us, out)
    }

    /// [`eval_many_exact_order_into`](Self::eval_many_exact_order_into) for parameters that
    /// must lie in the domain, as [`try_eval`](Self::try_eval) (the same values, bit for bit):
    /// nothing is written unless all do.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · d`; for the first parameter
    /// outside the domain, [`Error::NonFinite`] (NaN or ±∞) or [`Error::ParameterOutOfRange`].
    pub fn try_eval_many_into(&self, us: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("B-spline curve points", &[us.len(), d])?;
        crate::grid::check_len("B-spline curve point buffer", len, out)?;
        let (lo, hi) = self.domain();
        for u in us {
            check_in_domain(u, &lo, &hi)?;
        }
        self.eval_many_exact_order_into(us, out)
    }

    /// The derivative curve `C'(u) = Σ Q_i N_{i,p−1}(u)` with
    /// `Q_i = p (P_{i+1} − P_i)/(u_{i+p+1} − u_{i+1})` over the knots without the first and
    /// the last (octave-nurbs `bspderiv`). Where a knot difference is zero (a knot of
    /// multiplicity `p + 1` inside) the coefficient is set to zero: its basis function vanishes.
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] for a curve of degree 0.
    pub fn derivative(&self) -> Result<Self> {
        let p = self.degree;
        if p == 0 {
            return Err(Error::DerivativeOrder {
                order: 1,
                degree: 0,
            });
        }
        let k = self.knots.as_slice();
        let n = self.control.ncols();
        let pt = T::from_usize(p);
        let mut q = DMatrix::from_element(self.dim(), n - 1, T::zero());
        for i in 0..n - 1 {
            let h = k[i + p + 1].clone() - k[i + 1].clone();
            if h.is_zero() {
                continue;
            }
            let tmp = pt.clone() / h;
            for r in 0..self.dim() {
                q[(r, i)] =
                    tmp.clone() * (self.control[(r, i + 1)].clone() - self.control[(r, i)].clone());
            }
        }
        crate::error::check_overflow("B-spline derivative control points", q.iter())?;
        Ok(BSplineCurve {
            degree: p - 1,
            knots: KnotVector::new(k[1..k.len() - 1].to_vec())?,
            control: q,
        })
    }

    /// The first derivative `C'(u)`.
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] for degree 0, [`Error::ParameterOutOfRange`] outside the
    /// domain.
    pub fn try_eval_derivative(&self, u: T) -> Result<DVector<T>> {
        self.derivative()?.try_eval(u)
    }

    /// The same curve with the knot `u` inserted once (Boehm); see
    /// [`insert_knots`](Self::insert_knots).
    ///
    /// # Errors
    /// As [`insert_knots`](Self::insert_knots).
    pub fn insert_knot(&self, u: T) -> Result<Self> {
        self.insert_knots(&[u])
    }

    /// The same curve over a refined knot vector: the knots `us` (any order, repeats allowed)
    /// are inserted and the control points recomputed so that the curve does not change
    /// (Piegl & Tiller A5.4, in the operation order of octave-nurbs `bspkntins`).
    ///
    /// # Errors
    /// [`Error::NonFinite`]; [`Error::ParameterOutOfRange`] for a knot not strictly inside the
    /// domain; [`Error::InvalidArgument`] if a knot would occur more than `p + 1` times.
    pub fn insert_knots(&self, us: &[T]) -> Result<Self> {
        check_finite("inserted knots", us.iter())?;
        if us.is_empty() {
            return Ok(self.clone());
        }
        let d = self.degree;
        let (lo, hi) = self.domain();
        let mut u: Vec<T> = us.to_vec();
        u.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
        for x in &u {
            if !(&lo < x && x < &hi) {
                return Err(Error::ParameterOutOfRange {
                    what: "inserted knot",
                    value: x.to_f64(),
                    min: lo.to_f64(),
                    max: hi.to_f64(),
                });
            }
            let total = self.knots.multiplicity(x) + u.iter().filter(|y| *y == x).count();
            if total > d + 1 {
                return Err(Error::InvalidArgument {
                    what: "inserted knot",
                    message: format!(
                        "knot {x} would occur {total} times; at most degree + 1 = {} allowed",
                        d + 1
                    ),
                });
            }
        }
        let k = self.knots.as_slice();
        let c = &self.control;
        let nc = c.ncols();
        let nu = u.len();
        let (n, r, m) = (nc - 1, nu - 1, nc - 1 + d + 1);
        let a = span_of(d, nc, k, &u[0])?;
        let b = span_of(d, nc, k, &u[r])? + 1;
        let mut ic: Vec<DVector<T>> = vec![DVector::from_element(c.nrows(), T::zero()); nc + nu];
        let mut ik = vec![T::zero(); k.len() + nu];
        for (j, slot) in ic.iter_mut().enumerate().take(a - d + 1) {
            *slot = c.column(j).into_owned();
        }
        for j in b - 1..=n {
            ic[j + r + 1] = c.column(j).into_owned();
        }
        ik[..=a].clone_from_slice(&k[..=a]);
        for j in b + d..=m {
            ik[j + r + 1] = k[j].clone();
        }
        let mut i = b + d - 1;
        let mut s = b + d + r;
        for j in (0..=r).rev() {
            while u[j] <= k[i] && i > a {
                ic[s - d - 1] = c.column(i - d - 1).into_owned();
                ik[s] = k[i].clone();
                i -= 1;
                s -= 1;
            }
            ic[s - d - 1] = ic[s - d].clone();
            for l in 1..=d {
                let ind = s - d + l;
                let mut alfa = ik[s + l].clone() - u[j].clone();
                if alfa.is_zero() {
                    ic[ind - 1] = ic[ind].clone();
                } else {
                    alfa = alfa / (ik[s + l].clone() - k[i + l - d].clone());
                    // alfa·x + (1 − alfa)·y, the product with 1 − alfa first, as bspkntins.
                    let one_minus = T::one() - alfa.clone();
                    ic[ind - 1] = DVector::from_fn(ic[ind].len(), |q, _| {
                        let tmp = one_minus.clone() * ic[ind][q].clone();
                        alfa.clone() * ic[ind - 1][q].clone() + tmp
                    });
                }
            }
            ik[s] = u[j].clone();
            s -= 1;
        }
        let control = DMatrix::from_fn(c.nrows(), ic.len(), |row, col| ic[col][row].clone());
        crate::error::check_overflow(
            "B-spline control points after knot insertion",
            control.iter(),
        )?;
        Ok(BSplineCurve {
            degree: d,
            knots: KnotVector::new(ik)?,
            control,
        })
    }
}

/// `Σ_i n[i] · control[:, first + i]`, `i` ascending, starting from zero (as `bspeval`).
pub(crate) fn combine<T: Scalar>(control: &DMatrix<T>, first: usize, n: &[T]) -> DVector<T> {
    DVector::from_fn(control.nrows(), |r, _| {
        n.iter().enumerate().fold(T::zero(), |acc, (i, w)| {
            acc + w.clone() * control[(r, first + i)].clone()
        })
    })
}

/// `a · x + b · y`, coordinate-wise.
pub(crate) fn blend<T: Scalar>(x: &DVector<T>, a: T, y: &DVector<T>, b: T) -> DVector<T> {
    DVector::from_fn(x.len(), |r, _| {
        a.clone() * x[r].clone() + b.clone() * y[r].clone()
    })
}

impl<T: Scalar> Curve<T> for BSplineCurve<T> {
    fn dim(&self) -> usize {
        BSplineCurve::dim(self)
    }

    fn domain(&self) -> (T, T) {
        BSplineCurve::domain(self)
    }

    /// [`BSplineCurve::eval`]: the end pieces continue outside the domain.
    fn eval(&self, t: T) -> DVector<T> {
        BSplineCurve::eval(self, t)
    }

    fn try_eval(&self, t: T) -> Result<DVector<T>> {
        BSplineCurve::try_eval(self, t)
    }

    /// [`curve_point_cost`](crate::bspline::curve_point_cost) on the curve's own knots and
    /// control points.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        crate::bspline::curve_point_cost(
            self.degree(),
            self.dim(),
            param_bits,
            crate::cost::max_bits(self.knots().as_slice()),
            crate::cost::max_bits(self.control().iter()),
        )
    }

    /// [`BSplineCurve::eval_many_into`]: the fast batch (reciprocals per span, no division
    /// and no allocation per point).
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        BSplineCurve::eval_many_into(self, ts, out)
    }
}

impl<T: Scalar> crate::param::CurveDeriv<T> for BSplineCurve<T> {
    /// The derivative curve's [`eval`](BSplineCurve::eval) (the derivative of the continued
    /// piece outside the domain); zero for degree 0 (a piecewise constant curve).
    fn eval_derivative(&self, t: T) -> DVector<T> {
        match self.derivative() {
            Ok(d) => d.eval(t),
            Err(_) => DVector::from_element(self.dim(), T::zero()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fast_batch_names_a_bad_parameter_and_an_overflow() {
        // A NaN parameter is found by the scan of its block and reported as the parameter it
        // is; a point far outside the domain overflows; inside, nothing is scanned.
        let p = DMatrix::from_column_slice(1, 5, &[0.0, 3.0, -1.0, 2.0, 1.0]);
        let c = BSplineCurve::new(3, vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0], p).unwrap();
        let mut ts: Vec<f64> = (0..700).map(|k| k as f64 / 699.0).collect();
        let mut out = vec![0.0; 700];
        c.eval_many_into(&ts, &mut out).unwrap();
        assert_eq!(out[699], 1.0);
        ts[300] = f64::INFINITY;
        assert!(matches!(
            c.eval_many_into(&ts, &mut out),
            Err(Error::NonFinite { index: 300, .. })
        ));
        ts[300] = 1e120;
        assert!(matches!(
            c.eval_many_into(&ts, &mut out),
            Err(Error::Overflow { index: 300, .. })
        ));
    }

    #[test]
    fn de_boor_agrees_with_basis_sum() {
        let p = DMatrix::from_column_slice(
            2,
            6,
            &[0.0, 0.0, 1.0, 3.0, 2.0, -1.0, 4.0, 2.0, 5.0, 5.0, 7.0, 0.0],
        );
        let c = BSplineCurve::new(3, vec![0., 0., 0., 0., 0.3, 0.6, 1., 1., 1., 1.], p).unwrap();
        for k in 0..=10 {
            let u = k as f64 / 10.0;
            let a = c.try_eval(u).unwrap();
            let b = c.de_boor(u).unwrap();
            assert!((a - b).norm() < 1e-14);
        }
    }
}
