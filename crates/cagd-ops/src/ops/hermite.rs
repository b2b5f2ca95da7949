//! `hermite`: the Hermite (Ferguson) cubic of two end points and two end tangents (the
//! lecture notes), with its basis values and its Bézier control points as steps:
//!
//! `x(t) = H_0(t) p_0 + H_1(t) p_1 + H_2(t) t_0 + H_3(t) t_1`, `H_0 = 2t³ − 3t² + 1`,
//! `H_1 = −2t³ + 3t²`, `H_2 = t³ − 2t² + t`, `H_3 = t³ − t²`; the same cubic has the Bézier
//! points `p_0, p_0 + t_0/3, p_1 − t_1/3, p_1`.

use cagd::cost::max_bits;
use cagd::hermite::{basis_cost, hermite_basis, HermiteCubic};
use cagd::Scalar;
use nalgebra::{DMatrix, DVector};

use super::{eval_points, point_labels, to_f64};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The form of one of the four vectors.
pub const VECTOR_FORM: &str = "a point or vector (d values)";

/// Samples of the picture.
const PICTURE_SAMPLES: usize = 101;

/// A Hermite cubic.
///
/// ```
/// use cagd_ops::{ops::Hermite, Context, Operation, Params};
/// use nalgebra::dmatrix;
/// // x(½) = ½(p0 + p1) + ⅛(t0 − t1) = (½, 0) + ⅛(0, 2).
/// let op = Hermite {
///     t: Params::Given(vec![0.5]),
///     ..Hermite::new([dmatrix![0.0; 0.0], dmatrix![1.0; 0.0], dmatrix![1.0; 1.0], dmatrix![1.0; -1.0]])
/// };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.5, 0.25]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Hermite<T> {
    /// `[p0, p1, t0, t1]`: `x(0)`, `x(1)`, `x'(0)`, `x'(1)`, each a row or a column.
    pub data: [DMatrix<T>; 4],
    /// The parameters (samples cover `[0, 1]`).
    pub t: Params<T>,
    /// The basis values (`hermite_basis`, `k × 4`) and the Bézier control points
    /// (`bezier_control`, `d × 4`).
    pub steps: bool,
    /// A picture: the cubic over `[0, 1]`, its Bézier polygon and the points at `t`.
    pub drawing: bool,
}

/// The roles of the four vectors.
const ROLES: [Role; 4] = [Role::P0, Role::P1, Role::T0, Role::T1];

impl<T: Scalar> Hermite<T> {
    /// The cubic of `[p0, p1, t0, t1]` at the default parameters.
    pub fn new(data: [DMatrix<T>; 4]) -> Self {
        Hermite {
            data,
            t: Params::Default,
            steps: false,
            drawing: false,
        }
    }

    /// The cubic.
    ///
    /// # Errors
    /// [`Kind::Shape`] for a matrix that is not a vector; the library's errors about the four
    /// together ([`Role::Hermite`]).
    pub fn cubic(&self) -> Result<HermiteCubic<T>> {
        let [p0, p1, t0, t1] = [0, 1, 2, 3].map(|k| vector(ROLES[k], &self.data[k]));
        HermiteCubic::new(p0?, p1?, t0?, t1?)
            .map_err(lib(Role::Hermite, "four vectors of the same dimension"))
    }
}

impl<T: Scalar> Operation<T> for Hermite<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let h = self.cubic()?;
        let (zero, one) = (T::zero(), T::one());
        let ts = self.t.resolve(
            Role::T,
            (&zero, &one),
            "the cubic is extrapolated there",
            cx,
        )?;
        // The Bézier form (drawn, and printed with steps): its inner points x ± x'/3 overflow
        // for end points and tangents near ±1.8e308.
        let bezier = h.to_bezier().map_err(lib(
            Role::Hermite,
            "end points and tangents whose Bézier points x ± x'/3 stay within ±1.8e308",
        ))?;
        let dense = if self.drawing {
            cagd::linspace::linspace_in(&zero, &one, PICTURE_SAMPLES)
                .map_err(lib(Role::T, "a curve"))?
        } else {
            Vec::new()
        };
        let cost = |params: &[T], steps: bool| cost(&h, &bezier, params, steps);
        cx.check_cost(
            Role::T,
            cost(&ts, self.steps).and(cost(&dense, false)),
            T::EXACT,
        )?;
        let mut report = Report::new();
        if self.steps {
            let rows: Vec<[T; 4]> = ts.iter().map(|t| hermite_basis(t.clone())).collect();
            let basis = DMatrix::from_fn(ts.len(), 4, |i, j| rows[i][j].clone());
            report.push("hermite_basis", Value::Matrix(basis));
            report.push("bezier_control", Value::Matrix(bezier.control().clone()));
        }
        let values = eval_points(&h, &ts, Role::T, cx)?;
        report.push("t", Value::row(&ts));
        report.push("result", Value::Matrix(values.clone()));
        let drawing = if self.drawing {
            let line = crate::picture::curve_line(&h, (&zero, &one), PICTURE_SAMPLES, Role::T, cx)?;
            Some(
                Drawing::new("Hermite cubic")
                    .curve(line, Colour::Blue, "x(t)")
                    .control_polygon(to_f64(bezier.control()), "Bézier control polygon")
                    .points(to_f64(&values), point_labels("t", &ts), "points at t"),
            )
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

/// The work of the cubic `h` (whose Bézier form is `bezier`) at `params`, with the Hermite
/// basis values if `steps`.
fn cost<T: Scalar>(
    h: &HermiteCubic<T>,
    bezier: &cagd::bezier::BezierCurve<T>,
    params: &[T],
    steps: bool,
) -> cagd::cost::Cost {
    let mut per = h.eval_cost(max_bits(params), max_bits(bezier.control().iter()));
    if steps {
        per = per.and(basis_cost(max_bits(params)));
    }
    per.times(params.len() as u128)
}

/// A row or a column as a vector.
pub(crate) fn vector<T: Scalar>(role: Role, m: &DMatrix<T>) -> Result<DVector<T>> {
    if m.nrows() != 1 && m.ncols() != 1 {
        return Err(OpError::new(
            role,
            Kind::Shape,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            VECTOR_FORM,
        ));
    }
    Ok(DVector::from_iterator(m.len(), m.iter().cloned()))
}
