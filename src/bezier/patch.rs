//! Tensor-product Bézier patches of degree `(m, n)` (thesis chapter 3).

use crate::grid::PointGrid;
use nalgebra::{DMatrix, DVector};

use super::check_params;
use super::curve::BezierCurve;
use super::scheme::{patch_step_in_place, patch_steps, PatchScheme};
use crate::bernstein::{bernstein_all, bernstein_all_into, falling_factorial};
use crate::cost::{polynomial_bits, Cost};
use crate::error::{check_finite, check_overflow, Error, Result};
use crate::param::{check_parameter, Surface};
use crate::scalar::Scalar;

/// One of the four boundary curves of a patch over `[0, 1]²`.
///
/// With control points `b_{i,j}` (`i = 0..=m` along `u`, `j = 0..=n` along `v`):
///
/// | edge | curve | control points | runs along |
/// |------|-------|----------------|------------|
/// | [`U0`](Edge::U0) | `x(0, v)` | `b_{0,0}, …, b_{0,n}` | `j` (parameter `v`) |
/// | [`U1`](Edge::U1) | `x(1, v)` | `b_{m,0}, …, b_{m,n}` | `j` (parameter `v`) |
/// | [`V0`](Edge::V0) | `x(u, 0)` | `b_{0,0}, …, b_{m,0}` | `i` (parameter `u`) |
/// | [`V1`](Edge::V1) | `x(u, 1)` | `b_{0,n}, …, b_{m,n}` | `i` (parameter `u`) |
///
/// (thesis §3.4, property 5: the boundary curves of a Bézier patch are Bézier curves. Its proof
/// writes `Σ_j b_{i,j} B_j^n(v)` for `x(0, v)` where `b_{0,j}` is meant.)
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Edge {
    /// `u = 0`: the curve `v ↦ x(0, v)`, control points `b_{0,j}`, `j = 0..=n`.
    U0,
    /// `u = 1`: the curve `v ↦ x(1, v)`, control points `b_{m,j}`, `j = 0..=n`.
    U1,
    /// `v = 0`: the curve `u ↦ x(u, 0)`, control points `b_{i,0}`, `i = 0..=m`.
    V0,
    /// `v = 1`: the curve `u ↦ x(u, 1)`, control points `b_{i,n}`, `i = 0..=m`.
    V1,
}

impl Edge {
    /// All four edges, in the order `U0, U1, V0, V1`.
    pub const ALL: [Edge; 4] = [Edge::U0, Edge::U1, Edge::V0, Edge::V1];
}

/// A tensor-product Bézier patch of degree `(m, n)` over `[0, 1]²` (thesis eq. (3.5)):
///
/// ```text
/// x(u, v) = Σ_{i=0}^m Σ_{j=0}^n b_{i,j} B_i^m(u) B_j^n(v).
/// ```
///
/// **Layout:** one `(m + 1) × (n + 1)` matrix per coordinate; entry `(i, j)` of matrix `k` is
/// coordinate `k` of `b_{i,j}` (`i` along `u`, `j` along `v`, as in the thesis). `m ≠ n` is
/// allowed, and so is degree 0 in either direction.
///
/// **Evaluation.** [`eval`](Self::eval) (and [`Surface::eval`]) run the tensor de Casteljau
/// algorithm of thesis §3.2 (whose formula raises both level indices together,
/// `b^{p,r}` from `b^{p−1,r−1}`, and so only reaches `b^{m,n}_{0,0}` when `m = n`): `min(m, n)` bilinear steps
/// `(1−u)(1−v) b_{i,j} + u(1−v) b_{i+1,j} + (1−u)v b_{i,j+1} + uv b_{i+1,j+1}` (that term order,
/// as the fixed Octave `bilinearna`), then `|m − n|` linear steps `(1−u) b_{i,j} + u b_{i+1,j}`
/// (or the same in `v`) in the direction whose degree remains.
///
/// The thesis's `bilinearna` (appendix B) is wrong for `m ≠ n`: it runs `m` bilinear steps,
/// the `j` loop going to `n − k + 1`. For `m > n` the steps after the `n`-th find an empty `j`
/// range and change nothing, so it returns `b_{0,0}` of the level after `n` bilinear steps; for
/// `m < n` it stops after `m` steps with a row of `n − m + 1` points left and returns the first
/// of them; for `m = 0` no step runs and it returns the zero its work array was initialised
/// with. This type takes the bilinear steps while both degrees remain and linear steps after.
///
/// [`eval_bernstein`](Self::eval_bernstein) sums eq. (3.5) directly;
/// [`try_eval_grid`](Self::try_eval_grid) (and [`Surface::eval_grid`]) evaluate a whole grid as
/// `B_u · P_k · B_vᵀ` per coordinate.
///
/// ```
/// use cagd::bezier::BezierPatch;
/// // Degree (2, 1): x = u (spread), y = v, z lifts the middle row.
/// let patch = BezierPatch::from_net(&[
///     vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
///     vec![[0.5, 0.0, 1.0], [0.5, 1.0, 1.0]],
///     vec![[1.0, 0.0, 0.0], [1.0, 1.0, 0.0]],
/// ])?;
/// assert_eq!(patch.degree(), (2, 1));
/// assert_eq!(patch.eval(0.5, 0.25).as_slice(), &[0.5, 0.25, 0.5]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPatch<T: Scalar = f64> {
    coords: Vec<DMatrix<T>>,
}

