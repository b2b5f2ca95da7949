//! `nurbs-surface`: a tensor-product NURBS surface (the CAD notes §1.3),
//!
//! `S(u, v) = Σ_i Σ_j w_{ij} P_{ij} N_{i,p}(u) N_{j,q}(v) / Σ_i Σ_j w_{ij} N_{i,p}(u) N_{j,q}(v)`:
//! the B-spline surface of the homogeneous points `(w P, w)` projected onto `w = 1`. Arguments
//! as [`BSplineSurface`], with one positive weight per control point.

use cagd::nurbs::NurbsSurface as Surface;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::bspline_surface::{answer, BSplineSurface, Evaluated, NET_FORM};
use super::nurbs::WEIGHTS_FORM;
use super::surface::grid_f64;
use crate::error::{OpError, Result};
use crate::{Answer, Context, Operation, Role};

/// A NURBS surface.
///
/// ```
/// use cagd_ops::ops::{BSplineSurface, NurbsSurface};
/// use cagd_ops::knots::Degree;
/// use cagd_ops::{Context, Operation, Params};
/// use cagd::grid::PointGrid;
/// use nalgebra::DMatrix;
/// // z = 0, 1, 1, 3 with the weight 3 on the last: S(½, ½) = (0 + 1 + 1 + 9)/6.
/// let mut spline = BSplineSurface::new(PointGrid::from_vec((2, 2, 1), vec![0.0, 1.0, 1.0, 3.0]).unwrap());
/// spline.degrees = [Degree::Degree(1); 2];
/// spline.at.u = Params::Given(vec![0.5]);
/// spline.at.v = Params::Given(vec![0.5]);
/// let op = NurbsSurface { spline, weights: DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 3.0]) };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap()[0], 11.0 / 6.0);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSurface<T> {
    /// The control net, degrees, knots, parameters and outputs, as a B-spline surface's.
    pub spline: BSplineSurface<T>,
    /// The weights, `nu × nv`, one per control point, positive.
    pub weights: DMatrix<T>,
}

impl<T: Scalar> NurbsSurface<T> {
    /// The surface: the degrees resolved, the knots of both directions checked (or clamped),
    /// the weights and the net built (a front end that keeps the surface builds it here).
    ///
    /// # Errors
    /// The rules of [`crate::knots`]; [`crate::Kind::Weights`] and the library's errors about
    /// the weights; the library's errors about the net.
    pub fn surface(&self, cx: &Context) -> Result<Surface<T>> {
        let ((p, q), [ku, kv]) = self.spline.knots(cx)?;
        let coords = self.spline.coordinates();
        Surface::new(p, q, ku, kv, coords, self.weights.clone()).map_err(|e| match &e {
            cagd::Error::NonPositiveWeight { .. }
            | cagd::Error::ShapeMismatch {
                what: "NURBS surface weights",
                ..
            }
            | cagd::Error::NonFinite {
                what: "NURBS surface weights",
                ..
            } => OpError::library(Role::Weights, e, WEIGHTS_FORM),
            _ => OpError::library(Role::Net, e, NET_FORM),
        })
    }
}

impl<T: Scalar> Operation<T> for NurbsSurface<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let surface = self.surface(cx)?;
        let (ku, kv) = surface.homogeneous().knots();
        let evaluated = Evaluated {
            surface: &surface,
            cost: &|bu, bv| surface.point_cost(bu, bv),
            degrees: surface.homogeneous().degrees(),
            knots: [ku.as_slice(), kv.as_slice()],
            title: "NURBS surface",
        };
        // The control net drawn as given: the points, not the homogeneous ones.
        answer(&self.spline, evaluated, grid_f64(&self.spline.net), cx)
    }
}
