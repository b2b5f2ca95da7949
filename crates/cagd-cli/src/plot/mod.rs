//! Pictures of curves and surfaces, as the thesis's Octave functions draw them.
//!
//! - `deCasteljau` draws the curve with `plot3`, its control points as red circles (`'ro'`)
//!   and its control polygon as a red line (`'r'`): [`Figure::curve`] +
//!   [`Figure::control_polygon`];
//! - `ploskevB`, `krpaCoons` and `krpaGordon` draw the patch with `surf` (filled cells coloured
//!   by height, black edges), and `krpaCoons` overlays the boundary curves, `c1`, `c2` in red
//!   and `d1`, `d2` in green with line width 2.5: [`Figure::surface`] + [`Figure::curve`]; a
//!   Bézier patch's control net is drawn with [`Figure::net`].
//!
//! Input is plain data, so any construction can be drawn: curves are `DMatrix<f64>` with one
//! point per column (d = 2 or 3), grids are `PointGrid<f64>` of shape (nu, nv, d) (the thesis's
//! `P(i,j,:)`). If every layer is planar (d = 2) the figure is a 2-D chart with equal axis
//! scales; otherwise a 3-D chart (planar layers at z = 0), seen from Octave's default view
//! direction (azimuth −37.5°, elevation 30°), with the surface drawn back to front.
//!
//! Pictures are SVG or PNG, chosen by the file extension, with a title, axes and a legend;
//! text uses the embedded DejaVu Sans font (`assets/`, Bitstream Vera licence), so PNGs
//! render the same everywhere. Files are written atomically ([`crate::write_atomic`]).
//!
//! ```
//! use cagd_cli::plot::{Colour, Figure, ImageKind};
//! use nalgebra::DMatrix;
//!
//! let control = DMatrix::from_column_slice(3, 4, &[0., 0., 0., 0., 2., 2., 8., 2., 0., 4., 0., 0.]);
//! let curve = control.clone(); // any polyline through the curve's samples
//! let svg = Figure::new("Bézier curve")
//!     .curve(curve, Colour::Blue, "curve")
//!     .control_polygon(control, "control polygon")
//!     .render(ImageKind::Svg)
//!     .unwrap();
//! assert!(String::from_utf8(svg).unwrap().starts_with("<svg"));
//! ```

/// The largest coordinate magnitude drawn. Beyond it the padded axis ranges and their ticks
/// could overflow the range of doubles; no geometry a picture can show needs more.
pub const MAX_COORDINATE: f64 = 1e100;

/// The picture formats this build draws, by file extension: SVG and PNG natively; in the
/// browser (wasm32) SVG only, since there plotters lays text out with the page's own fonts and
/// cannot draw it into pixels.
#[cfg(not(target_arch = "wasm32"))]
pub const PICTURE_EXTENSIONS: &[&str] = &["svg", "png"];
/// The picture formats this build draws, by file extension: SVG and PNG natively; in the
/// browser (wasm32) SVG only, since there plotters lays text out with the page's own fonts and
/// cannot draw it into pixels.
#[cfg(target_arch = "wasm32")]
pub const PICTURE_EXTENSIONS: &[&str] = &["svg"];

mod canvas;
mod chart_2d;
mod chart_3d;
mod layers;
mod model;
mod render;
mod text_size;

pub use model::{Colour, Figure, ImageKind, Layer};

/// What can go wrong when drawing.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    /// The file name does not end in `.svg` or `.png`.
    #[error("{path}: unknown picture format; expected a file name ending in .svg or .png")]
    UnknownExtension {
        /// The path given.
        path: String,
    },
    /// A figure without layers.
    #[error("nothing to draw")]
    Empty,
    /// A layer whose points are not 2-D or 3-D, or a grid with an empty direction.
    #[error("layer `{label}`: {message}")]
    Shape {
        /// The layer's label.
        label: String,
        /// What is wrong.
        message: String,
    },
    /// A NaN or infinite coordinate.
    #[error("layer `{label}`: coordinate {index} is not finite")]
    NonFinite {
        /// The layer's label.
        label: String,
        /// Flat index of the offending value.
        index: usize,
    },
    /// A coordinate too large to draw: above [`MAX_COORDINATE`] in magnitude, where the axis
    /// ranges and ticks of the drawing would overflow.
    #[error("layer `{label}`: coordinate {index} is {value:e}, beyond ±{MAX_COORDINATE:e}")]
    OutOfRange {
        /// The layer's label.
        label: String,
        /// Flat index of the offending value.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A picture larger than 10000×10000 or smaller than 100×100 pixels.
    #[error("picture size {width}×{height} is outside 100…10000 pixels per side")]
    Size {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// The drawing library or the PNG encoder failed.
    #[error("drawing failed: {0}")]
    Drawing(String),
    /// Writing the file failed.
    #[error("{path}: {message}")]
    Io {
        /// The path.
        path: String,
        /// The I/O error.
        message: String,
    },
}

#[cfg(test)]
mod tests;
