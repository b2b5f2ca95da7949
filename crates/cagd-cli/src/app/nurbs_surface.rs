//! `cagd nurbs-surface`: a tensor-product NURBS surface (the CAD notes §1.3): the B-spline
//! surface of the homogeneous points `(w P, w)` projected onto `w = 1`. Inputs as
//! `bspline-surface`, with the weights from `--weights` or from an octave-nurbs `nrbmak`
//! struct.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::NurbsSurface;
use clap::Args;

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::run::{Names, Run};
use super::spline_args::matrix;
use super::spline_surface_args::SplineSurfaceArgs;
use crate::error::usage;
use crate::{CliError, Outcome};

/// A tensor-product NURBS surface (the CAD notes): weights and homogeneous points.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: as for bspline-surface, with --weights (an (m+1)×(n+1) matrix of positive weights), or
an Octave save -text file with an octave-nurbs nrbmak struct (coefs 4×nu×nv homogeneous
[w·x; w·y; w·z; w], knots {ku, kv}, order) — e.g. from Octave: srf = nrbmak(coefs, {ku, kv});
save -text srf.txt srf.
Layout: as for bspline-surface.

Example:
  cagd nurbs-surface srf.txt --n 20 --plot srf.png")]
pub struct NurbsSurfaceCommand {
    #[command(flatten)]
    pub args: SplineSurfaceArgs,
    /// The weights, an (m+1)×(n+1) matrix of positive numbers, one per control point (not
    /// needed with an nrbmak struct, which holds them).
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub weights: Option<String>,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "NET",
    special: &[],
};

impl Run for NurbsSurfaceCommand {
    fn exact(&self) -> bool {
        self.args.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let (spline, from_struct) = self.args.request::<T>(cx, &NAMES)?;
        let weights = match (&self.weights, from_struct) {
            (Some(text), _) => matrix(cx, "--weights", text)?,
            (None, Some(w)) => w,
            (None, None) => {
                return Err(usage(
                    "--weights",
                    "missing",
                    "an (m+1)×(n+1) matrix of positive weights, one per control point (or an nrbmak struct)",
                ))
            }
        };
        let to = Destinations {
            output: &self.args.output,
            plot: self.args.plot.plot.as_deref(),
            mesh: self.args.mesh.mesh.as_deref(),
        };
        respond(cx, &NAMES, &NurbsSurface { spline, weights }, to)
    }
}
