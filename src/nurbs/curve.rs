//! NURBS curves.

use nalgebra::{DMatrix, DVector};

use super::{check_weights, homogenize};
use crate::bspline::{check_in_domain, curve_points_fast_into, curve_points_into, BSplineCurve};
use crate::error::{Error, Result};
use crate::param::Curve;
use crate::scalar::Scalar;

/// A NURBS curve `C(u) = Σ_k R_{k,p}(u) P_k` in `ℝ^d` (the CAD notes eq. (4)), stored as the
/// homogeneous B-spline curve in `ℝ^{d+1}` with control points `(w_k P_k, w_k)`.
///
/// **Layout:** as octave-nurbs `nrbmak(coefs, knots)`: [`homogeneous`](Self::homogeneous) is a
/// B-spline curve whose control matrix is `(d + 1) × n`, rows `w·x, w·y, …, w`.
///
/// Evaluation ([`try_eval`](Self::try_eval)) divides the homogeneous point by its weight (as
/// `nrbeval`); the derivative ([`try_eval_derivative`](Self::try_eval_derivative)) is the
/// quotient rule `C' = (A' − w' C)/w` with `A = w C` (as `nrbdeval`).
///
/// ```
/// use cagd::nurbs::NurbsCurve;
/// // A quarter of the unit circle as a rational quadratic Bézier curve.
/// let h = std::f64::consts::FRAC_1_SQRT_2;
/// let p = nalgebra::DMatrix::from_column_slice(2, 3, &[1.0, 0.0, 1.0, 1.0, 0.0, 1.0]);
/// let c = NurbsCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], p, vec![1.0, h, 1.0])?;
/// let x = c.try_eval(0.3)?;
/// assert!((x.norm() - 1.0).abs() < 1e-15);
/// assert!(NurbsCurve::new(1, vec![0.0, 0.0, 1.0, 1.0],
///     nalgebra::DMatrix::zeros(2, 2), vec![1.0, 0.0]).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsCurve<T: Scalar = f64> {
    homogeneous: BSplineCurve<T>,
}

impl<T: Scalar> NurbsCurve<T> {
    /// The curve of degree `degree` with `knots`, control points `points` (`d × n`, columns)
    /// and `weights` (length `n`).
    ///
    /// # Errors
    /// [`Error::NonPositiveWeight`] for a zero or negative weight, [`Error::ShapeMismatch`] if
    /// the number of weights differs from the number of points, and the errors of
    /// [`BSplineCurve::new`].
    pub fn new(degree: usize, knots: Vec<T>, points: DMatrix<T>, weights: Vec<T>) -> Result<Self> {
        crate::error::check_finite("NURBS control points", points.iter())?;
        let h = homogenize("NURBS curve weights", &points, &weights)?;
        Ok(NurbsCurve {
            homogeneous: BSplineCurve::new(degree, knots, h)?,
        })
    }

    /// The curve whose homogeneous form is `homogeneous` (last row = weights, the other rows
    /// weighted coordinates), as octave-nurbs `nrbmak`.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for fewer than 2 rows, [`Error::NonPositiveWeight`].
    pub fn from_homogeneous(homogeneous: BSplineCurve<T>) -> Result<Self> {
        let rows = homogeneous.control().nrows();
        if rows < 2 {
            return Err(Error::ShapeMismatch {
                what: "NURBS homogeneous control points",
                expected: "at least 2 rows (coordinates and weight)".into(),
                found: format!("{rows} row(s)"),
            });
        }
        check_weights(
            "NURBS curve weights",
            homogeneous.control().row(rows - 1).iter(),
        )?;
        let h = super::finish_homogeneous(
            "NURBS curve weights",
            rows - 1,
            homogeneous.control().clone(),
        )?;
        let (p, knots) = (
            homogeneous.degree(),
            homogeneous.knots().as_slice().to_vec(),
        );
        Ok(NurbsCurve {
            homogeneous: BSplineCurve::new(p, knots, h)?,
        })
    }

