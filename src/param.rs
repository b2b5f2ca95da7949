//! The capability traits every construction is written against, and the one rule for their
//! parameters.
//!
//! A Coons patch or a Gordon surface needs nothing from its boundary curves but their values
//! (and, for the bicubic constructions, their derivatives), so it takes any [`Curve`]: a Bézier
//! curve, a sampled polyline such as the thesis passes to `krpaCoons` (values at
//! `linspace(0,1,N)`), a closure, a B-spline or a NURBS curve.
//!
//! Points are `nalgebra::DVector`s of any dimension; all curves of one construction must share it.
//!
//! # Domains
//!
//! Every curve knows the interval its parameter runs over, [`Curve::domain`] `= (start, end)`,
//! and every surface its rectangle, [`Surface::domain`] `= ((u_0, u_1), (v_0, v_1))`:
//!
//! | type | domain |
//! |---|---|
//! | [`BezierCurve`](crate::BezierCurve), [`MatrixForm`](crate::bezier::MatrixForm) | its interval `[a, b]`, `[0, 1]` unless built on another |
//! | [`BSplineCurve`](crate::BSplineCurve), [`NurbsCurve`](crate::NurbsCurve) | `[u_p, u_n]` of the knots (`BSplineCurve::uniform_cubic`: `[0, n − 3]`) |
//! | [`SampledCurve`] | the first to the last sample parameter, or what [`SampledCurve::with_domain`] sets |
//! | [`CubicSpline`](crate::CubicSpline), [`LagrangeInterpolant`](crate::lagrange::LagrangeInterpolant), [`ParametricInterpolant`](crate::interpolation::ParametricInterpolant) | the smallest to the largest parameter (node) |
//! | [`HermiteCubic`](crate::HermiteCubic) | `[0, 1]` |
//! | [`FnCurve`] | `[0, 1]`, or what [`FnCurve::with_domain`] sets |
//! | [`OnUnitInterval`] | `[0, 1]` |
//! | `&C`, `Box<C>` | that of `C` |
//! | [`BezierPatch`](crate::BezierPatch), Coons and Gordon surfaces, ruled, Ferguson and matrix patches | `[0, 1]²` |
//! | [`BSplineSurface`](crate::BSplineSurface), [`NurbsSurface`](crate::NurbsSurface) | `[u_p, u_nu] × [v_q, v_nv]` of the knots |
//!
//! # Evaluation: one rule for every curve and surface
//!
//! - **`eval` is total** — it never fails and never panics. On the domain it is the curve;
//!   outside it the curve's own formula continues: the one polynomial of a Bézier curve, a
//!   Hermite cubic, a Lagrange or matrix form; the first or last polynomial (rational) piece of
//!   a B-spline, NURBS curve or cubic spline; the first or last segment's line of a sampled
//!   curve; whatever the closure of an [`FnCurve`] returns; for surfaces, the same in each
//!   direction (a Coons, Gordon or ruled surface applies its formula to the continued curves).
//!   Nothing is clamped. A NaN or infinite parameter gives non-finite coordinates.
//! - **`try_eval` is `eval` on the domain**: for a parameter in the domain, ends included, it
//!   returns `eval`'s value bit for bit; it refuses a NaN or infinite parameter with
//!   [`Error::NonFinite`] and a finite one outside the domain with
//!   [`Error::ParameterOutOfRange`] (which names the domain).
//! - Batch evaluations follow the evaluation they batch: [`Curve::eval_many_into`],
//!   [`Surface::eval_grid_into`] and [`Surface::eval_grid`] as `eval`; `try_eval_many_into` and
//!   the B-spline and NURBS `eval_many` as `try_eval`. The thesis-shaped Bézier batches
//!   ([`BezierCurve::eval_many`](crate::BezierCurve::eval_many),
//!   [`BezierPatch::try_eval_grid`](crate::BezierPatch::try_eval_grid), the thesis's
//!   `deCasteljau` and `ploskevB` on any row of parameters) check only that the parameters
//!   are finite, and continue the polynomial outside `[0, 1]` as `eval` does.
//!
//! # Constructions that take curves: reparametrised onto `[0, 1]`
//!
//! Coons patches (bilinear, generalized, partially bicubic, bicubic with any twist, with given
//! corners), Gordon surfaces and ruled surfaces are defined over `[0, 1]²` as in the thesis and
//! the notes. Each curve they take is **reparametrised affinely** onto `[0, 1]` — a curve `c` on
//! `[a, b]` enters as `s ↦ c(a + (b − a)s)` ([`OnUnitInterval`]), its derivative as
//! `(b − a) c'(a + (b − a)s)` — so a boundary such as `BSplineCurve::uniform_cubic(…)` on
//! `[0, 4]` is used over its whole domain, and a curve already on `[0, 1]` is used unchanged,
//! bit for bit. A curve whose domain is not a finite interval `a < b` (an [`FnCurve`] on the
//! whole line, say) cannot be reparametrised and is refused with [`Error::UnusableDomain`],
//! which names the curve and its domain. Points are checked (corners, crossings) only after the
//! reparametrisation, so a curve on another interval is never reported as a corner mismatch.
//! [`continuity::curve_joint`](crate::continuity::curve_joint) takes the joint's parameters
//! explicitly and reparametrises nothing (continuity is a property of the curves' own
//! parametrisations). No construction of the crate takes surfaces.

