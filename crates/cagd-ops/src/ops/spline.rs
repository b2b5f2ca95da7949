//! `spline`: the interpolating cubic spline (the lecture notes, "Kubické spline křivky"): a
//! Hermite cubic on each segment whose tangents make the second derivative continuous,
//!
//! `h_k x'_{k−1} + 2(h_{k−1} + h_k) x'_k + h_{k−1} x'_{k+1} = 3(h_k δ_{k−1} + h_{k−1} δ_k)`,
//!
//! closed by the end conditions of cases a (clamped: given tangents), b (natural: zero second
//! derivatives) and c (closed: periodic). Steps: the parameters, the linear system as the
//! lecture notes write it, and each segment's Hermite data and Bézier control points.

use cagd::cost::max_bits;
use cagd::spline::{interpolation_cost, sample_cost, CubicSpline, EndCondition, Parametrization};
use cagd::Scalar;
use nalgebra::DMatrix;

use super::hermite::vector;
use super::{eval_points, point_labels, to_f64};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::{Answer, Context, Item, Operation, Params, Report, Role, Value};

/// The form of the points and their parameters.
pub const POINTS_FORM: &str =
    "at least 2 points (3 for a closed spline) as columns, at strictly increasing parameters";

/// Samples per segment when no parameters are given.
pub const SAMPLES_PER_SEGMENT: usize = 10;

/// The end conditions (the lecture notes' cases a, b, c).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ends {
    /// Given end tangents (case a).
    Clamped,
    /// Zero second derivatives at the ends (case b).
    Natural,
    /// A closed, periodic spline (case c).
    Closed,
}

/// How the parameters of the points are chosen.
#[derive(Debug, Clone, PartialEq)]
pub enum Knots<T> {
    /// Uniform, chord length or centripetal.
    Chosen(Parametrization),
    /// These values: one per point, one more for a closed spline.
    Given(Vec<T>),
}

/// An interpolating cubic spline.
///
/// ```
/// use cagd_ops::ops::Spline;
/// use cagd_ops::{Context, Operation, Params};
/// use num_rational::BigRational;
/// use nalgebra::DMatrix;
/// let q = |a: i64| BigRational::from_integer(a.into());
/// // The lecture notes' case a: x-tangents 1, 31/15, 41/15, −1.
/// let op = Spline {
///     start_tangent: Some(DMatrix::from_column_slice(2, 1, &[q(1), q(1)])),
///     end_tangent: Some(DMatrix::from_column_slice(2, 1, &[q(-1), q(1)])),
///     t: Params::Given(vec![q(0)]),
///     ..Spline::new(DMatrix::from_column_slice(2, 4, &[0, 0, 2, 1, 4, 4, 6, 0].map(q)))
/// };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// let d = answer.report.matrix("tangents").unwrap();
/// assert_eq!(d[(0, 1)].to_string(), "31/15");
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Spline<T> {
    /// The points to interpolate, one per column.
    pub points: DMatrix<T>,
    /// The end condition (default: clamped when a tangent is given, else natural).
    pub ends: Option<Ends>,
    /// The tangent at the first point (clamped ends).
    pub start_tangent: Option<DMatrix<T>>,
    /// The tangent at the last point (clamped ends).
    pub end_tangent: Option<DMatrix<T>>,
    /// The parameters of the points (default uniform, `t_k = k`).
    pub knots: Knots<T>,
    /// The curve parameters (default [`SAMPLES_PER_SEGMENT`] samples per segment); a closed
    /// spline is periodic, an open one continues its end segments with a warning.
    pub t: Params<T>,
    /// `params`, `system`, `rhs` and every segment's `hermite` and `bezier` data.
    pub steps: bool,
    /// A picture: the spline over its parameters, the points, the points at `t`.
    pub drawing: bool,
}

impl<T: Scalar> Spline<T> {
    /// The natural spline through `points` at uniform parameters.
    pub fn new(points: DMatrix<T>) -> Self {
        Spline {
            points,
            ends: None,
            start_tangent: None,
            end_tangent: None,
            knots: Knots::Chosen(Parametrization::Uniform),
            t: Params::Default,
            steps: false,
            drawing: false,
        }
    }

