//! `nurbs-surface`: a tensor-product NURBS surface (the CAD notes §1.3): the B-spline surface
//! of the homogeneous points `(w P, w)` projected onto `w = 1`. Inputs as `bspline-surface`,
//! with the weights from `--weights` or from an octave-nurbs `nrbmak` struct.

use cagd::limits::Limits;
use cagd_octave::literal::LiteralScalar;
use clap::Args;

use crate::CliError;

use super::bspline_surface::{spline_surface, SplineSurfaceArgs};
use super::Outcome;

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

/// A NURBS surface.
pub fn nurbs_surface<T: LiteralScalar>(
    limits: &Limits,
    cmd: &NurbsSurfaceCommand,
) -> Result<Outcome, CliError> {
    spline_surface::<T>(limits, &cmd.args, cmd.weights.as_deref(), true)
}
