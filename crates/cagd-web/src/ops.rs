//! The page's way into the operation layer ([`cagd_ops`]): a view builds a request, runs it
//! here at the default limits, and reads the answer's items. Checks, their wording and the
//! work estimates are the operation's; the page names each role by its key (`control`, `t`,
//! `knots`), the words after the name being the same as on the command line.

use cagd::limits::Limits;
use cagd::Scalar;
use cagd_cli::{CliError, ErrorKind};
use cagd_ops::{Answer, OpError, Operation, Warning};

/// Runs `op` at the default limits: its answer and warnings.
///
/// # Errors
/// The operation's error, named by the role's key.
pub(crate) fn execute<T: Scalar, O: Operation<T> + ?Sized>(
    op: &O,
) -> Result<(Answer<T>, Vec<Warning>), CliError> {
    let mut cx = cagd_ops::Context::new(Limits::default());
    let answer = cagd_ops::execute(op, &mut cx).map_err(op_error)?;
    Ok((answer, cx.take_warnings()))
}

/// An operation's error as the page shows it: `ROLE: PROBLEM; expected FORM` (a limit is the
/// page's own: no flag raises it).
pub(crate) fn op_error(e: OpError) -> CliError {
    CliError::new(
        e.role.key(),
        e.problem,
        e.expected,
        ErrorKind::Operation(e.kind),
    )
}