    /// The end condition: chosen or by default, its tangents checked.
    fn end_condition(&self) -> Result<EndCondition<T>> {
        let given = [
            (Role::T0, &self.start_tangent),
            (Role::T1, &self.end_tangent),
        ];
        let any = given.iter().any(|(_, t)| t.is_some());
        let chosen = self
            .ends
            .unwrap_or(if any { Ends::Clamped } else { Ends::Natural });
        if chosen == Ends::Clamped {
            let need = |(role, t): (Role, &Option<DMatrix<T>>)| match t {
                Some(m) => vector(role, m),
                None => Err(OpError::new(
                    role,
                    Kind::Usage,
                    "missing with clamped ends",
                    "a tangent vector",
                )),
            };
            return Ok(EndCondition::Clamped {
                start: need(given[0])?,
                end: need(given[1])?,
            });
        }
        let name = if chosen == Ends::Natural {
            "natural"
        } else {
            "closed"
        };
        // A tangent that the end condition ignores is a slip, not a choice.
        if let Some((role, _)) = given.iter().find(|(_, t)| t.is_some()) {
            return Err(OpError::new(
                *role,
                Kind::Usage,
                format!("has no effect with {name} ends"),
                "clamped ends with both tangents, or no tangents",
            ));
        }
        Ok(if chosen == Ends::Natural {
            EndCondition::Natural
        } else {
            EndCondition::Closed
        })
    }

    /// The parameters of the points.
    fn params(&self, closed: bool) -> Result<Vec<T>> {
        let m = self.points.ncols();
        let count = m + usize::from(closed);
        match &self.knots {
            Knots::Given(list) if list.len() != count => {
                Err(OpError::new(
                    Role::Nodes,
                    Kind::Shape,
                    format!("{} value(s) for {m} point(s)", list.len()),
                    format!(
                    "uniform, chord, centripetal, or {count} increasing values (one per point{})",
                    if closed { " and one for the return to the first" } else { "" }
                ),
                ))
            }
            Knots::Given(list) => Ok(list.clone()),
            Knots::Chosen(Parametrization::Uniform) => Parametrization::Uniform
                .params(&self.points, closed)
                .map_err(lib(Role::Points, POINTS_FORM)),
            Knots::Chosen(_) if T::EXACT => Err(OpError::new(
                Role::Nodes,
                Kind::Usage,
                "chord-length and centripetal parameters are sums of square roots, not rational",
                "uniform parameters or a list of values in exact arithmetic",
            )),
            Knots::Chosen(c) => c.params(&self.points, closed).map_err(lib(
                Role::Points,
                "distinct consecutive points for chord-length or centripetal parameters",
            )),
        }
    }
}

impl<T: Scalar> Spline<T> {
    /// The spline: the end condition and the parameters of the points checked, the work of
    /// the interpolation (and of the given curve parameters) refused above the limit (a front
    /// end that keeps the spline builds it here).
    ///
    /// # Errors
    /// [`Kind::Usage`] about tangents the end condition needs or ignores; [`Kind::Shape`]
    /// about the parameters of the points; [`Kind::Limit`]; the library's errors.
    pub fn spline(&self, cx: &Context) -> Result<CubicSpline<T>> {
        let end = self.end_condition()?;
        let closed = matches!(end, EndCondition::Closed);
        let params = self.params(closed)?;
        let given = match &self.t {
            Params::Given(ts) => {
                crate::params::check_given(Role::T, ts, cx)?;
                Some(ts.as_slice())
            }
            _ => None,
        };
        cx.check_work(Role::Points, work(&self.points, &end, given))?;
        CubicSpline::interpolate_with_params(self.points.clone(), params, end).map_err(|e| {
            let role = match &e {
                cagd::Error::InvalidArgument {
                    what: "spline parameters",
                    ..
                }
                | cagd::Error::ShapeMismatch {
                    what: "spline parameters",
                    ..
                } => Role::Nodes,
                cagd::Error::ShapeMismatch {
                    what: "spline end tangents",
                    ..
                } => Role::T0,
                _ => Role::Points,
            };
            OpError::library(role, e, POINTS_FORM)
        })
    }
}

