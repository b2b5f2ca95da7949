//! Argument groups shared by the subcommands (clap derive), so that every subcommand spells
//! the same option the same way: `--format`, `--exact`, `-o/--output`, `--plot`, `--mesh`,
//! `--steps`, `--script`, `--t`, `--u`, `--v`, `--n`, `--rows`.

use std::path::PathBuf;

use cagd::limits::{Limit, Limits};
use clap::Args;

use super::Format;

/// A path argument (`-o`, `--plot`, `--mesh`, `--dir`): any non-empty text (an empty one
/// names no file).
///
/// # Errors
/// The reason, for clap to report, when the text is empty.
pub fn path_value(text: &str) -> Result<PathBuf, String> {
    if text.is_empty() {
        return Err("an empty path names no file".into());
    }
    Ok(PathBuf::from(text))
}

/// How and where the numeric result is printed.
#[derive(Debug, Clone, Args)]
pub struct OutputArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Compute in exact rational arithmetic and print fractions such as 7/2 (decimal inputs
    /// are read exactly: 0.2 is 1/5). Only for rational constructions and expressions.
    #[arg(long)]
    pub exact: bool,
    /// Write the result to FILE (atomically) instead of standard output (`-` is standard
    /// output). An existing FILE must be a regular file: a FIFO, a device or a folder is
    /// refused, never replaced.
    #[arg(short = 'o', long, value_name = "FILE", value_parser = path_value)]
    pub output: Option<PathBuf>,
    /// Significant digits of the numbers in the text format (1 to 17; default 15, which hides
    /// round-off such as 0.30000000000000004). The octave, csv and json formats keep every bit.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: Option<u8>,
}

impl OutputArgs {
    /// The significant digits of the text format.
    pub fn text_digits(&self) -> usize {
        self.digits.map_or(crate::TEXT_DIGITS, usize::from)
    }
}

/// A picture of the result.
#[derive(Debug, Clone, Args)]
pub struct PlotArgs {
    /// Draw the result into FILE.svg or FILE.png (format chosen by the extension; `-` writes
    /// SVG to standard output, with the result sent elsewhere by -o).
    #[arg(long, value_name = "FILE", value_parser = path_value)]
    pub plot: Option<PathBuf>,
}

/// A triangulated surface of a grid result.
#[derive(Debug, Clone, Args)]
pub struct MeshArgs {
    /// Write the surface as a triangle mesh to FILE.stl (binary), FILE.obj or FILE.ply
    /// (ASCII), chosen by the extension (`-` writes OBJ to standard output, with the result
    /// sent elsewhere by -o).
    #[arg(long, value_name = "FILE", value_parser = path_value)]
    pub mesh: Option<PathBuf>,
}

/// Intermediate results of an algorithm.
#[derive(Debug, Clone, Args)]
pub struct StepsArgs {
    /// Also print the intermediate steps of the algorithm.
    #[arg(long)]
    pub steps: bool,
}

/// A thesis-style data script whose variables the other arguments may use.
#[derive(Debug, Clone, Args)]
pub struct ScriptArgs {
    /// Run the Octave data script FILE (assignments and for loops, as in the thesis
    /// appendices) first; its variables may be used in the other arguments. `N` is bound to
    /// `--n` when given.
    #[arg(long, value_name = "FILE")]
    pub script: Option<String>,
}

/// Parameters of a curve.
#[derive(Debug, Clone, Args)]
pub struct CurveParamArgs {
    /// Curve parameters: a number, a list "[0 0.25 0.5]" or a range 0:0.1:1.
    #[arg(
        long,
        value_name = "VALUES",
        allow_hyphen_values = true,
        conflicts_with = "n"
    )]
    pub t: Option<String>,
    /// Sample at linspace(0,1,N), like the thesis's N.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub n: Option<usize>,
}

