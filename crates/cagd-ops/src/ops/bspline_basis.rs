//! `bspline-basis`: the B-spline basis functions `N_{i,p}(u)` of a knot vector alone (the CAD
//! notes §1.2, the lecture notes), with the Cox–de Boor triangle as steps:
//!
//! `N_{i,0}(u) = 1` if `u_i ≤ u < u_{i+1}`, else 0;
//! `N_{i,j}(u) = (u − u_i)/(u_{i+j} − u_i) N_{i,j−1}(u) + (u_{i+j+1} − u)/(u_{i+j+1} − u_{i+1}) N_{i+1,j−1}(u)`.
//!
//! Every `N_{i,p}` lives on `[u_i, u_{i+p+1}]`: the values are taken over the whole knot range
//! `[u_1, u_(n+p+1)]`, not only the domain `[u_(p+1), u_(n+1)]` of a spline (knots and functions
//! numbered from 1 as in [`crate::knots`]: `N_1,p … N_n,p` for `n + p + 1` knots). The degree and the knots follow
//! the one convention of [`crate::knots`].

use cagd::bspline::{cox_de_boor_triangle, triangle_cost};
use cagd::cost::max_bits;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::bernstein::{graph_lines, graphs, marked};
use super::bspline::step_name;
use super::WRITE_OPS;
use crate::drawing::Drawing;
use crate::error::Result;
use crate::knots::{self, Degree};
use crate::{Answer, Context, Item, Operation, Params, Report, Role, Value};

/// The form of the parameters of the basis.
pub const RANGE_FORM: &str = "parameters between the first and the last knot";

/// The basis functions of a knot vector.
///
/// ```
/// use cagd_ops::{ops::BSplineBasis, knots::Degree, Context, Operation, Params};
/// // Knots 0,0,0,1,1,1 of degree 2 are Bernstein's: at ½ the values ¼, ½, ¼.
/// let op = BSplineBasis {
///     degree: Degree::Degree(2),
///     t: Params::Given(vec![0.5]),
///     ..BSplineBasis::new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
/// };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.25, 0.5, 0.25]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineBasis<T> {
    /// The knots `u_1 ≤ … ≤ u_(n+p+1)` (numbered from 1, as in the words).
    pub knots: Vec<T>,
    /// The degree (or order).
    pub degree: Degree,
    /// The parameters (samples cover `[u_1, u_(n+p+1)]`; outside it an error).
    pub t: Params<T>,
    /// The Cox–de Boor triangle of every parameter (`triangle`: `t`, levels `p0..pP`).
    pub steps: bool,
    /// A picture of the functions over `[u_1, u_(n+p+1)]`, with their values at `t` marked.
    pub drawing: bool,
}

impl<T: Scalar> BSplineBasis<T> {
    /// The cubic basis of `knots` at the default parameters.
    pub fn new(knots: Vec<T>) -> Self {
        BSplineBasis {
            knots,
            degree: Degree::Default,
            t: Params::Default,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for BSplineBasis<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let p = self.degree.resolve(cx)?;
        let n = knots::check_basis_knots(&self.knots, p)?;
        let (a, b) = (&self.knots[0], &self.knots[self.knots.len() - 1]);
        let what = ("B-spline basis", RANGE_FORM);
        let ts = knots::params_within(&self.t, Role::T, (a, b), what, cx)?;
        let dense = super::bspline::picture_params(self.drawing, (a, b))?;
        self.check_cost(p, n, (&ts, &dense), cx)?;
        let top = |t: &T| -> Vec<T> {
            let mut levels = cox_de_boor_triangle(p, &self.knots, t);
            levels.pop().unwrap_or_default()
        };
        let rows: Vec<Vec<T>> = ts.iter().map(top).collect();
        let mut report = Report::new();
        if self.steps {
            for (k, t) in ts.iter().enumerate() {
                report.push(step_name("triangle", k, ts.len()), self.triangle(p, t));
            }
        }
        // One layout for parameter vectors: t is a row, as linspace makes it.
        report.push("t", Value::row(&ts));
        let result = DMatrix::from_fn(ts.len(), n, |i, j| rows[i][j].clone());
        report.push("result", Value::Matrix(result.clone()));
        let drawing = if self.drawing {
            let lines = crate::picture::picture_lines(
                (a, b),
                dense.len(),
                true,
                |us| {
                    let rows: Vec<Vec<T>> = us.iter().map(top).collect();
                    let values = DMatrix::from_fn(us.len(), n, |k, i| rows[k][i].clone());
                    Ok(graph_lines(us, &values))
                },
                |us| self.check_cost(p, n, (&[], us), cx).is_ok(),
            )?;
            Some(picture(p, lines, (&ts, &result)))
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

impl<T: Scalar> BSplineBasis<T> {
    /// The triangles at `ts` (twice with steps) and at the picture's `dense`, and the numbers
    /// written: refused above the limit, about the parameters.
    fn check_cost(
        &self,
        p: usize,
        n: usize,
        (ts, dense): (&[T], &[T]),
        cx: &Context,
    ) -> Result<()> {
        let knot_bits = max_bits(&self.knots);
        let m = self.knots.len();
        let at = |params: &[T]| {
            triangle_cost(p, m, max_bits(params), knot_bits).times(params.len() as u128)
        };
        let times = if self.steps { 2 } else { 1 };
        let work = at(ts).times(times).and(at(dense)).weigh(T::EXACT);
        let per_t = n as u128
            + if self.steps {
                (p as u128 + 1) * m as u128
            } else {
                0
            };
        let written = (ts.len() as u128)
            .saturating_mul(per_t)
            .saturating_mul(WRITE_OPS);
        cx.check_work(Role::T, work.saturating_add(written))
    }

    /// The Cox–de Boor triangle at `t`: `t` and the levels `p0 … pP` (`N_{0,j} … N_{m−j−1,j}`).
    fn triangle(&self, p: usize, t: &T) -> Value<T> {
        let mut parts = vec![Item {
            name: "t".into(),
            value: Value::scalar(t.clone()),
        }];
        for (j, level) in cox_de_boor_triangle(p, &self.knots, t).iter().enumerate() {
            parts.push(Item {
                name: format!("p{j}"),
                value: Value::row(level),
            });
        }
        Value::Record(parts)
    }
}

/// The functions (their graphs `lines`), six labelled at most, and the values at `ts` marked.
fn picture<T: Scalar>(
    p: usize,
    lines: Vec<DMatrix<f64>>,
    (ts, result): (&[T], &DMatrix<T>),
) -> Drawing {
    let n = result.ncols();
    let title = format!("B-spline basis functions, degree {p}");
    let drawing = Drawing::graph(title, "t", &format!("N_i,{p}(t)"));
    // Numbered from 1, as the CAD notes number them.
    let numbers: Vec<usize> = (1..=n).collect();
    let drawing = graphs(drawing, lines, &numbers, |i| format!("N_{i},{p}"));
    marked(drawing, ts, result)
}
