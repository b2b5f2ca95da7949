//! `gordon`: the Gordon surface of a curve network (thesis §4.5, Izrek 4.4, algorithm 7):
//!
//! `g = g1 + g2 − g12`, `g1(u,v) = Σ_i g(u_i, v) L_i(u)`, `g2(u,v) = Σ_j g(u, v_j) L_j(v)`,
//! `g12(u,v) = Σ_i Σ_j g(u_i, v_j) L_i(u) L_j(v)`,
//!
//! `L_i`, `L_j` the Lagrange bases of the nodes ([`cagd::gordon::GordonSurface`]). The network
//! curves may be any curves (Bézier, B-spline, NURBS on their own domains, mapped onto
//! `[0, 1]`), samples (appendix D's packed data script), or expressions evaluated where the
//! surface needs them.

use cagd::cost::max_bits;
use cagd::gordon::{gordon_point_cost, gordon_setup_cost, GordonSurface};
use cagd::{Scalar, Surface, Tolerance};
use nalgebra::DVector;

use super::coons::boundary_line;
use super::patch::{answer, curve_costs, Pictures};
use super::surface::{evaluated_points, picture_grid, push_terms, SurfaceParams};
use crate::curves::{check_curves_work, needed, CurveArg, Realised};
use crate::drawing::{Colour, Drawing};
use crate::error::{Kind, OpError, Result};
use crate::params::check_given;
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The form of a compatible network.
pub const NETWORK_FORM: &str =
    "a compatible network: g(u_i, ·) at v_j equals g(·, v_j) at u_i, one curve per node";

/// The form of the nodes.
pub const NODES_FORM: &str = "increasing distinct values, one per curve";

/// A Gordon surface of a curve network.
///
/// ```
/// use cagd::bezier::BezierCurve;
/// use cagd_ops::{curves::CurveArg, execute, ops::Gordon, Context, Params};
/// use nalgebra::DMatrix;
/// use num_rational::BigRational;
/// let q = |a: i64, b: i64| BigRational::new(a.into(), b.into());
/// let line = |p: [i64; 3], r: [i64; 3]| {
///     let m = DMatrix::from_row_slice(3, 2, &[q(p[0], 1), q(r[0], 1), q(p[1], 1), q(r[1], 1), q(p[2], 1), q(r[2], 1)]);
///     CurveArg::curve(BezierCurve::new(m).unwrap())
/// };
/// // The hyperbolic paraboloid z = u·v as a network of its lines u = 0, 1 and v = 0, 1.
/// let mut op = Gordon::new(
///     vec![line([0, 0, 0], [0, 1, 0]), line([1, 0, 0], [1, 1, 1])],
///     vec![line([0, 0, 0], [1, 0, 0]), line([0, 1, 0], [1, 1, 1])],
/// );
/// op.at.u = Params::Given(vec![q(1, 3)]);
/// op.at.v = Params::Given(vec![q(3, 4)]);
/// let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
/// let x = answer.report.matrix("result").unwrap();
/// assert_eq!(x.iter().map(|v| v.to_string()).collect::<Vec<_>>(), ["1/3", "3/4", "1/4"]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug)]
pub struct Gordon<T: Scalar> {
    /// The curves `g(u_i, v)`, functions of `v`, in node order.
    pub u_curves: Vec<CurveArg<T>>,
    /// The curves `g(u, v_j)`, functions of `u`, in node order.
    pub v_curves: Vec<CurveArg<T>>,
    /// The nodes `u_i` (default: equally spaced on `[0, 1]`).
    pub u_nodes: Option<Vec<T>>,
    /// The nodes `v_j` (default: equally spaced on `[0, 1]`).
    pub v_nodes: Option<Vec<T>>,
    /// The crossings `g(u_i, v_j)` given (`[i][j]`, appendix D's `g_uv`), each checked against
    /// both curves through it; else taken from the curves `g(u_i, ·)`.
    pub crossings: Option<Vec<Vec<DVector<T>>>>,
    /// The parameters `(u, v)` at which a sampled network was sampled: the default `u` and
    /// `v` (else those of the first sampled curve in each direction, else samples of `[0, 1]`).
    pub sampled_at: Option<(Vec<T>, Vec<T>)>,
    /// Where: `u`, `v`, `--list` layout.
    pub at: SurfaceParams<T>,
    /// `g1`, `g2`, `g12` as steps.
    pub steps: bool,
    /// A picture: the surface, the curves `g(u_i, v)` in red and `g(u, v_j)` in green.
    pub drawing: bool,
    /// The surface sampled for a mesh.
    pub mesh: bool,
}

