//! octave-nurbs' evaluators with its arguments and layouts: `cagd_nrbeval`, `cagd_bspeval`,
//! `cagd_basisfun`, `cagd_findspan` take exactly what `nrbeval`, `bspeval`, `basisfun` and
//! `findspan` take (NURBS structures from `nrbmak`, `nrbcirc`, `nrbcoons`…, cell grids
//! `{u, v}`, scattered points) and return the same sizes.
//!
//! Curves and surfaces are the core's [`NurbsCurve`] and [`NurbsSurface`] built from the
//! structure's homogeneous `coefs` as they are (no division and multiplication by the
//! weights); grids are written straight into the array Octave returns. A surface grid
//! `{u, v}` is evaluated as the surface with its two directions swapped, on `(v, u)`: the
//! core's row-major `(nv, nu, 3)` grid of that surface is exactly Octave's `3 × nu × nv`, and
//! its sums run along `v` first, then along `u`, as `nrbeval`'s do. Volumes (three knot
//! vectors) are sums of the core's B-spline basis values, along `w`, then `v`, then `u`, as
//! `nrbeval` does.
//!
//! A curve at a few hundred or more non-decreasing parameters (the usual `linspace`) is
//! evaluated piece by piece: its homogeneous B-spline is cut into Bézier pieces by knot
//! insertion (the core's [`BSplineCurve::insert_knots`], octave-nurbs' `bspkntins`), and each
//! piece is evaluated by the core's Bézier batch ([`BezierCurve::eval_many_into`], Bernstein
//! sums with sizes fixed at compile time for degrees up to 3): the weighted points
//! `(w·x, w·y, w·z)` straight into Octave's array and the weights beside them, in blocks that
//! stay in the cache, then multiplied by `1/w`. This avoids the `p(p+1)/2` divisions per point
//! of the triangular B-spline basis; the values agree with `nrbeval` to rounding (knot
//! insertion and Bernstein sums are convex combinations). Other curves take the core's
//! [`NurbsCurve::eval_many_into`]. When every weight is exactly 1 (a B-spline written as a
//! NURBS, the usual case) the weights are not evaluated and nothing is divided: curves and
//! surface grids are the core's B-spline (or Bézier-piece) batches of the first three rows of
//! `coefs` (a division by a weight sum of 1 would only add rounding).
//!
//! One deliberate difference: a parameter outside the domain `[U(p+1), U(end-p)]` is an error
//! (`cagd:domain`) where octave-nurbs extrapolates the first or last polynomial piece.

use cagd::bezier::BezierCurve;
use cagd::bspline::{basis_functions, find_span, BSplineCurve, BSplineSurface, KnotVector};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use nalgebra::DMatrix;
use rayon::prelude::*;

use crate::args::{nonempty_of, params_of, real_of, Call};
use crate::error::{Kind, PkgError, Result};
use crate::value::{Real, Sink, Value};

/// The form of a NURBS structure.
const NURBS_FORM: &str = "a NURBS structure from nrbmak (fields form, coefs, knots, order)";

/// A NURBS structure read: per direction the degree and the knots, and the homogeneous
/// coefficients `coefs` (`4 × n1 × n2 × …`, column-major).
struct Nurbs<'a> {
    degrees: Vec<usize>,
    knots: Vec<&'a [f64]>,
    counts: Vec<usize>,
    coefs: &'a [f64],
}

/// `nurbs.field`, or the error naming the missing field.
fn field<'v, 'a>(nurbs: &'v Value<'a>, name: &str) -> Result<&'v Value<'a>> {
    nurbs.field(name).ok_or_else(|| {
        PkgError::arg(
            Kind::Struct,
            "NURBS",
            format!("the structure has no field '{name}'"),
            NURBS_FORM,
        )
    })
}

