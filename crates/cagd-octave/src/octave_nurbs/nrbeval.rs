//! octave-nurbs' `nrbeval`: NURBS curves, surfaces and volumes at parameters, on grids and at
//! scattered points, with the homogeneous form `[p, w]`.

use cagd::bspline::tensor_point_cost;
use cagd::cost::Cost;
use cagd::nurbs::{rational_point_cost, NurbsCurve, NurbsSurface};

use super::bspeval::{along_axis, bspeval_into, Bsp};
use super::error::{NurbsError, Result};
use super::fast::{
    bezier_pieces, eval_pieces, grid_band_rows, regular, rows_of, swapped_surface, PIECES_FROM,
};
use super::interrupt::Interrupt;
use super::nrb::{Kind, NrbParts};

/// A real array of parameters: Octave's size and its values in storage order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params<'a> {
    /// `size (tt)`.
    pub dims: &'a [usize],
    /// The values.
    pub data: &'a [f64],
}

impl Params<'_> {
    /// `length (tt)`: the largest dimension, 0 when empty.
    pub fn length(&self) -> usize {
        if self.data.is_empty() {
            0
        } else {
            self.dims.iter().copied().max().unwrap_or(0)
        }
    }
}

/// The parameters `tt` of `nrbeval`: an array, or the items of a cell (a grid).
#[derive(Debug, Clone, PartialEq)]
pub enum Tt<'a> {
    /// An array: a curve's parameters, or scattered points of a surface or volume.
    Array(Params<'a>),
    /// A cell: `{u, v}` or `{u, v, w}` (a curve takes a cell of one array).
    Cell(Vec<Params<'a>>),
}

/// How the points are computed.
#[derive(Debug, Clone)]
enum Plan<'a> {
    /// A curve at `u`.
    Curve { b: Bsp<'a>, u: &'a [f64] },
    /// A surface or volume on the grid of `params` (one array per direction).
    Grid {
        dirs: Vec<Bsp<'a>>,
        params: Vec<&'a [f64]>,
        numbers: Vec<usize>,
    },
    /// A surface or volume at the points `pts` (`dirs.len()` numbers each).
    Scattered {
        dirs: Vec<Bsp<'a>>,
        pts: Vec<f64>,
        numbers: Vec<usize>,
    },
}

/// One call of `nrbeval`: the structure and the parameters read and checked as octave-nurbs
/// reads them, with the sizes of the results, ready to evaluate into buffers of those sizes.
///
/// Every value is `bspeval`'s (see [`bspeval_into`]) in `nrbeval`'s order — along `v` then
/// `u` for surfaces, `w`, `v`, `u` for volumes — with the cartesian point the homogeneous one
/// divided by its weight (`p ./ w`): weights of any sign, zero giving ±Inf or NaN as there.
/// Parameters may lie anywhere in `[U(1), U(end)]` of their knots: past the last knot of the
/// domain the last span continues (or gives NaN when it is empty), as there; below `U(p+1)` of
/// a knot vector not clamped at its start, where `bspeval` reads before its arrays, the
/// B-spline's own value (see [`existing_basis`](super::existing_basis)).
///
/// Where every parameter lies in the domain of a well-formed direction (the usual case), the
/// values come from the core's batch kernels instead: curves at many sorted parameters by
/// their Bézier pieces, surface grids as one tensor-product sweep; they
/// agree with `bspeval`'s to rounding.
#[derive(Debug, Clone)]
pub struct NrbEval<'a> {
    plan: Plan<'a>,
    coefs: &'a [f64],
    homogeneous: bool,
    p_dims: Vec<usize>,
    w_dims: Vec<usize>,
}