    /// A B-spline curve as a NURBS curve with all weights 1.
    pub fn from_bspline(curve: &BSplineCurve<T>) -> Self {
        let c = curve.control();
        let h = DMatrix::from_fn(c.nrows() + 1, c.ncols(), |r, k| {
            if r < c.nrows() {
                c[(r, k)].clone()
            } else {
                T::one()
            }
        });
        let knots = curve.knots().as_slice().to_vec();
        NurbsCurve {
            homogeneous: BSplineCurve::new(curve.degree(), knots, h).expect("valid B-spline"),
        }
    }

    /// The homogeneous B-spline curve in `ℝ^{d+1}`.
    pub fn homogeneous(&self) -> &BSplineCurve<T> {
        &self.homogeneous
    }

    /// The degree `p`.
    pub fn degree(&self) -> usize {
        self.homogeneous.degree()
    }

    /// The dimension `d` of the points.
    pub fn dim(&self) -> usize {
        self.homogeneous.dim() - 1
    }

    /// The knots.
    pub fn knots(&self) -> &[T] {
        self.homogeneous.knots().as_slice()
    }

    /// The domain `[u_p, u_n]`.
    pub fn domain(&self) -> (T, T) {
        self.homogeneous.domain()
    }

    /// The weights `w_k`.
    pub fn weights(&self) -> Vec<T> {
        let h = self.homogeneous.control();
        h.row(h.nrows() - 1).iter().cloned().collect()
    }

    /// The control points `P_k` (`d × n`, the homogeneous points divided by their weights).
    pub fn points(&self) -> DMatrix<T> {
        let h = self.homogeneous.control();
        let d = h.nrows() - 1;
        DMatrix::from_fn(d, h.ncols(), |r, c| h[(r, c)].clone() / h[(d, c)].clone())
    }

    /// The point `C(u)` for `u` in the domain: [`eval`](Self::eval)'s value, bit for bit.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for NaN or ±∞, [`Error::ParameterOutOfRange`] outside the domain.
    pub fn try_eval(&self, u: T) -> Result<DVector<T>> {
        let h = self.homogeneous.try_eval(u)?;
        crate::checked::point("NURBS curve point", self.dim(), project(&h))
    }