/// Reads and checks a NURBS structure (the core checks knots, weights and values again when
/// it builds the curve or surface).
fn read_nurbs<'a>(v: &Value<'a>) -> Result<Nurbs<'a>> {
    if !matches!(v, Value::Struct { .. }) {
        return Err(PkgError::arg(
            Kind::Struct,
            "NURBS",
            format!("{} is not a NURBS structure", v.class()),
            NURBS_FORM,
        ));
    }
    let form = field(v, "form")?.text().unwrap_or_default();
    if form != "B-NURBS" {
        return Err(PkgError::arg(
            Kind::Struct,
            "NURBS.form",
            format!("'{form}' is not a recognised NURBS representation"),
            "'B-NURBS'",
        ));
    }
    let knots: Vec<&[f64]> = match field(v, "knots")? {
        Value::Cell { items, .. } => items
            .iter()
            .map(|k| nonempty_of(k, "NURBS.knots", "knot vectors").map(|r| r.data))
            .collect::<Result<_>>()?,
        other => vec![nonempty_of(other, "NURBS.knots", "a knot vector")?.data],
    };
    let dirs = knots.len();
    if !(1..=3).contains(&dirs) {
        return Err(PkgError::arg(
            Kind::Struct,
            "NURBS.knots",
            format!("{dirs} knot vectors"),
            "1 (curve), 2 (surface) or 3 (volume) knot vectors",
        ));
    }
    let order = real_of(field(v, "order")?, "NURBS.order", "the orders (degree + 1)")?;
    if order.len() != dirs {
        return Err(PkgError::arg(
            Kind::Struct,
            "NURBS.order",
            format!("{} values for {dirs} knot vector(s)", order.len()),
            "one order per knot vector",
        ));
    }
    let mut degrees = Vec::with_capacity(dirs);
    for &o in order.data {
        if !(o.is_finite() && o >= 1.0 && o.fract() == 0.0) {
            return Err(PkgError::arg(
                Kind::Value,
                "NURBS.order",
                format!("{o} is not a positive integer"),
                "the orders (degree + 1)",
            ));
        }
        degrees.push(o as usize - 1);
    }
    let coefs = nonempty_of(
        field(v, "coefs")?,
        "NURBS.coefs",
        "4 × n1 × … homogeneous coefficients",
    )?;
    let counts = coef_counts(&coefs, dirs)?;
    Ok(Nurbs {
        degrees,
        knots,
        counts,
        coefs: coefs.data,
    })
}

/// The numbers of control points per direction of `coefs` (`4 × n1 × n2 × …`, trailing
/// singletons dropped by Octave).
fn coef_counts(coefs: &Real<'_>, dirs: usize) -> Result<Vec<usize>> {
    let dims = coefs.dims;
    let extra_ok = dims.iter().skip(1 + dirs).all(|&d| d == 1);
    if dims[0] != 4 || !extra_ok {
        return Err(PkgError::arg(
            Kind::Shape,
            "NURBS.coefs",
            format!("size {}", coefs.size_str()),
            "4 × n1 × … (one n per knot vector): homogeneous coefficients (w·x, w·y, w·z, w)",
        ));
    }
    Ok((0..dirs)
        .map(|k| dims.get(1 + k).copied().unwrap_or(1))
        .collect())
}

