//! Drawing the layers of a [`Figure`] on a 2-D or 3-D chart: one function per kind of layer
//! (the surface is the chart's own), then the legend.

use cagd::grid::PointGrid;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::canvas::{font, px};
use super::model::{Colour, Figure, Layer};
use super::render::{drawing, rgb};
use super::text_size::text_size;
use super::PlotError;

impl Figure {
    /// Draws the layers in order on a 2-D or 3-D chart, then the legend. `project` maps a
    /// point (padded to 3-D) to the chart's coordinates; `surface` draws a surface layer,
    /// which differs between the two kinds of chart, and `surface_fill` is its mark in the
    /// legend; `net_points` marks the points of a net.
    pub(super) fn draw_layers<'a, DB, CT, P>(
        &self,
        chart: &mut ChartContext<'a, DB, CT>,
        project: impl Fn([f64; 3]) -> P + Copy,
        net_points: bool,
        surface_fill: ShapeStyle,
        mut surface: impl FnMut(&mut ChartContext<'a, DB, CT>, &PointGrid<f64>) -> Result<(), PlotError>,
    ) -> Result<(), PlotError>
    where
        DB: DrawingBackend + 'a,
        CT: CoordTranslate<From = P>,
        P: Clone + 'static,
    {
        let mut painter = Painter {
            chart,
            project,
            // Labels over a surface's dark cells stand on light boxes.
            label_boxes: self
                .layers()
                .iter()
                .any(|l| matches!(l, Layer::Surface { .. })),
        };
        for layer in self.ordered() {
            match layer {
                Layer::Surface { grid, .. } => surface(&mut *painter.chart, grid)?,
                Layer::Net { grid, colour, .. } => {
                    painter.net(grid, *colour)?;
                    if net_points {
                        painter.net_points(layer, *colour)?;
                    }
                }
                Layer::Curve { colour, width, .. } => painter.curve(layer, *colour, *width)?,
                Layer::Points { labels, .. } => painter.points(layer, labels)?,
                Layer::ControlPolygon { .. } => painter.control_polygon(layer)?,
            }
        }
        // A graph's legend stands beside the chart, drawn on the whole picture
        // ([`Figure::legend_beside`]).
        if self.has_legend() && self.legend_width() == 0 {
            painter.legend(&self.labelled(), surface_fill)?;
        }
        Ok(())
    }

    /// The layers with a label (the legend's lines), in drawing order.
    fn labelled(&self) -> Vec<&Layer> {
        self.ordered()
            .into_iter()
            .filter(|l| !l.label().is_empty())
            .collect()
    }
}

/// A chart to draw layers on, where a point (padded to 3-D) goes on it, and whether labels
/// stand on light boxes.
struct Painter<'c, 'a, DB: DrawingBackend, CT: CoordTranslate, F> {
    chart: &'c mut ChartContext<'a, DB, CT>,
    project: F,
    label_boxes: bool,
}

