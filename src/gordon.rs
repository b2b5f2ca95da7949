//! Gordon surfaces: interpolation of a network of curves (thesis §4.5, Izrek 4.4, appendix D).
//!
//! A network consists of `m+1` curves `g(u_i, v)` (functions of `v`, one per node `u_i`) and
//! `n+1` curves `g(u, v_j)` (functions of `u`, one per node `v_j`), all over `[0, 1]`, meeting
//! at the `(m+1)(n+1)` points `g(u_i, v_j)`. A network curve on another domain `[a, b]` is
//! reparametrised affinely onto `[0, 1]`, `s ↦ c(a + (b − a)s)`, and the nodes are parameters
//! of `[0, 1]` (a B-spline `g(u, v_j)` on `[0, 4]` with a node `u_i = 1/2` is met at its
//! parameter 2); a curve whose domain is not a finite interval is refused with
//! [`Error::UnusableDomain`] (see [`crate::param`]). The Gordon surface
//!
//! ```text
//! g = g1 + g2 − g12,
//!   g1(u,v)  = Σ_i g(u_i, v) L_i(u)                  (4.9)
//!   g2(u,v)  = Σ_j g(u, v_j) L_j(v)                  (4.10)
//!   g12(u,v) = Σ_i Σ_j g(u_i, v_j) L_i(u) L_j(v)     (4.11)
//! ```
//!
//! interpolates every curve of the network (Izrek 4.4), `L_i`, `L_j` being the Lagrange bases
//! of the nodes `u_0 < … < u_m` and `v_0 < … < v_n` — two separate node vectors, `m ≠ n`
//! allowed. (The thesis code, `krpaGordon`, uses one node vector and one count for both
//! directions; the Coons patch is the case `m = n = 1` with nodes `{0, 1}`.)
//!
//! **Reading appendix D's data.** The thesis lists `c0, c1, c2` as functions of `u`
//! (`c_j = [u; v_j; v_j + u − u²]`, with `y = v_j = 0, 0.5, 1`), so they are the curves
//! `g(u, v_j)`; and `d0, d1, d2` as functions of `v` (`d_i = [u_i; v; …]`, `x = u_i`), the
//! curves `g(u_i, v)`. The intersection points are printed as `g_ab` with the *first* index on
//! the `c` curves: `g01 = [0.5 0 0.25] = c0(0.5) = d1(0) = g(u_1, v_0)`, i.e. `g_ab = g(u_b, v_a)`.
//! Accordingly the matrix `g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22]` holds `g(u_i, v_j)`
//! in row `i`, column block `j`, which is how `krpaGordon` uses it
//! (`g_uv(l, 3s−2:3s)` with `L_l(u) L_s(v)`). The network is compatible: every `c_j(u_i)`
//! equals `d_i(v_j)`.
//!
//! **The thesis code** (`krpaGordon`, `Lagrange`) does not run as printed; the fixed Octave
//! reference (`octave_ref/fixed/krpaGordon.m`) lists each fix: `Lagrange` starts its product at
//! zero (so every blending function is 0); `krpaGordon` takes the curve counts from the number
//! of sample columns (`size(g_u)(2)` = 3N), weights `g_u(:, l)` — sample `l` of the first
//! sampled curve, not the curve `c_l` at the current parameter — by `L_l(v)`, adds the row
//! `g_uv(l, 3s−2:3s)` to the columns `g1`, `g2` (which Octave broadcasts to a 3 × 3 matrix),
//! and uses one node vector and one count for both directions. This type evaluates the same
//! formula as the fixed reference; on the thesis data it agrees with it to a few ULPs.

use nalgebra::{DMatrix, DVector};

use crate::bernstein::elevate;
use crate::bezier::{BezierCurve, BezierPatch};
use crate::coons::Tolerance;
use crate::cost::{blended, polynomial_bits, Cost};
use crate::error::{Error, Result};
use crate::lagrange::{bernstein_coefficients, check_nodes, Lagrange, LebesgueEstimate};
use crate::param::{usable_domain, Curve, OnUnitInterval, Surface};
use crate::scalar::Scalar;

/// A Gordon surface (Izrek 4.4) over a compatible curve network.
///
/// ```
/// use cagd::gordon::GordonSurface;
/// use cagd::{FnCurve, Surface};
/// use nalgebra::{dvector, DVector};
/// type F = fn(f64) -> DVector<f64>;
/// // Appendix D: d_i = g(u_i, v), c_j = g(u, v_j), nodes [0 0.5 1] in both directions.
/// let d: [F; 3] = [|v| dvector![0.0, v, v], |v| dvector![0.5, v, 0.25 + v], |v| dvector![1.0, v, v]];
/// let c: [F; 3] = [
///     |u| dvector![u, 0.0, u - u * u],
///     |u| dvector![u, 0.5, 0.5 + u - u * u],
///     |u| dvector![u, 1.0, 1.0 + u - u * u],
/// ];
/// let nodes = vec![0.0, 0.5, 1.0];
/// let g = GordonSurface::new(
///     nodes.clone(), nodes,
///     Vec::from(d.map(|f| FnCurve::new(3, f))),
///     Vec::from(c.map(|f| FnCurve::new(3, f))),
/// ).unwrap();
/// // The network is the surface (u, v, v + u − u²), which Gordon reproduces.
/// let p = g.eval(0.25, 0.75);
/// assert!((p - dvector![0.25, 0.75, 0.75 + 0.25 - 0.0625]).amax() < 1e-15);
/// ```
#[derive(Debug, Clone)]
pub struct GordonSurface<C, T: Scalar = f64> {
    u_basis: Lagrange<T>,
    v_basis: Lagrange<T>,
    curves_at_u: Vec<C>,
    curves_at_v: Vec<C>,
    /// The domains of `curves_at_u`, each a finite interval `a < b`.
    domains_at_u: Vec<(T, T)>,
    /// The domains of `curves_at_v`.
    domains_at_v: Vec<(T, T)>,
    /// `points[i][j] = g(u_i, v_j)`.
    points: Vec<Vec<DVector<T>>>,
    tolerance: Tolerance,
}

