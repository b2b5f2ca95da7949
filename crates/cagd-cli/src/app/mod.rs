//! The `cagd` command line in-process: parse the arguments, call the library, and return what
//! would be printed and written (see [`crate::run`]).

use std::ffi::OsString;

use clap::error::{ContextKind, ErrorKind as ClapKind};
use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

mod answer;

mod arc;

mod bernstein;

mod bezier_patch;

mod bspline;

mod boundary;

mod coons;

mod coons_bicubic;
mod curvature;

mod curve_arg;

mod curve_samples;

mod cx;

mod decasteljau;

mod derivative;

mod expr_curve;

mod serve;

mod read;

mod run;

mod script;

mod surface_samples;

mod bspline_basis;

mod bspline_surface;

mod circle;

mod circle_args;

mod common;

mod continuity;

mod convert;

mod course_examples;

mod discrete_coons;

mod elevate;

mod ferguson;

mod gordon;
mod hermite;

mod insert_knot;

mod integrate;

mod nurbs;

mod nurbs_surface;

mod outcome;

mod lagrange;

mod worked;

mod ruled;

mod spline;

mod spline_args;

mod spline_surface_args;

mod subdivide;

mod thesis;

mod work;

use crate::args::LimitArgs;
use crate::{CliError, ErrorKind, PendingWrites};

/// Curves and surfaces of computer-aided geometric design, checked against GNU Octave.
#[derive(Debug, Parser)]
#[command(name = "cagd", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    #[command(flatten)]
    limits: LimitArgs,
}

/// Declares the subcommands, in the order of `cagd --help`: each a clap struct (its help text
/// beside it, in its own file) implementing [`Run`]. The enum and its dispatch are generated,
/// so adding a subcommand is one file and one line here.
macro_rules! subcommands {
    ($($variant:ident($ty:ty),)*) => {
        #[derive(Debug, Subcommand)]
        enum Command {
            $($variant($ty),)*
        }

        impl Command {
            /// Runs the subcommand, in the arithmetic it asks for.
            fn run(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
                match self {
                    $(Command::$variant(c) => run::run_any(c, cx),)*
                }
            }
        }
    };
}

subcommands! {
    Thesis(thesis::ThesisCommand),
    Course(course_examples::CourseCommand),
    Decasteljau(decasteljau::DecasteljauCommand),
    BezierPatch(bezier_patch::BezierPatchCommand),
    Coons(coons::CoonsCommand),
    CoonsBicubic(coons_bicubic::CoonsBicubicCommand),
    DiscreteCoons(discrete_coons::DiscreteCoonsCommand),
    Gordon(gordon::GordonCommand),
    Lagrange(lagrange::LagrangeCommand),
    Bernstein(bernstein::BernsteinCommand),
    Derivative(derivative::DerivativeCommand),
    Spline(spline::SplineCommand),
    Hermite(hermite::HermiteCommand),
    Bspline(bspline::BSplineCommand),
    Nurbs(nurbs::NurbsCommand),
    Convert(convert::ConvertCommand),
    Elevate(elevate::ElevateCommand),
    Subdivide(subdivide::SubdivideCommand),
    InsertKnot(insert_knot::InsertKnotCommand),
    BsplineBasis(bspline_basis::BSplineBasisCommand),
    Continuity(continuity::ContinuityCommand),
    Curvature(curvature::CurvatureCommand),
    Integrate(integrate::IntegrateCommand),
    Ruled(ruled::RuledCommand),
    Ferguson(ferguson::FergusonCommand),
    BsplineSurface(bspline_surface::BSplineSurfaceCommand),
    NurbsSurface(nurbs_surface::NurbsSurfaceCommand),
    Circle(circle::CircleCommand),
    Arc(arc::ArcCommand),
    Curve(curve_samples::CurveCommand),
    Surface(surface_samples::SurfaceCommand),
    Serve(crate::serve::ServeCommand),
    Script(script::ScriptCommand),
}

use cx::Cx;
pub use outcome::Outcome;