use nalgebra::DVector;

use crate::cost::Cost;
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// A parametric curve `t ↦ c(t) ∈ ℝ^d` over its [domain](Curve::domain) (see the
/// [module documentation](self) for the rule `eval` and `try_eval` follow).
pub trait Curve<T: Scalar = f64> {
    /// The dimension `d` of the points.
    fn dim(&self) -> usize;

    /// The parameter domain `(start, end)`, `start ≤ end`: `start < end` for every curve of the
    /// crate except an interpolant through a single point (domain that one parameter); ends
    /// may be infinite only where a curve is defined everywhere (an [`FnCurve`] given that
    /// domain).
    fn domain(&self) -> (T, T);

    /// The point `c(t)`; outside the domain the curve's formula continued (never clamped).
    fn eval(&self, t: T) -> DVector<T>;

    /// The point `c(t)` for `t` in the domain: [`eval`](Self::eval)'s value, bit for bit.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite `t`, [`Error::ParameterOutOfRange`] for a
    /// finite `t` outside the domain.
    ///
    /// ```
    /// use cagd::{Curve, Error, FnCurve};
    /// use nalgebra::dvector;
    /// let c = FnCurve::new(1, |t: f64| dvector![t * t]).with_domain(-1.0, 2.0)?;
    /// assert_eq!(c.try_eval(2.0)?, dvector![4.0]);
    /// assert_eq!(c.eval(3.0), dvector![9.0]); // eval continues the curve
    /// assert!(matches!(c.try_eval(3.0), Err(Error::ParameterOutOfRange { min: -1.0, max: 2.0, .. })));
    /// assert!(matches!(c.try_eval(f64::NAN), Err(Error::NonFinite { .. })));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    fn try_eval(&self, t: T) -> Result<DVector<T>> {
        check_parameter("curve parameter", &t, &self.domain())?;
        Ok(self.eval(t))
    }

    /// What one evaluation costs ([`eval`](Self::eval) at a parameter of `param_bits` bits):
    /// the curve prices itself from its own data with the estimates of [`crate::cost`], so
    /// that a construction taking any curve (a Coons patch, a Gordon surface) can refuse its
    /// work before it starts.
    ///
    /// ```
    /// use cagd::{BezierCurve, Curve};
    /// use nalgebra::dmatrix;
    /// let c = BezierCurve::new(dmatrix![0.0, 1.0, 2.0; 0.0, 2.0, 0.0])?;
    /// assert_eq!(Curve::point_cost(&c, 0).ops(), 18); // d (n+1)²
    /// # Ok::<(), cagd::Error>(())
    /// ```
    fn point_cost(&self, param_bits: u128) -> Cost;

    /// The points at all parameters `ts`, written into `out` one after the other:
    /// `out[p·d + c]` is coordinate `c` of `c(ts[p])` (`ts.len() × d`, row-major; see
    /// [`crate::grid`]). Like [`eval`](Self::eval), any parameter is accepted.
    ///
    /// The default calls [`eval`](Self::eval) once per parameter; curves with a faster batch
    /// evaluation (Bézier curves: basis rows and no allocation per point) override it.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == ts.len() · d`.
    ///
    /// ```
    /// use cagd::{Curve, FnCurve};
    /// use nalgebra::dvector;
    /// let c = FnCurve::new(2, |t: f64| dvector![t, 2.0 * t]);
    /// let mut out = [0.0; 4];
    /// c.eval_many_into(&[0.5, 1.0], &mut out)?;
    /// assert_eq!(out, [0.5, 1.0, 1.0, 2.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("curve points", &[ts.len(), d])?;
        crate::grid::check_len("curve point buffer", len, out)?;
        if d == 0 {
            return Ok(());
        }
        for (t, p) in ts.iter().zip(out.chunks_exact_mut(d)) {
            let x = self.eval(t.clone());
            if x.len() != d {
                return Err(Error::ShapeMismatch {
                    what: "curve point",
                    expected: format!("{d} coordinates"),
                    found: format!("{} coordinates", x.len()),
                });
            }
            p.clone_from_slice(x.as_slice());
        }
        Ok(())
    }
}

