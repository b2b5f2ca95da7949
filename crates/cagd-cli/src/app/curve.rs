//! The curves of the command line: Bézier control points or samples of an expression, and
//! what evaluating one costs.

use cagd::bezier::BezierCurve;
use cagd::cost::Cost;
use cagd::{Curve, SampledCurve};
use cagd_octave::literal::LiteralScalar;
use nalgebra::DVector;

use super::work::bits;

/// A curve as the command line takes it.
#[derive(Debug, Clone)]
pub enum CliCurve<T: LiteralScalar> {
    /// A Bézier curve from control points.
    Bezier(BezierCurve<T>),
    /// Samples: an expression evaluated at every parameter the construction needs, or a
    /// thesis-style sampled curve (a polyline between samples).
    Sampled(SampledCurve<T>),
}

impl<T: LiteralScalar> Curve<T> for CliCurve<T> {
    fn dim(&self) -> usize {
        match self {
            CliCurve::Bezier(b) => b.dim(),
            CliCurve::Sampled(s) => s.dim(),
        }
    }

    fn eval(&self, t: T) -> DVector<T> {
        match self {
            CliCurve::Bezier(b) => b.eval(t),
            CliCurve::Sampled(s) => s.eval(t),
        }
    }

    fn eval_derivative(&self, t: T) -> Option<DVector<T>> {
        match self {
            CliCurve::Bezier(b) => Some(b.eval_derivative(t)),
            CliCurve::Sampled(_) => None,
        }
    }
}

/// What evaluating `curve` at one of `params` costs: a Bézier curve is a de Casteljau scheme
/// ([`BezierCurve::eval_cost`]), a sampled curve is looked up ([`SampledCurve::eval_cost`]),
/// on numbers the size of the parameters and of the curve's points.
pub fn curve_cost<T: LiteralScalar>(curve: &CliCurve<T>, params: &[T]) -> Cost {
    match curve {
        CliCurve::Bezier(b) => b.eval_cost(bits(params), bits(b.control().iter())),
        CliCurve::Sampled(s) => s.eval_cost(bits(params), bits(s.samples().iter())),
    }
}

/// [`curve_cost`] of each `(curve, parameters)` pair, for the blends of
/// [`cagd::cost::blended`].
pub fn curve_costs<T: LiteralScalar>(curves: &[(&CliCurve<T>, &[T])]) -> Vec<Cost> {
    curves
        .iter()
        .map(|(c, params)| curve_cost(c, params))
        .collect()
}
