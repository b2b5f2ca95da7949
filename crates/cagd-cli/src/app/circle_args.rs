//! What `circle` and `arc` share: the radius, the centre, the parameters and outputs, an
//! angle or radius read as one number (an expression such as `pi/2` allowed), and the answer.

use cagd_ops::ops::Circle;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::curve_params;
use super::run::Names;
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, StepsArgs};
use crate::error::{shape, usage};
use crate::{CliError, Outcome};

/// The arguments of a circle (and of an arc, with its angles).
#[derive(Debug, Args)]
pub struct CircleArgs {
    /// The radius r > 0.
    #[arg(
        long,
        value_name = "R",
        default_value = "1",
        allow_hyphen_values = true
    )]
    pub radius: String,
    /// The center, 2 or 3 coordinates (the circle lies in the plane z = center z).
    #[arg(
        long,
        value_name = "VECTOR",
        default_value = "[0 0]",
        allow_hyphen_values = true
    )]
    pub center: String,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// How `circle` and `arc` name the roles: the radius and the centre together, as the library
/// checks them, and the angles.
pub(crate) const SPECIAL: &[(Role, &str)] = &[
    (Role::Radius, "--radius/--center"),
    (Role::Angles, "--start/--end"),
];

impl CircleArgs {
    /// The circle (or, with `angles`, the arc) in doubles: its NURBS weights are irrational.
    pub(crate) fn respond(
        &self,
        cx: &mut Cx,
        names: &Names,
        angles: Option<(f64, f64)>,
    ) -> Result<Outcome, CliError> {
        if self.output.exact {
            return Err(usage(
                "--exact",
                "a circle's NURBS weights cos(Δ/2) (√2/2 for quarter arcs) are irrational",
                "the circle in doubles (leave out --exact)",
            ));
        }
        let center = crate::load_matrix::<f64>(&cx.limits, "--center", &self.center, None)?;
        let op = Circle {
            radius: number(cx, "--radius", &self.radius)?,
            center: center.iter().copied().collect(),
            angles,
            t: curve_params(cx, &self.params)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
        };
        let to = Destinations {
            output: &self.output,
            plot: self.plot.plot.as_deref(),
            mesh: None,
        };
        respond(cx, names, &op, to)
    }
}

/// One number of an argument (an expression such as `pi/2` is allowed).
pub(crate) fn number(cx: &Cx, argument: &str, text: &str) -> Result<f64, CliError> {
    let form = "one number, or an expression such as pi/2";
    let expr = cagd_octave::literal::ParamExpr::parse_with(text, &cx.limits)
        .map_err(|e| CliError::literal(argument, e, form))?;
    let m = expr
        .eval_at(&cagd_octave::literal::Env::with_limits(cx.limits), &[])
        .map_err(|e| CliError::literal(argument, e, form))?;
    match m.as_slice() {
        [x] => Ok(*x),
        _ => Err(shape(
            argument,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            form,
        )),
    }
}