/// A curve that knows its first derivative (as kurbo's `ParamCurveDeriv`): a construction
/// that needs tangents (the bicubically blended Coons patch, a continuity check) says so in
/// its bounds, so a curve without a derivative is refused by the compiler, never skipped at
/// run time.
///
/// ```
/// use cagd::{BezierCurve, CurveDeriv};
/// use nalgebra::dmatrix;
/// let c = BezierCurve::new(dmatrix![0.0, 1.0, 2.0; 0.0, 2.0, 0.0])?;
/// assert_eq!(CurveDeriv::eval_derivative(&c, 0.0).as_slice(), &[2.0, 4.0]); // n (b1 − b0)
/// # Ok::<(), cagd::Error>(())
/// ```
pub trait CurveDeriv<T: Scalar = f64>: Curve<T> {
    /// The first derivative `c'(t)`; outside the domain the derivative of the continued curve.
    fn eval_derivative(&self, t: T) -> DVector<T>;

    /// `c'(t)` for `t` in the domain.
    ///
    /// # Errors
    /// As [`Curve::try_eval`]: [`Error::NonFinite`], [`Error::ParameterOutOfRange`].
    fn try_eval_derivative(&self, t: T) -> Result<DVector<T>> {
        check_parameter("curve parameter", &t, &self.domain())?;
        Ok(self.eval_derivative(t))
    }
}

/// A parametric surface `(u, v) ↦ x(u, v) ∈ ℝ^d` over its [domain](Surface::domain) (see the
/// [module documentation](self) for the rule `eval` and `try_eval` follow).
pub trait Surface<T: Scalar = f64> {
    /// The dimension `d` of the points.
    fn dim(&self) -> usize;

    /// The parameter domain `((u_0, u_1), (v_0, v_1))`.
    fn domain(&self) -> ((T, T), (T, T));

    /// The point `x(u, v)`; outside the domain the surface's formula continued.
    fn eval(&self, u: T, v: T) -> DVector<T>;

    /// The point `x(u, v)` for `(u, v)` in the domain: [`eval`](Self::eval)'s value, bit for
    /// bit.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite parameter, [`Error::ParameterOutOfRange`]
    /// for a finite one outside the domain.
    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let (du, dv) = self.domain();
        check_parameter("surface parameter u", &u, &du)?;
        check_parameter("surface parameter v", &v, &dv)?;
        Ok(self.eval(u, v))
    }

    /// The surface on the grid `us × vs`, as an array of shape `(us.len(), vs.len(), d)`:
    /// `grid[[i, j, k]]` is coordinate `k` of `x(us[i], vs[j])`, the layout of `P(i,j,:)` in the
    /// thesis function `ploskevB`. Constructions override this with faster grid algorithms.
    fn eval_grid(&self, us: &[T], vs: &[T]) -> crate::grid::PointGrid<T> {
        let d = self.dim();
        let mut grid = crate::grid::PointGrid::from_elem((us.len(), vs.len(), d), T::zero());
        for (i, u) in us.iter().enumerate() {
            for (j, v) in vs.iter().enumerate() {
                let p = self.eval(u.clone(), v.clone());
                for k in 0..d {
                    grid[[i, j, k]] = p[k].clone();
                }
            }
        }
        grid
    }

    /// The surface on the grid `us × vs` written into `out`, row by row:
    /// `out[(a·nv + b)·d + c]` is coordinate `c` of `x(us[a], vs[b])` (`(nu, nv, d)`
    /// row-major, the memory layout of [`eval_grid`](Self::eval_grid); see [`crate::grid`]).
    /// Like [`eval`](Self::eval), any parameter is accepted.
    ///
    /// The default calls [`eval`](Self::eval) once per point; Bézier, Coons and Gordon
    /// surfaces override it with grid algorithms that allocate nothing per point.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · vs.len() · d`.
    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("surface grid", &[us.len(), vs.len(), d])?;
        crate::grid::check_len("surface grid buffer", len, out)?;
        if d == 0 {
            return Ok(());
        }
        let mut points = out.chunks_exact_mut(d);
        for u in us {
            for v in vs {
                let x = self.eval(u.clone(), v.clone());
                let p = points.next().expect("buffer length checked above");
                if x.len() != d {
                    return Err(Error::ShapeMismatch {
                        what: "surface point",
                        expected: format!("{d} coordinates"),
                        found: format!("{} coordinates", x.len()),
                    });
                }
                p.clone_from_slice(x.as_slice());
            }
        }
        Ok(())
    }
}

