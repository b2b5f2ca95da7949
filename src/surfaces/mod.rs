//! The classic surfaces of the lecture notes ("Parametrické plochy"): the ruled (cylindrical) surface
//! between two curves, the Hermite bicubic (Ferguson) patch with twist vectors, and cubic
//! patches in matrix form `vᵀ Mᵀ X M u` (Hermite, Bézier, uniform B-spline). B-spline and
//! NURBS surfaces are [`crate::bspline::BSplineSurface`] and [`crate::nurbs::NurbsSurface`].

mod ferguson;
mod matrix_patch;
mod ruled;

pub use ferguson::{ferguson_point_cost, FergusonPatch};
pub use matrix_patch::CubicMatrixPatch;
pub use ruled::{ruled_point_cost, RuledSurface};
