//! The Hermite bicubic (Ferguson) patch.

use nalgebra::{DMatrix, DVector};

use super::matrix_patch::CubicMatrixPatch;
use crate::conversion::CubicForm;
use crate::coons::CoonsBoundary;
use crate::cost::{polynomial_bits, Cost};
use crate::error::{Error, Result};
use crate::param::{Curve, CurveDeriv, Surface};
use crate::scalar::Scalar;

/// Corner data indexed `[i][j]` for the corner `(u, v) = (i, j)`.
pub type Corners<T> = [[DVector<T>; 2]; 2];

/// The Hermite bicubic (Ferguson) patch of the lecture notes ("Hermitova plocha"): given at the four
/// corners `(i, j) ∈ {0, 1}²` the points `x_{ij}`, the tangents `∂x/∂u`, `∂x/∂v` and the twist
/// vectors `∂²x/∂u∂v`, it is
/// `x(u, v) = Σ_a Σ_b f_a(u) f_b(v) G[a, b]` with the Hermite basis `f` and
///
/// ```text
///     [ x_00    x_01    x_v00    x_v01  ]
/// G = [ x_10    x_11    x_v10    x_v11  ]     (rows: x(0,·), x(1,·), x_u(0,·), x_u(1,·))
///     [ x_u00   x_u01   x_uv00   x_uv01 ]
///     [ x_u10   x_u11   x_uv10   x_uv11 ]
/// ```
///
/// The lecture notes write `x(u, v) = vᵀ M_Hᵀ X_H M_H u` with `X_H = [A B; C D]`, `A` the corner
/// points, `B` the `u`-tangents, `C` the `v`-tangents, `D` the twists. Its `X_H` is `Gᵀ`; but
/// inside the blocks it writes `A = [x_00 x_01; x_10 x_11]` although, with its own definition
/// `x_10 = x(1, 0)`, the entry `(0, 1)` of `Gᵀ` is `x_10` — the labels inside the blocks are
/// transposed. The twists only shape the interior ("bulge" of the corners); with zero twists
/// the patch is the notes' "F-patch".
///
/// ```
/// use cagd::surfaces::FergusonPatch;
/// use cagd::Surface;
/// use nalgebra::DVector;
/// let v = |x: f64, y: f64, z: f64| DVector::from_vec(vec![x, y, z]);
/// let x = [[v(0., 0., 0.), v(0., 1., 0.)], [v(1., 0., 0.), v(1., 1., 1.)]];
/// let du = [[v(1., 0., 0.), v(1., 0., 1.)], [v(1., 0., 0.), v(1., 0., 1.)]];
/// let dv = [[v(0., 1., 0.), v(0., 1., 0.)], [v(0., 1., 1.), v(0., 1., 1.)]];
/// let tw = [[v(0., 0., 1.), v(0., 0., 1.)], [v(0., 0., 1.), v(0., 0., 1.)]];
/// // This is the hyperbolic paraboloid z = u·v, exactly.
/// let p = FergusonPatch::new(&x, &du, &dv, &tw)?;
/// assert_eq!(p.eval(0.5, 0.25).as_slice(), &[0.5, 0.25, 0.125]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FergusonPatch<T: Scalar = f64> {
    patch: CubicMatrixPatch<T>,
}

impl<T: Scalar> FergusonPatch<T> {
    /// The patch from corner points, `u`-tangents, `v`-tangents and twists, each indexed
    /// `[i][j]` for the corner `(u, v) = (i, j)`.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for vectors of different (or zero) dimensions,
    /// [`Error::NonFinite`].
    pub fn new(
        points: &Corners<T>,
        du: &Corners<T>,
        dv: &Corners<T>,
        twist: &Corners<T>,
    ) -> Result<Self> {
        let d = points[0][0].len();
        let all = [points, du, dv, twist];
        if d == 0 || all.iter().any(|c| c.iter().flatten().any(|x| x.len() != d)) {
            return Err(Error::ShapeMismatch {
                what: "Ferguson patch",
                expected: "16 corner vectors of the same positive dimension".into(),
                found: "vectors of different dimensions".into(),
            });
        }
        let coords = (0..d)
            .map(|k| {
                DMatrix::from_fn(4, 4, |a, b| {
                    let (sa, ia) = (a / 2, a % 2);
                    let (sb, jb) = (b / 2, b % 2);
                    let src = match (sa, sb) {
                        (0, 0) => points,
                        (1, 0) => du,
                        (0, 1) => dv,
                        _ => twist,
                    };
                    src[ia][jb][k].clone()
                })
            })
            .collect();
        Ok(FergusonPatch {
            patch: CubicMatrixPatch::new(CubicForm::Hermite, coords)?,
        })
    }