impl Nurbs<'_> {
    /// The curve (one direction) as the core's NURBS curve and its homogeneous B-spline.
    fn curve(&self) -> Result<NurbsCurve> {
        let h = DMatrix::from_column_slice(4, self.counts[0], self.coefs);
        let b = BSplineCurve::new(self.degrees[0], self.knots[0].to_vec(), h)?;
        Ok(NurbsCurve::from_homogeneous(b)?)
    }

    /// The surface with its directions swapped: `S'(v, u) = S(u, v)` (see the module docs).
    fn swapped_surface(&self) -> Result<NurbsSurface> {
        let (n1, n2) = (self.counts[0], self.counts[1]);
        let coords = (0..4)
            .map(|k| DMatrix::from_fn(n2, n1, |j, i| self.coefs[k + 4 * (i + n1 * j)]))
            .collect();
        let b = BSplineSurface::new(
            self.degrees[1],
            self.degrees[0],
            self.knots[1].to_vec(),
            self.knots[0].to_vec(),
            coords,
        )?;
        Ok(NurbsSurface::from_homogeneous(b)?)
    }

    /// Whether every weight is exactly 1: then the NURBS is the B-spline of its first three
    /// rows of coefficients, and the division by the weight (1 up to rounding) is left out.
    fn unit_weights(&self) -> bool {
        self.coefs.iter().skip(3).step_by(4).all(|&w| w == 1.0)
    }

    /// The B-spline surface of the first three rows of coefficients, directions swapped (for
    /// unit weights, see [`unit_weights`](Self::unit_weights)).
    fn swapped_bspline(&self) -> Result<BSplineSurface> {
        let (n1, n2) = (self.counts[0], self.counts[1]);
        let coords = (0..3)
            .map(|k| DMatrix::from_fn(n2, n1, |j, i| self.coefs[k + 4 * (i + n1 * j)]))
            .collect();
        Ok(BSplineSurface::new(
            self.degrees[1],
            self.degrees[0],
            self.knots[1].to_vec(),
            self.knots[0].to_vec(),
            coords,
        )?)
    }

    /// The surface as it is, `S(u, v)`.
    fn surface(&self) -> Result<NurbsSurface> {
        let (n1, n2) = (self.counts[0], self.counts[1]);
        let coords = (0..4)
            .map(|k| DMatrix::from_fn(n1, n2, |i, j| self.coefs[k + 4 * (i + n1 * j)]))
            .collect();
        let b = BSplineSurface::new(
            self.degrees[0],
            self.degrees[1],
            self.knots[0].to_vec(),
            self.knots[1].to_vec(),
            coords,
        )?;
        Ok(NurbsSurface::from_homogeneous(b)?)
    }

    /// Checks a volume's knots (non-decreasing, `n + p + 1` of them) and weights.
    fn check_volume(&self) -> Result<()> {
        for k in 0..3 {
            let kv = KnotVector::new(self.knots[k].to_vec())?;
            let (p, n) = (self.degrees[k], self.counts[k]);
            if n < p + 1 {
                return Err(cagd::Error::TooFewControlPoints {
                    what: "NURBS volume",
                    degree: p,
                    min: p + 1,
                    found: n,
                }
                .into());
            }
            if kv.len() != n + p + 1 {
                return Err(cagd::Error::KnotCount {
                    what: "NURBS volume",
                    expected: n + p + 1,
                    found: kv.len(),
                }
                .into());
            }
        }
        cagd::error::check_finite("NURBS volume coefficients", self.coefs.iter())?;
        for (index, w) in self.coefs.iter().skip(3).step_by(4).enumerate() {
            if *w <= 0.0 {
                return Err(cagd::Error::NonPositiveWeight {
                    what: "NURBS volume weights",
                    index,
                    value: *w,
                }
                .into());
            }
        }
        Ok(())
    }

    /// The span and the non-zero basis values of direction `k` at `t` (domain checked).
    fn basis(&self, k: usize, t: f64) -> Result<(usize, Vec<f64>)> {
        let (p, n, knots) = (self.degrees[k], self.counts[k], self.knots[k]);
        let s = find_span(p, n, knots, &t)?;
        Ok((s - p, basis_functions(p, knots, s, &t)))
    }

    /// The homogeneous point of a volume from the basis of its three directions: the sums
    /// along `w`, then `v`, then `u` (as `nrbeval`).
    fn volume_point(
        &self,
        bu: &(usize, Vec<f64>),
        bv: &(usize, Vec<f64>),
        bw: &(usize, Vec<f64>),
    ) -> [f64; 4] {
        let (n1, n2) = (self.counts[0], self.counts[1]);
        let mut out = [0.0; 4];
        for (c, o) in out.iter_mut().enumerate() {
            let mut su = 0.0;
            for (a, nu) in bu.1.iter().enumerate() {
                let mut sv = 0.0;
                for (b, nv) in bv.1.iter().enumerate() {
                    let mut sw = 0.0;
                    for (e, nw) in bw.1.iter().enumerate() {
                        let (i, j, l) = (bu.0 + a, bv.0 + b, bw.0 + e);
                        sw += nw * self.coefs[c + 4 * (i + n1 * (j + n2 * l))];
                    }
                    sv += nv * sw;
                }
                su += nu * sv;
            }
            *o = su;
        }
        out
    }
}

/// The parameters of one direction of a grid `{u, v, …}`: item `k` of the cell, any real
/// array (column-major).
fn grid_params<'a>(items: &[Value<'a>], k: usize) -> Result<&'a [f64]> {
    const NAMES: [&str; 3] = ["tt{1}", "tt{2}", "tt{3}"];
    params_of(&items[k], NAMES[k])
}

/// Writes homogeneous points (`4` numbers each, in order) as `p` (`3 × …`, divided by the
/// weight unless `homogeneous`) and, when asked, `w` (`1 × …`): `p_dims`, `w_dims` are their
/// Octave sizes.
fn emit_points(
    call: &Call<'_, '_>,
    sink: &mut dyn Sink,
    h: &[f64],
    p_dims: &[usize],
    w_dims: &[usize],
) -> Result<()> {
    let homogeneous = call.nargout >= 2;
    let p = sink.real(0, p_dims)?;
    for (o, x) in p.chunks_exact_mut(3).zip(h.chunks_exact(4)) {
        for c in 0..3 {
            o[c] = if homogeneous { x[c] } else { x[c] / x[3] };
        }
    }
    if homogeneous {
        let w = sink.real(1, w_dims)?;
        for (o, x) in w.iter_mut().zip(h.chunks_exact(4)) {
            *o = x[3];
        }
    }
    Ok(())
}

/// `[p, w] = cagd_nrbeval (nurbs, tt)`: `nrbeval`.
pub fn nrbeval(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "[p, w] = cagd_nrbeval (nurbs, tt)")?;
    call.nargout_max(2)?;
    let nurbs = read_nurbs(call.arg(0))?;
    match nurbs.knots.len() {
        1 => nrbeval_curve(call, sink, &nurbs),
        2 => nrbeval_surface(call, sink, &nurbs),
        _ => nrbeval_volume(call, sink, &nurbs),
    }
}