/// A point of a Gordon surface with its three parts: `g = g1 + g2 − g12`.
#[derive(Debug, Clone, PartialEq)]
pub struct GordonPoint<T: Scalar = f64> {
    /// `g(u, v)`.
    pub g: DVector<T>,
    /// `g1 = Σ_i g(u_i, v) L_i(u)` (4.9).
    pub g1: DVector<T>,
    /// `g2 = Σ_j g(u, v_j) L_j(v)` (4.10).
    pub g2: DVector<T>,
    /// `g12 = Σ_i Σ_j g(u_i, v_j) L_i(u) L_j(v)` (4.11).
    pub g12: DVector<T>,
}

/// The conditioning of a Gordon surface's blending: the Lebesgue constants of its two node
/// vectors on `[0, 1]`. A perturbation `ε` of the network moves `g1`, `g2`, `g12` by at most
/// `Λ_u ε`, `Λ_v ε`, `Λ_u Λ_v ε`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditioning {
    /// For the nodes `u_i`.
    pub u: LebesgueEstimate,
    /// For the nodes `v_j`.
    pub v: LebesgueEstimate,
}

impl Conditioning {
    /// The bound `Λ_u + Λ_v + Λ_u Λ_v` on the amplification of network errors.
    pub fn amplification(&self) -> f64 {
        self.u.value + self.v.value + self.u.value * self.v.value
    }
}

impl<T: Scalar, C: Curve<T>> GordonSurface<C, T> {
    /// The Gordon surface of the curves `curves_at_u[i] = g(u_i, ·)` (functions of `v`) and
    /// `curves_at_v[j] = g(·, v_j)` (functions of `u`) at the nodes `u_nodes`, `v_nodes`, with
    /// the network checked at the default tolerance (relative `1e-10`, see [`Tolerance`]).
    /// The crossing points `g(u_i, v_j)` are taken from `curves_at_u`.
    ///
    /// # Errors
    /// - [`Error::TooFewCurves`]: fewer than 2 curves in a direction;
    /// - [`Error::ShapeMismatch`]: node and curve counts differ, or curves of different
    ///   dimensions;
    /// - [`Error::UnusableDomain`]: a curve whose domain is not a finite interval `a < b`;
    /// - [`Error::DuplicateNodes`], [`Error::UnsortedNodes`], [`Error::NonFinite`]: bad nodes;
    /// - [`Error::NetworkMismatch`]: `g(u_i, ·)` at `v_j` is not `g(·, v_j)` at `u_i`, naming
    ///   the worst pair, its gap and the tolerance.
    pub fn new(
        u_nodes: Vec<T>,
        v_nodes: Vec<T>,
        curves_at_u: Vec<C>,
        curves_at_v: Vec<C>,
    ) -> Result<Self> {
        Self::with_tolerance(
            u_nodes,
            v_nodes,
            curves_at_u,
            curves_at_v,
            Tolerance::default(),
        )
    }

    /// [`GordonSurface::new`] with a chosen network tolerance.
    ///
    /// # Errors
    /// As [`GordonSurface::new`].
    pub fn with_tolerance(
        u_nodes: Vec<T>,
        v_nodes: Vec<T>,
        curves_at_u: Vec<C>,
        curves_at_v: Vec<C>,
        tolerance: Tolerance,
    ) -> Result<Self> {
        let (bases, domains) =
            Self::check(&u_nodes, &v_nodes, &curves_at_u, &curves_at_v, &tolerance)?;
        let points: Vec<Vec<DVector<T>>> = unit_views(&curves_at_u, &domains.0)
            .iter()
            .map(|c| v_nodes.iter().map(|v| c.eval(v.clone())).collect())
            .collect();
        Self::finish(
            bases,
            (curves_at_u, curves_at_v),
            domains,
            points,
            tolerance,
        )
    }

