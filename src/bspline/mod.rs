//! B-splines (the CAD notes §1.2 and the lecture notes, "B-spline křivky"): knot vectors with multiplicities,
//! the Cox–de Boor basis, curves (de Boor evaluation, derivatives, knot insertion, degree
//! elevation, the uniform
//! cubic "Coons" B-spline of the lecture notes) and tensor-product surfaces; for scipy's
//! `BSpline` also derivatives of any order, the definite integral over any interval, the
//! value outside the domain ([`Extrapolation`]), the design matrix and the single basis element.
//!
//! Conventions follow octave-nurbs, the reference these are tested against: degree `p`
//! (the lecture notes' order `k = p + 1`), `n` control points, `n + p + 1` knots, domain
//! `[u_p, u_n]`, spans numbered from 0. Everything is generic over [`Scalar`](crate::Scalar):
//! evaluation, derivatives and knot insertion are rational, so they run exactly in
//! `BigRational` too.

mod basis;
mod batch;
mod boehm_scheme;
pub(crate) mod compatible;
mod curve;
mod de_boor_scheme;
mod definite_integral;
mod derivatives;
mod design_matrix;
mod elevate;
mod extrapolate;
mod grid;
mod knots;
mod surface;
mod surface_refine;
mod triangle;

pub use basis::{
    basis_all, basis_cost, basis_functions, basis_functions_into, cox_de_boor, curve_point_cost,
    find_span, tensor_point_cost,
};
pub use boehm_scheme::BoehmStep;
pub use compatible::make_compatible;
pub use curve::BSplineCurve;
pub use de_boor_scheme::DeBoorScheme;
pub use design_matrix::{design_matrix, DesignMatrix};
pub use extrapolate::{wrap_periodic, Extrapolation};
pub use knots::KnotVector;
pub use surface::BSplineSurface;
pub use triangle::{cox_de_boor_triangle, triangle_cost, try_cox_de_boor_triangle};

pub(crate) use basis::check_in_domain;
pub(crate) use batch::curve_points_fast_into;
pub(crate) use grid::curve_points_into;
pub(crate) use surface::nan_point;
