//! Tensor-product B-spline surfaces (the lecture notes "B-spline plocha", the CAD notes).

use crate::grid::PointGrid;
use nalgebra::{DMatrix, DVector};

use super::basis::{basis_cost, basis_values, extended_span, span_of};
use super::grid::{surface_grid_into, Net, SpanFinder};
use super::knots::{check_knots, KnotVector};
use crate::error::{check_finite, Error, Result};
use crate::param::Surface;
use crate::scalar::Scalar;

/// A tensor-product B-spline surface
/// `S(u, v) = Σ_i Σ_j P_{i,j} N_{i,p}(u) N_{j,q}(v)` over `[u_p, u_{nu}] × [v_q, v_{nv}]`.
///
/// **Layout:** one `nu × nv` matrix per coordinate, entry `(i, j)` belonging to `P_{i,j}`,
/// `i` along `u`, `j` along `v` (as [`BezierPatch`](crate::BezierPatch) and octave-nurbs
/// `coefs(k, i, j)`).
///
/// Evaluation sums along `v` first, then along `u`, each in `bspeval`'s order (as octave-nurbs
/// `nrbeval`). The uniform bicubic case on one span is the lecture notes' "Coons B-spline surface"
/// `vᵀ M_Sᵀ X_S M_S u` with `M_S = M_C` (the notes print the Bézier matrix for `M_S`; see
/// [`crate::conversion::bspline_matrix`]).
///
/// ```
/// use cagd::bspline::BSplineSurface;
/// use cagd::Surface;
/// use nalgebra::DMatrix;
/// // Bilinear: degree (1, 1), one span each way.
/// let z = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 1.0, 3.0]);
/// let s = BSplineSurface::new(1, 1, vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 0.0, 1.0, 1.0], vec![z])?;
/// assert_eq!(s.try_eval(0.5, 0.5)?[0], 1.25);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface<T: Scalar = f64> {
    degrees: (usize, usize),
    knots: (KnotVector<T>, KnotVector<T>),
    coords: Vec<DMatrix<T>>,
}

