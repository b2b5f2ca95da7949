//! `cagd.Steps`: the steps of a construction as the core gives them — named intermediate
//! values (the levels of a de Casteljau or de Boor scheme, the parts `r_c`, `r_d`, `r_cd` of a
//! Coons point, `g1`, `g2`, `g12` of a Gordon point) and, where the core formats the scheme
//! itself, its text.

use pyo3::prelude::*;
use pyo3::types::PyList;

/// The steps of one construction: `items` is a list of `(name, value)` pairs (values are
/// arrays, points as rows, or numbers); `str()` is the core's own text of the scheme where it
/// has one. In Jupyter it shows as a table.
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

/// Registers `Steps`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Steps>()
}
