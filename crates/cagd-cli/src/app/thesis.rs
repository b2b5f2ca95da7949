//! `cagd thesis`: every worked example and appendix run of the thesis, with steps, pictures
//! and meshes.

use cagd::limits::Limits;
use std::fmt::Write as _;
use std::path::PathBuf;

use cagd::grid::PointGrid;
use clap::Args;
use nalgebra::{DMatrix, DVector};

use crate::plot::{Colour, Figure};
use crate::{CliError, PendingWrites, Report, Value};
use cagd::bezier::{BezierCurve, BezierPatch};
use cagd::{CoonsPatch, GordonSurface, SampledCurve, Surface, Tolerance};
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr};

use super::common::*;
use super::run::Run;
use super::worked::{coons_figure, curve_line, heading, q, text, Files, Q};
use super::Outcome;
use crate::cx::Cx;

/// Reproduce every worked example and appendix run of the thesis, with steps and pictures.
#[derive(Debug, Args)]
#[command(after_help = "\
Needs no input. Prints Primer 2.4 (de Casteljau scheme at t = 1/2 and the curve), a Bézier
patch example in place of Primer 3.2 (whose net is garbled in the source and whose printed
z-values are inconsistent), Primer 4.3 (r_c, r_d, r_cd and x at (0.2, 0.5), exactly), the
appendix C Coons patch (data script with its N and P4 bugs fixed) and the appendix D Gordon
surface (g1, g2, g12 at a point, the grid, the conditioning). Pictures (SVG and PNG) and
meshes (STL, OBJ, PLY) go to --out, written atomically.

Example:
  cagd thesis --out cagd-out")]
pub struct ThesisCommand {
    /// The folder for the pictures and meshes (created if missing).
    #[arg(long, value_name = "DIR", default_value = "cagd-out")]
    pub out: PathBuf,
}

impl Run for ThesisCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        thesis(&cx.limits, self)
    }
}

/// The appendix C data script (algorithm 5's input), with the two bugs of the printed
/// script fixed: N is set (the printed script uses it undefined) and the last line sets P4
/// (the printed one sets P3 twice).
pub const APPENDIX_C: &str = "\
N = 10;
u = linspace(0,1,N);
v = linspace(0,1,N);
c1x = u; c1y = zeros(1,N); c1z = zeros(1,N);
for i = 1:N
  c1z(i) = u(i)-(u(i))^2;
end;
c1 = [c1x;c1y;c1z];
c2x = u; c2y = ones(1,N); c2z = u;
c2 = [c2x;c2y;c2z];
d1x = zeros(1,N); d1y = zeros(1,N);
for i = 1:N
  d1y(i) = (v(i))^2;
end;
d1z = zeros(1,N);
for i = 1:N
  d1z(i) = v(i)-(v(i))^2;
end;
d1 = [d1x;d1y;d1z];
d2x = ones(1,N); d2y = v; d2z = v;
d2 = [d2x; d2y; d2z];
P1 = [0;0;0];
P2 = [1;0;0];
P3 = [0;1;0];
P4 = [1;1;1];
";

fn expr(text: &str) -> Result<ParamExpr, CliError> {
    ParamExpr::parse(text).map_err(|e| CliError::literal("thesis", e, "a valid built-in example"))
}

/// An expression curve on `[0, 1]` sampled exactly where it is needed.
fn expr_curve<T: LiteralScalar>(
    text: &str,
    param: &str,
    at: &[T],
) -> Result<SampledCurve<T>, CliError> {
    let m = expr(text)?
        .sample_curve(&mut Env::new(), param, at)
        .map_err(|e| CliError::literal("thesis", e, "a valid built-in example"))?;
    SampledCurve::new(at.to_vec(), m)
        .and_then(|c| c.with_domain(T::zero(), T::one()))
        .map_err(lib("thesis", "a valid built-in example"))
}

const INTERNAL: &str = "a valid built-in example";

