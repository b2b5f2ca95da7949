//! The package's way into the operation layer ([`cagd_ops`]): a class or function translates
//! its Python arguments into a request (or into the operation layer's checks of one), runs it
//! here, and translates the report back. The checks, their words and the work estimates are
//! the operation layer's, the same as the command line's, the Octave package's and the page's;
//! the package names each role as its Python signature does ([`Names`]).
//!
//! **The context.** Every request runs in a [`Context`] with the interpreter's limits
//! ([`crate::limits::current`]) and with the interpreter's lock released, so that other
//! Python threads run meanwhile. Its interrupt ([`Context::with_interrupt`]) takes the lock
//! back for a moment between chunks of the work (every few thousand points) and asks Python
//! whether a signal arrived (`PyErr_CheckSignals`, which runs the handlers only on the main
//! thread): Ctrl-C stops the request, which raises the handler's exception
//! (`KeyboardInterrupt`) instead of a `CagdError`.

use std::sync::Mutex;

use cagd::Scalar;
use cagd_ops::{Context, Kind, Operation, Report};
use pyo3::prelude::*;

use crate::error::op_error;
pub use crate::error::{Names, OpIntoPy};

/// The exception a signal handler raised while a request ran.
#[derive(Default)]
struct Signals {
    raised: Mutex<Option<PyErr>>,
}

impl Signals {
    /// Whether a signal handler raised: the lock taken back for the check.
    fn asked(&self) -> bool {
        Python::attach(|py| match py.check_signals() {
            Ok(()) => false,
            Err(e) => {
                *self.raised.lock().unwrap_or_else(|p| p.into_inner()) = Some(e);
                true
            }
        })
    }

    fn take(&self) -> Option<PyErr> {
        self.raised.lock().unwrap_or_else(|p| p.into_inner()).take()
    }
}

/// Runs `f` in a context of the interpreter's limits that Ctrl-C interrupts, with the lock
/// released; its error as `cagd.CagdError` named by `names` (or the signal handler's
/// exception).
///
/// # Errors
/// `f`'s error; `KeyboardInterrupt`.
pub fn with_context<R: Send>(
    py: Python<'_>,
    names: Names,
    f: impl FnOnce(&mut Context) -> cagd_ops::Result<R> + Send,
) -> PyResult<R> {
    let signals = Signals::default();
    let limits = crate::limits::current();
    let result = py.detach(|| {
        let asked = || signals.asked();
        let mut cx = Context::new(limits).with_interrupt(&asked);
        f(&mut cx)
    });
    result.map_err(|e| match signals.take() {
        Some(raised) if e.kind == Kind::Interrupted => raised,
        _ => op_error(names, e),
    })
}

/// The operation layer's checks `f` of arguments that a call then hands to the core itself
/// (an evaluation of a kept object), in a context of the interpreter's limits; the lock kept.
///
/// # Errors
/// `f`'s error as `cagd.CagdError` named by `names`.
pub fn checked(names: Names, f: impl FnOnce(&Context) -> cagd_ops::Result<()>) -> PyResult<()> {
    f(&Context::new(crate::limits::current())).named(names)
}

/// Refuses a NaN or ±Inf among `values` in the operation layer's words
/// ([`cagd_ops::check::non_finite`]) about the argument `name`, for values a call hands to
/// the core itself (the thesis functions' arrays, counted in Octave's column-major order).
///
/// # Errors
/// `CagdError` of kind `NonFinite`.
pub fn finite<'a, T: Scalar + 'a>(
    name: &str,
    values: impl IntoIterator<Item = &'a T>,
) -> PyResult<()> {
    match cagd_ops::check::non_finite(values) {
        None => Ok(()),
        Some((problem, expected)) => {
            Err(crate::error::worded("NonFinite", name, &problem, expected))
        }
    }
}

/// Runs the request `op` ([`cagd_ops::execute`]: its answer checked finite) and returns its
/// report.
///
/// # Errors
/// As [`with_context`].
pub fn execute<T: Scalar + Send, O: Operation<T> + Sync>(
    py: Python<'_>,
    names: Names,
    op: &O,
) -> PyResult<Report<T>> {
    with_context(py, names, |cx| {
        cagd_ops::execute(op, cx).map(|answer| answer.report)
    })
}

/// The matrix `name` of a report (every request's documented item).
///
/// # Errors
/// An internal error if the request did not answer it.
pub fn item<T: Scalar>(report: &Report<T>, name: &str) -> PyResult<nalgebra::DMatrix<T>> {
    report.matrix(name).cloned().ok_or_else(|| {
        crate::error::cagd_error(
            "Internal",
            None,
            format!("the request answered no item '{name}'"),
        )
    })
}
