//! `coons`: the Coons patch of four boundary curves (thesis §4.1, algorithms 5 and 6), with
//! the linear blending functions of the bilinear patch, the cubic Hermite pair of the
//! partially bicubic patch (§4.2) or a pair of the user's (thesis (4.4)):
//!
//! `x(u, v) = r_c + r_d − r_cd`, `r_c = f1(v) c1(u) + f2(v) c2(u)`,
//! `r_d = f1(u) d1(v) + f2(u) d2(v)`, `r_cd` the same blend of the corners.
//!
//! The boundaries may be any curves (Bézier, B-spline, NURBS on their own domains, mapped
//! onto `[0, 1]`), samples of a data script, or expressions evaluated where they are needed.

use cagd::coons::{
    coons_point_cost, BlendingPair, CoonsBoundary, CoonsPatch, CoonsPoint, GeneralizedCoonsPatch,
};
use cagd::{Curve, Scalar, Surface, Tolerance};
use nalgebra::DVector;

use super::patch::mark_result;
use super::surface::{evaluated_points, grid_f64, picture_grid, push_terms, SurfaceParams};
use super::to_f64;
use crate::curves::{check_curves_work, needed, CurveArg, Evaluator, Realised};
use crate::drawing::{Colour, Drawing};
use crate::error::{Kind, OpError, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of the four boundary curves.
pub const BOUNDARY_FORM: &str = "four boundary curves that meet at the corners: c1(0)=d1(0), c1(1)=d2(0), c2(0)=d1(1), c2(1)=d2(1)";

/// The form of a blending pair.
pub const BLEND_FORM: &str = "linear, hermite, or f1 as an expression in t such as 1-3*t^2+2*t^3 (f2 = 1 − f1), or the pair [f1; f2]";

/// The blending functions of a Coons patch.
pub enum Blend<T: Scalar> {
    /// `(1 − t, t)`: the bilinearly blended patch.
    Linear,
    /// `(H0³, H3³)`: the partially bicubic patch.
    Hermite,
    /// `f1` (1 × k values; `f2 = 1 − f1`) or the pair `[f1; f2]` (2 × k), evaluated where the
    /// patch needs them and at the check points `k/32`.
    Custom(Box<dyn Evaluator<T>>),
}

impl<T: Scalar> std::fmt::Debug for Blend<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Blend::Linear => "Linear",
            Blend::Hermite => "Hermite",
            Blend::Custom(_) => "Custom",
        })
    }
}

/// A Coons patch.
#[derive(Debug)]
pub struct Coons<T: Scalar> {
    /// `[c1, c2, d1, d2]`: `x(u,0)`, `x(u,1)` in `u`, `x(0,v)`, `x(1,v)` in `v`.
    pub boundary: [CurveArg<T>; 4],
    /// The corners `P1..P4` of a data script (else the curves' ends).
    pub corners: Option<[DVector<T>; 4]>,
    /// The blending functions.
    pub blend: Blend<T>,
    /// Where: `u`, `v` (samples of `[0, 1]`, or a data script's samples), `--list` layout.
    pub at: SurfaceParams<T>,
    /// `r_c`, `r_d`, `r_cd` as steps.
    pub steps: bool,
    /// A picture: the surface with `c1`, `c2` in red and `d1`, `d2` in green (appendix C).
    pub drawing: bool,
    /// The surface sampled for a mesh.
    pub mesh: bool,
}

/// The roles of the four boundary curves.
pub const BOUNDARY_ROLES: [Role; 4] = [Role::C1, Role::C2, Role::D1, Role::D2];

impl<T: Scalar> Coons<T> {
    /// The bilinear patch of four boundary curves at the default parameters.
    pub fn new(boundary: [CurveArg<T>; 4]) -> Self {
        Coons {
            boundary,
            corners: None,
            blend: Blend::Linear,
            at: SurfaceParams::default(),
            steps: false,
            drawing: false,
            mesh: false,
        }
    }
}

/// A Coons patch of either kind.
enum Patch<C, T: Scalar> {
    Bilinear(CoonsPatch<C, T>),
    Blended(GeneralizedCoonsPatch<C, T>),
}

