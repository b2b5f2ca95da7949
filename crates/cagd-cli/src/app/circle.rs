//! `cagd circle`: a circle as an exact NURBS curve (octave-nurbs `nrbcirc`).

use cagd_octave::literal::LiteralScalar;
use clap::Args;

use super::circle_args::{CircleArgs, SPECIAL};
use super::cx::Cx;
use super::run::{Names, Run};
use crate::{CliError, Outcome};

/// A circle as an exact NURBS curve (octave-nurbs nrbcirc).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --radius (default 1), --center (2 or 3 coordinates, default [0 0]).
Layout: knots, control (d×9: four quarter arcs), weights (1 and √2/2), and the points at --t
(default --n 11 samples of [0, 1]). --steps prints the homogeneous coefficients (w·x, w·y, w),
as octave-nurbs stores them.

Example:
  cagd circle --radius 2 --center \"[1 -1]\" --n 9 --plot circle.svg")]
pub struct CircleCommand {
    #[command(flatten)]
    pub circle: CircleArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "--radius",
    special: SPECIAL,
};

impl Run for CircleCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        self.circle.respond(cx, &NAMES, None)
    }
}
