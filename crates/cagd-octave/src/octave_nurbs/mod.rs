//! octave-nurbs' functions with octave-nurbs' own conventions, for the Octave package's
//! twins (`cagd_nrbeval`, `cagd_bspeval`, …) and for Rust code ported from octave-nurbs.
//!
//! The core ([`cagd::bspline`], [`cagd::nurbs`]) is strict: finite coefficients, positive
//! weights, `n + p + 1` knots, parameters inside the domain `[u_p, u_n]`. octave-nurbs 1.4.3 is
//! not, and programs written for it rely on that. This module does what octave-nurbs does,
//! argument for argument, and says where it cannot:
//!
//! - **Layouts.** A NURBS is octave-nurbs' structure ([`NrbParts`] read, [`Nrb`] built by
//!   [`nrbmak`]): homogeneous coefficients `coefs` `4 × n1 × n2 × n3` with rows
//!   `(w·x, w·y, w·z, w)`, one knot vector per direction, `order = degree + 1`. Univariate
//!   functions take a degree `d`, control points `c` (`dim × nc`, one per column) and knots
//!   `k` ([`Bsp`]). Spans are numbered from 0, as octave-nurbs numbers them.
//! - **Evaluation on `[U(1), U(end)]`.** `bspeval` and `nrbeval` refuse only parameters
//!   outside the knots; inside them, every parameter belongs to the span octave-nurbs'
//!   search gives ([`eval_span`]): past the last domain knot the last span continues (an
//!   empty last span gives NaN, as in `nrbeval (nrbmak ([0 1 3 4 5; 0 2 2 0 1], [0 0 0 .4 .4
//!   .4 1 1]), 0.7)`), NaN gives NaN.
//! - **Weights of any sign.** A cartesian point is the homogeneous point divided by its weight:
//!   a zero weight gives ±Inf or NaN, a negative one is used as it is — octave-nurbs' own
//!   derivative code (`nrbderiv`, `nrbdeval`) evaluates NURBS whose weights are derivatives.
//! - **The searches as octave-nurbs' own.** [`findspan`] is its `.m` file: it does not
//!   check `n` against the knots (`bspinterpcrv` relies on it), and ignores `p`.
//!   [`basisfun_into`] takes a span as given (a wrong one gives that span's polynomials).
//! - **Undefined behaviour.** Where octave-nurbs' compiled code reads outside its arrays —
//!   a span without its knots, fewer spans than parameters, a parameter below `U(p+1)` of a
//!   knot vector not clamped at its start — its result is whatever memory lies there. The
//!   functions here then refuse ([`NurbsError::Undefined`]), except the last case, where they
//!   give the B-spline's value (the sum over the basis functions that exist,
//!   [`existing_basis`]), and one span for several parameters, which is used for all of them.
//!
//! Each function's documentation gives octave-nurbs' name and its result on an example from
//! octave-nurbs 1.4.3 itself; `octave_pkg/tests` compares them with octave-nurbs in live
//! Octave over random inputs of every argument form.

mod along;
mod basis;
mod bspdegelev;
mod bspderiv;
mod bspeval;
mod bspkntins;
mod error;
mod fast;
mod interrupt;
mod nd;
mod nrb;
mod nrbcoons;
mod nrbderiv;
mod nrbdeval;
mod nrbeval;
mod oct;
mod refine;
mod span;

pub use along::Net;
pub use basis::{
    basisfun_cost, basisfun_into, basisfunder_cost, basisfunder_into, existing_basis,
    span_has_knots, truncate,
};
pub use bspdegelev::bspdegelev;
pub use bspderiv::{bspderiv, bspderiv_into, check_bspderiv};
pub use bspeval::{along_axis, bspeval_into, combine, BasisWork, Bsp};
pub use bspkntins::bspkntins;
pub use error::{NurbsError, Result};
pub use interrupt::{Interrupt, Poll, CHECK_WORK, FEW_ITEMS};
pub use nd::Nd;
pub use nrb::{nrbmak, Kind, Knots, Nrb, NrbParts};
pub use nrbcoons::nrbcoons;
pub use nrbderiv::{nrbderiv, NrbDerivs};
pub use nrbdeval::{nrbdeval, Ders, NrbDeval, Slot};
pub use nrbeval::{NrbEval, Params, Tt};
pub use refine::{nrbdegelev, nrbkntins};
pub use span::{check_in_knots, eval_span, findspan, is_sorted};
