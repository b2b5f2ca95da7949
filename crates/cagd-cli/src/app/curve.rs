//! The curves of the command line: Bézier control points or samples of an expression, and
//! what evaluating one costs.

use cagd::bezier::BezierCurve;
use cagd::cost::Cost;
use cagd::{Curve, SampledCurve};
use cagd_octave::literal::LiteralScalar;
use nalgebra::DVector;

use super::work::bits;

/// A curve as the command line takes it, with its domain (what a Coons or Gordon construction
/// reparametrises onto `[0, 1]`).
#[derive(Debug, Clone)]
pub enum CliCurve<T: LiteralScalar> {
    /// A Bézier curve from control points, on `[0, 1]`.
    Bezier(BezierCurve<T>),
    /// Samples: an expression evaluated at every parameter the construction needs, on the
    /// domain `[0, 1]` even where the samples reach beyond it (the grid asked for them there);
    /// or a thesis-style sampled curve (a polyline between samples), on its first to last
    /// sample parameter (`linspace(0,1,N)` unless the data script gives others).
    Sampled(SampledCurve<T>),
}

impl<T: LiteralScalar> Curve<T> for CliCurve<T> {
    fn dim(&self) -> usize {
        match self {
            CliCurve::Bezier(b) => b.dim(),
            CliCurve::Sampled(s) => s.dim(),
        }
    }

    fn domain(&self) -> (T, T) {
        match self {
            CliCurve::Bezier(b) => b.domain(),
            CliCurve::Sampled(s) => s.domain(),
        }
    }

    fn eval(&self, t: T) -> DVector<T> {
        match self {
            CliCurve::Bezier(b) => b.eval(t),
            CliCurve::Sampled(s) => s.eval(t),
        }
    }

    fn point_cost(&self, param_bits: u128) -> Cost {
        match self {
            CliCurve::Bezier(b) => Curve::point_cost(b, param_bits),
            CliCurve::Sampled(s) => Curve::point_cost(s, param_bits),
        }
    }
}

impl<T: LiteralScalar> cagd::CurveDeriv<T> for CliCurve<T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        match self {
            CliCurve::Bezier(b) => b.eval_derivative(t),
            CliCurve::Sampled(s) => s.eval_derivative(t),
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

/// The rule of `cagd::param` for the command line's curves: the domain, `try_eval` inside it,
/// `eval` continuing outside.
#[cfg(test)]
#[test]
fn cli_curves_know_their_domain() {
    use cagd::Error;
    use nalgebra::{dmatrix, dvector};
    let bezier = CliCurve::Bezier(BezierCurve::new(dmatrix![0.0, 2.0]).unwrap());
    let samples = SampledCurve::new(vec![0.0, 1.0, 1.5], dmatrix![0.0, 1.0, 2.0]).unwrap();
    let expression = CliCurve::Sampled(samples.clone().with_domain(0.0, 1.0).unwrap());
    let sampled = CliCurve::Sampled(samples);
    assert_eq!(bezier.domain(), (0.0, 1.0));
    assert_eq!(expression.domain(), (0.0, 1.0));
    assert_eq!(sampled.domain(), (0.0, 1.5));
    for c in [&bezier, &expression, &sampled] {
        assert_eq!(c.try_eval(1.0).unwrap(), c.eval(1.0));
        assert!(matches!(
            c.try_eval(-0.5),
            Err(Error::ParameterOutOfRange { .. })
        ));
        assert!(matches!(c.try_eval(f64::NAN), Err(Error::NonFinite { .. })));
    }
    assert_eq!(bezier.eval(1.5), dvector![3.0]);
    assert_eq!(expression.eval(1.5), dvector![2.0]); // the sample there
    assert!(matches!(
        expression.try_eval(1.5),
        Err(Error::ParameterOutOfRange { .. })
    ));
    assert_eq!(sampled.try_eval(1.5).unwrap(), dvector![2.0]);
}
