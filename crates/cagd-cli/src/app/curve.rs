//! The curves of the command line: Bézier control points or samples of an expression, and
//! what evaluating one costs.

use cagd::bezier::BezierCurve;
use cagd::{Curve, SampledCurve};
use cagd_octave::literal::LiteralScalar;
use nalgebra::DVector;

use super::work::{bits, polynomial_bits};

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

/// What evaluating `curve` at one of `params` costs: (operations, bits its values reach).
/// A Bézier curve is a de Casteljau scheme (`d (n+1)²` operations on numbers of
/// [`polynomial_bits`]); a sampled curve is looked up (a binary search, then a copy of the
/// sample where the construction needs it).
pub fn curve_cost<T: LiteralScalar>(curve: &CliCurve<T>, params: &[T]) -> (u128, u128) {
    match curve {
        CliCurve::Bezier(b) => (
            b.dim() as u128 * (b.degree() as u128 + 1).pow(2),
            polynomial_bits(b.degree(), bits(params), bits(b.control().iter())),
        ),
        CliCurve::Sampled(s) => (
            s.dim() as u128 + (s.params().len() as u128).ilog2() as u128,
            bits(s.samples().iter()).saturating_add(bits(params)),
        ),
    }
}

/// [`curve_cost`] of each `(curve, parameters)` pair, for [`super::work::blend_work`].
pub fn curve_costs<T: LiteralScalar>(curves: &[(&CliCurve<T>, &[T])]) -> Vec<(u128, u128)> {
    curves
        .iter()
        .map(|(c, params)| curve_cost(c, params))
        .collect()
}
