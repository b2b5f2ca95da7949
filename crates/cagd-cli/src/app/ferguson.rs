//! `ferguson`: the Hermite bicubic (Ferguson) patch of the lecture notes ("Hermitova plocha")
//! from its corner points, tangents and twists.

use cagd::limits::Limits;
use cagd::surfaces::FergusonPatch;
use cagd::Surface;
use cagd_octave::literal::LiteralScalar;
use clap::Args;
use nalgebra::{DMatrix, DVector};

use crate::args::{MeshArgs, OutputArgs, PlotArgs, RowsArgs, StepsArgs, SurfaceParamArgs};
use crate::plot::Figure;
use crate::{CliError, PendingWrites, Report, Value};

use super::bezier::point_mode;
use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::polynomial_bits;
use cagd::cost::Cost;

/// The Hermite bicubic (Ferguson) patch from corner points, tangents and twists.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --points, --du, --dv, --twists (default zero: the F-patch): d×4 matrices whose columns
are the vectors at the corners (u,v) = (0,0), (1,0), (0,1), (1,1) (rows with --rows).
Layout: single --u and --v give the d×1 point; otherwise the grid nu×nv×d, or --list. --steps
prints the geometry matrices G (one per coordinate, rows x(0,·) x(1,·) x_u(0,·) x_u(1,·),
columns x(·,0) x(·,1) x_v(·,0) x_v(·,1)): x(u,v) = f(u)ᵀ G f(v) with the Hermite basis f. The
lecture notes write vᵀ M_Hᵀ X_H M_H u with X_H = Gᵀ.

Example (z = uv):
  cagd ferguson --points \"[0 0 0; 1 0 0; 0 1 0; 1 1 1]'\" --du \"[1 0 0; 1 0 0; 1 0 1; 1 0 1]'\" \\
            --dv \"[0 1 0; 0 1 1; 0 1 0; 0 1 1]'\" --twists \"[0 0 1; 0 0 1; 0 0 1; 0 0 1]'\" --u 0.5 --v 0.25 --exact")]
pub struct FergusonCommand {
    /// The corner points x(0,0), x(1,0), x(0,1), x(1,1) as the columns of a d×4 matrix.
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub points: String,
    /// The u-tangents ∂x/∂u at the corners, in the same order (d×4).
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub du: String,
    /// The v-tangents ∂x/∂v at the corners (d×4).
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub dv: String,
    /// The twists ∂²x/∂u∂v at the corners (d×4; default zero, the lecture notes' F-patch).
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub twists: Option<String>,
    #[command(flatten)]
    pub params: SurfaceParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
    #[command(flatten)]
    pub mesh: MeshArgs,
}

type Corners<T> = [[DVector<T>; 2]; 2];

/// A d×4 matrix of corner vectors as `[i][j]` for the corner `(u, v) = (i, j)`.
fn corners<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
    rows: bool,
) -> Result<Corners<T>, CliError> {
    let m = points::<T>(limits, argument, text, None, rows)?;
    if m.ncols() != 4 || m.nrows() == 0 {
        return Err(shape(
            argument,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            "a d×4 matrix: the vectors at the corners (0,0), (1,0), (0,1), (1,1) as columns",
        ));
    }
    let c = |k: usize| m.column(k).into_owned();
    Ok([[c(0), c(2)], [c(1), c(3)]])
}