impl<'a> NrbEval<'a> {
    /// `[p, w] = nrbeval (nurbs, tt)` read: `homogeneous` for two outputs.
    ///
    /// # Errors
    /// Where `nrbeval` fails: [`NurbsError::Refused`] for a structure or parameters it cannot
    /// use (inconsistent knots, `number` that does not fit `coefs`, a grid item that is not a
    /// vector, parameters of the wrong size, fewer than 4 coefficient rows, a cell of knots of
    /// another size than 2 or 3); [`NurbsError::Index`] for missing entries;
    /// [`NurbsError::OutsideKnots`] for a parameter outside its knots.
    pub fn new(nurbs: &NrbParts<'a>, tt: &Tt<'a>, homogeneous: bool) -> Result<Self> {
        match nurbs.kind() {
            Kind::Curve => Self::curve(nurbs, tt, homogeneous),
            Kind::Surface | Kind::Volume => {
                let dim = if nurbs.kind() == Kind::Surface { 2 } else { 3 };
                let numbers = nurbs.numbers(dim)?;
                match tt {
                    Tt::Cell(items) => Self::grid(nurbs, items, numbers, homogeneous),
                    Tt::Array(pts) => Self::scattered(nurbs, pts, numbers, homogeneous),
                }
            }
            Kind::Other(cols) => Err(NurbsError::refused(
                "knots",
                format!("a cell of {cols} columns (nrbeval takes 2 for a surface, 3 for a volume)"),
            )),
        }
    }

    fn curve(nurbs: &NrbParts<'a>, tt: &Tt<'a>, homogeneous: bool) -> Result<Self> {
        let u = match tt {
            Tt::Array(a) => *a,
            Tt::Cell(items) if items.len() == 1 => items[0],
            Tt::Cell(_) => {
                return Err(NurbsError::refused(
                    "tt",
                    "a cell of several arrays for a curve (octave-nurbs: \"the set of parametric points should be an array of doubles\")",
                ))
            }
        };
        if nurbs.order.len() != 1 {
            return Err(NurbsError::refused(
                "order",
                "a curve's order must be a scalar (octave-nurbs: \"degree should be a scalar\")",
            ));
        }
        let (rows, cols) = nurbs.coef_matrix();
        let b = Bsp::new(nurbs.degree(0)?, rows, cols, nurbs.coefs, nurbs.knots(0)?)?;
        if rows < 4 {
            return Err(NurbsError::Index {
                what: "coefs (row 4, the weights)",
                index: 4,
                bound: rows,
            });
        }
        let n = u.data.len();
        let (p_dims, w_dims) = if u.dims.len() == 2 && u.dims[0] == 1 {
            (vec![3, n], vec![1, n])
        } else {
            let mut p = vec![3];
            p.extend_from_slice(u.dims);
            (p, u.dims.to_vec())
        };
        Ok(NrbEval {
            plan: Plan::Curve { b, u: u.data },
            coefs: nurbs.coefs,
            homogeneous,
            p_dims,
            w_dims,
        })
    }

