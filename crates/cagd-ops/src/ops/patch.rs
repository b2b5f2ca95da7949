//! What the patches of curves and corner data share beyond [`super::surface`]: the result of
//! a surface without parts, the curves' costs once realised, the evaluated point marked in a
//! picture.

use cagd::cost::{max_bits, Cost};
use cagd::{Curve, Scalar, Surface};

use super::surface::push_surface;
use super::{point_labels, to_f64};
use crate::curves::Realised;
use crate::drawing::Drawing;
use crate::error::Result;
use crate::{Context, Report, Value};

/// Pushes `result`: at a single point (and no `list`) the `d × 1` column, else the grid
/// `us × vs × d` (or with `list` one row `u v x y z` per point).
pub fn push_result<T: Scalar, S: Surface<T>>(
    report: &mut Report<T>,
    surface: &S,
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
    cx.check_interrupt()?;
    push_surface(report, "result", (us, vs), surface.eval_grid(us, vs), list);
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
