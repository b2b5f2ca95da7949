//! octave-nurbs' `nrbkntins` and `nrbdegelev`: knot insertion and degree elevation of NURBS
//! curves, surfaces and volumes, direction by direction.

use super::along::Net;
use super::bspdegelev::bspdegelev;
use super::bspkntins::bspkntins;
use super::error::{NurbsError, Result};
use super::nrb::{nrbmak, Kind, Nrb, NrbParts};
use super::nrbeval::{Params, Tt};

/// The knot vectors of a structure and the number of its directions, checked as a curve,
/// surface or volume.
pub(crate) fn directions(nurbs: &NrbParts<'_>) -> Result<usize> {
    match nurbs.kind() {
        Kind::Curve => Ok(1),
        Kind::Surface => Ok(2),
        Kind::Volume => Ok(3),
        Kind::Other(cols) => Err(NurbsError::refused(
            "knots",
            format!("a cell of {cols} columns: neither a surface nor a volume"),
        )),
    }
}

/// The curve's degree (`order − 1`, one number).
fn curve_degree(nurbs: &NrbParts<'_>) -> Result<f64> {
    if nurbs.order.len() != 1 {
        return Err(NurbsError::refused("order", "a curve has one order"));
    }
    nurbs.degree(0)
}

/// octave-nurbs' `nrbkntins (nurbs, iknots)`: the knots `iknots` (a curve: an array; a
/// surface or volume: a cell `{iu, iv (, iw)}`, empty items for no knot) inserted into each
/// direction by [`bspkntins`], the last direction first, and the structure rebuilt by
/// [`nrbmak`]. Knots outside a direction's knot range are refused, as octave-nurbs refuses
/// them ("Trying to insert a knot outside the interval of definition"); knots at the ends of
/// the range and multiplicities beyond the order are inserted, as there.
///
/// # Errors
/// As `nrbkntins`: a knot outside the knots, `iknots` of the wrong kind (a cell for a curve,
/// a cell of another size for a surface), and the errors of [`bspkntins`] and [`nrbmak`].
///
/// ```
/// use std::borrow::Cow;
/// use cagd_octave::octave_nurbs::{nrbkntins, Knots, NrbParts, Params, Tt};
/// // nrbmak ([0 1; 0 0; 0 0; 1 1], [0 0 1 1]) with the knot 0.5: three points on the line.
/// let coefs = [0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0];
/// let line = NrbParts { coefs: &coefs, coef_dims: &[4, 2], knots: Knots::Vector(&[0.0, 0.0, 1.0, 1.0]),
///     order: Cow::Owned(vec![2.0]), number: Cow::Owned(vec![2.0]) };
/// let r = nrbkntins(&line, &Tt::Array(Params { dims: &[1, 1], data: &[0.5] }))?;
/// assert_eq!(r.number, vec![3]);
/// assert_eq!(r.knots[0], vec![0.0, 0.0, 0.5, 1.0, 1.0]);
/// assert_eq!(&r.coefs[4..8], &[0.5, 0.0, 0.0, 1.0]);
/// # Ok::<(), cagd_octave::octave_nurbs::NurbsError>(())
/// ```
pub fn nrbkntins(nurbs: &NrbParts<'_>, iknots: &Tt<'_>) -> Result<Nrb> {
    let dirs = directions(nurbs)?;
    if dirs == 1 {
        let Tt::Array(u) = iknots else {
            return Err(NurbsError::refused(
                "iknots",
                "a cell for a curve (octave-nurbs compares it with the knots and fails)",
            ));
        };
        let knots = nurbs.knots(0)?;
        check_inside(knots, u.data)?;
        let d = curve_degree(nurbs)?;
        let (rows, cols) = nurbs.coef_matrix();
        if u.data.is_empty() {
            return nrbmak(nurbs.coefs.to_vec(), nurbs.coef_dims, vec![knots.to_vec()]);
        }
        let (ic, n, ik) = bspkntins(d, rows, cols, nurbs.coefs, knots, u.data, u.dims)?;
        return nrbmak(ic, &[rows, n], vec![ik]);
    }
    let items: &[Params<'_>] = match iknots {
        Tt::Cell(items) if items.len() == dirs => items,
        _ => {
            return Err(NurbsError::refused(
                "iknots",
                format!("a surface or volume takes a cell of {dirs} knot arrays (octave-nurbs' cellfun fails)"),
            ))
        }
    };
    for (k, u) in items.iter().enumerate() {
        check_inside(nurbs.knots(k)?, u.data)?;
    }
    let mut net = Net {
        data: nurbs.coefs.to_vec(),
        sizes: nurbs.numbers(dirs)?,
    };
    let mut knots: Vec<Vec<f64>> = (0..dirs)
        .map(|k| nurbs.knots(k).map(<[f64]>::to_vec))
        .collect::<Result<_>>()?;
    for k in (0..dirs).rev() {
        let u = items[k];
        if u.data.is_empty() {
            continue;
        }
        let d = nurbs.degree(k)?;
        let mut new_knots = Vec::new();
        net = net.along(k, |rows, cols, c| {
            let (ic, n, ik) = bspkntins(d, rows, cols, c, &knots[k], u.data, u.dims)?;
            new_knots = ik;
            Ok((ic, n))
        })?;
        knots[k] = new_knots;
    }
    nrbmak(net.data.clone(), &net.dims(), knots)
}

