//! `bernstein`: the Bernstein polynomials of degree `n` (thesis (2.1)),
//!
//! `B_i^n(t) = C(n, i) t^i (1 − t)^(n−i)`,  `i = 0, …, n`,
//!
//! by the triangular recurrence `B_i^n = (1 − t) B_i^{n−1} + t B_{i−1}^{n−1}` (thesis (2.3)).
//!
//! ```
//! use cagd_ops::{execute, ops::Bernstein, Context, Params};
//! use num_rational::BigRational;
//! // B_0^3(1/2) … B_3^3(1/2) = 1/8, 3/8, 3/8, 1/8.
//! let op = Bernstein::<BigRational> {
//!     t: Params::Given(vec![BigRational::new(1.into(), 2.into())]),
//!     ..Bernstein::new(3)
//! };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! let b: Vec<String> = answer.report.matrix("result").unwrap().iter().map(|x| x.to_string()).collect();
//! assert_eq!(b, ["1/8", "3/8", "3/8", "1/8"]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::bernstein::{basis_cost, basis_matrix};
use cagd::cost::max_bits;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::point_labels;
use crate::drawing::{Colour, Drawing};
use crate::error::{Kind, OpError, Result};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// Samples of `[0, 1]` in the picture of the polynomials.
const PICTURE_SAMPLES: usize = 201;

/// The Bernstein polynomials of one degree at some parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Bernstein<T> {
    /// The degree `n`.
    pub degree: usize,
    /// Only `B_i^n` (else all of `B_0^n … B_n^n`).
    pub index: Option<usize>,
    /// The parameters (samples cover `[0, 1]`).
    pub t: Params<T>,
    /// A picture: the polynomials over `[0, 1]`, each as the plane curve `(t, B_i^n(t))`.
    pub drawing: bool,
}

impl<T> Bernstein<T> {
    /// All polynomials of degree `degree` at the default parameters.
    pub fn new(degree: usize) -> Self {
        Bernstein {
            degree,
            index: None,
            t: Params::Default,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Bernstein<T> {
    /// `t` (`k × 1`) and `result` (`k × (n+1)`, row = parameter, column = `B_0^n … B_n^n`; or
    /// `k × 1` for one index).
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let n = self.degree;
        cx.check_degree(Role::Degree, n)?;
        if let Some(i) = self.index.filter(|&i| i > n) {
            return Err(OpError::new(
                Role::Index,
                Kind::Shape,
                format!("i = {i} exceeds the degree {n}"),
                "an index 0 ≤ i ≤ n",
            ));
        }
        let unit = (&T::zero(), &T::one());
        let ts = self
            .t
            .resolve(Role::T, unit, "the polynomials are extrapolated there", cx)?;
        let picture = if self.drawing { PICTURE_SAMPLES } else { 0 };
        let cost = basis_cost(n, max_bits(&ts)).times(ts.len() as u128 + picture as u128);
        cx.check_cost(Role::T, cost, T::EXACT)?;
        cx.check_interrupt()?;
        let all = basis_matrix(n, &ts);
        let result = match self.index {
            Some(i) => all.columns(i, 1).into_owned(),
            None => all,
        };
        let mut report = Report::new();
        // One layout for parameter vectors: t is a row, as linspace makes it.
        report.push("t", Value::row(&ts));
        report.push("result", Value::Matrix(result.clone()));
        let drawing = if self.drawing {
            Some(self.picture((&ts, &result), cx)?)
        } else {
            None
        };
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }
}

impl<T: Scalar> Bernstein<T> {
    /// The polynomials over `[0, 1]`, each as the plane curve `(t, B_i^n(t))`, and their values
    /// `result` at `ts` marked.
    fn picture(&self, (ts, result): (&[T], &DMatrix<T>), cx: &Context) -> Result<Drawing> {
        let n = self.degree;
        let shown: Vec<usize> = match self.index {
            Some(i) => vec![i],
            None => (0..=n).collect(),
        };
        let lines = crate::picture::picture_lines(
            (&T::zero(), &T::one()),
            PICTURE_SAMPLES,
            true,
            |dense| {
                Ok(graph_lines(
                    dense,
                    &basis_matrix(n, dense).select_columns(&shown),
                ))
            },
            |dense| crate::picture::allowed(cx, dense, |bits| basis_cost(n, bits)),
        )?;
        let title = format!("Bernstein polynomials of degree {n}");
        let axes = Drawing::graph(title, "t", &format!("B_i^{n}(t)"));
        let drawing = graphs(axes, lines, &shown, |i| format!("B_{i}^{n}"));
        Ok(marked(drawing, ts, result))
    }
}

/// The graphs `(t, f_k(t))` of the columns of `values` (one per function, at `ts`).
pub(super) fn graph_lines<T: Scalar>(ts: &[T], values: &DMatrix<T>) -> Vec<DMatrix<f64>> {
    (0..values.ncols())
        .map(|k| {
            DMatrix::from_fn(2, ts.len(), |r, c| {
                if r == 0 {
                    ts[c].to_f64()
                } else {
                    values[(c, k)].to_f64()
                }
            })
        })
        .collect()
}

/// The graphs `lines` of functions (their `indices`), coloured in turn; up to six labelled
/// `label(index)` one by one, more by one label for all.
pub(super) fn graphs(
    mut drawing: Drawing,
    lines: Vec<DMatrix<f64>>,
    indices: &[usize],
    label: impl Fn(&str) -> String,
) -> Drawing {
    let colours = [
        Colour::Blue,
        Colour::Red,
        Colour::Green,
        Colour::Orange,
        Colour::Purple,
        Colour::Black,
    ];
    let first = indices.first().copied().unwrap_or(0);
    let last = indices.last().copied().unwrap_or(0);
    for (k, (&i, line)) in indices.iter().zip(lines).enumerate() {
        let text = match (indices.len() <= 6, k) {
            (true, _) => label(&i.to_string()),
            (false, 0) => format!("{}, i = {first}..{last}", label("i")),
            _ => String::new(),
        };
        drawing = drawing.curve(line, colours[k % colours.len()], text);
    }
    drawing
}

/// `drawing` with the values of the functions at each parameter marked: `values` is
/// `k × m` (row = parameter, column = function), each value drawn at `(t, value)` and
/// labelled with its parameter.
pub(super) fn marked<T: Scalar>(drawing: Drawing, ts: &[T], values: &DMatrix<T>) -> Drawing {
    if ts.is_empty() || values.ncols() == 0 {
        return drawing;
    }
    let m = values.ncols();
    let marks = DMatrix::from_fn(2, ts.len() * m, |r, c| {
        let (k, i) = (c / m, c % m);
        if r == 0 {
            ts[k].to_f64()
        } else {
            values[(k, i)].to_f64()
        }
    });
    let labels = ts
        .iter()
        .flat_map(|t| std::iter::repeat_n(point_labels("t", std::slice::from_ref(t)), m))
        .flatten()
        .collect();
    drawing.points(marks, labels, "values at t")
}
