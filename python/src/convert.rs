//! The one place where Python values become the core's types and back.
//!
//! **Numbers.** A call computes in doubles unless one of its numeric arguments is exact: a
//! numpy array of dtype `object` (a list holding a `fractions.Fraction` becomes one) or a
//! `Fraction` scalar; then it computes in exact rationals (`BigRational`) and every array it
//! returns is an `object` array of `Fraction`s. In exact mode an element is read as
//! `Fraction(x)` (ints, `Fraction`s, numpy integers, text such as `"1/3"`), a float as the
//! shortest decimal that gives it back (`0.1` is `1/10`, as the Octave package reads doubles).
//!
//! **Layouts.** numpy arrays are row-major: an `(n, d)` array of points as rows has the storage
//! of the core's `d × n` column-major matrix of points as columns, and the core's batch
//! evaluations write `(points, d)` row-major buffers, which are numpy's `(points, d)` arrays:
//! results are written straight into the array returned, without a copy. Double inputs that are
//! already `float64` and contiguous are read in place.
//!
//! **Long computations** run in chunks with the interpreter's lock released, and between
//! chunks `PyErr_CheckSignals` lets Ctrl-C stop them (`KeyboardInterrupt`).

use std::ops::Range;

use cagd::grid::PointGrid;
use nalgebra::DMatrix;
use ndarray::{Array, Dimension};
use num_rational::BigRational;
use numpy::{PyArray, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyFloat, PyString};

use crate::error::{conversion, IntoPy};

/// Points evaluated between two checks for Ctrl-C.
const CHUNK: usize = 1 << 15;

/// `f64` or an exact rational, with the package's input and output conventions.
pub trait Num: cagd_octave::literal::LiteralScalar + Send + Sync + 'static {
    /// Calls `f` with the shape and the values (row-major) of the array `obj`.
    ///
    /// # Errors
    /// A conversion error for what is not an array of real numbers; `f`'s error.
    fn with_values<R>(
        obj: &Bound<'_, PyAny>,
        what: &str,
        f: impl FnOnce(&[usize], &[Self]) -> PyResult<R>,
    ) -> PyResult<R>;

    /// One number.
    ///
    /// # Errors
    /// A conversion error.
    fn scalar(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Self>;

    /// The array of `shape` (row-major) whose values `fill` writes: a `float64` array written
    /// in place, or an `object` array of `Fraction`s.
    ///
    /// # Errors
    /// `fill`'s error; `MemoryError`.
    fn output<'py>(
        py: Python<'py>,
        shape: &[usize],
        fill: impl FnOnce(Python<'py>, &mut [Self]) -> PyResult<()>,
    ) -> PyResult<Bound<'py, PyAny>>;

    /// The array `a` (any rank): a `float64` array that takes over its buffer, or an `object`
    /// array of `Fraction`s.
    ///
    /// # Errors
    /// Conversion of a big integer.
    fn from_array<'py, D: Dimension>(
        py: Python<'py>,
        a: Array<Self, D>,
    ) -> PyResult<Bound<'py, PyAny>>;

    /// One number as a Python `float` or `Fraction`.
    ///
    /// # Errors
    /// Conversion of a big integer.
    fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>>;
}

