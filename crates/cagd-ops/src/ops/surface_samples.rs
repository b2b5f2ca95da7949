//! `surface`: a surface known only by evaluation — a user's expression in `u` and `v`
//! (`[u; v; u.*v]`) — sampled on a grid: `x(u_i, v_j)`. The front end evaluates the
//! expression ([`SurfaceEvaluator`]); the request decides where, prices the samples before any
//! is taken and lays out the answer.
//!
//! ```
//! use cagd::grid::PointGrid;
//! use cagd_ops::curves::Work;
//! use cagd_ops::ops::{SurfaceEvaluator, SurfaceSamples};
//! use cagd_ops::{execute, ops::surface::SurfaceParams, Context, Params};
//! struct Saddle;
//! impl SurfaceEvaluator<f64> for Saddle {
//!     fn grid(&self, us: &[f64], vs: &[f64]) -> cagd_ops::Result<PointGrid<f64>> {
//!         Ok(PointGrid::from_shape_fn((us.len(), vs.len(), 3), |(i, j, c)| {
//!             [us[i], vs[j], us[i] * vs[j]][c]
//!         }))
//!     }
//!     fn work(&self, us: &[f64], vs: &[f64]) -> Work {
//!         Work { operations: (us.len() * vs.len()) as u128, what: "samples" }
//!     }
//! }
//! let at = SurfaceParams { u: Params::Samples(2), v: Params::Samples(3), list: false };
//! let op = SurfaceSamples { at, ..SurfaceSamples::new(Box::new(Saddle), "[u; v; u.*v]") };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! let Some(cagd_ops::Value::Grid(g)) = answer.report.get("result") else { panic!() };
//! assert_eq!(g.dim(), (2, 3, 3));
//! assert_eq!(g[[1, 2, 2]], 1.0);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::grid::PointGrid;
use cagd::Scalar;

use super::curve_samples::SAMPLES_FORM;
use super::surface::{grid_f64, push_surface, SurfaceParams};
use crate::curves::Work;
use crate::drawing::Drawing;
use crate::error::{lib, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// A function of two parameters known only by evaluation (an expression typed by the user):
/// the front end evaluates it; the construction decides where.
pub trait SurfaceEvaluator<T: Scalar> {
    /// The values on the grid `us × vs`, shape `(nu, nv, d)`.
    ///
    /// # Errors
    /// What went wrong in the evaluation (about [`Role::Result`]; the construction names
    /// the argument).
    fn grid(&self, us: &[T], vs: &[T]) -> Result<PointGrid<T>>;

    /// The work of evaluating on all of `us × vs`, estimated or measured before any of it.
    fn work(&self, us: &[T], vs: &[T]) -> Work;
}

/// A surface known by evaluation, sampled on a grid; the surface is about [`Role::Control`].
pub struct SurfaceSamples<T: Scalar> {
    /// The surface.
    pub surface: Box<dyn SurfaceEvaluator<T>>,
    /// How the surface reads (its expression), for the picture.
    pub name: String,
    /// Where: `u`, `v` (given anywhere, or samples of `[0, 1]`), the `list` layout.
    pub at: SurfaceParams<T>,
    /// A picture: the surface.
    pub drawing: bool,
    /// The grid for a mesh.
    pub mesh: bool,
}

impl<T: Scalar> std::fmt::Debug for SurfaceSamples<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SurfaceSamples")
            .field("name", &self.name)
            .field("at", &self.at)
            .field("drawing", &self.drawing)
            .field("mesh", &self.mesh)
            .finish()
    }
}

impl<T: Scalar> SurfaceSamples<T> {
    /// `surface`, reading `name`, on the default grid.
    pub fn new(surface: Box<dyn SurfaceEvaluator<T>>, name: &str) -> Self {
        SurfaceSamples {
            surface,
            name: name.to_string(),
            at: SurfaceParams::default(),
            drawing: false,
            mesh: false,
        }
    }
}

impl<T: Scalar> Operation<T> for SurfaceSamples<T> {
    /// `u`, `v` (`1 × k`) and `result`, the grid `nu × nv × d` (`result(i,j,:)` at
    /// `(u(i), v(j))`), or with `list` one row `u v x y z` per point.
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let unit = (&T::zero(), &T::one());
        let us = self.at.u.anywhere(Role::U, unit, cx)?;
        let vs = self.at.v.anywhere(Role::V, unit, cx)?;
        cx.check_grid(Role::Grid, us.len(), vs.len())?;
        let work = self.surface.work(&us, &vs);
        cx.limits
            .check_work(work.what, work.operations)
            .map_err(lib(Role::Control, SAMPLES_FORM))?;
        cx.check_interrupt()?;
        let grid = self
            .surface
            .grid(&us, &vs)
            .map_err(|e| e.about(Role::Control))?;
        let mut report = Report::new();
        report.push("u", Value::row(&us));
        report.push("v", Value::row(&vs));
        let shown = (self.drawing || self.mesh).then(|| grid_f64(&grid));
        push_surface(&mut report, "result", (&us, &vs), grid, self.at.list);
        let drawing = match (&shown, self.drawing) {
            (Some(g), true) => Some(
                Drawing::new(format!("surface {}", self.name.trim())).surface(g.clone(), "surface"),
            ),
            _ => None,
        };
        Ok(Answer {
            report,
            drawing,
            mesh: if self.mesh { shown } else { None },
        })
    }
}
