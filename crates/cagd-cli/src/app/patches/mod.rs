//! The picture the patches of boundary curves share with `cagd thesis`: appendix C's surface
//! with its boundary curves (`coons`, `coons-bicubic` and the rest draw through the operation
//! layer's drawings now).

use cagd::grid::PointGrid;
use cagd::Curve;
use cagd_octave::literal::LiteralScalar;

use crate::plot::{Colour, Figure};

use super::common::{sample, to_f64};

/// The picture of appendix C: the surface, c1 and c2 in red, d1 and d2 in green. Each curve
/// is drawn as the patch uses it: its domain `[a, b]` mapped onto the grid's `[0, 1]`.
pub fn coons_figure<T: LiteralScalar, C: Curve<T>>(
    title: &str,
    grid: PointGrid<f64>,
    [c1, c2, d1, d2]: [&C; 4],
    us: &[T],
    vs: &[T],
) -> Figure {
    let along = |c: &C, ts: &[T]| {
        let (a, b) = c.domain();
        let own: Vec<T> = ts
            .iter()
            .map(|s| a.clone() + (b.clone() - a.clone()) * s.clone())
            .collect();
        to_f64(&sample(c, &own))
    };
    Figure::new(title)
        .surface(grid, "x(u,v)")
        .boundary(along(c1, us), Colour::Red, "c1, c2")
        .boundary(along(c2, us), Colour::Red, "")
        .boundary(along(d1, vs), Colour::Green, "d1, d2")
        .boundary(along(d2, vs), Colour::Green, "")
}