fn numpy(py: Python<'_>) -> PyResult<&Bound<'_, PyModule>> {
    static NUMPY: PyOnceLock<Py<PyModule>> = PyOnceLock::new();
    NUMPY
        .get_or_try_init(py, || py.import("numpy").map(Bound::unbind))
        .map(|m| m.bind(py))
}

fn fraction_class(py: Python<'_>) -> PyResult<&Bound<'_, PyAny>> {
    static FRACTION: PyOnceLock<Py<PyAny>> = PyOnceLock::new();
    FRACTION
        .get_or_try_init(py, || {
            Ok(py.import("fractions")?.getattr("Fraction")?.unbind())
        })
        .map(|c| c.bind(py))
}

/// `obj` as a numpy array (itself if it is one).
fn as_ndarray<'py>(obj: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    numpy(obj.py())?.call_method1("asarray", (obj,))
}

/// The dtype kind of `obj` as an array: `'f'`, `'i'`, `'O'`, …
fn dtype_kind(a: &Bound<'_, PyAny>) -> PyResult<char> {
    let kind: String = a.getattr("dtype")?.getattr("kind")?.extract()?;
    Ok(kind.chars().next().unwrap_or('?'))
}

/// Whether any of `objs` asks for exact arithmetic: a `Fraction`, or an array (or nested list)
/// of dtype `object`.
///
/// # Errors
/// What `numpy.asarray` raises.
pub fn any_exact(objs: &[&Bound<'_, PyAny>]) -> PyResult<bool> {
    for obj in objs {
        if obj.is_none() {
            continue;
        }
        let py = obj.py();
        if obj.is_instance(fraction_class(py)?)? {
            return Ok(true);
        }
        if obj.is_instance_of::<PyFloat>() || obj.extract::<i64>().is_ok() {
            continue;
        }
        if obj.is_instance_of::<PyString>() {
            return Ok(true);
        }
        if dtype_kind(&as_ndarray(obj)?)? == 'O' {
            return Ok(true);
        }
    }
    Ok(false)
}

/// The flat values and shape of `obj` as doubles.
fn float_values<'py>(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    if let Ok(a) = obj.cast::<PyArrayDyn<f64>>() {
        return Ok(a.clone());
    }
    let a = as_ndarray(obj)?;
    match dtype_kind(&a)? {
        'f' | 'i' | 'u' | 'b' => {}
        'O' => {
            // Fractions mixed with something else in doubles: read each element as a float.
            let floats = a
                .call_method1("astype", ("float64",))
                .map_err(|e| conversion(what, format!("not an array of real numbers ({e})")))?;
            return Ok(floats.cast_into::<PyArrayDyn<f64>>()?);
        }
        'c' => return Err(conversion(what, "complex numbers are not supported")),
        k => {
            return Err(conversion(
                what,
                format!("expected an array of real numbers, got dtype kind '{k}'"),
            ))
        }
    }
    let floats = a.call_method1("astype", ("float64",))?;
    Ok(floats.cast_into::<PyArrayDyn<f64>>()?)
}

impl Num for f64 {
    fn with_values<R>(
        obj: &Bound<'_, PyAny>,
        what: &str,
        f: impl FnOnce(&[usize], &[f64]) -> PyResult<R>,
    ) -> PyResult<R> {
        let a = float_values(obj, what)?;
        let shape = a.shape().to_vec();
        let ro = a.readonly();
        match ro.as_slice() {
            Ok(s) => f(&shape, s),
            Err(_) => {
                let v: Vec<f64> = ro.as_array().iter().copied().collect();
                f(&shape, &v)
            }
        }
    }

    fn scalar(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<f64> {
        obj.extract::<f64>().map_err(|_| {
            conversion(
                what,
                format!("expected a real number, got {}", type_name(obj)),
            )
        })
    }

    fn output<'py>(
        py: Python<'py>,
        shape: &[usize],
        fill: impl FnOnce(Python<'py>, &mut [f64]) -> PyResult<()>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let a = PyArrayDyn::<f64>::zeros(py, shape.to_vec(), false);
        {
            let mut rw = a.readwrite();
            fill(py, rw.as_slice_mut()?)?;
        }
        Ok(a.into_any())
    }

    fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(PyFloat::new(py, *self).into_any())
    }

    fn from_array<'py, D: Dimension>(
        py: Python<'py>,
        a: Array<f64, D>,
    ) -> PyResult<Bound<'py, PyAny>> {
        Ok(PyArray::from_owned_array(py, a).into_any())
    }
}

/// One element read exactly: `Fraction(x)`, a float by its shortest decimal.
fn exact_element(item: &Bound<'_, PyAny>, what: &str, index: usize) -> PyResult<BigRational> {
    let py = item.py();
    let fraction = fraction_class(py)?;
    let rational = py.import("numbers")?.getattr("Rational")?;
    let value = if item.is_instance(&rational)? || item.is_instance_of::<PyString>() {
        fraction.call1((item,))
    } else {
        let x: f64 = item.extract().map_err(|_| {
            conversion(
                what,
                format!("element {index} is not a real number ({})", type_name(item)),
            )
        })?;
        if !x.is_finite() {
            let (problem, expected) = cagd_ops::check::not_finite_at(index, &x);
            return Err(crate::error::worded("NonFinite", what, &problem, expected));
        }
        fraction.call1((PyFloat::new(py, x).repr()?,))
    };
    let value = value.map_err(|e| conversion(what, format!("element {index}: {e}")))?;
    value
        .extract::<BigRational>()
        .map_err(|e| conversion(what, format!("element {index}: {e}")))
}