impl<T: Scalar> Gordon<T> {
    /// The Gordon surface of the curves `g(u_i, ·)` and `g(·, v_j)` at equally spaced nodes,
    /// at the default parameters.
    pub fn new(u_curves: Vec<CurveArg<T>>, v_curves: Vec<CurveArg<T>>) -> Self {
        Gordon {
            u_curves,
            v_curves,
            u_nodes: None,
            v_nodes: None,
            crossings: None,
            sampled_at: None,
            at: SurfaceParams::default(),
            steps: false,
            drawing: false,
            mesh: false,
        }
    }
}

/// The nodes and where the surface is evaluated (and pictured).
struct Grids<T> {
    u_nodes: Vec<T>,
    v_nodes: Vec<T>,
    us: Vec<T>,
    vs: Vec<T>,
    pus: Vec<T>,
    pvs: Vec<T>,
}

impl<T: Scalar> Operation<T> for Gordon<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let g = self.grids(cx)?;
        let need_u = needed(&[&g.us, &g.pus, &g.u_nodes]);
        let need_v = needed(&[&g.vs, &g.pvs, &g.v_nodes]);
        // Curves g(u_i, ·) are evaluated in v, curves g(·, v_j) in u.
        let parts: Vec<(Role, &CurveArg<T>, &[T])> = (self.u_curves.iter())
            .map(|c| (Role::UCurves, c, need_v.as_slice()))
            .chain(
                self.v_curves
                    .iter()
                    .map(|c| (Role::VCurves, c, need_u.as_slice())),
            )
            .collect();
        check_curves_work(cx, &parts)?;
        let mut at_u = Vec::with_capacity(parts.len());
        for (role, c, at) in &parts {
            at_u.push(c.realise(*role, at, false)?);
        }
        let at_v = at_u.split_off(self.u_curves.len());
        // The set-up (crossings checked, Lagrange weights) before it runs: exact weights of
        // many nodes take minutes.
        let at_nodes = |curves: &[Realised<'_, T>], nodes: &[T]| {
            let pairs: Vec<(&Realised<'_, T>, &[T])> = curves.iter().map(|c| (c, nodes)).collect();
            curve_costs(&pairs)
        };
        let setup = gordon_setup_cost(
            at_nodes(&at_u, &g.v_nodes),
            at_nodes(&at_v, &g.u_nodes),
            (max_bits(&g.u_nodes), max_bits(&g.v_nodes)),
        );
        cx.check_cost(Role::Network, setup, T::EXACT)?;
        let network = [at_nodes(&at_u, &need_v), at_nodes(&at_v, &need_u)].concat();
        let (ku, kv) = (at_u.len(), at_v.len());
        let surface = self.surface(&g, at_u, at_v)?;
        let d = surface.dim();
        let per_point = gordon_point_cost(
            network,
            (ku, kv),
            d,
            (max_bits(&need_u), max_bits(&g.u_nodes)),
            (max_bits(&need_v), max_bits(&g.v_nodes)),
        );
        let pictures = self.drawing || self.mesh;
        let points = evaluated_points((&g.us, &g.vs), pictures.then_some((&g.pus, &g.pvs)));
        cx.check_cost(Role::Grid, per_point.times(points), T::EXACT)?;
        let report = self.report(&surface, &g, cx)?;
        let pictures = Pictures {
            at: (&g.us, &g.vs, self.at.single()),
            grid: (&g.pus, &g.pvs),
            drawing: self.drawing,
            mesh: self.mesh,
        };
        answer(report, &surface, pictures, |grid| {
            picture(&surface, grid, &g)
        })
    }
}

impl<T: Scalar> Gordon<T> {
    /// The nodes (checked against the limits), the parameters and the pictures' grid.
    fn grids(&self, cx: &mut Context) -> Result<Grids<T>> {
        let (ku, kv) = (self.u_curves.len(), self.v_curves.len());
        cx.check_degree(Role::UCurves, ku.saturating_sub(1))?;
        cx.check_degree(Role::VCurves, kv.saturating_sub(1))?;
        let u_nodes = nodes(cx, Role::UNodes, self.u_nodes.as_deref(), ku)?;
        let v_nodes = nodes(cx, Role::VNodes, self.v_nodes.as_deref(), kv)?;
        let mut at = self.at.clone();
        let (su, sv) = match &self.sampled_at {
            Some((su, sv)) => (Some(su.as_slice()), Some(sv.as_slice())),
            None => (
                self.v_curves.first().and_then(CurveArg::sample_params),
                self.u_curves.first().and_then(CurveArg::sample_params),
            ),
        };
        if let (Params::Default, Some(s)) = (&at.u, su) {
            at.u = Params::Given(s.to_vec());
        }
        if let (Params::Default, Some(s)) = (&at.v, sv) {
            at.v = Params::Given(s.to_vec());
        }
        let unit = (&T::zero(), &T::one());
        let (us, vs) = at.resolve((unit, unit), "the patch is extrapolated there", cx)?;
        let (pus, pvs) = if self.drawing || self.mesh {
            picture_grid((&us, &vs), self.at.single(), (unit, unit))?
        } else {
            (Vec::new(), Vec::new())
        };
        Ok(Grids {
            u_nodes,
            v_nodes,
            us,
            vs,
            pus,
            pvs,
        })
    }

