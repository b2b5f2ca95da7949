//! # cagd — curves and surfaces for computer-aided geometric design
//!
//! A faithful, bug-fixed reimplementation of the GNU Octave code of the thesis
//! *Bézierove in Gordon-Coons krpe* (I. Čavdek, Koper 2014), proven number by number against
//! GNU Octave, and grown into a small CAGD toolkit.
//!
//! This crate is the mathematics only: [`bernstein`], [`bezier::BezierCurve`],
//! [`bezier::BezierPatch`], the Coons and Gordon constructions, and the course material of the
//! notes: [`interpolation`] (Lagrange, piecewise linear, parametric), [`hermite`] (Ferguson
//! cubics), [`spline`] (interpolating cubic splines), [`continuity`], [`conversion`] (matrix
//! forms), [`bspline`], [`nurbs`], the [`surfaces`] of the notes and the [`integral`]s of the
//! CAD notes, all built on the [`param::Curve`] / [`param::Surface`] traits and generic over the [`scalar::Scalar`] (`f64`
//! or exact `BigRational`). Its dependencies are mathematical (nalgebra, num, thiserror; rayon
//! and pulp behind the default features `parallel` and `simd`).
//!
//! Two crates sit on top of it, and nothing here depends on them:
//! - `cagd-octave`, the Octave layer: the thesis functions under their own names
//!   (`de_casteljau`, `ploskev_b`, …) with the thesis array layouts, Octave's text file format,
//!   and the Octave syntax users type (matrix literals, ranges, curve expressions, the thesis's
//!   data scripts);
//! - `cagd-cli`, the `cagd` command line: inputs, output formats, pictures, meshes, atomic
//!   files, one-line errors.
//!
//! Whole grids are evaluated into caller-given buffers ([`Surface::eval_grid_into`],
//! [`Curve::eval_many_into`], layouts in [`grid`]) with `O(m + n)` work per point, no allocation
//! per point, and both cores for large grids; `docs/PERFORMANCE.md` has the measurements.
//!
//! **Domains.** Every curve and surface knows its parameter domain ([`Curve::domain`],
//! [`Surface::domain`]), and one rule holds for all of them: `eval` continues the curve outside
//! the domain (nothing is clamped), `try_eval` keeps to it. Coons, Gordon and ruled surfaces
//! reparametrise each curve's domain affinely onto `[0, 1]` (or refuse one that is not a finite
//! interval). See [`param`].
//!
//! **NaN and infinity** are rejected, once and for all: every `Result`-returning entry point
//! (constructors, the checked evaluations taking parameters — `try_eval`, the batches —,
//! tolerances, the parsers of literals, expressions and data scripts, every command-line input)
//! answers a non-finite number with a typed error ([`Error::NonFinite`]; in the Octave layer
//! `LiteralError::NonFinite`) instead of propagating it, and none panics on its arguments. The
//! infallible evaluations (`eval`, `eval_grid`, a basis at a parameter, [`linspace()`]) are total
//! functions, NaN in, NaN out, as in Octave; a fill value the caller chooses
//! ([`bspline::Extrapolation::Outside`]) is written as given; an infallible function that can
//! fail on its arguments documents it in a `# Panics` section (a panic naming the size, never an
//! abort). Only the Octave layer's text-format reader keeps the `Inf`, `NaN` and `NA` that
//! Octave wrote, as data. Finite input can still leave the range of doubles (control points near
//! ±1.7·10³⁰⁸, an interval `[−10³⁰⁸, 10³⁰⁸]`, knots 5·10⁻³²⁴ apart, a thousand equally spaced
//! Lagrange nodes): every `Result`-returning function checks what it computes and answers
//! [`Error::Overflow`], naming the quantity, instead of an `Ok` holding `inf` or NaN (the
//! checks live in one place each: [`error::check_overflow`], [`error::check_spacing`], the
//! grid kernels' row scan, the checked `try_eval` of every curve and surface). Exact results
//! are converted to doubles by [`exact::to_finite_f64`], which names a value whose double
//! overflows.
//!
//! **Resource limits** ([`limits`], a plain value passed to what needs it) refuse sizes that
//! would not fit in memory with [`Error::TooLarge`]; every error variant of the workspace, with
//! an example triggering it, is listed in `docs/ERRORS.md` (the `cagd-cli` crate's
//! `error_catalogue`). Each construction estimates its own work beside its code ([`cost`]), so
//! a caller can refuse a computation above [`Limits::max_work`] before it starts.
//!
//! **One owner per concept**: binomials, products and degree elevation live in [`bernstein`],
//! every form of the Lagrange basis and its node check in [`lagrange`], the cubic Hermite basis
//! in [`hermite`], every matrix form (one power order, ascending) in [`conversion`].
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bernstein;
pub mod bezier;
pub mod bspline;
mod checked;
pub mod continuity;
pub mod conversion;
pub mod coons;
pub mod cost;
pub mod curvature;
pub mod error;
pub mod exact;
pub mod gordon;
pub mod grid;
pub mod hermite;
pub mod integral;
pub mod interpolation;
pub mod lagrange;
pub mod limits;
pub mod linspace;
pub mod nurbs;
pub mod param;
pub mod scalar;
pub mod spline;
pub mod surfaces;
pub mod tolerance;

pub use bezier::{BezierCurve, BezierPatch, Edge};
pub use bspline::{BSplineCurve, BSplineSurface, KnotVector};
pub use coons::{CoonsPatch, Tolerance};
pub use error::{Error, Result};
pub use gordon::GordonSurface;
pub use hermite::HermiteCubic;
pub use limits::Limits;
pub use linspace::linspace;
pub use nurbs::{NurbsCurve, NurbsSurface};
pub use param::{Curve, CurveDeriv, FnCurve, NoDerivative, OnUnitInterval, SampledCurve, Surface};
pub use scalar::Scalar;
pub use spline::{CubicSpline, EndCondition};
