//! Calls of the core's public functions with hostile arguments, shared by the property test of
//! the core (`tests/it/hostile_library.rs`, arguments from a seeded LCG) and the `library` fuzz
//! target (`fuzz/fuzz_targets/library.rs`, arguments from the fuzzer's bytes). Both run [`call`]
//! under `catch_unwind` and require that it returns, and the property test that it returns
//! within a bounded time.
//!
//! The arguments ([`draws`]): sizes up to `usize::MAX`, indices out of range, knot vectors too
//! short or unsorted, NaN, ±∞ and any bit pattern, and finite values at the ends of the range
//! of doubles — control points ±1.7·10³⁰⁸, intervals `[−10³⁰⁸, 10³⁰⁸]`, knots, nodes and spline
//! parameters 5·10⁻³²⁴ apart, NURBS weights all 10³⁰⁸ or all 5·10⁻³²⁴, 1001 equally spaced
//! Lagrange nodes, boundary curves returning points of the wrong dimension. Sizes that the
//! caller itself allocates (matrices, lists) stay small ([`draws::small`]); sizes handed to
//! the library as numbers ([`draws::size`]) reach `usize::MAX`.
//!
//! What is checked ([`check`]): a `Result`-returning function returns `Err` or an `Ok` whose
//! every number is finite ([`check::ok`], which panics otherwise); every function returns (no
//! panic, no abort). Each check names its function by its path in the crate; the names are
//! what `fuzz/api_coverage.sh` counts against the public API.

pub mod basics;
pub mod bezier;
pub mod bspline;
pub mod check;
pub mod coons;
pub mod course;
pub mod draws;
pub mod interpolation;
pub mod refine;

pub use draws::Draws;

/// A group of calls: its name, and the function that draws its arguments and makes them.
pub type Group = (&'static str, fn(&Draws));

/// The groups of calls: each draws its arguments and calls a family of functions.
pub const GROUPS: [Group; 23] = [
    ("Bézier curves and schemes", bezier::curves),
    ("matrix forms", bezier::matrix_forms),
    ("Bézier patches and schemes", bezier::patches),
    ("knot vectors, spans, bases", bspline::bases),
    ("B-spline curves", bspline::bspline_curves),
    ("NURBS curves, conics", bspline::nurbs_curves),
    ("B-spline and NURBS surfaces", bspline::surfaces),
    ("Lagrange bases and interpolants", interpolation::lagrange),
    ("interpolation forms", interpolation::forms),
    ("interpolating splines", interpolation::splines),
    ("Hermite cubics", interpolation::hermite),
    ("Coons patches", coons::coons),
    ("Gregory twists", coons::gregory),
    ("discrete Coons, masks", coons::discrete),
    ("Gordon surfaces", coons::gordon),
    (
        "Coons and Gordon of Bézier curves, as Bézier patches",
        coons::bezier_networks,
    ),
    (
        "sampled curves, ruled, matrix and Ferguson patches",
        coons::surfaces,
    ),
    ("Bernstein bases, binomials, elevation", basics::bernstein),
    ("conversion matrices", basics::conversions),
    ("continuity, integrals", basics::continuity),
    ("linspace, point grids", basics::grids),
    ("exact numbers, limits, costs, tolerances", basics::numbers),
    (
        "B-spline refinement, compatible curves, Coons patches in B-spline form",
        refine::refinement,
    ),
];

/// The number of groups [`call`] chooses from.
pub const OPS: usize = GROUPS.len();

/// One call of group `op` (below [`OPS`]) with arguments from `rng`.
pub fn call(op: usize, rng: &Draws) {
    (GROUPS[op % OPS].1)(rng);
}
