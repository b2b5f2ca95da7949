//! The `cagd` command line in-process: parse the arguments, call the library, and return what
//! would be printed and written (see [`crate::run`]).

use cagd::limits::Limits;
use std::ffi::OsString;

use cagd::grid::PointGrid;
use clap::error::{ContextKind, ErrorKind as ClapKind};
use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use nalgebra::DMatrix;

mod answer;

mod bezier;

mod boundary;

mod coons;

mod curvature;

mod curve_arg;

mod cx;

mod decasteljau;

mod expr_curve;

mod legacy;

mod read;

mod run;

mod bspline_basis;

mod bspline_surface;

mod circle;

mod common;

mod continuity;

mod convert;

mod course;

mod course_examples;

mod curve;

mod discrete_parts;

mod elevate;

mod ferguson;

mod insert_knot;

mod integrate;

mod nurbs_surface;

mod outcome;

mod lagrange;

mod patches;

mod ruled;

mod scheme;

mod spline_steps;

mod subdivide;

mod thesis;

mod work;

use crate::args::{
    CurveParamArgs, LimitArgs, MeshArgs, OutputArgs, PlotArgs, ScriptArgs, SurfaceParamArgs,
};
use crate::plot::{Colour, Figure};
use crate::{
    load_expression, load_params, load_script, samples, CliError, ErrorKind, PendingWrites, Report,
    Value, CURVE_FORM,
};
use cagd_octave::literal::{Env, LiteralScalar, Warning};
use cagd_octave::script::{Binding, Script};

/// Curves and surfaces of computer-aided geometric design, checked against GNU Octave.
#[derive(Debug, Parser)]
#[command(name = "cagd", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    #[command(flatten)]
    limits: LimitArgs,
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
    BezierPatch(bezier::BezierPatchCommand),
    Coons(coons::CoonsCommand),
    CoonsBicubic(patches::CoonsBicubicCommand),
    DiscreteCoons(patches::DiscreteCoonsCommand),
    Gordon(patches::GordonCommand),
    Lagrange(lagrange::LagrangeCommand),
    Bernstein(bezier::BernsteinCommand),
    Derivative(bezier::DerivativeCommand),
    Spline(course::SplineCommand),
    Hermite(course::HermiteCommand),
    Bspline(course::BSplineCommand),
    Nurbs(course::NurbsCommand),
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
    Arc(circle::ArcCommand),
    Curve(CurveCommand),
    Surface(SurfaceCommand),
    Serve(crate::serve::ServeCommand),
    Script(ScriptCommand),
}

/// Sample a curve given as an expression in its parameter, as the thesis writes curves.
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: the result is d × k, one point per column (like T in the thesis's deCasteljau).

Examples:
  cagd curve \"[u; 0; u-u^2]\" --n 5
  cagd curve \"[u; 0.5; 0.5+u-u^2]\" --t \"[0 0.25 0.5]\" --exact
  cagd curve \"[cos(2*pi*t); sin(2*pi*t)]\" --n 50 --plot circle.svg")]
struct CurveCommand {
    /// The curve: an expression in one parameter t, u or v, e.g. "[u; 0; u-u^2]".
    #[arg(value_name = "EXPR", allow_hyphen_values = true)]
    expr: String,
    #[command(flatten)]
    params: CurveParamArgs,
    #[command(flatten)]
    script: ScriptArgs,
    #[command(flatten)]
    output: OutputArgs,
    #[command(flatten)]
    plot: PlotArgs,
}

/// Sample a surface given as an expression in u and v on a grid.
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: the result is a grid of shape (nu, nv, d): result(i,j,:) is the point at (u(i), v(j)),
like P in the thesis's ploskevB.

Examples:
  cagd surface \"[u; v; u.*v]\" --n 3
  cagd surface \"[u; v; u-u^2+v]\" --n 20 --plot patch.png --mesh patch.stl")]
struct SurfaceCommand {
    /// The surface: an expression in u and v, e.g. "[u; v; u.*v]".
    #[arg(value_name = "EXPR", allow_hyphen_values = true)]
    expr: String,
    #[command(flatten)]
    params: SurfaceParamArgs,
    #[command(flatten)]
    script: ScriptArgs,
    #[command(flatten)]
    output: OutputArgs,
    #[command(flatten)]
    plot: PlotArgs,
    #[command(flatten)]
    mesh: MeshArgs,
}

/// Run a thesis-style Octave data script and print the variables it defines.
#[derive(Debug, Args)]
#[command(after_help = "\
Scripts may contain assignments, indexed assignments x(i) = ..., for loops, comments and
continuations. Right-hand sides that use u, v or t without defining them are kept as curves
in that parameter (appendix C: c1 = [u;0;u-u^2]).

Examples:
  cagd script data.m --n 10
  cagd script data.m --format json")]