pub fn thesis(limits: &Limits, cmd: &ThesisCommand) -> Result<Outcome, CliError> {
    // A folder that cannot be created is refused before the examples are computed.
    PendingWrites::check_dir(&format!("--out {}", cmd.out.display()), &cmd.out)?;
    let mut out = String::new();
    let mut files = Files {
        dir: &cmd.out,
        pending: PendingWrites::new(),
        written: Vec::new(),
    };
    primer_2_4(&mut out, &mut files)?;
    patch_example(&mut out, &mut files)?;
    primer_4_3(&mut out, &mut files)?;
    appendix_c(limits, &mut out, &mut files)?;
    appendix_d(limits, &mut out, &mut files)?;
    let _ = writeln!(
        out,
        "Files written to {}:\n  {}",
        cmd.out.display(),
        files.written.join("\n  ")
    );
    // Everything is computed: the folder is created only when the files are committed, and
    // the files are then written atomically (all staged before any is renamed into place).
    let mut pending = files.pending;
    pending.create_dir(format!("--out {}", cmd.out.display()), &cmd.out);
    Ok(Outcome {
        stdout: out,
        files: pending,
        warnings: Vec::new(),
    })
}

fn primer_2_4(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(out, "Primer 2.4: de Casteljau's algorithm");
    out.push_str(
        "b0 = (0,0,0), b1 = (0,2,2), b2 = (8,2,0), b3 = (4,0,0); the point at t = 0.5, exactly.\n\
         Columns r = 0..3 of the scheme; the last entry is the point on the curve.\n\n",
    );
    let pts = [[0, 0, 0], [0, 2, 2], [8, 2, 0], [4, 0, 0]];
    let exact = BezierCurve::new(DMatrix::from_fn(3, 4, |i, j| q(pts[j][i], 1)))
        .map_err(lib("thesis", INTERNAL))?;
    let scheme = exact.scheme(q(1, 2));
    let _ = writeln!(out, "{scheme}");
    let mut r = Report::<Q>::new();
    r.push("b(1/2)", Value::Matrix(column(&scheme.point_on_curve())));
    out.push_str(&text(&r));
    out.push_str("The thesis prints (3.5, 1.5, 0.75): the same.\n\n");
    let curve = BezierCurve::new(to_f64(exact.control())).map_err(lib("thesis", INTERNAL))?;
    let ts = cagd::linspace(0.0, 1.0, 11);
    let points = curve.eval_many(&ts).map_err(lib("thesis", INTERNAL))?;
    out.push_str("The curve over [0,1] (deCasteljau(B, 11): T, one point per column):\n\n");
    let mut r = Report::<f64>::new();
    r.push("T", Value::Matrix(points));
    out.push_str(&text(&r));
    let dense = curve_line(&curve, (&0.0, &1.0), 101)?;
    let s = curve.scheme(0.5);
    let mut figure =
        Figure::new("Primer 2.4: Bézier curve and de Casteljau construction at t = 0.5")
            .curve(dense, Colour::Blue, "curve b(t)")
            .control_polygon(curve.control().clone(), "control polygon");
    for (r, level) in s.levels().iter().enumerate().skip(1) {
        let label = match r {
            1 => "de Casteljau points b_i^r(0.5)",
            _ => "",
        };
        figure = figure.boundary(level.clone(), Colour::Orange, label);
    }
    // The answer: the point b(1/2) = (7/2, 3/2, 3/4), marked and labelled.
    let figure = figure.points(
        column(&s.point_on_curve()),
        vec!["t = 0.5".into()],
        "b(0.5)",
    );
    files.picture("primer_2_4", &figure)
}

/// A 3×3 net standing in for Primer 3.2: b_ij = (2i, 2j, z_ij).
fn example_net<T: LiteralScalar>() -> PointGrid<T> {
    let z = [[0, 1, 0], [1, 4, 1], [0, 1, 0]];
    PointGrid::from_shape_fn((3, 3, 3), |(i, j, k)| {
        T::from_usize(match k {
            0 => 2 * i,
            1 => 2 * j,
            _ => z[i][j],
        })
    })
}

