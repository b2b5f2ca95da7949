//! Reading the arguments the spline subcommands share into the operation layer's values: the
//! degree or order (`--degree P`, `--order K`), a knot vector, a point or vector.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::knots::Degree;
use nalgebra::DMatrix;

use super::answer::op_error;
use super::cx::Cx;
use super::run::Names;
use crate::{load_matrix, load_params, CliError};

/// `--degree P` or `--order K` (at most one), as the command names them.
pub(crate) fn degree(
    names: &Names,
    degree: Option<usize>,
    order: Option<usize>,
) -> Result<Degree, CliError> {
    Degree::either(degree, order).map_err(|e| op_error(names, e))
}

/// The values of a list argument (knots, weights), if given.
pub(crate) fn values<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    given: &Option<String>,
) -> Result<Option<Vec<T>>, CliError> {
    given
        .as_ref()
        .map(|text| load_params(&cx.limits, argument, text))
        .transpose()
}

/// A matrix argument (a point, a vector, weights), as given.
pub(crate) fn matrix<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    text: &str,
) -> Result<DMatrix<T>, CliError> {
    load_matrix(&cx.limits, argument, text, None)
}
