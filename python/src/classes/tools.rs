//! Functions of the course that are not objects: Bernstein polynomials, the matrix forms of
//! cubics and their conversions, the continuity of a joint.

use cagd::conversion::{conversion_matrix, convert, CubicForm};
use cagd_ops::ops::Bernstein;
use cagd_ops::{Params, Role};
use nalgebra::DMatrix;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::shared::exactness;
use crate::convert::{columns_out, params, points_as_rows, rows_out, Num};
use crate::error::{conversion, IntoPy};
use crate::ops::{execute, item, Names};

/// `B_i^n(t) = C(n, i) t^i (1 − t)^{n−i}` at every `t` (same shape as `t`), by the request
/// [`Bernstein`].
///
/// >>> cagd.bernstein(1, 3, Fraction(1, 2)), cagd.bernstein(0, 2, [0, 0.5, 1]).tolist()
/// (Fraction(3, 8), [1.0, 0.25, 0.0])
#[pyfunction]
fn bernstein<'py>(i: usize, n: usize, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    fn run<'py, T: Num>(i: usize, n: usize, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        const NAMES: Names = &[(Role::Index, "i"), (Role::Degree, "n"), (Role::T, "t")];
        let (shape, ts) = params::<T>(t, "t")?;
        // An empty array of parameters gives an empty array (the request wants values).
        let values = if ts.is_empty() {
            Vec::new()
        } else {
            let op = Bernstein {
                index: Some(i),
                t: Params::Given(ts),
                ..Bernstein::new(n)
            };
            item(&execute(t.py(), NAMES, &op)?, "result")?
                .as_slice()
                .to_vec()
        };
        if shape.is_empty() {
            return values[0].to_py(t.py());
        }
        T::output(t.py(), &shape, |_, out| {
            out.clone_from_slice(&values);
            Ok(())
        })
    }
    if crate::convert::any_exact(&[t])? {
        run::<super::shared::Exact>(i, n, t)
    } else {
        run::<f64>(i, n, t)
    }
}

fn form(name: &str) -> PyResult<CubicForm> {
    match name {
        "hermite" => Ok(CubicForm::Hermite),
        "bezier" => Ok(CubicForm::Bezier),
        "bspline" => Ok(CubicForm::BSpline),
        other => Err(conversion(
            "form",
            format!("expected 'hermite', 'bezier' or 'bspline', got '{other}'"),
        )),
    }
}

/// The 4 × 4 matrix that turns the geometry of a cubic in the form `source` into the form
/// `target` (`'hermite'`, `'bezier'`, `'bspline'`; the lecture notes' matrix forms
/// `x(u) = G M u`): `G_target = G_source · M_source · M_target⁻¹`. Exact with `exact=True`.
///
/// >>> cagd.conversion_matrix("bezier", "hermite", exact=True).tolist()
/// [[Fraction(1, 1), Fraction(0, 1), Fraction(-3, 1), Fraction(0, 1)], [Fraction(0, 1), Fraction(0, 1), Fraction(3, 1), Fraction(0, 1)], [Fraction(0, 1), Fraction(0, 1), Fraction(0, 1), Fraction(-3, 1)], [Fraction(0, 1), Fraction(1, 1), Fraction(0, 1), Fraction(3, 1)]]
#[pyfunction]
#[pyo3(signature = (source, target, exact = false))]
fn conversion_matrix_of<'py>(
    py: Python<'py>,
    source: &str,
    target: &str,
    exact: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let (f, t) = (form(source)?, form(target)?);
    if exact {
        columns_out(py, &conversion_matrix::<super::shared::Exact>(f, t))
    } else {
        columns_out(py, &conversion_matrix::<f64>(f, t))
    }
}

/// The geometry of a cubic (4 points or tangents as rows, `(4, d)`) converted from the form
/// `source` to `target`.
///
/// >>> cagd.convert_cubic([[0, 0], [1, 1], [2, 1], [3, 0]], "bezier", "hermite").tolist()
/// [[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [3.0, -3.0]]
#[pyfunction]
#[pyo3(signature = (geometry, source, target, exact = None))]
fn convert_cubic<'py>(
    geometry: &Bound<'py, PyAny>,
    source: &str,
    target: &str,
    exact: Option<bool>,
) -> PyResult<Bound<'py, PyAny>> {
    fn run<'py, T: Num>(
        g: &Bound<'py, PyAny>,
        f: CubicForm,
        t: CubicForm,
    ) -> PyResult<Bound<'py, PyAny>> {
        let m: DMatrix<T> = points_as_rows(g, "geometry")?;
        rows_out(g.py(), &convert(&m, f, t).py()?)
    }
    let (f, t) = (form(source)?, form(target)?);
    if exactness(exact, &[geometry])? {
        run::<super::shared::Exact>(geometry, f, t)
    } else {
        run::<f64>(geometry, f, t)
    }
}

/// The continuity of the joint of two curves, `first` at its end and `second` at its start:
/// `{'c0': …, 'c1': …, 'g1': …}` (positions agree; and first derivatives; or derivatives
/// parallel with the same orientation), within `tol` (relative).
///
/// >>> a = cagd.BezierCurve([[0, 0], [1, 1], [2, 1]])
/// >>> b = cagd.BezierCurve([[2, 1], [4, 1], [5, 0]])              # the same direction, twice as fast
/// >>> cagd.continuity(a, b)
/// {'c0': True, 'c1': False, 'g1': True}
#[pyfunction]
#[pyo3(signature = (first, second, tol = 1e-12))]
fn continuity<'py>(
    py: Python<'py>,
    first: &Bound<'py, PyAny>,
    second: &Bound<'py, PyAny>,
    tol: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let j = super::patches::joint(first, second, tol)?;
    let out = PyDict::new(py);
    out.set_item("c0", j.c0)?;
    out.set_item("c1", j.c1)?;
    out.set_item("g1", j.g1)?;
    Ok(out)
}

/// Registers the functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(bernstein, m)?)?;
    m.add(
        "conversion_matrix",
        wrap_pyfunction!(conversion_matrix_of, m)?,
    )?;
    m.add_function(wrap_pyfunction!(convert_cubic, m)?)?;
    m.add_function(wrap_pyfunction!(continuity, m)?)?;
    Ok(())
}