    /// The Gordon surface with the crossing points given, `points[i][j] = g(u_i, v_j)` (the
    /// thesis's `g_uv`); each is checked against both curves through it.
    ///
    /// # Errors
    /// As [`GordonSurface::new`]; a wrong number or dimension of points is an
    /// [`Error::ShapeMismatch`].
    pub fn with_points(
        u_nodes: Vec<T>,
        v_nodes: Vec<T>,
        curves_at_u: Vec<C>,
        curves_at_v: Vec<C>,
        points: Vec<Vec<DVector<T>>>,
        tolerance: Tolerance,
    ) -> Result<Self> {
        let (bases, domains) =
            Self::check(&u_nodes, &v_nodes, &curves_at_u, &curves_at_v, &tolerance)?;
        let dim = curves_at_u[0].dim();
        let shape_ok = points.len() == u_nodes.len()
            && points
                .iter()
                .all(|row| row.len() == v_nodes.len() && row.iter().all(|p| p.len() == dim));
        if !shape_ok {
            return Err(Error::ShapeMismatch {
                what: "Gordon crossing points g(u_i, v_j)",
                expected: format!(
                    "{} × {} points of dimension {dim}",
                    u_nodes.len(),
                    v_nodes.len()
                ),
                found: format!(
                    "{} rows of lengths {:?}",
                    points.len(),
                    points.iter().map(Vec::len).collect::<Vec<_>>()
                ),
            });
        }
        for row in &points {
            for p in row {
                crate::error::check_finite("Gordon crossing points g(u_i, v_j)", p.iter())?;
            }
        }
        let mut worst: Option<(usize, usize, T, T)> = None;
        let mut count = 0;
        let (at_u, at_v) = (
            unit_views(&curves_at_u, &domains.0),
            unit_views(&curves_at_v, &domains.1),
        );
        for (i, u) in u_nodes.iter().enumerate() {
            for (j, v) in v_nodes.iter().enumerate() {
                for q in [at_u[i].eval(v.clone()), at_v[j].eval(u.clone())] {
                    let (gap, allowed) = tolerance.gap(&points[i][j], &q);
                    record(&mut worst, &mut count, i, j, gap, allowed);
                }
            }
        }
        if let Some(e) = mismatch(worst, count, &u_nodes, &v_nodes, tolerance) {
            return Err(e);
        }
        Self::finish(
            bases,
            (curves_at_u, curves_at_v),
            domains,
            points,
            tolerance,
        )
    }

