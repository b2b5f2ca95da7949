//! Estimates of a command's work, made before it starts and refused above
//! [`cagd::limits::Limits::max_work`] (`--max-work`, `CAGD_MAX_WORK`).
//!
//! An estimate is a [`Cost`]: a number of arithmetic operations, each weighing 1 in `f64` and,
//! with `--exact`, [`cagd::limits::exact_op_cost`] of the size its numbers reach, so that an
//! allowed command finishes in seconds in either arithmetic. Each construction estimates
//! itself in the library, beside its code ([`cagd::cost`] lists them); the command line
//! measures the sizes of its inputs ([`bits`]), multiplies by the points it asks for, and
//! weighs the result ([`weigh`]). A user expression is measured instead of estimated: it is
//! evaluated once at its largest parameter values ([`check_expression_work`]).

use crate::args::PlotArgs;
use crate::CliError;
use cagd::cost::Cost;
use cagd::limits::Limits;
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr};

use crate::error::lib;

/// The work of `cost` in the arithmetic `T`: its operations in `f64`, each weighed by
/// [`cagd::limits::exact_op_cost`] of its size in exact arithmetic ([`Cost::weigh`]).
pub fn weigh<T: LiteralScalar>(cost: Cost) -> u128 {
    cost.weigh(T::EXACT)
}

/// The most bits of any of `xs` (numerator and denominator together; 0 for `f64` and for
/// none).
pub fn bits<'a, T: LiteralScalar + 'a>(xs: impl IntoIterator<Item = &'a T>) -> u128 {
    if T::EXACT {
        xs.into_iter().map(T::bits).max().unwrap_or(0)
    } else {
        0
    }
}

/// The parameters of a picture, if `--plot` asks for one (else none): what an estimate
/// counts for it.
pub fn plotted<'a, T>(plot: &PlotArgs, params: &'a [T]) -> &'a [T] {
    if plot.plot.is_some() {
        params
    } else {
        &[]
    }
}

/// Refuses an estimated `work` above [`Limits::max_work`], naming `argument`.
pub fn check_work(limits: &Limits, argument: &str, work: u128) -> Result<(), CliError> {
    limits.check_work("estimated operations", work).map_err(lib(
        argument,
        "fewer points or a lower degree, or a higher --max-work",
    ))
}

/// A user expression to be sampled: the argument that gave it, the expression, and the values
/// of each of its free parameters (one list for a curve; `u` and `v` for a surface, sampled
/// at every pair).
pub struct Sampling<'a, T: LiteralScalar> {
    /// The argument (`EXPR`, `--c1`, `--u-curve`, …).
    pub argument: &'a str,
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
        let by_nodes = weigh::<T>(Cost::new(nodes, param_bits));
        match self.expr.eval_metered(env, &bindings) {
            Ok((_, measured)) => {
                let scale = if T::EXACT { 8 } else { 1 };
                by_nodes.max(measured.saturating_mul(scale))
            }
            Err(_) => by_nodes,
        }
    }
}

/// Refuses sampling user expressions whose estimated work is above
/// [`Limits::max_work`]: first samples × expression size ([`ParamExpr::node_count`]), which
/// needs no evaluation, then samples × the measured work of one sample
/// ([`Sampling::per_sample`]). The error names the argument with the largest share.
pub fn check_expression_work<T: LiteralScalar>(
    limits: &Limits,
    parts: &[Sampling<'_, T>],
    env: &Env<T>,
) -> Result<(), CliError> {
    let by_size: Vec<(&str, u128)> = parts
        .iter()
        .map(|p| {
            let cost = p.samples().saturating_mul(p.expr.node_count() as u128);
            (p.argument, cost)
        })
        .collect();
    refuse_above(
        limits,
        "estimated operations (samples × expression nodes)",
        &by_size,
    )?;
    let measured: Vec<(&str, u128)> = parts
        .iter()
        .map(|p| (p.argument, p.samples().saturating_mul(p.per_sample(env))))
        .collect();
    refuse_above(
        limits,
        "estimated operations (samples × work of one sample)",
        &measured,
    )
}

/// Refuses the sum of `costs` above [`Limits::max_work`], naming the argument of the largest.
fn refuse_above(
    limits: &Limits,
    what: &'static str,
    costs: &[(&str, u128)],
) -> Result<(), CliError> {
    let total = costs.iter().map(|c| c.1).fold(0u128, u128::saturating_add);
    let argument = costs.iter().max_by_key(|c| c.1).map_or("EXPR", |c| c.0);
    limits
        .check_work(what, total)
        .map_err(lib(
            argument,
            "fewer samples (a smaller --n, --t, --u, --v) or a shorter expression, or a higher --max-work",
        ))
}
