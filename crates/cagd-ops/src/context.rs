//! What every request runs within: the resource limits, the warnings it collects, how its
//! steps are laid out, and a way to be interrupted. A value passed by the front end, never a
//! global: two requests on two threads never see each other's warnings.

use cagd::cost::Cost;
use cagd::limits::Limits;

use crate::error::{lib, Kind, OpError, Result};
use crate::Role;

/// A warning about a likely slip: how the input was read and what to write instead.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Warning {
    /// The role of the argument the warning is about.
    pub role: Role,
    /// The message, one line.
    pub message: String,
}

/// The context of a request.
///
/// ```
/// use cagd_ops::{Context, Role};
/// let mut cx = Context::new(cagd::Limits::default());
/// cx.warn(Role::T, "t = 2 lies outside [0, 1]; the curve is extrapolated there");
/// cx.warn(Role::T, "t = 2 lies outside [0, 1]; the curve is extrapolated there");
/// assert_eq!(cx.take_warnings().len(), 1); // each distinct warning once
/// ```
pub struct Context<'i> {
    /// The resource limits every check is made against.
    pub limits: Limits,
    /// Significant digits of the numbers in readable step layouts (de Casteljau triangles);
    /// exact numbers print in full.
    pub digits: usize,
    warnings: Vec<Warning>,
    interrupt: Option<&'i (dyn Fn() -> bool + Sync)>,
}

impl std::fmt::Debug for Context<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Context")
            .field("limits", &self.limits)
            .field("digits", &self.digits)
            .field("warnings", &self.warnings)
            .field("interruptible", &self.interrupt.is_some())
            .finish()
    }
}

impl<'i> Context<'i> {
    /// A context with `limits`, 15 significant digits and no interrupt.
    pub fn new(limits: Limits) -> Self {
        Context {
            limits,
            digits: crate::format::TEXT_DIGITS,
            warnings: Vec::new(),
            interrupt: None,
        }
    }

    /// The same context, asking `interrupted` every few milliseconds of long work (Octave's
    /// Ctrl-C, Python's signals): when it answers `true` the request stops with
    /// [`Kind::Interrupted`].
    pub fn with_interrupt(self, interrupted: &'i (dyn Fn() -> bool + Sync)) -> Self {
        Context {
            interrupt: Some(interrupted),
            ..self
        }
    }

    /// Records a warning about `role` (each distinct one once).
    pub fn warn(&mut self, role: Role, message: impl Into<String>) {
        let w = Warning {
            role,
            message: crate::error::one_line(&message.into()),
        };
        if !self.warnings.contains(&w) {
            self.warnings.push(w);
        }
    }

    /// The warnings recorded so far, in order; the context keeps none.
    pub fn take_warnings(&mut self) -> Vec<Warning> {
        std::mem::take(&mut self.warnings)
    }

    /// The warnings recorded so far.
    pub fn warnings(&self) -> &[Warning] {
        &self.warnings
    }

    /// Stops with [`Kind::Interrupted`] if the front end says the user asked to.
    pub fn check_interrupt(&self) -> Result<()> {
        match self.interrupt {
            Some(asked) if asked() => Err(OpError::new(
                Role::Result,
                Kind::Interrupted,
                "interrupted",
                "the computation to run to its end",
            )),
            _ => Ok(()),
        }
    }

    /// Refuses `cost` (in the arithmetic `exact` or not) above
    /// [`Limits::max_work`], about `role`.
    pub fn check_cost(&self, role: Role, cost: Cost, exact: bool) -> Result<()> {
        self.check_work(role, cost.weigh(exact))
    }

    /// Refuses a weighed `work` above [`Limits::max_work`], about `role`.
    pub fn check_work(&self, role: Role, work: u128) -> Result<()> {
        self.limits
            .check_work("estimated operations", work)
            .map_err(lib(role, "fewer points or a lower degree"))
    }

    /// Refuses a degree above [`Limits::max_degree`].
    pub fn check_degree(&self, role: Role, degree: usize) -> Result<()> {
        self.limits
            .check_degree("degree", degree)
            .map_err(lib(role, "a lower degree (fewer control points or nodes)"))
    }

    /// Refuses a grid of `nu × nv` points above [`Limits::max_grid_points`].
    pub fn check_grid(&self, role: Role, nu: usize, nv: usize) -> Result<()> {
        self.limits
            .check_grid("surface grid", nu, nv)
            .map_err(lib(role, "fewer grid points"))
    }
}