    /// Checks the network: curve and node counts, nodes, tolerance, dimensions, domains
    /// (reparametrisable onto `[0, 1]`) and the crossings; gives the Lagrange bases and the
    /// curves' domains.
    #[allow(clippy::type_complexity)]
    fn check(
        u_nodes: &[T],
        v_nodes: &[T],
        curves_at_u: &[C],
        curves_at_v: &[C],
        tolerance: &Tolerance,
    ) -> Result<((Lagrange<T>, Lagrange<T>), (Vec<(T, T)>, Vec<(T, T)>))> {
        for (what, curves) in [
            ("Gordon curves g(u_i, v)", curves_at_u),
            ("Gordon curves g(u, v_j)", curves_at_v),
        ] {
            if curves.len() < 2 {
                return Err(Error::TooFewCurves {
                    what,
                    min: 2,
                    found: curves.len(),
                });
            }
        }
        for (what, nodes, curves) in [
            ("Gordon nodes u_i", u_nodes, curves_at_u.len()),
            ("Gordon nodes v_j", v_nodes, curves_at_v.len()),
        ] {
            if nodes.len() != curves {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!("{curves} nodes (one per curve)"),
                    found: format!("{} nodes", nodes.len()),
                });
            }
            check_nodes(what, nodes, 2)?;
        }
        crate::error::check_tolerance(tolerance)?;
        let dim = curves_at_u[0].dim();
        for c in curves_at_u.iter().chain(curves_at_v.iter()) {
            if c.dim() != dim {
                return Err(Error::ShapeMismatch {
                    what: "Gordon network curves",
                    expected: format!("curves of one dimension ({dim})"),
                    found: format!("a curve of dimension {}", c.dim()),
                });
            }
        }
        let domains_at_u = curves_at_u
            .iter()
            .map(|c| usable_domain("Gordon curve g(u_i, v)", c))
            .collect::<Result<Vec<_>>>()?;
        let domains_at_v = curves_at_v
            .iter()
            .map(|c| usable_domain("Gordon curve g(u, v_j)", c))
            .collect::<Result<Vec<_>>>()?;
        let (at_u, at_v) = (
            unit_views(curves_at_u, &domains_at_u),
            unit_views(curves_at_v, &domains_at_v),
        );
        // The bases first (their weights are refused at once for nodes no double can hold,
        // 1001 equally spaced ones), and the k_u · k_v crossings counted before they are
        // evaluated: the work grows with the product of the two families.
        let bases = (
            Lagrange::new(u_nodes.to_vec())?,
            Lagrange::new(v_nodes.to_vec())?,
        );
        let crossings = (u_nodes.len() as u128).saturating_mul(v_nodes.len() as u128);
        crate::checked::point_work::<T>(
            "Gordon network crossings",
            crate::cost::Cost::new(crossings.saturating_mul(2 * (dim as u128 + 1)), 0),
        )?;
        // Compatibility: g(u_i, ·)(v_j) against g(·, v_j)(u_i), each curve as it is (a point
        // of another dimension is named as such).
        let mut worst: Option<(usize, usize, T, T)> = None;
        let mut count = 0;
        for (i, u) in u_nodes.iter().enumerate() {
            for (j, v) in v_nodes.iter().enumerate() {
                let p = at_u[i].curve().eval(at_u[i].parameter(v.clone()));
                let q = at_v[j].curve().eval(at_v[j].parameter(u.clone()));
                if p.len() != dim || q.len() != dim {
                    return Err(Error::ShapeMismatch {
                        what: "Gordon network curves",
                        expected: format!("points of dimension {dim}"),
                        found: format!("points of dimension {} and {}", p.len(), q.len()),
                    });
                }
                crate::error::check_finite("Gordon network crossing", p.iter().chain(q.iter()))?;
                let (gap, allowed) = tolerance.gap(&p, &q);
                record(&mut worst, &mut count, i, j, gap, allowed);
            }
        }
        if let Some(e) = mismatch(worst, count, u_nodes, v_nodes, *tolerance) {
            return Err(e);
        }
        Ok((bases, (domains_at_u, domains_at_v)))
    }

    #[allow(clippy::type_complexity)]
    fn finish(
        (u_basis, v_basis): (Lagrange<T>, Lagrange<T>),
        (curves_at_u, curves_at_v): (Vec<C>, Vec<C>),
        (domains_at_u, domains_at_v): (Vec<(T, T)>, Vec<(T, T)>),
        points: Vec<Vec<DVector<T>>>,
        tolerance: Tolerance,
    ) -> Result<Self> {
        Ok(GordonSurface {
            u_basis,
            v_basis,
            curves_at_u,
            curves_at_v,
            domains_at_u,
            domains_at_v,
            points,
            tolerance,
        })
    }

    /// The curves `g(u_i, ·)` and `g(·, v_j)` as the surface uses them: reparametrised onto
    /// `[0, 1]` (unchanged for curves on `[0, 1]`).
    #[allow(clippy::type_complexity)]
    pub fn unit_curves(&self) -> (Vec<OnUnitInterval<&C, T>>, Vec<OnUnitInterval<&C, T>>) {
        (
            unit_views(&self.curves_at_u, &self.domains_at_u),
            unit_views(&self.curves_at_v, &self.domains_at_v),
        )
    }

    /// The surface on the grid `us × vs` written into `out`, row by row:
    /// `out[(a·nv + b)·d + c]` is coordinate `c` of `g(us[a], vs[b])` (`(nu, nv, d)`
    /// row-major, see [`crate::grid`]).
    ///
    /// Precomputed once per grid line: the Lagrange basis rows `L_i(us[a])`, `L_j(vs[b])`
    /// ([`Lagrange::basis_into`]), the samples `g(u_i, vs[b])` and `g(us[a], v_j)` of every
    /// network curve ([`Curve::eval_many_into`]: for Bézier curves the basis-row path). The
    /// formula is regrouped per row `u = us[a]`:
    ///
    /// ```text
    /// g(u, v) = Σ_j L_j(v) r_j(u) + Σ_i L_i(u) g(u_i, v),   r_j(u) = g(u, v_j) − Σ_i L_i(u) g(u_i, v_j),
    /// ```
    ///
    /// (the same polynomial as `g1 + g2 − g12`), so a point costs `(m + n + 2)·d`
    /// multiply-adds and no allocation; memory is `O(N·(m + n)·d)`, and large grids are split by
    /// rows over all cores. The `f64` values agree with [`Surface::eval`] up to rounding (a few
    /// ULPs of the network's magnitude times the Lebesgue constants) and exactly for
    /// rationals.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · vs.len() · d` (or if a curve
    /// returns points of another dimension).
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use cagd::gordon::GordonSurface;
    /// use cagd::Surface;
    /// // The bilinear surface (u, v, uv) from two lines in each direction.
    /// let line = |p: [f64; 3], q: [f64; 3]| BezierCurve::from_points(&[p, q]).unwrap();
    /// let at_u = vec![line([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), line([1.0, 0.0, 0.0], [1.0, 1.0, 1.0])];
    /// let at_v = vec![line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), line([0.0, 1.0, 0.0], [1.0, 1.0, 1.0])];
    /// let g = GordonSurface::new(vec![0.0, 1.0], vec![0.0, 1.0], at_u, at_v)?;
    /// let mut out = vec![0.0; 3];
    /// g.eval_grid_into(&[0.5], &[0.25], &mut out)?;
    /// assert_eq!(out, [0.5, 0.25, 0.125]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("Gordon surface grid", &[us.len(), vs.len(), d])?;
        crate::grid::check_len("Gordon surface grid buffer", len, out)?;
        crate::error::check_finite("Gordon surface grid parameters", us.iter().chain(vs))?;
        if len == 0 {
            return Ok(());
        }
        let (mu, mv) = (self.curves_at_u.len(), self.curves_at_v.len());
        let lu = crate::grid::rows_of(us, mu, |u, row| self.u_basis.fill_basis(u, row));
        let lv = crate::grid::rows_of(vs, mv, |v, row| self.v_basis.fill_basis(v, row));
        // at_u = one grid row per curve: g(u_i, vs[b]) at at_u[(i·nv + b)·d ..].
        let row_len = vs.len() * d;
        let (curves_u, curves_v) = self.unit_curves();
        let mut at_u = vec![T::zero(); mu * row_len];
        for (curve, samples) in curves_u.iter().zip(at_u.chunks_exact_mut(row_len)) {
            curve.eval_many_into(vs, samples)?;
        }
        // at_v[a] = [g(us[a], v_0), …, g(us[a], v_n)]: (n+1)·d values per row a.
        let mut at_v = samples_by_point(&curves_v, us, d)?;
        // Turn at_v[a] into r[a]: subtract Σ_i L_i(us[a]) g(u_i, v_j).
        for (a, ra) in at_v.chunks_exact_mut(mv * d).enumerate() {
            let la = &lu[a * mu..(a + 1) * mu];
            for (j, rj) in ra.chunks_exact_mut(d).enumerate() {
                for (k, x) in rj.iter_mut().enumerate() {
                    let crossing = la
                        .iter()
                        .zip(&self.points)
                        .fold(T::zero(), |acc, (l, row)| {
                            acc + l.clone() * row[j][k].clone()
                        });
                    *x = x.clone() - crossing;
                }
            }
        }
        let r = at_v;
        let work = out.len().saturating_mul(mu + mv);
        crate::grid::for_each_row(
            "Gordon surface grid",
            out,
            vs.len() * d,
            work,
            || (),
            |_, a, row| {
                let la = &lu[a * mu..(a + 1) * mu];
                let ra = &r[a * mv * d..(a + 1) * mv * d];
                crate::grid::blend_row(&lv, mv, ra, la, &at_u, row);
            },
        )
    }

    /// `g(u, v)` with its parts `g1`, `g2`, `g12`.
    pub fn eval_parts(&self, u: T, v: T) -> GordonPoint<T> {
        let lu = self.u_basis.basis(&u);
        let lv = self.v_basis.basis(&v);
        let unit = |(c, d): (&C, &(T, T)), t: &T| {
            OnUnitInterval::from_checked(c, d.clone()).eval(t.clone())
        };
        let at_u: Vec<_> = (self.curves_at_u.iter().zip(&self.domains_at_u))
            .map(|cd| unit(cd, &v))
            .collect();
        let at_v: Vec<_> = (self.curves_at_v.iter().zip(&self.domains_at_v))
            .map(|cd| unit(cd, &u))
            .collect();
        self.combine(&lu, &lv, &at_u, &at_v)
    }

    /// Combines the curve values `at_u[i] = g(u_i, v)`, `at_v[j] = g(u, v_j)` with the basis
    /// values `lu`, `lv`.
    fn combine(
        &self,
        lu: &[T],
        lv: &[T],
        at_u: &[DVector<T>],
        at_v: &[DVector<T>],
    ) -> GordonPoint<T> {
        let dim = self.dim();
        let mut out = GordonPoint {
            g: DVector::from_element(dim, T::zero()),
            g1: DVector::from_element(dim, T::zero()),
            g2: DVector::from_element(dim, T::zero()),
            g12: DVector::from_element(dim, T::zero()),
        };
        if crate::grid::exact::is_rational::<T>() {
            // Exact: the same values from dot products over a common denominator,
            // g12 = Σ_i L_i(u) Σ_j L_j(v) g(u_i, v_j); a fraction of the gcds.
            for k in 0..dim {
                let dot = |w: &[T], x: Vec<&T>| {
                    crate::grid::exact::dot(w.iter().zip(x)).unwrap_or_else(T::zero)
                };
                let g1 = dot(lu, at_u.iter().map(|p| &p[k]).collect());
                let g2 = dot(lv, at_v.iter().map(|p| &p[k]).collect());
                let rows: Vec<T> = self
                    .points
                    .iter()
                    .map(|row| dot(lv, row.iter().map(|p| &p[k]).collect()))
                    .collect();
                let g12 = dot(lu, rows.iter().collect());
                out.g[k] = g1.clone() + g2.clone() - g12.clone();
                out.g1[k] = g1;
                out.g2[k] = g2;
                out.g12[k] = g12;
            }
            return out;
        }
        for k in 0..dim {
            let mut g1 = T::zero();
            for (l, p) in lu.iter().zip(at_u) {
                g1 = g1 + p[k].clone() * l.clone();
            }
            let mut g2 = T::zero();
            for (l, p) in lv.iter().zip(at_v) {
                g2 = g2 + p[k].clone() * l.clone();
            }
            let mut g12 = T::zero();
            for (li, row) in lu.iter().zip(&self.points) {
                for (lj, p) in lv.iter().zip(row) {
                    g12 = g12 + p[k].clone() * li.clone() * lj.clone();
                }
            }
            out.g[k] = g1.clone() + g2.clone() - g12.clone();
            out.g1[k] = g1;
            out.g2[k] = g2;
            out.g12[k] = g12;
        }
        out
    }
}

