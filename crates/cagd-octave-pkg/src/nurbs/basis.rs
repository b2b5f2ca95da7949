//! `cagd_findspan`, `cagd_basisfun`, `cagd_basisfunder`.

use cagd_octave::octave_nurbs::{
    basisfun_cost, basisfun_into, basisfunder_cost, basisfunder_into, findspan as find_spans,
    truncate, Interrupt, NurbsError,
};

use super::eval::degree;
use super::read::{self, Classes};
use crate::args::Call;
use crate::error::Result;
use crate::value::Sink;

/// `s = cagd_findspan (n, p, u, U)`: octave-nurbs' `findspan` (its `.m` file; see
/// [`cagd_octave::octave_nurbs::findspan`]): `s` has the size of `u`; `p` is not used and `n`
/// is not checked against the knots.
pub fn findspan(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "s = cagd_findspan (n, p, u, U)")?;
    call.nargout_max(1)?;
    let u = read::params(call.arg(2), "u")?;
    let knots = read::real(call.arg(3), "U", Classes::Numeric)?;
    // n is read only when there is a parameter to compare with U(n+2).
    let n = if u.data.is_empty() {
        0.0
    } else {
        read::scalar(call.arg(0), "n", Classes::Numeric)?
    };
    call.check_samples("u", u.data.len())?;
    let out = sink.real(0, u.dims)?;
    // A binary search per parameter: chunks of the most parameters between two questions.
    let per = cagd::bspline::basis_cost(0, 0, 0);
    call.in_chunks((u.data, per), (out, 1), |part, buffer| {
        buffer.copy_from_slice(&find_spans(n, part, knots.data)?);
        Ok(())
    })
}

/// `B = cagd_basisfun (iv, uv, p, U)`: octave-nurbs' `basisfun` ([`basisfun_into`]): `B` is
/// `numel (uv) × (p+1)`.
pub fn basisfun(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "B = cagd_basisfun (iv, uv, p, U)")?;
    call.nargout_max(1)?;
    let iv = read::real(call.arg(0), "iv", Classes::Numeric)?;
    let uv = read::real(call.arg(1), "uv", Classes::Numeric)?;
    let p = count(degree(call.arg(2), "p")?, "p")?;
    call.check_degree("p", p)?;
    let knots = read::real(call.arg(3), "U", Classes::Numeric)?;
    let n = uv.len();
    call.check_samples("uv", n)?;
    call.check_cost("uv", basisfun_cost(p).times(n as u128))?;
    let out = sink.real(0, &[n, p + 1])?;
    let interrupt = Interrupt::new(call.interrupt);
    basisfun_into(iv.data, uv.data, p, knots.data, (out, interrupt))?;
    Ok(())
}

/// `ders = cagd_basisfunder (ii, pl, uu, U, nd)`: octave-nurbs' `basisfunder`
/// ([`basisfunder_into`]): `ders` is `numel (uu) × (nd+1) × (pl+1)`.
pub fn basisfunder(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(5, 5, "ders = cagd_basisfunder (ii, pl, uu, U, nd)")?;
    call.nargout_max(1)?;
    let ii = read::real(call.arg(0), "ii", Classes::Numeric)?;
    let pl = count(degree(call.arg(1), "pl")?, "pl")?;
    call.check_degree("pl", pl)?;
    let uu = read::real(call.arg(2), "uu", Classes::Numeric)?;
    let knots = read::real(call.arg(3), "U", Classes::Numeric)?;
    let nd = count(degree(call.arg(4), "nd")?, "nd")?;
    call.check_degree("nd", nd)?;
    let n = uu.len();
    call.check_samples("uu", n)?;
    call.check_cost("uu", basisfunder_cost(pl, nd).times(n as u128))?;
    let out = sink.real(0, &[n, nd + 1, pl + 1])?;
    let interrupt = Interrupt::new(call.interrupt);
    basisfunder_into((ii.data, pl), uu.data, knots.data, nd, (out, interrupt))?;
    Ok(())
}

/// A degree or order of octave-nurbs' compiled code: truncated toward zero; a negative one
/// makes it write before its arrays.
fn count(x: f64, what: &'static str) -> Result<usize> {
    let t = truncate(x);
    if t < 0 {
        return Err(NurbsError::undefined(what, format!("{x} is negative")).into());
    }
    Ok(t as usize)
}
