//! The functions of the Octave package `cagd` (`pkg load cagd`), in safe Rust.
//!
//! The package (sources in `octave_pkg/`) is a set of `.m` files, each documented with an
//! Octave docstring and tested with `%!test` blocks, that call one oct-file, `__cagd__`. The
//! oct-file is a thin C++ gateway: it turns Octave's arguments into [`Value`]s (borrowing
//! Octave's arrays), calls [`call`] through the C ABI of `cagd-octave-ffi` (the only crate of
//! the package with `unsafe` code), and raises the error or returns the results. Everything
//! else — checking every argument, the limits, the mathematics (the core `cagd` and the
//! Octave layer `cagd-octave`), the layouts — is here, with no `unsafe`.
//!
//! # Functions
//! - the thesis functions, fixed ([`thesis`]): `deCasteljau`, `ploskevB`, `bilinearna`,
//!   `tenzor`, `krpaCoons`, `vrednostCoons`, `krpaGordon`, `Lagrange`, with the arguments and
//!   results of `octave_ref/fixed/`;
//! - octave-nurbs' twins ([`nurbs`]): `cagd_nrbeval`, `cagd_bspeval`, `cagd_basisfun`,
//!   `cagd_findspan`, `cagd_basisfunder`, `cagd_bspderiv`, `cagd_bspkntins`, `cagd_bspdegelev`,
//!   `cagd_nrbkntins`, `cagd_nrbdegelev`, `cagd_nrbderiv`, `cagd_nrbdeval`, `cagd_nrbcoons`,
//!   with the arguments, results and errors of octave-nurbs' functions of those names;
//! - native functions ([`native`]): Bézier curves with derivatives, subdivision and
//!   elevation, Bézier patches, Coons and Gordon patches with their parts, B-splines, NURBS,
//!   interpolating splines, Hermite cubics, the cubic conversions, Bernstein values — exact
//!   with the option `"exact"` ([`number`]);
//! - `cagd_limits`: the resource limits of the session ([`limits`]).
//!
//! # Layouts
//! Points are columns: a curve's control points are `d × (n+1)`, its values `d × k`. Native
//! surfaces take nets `d × (m+1) × (n+1)` and return grids `d × nu × nv` (`X(:, i, j)` is the
//! point at `(u(i), v(j))`), octave-nurbs' layout. The thesis functions keep theirs (packed
//! nets `(m+1) × 3(n+1)`, grids `N × N × 3`).
//!
//! # Errors
//! Every refusal is an Octave error with an identifier `cagd:<kind>` ([`Kind`]) and a
//! one-line message `FUNCTION: …`: the library's own text for a library error (the text the
//! command line prints for it), `ARGUMENT: PROBLEM; expected FORM` for the package's own checks.
//! Wrong classes (integer, logical, single, complex, sparse, cell, struct, …), empty arrays,
//! NaN and ±Inf, and sizes over the limits are refused before anything is computed.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod args;
pub mod error;
pub mod limits;
pub mod native;
pub mod number;
pub mod nurbs;
pub mod ops;
pub mod thesis;
pub mod value;

pub use error::{Kind, PkgError, Result};
pub use value::{Output, Real, Sink, Value, VecSink};

use args::Call;
use cagd::limits::Limits;

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
    let c = Call::new(octave_name, args, nargout, *limits);
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
