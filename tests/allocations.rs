//! Memory of grid evaluation, counted by a wrapping global allocator: evaluating into a
//! caller-given buffer allocates only the basis rows and per-line samples (`O(N·(m+n))` bytes,
//! a number of allocations that does not grow with the grid), never anything per point.
//!
//! B-spline, NURBS and interpolating-spline batches likewise: basis rows and spans per grid
//! line, segment coefficients, a scratch per block of rows.
//!
//! All cases run in one test function, so that no other test thread allocates meanwhile.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use cagd::bernstein::bernstein_all;
use cagd::bezier::{BezierCurve, BezierPatch};
use cagd::bspline::{BSplineCurve, BSplineSurface, KnotVector};
use cagd::coons::CoonsPatch;
use cagd::gordon::GordonSurface;
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::spline::{CubicSpline, EndCondition};
use cagd::{Curve, Edge, Surface};
use nalgebra::DMatrix;

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);
static BYTES: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        unsafe {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
            BYTES.fetch_add(layout.size(), Ordering::SeqCst);
            System.alloc(layout)
        }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        unsafe {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
            BYTES.fetch_add(new_size, Ordering::SeqCst);
            System.realloc(ptr, layout, new_size)
        }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// `(allocations, bytes)` made while running `f`.
fn count(f: impl FnOnce()) -> (usize, usize) {
    let (a0, b0) = (
        ALLOCATIONS.load(Ordering::SeqCst),
        BYTES.load(Ordering::SeqCst),
    );
    f();
    (
        ALLOCATIONS.load(Ordering::SeqCst) - a0,
        BYTES.load(Ordering::SeqCst) - b0,
    )
}

fn patch(m: usize, n: usize) -> BezierPatch {
    let coords = (0..3)
        .map(|k| DMatrix::from_fn(m + 1, n + 1, |i, j| ((i * 7 + j * 3 + k) % 5) as f64 - 2.0))
        .collect();
    BezierPatch::new(coords).unwrap()
}

fn iso_u(p: &BezierPatch, u0: f64) -> BezierCurve {
    let (m, n) = p.degree();
    let w = bernstein_all(m, u0);
    BezierCurve::new(DMatrix::from_fn(3, n + 1, |k, j| {
        (0..=m).map(|i| w[i] * p.coordinates()[k][(i, j)]).sum()
    }))
    .unwrap()
}

fn iso_v(p: &BezierPatch, v0: f64) -> BezierCurve {
    let (m, n) = p.degree();
    let w = bernstein_all(n, v0);
    BezierCurve::new(DMatrix::from_fn(3, m + 1, |k, i| {
        (0..=n).map(|j| w[j] * p.coordinates()[k][(i, j)]).sum()
    }))
    .unwrap()
}

const F64: usize = std::mem::size_of::<f64>();

/// The side of the largest grids: 250 000 points, far above [`cagd::grid::PARALLEL_MIN_WORK`],
/// so that they are cut into blocks for the thread pool as the 10⁶-point grids were (the
/// claims do not depend on the size beyond that: an allocation per point or per grid line
/// would show as 250 000 or 500 allocations against bounds of a few dozen, and bytes growing
/// like N² as 2 500 times those of a 10² grid against the bound of 200 times). A quarter of
/// the work of 1000² grids in an unoptimised test build.
const LARGE: usize = 500;
/// The points of the largest curve batches (a quarter of 10⁶, for the same reasons).
const MANY: usize = LARGE * LARGE;

