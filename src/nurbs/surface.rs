//! NURBS surfaces.

use nalgebra::{DMatrix, DVector};

use super::check_weights;
use super::curve::{project, NurbsCurve};
use crate::bspline::BSplineSurface;
use crate::error::{check_finite, Error, Result};
use crate::param::Surface;
use crate::scalar::Scalar;

/// A tensor-product NURBS surface
/// `S(u, v) = Σ_i Σ_j w_{ij} P_{ij} N_{i,p}(u) N_{j,q}(v) / Σ_i Σ_j w_{ij} N_{i,p}(u) N_{j,q}(v)`,
/// stored as the homogeneous B-spline surface with control points `(w_{ij} P_{ij}, w_{ij})`.
///
/// **Layout:** points as [`BSplineSurface`] (one `nu × nv` matrix per coordinate, `i` along
/// `u`), weights an `nu × nv` matrix.
///
/// ```
/// use cagd::nurbs::NurbsSurface;
/// use nalgebra::DMatrix;
/// let one = DMatrix::from_element(2, 2, 1.0);
/// let x = DMatrix::from_row_slice(2, 2, &[0.0, 0.0, 1.0, 1.0]);
/// let y = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 1.0]);
/// let k = vec![0.0, 0.0, 1.0, 1.0];
/// let s = NurbsSurface::new(1, 1, k.clone(), k, vec![x, y], one)?;
/// assert_eq!(s.try_eval(0.25, 0.5)?.as_slice(), &[0.25, 0.5]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSurface<T: Scalar = f64> {
    homogeneous: BSplineSurface<T>,
}