    /// The point `C(u)` for any `u`: [`try_eval`](Self::try_eval)'s value in the domain,
    /// outside it the first or last rational piece continued (its weight may vanish there,
    /// giving non-finite coordinates); for NaN or ±∞ a point of NaNs.
    ///
    /// ```
    /// use cagd::nurbs::NurbsCurve;
    /// // The line (0,0)–(2,0) with weights 1, 1 on [0, 1], continued to u = 2.
    /// let c = NurbsCurve::new(1, vec![0.0, 0.0, 1.0, 1.0],
    ///     nalgebra::dmatrix![0.0, 2.0; 0.0, 0.0], vec![1.0, 1.0])?;
    /// assert_eq!(c.eval(2.0).as_slice(), &[4.0, 0.0]);
    /// assert!(c.try_eval(2.0).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval(&self, u: T) -> DVector<T> {
        if !u.is_finite_value() {
            return DVector::from_element(self.dim(), u.clone() - u);
        }
        project(&self.homogeneous.eval(u))
    }

    /// The points at all parameters `us` written into `out`, one after the other:
    /// `out[k·d + c]` is coordinate `c` of `C(us[k])` (`us.len() × d` row-major; see
    /// [`crate::grid`]). As [`eval`](Self::eval), outside the domain the end pieces continue
    /// and a NaN or infinite parameter gives a point of NaNs.
    ///
    /// Per parameter the homogeneous point `Σ_i N_{s−p+i,p}(u) (w P, w)_{s−p+i}` is formed by
    /// the fast batch of [`BSplineCurve::eval_many_into`] (reciprocals of the knot differences
    /// once per span, the points of a span four at a time, no allocation per point, long
    /// batches on all cores) and multiplied by the reciprocal of its weight: one division per
    /// point. The rational basis is non-negative, so relative roundings add up as for
    /// B-splines, in the projected coordinates: on the domain
    /// `|C_batch(u) − C(u)| ≤ (7p + 3) ε · max_k |P_k|`, exact for rationals. [`eval_many_exact_order_into`](Self::eval_many_exact_order_into) does the
    /// operations of [`try_eval`](Self::try_eval) (and octave-nurbs `nrbeval`) instead.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · d`.
    ///
    /// ```
    /// use cagd::nurbs::NurbsCurve;
    /// let c = NurbsCurve::circle(1.0, &[0.0, 0.0])?;
    /// let ts = cagd::linspace(0.0, 1.0, 9);
    /// let mut out = vec![0.0; 9 * 2];
    /// c.eval_many_into(&ts, &mut out)?;
    /// for x in out.chunks_exact(2) {
    ///     assert!((x[0].hypot(x[1]) - 1.0).abs() < 1e-15);
    /// }
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_many_into(&self, us: &[T], out: &mut [T]) -> Result<()> {
        self.batch(us, out, curve_points_fast_into)
    }

    /// [`eval_many_into`](Self::eval_many_into) in the exact order of
    /// [`try_eval`](Self::try_eval): the homogeneous point as
    /// [`BSplineCurve::eval_many_exact_order_into`], each coordinate divided by the weight —
    /// the values of `try_eval` bit for bit. Outside the domain the end pieces continue, as in
    /// `eval`.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · d`.
    pub fn eval_many_exact_order_into(&self, us: &[T], out: &mut [T]) -> Result<()> {
        self.batch(us, out, curve_points_into)
    }

    /// Checks the buffer and runs a curve kernel on the homogeneous curve.
    fn batch(&self, us: &[T], out: &mut [T], kernel: CurveKernel<T>) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("NURBS curve points", &[us.len(), d])?;
        crate::grid::check_len("NURBS curve point buffer", len, out)?;
        crate::error::check_finite_slice("NURBS curve parameters", us)?;
        let h = &self.homogeneous;
        let knots = h.knots().as_slice();
        kernel(
            h.degree(),
            knots,
            h.control().as_slice(),
            d + 1,
            true,
            us,
            out,
        )
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
        let len = crate::grid::grid_len("NURBS curve points", &[us.len(), d])?;
        crate::grid::check_len("NURBS curve point buffer", len, out)?;
        let (lo, hi) = self.domain();
        for u in us {
            check_in_domain(u, &lo, &hi)?;
        }
        self.eval_many_exact_order_into(us, out)
    }

    /// The rational basis `R_{0,p}(u), …, R_{n−1,p}(u)` (the CAD notes eq. (4)).
    ///
    /// # Errors
    /// [`Error::ParameterOutOfRange`] outside the domain.
    pub fn basis(&self, u: &T) -> Result<Vec<T>> {
        let n = self.homogeneous.basis(u)?;
        let w = self.weights();
        let wn: Vec<T> = n
            .iter()
            .zip(&w)
            .map(|(a, b)| a.clone() * b.clone())
            .collect();
        let sum = wn.iter().fold(T::zero(), |s, x| s + x.clone());
        let r: Vec<T> = wn.into_iter().map(|x| x / sum.clone()).collect();
        crate::error::check_overflow("NURBS rational basis", r.iter())?;
        Ok(r)
    }

    /// The first derivative `C'(u) = (A'(u) − w'(u) C(u)) / w(u)`.
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] for degree 0, [`Error::ParameterOutOfRange`] outside the
    /// domain.
    pub fn try_eval_derivative(&self, u: T) -> Result<DVector<T>> {
        let a = self.homogeneous.try_eval(u.clone())?;
        let da = self.homogeneous.derivative()?.try_eval(u)?;
        let d = self.dim();
        let (w, dw) = (a[d].clone(), da[d].clone());
        let derivative = DVector::from_fn(d, |r, _| {
            let p = a[r].clone() / w.clone();
            (da[r].clone() - dw.clone() * p) / w.clone()
        });
        crate::checked::point("NURBS curve derivative", d, derivative)
    }

    /// The same curve with the knots `us` inserted (on the homogeneous curve, as
    /// `nrbkntins`); see [`BSplineCurve::insert_knots`].
    ///
    /// # Errors
    /// As [`BSplineCurve::insert_knots`].
    pub fn insert_knots(&self, us: &[T]) -> Result<Self> {
        Ok(NurbsCurve {
            homogeneous: self.homogeneous.insert_knots(us)?,
        })
    }
}

