//! `cagd discrete-coons`: the interior of a control net from its boundary, by formula or mask.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::discrete_coons::MASK_FORM;
use cagd_ops::ops::DiscreteCoons;
use clap::Args;

use super::answer::{respond, Destinations};
use super::common::shape;
use super::cx::Cx;
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, ScriptArgs, StepsArgs};
use crate::{load_net, CliError, Outcome};

/// The discrete Coons patch: interior control points from the boundary of a net.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: a net as for bezier-patch; only its boundary rows and columns are used.
Layout: result is the full net (m+1)×(n+1)×3; --steps also prints its parts bu, bv, buv (the
CAD notes (6): net = bu + bv − buv).
--mask=ALPHA,BETA solves the affine mask instead (alpha + beta = 1/4): α = −1/4, β = 1/2 is the
permanence principle's mask, the discrete Coons patch again; α = 0, β = 1/4 the discrete Laplace
mask.

Examples:
  cagd discrete-coons \"[0 0 0 0 1 0 0 2 0; 1 0 0 0 0 0 1 2 1; 2 0 0 2 1 1 2 2 0]\"
  cagd discrete-coons net.txt --mask=0,0.25")]
pub struct DiscreteCoonsCommand {
    /// A Bézier control net, packed (m+1)×3(n+1) as ploskevB takes it, or an Octave
    /// (m+1)×(n+1)×3 array file. Only its boundary rows and columns are used.
    #[arg(value_name = "NET", allow_hyphen_values = true)]
    pub net: String,
    /// Solve the affine mask P_ij = α·(the 4 diagonal neighbours) + β·(the 4 edge neighbours)
    /// for every interior point instead of the discrete Coons formula; α + β must be 1/4.
    /// α = −1/4, β = 1/2 is the mask the permanence principle gives (the CAD notes (7)–(8)):
    /// the discrete Coons patch again; α = 0, β = 1/4 is the discrete Laplace mask (each
    /// point the average of its 4 edge neighbours). E.g. --mask=-0.25,0.5.
    #[arg(long, value_name = "ALPHA,BETA", allow_hyphen_values = true)]
    pub mask: Option<String>,
    /// Also print the three parts of the discrete Coons formula (the CAD notes (6)):
    /// b^u = (1 − i/m) P_0j + (i/m) P_mj, b^v = (1 − j/n) P_i0 + (j/n) P_in and the corner
    /// term b^uv; the net is b^u + b^v − b^uv.
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
    input: "NET",
    special: &[],
};

impl Run for DiscreteCoonsCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, None)?;
        let op = DiscreteCoons {
            net: load_net::<T>(&cx.limits, "NET", &self.net, script.as_ref())?,
            mask: self.mask.as_deref().map(|t| mask(cx, t)).transpose()?,
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

/// `α,β` of `--mask`.
fn mask<T: LiteralScalar>(cx: &Cx, text: &str) -> Result<(T, T), CliError> {
    // Not load_params: the comma between α and β is not a decimal comma.
    let values: Vec<T> = cagd_octave::literal::parse_params_with(&format!("[{text}]"), &cx.limits)
        .map_err(|e| CliError::literal("--mask", e, MASK_FORM))?;
    match <[T; 2]>::try_from(values) {
        Ok([alpha, beta]) => Ok((alpha, beta)),
        Err(v) => Err(shape("--mask", format!("{} value(s)", v.len()), MASK_FORM)),
    }
}
