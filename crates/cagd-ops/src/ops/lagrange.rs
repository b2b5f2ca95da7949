//! `lagrange`: the Lagrange basis at parameters, or the polynomial through values at nodes
//! (thesis algorithm 8, the lecture notes §3.11), in the barycentric form:
//!
//! `L_i(t) = Π_{j≠i} (t − t_j) / Π_{j≠i} (t_i − t_j)`, `p(t) = Σ_i y_i L_i(t)`;
//!
//! with the monomial coefficients (the lecture notes' blending matrix `G` and `A = X G`), or
//! the piecewise-linear interpolant instead. The nodes may come in any order (the lecture
//! notes' Příklad 1 takes `0, ½, ¼, 1`); samples cover `[min node, max node]`.

use cagd::cost::max_bits;
use cagd::interpolation::{blending_matrix, PiecewiseLinear};
use cagd::lagrange::{Lagrange as Barycentric, NodesInAnyOrder};
use cagd::Scalar;
use nalgebra::DMatrix;

use super::{to_f64, WRITE_OPS};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::params::check_given;
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// Samples of the interpolant in its picture, at first ([`crate::picture`]).
const PICTURE_SAMPLES: usize = 101;

/// The form of the nodes.
pub const NODES_FORM: &str = "distinct finite nodes, at least one";

/// The form of the values.
pub const VALUES_FORM: &str = "one column of values per node (d × (m+1))";

/// The Lagrange basis, or the interpolating polynomial.
///
/// ```
/// use cagd_ops::{ops::Lagrange, Context, Operation, Params};
/// use num_rational::BigRational;
/// use nalgebra::DMatrix;
/// let q = |a: i64| BigRational::from_integer(a.into());
/// // The lecture notes: the polynomial through (1,1), (2,2), (3,3), (4,2), (5,1) is 87/32 at 5/2.
/// let op = Lagrange {
///     values: Some(DMatrix::from_row_slice(1, 5, &[q(1), q(2), q(3), q(2), q(1)])),
///     t: Params::Given(vec![BigRational::new(5.into(), 2.into())]),
///     ..Lagrange::new((1..=5).map(q).collect())
/// };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap()[0].to_string(), "87/32");
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Lagrange<T> {
    /// The nodes `x_0..x_m`, distinct, in any order.
    pub nodes: Vec<T>,
    /// Values at the nodes, one column per node (`d × (m+1)`): then the interpolant.
    pub values: Option<DMatrix<T>>,
    /// The monomial coefficients too (highest power first): `coefficients` (row `i`: `L_i`,
    /// the lecture notes' `G`), and with values `polynomial` (`A = X G`).
    pub coefficients: bool,
    /// The piecewise-linear interpolant of the values instead (increasing nodes).
    pub linear: bool,
    /// The parameters (samples cover `[min node, max node]`).
    pub t: Params<T>,
    /// A picture of the interpolant through its data (with values).
    pub drawing: bool,
}