impl NurbsCurve<f64> {
    /// The circular arc of radius `radius` about `center` (2 or 3 coordinates; the arc lies
    /// in the plane z = center z) from angle `start` to `end` (radians, anticlockwise), built
    /// exactly as octave-nurbs `nrbcirc`: the sweep is split into 1–4 equal arcs of at most
    /// 90°, each a rational quadratic with middle weight `cos(Δ/2)`, joined with double knots.
    /// A negative sweep is taken modulo 2π.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite input, [`Error::InvalidArgument`] for a radius
    /// ≤ 0 or a center with other than 2 or 3 coordinates.
    ///
    /// ```
    /// use cagd::nurbs::NurbsCurve;
    /// let c = NurbsCurve::circle(2.0, &[1.0, -1.0])?;
    /// for k in 0..=16 {
    ///     let x = c.try_eval(k as f64 / 16.0)?;
    ///     let r = ((x[0] - 1.0).powi(2) + (x[1] + 1.0).powi(2)).sqrt();
    ///     assert!((r - 2.0).abs() < 1e-15);
    /// }
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn arc(radius: f64, center: &[f64], start: f64, end: f64) -> Result<Self> {
        let what = "circular arc";
        crate::error::check_finite(what, [radius, start, end].iter().chain(center))?;
        if radius <= 0.0 || !(center.len() == 2 || center.len() == 3) {
            return Err(Error::InvalidArgument {
                what,
                message: format!(
                    "expected a positive radius and a 2-D or 3-D center, got radius {radius} and {} coordinates",
                    center.len()
                ),
            });
        }
        use std::f64::consts::PI;
        // octave-nurbs' nrbcirc splits at most a full turn into quarter arcs; beyond a full turn
        // its middle weights cos(sweep/2n) turn negative. An arc is at most one turn: refuse more.
        if (end - start).abs() > 2.0 * PI {
            return Err(Error::InvalidArgument {
                what,
                message: format!(
                    "expected end − start within [−2π, 2π] (at most one full turn), got {} − {}",
                    end, start
                ),
            });
        }
        let mut sweep = end - start;
        if sweep < 0.0 {
            sweep += 2.0 * PI;
        }
        let (narcs, knots): (usize, Vec<f64>) = if sweep.abs() <= PI / 2.0 {
            (1, vec![0., 0., 0., 1., 1., 1.])
        } else if sweep.abs() <= PI {
            (2, vec![0., 0., 0., 0.5, 0.5, 1., 1., 1.])
        } else if sweep.abs() <= 3.0 * PI / 2.0 {
            (
                3,
                vec![0., 0., 0., 1. / 3., 1. / 3., 2. / 3., 2. / 3., 1., 1., 1.],
            )
        } else {
            (
                4,
                vec![0., 0., 0., 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1., 1., 1.],
            )
        };
        let dsweep = sweep / (2.0 * narcs as f64);
        let wm = dsweep.cos();
        let x = radius * wm;
        let y = radius * dsweep.sin();
        let xm = x + y * dsweep.tan();
        // Homogeneous (w·x, w·y, w·z, w) of the first arc, centred at the origin.
        let ctrl = [[x, -y, 0.0, 1.0], [wm * xm, 0.0, 0.0, wm], [x, y, 0.0, 1.0]];
        let rot = |angle: f64, p: &[f64; 4]| -> [f64; 4] {
            let (sn, cn) = (angle.sin(), angle.cos());
            [cn * p[0] + -sn * p[1], sn * p[0] + cn * p[1], p[2], p[3]]
        };
        let mut coefs: Vec<[f64; 4]> = ctrl.iter().map(|p| rot(start + dsweep, p)).collect();
        for n in 2..=narcs {
            for m in [2 * n - 1, 2 * n] {
                let prev = coefs[m - 2];
                coefs.push(rot(2.0 * dsweep, &prev));
            }
        }
        let cz = center.get(2).copied().unwrap_or(0.0);
        let dim = center.len();
        let h = DMatrix::from_fn(dim + 1, coefs.len(), |r, c| {
            let p = coefs[c];
            match r {
                _ if r == dim => p[3],
                0 => p[0] + center[0] * p[3],
                1 => p[1] + center[1] * p[3],
                _ => p[2] + cz * p[3],
            }
        });
        crate::error::check_overflow("circular arc control points", h.iter())?;
        Self::from_homogeneous(BSplineCurve::new(2, knots, h)?)
    }

