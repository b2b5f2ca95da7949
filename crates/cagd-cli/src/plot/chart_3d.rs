//! The 3-D chart of a [`Figure`]: Octave's view direction, the names of the axes beside their
//! tick labels, surfaces as depth-sorted cells coloured by height.

use cagd::grid::PointGrid;
use plotters::coord::ranged3d::Cartesian3d;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::canvas::{font, px, titled};
use super::model::Figure;
use super::render::{drawing, tick_text, viridis};
use super::PlotError;

/// Plotters' 3-D coordinates over `f64` ranges.
type Coord3 = Cartesian3d<RangedCoordf64, RangedCoordf64, RangedCoordf64>;

/// A point of the data, (x, y, z), in plotters' coordinates (y, z, x).
///
/// Plotters' vertical axis is its second one: data (x, y, z) is drawn at plotters' (y, z, x),
/// a cyclic permutation, so that the picture keeps the right-handed orientation of the data.
fn to3(p: [f64; 3]) -> (f64, f64, f64) {
    (p[1], p[2], p[0])
}

impl Figure {
    /// Draws the figure as a 3-D chart (some layer has a third coordinate).
    pub(super) fn draw_3d<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> Result<(), PlotError> {
        let [bx, by, bz] = self.bounds();
        let mut chart = chart_3d(root, &self.drawing.title, [by, bz, bx])?;
        let names = axis_name_positions(chart.as_coord_spec(), [by, bz, bx], root.dim_in_pixel());
        let axes = &self.drawing.axes;
        for (name, (x, y)) in [&axes[1], &axes[2], &axes[0]].into_iter().zip(names) {
            root.draw(&Text::new(
                name.to_string(),
                (x, y),
                font(18.0)
                    .into_font()
                    .into_text_style(root)
                    .pos(Pos::new(HPos::Center, VPos::Center)),
            ))
            .map_err(drawing)?;
        }
        // A 3-D net also marks its points.
        self.draw_layers(
            &mut chart,
            to3,
            true,
            viridis(0.6).filled(),
            |chart, grid| surface_3d(chart, grid, bz),
        )
    }
}

/// The chart with its caption, Octave's view and the axes with their ticks, over `bounds` in
/// plotters' axis order.
fn chart_3d<'a, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    title: &str,
    bounds: [(f64, f64); 3],
) -> Result<ChartContext<'a, DB, Coord3>, PlotError> {
    let [b0, b1, b2] = bounds;
    let area = titled(root, title, (px(20), px(20)))?;
    let mut chart = ChartBuilder::on(&area)
        .margin(px(20))
        .margin_top(0)
        .build_cartesian_3d(b0.0..b0.1, b1.0..b1.1, b2.0..b2.1)
        .map_err(drawing)?;
    chart.with_projection(|mut pb| {
        // Octave's default view, azimuth −37.5° and elevation 30°: the origin corner in
        // front, x running to the right, y to the left and back, z up. (Found by
        // comparing pictures: plotters measures yaw from another axis.)
        pb.yaw = 4.05;
        pb.pitch = 0.52;
        pb.scale = 0.78;
        pb.into_matrix()
    });
    chart
        .configure_axes()
        .light_grid_style(BLACK.mix(0.12))
        .max_light_lines(4)
        .tick_size(px(5))
        .x_formatter(&|x| tick_text(*x, b0.1 - b0.0))
        .y_formatter(&|y| tick_text(*y, b1.1 - b1.0))
        .z_formatter(&|z| tick_text(*z, b2.1 - b2.0))
        .label_style(font(13.0))
        .draw()
        .map_err(drawing)?;
    Ok(chart)
}

/// A cell of a surface: its depth from the viewer, its mean height, its corners (plotters'
/// coordinates).
type Cell = (i32, f64, [(f64, f64, f64); 4]);

/// A surface: its cells filled with the viridis colour of their height (`heights` the range
/// of z), far cells first, with dark edges.
fn surface_3d<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Coord3>,
    grid: &PointGrid<f64>,
    (zlo, zhi): (f64, f64),
) -> Result<(), PlotError> {
    let cells = depth_sorted_cells(chart.as_coord_spec(), grid);
    chart
        .draw_series(cells.iter().map(|(_, height, quad)| {
            let c = viridis((height - zlo) / (zhi - zlo));
            Polygon::new(quad.to_vec(), c.filled())
        }))
        .map_err(drawing)?;
    chart
        .draw_series(cells.iter().map(|(_, _, quad)| {
            let mut ring = quad.to_vec();
            ring.push(quad[0]);
            PathElement::new(ring, BLACK.mix(0.55).stroke_width(1))
        }))
        .map_err(drawing)?;
    Ok(())
}

