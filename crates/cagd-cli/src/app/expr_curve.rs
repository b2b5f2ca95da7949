//! A user's expression as a curve the operation layer evaluates where it needs it
//! ([`cagd_ops::curves::Evaluator`]): `--c1 "[u; 0; u-u^2]"`, a script's curve, `--blend`.

use std::cell::RefCell;
use std::rc::Rc;

use cagd::limits::Limits;
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr, Warning};
use cagd_ops::curves::{Evaluator, Work};
use cagd_ops::{Kind, OpError, Role};
use nalgebra::DMatrix;

use super::work::Sampling;

/// The form of a curve expression, for error messages.
pub(crate) const CURVE_FORM: &str =
    "an expression in the curve parameter such as \"[u; 0; u-u^2]\"";

/// An expression in one parameter, evaluated in a shared environment (whose warnings the
/// command reports afterwards).
pub(crate) struct ExprCurve<T: LiteralScalar> {
    expr: ParamExpr,
    param: &'static str,
    env: Rc<RefCell<Env<T>>>,
    limits: Limits,
    form: &'static str,
}

impl<T: LiteralScalar> ExprCurve<T> {
    /// `expr` in `param`, evaluated in `env`; errors name `form` as what was expected.
    pub fn new(
        expr: ParamExpr,
        param: &'static str,
        env: Rc<RefCell<Env<T>>>,
        limits: Limits,
        form: &'static str,
    ) -> Self {
        ExprCurve {
            expr,
            param,
            env,
            limits,
            form,
        }
    }

    fn error(&self, e: cagd_octave::literal::LiteralError) -> OpError {
        OpError::new(Role::Result, Kind::Value, e.to_string(), self.form).caused_by(e)
    }
}

impl<T: LiteralScalar> Evaluator<T> for ExprCurve<T> {
    fn values(&self, ts: &[T]) -> cagd_ops::Result<DMatrix<T>> {
        let mut env = self.env.borrow_mut();
        self.expr
            .sample_curve(&mut env, self.param, ts)
            .map_err(|e| self.error(e))
    }

    /// The derivative expression ([`ParamExpr::derivative`]) sampled at `ts`, after its own
    /// work is checked (a derivative may be several times larger than its curve).
    fn derivatives(&self, ts: &[T]) -> cagd_ops::Result<DMatrix<T>> {
        let derivative = self
            .expr
            .derivative(self.param)
            .map_err(|e| self.error(e))?;
        let work = Sampling {
            expr: &derivative,
            params: vec![(self.param, ts)],
        }
        .work(&self.env.borrow(), &self.limits);
        self.limits
            .check_work(work.what, work.operations)
            .map_err(|e| {
                OpError::library(Role::Result, e, "fewer samples or a shorter expression")
            })?;
        let mut env = self.env.borrow_mut();
        derivative
            .sample_curve(&mut env, self.param, ts)
            .map_err(|e| self.error(e))
    }

    fn work(&self, ts: &[T]) -> Work {
        let env = self.env.borrow();
        let sampling = Sampling {
            expr: &self.expr,
            params: vec![(self.param, ts)],
        };
        sampling.work(&env, &self.limits)
    }
}

/// The warnings an environment collected, about `argument`.
pub(crate) fn env_warnings<T: LiteralScalar>(
    argument: &str,
    env: &Rc<RefCell<Env<T>>>,
) -> Vec<(String, Warning)> {
    env.borrow_mut()
        .take_warnings()
        .into_iter()
        .map(|w| (argument.to_string(), w))
        .collect()
}

/// The environment curve expressions are evaluated in, shared by a command's curves: the
/// data script's (its variables), else an empty one within the limits.
pub(crate) fn expression_env<T: LiteralScalar>(
    limits: Limits,
    script: Option<&cagd_octave::script::Script<T>>,
) -> Rc<RefCell<Env<T>>> {
    Rc::new(RefCell::new(
        script.map_or_else(|| Env::with_limits(limits), |s| s.env().clone()),
    ))
}

/// `outcome` with the warnings `env` collected (about `expression`) that it does not give
/// already: an environment copied from a data script repeats the script's warnings, which
/// are reported once, about the script.
pub(crate) fn with_env_warnings<T: LiteralScalar>(
    mut outcome: crate::Outcome,
    env: &Rc<RefCell<Env<T>>>,
) -> crate::Outcome {
    for (argument, w) in env_warnings("expression", env) {
        if !outcome.warnings.iter().any(|(_, given)| *given == w) {
            outcome.warnings.push((argument, w));
        }
    }
    outcome
}
