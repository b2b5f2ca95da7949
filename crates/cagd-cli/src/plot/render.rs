//! Drawing a [`Figure`] with plotters into SVG or PNG: the fine canvas
//! ([`super::canvas`]), the choice between the 2-D and 3-D charts, the colour map, the tick
//! labels, the embedded font.

use std::path::Path;
use std::sync::Once;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{picture_size, Fine, SCALE};
use super::model::{drawable, has_points_too_far, validate, Colour, Figure, ImageKind};
use super::PlotError;

/// The font embedded for text in pictures.
#[cfg(not(target_arch = "wasm32"))]
static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
static REGISTER_FONT: Once = Once::new();

#[cfg(test)]
pub(super) fn register_font_for_tests() {
    register_font();
}

fn register_font() {
    REGISTER_FONT.call_once(|| {
        // The embedded font is a valid TrueType file; should registration ever fail, text is
        // simply not drawn. (In the browser the page's fonts draw the text, and its size comes
        // from the font's advances: super::text_size.)
        #[cfg(not(target_arch = "wasm32"))]
        let _ = plotters::style::register_font(super::canvas::FAMILY, FontStyle::Normal, FONT);
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
        // Marked points too far to draw are left out (and the legend says so).
        // (Asked of the layers themselves, not by comparing them: a NaN never equals itself.)
        if self.layers().iter().any(has_points_too_far) {
            let mut shown = self.clone();
            shown.drawing.layers = self.layers().iter().filter_map(drawable).collect();
            if shown.drawing.layers.is_empty() {
                return Err(PlotError::Empty);
            }
            return shown.render(kind);
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
                    let canvas = SVGBackend::with_string(&mut svg, (w * SCALE, h * SCALE));
                    let root = Fine(canvas).into_drawing_area();
                    self.draw(&root)?;
                    root.present().map_err(drawing)?;
                }
                let svg = picture_size(svg, (w, h))
                    .ok_or_else(|| PlotError::Drawing("an SVG without its size".into()))?;
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

    /// The ranges of x, y and z over all layers, padded.
    pub(super) fn bounds(&self) -> [(f64, f64); 3] {
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
pub(super) fn viridis(t: f64) -> RGBColor {
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

pub(super) fn drawing<E: std::fmt::Debug>(e: E) -> PlotError {
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
