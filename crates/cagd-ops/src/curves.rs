//! The curve arguments of the constructions that take any curve (the boundaries of Coons
//! patches, the network of a Gordon surface, the rulings of a ruled surface): a curve of the
//! library — Bézier, B-spline, NURBS on their own domains — samples of a curve (the thesis's
//! data scripts), or a curve known only by evaluation (a user's expression), which the
//! construction evaluates exactly at the parameters it needs.

use cagd::param::SampledCurve;
use cagd::{Curve, CurveDeriv, Scalar};
use nalgebra::{DMatrix, DVector};

use crate::error::{lib, Kind, OpError, Result};
use crate::{Context, Role};

/// A function of one parameter known only by evaluation (an expression typed by the user):
/// the front end evaluates it; the construction decides where.
pub trait Evaluator<T: Scalar> {
    /// The values at `ts`, one column per parameter (`d × k`).
    ///
    /// # Errors
    /// What went wrong in the evaluation (about [`Role::Result`]; the construction names
    /// the argument).
    fn values(&self, ts: &[T]) -> Result<DMatrix<T>>;

    /// The first derivatives at `ts` (`d × k`).
    ///
    /// # Errors
    /// As [`values`](Self::values); also a function that cannot be differentiated.
    fn derivatives(&self, ts: &[T]) -> Result<DMatrix<T>>;

    /// The work of evaluating at all of `ts` (in units of one `f64` operation, exact
    /// arithmetic weighed), estimated or measured before any of it is done.
    fn work(&self, ts: &[T]) -> Work;
}

/// An evaluator's estimate of its work, and how it was made (the words of a refusal:
/// `estimated operations (samples × expression nodes)`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Work {
    /// The operations.
    pub operations: u128,
    /// What they count.
    pub what: &'static str,
}

/// A curve argument.
pub enum CurveArg<T: Scalar> {
    /// A curve of the library on its own domain (reparametrised onto `[0, 1]` by the
    /// construction).
    Curve(Box<dyn CurveDeriv<T> + Send + Sync>),
    /// Samples of a curve at increasing parameters (the thesis's data scripts): the polyline
    /// through them.
    Samples(SampledCurve<T>),
    /// A curve on `[0, 1]` known by evaluation.
    Evaluated(Box<dyn Evaluator<T>>),
}

impl<T: Scalar> std::fmt::Debug for CurveArg<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CurveArg::Curve(c) => write!(f, "Curve(dim {}, domain {:?})", c.dim(), c.domain()),
            CurveArg::Samples(s) => write!(f, "Samples({s:?})"),
            CurveArg::Evaluated(_) => write!(f, "Evaluated"),
        }
    }
}

impl<T: Scalar> CurveArg<T> {
    /// A library curve.
    pub fn curve(c: impl CurveDeriv<T> + Send + Sync + 'static) -> Self {
        CurveArg::Curve(Box::new(c))
    }

    /// The parameters of sampled data, if that is what this is.
    pub fn sample_params(&self) -> Option<&[T]> {
        match self {
            CurveArg::Samples(s) => Some(s.params()),
            _ => None,
        }
    }

    /// The work of evaluating the curve once at each of `at` (weighed in the arithmetic `T`).
    pub fn work(&self, at: &[T]) -> Work {
        let bits = cagd::cost::max_bits(at);
        let per = |c: &dyn Curve<T>| Work {
            operations: c.point_cost(bits).times(at.len() as u128).weigh(T::EXACT),
            what: "estimated operations",
        };
        match self {
            CurveArg::Curve(c) => per(c.as_ref()),
            CurveArg::Samples(s) => per(s),
            CurveArg::Evaluated(e) => e.work(at),
        }
    }

    /// The curve, ready for a construction that evaluates it at `at` (and where `with_derivatives`,
    /// its derivative there): an evaluated curve is evaluated exactly at those parameters.
    ///
    /// # Errors
    /// The evaluator's errors, about `role`.
    pub fn realise(&self, role: Role, at: &[T], with_derivatives: bool) -> Result<Realised<'_, T>> {
        match self {
            CurveArg::Curve(c) => Ok(Realised::Curve(c.as_ref())),
            CurveArg::Samples(s) => Ok(Realised::Samples(s)),
            CurveArg::Evaluated(e) => {
                let values = e.values(at).map_err(|err| err.about(role))?;
                let derivatives = if with_derivatives {
                    Some(e.derivatives(at).map_err(|err| err.about(role))?)
                } else {
                    None
                };
                Tabulated::new(at.to_vec(), values, derivatives)
                    .map(Realised::Tabulated)
                    .map_err(lib(
                        role,
                        "a curve whose values are points of one dimension",
                    ))
            }
        }
    }
}

/// A curve argument as a construction evaluates it.
pub enum Realised<'a, T: Scalar> {
    /// A library curve.
    Curve(&'a (dyn CurveDeriv<T> + Send + Sync)),
    /// A sampled polyline.
    Samples(&'a SampledCurve<T>),
    /// An evaluated curve at the parameters it was evaluated at.
    Tabulated(Tabulated<T>),
}

impl<T: Scalar> std::fmt::Debug for Realised<'_, T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Realised::Curve(c) => write!(f, "Curve(dim {}, domain {:?})", c.dim(), c.domain()),
            Realised::Samples(s) => write!(f, "Samples({s:?})"),
            Realised::Tabulated(t) => write!(f, "Tabulated({t:?})"),
        }
    }
}

