//! Bézier curves of any degree in any dimension (thesis chapter 2).

use nalgebra::{DMatrix, DVector};

use super::scheme::DeCasteljauScheme;
use super::{check_param, check_params};
use crate::bernstein::{bernstein_all, bernstein_all_into, falling_factorial, power};
use crate::cost::{polynomial_bits, Cost};
use crate::error::{check_finite, check_overflow, Error, Result};
use crate::param::check_parameter;
use crate::param::Curve;
use crate::scalar::Scalar;

/// A polynomial Bézier curve `b^n(u) = Σ_i b_i B_i^n((u − a)/(b − a))`, `u ∈ [a, b]`
/// (thesis §2.1–2.3; `[a, b] = [0, 1]` unless set otherwise).
///
/// **Layout:** the control points `b_0, …, b_n` are the columns of a `d × (n + 1)` matrix
/// (the thesis's `3 × (n+1)` control matrices), `d ≥ 1`, `n ≥ 0`.
///
/// **Evaluation.** [`eval`](Self::eval) (and [`Curve::eval`]) run de Casteljau's algorithm,
/// eq. (2.1): `b_i^r = (1 − t) b_i^{r−1} + t b_{i+1}^{r−1}`, computed coordinate-wise in exactly
/// that operation order (so `f64` results agree bit for bit with the fixed Octave
/// `deCasteljau`). On `[a, b]` the weights are `(b − u)/(b − a)` and `(u − a)/(b − a)`
/// (thesis §2.3.2). [`eval_bernstein`](Self::eval_bernstein) sums the Bernstein form
/// (Izrek 2.9) and [`matrix_form`](Self::matrix_form) gives the monomial form of the course
/// notes.
///
/// The thesis's own `deCasteljau` (appendix A) is wrong as printed: its loops run over the
/// number of coordinate rows instead of the degree and update rows (coordinates) instead of
/// columns (points), and it overwrites the control points while stepping through the
/// parameters, so every parameter after the first starts from the previous scheme. This type
/// computes what the algorithm of §2.1 describes.
///
/// **Input policy.** Constructors reject empty or ragged input and NaN/∞ coordinates with a
/// typed [`Error`]; nothing panics on user input. The domain is `[a, b]`;
/// [`eval`](Self::eval) accepts any parameter (outside `[a, b]` the polynomial continues; NaN
/// in gives NaN out), [`try_eval`](Self::try_eval) only those in `[a, b]` (the rule of
/// [`crate::param`]).
///
/// ```
/// use cagd::bezier::BezierCurve;
/// // The matrix-form notes: p0 = (0,0), p1 = (1,1), p2 = (2,0), p3 = (3,1).
/// let p = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])?;
/// assert_eq!((p.degree(), p.dim()), (3, 2));
/// let x = p.eval(0.5);
/// assert_eq!(x.as_slice(), &[1.5, 0.5]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<T: Scalar = f64> {
    control: DMatrix<T>,
    a: T,
    b: T,
}

