//! The Python package `cagd` (`import cagd`), a thin front end over the core crate `cagd` and
//! the operation layer `cagd-ops`: Python values are translated into the core's types
//! ([`convert`]), the operation layer checks them and runs its requests ([`ops`]), the core
//! computes, errors become `cagd.CagdError` ([`error`]). No mathematics, checks or wording of
//! its own: every rule is the operation layer's or the core's.
//!
//! - [`octave`]: the eight thesis functions with the layouts of `octave_ref/fixed/`;
//! - [`limits`]: the core's resource limits for the interpreter;
//! - [`classes`]: the course's classes (points as rows), exact with `Fraction`s, with steps;
//! - [`scipy_bspline`]: the core calls behind `cagd.BSpline`, scipy's `BSpline` drop-in;
//!
//! Built with maturin (`pip install ./python`), one abi3 wheel for CPython ≥ 3.9.

use pyo3::prelude::*;

pub mod classes;
pub mod convert;
pub mod error;
pub mod limits;
pub mod octave;
pub mod ops;
pub mod scipy_bspline;

/// The extension module `cagd._cagd`; `cagd/__init__.py` arranges its names.
#[pymodule]
fn _cagd(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("CagdError", m.py().get_type::<error::CagdError>())?;
    let sub = PyModule::new(m.py(), "octave")?;
    octave::register(&sub)?;
    m.add_submodule(&sub)?;
    limits::register(m)?;
    scipy_bspline::register(m)?;
    classes::register(m)?;
    Ok(())
}
