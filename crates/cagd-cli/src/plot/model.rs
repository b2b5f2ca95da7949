//! The picture model: a [`Drawing`] of the operation layer (what a construction shows) with a
//! size in pixels, independent of how it is drawn ([`super::render`] draws it with
//! plotters).

use std::path::Path;

use cagd::grid::PointGrid;
pub use cagd_ops::drawing::{Colour, Layer};
use cagd_ops::Drawing;
use nalgebra::DMatrix;

use super::{PlotError, MAX_COORDINATE};

/// Picture file formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageKind {
    /// Scalable vector graphics.
    Svg,
    /// Portable network graphics (8-bit RGB).
    Png,
}

impl ImageKind {
    /// The format named by the extension of `path` (case-insensitive).
    pub fn from_path(path: &Path) -> Result<ImageKind, PlotError> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("svg") => Ok(ImageKind::Svg),
            Some("png") => Ok(ImageKind::Png),
            _ => Err(PlotError::UnknownExtension {
                path: path.display().to_string(),
            }),
        }
    }
}

/// Checks a layer before it is drawn: 2-D or 3-D points, at least one, finite and within
/// [`MAX_COORDINATE`].
pub(super) fn validate(layer: &Layer) -> Result<(), PlotError> {
    let label = layer.label().to_string();
    let d = layer.dim();
    if !(2..=3).contains(&d) {
        return Err(PlotError::Shape {
            label,
            message: format!("points have {d} coordinates, expected 2 or 3"),
        });
    }
    if layer.is_empty() {
        return Err(PlotError::Shape {
            label,
            message: "no points".into(),
        });
    }
    let values = layer.values();
    if let Some(index) = values.iter().position(|x| !x.is_finite()) {
        return Err(PlotError::NonFinite { label, index });
    }
    if let Some(index) = values.iter().position(|x| x.abs() > MAX_COORDINATE) {
        return Err(PlotError::OutOfRange {
            label,
            index,
            value: values[index],
        });
    }
    Ok(())
}

/// Whether `layer` marks points it cannot draw (see [`drawable`]).
pub(super) fn has_points_too_far(layer: &Layer) -> bool {
    match layer {
        Layer::Points { points, .. } => points
            .iter()
            .any(|x| x.is_nan() || x.abs() > MAX_COORDINATE),
        _ => false,
    }
}

/// `layer` without the marked points it cannot draw (a coordinate beyond [`MAX_COORDINATE`]):
/// the answer at a parameter far outside the curve's domain (`--t 1e308`) is a number the
/// command prints, not a reason to draw no picture. The legend says how many were left out;
/// a layer with none left is dropped. Curves, polygons and surfaces are unchanged (they are
/// checked by [`validate`]).
pub(super) fn drawable(layer: &Layer) -> Option<Layer> {
    let Layer::Points {
        points,
        labels,
        label,
    } = layer
    else {
        return Some(layer.clone());
    };
    let keep: Vec<usize> = (0..points.ncols())
        .filter(|&j| points.column(j).iter().all(|x| x.abs() <= MAX_COORDINATE))
        .collect();
    if keep.len() == points.ncols() {
        return Some(layer.clone());
    }
    if keep.is_empty() {
        return None;
    }
    let left_out = points.ncols() - keep.len();
    Some(Layer::Points {
        points: points.select_columns(&keep),
        labels: if labels.len() == points.ncols() {
            keep.iter().map(|&j| labels[j].clone()).collect()
        } else {
            labels.clone()
        },
        label: format!("{label} ({left_out} beyond ±{MAX_COORDINATE:e}, not drawn)"),
    })
}

/// A picture: a [`Drawing`] (title and layers) and its size.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub(super) drawing: Drawing,
    pub(super) size: (u32, u32),
}

impl From<Drawing> for Figure {
    /// The drawing at 900×700 pixels.
    fn from(drawing: Drawing) -> Self {
        Figure {
            drawing,
            size: (900, 700),
        }
    }
}

impl Figure {
    /// An empty figure of 900×700 pixels.
    pub fn new(title: impl Into<String>) -> Self {
        Figure::from(Drawing::new(title))
    }

    /// Sets the picture size in pixels (100…10000 per side).
    pub fn with_size(mut self, width: u32, height: u32) -> Self {
        self.size = (width, height);
        self
    }

    /// Adds a layer.
    pub fn layer(mut self, layer: Layer) -> Self {
        self.drawing = self.drawing.layer(layer);
        self
    }

    /// Adds a curve (d × k points, one per column), 2 pixels wide.
    pub fn curve(mut self, points: DMatrix<f64>, colour: Colour, label: impl Into<String>) -> Self {
        self.drawing = self.drawing.curve(points, colour, label);
        self
    }

    /// Adds a boundary curve drawn 3 pixels wide (the thesis's `'LineWidth', 2.5`).
    pub fn boundary(
        mut self,
        points: DMatrix<f64>,
        colour: Colour,
        label: impl Into<String>,
    ) -> Self {
        self.drawing = self.drawing.boundary(points, colour, label);
        self
    }

    /// Adds a control polygon (red circles joined by a red line).
    pub fn control_polygon(mut self, points: DMatrix<f64>, label: impl Into<String>) -> Self {
        self.drawing = self.drawing.control_polygon(points, label);
        self
    }

    /// Adds marked points with their labels.
    pub fn points(
        mut self,
        points: DMatrix<f64>,
        labels: Vec<String>,
        label: impl Into<String>,
    ) -> Self {
        self.drawing = self.drawing.points(points, labels, label);
        self
    }

    /// Adds a surface grid (nu, nv, d) drawn like `surf`.
    pub fn surface(mut self, grid: PointGrid<f64>, label: impl Into<String>) -> Self {
        self.drawing = self.drawing.surface(grid, label);
        self
    }

    /// Adds a net (m+1, n+1, d) drawn as lines with its points.
    pub fn net(mut self, grid: PointGrid<f64>, colour: Colour, label: impl Into<String>) -> Self {
        self.drawing = self.drawing.net(grid, colour, label);
        self
    }

    /// The layers.
    pub fn layers(&self) -> &[Layer] {
        &self.drawing.layers
    }

    pub(super) fn has_legend(&self) -> bool {
        self.layers().iter().any(|l| !l.label().is_empty())
    }

    /// The height in pixels the legend takes at the top of the plotting area (0 without one):
    /// a line of about 20 pixels per label and the margins of its box.
    pub(super) fn legend_height(&self) -> f64 {
        let labels = self
            .layers()
            .iter()
            .filter(|l| !l.label().is_empty())
            .count();
        if labels == 0 {
            0.0
        } else {
            24.0 + 22.0 * labels as f64
        }
    }

    /// The width in pixels of the legend beside a graph (0 for geometry, or without a
    /// legend): a graph's axes fit its data (`t` over its domain, basis values over
    /// `[0, 1]`), so its legend stands right of the plotting area instead of taking a band
    /// of the data's range; about 8 pixels a character of the longest label, the sample line
    /// and the margins of its box.
    pub(super) fn legend_width(&self) -> u32 {
        if self.drawing.equal_scales || !self.has_legend() {
            return 0;
        }
        let longest = self
            .layers()
            .iter()
            .map(|l| l.label().chars().count())
            .max()
            .unwrap_or(0);
        (60 + 8 * longest as u32).min(300)
    }

    /// Layers in drawing order: surfaces, nets, curves, control polygons, marked points.
    pub(super) fn ordered(&self) -> Vec<&Layer> {
        self.drawing.ordered()
    }
}
