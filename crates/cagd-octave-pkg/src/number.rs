//! Doubles and exact fractions: the two kinds of numbers a native function computes in.
//!
//! **Exact results.** A native function whose mathematics is rational (Bézier curves and
//! patches, Coons and Gordon patches at rational parameters, B-splines, NURBS, interpolating
//! splines, Hermite cubics, the conversions, Bernstein values) takes the option `"exact"` as its
//! last argument. It then computes in exact rationals and returns, in place of each numeric
//! array, a **cell array of strings of the same size**, each an exact fraction in lowest terms:
//! `"7/2"`, `"-3"`, `"0"`. Inputs are read as a person typed them:
//! - a double is read as the shortest decimal that gives it back (`0.2` is 1/5, not the double
//!   nearest to it; `1/3` typed in Octave is `0.3333333333333333`, so pass the text instead);
//! - text is an Octave expression read in exact arithmetic: `"[0 1/3 1]"`, `"1/3"`,
//!   `"0:0.1:1"` (ranges of exact steps), `"[0 0 8 4; 0 2 2 0; 0 2 0 0]"`.
//!
//! `str2num` or `cellfun (@str2num, X)` turns the strings back into doubles.

use cagd::exact::rational_from_decimal;
use cagd_octave::literal::{parse_matrix_with, parse_params_with, LiteralScalar};
use nalgebra::DMatrix;
use num_rational::BigRational;

use crate::args::{matrix_of, Call};
use crate::error::{Kind, PkgError, Result};
use crate::value::{Sink, Value};
use cagd::limits::Limits;

/// `f64` or an exact rational, with the package's input and output conventions.
///
/// Whether it is the exact arithmetic is [`cagd::Scalar::EXACT`].
pub trait Number: cagd::Scalar + LiteralScalar {
    /// An Octave double as this number: itself, or the shortest decimal that gives it back.
    fn from_input(x: f64) -> Self;

    /// Output `index`: a real array of size `dims` (doubles), or a cell array of exact
    /// fractions of that size (rationals). `values` are column-major.
    ///
    /// # Errors
    /// [`Kind::Memory`].
    fn emit(sink: &mut dyn Sink, index: usize, dims: &[usize], values: &[Self]) -> Result<()>;

    /// Output `index` of size `dims`, its values (column-major) written by `fill`: doubles
    /// straight into Octave's array, rationals into a vector turned into fractions.
    ///
    /// # Errors
    /// [`Kind::Memory`]; `fill`'s error.
    fn emit_with(
        sink: &mut dyn Sink,
        index: usize,
        dims: &[usize],
        fill: &mut dyn FnMut(&mut [Self]) -> cagd::Result<()>,
    ) -> Result<()> {
        let mut values = vec![Self::zero(); dims.iter().product()];
        fill(&mut values)?;
        Self::emit(sink, index, dims, &values)
    }
}

impl Number for f64 {
    fn from_input(x: f64) -> Self {
        x
    }

    fn emit(sink: &mut dyn Sink, index: usize, dims: &[usize], values: &[f64]) -> Result<()> {
        sink.real(index, dims)?.copy_from_slice(values);
        Ok(())
    }

    fn emit_with(
        sink: &mut dyn Sink,
        index: usize,
        dims: &[usize],
        fill: &mut dyn FnMut(&mut [f64]) -> cagd::Result<()>,
    ) -> Result<()> {
        Ok(fill(sink.real(index, dims)?)?)
    }
}

impl Number for BigRational {
    fn from_input(x: f64) -> Self {
        // `{:e}` prints the shortest digits that read back to `x`; the readers have refused
        // NaN and ±Inf before.
        rational_from_decimal(&format!("{x:e}"))
            .ok()
            .or_else(|| <BigRational as cagd::Scalar>::from_f64(x))
            .unwrap_or_default()
    }

    fn emit(sink: &mut dyn Sink, index: usize, dims: &[usize], values: &[Self]) -> Result<()> {
        let items: Vec<String> = values.iter().map(ToString::to_string).collect();
        sink.strings(index, dims, &items)
    }
}