impl<'a, DB, CT, P, F> Painter<'_, 'a, DB, CT, F>
where
    DB: DrawingBackend + 'a,
    CT: CoordTranslate<From = P>,
    P: Clone + 'static,
    F: Fn([f64; 3]) -> P + Copy,
{
    /// A net: its grid lines in `colour`, one pixel wide.
    fn net(&mut self, grid: &PointGrid<f64>, colour: Colour) -> Result<(), PlotError> {
        let project = self.project;
        let style = rgb(colour).stroke_width(1);
        self.chart
            .draw_series(
                net_lines(grid).into_iter().map(|l| {
                    PathElement::new(l.into_iter().map(project).collect::<Vec<_>>(), style)
                }),
            )
            .map_err(drawing)?;
        Ok(())
    }

    /// The points of a net, marked by small filled circles in `colour` (on 3-D charts).
    fn net_points(&mut self, layer: &Layer, colour: Colour) -> Result<(), PlotError> {
        let project = self.project;
        self.chart
            .draw_series(
                layer
                    .points()
                    .into_iter()
                    .map(|p| Circle::new(project(p), px(3), rgb(colour).filled())),
            )
            .map_err(drawing)?;
        Ok(())
    }

    /// A curve: a line through its points in `colour`, `width` pixels wide.
    fn curve(&mut self, layer: &Layer, colour: Colour, width: u32) -> Result<(), PlotError> {
        let style = rgb(colour).stroke_width(width);
        self.chart
            .draw_series(LineSeries::new(
                layer.points().into_iter().map(self.project),
                style,
            ))
            .map_err(drawing)?;
        Ok(())
    }

    /// Marked points: black discs, each with its text beside it (on a light box over a
    /// surface).
    fn points(&mut self, layer: &Layer, labels: &[String]) -> Result<(), PlotError> {
        let project = self.project;
        let black = rgb(Colour::Black);
        self.chart
            .draw_series(
                layer
                    .points()
                    .into_iter()
                    .map(|p| Circle::new(project(p), px(6), black.filled())),
            )
            .map_err(drawing)?;
        let desc = font(14.0).into_font();
        let style = desc.color(&black);
        // On a surface each label stands on a light box, legible over the dark cells.
        let shade = if self.label_boxes {
            WHITE.mix(0.7)
        } else {
            WHITE.mix(0.0)
        };
        let mut marks = Vec::with_capacity(labels.len());
        for (p, text) in layer.points().into_iter().zip(labels) {
            let (w, h) = text_size(&desc, text).map_err(drawing)?;
            let (x, y) = (px(9), px(-18));
            let corners = [
                (x - px(2), y - px(1)),
                (x + w as i32 + px(2), y + h as i32 + px(1)),
            ];
            marks.push(
                EmptyElement::at(project(p))
                    + Rectangle::new(corners, shade.filled())
                    + Text::new(text.clone(), (x, y), style.clone()),
            );
        }
        self.chart.draw_series(marks).map_err(drawing)?;
        Ok(())
    }

    /// A control polygon: red lines between its points, each point a red ring.
    fn control_polygon(&mut self, layer: &Layer) -> Result<(), PlotError> {
        let project = self.project;
        let red = rgb(Colour::Red);
        self.chart
            .draw_series(LineSeries::new(
                layer.points().into_iter().map(project),
                red.stroke_width(1),
            ))
            .map_err(drawing)?;
        self.chart
            .draw_series(
                layer
                    .points()
                    .into_iter()
                    .map(|p| Circle::new(project(p), px(5), red.stroke_width(2))),
            )
            .map_err(drawing)?;
        Ok(())
    }

    /// The legend of `layers` in the upper right corner of the plotting area, 5 pixels in from
    /// the corner, on a light background: one line per layer, its mark (as on the chart, a
    /// surface's in `surface_fill`) and its label. The layout is plotters' series labels' (lines
    /// 1.25 font sizes apart, a margin of 10 pixels, 30 for the marks), drawn here so that every
    /// text is measured by [`text_size`]: compiled to WebAssembly, plotters' own legend asked the
    /// page's DOM for its lines' sizes, a forced layout of the whole page before the picture.
    fn legend(&mut self, layers: &[&Layer], surface_fill: ShapeStyle) -> Result<(), PlotError> {
        let desc = font(15.0).into_font();
        let sizes = layers
            .iter()
            .map(|l| text_size(&desc, l.label()))
            .collect::<Result<Vec<_>, _>>()
            .map_err(drawing)?;
        let line = desc.get_size() * 1.25;
        let tops: Vec<i32> = (0..layers.len())
            .map(|k| (k as f64 * line).round() as i32)
            .collect();
        let widest = sizes.iter().map(|&(w, _)| w as i32).max().unwrap_or(0);
        let tallest = tops
            .iter()
            .zip(&sizes)
            .map(|(top, &(_, h))| top + h as i32)
            .max()
            .unwrap_or(0);
        let (margin, marks) = (px(10), px(30));
        let (w, h) = (widest + marks + 2 * margin, tallest + 2 * margin);
        let area = self.chart.plotting_area().strip_coord_spec();
        let (x, y) = (area.dim_in_pixel().0 as i32 - w - px(5), px(5));
        let corners = [(x, y), (x + w, y + h)];
        area.draw(&Rectangle::new(corners, WHITE.mix(0.85).filled()))
            .and_then(|()| area.draw(&Rectangle::new(corners, BLACK.mix(0.5))))
            .map_err(drawing)?;
        let style = TextStyle::from(desc.clone());
        for (layer, top) in layers.iter().zip(&tops) {
            let at = (x + marks + margin, y + margin + top);
            area.draw(&Text::new(layer.label(), at, style.clone()))
                .map_err(drawing)?;
        }
        for ((layer, top), &(_, h)) in layers.iter().zip(&tops).zip(&sizes) {
            let y0 = y + margin + top;
            legend_mark(
                &area,
                layer,
                (x + margin, (2 * y0 + h as i32) / 2),
                surface_fill,
            )?;
        }
        Ok(())
    }
}

