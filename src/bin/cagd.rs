//! The `cagd` command line: parse the arguments, call the library, print.
//!
//! Every input error is one line `cagd: error: <argument>: <problem>; expected <form>` on
//! standard error with exit code 2; exit code 1 is reserved for internal faults (a panic hook
//! prints one line, never a backtrace). Output files are written atomically, and only after
//! every result has been computed, so a failing command leaves no file behind.

use std::io::Write;
use std::path::Path;

use clap::error::{ContextKind, ErrorKind as ClapKind};
use clap::{Args, CommandFactory, Parser, Subcommand};
use nalgebra::DMatrix;
use ndarray::Array3;
use num_rational::BigRational;

use cagd::cli::args::{
    CurveParamArgs, MeshArgs, OutputArgs, PlotArgs, ScriptArgs, SurfaceParamArgs,
};
use cagd::cli::{
    load_expression, load_params, load_script, render, samples, CliError, ErrorKind, PendingWrites,
    Report, Value, CURVE_FORM,
};
use cagd::octave::literal::{Env, LiteralScalar, Warning};
use cagd::octave::script::{Binding, Script};
use cagd::plot::{Colour, Figure, ImageKind};

/// Curves and surfaces of computer-aided geometric design, checked against GNU Octave.
#[derive(Debug, Parser)]
#[command(name = "cagd", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Sample a curve given as an expression in its parameter, as the thesis writes curves.
    #[command(after_help = "\
Layout: the result is d × k, one point per column (like T in the thesis's deCasteljau).

Examples:
  cagd curve \"[u; 0; u-u^2]\" --n 5
  cagd curve \"[u; 0.5; 0.5+u-u^2]\" --t \"[0 0.25 0.5]\" --exact
  cagd curve \"[cos(2*pi*t); sin(2*pi*t)]\" --n 50 --plot circle.svg")]
    Curve(CurveCommand),
    /// Sample a surface given as an expression in u and v on a grid.
    #[command(after_help = "\
Layout: the result is a grid of shape (nu, nv, d): result(i,j,:) is the point at (u(i), v(j)),
like P in the thesis's ploskevB.

Examples:
  cagd surface \"[u; v; u.*v]\" --n 3
  cagd surface \"[u; v; u-u^2+v]\" --n 20 --plot patch.png --mesh patch.stl")]
    Surface(SurfaceCommand),
    /// Run a thesis-style Octave data script and print the variables it defines.
    #[command(after_help = "\
Scripts may contain assignments, indexed assignments x(i) = ..., for loops, comments and
continuations. Right-hand sides that use u, v or t without defining them are kept as curves
in that parameter (appendix C: c1 = [u;0;u-u^2]).

Examples:
  cagd script data.m --n 10
  cagd script data.m --format json")]
    Script(ScriptCommand),
}

#[derive(Debug, Args)]
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

#[derive(Debug, Args)]
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

#[derive(Debug, Args)]
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

/// Samples taken when neither `--t`/`--u`/`--v` nor `--n` is given: 0:0.1:1.
const DEFAULT_SAMPLES: usize = 11;

/// What a command produced: text for standard output, files, warnings.
struct Outcome {
    stdout: String,
    files: PendingWrites,
    warnings: Vec<(String, Warning)>,
}

fn main() {
    std::panic::set_hook(Box::new(|info| {
        let payload = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unexpected fault".to_string());
        let place = info
            .location()
            .map(|l| format!(" ({}:{})", l.file(), l.line()))
            .unwrap_or_default();
        let message = payload.split_whitespace().collect::<Vec<_>>().join(" ");
        let _ = writeln!(
            std::io::stderr(),
            "cagd: internal error: {message}{place}; this is a bug in cagd"
        );
        std::process::exit(1);
    }));
    std::process::exit(run());
}

fn run() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return usage_error(e),
    };
    let result = match &cli.command {
        Command::Curve(c) if c.output.exact => curve::<BigRational>(c),
        Command::Curve(c) => curve::<f64>(c),
        Command::Surface(c) if c.output.exact => surface::<BigRational>(c),
        Command::Surface(c) => surface::<f64>(c),
        Command::Script(c) if c.output.exact => script::<BigRational>(c),
        Command::Script(c) => script::<f64>(c),
    };
    match result.and_then(finish) {
        Ok(()) => 0,
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "cagd: error: {e}");
            e.exit_code()
        }
    }
}

/// Prints warnings, writes the files, then prints the result.
fn finish(outcome: Outcome) -> Result<(), CliError> {
    let mut stderr = std::io::stderr().lock();
    for (argument, w) in &outcome.warnings {
        let _ = writeln!(stderr, "cagd: warning: {argument}: {w}");
    }
    drop(stderr);
    outcome.files.commit()?;
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(outcome.stdout.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(CliError::io(
            "standard output",
            &e,
            "a writable standard output",
        )),
        _ => Ok(()),
    }
}