fn nrbeval_curve(call: &Call<'_, '_>, sink: &mut dyn Sink, nurbs: &Nurbs<'_>) -> Result<()> {
    let tt = match call.arg(1) {
        Value::Cell { items, .. } if items.len() == 1 => &items[0],
        other => other,
    };
    let r = real_of(tt, "tt", "the curve parameters (a double array)")?;
    let t = r.data;
    let curve = nurbs.curve()?;
    call.check_samples("tt", t.len())?;
    call.check_work("tt", t.len(), (curve.degree() + 1) * (curve.degree() + 5))?;
    // As nrbeval: a row gives 3 × n and 1 × n, any other shape [3, size(tt)] and size(tt).
    let (p_dims, w_dims) = if r.dims.len() == 2 && r.dims[0] == 1 {
        (vec![3, t.len()], vec![1, t.len()])
    } else {
        let mut p = vec![3];
        p.extend_from_slice(r.dims);
        (p, r.dims.to_vec())
    };
    // One pass over the parameters: finite, in the domain, and whether they are sorted.
    let (lo, hi) = curve.domain();
    let mut sorted = true;
    for (k, &x) in t.iter().enumerate() {
        if !x.is_finite() {
            return Err(cagd::Error::NonFinite {
                what: "tt",
                index: k,
                value: x,
            }
            .into());
        }
        check_domain(&[x], lo, hi)?;
        sorted &= k == 0 || t[k - 1] <= x;
    }
    if call.nargout >= 2 {
        let mut h = vec![0.0; 4 * t.len()];
        curve.homogeneous().eval_many_into(t, &mut h)?;
        return emit_points(call, sink, &h, &p_dims, &w_dims);
    }
    // Cutting the curve into pieces pays from a few hundred points on.
    let unit = nurbs.unit_weights();
    let pieces = if sorted && t.len() >= PIECES_FROM {
        bezier_pieces(curve.homogeneous(), unit)?
    } else {
        None
    };
    let out = sink.real(0, &p_dims)?;
    match pieces {
        Some(pieces) => eval_pieces(&pieces, t, out)?,
        None if unit => {
            let h = curve.homogeneous();
            let xyz = DMatrix::from_fn(3, h.control().ncols(), |i, j| h.control()[(i, j)]);
            let b = BSplineCurve::new(h.degree(), h.knots().as_slice().to_vec(), xyz)?;
            b.eval_many_into(t, out)?;
        }
        None => curve.eval_many_into(t, out)?,
    }
    Ok(())
}

/// The number of parameters from which a curve is evaluated by its Bézier pieces.
const PIECES_FROM: usize = 256;

/// One Bézier piece of a homogeneous curve: its interval, the curve of its weighted points
/// `(w·x, w·y, w·z)` and the curve of its weights as the plane curve `(w, 0)` (plane and
/// space curves of degree up to 3 have the core's fastest kernels); no weight curve when every
/// weight is 1.
struct Piece {
    a: f64,
    b: f64,
    weighted: BezierCurve,
    weight: Option<BezierCurve>,
}

/// The Bézier pieces of a homogeneous (4-D) B-spline curve whose domain ends are clamped
/// (the first and last `p + 1` knots of the domain equal): every interior knot raised to
/// multiplicity `p` by knot insertion, then one piece per non-empty span. `None` for other
/// knot vectors. With `unit_weights` the pieces carry no weight curve.
fn bezier_pieces(h: &BSplineCurve, unit_weights: bool) -> Result<Option<Vec<Piece>>> {
    let p = h.degree();
    let knots = h.knots().as_slice();
    let n = h.control().ncols();
    let (lo, hi) = (knots[p], knots[n]);
    let clamped = knots[1..=p].iter().all(|&k| k == lo) && knots[n..n + p].iter().all(|&k| k == hi);
    if !clamped {
        return Ok(None);
    }
    let mut insert = Vec::new();
    let mut k = p + 1;
    while k < n {
        let x = knots[k];
        let mult = knots[k..n].iter().take_while(|&&y| y == x).count();
        if lo < x && x < hi {
            insert.extend(std::iter::repeat_n(x, p.saturating_sub(mult)));
        }
        k += mult;
    }
    let r = h.insert_knots(&insert)?;
    let (rk, rc) = (r.knots().as_slice(), r.control());
    let mut pieces = Vec::new();
    for s in p..rc.ncols() {
        if rk[s] < rk[s + 1] {
            let cols = rc.columns(s - p, p + 1);
            let weighted = DMatrix::from_fn(3, p + 1, |i, j| cols[(i, j)]);
            let weight = DMatrix::from_fn(2, p + 1, |i, j| if i == 0 { cols[(3, j)] } else { 0.0 });
            let weight = if unit_weights {
                None
            } else {
                Some(BezierCurve::new_on_interval(weight, rk[s], rk[s + 1])?)
            };
            pieces.push(Piece {
                a: rk[s],
                b: rk[s + 1],
                weighted: BezierCurve::new_on_interval(weighted, rk[s], rk[s + 1])?,
                weight,
            });
        }
    }
    Ok(Some(pieces))
}

