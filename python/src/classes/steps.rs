//! `cagd.Steps`: the steps of a construction as the core and the operation layer give them —
//! named intermediate values (the levels of a de Casteljau or de Boor scheme, Boehm's `α`, a
//! spline's system, the parts `r_c`, `r_d`, `r_cd` of a Coons point, …) and, where they lay a
//! scheme out as text, that text.
//!
//! A request's steps ([`from_report`]) are the items of its report as the command line prints
//! them with `--steps`: the same names (a record's parts as `name.part`), the same numbers
//! (spans and indices counted from 1), laid out the Python way — a matrix of points as rows,
//! a row of knots or parameters as a 1-D array, a count as an `int`.
//!
//! An object made by a construction that has steps keeps the way to them ([`StepsOf`]): its
//! `steps` are computed when asked for (and shown with the object in Jupyter).

use std::sync::Arc;

use cagd_ops::{Operation, Report, Value};
use nalgebra::DMatrix;
use pyo3::prelude::*;
use pyo3::types::PyList;

use crate::convert::{grid_out, rows_out, vector_out, Num};
use crate::ops::{execute, Names};

/// The steps of one construction: `items` is a list of `(name, value)` pairs (values are
/// arrays, points as rows, or numbers); `str()` is the core's own text of the scheme where it
/// has one. In Jupyter it shows as a table.
///
/// >>> s = cagd.BezierCurve([[0], [1], [3]], exact=True).scheme(Fraction(1, 2))
/// >>> s.title, len(s), [name for name, _ in s.items]
/// ('de Casteljau scheme', 4, ['r = 0', 'r = 1', 'r = 2', 'point'])
/// >>> s["r = 1"].tolist(), s["point"].tolist()
/// ([[Fraction(1, 2)], [Fraction(2, 1)]], [Fraction(5, 4)])
// The doc comment is the class's Python docstring: its examples index arrays and print lists
// (`[1]`, `[[0], [1]]`), which are no Rust links.
#[allow(rustdoc::broken_intra_doc_links)]
#[pyclass(module = "cagd", name = "Steps", frozen)]
pub struct Steps {
    title: String,
    text: Option<String>,
    items: Vec<(String, Py<PyAny>)>,
}

impl Steps {
    /// Steps titled `title` with the core's text `text` (if any) and the named values.
    pub fn new(
        title: impl Into<String>,
        text: Option<String>,
        items: Vec<(String, Py<PyAny>)>,
    ) -> Self {
        Steps {
            title: title.into(),
            text,
            items,
        }
    }
}

#[pymethods]
impl Steps {
    /// What was computed.
    #[getter]
    fn title(&self) -> &str {
        &self.title
    }

    /// The `(name, value)` pairs, in the order they are computed.
    #[getter]
    fn items<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        PyList::new(
            py,
            self.items.iter().map(|(n, v)| (n.clone(), v.clone_ref(py))),
        )
    }

    /// The value named `name`.
    fn __getitem__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyAny>> {
        self.items
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.clone_ref(py))
            .ok_or_else(|| pyo3::exceptions::PyKeyError::new_err(name.to_string()))
    }

    fn __len__(&self) -> usize {
        self.items.len()
    }

    fn __str__(&self, py: Python<'_>) -> PyResult<String> {
        if let Some(t) = &self.text {
            return Ok(t.clone());
        }
        let mut out = self.title.clone();
        for (n, v) in &self.items {
            out.push_str(&format!("\n{n} = {}", v.bind(py).str()?));
        }
        Ok(out)
    }

    fn __repr__(&self) -> String {
        let names: Vec<&str> = self.items.iter().map(|(n, _)| n.as_str()).collect();
        format!("<Steps {}: {}>", self.title, names.join(", "))
    }

    /// A table of the values (exact fractions as written), for Jupyter.
    fn _repr_html_(&self, py: Python<'_>) -> PyResult<String> {
        let display = py.import("cagd._display")?;
        display
            .call_method1(
                "steps_html",
                (self.title.clone(), self.text.clone(), self.items(py)?),
            )?
            .extract()
    }
}

/// How an object computes the steps of the construction that made it, when asked.
pub type StepsOf = Arc<dyn Fn(Python<'_>) -> PyResult<Steps> + Send + Sync>;

/// The `steps` of an object: `None` when it was not made by a construction with steps.
///
/// # Errors
/// The construction's errors (a limit the steps exceed).
pub fn steps_of(py: Python<'_>, of: Option<&StepsOf>) -> PyResult<Option<Steps>> {
    of.map(|f| f(py)).transpose()
}

/// The steps of the request `op` (run with its steps asked for) when they are asked for:
/// every item of its report but those named in `skip`.
pub fn request_steps<T, O>(
    op: O,
    names: Names,
    title: String,
    skip: &'static [&'static str],
) -> StepsOf
where
    T: Num,
    O: Operation<T> + Send + Sync + 'static,
{
    Arc::new(move |py| from_report(py, &title, &execute(py, names, &op)?, skip))
}