impl Num for BigRational {
    fn with_values<R>(
        obj: &Bound<'_, PyAny>,
        what: &str,
        f: impl FnOnce(&[usize], &[BigRational]) -> PyResult<R>,
    ) -> PyResult<R> {
        let py = obj.py();
        let a = numpy(py)?.call_method1("asarray", (obj, "object"))?;
        let shape: Vec<usize> = a.getattr("shape")?.extract()?;
        let items = a.call_method0("ravel")?.call_method0("tolist")?;
        let mut values = Vec::with_capacity(shape.iter().product());
        for (k, item) in items.try_iter()?.enumerate() {
            values.push(exact_element(&item?, what, k)?);
        }
        f(&shape, &values)
    }

    fn scalar(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<BigRational> {
        exact_element(obj, what, 0)
    }

    fn output<'py>(
        py: Python<'py>,
        shape: &[usize],
        fill: impl FnOnce(Python<'py>, &mut [BigRational]) -> PyResult<()>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let mut values = vec![BigRational::default(); shape.iter().product()];
        fill(py, &mut values)?;
        object_array(py, shape, &values)
    }

    fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(self.clone().into_pyobject(py)?.into_any())
    }

    fn from_array<'py, D: Dimension>(
        py: Python<'py>,
        a: Array<BigRational, D>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let shape = a.shape().to_vec();
        let values: Vec<BigRational> = a.iter().cloned().collect();
        object_array(py, &shape, &values)
    }
}

/// An `object` array of `shape` holding `values` (row-major) as `Fraction`s.
fn object_array<'py>(
    py: Python<'py>,
    shape: &[usize],
    values: &[BigRational],
) -> PyResult<Bound<'py, PyAny>> {
    let np = numpy(py)?;
    let a = np.call_method1("empty", (values.len(), "object"))?;
    for (k, v) in values.iter().enumerate() {
        a.set_item(k, v.clone().into_pyobject(py)?)?;
    }
    a.call_method1("reshape", (shape.to_vec(),))
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "?".into())
}

/// Writes the points of a range into a block of the output.
pub type Fill<'a, T> = dyn Fn(Range<usize>, &mut [T]) -> cagd::Result<()> + Sync + 'a;

/// Runs `fill` over `out` (`points` blocks of `width` values) in chunks with the lock
/// released, checking for Ctrl-C between chunks. `fill(range, block)` writes the points
/// `range` into `block`.
///
/// # Errors
/// `fill`'s error; `KeyboardInterrupt`.
pub fn chunked<T: Num>(
    py: Python<'_>,
    out: &mut [T],
    width: usize,
    fill: &Fill<'_, T>,
) -> PyResult<()> {
    let points = out.len().checked_div(width).unwrap_or(0);
    if points == 0 {
        return py.detach(|| fill(0..0, out)).py();
    }
    let mut start = 0;
    for block in out.chunks_mut(CHUNK * width) {
        let end = start + block.len() / width;
        py.detach(|| fill(start..end, block)).py()?;
        py.check_signals()?;
        start = end;
    }
    Ok(())
}

/// An `(n, d)` array of points as rows (a 1-D array: `n` points of dimension 1) as the core's
/// `d × n` matrix of points as columns.
///
/// # Errors
/// A conversion error; `ShapeMismatch` for an array of another rank.
pub fn points_as_rows<T: Num>(obj: &Bound<'_, PyAny>, what: &'static str) -> PyResult<DMatrix<T>> {
    T::with_values(obj, what, |shape, v| match *shape {
        [n] => Ok(DMatrix::from_row_slice(1, n, v)),
        [n, d] => Ok(DMatrix::from_column_slice(d, n, v)),
        _ => Err(rank_error(what, "an (n, d) array of points as rows", shape)),
    })
}

/// A `(d, n)` array of points as columns (Octave's layout) as the core's `d × n` matrix.
///
/// # Errors
/// A conversion error; `ShapeMismatch` for an array of another rank.
pub fn points_as_columns<T: Num>(
    obj: &Bound<'_, PyAny>,
    what: &'static str,
) -> PyResult<DMatrix<T>> {
    T::with_values(obj, what, |shape, v| match *shape {
        [n] => Ok(DMatrix::from_row_slice(1, n, v)),
        [d, n] => Ok(DMatrix::from_row_slice(d, n, v)),
        _ => Err(rank_error(what, "a (d, n) matrix", shape)),
    })
}

