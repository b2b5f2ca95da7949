//! `cagd bspline-surface`: a tensor-product B-spline surface (the CAD notes §1.2–1.3, the
//! lecture notes "B-spline plocha").

use cagd_octave::literal::LiteralScalar;
use clap::Args;

use super::answer::{respond, Destinations};
use super::run::{Names, Run};
use super::spline_surface_args::SplineSurfaceArgs;
use crate::cx::Cx;
use crate::error::usage;
use crate::{CliError, Outcome};

/// A tensor-product B-spline surface (the CAD notes, the lecture notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: the control net packed (m+1)×3(n+1) as for bezier-patch, an Octave (m+1)×(n+1)×3 array
file, or an Octave save -text file with an octave-nurbs nrbmak struct (weights all 1);
--degree P or P,Q (default 3, cubic; or --order K = P + 1), --uknots and --vknots (in each
direction n + p + 1 non-decreasing values for its n control points and its degree p, numbered
from 1 as the notes number them; default clamped uniform on [0, 1]).
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3, or --list; u and v
are 1×nu and 1×nv. Parameters default to --n samples of the domain ([u_(p+1), u_(n+1)] in each
direction); outside it the surface is not defined (an error). --steps prints the knots and the
basis values N_i,p(u), N_j,q(v).

Example:
  cagd bspline-surface net.txt --degree 2 --n 20 --plot surface.png --mesh surface.stl")]
pub struct BSplineSurfaceCommand {
    #[command(flatten)]
    pub args: SplineSurfaceArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "NET",
    special: &[],
};

impl Run for BSplineSurfaceCommand {
    fn exact(&self) -> bool {
        self.args.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let (op, weights) = self.args.request::<T>(cx, &NAMES)?;
        if weights.is_some_and(|w| w.iter().any(|x| *x != T::one())) {
            return Err(usage(
                "NET",
                "the nrbmak struct has weights other than 1",
                "cagd nurbs-surface for a rational surface",
            ));
        }
        let to = Destinations {
            output: &self.args.output,
            plot: self.args.plot.plot.as_deref(),
            mesh: self.args.mesh.mesh.as_deref(),
        };
        respond(cx, &NAMES, &op, to)
    }
}