/// Parameters per block of [`eval_pieces`]: the weights of a block (`2 × BLOCK` numbers) and
/// its points stay in the cache between the evaluation and the division.
const BLOCK: usize = 4096;

/// The curve at the non-decreasing parameters `t` (all in the domain) into `out` (`3` numbers
/// per point), piece by piece: a parameter on a breakpoint belongs to the piece on its right
/// (as `findspan`), the right end of the domain to the last piece. Blocks of [`BLOCK`]
/// parameters run on all cores.
fn eval_pieces(pieces: &[Piece], t: &[f64], out: &mut [f64]) -> Result<()> {
    // Unit weights: nothing to divide, each piece's run straight into the output (the core
    // splits long runs over the cores itself).
    if pieces[0].weight.is_none() {
        return Ok(eval_runs(pieces, t, out, &mut [])?);
    }
    t.par_chunks(BLOCK)
        .zip(out.par_chunks_mut(3 * BLOCK))
        .try_for_each(|(ts, out)| {
            let mut w = vec![0.0; 2 * ts.len()];
            eval_runs(pieces, ts, out, &mut w)?;
            for (x, w) in out.chunks_exact_mut(3).zip(w.chunks_exact(2)) {
                let r = 1.0 / w[0];
                for c in x {
                    *c *= r;
                }
            }
            Ok::<(), cagd::Error>(())
        })?;
    Ok(())
}

/// The weighted points (into `out`, 3 per point) and, for pieces with a weight curve, the
/// weights (into `w`, 2 per point) at the non-decreasing parameters `ts`, each run of
/// parameters by the piece holding it.
fn eval_runs(pieces: &[Piece], ts: &[f64], out: &mut [f64], w: &mut [f64]) -> cagd::Result<()> {
    let Some(&t0) = ts.first() else {
        return Ok(());
    };
    let mut start = 0;
    // The first piece holding ts[0]: the last whose start is at most ts[0].
    let first = pieces.partition_point(|p| p.a <= t0).saturating_sub(1);
    for (k, piece) in pieces.iter().enumerate().skip(first) {
        if start == ts.len() {
            break;
        }
        let last = k + 1 == pieces.len();
        let len = ts[start..]
            .iter()
            .take_while(|&&x| x < piece.b || (last && x <= piece.b))
            .count();
        let end = start + len;
        if len > 0 {
            piece
                .weighted
                .eval_many_into(&ts[start..end], &mut out[3 * start..3 * end])?;
            if let Some(weight) = &piece.weight {
                weight.eval_many_into(&ts[start..end], &mut w[2 * start..2 * end])?;
            }
        }
        start = end;
    }
    Ok(())
}

/// Every parameter in `[lo, hi]`, or the core's out-of-domain error for the first that is not.
fn check_domain(t: &[f64], lo: f64, hi: f64) -> Result<()> {
    match t.iter().find(|&&x| !(lo..=hi).contains(&x)) {
        None => Ok(()),
        Some(&x) => Err(cagd::Error::ParameterOutOfRange {
            what: "NURBS parameter",
            value: x,
            min: lo,
            max: hi,
        }
        .into()),
    }
}

fn nrbeval_surface(call: &Call<'_, '_>, sink: &mut dyn Sink, nurbs: &Nurbs<'_>) -> Result<()> {
    let (p, q) = (nurbs.degrees[0], nurbs.degrees[1]);
    if let Value::Cell { items, .. } = call.arg(1) {
        if items.len() != 2 {
            return Err(PkgError::arg(
                Kind::Shape,
                "tt",
                format!("a cell of {} parameter arrays", items.len()),
                "{u, v} for a surface",
            ));
        }
        let (us, vs) = (grid_params(items, 0)?, grid_params(items, 1)?);
        call.check_grid("tt", us.len(), vs.len())?;
        call.check_work("tt", us.len() * vs.len(), (p + q + 2) * 4)?;
        let s = nurbs.swapped_surface()?;
        let ((v0, v1), (u0, u1)) = s.homogeneous().domain();
        check_domain(us, u0, u1)?;
        check_domain(vs, v0, v1)?;
        let p_dims = [3, us.len(), vs.len()];
        if call.nargout < 2 && nurbs.unit_weights() {
            let out = sink.real(0, &p_dims)?;
            nurbs.swapped_bspline()?.eval_grid_into(vs, us, out)?;
            return Ok(());
        }
        if call.nargout < 2 {
            let out = sink.real(0, &p_dims)?;
            s.eval_grid_into(vs, us, out)?;
            return Ok(());
        }
        let mut h = vec![0.0; 4 * us.len() * vs.len()];
        s.homogeneous().eval_grid_into(vs, us, &mut h)?;
        return emit_points(call, sink, &h, &p_dims, &[1, us.len(), vs.len()]);
    }
    let (pts, out_dims) = scattered(call, 2)?;
    call.check_samples("tt", pts.len() / 2)?;
    let s = nurbs.surface()?;
    let mut h = Vec::with_capacity(2 * pts.len());
    for uv in pts.chunks_exact(2) {
        h.extend(s.homogeneous().try_eval(uv[0], uv[1])?.iter().copied());
    }
    emit_scattered(call, sink, &h, &out_dims)
}

