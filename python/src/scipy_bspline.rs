//! The Rust half of `cagd.BSpline`, the drop-in for `scipy.interpolate.BSpline`: each function
//! takes scipy's arrays (knots `t`, coefficients `c` flattened to `(n, d)` with the first `n`
//! rows used, degree `k`), builds the core's [`BSplineCurve`] (points as columns: the storage of
//! `(n, d)` row-major) and calls it. The Python class (`cagd/_bspline.py`) does scipy's layout
//! (axis, trailing dimensions, complex as pairs of reals).

use cagd::bspline::{design_matrix, BSplineCurve, Extrapolation};
use nalgebra::DMatrix;
use pyo3::prelude::*;
use pyo3::types::{PyString, PyTuple};

use crate::convert::{chunked, rows_out, vector_out, Num};
use crate::error::{conversion, IntoPy};

/// scipy's `extrapolate`: `True`, `False` (NaN outside) or `'periodic'`.
fn extrapolation(obj: &Bound<'_, PyAny>) -> PyResult<Extrapolation<f64>> {
    if let Ok(s) = obj.cast::<PyString>() {
        let s: String = s.extract()?;
        return match s.as_str() {
            "periodic" => Ok(Extrapolation::Periodic),
            other => Err(conversion(
                "extrapolate",
                format!("expected True, False or 'periodic', got '{other}'"),
            )),
        };
    }
    Ok(if obj.is_truthy()? {
        Extrapolation::Continue
    } else {
        Extrapolation::Outside(f64::NAN)
    })
}

/// The core's curve of scipy's `(t, c, k)`: `c` is `(≥ n, d)` and its first `n = len(t) − k − 1`
/// rows are the control points.
fn curve(t: &Bound<'_, PyAny>, c: &Bound<'_, PyAny>, k: usize) -> PyResult<BSplineCurve<f64>> {
    let (_, knots) = crate::convert::params::<f64>(t, "t")?;
    f64::with_values(c, "c", |shape, v| {
        let (rows, d) = match *shape {
            [rows, d] => (rows, d),
            _ => return Err(crate::convert::rank_error("c", "an (n, d) array", shape)),
        };
        let n = knots.len().saturating_sub(k + 1).min(rows);
        let control = DMatrix::from_column_slice(d, n, &v[..n * d]);
        BSplineCurve::new(k, knots.clone(), control).py()
    })
}

/// `(t', c')` of a curve, `c'` as `(n', d)`.
fn tc<'py>(py: Python<'py>, s: &BSplineCurve<f64>) -> PyResult<Bound<'py, PyTuple>> {
    PyTuple::new(
        py,
        [
            vector_out(py, s.knots().as_slice())?,
            rows_out(py, s.control())?,
        ],
    )
}

/// Checks scipy's `(t, c, k)` as the core's constructor does.
#[pyfunction]
fn bspline_check(t: &Bound<'_, PyAny>, c: &Bound<'_, PyAny>, k: usize) -> PyResult<()> {
    curve(t, c, k).map(|_| ())
}

/// The derivative of order `nu` at the points `x` (1-D), `(len(x), d)`.
#[pyfunction]
fn bspline_eval<'py>(
    t: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    k: usize,
    x: &Bound<'py, PyAny>,
    nu: usize,
    extrapolate: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let py = x.py();
    let s = curve(t, c, k)?;
    let mode = extrapolation(extrapolate)?;
    let d = s.dim();
    f64::with_values(x, "x", |_, xs| {
        // scipy's rule: NaN (or ±∞) in, NaN out. The core refuses a parameter that is not
        // finite, so those are evaluated at the domain's start and then overwritten.
        let bad: Vec<usize> = (0..xs.len()).filter(|&i| !xs[i].is_finite()).collect();
        let start = s.domain().0;
        let finite: std::borrow::Cow<'_, [f64]> = if bad.is_empty() {
            std::borrow::Cow::Borrowed(xs)
        } else {
            xs.iter()
                .map(|v| if v.is_finite() { *v } else { start })
                .collect()
        };
        f64::output(py, &[xs.len(), d], |py, out| {
            chunked(py, out, d, &|range, block| {
                s.eval_derivative_many_into(nu, &finite[range], block, &mode)
            })?;
            for i in &bad {
                out[i * d..(i + 1) * d].fill(f64::NAN);
            }
            Ok(())
        })
    })
}

