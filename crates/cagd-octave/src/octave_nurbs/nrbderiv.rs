//! octave-nurbs' `nrbderiv`: the NURBS structures of the derivatives.

use super::along::Net;
use super::bspderiv::bspderiv;
use super::error::Result;
use super::nrb::{nrbmak, Nrb, NrbParts};
use super::refine::{directions, nrbdegelev};

/// octave-nurbs' `[ders, ders2, ders3, ders4] = nrbderiv (nurbs)` with `orders` outputs
/// (1 to 4): the homogeneous coefficients differentiated along each direction by
/// [`bspderiv`] (so the weights of a derivative structure are derivatives of the weights, of
/// any sign), each result built by [`nrbmak`]. With two or more outputs the NURBS is first
/// raised to degree `orders` in every direction where it is lower ([`nrbdegelev`](super::nrbdegelev)),
/// as there.
///
/// `levels[r − 1]` holds the `D^r` structures of the `r`-th derivatives (`D` directions) in
/// the order of octave-nurbs' loops: `(i)`, then `(i, j)` with `j` fastest, and so on
/// (`ders2{i, j}`). [`NrbDerivs::has_nonfinite_second`] says whether octave-nurbs warns
/// ("nrbderiv:SecondDerivative").
///
/// # Errors
/// As `nrbderiv`: the errors of `bspderiv`, `nrbdegelev` and `nrbmak` (a derivative of
/// degree below 0), `number` that does not fit `coefs`.
pub fn nrbderiv(nurbs: &NrbParts<'_>, orders: usize) -> Result<NrbDerivs> {
    let dirs = directions(nurbs)?;
    let elevated;
    let parts = if orders >= 2 {
        let degelev: Vec<f64> = (0..dirs)
            .map(|k| nurbs.degree(k).map(|d| (orders as f64 - d).max(0.0)))
            .collect::<Result<_>>()?;
        elevated = nrbdegelev(nurbs, &degelev)?;
        elevated.parts()
    } else {
        nurbs.clone()
    };
    let sizes = if dirs == 1 {
        vec![parts.coef_matrix().1]
    } else {
        parts.numbers(dirs)?
    };
    let net = Net {
        data: parts.coefs.to_vec(),
        sizes,
    };
    let knots: Vec<Vec<f64>> = (0..dirs)
        .map(|k| parts.knots(k).map(<[f64]>::to_vec))
        .collect::<Result<_>>()?;
    let degrees: Vec<f64> = (0..dirs).map(|k| parts.degree(k)).collect::<Result<_>>()?;
    let mut levels = vec![Vec::new(); orders];
    derive(&net, &knots, &degrees, 0, orders, &mut levels)?;
    Ok(NrbDerivs { levels })
}

/// The derivative structures of [`nrbderiv`].
#[derive(Debug, Clone, PartialEq)]
pub struct NrbDerivs {
    /// `levels[r − 1]`: the structures of the `r`-th derivatives.
    pub levels: Vec<Vec<Nrb>>,
}

impl NrbDerivs {
    /// Whether a second-derivative structure has a NaN or infinite coefficient (octave-nurbs
    /// then warns, `nrbderiv:SecondDerivative`: low continuity at repeated knots).
    pub fn has_nonfinite_second(&self) -> bool {
        self.levels
            .get(1)
            .is_some_and(|l| l.iter().any(|n| n.coefs.iter().any(|x| !x.is_finite())))
    }
}

/// Differentiates `net` along every direction (degrees `degrees`, already lowered for the
/// derivatives taken), records each result at `level`, and goes on to the next level.
fn derive(
    net: &Net,
    knots: &[Vec<f64>],
    degrees: &[f64],
    level: usize,
    orders: usize,
    levels: &mut [Vec<Nrb>],
) -> Result<()> {
    for j in 0..knots.len() {
        let mut dk = Vec::new();
        let dnet = net.along(j, |rows, cols, c| {
            let (dc, k) = bspderiv(degrees[j], rows, cols, c, &knots[j])?;
            dk = k;
            Ok((dc, cols.saturating_sub(1)))
        })?;
        let mut dknots = knots.to_vec();
        dknots[j] = dk;
        levels[level].push(nrbmak(dnet.data.clone(), &dnet.dims(), dknots.clone())?);
        if level + 1 < orders {
            let mut lowered = degrees.to_vec();
            lowered[j] -= 1.0;
            derive(&dnet, &dknots, &lowered, level + 1, orders, levels)?;
        }
    }
    Ok(())
}
