//! `cagd derivative`: the control points (and values) of a derivative of a Bézier curve.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Derivative;
use cagd_ops::Params;
use clap::Args;

use super::answer::{respond, Destinations};
use super::read::{given_or_samples, points};
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, ScriptArgs};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// Control points (and values) of the r-th derivative of a Bézier curve.
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: control is d×(n-r+1), the points n!/(n-r)! Δ^r b_i as columns; with --t, result is d×k.

Example:
  cagd derivative \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'\" -r 1 --t 0.5 --exact

-r/--r is the derivative's order r; --order means the order of a B-spline (degree + 1) in every
command, so it is refused here.")]
pub struct DerivativeCommand {
    /// Control points of the curve (columns), as for decasteljau.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The order r of the derivative (the r-th derivative).
    #[arg(long = "r", short = 'r', value_name = "R", default_value_t = 1)]
    pub order: usize,
    /// Refused: --order is a B-spline's order (degree + 1) in every command; the derivative's
    /// order is -r.
    #[arg(
        long = "order",
        value_name = "K",
        hide = true,
        allow_hyphen_values = true
    )]
    pub spline_order: Option<String>,
    /// Also the values of the derivative at these parameters.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub t: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub script: ScriptArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "CONTROL",
    special: &[],
};

impl Run for DerivativeCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        if let Some(k) = &self.spline_order {
            return Err(crate::error::usage(
                "--order",
                &format!("--order {k} would be a B-spline's order (degree + 1), as in every command; the derivative's order is -r"),
                "-r R (or --r R) for the R-th derivative",
            ));
        }
        let script = cx.script::<T>(&self.script, None)?;
        let control = points(
            cx,
            "CONTROL",
            &self.control,
            script.as_ref(),
            self.rows.rows,
        )?;
        let t = match &self.t {
            Some(_) => Some(given_or_samples(cx, "--t", &self.t, None)?),
            None => None::<Params<T>>,
        };
        let op = Derivative::<T> {
            t,
            drawing: self.plot.plot.is_some(),
            ..Derivative::new(control, self.order)
        };
        let to = Destinations {
            output: &self.output,
            plot: self.plot.plot.as_deref(),
            mesh: None,
        };
        respond(cx, &NAMES, &op, to).map(|o| o.with_script_warnings(&self.script, script.as_ref()))
    }
}