/// Parameter values: any array (or a number), flattened row-major, with its shape.
///
/// # Errors
/// A conversion error.
pub fn params<T: Num>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<(Vec<usize>, Vec<T>)> {
    T::with_values(obj, what, |shape, v| Ok((shape.to_vec(), v.to_vec())))
}

/// The `ShapeMismatch` of an array of the wrong rank.
pub fn rank_error(what: &'static str, expected: &str, shape: &[usize]) -> PyErr {
    crate::error::to_py(cagd::Error::ShapeMismatch {
        what,
        expected: expected.to_string(),
        found: format!("an array of shape {shape:?}"),
    })
}

/// A `d × n` matrix as an `(n, d)` array of points as rows.
///
/// # Errors
/// `MemoryError`; conversion of a big integer.
pub fn rows_out<'py, T: Num>(py: Python<'py>, m: &DMatrix<T>) -> PyResult<Bound<'py, PyAny>> {
    T::output(py, &[m.ncols(), m.nrows()], |_, out| {
        out.clone_from_slice(m.as_slice());
        Ok(())
    })
}

/// A `d × n` matrix as a `(d, n)` array (Octave's layout).
///
/// # Errors
/// `MemoryError`; conversion of a big integer.
pub fn columns_out<'py, T: Num>(py: Python<'py>, m: &DMatrix<T>) -> PyResult<Bound<'py, PyAny>> {
    rows_out(py, m)?.getattr("T")
}

/// A vector as a 1-D array.
///
/// # Errors
/// `MemoryError`; conversion of a big integer.
pub fn vector_out<'py, T: Num>(py: Python<'py>, v: &[T]) -> PyResult<Bound<'py, PyAny>> {
    T::output(py, &[v.len()], |_, out| {
        out.clone_from_slice(v);
        Ok(())
    })
}

/// A `(rows, cols, d)` array as `d` coordinate matrices.
pub fn net_in<T: Num>(obj: &Bound<'_, PyAny>, what: &'static str) -> PyResult<Vec<DMatrix<T>>> {
    T::with_values(obj, what, |shape, v| match *shape {
        [rows, cols, d] => Ok((0..d)
            .map(|c| DMatrix::from_fn(rows, cols, |i, j| v[(i * cols + j) * d + c].clone()))
            .collect()),
        _ => Err(rank_error(what, "an (m+1, n+1, d) array of points", shape)),
    })
}

/// A `(rows, cols, d)` array as the core's grid of points (the same row-major layout).
pub fn grid_in<T: Num>(obj: &Bound<'_, PyAny>, what: &'static str) -> PyResult<PointGrid<T>> {
    T::with_values(obj, what, |shape, v| match *shape {
        [rows, cols, d] => PointGrid::from_vec((rows, cols, d), v.to_vec())
            .ok_or_else(|| rank_error(what, "an (m+1, n+1, d) array of points", shape)),
        _ => Err(rank_error(what, "an (m+1, n+1, d) array of points", shape)),
    })
}

/// A grid of points as a `(rows, cols, d)` array.
///
/// # Errors
/// `MemoryError`; conversion of a big integer.
pub fn grid_out<'py, T: Num>(py: Python<'py>, g: &PointGrid<T>) -> PyResult<Bound<'py, PyAny>> {
    let (rows, cols, d) = g.dim();
    T::output(py, &[rows, cols, d], |_, out| {
        out.clone_from_slice(g.as_slice());
        Ok(())
    })
}

/// `d` coordinate matrices as a `(rows, cols, d)` array.
pub fn net_out<'py, T: Num>(py: Python<'py>, coords: &[DMatrix<T>]) -> PyResult<Bound<'py, PyAny>> {
    let (rows, cols) = coords.first().map_or((0, 0), |m| (m.nrows(), m.ncols()));
    let d = coords.len();
    T::output(py, &[rows, cols, d], |_, out| {
        for (c, m) in coords.iter().enumerate() {
            for i in 0..rows {
                for j in 0..cols {
                    out[(i * cols + j) * d + c] = m[(i, j)].clone();
                }
            }
        }
        Ok(())
    })
}
