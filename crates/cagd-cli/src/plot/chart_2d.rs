//! The 2-D chart of a [`Figure`]: equal scales for geometry with a band at the top kept free
//! for the legend; a graph's axes fitted to its data with the legend beside them; surfaces as
//! filled cells under their net.

use std::ops::Range;

use cagd::grid::PointGrid;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{font, px, titled};
use super::layers::net_lines;
use super::model::Figure;
use super::render::{drawing, tick_text, viridis};
use super::PlotError;

/// Plotters' 2-D coordinates over `f64` ranges.
type Coord2 = Cartesian2d<RangedCoordf64, RangedCoordf64>;

/// A point of the data (padded to 3-D) in the chart's coordinates.
fn to2(p: [f64; 3]) -> (f64, f64) {
    (p[0], p[1])
}

/// The ranges of a 2-D chart's axes, and the half-widths of the data's part of them.
struct Window {
    x: Range<f64>,
    y: Range<f64>,
    half: (f64, f64),
}

impl Figure {
    /// Draws the figure as a 2-D chart (every layer is planar).
    pub(super) fn draw_2d<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> Result<(), PlotError> {
        let side = self.legend_width();
        let right = px(20 + side as i32);
        let area = titled(root, &self.drawing.title, (px(20), right))?;
        // The plotting area: the area below the title less the margins (20 pixels left and
        // below, `right` on the right) and the label areas (50 pixels left, 40 below).
        let (w, h) = area.dim_in_pixel();
        let plot = (
            f64::from((w as i32 - px(20) - right - px(50)).max(px(50))),
            f64::from((h as i32 - px(20) - px(40)).max(px(50))),
        );
        let Window { x, y, half } = self.window(plot, side > 0);
        let (hx, hy) = half;
        let mut chart = ChartBuilder::on(&area)
            .margin(px(20))
            .margin_top(0)
            .margin_right(right)
            .x_label_area_size(px(40))
            .y_label_area_size(px(50))
            .build_cartesian_2d(x, y)
            .map_err(drawing)?;
        chart
            .configure_mesh()
            .light_line_style(BLACK.mix(0.08))
            .set_tick_mark_size(LabelAreaPosition::Left, px(5))
            .set_tick_mark_size(LabelAreaPosition::Bottom, px(5))
            .x_label_formatter(&|x| tick_text(*x, 2.0 * hx))
            .y_label_formatter(&|y| tick_text(*y, 2.0 * hy))
            .x_desc(self.drawing.axes[0].as_str())
            .y_desc(self.drawing.axes[1].as_str())
            .label_style(font(13.0))
            .axis_desc_style(font(16.0))
            .draw()
            .map_err(drawing)?;
        self.draw_layers(&mut chart, to2, false, surface_fill().filled(), surface_2d)?;
        if side > 0 {
            let (xs, ys) = chart.plotting_area().get_pixel_range();
            self.legend_beside(root, (xs.end + px(12), ys.start))?;
        }
        Ok(())
    }

    /// The axes' ranges on a plotting area of `aw × ah` canvas units, the legend beside it
    /// (`side`) or in it.
    ///
    /// Geometry: equal scales on both axes, so that shapes are not distorted, and the data
    /// keeps out of a band at the top where the legend goes, so the legend never hides a
    /// point. A graph: each axis its data's range (padded), the legend beside it.
    fn window(&self, (aw, ah): (f64, f64), side: bool) -> Window {
        let [bx, by, _] = self.bounds();
        let band = if side {
            0.0
        } else {
            (f64::from(px(1)) * self.legend_height()).min(ah / 2.0)
        };
        let (sx, sy) = ((bx.1 - bx.0) / aw, (by.1 - by.0) / (ah - band));
        // Geometry: one scale for both axes; a graph: each axis fitted to its data.
        let (sx, sy) = if self.drawing.equal_scales {
            (sx.max(sy), sx.max(sy))
        } else {
            (sx, sy)
        };
        let scale = sy;
        let (cx, cy) = ((bx.0 + bx.1) / 2.0, (by.0 + by.1) / 2.0);
        let (hx, hy) = (sx * aw / 2.0, sy * (ah - band) / 2.0);
        Window {
            x: cx - hx..cx + hx,
            y: cy - hy..cy + hy + scale * band,
            half: (hx, hy),
        }
    }
}

/// The light viridis colour of a surface's cells (and of its mark in the legend).
fn surface_fill() -> RGBAColor {
    viridis(0.6).mix(0.35)
}

/// A surface: its cells filled in a light viridis colour, its net drawn over them.
fn surface_2d<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Coord2>,
    grid: &PointGrid<f64>,
) -> Result<(), PlotError> {
    let (nu, nv, _) = grid.dim();
    let p = |i: usize, j: usize| (grid[[i, j, 0]], grid[[i, j, 1]]);
    let mut cells = Vec::new();
    for i in 0..nu.saturating_sub(1) {
        for j in 0..nv.saturating_sub(1) {
            cells.push([p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
        }
    }
    chart
        .draw_series(
            cells
                .iter()
                .map(|q| Polygon::new(q.to_vec(), surface_fill().filled())),
        )
        .map_err(drawing)?;
    chart
        .draw_series(
            net_lines(grid).into_iter().map(|l| {
                PathElement::new(l.into_iter().map(to2).collect::<Vec<_>>(), BLACK.mix(0.55))
            }),
        )
        .map_err(drawing)?;
    Ok(())
}
