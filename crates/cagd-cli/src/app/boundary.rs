//! The four boundary curves of a Coons patch (`coons`, `coons-bicubic`): their arguments and
//! how they are read, from the command line or from a data script's `c1`, `c2`, `d1`, `d2`.

use std::cell::RefCell;
use std::rc::Rc;

use cagd_octave::literal::{Env, LiteralScalar};
use cagd_octave::script::Script;
use cagd_ops::curves::CurveArg;
use clap::Args;
use nalgebra::DVector;

use super::common::usage;
use super::curve_arg::{curve_arg, names_data, script_curve, Reading, CURVE_ARG_FORM};
use super::cx::Cx;
use crate::CliError;

/// The boundary curve arguments shared by `coons` and `coons-bicubic`.
#[derive(Debug, Clone, Args)]
pub struct BoundaryArgs {
    /// x(u,0): an expression in u such as "[u;0;u-u^2]", Bézier control points, or
    /// bezier(P), bspline(P, U), nurbs(P, W, U).
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub c1: Option<String>,
    /// x(u,1), in u.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub c2: Option<String>,
    /// x(0,v), in v.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub d1: Option<String>,
    /// x(1,v), in v.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub d2: Option<String>,
    /// Curves given as data (a matrix of the --script, a data file) are samples of the
    /// curve, one column per parameter value (the script's u or v, else linspace(0,1,N)),
    /// not Bézier control points.
    #[arg(long)]
    pub samples: bool,
}

/// The four boundary curves: from the arguments, else from the script's c1, c2, d1, d2.
pub(crate) fn boundary<T: LiteralScalar>(
    cx: &mut Cx,
    b: &BoundaryArgs,
    script: Option<&Script<T>>,
    rows: bool,
    env: &Rc<RefCell<Env<T>>>,
) -> Result<[CurveArg<T>; 4], CliError> {
    let given = [&b.c1, &b.c2, &b.d1, &b.d2];
    if b.samples
        && !given
            .iter()
            .any(|g| g.as_deref().is_some_and(|t| names_data(cx, t, script)))
    {
        return Err(usage(
            "--samples",
            "has no effect: no curve argument names a matrix of the script or a data file",
            "--samples with curves such as --c1 c1 from a --script, or without --samples",
        ));
    }
    let mut out = Vec::with_capacity(4);
    for (arg, given, name, param) in [
        ("--c1", &b.c1, "c1", "u"),
        ("--c2", &b.c2, "c2", "u"),
        ("--d1", &b.d1, "d1", "v"),
        ("--d2", &b.d2, "d2", "v"),
    ] {
        let how = Reading {
            script,
            rows,
            samples: b.samples.then_some(param),
        };
        let curve = match (given, script) {
            (Some(text), _) => curve_arg(cx, arg, text, how, env)?,
            (None, Some(s)) => script_curve(cx, s, name, param, env).ok_or_else(|| {
                usage(
                    arg,
                    &format!("missing, and the script defines no `{name}`"),
                    CURVE_ARG_FORM,
                )
            })?,
            (None, None) => return Err(usage(arg, "missing", CURVE_ARG_FORM)),
        };
        out.push(curve);
    }
    out.try_into()
        .map_err(|_| usage("--c1", "not four curves", CURVE_ARG_FORM))
}

/// The script's corner points P1..P4 if it defines all four as vectors and no curve argument
/// is given.
pub(crate) fn script_corners<T: LiteralScalar>(
    b: &BoundaryArgs,
    script: Option<&Script<T>>,
) -> Option<[DVector<T>; 4]> {
    let s = script?;
    if b.c1.is_some() {
        return None;
    }
    let get = |n: &str| {
        s.value(n)
            .filter(|m| m.ncols() == 1 || m.nrows() == 1)
            .map(|m| DVector::from_iterator(m.len(), m.iter().cloned()))
    };
    Some([get("P1")?, get("P2")?, get("P3")?, get("P4")?])
}
