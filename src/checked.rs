//! The checks every fallible evaluation of the crate makes, in one place: the parameters
//! (NaN, ±∞, the domain), the work of one point against [`Limits::DEFAULT`], and the point
//! itself — its dimension (a user's curve may return a point of another dimension) and that
//! every coordinate is finite ([`Error::Overflow`] otherwise: finite control points can still
//! give `1.7e308 + 1.7e308`).
//!
//! The trait methods `Curve::try_eval`, `Curve::eval_many_into`, `Surface::try_eval` and
//! `Surface::eval_grid_into` of every curve and surface of the crate go through these (their
//! grid kernels check each block of rows as they write it: [`crate::grid`]); a type outside
//! the crate gets the trait's defaults.

use nalgebra::DVector;

use crate::cost::Cost;
use crate::error::{check_finite, check_overflow, Error, Result};
use crate::limits::Limits;
use crate::param::{check_parameter, Curve, Surface};
use crate::scalar::Scalar;

/// `point` if it has `dim` coordinates, all finite.
///
/// # Errors
/// [`Error::ShapeMismatch`] for another number of coordinates, [`Error::Overflow`] for a
/// non-finite one.
pub(crate) fn point<T: Scalar>(what: &'static str, dim: usize, point: DVector<T>) -> Result<DVector<T>> {
    if point.len() != dim {
        return Err(Error::ShapeMismatch {
            what,
            expected: format!("{dim} coordinates"),
            found: format!("{} coordinates", point.len()),
        });
    }
    check_overflow(what, point.iter())?;
    Ok(point)
}

/// The work of one point, `cost`, against [`Limits::DEFAULT`]`.max_work` (weighed as exact
/// arithmetic for rationals): what keeps a `try_eval` of a degree-100 000 curve (10¹⁰
/// operations per point) from running for minutes.
///
/// # Errors
/// [`Error::TooLarge`] (limit `Work`) above the limit.
pub(crate) fn point_work<T: Scalar>(what: &'static str, cost: Cost) -> Result<()> {
    Limits::DEFAULT.check_work(what, cost.weigh(crate::grid::exact::is_rational::<T>()))
}

/// What `Curve::try_eval` does for the crate's curves: the parameter checked against the
/// domain, the curve evaluated, the point checked ([`point`]).
///
/// # Errors
/// [`Error::NonFinite`], [`Error::ParameterOutOfRange`], and those of [`point`].
pub(crate) fn try_eval_curve<T: Scalar, C: Curve<T> + ?Sized>(
    curve: &C,
    what: &'static str,
    t: T,
) -> Result<DVector<T>> {
    check_parameter(what, &t, &curve.domain())?;
    point(what, curve.dim(), curve.eval(t))
}

/// What `Surface::try_eval` does for the crate's surfaces, as [`try_eval_curve`].
///
/// # Errors
/// As [`try_eval_curve`], for either parameter.
pub(crate) fn try_eval_surface<T: Scalar, S: Surface<T> + ?Sized>(
    surface: &S,
    what: &'static str,
    u: T,
    v: T,
) -> Result<DVector<T>> {
    let (du, dv) = surface.domain();
    check_parameter(what, &u, &du)?;
    check_parameter(what, &v, &dv)?;
    point(what, surface.dim(), surface.eval(u, v))
}

/// `Curve::eval_many_into` by one evaluation per parameter: finite parameters (anywhere: the
/// curve continues outside its domain), every point of the right dimension and finite.
///
/// # Errors
/// [`Error::NonFinite`] for a NaN or infinite parameter, [`Error::ShapeMismatch`] for a
/// buffer of another length, and those of [`point`].
pub(crate) fn eval_many_into<T: Scalar, C: Curve<T> + ?Sized>(
    curve: &C,
    what: &'static str,
    ts: &[T],
    out: &mut [T],
) -> Result<()> {
    check_finite(what, ts.iter())?;
    let d = curve.dim();
    let len = crate::grid::grid_len(what, &[ts.len(), d])?;
    crate::grid::check_len(what, len, out)?;
    if d == 0 {
        return Ok(());
    }
    for (t, p) in ts.iter().zip(out.chunks_exact_mut(d)) {
        p.clone_from_slice(point(what, d, curve.eval(t.clone()))?.as_slice());
    }
    Ok(())
}

/// `Surface::eval_grid_into` by one evaluation per point, as [`eval_many_into`].
///
/// # Errors
/// As [`eval_many_into`].
pub(crate) fn eval_grid_into<T: Scalar, S: Surface<T> + ?Sized>(
    surface: &S,
    what: &'static str,
    us: &[T],
    vs: &[T],
    out: &mut [T],
) -> Result<()> {
    check_finite(what, us.iter().chain(vs))?;
    let d = surface.dim();
    let len = crate::grid::grid_len(what, &[us.len(), vs.len(), d])?;
    crate::grid::check_len(what, len, out)?;
    if d == 0 {
        return Ok(());
    }
    let mut points = out.chunks_exact_mut(d);
    for u in us {
        for v in vs {
            let x = point(what, d, surface.eval(u.clone(), v.clone()))?;
            if let Some(p) = points.next() {
                p.clone_from_slice(x.as_slice());
            }
        }
    }
    Ok(())
}

/// `point` if it has `dim` coordinates, else `dim` NaNs (for `f64`; zeros for exact numbers,
/// which have no NaN): how the infallible evaluations of constructions keep a user's curve
/// that returns a point of another dimension from making them index past it.
pub(crate) fn of_dim<T: Scalar>(dim: usize, point: DVector<T>) -> DVector<T> {
    if point.len() == dim {
        return point;
    }
    let nan = T::from_f64(0.0).map_or_else(T::zero, |z| {
        if crate::grid::exact::is_rational::<T>() {
            z
        } else {
            T::from_ratio(0, 1) / T::from_ratio(0, 1)
        }
    });
    DVector::from_element(dim, nan)
}

/// `error` with `what` naming the curve of a construction instead of the curve's own name.
pub(crate) fn named(what: &'static str, error: Error) -> Error {
    match error {
        Error::ShapeMismatch {
            expected, found, ..
        } => Error::ShapeMismatch {
            what,
            expected,
            found,
        },
        Error::Overflow { index, value, .. } => Error::Overflow { what, index, value },
        other => other,
    }
}