    /// The full circle of radius `radius` about `center` (`nrbcirc(radius, center)`).
    ///
    /// # Errors
    /// As [`arc`](Self::arc).
    pub fn circle(radius: f64, center: &[f64]) -> Result<Self> {
        Self::arc(radius, center, 0.0, 2.0 * std::f64::consts::PI)
    }
}

/// A curve kernel of the B-spline module: degree, knots, control points, numbers per control
/// point, whether to project, parameters, output.
type CurveKernel<T> = fn(usize, &[T], &[T], usize, bool, &[T], &mut [T]) -> Result<()>;

/// `(x_1, …, x_d, w) ↦ (x_1/w, …, x_d/w)`.
pub(crate) fn project<T: Scalar>(h: &DVector<T>) -> DVector<T> {
    let d = h.len() - 1;
    DVector::from_fn(d, |r, _| h[r].clone() / h[d].clone())
}

impl<T: Scalar> Curve<T> for NurbsCurve<T> {
    fn dim(&self) -> usize {
        NurbsCurve::dim(self)
    }

    fn domain(&self) -> (T, T) {
        NurbsCurve::domain(self)
    }

    /// [`NurbsCurve::eval`]: the end pieces continue outside the domain.
    fn eval(&self, t: T) -> DVector<T> {
        NurbsCurve::eval(self, t)
    }

    fn try_eval(&self, t: T) -> Result<DVector<T>> {
        NurbsCurve::try_eval(self, t)
    }

    /// The homogeneous B-spline's cost ([`Curve::point_cost`] of
    /// [`homogeneous`](NurbsCurve::homogeneous)) and `d` divisions by the weight.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        super::rational_point_cost(Curve::point_cost(&self.homogeneous, param_bits), self.dim())
    }

    /// [`NurbsCurve::eval_many_into`]: the fast batch (reciprocals per span, one division and no
    /// allocation per point).
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        NurbsCurve::eval_many_into(self, ts, out)
    }
}

impl<T: Scalar> crate::param::CurveDeriv<T> for NurbsCurve<T> {
    /// The quotient rule `C' = (A' − w' C)/w` on the continued pieces (zero for degree 0).
    fn eval_derivative(&self, t: T) -> DVector<T> {
        let d = self.dim();
        let Ok(derivative) = self.homogeneous.derivative() else {
            return DVector::from_element(d, T::zero());
        };
        let da = derivative.eval(t.clone());
        let a = self.homogeneous.eval(t);
        let (w, dw) = (a[d].clone(), da[d].clone());
        DVector::from_fn(d, |r, _| {
            let p = a[r].clone() / w.clone();
            (da[r].clone() - dw.clone() * p) / w.clone()
        })
    }
}
