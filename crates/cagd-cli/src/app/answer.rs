//! From a request of the operation layer to what the command line prints and writes: the
//! request runs ([`cagd_ops::execute`]), its errors and warnings are named as this command
//! names its arguments ([`Names`]), its report is rendered as `--format` says and its picture
//! and mesh are staged as files.

use std::path::Path;

use cagd_octave::literal::{LiteralScalar, Position, Warning};
use cagd_ops::{Answer, OpError, Operation};

use super::common::{add_mesh, add_plot, finish};
use super::run::Names;
use crate::args::{MeshArgs, OutputArgs, PlotArgs};
use crate::cx::Cx;
use crate::plot::Figure;
use crate::{CliError, ErrorKind, Outcome, PendingWrites};

/// Where a subcommand's answer goes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Destinations<'a> {
    /// `--format`, `--exact`, `-o`, `--digits`.
    pub output: &'a OutputArgs,
    /// `--plot FILE`.
    pub plot: Option<&'a Path>,
    /// `--mesh FILE`.
    pub mesh: Option<&'a Path>,
}

impl<'a> Destinations<'a> {
    /// A surface's destinations: the output, `--plot FILE` and `--mesh FILE`.
    pub(crate) fn surface(output: &'a OutputArgs, plot: &'a PlotArgs, mesh: &'a MeshArgs) -> Self {
        Destinations {
            output,
            plot: plot.plot.as_deref(),
            mesh: mesh.mesh.as_deref(),
        }
    }
}

/// Runs `op` and turns its answer into the command's outcome.
pub(crate) fn respond<T: LiteralScalar, O: Operation<T> + ?Sized>(
    cx: &mut Cx,
    names: &Names,
    op: &O,
    to: Destinations<'_>,
) -> Result<Outcome, CliError> {
    let mut context = cagd_ops::Context::new(cx.limits);
    context.digits = to.output.text_digits();
    let result = cagd_ops::execute(op, &mut context);
    let warnings: Vec<(String, Warning)> = context
        .take_warnings()
        .into_iter()
        .map(|w| {
            let warning = Warning {
                at: Position::default(),
                message: w.message,
            };
            (names.of(w.role).to_string(), warning)
        })
        .collect();
    let answer = result.map_err(|e| op_error(names, e))?;
    outcome(answer, to, warnings, names)
}

/// The report rendered, the picture and the mesh staged.
fn outcome<T: LiteralScalar>(
    answer: Answer<T>,
    to: Destinations<'_>,
    warnings: Vec<(String, Warning)>,
    names: &Names,
) -> Result<Outcome, CliError> {
    let mut files = PendingWrites::new();
    if let (Some(path), Some(drawing)) = (to.plot, answer.drawing) {
        add_plot(&mut files, "--plot", path, &Figure::from(drawing))?;
    }
    if let (Some(path), Some(grid)) = (to.mesh, &answer.mesh) {
        add_mesh(&mut files, "--mesh", path, grid)?;
    }
    finish(&answer.report, to.output, files, warnings, names)
}

/// An error of the operation layer as the command line prints it: the role named as this
/// command names it, a limit with the flag and the variable that raise it.
pub(crate) fn op_error(names: &Names, e: OpError) -> CliError {
    let mut problem = e.problem;
    if let Some(limit) = e.limit {
        problem = format!(
            "{problem} (raise it with {} or {})",
            crate::limits::flag(limit),
            crate::limits::variable(limit)
        );
    }
    let literal = e
        .cause
        .as_ref()
        .and_then(|c| c.downcast_ref::<cagd_octave::literal::LiteralError>())
        .cloned();
    let kind = match (e.source, e.kind) {
        _ if literal.is_some() => ErrorKind::Literal(Box::new(
            literal.unwrap_or_else(|| unreachable!("checked just above")),
        )),
        (Some(source), _) => ErrorKind::Library(source),
        (None, cagd_ops::Kind::Shape) => ErrorKind::Shape,
        (None, cagd_ops::Kind::Usage) => ErrorKind::Usage,
        (None, cagd_ops::Kind::Internal) => ErrorKind::Internal,
        (None, kind) => ErrorKind::Operation(kind),
    };
    CliError::new(names.of(e.role), problem, e.expected, kind)
}
