//! `curve`: a curve known only by evaluation — a user's expression in one parameter, as the
//! thesis writes curves (`[u; 0; u-u^2]`) — sampled at parameters: `x(t_1) … x(t_k)`. The
//! front end evaluates the expression ([`Evaluator`]); the request decides where, prices the
//! samples before any is taken and lays out the answer.
//!
//! ```
//! use cagd_ops::curves::{Evaluator, Work};
//! use cagd_ops::{execute, ops::CurveSamples, Context, Params};
//! use nalgebra::DMatrix;
//! struct Parabola;
//! impl Evaluator<f64> for Parabola {
//!     fn values(&self, ts: &[f64]) -> cagd_ops::Result<DMatrix<f64>> {
//!         Ok(DMatrix::from_fn(2, ts.len(), |r, k| if r == 0 { ts[k] } else { ts[k] * ts[k] }))
//!     }
//!     fn derivatives(&self, ts: &[f64]) -> cagd_ops::Result<DMatrix<f64>> { self.values(ts) }
//!     fn work(&self, ts: &[f64]) -> Work { Work { operations: ts.len() as u128, what: "samples" } }
//! }
//! let op = CurveSamples { t: Params::Samples(3), ..CurveSamples::new(Box::new(Parabola), "u", "[u; u^2]") };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.0, 0.0, 0.5, 0.25, 1.0, 1.0]);
//! assert_eq!(answer.report.matrix("u").unwrap().as_slice(), &[0.0, 0.5, 1.0]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::Scalar;

use super::{point_labels, to_f64};
use crate::curves::Evaluator;
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The expected form of the samples' work.
pub const SAMPLES_FORM: &str = "fewer samples or a shorter expression";

/// A curve known by evaluation, sampled; the curve is about [`Role::Control`].
pub struct CurveSamples<T: Scalar> {
    /// The curve.
    pub curve: Box<dyn Evaluator<T>>,
    /// The name of its parameter (`t`, `u` or `v`): the name of the parameters' item.
    pub param: String,
    /// How the curve reads (its expression), for the picture.
    pub name: String,
    /// The parameters (given anywhere, or samples of `[0, 1]`).
    pub t: Params<T>,
    /// A picture: the polyline through the samples, the samples marked.
    pub drawing: bool,
}

impl<T: Scalar> std::fmt::Debug for CurveSamples<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CurveSamples")
            .field("param", &self.param)
            .field("name", &self.name)
            .field("t", &self.t)
            .field("drawing", &self.drawing)
            .finish()
    }
}

impl<T: Scalar> CurveSamples<T> {
    /// `curve`, a function of `param` reading `name`, at the default samples.
    pub fn new(curve: Box<dyn Evaluator<T>>, param: &str, name: &str) -> Self {
        CurveSamples {
            curve,
            param: param.to_string(),
            name: name.to_string(),
            t: Params::Default,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for CurveSamples<T> {
    /// The parameters (`1 × k`, named as the curve's parameter) and `result` (`d × k`).
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let unit = (&T::zero(), &T::one());
        let ts = self.t.anywhere(Role::T, unit, cx)?;
        let work = self.curve.work(&ts);
        cx.limits
            .check_work(work.what, work.operations)
            .map_err(lib(Role::Control, SAMPLES_FORM))?;
        cx.check_interrupt()?;
        let points = self.curve.values(&ts).map_err(|e| e.about(Role::Control))?;
        let mut report = Report::new();
        report.push(self.param.as_str(), Value::row(&ts));
        report.push("result", Value::Matrix(points.clone()));
        let drawing = self.drawing.then(|| {
            let name = self.name.trim();
            Drawing::new(format!("curve {name}"))
                .curve(
                    to_f64(&points),
                    Colour::Blue,
                    format!("{} ↦ {name}", self.param),
                )
                .points(to_f64(&points), point_labels(&self.param, &ts), "samples")
        });
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }
}