/// Parameters of a surface.
#[derive(Debug, Clone, Args)]
pub struct SurfaceParamArgs {
    /// Parameters u: a number, a list "[0 0.5 1]" or a range 0:0.1:1 (default: --n samples).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub u: Option<String>,
    /// Parameters v: a number, a list or a range (default: --n samples).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub v: Option<String>,
    /// Sample u and v at linspace(0,1,N), like the thesis's N.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub n: Option<usize>,
    /// List the surface one point per line, `u v x y z` (a matrix with one row per grid
    /// point, u varying slowest), instead of the nu×nv×d grid.
    #[arg(long)]
    pub list: bool,
}

/// Orientation of point matrices.
#[derive(Debug, Clone, Args)]
pub struct RowsArgs {
    /// Points are the rows of the input matrices (default: the columns, as in the thesis).
    #[arg(long)]
    pub rows: bool,
}

/// Resource limits (see [`cagd::limits`] and [`crate::limits`]); each overrides its `CAGD_MAX_…` environment
/// variable, which overrides the default.
#[derive(Debug, Clone, Default, Args)]
pub struct LimitArgs {
    /// Largest input file or standard input, in bytes [env: CAGD_MAX_INPUT_BYTES; default 64 MiB].
    #[arg(long, global = true, value_name = "BYTES", help_heading = "Limits")]
    pub max_input_bytes: Option<u64>,
    /// Longest literal, expression or script, in bytes [env: CAGD_MAX_EXPRESSION_BYTES; default 1 MiB].
    #[arg(long, global = true, value_name = "BYTES", help_heading = "Limits")]
    pub max_expression_bytes: Option<u64>,
    /// Deepest nesting in an expression [env: CAGD_MAX_DEPTH; default 64].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_depth: Option<u64>,
    /// Most elements of a matrix or range in a literal or script [env: CAGD_MAX_ELEMENTS; default 4000000].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_elements: Option<u64>,
    /// Most loop iterations of a data script [env: CAGD_MAX_ITERATIONS; default 1000000].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_iterations: Option<u64>,
    /// Most parameter values along one axis [env: CAGD_MAX_SAMPLES; default 1000000].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_samples: Option<u64>,
    /// Most points of a surface grid [env: CAGD_MAX_GRID_POINTS; default 10000000].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_grid_points: Option<u64>,
    /// Highest degree of a curve, patch direction or basis [env: CAGD_MAX_DEGREE; default 1000].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_degree: Option<u64>,
    /// Most stored entries of a linear system [env: CAGD_MAX_SYSTEM_ENTRIES; default 100000000].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_system_entries: Option<u64>,
    /// Most arithmetic operations of one command, estimated up front [env: CAGD_MAX_WORK; default 2000000000].
    #[arg(long, global = true, value_name = "N", help_heading = "Limits")]
    pub max_work: Option<u64>,
}

impl LimitArgs {
    /// The limits: defaults, then the environment, then these flags.
    ///
    /// # Errors
    /// A [`CliError`](crate::CliError) naming an environment variable that is not a whole
    /// number.
    pub fn resolve(&self) -> Result<Limits, crate::CliError> {
        let mut limits = crate::limits::from_env()?;
        let flags = [
            (Limit::InputBytes, self.max_input_bytes),
            (Limit::ExpressionBytes, self.max_expression_bytes),
            (Limit::Depth, self.max_depth),
            (Limit::Elements, self.max_elements),
            (Limit::Iterations, self.max_iterations),
            (Limit::Samples, self.max_samples),
            (Limit::GridPoints, self.max_grid_points),
            (Limit::Degree, self.max_degree),
            (Limit::SystemEntries, self.max_system_entries),
            (Limit::Work, self.max_work),
        ];
        for (limit, value) in flags {
            if let Some(v) = value {
                crate::limits::check_cap(crate::limits::flag(limit), limit, v)?;
                limits.set(limit, v);
            }
        }
        Ok(limits)
    }
}
