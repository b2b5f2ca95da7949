//! The command line's grammar: the top-level options and the list of subcommands, from which
//! clap's parser, the `Command` enum and its dispatch are generated.

use std::ffi::OsString;

use clap::{CommandFactory, Parser, Subcommand};

use super::outcome::Outcome;
use crate::args::LimitArgs;
use crate::cx::Cx;
use crate::CliError;

/// Curves and surfaces of computer-aided geometric design, checked against GNU Octave.
#[derive(Debug, Parser)]
#[command(name = "cagd", version, about, long_about = None)]
pub(super) struct Cli {
    #[command(subcommand)]
    pub(super) command: Command,
    #[command(flatten)]
    pub(super) limits: LimitArgs,
    /// `--lang` before the subcommand; each subcommand reads it as its own (see `LangArgs`).
    #[command(flatten)]
    #[allow(dead_code)]
    lang: crate::args::LangArgs,
}

/// Declares the subcommands, in the order of `cagd --help`: each a clap struct (its help text
/// beside it, in its own file) implementing [`Run`]. The enum and its dispatch are generated,
/// so adding a subcommand is one file and one line here.
macro_rules! subcommands {
    ($($variant:ident($ty:ty),)*) => {
        #[derive(Debug, Subcommand)]
        pub(super) enum Command {
            $($variant($ty),)*
        }

        impl Command {
            /// Runs the subcommand, in the arithmetic it asks for.
            pub(super) fn run(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
                match self {
                    $(Command::$variant(c) => super::run::run_any(c, cx),)*
                }
            }
        }
    };
}

subcommands! {
    Thesis(super::thesis::ThesisCommand),
    Course(super::course_examples::CourseCommand),
    Decasteljau(super::decasteljau::DecasteljauCommand),
    BezierPatch(super::bezier_patch::BezierPatchCommand),
    Coons(super::coons::CoonsCommand),
    CoonsBicubic(super::coons_bicubic::CoonsBicubicCommand),
    DiscreteCoons(super::discrete_coons::DiscreteCoonsCommand),
    Gordon(super::gordon::GordonCommand),
    Lagrange(super::lagrange::LagrangeCommand),
    Bernstein(super::bernstein::BernsteinCommand),
    Derivative(super::derivative::DerivativeCommand),
    Spline(super::spline::SplineCommand),
    Hermite(super::hermite::HermiteCommand),
    Bspline(super::bspline::BSplineCommand),
    Nurbs(super::nurbs::NurbsCommand),
    Convert(super::convert::ConvertCommand),
    Elevate(super::elevate::ElevateCommand),
    Subdivide(super::subdivide::SubdivideCommand),
    InsertKnot(super::insert_knot::InsertKnotCommand),
    BsplineBasis(super::bspline_basis::BSplineBasisCommand),
    Continuity(super::continuity::ContinuityCommand),
    Curvature(super::curvature::CurvatureCommand),
    Integrate(super::integrate::IntegrateCommand),
    Ruled(super::ruled::RuledCommand),
    Ferguson(super::ferguson::FergusonCommand),
    BsplineSurface(super::bspline_surface::BSplineSurfaceCommand),
    NurbsSurface(super::nurbs_surface::NurbsSurfaceCommand),
    Circle(super::circle::CircleCommand),
    Arc(super::arc::ArcCommand),
    Curve(super::curve_samples::CurveCommand),
    Surface(super::surface_samples::SurfaceCommand),
    Serve(crate::serve::ServeCommand),
    Script(super::script::ScriptCommand),
}

/// The clap definition of the whole command line (see [`crate::schema`]).
pub(crate) fn command() -> clap::Command {
    Cli::command()
}

/// The names of the subcommands, in the order of `cagd --help` (without clap's `help`).
pub fn subcommands() -> Vec<String> {
    Cli::command()
        .get_subcommands()
        .map(|s| s.get_name().to_string())
        .collect()
}

/// The `serve` subcommand, if `args` (the program name first) ask for it and parse; anything
/// else, including errors and `--help`, is left to [`super::run`].
pub fn serve_request<I, A>(args: I) -> Option<crate::serve::ServeCommand>
where
    I: IntoIterator<Item = A>,
    A: Into<OsString> + Clone,
{
    match Cli::try_parse_from(args) {
        Ok(Cli {
            command: Command::Serve(c),
            ..
        }) => Some(c),
        _ => None,
    }
}
