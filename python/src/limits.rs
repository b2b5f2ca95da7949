//! `cagd.limits()` and `cagd.set_limit(name, value)`: the core's resource limits
//! ([`cagd::limits::Limits`]) for this interpreter, one value passed to every call (the core
//! reads no global setting; this module holds the value the Python calls pass).

use std::sync::Mutex;

use cagd::limits::{Limit, Limits};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::error::conversion;

static LIMITS: Mutex<Option<Limits>> = Mutex::new(None);

/// The limits in force.
pub fn current() -> Limits {
    let guard = LIMITS.lock().unwrap_or_else(|e| e.into_inner());
    (*guard).unwrap_or_default()
}

/// The limits in force, by name (`max_samples`, `max_grid_points`, `max_degree`, `max_work`, …).
///
/// >>> cagd.limits()["max_degree"]
/// 1000
#[pyfunction]
fn limits(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let l = current();
    let out = PyDict::new(py);
    for limit in Limit::ALL {
        out.set_item(limit.field(), l.get(limit))?;
    }
    Ok(out)
}

/// Sets the limit `name` (a key of `cagd.limits()`) to `value` (a positive integer); with no
/// arguments, restores the defaults.
///
/// >>> cagd.set_limit("max_degree", 2)
/// >>> cagd.BezierCurve([[0], [1], [2], [3]])
/// Traceback (most recent call last):
///     ...
/// cagd.CagdError: points: degree: 3 exceeds the limit of 2 (raise it with cagd.set_limit("max_degree", VALUE)); expected ...
/// >>> cagd.set_limit()
/// >>> cagd.limits()["max_degree"]
/// 1000
#[pyfunction]
#[pyo3(signature = (name = None, value = None))]
fn set_limit(name: Option<&str>, value: Option<u64>) -> PyResult<()> {
    let mut guard = LIMITS.lock().unwrap_or_else(|e| e.into_inner());
    let (name, value) = match (name, value) {
        (None, None) => {
            *guard = None;
            return Ok(());
        }
        (Some(n), Some(v)) if v > 0 => (n, v),
        _ => {
            return Err(conversion(
                "value",
                "expected a name and a positive integer",
            ))
        }
    };
    let Some(limit) = Limit::ALL.into_iter().find(|l| l.field() == name) else {
        let names: Vec<&str> = Limit::ALL.iter().map(|l| l.field()).collect();
        return Err(conversion(
            "name",
            format!("no limit '{name}' (one of {})", names.join(", ")),
        ));
    };
    guard.get_or_insert_with(Limits::default).set(limit, value);
    Ok(())
}

/// Registers `limits` and `set_limit`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(limits, m)?)?;
    m.add_function(wrap_pyfunction!(set_limit, m)?)?;
    Ok(())
}