#[test]
fn grid_evaluation_allocates_basis_rows_not_points() {
    // Start the thread pool (its one-time setup is not part of any evaluation): any grid large
    // enough to be evaluated on it.
    let warm = patch(3, 3);
    let ts = cagd::linspace(0.0, 1.0, 200);
    let mut out = vec![0.0; 200 * 200 * 3];
    warm.eval_grid_into(&ts, &ts, &mut out).unwrap();

    // Bézier patches, sequential (small) and threaded (large) grids, degrees 3 and 20.
    for (m, n) in [(3, 3), (20, 20)] {
        let p = patch(m, n);
        let mut seen = Vec::new();
        for size in [10, 40, 200, LARGE] {
            let ts = cagd::linspace(0.0, 1.0, size);
            let mut out = vec![0.0; size * size * 3];
            let (allocs, bytes) = count(|| p.eval_grid_into(&ts, &ts, &mut out).unwrap());
            // Basis rows for u and v, the repacked net, one row of coefficients per block of
            // rows, and what the thread pool needs to hand out the blocks.
            let basis = size * (m + 1 + n + 1) + (m + 1) * (n + 1) * 3;
            let scratch_per_block = (n + 1) * 3;
            assert!(allocs <= 48, "({m},{n}) {size}²: {allocs} allocations");
            assert!(
                bytes <= F64 * (basis + 16 * scratch_per_block) + 8192,
                "({m},{n}) {size}²: {bytes} bytes, basis rows {} bytes",
                F64 * basis
            );
            seen.push((size, allocs, bytes));
        }
        // No growth with the number of points: a 500² grid (250 000 points) allocates about as
        // often as a 10² grid; bytes grow like N, not N².
        println!("Bézier ({m},{n}): (N, allocations, bytes) = {seen:?}");
        let (small, large) = (seen[0], seen[3]);
        assert!(large.1 <= small.1 + 40);
        assert!(large.2 < 200 * small.2.max(1024));
    }

    // The Array3 path: the output itself plus the same basis rows.
    let p = patch(3, 3);
    let ts = cagd::linspace(0.0, 1.0, 500);
    let (allocs, bytes) = count(|| {
        let g = p.try_eval_grid(&ts, &ts).unwrap();
        assert_eq!(g.dim(), (500, 500, 3));
    });
    let output = 500 * 500 * 3 * F64;
    assert!(allocs <= 48, "{allocs}");
    assert!(
        bytes <= output + F64 * 500 * 8 + 8192,
        "{bytes} vs output {output}"
    );

    // 250 000 points of a cubic curve: one basis scratch per block of points.
    let c = iso_u(&p, 0.3);
    let ts = cagd::linspace(0.0, 1.0, MANY);
    let mut out = vec![0.0; ts.len() * 3];
    let (allocs, bytes) = count(|| c.eval_many_into(&ts, &mut out).unwrap());
    println!("curve {MANY} points: {allocs} allocations, {bytes} bytes");
    assert!(allocs <= 48, "{allocs}");
    assert!(bytes <= 48 * 256 * 4 * F64, "{bytes}");

    // Coons (Bézier boundaries) and Gordon (5 × 5 cubic Bézier network): samples per grid line.
    let coons = CoonsPatch::new(
        p.boundary(Edge::V0),
        p.boundary(Edge::V1),
        p.boundary(Edge::U0),
        p.boundary(Edge::U1),
    )
    .unwrap();
    let nodes: Vec<f64> = (0..5).map(|i| i as f64 / 4.0).collect();
    let gordon = GordonSurface::new(
        nodes.clone(),
        nodes.clone(),
        nodes.iter().map(|&u| iso_u(&p, u)).collect(),
        nodes.iter().map(|&v| iso_v(&p, v)).collect(),
    )
    .unwrap();
    for size in [100, LARGE] {
        let ts = cagd::linspace(0.0, 1.0, size);
        let mut out = vec![0.0; size * size * 3];
        let (allocs, bytes) = count(|| coons.eval_grid_into(&ts, &ts, &mut out).unwrap());
        println!("Coons {size}²: {allocs} allocations, {bytes} bytes");
        assert!(allocs <= 64, "Coons {size}²: {allocs}");
        // e (2d per row), two sample buffers, d1/d2 (2d per column), [1 − v, v].
        assert!(
            bytes <= F64 * size * 20 + 64 * 1024,
            "Coons {size}²: {bytes}"
        );
        let (allocs, bytes) = count(|| gordon.eval_grid_into(&ts, &ts, &mut out).unwrap());
        println!("Gordon {size}²: {allocs} allocations, {bytes} bytes");
        assert!(allocs <= 80, "Gordon {size}²: {allocs}");
        // Basis rows (5 + 5 per line), samples (5·3 per line, twice, plus a buffer).
        assert!(
            bytes <= F64 * size * 60 + 64 * 1024,
            "Gordon {size}²: {bytes}"
        );
    }

    splines_allocate_per_line_not_per_point();
}

