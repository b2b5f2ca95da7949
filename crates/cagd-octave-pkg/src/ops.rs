//! The package's way into the operation layer ([`cagd_ops`]): a native function translates
//! its Octave arguments into a request, runs it here, and writes the answer's items as its
//! outputs. Checks, their wording and the work estimates are the operation's; the package
//! names each role as its function's usage does (`P`, `U`, `t`).

use cagd_ops::{OpError, Operation, Report, Role};

use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::number::Number;

/// How a function names the roles of its operation: `(role, Octave name)`.
pub type Names = &'static [(Role, &'static str)];

/// Runs `op` within the call's limits and returns its report (checked finite).
///
/// # Errors
/// The operation's error, named as `names` say.
pub fn execute<T: Number, O: Operation<T> + ?Sized>(
    call: &Call<'_, '_>,
    names: Names,
    op: &O,
) -> Result<Report<T>> {
    let mut cx = call.context();
    cagd_ops::execute(op, &mut cx)
        .map(|answer| answer.report)
        .map_err(|e| op_error(names, e))
}

/// An operation's error as the package raises it: `ARGUMENT: PROBLEM; expected FORM`, the
/// argument named as the function's usage names it, a limit with the call that raises it.
pub fn op_error(names: &[(Role, &str)], e: OpError) -> PkgError {
    if e.kind == cagd_ops::Kind::Interrupted {
        // Octave's own interrupt in the session; the same words as every other function.
        return PkgError::new(Kind::Interrupted, "interrupted");
    }
    let name = names
        .iter()
        .find(|(r, _)| *r == e.role)
        .map_or_else(|| e.role.key(), |(_, n)| *n);
    let mut problem = e.problem;
    if let Some(limit) = e.limit {
        problem = format!(
            "{problem} (raise it with cagd_limits (\"{}\", VALUE))",
            limit.field()
        );
    }
    PkgError::arg(Kind::from(e.kind), name, problem, &e.expected)
}
