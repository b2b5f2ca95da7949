//! `convert`: a polynomial curve from one geometry form to another (the lecture notes,
//! "Konverze mezi reprezentacemi"; the matrix-form notes' product `P · M`):
//!
//! `X_to = X_from · T`,  `T = T_{from→Bézier} · T_{Bézier→to}`,
//!
//! between the cubic forms the lecture notes' `T = M_from · M_to⁻¹`, for the monomial forms
//! the Bernstein-to-monomial matrix `M[i, j] = (−1)^{j−i} C(n, j) C(j, i)` and its inverse
//! ([`cagd::conversion::GeometryForm`]).
//!
//! ```
//! use cagd_ops::{execute, ops::Convert, Context};
//! use cagd::conversion::GeometryForm;
//! use nalgebra::dmatrix;
//! // The Bézier cubic 0, 1, 2, 4 in Hermite form: x(0) = 0, x(1) = 4, x'(0) = 3, x'(1) = 6.
//! let op = Convert::new(dmatrix![0.0, 1.0, 2.0, 4.0], GeometryForm::Bezier, GeometryForm::Hermite);
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.0, 4.0, 3.0, 6.0]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::bezier::BezierCurve;
use cagd::conversion::{form_conversion, form_conversion_cost, invert, GeometryForm};
use cagd::cost::max_bits;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::to_f64;
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of a geometry matrix.
pub const GEOMETRY_FORM: &str = "a d×(n+1) geometry matrix, one vector per column";

/// A conversion between geometry forms.
#[derive(Debug, Clone, PartialEq)]
pub struct Convert<T> {
    /// The geometry `X_from` (`d × (n+1)`, one vector per column), about [`Role::Control`].
    pub geometry: DMatrix<T>,
    /// Its form.
    pub from: GeometryForm,
    /// The form wanted.
    pub to: GeometryForm,
    /// The matrices: `T`, and the lecture notes' `M_from`, `M_to`, `M_to⁻¹` between cubic
    /// forms, or the matrices to and from the Bézier form.
    pub steps: bool,
    /// A picture: the curve, its Bézier polygon and any B-spline polygon.
    pub drawing: bool,
}

impl<T> Convert<T> {
    /// The conversion of `geometry` from `from` to `to`.
    pub fn new(geometry: DMatrix<T>, from: GeometryForm, to: GeometryForm) -> Self {
        Convert {
            geometry,
            from,
            to,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Convert<T> {
    /// `result`, the geometry in the form wanted (`d × (n+1)`); with steps first the
    /// matrices and `T`.
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let x = &self.geometry;
        let k = x.ncols();
        cx.check_degree(Role::Control, k.saturating_sub(1))?;
        self.check_shape()?;
        let cost = form_conversion_cost(k, x.nrows(), max_bits(x.iter()));
        cx.check_cost(Role::Control, cost, T::EXACT)?;
        let (t, into, out) = form_conversion::<T>(self.from, self.to, k)
            .map_err(lib(Role::Control, GEOMETRY_FORM))?;
        let result = T::mat_mul(x, &t);
        let control = T::mat_mul(x, &into);
        // Finite geometry whose Bézier points overflow: an overflow, not a non-finite input.
        cagd::error::check_overflow("the geometry's Bézier points", control.iter()).map_err(
            lib(
                Role::Control,
                "a geometry whose Bézier points stay within ±1.8e308",
            ),
        )?;
        let bezier = BezierCurve::new(control).map_err(lib(
            Role::Control,
            "a d×(n+1) geometry matrix of finite numbers",
        ))?;
        let mut report = Report::new();
        if self.steps {
            self.push_matrices(&mut report, (into, out))?;
            report.push("T", Value::Matrix(t));
        }
        report.push("result", Value::Matrix(result.clone()));
        let drawing = if self.drawing {
            Some(self.picture(cx, &bezier, &result)?)
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

impl<T: Scalar> Convert<T> {
    /// A non-empty geometry, of 4 columns for the cubic-only forms.
    fn check_shape(&self) -> Result<()> {
        let (d, k) = self.geometry.shape();
        if k == 0 || d == 0 {
            return Err(OpError::new(
                Role::Control,
                Kind::Shape,
                format!("a {d}×{k} matrix"),
                GEOMETRY_FORM,
            ));
        }
        match [self.from, self.to]
            .into_iter()
            .find(|f| f.is_cubic_only() && k != 4)
        {
            Some(form) => Err(OpError::new(
                Role::Control,
                Kind::Shape,
                format!("{k} column(s) for the {} form", form.name()),
                "4 columns: the Hermite and B-spline forms are cubic (bezier, monomial and algebraic take any degree)",
            )),
            None => Ok(()),
        }
    }

    /// Between cubic forms the lecture notes' table `T = M_from · M_to⁻¹`; otherwise the
    /// matrices to and from the Bézier form.
    fn push_matrices(
        &self,
        report: &mut Report<T>,
        (into, out): (DMatrix<T>, DMatrix<T>),
    ) -> Result<()> {
        match (self.from.cubic(), self.to.cubic()) {
            (Some(f), Some(g)) => {
                let m_to = g.lecture_notes_matrix::<T>();
                let inverse = invert(&m_to).map_err(lib(Role::To, "a basis matrix"))?;
                report.push("M_from", Value::Matrix(f.lecture_notes_matrix::<T>()));
                report.push("M_to", Value::Matrix(m_to));
                report.push("M_to_inverse", Value::Matrix(inverse));
            }
            _ => {
                report.push("to_bezier", Value::Matrix(into));
                report.push("from_bezier", Value::Matrix(out));
            }
        }
        Ok(())
    }

    /// The curve over `[0, 1]`, its Bézier polygon, and the B-spline polygon of either end.
    fn picture(
        &self,
        cx: &Context,
        bezier: &BezierCurve<T>,
        result: &DMatrix<T>,
    ) -> Result<Drawing> {
        let unit = (&T::zero(), &T::one());
        let line = crate::picture::curve_line(bezier, unit, 101, Role::Control, cx)?;
        let mut drawing = Drawing::new(format!("{} → {}", self.from.name(), self.to.name()))
            .curve(line, Colour::Blue, "curve")
            .control_polygon(to_f64(bezier.control()), "Bézier control polygon");
        for (form, geometry) in [(self.from, &self.geometry), (self.to, result)] {
            if form == GeometryForm::BSpline {
                drawing = drawing.boundary(to_f64(geometry), Colour::Green, "B-spline polygon");
            }
        }
        Ok(drawing)
    }
}