/// `(t', c')` of the derivative of order `nu`.
#[pyfunction]
fn bspline_derivative<'py>(
    t: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    k: usize,
    nu: usize,
) -> PyResult<Bound<'py, PyTuple>> {
    tc(t.py(), &curve(t, c, k)?.derivative_of_order(nu).py()?)
}

/// `(t', c')` of the antiderivative of order `nu`.
#[pyfunction]
fn bspline_antiderivative<'py>(
    t: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    k: usize,
    nu: usize,
) -> PyResult<Bound<'py, PyTuple>> {
    let mut s = curve(t, c, k)?;
    for _ in 0..nu {
        s = cagd::integral::bspline_antiderivative(&s).py()?;
    }
    tc(t.py(), &s)
}

/// `∫_a^b`, a vector of length `d`.
#[pyfunction]
fn bspline_integrate<'py>(
    t: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    k: usize,
    a: f64,
    b: f64,
    extrapolate: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let s = curve(t, c, k)?;
    let v = s.integral(a, b, extrapolation(extrapolate)?).py()?;
    vector_out(t.py(), v.as_slice())
}

/// The design matrix in scipy's CSR parts: `(data, first_column, n_columns)`; `data` is
/// `(len(x), k+1)`.
#[pyfunction]
fn bspline_design_matrix<'py>(
    x: &Bound<'py, PyAny>,
    t: &Bound<'py, PyAny>,
    k: usize,
    extrapolate: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyTuple>> {
    let py = x.py();
    let (_, knots) = crate::convert::params::<f64>(t, "t")?;
    let (_, mut xs) = crate::convert::params::<f64>(x, "x")?;
    let mode = extrapolation(extrapolate)?;
    if mode == Extrapolation::Periodic {
        let n = knots.len().saturating_sub(k + 1);
        if n > k && n < knots.len() {
            let (lo, hi) = (knots[k], knots[n]);
            xs.iter_mut()
                .for_each(|u| *u = cagd::bspline::wrap_periodic(*u, &lo, &hi));
        }
    }
    let continue_ends = mode == Extrapolation::Continue;
    let a = py
        .detach(|| design_matrix(k, &knots, &xs, continue_ends))
        .py()?;
    let data = f64::output(py, &[a.rows, k + 1], |_, out| {
        out.copy_from_slice(&a.values);
        Ok(())
    })?;
    let first: Vec<i64> = a.first_column.iter().map(|&c| c as i64).collect();
    PyTuple::new(
        py,
        [
            data,
            numpy::PyArray1::from_vec(py, first).into_any(),
            a.columns.into_pyobject(py)?.into_any(),
        ],
    )
}

/// `(t', c', k)` of the single B-spline over `t`.
#[pyfunction]
fn bspline_basis_element<'py>(t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyTuple>> {
    let py = t.py();
    let (_, knots) = crate::convert::params::<f64>(t, "t")?;
    let s = BSplineCurve::basis_element(&knots).py()?;
    let (t2, c2) = (
        vector_out(py, s.knots().as_slice())?,
        rows_out(py, s.control())?,
    );
    PyTuple::new(py, [t2, c2, s.degree().into_pyobject(py)?.into_any()])
}

/// `(t', c')` with the knot `x` inserted `m` times.
#[pyfunction]
fn bspline_insert_knot<'py>(
    t: &Bound<'py, PyAny>,
    c: &Bound<'py, PyAny>,
    k: usize,
    x: f64,
    m: usize,
) -> PyResult<Bound<'py, PyTuple>> {
    let s = curve(t, c, k)?.insert_knots(&vec![x; m]).py()?;
    tc(t.py(), &s)
}

/// Registers the functions (private names, used by `cagd._bspline`).
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(bspline_check, m)?)?;
    m.add_function(wrap_pyfunction!(bspline_eval, m)?)?;
    m.add_function(wrap_pyfunction!(bspline_derivative, m)?)?;
    m.add_function(wrap_pyfunction!(bspline_antiderivative, m)?)?;
    m.add_function(wrap_pyfunction!(bspline_integrate, m)?)?;
    m.add_function(wrap_pyfunction!(bspline_design_matrix, m)?)?;
    m.add_function(wrap_pyfunction!(bspline_basis_element, m)?)?;
    m.add_function(wrap_pyfunction!(bspline_insert_knot, m)?)?;
    Ok(())
}