impl<T: Scalar> Lagrange<T> {
    /// The basis of `nodes` at the default parameters.
    pub fn new(nodes: Vec<T>) -> Self {
        Lagrange {
            nodes,
            values: None,
            coefficients: false,
            linear: false,
            t: Params::Default,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Lagrange<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        cx.check_degree(Role::Nodes, self.nodes.len().saturating_sub(1))?;
        check_given(Role::Nodes, &self.nodes, cx)?;
        let span = self.span();
        let ts = self.t.resolve(
            Role::T,
            (&span.0, &span.1),
            "the polynomial is extrapolated beyond its nodes",
            cx,
        )?;
        self.check_cost(&ts, cx)?;
        let mut report = Report::new();
        if self.linear {
            let result = self.linear_values(&ts)?;
            report.push("t", Value::row(&ts));
            report.push("result", Value::Matrix(result.clone()));
            return self.answer(report, &ts, &result, cx);
        }
        let basis =
            NodesInAnyOrder::new(self.nodes.clone()).map_err(lib(Role::Nodes, NODES_FORM))?;
        if self.coefficients {
            let g = blending_matrix(&self.nodes).map_err(lib(Role::Nodes, NODES_FORM))?;
            if let Some(v) = self
                .values
                .as_ref()
                .filter(|v| v.ncols() == self.nodes.len())
            {
                report.push("polynomial", Value::Matrix(T::mat_mul(v, &g)));
            }
            report.push("coefficients", Value::Matrix(g));
        }
        report.push("t", Value::row(&ts));
        let result = match &self.values {
            None => {
                let rows: Vec<Vec<T>> = ts.iter().map(|t| basis.basis(t)).collect();
                DMatrix::from_fn(ts.len(), self.nodes.len(), |i, j| rows[i][j].clone())
            }
            Some(values) => {
                if values.nrows() > 1 && values.ncols() == self.nodes.len() && !basis.increasing() {
                    cx.warn(Role::Nodes, "the nodes do not increase, so the curve passes the points in the order of their nodes, not in the order given");
                }
                let mut cols = Vec::with_capacity(ts.len());
                for t in &ts {
                    cols.push(
                        basis
                            .interpolate(values, t)
                            .map_err(lib(Role::Points, VALUES_FORM))?,
                    );
                }
                DMatrix::from_columns(&cols)
            }
        };
        report.push("result", Value::Matrix(result.clone()));
        self.answer(report, &ts, &result, cx)
    }
}

impl<T: Scalar> Lagrange<T> {
    /// The smallest and the largest node.
    fn span(&self) -> (T, T) {
        let pick = |keep: fn(&T, &T) -> bool| {
            self.nodes.iter().fold(self.nodes[0].clone(), |a, x| {
                if keep(x, &a) {
                    x.clone()
                } else {
                    a
                }
            })
        };
        (pick(|x, a| x < a), pick(|x, a| x > a))
    }

    /// The barycentric weights (`Barycentric::weights_cost`), then per parameter the basis
    /// (`basis_cost`, every value written out) or the interpolant (`interpolation_cost`);
    /// a refusal names what drives it: many (exact) nodes, or many parameters.
    fn check_cost(&self, ts: &[T], cx: &Context) -> Result<()> {
        let m1 = self.nodes.len();
        let (node_bits, param_bits) = (max_bits(&self.nodes), max_bits(ts));
        let k = ts.len() as u128;
        let (per, written) = match &self.values {
            Some(v) => (
                Barycentric::<T>::interpolation_cost(
                    m1,
                    v.nrows(),
                    param_bits,
                    node_bits,
                    max_bits(v.iter()),
                ),
                0,
            ),
            None => (
                Barycentric::<T>::basis_cost(m1, param_bits, node_bits),
                k.saturating_mul(m1 as u128).saturating_mul(WRITE_OPS),
            ),
        };
        let setup = Barycentric::<T>::weights_cost(m1, node_bits).weigh(T::EXACT);
        let per = per.times(k).weigh(T::EXACT).saturating_add(written);
        let role = if setup > per { Role::Nodes } else { Role::T };
        cx.check_work(role, setup.saturating_add(per))
    }

    /// The piecewise-linear interpolant of every row of the values at `ts`.
    fn linear_values(&self, ts: &[T]) -> Result<DMatrix<T>> {
        let values = self.values.as_ref().ok_or_else(|| {
            OpError::new(
                Role::Points,
                Kind::Usage,
                "missing",
                "values at the nodes to interpolate piecewise linearly",
            )
        })?;
        let mut rows = Vec::with_capacity(values.nrows());
        for r in 0..values.nrows() {
            let f =
                PiecewiseLinear::new(self.nodes.clone(), values.row(r).iter().cloned().collect())
                    .map_err(|e| match e {
                    cagd::Error::ShapeMismatch { .. } => {
                        OpError::library(Role::Points, e, VALUES_FORM)
                    }
                    _ => OpError::library(Role::Nodes, e, "increasing nodes, at least two"),
                })?;
            rows.push(ts.iter().map(|t| f.eval(t.clone())).collect::<Vec<T>>());
        }
        Ok(DMatrix::from_fn(rows.len(), ts.len(), |r, k| {
            rows[r][k].clone()
        }))
    }

