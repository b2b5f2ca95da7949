//! `lagrange`: the Lagrange basis at parameters, or the polynomial through values at nodes.

use cagd::limits::Limits;
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, RowsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, CliError, PendingWrites, Report, Value};
use cagd::lagrange::Lagrange;

use cagd_octave::literal::LiteralScalar;

use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;

/// Lagrange basis polynomials, or the polynomial interpolating values at nodes.
#[derive(Debug, Args)]
#[command(after_help = "\
Nodes: distinct, in any order (the lecture notes' Příklad 1 takes 0, 1/2, 1/4, 1).
Layout: without --points, result is k×(m+1): row = parameter, column = L_0..L_m (in the order of
the nodes given). With --points (d×(m+1), one column per node), result is d×k, the interpolant
at each t. --coefficients adds coefficients (row i: L_i, highest power first, the lecture notes'
G) and with --points polynomial (the interpolant's, A = X G). --linear interpolates --points
piecewise linearly instead (the lecture notes' linear interpolation; increasing nodes).

Examples:
  cagd lagrange --nodes \"[0 0.5 1]\" --t 0.25 --exact
  cagd lagrange --nodes 1:5 --points \"[1 2 3 2 1]\" --t 1:0.5:5")]
pub struct LagrangeCommand {
    /// The nodes x_0..x_m: a list such as "[0 0.5 1]" or a range.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub nodes: String,
    /// Values at the nodes, one column per node (a d×(m+1) matrix, or 1×(m+1) for numbers):
    /// then the interpolating polynomial's values are printed; without it, the basis
    /// polynomials L_0..L_m.
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub points: Option<String>,
    /// Also print the monomial coefficients (highest power first, as Octave's polyfit):
    /// `coefficients`, row i those of L_i (the lecture notes' blending matrix G), and with
    /// --points `polynomial`, those of the interpolant (the lecture notes' A = X G).
    #[arg(long)]
    pub coefficients: bool,
    /// Piecewise-linear interpolation of --points instead of the polynomial (the lecture
    /// notes' "lineární interpolace"; the nodes must increase, the end pieces are extended).
    #[arg(long, requires = "points", conflicts_with = "coefficients")]
    pub linear: bool,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// Lagrange basis values or interpolation (thesis algorithm 8, `Lagrange`).
pub fn lagrange<T: LiteralScalar>(
    limits: &Limits,
    cmd: &LagrangeCommand,
) -> Result<Outcome, CliError> {
    let nodes: Vec<T> = load_params(limits, "--nodes", &cmd.nodes)?;
    check_degree(limits, "--nodes", nodes.len().saturating_sub(1))?;
    // Any order of distinct nodes (the lecture notes' Příklad 1 takes 0, 1/2, 1/4, 1): the
    // barycentric basis is built on the sorted nodes and read back in the order given.
    let mut order: Vec<usize> = (0..nodes.len()).collect();
    order.sort_by(|&a, &b| {
        nodes[a]
            .partial_cmp(&nodes[b])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    let sorted: Vec<T> = order.iter().map(|&k| nodes[k].clone()).collect();
    let ts: Vec<T> =
        params_or_samples(limits, "--t", &cmd.params.t, cmd.params.n, DEFAULT_SAMPLES)?;
    crate::slips::outside(
        "--t",
        &ts,
        &sorted[0],
        &sorted[sorted.len() - 1],
        "the polynomial is extrapolated beyond its nodes",
    );
    // The weights (Lagrange::weights_cost), then per parameter the barycentric basis
    // (Lagrange::basis_cost) or, with values, the interpolant (Lagrange::interpolation_cost).
    // Without values the m+1 basis values of every parameter are written out: about 100
    // operations each to format.
    let values = match &cmd.points {
        Some(text) => Some(points::<T>(limits, "--points", text, None, cmd.rows.rows)?),
        None => None,
    };
    let m1 = nodes.len() as u128;
    let k = ts.len() as u128;
    let (node_bits, param_bits) = (bits(&nodes), bits(&ts));
    let (per_param, written) = match &values {
        Some(v) => (
            Lagrange::<T>::interpolation_cost(
                nodes.len(),
                v.nrows(),
                param_bits,
                node_bits,
                bits(v.iter()),
            ),
            0,
        ),
        None => (
            Lagrange::<T>::basis_cost(nodes.len(), param_bits, node_bits),
            100 * k * m1,
        ),
    };
    // Everything, the set-up (the barycentric weights) included, is charged before it runs,
    // and a refusal names what drives it: many (exact) nodes, or many parameters.
    let setup = weigh::<T>(Lagrange::<T>::weights_cost(nodes.len(), node_bits));
    let per = weigh::<T>(per_param.times(k)).saturating_add(written);
    check_work(
        limits,
        if setup > per { "--nodes" } else { "--t" },
        setup.saturating_add(per),
    )?;
    let basis = Lagrange::new(sorted.clone())
        .map_err(lib("--nodes", "distinct finite nodes, at least one"))?;
    if cmd.linear {
        let values = values.unwrap_or_else(|| DMatrix::zeros(0, 0));
        let mut rows = Vec::with_capacity(values.nrows());
        for r in 0..values.nrows() {
            let f = cagd::interpolation::PiecewiseLinear::new(
                nodes.clone(),
                values.row(r).iter().cloned().collect(),
            )
            .map_err(lib(
                "--nodes/--points",
                "increasing nodes and one value per node (a d×(m+1) --points)",
            ))?;
            rows.push(ts.iter().map(|t| f.eval(t.clone())).collect::<Vec<T>>());
        }
        let mut report = Report::new();
        report.push("t", Value::Matrix(row(&ts)));
        report.push(
            "result",
            Value::Matrix(DMatrix::from_fn(rows.len(), ts.len(), |r, k| {
                rows[r][k].clone()
            })),
        );
        return finish(&report, &cmd.output, PendingWrites::new(), Vec::new());
    }
    let mut report = Report::new();
    if cmd.coefficients {
        let g = cagd::interpolation::blending_matrix(&nodes)
            .map_err(lib("--nodes", "distinct finite nodes, at least one"))?;
        if let Some(v) = &values {
            if v.ncols() == nodes.len() {
                report.push("polynomial", Value::Matrix(T::mat_mul(v, &g)));
            }
        }
        report.push("coefficients", Value::Matrix(g));
    }
    report.push("t", Value::Matrix(row(&ts)));
    let mut files = PendingWrites::new();
    // Position k of the sorted nodes is node order[k] as given.
    let unsorted = |b: Vec<T>| -> Vec<T> {
        let mut out = b.clone();
        for (k, v) in b.into_iter().enumerate() {
            out[order[k]] = v;
        }
        out
    };
    match values {
        None => {
            let rows: Vec<Vec<T>> = ts.iter().map(|t| unsorted(basis.basis(t))).collect();
            let m = DMatrix::from_fn(ts.len(), nodes.len(), |i, j| rows[i][j].clone());
            report.push("result", Value::Matrix(m));
        }
        Some(values) => {
            if values.ncols() == nodes.len()
                && values.nrows() > 1
                && order.iter().enumerate().any(|(k, &j)| k != j)
            {
                crate::slips::warn(
                    "--nodes",
                    "the nodes do not increase, so the curve passes the points in the order of their nodes, not in the order given",
                );
            }
            let sorted_values = if values.ncols() == nodes.len() {
                DMatrix::from_fn(values.nrows(), values.ncols(), |r, k| {
                    values[(r, order[k])].clone()
                })
            } else {
                values.clone()
            };
            let mut cols = Vec::with_capacity(ts.len());
            for t in &ts {
                cols.push(
                    basis
                        .interpolate(&sorted_values, t)
                        .map_err(lib("--points", "one column of values per node"))?,
                );
            }
            let result = DMatrix::from_columns(&cols);
            if let Some(path) = &cmd.plot.plot {
                let (line, pts) = if result.nrows() == 1 {
                    // Numbers: plot (t, p(t)) and (x_i, y_i).
                    let l = DMatrix::from_fn(2, ts.len(), |r, k| {
                        if r == 0 {
                            ts[k].to_f64()
                        } else {
                            result[(0, k)].to_f64()
                        }
                    });
                    let p = DMatrix::from_fn(2, nodes.len(), |r, k| {
                        if r == 0 {
                            nodes[k].to_f64()
                        } else {
                            values[(0, k)].to_f64()
                        }
                    });
                    (l, p)
                } else {
                    (to_f64(&result), to_f64(&values))
                };
                let figure = Figure::new("Lagrange interpolation")
                    .curve(line, Colour::Blue, "interpolating polynomial")
                    .control_polygon(pts, "data");
                add_plot(&mut files, "--plot", path, &figure)?;
            }
            report.push("result", Value::Matrix(result));
        }
    }
    finish(&report, &cmd.output, files, Vec::new())
}
