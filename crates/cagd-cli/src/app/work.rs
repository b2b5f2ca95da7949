//! The work of sampling a user expression, measured rather than estimated: the expression is
//! evaluated once at its largest parameter values ([`Sampling::work`]), and the operation
//! layer refuses it above [`cagd::limits::Limits::max_work`] (`--max-work`, `CAGD_MAX_WORK`).

use cagd::cost::Cost;
use cagd::limits::Limits;
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr};

/// The work of `cost` in the arithmetic `T`: its operations in `f64`, each weighed by
/// [`cagd::limits::exact_op_cost`] of its size in exact arithmetic ([`Cost::weigh`]).
pub fn weigh<T: LiteralScalar>(cost: Cost) -> u128 {
    cost.weigh(T::EXACT)
}

/// A user expression to be sampled: the expression and the values
/// of each of its free parameters (one list for a curve; `u` and `v` for a surface, sampled
/// at every pair).
pub struct Sampling<'a, T: LiteralScalar> {
    /// The expression.
    pub expr: &'a ParamExpr,
    /// Each free parameter and its values.
    pub params: Vec<(&'a str, &'a [T])>,
}

impl<T: LiteralScalar> Sampling<'_, T> {
    /// The estimated work of all the samples: samples × expression size, and, unless that is
    /// over the limit already, samples × the measured work of one sample
    /// ([`per_sample`](Self::per_sample)).
    pub fn work(&self, env: &Env<T>, limits: &Limits) -> cagd_ops::curves::Work {
        let by_size = self
            .samples()
            .saturating_mul(self.expr.node_count() as u128);
        if by_size > limits.max_work as u128 {
            return cagd_ops::curves::Work {
                operations: by_size,
                what: "estimated operations (samples × expression nodes)",
            };
        }
        cagd_ops::curves::Work {
            operations: by_size.max(self.samples().saturating_mul(self.per_sample(env))),
            what: "estimated operations (samples × work of one sample)",
        }
    }

    fn samples(&self) -> u128 {
        self.params
            .iter()
            .map(|(_, values)| values.len() as u128)
            .fold(1, u128::saturating_mul)
    }

    /// The estimated work of one sample: the larger of `node_count` operations on numbers the
    /// size of the parameters, and the work of one evaluation at the largest value of each
    /// parameter, measured by the evaluator ([`ParamExpr::eval_metered`]: element
    /// operations; an exact operation on operands of `a` and `b` words counts `32 (a + b)²`,
    /// an eighth of [`cagd::limits::exact_op_cost`] at one word and more beyond 16 words, so in exact
    /// arithmetic 8 times that). If that evaluation fails, the node count stands and
    /// sampling reports the error.
    fn per_sample(&self, env: &Env<T>) -> u128 {
        let nodes = self.expr.node_count() as u128;
        let largest = |values: &[T]| values.iter().max_by_key(|x| x.bits()).cloned();
        let Some(bindings) = self
            .params
            .iter()
            .map(|(name, values)| largest(values).map(|x| (*name, x)))
            .collect::<Option<Vec<(&str, T)>>>()
        else {
            return nodes;
        };
        let param_bits: u128 = bindings.iter().map(|(_, x)| x.bits()).sum();
        let by_nodes = weigh::<T>(self.expr.point_cost(param_bits));
        match self.expr.eval_metered(env, &bindings) {
            Ok((_, measured)) => {
                let scale = if T::EXACT { 8 } else { 1 };
                by_nodes.max(measured.saturating_mul(scale))
            }
            Err(_) => by_nodes,
        }
    }
}
