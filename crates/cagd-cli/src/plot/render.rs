//! Drawing a [`Figure`] with plotters into SVG or PNG: the 2-D and 3-D charts, Octave's view
//! direction, the colour map, the embedded font.

use std::path::Path;
use std::sync::Once;

use cagd::grid::PointGrid;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::model::{validate, Colour, Figure, ImageKind, Layer};
use super::PlotError;

/// The font embedded for text in pictures.
#[cfg(not(target_arch = "wasm32"))]
static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
static REGISTER_FONT: Once = Once::new();
const FAMILY: &str = "sans-serif";

fn register_font() {
    REGISTER_FONT.call_once(|| {
        // The embedded font is a valid TrueType file; should registration ever fail, text is
        // simply not drawn. (In the browser plotters measures text with the page's fonts.)
        #[cfg(not(target_arch = "wasm32"))]
        let _ = plotters::style::register_font(FAMILY, FontStyle::Normal, FONT);
    });
}

/// The colour's RGB value.
pub(super) fn rgb(colour: Colour) -> RGBColor {
    match colour {
        Colour::Blue => RGBColor(0, 114, 189),
        Colour::Red => RGBColor(220, 20, 20),
        Colour::Green => RGBColor(0, 150, 0),
        Colour::Black => RGBColor(0, 0, 0),
        Colour::Orange => RGBColor(237, 145, 33),
        Colour::Purple => RGBColor(126, 47, 142),
    }
}

impl Figure {
    /// Draws the figure into an in-memory SVG or PNG file.
    pub fn render(&self, kind: ImageKind) -> Result<Vec<u8>, PlotError> {
        if self.layers().is_empty() {
            return Err(PlotError::Empty);
        }
        for l in self.layers() {
            validate(l)?;
        }
        let (w, h) = self.size;
        if !(100..=10_000).contains(&w) || !(100..=10_000).contains(&h) {
            return Err(PlotError::Size {
                width: w,
                height: h,
            });
        }
        register_font();
        match kind {
            ImageKind::Svg => {
                let mut svg = String::new();
                {
                    let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
                    self.draw(&root)?;
                    root.present().map_err(drawing)?;
                }
                Ok(svg.into_bytes())
            }
            #[cfg(target_arch = "wasm32")]
            ImageKind::Png => Err(PlotError::Drawing(
                "PNG pictures are drawn by the cagd program only; in the browser, name the picture .svg"
                    .into(),
            )),
            #[cfg(not(target_arch = "wasm32"))]
            ImageKind::Png => {
                let svg = self.render(ImageKind::Svg)?;
                rasterize(&String::from_utf8_lossy(&svg), w, h)
            }
        }
    }

