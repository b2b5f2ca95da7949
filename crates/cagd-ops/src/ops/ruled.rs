//! `ruled`: the ruled surface between two curves (the lecture notes, "plochy válcové"):
//!
//! `x(u, v) = (1 − v) ¹x(u) + v ²x(u)`, `u, v ∈ [0, 1]`,
//!
//! each curve on its own domain `[a, b]` reparametrised onto `u ∈ [0, 1]`
//! ([`cagd::surfaces::RuledSurface`]). The curves may be any curves (Bézier, B-spline, NURBS),
//! samples of a data script, or expressions evaluated where the surface needs them.

use cagd::surfaces::{ruled_point_cost, RuledSurface};
use cagd::{OnUnitInterval, Scalar, Surface};

use super::coons::boundary_line;
use super::eval_points;
use super::patch::{answer, curve_costs, push_result, Pictures};
use super::surface::{evaluated_points, picture_grid, SurfaceParams};
use crate::curves::{check_curves_work, needed, CurveArg, Realised};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of the two curves.
pub const RULED_FORM: &str = "two curves of the same dimension";

/// The ruled surface between two curves.
///
/// ```
/// use cagd::nurbs::NurbsCurve;
/// use cagd_ops::{curves::CurveArg, execute, ops::Ruled, Context, Params};
/// use nalgebra::DMatrix;
/// use num_rational::BigRational;
/// let q = |a: i64, b: i64| BigRational::new(a.into(), b.into());
/// // The quarter circle as a NURBS (weights 1, 1, 2) at z = 0, and the same at z = 1.
/// let arc = |z: i64| {
///     let p = DMatrix::from_row_slice(3, 3, &[q(1, 1), q(1, 1), q(0, 1), q(0, 1), q(1, 1), q(1, 1), q(z, 1), q(z, 1), q(z, 1)]);
///     NurbsCurve::new(2, vec![q(0, 1), q(0, 1), q(0, 1), q(1, 1), q(1, 1), q(1, 1)], p, vec![q(1, 1), q(1, 1), q(2, 1)]).unwrap()
/// };
/// let mut op = Ruled::new(CurveArg::curve(arc(0)), CurveArg::curve(arc(1)));
/// op.at.u = Params::Given(vec![q(1, 2)]);
/// op.at.v = Params::Given(vec![q(1, 4)]);
/// let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
/// let x = answer.report.matrix("result").unwrap();
/// assert_eq!(x.iter().map(|v| v.to_string()).collect::<Vec<_>>(), ["3/5", "4/5", "1/4"]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug)]
pub struct Ruled<T: Scalar> {
    /// `¹x(u)`, the curve at `v = 0`.
    pub first: CurveArg<T>,
    /// `²x(u)`, the curve at `v = 1`.
    pub second: CurveArg<T>,
    /// Where: `u`, `v` (samples of `[0, 1]`), `--list` layout.
    pub at: SurfaceParams<T>,
    /// Both curves at the `u` values as steps (`first`, `second`).
    pub steps: bool,
    /// A picture: the surface, `¹x` in red and `²x` in green.
    pub drawing: bool,
    /// The surface sampled for a mesh.
    pub mesh: bool,
}

impl<T: Scalar> Ruled<T> {
    /// The surface between `first` and `second` at the default parameters.
    pub fn new(first: CurveArg<T>, second: CurveArg<T>) -> Self {
        Ruled {
            first,
            second,
            at: SurfaceParams::default(),
            steps: false,
            drawing: false,
            mesh: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Ruled<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let [us, vs, pus, pvs] = self.grids(cx)?;
        let single = self.at.single();
        let pictures = self.drawing || self.mesh;
        let at_u = needed(&[&us, &pus]);
        check_curves_work(
            cx,
            &[
                (Role::First, &self.first, &at_u),
                (Role::Second, &self.second, &at_u),
            ],
        )?;
        let a = self.first.realise(Role::First, &at_u, false)?;
        let b = self.second.realise(Role::Second, &at_u, false)?;
        let surface = RuledSurface::new(&a, &b).map_err(lib(Role::Boundary, RULED_FORM))?;
        let costs = curve_costs(&[(&a, &at_u), (&b, &at_u)]);
        let all_v = needed(&[&vs, &pvs]);
        let (u_bits, v_bits) = (cagd::cost::max_bits(&at_u), cagd::cost::max_bits(&all_v));
        let per_point = ruled_point_cost(costs, surface.dim(), u_bits, v_bits);
        let points = evaluated_points((&us, &vs), pictures.then_some((&pus, &pvs)));
        cx.check_cost(Role::Grid, per_point.times(points), T::EXACT)?;
        let mut report = Report::new();
        report.push("u", Value::row(&us));
        report.push("v", Value::row(&vs));
        if self.steps {
            report.push("first", Value::Matrix(along(&a, &us, Role::First, cx)?));
            report.push("second", Value::Matrix(along(&b, &us, Role::Second, cx)?));
        }
        push_result(
            &mut report,
            (&surface, per_point),
            (&us, &vs),
            (single, self.at.list),
            cx,
        )?;
        let pictures = Pictures {
            at: (&us, &vs, single),
            grid: (&pus, &pvs),
            drawing: self.drawing,
            mesh: self.mesh,
        };
        answer(report, &surface, pictures, |grid| {
            Ok(Drawing::new("ruled surface")
                .surface(grid, "x(u,v)")
                .boundary(boundary_line(&a, &pus)?, Colour::Red, "¹x(u)")
                .boundary(boundary_line(&b, &pus)?, Colour::Green, "²x(u)"))
        })
    }
}

impl<T: Scalar> Ruled<T> {
    /// `u` and `v` (samples of `[0, 1]`, each with its warning outside it), and the
    /// pictures' grid.
    fn grids(&self, cx: &mut Context) -> Result<[Vec<T>; 4]> {
        let unit = (&T::zero(), &T::one());
        let extrapolated = "the curves are extrapolated there";
        let us = self.at.u.resolve(Role::U, unit, extrapolated, cx)?;
        let beyond = "the surface is extrapolated beyond its curves";
        let vs = self.at.v.resolve(Role::V, unit, beyond, cx)?;
        cx.check_grid(Role::Grid, us.len(), vs.len())?;
        let (pus, pvs) = if self.drawing || self.mesh {
            picture_grid((&us, &vs), self.at.single(), (unit, unit))?
        } else {
            (Vec::new(), Vec::new())
        };
        Ok([us, vs, pus, pvs])
    }
}

/// The curve at the unit parameters `us` as the surface uses it (its domain mapped onto
/// `[0, 1]`), one point per column.
fn along<T: Scalar>(
    curve: &Realised<'_, T>,
    us: &[T],
    role: Role,
    cx: &Context,
) -> Result<nalgebra::DMatrix<T>> {
    let unit = OnUnitInterval::new(curve, "ruled surface curve").map_err(lib(role, RULED_FORM))?;
    eval_points(&unit, us, role, cx)
}
