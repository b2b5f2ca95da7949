//! The bicubically blended (Hermite) Coons patch (thesis §4.3, twists §4.4).

use nalgebra::DVector;

use super::gregory::GregoryTwist;
use super::{push_gap, CoonsBoundary, Corner};
use crate::cost::{blended, polynomial_bits, Cost};
use crate::error::{Error, Result};
use crate::hermite::{hermite_basis, hermite_basis_derivative};
use crate::param::{usable_domain, Curve, CurveDeriv, OnUnitInterval, Surface};
use crate::scalar::Scalar;

/// The cubic Hermite basis in the thesis's order `[H0, H1, H2, H3](t)` (§4.2–4.3), the order of
/// the rows and columns of the matrix (4.5): [`hermite_basis`] `[f_1, f_2, f_3, f_4]` (the
/// crate's one Hermite basis, in the order of the Ferguson geometry) rearranged as
/// `[f_1, f_3, f_4, f_2]`.
fn thesis_order<T>([f1, f2, f3, f4]: [T; 4]) -> [T; 4] {
    [f1, f3, f4, f2]
}

/// The four cross-boundary derivative curves of a bicubically blended Coons patch (thesis
/// §4.3, Slika 10): `du0(v) = x_u(0, v)`, `du1(v) = x_u(1, v)`, `dv0(u) = x_v(u, 0)`,
/// `dv1(u) = x_v(u, 1)`.
#[derive(Debug, Clone)]
pub struct CrossDerivatives<D> {
    /// `x_u(0, v)`, the derivative across the edge `d1`.
    pub du0: D,
    /// `x_u(1, v)`, the derivative across the edge `d2`.
    pub du1: D,
    /// `x_v(u, 0)`, the derivative across the edge `c1`.
    pub dv0: D,
    /// `x_v(u, 1)`, the derivative across the edge `c2`.
    pub dv1: D,
}

/// The twist (mixed derivative `x_uv`) at the corners, the four middle entries of the matrix
/// (4.5), which the boundary data do not determine.
#[derive(Debug, Clone, PartialEq)]
pub enum Twist<T: Scalar = f64> {
    /// All four twists zero (the thesis's remark after (4.5)). The patch still interpolates the
    /// positions and, where the data's own twists are zero, the cross-boundary derivatives.
    Zero,
    /// Given twists `x_uv` at `P1..P4 = (0,0), (1,0), (0,1), (1,1)`.
    Given([DVector<T>; 4]),
    /// Gregory's square ([`GregoryTwist`]), built from the derivatives of the cross-boundary
    /// curves at their ends; interpolates incompatible twist data edge by edge.
    Gregory,
}

/// The twist entries once resolved.
#[derive(Debug, Clone, PartialEq)]
enum TwistData<T: Scalar> {
    Constant([DVector<T>; 4]),
    Gregory(GregoryTwist<T>),
}

/// A point of a bicubically blended Coons patch with the three parts of (4.5).
#[derive(Debug, Clone, PartialEq)]
pub struct BicubicCoonsPoint<T: Scalar = f64> {
    /// `x = h_c + h_d − h_cd`.
    pub x: DVector<T>,
    /// `h_c(u,v) = H0(u) x(0,v) + H1(u) x_u(0,v) + H2(u) x_u(1,v) + H3(u) x(1,v)`.
    pub hc: DVector<T>,
    /// `h_d(u,v) = H0(v) x(u,0) + H1(v) x_v(u,0) + H2(v) x_v(u,1) + H3(v) x(u,1)`.
    pub hd: DVector<T>,
    /// `h_cd(u,v) = [H0(u) … H3(u)] M [H0(v) … H3(v)]ᵀ`.
    pub hcd: DVector<T>,
}

/// A point with its first partial derivatives.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfacePartials<T: Scalar = f64> {
    /// `x(u, v)`.
    pub x: DVector<T>,
    /// `x_u(u, v)`.
    pub xu: DVector<T>,
    /// `x_v(u, v)`.
    pub xv: DVector<T>,
}