impl<C: Curve<T>, T: Scalar> Patch<C, T> {
    fn parts(&self, u: T, v: T) -> CoonsPoint<T> {
        match self {
            Patch::Bilinear(p) => p.eval_parts(u, v),
            Patch::Blended(p) => p.eval_parts(u, v),
        }
    }

    fn grid(&self, us: &[T], vs: &[T]) -> cagd::grid::PointGrid<T> {
        match self {
            Patch::Bilinear(p) => p.eval_grid(us, vs),
            Patch::Blended(p) => p.eval_grid(us, vs),
        }
    }
}

impl<T: Scalar> Operation<T> for Coons<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let (us, vs) = self.parameters(cx)?;
        let single = self.at.single();
        let unit = (&T::zero(), &T::one());
        let pictures = self.drawing || self.mesh;
        let (pus, pvs) = if pictures {
            picture_grid((&us, &vs), single, (unit, unit))?
        } else {
            (Vec::new(), Vec::new())
        };
        let at_u = needed(&[&us, &pus]);
        let at_v = needed(&[&vs, &pvs]);
        let ats = [&at_u, &at_u, &at_v, &at_v];
        let parts: Vec<(Role, &CurveArg<T>, &[T])> = BOUNDARY_ROLES
            .into_iter()
            .zip(&self.boundary)
            .zip(ats)
            .map(|((r, c), at)| (r, c, at.as_slice()))
            .collect();
        check_curves_work(cx, &parts)?;
        let curves = realise_all(&parts, false)?;
        // x = rc + rd − rcd at every point (cagd::coons::coons_point_cost), each boundary at
        // the cost of a point of it as the patch evaluates it (an evaluated curve: a look-up
        // in its table).
        let per_point = boundary_point_cost(&curves, &at_u, &at_v);
        let pair = self.pair(cx, &needed(&[&at_u, &at_v]))?;
        let patch = self.patch(curves, pair)?;
        let points = evaluated_points((&us, &vs), pictures.then_some((&pus, &pvs)));
        cx.check_cost(Role::Grid, per_point.times(points), T::EXACT)?;
        let mut answer = Answer {
            report: self.report(&patch, (&us, &vs), cx)?,
            drawing: None,
            mesh: None,
        };
        if pictures {
            self.pictures(&mut answer, &patch, (&us, &vs), (&pus, &pvs))?;
        }
        Ok(answer)
    }
}

