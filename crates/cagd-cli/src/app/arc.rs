//! `cagd arc`: a circular arc as an exact NURBS curve (octave-nurbs `nrbcirc` with angles).

use cagd_octave::literal::LiteralScalar;
use clap::Args;

use super::circle_args::{number, CircleArgs, SPECIAL};
use super::cx::Cx;
use super::run::{Names, Run};
use crate::{CliError, Outcome};

/// A circular arc as an exact NURBS curve (octave-nurbs nrbcirc with angles).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: as for circle, with --start and --end angles in radians (expressions such as pi/2),
at most one full turn apart.
Layout: as for circle; 1 to 4 rational quadratic pieces of at most 90° each.

Example:
  cagd arc --radius 1 --start 0 --end pi/2 --n 5")]
pub struct ArcCommand {
    #[command(flatten)]
    pub circle: CircleArgs,
    /// The start angle in radians (anticlockwise from the x axis); expressions such as pi/4
    /// are allowed.
    #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
    pub start: String,
    /// The end angle in radians (at most one full turn from the start).
    #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
    pub end: String,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "--radius",
    special: SPECIAL,
};

impl Run for ArcCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let angles = (
            number(cx, "--start", &self.start)?,
            number(cx, "--end", &self.end)?,
        );
        self.circle.respond(cx, &NAMES, Some(angles))
    }
}