/// The bicubically blended Coons patch (thesis §4.3):
///
/// ```text
/// h_c(u,v)  = H0(u) x(0,v) + H1(u) x_u(0,v) + H2(u) x_u(1,v) + H3(u) x(1,v)
/// h_d(u,v)  = H0(v) x(u,0) + H1(v) x_v(u,0) + H2(v) x_v(u,1) + H3(v) x(u,1)
/// h_cd(u,v) = [H0(u) H1(u) H2(u) H3(u)] M [H0(v) H1(v) H2(v) H3(v)]ᵀ              (4.5)
/// x = h_c + h_d − h_cd
///
///     ⎡ x(0,0)    x_v(0,0)   x_v(0,1)   x(0,1)  ⎤
/// M = ⎢ x_u(0,0)  x_uv(0,0)  x_uv(0,1)  x_u(0,1)⎥
///     ⎢ x_u(1,0)  x_uv(1,0)  x_uv(1,1)  x_u(1,1)⎥
///     ⎣ x(1,0)    x_v(1,0)   x_v(1,1)   x(1,1)  ⎦
/// ```
///
/// with the Hermite basis `H0 … H3` of [`hermite_basis`](crate::hermite::hermite_basis).
///
/// **Domains.** The patch is over `[0, 1]²`. The boundary curves are reparametrised onto
/// `[0, 1]` as for every Coons patch ([`CoonsBoundary`]); so are the cross-boundary curves in
/// their own parameter (`x_u(0, ·)` runs along `d1`, so it may share `d1`'s domain). Their
/// *values* are derivatives with respect to the patch parameters `u, v ∈ [0, 1]` and are used
/// as given; the boundary tangents they are checked against, `c1'(0)` etc., are those of the
/// reparametrised boundary curves (`(b − a) c1'(a)` for `c1` on `[a, b]`), and Gregory's twist
/// uses the derivatives of the reparametrised cross-boundary curves likewise.
///
/// The positions in `M` are the corners of the
/// [`CoonsBoundary`]; `x_u(i, j)` is taken from the cross-boundary curve `x_u(i, ·)` at `v = j`
/// and `x_v(i, j)` from `x_v(·, j)` at `u = i`. With that choice the patch interpolates the four
/// boundary curves whatever the derivative data. It also interpolates the four cross-boundary
/// derivatives when the data are compatible: the boundary tangents at the corners agree with
/// the cross-boundary curves (`c1'(0) = x_u(0, 0)`, … — checked by [`BicubicCoonsPatch::new`];
/// every curve here knows its derivative, [`CurveDeriv`]), and the twist used at each corner is the one
/// the data imply along the edge in question. Constant twists ([`Twist::Zero`],
/// [`Twist::Given`]) can satisfy both edges through a corner only when
/// `∂/∂v x_u = ∂/∂u x_v` there; [`Twist::Gregory`] satisfies each edge separately.
///
/// ```
/// use cagd::coons::{BicubicCoonsPatch, CoonsBoundary, CrossDerivatives, Tolerance, Twist};
/// use cagd::{FnCurve, Surface};
/// use nalgebra::{dvector, DVector};
/// type F = fn(f64) -> DVector<f64>;
/// // The boundary data of the surface z = x·y on the unit square, with their derivatives.
/// let c: [(F, F); 4] = [
///     (|u| dvector![u, 0.0, 0.0], |_| dvector![1.0, 0.0, 0.0]),
///     (|u| dvector![u, 1.0, u], |_| dvector![1.0, 0.0, 1.0]),
///     (|v| dvector![0.0, v, 0.0], |_| dvector![0.0, 1.0, 0.0]),
///     (|v| dvector![1.0, v, v], |_| dvector![0.0, 1.0, 1.0]),
/// ];
/// let d: [(F, F); 4] = [
///     (|v| dvector![1.0, 0.0, v], |_| dvector![0.0, 0.0, 1.0]),
///     (|v| dvector![1.0, 0.0, v], |_| dvector![0.0, 0.0, 1.0]),
///     (|u| dvector![0.0, 1.0, u], |_| dvector![0.0, 0.0, 1.0]),
///     (|u| dvector![0.0, 1.0, u], |_| dvector![0.0, 0.0, 1.0]),
/// ];
/// let [c1, c2, d1, d2] = c.map(|(f, df)| FnCurve::with_derivative(3, f, df));
/// let [du0, du1, dv0, dv1] = d.map(|(f, df)| FnCurve::with_derivative(3, f, df));
/// let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default()).unwrap();
/// let one = dvector![0.0, 0.0, 1.0];
/// let twist = Twist::Given([one.clone(), one.clone(), one.clone(), one]);
/// let patch = BicubicCoonsPatch::new(boundary, CrossDerivatives { du0, du1, dv0, dv1 }, twist).unwrap();
/// assert_eq!(patch.eval(0.25, 0.5), dvector![0.25, 0.5, 0.125]);
/// ```
#[derive(Debug, Clone)]
pub struct BicubicCoonsPatch<C, D, T: Scalar = f64> {
    boundary: CoonsBoundary<C, T>,
    cross: CrossDerivatives<D>,
    /// The domains of `du0, du1, dv0, dv1`, each a finite interval `a < b`.
    cross_domains: [(T, T); 4],
    /// `x_u` at `P1..P4`.
    xu: [DVector<T>; 4],
    /// `x_v` at `P1..P4`.
    xv: [DVector<T>; 4],
    twist: TwistData<T>,
}