impl<T: Scalar> BSplineSurface<T> {
    /// The surface of degrees `(p, q)` with knots `knots_u` (`nu + p + 1`), `knots_v`
    /// (`nv + q + 1`) and control net `coords` (one `nu × nv` matrix per coordinate).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for no coordinates or matrices of different shapes;
    /// [`Error::NonFinite`]; and per direction the knot errors of
    /// [`BSplineCurve::new`](super::BSplineCurve::new).
    pub fn new(
        p: usize,
        q: usize,
        knots_u: Vec<T>,
        knots_v: Vec<T>,
        coords: Vec<DMatrix<T>>,
    ) -> Result<Self> {
        let what = "B-spline surface";
        let first = coords.first().ok_or_else(|| Error::ShapeMismatch {
            what,
            expected: "at least one coordinate matrix".into(),
            found: "none".into(),
        })?;
        let shape = first.shape();
        for (k, c) in coords.iter().enumerate() {
            if c.shape() != shape {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!(
                        "{}×{} in every coordinate (as coordinate 0)",
                        shape.0, shape.1
                    ),
                    found: format!("{}×{} in coordinate {k}", c.nrows(), c.ncols()),
                });
            }
            check_finite("B-spline surface control points", c.iter())?;
        }
        let ku = KnotVector::new(knots_u)?;
        let kv = KnotVector::new(knots_v)?;
        check_knots("B-spline surface, u direction", p, shape.0, &ku)?;
        check_knots("B-spline surface, v direction", q, shape.1, &kv)?;
        Ok(BSplineSurface {
            degrees: (p, q),
            knots: (ku, kv),
            coords,
        })
    }

    /// The surface with clamped uniform knots on `[0, 1]²` in both directions.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn clamped(p: usize, q: usize, coords: Vec<DMatrix<T>>) -> Result<Self> {
        let (nu, nv) = coords.first().map(|c| c.shape()).unwrap_or((0, 0));
        let ku = KnotVector::<T>::clamped_uniform(p, nu)?;
        let kv = KnotVector::<T>::clamped_uniform(q, nv)?;
        Self::new(p, q, ku.as_slice().to_vec(), kv.as_slice().to_vec(), coords)
    }

    /// The degrees `(p, q)`.
    pub fn degrees(&self) -> (usize, usize) {
        self.degrees
    }

    /// The knot vectors `(u, v)`.
    pub fn knots(&self) -> (&KnotVector<T>, &KnotVector<T>) {
        (&self.knots.0, &self.knots.1)
    }

    /// The control net, one `nu × nv` matrix per coordinate.
    pub fn coordinates(&self) -> &[DMatrix<T>] {
        &self.coords
    }

    /// The domain `([u_p, u_nu], [v_q, v_nv])`.
    pub fn domain(&self) -> ((T, T), (T, T)) {
        (
            self.knots.0.domain(self.degrees.0),
            self.knots.1.domain(self.degrees.1),
        )
    }

    /// The cost of one point `S(u, v)` at parameters of `u_bits` and `v_bits` bits: the two
    /// bases ([`basis_cost`](super::basis_cost)) and the `(p + 1)(q + 1)` products and sums
    /// of every coordinate, on numbers of both bases' sizes and the net's.
    ///
    /// ```
    /// use cagd::bspline::BSplineSurface;
    /// use cagd::cost::Cost;
    /// use nalgebra::DMatrix;
    /// let z = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 1.0, 3.0]);
    /// let s = BSplineSurface::clamped(1, 1, vec![z])?;
    /// // 4 + 4 for the bases, 2 · 2 · 2 · 1 for the sum.
    /// assert_eq!(s.point_cost(0, 0), Cost::new(16, 2));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn point_cost(&self, u_bits: u128, v_bits: u128) -> crate::cost::Cost {
        let (p, q) = self.degrees;
        let knot_bits = crate::cost::max_bits(self.knots.0.as_slice())
            .max(crate::cost::max_bits(self.knots.1.as_slice()));
        let net_bits = self
            .coords
            .iter()
            .map(|c| crate::cost::max_bits(c.iter()))
            .max()
            .unwrap_or(0);
        super::tensor_point_cost(
            &[(p, u_bits), (q, v_bits)],
            self.coords.len(),
            knot_bits,
            net_bits,
        )
    }

    /// The point `S(u, v)` for `(u, v)` in the domain: [`Surface::eval`]'s value, bit for bit.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for NaN or ±∞, [`Error::ParameterOutOfRange`] outside the domain,
    /// [`Error::TooLarge`] when one point's work exceeds the default limit,
    /// [`Error::Overflow`] for a point whose double overflows.
    pub fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let (p, q) = self.degrees;
        let (nu, nv) = self.coords[0].shape();
        let (ku, kv) = (self.knots.0.as_slice(), self.knots.1.as_slice());
        let su = span_of(p, nu, ku, &u)?;
        let sv = span_of(q, nv, kv, &v)?;
        self.check_point_work(u.bits(), v.bits())?;
        crate::checked::point(
            "B-spline surface point",
            self.coords.len(),
            self.eval_on_spans(su, sv, &u, &v),
        )
    }

    /// One point's work — the two bases and `(p+1)(q+1)` products per coordinate — against
    /// the default limit ([`crate::checked::point_work`]).
    fn check_point_work(&self, u_bits: u128, v_bits: u128) -> Result<()> {
        let (p, q) = self.degrees;
        let knot_bits = crate::cost::max_bits(
            self.knots
                .0
                .as_slice()
                .iter()
                .chain(self.knots.1.as_slice()),
        );
        let control_bits = crate::cost::max_bits(self.coords.iter().flat_map(|x| x.iter()));
        let products = 2 * (p as u128 + 1) * (q as u128 + 1) * self.coords.len() as u128;
        let cost = basis_cost(p, u_bits, knot_bits)
            .and(basis_cost(q, v_bits, knot_bits))
            .and(crate::cost::Cost::new(products, 0))
            .grown(control_bits);
        crate::checked::point_work::<T>("B-spline surface point", cost)
    }

    /// The point `S(u, v)` for any `(u, v)`: [`try_eval`](Self::try_eval)'s value in the
    /// domain; outside it the first or last polynomial piece in each direction continues; a
    /// NaN or infinite parameter gives a point of NaNs.
    pub fn eval(&self, u: T, v: T) -> DVector<T> {
        let (p, q) = self.degrees;
        let (nu, nv) = self.coords[0].shape();
        let (ku, kv) = (self.knots.0.as_slice(), self.knots.1.as_slice());
        match (extended_span(p, nu, ku, &u), extended_span(q, nv, kv, &v)) {
            (Some(su), Some(sv)) => self.eval_on_spans(su, sv, &u, &v),
            _ => nan_point(self.coords.len(), u, v),
        }
    }

    /// `Σ_a N_{su−p+a,p}(u) Σ_b N_{sv−q+b,q}(v) P_{su−p+a, sv−q+b}` on the given spans.
    fn eval_on_spans(&self, su: usize, sv: usize, u: &T, v: &T) -> DVector<T> {
        let (p, q) = self.degrees;
        let (ku, kv) = (self.knots.0.as_slice(), self.knots.1.as_slice());
        let bu = basis_values(p, ku, su, u);
        let bv = basis_values(q, kv, sv, v);
        DVector::from_fn(self.coords.len(), |k, _| {
            let c = &self.coords[k];
            bu.iter().enumerate().fold(T::zero(), |acc, (a, nu_a)| {
                let row = su - p + a;
                let along_v = bv.iter().enumerate().fold(T::zero(), |s, (b, nv_b)| {
                    s + nv_b.clone() * c[(row, sv - q + b)].clone()
                });
                acc + nu_a.clone() * along_v
            })
        })
    }

    /// The surface on the grid `us × vs` written into `out`, row by row:
    /// `out[(a·nv + b)·d + c]` is coordinate `c` of `S(us[a], vs[b])` (`(nu, nv, d)` row-major,
    /// the memory layout of [`Surface::eval_grid`]; see [`crate::grid`]). As
    /// [`eval`](Self::eval), outside the domain the end pieces continue; a NaN or infinite
    /// parameter is refused.
    ///
    /// The algorithm: the knot span and the `p + 1` (`q + 1`) non-zero basis values of every
    /// `u` (`v`) are computed once (`O(N·(p + q))` memory for an `N × N` grid, binary search
    /// for a span unless it is the previous one or the next). For each grid row `u_a` in span
    /// `s`, the net is contracted with the `u` basis,
    /// `c_j = Σ_{i=0}^{p} N_{s−p+i,p}(u_a) P_{s−p+i,j}` for `j = 0, …, nv − 1` (the control
    /// points of the B-spline curve `v ↦ S(u_a, v)`, `(p + 1)·nv·d` operations per row); then
    /// each point is `Σ_{l=0}^{q} N_{t−q+l,q}(v_b) c_{t−q+l}` (`t` the span of `v_b`):
    /// `(q + 1)·d` multiply-adds per point, `O(p + q)` per point instead of the `O(p·q)` of
    /// [`try_eval`](Self::try_eval). Nothing is allocated per point, and large grids are split
    /// by rows over all cores.
    ///
    /// Accuracy: the sums run along `u` first ([`try_eval`](Self::try_eval) runs along `v`
    /// first), with non-negative basis values, so the two agree to a few units of
    /// `(p + q) ε · max |P_{i,j}|` in `f64` and exactly for rationals.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · vs.len() · d`;
    /// [`Error::NonFinite`] for a NaN or infinite parameter; [`Error::TooLarge`] when one
    /// point's work exceeds the default limit; [`Error::Overflow`] for a point whose double
    /// overflows (the grid is written all the same).
    ///
    /// ```
    /// use cagd::bspline::BSplineSurface;
    /// use nalgebra::DMatrix;
    /// // z = u·v as a bilinear B-spline surface, evaluated on a 2 × 3 grid.
    /// let z = DMatrix::from_row_slice(2, 2, &[0.0, 0.0, 0.0, 1.0]);
    /// let k = vec![0.0, 0.0, 1.0, 1.0];
    /// let s = BSplineSurface::new(1, 1, k.clone(), k, vec![z])?;
    /// let mut out = [0.0; 6];
    /// s.eval_grid_into(&[0.5, 1.0], &[0.0, 0.5, 2.0], &mut out)?; // v = 2: z = uv continued
    /// assert_eq!(out, [0.0, 0.25, 1.0, 0.0, 0.5, 2.0]);
    /// assert!(s.eval_grid_into(&[0.5], &[0.5], &mut [0.0; 2]).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        let d = self.coords.len();
        let len = crate::grid::grid_len("B-spline surface grid", &[us.len(), vs.len(), d])?;
        crate::grid::check_len("B-spline surface grid buffer", len, out)?;
        check_finite("B-spline surface grid parameters", us.iter().chain(vs))?;
        self.check_point_work(crate::cost::max_bits(us), crate::cost::max_bits(vs))?;
        self.fill_grid(us, vs, out, false)
    }

    /// [`eval_grid_into`](Self::eval_grid_into) after the length check; with `project` the
    /// last coordinate is a weight and the points written are the others divided by it
    /// (`d − 1` numbers per point: the NURBS surface of this homogeneous one).
    pub(crate) fn fill_grid(&self, us: &[T], vs: &[T], out: &mut [T], project: bool) -> Result<()> {
        let (p, q) = self.degrees;
        let (nu, nv) = self.coords[0].shape();
        let dh = self.coords.len();
        let mut net = Vec::with_capacity(nu * nv * dh);
        for i in 0..nu {
            for j in 0..nv {
                net.extend(self.coords.iter().map(|x| x[(i, j)].clone()));
            }
        }
        let net = Net {
            u: SpanFinder::new(p, nu, self.knots.0.as_slice()),
            v: SpanFinder::new(q, nv, self.knots.1.as_slice()),
            net,
            dh,
            project,
        };
        surface_grid_into(&net, us, vs, out)
    }

    /// The grid `us × vs` as an array of shape `(us.len(), vs.len(), d)` by
    /// [`eval_grid_into`](Self::eval_grid_into)'s algorithm (see [`Surface::eval_grid`]).
    pub(crate) fn grid_array(&self, us: &[T], vs: &[T], d: usize, project: bool) -> PointGrid<T> {
        let mut grid = PointGrid::from_elem((us.len(), vs.len(), d), T::zero());
        let out = grid.as_mut_slice();
        // The infallible `Surface::eval_grid`: non-finite points, if any, stay in place.
        let _ = self.fill_grid(us, vs, out, project);
        grid
    }
}

/// The point of an evaluation at a NaN or infinite parameter: NaNs (`u − u` if `u` is not
/// finite, else `v − v`), as the grid evaluation writes it.
pub(crate) fn nan_point<T: Scalar>(dim: usize, u: T, v: T) -> DVector<T> {
    let bad = if u.is_finite_value() { v } else { u };
    DVector::from_element(dim, bad.clone() - bad)
}

impl<T: Scalar> Surface<T> for BSplineSurface<T> {
    fn dim(&self) -> usize {
        self.coords.len()
    }

    fn domain(&self) -> ((T, T), (T, T)) {
        BSplineSurface::domain(self)
    }

    /// [`BSplineSurface::eval`]: the end pieces continue outside the domain.
    fn eval(&self, u: T, v: T) -> DVector<T> {
        BSplineSurface::eval(self, u, v)
    }

    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        BSplineSurface::try_eval(self, u, v)
    }

    /// The grid by [`BSplineSurface::eval_grid_into`]'s algorithm (`O(p + q)` per point).
    fn eval_grid(&self, us: &[T], vs: &[T]) -> PointGrid<T> {
        self.grid_array(us, vs, self.coords.len(), false)
    }

    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        BSplineSurface::eval_grid_into(self, us, vs, out)
    }
}
