//! What the classes share: the two arithmetics, evaluation in batches, points in and out,
//! the methods every curve and surface class has.

use cagd::param::{Curve, Surface};
use nalgebra::DVector;
use num_rational::BigRational;
use pyo3::prelude::*;

use cagd_ops::Role;

use crate::convert::{chunked, params, Num};
use crate::ops::{checked, Names};

/// How evaluations name their parameters.
const EVAL_NAMES: Names = &[
    (Role::T, "t"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
];

/// A core object in doubles or in exact rationals.
#[derive(Clone, Debug)]
pub enum Ex<F, E> {
    /// In doubles.
    F(F),
    /// In exact rationals.
    E(E),
}

/// `$body` with `$c` bound to the core object, whichever arithmetic it is in.
macro_rules! on {
    ($inner:expr, $c:ident => $body:expr) => {
        match &$inner {
            $crate::classes::shared::Ex::F($c) => $body,
            $crate::classes::shared::Ex::E($c) => $body,
        }
    };
}
pub(crate) use on;

/// `Ex::F(f::<f64>(…))` or `Ex::E(f::<BigRational>(…))` by `exact`.
macro_rules! build {
    ($exact:expr, $f:ident ( $($arg:expr),* )) => {
        if $exact {
            $crate::classes::shared::Ex::E($f::<num_rational::BigRational>($($arg),*)?)
        } else {
            $crate::classes::shared::Ex::F($f::<f64>($($arg),*)?)
        }
    };
}
pub(crate) use build;

/// The methods every curve class shares, from the core's [`Curve`] trait: `c(t)`, `dim`,
/// `domain`, `exact`, `repr`, and the pictures in Jupyter.
macro_rules! curve_methods {
    ($ty:ident, $name:literal) => {
        #[pyo3::pymethods]
        impl $ty {
            /// The points at `t`: a number gives one point `(d,)`, an array of shape `S` gives
            /// `S + (d,)` (outside the domain the curve continues, as the core's `eval`).
            fn __call__<'py>(
                &self,
                t: &pyo3::Bound<'py, pyo3::PyAny>,
            ) -> pyo3::PyResult<pyo3::Bound<'py, pyo3::PyAny>> {
                $crate::classes::shared::on!(self.inner, c => $crate::classes::shared::eval_curve(c, t))
            }

            /// The dimension `d` of the points.
            #[getter]
            fn dim(&self) -> usize {
                $crate::classes::shared::on!(self.inner, c => cagd::Curve::dim(c))
            }

            /// The parameter domain `(a, b)`.
            #[getter]
            fn domain<'py>(&self, py: pyo3::Python<'py>) -> pyo3::PyResult<$crate::classes::shared::Pair<'py>> {
                $crate::classes::shared::on!(self.inner, c => $crate::classes::shared::pair_out(py, cagd::Curve::domain(c)))
            }

            /// Whether the object computes in exact rationals.
            #[getter]
            fn exact(&self) -> bool {
                matches!(self.inner, $crate::classes::shared::Ex::E(_))
            }

            fn __repr__(&self) -> String {
                let kind = if self.exact() { "exact" } else { "float" };
                format!("{}(dim={}, {kind})", $name, self.dim())
            }

            /// A picture (SVG) of the curve with its control polygon.
            fn _repr_svg_(slf: &pyo3::Bound<'_, Self>) -> pyo3::PyResult<String> {
                $crate::classes::shared::display(slf, "curve_svg")
            }

            /// The control points (exact fractions as written) and the picture.
            fn _repr_html_(slf: &pyo3::Bound<'_, Self>) -> pyo3::PyResult<String> {
                $crate::classes::shared::display(slf, "object_html")
            }
        }
    };
}
pub(crate) use curve_methods;

