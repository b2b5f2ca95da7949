//! The bicubically blended (Hermite) Coons patch (thesis §4.3, twists §4.4).

use nalgebra::DVector;

use super::gregory::GregoryTwist;
use super::{push_gap, CoonsBoundary, Corner};
use crate::error::{Error, Result};
use crate::param::{Curve, Surface};
use crate::scalar::Scalar;

/// The cubic Hermite basis `[H0³, H1³, H2³, H3³](t)` of thesis §4.2–4.3, from the cubic
/// Bernstein polynomials `B_i³`:
///
/// ```text
/// H0 = B0 + B1 = (1−t)²(1+2t)      H1 =  B1/3 = t(1−t)²
/// H2 = −B2/3   = −t²(1−t)          H3 = B2 + B3 = t²(3−2t)
/// ```
///
/// Checked against the Hermite conditions (the thesis states them only partly): `H0`, `H3`
/// interpolate the values (`H0(0) = 1`, `H0(1) = 0`, `H3 = 1 − H0`) and have zero derivative at
/// both ends; `H1`, `H2` vanish at both ends and carry the derivatives: `H1'(0) = 1`,
/// `H1'(1) = 0`, `H2'(0) = 0`, `H2'(1) = 1`. So `H1 = B1/3` and `H2 = −B2/3` are right, signs
/// included (the minus makes `H2'(1) = +1`).
///
/// ```
/// use cagd::coons::{hermite_cubic, hermite_cubic_derivative};
/// assert_eq!(hermite_cubic(&0.5), [0.5, 0.125, -0.125, 0.5]);
/// assert_eq!(hermite_cubic_derivative(&0.0), [0.0, 1.0, 0.0, 0.0]);
/// assert_eq!(hermite_cubic_derivative(&1.0), [0.0, 0.0, 1.0, 0.0]);
/// ```
pub fn hermite_cubic<T: Scalar>(t: &T) -> [T; 4] {
    let s = T::one() - t.clone();
    let three = T::from_usize(3);
    let b0 = s.clone() * s.clone() * s.clone();
    let ts2 = t.clone() * s.clone() * s.clone();
    let t2s = t.clone() * t.clone() * s;
    let b3 = t.clone() * t.clone() * t.clone();
    [
        b0 + three.clone() * ts2.clone(),
        ts2,
        -t2s.clone(),
        three * t2s + b3,
    ]
}

/// The derivatives `[H0', H1', H2', H3'](t)` of [`hermite_cubic`]:
/// `H0' = −6t(1−t)`, `H1' = (1−t)(1−3t)`, `H2' = t(3t−2)`, `H3' = 6t(1−t)`.
pub fn hermite_cubic_derivative<T: Scalar>(t: &T) -> [T; 4] {
    let s = T::one() - t.clone();
    let three = T::from_usize(3);
    let six_ts = T::from_usize(6) * t.clone() * s.clone();
    [
        -six_ts.clone(),
        s * (T::one() - three.clone() * t.clone()),
        t.clone() * (three * t.clone() - T::from_usize(2)),
        six_ts,
    ]
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
/// with the Hermite basis of [`hermite_cubic`]. The positions in `M` are the corners of the
/// [`CoonsBoundary`]; `x_u(i, j)` is taken from the cross-boundary curve `x_u(i, ·)` at `v = j`
/// and `x_v(i, j)` from `x_v(·, j)` at `u = i`. With that choice the patch interpolates the four
/// boundary curves whatever the derivative data. It also interpolates the four cross-boundary
/// derivatives when the data are compatible: the boundary tangents at the corners agree with
/// the cross-boundary curves (`c1'(0) = x_u(0, 0)`, … — checked by [`BicubicCoonsPatch::new`]
/// where the boundary curves provide derivatives), and the twist used at each corner is the one
/// the data imply along the edge in question. Constant twists ([`Twist::Zero`],
/// [`Twist::Given`]) can satisfy both edges through a corner only when
/// `∂/∂v x_u = ∂/∂u x_v` there; [`Twist::Gregory`] satisfies each edge separately.
///
/// ```
/// use cagd::coons::{BicubicCoonsPatch, CoonsBoundary, CrossDerivatives, Tolerance, Twist};
/// use cagd::{FnCurve, Surface};
/// use nalgebra::{dvector, DVector};
/// type F = fn(f64) -> DVector<f64>;
/// // The boundary data of the surface z = x·y on the unit square.
/// let c: [F; 4] = [|u| dvector![u, 0.0, 0.0], |u| dvector![u, 1.0, u], |v| dvector![0.0, v, 0.0], |v| dvector![1.0, v, v]];
/// let d: [F; 4] = [|v| dvector![1.0, 0.0, v], |v| dvector![1.0, 0.0, v], |u| dvector![0.0, 1.0, u], |u| dvector![0.0, 1.0, u]];
/// let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(3, f));
/// let [du0, du1, dv0, dv1] = d.map(|f| FnCurve::new(3, f));
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
    /// `x_u` at `P1..P4`.
    xu: [DVector<T>; 4],
    /// `x_v` at `P1..P4`.
    xv: [DVector<T>; 4],
    twist: TwistData<T>,
}