    /// The surface of the realised network.
    fn surface<'a>(
        &self,
        g: &Grids<T>,
        at_u: Vec<Realised<'a, T>>,
        at_v: Vec<Realised<'a, T>>,
    ) -> Result<GordonSurface<Realised<'a, T>, T>> {
        let (un, vn) = (g.u_nodes.clone(), g.v_nodes.clone());
        match &self.crossings {
            Some(p) => {
                GordonSurface::with_points(un, vn, at_u, at_v, p.clone(), Tolerance::default())
            }
            None => GordonSurface::new(un, vn, at_u, at_v),
        }
        .map_err(network_error)
    }

    /// `u`, `v`, the parts with steps, the result, the conditioning.
    fn report(
        &self,
        surface: &GordonSurface<Realised<'_, T>, T>,
        g: &Grids<T>,
        cx: &Context,
    ) -> Result<Report<T>> {
        let mut report = Report::new();
        report.push("u", Value::row(&g.us));
        report.push("v", Value::row(&g.vs));
        push_terms(
            &mut report,
            ["g1", "g2", "g12"],
            (self.steps, self.at.list, self.at.single()),
            (&g.us, &g.vs),
            cx,
            |u, v| {
                let p = surface.eval_parts(u, v);
                [p.g1, p.g2, p.g12, p.g]
            },
        )?;
        let c = surface.conditioning();
        report.push(
            "conditioning",
            Value::Text(format!(
                "Lebesgue constants Λ_u = {:.4}, Λ_v = {:.4}; network errors are amplified at most {:.4}-fold",
                c.u.value,
                c.v.value,
                c.amplification()
            )),
        );
        Ok(report)
    }
}

/// The picture: the surface, the curves `g(u_i, v)` in red and `g(u, v_j)` in green, each as
/// the surface uses it (its domain mapped onto `[0, 1]`).
fn picture<T: Scalar>(
    surface: &GordonSurface<Realised<'_, T>, T>,
    grid: cagd::grid::PointGrid<f64>,
    g: &Grids<T>,
) -> Result<Drawing> {
    let mut drawing = Drawing::new("Gordon surface").surface(grid, "g(u,v)");
    for (k, c) in surface.curves_at_u().iter().enumerate() {
        let label = if k == 0 { "g(u_i, v)" } else { "" };
        drawing = drawing.boundary(boundary_line(c, &g.pvs)?, Colour::Red, label);
    }
    for (k, c) in surface.curves_at_v().iter().enumerate() {
        let label = if k == 0 { "g(u, v_j)" } else { "" };
        drawing = drawing.boundary(boundary_line(c, &g.pus)?, Colour::Green, label);
    }
    Ok(drawing)
}

/// The nodes of a direction with `count` curves: given (finite), or equally spaced on
/// `[0, 1]` (at least 2 curves).
/// The library's refusal of a Gordon network, about the network: its nodes (unsorted,
/// repeated) or its curves (too few, not crossing where they should).
pub fn network_error(e: cagd::Error) -> OpError {
    let form = match e {
        cagd::Error::UnsortedNodes { .. } | cagd::Error::DuplicateNodes { .. } => NODES_FORM,
        _ => NETWORK_FORM,
    };
    OpError::library(Role::Network, e, form)
}

fn nodes<T: Scalar>(cx: &Context, role: Role, given: Option<&[T]>, count: usize) -> Result<Vec<T>> {
    if let Some(values) = given {
        check_given(role, values, cx)?;
        return Ok(values.to_vec());
    }
    let curves = if role == Role::UNodes {
        Role::UCurves
    } else {
        Role::VCurves
    };
    if count < 2 {
        return Err(OpError::new(
            curves,
            Kind::Shape,
            format!("{count} curve(s)"),
            "at least 2 curves in each direction",
        ));
    }
    cagd::linspace::linspace_in(&T::zero(), &T::one(), count).map_err(crate::error::lib(
        curves,
        "at least 2 curves in each direction",
    ))
}