impl<T: Scalar> BezierPatch<T> {
    /// The patch with coordinate matrices `coords` (one `(m + 1) × (n + 1)` matrix per
    /// coordinate, all the same shape).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for an empty list or matrices of different shapes;
    /// [`Error::TooFewPoints`] for a matrix with no rows or no columns;
    /// [`Error::NonFinite`] for a NaN or infinite entry.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// use nalgebra::DMatrix;
    /// let x = DMatrix::from_row_slice(2, 3, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    /// let y = DMatrix::from_row_slice(2, 3, &[0.0, 0.5, 1.0, 0.0, 0.5, 1.0]);
    /// let p = BezierPatch::new(vec![x, y])?;
    /// assert_eq!((p.degree(), p.dim()), ((1, 2), 2));
    /// assert_eq!(p.eval(0.25, 0.5).as_slice(), &[0.25, 0.5]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn new(coords: Vec<DMatrix<T>>) -> Result<Self> {
        let what = "Bézier patch control net";
        let first = coords.first().ok_or_else(|| Error::ShapeMismatch {
            what,
            expected: "at least one coordinate matrix".into(),
            found: "none".into(),
        })?;
        let shape = first.shape();
        if shape.0 == 0 || shape.1 == 0 {
            return Err(Error::TooFewPoints {
                what,
                min: 1,
                found: 0,
            });
        }
        for (k, x) in coords.iter().enumerate() {
            if x.shape() != shape {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!(
                        "every coordinate matrix {} × {} (as coordinate 0)",
                        shape.0, shape.1
                    ),
                    found: format!("{} × {} for coordinate {k}", x.nrows(), x.ncols()),
                });
            }
        }
        // Flat index over the coordinates in order, each matrix column-major.
        check_finite(what, coords.iter().flat_map(|x| x.iter()))?;
        Ok(BezierPatch { coords })
    }

    /// The patch from a net of points: `net[i][j]` is `b_{i,j}`, a slice of `d` coordinates
    /// (`i` along `u`, `j` along `v`), e.g. `Vec<Vec<Vec<f64>>>` or `&[Vec<[f64; 3]>]`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for no rows or an empty first row; [`Error::ShapeMismatch`] for
    /// ragged rows or points of different dimension (or of dimension 0);
    /// [`Error::NonFinite`] for a NaN or infinite coordinate.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p = BezierPatch::from_net(&[vec![[0.0, 0.0], [0.0, 1.0]], vec![[1.0, 0.0], [1.0, 1.0]]])?;
    /// assert_eq!(p.control_point(1, 0).unwrap().as_slice(), &[1.0, 0.0]);
    /// let ragged = BezierPatch::from_net(&[vec![[0.0, 0.0], [0.0, 1.0]], vec![[1.0, 0.0]]]);
    /// assert!(matches!(ragged, Err(cagd::Error::ShapeMismatch { .. })));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn from_net<R, P>(net: &[R]) -> Result<Self>
    where
        R: AsRef<[P]>,
        P: AsRef<[T]>,
    {
        let what = "Bézier patch control net";
        let rows = net.len();
        let cols = net.first().map_or(0, |r| r.as_ref().len());
        if rows == 0 || cols == 0 {
            return Err(Error::TooFewPoints {
                what,
                min: 1,
                found: 0,
            });
        }
        for (i, row) in net.iter().enumerate() {
            if row.as_ref().len() != cols {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!("{cols} points in every row (as in row 0)"),
                    found: format!("{} points in row {i}", row.as_ref().len()),
                });
            }
        }
        let d = net[0].as_ref()[0].as_ref().len();
        if d == 0 {
            return Err(Error::ShapeMismatch {
                what,
                expected: "at least one coordinate per point".into(),
                found: "0 coordinates in point (0, 0)".into(),
            });
        }
        for (i, row) in net.iter().enumerate() {
            for (j, p) in row.as_ref().iter().enumerate() {
                if p.as_ref().len() != d {
                    return Err(Error::ShapeMismatch {
                        what,
                        expected: format!("{d} coordinates in every point (as in point (0, 0))"),
                        found: format!("{} coordinates in point ({i}, {j})", p.as_ref().len()),
                    });
                }
            }
        }
        let coords = (0..d)
            .map(|k| DMatrix::from_fn(rows, cols, |i, j| net[i].as_ref()[j].as_ref()[k].clone()))
            .collect();
        Self::new(coords)
    }

    /// The patch from a net of shape `(m + 1, n + 1, d)`, `net[[i, j, k]]` being coordinate
    /// `k` of `b_{i,j}` — the layout the thesis's `tenzor` produces.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let net = cagd::grid::PointGrid::from_shape_fn((2, 2, 1), |(i, j, _)| (i + 2 * j) as f64);
    /// let p = BezierPatch::from_grid(&net)?;
    /// assert_eq!(p.eval(0.5, 0.5)[0], 1.5);
    /// assert_eq!(p.to_grid(), net);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn from_grid(net: &PointGrid<T>) -> Result<Self> {
        let (rows, cols, d) = net.dim();
        if d == 0 {
            return Err(Error::ShapeMismatch {
                what: "Bézier patch control net",
                expected: "at least one coordinate (third dimension)".into(),
                found: "0".into(),
            });
        }
        let coords = (0..d)
            .map(|k| DMatrix::from_fn(rows, cols, |i, j| net[[i, j, k]].clone()))
            .collect();
        Self::new(coords)
    }

    /// A patch from parts already known to be valid.
    pub(crate) fn from_valid(coords: Vec<DMatrix<T>>) -> Self {
        BezierPatch { coords }
    }

    /// The control net as a grid of shape `(m + 1, n + 1, d)` (the layout of `tenzor`).
    pub fn to_grid(&self) -> PointGrid<T> {
        let (rows, cols) = self.coords[0].shape();
        PointGrid::from_shape_fn((rows, cols, self.dim()), |(i, j, k)| {
            self.coords[k][(i, j)].clone()
        })
    }

    /// The degree `(m, n)`: `m` in `u`, `n` in `v`.
    pub fn degree(&self) -> (usize, usize) {
        let (rows, cols) = self.coords[0].shape();
        (rows - 1, cols - 1)
    }

    /// The dimension `d` of the points.
    pub fn dim(&self) -> usize {
        self.coords.len()
    }

    /// The coordinate matrices, one `(m + 1) × (n + 1)` matrix per coordinate.
    pub fn coordinates(&self) -> &[DMatrix<T>] {
        &self.coords
    }

    /// The control point `b_{i,j}` (`None` outside the net).
    pub fn control_point(&self, i: usize, j: usize) -> Option<DVector<T>> {
        let (rows, cols) = self.coords[0].shape();
        (i < rows && j < cols).then(|| {
            DVector::from_iterator(self.dim(), self.coords.iter().map(|x| x[(i, j)].clone()))
        })
    }

    /// The point `x(u, v)` by the tensor de Casteljau algorithm (see the type docs). Any
    /// parameters are accepted (outside the domain `[0, 1]²` the polynomial continues; NaN
    /// gives NaN); [`try_eval`](Self::try_eval) accepts only the domain.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    /// assert_eq!(p.eval(0.5, 0.5).as_slice(), &[0.5, 0.5, 0.25]);
    /// ```
    pub fn eval(&self, u: T, v: T) -> DVector<T> {
        let (m, n) = self.degree();
        let mut work = self.coords.clone();
        let mut shape = (m + 1, n + 1);
        for step in patch_steps(m, n) {
            shape = patch_step_in_place(&mut work, shape, step, &u, &v);
        }
        DVector::from_iterator(work.len(), work.iter().map(|x| x[(0, 0)].clone()))
    }

    /// [`eval`](Self::eval) for parameters in the domain `[0, 1]²`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite `u` or `v`, [`Error::ParameterOutOfRange`]
    /// for a finite one outside `[0, 1]`.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// use cagd::Error;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    /// assert_eq!(p.try_eval(1.0, 0.5)?.as_slice(), &[1.0, 0.5, 0.5]);
    /// assert!(matches!(p.try_eval(f64::INFINITY, 0.5), Err(Error::NonFinite { .. })));
    /// assert!(matches!(p.try_eval(0.5, 1.5), Err(Error::ParameterOutOfRange { .. })));
    /// assert_eq!(p.eval(0.5, 1.5).as_slice(), &[0.5, 1.5, 0.75]); // eval continues
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let unit = (T::zero(), T::one());
        check_parameter("Bézier patch parameter u", &u, &unit)?;
        check_parameter("Bézier patch parameter v", &v, &unit)?;
        self.check_point_work(u.bits(), v.bits())?;
        crate::checked::point("Bézier patch point", self.dim(), self.eval(u, v))
    }

    /// The work of one point against the default limit ([`crate::checked::point_work`]).
    fn check_point_work(&self, u_bits: u128, v_bits: u128) -> Result<()> {
        let control_bits = crate::cost::max_bits(self.coords.iter().flat_map(|x| x.iter()));
        crate::checked::point_work::<T>(
            "Bézier patch point",
            self.scheme_cost(u_bits, v_bits, control_bits),
        )
    }

    /// Every level of the tensor de Casteljau algorithm at `(u, v)`; the last point equals
    /// [`eval`](Self::eval) bit for bit.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    /// let s = p.scheme(0.5, 0.5);
    /// assert_eq!(s.level_count(), 2);
    /// assert_eq!(s.point(0, 1, 1).unwrap().as_slice(), &[1.0, 1.0, 1.0]);
    /// assert_eq!(s.point_on_surface(), p.eval(0.5, 0.5));
    /// println!("{s}");
    /// ```
    pub fn scheme(&self, u: T, v: T) -> PatchScheme<T> {
        PatchScheme::compute(&self.coords, u, v)
    }

    /// The cost of the tensor de Casteljau scheme at one point ([`scheme`](Self::scheme)):
    /// `(m+1)(n+1)(m+n+2)` operations per coordinate (`m + n` levels over at most
    /// `(m+1)(n+1)` points), counted for the three coordinates of a net in space, on numbers
    /// of the size of [`grid_cost`](Self::grid_cost).
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // degree (1, 1)
    /// assert_eq!(p.scheme_cost(0, 0, 0).ops(), 3 * 4 * 4);
    /// ```
    pub fn scheme_cost(&self, u_bits: u128, v_bits: u128, control_bits: u128) -> Cost {
        let (m1, n1) = self.net_size();
        Cost::new(
            3 * (m1 * n1) * (m1 + n1),
            self.point_bits(u_bits, v_bits, control_bits),
        )
    }

    /// `(m + 1, n + 1)`.
    fn net_size(&self) -> (u128, u128) {
        let (m, n) = self.degree();
        (m as u128 + 1, n as u128 + 1)
    }

    /// The size the values reach: the bits of `u` at `m` levels, of `v` at `n`, over the
    /// control points'.
    fn point_bits(&self, u_bits: u128, v_bits: u128, control_bits: u128) -> u128 {
        let (m, n) = self.degree();
        polynomial_bits(m, u_bits, 0).saturating_add(polynomial_bits(n, v_bits, control_bits))
    }

    /// The point from the Bernstein form, eq. (3.5): `Σ_i B_i^m(u) (Σ_j B_j^n(v) b_{i,j})`, the
    /// bases from [`bernstein_all`]. Agrees with [`eval`](Self::eval) up to rounding (exactly,
    /// for rationals).
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    /// assert_eq!(p.eval_bernstein(0.5, 0.25).as_slice(), &[0.5, 0.25, 0.125]);
    /// ```
    pub fn eval_bernstein(&self, u: T, v: T) -> DVector<T> {
        let (m, n) = self.degree();
        let bu = bernstein_all(m, u);
        let bv = bernstein_all(n, v);
        DVector::from_iterator(
            self.dim(),
            self.coords.iter().map(|x| {
                bu.iter().enumerate().fold(T::zero(), |acc, (i, wu)| {
                    let inner = bv
                        .iter()
                        .enumerate()
                        .fold(T::zero(), |s, (j, wv)| s + wv.clone() * x[(i, j)].clone());
                    acc + wu.clone() * inner
                })
            }),
        )
    }

    /// The partial derivative `∂^{r+s} x / ∂u^r ∂v^s` as a patch of degree `(m − r, n − s)`
    /// (thesis Trditev 3.3 and the higher-order formulas after it):
    ///
    /// ```text
    /// ∂^{r+s}/∂u^r∂v^s x = m!/(m−r)! · n!/(n−s)! · Σ_i Σ_j Δ^{(r,s)} b_{i,j} B_i^{m−r}(u) B_j^{n−s}(v),
    /// ```
    ///
    /// with `Δ^{(r,s)}` the forward differences taken `r` times along `i` and `s` times along
    /// `j` (`Δ^{(1,1)} b_{i,j} = b_{i+1,j+1} − b_{i,j+1} − b_{i+1,j} + b_{i,j}`), scaled once at
    /// the end. `(0, 0)` gives a copy.
    ///
    /// Notes on the thesis text: the proof of Trditev 3.3 writes `b_{i+j,j} − b_{i,j}` where
    /// `Δ^{(1,0)} b_{i,j} = b_{i+1,j} − b_{i,j}` is meant; the higher-order formulas write
    /// `∂/∂u^r` for `∂^r/∂u^r` and cite an equation (2.6) that is the unnumbered r-th derivative
    /// formula of §2.4; the mixed case `r, s > 0` of higher order is not stated there but
    /// follows in the same way, since the differences in `i` and `j` commute.
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] if `r > m` or `s > n`; [`Error::Overflow`] for a control
    /// point whose double overflows.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // (u, v, uv)
    /// let xu = p.derivative(1, 0)?;
    /// assert_eq!(xu.eval(0.3, 0.5).as_slice(), &[1.0, 0.0, 0.5]); // (1, 0, v)
    /// assert!(p.derivative(2, 0).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn derivative(&self, r: usize, s: usize) -> Result<Self> {
        let (m, n) = self.degree();
        if r > m {
            return Err(Error::DerivativeOrder {
                order: r,
                degree: m,
            });
        }
        if s > n {
            return Err(Error::DerivativeOrder {
                order: s,
                degree: n,
            });
        }
        let factor = falling_factorial::<T>(m, r) * falling_factorial::<T>(n, s);
        let coords = self
            .coords
            .iter()
            .map(|x| {
                let mut diff = x.clone();
                for _ in 0..r {
                    diff = DMatrix::from_fn(diff.nrows() - 1, diff.ncols(), |i, j| {
                        diff[(i + 1, j)].clone() - diff[(i, j)].clone()
                    });
                }
                for _ in 0..s {
                    diff = DMatrix::from_fn(diff.nrows(), diff.ncols() - 1, |i, j| {
                        diff[(i, j + 1)].clone() - diff[(i, j)].clone()
                    });
                }
                if r + s > 0 {
                    diff = diff.map(|e| factor.clone() * e);
                }
                diff
            })
            .collect::<Vec<_>>();
        check_overflow(
            "Bézier patch derivative control points",
            coords.iter().flat_map(|x| x.iter()),
        )?;
        Ok(BezierPatch { coords })
    }

    /// The twist `∂²x/∂u∂v` as a patch of degree `(m − 1, n − 1)`: `m n Δ^{(1,1)} b_{i,j}`
    /// (thesis Trditev 3.3).
    ///
    /// # Errors
    /// [`Error::DerivativeOrder`] if `m = 0` or `n = 0`.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // z = uv: twist (0, 0, 1)
    /// assert_eq!(p.twist()?.eval(0.7, 0.2).as_slice(), &[0.0, 0.0, 1.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn twist(&self) -> Result<Self> {
        self.derivative(1, 1)
    }

    /// The boundary curve along `edge` as a Bézier curve over `[0, 1]` (see [`Edge`] for which
    /// control points and which parameter).
    ///
    /// ```
    /// use cagd::bezier::{BezierPatch, Edge};
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    /// let top = p.boundary(Edge::U1); // x(1, v) = (1, v, v)
    /// assert_eq!(top.eval(0.25).as_slice(), &[1.0, 0.25, 0.25]);
    /// ```
    pub fn boundary(&self, edge: Edge) -> BezierCurve<T> {
        let (m, n) = self.degree();
        let d = self.dim();
        let control = match edge {
            Edge::U0 => DMatrix::from_fn(d, n + 1, |k, j| self.coords[k][(0, j)].clone()),
            Edge::U1 => DMatrix::from_fn(d, n + 1, |k, j| self.coords[k][(m, j)].clone()),
            Edge::V0 => DMatrix::from_fn(d, m + 1, |k, i| self.coords[k][(i, 0)].clone()),
            Edge::V1 => DMatrix::from_fn(d, m + 1, |k, i| self.coords[k][(i, n)].clone()),
        };
        BezierCurve::from_valid(control, T::zero(), T::one())
    }

    /// The patch on the grid `us × vs`: an array of shape `(us.len(), vs.len(), d)` with
    /// `grid[[a, b, k]]` coordinate `k` of `x(us[a], vs[b])` (the layout of `P(i,j,:)` in the
    /// thesis's `ploskevB`).
    ///
    /// Computed through basis rows, not point by point: coordinate `k` of the grid is
    /// `S_k = B_u · P_k · B_vᵀ` with `B_u` = [`basis_matrix`](crate::bernstein::basis_matrix)`(m, us)` and
    /// `B_v` = `basis_matrix(n, vs)`, formed row by row as described at
    /// [`eval_grid_into`](Self::eval_grid_into) (`O(m + n)` per point). Agrees with
    /// [`eval`](Self::eval) up to rounding (exactly for rationals).
    ///
    /// Like the thesis's `ploskevB` it takes any finite parameters: outside `[0, 1]` the
    /// polynomial continues, as in [`eval`](Self::eval) (a grid check, not
    /// [`try_eval`](Self::try_eval)'s domain check).
    ///
    /// # Errors
    /// [`Error::EmptyGrid`] for an empty `us` or `vs`; [`Error::NonFinite`] for a NaN or
    /// infinite parameter.
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    /// let g = p.try_eval_grid(&[0.0, 0.5, 1.0], &[0.0, 1.0])?;
    /// assert_eq!(g.dim(), (3, 2, 3));
    /// assert_eq!(g[[1, 1, 2]], 0.5); // z(0.5, 1) = 0.5
    /// assert!(p.try_eval_grid(&[], &[0.0]).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn try_eval_grid(&self, us: &[T], vs: &[T]) -> Result<PointGrid<T>> {
        check_params("Bézier patch u grid", us)?;
        check_params("Bézier patch v grid", vs)?;
        let mut grid = PointGrid::try_from_elem((us.len(), vs.len(), self.dim()), T::zero())?;
        self.check_grid_work(us, vs)?;
        self.fill_grid(us, vs, grid.as_mut_slice())?;
        Ok(grid)
    }

    /// The work of one grid point against the default limit ([`crate::checked::point_work`]).
    fn check_grid_work(&self, us: &[T], vs: &[T]) -> Result<()> {
        let control_bits = crate::cost::max_bits(self.coords.iter().flat_map(|x| x.iter()));
        crate::checked::point_work::<T>(
            "Bézier patch grid point",
            self.grid_cost(
                crate::cost::max_bits(us),
                crate::cost::max_bits(vs),
                control_bits,
            ),
        )
    }

    /// The cost of one point of [`try_eval_grid`](Self::try_eval_grid): the basis rows in `u`
    /// and `v`, then about `2 (m+1)(n+1)` operations per coordinate, counted for the three
    /// coordinates of a net in space (`6 (m+1)(n+1)`), on numbers that grow by the bits of `u`
    /// at `m` levels and of `v` at `n` over the control points' `control_bits`
    /// ([`polynomial_bits`]).
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// use cagd::cost::Cost;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // degree (1, 1)
    /// assert_eq!(p.grid_cost(3, 5, 2), Cost::new(24, 4 + 8));
    /// ```
    pub fn grid_cost(&self, u_bits: u128, v_bits: u128, control_bits: u128) -> Cost {
        let (m1, n1) = self.net_size();
        Cost::new(6 * m1 * n1, self.point_bits(u_bits, v_bits, control_bits))
    }

    /// The grid for the infallible `Surface::eval_grid` (non-finite values, if any, are
    /// left in place there).
    fn grid(&self, us: &[T], vs: &[T]) -> PointGrid<T> {
        let mut grid = PointGrid::from_elem((us.len(), vs.len(), self.dim()), T::zero());
        let out = grid.as_mut_slice();
        let _ = self.fill_grid(us, vs, out);
        grid
    }

    /// The patch on the grid `us × vs` written into `out`, row by row:
    /// `out[(a·nv + b)·d + c]` is coordinate `c` of `x(us[a], vs[b])` (`(nu, nv, d)` row-major,
    /// the memory layout of [`try_eval_grid`](Self::try_eval_grid)'s array; see
    /// [`crate::grid`]). Like [`try_eval_grid`](Self::try_eval_grid), any finite parameter is accepted (the polynomial continues outside `[0, 1]`).
    ///
    /// The algorithm (the same as `try_eval_grid`): the basis rows `B^m(us[a])` and
    /// `B^n(vs[b])` are computed once (`O(N·(m+n))` memory for an `N × N` grid); for each row
    /// `a`, the net is contracted with the `u` basis first, `c_j = Σ_i B_i^m(us[a]) b_{i,j}`
    /// (the control points of the curve `v ↦ x(us[a], v)`, `(m+1)(n+1)d` operations per row),
    /// then each point of the row is `Σ_j B_j^n(vs[b]) c_j`: `(n+1)·d` multiply-adds per point,
    /// `O(m + n)` per point overall instead of de Casteljau's `O(m·n·min(m, n))`. Nothing is
    /// allocated per point, and large grids are split by rows over all cores.
    ///
    /// Accuracy: the Bernstein sums of non-negative weights agree with [`eval`](Self::eval) to
    /// a few units of `(m + n) ε · max |b_{i,j}|` in `f64` for `(u, v) ∈ [0, 1]²`, and exactly
    /// for rationals.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · vs.len() · d`;
    /// [`Error::NonFinite`] for a NaN or infinite parameter; [`Error::TooLarge`] when the work
    /// of one point exceeds the default limit; [`Error::Overflow`] for a point whose double
    /// overflows (the grid is written all the same).
    ///
    /// ```
    /// use cagd::bezier::BezierPatch;
    /// let p: BezierPatch = BezierPatch::hyperbolic_paraboloid(); // (u, v, uv)
    /// let (us, vs) = ([0.0, 0.5], [0.25, 1.0]);
    /// let mut out = vec![0.0; 2 * 2 * 3];
    /// p.eval_grid_into(&us, &vs, &mut out)?;
    /// assert_eq!(&out[6..9], &[0.5, 0.25, 0.125]); // x(0.5, 0.25)
    /// assert!(p.eval_grid_into(&us, &vs, &mut [0.0; 5]).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        let len = crate::grid::grid_len("Bézier patch grid", &[us.len(), vs.len(), self.dim()])?;
        crate::grid::check_len("Bézier patch grid buffer", len, out)?;
        check_finite("Bézier patch grid parameters", us.iter().chain(vs))?;
        self.check_grid_work(us, vs)?;
        self.fill_grid(us, vs, out)
    }

    /// [`eval_grid_into`](Self::eval_grid_into) after the length check.
    fn fill_grid(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        let (m, n) = self.degree();
        let d = self.dim();
        let (rows_u, terms) = (m + 1, n + 1);
        let bu = crate::grid::rows_of(us, rows_u, |t, row| bernstein_all_into(t, row));
        let bv = crate::grid::planar_rows_of(vs, terms, |t, row| bernstein_all_into(t, row));
        // The net as (m+1) blocks of (n+1)·d: net[(i·(n+1) + j)·d + k] = b_{i,j}[k].
        let mut net = Vec::with_capacity(rows_u * terms * d);
        for i in 0..rows_u {
            for j in 0..terms {
                net.extend(self.coords.iter().map(|x| x[(i, j)].clone()));
            }
        }
        let work = out.len().saturating_mul(terms);
        // Every point is a sum `Σ_ij B_i(u) B_j(v) b_ij`, bounded by (m+1) max|B_i| ·
        // (n+1) max|B_j| · max|b_ij|: when that is finite no row is scanned
        // ([`crate::grid::bounded_by`]).
        let bounded = T::EXACT || {
            let weight = crate::grid::max_abs(&bu) * rows_u as f64;
            let weight = weight * crate::grid::max_abs(&bv) * terms as f64;
            crate::grid::bounded_by::<T>(weight, crate::grid::max_abs(&net))
        };
        crate::grid::for_each_bounded_row(
            "Bézier patch grid",
            out,
            vs.len() * d,
            work,
            || vec![T::zero(); terms * d],
            |coeffs, a, row| {
                crate::grid::weighted_sum_into(&bu[a * rows_u..(a + 1) * rows_u], &net, coeffs);
                crate::grid::contract_row_planar(&bv, vs.len(), 0, terms, coeffs, row);
                bounded
            },
        )
    }
}