fn patch_example(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(out, "Bézier patch example (in place of Primer 3.2)");
    out.push_str(
        "Primer 3.2's control net is garbled in the source text, and its printed z-values are\n\
         inconsistent (four intermediate points all at z = 1.25 cannot average to the printed\n\
         1.125). What can be reconstructed is x and y: a 3×3 net on the grid 0, 2, 4, whose\n\
         intermediate points at u = v = 0.5 are (1,1), (1,3), (3,1), (3,3) and whose point is\n\
         (2,2). We keep that grid and choose z = [0 1 0; 1 4 1; 0 1 0]:\n\
         b_ij = (2i, 2j, z_ij), packed for ploskevB as\n\
         [0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0].\n\n",
    );
    let exact = BezierPatch::from_grid(&example_net::<Q>()).map_err(lib("thesis", INTERNAL))?;
    let _ = writeln!(out, "{}", exact.scheme(q(1, 2), q(1, 2)));
    let mut r = Report::<Q>::new();
    r.push(
        "b(1/2, 1/2)",
        Value::Matrix(column(&exact.eval(q(1, 2), q(1, 2)))),
    );
    out.push_str(&text(&r));
    let patch = BezierPatch::from_grid(&example_net::<f64>()).map_err(lib("thesis", INTERNAL))?;
    let t = cagd::linspace(0.0, 1.0, 5);
    let grid = patch
        .try_eval_grid(&t, &t)
        .map_err(lib("thesis", INTERNAL))?;
    out.push_str("ploskevB(B, 5): the grid P (5×5×3):\n\n");
    let mut r = Report::<f64>::new();
    r.push("P", Value::Grid(grid));
    out.push_str(&text(&r));
    let t = cagd::linspace(0.0, 1.0, 21);
    let grid = patch
        .try_eval_grid(&t, &t)
        .map_err(lib("thesis", INTERNAL))?;
    let figure = Figure::new("Bézier patch with its control net (example in place of Primer 3.2)")
        .surface(grid.clone(), "patch")
        .net(example_net::<f64>(), Colour::Red, "control net");
    files.picture("patch_example", &figure)?;
    files.meshes("patch_example", &grid)
}

const C1: &str = "[u;0;u-u^2]";
const C2: &str = "[u;1;u]";
const D1: &str = "[0;v^2;v-v^2]";
const D2: &str = "[1;v;v]";

fn primer_4_3(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(out, "Primer 4.3: a point on a Coons patch");
    let _ = writeln!(
        out,
        "c1(u) = {C1}, c2(u) = {C2}, d1(v) = {D1}, d2(v) = {D2}; u = 0.2, v = 0.5, exactly.\n"
    );
    let (u, v) = (q(1, 5), q(1, 2));
    let at_u = needed(&[std::slice::from_ref(&u)]);
    let at_v = needed(&[std::slice::from_ref(&v)]);
    let patch = CoonsPatch::new(
        expr_curve::<Q>(C1, "u", &at_u)?,
        expr_curve::<Q>(C2, "u", &at_u)?,
        expr_curve::<Q>(D1, "v", &at_v)?,
        expr_curve::<Q>(D2, "v", &at_v)?,
    )
    .map_err(lib("thesis", INTERNAL))?;
    let p = patch.eval_parts(u, v);
    let mut r = Report::<Q>::new();
    r.push("rc", Value::Matrix(column(&p.rc)));
    r.push("rd", Value::Matrix(column(&p.rd)));
    r.push("rcd", Value::Matrix(column(&p.rcd)));
    r.push("x = rc + rd - rcd", Value::Matrix(column(&p.x)));
    out.push_str(&text(&r));
    out.push_str(
        "The thesis prints r_c = (0.2, 0.5, 0.18), r_d = (0.2, 0.3, 0.3), r_cd = (0.2, 0.5, 0.1)\n\
         and x = (0.2, 0.3, 0.38): the same.\n\n",
    );
    let t = cagd::linspace(0.0, 1.0, 21);
    let [c1, c2, d1, d2] =
        [(C1, "u"), (C2, "u"), (D1, "v"), (D2, "v")].map(|(e, p)| expr_curve::<f64>(e, p, &t));
    let (c1, c2, d1, d2) = (c1?, c2?, d1?, d2?);
    let patch = CoonsPatch::new(c1.clone(), c2.clone(), d1.clone(), d2.clone())
        .map_err(lib("thesis", INTERNAL))?;
    let grid = patch.eval_grid(&t, &t);
    let figure = coons_figure(
        "Primer 4.3: Coons patch, c1 and c2 red, d1 and d2 green",
        grid.clone(),
        [&c1, &c2, &d1, &d2],
        &t,
        &t,
    )
    // The answer: x(0.2, 0.5) = (1/5, 3/10, 19/50), marked and labelled.
    .points(
        column(&patch.eval_parts(0.2, 0.5).x),
        vec!["u = 0.2, v = 0.5".into()],
        "x(0.2, 0.5)",
    );
    files.picture("primer_4_3", &figure)?;
    files.meshes("primer_4_3", &grid)
}

