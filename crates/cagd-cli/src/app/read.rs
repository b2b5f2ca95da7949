//! Reading a subcommand's arguments into the typed values of a request: points (columns, or
//! rows with `--rows`), parameters (`--t`, `--u`, `--v`, `--n`), an interval, a data script.

use cagd_octave::literal::{Env, LiteralScalar};
use cagd_octave::script::Script;
use cagd_ops::bspline_arg::{BSplineArg, SplineDegree};
use cagd_ops::Params;
use nalgebra::DMatrix;

use super::common::shape;
use super::cx::Cx;
use crate::args::{CurveParamArgs, ScriptArgs, SurfaceParamArgs};
use crate::{load_matrix, load_params, CliError, Outcome};

/// A matrix argument with points as columns (or rows with `--rows`), with the orientation
/// slip noticed.
pub(crate) fn points<T: LiteralScalar>(
    cx: &mut Cx,
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
    rows: bool,
) -> Result<DMatrix<T>, CliError> {
    let m = load_matrix(&cx.limits, argument, text, script)?;
    crate::slips::point_matrix(argument, &m, rows);
    Ok(if rows { m.transpose() } else { m })
}

/// The parameters of a curve: `--t` values, `--n` samples of the curve's domain, or the
/// default samples.
pub(crate) fn curve_params<T: LiteralScalar>(
    cx: &mut Cx,
    params: &CurveParamArgs,
) -> Result<Params<T>, CliError> {
    given_or_samples(cx, "--t", &params.t, params.n)
}

/// The parameters of a surface: `--u`, `--v` values or `--n` samples of the domain, and
/// `--list`.
pub(crate) fn surface_params<T: LiteralScalar>(
    cx: &mut Cx,
    params: &SurfaceParamArgs,
) -> Result<cagd_ops::ops::surface::SurfaceParams<T>, CliError> {
    Ok(cagd_ops::ops::surface::SurfaceParams {
        u: given_or_samples(cx, "--u", &params.u, params.n)?,
        v: given_or_samples(cx, "--v", &params.v, params.n)?,
        list: params.list,
    })
}

/// `given` values of `argument`, else `n` samples, else the default.
pub(crate) fn given_or_samples<T: LiteralScalar>(
    cx: &mut Cx,
    argument: &str,
    given: &Option<String>,
    n: Option<usize>,
) -> Result<Params<T>, CliError> {
    Ok(match (given, n) {
        (Some(text), _) => Params::Given(load_params(&cx.limits, argument, text)?),
        (None, Some(n)) => Params::Samples(n),
        (None, None) => Params::Default,
    })
}

/// The interval `a,b` of `--interval`, if given.
pub(crate) fn interval<T: LiteralScalar>(
    cx: &mut Cx,
    given: &Option<String>,
) -> Result<Option<(T, T)>, CliError> {
    let Some(text) = given else {
        return Ok(None);
    };
    let form = "two numbers a,b with a < b, e.g. --interval 2,5";
    let inner = text.trim().trim_start_matches('[').trim_end_matches(']');
    // Not load_params: the comma between a and b is not a decimal comma.
    let values: Vec<T> = cagd_octave::literal::parse_params_with(&format!("[{inner}]"), &cx.limits)
        .map_err(|e| CliError::literal("--interval", e, form))?;
    match values.as_slice() {
        [a, b] if a < b => Ok(Some((a.clone(), b.clone()))),
        _ => Err(shape(
            "--interval",
            format!("`{}` is not an interval a < b", text.trim()),
            form,
        )),
    }
}

/// Runs `--script` if given, binding `N` to `n` first.
pub(crate) fn run_script<T: LiteralScalar>(
    limits: &cagd::limits::Limits,
    script: &ScriptArgs,
    n: Option<usize>,
) -> Result<Option<Script<T>>, CliError> {
    let Some(path) = &script.script else {
        return Ok(None);
    };
    let mut env = Env::with_limits(*limits);
    if let Some(n) = n {
        env.bind_scalar("N", T::from_usize(n));
    }
    crate::load_script(limits, "--script", path, env).map(Some)
}

impl Cx {
    /// Runs `--script` if given, binding `N` to `n` first.
    pub(crate) fn script<T: LiteralScalar>(
        &mut self,
        script: &ScriptArgs,
        n: Option<usize>,
    ) -> Result<Option<Script<T>>, CliError> {
        run_script(&self.limits, script, n)
    }
}

impl Outcome {
    /// The outcome with the warnings of the data script (`--script`) first.
    pub(crate) fn with_script_warnings<T: LiteralScalar>(
        mut self,
        args: &ScriptArgs,
        script: Option<&Script<T>>,
    ) -> Self {
        let mut warnings = super::common::warnings(
            &args.script,
            script,
            &mut Env::<T>::with_limits(Default::default()),
        );
        warnings.append(&mut self.warnings);
        self.warnings = warnings;
        self
    }
}

/// The one number of `argument` (a list of one value, as `--t` and `--k` take), else an error
/// expecting `form`.
pub(crate) fn one_value<T: LiteralScalar>(
    cx: &mut Cx,
    argument: &str,
    text: &str,
    form: &str,
) -> Result<T, CliError> {
    let values: Vec<T> = load_params(&cx.limits, argument, text)?;
    match <[T; 1]>::try_from(values) {
        Ok([x]) => Ok(x),
        Err(values) => Err(shape(argument, format!("{} values", values.len()), form)),
    }
}

/// The B-spline of `--degree`/`--order` and `--knots` (degree 3 with knots alone), if any of
/// them is given.
pub(crate) fn bspline_arg<T: LiteralScalar>(
    cx: &mut Cx,
    degree: Option<usize>,
    order: Option<usize>,
    knots: &Option<String>,
) -> Result<Option<BSplineArg<T>>, CliError> {
    let degree = match (degree, order) {
        (_, Some(k)) => SplineDegree::Order(k),
        (Some(p), None) => SplineDegree::Degree(p),
        (None, None) if knots.is_some() => SplineDegree::Degree(3),
        (None, None) => return Ok(None),
    };
    let knots = match knots {
        Some(text) => Some(load_params(&cx.limits, "--knots", text)?),
        None => None,
    };
    Ok(Some(BSplineArg { degree, knots }))
}