impl<T: Scalar> Operation<T> for Spline<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let s = self.spline(cx)?;
        let ts = self.parameters(&s, cx)?;
        let at: Vec<T> = ts.iter().map(|t| s.wrap(t)).collect();
        let mut report = Report::new();
        if self.steps {
            let (a, rhs) = s.system(&self.end_condition()?);
            report.push("params", Value::row(s.params()));
            report.push("system", Value::Matrix(a));
            report.push("rhs", Value::Matrix(rhs));
            for item in segments(&s)? {
                report.items.push(item);
            }
        }
        report.push("tangents", Value::Matrix(s.tangents().clone()));
        report.push("t", Value::row(&ts));
        let values = eval_points(&s, &at, Role::T, cx)?;
        report.push("result", Value::Matrix(values.clone()));
        let drawing = if self.drawing {
            let (first, last) = ends_of(&s);
            let samples = SAMPLES_PER_SEGMENT * s.segment_count() + 1;
            let line = crate::picture::curve_line(&s, (&first, &last), samples, Role::T, cx)?;
            Some(
                Drawing::new("interpolating cubic spline")
                    .curve(line, Colour::Blue, "spline")
                    .control_polygon(to_f64(s.points()), "points")
                    .points(to_f64(&values), point_labels("t", &ts), "points at t"),
            )
        } else {
            None
        };
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }
}

impl<T: Scalar> Spline<T> {
    /// The curve parameters: given (an open spline's outside `[t_0, t_last]` warned about),
    /// `N` samples, or [`SAMPLES_PER_SEGMENT`] per segment of `[t_0, t_last]`.
    fn parameters(&self, s: &CubicSpline<T>, cx: &mut Context) -> Result<Vec<T>> {
        let (first, last) = ends_of(s);
        match &self.t {
            Params::Default => {
                // Too many default samples is about the points (they make the segments).
                let count = SAMPLES_PER_SEGMENT * s.segment_count() + 1;
                cx.limits
                    .check_samples("samples (10 per segment)", count)
                    .map_err(lib(
                        Role::Points,
                        "fewer points (10 samples per segment), or given parameters",
                    ))?;
                crate::params::samples(count, (&first, &last), cx)
            }
            // A closed spline is periodic: every parameter is on the curve.
            Params::Given(ts) if s.is_closed() => {
                crate::params::check_given(Role::T, ts, cx)?;
                Ok(ts.clone())
            }
            t => t.resolve(
                Role::T,
                (&first, &last),
                "the end segments are extended there",
                cx,
            ),
        }
    }
}

/// The first and the last parameter of the spline.
fn ends_of<T: Scalar>(s: &CubicSpline<T>) -> (T, T) {
    let p = s.params();
    (p[0].clone(), p[p.len() - 1].clone())
}

/// The work of the spline through `points`: the (cyclic) tridiagonal solve
/// ([`interpolation_cost`]), then a cubic at every parameter ([`sample_cost`]; at `ts`, else
/// 10 per segment, whose parameters `k/10s` have about twice the bits of the sample count).
fn work<T: Scalar>(points: &DMatrix<T>, end: &EndCondition<T>, ts: Option<&[T]>) -> u128 {
    let (d, n) = (points.nrows(), points.ncols());
    let data_bits = match end {
        EndCondition::Clamped { start, end } => {
            max_bits(points.iter().chain(start.iter()).chain(end.iter()))
        }
        EndCondition::Closed | EndCondition::Natural => max_bits(points.iter()),
    };
    let default_samples = (SAMPLES_PER_SEGMENT * n) as u128 + 1;
    let samples = ts.map_or(default_samples, |t| t.len() as u128);
    let param_bits = ts.map_or(2 * (128 - default_samples.leading_zeros() as u128), |t| {
        max_bits(t)
    });
    interpolation_cost(n, d, end, data_bits)
        .weigh(T::EXACT)
        .saturating_add(
            sample_cost(n, d, data_bits, param_bits)
                .times(samples)
                .weigh(T::EXACT),
        )
}

/// Each segment's Hermite data `[x_k, x_{k+1}, h_k x'_k, h_k x'_{k+1}]` (over its own
/// parameter `u ∈ [0, 1]`) and the Bézier control points of the same cubic: records
/// `segment_1`, `segment_2`, ….
fn segments<T: Scalar>(s: &CubicSpline<T>) -> Result<Vec<Item<T>>> {
    let mut out = Vec::with_capacity(s.segment_count());
    for k in 0..s.segment_count() {
        let h = s.segment(k).map_err(lib(Role::Points, POINTS_FORM))?;
        let bezier = h.to_bezier().map_err(lib(
            Role::Points,
            "points whose segments' Bézier points stay within ±1.8e308",
        ))?;
        out.push(Item {
            name: format!("segment_{}", k + 1),
            value: Value::record(vec![
                ("hermite", Value::Matrix(h.geometry().clone())),
                ("bezier", Value::Matrix(bezier.control().clone())),
            ]),
        });
    }
    Ok(out)
}