    /// The patch whose corner data are those of four boundary curves (checked to meet at the
    /// corners, [`CoonsBoundary`]): the corner points `x_ij`, the `u`-tangents from the curves
    /// in `u`, `x_u(i, 0) = c1'(i)`, `x_u(i, 1) = c2'(i)`, the `v`-tangents from the curves in
    /// `v`, `x_v(0, j) = d1'(j)`, `x_v(1, j) = d2'(j)` — each curve reparametrised onto
    /// `[0, 1]` as the boundary uses it —, and the given `twist` vectors. Its edges are the
    /// Hermite cubics of those end data: the curves themselves when they are cubics (of degree
    /// at most 3, in a parameter affine in `u` or `v`).
    ///
    /// # Errors
    /// As [`FergusonPatch::new`]: twists of another dimension, non-finite tangents.
    ///
    /// ```
    /// use cagd::coons::{CoonsBoundary, Tolerance};
    /// use cagd::surfaces::FergusonPatch;
    /// use cagd::{BezierCurve, Surface};
    /// use nalgebra::{dvector, DVector};
    /// // The edges of z = u·v on the unit square, as Bézier lines.
    /// let line = |p: [f64; 3], q: [f64; 3]| BezierCurve::from_points(&[p, q]).unwrap();
    /// let boundary = CoonsBoundary::new(
    ///     line([0., 0., 0.], [1., 0., 0.]), line([0., 1., 0.], [1., 1., 1.]),
    ///     line([0., 0., 0.], [0., 1., 0.]), line([1., 0., 0.], [1., 1., 1.]),
    ///     Tolerance::default(),
    /// )?;
    /// let one = || dvector![0.0, 0.0, 1.0];
    /// let p = FergusonPatch::from_boundary(&boundary, &[[one(), one()], [one(), one()]])?;
    /// assert_eq!(p.eval(0.5, 0.25).as_slice(), &[0.5, 0.25, 0.125]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn from_boundary<C: CurveDeriv<T>>(
        boundary: &CoonsBoundary<C, T>,
        twist: &Corners<T>,
    ) -> Result<Self> {
        let [c1, c2, d1, d2] = boundary.unit_curves();
        let p = boundary.corners();
        let at = |i: usize| if i == 0 { T::zero() } else { T::one() };
        let points: Corners<T> =
            std::array::from_fn(|i| std::array::from_fn(|j| p[i + 2 * j].clone()));
        let du: Corners<T> =
            std::array::from_fn(|i| [c1.eval_derivative(at(i)), c2.eval_derivative(at(i))]);
        let dv: Corners<T> = [
            [d1.eval_derivative(at(0)), d1.eval_derivative(at(1))],
            [d2.eval_derivative(at(0)), d2.eval_derivative(at(1))],
        ];
        for tangent in du.iter().chain(dv.iter()).flatten() {
            crate::error::check_finite("boundary tangent at a corner", tangent.iter())?;
            if tangent.len() != c1.dim() {
                return Err(Error::ShapeMismatch {
                    what: "boundary tangent at a corner",
                    expected: format!("vectors of dimension {}", c1.dim()),
                    found: format!("dimension {}", tangent.len()),
                });
            }
        }
        Self::new(&points, &du, &dv, twist)
    }

    /// The geometry matrices `G` (one `4 × 4` per coordinate, layout in the type's docs).
    pub fn geometry(&self) -> &[DMatrix<T>] {
        self.patch.coordinates()
    }

    /// The same patch as a [`CubicMatrixPatch`] in Hermite form.
    pub fn as_matrix_patch(&self) -> &CubicMatrixPatch<T> {
        &self.patch
    }
}

impl<T: Scalar> Surface<T> for FergusonPatch<T> {
    fn dim(&self) -> usize {
        self.patch.dim()
    }
    /// `[0, 1]²`.
    fn domain(&self) -> ((T, T), (T, T)) {
        self.patch.domain()
    }
    fn eval(&self, u: T, v: T) -> DVector<T> {
        self.patch.eval(u, v)
    }
}

/// The cost of one point of a Ferguson patch in `d` coordinates, `x(u, v) = f(u)ᵀ G f(v)`:
/// the two cubic Hermite bases (about 40 operations) and the `4 × 4` products of each
/// coordinate (32), on numbers as large as the geometry data (`data_bits`) grown by the
/// cubics in `u` and `v` ([`polynomial_bits`]).
///
/// ```
/// use cagd::surfaces::ferguson_point_cost;
/// let c = ferguson_point_cost(3, 2, 4, 10);
/// assert_eq!((c.ops(), c.bits()), (40 + 96, 3 * 3 + 3 * 5 + 10));
/// ```
pub fn ferguson_point_cost(d: usize, u_bits: u128, v_bits: u128, data_bits: u128) -> Cost {
    Cost::new(
        40 + 32 * d as u128,
        polynomial_bits(3, u_bits, 0).saturating_add(polynomial_bits(3, v_bits, data_bits)),
    )
}