impl<T: Scalar, C: Curve<T>, D: Curve<T>> BicubicCoonsPatch<C, D, T> {
    /// The bicubically blended patch of a checked boundary, its cross-boundary derivatives
    /// and a twist choice.
    ///
    /// # Errors
    /// - [`Error::ShapeMismatch`]: a cross-boundary curve or given twist of the wrong dimension;
    /// - [`Error::NonFinite`]: non-finite derivative data at a corner;
    /// - [`Error::CornerMismatch`]: where a boundary curve provides its derivative, its tangent
    ///   at a corner disagrees with the cross-boundary curve there (e.g. `c1'(0)` against
    ///   `x_u(0,v)` at `v = 0`), beyond the boundary's tolerance;
    /// - [`Error::MissingDerivative`]: [`Twist::Gregory`] with a cross-boundary curve that
    ///   provides no derivative.
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
        let (zero, one) = (T::zero(), T::one());
        let xu = [
            cross.du0.eval(zero.clone()),
            cross.du1.eval(zero.clone()),
            cross.du0.eval(one.clone()),
            cross.du1.eval(one.clone()),
        ];
        let xv = [
            cross.dv0.eval(zero.clone()),
            cross.dv0.eval(one.clone()),
            cross.dv1.eval(zero.clone()),
            cross.dv1.eval(one.clone()),
        ];
        for p in xu.iter().chain(xv.iter()) {
            check("cross-boundary derivative at a corner", p)?;
        }