    /// The answer with its picture: the interpolant through the data (numbers as `(t, p(t))`
    /// over `(x_i, y_i)`), the data, and the points at `t`.
    fn answer(
        &self,
        report: Report<T>,
        ts: &[T],
        result: &DMatrix<T>,
        cx: &Context,
    ) -> Result<Answer<T>> {
        let drawing = match (&self.values, self.drawing) {
            (Some(values), true) => {
                let title = if self.linear {
                    "piecewise-linear interpolation"
                } else {
                    "Lagrange interpolation"
                };
                Some(
                    Drawing::new(title)
                        .curve(
                            self.line(values, (ts, result), cx)?,
                            Colour::Blue,
                            "interpolant",
                        )
                        .control_polygon(plane(&self.nodes, values), "data")
                        .points(
                            plane(ts, result),
                            super::point_labels("t", ts),
                            "points at t",
                        ),
                )
            }
            _ => None,
        };
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }

    /// The interpolant of `values` drawn over the nodes and the parameters `ts`, sampled
    /// densely enough that it shows no corners it does not have; where the work of that is
    /// not allowed, the polyline through its values `result` at `ts`.
    fn line(
        &self,
        values: &DMatrix<T>,
        (ts, result): (&[T], &DMatrix<T>),
        cx: &Context,
    ) -> Result<DMatrix<f64>> {
        let (lo, hi) = ts.iter().fold(self.span(), |(lo, hi), t| {
            (
                if *t < lo { t.clone() } else { lo },
                if *t > hi { t.clone() } else { hi },
            )
        });
        if self.linear {
            // Straight between the nodes: exactly the polyline through its values there.
            let mut breaks: Vec<T> = self
                .nodes
                .iter()
                .filter(|x| lo < **x && **x < hi)
                .cloned()
                .collect();
            breaks.push(lo.clone());
            breaks.push(hi.clone());
            breaks.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
            return Ok(plane(&breaks, &self.linear_values(&breaks)?));
        }
        let basis =
            NodesInAnyOrder::new(self.nodes.clone()).map_err(lib(Role::Nodes, NODES_FORM))?;
        let eval = |us: &[T]| -> Result<DMatrix<f64>> {
            let cols = us
                .iter()
                .map(|t| basis.interpolate(values, t))
                .collect::<cagd::Result<Vec<_>>>()
                .map_err(lib(Role::Points, VALUES_FORM))?;
            Ok(plane(us, &DMatrix::from_columns(&cols)))
        };
        let (m1, d) = (self.nodes.len(), values.nrows());
        let (node_bits, value_bits) = (max_bits(&self.nodes), max_bits(values.iter()));
        let point = |bits| Barycentric::<T>::interpolation_cost(m1, d, bits, node_bits, value_bits);
        let first = cagd::linspace::linspace_in(&lo, &hi, PICTURE_SAMPLES)
            .map_err(lib(Role::T, "a curve"))?;
        if !crate::picture::allowed(cx, &first, point) {
            return Ok(plane(ts, result));
        }
        crate::picture::picture_line((&lo, &hi), PICTURE_SAMPLES, false, eval, |us| {
            crate::picture::allowed(cx, us, point)
        })
    }
}

/// Points to draw: numbers `y` (1 × k) as the graph `(x_k, y_k)`, points as they are.
fn plane<T: Scalar>(x: &[T], y: &DMatrix<T>) -> DMatrix<f64> {
    if y.nrows() == 1 {
        graph(x, y)
    } else {
        to_f64(y)
    }
}

/// The graph `(x_k, y_k)` of numbers `y` (1 × k) over `x`.
fn graph<T: Scalar>(x: &[T], y: &DMatrix<T>) -> DMatrix<f64> {
    DMatrix::from_fn(2, x.len().min(y.ncols()), |r, k| {
        if r == 0 {
            x[k].to_f64()
        } else {
            y[(0, k)].to_f64()
        }
    })
}