impl<T: Scalar> BezierCurve<T> {
    /// The curve over `[0, 1]` with control points the columns of `control` (`d × (n + 1)`).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for no columns, [`Error::ShapeMismatch`] for no rows,
    /// [`Error::NonFinite`] for a NaN or infinite entry (index counted column-major).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use nalgebra::DMatrix;
    /// // Two points (columns) in 3-D: a segment.
    /// let c = BezierCurve::new(DMatrix::from_column_slice(3, 2, &[0.0, 0.0, 0.0, 2.0, 4.0, 6.0]))?;
    /// assert_eq!(c.eval(0.5).as_slice(), &[1.0, 2.0, 3.0]);
    /// assert!(BezierCurve::new(DMatrix::<f64>::zeros(3, 0)).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn new(control: DMatrix<T>) -> Result<Self> {
        Self::new_on_interval(control, T::zero(), T::one())
    }

    /// The curve over `[a, b]` with control points the columns of `control`: its value at
    /// `u ∈ [a, b]` is the value of the `[0, 1]` curve at `t = (u − a)/(b − a)` (thesis §2.3.2).
    ///
    /// # Errors
    /// As [`new`](Self::new), plus [`Error::NonFinite`] for a non-finite end,
    /// [`Error::EmptyInterval`] unless `a < b`, and [`Error::Overflow`] for an interval whose
    /// width `b − a` (or its reciprocal) is not a finite double (`[−10³⁰⁸, 10³⁰⁸]`).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use nalgebra::DMatrix;
    /// let control = DMatrix::from_column_slice(1, 3, &[0.0, 4.0, 2.0]);
    /// let unit = BezierCurve::new(control.clone())?;
    /// let wide = BezierCurve::new_on_interval(control, 2.0, 6.0)?;
    /// assert_eq!(wide.eval(3.0), unit.eval(0.25));
    /// assert!(BezierCurve::new_on_interval(DMatrix::from_element(1, 1, 0.0), 1.0, 1.0).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn new_on_interval(control: DMatrix<T>, a: T, b: T) -> Result<Self> {
        check_control("Bézier curve control points", &control)?;
        check_interval("Bézier curve interval", &a, &b)?;
        Ok(BezierCurve { control, a, b })
    }

    /// The curve over `[0, 1]` through a list of points, each a slice of `d` coordinates
    /// (`Vec<Vec<T>>`, `&[[f64; 3]]`, …).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for an empty list; [`Error::ShapeMismatch`] if a point has a
    /// different number of coordinates than the first (or the first has none);
    /// [`Error::NonFinite`] for a NaN or infinite coordinate.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[vec![0.0, 0.0], vec![2.0, 2.0]])?;
    /// assert_eq!(c.eval(0.25).as_slice(), &[0.5, 0.5]);
    /// let ragged = BezierCurve::from_points(&[vec![0.0, 0.0], vec![2.0]]);
    /// assert!(matches!(ragged, Err(cagd::Error::ShapeMismatch { .. })));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn from_points<P: AsRef<[T]>>(points: &[P]) -> Result<Self> {
        let what = "Bézier curve control points";
        let first = points.first().ok_or(Error::TooFewPoints {
            what,
            min: 1,
            found: 0,
        })?;
        let d = first.as_ref().len();
        for (k, p) in points.iter().enumerate() {
            if p.as_ref().len() != d {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!("{d} coordinates in every point (as in point 0)"),
                    found: format!("{} coordinates in point {k}", p.as_ref().len()),
                });
            }
        }
        let control = DMatrix::from_fn(d, points.len(), |c, k| points[k].as_ref()[c].clone());
        Self::new(control)
    }

    /// A curve from parts already known to be valid.
    pub(crate) fn from_valid(control: DMatrix<T>, a: T, b: T) -> Self {
        BezierCurve { control, a, b }
    }

    /// The same control points over the interval `[a, b]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite end, [`Error::EmptyInterval`] unless `a < b`.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0], [8.0]])?.with_interval(-1.0, 1.0)?;
    /// assert_eq!(c.interval(), (&-1.0, &1.0));
    /// assert_eq!(c.local_parameter(0.0), 0.5);
    /// assert_eq!(c.eval(0.0).as_slice(), &[4.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn with_interval(self, a: T, b: T) -> Result<Self> {
        check_interval("Bézier curve interval", &a, &b)?;
        Ok(BezierCurve { a, b, ..self })
    }

    /// The degree `n` (number of control points minus one).
    pub fn degree(&self) -> usize {
        self.control.ncols() - 1
    }

    /// The dimension `d` of the points.
    pub fn dim(&self) -> usize {
        self.control.nrows()
    }

    /// The control points, one per column (`d × (n + 1)`).
    pub fn control(&self) -> &DMatrix<T> {
        &self.control
    }

    /// The control point `b_i` (`None` for `i > n`).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 1.0], [2.0, 3.0]])?;
    /// assert_eq!(c.control_point(1).unwrap().as_slice(), &[2.0, 3.0]);
    /// assert!(c.control_point(2).is_none());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn control_point(&self, i: usize) -> Option<DVector<T>> {
        (i < self.control.ncols()).then(|| self.control.column(i).into_owned())
    }

    /// The parameter interval `[a, b]`.
    pub fn interval(&self) -> (&T, &T) {
        (&self.a, &self.b)
    }

    fn is_unit_interval(&self) -> bool {
        self.a.is_zero() && self.b.is_one()
    }

    /// The local parameter `t = (u − a)/(b − a)` (just `u` on `[0, 1]`).
    pub fn local_parameter(&self, u: T) -> T {
        if self.is_unit_interval() {
            u
        } else {
            (u - self.a.clone()) / (self.b.clone() - self.a.clone())
        }
    }

    /// The de Casteljau weights `(1 − t, t)` at `u`: `((b − u)/(b − a), (u − a)/(b − a))`,
    /// which is `(1 − u, u)` on `[0, 1]`.
    fn weights(&self, u: &T) -> (T, T) {
        if self.is_unit_interval() {
            (T::one() - u.clone(), u.clone())
        } else {
            let h = self.b.clone() - self.a.clone();
            (
                (self.b.clone() - u.clone()) / h.clone(),
                (u.clone() - self.a.clone()) / h,
            )
        }
    }

    /// The point `b^n(u)` by de Casteljau's algorithm (thesis eq. (2.1)).
    ///
    /// Any parameter is accepted: outside `[a, b]` this extrapolates the polynomial, NaN gives
    /// NaN. Use [`try_eval`](Self::try_eval) to reject non-finite parameters.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0, 0.0], [0.0, 2.0, 2.0], [8.0, 2.0, 0.0], [4.0, 0.0, 0.0]])?;
    /// assert_eq!(c.eval(0.5).as_slice(), &[3.5, 1.5, 0.75]); // thesis Primer 2.4
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval(&self, u: T) -> DVector<T> {
        let (s, t) = self.weights(&u);
        let mut work = self.control.clone();
        let (d, n) = (self.dim(), self.degree());
        for r in 1..=n {
            for i in 0..=n - r {
                for c in 0..d {
                    // (1 − t)·b_i + t·b_{i+1}, in this order.
                    work[(c, i)] =
                        s.clone() * work[(c, i)].clone() + t.clone() * work[(c, i + 1)].clone();
                }
            }
        }
        work.column(0).into_owned()
    }

    /// [`eval`](Self::eval) for a parameter in the domain `[a, b]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite `u`, [`Error::ParameterOutOfRange`] for a
    /// finite `u` outside `[a, b]`, [`Error::TooLarge`] when the work of the point
    /// ([`eval_cost`](Self::eval_cost): `d (n+1)²` operations, weighed by the size of the
    /// numbers in exact arithmetic) exceeds [`Limits::DEFAULT`](crate::limits::Limits::DEFAULT)
    /// (a curve of degree 100 000), [`Error::Overflow`] for a point whose double overflows.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use cagd::Error;
    /// let c = BezierCurve::from_points(&[[0.0], [2.0]])?;
    /// assert_eq!(c.try_eval(0.25)?.as_slice(), &[0.5]);
    /// assert_eq!(c.eval(1.5).as_slice(), &[3.0]); // eval continues the line
    /// assert!(matches!(c.try_eval(1.5), Err(Error::ParameterOutOfRange { .. })));
    /// assert!(matches!(c.try_eval(f64::NAN), Err(Error::NonFinite { .. })));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn try_eval(&self, u: T) -> Result<DVector<T>> {
        check_parameter("Bézier curve parameter", &u, &self.domain())?;
        self.check_point_work(u.bits())?;
        crate::checked::point("Bézier curve point", self.dim(), self.eval(u))
    }

    /// One point's work ([`eval_cost`](Self::eval_cost)) at a parameter of `param_bits` bits
    /// against the default limit ([`crate::checked::point_work`]).
    fn check_point_work(&self, param_bits: u128) -> Result<()> {
        let cost = self.eval_cost(param_bits, crate::cost::max_bits(self.control.iter()));
        crate::checked::point_work::<T>("Bézier curve point", cost)
    }

    /// The domain `[a, b]` (the interval the curve was built on, `[0, 1]` by default).
    pub fn domain(&self) -> (T, T) {
        (self.a.clone(), self.b.clone())
    }

    /// The whole de Casteljau scheme at `u` (every `b_i^r`, thesis §2.1). Its last point equals
    /// [`eval`](Self::eval) bit for bit.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0], [1.0], [3.0]])?;
    /// let s = c.scheme(0.5);
    /// assert_eq!(s.level(1).unwrap().as_slice(), &[0.5, 2.0]);
    /// assert_eq!(s.point_on_curve(), c.eval(0.5));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn scheme(&self, u: T) -> DeCasteljauScheme<T> {
        let (s, t) = self.weights(&u);
        DeCasteljauScheme::compute(&self.control, &s, &t, u)
    }

    /// The cost of the point at one parameter of `param_bits` bits by de Casteljau's scheme
    /// ([`scheme`](Self::scheme); [`eval`](Self::eval) does no more): `d (n+1)²` operations
    /// (`n` levels of convex combinations, two products and a sum per coordinate and point), on
    /// numbers of [`polynomial_bits`]`(n, param_bits,
    /// control_bits)` bits, `control_bits` the size of the control points.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use cagd::cost::Cost;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]])?;
    /// assert_eq!(c.eval_cost(4, 10), Cost::new(18, 20));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_cost(&self, param_bits: u128, control_bits: u128) -> Cost {
        let n = self.degree();
        Cost::new(
            (self.dim() as u128).saturating_mul((n as u128 + 1).saturating_pow(2)),
            polynomial_bits(n, param_bits, control_bits),
        )
    }

    /// The point `Σ_i b_i B_i^n(t)`, `t = (u − a)/(b − a)`, from the Bernstein form (thesis
    /// Izrek 2.9), with the basis from [`bernstein_all`]. Agrees with [`eval`](Self::eval) up to
    /// rounding (exactly, for rationals).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])?;
    /// let p = c.eval_bernstein(0.2);
    /// assert!((p[0] - 0.6).abs() < 1e-15 && (p[1] - 0.392).abs() < 1e-15);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_bernstein(&self, u: T) -> DVector<T> {
        let basis = bernstein_all(self.degree(), self.local_parameter(u));
        DVector::from_fn(self.dim(), |c, _| {
            basis.iter().enumerate().fold(T::zero(), |acc, (i, b)| {
                acc + self.control[(c, i)].clone() * b.clone()
            })
        })
    }

    /// The points at all parameters `us`, by de Casteljau: a `d × k` matrix whose column `k`
    /// is `b^n(us[k])` (the layout of the thesis's sample matrices `T(:, k)`). Like the
    /// thesis's `deCasteljau` it takes any finite parameters, continuing the polynomial outside
    /// the domain as [`eval`](Self::eval) does. In exact rationals the same values come from the
    /// Bernstein sums of [`eval_many_into`](Self::eval_many_into), with far fewer operations.
    ///
    /// # Errors
    /// [`Error::EmptyGrid`] for an empty list, [`Error::NonFinite`] for a NaN or infinite
    /// parameter, [`Error::TooLarge`] when one point's work ([`eval_cost`](Self::eval_cost))
    /// exceeds the default limit, [`Error::Overflow`] for a point whose double overflows (far
    /// outside the domain, or control points near ±1.7·10³⁰⁸).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 2.0]])?;
    /// let pts = c.eval_many(&cagd::linspace(0.0, 1.0, 3))?;
    /// assert_eq!(pts.shape(), (2, 3));
    /// assert_eq!(pts.column(1).as_slice(), &[0.5, 1.0]);
    /// assert!(c.eval_many(&[]).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_many(&self, us: &[T]) -> Result<DMatrix<T>> {
        check_params("Bézier curve parameters", us)?;
        let len = crate::grid::grid_len("Bézier curve points", &[us.len(), self.dim()])?;
        let mut out = DMatrix::from_vec(
            self.dim(),
            us.len(),
            crate::grid::try_filled("Bézier curve points", len, T::zero())?,
        );
        if crate::grid::exact::is_rational::<T>() {
            // Exact: the same values from the Bernstein sums of the batch, a fraction of the
            // operations (and gcds) of de Casteljau's triangle.
            self.eval_many_into(us, out.as_mut_slice())?;
            return Ok(out);
        }
        self.check_point_work(0)?;
        for (u, mut column) in us.iter().zip(out.column_iter_mut()) {
            column.copy_from(&self.eval(u.clone()));
        }
        check_overflow("Bézier curve points", out.iter())?;
        Ok(out)
    }

    /// The points at all parameters `us` written into `out`, one after the other:
    /// `out[p·d + c]` is coordinate `c` of `b^n(us[p])` (`us.len() × d` row-major, which is
    /// the storage of the `d × k` matrix of [`eval_many`](Self::eval_many); see
    /// [`crate::grid`]). Like [`eval_many`](Self::eval_many), any finite parameter is accepted
    /// (the polynomial continues outside the domain).
    ///
    /// Each point is the Bernstein sum `Σ_i B_i^n(t) b_i`: for degree ≤ 3 in 2-D or 3-D with the
    /// basis as the products `C(n, i) t^i (1 − t)^(n−i)` and every size fixed at compile time,
    /// otherwise with the triangular recurrence of
    /// [`bernstein_all`](crate::bernstein::bernstein_all) (`O(n² + n·d)` per point, the basis
    /// rows of a block of points sharing one scratch buffer). Nothing is allocated per point,
    /// and large batches are split over all cores. The result agrees with
    /// [`eval`](Self::eval) to a few units of `ε · max |b_i|` in `f64` and exactly for
    /// rationals.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · d`; [`Error::NonFinite`] for a
    /// NaN or infinite parameter; [`Error::TooLarge`] when one point's work
    /// ([`eval_cost`](Self::eval_cost)) exceeds the default limit; [`Error::Overflow`] for a
    /// point whose double overflows (the buffer is written all the same).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])?;
    /// let mut out = vec![0.0; 3 * 2];
    /// c.eval_many_into(&[0.0, 0.5, 1.0], &mut out)?;
    /// assert_eq!(out, [0.0, 0.0, 1.0, 1.0, 2.0, 0.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_many_into(&self, us: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("Bézier curve points", &[us.len(), d])?;
        crate::grid::check_len("Bézier curve point buffer", len, out)?;
        self.check_point_work(crate::cost::max_bits(us))?;
        // A NaN or infinite parameter gives a non-finite point, which the scan of its block
        // finds: only then are the parameters looked at (one pass fewer over a large batch).
        self.fill_many(us, out).map_err(|e| {
            crate::error::check_finite_slice("Bézier curve parameters", us)
                .err()
                .unwrap_or(e)
        })
    }

    /// [`eval_many_into`](Self::eval_many_into) after its checks of the lengths and the work.
    fn fill_many(&self, us: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let local = |u: &T| self.local_parameter(u.clone());
        if crate::grid::exact::bezier_points(self.control.as_slice(), d, local, us, out) {
            return Ok(());
        }
        // Points per block: their basis rows fit in a small scratch buffer.
        const BLOCK: usize = 256;
        let terms = self.degree() + 1;
        let control = self.control.as_slice();
        let work = us.len().saturating_mul(terms * (terms + d));
        // Low degrees in 2-D and 3-D: basis and sums with sizes fixed at compile time, the
        // basis kept in registers (same arithmetic, and results, as the general path).
        let unit = {
            let (a, b) = self.interval();
            a.is_zero() && b.is_one()
        };
        // A block of points is finite, and is not scanned, when `Σ |B_i(t)| · max |b_i|` is
        // ([`crate::grid::bounded_by`]): on the domain the basis is positive and sums to 1.
        let small = T::EXACT || crate::grid::bounded_by::<T>(1.0, crate::grid::max_abs(control));
        let (a, b) = self.interval();
        let bounded = |ts: &[T]| T::EXACT || small && T::all_within(ts, a, b);
        macro_rules! fixed {
            ($l:literal, $d:literal) => {{
                let c: [[T; $d]; $l] =
                    std::array::from_fn(|i| std::array::from_fn(|k| control[i * $d + k].clone()));
                let binomials: [T; $l] =
                    std::array::from_fn(|i| crate::bernstein::binomial_scalar($l - 1, i));
                return crate::grid::for_each_bounded_row(
                    "Bézier curve points",
                    out,
                    BLOCK * $d,
                    work,
                    || (),
                    |_, block, chunk| {
                        let ts = &us[block * BLOCK..];
                        let ts = &ts[..(chunk.len() / $d).min(ts.len())];
                        let inside = if unit {
                            T::vectorized(|| {
                                points_fixed::<T, $l, $d>(&c, &binomials, ts, chunk, T::clone)
                            })
                        } else {
                            T::vectorized(|| {
                                points_fixed::<T, $l, $d>(&c, &binomials, ts, chunk, |u| {
                                    self.local_parameter(u.clone())
                                })
                            })
                        };
                        T::EXACT || inside && small
                    },
                );
            }};
        }
        match (terms, d) {
            (2, 2) => fixed!(2, 2),
            (2, 3) => fixed!(2, 3),
            (3, 2) => fixed!(3, 2),
            (3, 3) => fixed!(3, 3),
            (4, 2) => fixed!(4, 2),
            (4, 3) => fixed!(4, 3),
            _ => {}
        }
        crate::grid::for_each_bounded_row(
            "Bézier curve points",
            out,
            BLOCK * d,
            work,
            || vec![T::zero(); BLOCK.min(us.len()) * terms],
            |basis, block, chunk| {
                let first = block * BLOCK;
                let count = chunk.len() / d;
                let ts = &us[first..first + count];
                for (u, row) in ts.iter().zip(basis.chunks_exact_mut(terms)) {
                    bernstein_all_into(&self.local_parameter(u.clone()), row);
                }
                crate::grid::contract_row(&basis[..count * terms], terms, control, chunk);
                bounded(ts)
            },
        )
    }

    /// The `r`-th derivative as a Bézier curve of degree `n − r` over the same interval
    /// (thesis §2.4):
    ///
    /// ```text
    /// d^r/du^r b^n(u) = n!/(n−r)! · 1/(b−a)^r · Σ_{i=0}^{n−r} Δ^r b_i B_i^{n−r}(t),
    /// Δ^r b_i = Δ^{r−1} b_{i+1} − Δ^{r−1} b_i,
    /// ```
    ///
    /// the forward differences taken first and scaled once at the end (the factor `1/(b−a)^r`
    /// is the chain rule for `t = (u−a)/(b−a)`; it is 1 on `[0, 1]`). `r = 0` gives a copy.
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] if `r > n`; [`Error::Overflow`] for a control point whose
    /// double overflows (differences of control points near ±1.7·10³⁰⁸, or the factor
    /// `n!/(n−r)!`).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// // b(t) = (t², ·) from control points 0, 0, 1 in x: b'' = 2.
    /// let c = BezierCurve::from_points(&[[0.0], [0.0], [1.0]])?;
    /// let d2 = c.derivative(2)?;
    /// assert_eq!(d2.degree(), 0);
    /// assert_eq!(d2.eval(0.3).as_slice(), &[2.0]);
    /// assert!(c.derivative(3).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn derivative(&self, r: usize) -> Result<Self> {
        let n = self.degree();
        if r > n {
            return Err(Error::DerivativeOrder {
                order: r,
                degree: n,
            });
        }
        let mut diff = self.control.clone();
        for _ in 0..r {
            diff = DMatrix::from_fn(diff.nrows(), diff.ncols() - 1, |c, i| {
                diff[(c, i + 1)].clone() - diff[(c, i)].clone()
            });
        }
        let mut factor = falling_factorial::<T>(n, r);
        if !self.is_unit_interval() {
            factor = factor / power(&(self.b.clone() - self.a.clone()), r);
        }
        if r > 0 {
            diff = diff.map(|x| factor.clone() * x);
        }
        check_overflow("Bézier derivative control points", diff.iter())?;
        Ok(BezierCurve::from_valid(
            diff,
            self.a.clone(),
            self.b.clone(),
        ))
    }

    /// The hodograph: the first derivative as a curve of degree `n − 1` (thesis eq. (2.5),
    /// control points `n Δb_i`, divided by `b − a` off `[0, 1]`).
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] for a curve of degree 0 (a point).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])?;
    /// let h = c.hodograph()?;
    /// assert_eq!(h.control().column(0).as_slice(), &[3.0, 3.0]); // 3 (p1 − p0)
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn hodograph(&self) -> Result<Self> {
        self.derivative(1)
    }

    /// The first derivative at `u` straight from the scheme:
    /// `n (b_1^{n−1} − b_0^{n−1}) / (b − a)`; the zero vector for degree 0.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// // x(t) = t² (control values 0, 0, 1): x'(0.5) = 1.
    /// let c = BezierCurve::from_points(&[[0.0], [0.0], [1.0]])?;
    /// assert_eq!(c.eval_derivative(0.5).as_slice(), &[1.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_derivative(&self, u: T) -> DVector<T> {
        let n = self.degree();
        if n == 0 {
            return DVector::from_element(self.dim(), T::zero());
        }
        let scheme = self.scheme(u);
        let level = &scheme.levels()[n - 1];
        let mut factor = T::from_usize(n);
        if !self.is_unit_interval() {
            factor = factor / (self.b.clone() - self.a.clone());
        }
        DVector::from_fn(self.dim(), |c, _| {
            factor.clone() * (level[(c, 1)].clone() - level[(c, 0)].clone())
        })
    }

    /// Splits the curve at `u` into the parts over `[a, u]` and `[u, b]`, with the control
    /// polygons read off the edges of the de Casteljau scheme: `b_0^0, b_0^1, …, b_0^n` and
    /// `b_0^n, b_1^{n−1}, …, b_n^0`. Each half keeps the original parametrisation, so
    /// `left.eval(x) = self.eval(x)` for `x ∈ [a, u]` (up to rounding).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite `u`; [`Error::EmptyInterval`] unless `a < u < b`
    /// (one half would be empty).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0, 0.0], [0.0, 2.0, 2.0], [8.0, 2.0, 0.0], [4.0, 0.0, 0.0]])?;
    /// let (left, right) = c.subdivide(0.5)?;
    /// assert_eq!(left.control().column(3).as_slice(), &[3.5, 1.5, 0.75]);
    /// assert_eq!(right.control().column(1).as_slice(), &[5.0, 1.5, 0.5]);
    /// assert_eq!(left.interval(), (&0.0, &0.5));
    /// assert_eq!(left.eval(0.25), c.eval(0.25));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn subdivide(&self, u: T) -> Result<(Self, Self)> {
        check_param("Bézier curve subdivision parameter", &u)?;
        if u <= self.a {
            return Err(Error::EmptyInterval {
                what: "left half of a subdivided Bézier curve",
                a: self.a.to_f64(),
                b: u.to_f64(),
            });
        }
        if u >= self.b {
            return Err(Error::EmptyInterval {
                what: "right half of a subdivided Bézier curve",
                a: u.to_f64(),
                b: self.b.to_f64(),
            });
        }
        check_interval("left half of a subdivided Bézier curve", &self.a, &u)?;
        check_interval("right half of a subdivided Bézier curve", &u, &self.b)?;
        let scheme = self.scheme(u.clone());
        let (left, right) = (scheme.left_control(), scheme.right_control());
        check_overflow(
            "subdivided Bézier curve control points",
            left.iter().chain(right.iter()),
        )?;
        let left = BezierCurve::from_valid(left, self.a.clone(), u.clone());
        let right = BezierCurve::from_valid(right, u, self.b.clone());
        Ok((left, right))
    }

    /// The same curve written with degree `n + 1` (degree elevation, coordinate by coordinate
    /// [`bernstein::elevate_once`](crate::bernstein::elevate_once)):
    /// `b'_i = i/(n+1) · b_{i−1} + (1 − i/(n+1)) · b_i`, `i = 0, …, n + 1` (with the
    /// out-of-range terms dropped, so `b'_0 = b_0` and `b'_{n+1} = b_n`).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0], [3.0]])?;
    /// let e = c.elevate();
    /// assert_eq!(e.control().as_slice(), &[0.0, 1.5, 3.0]);
    /// assert!((e.eval(0.3)[0] - c.eval(0.3)[0]).abs() < 1e-15);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn elevate(&self) -> Self {
        let rows: Vec<Vec<T>> = self
            .control
            .row_iter()
            .map(|r| crate::bernstein::elevate_once(&r.iter().cloned().collect::<Vec<_>>()))
            .collect();
        let control = DMatrix::from_fn(self.dim(), self.degree() + 2, |c, i| rows[c][i].clone());
        BezierCurve::from_valid(control, self.a.clone(), self.b.clone())
    }

    /// The cost of raising the degree by `r` ([`elevate`](Self::elevate) `r` times): each
    /// coordinate is [`bernstein::elevate_cost`](crate::bernstein::elevate_cost) of the
    /// control points' `control_bits`.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 0.0]])?;
    /// assert_eq!(c.elevate_cost(2, 0).ops(), 2 * 55);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn elevate_cost(&self, r: usize, control_bits: u128) -> Cost {
        crate::bernstein::elevate_cost(self.degree(), r, control_bits).times(self.dim() as u128)
    }

    /// The same point set traversed backwards: control points in reverse order, same interval,
    /// so `reversed().eval(a + b − u) = eval(u)` (thesis §2.3, symmetry).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let c = BezierCurve::from_points(&[[0.0], [1.0], [5.0]])?;
    /// assert_eq!(c.reversed().eval(0.25), c.eval(0.75));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn reversed(&self) -> Self {
        let n = self.degree();
        let control = DMatrix::from_fn(self.dim(), n + 1, |c, i| self.control[(c, n - i)].clone());
        BezierCurve::from_valid(control, self.a.clone(), self.b.clone())
    }
}

