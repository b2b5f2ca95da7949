//! The picture model: what a figure holds (title, layers, size), independent of how it is
//! drawn ([`super::render`] draws it with plotters).

use std::path::Path;

use cagd::grid::PointGrid;
use nalgebra::DMatrix;

use super::{PlotError, MAX_COORDINATE};

/// Colours of lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Colour {
    /// Curves (Octave's default line colour).
    Blue,
    /// Control points and polygons; `c1`, `c2` of a Coons patch.
    Red,
    /// `d1`, `d2` of a Coons patch.
    Green,
    /// Nets and edges.
    Black,
    /// Extra curves.
    Orange,
    /// Extra curves.
    Purple,
}

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

/// One thing drawn in a figure.
#[derive(Debug, Clone, PartialEq)]
pub enum Layer {
    /// A line through the points (d × k, one point per column).
    Curve {
        /// The points.
        points: DMatrix<f64>,
        /// Line colour.
        colour: Colour,
        /// Line width in pixels.
        width: u32,
        /// Legend text.
        label: String,
    },
    /// A control polygon: red circles at the points joined by a red line.
    ControlPolygon {
        /// The control points (d × (n+1)).
        points: DMatrix<f64>,
        /// Legend text.
        label: String,
    },
    /// A surface drawn like Octave's `surf`: filled cells coloured by height, black edges.
    Surface {
        /// The grid (nu, nv, d).
        grid: PointGrid<f64>,
        /// Legend text.
        label: String,
    },
    /// A wire net (lines along both grid directions), e.g. a control net, with its points.
    Net {
        /// The net (m+1, n+1, d).
        grid: PointGrid<f64>,
        /// Line colour.
        colour: Colour,
        /// Legend text.
        label: String,
    },
}

impl Layer {
    pub(super) fn label(&self) -> &str {
        match self {
            Layer::Curve { label, .. }
            | Layer::ControlPolygon { label, .. }
            | Layer::Surface { label, .. }
            | Layer::Net { label, .. } => label,
        }
    }

    /// Dimension of the points.
    pub(super) fn dim(&self) -> usize {
        match self {
            Layer::Curve { points, .. } | Layer::ControlPolygon { points, .. } => points.nrows(),
            Layer::Surface { grid, .. } | Layer::Net { grid, .. } => grid.dim().2,
        }
    }

    /// Every point, padded to 3-D with z = 0.
    pub(super) fn points(&self) -> Vec<[f64; 3]> {
        let pad = |p: &[f64]| [p[0], p[1], if p.len() > 2 { p[2] } else { 0.0 }];
        match self {
            Layer::Curve { points, .. } | Layer::ControlPolygon { points, .. } => {
                points.column_iter().map(|c| pad(c.as_slice())).collect()
            }
            Layer::Surface { grid, .. } | Layer::Net { grid, .. } => {
                let (nu, nv, _) = grid.dim();
                let mut out = Vec::with_capacity(nu * nv);
                for i in 0..nu {
                    for j in 0..nv {
                        let p: Vec<f64> = (0..grid.dim().2).map(|k| grid[[i, j, k]]).collect();
                        out.push(pad(&p));
                    }
                }
                out
            }
        }
    }

    pub(super) fn validate(&self) -> Result<(), PlotError> {
        let label = self.label().to_string();
        let d = self.dim();
        if !(2..=3).contains(&d) {
            return Err(PlotError::Shape {
                label,
                message: format!("points have {d} coordinates, expected 2 or 3"),
            });
        }
        let (values, empty): (Vec<f64>, bool) = match self {
            Layer::Curve { points, .. } | Layer::ControlPolygon { points, .. } => {
                (points.iter().copied().collect(), points.ncols() == 0)
            }
            Layer::Surface { grid, .. } | Layer::Net { grid, .. } => (
                grid.iter().copied().collect(),
                grid.dim().0 == 0 || grid.dim().1 == 0,
            ),
        };
        if empty {
            return Err(PlotError::Shape {
                label,
                message: "no points".into(),
            });
        }
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
}

/// A picture: a title and layers, drawn in order (surfaces first, then nets, curves and
/// control polygons on top).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub(super) title: String,
    pub(super) layers: Vec<Layer>,
    pub(super) size: (u32, u32),
}

impl Figure {
    /// An empty figure of 900×700 pixels.
    pub fn new(title: impl Into<String>) -> Self {
        Figure {
            title: title.into(),
            layers: Vec::new(),
            size: (900, 700),
        }
    }

    /// Sets the picture size in pixels (100…10000 per side).
    pub fn with_size(mut self, width: u32, height: u32) -> Self {
        self.size = (width, height);
        self
    }

    /// Adds a layer.
    pub fn layer(mut self, layer: Layer) -> Self {
        self.layers.push(layer);
        self
    }

    /// Adds a curve (d × k points, one per column), 2 pixels wide.
    pub fn curve(self, points: DMatrix<f64>, colour: Colour, label: impl Into<String>) -> Self {
        self.layer(Layer::Curve {
            points,
            colour,
            width: 2,
            label: label.into(),
        })
    }

    /// Adds a boundary curve drawn 3 pixels wide (the thesis's `'LineWidth', 2.5`).
    pub fn boundary(self, points: DMatrix<f64>, colour: Colour, label: impl Into<String>) -> Self {
        self.layer(Layer::Curve {
            points,
            colour,
            width: 3,
            label: label.into(),
        })
    }

    /// Adds a control polygon (red circles joined by a red line).
    pub fn control_polygon(self, points: DMatrix<f64>, label: impl Into<String>) -> Self {
        self.layer(Layer::ControlPolygon {
            points,
            label: label.into(),
        })
    }

    /// Adds a surface grid (nu, nv, d) drawn like `surf`.
    pub fn surface(self, grid: PointGrid<f64>, label: impl Into<String>) -> Self {
        self.layer(Layer::Surface {
            grid,
            label: label.into(),
        })
    }

    /// Adds a net (m+1, n+1, d) drawn as lines with its points.
    pub fn net(self, grid: PointGrid<f64>, colour: Colour, label: impl Into<String>) -> Self {
        self.layer(Layer::Net {
            grid,
            colour,
            label: label.into(),
        })
    }

    /// The layers.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    pub(super) fn has_legend(&self) -> bool {
        self.layers.iter().any(|l| !l.label().is_empty())
    }

    /// The height in pixels the legend takes at the top of the plotting area (0 without one):
    /// a line of about 20 pixels per label and the margins of its box.
    pub(super) fn legend_height(&self) -> f64 {
        let labels = self.layers.iter().filter(|l| !l.label().is_empty()).count();
        if labels == 0 {
            0.0
        } else {
            24.0 + 22.0 * labels as f64
        }
    }

    /// Layers in drawing order: surfaces, nets, curves, control polygons.
    pub(super) fn ordered(&self) -> Vec<&Layer> {
        let rank = |l: &Layer| match l {
            Layer::Surface { .. } => 0,
            Layer::Net { .. } => 1,
            Layer::Curve { .. } => 2,
            Layer::ControlPolygon { .. } => 3,
        };
        let mut v: Vec<&Layer> = self.layers.iter().collect();
        v.sort_by_key(|l| rank(l));
        v
    }
}
