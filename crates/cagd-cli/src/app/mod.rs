//! The `cagd` command line in-process: parse the arguments, call the library, and return what
//! would be printed and written (see [`crate::run`]).

use std::ffi::OsString;

use clap::{CommandFactory, FromArgMatches};

mod answer;

mod cli;

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
mod usage;

mod work;

use crate::CliError;

use crate::cx::Cx;
pub(crate) use cli::command;
pub use cli::{serve_request, subcommands};
pub use outcome::Outcome;

/// Parses `args` (the program name first, as `std::env::args_os` gives them) and runs the
/// subcommand. Nothing is written: the files are returned staged in the [`Outcome`].
pub fn run<I, A>(args: I) -> Result<Outcome, CliError>
where
    I: IntoIterator<Item = A>,
    A: Into<OsString> + Clone,
{
    run_with_files(args, Vec::new())
}

/// [`run`] with `files` (name, contents) readable as input files of that name, before the
/// file system: so the web page, which has none, passes a data script typed into it as
/// `--script data.m`.
///
/// ```
/// let files = vec![("data.m".to_string(), "B = [0 0; 1 2]';".to_string())];
/// let out = cagd_cli::run_with_files(["cagd", "script", "data.m"], files).unwrap();
/// assert!(out.stdout.contains("B ="));
/// ```
pub fn run_with_files<I, A>(args: I, files: Vec<(String, String)>) -> Result<Outcome, CliError>
where
    I: IntoIterator<Item = A>,
    A: Into<OsString> + Clone,
{
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    let matches = match cli::Cli::command().try_get_matches_from(&args) {
        Ok(m) => m,
        Err(e) => return usage::usage_error(e, &args),
    };
    // Output targets are checked before any work (and before the limits, which may fail).
    crate::outputs::check(&matches)?;
    let cli = match cli::Cli::from_arg_matches(&matches) {
        Ok(cli) => cli,
        Err(e) => return usage::usage_error(e, &args),
    };
    let mut cx = Cx::new(cli.limits.resolve()?)
        .with_files(files)
        .stating_orientation(orientation_stated(&matches));
    let outcome = cli.command.run(&mut cx).map_err(|e| {
        // An error about points says how they were read; one about numbers read with
        // decimal commas says so.
        let how = crate::slips::explain(&cx, &e.argument, &e.problem);
        if how.is_empty() {
            e
        } else {
            CliError {
                problem: format!("{} ({how})", e.problem),
                ..e
            }
        }
    });
    // The slips noticed while reading the input come first; each warning is printed once.
    let mut warnings = crate::slips::take(&cx);
    let mut outcome = outcome?;
    warnings.append(&mut outcome.warnings);
    outcome.warnings = crate::slips::dedup(warnings);
    Ok(outcome)
}

/// Whether the subcommand's command line states the orientation of points (`--rows` or
/// `--columns`).
fn orientation_stated(matches: &clap::ArgMatches) -> bool {
    let Some((_, sub)) = matches.subcommand() else {
        return false;
    };
    ["rows", "columns"]
        .iter()
        .any(|id| matches!(sub.try_get_one::<bool>(id), Ok(Some(true))))
}