impl<T: Scalar, C: Curve<T> + ?Sized> Curve<T> for &C {
    fn dim(&self) -> usize {
        (**self).dim()
    }
    fn domain(&self) -> (T, T) {
        (**self).domain()
    }
    fn eval(&self, t: T) -> DVector<T> {
        (**self).eval(t)
    }
    fn try_eval(&self, t: T) -> Result<DVector<T>> {
        (**self).try_eval(t)
    }
    fn point_cost(&self, param_bits: u128) -> Cost {
        (**self).point_cost(param_bits)
    }
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        (**self).eval_many_into(ts, out)
    }
}

impl<T: Scalar, C: CurveDeriv<T> + ?Sized> CurveDeriv<T> for &C {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        (**self).eval_derivative(t)
    }
}

impl<T: Scalar, C: Curve<T> + ?Sized> Curve<T> for Box<C> {
    fn dim(&self) -> usize {
        (**self).dim()
    }
    fn domain(&self) -> (T, T) {
        (**self).domain()
    }
    fn eval(&self, t: T) -> DVector<T> {
        (**self).eval(t)
    }
    fn try_eval(&self, t: T) -> Result<DVector<T>> {
        (**self).try_eval(t)
    }
    fn point_cost(&self, param_bits: u128) -> Cost {
        (**self).point_cost(param_bits)
    }
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        (**self).eval_many_into(ts, out)
    }
}

impl<T: Scalar, C: CurveDeriv<T> + ?Sized> CurveDeriv<T> for Box<C> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        (**self).eval_derivative(t)
    }
}

/// A curve given by a closure (and optionally its derivative), e.g. the thesis's
/// `c1(u) = [u; 0; u - u^2]`, over the domain `[0, 1]` unless
/// [`with_domain`](FnCurve::with_domain) says otherwise. Outside its domain `eval` calls the
/// closure all the same (the closure is the curve's formula).
///
/// [`FnCurve::new`] makes a [`Curve`]; [`FnCurve::with_derivative`] also a [`CurveDeriv`].
/// A closure's work is unknown to the crate: [`Curve::point_cost`] counts `dim` operations
/// unless [`with_cost`](FnCurve::with_cost) says more (a closure is the Rust caller's own code,
/// not untrusted input).
///
/// The scalar `T` of the domain is the closures' parameter type; a type written
/// `FnCurve<F, D>` with `D` a function pointer `fn(T) -> DVector<T>` takes it from `D`
/// (`f64` for [`NoDerivative`]).
#[derive(Clone)]
pub struct FnCurve<F, D = NoDerivative, T = <D as FnParameter>::Parameter> {
    dim: usize,
    f: F,
    df: D,
    domain: (T, T),
    cost: Option<Cost>,
}

/// The derivative of an [`FnCurve`] made by [`FnCurve::new`]: none (such a curve is not a
/// [`CurveDeriv`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct NoDerivative;

impl<F, D, T: std::fmt::Debug> std::fmt::Debug for FnCurve<F, D, T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FnCurve")
            .field("dim", &self.dim)
            .field("domain", &self.domain)
            .finish_non_exhaustive()
    }
}

/// The parameter type `T` of a function pointer `fn(T) -> R`: how `FnCurve<F, D>` names the
/// scalar of its domain from the type of its derivative.
pub trait FnParameter {
    /// The type `T` of the parameter.
    type Parameter;
}

impl<T, R> FnParameter for fn(T) -> R {
    type Parameter = T;
}

impl FnParameter for NoDerivative {
    type Parameter = f64;
}

