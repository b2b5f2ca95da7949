//! `cagd_bspderiv`, `cagd_nrbderiv`, `cagd_nrbdeval`.

use cagd_octave::octave_nurbs::{bspderiv_into, check_bspderiv, Interrupt};

use super::eval::degree;
use super::read::{self, Classes};
use crate::args::Call;
use crate::error::Result;
use crate::value::Sink;

/// `[dc, dk] = cagd_bspderiv (d, c, k)`: octave-nurbs' `bspderiv`
/// ([`cagd_octave::octave_nurbs::bspderiv`]): `dc` is `size (c, 1) × (columns (c) − 1)`, `dk`
/// `1 × (numel (k) − 2)`.
pub fn bspderiv(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(3, 3, "[dc, dk] = cagd_bspderiv (d, c, k)")?;
    call.nargout_max(2)?;
    let d = degree(call.arg(0), "d")?;
    let c = read::real(call.arg(1), "c", Classes::Numeric)?;
    let k = read::real(call.arg(2), "k", Classes::Numeric)?;
    let (rows, cols) = (c.rows(), c.cols());
    check_bspderiv(d, cols, k.len())?;
    if call.nargout >= 2 {
        // dk is k(2:end-1).
        sink.real(1, &[1, k.len() - 2])?
            .copy_from_slice(&k.data[1..k.len() - 1]);
    }
    bspderiv_into(
        d,
        rows,
        cols,
        c.data,
        k.data,
        sink.real(0, &[rows, cols - 1])?,
    )?;
    Ok(())
}

/// `[flag, coefs, order, number, k1, …] = __cagd__ ("cagd_nrbderiv", nurbs, nout)`:
/// octave-nurbs' `nrbderiv` with `nout` outputs
/// ([`cagd_octave::octave_nurbs::nrbderiv`]) for `cagd_nrbderiv.m`: `flag` is 1 when
/// octave-nurbs warns about NaN or Inf in the second derivatives, then the structures of
/// every level in order, `3 + D` arrays each ([`emit_nrb`](super::refine::emit_nrb)).
pub fn nrbderiv(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "[ders, ders2, ders3, ders4] = cagd_nrbderiv (nurbs)")?;
    let nurbs = read::nrb_parts(call.arg(0))?;
    let nout = read::scalar(call.arg(1), "nargout", Classes::Numeric)?.clamp(1.0, 4.0) as usize;
    let ders = cagd_octave::octave_nurbs::nrbderiv(&nurbs, nout)?;
    sink.real(0, &[1, 1])?[0] = f64::from(u8::from(ders.has_nonfinite_second()));
    let mut next = 1;
    for n in ders.levels.iter().flatten() {
        let per = 3 + n.knots.len();
        super::refine::emit_nrb(sink, next, next + per, n)?;
        next += per;
    }
    Ok(())
}

/// `[status, pnt, jac…, hess…, third…, fourth…] = __cagd__ ("cagd_nrbdeval", nurbs, dnurbs,
/// …, tt, nout)`: octave-nurbs' `nrbdeval` with `nout` outputs
/// ([`cagd_octave::octave_nurbs::nrbdeval`]) for `cagd_nrbdeval.m`. `status(r)` says for
/// `hess`, `third_der`, `fourth_der` whether it was not asked for (0), is `[]` with
/// octave-nurbs' warning (1), or follows (2): `D^r` arrays, the cell's entries in storage
/// order. Outputs past the last array are empty.
pub fn nrbdeval(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    use cagd_octave::octave_nurbs::{nrbdeval as deval, Slot};
    call.nargin(4, 7, "[pnt, jac, hess, third_der, fourth_der] = cagd_nrbdeval (nurbs, dnurbs, [dnurbs2, dnurbs3, dnurbs4,] tt)")?;
    let n = call.args.len();
    let nout = read::scalar(call.arg(n - 1), "nargout", Classes::Numeric)?.clamp(1.0, 5.0) as usize;
    let nurbs = read::nrb_parts(call.arg(0))?;
    let ders: Vec<_> = (1..n - 2)
        .map(|k| read::ders(call.arg(k)))
        .collect::<Result<_>>()?;
    let tt = read::tt(call.arg(n - 2))?;
    let r = deval(
        &nurbs,
        (&ders[0], &ders[1..]),
        &tt,
        nout,
        Interrupt::new(call.interrupt),
    )?;
    let slots = [&r.hess, &r.third, &r.fourth];
    let status = sink.real(0, &[1, 3])?;
    for (s, slot) in status.iter_mut().zip(slots) {
        *s = match slot {
            Slot::NotAsked => 0.0,
            Slot::Empty { .. } => 1.0,
            Slot::Values(_) => 2.0,
        };
    }
    let mut arrays = vec![&r.pnt];
    arrays.extend(r.jac.iter());
    for slot in slots {
        if let Slot::Values(v) = slot {
            arrays.extend(v.iter());
        }
    }
    for index in 1..call.nargout {
        match arrays.get(index - 1) {
            Some(a) => sink.real(index, &a.dims)?.copy_from_slice(&a.data),
            None => {
                sink.real(index, &[0, 0])?;
            }
        }
    }
    Ok(())
}