impl<T: Scalar, C> GordonSurface<C, T> {
    /// The nodes `u_0 < … < u_m`.
    pub fn u_nodes(&self) -> &[T] {
        self.u_basis.nodes()
    }

    /// The nodes `v_0 < … < v_n`.
    pub fn v_nodes(&self) -> &[T] {
        self.v_basis.nodes()
    }

    /// The curves `g(u_i, v)`, functions of `v`.
    pub fn curves_at_u(&self) -> &[C] {
        &self.curves_at_u
    }

    /// The curves `g(u, v_j)`, functions of `u`.
    pub fn curves_at_v(&self) -> &[C] {
        &self.curves_at_v
    }

    /// The crossing points, `points()[i][j] = g(u_i, v_j)`.
    pub fn points(&self) -> &[Vec<DVector<T>>] {
        &self.points
    }

    /// The tolerance the network was checked against.
    pub fn tolerance(&self) -> Tolerance {
        self.tolerance
    }

    /// The Lagrange bases in `u` and `v`.
    pub fn bases(&self) -> (&Lagrange<T>, &Lagrange<T>) {
        (&self.u_basis, &self.v_basis)
    }

    /// The Lebesgue constants of the two node vectors on `[0, 1]`, estimated on a grid of
    /// `max(2001, 200·(nodes+1))` points.
    ///
    /// ```
    /// # use cagd::gordon::GordonSurface;
    /// # use cagd::{FnCurve, Surface};
    /// # use nalgebra::{dvector, DVector};
    /// # type F = fn(f64) -> DVector<f64>;
    /// # let d: [F; 3] = [|v| dvector![0.0, v, v], |v| dvector![0.5, v, 0.25 + v], |v| dvector![1.0, v, v]];
    /// # let c: [F; 3] = [|u| dvector![u, 0.0, u - u * u], |u| dvector![u, 0.5, 0.5 + u - u * u], |u| dvector![u, 1.0, 1.0 + u - u * u]];
    /// # let nodes = vec![0.0, 0.5, 1.0];
    /// # let g = GordonSurface::new(nodes.clone(), nodes, Vec::from(d.map(|f| FnCurve::new(3, f))), Vec::from(c.map(|f| FnCurve::new(3, f)))).unwrap();
    /// // Nodes [0, 0.5, 1]: Λ = 1.25, at t = 1/4 and 3/4 (the grid contains both).
    /// let k = g.conditioning();
    /// assert!((k.u.value - 1.25).abs() < 1e-12 && (k.v.value - 1.25).abs() < 1e-12);
    /// ```
    pub fn conditioning(&self) -> Conditioning {
        let samples = |b: &Lagrange<T>| (200 * (b.nodes().len() + 1)).max(2001);
        Conditioning {
            u: self
                .u_basis
                .lebesgue_estimate(0.0, 1.0, samples(&self.u_basis)),
            v: self
                .v_basis
                .lebesgue_estimate(0.0, 1.0, samples(&self.v_basis)),
        }
    }
}

