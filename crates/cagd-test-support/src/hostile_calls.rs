//! Calls of the core's public constructors and evaluators with arbitrary arguments: sizes up to
//! `usize::MAX`, indices out of range, knot vectors too short or unsorted, magnitudes near the
//! `f64` range, subnormals, NaN, ±∞ and arbitrary bit patterns. Shared by the property test of
//! the core (`tests/it/hostile_library.rs`, arguments from a seeded LCG) and the `library` fuzz
//! target (`fuzz/fuzz_targets/library.rs`, arguments from the fuzzer's bytes): both call
//! [`call`] under `catch_unwind` and require that it returns.
//!
//! Sizes that the caller itself allocates (matrices, lists) stay small ([`small`]); sizes handed
//! to the library ([`size`]) reach `usize::MAX`.

use std::cell::Cell;

use cagd::bspline::{basis_all, cox_de_boor, find_span, BSplineCurve, BSplineSurface, KnotVector};
use cagd::conversion::{convert, CubicForm};
use cagd::lagrange::{basis_product, try_chebyshev_nodes, Lagrange};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::spline::{solve_tridiagonal, CubicSpline, EndCondition};
use cagd::surfaces::{CubicMatrixPatch, FergusonPatch, RuledSurface};
use cagd::{
    BezierCurve, BezierPatch, Curve, GordonSurface, HermiteCubic, SampledCurve, Surface, Tolerance,
};
use nalgebra::{DMatrix, DVector};

/// The number of groups [`call`] chooses from.
pub const OPS: usize = 14;

/// Where the arguments come from: a seeded 64-bit LCG (the property test), or the bytes of a
/// fuzzer's input, read front to back and continued by the LCG when they run out (the `library`
/// fuzz target, so that every byte the fuzzer mutates changes one choice or one value).
/// Behind a shared reference, so that arguments can be drawn inside the argument lists of other
/// draws.
pub struct Draws<'a> {
    bytes: Cell<&'a [u8]>,
    state: Cell<u64>,
}

impl<'a> Draws<'a> {
    /// Draws from the LCG seeded with `seed`.
    pub fn seeded(seed: u64) -> Self {
        Draws {
            bytes: Cell::new(&[]),
            state: Cell::new(seed | 1),
        }
    }

    /// Draws from `bytes`, then from an LCG.
    pub fn from_bytes(bytes: &'a [u8]) -> Self {
        Draws {
            bytes: Cell::new(bytes),
            state: Cell::new(1),
        }
    }

    fn lcg(&self) -> u64 {
        let x = self
            .state
            .get()
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.state.set(x);
        x
    }

    /// Up to `n` bytes of the input as a little-endian number, or none left.
    fn take(&self, n: usize) -> Option<u64> {
        let bytes = self.bytes.get();
        if bytes.is_empty() {
            return None;
        }
        let (head, rest) = bytes.split_at(n.min(bytes.len()));
        self.bytes.set(rest);
        Some(
            head.iter()
                .rev()
                .fold(0u64, |acc, &b| (acc << 8) | u64::from(b)),
        )
    }

    /// 64 arbitrary bits.
    pub fn bits(&self) -> u64 {
        self.take(8).unwrap_or_else(|| self.lcg())
    }