impl<T: Scalar> NurbsSurface<T> {
    /// The surface of degrees `(p, q)` with knots `knots_u`, `knots_v`, control points
    /// `coords` (one `nu × nv` matrix per coordinate) and weights `weights` (`nu × nv`).
    ///
    /// # Errors
    /// [`Error::NonPositiveWeight`], [`Error::ShapeMismatch`] if the weights have another
    /// shape than the points, and the errors of [`BSplineSurface::new`].
    pub fn new(
        p: usize,
        q: usize,
        knots_u: Vec<T>,
        knots_v: Vec<T>,
        coords: Vec<DMatrix<T>>,
        weights: DMatrix<T>,
    ) -> Result<Self> {
        let what = "NURBS surface weights";
        for c in &coords {
            check_finite("NURBS surface control points", c.iter())?;
            if c.shape() != weights.shape() {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!("{}×{} (as the control points)", c.nrows(), c.ncols()),
                    found: format!("{}×{}", weights.nrows(), weights.ncols()),
                });
            }
        }
        check_weights(what, weights.iter())?;
        let mut h: Vec<DMatrix<T>> = coords
            .iter()
            .map(|c| c.zip_map(&weights, |x, w| w * x))
            .collect();
        h.push(weights);
        let h = finish_net(what, h)?;
        Ok(NurbsSurface {
            homogeneous: BSplineSurface::new(p, q, knots_u, knots_v, h)?,
        })
    }

    /// The surface whose homogeneous form is `homogeneous` (last coordinate = weights).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for fewer than 2 coordinates, [`Error::NonPositiveWeight`].
    pub fn from_homogeneous(homogeneous: BSplineSurface<T>) -> Result<Self> {
        let c = homogeneous.coordinates();
        if c.len() < 2 {
            return Err(Error::ShapeMismatch {
                what: "NURBS homogeneous control net",
                expected: "at least 2 coordinates (points and weight)".into(),
                found: format!("{}", c.len()),
            });
        }
        check_weights("NURBS surface weights", c[c.len() - 1].iter())?;
        let h = finish_net("NURBS surface weights", c.to_vec())?;
        let (p, q) = homogeneous.degrees();
        let (ku, kv) = homogeneous.knots();
        Ok(NurbsSurface {
            homogeneous: BSplineSurface::new(
                p,
                q,
                ku.as_slice().to_vec(),
                kv.as_slice().to_vec(),
                h,
            )?,
        })
    }

    /// The ruled surface between two NURBS curves in homogeneous space, as octave-nurbs
    /// `nrbruled`: `u` runs along the curves, `v ∈ [0, 1]` from `c1` to `c2` (degree 1). The
    /// knot vectors are merged first (each curve gets the knots of the other it lacks, by
    /// knot insertion). With equal weights this is the lecture notes' `(1 − v) c1(u) + v c2(u)`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for curves of different degree, dimension or domain (degree
    /// elevation is not done here).
    pub fn ruled(c1: &NurbsCurve<T>, c2: &NurbsCurve<T>) -> Result<Self> {
        let what = "ruled NURBS surface";
        if c1.degree() != c2.degree() || c1.dim() != c2.dim() || c1.domain() != c2.domain() {
            return Err(Error::InvalidArgument {
                what,
                message: "both curves must have the same degree, dimension and domain".into(),
            });
        }
        let (k1, k2) = (c1.knots(), c2.knots());
        let missing = |a: &[T], b: &[T]| -> Vec<T> {
            // Knots of b (with multiplicity) that a lacks.
            let mut out = Vec::new();
            let mut seen: Vec<&T> = Vec::new();
            for x in b {
                if seen.contains(&x) {
                    continue;
                }
                seen.push(x);
                let (ma, mb) = (
                    a.iter().filter(|y| *y == x).count(),
                    b.iter().filter(|y| *y == x).count(),
                );
                out.extend(std::iter::repeat_n(x.clone(), mb.saturating_sub(ma)));
            }
            out
        };
        let c1 = c1.insert_knots(&missing(k1, k2))?;
        let c2 = c2.insert_knots(&missing(k2, k1))?;
        let (h1, h2) = (c1.homogeneous().control(), c2.homogeneous().control());
        let coords: Vec<DMatrix<T>> = (0..h1.nrows())
            .map(|r| {
                DMatrix::from_fn(h1.ncols(), 2, |i, j| {
                    if j == 0 {
                        h1[(r, i)].clone()
                    } else {
                        h2[(r, i)].clone()
                    }
                })
            })
            .collect();
        let kv = vec![T::zero(), T::zero(), T::one(), T::one()];
        Ok(NurbsSurface {
            homogeneous: BSplineSurface::new(c1.degree(), 1, c1.knots().to_vec(), kv, coords)?,
        })
    }

    /// The homogeneous B-spline surface.
    pub fn homogeneous(&self) -> &BSplineSurface<T> {
        &self.homogeneous
    }

    /// The dimension `d` of the points.
    pub fn dim(&self) -> usize {
        self.homogeneous.coordinates().len() - 1
    }

    /// The domain `([u_p, u_nu], [v_q, v_nv])` of the knots.
    pub fn domain(&self) -> ((T, T), (T, T)) {
        self.homogeneous.domain()
    }

    /// The cost of one point `S(u, v)`: the homogeneous surface's
    /// ([`BSplineSurface::point_cost`]) and `d` divisions by the weight.
    pub fn point_cost(&self, u_bits: u128, v_bits: u128) -> crate::cost::Cost {
        super::rational_point_cost(self.homogeneous.point_cost(u_bits, v_bits), self.dim())
    }

    /// The point `S(u, v)` for `(u, v)` in the domain: [`eval`](Self::eval)'s value, bit for
    /// bit.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for NaN or ±∞, [`Error::ParameterOutOfRange`] outside the domain.
    pub fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let h = self.homogeneous.try_eval(u, v)?;
        crate::checked::point("NURBS surface point", self.dim(), project(&h))
    }

    /// The point `S(u, v)` for any `(u, v)`: [`try_eval`](Self::try_eval)'s value in the
    /// domain, outside it the end pieces continued (the weight may vanish there); a NaN or
    /// infinite parameter gives a point of NaNs.
    pub fn eval(&self, u: T, v: T) -> DVector<T> {
        if !(u.is_finite_value() && v.is_finite_value()) {
            return crate::bspline::nan_point(self.dim(), u, v);
        }
        project(&self.homogeneous.eval(u, v))
    }

    /// The surface on the grid `us × vs` written into `out`, row by row:
    /// `out[(a·nv + b)·d + c]` is coordinate `c` of `S(us[a], vs[b])` (`(nu, nv, d)`
    /// row-major; see [`crate::grid`]). As [`eval`](Self::eval), outside the domain the end
    /// pieces continue and a NaN or infinite parameter gives points of NaNs.
    ///
    /// The homogeneous surface (weighted points and weights, `d + 1` coordinates) is evaluated
    /// row by row as in [`BSplineSurface::eval_grid_into`] (`O(p + q)` per point, nothing
    /// allocated per point, large grids on all cores), then each point is divided by its
    /// weight, `S = (Σ w P N N) / (Σ w N N)` — what [`try_eval`](Self::try_eval) does with the
    /// homogeneous point. The values agree with `try_eval` to a few units of `ε` relative to
    /// the size of the control points (with weights of moderate ratio), and exactly for
    /// rationals.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == us.len() · vs.len() · d`.
    ///
    /// ```
    /// use cagd::nurbs::NurbsSurface;
    /// use nalgebra::DMatrix;
    /// // A bilinear patch with one corner weighted 3: x(u, v) = (u, v) still, on a 2 × 2 grid.
    /// let x = DMatrix::from_row_slice(2, 2, &[0.0, 0.0, 1.0, 1.0]);
    /// let y = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 1.0]);
    /// let w = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 3.0]);
    /// let k = vec![0.0, 0.0, 1.0, 1.0];
    /// let s = NurbsSurface::new(1, 1, k.clone(), k, vec![x, y], w)?;
    /// let mut out = [0.0; 8];
    /// s.eval_grid_into(&[0.0, 1.0], &[0.0, 1.0], &mut out)?;
    /// assert_eq!(out, [0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 1.0, 1.0]);
    /// assert!(s.eval_grid_into(&[0.0], &[0.0], &mut out).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        let d = self.dim();
        let len = crate::grid::grid_len("NURBS surface grid", &[us.len(), vs.len(), d])?;
        crate::grid::check_len("NURBS surface grid buffer", len, out)?;
        crate::error::check_finite("NURBS surface grid parameters", us.iter().chain(vs))?;
        self.homogeneous.fill_grid(us, vs, out, true)
    }
}

