//! Memory of grid evaluation, counted by a wrapping global allocator: evaluating into a
//! caller-given buffer allocates only the basis rows and per-line samples (`O(N·(m+n))` bytes,
//! a number of allocations that does not grow with the grid), never anything per point.
//!
//! All cases run in one test function, so that no other test thread allocates meanwhile.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use cagd::bernstein::bernstein_all;
use cagd::bezier::{BezierCurve, BezierPatch};
use cagd::coons::CoonsPatch;
use cagd::gordon::GordonSurface;
use cagd::Edge;
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

#[test]
fn grid_evaluation_allocates_basis_rows_not_points() {
    // Start the thread pool (its one-time setup is not part of any evaluation).
    let warm = patch(3, 3);
    let ts = cagd::linspace(0.0, 1.0, 1000);
    let mut out = vec![0.0; 1000 * 1000 * 3];
    warm.eval_grid_into(&ts, &ts, &mut out).unwrap();

    // Bézier patches, sequential (small) and threaded (large) grids, degrees 3 and 20.
    for (m, n) in [(3, 3), (20, 20)] {
        let p = patch(m, n);
        let mut seen = Vec::new();
        for size in [10, 40, 200, 1000] {
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
        // No growth with the number of points: a 1000² grid (10⁶ points) allocates about as
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

    // 10⁶ points of a cubic curve: one basis scratch per block of points.
    let c = iso_u(&p, 0.3);
    let ts = cagd::linspace(0.0, 1.0, 1_000_000);
    let mut out = vec![0.0; ts.len() * 3];
    let (allocs, bytes) = count(|| c.eval_many_into(&ts, &mut out).unwrap());
    println!("curve 10⁶ points: {allocs} allocations, {bytes} bytes");
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
    for size in [100, 1000] {
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
}
