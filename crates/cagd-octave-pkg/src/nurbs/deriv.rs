//! `cagd_bspderiv`.

use cagd_octave::octave_nurbs::bspderiv as derivative;

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
    let (dc, dk) = derivative(d, rows, cols, c.data, k.data)?;
    sink.real(0, &[rows, cols - 1])?.copy_from_slice(&dc);
    if call.nargout >= 2 {
        sink.real(1, &[1, dk.len()])?.copy_from_slice(&dk);
    }
    Ok(())
}