/// Runs `--script` if given, binding `N` first.
fn prepare_script<T: LiteralScalar>(
    script: &ScriptArgs,
    n: Option<usize>,
) -> Result<Option<Script<T>>, CliError> {
    let Some(path) = &script.script else {
        return Ok(None);
    };
    let mut env = Env::new();
    if let Some(n) = n {
        env.bind_scalar("N", T::from_usize(n));
    }
    load_script("--script", path, env).map(Some)
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

/// The result text (to standard output, or to `-o FILE`).
fn emit<T: LiteralScalar>(
    report: &Report<T>,
    output: &OutputArgs,
    files: &mut PendingWrites,
) -> Result<String, CliError> {
    let text = render(report, output.format)?;
    match &output.output {
        Some(path) => {
            files.add("--output", path, text.into_bytes());
            Ok(String::new())
        }
        None => Ok(text),
    }
}

fn to_f64_matrix<T: LiteralScalar>(m: &DMatrix<T>) -> DMatrix<f64> {
    m.map(|x| x.to_f64())
}

fn add_plot(files: &mut PendingWrites, path: &Path, figure: &Figure) -> Result<(), CliError> {
    let plot_error =
        |e: cagd::plot::PlotError| CliError::plot(format!("--plot {}", path.display()), &e);
    let kind = ImageKind::from_path(path).map_err(plot_error)?;
    let bytes = figure.render(kind).map_err(plot_error)?;
    files.add("--plot", path, bytes);
    Ok(())
}

fn curve<T: LiteralScalar>(cmd: &CurveCommand) -> Result<Outcome, CliError> {
    let loaded = prepare_script::<T>(&cmd.script, cmd.params.n)?;
    let expr = load_expression("EXPR", &cmd.expr, loaded.as_ref())?;
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
        (Some(t), _) => load_params("--t", t)?,
        (None, n) => samples(n.unwrap_or(DEFAULT_SAMPLES), 2)?,
    };
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
        add_plot(&mut files, path, &figure)?;
    }
    let stdout = emit(&report, &cmd.output, &mut files)?;
    let mut warnings = script_warnings(&cmd.script, loaded.as_ref());
    warnings.extend(env.take_warnings().into_iter().map(|w| ("EXPR".into(), w)));
    Ok(Outcome {
        stdout,
        files,
        warnings,
    })
}

fn surface<T: LiteralScalar>(cmd: &SurfaceCommand) -> Result<Outcome, CliError> {
    let loaded = prepare_script::<T>(&cmd.script, cmd.params.n)?;
    let expr = load_expression("EXPR", &cmd.expr, loaded.as_ref())?;
    let mut env = loaded.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let grid_samples = |given: &Option<String>, name: &str| -> Result<Vec<T>, CliError> {
        match given {
            Some(text) => load_params(name, text),
            None => samples(cmd.params.n.unwrap_or(DEFAULT_SAMPLES), 2),
        }
    };
    let us = grid_samples(&cmd.params.u, "--u")?;
    let vs = grid_samples(&cmd.params.v, "--v")?;
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
    let grid_f64: Array3<f64> = grid.map(|x| x.to_f64());
    report.push("result", Value::Grid(grid));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let figure = Figure::new(format!("surface {}", cmd.expr.trim()))
            .surface(grid_f64.clone(), "surface");
        add_plot(&mut files, path, &figure)?;
    }
    if let Some(path) = &cmd.mesh.mesh {
        let mesh_error =
            |e: cagd::mesh::MeshError| CliError::mesh(format!("--mesh {}", path.display()), &e);
        let format = cagd::mesh::MeshFormat::from_path(path).map_err(mesh_error)?;
        let bytes = cagd::mesh::encode(&grid_f64, format).map_err(mesh_error)?;
        files.add("--mesh", path, bytes);
    }
    let stdout = emit(&report, &cmd.output, &mut files)?;
    let mut warnings = script_warnings(&cmd.script, loaded.as_ref());
    warnings.extend(env.take_warnings().into_iter().map(|w| ("EXPR".into(), w)));
    Ok(Outcome {
        stdout,
        files,
        warnings,
    })
}

fn script<T: LiteralScalar>(cmd: &ScriptCommand) -> Result<Outcome, CliError> {
    let args = ScriptArgs {
        script: Some(cmd.file.clone()),
    };
    let loaded = prepare_script::<T>(&args, cmd.n)?
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
    let mut files = PendingWrites::new();
    let stdout = emit(&report, &cmd.output, &mut files)?;
    Ok(Outcome {
        stdout,
        files,
        warnings: loaded
            .warnings()
            .into_iter()
            .map(|w| (cmd.file.clone(), w))
            .collect(),
    })
}

/// Turns a clap error into the one-line form (help and version print normally, exit 0).
fn usage_error(e: clap::Error) -> i32 {
    if matches!(e.kind(), ClapKind::DisplayHelp | ClapKind::DisplayVersion) {
        let _ = e.print();
        return 0;
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
    let subcommands = Cli::command()
        .get_subcommands()
        .map(|s| s.get_name().to_string())
        .collect::<Vec<_>>()
        .join(", ");
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
    let _ = writeln!(
        std::io::stderr(),
        "cagd: error: {argument}: {problem}; expected {expected}"
    );
    2
}