        // Boundary tangents against the cross-boundary curves, where the tangents are known.
        let (c1, c2, d1, d2) = boundary.curves();
        let tolerance = boundary.tolerance();
        type Pair<'a, T> = (
            Corner,
            &'static str,
            Option<DVector<T>>,
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
            if let Some(t) = tangent {
                check("boundary tangent at a corner", &t)?;
                push_gap(
                    &mut gaps,
                    &tolerance,
                    corner,
                    first,
                    second,
                    &t,
                    cross_value,
                );
            }
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
                let deriv = |c: &D, what: &'static str, t: T| -> Result<DVector<T>> {
                    let d = c
                        .eval_derivative(t)
                        .ok_or(Error::MissingDerivative { what })?;
                    check(what, &d)?;
                    Ok(d)
                };
                // a = ∂/∂v x_u(i, v) at v = j; b = ∂/∂u x_v(u, j) at u = i.
                let along_v = [
                    deriv(&cross.du0, "x_u(0,v)", zero.clone())?,
                    deriv(&cross.du1, "x_u(1,v)", zero.clone())?,
                    deriv(&cross.du0, "x_u(0,v)", one.clone())?,
                    deriv(&cross.du1, "x_u(1,v)", one.clone())?,
                ];
                let along_u = [
                    deriv(&cross.dv0, "x_v(u,0)", zero.clone())?,
                    deriv(&cross.dv0, "x_v(u,0)", one.clone())?,
                    deriv(&cross.dv1, "x_v(u,1)", zero.clone())?,
                    deriv(&cross.dv1, "x_v(u,1)", one)?,
                ];
                TwistData::Gregory(GregoryTwist::new(along_v, along_u))
            }
        };
        Ok(BicubicCoonsPatch {
            boundary,
            cross,
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
        let hu = hermite_cubic(u);
        let hv = hermite_cubic(v);
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
        let (hu, hv) = (hermite_cubic(&u), hermite_cubic(&v));
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
        let (c1, c2, _, _) = self.boundary.curves();
        [
            c1.eval(u.clone()),
            self.cross.dv0.eval(u.clone()),
            self.cross.dv1.eval(u.clone()),
            c2.eval(u.clone()),
        ]
    }

    fn values_at_v(&self, v: &T) -> [DVector<T>; 4] {
        let (_, _, d1, d2) = self.boundary.curves();
        [
            d1.eval(v.clone()),
            self.cross.du0.eval(v.clone()),
            self.cross.du1.eval(v.clone()),
            d2.eval(v.clone()),
        ]
    }

    /// `x(u, v)` with its first partial derivatives `x_u`, `x_v`, in closed form (the Gregory
    /// twist differentiated as a rational function).
    ///
    /// # Errors
    /// [`Error::MissingDerivative`] if a boundary or cross-boundary curve provides no
    /// derivative.
    pub fn eval_partials(&self, u: T, v: T) -> Result<SurfacePartials<T>> {
        let (c1, c2, d1, d2) = self.boundary.curves();
        let deriv = |c: &dyn Fn(T) -> Option<DVector<T>>, what: &'static str, t: &T| {
            c(t.clone()).ok_or(Error::MissingDerivative { what })
        };
        let at_u = self.values_at_u(&u);
        let at_v = self.values_at_v(&v);
        let at_u_d = [
            deriv(&|t| c1.eval_derivative(t), "c1", &u)?,
            deriv(&|t| self.cross.dv0.eval_derivative(t), "x_v(u,0)", &u)?,
            deriv(&|t| self.cross.dv1.eval_derivative(t), "x_v(u,1)", &u)?,
            deriv(&|t| c2.eval_derivative(t), "c2", &u)?,
        ];
        let at_v_d = [
            deriv(&|t| d1.eval_derivative(t), "d1", &v)?,
            deriv(&|t| self.cross.du0.eval_derivative(t), "x_u(0,v)", &v)?,
            deriv(&|t| self.cross.du1.eval_derivative(t), "x_u(1,v)", &v)?,
            deriv(&|t| d2.eval_derivative(t), "d2", &v)?,
        ];
        let hu = hermite_cubic(&u);
        let hv = hermite_cubic(&v);
        let hu_d = hermite_cubic_derivative(&u);
        let hv_d = hermite_cubic_derivative(&v);
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
        let dim = self.boundary.dim();
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

/// `Σ_i h[i] · values[i][k]`.
fn dot<T: Scalar>(h: &[T; 4], values: &[DVector<T>; 4], k: usize) -> T {
    h.iter()
        .zip(values.iter())
        .fold(T::zero(), |acc, (h, p)| acc + h.clone() * p[k].clone())
}

impl<T: Scalar, C: Curve<T>, D: Curve<T>> Surface<T> for BicubicCoonsPatch<C, D, T> {
    fn dim(&self) -> usize {
        self.boundary.dim()
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        let at_u = self.values_at_u(&u);
        let at_v = self.values_at_v(&v);
        self.combine(&u, &v, &at_u, &at_v)
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
