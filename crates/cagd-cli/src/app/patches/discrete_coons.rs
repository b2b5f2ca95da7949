//! `discrete-coons`: the interior of a control net from its boundary, by formula or mask.

use cagd::grid::PointGrid;
use cagd::limits::Limits;
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{OutputArgs, PlotArgs, ScriptArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_net, CliError, PendingWrites, Report, Value};
use cagd::coons::{discrete_coons, discrete_coons_cost, solve_mask, Mask};

use cagd_octave::literal::{Env, LiteralScalar};

use super::super::common::*;
use super::super::work::{bits, check_work, weigh};
use super::super::{prepare_script, Outcome};

/// The discrete Coons patch: interior control points from the boundary of a net.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: a net as for bezier-patch; only its boundary rows and columns are used.
Layout: result is the full net (m+1)×(n+1)×3; --steps also prints its parts bu, bv, buv (the
CAD notes (6): net = bu + bv − buv).
--mask=ALPHA,BETA solves the affine mask instead (alpha + beta = 1/4): α = −1/4, β = 1/2 is the
permanence principle's mask, the discrete Coons patch again; α = 0, β = 1/4 the discrete Laplace
mask.

Examples:
  cagd discrete-coons \"[0 0 0 0 1 0 0 2 0; 1 0 0 0 0 0 1 2 1; 2 0 0 2 1 1 2 2 0]\"
  cagd discrete-coons net.txt --mask=0,0.25")]
pub struct DiscreteCoonsCommand {
    /// A Bézier control net, packed (m+1)×3(n+1) as ploskevB takes it, or an Octave
    /// (m+1)×(n+1)×3 array file. Only its boundary rows and columns are used.
    #[arg(value_name = "NET", allow_hyphen_values = true)]
    pub net: String,
    /// Solve the affine mask P_ij = α·(the 4 diagonal neighbours) + β·(the 4 edge neighbours)
    /// for every interior point instead of the discrete Coons formula; α + β must be 1/4.
    /// α = −1/4, β = 1/2 is the mask the permanence principle gives (the CAD notes (7)–(8)):
    /// the discrete Coons patch again; α = 0, β = 1/4 is the discrete Laplace mask (each
    /// point the average of its 4 edge neighbours). E.g. --mask=-0.25,0.5.
    #[arg(long, value_name = "ALPHA,BETA", allow_hyphen_values = true)]
    pub mask: Option<String>,
    /// Also print the three parts of the discrete Coons formula (the CAD notes (6)):
    /// b^u = (1 − i/m) P_0j + (i/m) P_mj, b^v = (1 − j/n) P_i0 + (j/n) P_in and the corner
    /// term b^uv; the net is b^u + b^v − b^uv.
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub script: ScriptArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The work of the exact band solve of a mask on `net` ([`Mask::solve_cost`] for every
/// coordinate), on numbers as large as the net's and the mask's. The library refuses the
/// operation count itself above `--max-work`, counting each as one.
fn exact_mask_work<T: LiteralScalar>(net: &PointGrid<T>, mask: &Mask<T>) -> u128 {
    let (m1, n1, d) = net.dim();
    let size_bits = bits(net.iter()).max(bits(&[mask.alpha(), mask.beta()]));
    weigh::<T>(
        mask.solve_cost(m1.saturating_sub(1), n1.saturating_sub(1))
            .times(d as u128)
            .grown(size_bits),
    )
}

/// The interior control points from the boundary of a net.
pub fn discrete<T: LiteralScalar>(
    limits: &Limits,
    cmd: &DiscreteCoonsCommand,
) -> Result<Outcome, CliError> {
    let script = prepare_script::<T>(limits, &cmd.script, None)?;
    let net = load_net::<T>(limits, "NET", &cmd.net, script.as_ref())?;
    let (m1, n1, d) = net.dim();
    check_degree(limits, "NET", m1.max(n1).saturating_sub(1))?;
    let coords: Vec<DMatrix<T>> = (0..d)
        .map(|k| DMatrix::from_fn(m1, n1, |i, j| net[[i, j, k]].clone()))
        .collect();
    let expected = "a net of at least 3×3 points";
    if cmd.steps.steps && cmd.mask.is_some() {
        return Err(usage(
            "--steps",
            "has no effect with --mask (the mask is solved as one linear system)",
            "--steps without --mask (the parts of the discrete Coons formula)",
        ));
    }
    let full = match &cmd.mask {
        None => {
            // The formula, and with --steps its three parts once more.
            let passes = if cmd.steps.steps { 2 } else { 1 };
            let cost = discrete_coons_cost(m1.saturating_sub(1), n1.saturating_sub(1), d)
                .times(passes)
                .grown(bits(net.iter()));
            check_work(limits, "NET", weigh::<T>(cost))?;
            discrete_coons(&coords).map_err(lib("NET", expected))?
        }
        Some(text) => {
            let form = "two numbers α,β with α + β = 1/4, e.g. -0.25,0.5";
            // Not load_params: the comma between α and β is not a decimal comma.
            let values: Vec<T> =
                cagd_octave::literal::parse_params_with(&format!("[{text}]"), limits)
                    .map_err(|e| CliError::literal("--mask", e, form))?;
            let [alpha, beta]: [T; 2] = values
                .try_into()
                .map_err(|v: Vec<T>| shape("--mask", format!("{} value(s)", v.len()), form))?;
            let mask = Mask::new(alpha, beta).map_err(lib("--mask", form))?;
            if T::EXACT {
                check_work(limits, "NET", exact_mask_work(&net, &mask))?;
            }
            solve_mask(&coords, &mask, limits).map_err(lib("NET", expected))?
        }
    };
    let grid = PointGrid::from_shape_fn((m1, n1, d), |(i, j, k)| full[k][(i, j)].clone());
    let mut report = Report::new();
    if cmd.steps.steps {
        let [bu, bv, buv] = super::super::discrete_parts::parts(&net);
        report.push("bu", Value::Grid(bu));
        report.push("bv", Value::Grid(bv));
        report.push("buv", Value::Grid(buv));
    }
    report.push("result", Value::Grid(grid.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let g = grid_f64(&grid);
        let figure = Figure::new("discrete Coons net")
            .surface(g.clone(), "net as a surface")
            .net(g, Colour::Red, "control net");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(
        &report,
        &cmd.output,
        files,
        warnings(
            &cmd.script.script,
            script.as_ref(),
            &mut Env::with_limits(*limits),
        ),
    )
}