/// The work of one point `x = rc + rd − rcd` of the patch of the realised `curves`, each
/// evaluated at parameters of the bits of `at_u` (`c1`, `c2`) or `at_v` (`d1`, `d2`).
fn boundary_point_cost<T: Scalar>(
    curves: &[Realised<'_, T>; 4],
    at_u: &[T],
    at_v: &[T],
) -> cagd::cost::Cost {
    let bits = [at_u, at_u, at_v, at_v].map(cagd::cost::max_bits);
    let costs: [cagd::cost::Cost; 4] = std::array::from_fn(|k| curves[k].point_cost(bits[k]));
    coons_point_cost(costs, curves[0].dim(), bits[0], bits[2])
}

impl<T: Scalar> Coons<T> {
    /// The parameters: given, `N` samples, or the data script's samples of the boundary.
    fn parameters(&self, cx: &mut Context) -> Result<(Vec<T>, Vec<T>)> {
        let mut at = self.at.clone();
        if let (crate::Params::Default, Some(s)) = (&at.u, self.boundary[0].sample_params()) {
            at.u = crate::Params::Given(s.to_vec());
        }
        if let (crate::Params::Default, Some(s)) = (&at.v, self.boundary[2].sample_params()) {
            at.v = crate::Params::Given(s.to_vec());
        }
        let unit = (&T::zero(), &T::one());
        at.resolve((unit, unit), "the patch is extrapolated there", cx)
    }

    /// `u`, `v`, the parts `rc`, `rd`, `rcd` with steps, and the `result`.
    fn report(
        &self,
        patch: &Patch<Realised<'_, T>, T>,
        (us, vs): (&[T], &[T]),
        cx: &Context,
    ) -> Result<Report<T>> {
        let mut report = Report::new();
        report.push("u", Value::row(us));
        report.push("v", Value::row(vs));
        push_terms(
            &mut report,
            ["rc", "rd", "rcd"],
            (self.steps, self.at.list, self.at.single()),
            (us, vs),
            cx,
            |u, v| {
                let p = patch.parts(u, v);
                [p.rc, p.rd, p.rcd, p.x]
            },
        )?;
        Ok(report)
    }

    /// The picture (the evaluated points marked) and the mesh asked for, on the pictures'
    /// grid `pus × pvs`.
    fn pictures(
        &self,
        answer: &mut Answer<T>,
        patch: &Patch<Realised<'_, T>, T>,
        (us, vs): (&[T], &[T]),
        (pus, pvs): (&[T], &[T]),
    ) -> Result<()> {
        let grid = grid_f64(&patch.grid(pus, pvs));
        if self.drawing {
            let drawing = self.picture("Coons patch", grid.clone(), (pus, pvs))?;
            let single = self.at.single();
            answer.drawing = Some(mark_result(drawing, &answer.report, (us, vs), single));
        }
        if self.mesh {
            answer.mesh = Some(grid);
        }
        Ok(())
    }

    /// The blending pair (none: linear).
    fn pair(&self, cx: &Context, at: &[T]) -> Result<Option<BlendingPair<T>>> {
        match &self.blend {
            Blend::Linear => Ok(None),
            Blend::Hermite => Ok(Some(BlendingPair::hermite_cubic())),
            Blend::Custom(f) => custom_pair(cx, f.as_ref(), at).map(Some),
        }
    }

    /// The patch of the realised curves.
    fn patch<'a>(
        &self,
        [c1, c2, d1, d2]: [Realised<'a, T>; 4],
        pair: Option<BlendingPair<T>>,
    ) -> Result<Patch<Realised<'a, T>, T>> {
        let tolerance = Tolerance::default();
        let corners = self.corners.clone();
        let built = match pair {
            None => match corners {
                Some(c) => CoonsPatch::with_corners(c1, c2, d1, d2, c, tolerance),
                None => CoonsPatch::new(c1, c2, d1, d2),
            }
            .map(Patch::Bilinear),
            Some(f) => match corners {
                Some(c) => CoonsBoundary::with_corners(c1, c2, d1, d2, c, tolerance),
                None => CoonsBoundary::new(c1, c2, d1, d2, tolerance),
            }
            .and_then(|b| {
                GeneralizedCoonsPatch::from_boundary(b, f.clone(), f, cagd::coons::BLEND_TOLERANCE)
            })
            .map(Patch::Blended),
        };
        built.map_err(boundary_error)
    }

    /// The picture of appendix C ([`boundary_picture`]), each boundary realised where the
    /// picture samples it.
    fn picture(
        &self,
        title: &str,
        grid: cagd::grid::PointGrid<f64>,
        (us, vs): (&[T], &[T]),
    ) -> Result<Drawing> {
        let mut curves = Vec::with_capacity(4);
        for (k, c) in self.boundary.iter().enumerate() {
            let ts = if k < 2 { us } else { vs };
            curves.push(c.realise(BOUNDARY_ROLES[k], ts, false)?);
        }
        let [c1, c2, d1, d2] = &curves[..] else {
            return Err(OpError::new(
                Role::C1,
                Kind::Internal,
                "not four curves",
                BOUNDARY_FORM,
            ));
        };
        boundary_picture(title, grid, [c1, c2, d1, d2], (us, vs))
    }
}

/// The library's refusal of a Coons patch: its blending functions, or its boundary (curves
/// that do not meet at the corners, of different dimensions).
pub fn boundary_error(e: cagd::Error) -> OpError {
    match e {
        cagd::Error::BlendingCondition { .. } => OpError::library(Role::Blend, e, BLEND_FORM),
        _ => OpError::library(Role::Boundary, e, BOUNDARY_FORM),
    }
}

