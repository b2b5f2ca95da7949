//! octave-nurbs' `nrbcoons`: the Coons patch of four NURBS boundaries as a NURBS surface.

use cagd::coons::coons_bspline_net;
use nalgebra::DVector;

use super::error::{NurbsError, Result};
use super::nrb::{nrbmak, Kind, Nrb, NrbParts};
use super::nrbeval::{NrbEval, Params, Tt};

/// octave-nurbs' `srf = nrbcoons (u1, u2, v1, v2)`: the bilinearly blended Coons patch of the
/// NURBS curves `u1 = S(·, 0)`, `u2 = S(·, 1)`, `v1 = S(0, ·)`, `v2 = S(1, ·)` as one NURBS
/// surface — the core's [`coons_bspline_net`] (the curves made compatible by degree elevation
/// and knot insertion, the ruled surfaces and the bilinear patch of the corners summed in
/// B-spline form) applied to the homogeneous coefficients, with the corners
/// `u1.coefs(:, 1)`, `u1.coefs(:, end)`, `u2.coefs(:, 1)`, `u2.coefs(:, end)`, as octave-nurbs
/// builds it: the same knots and degrees, the coefficients to rounding.
///
/// As there, the curves must meet at the corners: their cartesian end points (`nrbeval` at
/// the first and last knot) may differ by at most `1e-10` in each coordinate ("The four curves
/// do not define a closed boundary"). And as there, all four must have the knot range
/// `[0, 1]` (octave-nurbs fails otherwise, "Trying to insert a knot outside the interval of
/// definition"). Unlike octave-nurbs, a knot vector not clamped at both ends is refused
/// (octave-nurbs then builds a surface that does not interpolate the curves).
///
/// # Errors
/// [`NurbsError::Refused`] for the cases above and for a structure that is not a curve;
/// the errors of reading the curves (coefficients `4 × n`, `n + p + 1` knots, finite values).
pub fn nrbcoons(
    u1: &NrbParts<'_>,
    u2: &NrbParts<'_>,
    v1: &NrbParts<'_>,
    v2: &NrbParts<'_>,
) -> Result<Nrb> {
    let curves = [u1, u2, v1, v2];
    for (c, name) in curves.iter().zip(["u1", "u2", "v1", "v2"]) {
        if c.kind() != Kind::Curve {
            return Err(NurbsError::refused(
                name,
                "not a NURBS curve (its knots are a cell)",
            ));
        }
    }
    check_closed(u1, u2, v1, v2)?;
    let homogeneous: Vec<_> = curves
        .iter()
        .map(|c| c.to_homogeneous_curve())
        .collect::<Result<_>>()?;
    for (c, name) in homogeneous.iter().zip(["u1", "u2", "v1", "v2"]) {
        let k = c.knots().as_slice();
        if k[0] != 0.0 || k[k.len() - 1] != 1.0 {
            return Err(NurbsError::refused(
                name,
                format!(
                    "knots from {} to {}: nrbcoons needs [0, 1] (octave-nurbs: \"Trying to insert a knot outside the interval of definition\")",
                    k[0],
                    k[k.len() - 1]
                ),
            ));
        }
        if !c.knots().is_clamped(c.degree()) {
            return Err(NurbsError::refused(
                name,
                "a knot vector not clamped at both ends (its curve does not start and end at its end control points)",
            ));
        }
    }
    let end = |c: &cagd::BSplineCurve, last: bool| -> DVector<f64> {
        let m = c.control();
        m.column(if last { m.ncols() - 1 } else { 0 }).into_owned()
    };
    let corners = [
        end(&homogeneous[0], false),
        end(&homogeneous[0], true),
        end(&homogeneous[1], false),
        end(&homogeneous[1], true),
    ];
    let s = coons_bspline_net(
        &homogeneous[0],
        &homogeneous[1],
        &homogeneous[2],
        &homogeneous[3],
        &corners,
    )?;
    let coords = s.coordinates();
    let (nu, nv) = coords[0].shape();
    let mut coefs = Vec::with_capacity(4 * nu * nv);
    for j in 0..nv {
        for i in 0..nu {
            coefs.extend(coords.iter().map(|c| c[(i, j)]));
        }
    }
    let (ku, kv) = s.knots();
    nrbmak(
        coefs,
        &[4, nu, nv],
        vec![ku.as_slice().to_vec(), kv.as_slice().to_vec()],
    )
}

/// octave-nurbs' check: the cartesian points of the curves at their first and last knots
/// agree at the four corners within `1e-10` (NaN differences pass, as `max` skips them).
fn check_closed(
    u1: &NrbParts<'_>,
    u2: &NrbParts<'_>,
    v1: &NrbParts<'_>,
    v2: &NrbParts<'_>,
) -> Result<()> {
    let at = |c: &NrbParts<'_>, last: bool| -> Result<Vec<f64>> {
        let k = c.knots(0)?;
        let x = if last { k.last() } else { k.first() };
        let x = [*x.ok_or_else(|| NurbsError::refused("knots", "an empty knot vector"))?];
        let e = NrbEval::new(
            c,
            &Tt::Array(Params {
                dims: &[1, 1],
                data: &x,
            }),
            false,
        )?;
        let mut p = vec![0.0; 3];
        e.eval_into(&mut p, None, super::Interrupt::never())?;
        Ok(p)
    };
    let pairs = [
        (at(u1, false)?, at(v1, false)?),
        (at(u1, true)?, at(v2, false)?),
        (at(u2, false)?, at(v1, true)?),
        (at(u2, true)?, at(v2, true)?),
    ];
    for (a, b) in pairs {
        let gap = a
            .iter()
            .zip(&b)
            .map(|(x, y)| (x - y).abs())
            .filter(|g| !g.is_nan())
            .reduce(f64::max);
        if gap.is_some_and(|g| g > 1e-10) {
            return Err(NurbsError::refused(
                "curves",
                format!(
                    "corners {a:?} and {b:?} differ by {}: the four curves do not define a closed boundary (octave-nurbs)",
                    gap.unwrap_or(0.0)
                ),
            ));
        }
    }
    Ok(())
}