/// Keeps the worst gap over the tolerance and counts such gaps.
fn record<T: Scalar>(
    worst: &mut Option<(usize, usize, T, T)>,
    count: &mut usize,
    i: usize,
    j: usize,
    gap: T,
    allowed: T,
) {
    if gap > allowed {
        *count += 1;
        let worse = match worst {
            None => true,
            Some((_, _, g, _)) => gap > *g,
        };
        if worse {
            *worst = Some((i, j, gap, allowed));
        }
    }
}

fn mismatch<T: Scalar>(
    worst: Option<(usize, usize, T, T)>,
    count: usize,
    u_nodes: &[T],
    v_nodes: &[T],
    tolerance: Tolerance,
) -> Option<Error> {
    worst.map(|(i, j, gap, allowed)| Error::NetworkMismatch {
        u_curve: i,
        v_curve: j,
        u: u_nodes[i].to_f64(),
        v: v_nodes[j].to_f64(),
        gap: gap.to_f64(),
        allowed: allowed.to_f64(),
        tolerance,
        count,
    })
}

/// The curves on their checked domains, reparametrised onto `[0, 1]`.
fn unit_views<'a, T: Scalar, C>(
    curves: &'a [C],
    domains: &[(T, T)],
) -> Vec<OnUnitInterval<&'a C, T>> {
    curves
        .iter()
        .zip(domains)
        .map(|(c, d)| OnUnitInterval::from_checked(c, d.clone()))
        .collect()
}

/// The samples of every curve at every parameter, grouped by parameter:
/// `out[(p·curves.len() + c)·d + k]` is coordinate `k` of `curves[c](ts[p])`.
fn samples_by_point<T: Scalar, C: Curve<T>>(curves: &[C], ts: &[T], d: usize) -> Result<Vec<T>> {
    let count = curves.len();
    let mut out = vec![T::zero(); ts.len() * count * d];
    let mut samples = vec![T::zero(); ts.len() * d];
    for (c, curve) in curves.iter().enumerate() {
        curve.eval_many_into(ts, &mut samples)?;
        for (x, dst) in samples.chunks_exact(d).zip(out.chunks_exact_mut(count * d)) {
            dst[c * d..(c + 1) * d].clone_from_slice(x);
        }
    }
    Ok(out)
}

impl<T: Scalar, C: Curve<T>> Surface<T> for GordonSurface<C, T> {
    fn dim(&self) -> usize {
        self.points[0][0].len()
    }

    /// `[0, 1]²` (the network curves reparametrised onto `[0, 1]`).
    fn domain(&self) -> ((T, T), (T, T)) {
        ((T::zero(), T::one()), (T::zero(), T::one()))
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        self.eval_parts(u, v).g
    }

    /// [`eval`](Surface::eval) on `[0, 1]²`, every network curve through its own `try_eval`
    /// (its work bounded, its point checked: a curve returning a point of another dimension
    /// is an [`Error::ShapeMismatch`]), the point checked for overflow.
    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let unit = (T::zero(), T::one());
        crate::param::check_parameter("Gordon surface parameter u", &u, &unit)?;
        crate::param::check_parameter("Gordon surface parameter v", &v, &unit)?;
        let values = |curves: &[C], domains: &[(T, T)], t: &T, what| -> Result<Vec<DVector<T>>> {
            curves
                .iter()
                .zip(domains)
                .map(|(c, d)| {
                    OnUnitInterval::from_checked(c, d.clone())
                        .try_eval(t.clone())
                        .and_then(|p| crate::checked::point(what, self.dim(), p))
                        .map_err(|e| crate::checked::named(what, e))
                })
                .collect()
        };
        let at_u = values(
            &self.curves_at_u,
            &self.domains_at_u,
            &v,
            "Gordon curve g(u_i, v)",
        )?;
        let at_v = values(
            &self.curves_at_v,
            &self.domains_at_v,
            &u,
            "Gordon curve g(u, v_j)",
        )?;
        let (lu, lv) = (self.u_basis.basis(&u), self.v_basis.basis(&v));
        let g = self.combine(&lu, &lv, &at_u, &at_v).g;
        crate::checked::point("Gordon surface point", self.dim(), g)
    }

    /// The surface on the grid `us × vs`, shape `(us.len(), vs.len(), d)` (the layout of
    /// `P = tenzor(R)` in `krpaGordon`); each network curve and each Lagrange basis is evaluated
    /// once per grid line.
    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        GordonSurface::eval_grid_into(self, us, vs, out)
    }

    fn eval_grid(&self, us: &[T], vs: &[T]) -> crate::grid::PointGrid<T> {
        let lu: Vec<_> = us.iter().map(|u| self.u_basis.basis(u)).collect();
        let lv: Vec<_> = vs.iter().map(|v| self.v_basis.basis(v)).collect();
        // at_u[j][i] = g(u_i, vs[j]); at_v[i][j] = g(us[i], v_j).
        let (curves_u, curves_v) = self.unit_curves();
        let at_u: Vec<Vec<_>> = vs
            .iter()
            .map(|v| curves_u.iter().map(|c| c.eval(v.clone())).collect())
            .collect();
        let at_v: Vec<Vec<_>> = us
            .iter()
            .map(|u| curves_v.iter().map(|c| c.eval(u.clone())).collect())
            .collect();
        let dim = self.dim();
        let mut grid = crate::grid::PointGrid::from_elem((us.len(), vs.len(), dim), T::zero());
        for i in 0..us.len() {
            for j in 0..vs.len() {
                let p = self.combine(&lu[i], &lv[j], &at_u[j], &at_v[i]);
                for k in 0..dim {
                    grid[[i, j, k]] = p.g[k].clone();
                }
            }
        }
        grid
    }
}