impl<T: Scalar> Surface<T> for BezierPatch<T> {
    fn dim(&self) -> usize {
        BezierPatch::dim(self)
    }

    /// `[0, 1]²`.
    fn domain(&self) -> ((T, T), (T, T)) {
        ((T::zero(), T::one()), (T::zero(), T::one()))
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        BezierPatch::eval(self, u, v)
    }

    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        BezierPatch::try_eval(self, u, v)
    }

    /// Grid evaluation through basis matrices (see [`BezierPatch::try_eval_grid`]); empty
    /// parameter lists give an empty array.
    fn eval_grid(&self, us: &[T], vs: &[T]) -> PointGrid<T> {
        self.grid(us, vs)
    }

    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        BezierPatch::eval_grid_into(self, us, vs, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        <BigRational as Scalar>::from_ratio(n, d)
    }

    #[test]
    fn grid_and_scheme_costs() {
        let p = rational_patch(3, 2); // (m + 1)(n + 1) = 12
        assert_eq!(p.grid_cost(0, 0, 0), Cost::new(72, 5));
        assert_eq!(p.scheme_cost(0, 0, 0), Cost::new(3 * 12 * 7, 5));
        // u at m = 3 levels, v at n = 2 over the control points.
        assert_eq!(p.grid_cost(4, 9, 20).bits(), 3 * 5 + 2 * 10 + 20);
        assert_eq!(p.scheme_cost(4, 9, 20).bits(), p.grid_cost(4, 9, 20).bits());
    }

    fn rational_patch(m: usize, n: usize) -> BezierPatch<BigRational> {
        let coords = (0..3)
            .map(|k| {
                DMatrix::from_fn(m + 1, n + 1, |i, j| {
                    q(((i * 7 + j * 3 + k * 5) % 11) as i64 - 5, 1 + k as i64)
                })
            })
            .collect();
        BezierPatch::new(coords).unwrap()
    }

    #[test]
    fn all_evaluations_agree_exactly_for_unequal_degrees() {
        for (m, n) in [
            (0, 0),
            (0, 3),
            (3, 0),
            (1, 4),
            (4, 1),
            (2, 5),
            (5, 2),
            (3, 3),
        ] {
            let p = rational_patch(m, n);
            let us = [q(0, 1), q(1, 3), q(3, 4), q(1, 1)];
            let vs = [q(1, 5), q(1, 2), q(-1, 2)];
            let grid = p.try_eval_grid(&us, &vs).unwrap();
            for (a, u) in us.iter().enumerate() {
                for (b, v) in vs.iter().enumerate() {
                    let x = p.eval(u.clone(), v.clone());
                    assert_eq!(x, p.eval_bernstein(u.clone(), v.clone()), "({m},{n})");
                    assert_eq!(x, p.scheme(u.clone(), v.clone()).point_on_surface());
                    for k in 0..3 {
                        assert_eq!(grid[[a, b, k]], x[k]);
                    }
                }
            }
        }
    }

    #[test]
    fn scheme_shapes_follow_the_fixed_algorithm() {
        let p = rational_patch(2, 5);
        let s = p.scheme(q(1, 2), q(1, 3));
        let shapes: Vec<_> = (0..s.level_count())
            .map(|k| s.level_shape(k).unwrap())
            .collect();
        assert_eq!(shapes, vec![(3, 6), (2, 5), (1, 4), (1, 3), (1, 2), (1, 1)]);
        assert_eq!(
            s.steps(),
            &[
                PatchStep::Bilinear,
                PatchStep::Bilinear,
                PatchStep::LinearV,
                PatchStep::LinearV,
                PatchStep::LinearV
            ]
        );
        let text = s.to_string();
        assert!(
            text.contains("level 3 (linear step in v), 1 × 3:"),
            "{text}"
        );
    }

    use super::super::scheme::PatchStep;

    #[test]
    fn twist_of_the_hyperbolic_paraboloid() {
        let p = BezierPatch::<BigRational>::hyperbolic_paraboloid();
        let t = p.twist().unwrap();
        assert_eq!(t.degree(), (0, 0));
        assert_eq!(
            t.control_point(0, 0).unwrap().as_slice(),
            &[q(0, 1), q(0, 1), q(1, 1)]
        );
    }

    #[test]
    fn surface_grid_accepts_empty_lists_without_panicking() {
        let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
        let g = Surface::eval_grid(&p, &[], &[0.5]);
        assert_eq!(g.dim(), (0, 1, 3));
    }
}