impl<T: Scalar> Curve<T> for BezierCurve<T> {
    fn dim(&self) -> usize {
        BezierCurve::dim(self)
    }

    fn domain(&self) -> (T, T) {
        BezierCurve::domain(self)
    }

    fn eval(&self, t: T) -> DVector<T> {
        BezierCurve::eval(self, t)
    }

    fn try_eval(&self, t: T) -> Result<DVector<T>> {
        BezierCurve::try_eval(self, t)
    }

    /// [`BezierCurve::eval_cost`] on the curve's own control points.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        BezierCurve::eval_cost(
            self,
            param_bits,
            crate::cost::max_bits(self.control().iter()),
        )
    }

    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        BezierCurve::eval_many_into(self, ts, out)
    }
}

impl<T: Scalar> crate::param::CurveDeriv<T> for BezierCurve<T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        BezierCurve::eval_derivative(self, t)
    }
}

/// The points at `ts` (as many as `out` holds) of a curve of degree `L − 1` in `D` dimensions
/// with control points `c` and binomials `C(L−1, i)`, `local` mapping a parameter to `[0, 1]`:
/// `B_i^n(t) = C(n, i) t^i (1 − t)^(n−i)`, the powers built up by products (positive factors
/// on `[0, 1]`: a few ULPs; exact in rationals), cheaper than the triangular recurrence.
///
/// Returns whether every local parameter was in `[0, 1]` (`t ≥ 0` and `1 − t ≥ 0`; not for a
/// NaN): then every weight is in `[0, 1]`, they sum to 1, and each point is bounded by the
/// largest control point.
#[inline(always)]
fn points_fixed<T: Scalar, const L: usize, const D: usize>(
    c: &[[T; D]; L],
    binomials: &[T; L],
    ts: &[T],
    out: &mut [T],
    local: impl Fn(&T) -> T,
) -> bool {
    let mut inside = true;
    for (u, p) in ts.iter().zip(out.chunks_exact_mut(D)) {
        let t = local(u);
        let s = T::one() - t.clone();
        inside &= (t >= T::zero()) & (s >= T::zero());
        let mut tp: [T; L] = std::array::from_fn(|_| T::one());
        let mut sp: [T; L] = std::array::from_fn(|_| T::one());
        for i in 1..L {
            tp[i] = tp[i - 1].clone() * t.clone();
            sp[L - 1 - i] = sp[L - i].clone() * s.clone();
        }
        let w: [T; L] =
            std::array::from_fn(|i| binomials[i].clone() * tp[i].clone() * sp[i].clone());
        let mut acc: [T; D] = std::array::from_fn(|k| w[0].clone() * c[0][k].clone());
        for i in 1..L {
            for k in 0..D {
                acc[k] = acc[k].clone() + w[i].clone() * c[i][k].clone();
            }
        }
        for (o, a) in p.iter_mut().zip(acc) {
            *o = a;
        }
    }
    inside
}

