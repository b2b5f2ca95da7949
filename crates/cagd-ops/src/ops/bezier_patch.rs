//! `bezier-patch`: points of a tensor-product Bézier patch (thesis algorithms 2–4,
//! `ploskevB`, `bilinearna`, `tenzor`),
//!
//! `x(u, v) = Σ_i Σ_j b_ij B_i^m(u) B_j^n(v)`,
//!
//! by the tensor de Casteljau scheme (thesis §3.2), and its partial derivatives
//! `∂^(r+s) x / ∂u^r ∂v^s` (thesis Trditev 3.3: a Bézier patch of degree `(m − r, n − s)`
//! with the net `m!/(m−r)! n!/(n−s)! Δ^{r,s} b_ij`; `r = s = 1` is the twist).
//!
//! ```
//! use cagd_ops::{execute, ops::BezierPatchPoints, ops::surface::SurfaceParams, Context, Params};
//! use cagd::grid::PointGrid;
//! // The bilinear patch of (0,0,0), (0,1,0), (1,0,0), (1,1,1) at (1/2, 1/2): (1/2, 1/2, 1/4).
//! let net = PointGrid::from_vec((2, 2, 3), vec![0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 1.]).unwrap();
//! let at = SurfaceParams { u: Params::Given(vec![0.5]), v: Params::Given(vec![0.5]), list: false };
//! let op = BezierPatchPoints { at, ..BezierPatchPoints::new(net) };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.5, 0.5, 0.25]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::bezier::BezierPatch;
use cagd::cost::{max_bits, Cost};
use cagd::grid::PointGrid;
use cagd::Scalar;

use super::surface::{evaluated_points, grid_f64, picture_grid, push_surface, SurfaceParams};
use super::{to_f64, STEPS_FACTOR};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::layout::scheme::patch_scheme;
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of a control net.
pub const NET_FORM: &str = "a control net of (m+1)×(n+1) points b_ij of one dimension";

/// Points of a Bézier patch (or of one of its partial derivatives).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPatchPoints<T> {
    /// The net `b_ij`, shape `(m+1, n+1, d)`.
    pub net: PointGrid<T>,
    /// Differentiate `r` times along `u`.
    pub du: usize,
    /// Differentiate `s` times along `v`.
    pub dv: usize,
    /// Where: `u`, `v` (samples cover `[0, 1]`), the `--list` layout.
    pub at: SurfaceParams<T>,
    /// The tensor de Casteljau scheme of every point.
    pub steps: bool,
    /// A picture: the patch and its control net.
    pub drawing: bool,
    /// The patch sampled for a mesh.
    pub mesh: bool,
}

impl<T> BezierPatchPoints<T> {
    /// The patch of `net` at the default parameters.
    pub fn new(net: PointGrid<T>) -> Self {
        BezierPatchPoints {
            net,
            du: 0,
            dv: 0,
            at: SurfaceParams::default(),
            steps: false,
            drawing: false,
            mesh: false,
        }
    }
}

impl<T: Scalar> Operation<T> for BezierPatchPoints<T> {
    /// With steps the schemes (`scheme`, or `scheme_1 …` row by row of the grid); for a
    /// derivative its `net`; `u`, `v` (`1 × k`) and `result`: a single point as `d × 1`, else
    /// the grid `nu × nv × d` (or with `list` one row `u v x y z` per point).
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let (m1, n1, _) = self.net.dim();
        cx.check_degree(Role::Net, m1.max(n1).saturating_sub(1))?;
        let patch = self.patch()?;
        let unit = (&T::zero(), &T::one());
        let (us, vs) = self
            .at
            .resolve((unit, unit), "the patch is extrapolated there", cx)?;
        let single = self.at.single();
        let pictures = self.drawing || self.mesh;
        let (pus, pvs) = if pictures && single {
            picture_grid((&us, &vs), single, (unit, unit))?
        } else {
            (Vec::new(), Vec::new())
        };
        let cost = cost(&patch, (&us, &vs), self.steps).and(cost(&patch, (&pus, &pvs), false));
        cx.check_cost(Role::Grid, cost, T::EXACT)?;
        let coefficients = max_bits(patch.to_grid().iter());
        let grid = grid_points(&patch, (&us, &vs), coefficients, cx)?;
        let report = self.report(&patch, (&us, &vs), &grid, cx)?;
        let mut answer = Answer {
            report,
            drawing: None,
            mesh: None,
        };
        if pictures {
            self.pictures(&mut answer, &patch, &grid, (&pus, &pvs))?;
        }
        Ok(answer)
    }
}

/// The work of `patch` at the grid `us × vs`, with its schemes if `steps`.
fn cost<T: Scalar>(patch: &BezierPatch<T>, (us, vs): (&[T], &[T]), steps: bool) -> Cost {
    let coefficients = max_bits(patch.to_grid().iter());
    let (u_bits, v_bits) = (max_bits(us), max_bits(vs));
    let grid = patch.grid_cost(u_bits, v_bits, coefficients);
    let per = if steps {
        grid.and(
            patch
                .scheme_cost(u_bits, v_bits, coefficients)
                .times(STEPS_FACTOR),
        )
    } else {
        grid
    };
    per.times(evaluated_points((us, vs), None))
}