impl<T: Scalar, F: Fn(T) -> DVector<T>> FnCurve<F, NoDerivative, T> {
    /// A curve of dimension `dim` whose value at `t` is `f(t)` (no derivative), on `[0, 1]`.
    pub fn new(dim: usize, f: F) -> Self {
        FnCurve {
            dim,
            f,
            df: NoDerivative,
            domain: (T::zero(), T::one()),
            cost: None,
        }
    }
}

impl<T: Scalar, F: Fn(T) -> DVector<T>, D> FnCurve<F, D, T> {
    /// A curve with value `f(t)` and derivative `df(t)`, on `[0, 1]`.
    pub fn with_derivative(dim: usize, f: F, df: D) -> Self
    where
        D: Fn(T) -> DVector<T>,
    {
        FnCurve {
            dim,
            f,
            df,
            domain: (T::zero(), T::one()),
            cost: None,
        }
    }

    /// The same curve, one evaluation of which costs `cost` ([`Curve::point_cost`]).
    pub fn with_cost(self, cost: Cost) -> Self {
        FnCurve {
            cost: Some(cost),
            ..self
        }
    }

    /// The same curve on the domain `[start, end]`. Infinite ends are allowed (a closure may
    /// be defined everywhere), but constructions that reparametrise their curves onto
    /// `[0, 1]` refuse such a curve with [`Error::UnusableDomain`].
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN end, [`Error::EmptyInterval`] unless `start < end`.
    ///
    /// ```
    /// use cagd::{Curve, FnCurve};
    /// use nalgebra::dvector;
    /// let c = FnCurve::new(2, |t: f64| dvector![t.cos(), t.sin()]).with_domain(0.0, std::f64::consts::PI)?;
    /// assert_eq!(c.domain(), (0.0, std::f64::consts::PI));
    /// assert!(FnCurve::new(1, |t: f64| dvector![t]).with_domain(1.0, 1.0).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn with_domain(self, start: T, end: T) -> Result<Self> {
        for (index, x) in [&start, &end].into_iter().enumerate() {
            if x.partial_cmp(x).is_none() {
                return Err(Error::NonFinite {
                    what: "curve domain",
                    index,
                    value: f64::NAN,
                });
            }
        }
        if start >= end {
            return Err(Error::EmptyInterval {
                what: "curve domain",
                a: start.to_f64(),
                b: end.to_f64(),
            });
        }
        Ok(FnCurve {
            domain: (start, end),
            ..self
        })
    }
}

impl<T, F, D> Curve<T> for FnCurve<F, D, T>
where
    T: Scalar,
    F: Fn(T) -> DVector<T>,
{
    fn dim(&self) -> usize {
        self.dim
    }
    fn domain(&self) -> (T, T) {
        self.domain.clone()
    }
    fn eval(&self, t: T) -> DVector<T> {
        (self.f)(t)
    }
    fn point_cost(&self, param_bits: u128) -> Cost {
        self.cost
            .unwrap_or_else(|| Cost::new(self.dim as u128, param_bits))
    }
}

impl<T, F, D> CurveDeriv<T> for FnCurve<F, D, T>
where
    T: Scalar,
    F: Fn(T) -> DVector<T>,
    D: Fn(T) -> DVector<T>,
{
    fn eval_derivative(&self, t: T) -> DVector<T> {
        (self.df)(t)
    }
}

/// A curve known only by samples, as the thesis passes curves to `krpaCoons` and `krpaGordon`:
/// the points `samples[:, k]` at the increasing parameters `params[k]`, joined linearly.
///
/// At a sample parameter the value is the sample itself, bit for bit, so a construction
/// evaluated on the sampling grid reproduces the thesis code exactly. The domain is
/// `[params[0], params[last]]` unless [`with_domain`](SampledCurve::with_domain) sets another
/// (a curve on `[0, 1]` sampled also where a construction needs it beyond); outside the sample
/// parameters the end segments are extended linearly.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledCurve<T: Scalar = f64> {
    params: Vec<T>,
    samples: nalgebra::DMatrix<T>,
    domain: (T, T),
}