/// Argument `i` as a non-empty matrix: a real array, or in exact arithmetic also an Octave
/// expression such as `"[0 1/3; 1 2]"`.
///
/// # Errors
/// As [`Call::matrix`]; a text that does not parse is a [`Kind::Value`].
pub fn matrix<T: Number>(
    call: &Call<'_, '_>,
    i: usize,
    what: &'static str,
    form: &str,
) -> Result<DMatrix<T>> {
    matrix_value(call.arg(i), what, form, &call.limits)
}

/// A value as a non-empty matrix (see [`matrix`]).
///
/// # Errors
/// As [`matrix`].
pub fn matrix_value<T: Number>(
    v: &Value<'_>,
    what: &'static str,
    form: &str,
    limits: &Limits,
) -> Result<DMatrix<T>> {
    if <T as cagd::Scalar>::EXACT {
        if let Some(text) = v.text() {
            let m: DMatrix<T> = parse_matrix_with(&text, limits)
                .map_err(|e| PkgError::arg(Kind::Value, what, e.to_string(), form))?;
            if m.is_empty() {
                return Err(PkgError::arg(
                    Kind::Empty,
                    what,
                    format!("empty ({}×{})", m.nrows(), m.ncols()),
                    form,
                ));
            }
            return Ok(m);
        }
    }
    Ok(matrix_of(v, what, form)?.map(T::from_input))
}

/// Argument `i` as parameter values (any real array, column-major; in exact arithmetic also a
/// text such as `"1/3"`, `"[0 1/3 1]"` or `"0:1/4:1"`).
///
/// # Errors
/// As [`Call::params`]; a text that does not parse is a [`Kind::Value`].
pub fn params<T: Number>(call: &Call<'_, '_>, i: usize, what: &'static str) -> Result<Vec<T>> {
    if <T as cagd::Scalar>::EXACT {
        if let Some(text) = call.arg(i).text() {
            return parse_params_with(&text, &call.limits)
                .map_err(|e| PkgError::arg(Kind::Value, what, e.to_string(), "parameter values"));
        }
    }
    Ok(call
        .params(i, what)?
        .iter()
        .map(|&x| T::from_input(x))
        .collect())
}

/// Argument `i` as one value (a real scalar; in exact arithmetic also a text such as `"1/3"`).
///
/// # Errors
/// As [`Call::scalar`].
pub fn scalar<T: Number>(call: &Call<'_, '_>, i: usize, what: &'static str) -> Result<T> {
    if <T as cagd::Scalar>::EXACT && matches!(call.arg(i), Value::Char { .. }) {
        let v = params::<T>(call, i, what)?;
        if v.len() != 1 {
            return Err(PkgError::arg(
                Kind::Shape,
                what,
                format!("{} values", v.len()),
                "one value",
            ));
        }
        return Ok(v.into_iter().next().expect("one value"));
    }
    Ok(T::from_input(call.scalar(i, what)?))
}

/// Output `index`: the matrix `m` (`rows × cols`).
///
/// # Errors
/// [`Kind::Memory`].
pub fn emit_matrix<T: Number>(sink: &mut dyn Sink, index: usize, m: &DMatrix<T>) -> Result<()> {
    T::emit(sink, index, &[m.nrows(), m.ncols()], m.as_slice())
}

/// Output `index`: a grid held row-major as `(nu, nv, d)` (the core's layout) written as
/// Octave's `d × nu × nv` array (octave-nurbs' layout: `X(:, i, j)` is the point at
/// `(u(i), v(j))`).
///
/// # Errors
/// [`Kind::Memory`].
pub fn emit_grid<T: Number>(
    sink: &mut dyn Sink,
    index: usize,
    (nu, nv, d): (usize, usize, usize),
    grid: &[T],
) -> Result<()> {
    let mut values = Vec::with_capacity(grid.len());
    for b in 0..nv {
        for a in 0..nu {
            values.extend_from_slice(&grid[(a * nv + b) * d..(a * nv + b + 1) * d]);
        }
    }
    T::emit(sink, index, &[d, nu, nv], &values)
}