impl Figure {
    /// The legend of a graph beside its chart, its upper left corner at `(x, y)` of `root`
    /// (plotters draws a chart's own legend inside the plotting area, which clamps anything
    /// beyond it to its edge): a box with one line per labelled layer, the layer's mark (as
    /// on the chart) and its label.
    pub(super) fn legend_beside<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        (x, y): (i32, i32),
    ) -> Result<(), PlotError> {
        let labelled = self.labelled();
        let (w, h) = (
            px(self.legend_width() as i32 - 24),
            px(12 + 22 * labelled.len() as i32),
        );
        let corners = [(x, y), (x + w, y + h)];
        root.draw(&Rectangle::new(corners, WHITE.mix(0.85).filled()))
            .map_err(drawing)?;
        root.draw(&Rectangle::new(corners, BLACK.mix(0.5)))
            .map_err(drawing)?;
        let font = font(15.0)
            .into_font()
            .color(&BLACK)
            .pos(Pos::new(HPos::Left, VPos::Center));
        for (k, layer) in labelled.into_iter().enumerate() {
            let at = (x + px(8), y + px(17 + 22 * k as i32));
            legend_mark(root, layer, at, super::render::viridis(0.6).filled())?;
            let text = Text::new(
                layer.label().to_string(),
                (at.0 + px(30), at.1),
                font.clone(),
            );
            root.draw(&text).map_err(drawing)?;
        }
        Ok(())
    }
}

/// Draws the mark of `layer` in a legend on `root`, its left end at `(x, y)`: as the layer is
/// drawn on the chart (a surface as a patch of `surface_fill`).
fn legend_mark<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    layer: &Layer,
    (x, y): (i32, i32),
    surface_fill: ShapeStyle,
) -> Result<(), PlotError> {
    let line = |style: ShapeStyle| PathElement::new(vec![(x, y), (x + px(20), y)], style);
    match layer {
        Layer::Curve { colour, width, .. } => root.draw(&line(rgb(*colour).stroke_width(*width))),
        Layer::Net { colour, .. } => root.draw(&line(rgb(*colour).stroke_width(1))),
        Layer::Points { .. } => root.draw(&Circle::new((x + px(10), y), px(5), BLACK.filled())),
        Layer::ControlPolygon { .. } => {
            let red = rgb(Colour::Red);
            root.draw(&line(red.stroke_width(1)))
                .and_then(|()| root.draw(&Circle::new((x + px(10), y), px(4), red.stroke_width(2))))
        }
        Layer::Surface { .. } => root.draw(&Rectangle::new(
            [(x, y - px(6)), (x + px(20), y + px(6))],
            surface_fill,
        )),
    }
    .map_err(drawing)
}

/// The grid lines of a net: every row `i` and every column `j`, as 3-D points.
pub(super) fn net_lines(grid: &PointGrid<f64>) -> Vec<Vec<[f64; 3]>> {
    let (nu, nv, d) = grid.dim();
    let p = |i: usize, j: usize| {
        [
            grid[[i, j, 0]],
            grid[[i, j, 1]],
            if d > 2 { grid[[i, j, 2]] } else { 0.0 },
        ]
    };
    let mut lines = Vec::with_capacity(nu + nv);
    for i in 0..nu {
        lines.push((0..nv).map(|j| p(i, j)).collect());
    }
    for j in 0..nv {
        lines.push((0..nu).map(|i| p(i, j)).collect());
    }
    lines
}
