//! `cagd decasteljau`: points of a Bézier curve by de Casteljau's algorithm.

use clap::Args;

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::DeCasteljau;

use super::answer::{respond, Destinations};
use super::read::{curve_params, interval, points};
use super::run::{Names, Run};
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// Points of a Bézier curve by de Casteljau's algorithm (thesis algorithm 1).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: control points b_0..b_n as the columns of a d×(n+1) matrix (rows with --rows): a
literal, a numeric text/CSV file, an Octave save -text file (FILE or FILE:NAME; else its first
numeric variable), or - for standard input.
Layout: result is d×k, one point per column (like T in deCasteljau); t is 1×k.
--steps prints the whole scheme b_i^r(t) for each t, columns r = 0..n, as in Primer 2.4 (in
json and octave formats as data: scheme.r0 … scheme.rn, level r a d×(n+1−r) matrix).
--interval a,b puts the curve on [a, b] (thesis §2.3.2). A matrix that reads both ways (both
sizes at most 3) is read as columns with a note naming --rows; --rows or --columns states the
reading.

Examples:
  cagd decasteljau \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'\" --t 0.5 --steps --exact
  cagd decasteljau \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]\" --rows --n 50 --plot curve.svg")]
#[command(mut_arg("n", |a| a.help("Sample at linspace(0,1,N), like the thesis's N (mapped onto --interval if given)")))]
pub struct DecasteljauCommand {
    /// Control points b_0..b_n: a matrix literal, a data file (FILE or FILE.txt:NAME for an
    /// Octave save -text file) or - for standard input; one point per column.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    #[command(flatten)]
    pub params: CurveParamArgs,
    /// The parameter interval [a, b] of the curve (thesis §2.3.2), e.g. --interval 2,5: the
    /// weights of each step are (b − t)/(b − a) and (t − a)/(b − a); --n samples [a, b].
    #[arg(long, value_name = "A,B", allow_hyphen_values = true)]
    pub interval: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
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

impl Run for DecasteljauCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, None)?;
        let op = DeCasteljau {
            control: points(
                cx,
                "CONTROL",
                &self.control,
                script.as_ref(),
                self.rows.rows,
            )?,
            interval: interval(cx, &self.interval)?,
            t: curve_params(cx, &self.params)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
        };
        let to = Destinations {
            output: &self.output,
            plot: self.plot.plot.as_deref(),
            mesh: None,
        };
        respond(cx, &NAMES, &op, to).map(|o| o.with_script_warnings(&self.script, script.as_ref()))
    }
}