struct ScriptCommand {
    /// The Octave data script, or - for standard input.
    #[arg(value_name = "FILE")]
    file: String,
    /// Bind N (used by the thesis scripts, e.g. u = linspace(0,1,N)) before running.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    n: Option<usize>,
    #[command(flatten)]
    output: OutputArgs,
}

use common::DEFAULT_SAMPLES;
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
    let outcome = cli.command.run(&mut cx).map_err(|e| {
        // A non-finite result is about the command's input (see `common::finish`).
        if e.argument == common::RESULT {
            let (name, input) = cli.command.input();
            CliError {
                argument: input.to_string(),
                problem: e
                    .problem
                    .replacen("the result", &format!("the {name} result"), 1),
                ..e
            }
        } else {
            e
        }
    });
    // The slips noticed while reading the input come first; each warning is printed once.
    let mut warnings = crate::slips::take();
    let mut outcome = outcome?;
    warnings.append(&mut outcome.warnings);
    outcome.warnings = crate::slips::dedup(warnings);
    Ok(outcome)
}

impl Command {
    /// The subcommand's name and the input its result is computed from.
    fn input(&self) -> (&'static str, &'static str) {
        match self {
            Command::Thesis(_) => ("thesis", "thesis"),
            Command::Decasteljau(_) => ("decasteljau", "CONTROL"),
            Command::BezierPatch(_) => ("bezier-patch", "NET"),
            Command::Coons(_) => ("coons", "--c1/--c2/--d1/--d2"),
            Command::CoonsBicubic(_) => ("coons-bicubic", "--c1/--c2/--d1/--d2"),
            Command::DiscreteCoons(_) => ("discrete-coons", "NET"),
            Command::Gordon(_) => ("gordon", "--u-curve/--v-curve"),
            Command::Lagrange(_) => ("lagrange", "--nodes/--points"),
            Command::Bernstein(_) => ("bernstein", "--degree"),
            Command::Derivative(_) => ("derivative", "CONTROL"),
            Command::Spline(_) => ("spline", "POINTS"),
            Command::Hermite(_) => ("hermite", "--p0/--p1/--t0/--t1"),
            Command::Bspline(_) => ("bspline", "CONTROL"),
            Command::Nurbs(_) => ("nurbs", "CONTROL"),
            Command::Curve(_) => ("curve", "EXPR"),
            Command::Surface(_) => ("surface", "EXPR"),
            Command::Script(_) => ("script", "FILE"),
            Command::Serve(_) => ("serve", "--dir"),
            Command::Course(_) => ("course", "course"),
            Command::Convert(_) => ("convert", "GEOMETRY"),
            Command::Elevate(_) => ("elevate", "CONTROL"),
            Command::Subdivide(_) => ("subdivide", "CONTROL"),
            Command::InsertKnot(_) => ("insert-knot", "CONTROL"),
            Command::BsplineBasis(_) => ("bspline-basis", "--knots"),
            Command::Continuity(_) => ("continuity", "FIRST/SECOND"),
            Command::Curvature(_) => ("curvature", "CURVE"),
            Command::Integrate(_) => ("integrate", "CONTROL"),
            Command::Ruled(_) => ("ruled", "--first/--second"),
            Command::Ferguson(_) => ("ferguson", "--points"),
            Command::BsplineSurface(_) => ("bspline-surface", "NET"),
            Command::NurbsSurface(_) => ("nurbs-surface", "NET"),
            Command::Circle(_) => ("circle", "--radius"),
            Command::Arc(_) => ("arc", "--radius"),
        }
    }
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

/// Runs `--script` if given, binding `N` first.
pub fn prepare_script<T: LiteralScalar>(
    limits: &Limits,
    script: &ScriptArgs,
    n: Option<usize>,
) -> Result<Option<Script<T>>, CliError> {
    read::run_script(limits, script, n)
}

fn script_warnings<T: LiteralScalar>(
    script: &ScriptArgs,
    loaded: Option<&Script<T>>,
) -> Vec<(String, Warning)> {
    match (&script.script, loaded) {
        (Some(path), Some(s)) => s
            .warnings()
            .into_iter()
            .map(|w| (format!("--script {path}"), w))
            .collect(),
        _ => Vec::new(),
    }
}

fn to_f64_matrix<T: LiteralScalar>(m: &DMatrix<T>) -> DMatrix<f64> {
    m.map(|x| x.to_f64())
}

fn curve<T: LiteralScalar>(limits: &Limits, cmd: &CurveCommand) -> Result<Outcome, CliError> {
    let loaded = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let expr = load_expression(limits, "EXPR", &cmd.expr, loaded.as_ref())?;
    let mut env = loaded.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let params = expr.parameters(&env);
    let param = match params.as_slice() {
        [] => "t",
        [p] => p,
        _ => {
            return Err(CliError::new(
                "EXPR",
                format!(
                    "`{}` uses the parameters {}",
                    cmd.expr.trim(),
                    params.join(" and ")
                ),
                "a curve in one parameter (t, u or v); use `cagd surface` for u and v",
                ErrorKind::Shape,
            ))
        }
    };
    let values: Vec<T> = match (&cmd.params.t, cmd.params.n) {
        (Some(t), _) => load_params(limits, "--t", t)?,
        (None, n) => samples(limits, n.unwrap_or(DEFAULT_SAMPLES), 2)?,
    };
    work::check_expression_work(
        limits,
        &[work::Sampling {
            argument: "EXPR",
            expr: &expr,
            params: vec![(param, &values)],
        }],
        &env,
    )?;
    let points = expr
        .sample_curve(&mut env, param, &values)
        .map_err(|e| CliError::literal("EXPR", e, CURVE_FORM))?;
    let mut report = Report::new();
    report.push(
        param,
        Value::Matrix(DMatrix::from_row_slice(1, values.len(), &values)),
    );
    report.push("result", Value::Matrix(points.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let figure = Figure::new(format!("curve {}", cmd.expr.trim())).curve(
            to_f64_matrix(&points),
            Colour::Blue,
            format!("{param} ↦ {}", cmd.expr.trim()),
        );
        common::add_plot(&mut files, "--plot", path, &figure)?;
    }
    let mut warnings = script_warnings(&cmd.script, loaded.as_ref());
    warnings.extend(env.take_warnings().into_iter().map(|w| ("EXPR".into(), w)));
    common::finish(&report, &cmd.output, files, warnings)
}

fn surface<T: LiteralScalar>(limits: &Limits, cmd: &SurfaceCommand) -> Result<Outcome, CliError> {
    let loaded = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let expr = load_expression(limits, "EXPR", &cmd.expr, loaded.as_ref())?;
    let mut env = loaded.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let grid_samples = |given: &Option<String>, name: &str| -> Result<Vec<T>, CliError> {
        match given {
            Some(text) => load_params(limits, name, text),
            None => samples(limits, cmd.params.n.unwrap_or(DEFAULT_SAMPLES), 2),
        }
    };
    let us = grid_samples(&cmd.params.u, "--u")?;
    let vs = grid_samples(&cmd.params.v, "--v")?;
    common::check_grid(limits, us.len(), vs.len())?;
    work::check_expression_work(
        limits,
        &[work::Sampling {
            argument: "EXPR",
            expr: &expr,
            params: vec![("u", &us), ("v", &vs)],
        }],
        &env,
    )?;
    let grid = expr.sample_surface(&mut env, &us, &vs).map_err(|e| {
        CliError::literal(
            "EXPR",
            e,
            "an expression in u and v such as \"[u; v; u.*v]\"",
        )
    })?;
    let mut report = Report::new();
    report.push(
        "u",
        Value::Matrix(DMatrix::from_row_slice(1, us.len(), &us)),
    );
    report.push(
        "v",
        Value::Matrix(DMatrix::from_row_slice(1, vs.len(), &vs)),
    );
    let grid_f64: PointGrid<f64> = grid.map(|x| x.to_f64());
    common::push_surface(&mut report, "result", (&us, &vs), grid, cmd.params.list);
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let figure = Figure::new(format!("surface {}", cmd.expr.trim()))
            .surface(grid_f64.clone(), "surface");
        common::add_plot(&mut files, "--plot", path, &figure)?;
    }
    if let Some(path) = &cmd.mesh.mesh {
        common::add_mesh(&mut files, "--mesh", path, &grid_f64)?;
    }
    let mut warnings = script_warnings(&cmd.script, loaded.as_ref());
    warnings.extend(env.take_warnings().into_iter().map(|w| ("EXPR".into(), w)));
    common::finish(&report, &cmd.output, files, warnings)
}

fn script<T: LiteralScalar>(limits: &Limits, cmd: &ScriptCommand) -> Result<Outcome, CliError> {
    let args = ScriptArgs {
        script: Some(cmd.file.clone()),
    };
    let loaded = prepare_script::<T>(limits, &args, cmd.n)?
        .ok_or_else(|| CliError::new("FILE", "no script", "a script file", ErrorKind::Internal))?;
    let mut report = Report::new();
    for name in loaded.names() {
        match loaded.get(name) {
            Some(Binding::Value(m)) => {
                report.push(name, Value::Matrix(m.clone()));
            }
            Some(Binding::Function(f)) => {
                let params = f.parameters(loaded.env());
                report.push(
                    name,
                    Value::Text(format!(
                        "{}    (expression in {})",
                        f.source(),
                        params.join(", ")
                    )),
                );
            }
            None => {}
        }
    }
    let warnings = loaded
        .warnings()
        .into_iter()
        .map(|w| (cmd.file.clone(), w))
        .collect();
    common::finish(&report, &cmd.output, PendingWrites::new(), warnings)
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