    /// A number in `[0, 1)`.
    pub fn unit(&self) -> f64 {
        (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A number in `[-1, 1)`.
    pub fn signed(&self) -> f64 {
        2.0 * self.unit() - 1.0
    }

    /// A choice among `n ≥ 1` (one byte of the input, for `n ≤ 256`).
    pub fn below(&self, n: usize) -> usize {
        match self.take(if n <= 256 { 1 } else { 8 }) {
            Some(b) => (b % n as u64) as usize,
            None => {
                ((((self.lcg() >> 11) as f64 / (1u64 << 53) as f64) * n as f64) as usize).min(n - 1)
            }
        }
    }
}

/// A value for an argument: ordinary, tiny, huge, non-finite, or any 64 bits.
pub fn value(rng: &Draws) -> f64 {
    match rng.below(14) {
        12 | 13 => f64::from_bits(rng.bits()),
        0 => f64::NAN,
        1 => f64::INFINITY,
        2 => f64::NEG_INFINITY,
        3 => f64::MAX,
        4 => -1.5e308,
        5 => 5e-324,
        6 => 0.0,
        7 => 1e154,
        _ => 10.0 * rng.signed(),
    }
}

/// A size or index: mostly small, sometimes at or near `usize::MAX`.
pub fn size(rng: &Draws) -> usize {
    match rng.below(10) {
        0 => usize::MAX,
        1 => usize::MAX / 2 + 1,
        2 => 1 << 40,
        _ => rng.below(6),
    }
}

/// A small size, for arguments that are allocated by the test itself.
pub fn small(rng: &Draws) -> usize {
    rng.below(6)
}

pub fn values(rng: &Draws, n: usize) -> Vec<f64> {
    (0..n).map(|_| value(rng)).collect()
}

pub fn matrix(rng: &Draws, rows: usize, cols: usize) -> DMatrix<f64> {
    DMatrix::from_fn(rows, cols, |_, _| value(rng))
}

/// Sorted knots, with repeats, or unsorted and non-finite ones.
pub fn knots(rng: &Draws, n: usize) -> Vec<f64> {
    let mut k = values(rng, n);
    if rng.below(3) > 0 {
        k.retain(|x| x.is_finite());
        k.sort_by(f64::total_cmp);
    }
    k
}

/// One call with arbitrary arguments: `op` (below [`OPS`]) picks the group of functions.
pub fn call(op: usize, rng: &Draws) {
    let t = value(rng);
    match op {
        0 => {
            let c = BezierCurve::new(matrix(rng, small(rng), small(rng)));
            if let Ok(c) = c {
                let _ = c.eval(t);
                let _ = c.try_eval(t);
                let _ = c.eval_many(&values(rng, 3));
                let _ = c.derivative(size(rng));
                let _ = c.subdivide(t);
                let _ = c.scheme(t);
                let _ = c.with_interval(value(rng), value(rng));
            }
        }
        1 => {
            let (d, m, n) = (small(rng), small(rng), small(rng));
            let coords = (0..d).map(|_| matrix(rng, m, n)).collect();
            if let Ok(p) = BezierPatch::new(coords) {
                let _ = p.eval(t, value(rng));
                let _ = p.try_eval(t, value(rng));
                let _ = p.try_eval_grid(&values(rng, 2), &values(rng, 2));
                let _ = p.derivative(size(rng), size(rng));
                let _ = p.control_point(size(rng), size(rng));
            }
        }
        2 => {
            let (p, n, d) = (size(rng), small(rng), small(rng));
            let k = knots(rng, small(rng) + small(rng));
            let _ = find_span(p, n, &k, &t);
            let _ = basis_all(p, n, &k, &t);
            let _ = cox_de_boor(size(rng), p, &k, &t);
            if let Ok(c) = BSplineCurve::new(p, k.clone(), matrix(rng, d, n)) {
                let _ = c.eval(t);
                let _ = c.try_eval(t);
                let _ = c.de_boor(t);
                let _ = c.basis(&t);
                let _ = c.eval_many(&values(rng, 4));
                let _ = c.derivative();
                let _ = c.insert_knot(value(rng));
                let _ = c.insert_knots(&values(rng, 2));
                let _ = cagd::integral::bspline_integral(&c);
            }
            let _ = BSplineCurve::clamped(p, matrix(rng, d, n));
            let _ = BSplineCurve::uniform_cubic(&matrix(rng, d, n), rng.below(2) == 0);
        }
        3 => {
            let (p, n) = (size(rng), size(rng));
            let _ = KnotVector::<f64>::clamped_uniform(p, n);
            let _ = KnotVector::<f64>::uniform(p, n);
            let _ = KnotVector::new(knots(rng, small(rng)));
        }
        4 => {
            let (p, n, d) = (size(rng), small(rng), small(rng));
            let k = knots(rng, small(rng) + small(rng));
            let w = values(rng, n);
            if let Ok(c) = NurbsCurve::new(p, k, matrix(rng, d, n), w) {
                let _ = c.eval(t);
                let _ = c.try_eval(t);
                let _ = c.basis(&t);
                let _ = c.try_eval_derivative(t);
                let _ = c.insert_knots(&values(rng, 2));
                let mut out = vec![0.0; 2 * d];
                let _ = c.eval_many_into(&values(rng, 2), &mut out);
            }
            let _ = NurbsCurve::circle(value(rng), &values(rng, small(rng)));
            let _ = NurbsCurve::arc(value(rng), &values(rng, small(rng)), t, value(rng));
        }
        5 => {
            let (p, q, d) = (size(rng), size(rng), small(rng));
            let (m, n) = (small(rng), small(rng));
            let coords: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
            if let Ok(s) = BSplineSurface::clamped(p, q, coords.clone()) {
                let _ = s.eval(t, value(rng));
                let _ = s.try_eval(t, value(rng));
                let mut out = vec![0.0; 4 * d];
                let _ = s.eval_grid_into(&values(rng, 2), &values(rng, 2), &mut out);
                let weights = matrix(rng, m, n);
                let (ku, kv) = s.knots();
                let _ = NurbsSurface::new(
                    p,
                    q,
                    ku.as_slice().to_vec(),
                    kv.as_slice().to_vec(),
                    coords,
                    weights,
                );
            }
        }
        6 => {
            let n = small(rng);
            let xs = values(rng, n);
            let ys = matrix(rng, small(rng), n);
            let end = match rng.below(3) {
                0 => EndCondition::Natural,
                1 => EndCondition::Closed,
                _ => EndCondition::Clamped {
                    start: DVector::from_vec(values(rng, small(rng))),
                    end: DVector::from_vec(values(rng, small(rng))),
                },
            };
            if let Ok(s) = CubicSpline::interpolate_with_params(ys, xs, end) {
                let _ = s.eval(t);
                let _ = s.try_eval(t);
            }
            let k = small(rng);
            let rhs: Vec<DVector<f64>> = (0..k)
                .map(|_| DVector::from_vec(values(rng, small(rng))))
                .collect();
            let _ = solve_tridiagonal(
                &values(rng, small(rng)),
                &values(rng, k),
                &values(rng, small(rng)),
                &rhs,
            );
        }
        7 => {
            let nodes = values(rng, small(rng));
            let _ = basis_product(&nodes, size(rng), &t);
            if let Ok(l) = Lagrange::new(nodes) {
                let _ = l.basis(&t);
                let mut out = vec![0.0; small(rng)];
                let _ = l.basis_into(&t, &mut out);
                let _ = l.interpolate(&matrix(rng, small(rng), small(rng)), &t);
            }
            let _ = try_chebyshev_nodes(size(rng));
            let _ = cagd::linspace::try_linspace(t, value(rng), size(rng));
        }
        8 => {
            let v = |rng: &Draws, d: usize| DVector::from_vec(values(rng, d));
            let d = small(rng);
            if let Ok(h) = HermiteCubic::new(v(rng, d), v(rng, d), v(rng, d), v(rng, small(rng))) {
                let _ = h.eval(t);
                let _ = h.to_bezier();
            }
            let _ = HermiteCubic::from_geometry(matrix(rng, small(rng), small(rng)));
            let forms = [CubicForm::Hermite, CubicForm::Bezier, CubicForm::BSpline];
            let g = matrix(rng, small(rng), small(rng) + 2);
            let _ = convert(&g, forms[rng.below(3)], forms[rng.below(3)]);
        }
        9 => {
            let (m, n, d) = (small(rng), small(rng), small(rng));
            let net: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
            let _ = cagd::coons::discrete_coons(&net);
            if let Ok(mask) = cagd::coons::Mask::new(value(rng), value(rng)) {
                let _ = cagd::coons::solve_mask(&net, &mask, &cagd::Limits::default());
            }
        }
        10 => {
            // Coons and Gordon over Bézier boundaries of arbitrary values.
            let d = 1 + small(rng) % 3;
            let curve = |rng: &Draws| BezierCurve::new(matrix(rng, d, 1 + small(rng))).ok();
            let (Some(c1), Some(c2), Some(d1), Some(d2)) =
                (curve(rng), curve(rng), curve(rng), curve(rng))
            else {
                return;
            };
            if let Ok(p) = cagd::CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::default()) {
                let _ = p.eval(t, value(rng));
                let _ = p.try_eval(t, value(rng));
            }
            let (Some(us), Some(vs)) = (
                (0..small(rng))
                    .map(|_| curve(rng))
                    .collect::<Option<Vec<_>>>(),
                (0..small(rng))
                    .map(|_| curve(rng))
                    .collect::<Option<Vec<_>>>(),
            ) else {
                return;
            };
            let (un, vn) = (values(rng, us.len()), values(rng, vs.len()));
            if let Ok(g) = GordonSurface::new(un, vn, us, vs) {
                let _ = g.eval(t, value(rng));
                let _ = g.try_eval(t, value(rng));
                let _ = g.eval_parts(t, value(rng));
            }
        }
        12 => {
            // Bernstein bases, degree elevation, products, on arbitrary values.
            let n = small(rng);
            let _ = cagd::bernstein::bernstein(small(rng), n, t);
            let _ = cagd::bernstein::bernstein_all(n, t);
            let _ = cagd::bernstein::bernstein_derivative_all(n, small(rng), t);
            let _ = cagd::bernstein::basis_matrix(n, &values(rng, small(rng)));
            let a = values(rng, small(rng));
            let _ = cagd::bernstein::elevate_once(&a);
            let _ = cagd::bernstein::elevate(&a, small(rng) + small(rng));
            let _ = cagd::bernstein::product(&a, &values(rng, small(rng)));
            if let Ok(c) = BezierCurve::new(matrix(rng, small(rng), small(rng))) {
                let _ = c.elevate().eval(t);
                let _ = c.reversed().eval(t);
                let _ = c.control_point(size(rng));
                let _ = c.eval_derivative(t);
                let _ = c.hodograph();
                let _ = c.eval_bernstein(t);
                let mut out = vec![0.0; small(rng) * 2];
                let _ = c.eval_many_into(&values(rng, 2), &mut out);
            }
        }
        13 => {
            // Sampled curves, ruled surfaces, bicubic matrix patches, Ferguson patches.
            let d = small(rng);
            let n = small(rng);
            let sampled = |rng: &Draws| SampledCurve::new(values(rng, n), matrix(rng, d, n));
            if let (Ok(a), Ok(b)) = (sampled(rng), sampled(rng)) {
                let _ = a.eval(t);
                let _ = a.try_eval(t);
                if let Ok(r) = RuledSurface::new(a, b) {
                    let _ = r.eval(t, value(rng));
                    let _ = r.try_eval(t, value(rng));
                }
            }
            let forms = [CubicForm::Hermite, CubicForm::Bezier, CubicForm::BSpline];
            let coords: Vec<DMatrix<f64>> = (0..d)
                .map(|_| matrix(rng, 3 + small(rng) % 2, 3 + small(rng) % 2))
                .collect();
            if let Ok(p) = CubicMatrixPatch::new(forms[rng.below(3)], coords) {
                let _ = p.eval(t, value(rng));
                let _ = p.try_eval(t, value(rng));
            }
            let v = |rng: &Draws| DVector::from_vec(values(rng, 1 + small(rng) % 3));
            let corners = |rng: &Draws| [[v(rng), v(rng)], [v(rng), v(rng)]];
            if let Ok(p) =
                FergusonPatch::new(&corners(rng), &corners(rng), &corners(rng), &corners(rng))
            {
                let _ = p.eval(t, value(rng));
                let _ = p.try_eval(t, value(rng));
            }
        }
        _ => {
            let d = small(rng);
            let v = |rng: &Draws| DVector::from_vec(values(rng, d));
            let _ = cagd::continuity::joint((&v(rng), &v(rng)), (&v(rng), &v(rng)), value(rng));
            let _ = cagd::continuity::c1_free_point(&v(rng), &v(rng));
            let _ = cagd::bernstein::binomial_f64(size(rng), size(rng));
        }
    }
}