impl<T: Scalar, C: CurveDeriv<T>, D: CurveDeriv<T>> BicubicCoonsPatch<C, D, T> {
    /// The bicubically blended patch of a checked boundary, its cross-boundary derivatives
    /// and a twist choice.
    ///
    /// # Errors
    /// - [`Error::ShapeMismatch`]: a cross-boundary curve or given twist of the wrong dimension;
    /// - [`Error::UnusableDomain`]: a cross-boundary curve whose domain is not a finite
    ///   interval `a < b` (it is reparametrised onto `[0, 1]` as the boundary curves are);
    /// - [`Error::NonFinite`]: non-finite derivative data at a corner;
    /// - [`Error::CornerMismatch`]: a boundary curve's tangent at a corner disagrees with the
    ///   cross-boundary curve there (e.g. `c1'(0)` against `x_u(0,v)` at `v = 0`), beyond the
    ///   boundary's tolerance. Every curve knows its derivative ([`CurveDeriv`]), so every
    ///   corner is checked.
    pub fn new(
        boundary: CoonsBoundary<C, T>,
        cross: CrossDerivatives<D>,
        twist: Twist<T>,
    ) -> Result<Self> {
        let dim = boundary.dim();
        let check = |what: &'static str, p: &DVector<T>| -> Result<()> {
            if p.len() != dim {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!("points of dimension {dim}"),
                    found: format!("dimension {}", p.len()),
                });
            }
            crate::error::check_finite(what, p.iter())
        };
        for (name, c) in [
            ("x_u(0,v)", &cross.du0),
            ("x_u(1,v)", &cross.du1),
            ("x_v(u,0)", &cross.dv0),
            ("x_v(u,1)", &cross.dv1),
        ] {
            if c.dim() != dim {
                return Err(Error::ShapeMismatch {
                    what: "cross-boundary derivative curves",
                    expected: format!("curves of dimension {dim}"),
                    found: format!("{name} of dimension {}", c.dim()),
                });
            }
        }
        let cross_domains = [
            usable_domain("cross-boundary curve x_u(0,v)", &cross.du0)?,
            usable_domain("cross-boundary curve x_u(1,v)", &cross.du1)?,
            usable_domain("cross-boundary curve x_v(u,0)", &cross.dv0)?,
            usable_domain("cross-boundary curve x_v(u,1)", &cross.dv1)?,
        ];
        let [du0, du1, dv0, dv1] = unit_cross(&cross, &cross_domains);
        let (zero, one) = (T::zero(), T::one());
        let xu = [
            du0.eval(zero.clone()),
            du1.eval(zero.clone()),
            du0.eval(one.clone()),
            du1.eval(one.clone()),
        ];
        let xv = [
            dv0.eval(zero.clone()),
            dv0.eval(one.clone()),
            dv1.eval(zero.clone()),
            dv1.eval(one.clone()),
        ];
        for p in xu.iter().chain(xv.iter()) {
            check("cross-boundary derivative at a corner", p)?;
        }

        // Boundary tangents against the cross-boundary curves, at all four corners.
        let [c1, c2, d1, d2] = boundary.unit_curves();
        let tolerance = boundary.tolerance();
        type Pair<'a, T> = (
            Corner,
            &'static str,
            DVector<T>,
            &'static str,
            &'a DVector<T>,
        );
        let tangents: [Pair<'_, T>; 8] = [
            (
                Corner::U0V0,
                "c1'(0)",
                c1.eval_derivative(zero.clone()),
                "x_u(0,v) at v=0",
                &xu[0],
            ),
            (
                Corner::U1V0,
                "c1'(1)",
                c1.eval_derivative(one.clone()),
                "x_u(1,v) at v=0",
                &xu[1],
            ),
            (
                Corner::U0V1,
                "c2'(0)",
                c2.eval_derivative(zero.clone()),
                "x_u(0,v) at v=1",
                &xu[2],
            ),
            (
                Corner::U1V1,
                "c2'(1)",
                c2.eval_derivative(one.clone()),
                "x_u(1,v) at v=1",
                &xu[3],
            ),
            (
                Corner::U0V0,
                "d1'(0)",
                d1.eval_derivative(zero.clone()),
                "x_v(u,0) at u=0",
                &xv[0],
            ),
            (
                Corner::U1V0,
                "d2'(0)",
                d2.eval_derivative(zero.clone()),
                "x_v(u,0) at u=1",
                &xv[1],
            ),
            (
                Corner::U0V1,
                "d1'(1)",
                d1.eval_derivative(one.clone()),
                "x_v(u,1) at u=0",
                &xv[2],
            ),
            (
                Corner::U1V1,
                "d2'(1)",
                d2.eval_derivative(one.clone()),
                "x_v(u,1) at u=1",
                &xv[3],
            ),
        ];
        let mut gaps = Vec::new();
        for (corner, first, tangent, second, cross_value) in tangents {
            check("boundary tangent at a corner", &tangent)?;
            push_gap(
                &mut gaps,
                &tolerance,
                corner,
                first,
                second,
                &tangent,
                cross_value,
            );
        }
        if !gaps.is_empty() {
            return Err(Error::CornerMismatch { gaps, tolerance });
        }

        let twist = match twist {
            Twist::Zero => TwistData::Constant(std::array::from_fn(|_| {
                DVector::from_element(dim, T::zero())
            })),
            Twist::Given(t) => {
                for p in &t {
                    check("given twists", p)?;
                }
                TwistData::Constant(t)
            }
            Twist::Gregory => {
                let deriv =
                    |c: &OnUnitInterval<&D, T>, what: &'static str, t: T| -> Result<DVector<T>> {
                        let d = c.eval_derivative(t);
                        check(what, &d)?;
                        Ok(d)
                    };
                // a = ∂/∂v x_u(i, v) at v = j; b = ∂/∂u x_v(u, j) at u = i.
                let along_v = [
                    deriv(&du0, "x_u(0,v)", zero.clone())?,
                    deriv(&du1, "x_u(1,v)", zero.clone())?,
                    deriv(&du0, "x_u(0,v)", one.clone())?,
                    deriv(&du1, "x_u(1,v)", one.clone())?,
                ];
                let along_u = [
                    deriv(&dv0, "x_v(u,0)", zero.clone())?,
                    deriv(&dv0, "x_v(u,0)", one.clone())?,
                    deriv(&dv1, "x_v(u,1)", zero.clone())?,
                    deriv(&dv1, "x_v(u,1)", one)?,
                ];
                TwistData::Gregory(GregoryTwist::new(along_v, along_u)?)
            }
        };
        Ok(BicubicCoonsPatch {
            boundary,
            cross,
            cross_domains,
            xu,
            xv,
            twist,
        })
    }

    /// The twist entries of `M` at `(u, v)`, order `P1..P4`.
    fn twists(&self, u: &T, v: &T) -> [DVector<T>; 4] {
        match &self.twist {
            TwistData::Constant(t) => t.clone(),
            TwistData::Gregory(g) => Corner::ALL.map(|c| g.eval(c, u, v)),
        }
    }

    /// `[H(u)ᵀ M H(v)]` for one coordinate `k`, with twist entries `tw`.
    fn corner_blend(&self, hu: &[T; 4], hv: &[T; 4], tw: &[DVector<T>; 4], k: usize) -> T {
        let p = self.boundary.corners();
        let (xu, xv) = (&self.xu, &self.xv);
        // Rows of M as (P1..P4 indices): row i of M, column j of M.
        let m = [
            [&p[0][k], &xv[0][k], &xv[2][k], &p[2][k]],
            [&xu[0][k], &tw[0][k], &tw[2][k], &xu[2][k]],
            [&xu[1][k], &tw[1][k], &tw[3][k], &xu[3][k]],
            [&p[1][k], &xv[1][k], &xv[3][k], &p[3][k]],
        ];
        let mut sum = T::zero();
        for (row, h) in m.iter().zip(hu.iter()) {
            let mut r = T::zero();
            for (e, g) in row.iter().zip(hv.iter()) {
                r = r + (*e).clone() * g.clone();
            }
            sum = sum + h.clone() * r;
        }
        sum
    }

    /// `x(u, v)` from the curve values at `u` (`[c1, dv0, dv1, c2]`) and at `v`
    /// (`[d1, du0, du1, d2]`).
    fn combine(&self, u: &T, v: &T, at_u: &[DVector<T>; 4], at_v: &[DVector<T>; 4]) -> DVector<T> {
        let hu = thesis_order(hermite_basis(u.clone()));
        let hv = thesis_order(hermite_basis(v.clone()));
        let tw = self.twists(u, v);
        DVector::from_fn(self.boundary.dim(), |k, _| {
            let hc = dot(&hu, at_v, k);
            let hd = dot(&hv, at_u, k);
            hc + hd - self.corner_blend(&hu, &hv, &tw, k)
        })
    }

    /// The three parts of (4.5) at `(u, v)`: `h_c` (the curves `x(0,v)`, `x_u(0,v)`,
    /// `x_u(1,v)`, `x(1,v)` blended along `u`), `h_d` (the curves in `u` blended along `v`),
    /// `h_cd` (the corner data `M`) and `x = h_c + h_d − h_cd`, the point [`Surface::eval`]
    /// gives (the same operations).
    pub fn eval_parts(&self, u: T, v: T) -> BicubicCoonsPoint<T> {
        let (at_u, at_v) = (self.values_at_u(&u), self.values_at_v(&v));
        let (hu, hv) = (
            thesis_order(hermite_basis(u.clone())),
            thesis_order(hermite_basis(v.clone())),
        );
        let tw = self.twists(&u, &v);
        let dim = self.boundary.dim();
        let hc = DVector::from_fn(dim, |k, _| dot(&hu, &at_v, k));
        let hd = DVector::from_fn(dim, |k, _| dot(&hv, &at_u, k));
        let hcd = DVector::from_fn(dim, |k, _| self.corner_blend(&hu, &hv, &tw, k));
        let x = DVector::from_fn(dim, |k, _| hc[k].clone() + hd[k].clone() - hcd[k].clone());
        BicubicCoonsPoint { x, hc, hd, hcd }
    }

    /// The curve values `[c1(u), x_v(u,0), x_v(u,1), c2(u)]` and `[d1(v), x_u(0,v), x_u(1,v), d2(v)]`.
    fn values_at_u(&self, u: &T) -> [DVector<T>; 4] {
        let [c1, c2, _, _] = self.boundary.unit_curves();
        let [_, _, dv0, dv1] = self.unit_cross();
        [
            c1.eval(u.clone()),
            dv0.eval(u.clone()),
            dv1.eval(u.clone()),
            c2.eval(u.clone()),
        ]
    }

    fn values_at_v(&self, v: &T) -> [DVector<T>; 4] {
        let [_, _, d1, d2] = self.boundary.unit_curves();
        let [du0, du1, _, _] = self.unit_cross();
        [
            d1.eval(v.clone()),
            du0.eval(v.clone()),
            du1.eval(v.clone()),
            d2.eval(v.clone()),
        ]
    }

    /// The cross-boundary curves `[x_u(0,·), x_u(1,·), x_v(·,0), x_v(·,1)]` reparametrised onto
    /// `[0, 1]`.
    fn unit_cross(&self) -> [OnUnitInterval<&D, T>; 4] {
        unit_cross(&self.cross, &self.cross_domains)
    }

    /// `x(u, v)` with its first partial derivatives `x_u`, `x_v`, in closed form (the Gregory
    /// twist differentiated as a rational function).
    ///
    /// # Errors
    /// [`Error::NonFinite`] or [`Error::ParameterOutOfRange`] for a parameter outside
    /// `[0, 1]`; [`Error::ShapeMismatch`] or [`Error::Overflow`] for a curve's derivative of
    /// another dimension or not finite.
    pub fn eval_partials(&self, u: T, v: T) -> Result<SurfacePartials<T>> {
        let [c1, c2, d1, d2] = self.boundary.unit_curves();
        let [du0, du1, dv0, dv1] = self.unit_cross();
        let unit = (T::zero(), T::one());
        crate::param::check_parameter("bicubic Coons patch parameter u", &u, &unit)?;
        crate::param::check_parameter("bicubic Coons patch parameter v", &v, &unit)?;
        let dim = self.boundary.dim();
        let deriv = |c: &dyn Fn(T) -> DVector<T>, what: &'static str, t: &T| {
            crate::checked::point(what, dim, c(t.clone()))
        };
        let at_u = self.values_at_u(&u);
        let at_v = self.values_at_v(&v);
        let at_u_d = [
            deriv(&|t| c1.eval_derivative(t), "c1", &u)?,
            deriv(&|t| dv0.eval_derivative(t), "x_v(u,0)", &u)?,
            deriv(&|t| dv1.eval_derivative(t), "x_v(u,1)", &u)?,
            deriv(&|t| c2.eval_derivative(t), "c2", &u)?,
        ];
        let at_v_d = [
            deriv(&|t| d1.eval_derivative(t), "d1", &v)?,
            deriv(&|t| du0.eval_derivative(t), "x_u(0,v)", &v)?,
            deriv(&|t| du1.eval_derivative(t), "x_u(1,v)", &v)?,
            deriv(&|t| d2.eval_derivative(t), "d2", &v)?,
        ];
        let hu = thesis_order(hermite_basis(u.clone()));
        let hv = thesis_order(hermite_basis(v.clone()));
        let hu_d = thesis_order(hermite_basis_derivative(u.clone()));
        let hv_d = thesis_order(hermite_basis_derivative(v.clone()));
        let tw = self.twists(&u, &v);
        let (tw_u, tw_v): ([DVector<T>; 4], [DVector<T>; 4]) = match &self.twist {
            TwistData::Constant(_) => {
                let z = || {
                    std::array::from_fn(|_| DVector::from_element(self.boundary.dim(), T::zero()))
                };
                (z(), z())
            }
            TwistData::Gregory(g) => {
                let d = Corner::ALL.map(|c| g.derivatives(c, &u, &v));
                (
                    std::array::from_fn(|k| d[k].0.clone()),
                    std::array::from_fn(|k| d[k].1.clone()),
                )
            }
        };
        let x = self.combine(&u, &v, &at_u, &at_v);
        let xu = DVector::from_fn(dim, |k, _| {
            dot(&hu_d, &at_v, k) + dot(&hv, &at_u_d, k)
                - self.corner_blend(&hu_d, &hv, &tw, k)
                - self.corner_blend_twist_only(&hu, &hv, &tw_u, k)
        });
        let xv = DVector::from_fn(dim, |k, _| {
            dot(&hu, &at_v_d, k) + dot(&hv_d, &at_u, k)
                - self.corner_blend(&hu, &hv_d, &tw, k)
                - self.corner_blend_twist_only(&hu, &hv, &tw_v, k)
        });
        let x = crate::checked::point("bicubic Coons patch point", dim, x)?;
        let xu = crate::checked::point("bicubic Coons patch derivative x_u", dim, xu)?;
        let xv = crate::checked::point("bicubic Coons patch derivative x_v", dim, xv)?;
        Ok(SurfacePartials { x, xu, xv })
    }

    /// The twist entries alone of `H(u)ᵀ M H(v)` (for the derivative of a variable twist).
    fn corner_blend_twist_only(
        &self,
        hu: &[T; 4],
        hv: &[T; 4],
        tw: &[DVector<T>; 4],
        k: usize,
    ) -> T {
        hu[1].clone() * (hv[1].clone() * tw[0][k].clone() + hv[2].clone() * tw[2][k].clone())
            + hu[2].clone() * (hv[1].clone() * tw[1][k].clone() + hv[2].clone() * tw[3][k].clone())
    }
}

