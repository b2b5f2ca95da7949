//! `cagd_limits`: the resource limits of the Octave session.
//!
//! The limits are one [`Limits`] value, held by the oct-file for the session and passed to
//! every call (the library reads no global setting). Sizes over them are refused before
//! anything is allocated, with `cagd:limit` and a message naming the limit:
//! `max_samples` (parameter values along one axis, `N`), `max_grid_points` (points of a surface
//! grid), `max_degree` (degree of a curve or patch direction, nodes − 1), `max_work`
//! (arithmetic operations of one call, estimated up front), and for exact text input
//! `max_expression_bytes`, `max_depth`, `max_elements`.

use cagd::limits::{Limit, Limits};

use crate::args::{count_of, text_of};
use crate::error::{limit_by_name, Kind, PkgError, Result};
use crate::value::{Sink, Value};

/// `[names, values] = __cagd__ ("cagd_limits", …)`: with no argument the limits in force;
/// with `("default")` the defaults restored; with `(name, value)` one limit set. Returns
/// (after the change) the field names (a cell column) and their values (a column).
///
/// # Errors
/// [`Kind::Nargin`], [`Kind::Value`] for an unknown name or a value that is not a positive
/// integer.
pub fn cagd_limits(
    args: &[Value<'_>],
    nargout: usize,
    limits: &mut Limits,
    sink: &mut dyn Sink,
) -> Result<()> {
    let names: Vec<&str> = Limit::ALL.iter().map(|l| l.field()).collect();
    let form = format!("one of {}", names.join(", "));
    match args.len() {
        0 => {}
        1 => {
            let word = text_of(&args[0], "NAME", "\"default\" or NAME, VALUE")?;
            if word != "default" {
                return Err(PkgError::arg(
                    Kind::Value,
                    "NAME",
                    format!("'{word}' without a value"),
                    "\"default\" or NAME, VALUE",
                ));
            }
            *limits = Limits::default();
        }
        2 => {
            let name = text_of(&args[0], "NAME", &form)?;
            let limit = limit_by_name(&name).ok_or_else(|| {
                PkgError::arg(Kind::Value, "NAME", format!("no limit '{name}'"), &form)
            })?;
            let value = count_of(&args[1], "VALUE")?;
            if value == 0 {
                return Err(PkgError::arg(
                    Kind::Value,
                    "VALUE",
                    "0",
                    "a positive integer",
                ));
            }
            limits.set(limit, value as u64);
        }
        n => {
            return Err(PkgError::new(
                Kind::Nargin,
                format!("called with {n} arguments; expected cagd_limits (), cagd_limits (\"default\") or cagd_limits (NAME, VALUE)"),
            ));
        }
    }
    let items: Vec<String> = names.iter().map(|s| s.to_string()).collect();
    sink.strings(0, &[items.len(), 1], &items)?;
    if nargout > 1 {
        let out = sink.real(1, &[items.len(), 1])?;
        for (o, l) in out.iter_mut().zip(Limit::ALL) {
            *o = limits.get(l) as f64;
        }
    }
    Ok(())
}