fn appendix_c(limits: &Limits, out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(out, "Appendix C: krpaCoons on the sampled boundary curves");
    out.push_str(
        "The data script of appendix C, with its two bugs fixed: N is set (N = 10; the printed\n\
         script uses it undefined) and the last line sets P4 = [1;1;1] (the printed script sets\n\
         P3 twice, so krpaCoons would fail on the missing P4).\n\n",
    );
    let script = cagd_octave::script::run::<f64>(APPENDIX_C, Env::with_limits(*limits))
        .map_err(|e| CliError::literal("thesis", e, INTERNAL))?;
    let get =
        |name: &str| script_curve(&script, name, if name.starts_with('c') { "u" } else { "v" });
    let mut env = script.env().clone();
    let mut curves = Vec::new();
    for name in ["c1", "c2", "d1", "d2"] {
        let source = get(name).ok_or_else(|| shape("thesis", format!("no {name}"), INTERNAL))?;
        curves.push(source.build("thesis", &[], &mut env)?);
    }
    let corner = |name: &str| -> Result<DVector<f64>, CliError> {
        script
            .value(name)
            .map(|m| DVector::from_column_slice(m.as_slice()))
            .ok_or_else(|| shape("thesis", format!("no {name}"), INTERNAL))
    };
    let corners = [corner("P1")?, corner("P2")?, corner("P3")?, corner("P4")?];
    let [c1, c2, d1, d2]: [SampledCurve<f64>; 4] =
        curves.try_into().unwrap_or_else(|_| unreachable!());
    let patch = CoonsPatch::with_corners(
        c1.clone(),
        c2.clone(),
        d1.clone(),
        d2.clone(),
        corners,
        Tolerance::default(),
    )
    .map_err(lib("thesis", INTERNAL))?;
    let t = cagd::linspace(0.0, 1.0, 10);
    let grid = patch.eval_grid(&t, &t);
    out.push_str("krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4) with N = 10: the grid P = tenzor(R):\n\n");
    let mut r = Report::<f64>::new();
    r.push("P", Value::Grid(grid.clone()));
    out.push_str(&text(&r));
    let figure = coons_figure(
        "Appendix C: Coons patch, c1 and c2 red, d1 and d2 green",
        grid.clone(),
        [&c1, &c2, &d1, &d2],
        &t,
        &t,
    );
    files.picture("appendix_c", &figure)?;
    files.meshes("appendix_c", &grid)
}

/// Appendix D's network: g(u, v_j) in u (c0, c1, c2) and g(u_i, v) in v (d0, d1, d2), nodes
/// x = [0 0.5 1], crossing points g_uv.
const V_CURVES: [&str; 3] = ["[u;0;u-u^2]", "[u;0.5;0.5+u-u^2]", "[u;1;1+u-u^2]"];
const U_CURVES: [&str; 3] = ["[0;v;v]", "[0.5;v;0.25+v]", "[1;v;v]"];
const G_UV: &str =
    "[0 0 0 0 0.5 0.5 0 1 1; 0.5 0 0.25 0.5 0.5 0.75 0.5 1 1.25; 1 0 0 1 0.5 0.5 1 1 1]";