impl<T: Scalar, C, D> BicubicCoonsPatch<C, D, T> {
    /// The checked boundary curves and corners.
    pub fn boundary(&self) -> &CoonsBoundary<C, T> {
        &self.boundary
    }

    /// The cross-boundary derivative curves.
    pub fn cross_derivatives(&self) -> &CrossDerivatives<D> {
        &self.cross
    }

    /// The Gregory twist, when [`Twist::Gregory`] was chosen.
    pub fn gregory_twist(&self) -> Option<&GregoryTwist<T>> {
        match &self.twist {
            TwistData::Gregory(g) => Some(g),
            TwistData::Constant(_) => None,
        }
    }
}

/// The cross-boundary curves `[du0, du1, dv0, dv1]` on their checked domains, reparametrised
/// onto `[0, 1]`.
fn unit_cross<'a, T: Scalar, D>(
    cross: &'a CrossDerivatives<D>,
    domains: &[(T, T); 4],
) -> [OnUnitInterval<&'a D, T>; 4] {
    let curves = [&cross.du0, &cross.du1, &cross.dv0, &cross.dv1];
    [0, 1, 2, 3].map(|k| OnUnitInterval::from_checked(curves[k], domains[k].clone()))
}

/// `Σ_i h[i] · values[i][k]`.
fn dot<T: Scalar>(h: &[T; 4], values: &[DVector<T>; 4], k: usize) -> T {
    h.iter()
        .zip(values.iter())
        .fold(T::zero(), |acc, (h, p)| acc + h.clone() * p[k].clone())
}

