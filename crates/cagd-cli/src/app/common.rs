//! Helpers shared by the subcommands: loading curves given as expressions or control points,
//! parameter lists, library errors, pictures and meshes.

use cagd::limits::Limits;
use std::path::Path;

use cagd::grid::PointGrid;
use nalgebra::{DMatrix, DVector};

use crate::args::OutputArgs;
use crate::plot::{Figure, ImageKind};
use crate::{load_matrix, render_with, CliError, ErrorKind, PendingWrites, Report, CURVE_FORM};
use cagd::{Curve, SampledCurve};
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr, Warning};
use cagd_octave::script::{Binding, Script};

use super::outcome::Outcome;
use super::run::Names;
pub(crate) use crate::error::{lib, shape, usage};

/// The form of a boundary or network curve argument.
pub const CURVE_ARG_FORM: &str = "an expression in the curve parameter such as \"[u; 0; u-u^2]\", or control points (columns) of a Bézier curve such as \"[0 0 0; 1 0 1]'\"";

/// Refuses a degree above [`cagd::limits::Limits::max_degree`].
pub fn check_degree(limits: &Limits, argument: &str, degree: usize) -> Result<(), CliError> {
    limits.check_degree("degree", degree).map_err(lib(
        argument,
        "a lower degree (fewer control points or nodes), or a higher --max-degree",
    ))
}

/// A 1×k row of values.
pub fn row<T: LiteralScalar>(values: &[T]) -> DMatrix<T> {
    DMatrix::from_row_slice(1, values.len(), values)
}

/// A column point as a d×1 matrix.
pub fn column<T: LiteralScalar>(p: &DVector<T>) -> DMatrix<T> {
    DMatrix::from_column_slice(p.len(), 1, p.as_slice())
}

/// A matrix in doubles, for pictures.
pub fn to_f64<T: LiteralScalar>(m: &DMatrix<T>) -> DMatrix<f64> {
    m.map(|x| x.to_f64())
}

/// Sorted distinct values of `lists` together with 0 and 1: where a sampled curve must be
/// exact.
pub fn needed<T: LiteralScalar>(lists: &[&[T]]) -> Vec<T> {
    let mut all: Vec<T> = vec![T::zero(), T::one()];
    for l in lists {
        all.extend(l.iter().cloned());
    }
    all.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    all.dedup();
    all
}