/// The Ferguson patch.
pub fn ferguson<T: LiteralScalar>(
    limits: &Limits,
    cmd: &FergusonCommand,
) -> Result<Outcome, CliError> {
    let rows = cmd.rows.rows;
    let points = corners::<T>(limits, "--points", &cmd.points, rows)?;
    let du = corners::<T>(limits, "--du", &cmd.du, rows)?;
    let dv = corners::<T>(limits, "--dv", &cmd.dv, rows)?;
    let d = points[0][0].len();
    let twists = match &cmd.twists {
        Some(t) => corners::<T>(limits, "--twists", t, rows)?,
        None => {
            std::array::from_fn(|_| std::array::from_fn(|_| DVector::from_element(d, T::zero())))
        }
    };
    let patch = FergusonPatch::new(&points, &du, &dv, &twists).map_err(lib(
        "--points/--du/--dv/--twists",
        "four d×4 matrices of the same dimension d",
    ))?;
    let single = point_mode(limits, &cmd.params);
    let us: Vec<T> =
        params_or_samples(limits, "--u", &cmd.params.u, cmd.params.n, DEFAULT_SAMPLES)?;
    let vs: Vec<T> =
        params_or_samples(limits, "--v", &cmd.params.v, cmd.params.n, DEFAULT_SAMPLES)?;
    check_grid(limits, us.len(), vs.len())?;
    let (zero, one) = (T::zero(), T::one());
    crate::slips::outside("--u", &us, &zero, &one, "the patch is extrapolated there");
    crate::slips::outside("--v", &vs, &zero, &one, "the patch is extrapolated there");
    let pictures = cmd.plot.plot.is_some() || cmd.mesh.mesh.is_some();
    let picture: Vec<T> = if single && pictures {
        T::linspace(&zero, &one, 21)
    } else {
        Vec::new()
    };
    // Per point the two Hermite bases (cubics) and 16·d products.
    let data_bits = patch
        .geometry()
        .iter()
        .map(|g| bits(g.iter()))
        .max()
        .unwrap_or(0);
    let grid_work = |us: &[T], vs: &[T]| {
        weigh::<T>(Cost::new(
            us.len() as u128 * vs.len() as u128 * (40 + 32 * d as u128),
            polynomial_bits(3, bits(us), 0) + polynomial_bits(3, bits(vs), data_bits),
        ))
    };
    check_work(
        limits,
        "--u/--v",
        grid_work(&us, &vs).saturating_add(grid_work(&picture, &picture)),
    )?;
    let mut report = Report::new();
    if cmd.steps.steps {
        // G = [x(0,·) x(1,·) x_u(0,·) x_u(1,·)] by rows, [x(·,0) x(·,1) x_v(·,0) x_v(·,1)] by
        // columns, one per coordinate: x(u,v) = f(u)ᵀ G f(v) with the Hermite basis f.
        for (k, g) in patch.geometry().iter().enumerate() {
            report.push(format!("G_{}", k + 1), Value::Matrix(g.clone()));
        }
    }
    report.push("u", Value::Matrix(row(&us)));
    report.push("v", Value::Matrix(row(&vs)));
    let grid = patch.eval_grid(&us, &vs);
    if single && !cmd.params.list {
        report.push(
            "result",
            Value::Matrix(column(&patch.eval(us[0].clone(), vs[0].clone()))),
        );
    } else {
        push_surface(
            &mut report,
            "result",
            (&us, &vs),
            grid.clone(),
            cmd.params.list,
        );
    }
    let mut files = PendingWrites::new();
    if pictures {
        let g = if single {
            grid_f64(&patch.eval_grid(&picture, &picture))
        } else {
            grid_f64(&grid)
        };
        if let Some(path) = &cmd.plot.plot {
            // Around the square: (0,0), (1,0), (1,1), (0,1).
            let corner_points = DMatrix::from_fn(d, 4, |r, c| {
                let (i, j) = ([0, 1, 1, 0][c], [0, 0, 1, 1][c]);
                points[i][j][r].to_f64()
            });
            let figure = Figure::new("Ferguson (Hermite bicubic) patch")
                .surface(g.clone(), "x(u,v)")
                .control_polygon(corner_points, "corners");
            add_plot(&mut files, "--plot", path, &figure)?;
        }
        if let Some(path) = &cmd.mesh.mesh {
            add_mesh(&mut files, "--mesh", path, &g)?;
        }
    }
    finish(&report, &cmd.output, files, Vec::new())
}