fn gordon_of<T: LiteralScalar>(
    limits: &Limits,
    us: &[T],
    vs: &[T],
) -> Result<GordonSurface<SampledCurve<T>, T>, CliError> {
    let nodes: Vec<T> = vec![T::zero(), T::from_ratio(1, 2), T::one()];
    let at_u = needed(&[us, &nodes]);
    let at_v = needed(&[vs, &nodes]);
    let curves_u = U_CURVES
        .iter()
        .map(|e| expr_curve::<T>(e, "v", &at_v))
        .collect::<Result<Vec<_>, _>>()?;
    let curves_v = V_CURVES
        .iter()
        .map(|e| expr_curve::<T>(e, "u", &at_u))
        .collect::<Result<Vec<_>, _>>()?;
    let g_uv = crate::load_matrix::<T>(&crate::Cx::new(*limits), "thesis", G_UV, None)?;
    let points = (0..3)
        .map(|i| {
            (0..3)
                .map(|j| DVector::from_iterator(3, (0..3).map(|c| g_uv[(i, 3 * j + c)].clone())))
                .collect()
        })
        .collect();
    GordonSurface::with_points(
        nodes.clone(),
        nodes,
        curves_u,
        curves_v,
        points,
        Tolerance::default(),
    )
    .map_err(lib("thesis", INTERNAL))
}

fn appendix_d(limits: &Limits, out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(out, "Appendix D: krpaGordon on the curve network");
    let _ = writeln!(
        out,
        "Curves g(u, v_j) in u (the thesis's c0, c1, c2 in g_u): {}\n\
         Curves g(u_i, v) in v (d0, d1, d2 in g_v): {}\n\
         Nodes x = [0 0.5 1] in both directions; crossing points g_uv as in the data script.\n\
         The printed krpaGordon takes m = size(g_u)(2) (the number of samples, not of curves)\n\
         and indexes g_u(:,l) as a point; here each curve is evaluated as the thesis means it.\n",
        V_CURVES.join(", "),
        U_CURVES.join(", ")
    );
    let (u, v) = (q(1, 4), q(3, 4));
    let g = gordon_of::<Q>(limits, std::slice::from_ref(&u), std::slice::from_ref(&v))?;
    let p = g.eval_parts(u, v);
    out.push_str("At (u, v) = (1/4, 3/4), exactly:\n\n");
    let mut r = Report::<Q>::new();
    r.push("g1", Value::Matrix(column(&p.g1)));
    r.push("g2", Value::Matrix(column(&p.g2)));
    r.push("g12", Value::Matrix(column(&p.g12)));
    r.push("g = g1 + g2 - g12", Value::Matrix(column(&p.g)));
    out.push_str(&text(&r));
    out.push_str(
        "The network lies on (u, v, v + u - u^2), which Gordon reproduces: 15/16 = 3/4 + 1/4 - 1/16.\n\n",
    );
    let t = cagd::linspace(0.0, 1.0, 10);
    let g = gordon_of::<f64>(limits, &t, &t)?;
    let grid = g.eval_grid(&t, &t);
    out.push_str("krpaGordon(g_u, g_v, g_uv, x, 10): the grid P:\n\n");
    let mut r = Report::<f64>::new();
    r.push("P", Value::Grid(grid));
    out.push_str(&text(&r));
    let c = g.conditioning();
    let _ = writeln!(
        out,
        "conditioning: Lebesgue constants Λ_u = {:.4}, Λ_v = {:.4}; network errors are amplified at most {:.4}-fold\n",
        c.u.value,
        c.v.value,
        c.amplification()
    );
    let t = cagd::linspace(0.0, 1.0, 21);
    let g = gordon_of::<f64>(limits, &t, &t)?;
    let grid = g.eval_grid(&t, &t);
    let mut figure = Figure::new("Appendix D: Gordon surface and its curve network")
        .surface(grid.clone(), "g(u,v)");
    for (k, c) in g.curves_at_u().iter().enumerate() {
        let label = if k == 0 { "g(u_i, v)" } else { "" };
        figure = figure.boundary(sample(c, &t), Colour::Red, label);
    }
    for (k, c) in g.curves_at_v().iter().enumerate() {
        let label = if k == 0 { "g(u, v_j)" } else { "" };
        figure = figure.boundary(sample(c, &t), Colour::Green, label);
    }
    // The answer: g(1/4, 3/4) = (1/4, 3/4, 15/16), marked and labelled.
    let at = column(&g.eval_parts(0.25, 0.75).g);
    let figure = figure.points(at, vec!["u = 0.25, v = 0.75".into()], "g(0.25, 0.75)");
    files.picture("appendix_d", &figure)?;
    files.meshes("appendix_d", &grid)
}