    /// Draws the figure into `path` (SVG or PNG by extension), atomically.
    pub fn save(&self, path: &Path) -> Result<(), PlotError> {
        let kind = ImageKind::from_path(path)?;
        let bytes = self.render(kind)?;
        crate::write_atomic(path, &bytes).map_err(|e| PlotError::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        })
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        root.fill(&WHITE).map_err(drawing)?;
        if self.layers().iter().all(|l| l.dim() == 2) {
            self.draw_2d(root)
        } else {
            self.draw_3d(root)
        }
    }

    fn bounds(&self) -> [(f64, f64); 3] {
        let mut b = [(f64::INFINITY, f64::NEG_INFINITY); 3];
        for l in self.layers() {
            for p in l.points() {
                for k in 0..3 {
                    b[k].0 = b[k].0.min(p[k]);
                    b[k].1 = b[k].1.max(p[k]);
                }
            }
        }
        b.map(|(lo, hi)| padded(lo, hi))
    }

    fn draw_3d<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        let [bx, by, bz] = self.bounds();
        // Plotters' vertical axis is its second one: data (x, y, z) is drawn at plotters'
        // (y, z, x), a cyclic permutation, so that the picture keeps the right-handed
        // orientation of the data.
        let mut chart = ChartBuilder::on(root)
            .caption(&self.drawing.title, (FAMILY, 24))
            .margin(20)
            .build_cartesian_3d(by.0..by.1, bz.0..bz.1, bx.0..bx.1)
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
            .x_formatter(&|x| tick_text(*x, by.1 - by.0))
            .y_formatter(&|y| tick_text(*y, bz.1 - bz.0))
            .z_formatter(&|z| tick_text(*z, bx.1 - bx.0))
            .label_style((FAMILY, 13))
            .draw()
            .map_err(drawing)?;
        let to3 = |p: [f64; 3]| (p[1], p[2], p[0]);
        let names = axis_name_positions(chart.as_coord_spec(), [by, bz, bx], root.dim_in_pixel());
        let axes = &self.drawing.axes;
        for (name, (x, y)) in [&axes[1], &axes[2], &axes[0]].into_iter().zip(names) {
            root.draw(&Text::new(
                name.to_string(),
                (x, y),
                (FAMILY, 18)
                    .into_font()
                    .into_text_style(root)
                    .pos(Pos::new(HPos::Center, VPos::Center)),
            ))
            .map_err(drawing)?;
        }

        // A 3-D net also marks its points.
        self.draw_layers(&mut chart, to3, true, |chart, grid, label| {
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
                    let depth = chart
                        .as_coord_spec()
                        .projected_depth(&centre.0, &centre.1, &centre.2);
                    cells.push((depth, height, quad));
                }
            }
            // Painter's algorithm: far cells first.
            cells.sort_by_key(|c| std::cmp::Reverse(c.0));
            let (zlo, zhi) = bz;
            let anno = chart
                .draw_series(cells.iter().map(|(_, height, quad)| {
                    let c = viridis((height - zlo) / (zhi - zlo));
                    Polygon::new(quad.to_vec(), c.filled())
                }))
                .map_err(drawing)?;
            if !label.is_empty() {
                anno.label(label).legend(|(x, y)| {
                    Rectangle::new([(x, y - 6), (x + 20, y + 6)], viridis(0.6).filled())
                });
            }
            chart
                .draw_series(cells.iter().map(|(_, _, quad)| {
                    let mut ring = quad.to_vec();
                    ring.push(quad[0]);
                    PathElement::new(ring, BLACK.mix(0.55).stroke_width(1))
                }))
                .map_err(drawing)?;
            Ok(())
        })
    }

    fn draw_2d<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        let [bx, by, _] = self.bounds();
        // Equal scales on both axes, so that shapes are not distorted; the data keeps out of a
        // band at the top where the legend goes, so the legend never hides a point.
        let (w, h) = root.dim_in_pixel();
        let (aw, ah) = ((w as f64 - 110.0).max(50.0), (h as f64 - 120.0).max(50.0));
        let band = self.legend_height().min(ah / 2.0);
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
        let mut chart = ChartBuilder::on(root)
            .caption(&self.drawing.title, (FAMILY, 24))
            .margin(20)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(cx - hx..cx + hx, cy - hy..cy + hy + scale * band)
            .map_err(drawing)?;
        chart
            .configure_mesh()
            .light_line_style(BLACK.mix(0.08))
            .x_label_formatter(&|x| tick_text(*x, 2.0 * hx))
            .y_label_formatter(&|y| tick_text(*y, 2.0 * hy))
            .x_desc(self.drawing.axes[0].as_str())
            .y_desc(self.drawing.axes[1].as_str())
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 16))
            .draw()
            .map_err(drawing)?;
        let to2 = |p: [f64; 3]| (p[0], p[1]);
        self.draw_layers(&mut chart, to2, false, |chart, grid, label| {
            let (nu, nv, _) = grid.dim();
            let p = |i: usize, j: usize| (grid[[i, j, 0]], grid[[i, j, 1]]);
            let mut cells = Vec::new();
            for i in 0..nu.saturating_sub(1) {
                for j in 0..nv.saturating_sub(1) {
                    cells.push([p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
                }
            }
            let fill = viridis(0.6).mix(0.35);
            let anno = chart
                .draw_series(
                    cells
                        .iter()
                        .map(|q| Polygon::new(q.to_vec(), fill.filled())),
                )
                .map_err(drawing)?;
            if !label.is_empty() {
                anno.label(label).legend(move |(x, y)| {
                    Rectangle::new([(x, y - 6), (x + 20, y + 6)], fill.filled())
                });
            }
            chart
                .draw_series(net_lines(grid).into_iter().map(|l| {
                    PathElement::new(l.into_iter().map(to2).collect::<Vec<_>>(), BLACK.mix(0.55))
                }))
                .map_err(drawing)?;
            Ok(())
        })
    }

    /// Draws the layers in order on a 2-D or 3-D chart, then the legend. `project` maps a
    /// point (padded to 3-D) to the chart's coordinates; `surface` draws a surface layer,
    /// which differs between the two kinds of chart; `net_points` marks the points of a net.
    fn draw_layers<'a, DB, CT, P>(
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
        for layer in self.ordered() {
            match layer {
                Layer::Surface { grid, label } => surface(chart, grid, label)?,
                Layer::Net {
                    grid,
                    colour,
                    label,
                } => {
                    let style = rgb(*colour).stroke_width(1);
                    let anno = chart
                        .draw_series(net_lines(grid).into_iter().map(|l| {
                            PathElement::new(l.into_iter().map(project).collect::<Vec<_>>(), style)
                        }))
                        .map_err(drawing)?;
                    if !label.is_empty() {
                        anno.label(label.as_str()).legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 20, y)], style)
                        });
                    }
                    if net_points {
                        chart
                            .draw_series(
                                layer
                                    .points()
                                    .into_iter()
                                    .map(|p| Circle::new(project(p), 3, rgb(*colour).filled())),
                            )
                            .map_err(drawing)?;
                    }
                }
                Layer::Curve {
                    colour,
                    width,
                    label,
                    ..
                } => {
                    let style = rgb(*colour).stroke_width(*width);
                    let anno = chart
                        .draw_series(LineSeries::new(
                            layer.points().into_iter().map(project),
                            style,
                        ))
                        .map_err(drawing)?;
                    if !label.is_empty() {
                        anno.label(label.as_str()).legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 20, y)], style)
                        });
                    }
                }
                Layer::Points { labels, label, .. } => {
                    let black = rgb(Colour::Black);
                    let anno = chart
                        .draw_series(
                            layer
                                .points()
                                .into_iter()
                                .map(|p| Circle::new(project(p), 6, black.filled())),
                        )
                        .map_err(drawing)?;
                    if !label.is_empty() {
                        anno.label(label.as_str())
                            .legend(move |(x, y)| Circle::new((x + 10, y), 5, black.filled()));
                    }
                    let font = (FAMILY, 14).into_font().color(&black);
                    chart
                        .draw_series(layer.points().into_iter().zip(labels).map(|(p, text)| {
                            EmptyElement::at(project(p))
                                + Text::new(text.clone(), (9, -18), font.clone())
                        }))
                        .map_err(drawing)?;
                }
                Layer::ControlPolygon { label, .. } => {
                    let red = rgb(Colour::Red);
                    let anno = chart
                        .draw_series(LineSeries::new(
                            layer.points().into_iter().map(project),
                            red.stroke_width(1),
                        ))
                        .map_err(drawing)?;
                    if !label.is_empty() {
                        anno.label(label.as_str()).legend(move |(x, y)| {
                            EmptyElement::at((x, y))
                                + PathElement::new(vec![(0, 0), (20, 0)], red.stroke_width(1))
                                + Circle::new((10, 0), 4, red.stroke_width(2))
                        });
                    }
                    chart
                        .draw_series(
                            layer
                                .points()
                                .into_iter()
                                .map(|p| Circle::new(project(p), 5, red.stroke_width(2))),
                        )
                        .map_err(drawing)?;
                }
            }
        }
        if self.has_legend() {
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK.mix(0.5))
                .label_font((FAMILY, 15))
                .draw()
                .map_err(drawing)?;
        }
        Ok(())
    }
}

