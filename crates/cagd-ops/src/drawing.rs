//! What a construction's picture shows, independent of how it is drawn: the command line
//! renders a [`Drawing`] with plotters (SVG, PNG), the page in the browser.
//!
//! The operation decides what is drawn (the curve, its control polygon, the evaluated points
//! with their labels, a surface and its boundary curves), so that every front end shows the
//! same answer.

use cagd::grid::PointGrid;
use nalgebra::DMatrix;

/// Colours of lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Colour {
    /// Curves (Octave's default line colour).
    Blue,
    /// Control points and polygons; `c1`, `c2` of a Coons patch.
    Red,
    /// `d1`, `d2` of a Coons patch.
    Green,
    /// Nets and edges; the evaluated points.
    Black,
    /// Extra curves.
    Orange,
    /// Extra curves.
    Purple,
}

/// One thing drawn.
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
    /// Points marked one by one (the answer at the parameters asked for), each with its
    /// label where there are few (`t = 1/2`).
    Points {
        /// The points (d × k).
        points: DMatrix<f64>,
        /// One label per point, or none.
        labels: Vec<String>,
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

/// The most evaluated points labelled one by one in a picture.
pub const MAX_POINT_LABELS: usize = 12;

impl Layer {
    /// The legend text.
    pub fn label(&self) -> &str {
        match self {
            Layer::Curve { label, .. }
            | Layer::ControlPolygon { label, .. }
            | Layer::Points { label, .. }
            | Layer::Surface { label, .. }
            | Layer::Net { label, .. } => label,
        }
    }

    /// The dimension of the points.
    pub fn dim(&self) -> usize {
        match self {
            Layer::Curve { points, .. }
            | Layer::ControlPolygon { points, .. }
            | Layer::Points { points, .. } => points.nrows(),
            Layer::Surface { grid, .. } | Layer::Net { grid, .. } => grid.dim().2,
        }
    }

    /// Every coordinate, in order (for checks before drawing).
    pub fn values(&self) -> Vec<f64> {
        match self {
            Layer::Curve { points, .. }
            | Layer::ControlPolygon { points, .. }
            | Layer::Points { points, .. } => points.iter().copied().collect(),
            Layer::Surface { grid, .. } | Layer::Net { grid, .. } => grid.iter().copied().collect(),
        }
    }

    /// Whether the layer has no point.
    pub fn is_empty(&self) -> bool {
        match self {
            Layer::Curve { points, .. }
            | Layer::ControlPolygon { points, .. }
            | Layer::Points { points, .. } => points.ncols() == 0,
            Layer::Surface { grid, .. } | Layer::Net { grid, .. } => {
                grid.dim().0 == 0 || grid.dim().1 == 0
            }
        }
    }

    /// Every point, padded to 3-D with z = 0.
    pub fn points(&self) -> Vec<[f64; 3]> {
        let pad = |p: &[f64]| [p[0], p[1], if p.len() > 2 { p[2] } else { 0.0 }];
        match self {
            Layer::Curve { points, .. }
            | Layer::ControlPolygon { points, .. }
            | Layer::Points { points, .. } => {
                points.column_iter().map(|c| pad(c.as_slice())).collect()
            }
            Layer::Surface { grid, .. } | Layer::Net { grid, .. } => {
                let (nu, nv, d) = grid.dim();
                let mut out = Vec::with_capacity(nu * nv);
                for i in 0..nu {
                    for j in 0..nv {
                        let p: Vec<f64> = (0..d).map(|k| grid[[i, j, k]]).collect();
                        out.push(pad(&p));
                    }
                }
                out
            }
        }
    }
}

/// A picture: a title, the names of its axes, and layers (drawn surfaces first, then nets,
/// curves, control polygons and marked points on top).
#[derive(Debug, Clone, PartialEq)]
pub struct Drawing {
    /// The title.
    pub title: String,
    /// The layers, in the order added.
    pub layers: Vec<Layer>,
    /// What the axes show (`x`, `y`, `z` for points; `t` and `N_i,p(t)` for functions).
    pub axes: [String; 3],
    /// Equal scales on all axes (geometry, so shapes are not distorted), or each axis fitted
    /// to its data (graphs of functions).
    pub equal_scales: bool,
}

impl Drawing {
    /// An empty drawing of points in space (axes `x`, `y`, `z`, equal scales).
    pub fn new(title: impl Into<String>) -> Self {
        Drawing {
            title: title.into(),
            layers: Vec::new(),
            axes: ["x".into(), "y".into(), "z".into()],
            equal_scales: true,
        }
    }

    /// A graph of functions: the horizontal axis `x_name`, the vertical `y_name`, each fitted
    /// to the data.
    pub fn graph(title: impl Into<String>, x_name: &str, y_name: &str) -> Self {
        Drawing {
            axes: [x_name.into(), y_name.into(), String::new()],
            equal_scales: false,
            ..Drawing::new(title)
        }
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

    /// Adds the answer's points as markers; with at most [`MAX_POINT_LABELS`] of them each is
    /// labelled (`labels`, e.g. `t = 1/2`).
    pub fn points(
        self,
        points: DMatrix<f64>,
        labels: Vec<String>,
        label: impl Into<String>,
    ) -> Self {
        let labels = if labels.len() <= MAX_POINT_LABELS {
            labels
        } else {
            Vec::new()
        };
        self.layer(Layer::Points {
            points,
            labels,
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

    /// Layers in drawing order: surfaces, nets, curves, control polygons, marked points.
    pub fn ordered(&self) -> Vec<&Layer> {
        let rank = |l: &Layer| match l {
            Layer::Surface { .. } => 0,
            Layer::Net { .. } => 1,
            Layer::Curve { .. } => 2,
            Layer::ControlPolygon { .. } => 3,
            Layer::Points { .. } => 4,
        };
        let mut v: Vec<&Layer> = self.layers.iter().collect();
        v.sort_by_key(|l| rank(l));
        v
    }
}