impl<T: Scalar, C: CurveDeriv<T>, D: CurveDeriv<T>> Surface<T> for BicubicCoonsPatch<C, D, T> {
    fn dim(&self) -> usize {
        self.boundary.dim()
    }

    /// `[0, 1]²`.
    fn domain(&self) -> ((T, T), (T, T)) {
        ((T::zero(), T::one()), (T::zero(), T::one()))
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        let at_u = self.values_at_u(&u);
        let at_v = self.values_at_v(&v);
        self.combine(&u, &v, &at_u, &at_v)
    }

    /// [`eval`](Surface::eval) on `[0, 1]²`, the eight curves through their own `try_eval`
    /// (their work bounded, their points checked), the point checked for overflow.
    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let unit = (T::zero(), T::one());
        crate::param::check_parameter("bicubic Coons patch parameter u", &u, &unit)?;
        crate::param::check_parameter("bicubic Coons patch parameter v", &v, &unit)?;
        let dim = self.boundary.dim();
        let checked = |c: &dyn Curve<T>, what: &'static str, t: &T| -> Result<DVector<T>> {
            c.try_eval(t.clone())
                .and_then(|p| crate::checked::point(what, dim, p))
                .map_err(|e| crate::checked::named(what, e))
        };
        let [c1, c2, d1, d2] = self.boundary.unit_curves();
        let [du0, du1, dv0, dv1] = self.unit_cross();
        let at_u = [
            checked(&c1, "Coons boundary curve c1", &u)?,
            checked(&dv0, "cross-boundary curve x_v(u,0)", &u)?,
            checked(&dv1, "cross-boundary curve x_v(u,1)", &u)?,
            checked(&c2, "Coons boundary curve c2", &u)?,
        ];
        let at_v = [
            checked(&d1, "Coons boundary curve d1", &v)?,
            checked(&du0, "cross-boundary curve x_u(0,v)", &v)?,
            checked(&du1, "cross-boundary curve x_u(1,v)", &v)?,
            checked(&d2, "Coons boundary curve d2", &v)?,
        ];
        crate::checked::point(
            "bicubic Coons patch point",
            dim,
            self.combine(&u, &v, &at_u, &at_v),
        )
    }

    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        crate::checked::eval_grid_into(self, "bicubic Coons patch grid", us, vs, out)
    }

    /// The patch on the grid `us × vs`, shape `(us.len(), vs.len(), d)`; each of the eight
    /// curves is evaluated once per grid line.
    fn eval_grid(&self, us: &[T], vs: &[T]) -> crate::grid::PointGrid<T> {
        let at_u: Vec<_> = us.iter().map(|u| self.values_at_u(u)).collect();
        let at_v: Vec<_> = vs.iter().map(|v| self.values_at_v(v)).collect();
        let dim = self.boundary.dim();
        let mut grid = crate::grid::PointGrid::from_elem((us.len(), vs.len(), dim), T::zero());
        for (i, u) in us.iter().enumerate() {
            for (j, v) in vs.iter().enumerate() {
                let x = self.combine(u, v, &at_u[i], &at_v[j]);
                for k in 0..dim {
                    grid[[i, j, k]] = x[k].clone();
                }
            }
        }
        grid
    }
}