// ------------------------------------------------------------------------------------------
// Gordon surfaces of Bézier networks as one Bézier patch

/// The control points of a Bézier curve elevated to degree `to`, as one vector of
/// coefficients per coordinate. They are those of the curve reparametrised onto `[0, 1]`
/// whatever its interval `[a, b]` (the Bernstein form is in `(u − a)/(b − a)`).
fn elevated_control<T: Scalar>(curve: &BezierCurve<T>, to: usize) -> Result<Vec<Vec<T>>> {
    let c = curve.control();
    (0..c.nrows())
        .map(|k| {
            let row: Vec<T> = c.row(k).iter().cloned().collect();
            elevate(&row, to)
        })
        .collect()
}

/// The tensor-product Bézier net of `g1 + g2 − g12` for Bézier network curves: see
/// [`GordonSurface::to_bezier`].
pub(crate) fn gordon_bezier_net<T: Scalar>(
    u_nodes: &[T],
    v_nodes: &[T],
    curves_at_u: &[BezierCurve<T>],
    curves_at_v: &[BezierCurve<T>],
    points: &[Vec<DVector<T>>],
) -> Result<BezierPatch<T>> {
    let (m, n) = (u_nodes.len() - 1, v_nodes.len() - 1);
    let p = curves_at_v.iter().map(|c| c.degree()).max().unwrap_or(0);
    let q = curves_at_u.iter().map(|c| c.degree()).max().unwrap_or(0);
    let (deg_u, deg_v) = (m.max(p), n.max(q));
    let lu = bernstein_coefficients(u_nodes, deg_u)?;
    let lv = bernstein_coefficients(v_nodes, deg_v)?;
    let at_u = curves_at_u
        .iter()
        .map(|c| elevated_control(c, deg_v))
        .collect::<Result<Vec<_>>>()?;
    let at_v = curves_at_v
        .iter()
        .map(|c| elevated_control(c, deg_u))
        .collect::<Result<Vec<_>>>()?;
    let dim = points[0][0].len();
    let coords = (0..dim)
        .map(|d| {
            DMatrix::from_fn(deg_u + 1, deg_v + 1, |k, l| {
                let mut g1 = T::zero();
                for (li, ci) in lu.iter().zip(&at_u) {
                    g1 = g1 + li[k].clone() * ci[d][l].clone();
                }
                let mut g2 = T::zero();
                for (lj, cj) in lv.iter().zip(&at_v) {
                    g2 = g2 + lj[l].clone() * cj[d][k].clone();
                }
                let mut g12 = T::zero();
                for (li, row) in lu.iter().zip(points) {
                    for (lj, pt) in lv.iter().zip(row) {
                        g12 = g12 + li[k].clone() * lj[l].clone() * pt[d].clone();
                    }
                }
                g1 + g2 - g12
            })
        })
        .collect::<Vec<_>>();
    crate::error::check_overflow(
        "Bézier net of a Gordon surface",
        coords.iter().flat_map(|c| c.iter()),
    )?;
    BezierPatch::new(coords)
}

impl<T: Scalar> GordonSurface<BezierCurve<T>, T> {
    /// The Gordon surface of a network of Bézier curves, exactly, as one tensor-product Bézier
    /// patch (a curve on an interval `[a, b]` enters reparametrised onto `[0, 1]`, which keeps
    /// its control points).
    ///
    /// With `p` the largest degree of the curves `g(u, v_j)` and `q` that of the curves
    /// `g(u_i, v)`, the patch has degree `(max(m, p), max(n, q))`: each Lagrange basis function
    /// is converted to Bernstein form (a product of linear factors), the network curves are
    /// degree-elevated to the common degree, and `g1`, `g2`, `g12` are summed control point by
    /// control point. The conversion is exact in rationals; in `f64` it agrees with
    /// [`Surface::eval`] to round-off.
    ///
    /// # Errors
    /// [`Error::NonFinite`] if a control point overflows in `f64`.
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// use cagd::gordon::GordonSurface;
    /// use cagd::Surface;
    /// use nalgebra::dmatrix;
    /// // The Coons case: four straight edges of the unit square, nodes {0, 1}.
    /// let line = |x0: f64, y0: f64, x1: f64, y1: f64| BezierCurve::new(dmatrix![x0, x1; y0, y1]).unwrap();
    /// let g = GordonSurface::new(
    ///     vec![0.0, 1.0], vec![0.0, 1.0],
    ///     vec![line(0.0, 0.0, 0.0, 1.0), line(1.0, 0.0, 1.0, 1.0)],
    ///     vec![line(0.0, 0.0, 1.0, 0.0), line(0.0, 1.0, 1.0, 1.0)],
    /// ).unwrap();
    /// let patch = g.to_bezier().unwrap();
    /// assert_eq!(patch.degree(), (1, 1));
    /// assert_eq!(patch.eval(0.25, 0.5), g.eval(0.25, 0.5));
    /// ```
    pub fn to_bezier(&self) -> Result<BezierPatch<T>> {
        gordon_bezier_net(
            self.u_nodes(),
            self.v_nodes(),
            &self.curves_at_u,
            &self.curves_at_v,
            &self.points,
        )
    }
}

