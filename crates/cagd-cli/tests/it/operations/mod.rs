//! The operation layer's own tests (`cagd-ops`), through its public API: knot vectors and
//! parameters ([`knots`]), pictures' polylines ([`picture`]) and requests of several
//! operations, their results and refusals.
//!
//! They are here, in the command line's test binary, rather than in one of `cagd-ops`' own:
//! the command line's library already compiles every request in both arithmetics, and a test
//! build shares those compiled generics with this binary, so these tests add about a second
//! of compile work here against 8 s in a binary of their own (and 14 s as unit tests, which
//! compiled the library a second time). `cagd-ops` keeps its doctests.

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