impl<T: Scalar> Surface<T> for NurbsSurface<T> {
    fn dim(&self) -> usize {
        NurbsSurface::dim(self)
    }

    fn domain(&self) -> ((T, T), (T, T)) {
        NurbsSurface::domain(self)
    }

    /// [`NurbsSurface::eval`]: the end pieces continue outside the domain.
    fn eval(&self, u: T, v: T) -> DVector<T> {
        NurbsSurface::eval(self, u, v)
    }

    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        NurbsSurface::try_eval(self, u, v)
    }

    /// The grid by [`NurbsSurface::eval_grid_into`]'s algorithm (`O(p + q)` per point).
    fn eval_grid(&self, us: &[T], vs: &[T]) -> crate::grid::PointGrid<T> {
        self.homogeneous.grid_array(us, vs, self.dim(), true)
    }

    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        NurbsSurface::eval_grid_into(self, us, vs, out)
    }
}

/// The homogeneous net (weights last) through [`super::finish_homogeneous`]: weights scaled
/// into a safe range by a power of two, every number checked.
fn finish_net<T: Scalar>(what: &'static str, net: Vec<DMatrix<T>>) -> Result<Vec<DMatrix<T>>> {
    let (rows, cols) = net[0].shape();
    let dh = net.len();
    // One column per control point, the coordinates and the weight down it.
    let flat = DMatrix::from_fn(dh, rows * cols, |k, c| net[k][(c % rows, c / rows)].clone());
    let flat = super::finish_homogeneous(what, dh - 1, flat)?;
    Ok((0..dh)
        .map(|k| DMatrix::from_fn(rows, cols, |i, j| flat[(k, j * rows + i)].clone()))
        .collect())
}