/// Scattered parameters `tt` of a surface (`dim = 2`) or volume (`dim = 3`): `dim × n` (or
/// `n × dim`, transposed, as nrbeval), or `dim × a × b…`. Returns the points one after the
/// other and the size of the point array after the first dimension.
fn scattered(call: &Call<'_, '_>, dim: usize) -> Result<(Vec<f64>, Vec<usize>)> {
    let r = real_of(
        call.arg(1),
        "tt",
        "scattered parameters (dim × n) or a cell grid",
    )?;
    let t = params_of(call.arg(1), "tt")?;
    let dims = r.dims;
    if dims.len() == 2 && dims[0] != dim && dims[1] == dim {
        let n = dims[0];
        let mut pts = Vec::with_capacity(t.len());
        for k in 0..n {
            for c in 0..dim {
                pts.push(t[k + n * c]);
            }
        }
        return Ok((pts, vec![n]));
    }
    if dims[0] != dim {
        return Err(PkgError::arg(
            Kind::Shape,
            "tt",
            format!("size {}", r.size_str()),
            &format!("{dim} × n scattered parameters, or a cell grid"),
        ));
    }
    Ok((t.to_vec(), dims[1..].to_vec()))
}

/// Writes scattered homogeneous points: `p` is `3 × n` (`3 × a × b…` for an n-d `tt`), `w`
/// is `1 × n` (`a × b…`).
fn emit_scattered(
    call: &Call<'_, '_>,
    sink: &mut dyn Sink,
    h: &[f64],
    rest: &[usize],
) -> Result<()> {
    let n: usize = rest.iter().product();
    let (p_dims, w_dims) = if rest.len() <= 1 {
        (vec![3, n], vec![1, n])
    } else {
        let mut p = vec![3];
        p.extend_from_slice(rest);
        (p, rest.to_vec())
    };
    emit_points(call, sink, h, &p_dims, &w_dims)
}

fn nrbeval_volume(call: &Call<'_, '_>, sink: &mut dyn Sink, nurbs: &Nurbs<'_>) -> Result<()> {
    nurbs.check_volume()?;
    let terms: usize = nurbs.degrees.iter().map(|p| p + 1).product();
    if let Value::Cell { items, .. } = call.arg(1) {
        if items.len() != 3 {
            return Err(PkgError::arg(
                Kind::Shape,
                "tt",
                format!("a cell of {} parameter arrays", items.len()),
                "{u, v, w} for a volume",
            ));
        }
        let t: Vec<&[f64]> = (0..3)
            .map(|k| grid_params(items, k))
            .collect::<Result<_>>()?;
        let (n1, n2, n3) = (t[0].len(), t[1].len(), t[2].len());
        call.check_grid("tt", n1, n2)?;
        call.check_grid("tt", n1 * n2, n3)?;
        call.check_work("tt", n1 * n2 * n3, terms * 4)?;
        let b: Vec<Vec<(usize, Vec<f64>)>> = (0..3)
            .map(|k| {
                t[k].iter()
                    .map(|&x| nurbs.basis(k, x))
                    .collect::<Result<_>>()
            })
            .collect::<Result<_>>()?;
        let mut h = Vec::with_capacity(4 * n1 * n2 * n3);
        for bw in &b[2] {
            for bv in &b[1] {
                for bu in &b[0] {
                    h.extend(nurbs.volume_point(bu, bv, bw));
                }
            }
        }
        return emit_points(call, sink, &h, &[3, n1, n2, n3], &[1, n1, n2, n3]);
    }
    let (pts, out_dims) = scattered(call, 3)?;
    call.check_samples("tt", pts.len() / 3)?;
    call.check_work("tt", pts.len() / 3, terms * 4)?;
    let mut h = Vec::with_capacity(4 * pts.len() / 3);
    for x in pts.chunks_exact(3) {
        let (bu, bv, bw) = (
            nurbs.basis(0, x[0])?,
            nurbs.basis(1, x[1])?,
            nurbs.basis(2, x[2])?,
        );
        h.extend(nurbs.volume_point(&bu, &bv, &bw));
    }
    emit_scattered(call, sink, &h, &out_dims)
}