/// A control matrix must have at least one point (column) and one coordinate (row), all finite.
pub(crate) fn check_control<T: Scalar>(what: &'static str, control: &DMatrix<T>) -> Result<()> {
    if control.ncols() == 0 {
        return Err(Error::TooFewPoints {
            what,
            min: 1,
            found: 0,
        });
    }
    if control.nrows() == 0 {
        return Err(Error::ShapeMismatch {
            what,
            expected: "at least one coordinate row".into(),
            found: "0 rows".into(),
        });
    }
    check_finite(what, control.iter())
}

/// An interval must have finite ends with `a < b`, and a width `b − a` that is a finite double
/// with a finite reciprocal (the local parameter divides by it).
pub(crate) fn check_interval<T: Scalar>(what: &'static str, a: &T, b: &T) -> Result<()> {
    check_finite(what, [a, b])?;
    if a >= b {
        return Err(Error::EmptyInterval {
            what,
            a: a.to_f64(),
            b: b.to_f64(),
        });
    }
    crate::error::check_spacing(what, &[a.clone(), b.clone()])
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn batches_skip_the_scan_only_where_points_are_bounded() {
        // Every kernel (degree 3 in 3-D is a fixed one, degree 5 the general one), on the unit
        // interval and on [2, 6]: inside the domain with small control points the blocks are
        // not scanned; outside, with control points near the largest double, or with a NaN
        // parameter they are, and the errors are those of the scan and of the parameters.
        for degree in [3, 5] {
            for (a, b) in [(0.0, 1.0), (2.0, 6.0)] {
                let mut small = DMatrix::from_element(3, degree + 1, 1.0);
                small[(0, 1)] = -2.0;
                let c = BezierCurve::new_on_interval(small, a, b).unwrap();
                let mut out = vec![0.0; 3 * 600];
                let inside: Vec<f64> = (0..600).map(|k| a + (b - a) * k as f64 / 599.0).collect();
                c.eval_many_into(&inside, &mut out).unwrap();
                assert!((out[3] - c.eval(inside[1])[0]).abs() < 1e-12);
                let mut far = inside.clone();
                far[517] = 1e200;
                assert!(matches!(
                    c.eval_many_into(&far, &mut out),
                    Err(Error::Overflow { index, .. }) if index / 3 == 517
                ));
                far[517] = f64::NAN;
                assert!(matches!(
                    c.eval_many_into(&far, &mut out),
                    Err(Error::NonFinite { index: 517, .. })
                ));
                let huge =
                    DMatrix::from_fn(
                        3,
                        degree + 1,
                        |_, j| {
                            if j % 2 == 0 {
                                1.7e308
                            } else {
                                -1.7e308
                            }
                        },
                    );
                let c = BezierCurve::new_on_interval(huge, a, b).unwrap();
                // Finite at the ends (the control points themselves), overflowing in between
                // or not: never an infinite value in an `Ok`.
                match c.eval_many_into(&inside, &mut out) {
                    Ok(()) => assert!(out.iter().all(|x| x.is_finite())),
                    Err(e) => assert!(matches!(e, Error::Overflow { .. }), "{e}"),
                }
            }
        }
    }

    fn q(n: i64, d: i64) -> BigRational {
        <BigRational as Scalar>::from_ratio(n, d)
    }

    #[test]
    fn de_casteljau_cost_grows_with_the_degree_and_the_parameter() {
        let c = BezierCurve::new(DMatrix::<f64>::zeros(3, 5)).unwrap();
        assert_eq!(c.eval_cost(0, 0), Cost::new(3 * 25, 4));
        // Each of the 4 levels multiplies by t = p/q: 10-bit parameters add 11 bits each.
        assert_eq!(c.eval_cost(10, 7).bits(), 7 + 4 * 11);
        let point = BezierCurve::new(DMatrix::<f64>::zeros(2, 1)).unwrap();
        assert_eq!(point.eval_cost(10, 7), Cost::new(2, 7));
    }

    #[test]
    fn interval_weights_follow_the_thesis() {
        // On [2, 6] the value at u is the unit curve's value at (u − 2)/4, exactly in rationals.
        let control = DMatrix::from_row_slice(1, 4, &[q(0, 1), q(5, 1), q(-2, 1), q(7, 3)]);
        let unit = BezierCurve::new(control.clone()).unwrap();
        let wide = BezierCurve::new_on_interval(control, q(2, 1), q(6, 1)).unwrap();
        for k in 0..=8 {
            let u = q(2, 1) + q(k, 2);
            assert_eq!(wide.eval(u.clone()), unit.eval(q(k, 8)));
            assert_eq!(wide.eval_bernstein(u), unit.eval(q(k, 8)));
        }
        // Derivatives pick up 1/(b − a) per order.
        let d1 = wide.derivative(1).unwrap();
        let u1 = unit.derivative(1).unwrap();
        assert_eq!(d1.eval(q(3, 1)), u1.eval(q(1, 4)).map(|x| x / q(4, 1)));
        assert_eq!(wide.eval_derivative(q(3, 1)), d1.eval(q(3, 1)));
    }

    #[test]
    fn degree_zero_curve() {
        let c = BezierCurve::from_points(&[[1.0, 2.0]]).unwrap();
        assert_eq!(c.degree(), 0);
        assert_eq!(c.eval(0.7).as_slice(), &[1.0, 2.0]);
        assert_eq!(c.eval_derivative(0.7).as_slice(), &[0.0, 0.0]);
        assert!(c.hodograph().is_err());
        assert_eq!(c.derivative(0).unwrap(), c);
        let s = c.scheme(0.3);
        assert_eq!(s.degree(), 0);
        assert_eq!(s.left_control(), *c.control());
        assert_eq!(c.elevate().control().as_slice(), &[1.0, 2.0, 1.0, 2.0]);
    }

    #[test]
    fn subdivision_bounds() {
        let c = BezierCurve::from_points(&[[0.0], [1.0]]).unwrap();
        assert!(matches!(c.subdivide(0.0), Err(Error::EmptyInterval { .. })));
        assert!(matches!(c.subdivide(1.0), Err(Error::EmptyInterval { .. })));
        assert!(matches!(c.subdivide(1.5), Err(Error::EmptyInterval { .. })));
        assert!(matches!(
            c.subdivide(f64::NAN),
            Err(Error::NonFinite { .. })
        ));
    }
}
