//! The capability traits every construction is written against.
//!
//! A Coons patch or a Gordon surface needs nothing from its boundary curves but their values
//! (and, for the bicubic constructions, their derivatives), so it takes any [`Curve`]: a Bézier
//! curve, a sampled polyline such as the thesis passes to `krpaCoons` (values at
//! `linspace(0,1,N)`), a closure, and later B-splines and NURBS.
//!
//! Points are `nalgebra::DVector`s of any dimension; all curves of one construction must share it.

use nalgebra::DVector;

use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// A parametric curve `t ↦ c(t) ∈ ℝ^d`, usually over `[0, 1]`.
pub trait Curve<T: Scalar = f64> {
    /// The dimension `d` of the points.
    fn dim(&self) -> usize;

    /// The point `c(t)`.
    fn eval(&self, t: T) -> DVector<T>;

    /// The first derivative `c'(t)`, where the curve knows it (`None` otherwise).
    fn eval_derivative(&self, t: T) -> Option<DVector<T>> {
        let _ = t;
        None
    }

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

/// A parametric surface `(u, v) ↦ x(u, v) ∈ ℝ^d`, usually over `[0, 1]²`.
pub trait Surface<T: Scalar = f64> {
    /// The dimension `d` of the points.
    fn dim(&self) -> usize;

    /// The point `x(u, v)`.
    fn eval(&self, u: T, v: T) -> DVector<T>;

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
    fn eval(&self, t: T) -> DVector<T> {
        (**self).eval(t)
    }
    fn eval_derivative(&self, t: T) -> Option<DVector<T>> {
        (**self).eval_derivative(t)
    }
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        (**self).eval_many_into(ts, out)
    }
}

impl<T: Scalar, C: Curve<T> + ?Sized> Curve<T> for Box<C> {
    fn dim(&self) -> usize {
        (**self).dim()
    }
    fn eval(&self, t: T) -> DVector<T> {
        (**self).eval(t)
    }
    fn eval_derivative(&self, t: T) -> Option<DVector<T>> {
        (**self).eval_derivative(t)
    }
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        (**self).eval_many_into(ts, out)
    }
}

/// A curve given by a closure (and optionally its derivative), e.g. the thesis's
/// `c1(u) = [u; 0; u - u^2]`.
pub struct FnCurve<F, D = fn(f64) -> DVector<f64>> {
    dim: usize,
    f: F,
    df: Option<D>,
}

impl<T: Scalar, F: Fn(T) -> DVector<T>> FnCurve<F, fn(T) -> DVector<T>> {
    /// A curve of dimension `dim` whose value at `t` is `f(t)` (no derivative).
    pub fn new(dim: usize, f: F) -> Self {
        FnCurve { dim, f, df: None }
    }
}

impl<F, D> FnCurve<F, D> {
    /// A curve with value `f(t)` and derivative `df(t)`.
    pub fn with_derivative(dim: usize, f: F, df: D) -> Self {
        FnCurve {
            dim,
            f,
            df: Some(df),
        }
    }
}

impl<T, F, D> Curve<T> for FnCurve<F, D>
where
    T: Scalar,
    F: Fn(T) -> DVector<T>,
    D: Fn(T) -> DVector<T>,
{
    fn dim(&self) -> usize {
        self.dim
    }
    fn eval(&self, t: T) -> DVector<T> {
        (self.f)(t)
    }
    fn eval_derivative(&self, t: T) -> Option<DVector<T>> {
        self.df.as_ref().map(|df| df(t))
    }
}

/// A curve known only by samples, as the thesis passes curves to `krpaCoons` and `krpaGordon`:
/// the points `samples[:, k]` at the increasing parameters `params[k]`, joined linearly.
///
/// At a sample parameter the value is the sample itself, bit for bit, so a construction
/// evaluated on the sampling grid reproduces the thesis code exactly. Outside
/// `[params[0], params[last]]` the end segments are extended linearly.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledCurve<T: Scalar = f64> {
    params: Vec<T>,
    samples: nalgebra::DMatrix<T>,
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
        Ok(SampledCurve { params, samples })
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

    fn eval_derivative(&self, t: T) -> Option<DVector<T>> {
        let k = self.segment(&t);
        let h = self.params[k + 1].clone() - self.params[k].clone();
        let p = self.samples.column(k);
        let q = self.samples.column(k + 1);
        Some(DVector::from_iterator(
            p.len(),
            p.iter()
                .zip(q.iter())
                .map(|(x, y)| (y.clone() - x.clone()) / h.clone()),
        ))
    }
}
