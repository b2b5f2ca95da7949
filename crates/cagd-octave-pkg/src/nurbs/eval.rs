//! `cagd_nrbeval` and `cagd_bspeval`.

use cagd_octave::octave_nurbs::{bspeval_into, Bsp, Interrupt, NrbEval};

use super::read::{self, Classes};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::value::{Sink, Value};

/// `[p, w] = cagd_nrbeval (nurbs, tt)`: octave-nurbs' `nrbeval` (see
/// [`NrbEval`]): curves at parameters of any size,
/// surfaces and volumes on grids `{u, v (, w)}` and at scattered points, one output
/// cartesian, two homogeneous.
pub fn nrbeval(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "[p, w] = cagd_nrbeval (nurbs, tt)")?;
    call.nargout_max(2)?;
    let nurbs = read::nrb_parts(call.arg(0))?;
    let tt = read::tt(call.arg(1))?;
    let homogeneous = call.nargout == 2;
    let plan = NrbEval::new(&nurbs, &tt, homogeneous)?;
    let points = plan.points();
    call.check_samples("tt", points)?;
    call.check_cost("tt", plan.point_cost().times(points as u128))?;
    let interrupt = Interrupt::new(call.interrupt);
    let p = sink.real(0, plan.p_dims())?;
    if homogeneous {
        let mut w = vec![0.0; points];
        plan.eval_into(p, Some(&mut w), interrupt)?;
        sink.real(1, plan.w_dims())?.copy_from_slice(&w);
    } else {
        plan.eval_into(p, None, interrupt)?;
    }
    Ok(())
}

/// `p = cagd_bspeval (d, c, k, u)`: octave-nurbs' `bspeval` ([`bspeval_into`]): `p` is
/// `size (c, 1) × numel (u)`.
pub fn bspeval(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "p = cagd_bspeval (d, c, k, u)")?;
    call.nargout_max(1)?;
    let d = degree(call.arg(0), "d")?;
    let c = read::real(call.arg(1), "c", Classes::Float)?;
    let k = read::real(call.arg(2), "k", Classes::Float)?;
    let u = read::params(call.arg(3), "u")?;
    let rows = c.rows();
    let cols = c.cols();
    let b = Bsp::new(d, rows, cols, c.data, k.data)?;
    call.check_samples("u", u.data.len())?;
    call.check_cost("u", b.point_cost().times(u.data.len() as u128))?;
    let out = sink.real(0, &[rows, u.data.len()])?;
    bspeval_into(&b, u.data, out, Interrupt::new(call.interrupt))?;
    Ok(())
}

/// A degree of octave-nurbs' compiled functions: one real number of any class but sparse
/// (`is_real_scalar`).
pub fn degree(v: &Value<'_>, what: &str) -> Result<f64> {
    if let Value::Numeric { class, .. } = v {
        if class.starts_with("sparse") {
            return Err(PkgError::arg(
                Kind::Class,
                what,
                format!("{class} is not accepted"),
                "a real scalar (octave-nurbs: \"degree should be a scalar\")",
            ));
        }
    }
    read::scalar(v, what, Classes::Numeric)
}
