//! The checks every fallible evaluation of the crate makes, in one place: the parameters
//! (NaN, ±∞, the domain), the work of one point against [`Limits::DEFAULT`](crate::limits::Limits::DEFAULT), and the point
//! itself — its dimension (a user's curve may return a point of another dimension) and that
//! every coordinate is finite ([`Error::Overflow`] otherwise: finite control points can still
//! give `1.7e308 + 1.7e308`).
//!
//! The trait methods `Curve::try_eval`, `Curve::eval_many_into`, `Surface::try_eval` and
//! `Surface::eval_grid_into` of every curve and surface of the crate go through these (their
//! grid kernels check each block of rows as they write it: [`crate::grid`]); a type outside
//! the crate gets the trait's defaults.

use nalgebra::DVector;

use crate::error::{check_finite, Error, Result};
use crate::param::{check_parameter, Surface};
use crate::scalar::Scalar;

// The checks of curves live with the `Curve` trait (the curves of `param` use them too).
pub(crate) use crate::param::{eval_many_into, of_dim, point, point_work, try_eval_curve};

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