    /// The B-spline of direction `k` along which `nrbeval` evaluates an array with `lead`
    /// rows per control point.
    fn direction(nurbs: &NrbParts<'a>, k: usize, lead: usize, n: usize) -> Result<Bsp<'a>> {
        Bsp::new(nurbs.degree(k)?, lead, n, nurbs.coefs, nurbs.knots(k)?)
    }

    fn grid(
        nurbs: &NrbParts<'a>,
        items: &[Params<'a>],
        numbers: Vec<usize>,
        homogeneous: bool,
    ) -> Result<Self> {
        let dim = numbers.len();
        if items.len() < dim {
            return Err(NurbsError::Index {
                what: "tt (a cell)",
                index: items.len() as i64 + 1,
                bound: items.len(),
            });
        }
        let params: Vec<&[f64]> = items[..dim].iter().map(|p| p.data).collect();
        // A surface reshapes by length (tt{k}), a volume by numel (tt{k}).
        if dim == 2 {
            for (k, p) in items[..2].iter().enumerate() {
                if p.length() != p.data.len() {
                    return Err(NurbsError::refused(
                        if k == 0 { "tt{1}" } else { "tt{2}" },
                        format!(
                            "a {} array: nrbeval reshapes by its length {} (Octave's reshape fails)",
                            p.dims.iter().map(usize::to_string).collect::<Vec<_>>().join("×"),
                            p.length()
                        ),
                    ));
                }
            }
        }
        let dirs = (0..dim)
            .map(|k| Self::direction(nurbs, k, 4, numbers[k]))
            .collect::<Result<Vec<_>>>()?;
        let mut p_dims = vec![3];
        p_dims.extend(params.iter().map(|p| p.len()));
        let mut w_dims = vec![1];
        w_dims.extend(params.iter().map(|p| p.len()));
        Ok(NrbEval {
            plan: Plan::Grid {
                dirs,
                params,
                numbers,
            },
            coefs: nurbs.coefs,
            homogeneous,
            p_dims,
            w_dims,
        })
    }

    fn scattered(
        nurbs: &NrbParts<'a>,
        tt: &Params<'a>,
        numbers: Vec<usize>,
        homogeneous: bool,
    ) -> Result<Self> {
        let dim = numbers.len();
        let st = tt.dims;
        let transpose = st.len() == 2 && st[0] != dim && st[1] == dim;
        let (st, pts): (Vec<usize>, Vec<f64>) = if transpose {
            let n = st[0];
            let mut pts = Vec::with_capacity(tt.data.len());
            for k in 0..n {
                for c in 0..dim {
                    pts.push(tt.data[k + n * c]);
                }
            }
            (vec![dim, n], pts)
        } else {
            (st.to_vec(), tt.data.to_vec())
        };
        let nt: usize = st[1..].iter().product();
        if pts.len() != dim * nt {
            return Err(NurbsError::refused(
                "tt",
                format!(
                    "{} scattered parameters cannot be reshaped to {dim} × {nt} (Octave's reshape fails)",
                    pts.len()
                ),
            ));
        }
        let dirs = (0..dim)
            .map(|k| Self::direction(nurbs, k, 4, numbers[k]))
            .collect::<Result<Vec<_>>>()?;
        let (p_dims, w_dims) = if st.len() != 2 {
            let mut p = vec![3];
            p.extend_from_slice(&st[1..]);
            (p, st[1..].to_vec())
        } else {
            (vec![3, nt], vec![1, nt])
        };
        Ok(NrbEval {
            plan: Plan::Scattered { dirs, pts, numbers },
            coefs: nurbs.coefs,
            homogeneous,
            p_dims,
            w_dims,
        })
    }

    /// `size (p)`.
    pub fn p_dims(&self) -> &[usize] {
        &self.p_dims
    }

    /// `size (w)` (asked for with two outputs).
    pub fn w_dims(&self) -> &[usize] {
        &self.w_dims
    }

    /// The number of points.
    pub fn points(&self) -> usize {
        self.w_dims.iter().product()
    }

    /// The cost of one point: the core's estimate of a NURBS point of these degrees
    /// ([`rational_point_cost`] of the homogeneous tensor product, [`tensor_point_cost`]) —
    /// for a curve or a surface what the core's [`NurbsCurve`] and [`NurbsSurface`] estimate
    /// for themselves, so that the command line's `nurbs` and `nurbs-surface` price the same
    /// points the same.
    pub fn point_cost(&self) -> Cost {
        let dirs: &[Bsp<'_>] = match &self.plan {
            Plan::Curve { b, .. } => std::slice::from_ref(b),
            Plan::Grid { dirs, .. } | Plan::Scattered { dirs, .. } => dirs,
        };
        let mut degrees = [(0, 0); 3];
        for (d, b) in degrees.iter_mut().zip(dirs) {
            d.0 = b.degree;
        }
        rational_point_cost(tensor_point_cost(&degrees[..dirs.len().min(3)], 4, 0, 0), 3)
    }

    /// The points into `p` (of [`p_dims`](Self::p_dims)) and, when homogeneous, the weights
    /// into `w` (of [`w_dims`](Self::w_dims)), in chunks of a few milliseconds of work,
    /// `interrupt` asked before each.
    ///
    /// # Errors
    /// [`NurbsError::OutsideKnots`] for a parameter outside its knots (nothing else is left to
    /// fail); the core's errors on the fast paths (none for the inputs they take);
    /// [`NurbsError::Interrupted`].
    pub fn eval_into(
        &self,
        p: &mut [f64],
        w: Option<&mut [f64]>,
        interrupt: Interrupt<'_>,
    ) -> Result<()> {
        let chunk = if self.points() > super::FEW_ITEMS {
            Interrupt::chunk(self.point_cost().weigh(false))
        } else {
            usize::MAX
        };
        let run = Run { interrupt, chunk };
        match &self.plan {
            Plan::Curve { b, u } => self.curve_into(b, u, (p, w), run),
            Plan::Grid {
                dirs,
                params,
                numbers,
            } => self.grid_into((dirs, params, numbers), (p, w), run),
            Plan::Scattered { dirs, pts, numbers } => {
                self.scattered_into((dirs, pts, numbers), (p, w), run)
            }
        }
    }

    fn unit_weights(&self) -> bool {
        self.coefs.iter().skip(3).step_by(4).all(|&w| w == 1.0)
    }

    fn positive_weights(&self) -> bool {
        self.coefs.iter().skip(3).step_by(4).all(|&w| w > 0.0)
    }

    fn finite_coefs(&self) -> bool {
        self.coefs.iter().all(|x| x.is_finite())
    }

    fn curve_into(
        &self,
        b: &Bsp<'_>,
        u: &[f64],
        (p, w): (&mut [f64], Option<&mut [f64]>),
        run: Run<'_>,
    ) -> Result<()> {
        if b.rows == 4 && regular(b, u) && self.finite_coefs() {
            return self.curve_fast(b, u, (p, w), run);
        }
        let mut h = vec![0.0; b.rows * u.len()];
        bspeval_into(b, u, &mut h, run.interrupt)?;
        split(&h, b.rows, self.homogeneous, p, w);
        Ok(())
    }

    fn curve_fast(
        &self,
        b: &Bsp<'_>,
        u: &[f64],
        (p, w): (&mut [f64], Option<&mut [f64]>),
        run: Run<'_>,
    ) -> Result<()> {
        let nc = b.cols;
        let h = cagd::BSplineCurve::new(b.degree, b.knots.to_vec(), rows_of(b.coefs, 4, 4, nc))?;
        if !self.homogeneous && self.positive_weights() {
            let unit = self.unit_weights();
            let sorted = u.windows(2).all(|x| x[0] <= x[1]);
            if sorted && u.len() >= PIECES_FROM {
                if let Some(pieces) = bezier_pieces(&h, unit)? {
                    return run.chunks(u, (p, 3), |part, out| eval_pieces(&pieces, part, out));
                }
            }
            if unit {
                let xyz = cagd::BSplineCurve::new(
                    b.degree,
                    b.knots.to_vec(),
                    rows_of(b.coefs, 4, 3, nc),
                )?;
                return run.chunks(u, (p, 3), |part, out| Ok(xyz.eval_many_into(part, out)?));
            }
            let nurbs = NurbsCurve::from_homogeneous(h)?;
            return run.chunks(u, (p, 3), |part, out| Ok(nurbs.eval_many_into(part, out)?));
        }
        let mut hv = vec![0.0; 4 * u.len()];
        run.chunks(
            u,
            (&mut hv, 4),
            |part, out| Ok(h.eval_many_into(part, out)?),
        )?;
        split(&hv, 4, self.homogeneous, p, w);
        Ok(())
    }

    fn grid_into(
        &self,
        (dirs, params, numbers): (&[Bsp<'_>], &[&[f64]], &[usize]),
        (p, w): (&mut [f64], Option<&mut [f64]>),
        run: Run<'_>,
    ) -> Result<()> {
        let fast = dirs.len() == 2
            && self.finite_coefs()
            && dirs.iter().zip(params).all(|(b, t)| regular(b, t));
        if fast {
            return self.surface_grid_fast((dirs, params, numbers), (p, w), run);
        }
        let h = self.separable(dirs, params, numbers, run.interrupt)?;
        split(&h, 4, self.homogeneous, p, w);
        Ok(())
    }

    /// `nrbeval`'s passes: along the last direction first, then the others back to `u`, each
    /// by [`along_axis`]; the result is `4 × nt1 × nt2 (× nt3)`.
    fn separable(
        &self,
        dirs: &[Bsp<'_>],
        params: &[&[f64]],
        numbers: &[usize],
        interrupt: Interrupt<'_>,
    ) -> Result<Vec<f64>> {
        let mut sizes: Vec<usize> = numbers.to_vec();
        let mut a = self.coefs.to_vec();
        for k in (0..dirs.len()).rev() {
            let lead: usize = 4 * sizes[..k].iter().product::<usize>();
            let trail: usize = sizes[k + 1..].iter().product();
            let mut out = vec![0.0; lead * params[k].len() * trail];
            along_axis(&dirs[k], (&a, lead, trail), params[k], &mut out, interrupt)?;
            sizes[k] = params[k].len();
            a = out;
        }
        Ok(a)
    }

    /// A surface grid by the core's tensor-product sweep of the surface with its directions
    /// swapped (see [`swapped_surface`]), a band of `v` rows at a time.
    fn surface_grid_fast(
        &self,
        (dirs, params, numbers): (&[Bsp<'_>], &[&[f64]], &[usize]),
        (p, w): (&mut [f64], Option<&mut [f64]>),
        run: Run<'_>,
    ) -> Result<()> {
        let (bu, bv) = (&dirs[0], &dirs[1]);
        let (us, vs) = (params[0], params[1]);
        let (n1, n2) = (numbers[0], numbers[1]);
        let Some(rows) = grid_band_rows(bu, bv, us.len(), 4) else {
            let h = self.separable(dirs, params, numbers, run.interrupt)?;
            split(&h, 4, self.homogeneous, p, w);
            return Ok(());
        };
        let run = Run {
            chunk: rows.saturating_mul(us.len()),
            ..run
        };
        if !self.homogeneous && self.unit_weights() {
            let s = swapped_surface(bu, bv, self.coefs, n1, n2, 3)?;
            return run.bands((vs, us.len()), (p, 3), |band, out| {
                Ok(s.eval_grid_into(band, us, out)?)
            });
        }
        let s = swapped_surface(bu, bv, self.coefs, n1, n2, 4)?;
        if !self.homogeneous && self.positive_weights() {
            let s = NurbsSurface::from_homogeneous(s)?;
            return run.bands((vs, us.len()), (p, 3), |band, out| {
                Ok(s.eval_grid_into(band, us, out)?)
            });
        }
        let mut h = vec![0.0; 4 * us.len() * vs.len()];
        run.bands((vs, us.len()), (&mut h, 4), |band, out| {
            Ok(s.eval_grid_into(band, us, out)?)
        })?;
        split(&h, 4, self.homogeneous, p, w);
        Ok(())
    }

    fn scattered_into(
        &self,
        (dirs, pts, numbers): (&[Bsp<'_>], &[f64], &[usize]),
        (p, w): (&mut [f64], Option<&mut [f64]>),
        run: Run<'_>,
    ) -> Result<()> {
        let dim = dirs.len();
        let nt = pts.len() / dim.max(1);
        // nrbeval checks every parameter of the last direction before the others.
        for k in (0..dim).rev() {
            for x in pts.iter().skip(k).step_by(dim) {
                super::span::check_in_knots("tt", *x, dirs[k].knots)?;
            }
        }
        let mut h = vec![0.0; 4 * nt];
        let mut works: Vec<_> = dirs
            .iter()
            .map(|b| super::bspeval::BasisWork::new(b.degree))
            .collect();
        let mut firsts = [0usize; 3];
        let mut scratch = Vec::new();
        for (j, x) in pts.chunks_exact(dim).enumerate() {
            if j > 0 && j % run.chunk == 0 {
                run.interrupt.check()?;
            }
            for k in 0..dim {
                firsts[k] = works[k].at(&dirs[k], x[k])?;
            }
            point(
                self.coefs,
                numbers,
                &firsts[..dim],
                &works,
                &mut scratch,
                &mut h[4 * j..4 * j + 4],
            );
        }
        split(&h, 4, self.homogeneous, p, w);
        Ok(())
    }
}

/// How the points are evaluated: `chunk` points at a time, `interrupt` asked before each
/// chunk.
#[derive(Debug, Clone, Copy)]
struct Run<'i> {
    interrupt: Interrupt<'i>,
    chunk: usize,
}

impl Run<'_> {
    /// `fill(part, buffer)` over the chunks of `items` and the matching chunks of `out`
    /// (`per` numbers per item), `interrupt` asked between them.
    fn chunks(
        &self,
        items: &[f64],
        (out, per): (&mut [f64], usize),
        mut fill: impl FnMut(&[f64], &mut [f64]) -> Result<()>,
    ) -> Result<()> {
        let size = self.chunk.saturating_mul(per.max(1));
        for (k, (part, buffer)) in items
            .chunks(self.chunk)
            .zip(out.chunks_mut(size))
            .enumerate()
        {
            if k > 0 {
                self.interrupt.check()?;
            }
            fill(part, buffer)?;
        }
        Ok(())
    }

    /// [`chunks`](Self::chunks) of whole rows: `rows` of `row_len` points each (`per`
    /// numbers per point), as many rows at a time as make a chunk of points (at least one).
    fn bands(
        &self,
        (rows, row_len): (&[f64], usize),
        (out, per): (&mut [f64], usize),
        fill: impl FnMut(&[f64], &mut [f64]) -> Result<()>,
    ) -> Result<()> {
        let band = Run {
            chunk: (self.chunk / row_len.max(1)).max(1),
            ..*self
        };
        band.chunks(rows, (out, row_len * per), fill)
    }
}

/// The homogeneous point of a tensor product from the basis of each direction: the sums along
/// the last direction first, then back to the first (`nrbeval`'s order), each from zero.
fn point(
    coefs: &[f64],
    numbers: &[usize],
    firsts: &[usize],
    works: &[super::bspeval::BasisWork],
    scratch: &mut Vec<f64>,
    out: &mut [f64],
) {
    let dim = numbers.len();
    let terms: Vec<usize> = (0..dim)
        .map(|k| {
            works[k]
                .values()
                .len()
                .min(numbers[k].saturating_sub(firsts[k]))
        })
        .collect();
    // Collapse the last direction over the box of the other directions' terms.
    let lead_terms: usize = terms[..dim - 1].iter().product();
    scratch.clear();
    scratch.resize(4 * lead_terms, 0.0);
    for (idx, cell) in scratch.chunks_exact_mut(4).enumerate() {
        // Multi-index of the leading directions (first fastest).
        let mut rem = idx;
        let mut offset = 0;
        let mut stride = 4;
        for k in 0..dim - 1 {
            let t = rem % terms[k];
            rem /= terms[k];
            offset += stride * (firsts[k] + t);
            stride *= numbers[k];
        }
        let last = dim - 1;
        for (c, o) in cell.iter_mut().enumerate() {
            let mut acc = 0.0;
            for (i, nw) in works[last].values()[..terms[last]].iter().enumerate() {
                acc += nw * coefs[c + offset + stride * (firsts[last] + i)];
            }
            *o = acc;
        }
    }
    // Then each remaining direction, from the last of them back to the first.
    let mut len = lead_terms;
    for k in (0..dim - 1).rev() {
        let inner: usize = terms[..k].iter().product();
        let mut next = vec![0.0; 4 * inner];
        for a in 0..inner {
            for c in 0..4 {
                let mut acc = 0.0;
                for (i, nw) in works[k].values()[..terms[k]].iter().enumerate() {
                    acc += nw * scratch[c + 4 * (a + inner * i)];
                }
                next[c + 4 * a] = acc;
            }
        }
        len = inner;
        *scratch = next;
    }
    debug_assert_eq!(len, 1);
    out.copy_from_slice(&scratch[..4]);
}

/// Homogeneous points `h` (`rows` numbers each, weight in row 4) into `p` (3 per point:
/// divided by the weight, `p ./ w`, unless `homogeneous`) and `w`.
fn split(h: &[f64], rows: usize, homogeneous: bool, p: &mut [f64], w: Option<&mut [f64]>) {
    for (o, x) in p.chunks_exact_mut(3).zip(h.chunks_exact(rows)) {
        for c in 0..3 {
            o[c] = if homogeneous { x[c] } else { x[c] / x[3] };
        }
    }
    if let Some(w) = w {
        for (o, x) in w.iter_mut().zip(h.chunks_exact(rows)) {
            *o = x[3];
        }
    }
}