/// Where to write the name of each axis (plotters' axis order): beyond the middle of the
/// edge along which plotters draws that axis's tick labels.
///
/// Plotters puts the ticks of axis `a` on an edge of the back panels (the faces of the box
/// farther from the viewer): for each other axis `i` at its back-panel value and the third
/// axis at either end, the candidate nearest the viewer (then highest on screen) wins. This
/// repeats that choice, then steps outwards from the picture's centre as the tick labels do.
fn axis_name_positions(
    coord: &plotters::coord::ranged3d::Cartesian3d<
        plotters::coord::types::RangedCoordf64,
        plotters::coord::types::RangedCoordf64,
        plotters::coord::types::RangedCoordf64,
    >,
    bounds: [(f64, f64); 3],
    (width, height): (u32, u32),
) -> [(i32, i32); 3] {
    let ranges = bounds.map(|(start, end)| start..end);
    let ends = |k: usize| [ranges[k].start, ranges[k].end];
    let depth = |p: [f64; 3]| coord.projected_depth(&p[0], &p[1], &p[2]);
    // The back panel of each axis: the end whose all-minimum corner lies deeper.
    let back: [f64; 3] = std::array::from_fn(|k| {
        let mut a = [ranges[0].start, ranges[1].start, ranges[2].start];
        let low = depth(a);
        a[k] = ranges[k].end;
        if low >= depth(a) {
            ranges[k].start
        } else {
            ranges[k].end
        }
    });
    let centre = (width as i32 / 2, height as i32 / 2);
    std::array::from_fn(|axis| {
        // (depth sum, screen y sum) of the best edge so far, and its two ends.
        type Edge = ((i32, i32), [f64; 3], [f64; 3]);
        let mut best: Option<Edge> = None;
        for i in (0..3).filter(|&i| i != axis) {
            let j = 3 - axis - i;
            for end_j in ends(j) {
                let mut s = [0.0; 3];
                s[i] = back[i];
                s[j] = end_j;
                s[axis] = ranges[axis].start;
                let mut e = s;
                e[axis] = ranges[axis].end;
                let (_, y1) = coord.translate(&(s[0], s[1], s[2]));
                let (_, y2) = coord.translate(&(e[0], e[1], e[2]));
                let key = (depth(s) + depth(e), y1 + y2);
                if best.as_ref().is_none_or(|b| key < b.0) {
                    best = Some((key, s, e));
                }
            }
        }
        let Some((_, s, e)) = best else {
            return centre;
        };
        let m: [f64; 3] = std::array::from_fn(|k| (s[k] + e[k]) / 2.0);
        let (mx, my) = coord.translate(&(m[0], m[1], m[2]));
        let (bx, by) = coord.translate(&(s[0], s[1], s[2]));
        let (ex, ey) = coord.translate(&(e[0], e[1], e[2]));
        let (dx, dy) = ((ex - bx) as f64, (ey - by) as f64);
        // Tick labels go horizontally or vertically away from the centre, whichever is more
        // across the axis; the name goes a little further the same way.
        let horizontal = dx.abs() < dy.abs();
        if horizontal {
            let sign = if bx < centre.0 { -1 } else { 1 };
            (mx + sign * 55, my)
        } else {
            let sign = if by < centre.1 { -1 } else { 1 };
            (mx, my + sign * 38)
        }
    })
}