/// Parses `args` (the program name first, as `std::env::args_os` gives them) and runs the
/// subcommand. Nothing is written: the files are returned staged in the [`Outcome`].
pub fn run<I, A>(args: I) -> Result<Outcome, CliError>
where
    I: IntoIterator<Item = A>,
    A: Into<OsString> + Clone,
{
    let matches = match Cli::command().try_get_matches_from(args) {
        Ok(m) => m,
        Err(e) => return usage_error(e),
    };
    // Output targets are checked before any work (and before the limits, which may fail).
    crate::outputs::check(&matches)?;
    let cli = match Cli::from_arg_matches(&matches) {
        Ok(cli) => cli,
        Err(e) => return usage_error(e),
    };
    let limits = &cli.limits.resolve()?;
    crate::slips::take();
    let mut cx = Cx::new(*limits);
    let outcome = cli.command.run(&mut cx);
    // The slips noticed while reading the input come first; each warning is printed once.
    let mut warnings = crate::slips::take();
    let mut outcome = outcome?;
    warnings.append(&mut outcome.warnings);
    outcome.warnings = crate::slips::dedup(warnings);
    Ok(outcome)
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
/// else, including errors and `--help`, is left to [`run`].
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

/// Turns a clap error into the one-line form (help and version are printed as a result).
fn usage_error(e: clap::Error) -> Result<Outcome, CliError> {
    if matches!(e.kind(), ClapKind::DisplayHelp | ClapKind::DisplayVersion) {
        return Ok(Outcome {
            stdout: e.render().to_string(),
            files: PendingWrites::new(),
            warnings: Vec::new(),
        });
    }
    let context = |k: ContextKind| e.get(k).map(|v| v.to_string());
    // Clap names an option with its value placeholder (`--format <FORMAT>`); keep the name.
    let strip = |s: String| -> String {
        s.split(", ")
            .map(|a| a.split_whitespace().next().unwrap_or(a))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let arg = context(ContextKind::InvalidArg)
        .map(strip)
        .unwrap_or_else(|| "cagd".into());
    let value = context(ContextKind::InvalidValue).unwrap_or_default();
    let subcommands = subcommands().join(", ");
    let (argument, problem, expected) = match e.kind() {
        ClapKind::InvalidValue => (
            arg,
            format!("invalid value '{value}'"),
            context(ContextKind::ValidValue)
                .map(|v| format!("one of {v}"))
                .unwrap_or_else(|| "a value".into()),
        ),
        ClapKind::ValueValidation => {
            let reason = std::error::Error::source(&e)
                .map(|s| s.to_string())
                .unwrap_or_default();
            let expected = if reason.contains("digit") || reason.contains("empty string") {
                "a whole number such as 10".to_string()
            } else {
                "a value of the form shown by --help".to_string()
            };
            let reason = if reason.is_empty() {
                reason
            } else {
                format!(" ({reason})")
            };
            (arg, format!("invalid value '{value}'{reason}"), expected)
        }
        ClapKind::UnknownArgument => (
            arg,
            "unknown option".into(),
            context(ContextKind::SuggestedArg)
                .map(|s| format!("{s} perhaps, or an option listed by --help"))
                .unwrap_or_else(|| "an option listed by --help".into()),
        ),
        ClapKind::InvalidSubcommand => (
            context(ContextKind::InvalidSubcommand).unwrap_or(value),
            "unknown subcommand".into(),
            format!("one of {subcommands}"),
        ),
        ClapKind::MissingSubcommand | ClapKind::DisplayHelpOnMissingArgumentOrSubcommand => (
            "cagd".into(),
            "no subcommand given".into(),
            format!("one of {subcommands} (see cagd --help)"),
        ),
        ClapKind::MissingRequiredArgument => {
            (arg, "missing".into(), "the argument (see --help)".into())
        }
        ClapKind::ArgumentConflict
            if context(ContextKind::PriorArg).map(strip).as_deref() == Some(arg.as_str()) =>
        {
            (arg, "given more than once".into(), "the option once".into())
        }
        ClapKind::ArgumentConflict => (
            arg,
            format!(
                "cannot be used together with {}",
                context(ContextKind::PriorArg)
                    .map(strip)
                    .unwrap_or_else(|| "another option".into())
            ),
            "only one of them".into(),
        ),
        _ => {
            let rendered = e.render().to_string();
            let first = rendered
                .lines()
                .next()
                .unwrap_or("invalid arguments")
                .trim_start_matches("error: ")
                .to_string();
            ("cagd".into(), first, "arguments as listed by --help".into())
        }
    };
    Err(CliError::new(argument, problem, expected, ErrorKind::Usage))
}