/// A curve argument before it is sampled.
#[derive(Debug, Clone)]
pub enum CurveSource<T: LiteralScalar> {
    /// An expression in one parameter.
    Expr(ParamExpr, &'static str),
    /// Samples of a thesis data script at the given parameters.
    Samples(Vec<T>, DMatrix<T>),
}

/// A script's variable as a curve: a curve expression, or a sampled 3×N matrix whose
/// parameters are the script's `param` variable (or `linspace(0,1,N)`).
pub fn script_curve<T: LiteralScalar>(
    script: &Script<T>,
    name: &str,
    param: &str,
) -> Option<CurveSource<T>> {
    match script.get(name)? {
        Binding::Function(f) => {
            let params = f.parameters(script.env());
            let p = params.first().copied().unwrap_or("t");
            Some(CurveSource::Expr(script.resolve(name).ok()?, p))
        }
        Binding::Value(m) => Some(CurveSource::Samples(
            script_params(script, param, m.ncols()),
            m.clone(),
        )),
    }
}

/// The script's parameter row `name` if it has `count` values, else `linspace(0,1,count)`.
pub fn script_params<T: LiteralScalar>(script: &Script<T>, name: &str, count: usize) -> Vec<T> {
    match script.value(name) {
        Some(m) if m.len() == count && (m.nrows() == 1 || m.ncols() == 1) => {
            m.iter().cloned().collect()
        }
        _ => T::linspace(&T::zero(), &T::one(), count),
    }
}

impl<T: LiteralScalar> CurveSource<T> {
    /// The curve, exact at every value of `at` (expressions are evaluated there).
    pub fn build(
        &self,
        argument: &str,
        at: &[T],
        env: &mut Env<T>,
    ) -> Result<SampledCurve<T>, CliError> {
        match self {
            CurveSource::Expr(e, p) => {
                let m = e
                    .sample_curve(env, p, at)
                    .map_err(|e| CliError::literal(argument, e, CURVE_FORM))?;
                // An expression is a curve on [0, 1], sampled also where the grid reaches beyond.
                SampledCurve::new(at.to_vec(), m)
                    .and_then(|c| c.with_domain(T::zero(), T::one()))
                    .map_err(lib(argument, CURVE_ARG_FORM))
            }
            CurveSource::Samples(params, m) => SampledCurve::new(params.clone(), m.clone())
                .map_err(lib(argument, "a curve sampled at increasing parameters")),
        }
    }
}

/// Samples a curve at `ts` as a d×k matrix.
pub fn sample<T: LiteralScalar, C: Curve<T>>(c: &C, ts: &[T]) -> DMatrix<T> {
    let cols: Vec<DVector<T>> = ts.iter().map(|t| c.eval(t.clone())).collect();
    DMatrix::from_columns(&cols)
}

/// Adds a picture to the pending files.
pub fn add_plot(
    files: &mut PendingWrites,
    argument: &str,
    path: &Path,
    figure: &Figure,
) -> Result<(), CliError> {
    let plot_error =
        |e: crate::plot::PlotError| CliError::plot(format!("{argument} {}", path.display()), &e);
    // Standard output gets SVG, the picture format that is text.
    let kind = if path.as_os_str() == "-" {
        ImageKind::Svg
    } else {
        ImageKind::from_path(path).map_err(plot_error)?
    };
    let bytes = figure.render(kind).map_err(plot_error)?;
    files.add(argument, path, bytes);
    Ok(())
}

/// Adds a triangle mesh of a grid to the pending files.
pub fn add_mesh(
    files: &mut PendingWrites,
    argument: &str,
    path: &Path,
    grid: &PointGrid<f64>,
) -> Result<(), CliError> {
    let mesh_error =
        |e: crate::mesh::MeshError| CliError::mesh(format!("{argument} {}", path.display()), &e);
    // Standard output gets OBJ, a mesh format that is text.
    let format = if path.as_os_str() == "-" {
        crate::mesh::MeshFormat::Obj
    } else {
        crate::mesh::MeshFormat::from_path(path).map_err(mesh_error)?
    };
    let bytes = crate::mesh::encode(grid, format).map_err(mesh_error)?;
    files.add(argument, path, bytes);
    Ok(())
}

/// The end of every subcommand: the result text goes to standard output, or with `-o FILE`
/// to that file (staged with the other `files`), and is handed back with the files and the
/// warnings. A result that overflows is refused about the input it was computed from.
pub fn finish<T: LiteralScalar>(
    report: &Report<T>,
    output: &OutputArgs,
    mut files: PendingWrites,
    warnings: Vec<(String, Warning)>,
    names: &Names,
) -> Result<Outcome, CliError> {
    if let Some((name, index, value)) = report.first_non_finite() {
        return Err(CliError::new(
            names.input,
            format!("the result overflows the range of doubles ({name}, element {index}: {value})"),
            "inputs whose result stays within ±1.8e308 (smaller coordinates, parameters or orders)",
            ErrorKind::Library(Box::new(cagd::Error::NonFinite {
                what: "result",
                index,
                value,
            })),
        ));
    }
    let text = render_with(report, output.format, output.text_digits())?;
    let stdout = match &output.output {
        Some(path) => {
            files.add("--output", path, text.into_bytes());
            String::new()
        }
        None => text,
    };
    Ok(Outcome {
        stdout,
        files,
        warnings,
    })
}

/// Warnings of a script and of an evaluation environment, named by argument.
pub fn warnings<T: LiteralScalar>(
    script_path: &Option<String>,
    script: Option<&Script<T>>,
    env: &mut Env<T>,
) -> Vec<(String, Warning)> {
    let mut out: Vec<(String, Warning)> = match (script_path, script) {
        (Some(path), Some(s)) => s
            .warnings()
            .into_iter()
            .map(|w| (format!("--script {path}"), w))
            .collect(),
        _ => Vec::new(),
    };
    // The environment starts as a copy of the script's, so it repeats the script's warnings:
    // each is reported once, about the script.
    let from_script: Vec<Warning> = out.iter().map(|(_, w)| w.clone()).collect();
    out.extend(
        env.take_warnings()
            .into_iter()
            .filter(|w| !from_script.contains(w))
            .map(|w| ("expression".to_string(), w)),
    );
    out
}

/// The net of `--x`, `--y`, `--z` (the lecture notes' `X`, `Y`, `Z` of a patch): one
/// `(m+1) × (n+1)` matrix per coordinate given (`--x` at least), entry `(i, j)` of point
/// `P_ij`.
pub fn coordinate_net<T: LiteralScalar>(
    limits: &Limits,
    given: [&Option<String>; 3],
    script: Option<&Script<T>>,
) -> Result<PointGrid<T>, CliError> {
    let mut coords = Vec::with_capacity(3);
    for (arg, given) in ["--x", "--y", "--z"].into_iter().zip(given) {
        if let Some(text) = given {
            coords.push((arg, load_matrix::<T>(limits, arg, text, script)?));
        }
    }
    let Some((_, first)) = coords.first() else {
        return Err(usage(
            "--x",
            "missing",
            "the coordinate matrices --x, --y (and --z)",
        ));
    };
    let shape0 = first.shape();
    if let Some((arg, m)) = coords.iter().find(|(_, m)| m.shape() != shape0) {
        return Err(shape(
            arg,
            format!(
                "a {}×{} matrix, but --x is {}×{}",
                m.nrows(),
                m.ncols(),
                shape0.0,
                shape0.1
            ),
            "coordinate matrices of one shape (m+1)×(n+1)",
        ));
    }
    Ok(PointGrid::from_shape_fn(
        (shape0.0, shape0.1, coords.len()),
        |(i, j, k)| coords[k].1[(i, j)].clone(),
    ))
}