/// `p = cagd_bspeval (d, c, k, u)`: `bspeval`.
pub fn bspeval(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "p = cagd_bspeval (d, c, k, u)")?;
    call.nargout_max(1)?;
    let d = call.count(0, "d")?;
    call.check_degree("d", d)?;
    let c = call.matrix(1, "c", "the control points, mc × nc (one per column)")?;
    let k = knot_vector(call, 2, "k")?;
    let u = call.params(3, "u")?;
    call.check_samples("u", u.len())?;
    call.check_work("u", u.len(), (d + 1) * (d + 1 + c.nrows()))?;
    let mc = c.nrows();
    let curve = BSplineCurve::new(d, k, c)?;
    let (lo, hi) = curve.domain();
    check_domain(u, lo, hi)?;
    let out = sink.real(0, &[mc, u.len()])?;
    curve.try_eval_many_into(u, out)?;
    Ok(())
}

/// Argument `i` as a knot vector (any real vector, finite, non-decreasing).
fn knot_vector(call: &Call<'_, '_>, i: usize, what: &'static str) -> Result<Vec<f64>> {
    let r = call.nonempty(i, what, "a knot vector")?;
    let knots = KnotVector::new(r.data.to_vec()).map_err(|e| match e {
        cagd::Error::DecreasingKnots {
            index,
            previous,
            next,
            ..
        } => cagd::Error::DecreasingKnots {
            what,
            index,
            previous,
            next,
        },
        other => other,
    })?;
    Ok(knots.as_slice().to_vec())
}

/// `B = cagd_basisfun (iv, uv, p, U)`: `basisfun`.
pub fn basisfun(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "B = cagd_basisfun (iv, uv, p, U)")?;
    call.nargout_max(1)?;
    let iv = call.params(0, "iv")?;
    let uv = call.params(1, "uv")?;
    let p = call.count(2, "p")?;
    call.check_degree("p", p)?;
    let knots = knot_vector(call, 3, "U")?;
    if iv.len() != uv.len() {
        return Err(PkgError::arg(
            Kind::Shape,
            "iv",
            format!("{} spans for {} parameters", iv.len(), uv.len()),
            "one span per parameter (from cagd_findspan)",
        ));
    }
    call.check_samples("uv", uv.len())?;
    call.check_work("uv", uv.len(), (p + 1) * (p + 1))?;
    let last = knots.len().saturating_sub(p + 2);
    let mut spans = Vec::with_capacity(iv.len());
    for &s in iv {
        let ok = s.fract() == 0.0 && s >= p as f64 && s <= last as f64;
        let si = s as usize;
        if !ok || knots[si] >= knots[si + 1] {
            return Err(PkgError::arg(
                Kind::Value,
                "iv",
                format!("span {s} is not a non-empty knot span of degree {p}"),
                &format!(
                    "an integer s, {p} ≤ s ≤ {last}, with U(s+1) < U(s+2) (as cagd_findspan gives)"
                ),
            ));
        }
        spans.push(si);
    }
    let n = uv.len();
    let out = sink.real(0, &[n, p + 1])?;
    for (row, (&s, u)) in spans.iter().zip(uv).enumerate() {
        for (j, b) in basis_functions(p, &knots, s, u).into_iter().enumerate() {
            out[row + n * j] = b;
        }
    }
    Ok(())
}

