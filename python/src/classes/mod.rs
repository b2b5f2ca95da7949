//! The Pythonic classes of the course, points as rows: each holds the core's object in doubles
//! or in exact rationals ([`shared::Ex`]) and each method is a small translation — arrays in
//! ([`crate::convert`]), the operation layer's request or checks ([`crate::ops`]), arrays or
//! `cagd.CagdError` out. Constructors build their object as the operation layer's requests
//! build it (the same checks and words); methods that are requests (`derivative`, `elevate`,
//! `subdivide`, `insert_knots`, `bernstein`, `discrete_coons`) run them, and an object they
//! make keeps the way to the request's steps (`obj.steps`, [`steps::StepsOf`], computed when
//! asked for and shown with the object in Jupyter); evaluation of a kept
//! object (`obj(t)`, `surface(u, v)`) checks its parameters by the operation layer and calls
//! the core's batch evaluation, writing straight into the array returned.
//!
//! - [`bezier`]: `BezierCurve`; [`bezier_patch`]: `BezierPatch`;
//! - [`splines`]: `BSplineCurve`, `BSplineSurface`, `NurbsCurve`, `NurbsSurface`;
//! - [`interp`]: `HermiteCubic`, `CubicSpline`, `Lagrange`;
//! - [`patches`]: `CoonsPatch`, `GordonSurface`, `discrete_coons`;
//! - [`tools`]: Bernstein polynomials, matrix forms and conversions, continuity;
//! - [`steps`]: the `Steps` view of a construction.

pub mod bezier;
pub mod bezier_patch;
pub mod interp;
pub mod patches;
pub mod shared;
pub mod splines;
pub mod steps;
pub mod tools;

use pyo3::prelude::*;

/// Registers every class and function.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    bezier::register(m)?;
    bezier_patch::register(m)?;
    splines::register(m)?;
    interp::register(m)?;
    patches::register(m)?;
    tools::register(m)?;
    steps::register(m)?;
    Ok(())
}