/// The cost of one point of a bicubically blended Coons patch in `d` coordinates: the eight
/// curves at their parameters (`curves`, the cost of each: the four boundary curves and the
/// four cross-boundary derivatives) and about 64 operations per coordinate for the blend, on
/// numbers as large as the curves' values grown by the cubic Hermite functions of `u` and `v`
/// ([`polynomial_bits`]`(3, u_bits, 0) + polynomial_bits(3, v_bits, 0)`;
/// [`blended`](crate::cost::blended)).
///
/// ```
/// use cagd::coons::bicubic_point_cost;
/// use cagd::cost::Cost;
/// assert_eq!(bicubic_point_cost([Cost::new(2, 10); 8], 3, 1, 1), Cost::new(16 + 192, 10 + 12));
/// ```
pub fn bicubic_point_cost(
    curves: impl IntoIterator<Item = Cost>,
    d: usize,
    u_bits: u128,
    v_bits: u128,
) -> Cost {
    blended(
        curves,
        64 * d as u128,
        polynomial_bits(3, u_bits, 0).saturating_add(polynomial_bits(3, v_bits, 0)),
    )
}

#[cfg(test)]
mod cost_tests {
    use super::*;

    #[test]
    fn the_hermite_blend_grows_by_cubics_in_u_and_v() {
        let c = bicubic_point_cost([Cost::new(1, 0); 8], 1, 0, 0);
        assert_eq!(c, Cost::new(8 + 64, 6));
        assert_eq!(
            bicubic_point_cost([Cost::new(1, 100); 8], 1, 10, 0).bits(),
            100 + 33 + 3
        );
    }
}
