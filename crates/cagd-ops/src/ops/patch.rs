//! What the patches of curves and corner data share beyond [`super::surface`]: the result of
//! a surface without parts, the curves' costs once realised, the evaluated point marked in a
//! picture.

use cagd::cost::{max_bits, Cost};
use cagd::{Curve, Scalar, Surface};

use cagd::grid::PointGrid;

use super::surface::{grid_f64, push_surface};
use super::{point_labels, to_f64};
use crate::curves::Realised;
use crate::drawing::Drawing;
use crate::error::Result;
use crate::{Answer, Context, Report, Value};

/// Pushes `result`: at a single point (and no `list`) the `d × 1` column, else the grid
/// `us × vs × d` (or with `list` one row `u v x y z` per point), evaluated in bands of rows
/// between which the front end may interrupt (`per_point` the cost of one point).
pub fn push_result<T: Scalar, S: Surface<T>>(
    report: &mut Report<T>,
    (surface, per_point): (&S, Cost),
    (us, vs): (&[T], &[T]),
    (single, list): (bool, bool),
    cx: &Context,
) -> Result<()> {
    if single && !list {
        report.push(
            "result",
            Value::column(&surface.eval(us[0].clone(), vs[0].clone())),
        );
        return Ok(());
    }
    let grid = super::grid_in_bands((us, vs), per_point.weigh(T::EXACT), cx, |band, vs| {
        Ok(surface.eval_grid(band, vs))
    })?;
    push_surface(report, "result", (us, vs), grid, list);
    Ok(())
}

/// The cost of one evaluation of each realised curve at parameters like `at`.
pub fn curve_costs<T: Scalar>(curves: &[(&Realised<'_, T>, &[T])]) -> Vec<Cost> {
    curves
        .iter()
        .map(|(c, at)| c.point_cost(max_bits(*at)))
        .collect()
}

/// The picture with the single evaluated point `x(u, v)` of `report`'s `result` marked and
/// labelled (a grid result is the drawn surface itself).
pub fn mark_result<T: Scalar>(
    drawing: Drawing,
    report: &Report<T>,
    (us, vs): (&[T], &[T]),
    single: bool,
) -> Drawing {
    match (single, report.matrix("result")) {
        (true, Some(x)) if x.ncols() == 1 => {
            let u = point_labels("u", &us[..1]);
            let v = point_labels("v", &vs[..1]);
            let label = format!("{}, {}", u[0], v[0]);
            drawing.points(to_f64(x), vec![label], "x(u, v)")
        }
        _ => drawing,
    }
}

/// What a surface request asks for besides its report.
#[derive(Debug, Clone, Copy)]
pub struct Pictures<'a, T> {
    /// The result's parameters `(us, vs)` and whether it is a single point.
    pub at: (&'a [T], &'a [T], bool),
    /// The picture's grid `(pus, pvs)` (empty when neither a picture nor a mesh is asked for).
    pub grid: (&'a [T], &'a [T]),
    /// A picture.
    pub drawing: bool,
    /// A mesh.
    pub mesh: bool,
}

/// The answer: `report`, and as asked for the picture `draw` makes of the surface sampled on
/// the picture's grid (with the evaluated point marked, [`mark_result`]) and that grid as the
/// mesh.
pub fn answer<T: Scalar, S: Surface<T>>(
    report: Report<T>,
    surface: &S,
    p: Pictures<'_, T>,
    draw: impl FnOnce(PointGrid<f64>) -> Result<Drawing>,
) -> Result<Answer<T>> {
    let mut answer = Answer {
        report,
        drawing: None,
        mesh: None,
    };
    if !(p.drawing || p.mesh) {
        return Ok(answer);
    }
    let grid = grid_f64(&surface.eval_grid(p.grid.0, p.grid.1));
    if p.drawing {
        let (us, vs, single) = p.at;
        let drawing = draw(grid.clone())?;
        answer.drawing = Some(mark_result(drawing, &answer.report, (us, vs), single));
    }
    if p.mesh {
        answer.mesh = Some(grid);
    }
    Ok(answer)
}