/// The cost of one point of a Gordon surface of `k_u × k_v` curves in `d` coordinates,
/// `g = g1 + g2 − g12`: every curve of the network at its parameter (`curves`, the cost of
/// each), the `k_u k_v` points of `g12` and the Lagrange bases in `u` and `v`,
/// `(4(k_u + k_v) + 2 k_u k_v)(1 + d)` operations, on numbers as large as the curves' values
/// grown by the bases: products of `k − 1` factors `(u − u_j)/(u_i − u_j)`,
/// [`polynomial_bits`]`(k_u − 1, u_bits + 2 u_node_bits, 0)` and the same in `v`
/// ([`blended`]). `u = (u_bits, u_node_bits)` are the sizes of the parameter and of the nodes
/// in `u`, `v` those in `v`.
///
/// ```
/// use cagd::cost::Cost;
/// use cagd::gordon::gordon_point_cost;
/// let c = gordon_point_cost([Cost::new(1, 0); 6], (3, 3), 3, (0, 0), (0, 0));
/// assert_eq!(c, Cost::new(6 + (24 + 18) * 4, 4));
/// ```
pub fn gordon_point_cost(
    curves: impl IntoIterator<Item = Cost>,
    (k_u, k_v): (usize, usize),
    d: usize,
    u: (u128, u128),
    v: (u128, u128),
) -> Cost {
    let (ku, kv) = (k_u as u128, k_v as u128);
    let basis_bits = |k: usize, (param_bits, node_bits): (u128, u128)| {
        polynomial_bits(
            k.saturating_sub(1),
            param_bits.saturating_add(node_bits.saturating_mul(2)),
            0,
        )
    };
    blended(
        curves,
        (4 * (ku + kv))
            .saturating_add(ku.saturating_mul(kv).saturating_mul(2))
            .saturating_mul(1 + d as u128),
        basis_bits(k_u, u).saturating_add(basis_bits(k_v, v)),
    )
}

/// The cost of setting up a Gordon surface ([`GordonSurface::new`]) of `k_u × k_v` curves
/// whose evaluations cost `curves_at_u` and `curves_at_v` (one each): the compatibility check
/// evaluates both curves through each of the `k_u k_v` crossings, the crossing points
/// `g(u_i, v_j)` are taken from the curves `g(u_i, ·)` once more, and the barycentric weights of
/// the Lagrange bases in `u` and `v` ([`Lagrange::weights_cost`]) are built from nodes of
/// `u_node_bits` and `v_node_bits` bits. Known before the set-up, so that a caller can refuse it
/// before doing any: exact weights of 400 nodes `i/399` alone took 17 s.
///
/// ```
/// use cagd::cost::Cost;
/// use cagd::gordon::gordon_setup_cost;
/// let c = gordon_setup_cost([Cost::new(2, 0); 3], [Cost::new(1, 5); 4], (0, 0));
/// // 3 curves at 4 nodes, twice; 4 curves at 3 nodes; weights of 3 and of 4 nodes.
/// assert_eq!(c.ops(), 2 * 3 * 4 * 2 + 4 * 3 + 9 + 16);
/// assert_eq!(c.bits(), 5);
/// ```
pub fn gordon_setup_cost(
    curves_at_u: impl IntoIterator<Item = Cost>,
    curves_at_v: impl IntoIterator<Item = Cost>,
    (u_node_bits, v_node_bits): (u128, u128),
) -> Cost {
    let (at_u, k_u) = one_of_each(curves_at_u);
    let (at_v, k_v) = one_of_each(curves_at_v);
    at_u.times(2 * k_v as u128)
        .and(at_v.times(k_u as u128))
        .and(Lagrange::<f64>::weights_cost(k_u, u_node_bits))
        .and(Lagrange::<f64>::weights_cost(k_v, v_node_bits))
}

/// One evaluation of each curve ([`Cost::and`] of their costs), and how many curves.
fn one_of_each(curves: impl IntoIterator<Item = Cost>) -> (Cost, usize) {
    curves
        .into_iter()
        .fold((Cost::default(), 0), |(c, k), x| (c.and(x), k + 1))
}

#[cfg(test)]
mod cost_tests {
    use super::*;

    #[test]
    fn the_lagrange_bases_grow_the_numbers() {
        let c = gordon_point_cost(
            [Cost::new(5, 20), Cost::new(5, 30)],
            (2, 4),
            2,
            (3, 1),
            (0, 2),
        );
        assert_eq!(c.ops(), 10 + (24 + 16) * 3);
        assert_eq!(c.bits(), 30 + (3 + 2 + 1) + 3 * (4 + 1));
    }
}