/// B-spline, NURBS and interpolating-spline batches (called from the one test above, so that
/// no other test thread allocates meanwhile): basis rows and spans per grid line, the repacked
/// net, segment coefficients, and a scratch per block of rows — nothing per point. The number
/// of blocks is at most four per thread of the pool.
fn splines_allocate_per_line_not_per_point() {
    let blocks = 4 * std::thread::available_parallelism().map_or(1, |n| n.get()) + 1;
    let k = |p: usize, n: usize| KnotVector::<f64>::clamped_uniform(p, n).unwrap();
    let coords: Vec<DMatrix<f64>> = (0..3)
        .map(|c| DMatrix::from_fn(10, 10, |i, j| ((i * 7 + j * 3 + c) % 5) as f64 - 2.0))
        .collect();
    let ku = k(3, 10).as_slice().to_vec();
    let s = BSplineSurface::new(3, 3, ku.clone(), ku.clone(), coords.clone()).unwrap();
    let w = DMatrix::from_fn(10, 10, |i, j| 1.0 + ((i + j) % 3) as f64 / 2.0);
    let n = NurbsSurface::new(3, 3, ku.clone(), ku.clone(), coords, w).unwrap();
    for (name, surface) in [
        ("B-spline", &s as &dyn Surface),
        ("NURBS", &n as &dyn Surface),
    ] {
        let mut seen = Vec::new();
        for size in [10, 40, 200, LARGE] {
            let ts = cagd::linspace(0.0, 1.0, size);
            let mut out = vec![0.0; size * size * 3];
            let (allocs, bytes) = count(|| surface.eval_grid_into(&ts, &ts, &mut out).unwrap());
            // Basis rows and spans of u and v (4 + 4 numbers per line), the net (300), the
            // runs of v in one span; per block the row's curve (10·4) and, for NURBS, one
            // homogeneous row (4 per point of the row).
            let per_block = 40 + 4 * size;
            assert!(
                allocs <= 24 + 2 * blocks,
                "{name} {size}²: {allocs} allocations"
            );
            assert!(
                bytes <= F64 * (size * 16 + 300 + blocks * per_block) + 8192,
                "{name} {size}²: {bytes} bytes"
            );
            seen.push((size, allocs, bytes));
        }
        println!("{name} bicubic 10×10: (N, allocations, bytes) = {seen:?}");
        let (small, large) = (seen[0], seen[3]);
        assert!(large.1 <= small.1 + 2 * blocks, "{seen:?}");
    }

    // 250 000 points of a cubic B-spline / NURBS curve and of an interpolating spline.
    let control = DMatrix::from_fn(3, 10, |c, i| ((i * 5 + c) % 7) as f64);
    let c = BSplineCurve::new(3, ku.clone(), control.clone()).unwrap();
    let r = NurbsCurve::new(
        3,
        ku,
        control.clone(),
        (0..10).map(|i| 1.0 + i as f64 / 9.0).collect(),
    )
    .unwrap();
    let sp = CubicSpline::interpolate(control, EndCondition::Natural).unwrap();
    for (name, curve, ts) in [
        ("B-spline", &c as &dyn Curve, cagd::linspace(0.0, 1.0, MANY)),
        ("NURBS", &r as &dyn Curve, cagd::linspace(0.0, 1.0, MANY)),
        (
            "spline",
            &sp as &dyn Curve,
            cagd::linspace(-1.0, 10.0, MANY),
        ),
    ] {
        let mut out = vec![0.0; ts.len() * 3];
        let (allocs, bytes) = count(|| curve.eval_many_into(&ts, &mut out).unwrap());
        println!("{name} curve {MANY} points: {allocs} allocations, {bytes} bytes");
        // Four scratch vectors of p + 1 or d + 1 numbers per block; the spline's segment
        // coefficients (9 segments · 3 coordinates · 4).
        assert!(allocs <= 8 + 4 * blocks, "{name}: {allocs}");
        assert!(bytes <= F64 * (108 + 16 * blocks) + 8192, "{name}: {bytes}");
    }
}