/// The methods every surface class shares, from the core's [`Surface`] trait: `s(u, v)` on a
/// grid, `dim`, `domain`, `exact`, `repr`, and the pictures in Jupyter.
macro_rules! surface_methods {
    ($ty:ident, $name:literal) => {
        #[pyo3::pymethods]
        impl $ty {
            /// The surface on the grid `u × v`, `(len(u), len(v), d)`; numbers give one point
            /// `(d,)`.
            fn __call__<'py>(
                &self,
                u: &pyo3::Bound<'py, pyo3::PyAny>,
                v: &pyo3::Bound<'py, pyo3::PyAny>,
            ) -> pyo3::PyResult<pyo3::Bound<'py, pyo3::PyAny>> {
                $crate::classes::shared::on!(self.inner, s => $crate::classes::shared::eval_surface(s, u, v))
            }

            /// The dimension `d` of the points.
            #[getter]
            fn dim(&self) -> usize {
                $crate::classes::shared::on!(self.inner, s => cagd::Surface::dim(s))
            }

            /// The parameter domain `((u0, u1), (v0, v1))`.
            #[getter]
            fn domain<'py>(
                &self,
                py: pyo3::Python<'py>,
            ) -> pyo3::PyResult<($crate::classes::shared::Pair<'py>, $crate::classes::shared::Pair<'py>)> {
                $crate::classes::shared::on!(self.inner, s => {
                    let (u, v) = cagd::Surface::domain(s);
                    Ok(($crate::classes::shared::pair_out(py, u)?, $crate::classes::shared::pair_out(py, v)?))
                })
            }

            /// Whether the object computes in exact rationals.
            #[getter]
            fn exact(&self) -> bool {
                matches!(self.inner, $crate::classes::shared::Ex::E(_))
            }

            fn __repr__(&self) -> String {
                let kind = if self.exact() { "exact" } else { "float" };
                format!("{}(dim={}, {kind})", $name, self.dim())
            }

            /// A picture (SVG): eleven lines of the surface each way, with its control net.
            fn _repr_svg_(slf: &pyo3::Bound<'_, Self>) -> pyo3::PyResult<String> {
                $crate::classes::shared::display(slf, "surface_svg")
            }

            /// The control net (exact fractions as written) and the picture.
            fn _repr_html_(slf: &pyo3::Bound<'_, Self>) -> pyo3::PyResult<String> {
                $crate::classes::shared::display(slf, "object_html")
            }
        }
    };
}
pub(crate) use surface_methods;

/// A pair of Python numbers.
pub type Pair<'py> = (Bound<'py, PyAny>, Bound<'py, PyAny>);

/// What `cagd._display.<function>(obj)` draws or writes for Jupyter.
pub fn display<T: pyo3::PyClass>(obj: &Bound<'_, T>, function: &str) -> PyResult<String> {
    obj.py()
        .import("cagd._display")?
        .call_method1(function, (obj,))?
        .extract()
}

/// The error for objects of both arithmetics in one construction.
pub fn mixed(what: &str) -> PyErr {
    crate::error::conversion(
        what,
        "mixes exact and float curves: build all of them exact (or all in floats)",
    )
}

/// Whether a constructor computes exactly: `exact=True`/`False` as given, else as the
/// arguments are ([`crate::convert::any_exact`]).
pub fn exactness(exact: Option<bool>, objs: &[&Bound<'_, PyAny>]) -> PyResult<bool> {
    match exact {
        Some(e) => Ok(e),
        None => crate::convert::any_exact(objs),
    }
}

/// The curve at the parameters `t` (a number: one point `(d,)`; an array of shape `S`:
/// `S + (d,)`), by the core's batch evaluation, in chunks that Ctrl-C can stop.
pub fn eval_curve<'py, T: Num, C: Curve<T> + Sync + ?Sized>(
    c: &C,
    t: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    // The parameters are read in place (float64, contiguous) and the points written straight
    // into the array returned.
    T::with_values(t, "t", |shape, ts| {
        checked(EVAL_NAMES, |_| cagd_ops::check::finite(Role::T, ts))?;
        let d = c.dim();
        let mut out_shape = shape.to_vec();
        out_shape.push(d);
        T::output(t.py(), &out_shape, |py, out| {
            chunked(py, out, d, &|range, block| {
                c.eval_many_into(&ts[range], block)
            })
        })
    })
}

/// The surface on the grid `u × v` (`(len(u), len(v), d)`), by the core's grid evaluation,
/// row chunks that Ctrl-C can stop. Numbers for `u` and `v` give one point `(d,)`.
pub fn eval_surface<'py, T: Num, S: Surface<T> + Sync + ?Sized>(
    s: &S,
    u: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let (su, us) = params::<T>(u, "u")?;
    let (sv, vs) = params::<T>(v, "v")?;
    let d = s.dim();
    checked(EVAL_NAMES, |cx| {
        cagd_ops::check::finite(Role::U, &us)?;
        cagd_ops::check::finite(Role::V, &vs)?;
        cx.check_grid(Role::Grid, us.len(), vs.len())
    })?;
    let row = vs.len() * d;
    let shape = if su.is_empty() && sv.is_empty() {
        vec![d]
    } else {
        vec![us.len(), vs.len(), d]
    };
    T::output(u.py(), &shape, |py, out| {
        chunked(py, out, row, &|range, block| {
            s.eval_grid_into(&us[range], &vs, block)
        })
    })
}

/// A point as a 1-D array.
pub fn point_out<'py, T: Num>(py: Python<'py>, p: &DVector<T>) -> PyResult<Bound<'py, PyAny>> {
    crate::convert::vector_out(py, p.as_slice())
}

/// A pair of numbers as a tuple.
pub fn pair_out<'py, T: Num>(py: Python<'py>, (a, b): (T, T)) -> PyResult<Pair<'py>> {
    Ok((a.to_py(py)?, b.to_py(py)?))
}

/// `BigRational` and `f64` are the two arithmetics.
pub type Exact = BigRational;
