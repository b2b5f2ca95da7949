//! The fine canvas pictures are drawn on: [`SCALE`] canvas units to a pixel of the picture.
//!
//! Plotters places every point on a whole unit of its canvas (rounding down), so on a canvas
//! of the picture's own size a smooth curve becomes a staircase of points up to a pixel off
//! the curve, which shows as wobbles and kinks even when anti-aliased. The picture is drawn
//! on a canvas [`SCALE`] times its size instead, each coordinate within 1/[`SCALE`] pixel of
//! where it belongs, and the SVG maps the canvas back onto the picture (its `viewBox` the canvas, its
//! `width` and `height` the picture's). Positions, lengths, radii and font sizes are given in
//! canvas units ([`px`], [`font`]); line widths in pixels of the picture, which [`Fine`]
//! widens to canvas units for every line drawn, also plotters' own (axes, ticks, grid).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind,
};

use super::PlotError;

/// The font family of the text in pictures (the embedded DejaVu Sans, registered by
/// [`super::render`]).
pub(super) const FAMILY: &str = "sans-serif";

/// Canvas units to a pixel of the picture.
pub(super) const SCALE: u32 = 20;

/// `pixels` pixels of the picture in canvas units.
pub(super) const fn px(pixels: i32) -> i32 {
    pixels * SCALE as i32
}

/// The picture's font at `size` pixels of the picture.
pub(super) fn font(size: f64) -> (&'static str, f64) {
    (FAMILY, size * f64::from(SCALE))
}

/// The SVG of a picture of `w × h` pixels drawn on the canvas ([`SCALE`] times as large):
/// plotters' SVG with the picture's size as its width and height, the canvas as its viewBox.
pub(super) fn picture_size(svg: String, (w, h): (u32, u32)) -> Option<String> {
    let (cw, ch) = (w * SCALE, h * SCALE);
    let canvas = format!("<svg width=\"{cw}\" height=\"{ch}\" viewBox=\"0 0 {cw} {ch}\"");
    let rest = svg.strip_prefix(&canvas)?;
    Some(format!(
        "<svg width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {cw} {ch}\"{rest}"
    ))
}

/// Draws `title` at the top of `root`, centred between the margins `left` and `right`, and
/// returns the area below it: the title 5 pixels below the top margin of 20, the area 5 pixels
/// below the title. (Plotters' own caption keeps 5 canvas units, half a pixel here, which would
/// crowd the title against the chart.)
pub(super) fn titled<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    (left, right): (i32, i32),
) -> Result<DrawingArea<DB, Shift>, PlotError> {
    let style = font(24.0)
        .into_text_style(root)
        .pos(Pos::new(HPos::Center, VPos::Top));
    let drawing = |e: DrawingAreaErrorKind<DB::ErrorType>| PlotError::Drawing(format!("{e:?}"));
    let (_, text_h) = root.estimate_text_size(title, &style).map_err(drawing)?;
    let (w, _) = root.dim_in_pixel();
    let x = left + (w as i32 - left - right) / 2;
    root.draw_text(title, &style, (x, px(25)))
        .map_err(drawing)?;
    Ok(root.margin(px(30) + text_h as i32, 0, 0, 0))
}

/// A backend whose lines are [`SCALE`] times as wide as their styles say: line widths are
/// pixels of the picture, the canvas's units [`SCALE`] to a pixel.
pub(super) struct Fine<DB>(pub(super) DB);

/// A style with its line width in canvas units.
struct Wide<'s, S>(&'s S);

impl<S: BackendStyle> BackendStyle for Wide<'_, S> {
    fn color(&self) -> BackendColor {
        self.0.color()
    }

    fn stroke_width(&self) -> u32 {
        self.0.stroke_width() * SCALE
    }
}

type Drawn<DB> = Result<(), DrawingErrorKind<<DB as DrawingBackend>::ErrorType>>;

impl<DB: DrawingBackend> DrawingBackend for Fine<DB> {
    type ErrorType = DB::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }

    fn ensure_prepared(&mut self) -> Drawn<DB> {
        self.0.ensure_prepared()
    }

    fn present(&mut self) -> Drawn<DB> {
        self.0.present()
    }

    fn draw_pixel(&mut self, point: BackendCoord, color: BackendColor) -> Drawn<DB> {
        self.0.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Drawn<DB> {
        self.0.draw_line(from, to, &Wide(style))
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Drawn<DB> {
        if fill {
            return self.0.draw_rect(upper_left, bottom_right, style, true);
        }
        // An outline as a closed line: plotters' SVG writes a rectangle's outline without
        // its width.
        let ((x0, y0), (x1, y1)) = (upper_left, bottom_right);
        let ring = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)];
        self.0.draw_path(ring, &Wide(style))
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Drawn<DB> {
        self.0.draw_path(path, &Wide(style))
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Drawn<DB> {
        self.0.draw_circle(center, radius, &Wide(style), fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Drawn<DB> {
        self.0.fill_polygon(vert, style)
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Drawn<DB> {
        self.0.draw_text(text, style, pos)
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
        // In WebAssembly plotters would measure with the page's DOM (super::text_size).
        #[cfg(target_arch = "wasm32")]
        {
            Ok(super::text_size::from_table(style.size(), text))
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.0.estimate_text_size(text, style)
        }
    }

    fn blit_bitmap(&mut self, pos: BackendCoord, size: (u32, u32), src: &[u8]) -> Drawn<DB> {
        self.0.blit_bitmap(pos, size, src)
    }
}
