//! The functions of the Octave package `cagd` (`pkg load cagd`), in safe Rust.
//!
//! The package (sources in `octave_pkg/`) is a set of `.m` files, each documented with an
//! Octave docstring and tested with `%!test` blocks, that call one oct-file, `__cagd__`. The
//! oct-file is a thin C++ gateway: it turns Octave's arguments into [`Value`]s (borrowing
//! Octave's arrays), calls [`call`] through the C ABI of `cagd-octave-ffi` (the only crate of
//! the package with `unsafe` code), and raises the error or returns the results. Everything
//! else — checking every argument, the limits, the mathematics (the core `cagd` and the
//! Octave layer `cagd-octave`), the layouts — is here, with no `unsafe`.
//!
//! # Functions
//! - the thesis functions, fixed ([`thesis`]): `deCasteljau`, `ploskevB`, `bilinearna`,
//!   `tenzor`, `krpaCoons`, `vrednostCoons`, `krpaGordon`, `Lagrange`, with the arguments and
//!   results of `octave_ref/fixed/`;
//! - octave-nurbs' twins ([`nurbs`]): `cagd_nrbeval`, `cagd_bspeval`, `cagd_basisfun`,
//!   `cagd_findspan`, `cagd_basisfunder`, `cagd_bspderiv`, `cagd_bspkntins`, `cagd_bspdegelev`,
//!   `cagd_nrbkntins`, `cagd_nrbdegelev`, `cagd_nrbderiv`, `cagd_nrbdeval`, `cagd_nrbcoons`,
//!   with the arguments, results and errors of octave-nurbs' functions of those names;
//! - native functions ([`native`]): Bézier curves with derivatives, subdivision and
//!   elevation, Bézier patches, Coons and Gordon patches with their parts, ruled surfaces,
//!   B-splines, NURBS, interpolating splines, Hermite cubics, the cubic conversions, Bernstein
//!   values — exact
//!   with the option `"exact"` ([`number`]);
//! - `cagd_limits`: the resource limits of the session ([`limits`]).
//!
//! # Layouts
//! Points are columns: a curve's control points are `d × (n+1)`, its values `d × k`. Native
//! surfaces take nets `d × (m+1) × (n+1)` and return grids `d × nu × nv` (`X(:, i, j)` is the
//! point at `(u(i), v(j))`), octave-nurbs' layout. The thesis functions keep theirs (packed
//! nets `(m+1) × 3(n+1)`, grids `N × N × 3`).
//!
//! # Errors
//! Every refusal is an Octave error with an identifier `cagd:<kind>` ([`Kind`]) and a
//! one-line message `FUNCTION: …`: the library's own text for a library error (the text the
//! command line prints for it), `ARGUMENT: PROBLEM; expected FORM` for the package's own checks.
//! Wrong classes (integer, logical, single, complex, sparse, cell, struct, …), empty arrays,
//! NaN and ±Inf, and sizes over the limits are refused before anything is computed.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod args;
pub mod error;
mod functions;
pub mod limits;
pub mod native;
pub mod number;
pub mod nurbs;
pub mod ops;
pub mod thesis;
pub mod value;

pub use error::{Kind, PkgError, Result};
pub use functions::{call, call_interruptible, FUNCTIONS};
pub use value::{Output, Real, Sink, Value, VecSink};
