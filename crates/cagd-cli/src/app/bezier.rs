//! What the subcommands not yet on the operation layer still share from the former Bézier
//! subcommands: whether `--u` and `--v` ask for one point, the interval of `--interval` (the
//! operation layer's surfaces decide the first themselves, `read::interval` reads the second).

use cagd::limits::Limits;
use cagd_octave::literal::LiteralScalar;

use super::common::shape;
use crate::args::SurfaceParamArgs;
use crate::CliError;

/// The interval `a,b` of `--interval` (default `[0, 1]`).
pub fn interval<T: LiteralScalar>(
    limits: &Limits,
    given: &Option<String>,
) -> Result<(T, T), CliError> {
    let Some(text) = given else {
        return Ok((T::zero(), T::one()));
    };
    let form = "two numbers a,b with a < b, e.g. --interval 2,5";
    let inner = text.trim().trim_start_matches('[').trim_end_matches(']');
    // Not load_params: the comma between a and b is not a decimal comma.
    let values: Vec<T> = cagd_octave::literal::parse_params_with(&format!("[{inner}]"), limits)
        .map_err(|e| crate::CliError::literal("--interval", e, form))?;
    match values.as_slice() {
        [a, b] if a < b => Ok((a.clone(), b.clone())),
        _ => Err(shape(
            "--interval",
            format!("`{}` is not an interval a < b", text.trim()),
            form,
        )),
    }
}

/// Whether `--u` and `--v` ask for one point.
pub fn point_mode(limits: &Limits, params: &SurfaceParamArgs) -> bool {
    let single = |s: &Option<String>| {
        s.as_ref().is_some_and(|t| {
            cagd_octave::literal::parse_params_with::<f64>(t, limits).is_ok_and(|v| v.len() == 1)
        })
    };
    params.n.is_none() && single(&params.u) && single(&params.v)
}