/// `s = cagd_findspan (n, p, u, U)`: `findspan`.
pub fn findspan(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "s = cagd_findspan (n, p, u, U)")?;
    call.nargout_max(1)?;
    let n = call.count(0, "n")?;
    let p = call.count(1, "p")?;
    call.check_degree("p", p)?;
    let u_dims = call.real(2, "u", "the parameters")?.dims;
    let u = call.params(2, "u")?;
    let knots = knot_vector(call, 3, "U")?;
    if n < p {
        return Err(cagd::Error::TooFewControlPoints {
            what: "n",
            degree: p,
            min: p + 1,
            found: n + 1,
        }
        .into());
    }
    if knots.len() != n + p + 2 {
        return Err(cagd::Error::KnotCount {
            what: "U",
            expected: n + p + 2,
            found: knots.len(),
        }
        .into());
    }
    call.check_samples("u", u.len())?;
    let spans = u
        .iter()
        .map(|x| find_span(p, n + 1, &knots, x))
        .collect::<cagd::Result<Vec<_>>>()?;
    let out = sink.real(0, u_dims)?;
    for (o, s) in out.iter_mut().zip(spans) {
        *o = s as f64;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::value::{Output, Real, VecSink};
    use cagd::Limits;

    /// A small deterministic generator (SplitMix64) for the tests.
    struct Rng(u64);

    impl Rng {
        fn unit(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// Clamped knots of degree `p` for `n` points, interior knots repeated up to `p` times.
    fn knots(rng: &mut Rng, p: usize, n: usize) -> Vec<f64> {
        let mut interior = Vec::new();
        while interior.len() < n - p - 1 {
            let x = 0.05 + 0.9 * rng.unit();
            let m = (1 + (rng.unit() * p as f64) as usize).min(n - p - 1 - interior.len());
            interior.extend(std::iter::repeat_n(x, m));
        }
        interior.sort_by(f64::total_cmp);
        let mut k = vec![0.0; p + 1];
        k.extend(interior);
        k.extend(std::iter::repeat_n(1.0, p + 1));
        k
    }

    #[test]
    fn bezier_pieces_give_the_curve() {
        let mut rng = Rng(7);
        for case in 0..60 {
            let p = 1 + case % 5;
            let n = p + 1 + (rng.unit() * 7.0) as usize;
            let unit = case % 3 == 0;
            let h = DMatrix::from_fn(4, n, |r, _| match r {
                3 if unit => 1.0,
                3 => 0.3 + 2.7 * rng.unit(),
                _ => 2.0 * rng.unit() - 1.0,
            });
            let b = BSplineCurve::new(p, knots(&mut rng, p, n), h).unwrap();
            let curve = NurbsCurve::from_homogeneous(b).unwrap();
            let pieces = bezier_pieces(curve.homogeneous(), unit).unwrap().unwrap();
            let t = cagd::linspace(0.0, 1.0, 301);
            let (mut fast, mut slow) = (vec![0.0; 3 * t.len()], vec![0.0; 3 * t.len()]);
            eval_pieces(&pieces, &t, &mut fast).unwrap();
            curve.try_eval_many_into(&t, &mut slow).unwrap();
            let scale = slow.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for (a, b) in fast.iter().zip(&slow) {
                assert!(
                    (a - b).abs() <= 1e-13 * scale,
                    "case {case} (degree {p}): {a} vs {b}"
                );
            }
        }
    }

    #[test]
    fn unclamped_knots_have_no_pieces() {
        let h = DMatrix::from_element(4, 4, 1.0);
        let b = BSplineCurve::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], h).unwrap();
        assert!(bezier_pieces(&b, false).unwrap().is_none());
    }

    /// `nrbmak ([0 1 3 4; 0 2 -1 1; 0 1 2 0; 1 1 1 1], [0 0 0 0 1 1 1 1])` as Octave passes it.
    fn cubic<'a>(coefs: &'a [f64], knots: &'a [f64]) -> Value<'a> {
        Value::Struct {
            fields: vec![
                (
                    "form",
                    Value::Char {
                        dims: &[1, 7],
                        bytes: b"B-NURBS",
                    },
                ),
                (
                    "coefs",
                    Value::Real(Real {
                        dims: &[4, 4],
                        data: coefs,
                    }),
                ),
                (
                    "knots",
                    Value::Real(Real {
                        dims: &[1, 8],
                        data: knots,
                    }),
                ),
                (
                    "order",
                    Value::Real(Real {
                        dims: &[1, 1],
                        data: &[4.0],
                    }),
                ),
            ],
        }
    }

    #[test]
    fn nrbeval_layouts() {
        let coefs = [
            0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 1.0, 1.0, 3.0, -1.0, 2.0, 1.0, 4.0, 1.0, 0.0, 1.0,
        ];
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let t: Vec<f64> = cagd::linspace(0.0, 1.0, 600);
        let mut limits = Limits::default();
        let run = |dims: &[usize], nargout: usize, limits: &mut Limits| {
            let args = [cubic(&coefs, &knots), Value::Real(Real { dims, data: &t })];
            let mut out = VecSink::default();
            nrbeval(
                &crate::args::Call::new("cagd_nrbeval", &args, nargout, *limits),
                &mut out,
            )
            .unwrap();
            out
        };
        // A row: 3 × n; a column: [3, n, 1]; two outputs: homogeneous points and weights.
        let row = run(&[1, 600], 1, &mut limits);
        assert_eq!(row.get(0).dims(), &[3, 600]);
        let col = run(&[600, 1], 1, &mut limits);
        assert_eq!(col.get(0).dims(), &[3, 600, 1]);
        assert_eq!(row.get(0).data(), col.get(0).data());
        let two = run(&[1, 600], 2, &mut limits);
        assert!(
            matches!(two.get(1), Output::Real(d, w) if d == &[1, 600] && w.iter().all(|&x| (x - 1.0).abs() < 1e-15))
        );
        // The Bézier-piece path (600 sorted parameters) is the cubic b(t): check t = 1/2.
        let mid = &row.get(0).data()[3 * 299..3 * 300];
        let b = cagd::BezierCurve::new(DMatrix::from_column_slice(
            3,
            4,
            &[0.0, 0.0, 0.0, 1.0, 2.0, 1.0, 3.0, -1.0, 2.0, 4.0, 1.0, 0.0],
        ))
        .unwrap();
        let want = b.eval(t[299]);
        for c in 0..3 {
            assert!((mid[c] - want[c]).abs() < 1e-15);
        }
    }
}