impl<T: Scalar> Curve<T> for Realised<'_, T> {
    fn dim(&self) -> usize {
        match self {
            Realised::Curve(c) => c.dim(),
            Realised::Samples(s) => s.dim(),
            Realised::Tabulated(t) => t.dim(),
        }
    }
    fn domain(&self) -> (T, T) {
        match self {
            Realised::Curve(c) => c.domain(),
            Realised::Samples(s) => s.domain(),
            Realised::Tabulated(t) => t.domain(),
        }
    }
    fn eval(&self, t: T) -> DVector<T> {
        match self {
            Realised::Curve(c) => c.eval(t),
            Realised::Samples(s) => s.eval(t),
            Realised::Tabulated(c) => c.eval(t),
        }
    }
    fn point_cost(&self, param_bits: u128) -> cagd::cost::Cost {
        match self {
            Realised::Curve(c) => c.point_cost(param_bits),
            Realised::Samples(s) => s.point_cost(param_bits),
            Realised::Tabulated(t) => t.point_cost(param_bits),
        }
    }
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> cagd::Result<()> {
        match self {
            Realised::Curve(c) => c.eval_many_into(ts, out),
            Realised::Samples(s) => s.eval_many_into(ts, out),
            Realised::Tabulated(t) => t.eval_many_into(ts, out),
        }
    }
}

impl<T: Scalar> CurveDeriv<T> for Realised<'_, T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        match self {
            Realised::Curve(c) => c.eval_derivative(t),
            Realised::Samples(s) => s.eval_derivative(t),
            Realised::Tabulated(c) => c.eval_derivative(t),
        }
    }
}

/// A curve on `[0, 1]` evaluated exactly at some parameters (with its derivatives there, when
/// a construction needs them): at those parameters its values are the evaluations bit for
/// bit; between them the polyline (and the derivatives' polyline).
#[derive(Debug, Clone, PartialEq)]
pub struct Tabulated<T: Scalar> {
    values: SampledCurve<T>,
    derivatives: Option<SampledCurve<T>>,
}

impl<T: Scalar> Tabulated<T> {
    /// The curve with `values` (and `derivatives`) at `at` (sorted and without repeats by
    /// the caller, at least two).
    ///
    /// # Errors
    /// The errors of [`SampledCurve::new`].
    pub fn new(
        at: Vec<T>,
        values: DMatrix<T>,
        derivatives: Option<DMatrix<T>>,
    ) -> cagd::Result<Self> {
        let unit = |m: DMatrix<T>| {
            SampledCurve::new(at.clone(), m).and_then(|c| c.with_domain(T::zero(), T::one()))
        };
        Ok(Tabulated {
            values: unit(values)?,
            derivatives: derivatives.map(unit).transpose()?,
        })
    }
}

impl<T: Scalar> Curve<T> for Tabulated<T> {
    fn dim(&self) -> usize {
        self.values.dim()
    }
    fn domain(&self) -> (T, T) {
        self.values.domain()
    }
    fn eval(&self, t: T) -> DVector<T> {
        self.values.eval(t)
    }
    fn point_cost(&self, param_bits: u128) -> cagd::cost::Cost {
        self.values.point_cost(param_bits)
    }
}

impl<T: Scalar> CurveDeriv<T> for Tabulated<T> {
    /// The evaluated derivative at a tabulated parameter (the polyline of the derivatives
    /// between them); without evaluated derivatives, the chord's slope.
    fn eval_derivative(&self, t: T) -> DVector<T> {
        match &self.derivatives {
            Some(d) => d.eval(t),
            None => self.values.eval_derivative(t),
        }
    }
}

/// Sorted distinct values of `lists` together with 0 and 1: where an evaluated curve on
/// `[0, 1]` must be exact.
pub fn needed<T: Scalar>(lists: &[&[T]]) -> Vec<T> {
    let mut all: Vec<T> = vec![T::zero(), T::one()];
    for l in lists {
        all.extend(l.iter().cloned());
    }
    all.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    all.dedup();
    all
}

/// Refuses the work of evaluating `curves` (each with its role and parameters) above the
/// limit, naming the role with the largest share and saying how its work was estimated.
pub fn check_curves_work<T: Scalar>(
    cx: &Context,
    curves: &[(Role, &CurveArg<T>, &[T])],
) -> Result<()> {
    let works: Vec<(Role, Work)> = curves
        .iter()
        .map(|(role, c, at)| (*role, c.work(at)))
        .collect();
    let total = works
        .iter()
        .map(|w| w.1.operations)
        .fold(0u128, u128::saturating_add);
    let Some((role, largest)) = works.iter().max_by_key(|w| w.1.operations) else {
        return Ok(());
    };
    cx.limits
        .check_work(largest.what, total)
        .map_err(lib(*role, "fewer samples or shorter expressions"))
}

/// The dimension shared by `curves`, or an error naming the first that differs.
pub fn common_dim<T: Scalar>(curves: &[(Role, &dyn Curve<T>)]) -> Result<usize> {
    let Some((_, first)) = curves.first() else {
        return Ok(0);
    };
    let d = first.dim();
    match curves.iter().find(|(_, c)| c.dim() != d) {
        None => Ok(d),
        Some((role, c)) => Err(OpError::new(
            *role,
            Kind::Shape,
            format!(
                "a curve of dimension {}, the first is of dimension {d}",
                c.dim()
            ),
            "curves of one dimension",
        )),
    }
}
