//! Drawing the layers of a [`Figure`] on a 2-D or 3-D chart: one function per kind of layer
//! (the surface is the chart's own), then the legend.

use cagd::grid::PointGrid;
use plotters::chart::SeriesAnno;
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
    /// which differs between the two kinds of chart; `net_points` marks the points of a net.
    pub(super) fn draw_layers<'a, DB, CT, P>(
        &self,
        chart: &mut ChartContext<'a, DB, CT>,
        project: impl Fn([f64; 3]) -> P + Copy,
        net_points: bool,
        mut surface: impl FnMut(
            &mut ChartContext<'a, DB, CT>,
            &PointGrid<f64>,
            &str,
        ) -> Result<(), PlotError>,
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
                Layer::Surface { grid, label } => surface(&mut *painter.chart, grid, label)?,
                Layer::Net {
                    grid,
                    colour,
                    label,
                } => {
                    painter.net(grid, *colour, label)?;
                    if net_points {
                        painter.net_points(layer, *colour)?;
                    }
                }
                Layer::Curve {
                    colour,
                    width,
                    label,
                    ..
                } => painter.curve(layer, *colour, *width, label)?,
                Layer::Points { labels, label, .. } => painter.points(layer, labels, label)?,
                Layer::ControlPolygon { label, .. } => painter.control_polygon(layer, label)?,
            }
        }
        // A graph's legend stands beside the chart, drawn on the whole picture
        // ([`Figure::legend_beside`]).
        if self.has_legend() && self.legend_width() == 0 {
            painter.legend(&self.legend_labels())?;
        }
        Ok(())
    }

    /// The labels of the legend, in drawing order.
    fn legend_labels(&self) -> Vec<&str> {
        self.ordered()
            .into_iter()
            .map(Layer::label)
            .filter(|l| !l.is_empty())
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
    fn net(&mut self, grid: &PointGrid<f64>, colour: Colour, label: &str) -> Result<(), PlotError> {
        let project = self.project;
        let style = rgb(colour).stroke_width(1);
        let anno =
            self.chart
                .draw_series(net_lines(grid).into_iter().map(|l| {
                    PathElement::new(l.into_iter().map(project).collect::<Vec<_>>(), style)
                }))
                .map_err(drawing)?;
        line_legend(anno, label, style);
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
    fn curve(
        &mut self,
        layer: &Layer,
        colour: Colour,
        width: u32,
        label: &str,
    ) -> Result<(), PlotError> {
        let style = rgb(colour).stroke_width(width);
        let anno = self
            .chart
            .draw_series(LineSeries::new(
                layer.points().into_iter().map(self.project),
                style,
            ))
            .map_err(drawing)?;
        line_legend(anno, label, style);
        Ok(())
    }

    /// Marked points: black discs, each with its text beside it (on a light box over a
    /// surface).
    fn points(&mut self, layer: &Layer, labels: &[String], label: &str) -> Result<(), PlotError> {
        let project = self.project;
        let black = rgb(Colour::Black);
        let anno = self
            .chart
            .draw_series(
                layer
                    .points()
                    .into_iter()
                    .map(|p| Circle::new(project(p), px(6), black.filled())),
            )
            .map_err(drawing)?;
        if !label.is_empty() {
            anno.label(label)
                .legend(move |(x, y)| Circle::new((x + px(10), y), px(5), black.filled()));
        }
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
    fn control_polygon(&mut self, layer: &Layer, label: &str) -> Result<(), PlotError> {
        let project = self.project;
        let red = rgb(Colour::Red);
        let anno = self
            .chart
            .draw_series(LineSeries::new(
                layer.points().into_iter().map(project),
                red.stroke_width(1),
            ))
            .map_err(drawing)?;
        if !label.is_empty() {
            anno.label(label).legend(move |(x, y)| {
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 0), (px(20), 0)], red.stroke_width(1))
                    + Circle::new((px(10), 0), px(4), red.stroke_width(2))
            });
        }
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

    /// The legend of the layers labelled `labels`, in the upper right corner on a light
    /// background, 5 pixels in from the corner. (Plotters' own corner positions keep 5 canvas
    /// units, half a pixel here: the box is placed at that corner from the width plotters gives
    /// it, the widest label and the margins and sample lines.)
    fn legend(&mut self, labels: &[&str]) -> Result<(), PlotError> {
        let text = font(15.0).into_font();
        let widest = labels
            .iter()
            .map(|l| text_size(&text, l).map(|(w, _)| w as i32))
            .try_fold(0, |m, w| w.map(|w| m.max(w)))
            .map_err(drawing)?;
        let (area_w, _) = self.chart.plotting_area().dim_in_pixel();
        let x = area_w as i32 - (widest + px(30) + 2 * px(10)) - px(5);
        self.chart
            .configure_series_labels()
            .position(SeriesLabelPosition::Coordinate(x, px(5)))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.5))
            .label_font(font(15.0))
            .margin(px(10))
            .legend_area_size(px(30))
            .draw()
            .map_err(drawing)
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
        let labelled: Vec<&Layer> = self
            .ordered()
            .into_iter()
            .filter(|l| !l.label().is_empty())
            .collect();
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
            legend_mark(root, layer, at)?;
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
/// drawn on the chart.
fn legend_mark<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    layer: &Layer,
    (x, y): (i32, i32),
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
            super::render::viridis(0.6).filled(),
        )),
    }
    .map_err(drawing)
}

/// The legend entry of a line drawn in `style`: a short stretch of it (none without a label).
fn line_legend<'a, DB: DrawingBackend + 'a>(
    anno: &mut SeriesAnno<'a, DB>,
    label: &str,
    style: ShapeStyle,
) {
    if !label.is_empty() {
        anno.label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + px(20), y)], style));
    }
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