impl<T: Scalar> BezierPatchPoints<T> {
    /// The schemes with steps, a derivative's net, `u`, `v` and the `result` on `grid`.
    fn report(
        &self,
        patch: &BezierPatch<T>,
        (us, vs): (&[T], &[T]),
        grid: &PointGrid<T>,
        cx: &Context,
    ) -> Result<Report<T>> {
        let single = self.at.single();
        let mut report = Report::new();
        if self.steps {
            self.push_schemes(&mut report, patch, (us, vs), single, cx)?;
        }
        if self.du > 0 || self.dv > 0 {
            report.push("net", Value::Grid(patch.to_grid()));
        }
        report.push("u", Value::row(us));
        report.push("v", Value::row(vs));
        if single && !self.at.list {
            let point = patch.eval(us[0].clone(), vs[0].clone());
            report.push("result", Value::column(&point));
        } else {
            push_surface(&mut report, "result", (us, vs), grid.clone(), self.at.list);
        }
        Ok(report)
    }

    /// The picture and the mesh asked for: the patch on `grid`, or for a single point on the
    /// picture's own grid `pus × pvs`.
    fn pictures(
        &self,
        answer: &mut Answer<T>,
        patch: &BezierPatch<T>,
        grid: &PointGrid<T>,
        (pus, pvs): (&[T], &[T]),
    ) -> Result<()> {
        let single = self.at.single();
        let shown = if single {
            grid_f64(
                &patch
                    .try_eval_grid(pus, pvs)
                    .map_err(lib(Role::Grid, "a patch"))?,
            )
        } else {
            grid_f64(grid)
        };
        if self.drawing {
            let net = patch.to_grid();
            answer.drawing = Some(self.picture(shown.clone(), &net, &answer.report, single));
        }
        if self.mesh {
            answer.mesh = Some(shown);
        }
        Ok(())
    }

    /// The patch of the net, or its partial derivative.
    fn patch(&self) -> Result<BezierPatch<T>> {
        let patch = BezierPatch::from_grid(&self.net).map_err(lib(Role::Net, NET_FORM))?;
        if self.du == 0 && self.dv == 0 {
            return Ok(patch);
        }
        patch.derivative(self.du, self.dv).map_err(lib(
            Role::DerivativeOrder,
            "orders R ≤ m and S ≤ n (the degrees of the patch)",
        ))
    }

    /// The tensor de Casteljau scheme of each point, `u` varying slowest.
    fn push_schemes(
        &self,
        report: &mut Report<T>,
        patch: &BezierPatch<T>,
        (us, vs): (&[T], &[T]),
        single: bool,
        cx: &Context,
    ) -> Result<()> {
        let mut k = 0;
        for u in us {
            cx.check_interrupt()?;
            for v in vs {
                k += 1;
                let name = if single {
                    "scheme".to_string()
                } else {
                    format!("scheme_{k}")
                };
                report.push(name, patch_scheme(&patch.scheme(u.clone(), v.clone())));
            }
        }
        Ok(())
    }

    /// The patch drawn like `surf`, its control net in red, and a single point asked for.
    fn picture(
        &self,
        grid: PointGrid<f64>,
        net: &PointGrid<T>,
        report: &Report<T>,
        single: bool,
    ) -> Drawing {
        let drawing = Drawing::new("Bézier patch").surface(grid, "patch").net(
            grid_f64(net),
            Colour::Red,
            "control net",
        );
        match (single, report.matrix("result")) {
            (true, Some(point)) if !self.at.list => {
                let (u, v) = (report.matrix("u"), report.matrix("v"));
                let label = match (u, v) {
                    (Some(u), Some(v)) => vec![format!(
                        "(u, v) = ({}, {})",
                        crate::number_text(&u[0]),
                        crate::number_text(&v[0])
                    )],
                    _ => Vec::new(),
                };
                drawing.points(to_f64(point), label, "point at (u, v)")
            }
            _ => drawing,
        }
    }
}

/// The patch on the grid `us × vs` (coefficients of `coefficients` bits), in bands of rows
/// between which the front end may interrupt.
fn grid_points<T: Scalar>(
    patch: &BezierPatch<T>,
    (us, vs): (&[T], &[T]),
    coefficients: u128,
    cx: &Context,
) -> Result<PointGrid<T>> {
    let one = patch.grid_cost(max_bits(us), max_bits(vs), coefficients);
    super::grid_in_bands((us, vs), one.weigh(T::EXACT), cx, |band, vs| {
        patch
            .try_eval_grid(band, vs)
            .map_err(lib(Role::Grid, "finite parameter values"))
    })
}