impl<T: Scalar> SampledCurve<T> {
    /// Samples `samples` (d × N, one point per column) at the strictly increasing `params`
    /// (length N ≥ 2).
    pub fn new(params: Vec<T>, samples: nalgebra::DMatrix<T>) -> Result<Self> {
        if params.len() != samples.ncols() {
            return Err(Error::ShapeMismatch {
                what: "sampled curve",
                expected: format!(
                    "{} parameter values (one per sample column)",
                    samples.ncols()
                ),
                found: format!("{}", params.len()),
            });
        }
        if params.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "sampled curve",
                min: 2,
                found: params.len(),
            });
        }
        crate::error::check_finite("sampled curve parameters", params.iter())?;
        crate::error::check_finite("sampled curve points", samples.iter())?;
        if let Some(k) = params.windows(2).position(|w| w[0] >= w[1]) {
            return Err(Error::InvalidArgument {
                what: "sampled curve parameters",
                message: format!(
                    "expected strictly increasing values, but value {} ({}) is not below value {} ({})",
                    k,
                    params[k],
                    k + 1,
                    params[k + 1]
                ),
            });
        }
        let domain = (params[0].clone(), params[params.len() - 1].clone());
        Ok(SampledCurve {
            params,
            samples,
            domain,
        })
    }

    /// The same samples on the domain `[start, end]`, which need not be the range of the
    /// sample parameters: an expression on `[0, 1]` sampled also at `1.5` (because a grid asks
    /// for it there) is still a curve on `[0, 1]`, and a construction reparametrises that.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite end, [`Error::EmptyInterval`] unless
    /// `start < end`.
    ///
    /// ```
    /// use cagd::{Curve, SampledCurve};
    /// use nalgebra::dmatrix;
    /// let c = SampledCurve::new(vec![0.0, 1.0, 1.5], dmatrix![0.0, 2.0, 3.0])?;
    /// assert_eq!(c.domain(), (0.0, 1.5));
    /// let c = c.with_domain(0.0, 1.0)?;
    /// assert_eq!(c.domain(), (0.0, 1.0));
    /// assert_eq!(c.eval(1.5).as_slice(), &[3.0]); // the sample, outside the domain
    /// assert!(c.try_eval(1.5).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn with_domain(self, start: T, end: T) -> Result<Self> {
        crate::error::check_finite("sampled curve domain", [&start, &end])?;
        if start >= end {
            return Err(Error::EmptyInterval {
                what: "sampled curve domain",
                a: start.to_f64(),
                b: end.to_f64(),
            });
        }
        Ok(SampledCurve {
            domain: (start, end),
            ..self
        })
    }

    /// The sample parameters.
    pub fn params(&self) -> &[T] {
        &self.params
    }

    /// The samples, one point per column.
    pub fn samples(&self) -> &nalgebra::DMatrix<T> {
        &self.samples
    }

    /// The cost of the point at one parameter of `param_bits` bits: a binary search among the
    /// `N` parameters (`log₂ N` comparisons) and a copy of the sample (`d`) where the parameter
    /// is one, on numbers of `sample_bits + param_bits` bits.
    ///
    /// ```
    /// use cagd::{cost::Cost, SampledCurve};
    /// let c = SampledCurve::new(vec![0.0, 0.5, 1.0, 1.5], nalgebra::DMatrix::zeros(3, 4))?;
    /// assert_eq!(c.eval_cost(2, 7), Cost::new(3 + 2, 9));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_cost(&self, param_bits: u128, sample_bits: u128) -> crate::cost::Cost {
        crate::cost::Cost::new(
            self.samples.nrows() as u128 + (self.params.len() as u128).ilog2() as u128,
            sample_bits.saturating_add(param_bits),
        )
    }

    /// Index `k` of the segment `[params[k], params[k+1]]` that holds `t` (clamped to the ends).
    fn segment(&self, t: &T) -> usize {
        let last = self.params.len() - 2;
        // partition_point: number of params <= t.
        let above = self.params.partition_point(|p| p <= t);
        above.saturating_sub(1).min(last)
    }
}

impl<T: Scalar> Curve<T> for SampledCurve<T> {
    fn dim(&self) -> usize {
        self.samples.nrows()
    }

    fn domain(&self) -> (T, T) {
        self.domain.clone()
    }

