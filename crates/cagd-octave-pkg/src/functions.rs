//! The table of the functions the oct-file serves and the one entry point that calls them.

use cagd::limits::Limits;

use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::value::{Sink, Value};
use crate::{limits, native, nurbs, thesis};

/// A package function: its call and where its results go.
type Function = fn(&Call<'_, '_>, &mut dyn Sink) -> Result<()>;

/// Every function the oct-file serves, by its Octave name.
pub const FUNCTIONS: &[(&str, Function)] = &[
    ("deCasteljau", thesis::de_casteljau),
    ("ploskevB", thesis::ploskev_b),
    ("bilinearna", thesis::bilinearna),
    ("tenzor", thesis::tenzor),
    ("krpaCoons", thesis::krpa_coons),
    ("vrednostCoons", thesis::vrednost_coons),
    ("krpaGordon", thesis::krpa_gordon),
    ("Lagrange", thesis::lagrange),
    ("cagd_nrbeval", nurbs::nrbeval),
    ("cagd_bspeval", nurbs::bspeval),
    ("cagd_basisfun", nurbs::basisfun),
    ("cagd_findspan", nurbs::findspan),
    ("cagd_basisfunder", nurbs::basisfunder),
    ("cagd_bspderiv", nurbs::bspderiv),
    ("cagd_bspkntins", nurbs::bspkntins),
    ("cagd_bspdegelev", nurbs::bspdegelev),
    ("cagd_nrbkntins", nurbs::nrbkntins),
    ("cagd_nrbdegelev", nurbs::nrbdegelev),
    ("cagd_nrbderiv", nurbs::nrbderiv),
    ("cagd_nrbdeval", nurbs::nrbdeval),
    ("cagd_nrbcoons", nurbs::nrbcoons),
    ("cagd_bezier", native::bezier),
    ("cagd_bezier_derivative", native::bezier_derivative),
    ("cagd_bezier_subdivide", native::bezier_subdivide),
    ("cagd_bezier_elevate", native::bezier_elevate),
    ("cagd_bezier_patch", native::bezier_patch),
    ("cagd_coons", native::coons),
    ("cagd_gordon", native::gordon),
    ("cagd_ruled", native::ruled),
    ("cagd_bspline", native::bspline),
    ("cagd_nurbs", native::nurbs_curve),
    ("cagd_spline", native::spline),
    ("cagd_hermite", native::hermite),
    ("cagd_convert", native::convert),
    ("cagd_bernstein", native::bernstein),
];

/// Calls the package function `name` with `args`, asking for `nargout` outputs (0 counts as
/// 1), within `limits` (which `cagd_limits` reads and changes), writing the results into
/// `sink`.
///
/// # Errors
/// The function's [`PkgError`], its message prefixed with the function's name.
///
/// ```
/// use cagd_octave_pkg::{call, Real, Value, VecSink};
/// // deCasteljau ([0 0 8 4; 0 2 2 0; 0 2 0 0], 3): thesis Primer 2.4.
/// let p = [0.0, 0.0, 0.0, 0.0, 2.0, 2.0, 8.0, 2.0, 0.0, 4.0, 0.0, 0.0];
/// let args = [
///     Value::Real(Real { dims: &[3, 4], data: &p }),
///     Value::Real(Real { dims: &[1, 1], data: &[3.0] }),
/// ];
/// let mut limits = cagd::Limits::default();
/// let mut out = VecSink::default();
/// call("deCasteljau", &args, 1, &mut limits, &mut out)?;
/// assert_eq!(out.get(0).dims(), &[3, 3]);
/// assert_eq!(&out.get(0).data()[3..6], &[3.5, 1.5, 0.75]);
/// let e = call("deCasteljau", &args[..1], 1, &mut limits, &mut out).unwrap_err();
/// assert_eq!(e.identifier(), "cagd:nargin");
/// # Ok::<(), cagd_octave_pkg::PkgError>(())
/// ```
pub fn call(
    name: &str,
    args: &[Value<'_>],
    nargout: usize,
    limits: &mut Limits,
    sink: &mut dyn Sink,
) -> Result<()> {
    call_interruptible(name, (args, nargout), limits, &|| false, sink)
}

/// [`call`], asking `interrupted` every few milliseconds of long work (Octave's Ctrl-C, which
/// the oct-file reads): when it answers `true` the function stops with
/// [`Kind::Interrupted`] and writes nothing more.
///
/// # Errors
/// As [`call`]; [`Kind::Interrupted`].
///
/// ```
/// use cagd_octave_pkg::{call_interruptible, Kind, Real, Value, VecSink};
/// let p = [0.0, 1.0];
/// let t: Vec<f64> = (0..100_000).map(|k| k as f64 / 1e5).collect();
/// let dims = [1, t.len()];
/// let args = [
///     Value::Real(Real { dims: &[1, 2], data: &p }),
///     Value::Real(Real { dims: &dims, data: &t }),
/// ];
/// let mut limits = cagd::Limits::default();
/// let e = call_interruptible("cagd_bezier", (&args, 1), &mut limits, &|| true, &mut VecSink::default())
///     .unwrap_err();
/// assert_eq!(e.kind, Kind::Interrupted);
/// ```
pub fn call_interruptible(
    name: &str,
    (args, nargout): (&[Value<'_>], usize),
    limits: &mut Limits,
    interrupted: &(dyn Fn() -> bool + Sync),
    sink: &mut dyn Sink,
) -> Result<()> {
    if name == "cagd_limits" {
        return limits::cagd_limits(args, nargout, limits, sink).map_err(|e| e.prefixed(name));
    }
    // A one-point call costs about a microsecond: the lookup by name is a hash (FNV-1a, short
    // keys) rather than a search of the table.
    static INDEX: std::sync::LazyLock<
        std::collections::HashMap<&'static str, usize, std::hash::BuildHasherDefault<Fnv>>,
    > = std::sync::LazyLock::new(|| {
        FUNCTIONS
            .iter()
            .enumerate()
            .map(|(k, (n, _))| (*n, k))
            .collect()
    });
    let Some((octave_name, function)) = INDEX.get(name).map(|&k| &FUNCTIONS[k]) else {
        return Err(PkgError::new(
            Kind::Internal,
            format!("__cagd__: no package function '{name}'"),
        ));
    };
    let c = Call::new(octave_name, args, nargout, *limits).with_interrupt(interrupted);
    function(&c, sink).map_err(|e| e.prefixed(octave_name))
}

/// FNV-1a: the hash of the function names (a few short keys, no adversary).
#[derive(Default)]
struct Fnv(u64);

impl std::hash::Hasher for Fnv {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        let mut h = if self.0 == 0 {
            0xcbf2_9ce4_8422_2325
        } else {
            self.0
        };
        for &b in bytes {
            h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
        self.0 = h;
    }
}