/// A getter `steps` for a class whose field `steps` is an `Option<StepsOf>`.
macro_rules! steps_getter {
    ($ty:ident) => {
        #[pyo3::pymethods]
        impl $ty {
            /// The steps of the construction that made this object (`None` if it was given
            /// directly): computed when asked for, shown with the object in Jupyter.
            #[getter]
            fn steps(
                &self,
                py: pyo3::Python<'_>,
            ) -> pyo3::PyResult<Option<$crate::classes::steps::Steps>> {
                $crate::classes::steps::steps_of(py, self.steps.as_ref())
            }
        }
    };
}
pub(crate) use steps_getter;

/// Names of report rows that are lists of numbers (knots, parameters, weights, `α`).
const VECTORS: &[&str] = &[
    "t",
    "u",
    "knots",
    "knots_before",
    "weights",
    "params",
    "alpha",
];

/// Names of report values that are counts (printed as integers).
const COUNTS: &[&str] = &["span", "degree"];

/// Names of report matrices that are tables, not points (a row per parameter or equation).
const TABLES: &[&str] = &["basis", "system", "hermite_basis", "coefficients"];

/// A report matrix named `leaf` the Python way: a count as an `int`, a row of numbers as a
/// 1-D array, a table as it is, points (`d × k`, one per column) as rows `(k, d)`.
fn matrix_out<'py, T: Num>(
    py: Python<'py>,
    leaf: &str,
    m: &DMatrix<T>,
) -> PyResult<Bound<'py, PyAny>> {
    let vector = VECTORS.contains(&leaf) || leaf.starts_with("alpha");
    if COUNTS.contains(&leaf) && m.len() == 1 {
        return Ok((m[0].to_f64() as i64).into_pyobject(py)?.into_any());
    }
    if vector && m.nrows() == 1 {
        return vector_out(py, m.as_slice());
    }
    if TABLES.contains(&leaf) || vector {
        return rows_out(py, &m.transpose());
    }
    rows_out(py, m)
}

/// The items of `value` named `name`, records flattened to `name.part` (the command line's
/// names), texts of laid-out schemes collected into `texts`.
fn flatten<T: Num>(
    py: Python<'_>,
    name: String,
    value: &Value<T>,
    out: &mut Vec<(String, Py<PyAny>)>,
    texts: &mut Vec<String>,
) -> PyResult<()> {
    let leaf = name.rsplit('.').next().unwrap_or(&name).to_string();
    let item = match value {
        Value::Matrix(m) => matrix_out(py, &leaf, m)?,
        Value::Grid(g) => grid_out(py, g)?,
        Value::Text(t) => t.clone().into_pyobject(py)?.into_any(),
        Value::Record(items) => {
            for i in items {
                let part = if name.is_empty() {
                    i.name.clone()
                } else {
                    format!("{name}.{}", i.name)
                };
                flatten(py, part, &i.value, out, texts)?;
            }
            return Ok(());
        }
        Value::Shown { text, data } => {
            texts.push(text.trim_end().to_string());
            return flatten(py, name, data, out, texts);
        }
    };
    out.push((name, item.unbind()));
    Ok(())
}

/// The steps of a request's report: every item but those named in `skip`, in order.
///
/// # Errors
/// `MemoryError`; conversion of a big integer.
pub fn from_report<T: Num>(
    py: Python<'_>,
    title: &str,
    report: &Report<T>,
    skip: &[&str],
) -> PyResult<Steps> {
    let (mut items, mut texts) = (Vec::new(), Vec::new());
    for item in report
        .items
        .iter()
        .filter(|i| !skip.contains(&i.name.as_str()))
    {
        flatten(py, item.name.clone(), &item.value, &mut items, &mut texts)?;
    }
    let text = (!texts.is_empty()).then(|| texts.join("\n\n"));
    Ok(Steps::new(title, text, items))
}

/// The steps of the record `name` of a report, its parts unprefixed, then the items `more`.
///
/// # Errors
/// As [`from_report`].
pub fn from_record<T: Num>(
    py: Python<'_>,
    title: &str,
    report: &Report<T>,
    name: &str,
    more: &[&str],
) -> PyResult<Steps> {
    let (mut items, mut texts) = (Vec::new(), Vec::new());
    if let Some(value) = report.get(name) {
        flatten(py, String::new(), value, &mut items, &mut texts)?;
    }
    for item in report
        .items
        .iter()
        .filter(|i| more.contains(&i.name.as_str()))
    {
        flatten(py, item.name.clone(), &item.value, &mut items, &mut texts)?;
    }
    let text = (!texts.is_empty()).then(|| texts.join("\n\n"));
    Ok(Steps::new(title, text, items))
}

/// Registers `Steps`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Steps>()
}
