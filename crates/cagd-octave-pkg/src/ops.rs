//! The package's way into the operation layer ([`cagd_ops`]): a native function translates
//! its Octave arguments into a request, runs it here, and writes the answer's items as its
//! outputs. Checks, their wording and the work estimates are the operation's; the package
//! names each role as its function's usage does (`P`, `U`, `t`).

use cagd_ops::{Operation, Report, Role};

use crate::args::Call;
use crate::error::Result;
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

pub use crate::error::op_error;