    fn eval(&self, t: T) -> DVector<T> {
        let k = self.segment(&t);
        if t == self.params[k] {
            return self.samples.column(k).into_owned();
        }
        if t == self.params[k + 1] {
            return self.samples.column(k + 1).into_owned();
        }
        let (a, b) = (&self.params[k], &self.params[k + 1]);
        let s = (t - a.clone()) / (b.clone() - a.clone());
        let one_minus = T::one() - s.clone();
        let p = self.samples.column(k);
        let q = self.samples.column(k + 1);
        DVector::from_iterator(
            p.len(),
            p.iter()
                .zip(q.iter())
                .map(|(x, y)| one_minus.clone() * x.clone() + s.clone() * y.clone()),
        )
    }

    fn point_cost(&self, param_bits: u128) -> Cost {
        let sample_bits = self.samples.iter().map(Scalar::bits).max().unwrap_or(0);
        self.eval_cost(param_bits, sample_bits)
    }
}

/// The derivative of the polyline: on each segment the slope of its chord (at a sample
/// parameter, the segment that starts there; the last one at the end).
impl<T: Scalar> CurveDeriv<T> for SampledCurve<T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        let k = self.segment(&t);
        let h = self.params[k + 1].clone() - self.params[k].clone();
        let p = self.samples.column(k);
        let q = self.samples.column(k + 1);
        DVector::from_iterator(
            p.len(),
            p.iter()
                .zip(q.iter())
                .map(|(x, y)| (y.clone() - x.clone()) / h.clone()),
        )
    }
}

/// A curve on `[a, b]` seen on `[0, 1]`: `s ↦ c(a + (b − a)s)`, the affine reparametrisation
/// through which Coons patches, Gordon surfaces and ruled surfaces take their curves (see the
/// [module documentation](self)).
///
/// The parameter maps `0 ↦ a` and `1 ↦ b` exactly and stays in `[a, b]` for `s ∈ [0, 1]`;
/// outside `[0, 1]` it continues affinely (so `eval` continues the curve, as everywhere). The
/// derivative is `(b − a) c'(a + (b − a)s)`. A curve already on `[0, 1]` is passed through
/// untouched, so its values are the same bit for bit.
///
/// ```
/// use cagd::bspline::BSplineCurve;
/// use cagd::{Curve, OnUnitInterval};
/// use nalgebra::DMatrix;
/// // The uniform cubic B-spline through (0,0), (6,6), (12,0), ends replicated: domain [0, 4].
/// let x = DMatrix::from_column_slice(2, 3, &[0.0, 0.0, 6.0, 6.0, 12.0, 0.0]);
/// let c = BSplineCurve::uniform_cubic(&x, true)?;
/// let unit = OnUnitInterval::new(&c, "the example curve")?;
/// assert_eq!(unit.domain(), (0.0, 1.0));
/// assert_eq!(unit.eval(1.0), c.eval(4.0));
/// assert_eq!(unit.eval(0.5), c.eval(2.0));
/// use cagd::CurveDeriv;
/// assert_eq!(unit.eval_derivative(0.5), 4.0 * c.eval_derivative(2.0));
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct OnUnitInterval<C, T: Scalar = f64> {
    curve: C,
    start: T,
    end: T,
}

impl<T: Scalar, C: Curve<T>> OnUnitInterval<C, T> {
    /// `curve` reparametrised from its domain onto `[0, 1]`; `what` names the curve in the
    /// error.
    ///
    /// # Errors
    /// [`Error::UnusableDomain`] unless the domain `[a, b]` has finite ends and `a < b`.
    ///
    /// ```
    /// use cagd::{Error, FnCurve, OnUnitInterval};
    /// use nalgebra::dvector;
    /// let line = FnCurve::new(1, |t: f64| dvector![t]).with_domain(0.0, f64::INFINITY)?;
    /// let err = OnUnitInterval::new(line, "the line").unwrap_err();
    /// assert!(matches!(err, Error::UnusableDomain { what: "the line", start: 0.0, end: f64::INFINITY }));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn new(curve: C, what: &'static str) -> Result<Self> {
        let (start, end) = usable_domain(what, &curve)?;
        Ok(OnUnitInterval { curve, start, end })
    }
}

impl<C, T: Scalar> OnUnitInterval<C, T> {
    /// `curve` on `[start, end]`, already checked by [`usable_domain`].
    pub(crate) fn from_checked(curve: C, (start, end): (T, T)) -> Self {
        OnUnitInterval { curve, start, end }
    }

    /// The curve in its own parameter.
    pub fn curve(&self) -> &C {
        &self.curve
    }

    /// The curve in its own parameter, by value.
    pub fn into_inner(self) -> C {
        self.curve
    }

