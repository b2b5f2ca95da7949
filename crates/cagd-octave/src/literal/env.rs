//! [`Env`]: the variables an expression may read, the limits in force, the warnings collected.

use std::collections::{BTreeMap, BTreeSet};

use nalgebra::DMatrix;

use cagd::limits::Limits;

use super::{LiteralScalar, Position, Warning};

/// Variables bound to matrices, the limits in force, and the warnings collected while
/// evaluating.
#[derive(Debug, Clone, PartialEq)]
pub struct Env<T: LiteralScalar = f64> {
    pub(crate) vars: BTreeMap<String, DMatrix<T>>,
    pub(crate) warnings: BTreeSet<Warning>,
    pub(crate) limits: Limits,
    pub(crate) meter: Meter,
}

impl<T: LiteralScalar> Default for Env<T> {
    fn default() -> Self {
        Env {
            vars: BTreeMap::new(),
            warnings: BTreeSet::new(),
            limits: Limits::default(),
            meter: Meter::default(),
        }
    }
}

impl<T: LiteralScalar> Env<T> {
    /// An empty environment with the default [`Limits`].
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty environment with the given limits.
    pub fn with_limits(limits: Limits) -> Self {
        Env {
            limits,
            ..Self::default()
        }
    }

    /// The limits in force.
    pub fn limits(&self) -> &Limits {
        &self.limits
    }

    /// Binds `name` to a matrix (replacing any previous value).
    pub fn bind(&mut self, name: &str, value: DMatrix<T>) {
        self.vars.insert(name.to_string(), value);
    }

    /// Binds `name` to a scalar (a 1×1 matrix).
    pub fn bind_scalar(&mut self, name: &str, value: T) {
        self.bind(name, DMatrix::from_element(1, 1, value));
    }

    /// Removes a binding.
    pub fn unbind(&mut self, name: &str) -> Option<DMatrix<T>> {
        self.vars.remove(name)
    }

    /// The value bound to `name`.
    pub fn get(&self, name: &str) -> Option<&DMatrix<T>> {
        self.vars.get(name)
    }

    /// All bound names, sorted.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.vars.keys().map(String::as_str)
    }

    /// The warnings collected so far, sorted by position.
    pub fn warnings(&self) -> impl Iterator<Item = &Warning> {
        self.warnings.iter()
    }

    /// Removes and returns the warnings collected so far.
    pub fn take_warnings(&mut self) -> Vec<Warning> {
        std::mem::take(&mut self.warnings).into_iter().collect()
    }

    pub(crate) fn warn(&mut self, at: Position, message: String) {
        self.warnings.insert(Warning { at, message });
    }
}

/// Work done by the evaluation in progress: nesting of `eval` calls and the number of element
/// results (and matrix-product terms) computed since the outermost call began. Bounds the
/// time of one evaluation to `64 × max_elements` element operations, so that a short text
/// (`A*A*A*…` of large matrices, long chains of large sums) cannot run for minutes.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Meter {
    pub(crate) depth: usize,
    pub(crate) work: u128,
}

impl Meter {
    /// The work of the last (or current) outermost evaluation.
    pub(crate) fn work(&self) -> u128 {
        self.work
    }
}

/// Meters never make two environments different.
impl PartialEq for Meter {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}
