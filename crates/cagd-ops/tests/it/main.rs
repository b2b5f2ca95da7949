//! The operation layer's own tests, one binary, through its public API: knot vectors and
//! parameters ([`knots`]), pictures' polylines ([`picture`]) and requests of several
//! operations, their results and refusals. The library itself has no unit tests
//! (`[lib] test = false`): this binary links it instead of compiling it a second time in test
//! mode; the doctests stay with the items they document.

mod bernstein;
mod bezier_patch;
mod continuity;
mod convert;
mod derivative;
mod elevate;
mod integrate;
mod knots;
mod picture;
mod subdivide;