    /// The curve's own domain `[a, b]`.
    pub fn original_domain(&self) -> (T, T) {
        (self.start.clone(), self.end.clone())
    }

    /// The curve's parameter `t = a + (b − a)s` of the unit parameter `s` (exactly `a` at 0
    /// and `b` at 1, inside `[a, b]` for `s ∈ [0, 1]`).
    pub fn parameter(&self, s: T) -> T {
        to_domain(&self.start, &self.end, s)
    }

    /// Whether the curve's domain is `[0, 1]` already.
    fn is_identity(&self) -> bool {
        self.start.is_zero() && self.end.is_one()
    }
}

impl<T: Scalar, C: Curve<T>> Curve<T> for OnUnitInterval<C, T> {
    fn dim(&self) -> usize {
        self.curve.dim()
    }

    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }

    fn eval(&self, s: T) -> DVector<T> {
        self.curve.eval(self.parameter(s))
    }

    /// The curve's own cost at a parameter `a + (b − a)s`: the mapping's three operations
    /// (none on `[0, 1]`) on numbers of the parameter, the ends and `s` together.
    fn point_cost(&self, param_bits: u128) -> Cost {
        if self.is_identity() {
            return self.curve.point_cost(param_bits);
        }
        let mapped = param_bits
            .saturating_add(self.start.bits())
            .saturating_add(self.end.bits())
            .saturating_add(2);
        self.curve.point_cost(mapped).and(Cost::new(3, mapped))
    }

    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        if self.is_identity() {
            return self.curve.eval_many_into(ts, out);
        }
        let mapped: Vec<T> = ts.iter().map(|s| self.parameter(s.clone())).collect();
        self.curve.eval_many_into(&mapped, out)
    }
}

/// `(b − a) c'(a + (b − a)s)`.
impl<T: Scalar, C: CurveDeriv<T>> CurveDeriv<T> for OnUnitInterval<C, T> {
    fn eval_derivative(&self, s: T) -> DVector<T> {
        let d = self.curve.eval_derivative(self.parameter(s));
        if self.is_identity() {
            return d;
        }
        let scale = self.end.clone() - self.start.clone();
        d.map(|x| scale.clone() * x)
    }
}

/// `a + (b − a)s`, exactly `a` at `s = 0`, `b` at `s = 1`, and `s` itself for `[a, b] = [0, 1]`;
/// kept inside `[a, b]` for `s ∈ [0, 1]` (rounding could otherwise step just outside).
pub(crate) fn to_domain<T: Scalar>(a: &T, b: &T, s: T) -> T {
    if a.is_zero() && b.is_one() {
        return s;
    }
    if s.is_zero() {
        return a.clone();
    }
    if s.is_one() {
        return b.clone();
    }
    let inside = s > T::zero() && s < T::one();
    let t = a.clone() + (b.clone() - a.clone()) * s;
    if inside && &t > b {
        b.clone()
    } else if inside && &t < a {
        a.clone()
    } else {
        t
    }
}

/// The domain of `curve` if a construction can reparametrise it onto `[0, 1]`: finite ends,
/// start below end.
///
/// # Errors
/// [`Error::UnusableDomain`] naming `what` and the domain otherwise.
pub(crate) fn usable_domain<T: Scalar, C: Curve<T> + ?Sized>(
    what: &'static str,
    curve: &C,
) -> Result<(T, T)> {
    let (start, end) = curve.domain();
    if start.is_finite_value() && end.is_finite_value() && start < end {
        Ok((start, end))
    } else {
        Err(Error::UnusableDomain {
            what,
            start: start.to_f64(),
            end: end.to_f64(),
        })
    }
}

/// `Ok` for a parameter in `[lo, hi]`; [`Error::NonFinite`] for NaN or ±∞,
/// [`Error::ParameterOutOfRange`] for a finite parameter outside: the check of every
/// `try_eval`.
pub(crate) fn check_parameter<T: Scalar>(
    what: &'static str,
    t: &T,
    (lo, hi): &(T, T),
) -> Result<()> {
    if !t.is_finite_value() {
        return Err(Error::NonFinite {
            what,
            index: 0,
            value: t.to_f64(),
        });
    }
    if t < lo || t > hi {
        return Err(Error::ParameterOutOfRange {
            what,
            value: t.to_f64(),
            min: lo.to_f64(),
            max: hi.to_f64(),
        });
    }
    Ok(())
}