/// octave-nurbs' refusal of knots outside `[min (knots), max (knots)]` (NaN passes there).
fn check_inside(knots: &[f64], u: &[f64]) -> Result<()> {
    let max = knots
        .iter()
        .copied()
        .filter(|x| !x.is_nan())
        .reduce(f64::max);
    let min = knots
        .iter()
        .copied()
        .filter(|x| !x.is_nan())
        .reduce(f64::min);
    let (Some(min), Some(max)) = (min, max) else {
        return Err(NurbsError::refused("knots", "an empty knot vector"));
    };
    if u.iter().any(|&x| x > max || x < min) {
        return Err(NurbsError::refused(
            "iknots",
            format!("a knot outside [{min}, {max}] (octave-nurbs: \"Trying to insert a knot outside the interval of definition\")"),
        ));
    }
    Ok(())
}

/// octave-nurbs' `nrbdegelev (nurbs, ntimes)`: each direction's degree raised `ntimes(k)`
/// times by [`bspdegelev`], the last direction first, and the structure rebuilt by
/// [`nrbmak`]; a direction with `ntimes(k) = 0` (a curve: also an empty `ntimes`) is left as
/// it is. Surfaces and volumes take their sizes from `size (coefs)`, as there.
///
/// # Errors
/// As `nrbdegelev`: fewer entries in `ntimes` than directions, coefficients that are not
/// `4 × …`, and the errors of [`bspdegelev`] (knot vectors not clamped at their end) and
/// [`nrbmak`].
pub fn nrbdegelev(nurbs: &NrbParts<'_>, ntimes: &[f64]) -> Result<Nrb> {
    let dirs = directions(nurbs)?;
    if dirs == 1 {
        let knots = nurbs.knots(0)?;
        if ntimes.is_empty() || ntimes.iter().all(|&t| t == 0.0) && ntimes.len() == 1 {
            return nrbmak(nurbs.coefs.to_vec(), nurbs.coef_dims, vec![knots.to_vec()]);
        }
        if ntimes.len() != 1 {
            return Err(NurbsError::refused("ntimes", "a curve takes one number"));
        }
        let d = curve_degree(nurbs)?;
        let (rows, cols) = nurbs.coef_matrix();
        let (ic, n, ik) = bspdegelev(d, rows, cols, nurbs.coefs, knots, ntimes[0])?;
        return nrbmak(ic, &[rows, n], vec![ik]);
    }
    if ntimes.len() < dirs {
        return Err(NurbsError::Index {
            what: "ntimes",
            index: ntimes.len() as i64 + 1,
            bound: ntimes.len(),
        });
    }
    let dims = nurbs.coef_dims;
    let mut sizes: Vec<usize> = (0..dirs)
        .map(|k| dims.get(1 + k).copied().unwrap_or(1))
        .collect();
    sizes[dirs - 1] *= dims.iter().skip(1 + dirs).product::<usize>();
    if dims.first() != Some(&4) {
        return Err(NurbsError::refused(
            "coefs",
            format!(
                "{} rows: nrbdegelev reshapes coefs to 4 × …",
                dims.first().copied().unwrap_or(0)
            ),
        ));
    }
    let mut net = Net {
        data: nurbs.coefs.to_vec(),
        sizes,
    };
    let mut knots: Vec<Vec<f64>> = (0..dirs)
        .map(|k| nurbs.knots(k).map(<[f64]>::to_vec))
        .collect::<Result<_>>()?;
    for k in (0..dirs).rev() {
        if ntimes[k] == 0.0 {
            continue;
        }
        let d = nurbs.degree(k)?;
        let mut new_knots = Vec::new();
        net = net.along(k, |rows, cols, c| {
            let (ic, n, ik) = bspdegelev(d, rows, cols, c, &knots[k], ntimes[k])?;
            new_knots = ik;
            Ok((ic, n))
        })?;
        knots[k] = new_knots;
    }
    nrbmak(net.data.clone(), &net.dims(), knots)
}