/// The picture of appendix C: the surface, `c1`, `c2` in red, `d1`, `d2` in green, each
/// boundary drawn as the patch uses it (its domain mapped onto the grid's `[0, 1]`).
pub fn boundary_picture<T: Scalar, C: Curve<T>>(
    title: &str,
    grid: cagd::grid::PointGrid<f64>,
    curves: [&C; 4],
    (us, vs): (&[T], &[T]),
) -> Result<Drawing> {
    let mut drawing = Drawing::new(title).surface(grid, "x(u,v)");
    let labels = ["c1, c2", "", "d1, d2", ""];
    let colours = [Colour::Red, Colour::Red, Colour::Green, Colour::Green];
    for (k, curve) in curves.into_iter().enumerate() {
        let ts = if k < 2 { us } else { vs };
        drawing = drawing.boundary(boundary_line(curve, ts)?, colours[k], labels[k]);
    }
    Ok(drawing)
}

/// The curve sampled along the unit parameters `ts` of a construction: its domain `[a, b]`
/// mapped onto `[0, 1]`.
pub fn boundary_line<T: Scalar, C: Curve<T>>(
    curve: &C,
    ts: &[T],
) -> Result<nalgebra::DMatrix<f64>> {
    let (a, b) = curve.domain();
    let own: Vec<T> = ts
        .iter()
        .map(|s| a.clone() + (b.clone() - a.clone()) * s.clone())
        .collect();
    let cols: Vec<DVector<T>> = own.into_iter().map(|t| curve.eval(t)).collect();
    if cols.is_empty() {
        return Ok(nalgebra::DMatrix::zeros(curve.dim(), 0));
    }
    Ok(to_f64(&nalgebra::DMatrix::from_columns(&cols)))
}

/// Every curve realised at its parameters.
pub fn realise_all<'a, T: Scalar>(
    parts: &[(Role, &'a CurveArg<T>, &[T])],
    with_derivatives: bool,
) -> Result<[Realised<'a, T>; 4]> {
    let mut out = Vec::with_capacity(4);
    for (role, c, at) in parts {
        out.push(c.realise(*role, at, with_derivatives)?);
    }
    out.try_into()
        .map_err(|_| OpError::new(Role::C1, Kind::Internal, "not four curves", BOUNDARY_FORM))
}

/// The user's blending pair, tabulated at `at` and at the check points `k/32` of
/// [`GeneralizedCoonsPatch::from_boundary`] (the patch evaluates it only there).
fn custom_pair<T: Scalar>(cx: &Context, f: &dyn Evaluator<T>, at: &[T]) -> Result<BlendingPair<T>> {
    let mut points: Vec<T> = at.to_vec();
    points.extend((0..=32).map(|k| T::from_ratio(k, 32)));
    points.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    points.dedup();
    let work = f.work(&points);
    cx.limits
        .check_work(work.what, work.operations)
        .map_err(crate::error::lib(Role::Blend, BLEND_FORM))?;
    let m = f.values(&points).map_err(|e| e.about(Role::Blend))?;
    let table: Vec<(T, T, T)> = match m.nrows() {
        1 => points
            .into_iter()
            .zip(m.row(0).iter())
            .map(|(t, f1)| (t, f1.clone(), T::one() - f1.clone()))
            .collect(),
        2 => points
            .into_iter()
            .enumerate()
            .map(|(k, t)| (t, m[(0, k)].clone(), m[(1, k)].clone()))
            .collect(),
        rows => {
            return Err(OpError::new(
                Role::Blend,
                Kind::Shape,
                format!("a {rows}×1 value"),
                BLEND_FORM,
            ))
        }
    };
    let table = std::sync::Arc::new(table);
    let lookup = |table: &[(T, T, T)], t: &T, second: bool| -> T {
        match table
            .binary_search_by(|(x, _, _)| x.partial_cmp(t).unwrap_or(std::cmp::Ordering::Equal))
        {
            Ok(k) if second => table[k].2.clone(),
            Ok(k) => table[k].1.clone(),
            // Every parameter the patch asks for was tabulated.
            Err(_) => T::zero(),
        }
    };
    let (t1, t2) = (table.clone(), table);
    Ok(BlendingPair::new(
        "the blending functions",
        move |t: T| lookup(&t1, &t, false),
        move |t: T| lookup(&t2, &t, true),
    ))
}
