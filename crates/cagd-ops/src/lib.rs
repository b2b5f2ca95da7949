//! The operation layer of cagd: one typed request per construction the front ends offer.
//!
//! The command line, the Octave package, the web page and the Python package are four doors
//! into one house. Each construction is a request here ([`ops`]): its arguments by
//! [`Role`], its checks and their wording ([`OpError`], worded once, front-end neutral),
//! its cost (from the core's own `*_cost` functions only, checked against the
//! [`cagd::Limits`] of the [`Context`] before any work), its result and steps ([`Report`])
//! and, when asked for, its picture ([`Drawing`]). Every answer is checked finite
//! ([`execute`]). A front end only translates: its arguments into a request (a role named
//! its own way: `--knots`, `U`, `knots`), the answer into its output.
//!
//! The crate depends on the core `cagd` only; nothing here knows about a command line, Octave
//! or a browser. Requests are generic over the scalar ([`cagd::Scalar`]): `f64`, or exact
//! rationals where the construction is rational.
//!
//! ```
//! use cagd_ops::{execute, ops::DeCasteljau, Context, Params};
//! use nalgebra::dmatrix;
//! let op = DeCasteljau { t: Params::Given(vec![0.5]), ..DeCasteljau::new(dmatrix![0.0, 1.0; 0.0, 1.0]) };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.5, 0.5]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

#![warn(missing_docs)]

pub mod bspline_arg;
pub mod check;
pub mod context;
pub mod curves;
pub mod drawing;
pub mod error;
pub mod format;
pub mod knots;
pub mod layout;
pub mod ops;
pub mod output;
pub mod params;
pub mod picture;
mod role;

pub use context::{Context, Warning};
pub use drawing::Drawing;
pub use error::{Kind, OpError, Result};
pub use format::{number_text, number_text_digits, number_text_scaled, TEXT_DIGITS};
pub use output::{Item, Report, Value};
pub use params::Params;
pub use role::Role;

use cagd::grid::PointGrid;
use cagd::Scalar;

/// What a request answers.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer<T: Scalar> {
    /// The result and the steps, named.
    pub report: Report<T>,
    /// The picture, if asked for.
    pub drawing: Option<Drawing>,
    /// The surface sampled for a mesh, if asked for.
    pub mesh: Option<PointGrid<f64>>,
}

/// A construction: its arguments are the fields of the implementing type.
pub trait Operation<T: Scalar> {
    /// Checks the arguments, prices the work (refusing it above the limits before it starts),
    /// computes, and lays out the answer. Front ends call [`execute`], which also checks the
    /// answer.
    ///
    /// # Errors
    /// An [`OpError`] about the role at fault.
    fn run(&self, cx: &mut Context) -> Result<Answer<T>>;
}

/// Runs `op` and refuses an answer holding a non-finite number (NaN or ±Inf from finite
/// input: an overflow), naming it.
///
/// # Errors
/// The request's own errors; [`Kind::Overflow`] about [`Role::Result`] for a non-finite answer.
pub fn execute<T: Scalar, O: Operation<T> + ?Sized>(op: &O, cx: &mut Context) -> Result<Answer<T>> {
    let answer = op.run(cx)?;
    if let Some((name, index, value)) = answer.report.first_non_finite() {
        return Err(OpError::new(
            Role::Result,
            Kind::Overflow,
            format!("the result overflows the range of doubles ({name}, element {index}: {value})"),
            "inputs whose result stays within ±1.8e308 (smaller coordinates, parameters or orders)",
        ));
    }
    Ok(answer)
}
