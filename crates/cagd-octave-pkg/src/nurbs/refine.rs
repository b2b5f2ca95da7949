//! `cagd_bspkntins`, `cagd_bspdegelev`, `cagd_nrbkntins`, `cagd_nrbdegelev`, `cagd_nrbcoons`.
//!
//! The structures they return are assembled by their `.m` files from the arrays given here
//! ([`emit_nrb`]): `coefs`, `order`, `number` and one knot vector per direction.

use cagd_octave::octave_nurbs::{
    bspdegelev as elevate, bspkntins as insert, nrbcoons as coons, nrbdegelev as degelev,
    nrbkntins as kntins, Nrb,
};

use super::read::{self, Classes};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::value::{Sink, Value};

/// The outputs of a function that returns a NURBS structure: `coefs`, `order`, `number` and
/// the knot vectors (rows) as outputs `first …`, up to `nargout` (the directions a structure
/// lacks are empty), for the `.m` file to build `struct ("form", "B-NURBS", …)` as `nrbmak`.
pub fn emit_nrb(sink: &mut dyn Sink, first: usize, nargout: usize, nrb: &Nrb) -> Result<()> {
    sink.real(first, &nrb.coef_dims)?
        .copy_from_slice(&nrb.coefs);
    let order: Vec<f64> = nrb.order.iter().map(|&o| o as f64).collect();
    let number: Vec<f64> = nrb.number.iter().map(|&n| n as f64).collect();
    sink.real(first + 1, &[1, order.len()])?
        .copy_from_slice(&order);
    sink.real(first + 2, &[1, number.len()])?
        .copy_from_slice(&number);
    for k in 0..nargout.saturating_sub(first + 3) {
        match nrb.knots.get(k) {
            Some(v) => sink.real(first + 3 + k, &[1, v.len()])?.copy_from_slice(v),
            None => {
                sink.real(first + 3 + k, &[0, 0])?;
            }
        }
    }
    Ok(())
}

/// A degree or count that octave-nurbs' `.m` code uses in a range: any numeric class but
/// logical ("invalid types found in range expression").
fn range_number(v: &Value<'_>, what: &str) -> Result<f64> {
    if let Value::Numeric { class, .. } = v {
        if class.contains("logical") {
            return Err(PkgError::arg(
                Kind::Class,
                what,
                format!("{class} is not accepted"),
                "a number (octave-nurbs: \"invalid types found in range expression\")",
            ));
        }
    }
    read::scalar(v, what, Classes::Numeric)
}

/// `[ic, ik] = cagd_bspkntins (d, c, k, u)`: octave-nurbs' `bspkntins`
/// ([`cagd_octave::octave_nurbs::bspkntins`]).
pub fn bspkntins(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "[ic, ik] = cagd_bspkntins (d, c, k, u)")?;
    call.nargout_max(2)?;
    let d = range_number(call.arg(0), "d")?;
    let c = read::real(call.arg(1), "c", Classes::Numeric)?;
    let k = read::real(call.arg(2), "k", Classes::Numeric)?;
    let u = read::params(call.arg(3), "u")?;
    call.check_samples("u", u.data.len())?;
    let (ic, cols, ik) = insert(d, c.rows(), c.cols(), c.data, k.data, u.data, u.dims)?;
    sink.real(0, &[c.rows(), cols])?.copy_from_slice(&ic);
    if call.nargout >= 2 {
        sink.real(1, &[1, ik.len()])?.copy_from_slice(&ik);
    }
    Ok(())
}

/// `[ic, ik] = cagd_bspdegelev (d, c, k, t)`: octave-nurbs' `bspdegelev`
/// ([`cagd_octave::octave_nurbs::bspdegelev`]), in double (the `.m` file gives `ic` the class
/// of `c` and `ik` that of `k`, as octave-nurbs does).
pub fn bspdegelev(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "[ic, ik] = cagd_bspdegelev (d, c, k, t)")?;
    call.nargout_max(2)?;
    let d = range_number(call.arg(0), "d")?;
    let c = read::real(call.arg(1), "c", Classes::Numeric)?;
    let k = read::real(call.arg(2), "k", Classes::Numeric)?;
    // bspdegelev uses t in sums and max (i - t) only: logical t as well (octave-nurbs).
    let t = read::scalar(call.arg(3), "t", Classes::Numeric)?;
    call.check_degree("t", t.max(0.0) as usize)?;
    call.check_degree("d", d.max(0.0) as usize)?;
    let (ic, cols, ik) = elevate(d, c.rows(), c.cols(), c.data, k.data, t)?;
    sink.real(0, &[c.rows(), cols])?.copy_from_slice(&ic);
    if call.nargout >= 2 {
        sink.real(1, &[1, ik.len()])?.copy_from_slice(&ik);
    }
    Ok(())
}

/// `[coefs, order, number, k1, k2, k3] = __cagd__ ("cagd_nrbkntins", nurbs, iknots)`:
/// octave-nurbs' `nrbkntins` ([`cagd_octave::octave_nurbs::nrbkntins`]) for `cagd_nrbkntins.m`.
pub fn nrbkntins(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "inurbs = cagd_nrbkntins (nurbs, iknots)")?;
    let nurbs = read::nrb_parts(call.arg(0))?;
    let iknots = read::tt(call.arg(1))?;
    let r = kntins(&nurbs, &iknots)?;
    emit_nrb(sink, 0, call.nargout, &r)
}

/// `[coefs, order, number, k1, k2, k3] = __cagd__ ("cagd_nrbdegelev", nurbs, ntimes)`:
/// octave-nurbs' `nrbdegelev` ([`cagd_octave::octave_nurbs::nrbdegelev`]) for
/// `cagd_nrbdegelev.m`.
pub fn nrbdegelev(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "inurbs = cagd_nrbdegelev (nurbs, ntimes)")?;
    let nurbs = read::nrb_parts(call.arg(0))?;
    let ntimes = read::real(call.arg(1), "ntimes", Classes::Numeric)?;
    for &t in ntimes.data {
        call.check_degree("ntimes", t.max(0.0).min(u32::MAX as f64) as usize)?;
    }
    let r = degelev(&nurbs, ntimes.data)?;
    emit_nrb(sink, 0, call.nargout, &r)
}

/// `[coefs, order, number, ku, kv] = __cagd__ ("cagd_nrbcoons", u1, u2, v1, v2)`:
/// octave-nurbs' `nrbcoons` ([`cagd_octave::octave_nurbs::nrbcoons`]) for `cagd_nrbcoons.m`.
pub fn nrbcoons(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "srf = cagd_nrbcoons (u1, u2, v1, v2)")?;
    let curves = (0..4)
        .map(|k| read::nrb_parts(call.arg(k)))
        .collect::<Result<Vec<_>>>()?;
    let r = coons(&curves[0], &curves[1], &curves[2], &curves[3])?;
    emit_nrb(sink, 0, call.nargout, &r)
}