/// The grid lines of a net: every row `i` and every column `j`, as 3-D points.
fn net_lines(grid: &PointGrid<f64>) -> Vec<Vec<[f64; 3]>> {
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

/// A tick label on an axis spanning `span`: at most 7 significant digits, no trailing zeros,
/// and never `-0` (a tick at zero computed as −1e-17 is 0).
pub(super) fn tick_text(x: f64, span: f64) -> String {
    if !x.is_finite() {
        return String::new();
    }
    let rounded: f64 = format!("{x:.6e}").parse().unwrap_or(x);
    if rounded == 0.0 || x.abs() <= 1e-9 * span.abs() {
        return "0".into();
    }
    let a = rounded.abs();
    if (1e-4..1e7).contains(&a) {
        format!("{rounded}")
    } else {
        format!("{rounded:e}")
    }
}

/// A range with room around the data; a degenerate range is widened.
fn padded(lo: f64, hi: f64) -> (f64, f64) {
    if !lo.is_finite() || !hi.is_finite() {
        return (-1.0, 1.0);
    }
    let span = hi - lo;
    if span <= 1e-12 * (1.0 + lo.abs().max(hi.abs())) {
        let half = 0.5 * (1.0 + lo.abs() * 0.1);
        return (lo - half, hi + half);
    }
    (lo - 0.05 * span, hi + 0.05 * span)
}

/// The viridis colour map (Octave's default) at `t` in [0, 1], interpolated between five
/// of its colours.
fn viridis(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.5
    };
    let x = t * (STOPS.len() - 1) as f64;
    let k = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - k as f64;
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * f).round().clamp(0.0, 255.0) as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

fn drawing<E: std::fmt::Debug>(e: E) -> PlotError {
    PlotError::Drawing(format!("{e:?}"))
}

#[cfg(not(target_arch = "wasm32"))]
/// The font database of PNG pictures: the embedded DejaVu Sans as the sans-serif family the
/// SVG names.
#[cfg(not(target_arch = "wasm32"))]
fn fonts() -> std::sync::Arc<resvg::usvg::fontdb::Database> {
    static FONTS: std::sync::OnceLock<std::sync::Arc<resvg::usvg::fontdb::Database>> =
        std::sync::OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = resvg::usvg::fontdb::Database::new();
            db.load_font_data(FONT.to_vec());
            db.set_sans_serif_family("DejaVu Sans");
            std::sync::Arc::new(db)
        })
        .clone()
}

/// A PNG of the picture's SVG, drawn with anti-aliasing (resvg) on white: lines and text as
/// smooth as the SVG's in a browser, and the same picture.
#[cfg(not(target_arch = "wasm32"))]
fn rasterize(svg: &str, width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    use resvg::{tiny_skia, usvg};
    let options = usvg::Options {
        fontdb: fonts(),
        ..Default::default()
    };
    let tree =
        usvg::Tree::from_str(svg, &options).map_err(|e| PlotError::Drawing(e.to_string()))?;
    let mut pixmap = tiny_skia::Pixmap::new(width, height)
        .ok_or_else(|| PlotError::Drawing(format!("no {width}×{height} picture")))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    // Opaque on white: the premultiplied colours are the colours.
    let rgb: Vec<u8> = pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    encode_png(&rgb, width, height)
}

#[cfg(not(target_arch = "wasm32"))]
fn encode_png(rgb: &[u8], width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    let mut out = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut out, width, height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder
            .write_header()
            .map_err(|e| PlotError::Drawing(e.to_string()))?;
        writer
            .write_image_data(rgb)
            .map_err(|e| PlotError::Drawing(e.to_string()))?;
        writer
            .finish()
            .map_err(|e| PlotError::Drawing(e.to_string()))?;
    }
    Ok(out)
}