/// The cells of the grid in the painter's order: far cells first.
fn depth_sorted_cells(coord: &Coord3, grid: &PointGrid<f64>) -> Vec<Cell> {
    let (nu, nv, _) = grid.dim();
    let p = |i: usize, j: usize| {
        to3([
            grid[[i, j, 0]],
            grid[[i, j, 1]],
            if grid.dim().2 > 2 {
                grid[[i, j, 2]]
            } else {
                0.0
            },
        ])
    };
    let mut cells = Vec::new();
    for i in 0..nu.saturating_sub(1) {
        for j in 0..nv.saturating_sub(1) {
            let quad = [p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)];
            let height = quad.iter().map(|q| q.1).sum::<f64>() / 4.0;
            let centre = (
                quad.iter().map(|q| q.0).sum::<f64>() / 4.0,
                height,
                quad.iter().map(|q| q.2).sum::<f64>() / 4.0,
            );
            let depth = coord.projected_depth(&centre.0, &centre.1, &centre.2);
            cells.push((depth, height, quad));
        }
    }
    cells.sort_by_key(|c| std::cmp::Reverse(c.0));
    cells
}

/// Where to write the name of each axis (plotters' axis order): beyond the middle of the
/// edge along which plotters draws that axis's tick labels.
///
/// Plotters puts the ticks of axis `a` on an edge of the back panels (the faces of the box
/// farther from the viewer): for each other axis `i` at its back-panel value and the third
/// axis at either end, the candidate nearest the viewer (then highest on screen) wins. This
/// repeats that choice, then steps outwards from the picture's centre as the tick labels do.
fn axis_name_positions(
    coord: &Coord3,
    bounds: [(f64, f64); 3],
    (width, height): (u32, u32),
) -> [(i32, i32); 3] {
    let back = back_panels(coord, bounds);
    let centre = (width as i32 / 2, height as i32 / 2);
    std::array::from_fn(|axis| match tick_edge(coord, bounds, back, axis) {
        Some((s, e)) => name_position(coord, s, e, centre),
        None => centre,
    })
}

/// The back panel of each axis: the end whose all-minimum corner lies deeper.
fn back_panels(coord: &Coord3, bounds: [(f64, f64); 3]) -> [f64; 3] {
    let depth = |p: [f64; 3]| coord.projected_depth(&p[0], &p[1], &p[2]);
    std::array::from_fn(|k| {
        let mut a = [bounds[0].0, bounds[1].0, bounds[2].0];
        let low = depth(a);
        a[k] = bounds[k].1;
        if low >= depth(a) {
            bounds[k].0
        } else {
            bounds[k].1
        }
    })
}

/// The two ends of the edge along which plotters draws the tick labels of `axis`: of the
/// edges on the back panels, the nearest the viewer, then the highest on screen.
fn tick_edge(
    coord: &Coord3,
    bounds: [(f64, f64); 3],
    back: [f64; 3],
    axis: usize,
) -> Option<([f64; 3], [f64; 3])> {
    let depth = |p: [f64; 3]| coord.projected_depth(&p[0], &p[1], &p[2]);
    // (depth sum, screen y sum) of the best edge so far, and its two ends.
    type Edge = ((i32, i32), [f64; 3], [f64; 3]);
    let mut best: Option<Edge> = None;
    for i in (0..3).filter(|&i| i != axis) {
        let j = 3 - axis - i;
        for end_j in [bounds[j].0, bounds[j].1] {
            let mut s = [0.0; 3];
            s[i] = back[i];
            s[j] = end_j;
            s[axis] = bounds[axis].0;
            let mut e = s;
            e[axis] = bounds[axis].1;
            let (_, y1) = coord.translate(&(s[0], s[1], s[2]));
            let (_, y2) = coord.translate(&(e[0], e[1], e[2]));
            let key = (depth(s) + depth(e), y1 + y2);
            if best.as_ref().is_none_or(|b| key < b.0) {
                best = Some((key, s, e));
            }
        }
    }
    best.map(|(_, s, e)| (s, e))
}

/// Where the name of the axis whose tick labels run along the edge from `s` to `e` goes.
///
/// Tick labels go horizontally or vertically away from the centre, whichever is more across
/// the axis; the name goes a little further the same way.
fn name_position(coord: &Coord3, s: [f64; 3], e: [f64; 3], centre: (i32, i32)) -> (i32, i32) {
    let m: [f64; 3] = std::array::from_fn(|k| (s[k] + e[k]) / 2.0);
    let (mx, my) = coord.translate(&(m[0], m[1], m[2]));
    let (bx, by) = coord.translate(&(s[0], s[1], s[2]));
    let (ex, ey) = coord.translate(&(e[0], e[1], e[2]));
    let (dx, dy) = ((ex - bx) as f64, (ey - by) as f64);
    let horizontal = dx.abs() < dy.abs();
    if horizontal {
        let sign = if bx < centre.0 { -1 } else { 1 };
        (mx + sign * px(55), my)
    } else {
        let sign = if by < centre.1 { -1 } else { 1 };
        (mx, my + sign * px(38))
    }
}
