//! What the subcommands not yet on the operation layer still share from the former Bézier
//! subcommands: whether `--u` and `--v` ask for one point (the operation layer's surfaces
//! decide it themselves, [`cagd_ops::ops::surface::SurfaceParams::single`]).

use cagd::limits::Limits;

use crate::args::SurfaceParamArgs;

/// Whether `--u` and `--v` ask for one point.
pub fn point_mode(limits: &Limits, params: &SurfaceParamArgs) -> bool {
    let single = |s: &Option<String>| {
        s.as_ref().is_some_and(|t| {
            cagd_octave::literal::parse_params_with::<f64>(t, limits).is_ok_and(|v| v.len() == 1)
        })
    };
    params.n.is_none() && single(&params.u) && single(&params.v)
}
