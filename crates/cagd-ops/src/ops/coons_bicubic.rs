//! `coons-bicubic`: the bicubically blended Coons patch with cross-boundary derivatives
//! (thesis §4.3, twists §4.4):
//!
//! `x = h_c + h_d − h_cd`, `h_c(u,v) = H0(u) x(0,v) + H1(u) x_u(0,v) + H2(u) x_u(1,v) + H3(u) x(1,v)`,
//! `h_d` the same in `v`, `h_cd = [H0(u) … H3(u)] M [H0(v) … H3(v)]ᵀ` (4.5)
//! ([`cagd::coons::BicubicCoonsPatch`]). Every curve needs its derivative (the corner tangents
//! are checked against the cross-boundary curves; Gregory's twists use the derivatives of the
//! cross-boundary curves): the curves may be any curves of the library (Bézier, B-spline,
//! NURBS on their own domains, mapped onto `[0, 1]`), samples of a data script (their
//! polyline's slopes), or expressions evaluated with their derivatives where the patch needs
//! them.

use cagd::coons::{bicubic_point_cost, BicubicCoonsPatch, CoonsBoundary, CrossDerivatives, Twist};
use cagd::cost::max_bits;
use cagd::{Curve, Scalar, Surface, Tolerance};
use nalgebra::DMatrix;

use super::coons::{boundary_picture, realise_all, BOUNDARY_FORM, BOUNDARY_ROLES};
use super::patch::{answer, curve_costs, Pictures};
use super::surface::{evaluated_points, picture_grid, push_terms, SurfaceParams};
use crate::curves::{check_curves_work, needed, CurveArg, Realised};
use crate::error::{Kind, OpError, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of the cross-boundary derivatives.
pub const CROSS_FORM: &str =
    "cross-boundary derivatives that agree with the boundary tangents at the corners";

/// The form of given twists.
pub const TWISTS_FORM: &str = "a d×4 matrix, the twists at P1..P4 as columns";

/// The roles of the cross-boundary curves `[x_v(u,0), x_v(u,1), x_u(0,v), x_u(1,v)]`.
pub const CROSS_ROLES: [Role; 4] = [Role::C1v, Role::C2v, Role::D1u, Role::D2u];

/// The corner twists `x_uv` (thesis §4.4).
#[derive(Debug, Clone, PartialEq)]
pub enum TwistChoice<T> {
    /// All four zero.
    Zero,
    /// Gregory's square from the derivatives of the cross-boundary curves.
    Gregory,
    /// Given: the twists at `P1..P4 = (0,0), (1,0), (0,1), (1,1)` as the columns of a `d × 4`
    /// matrix.
    Given(DMatrix<T>),
}

/// A bicubically blended Coons patch.
///
/// ```
/// use cagd::bezier::BezierCurve;
/// use cagd_ops::{curves::CurveArg, execute, ops::{CoonsBicubic, TwistChoice}, Context, Params};
/// use nalgebra::DMatrix;
/// // z = u·v on the unit square: its edges as Bézier lines, the cross-boundary derivatives
/// // x_u(i, v) = (1, 0, v) and x_v(u, j) = (0, 1, u), Gregory's twists (1 at every corner).
/// let line = |p: [f64; 3], q: [f64; 3]| {
///     CurveArg::curve(BezierCurve::new(DMatrix::from_column_slice(3, 2, &[p, q].concat())).unwrap())
/// };
/// let boundary = [
///     line([0., 0., 0.], [1., 0., 0.]),
///     line([0., 1., 0.], [1., 1., 1.]),
///     line([0., 0., 0.], [0., 1., 0.]),
///     line([1., 0., 0.], [1., 1., 1.]),
/// ];
/// let cross = [
///     line([0., 1., 0.], [0., 1., 1.]),
///     line([0., 1., 0.], [0., 1., 1.]),
///     line([1., 0., 0.], [1., 0., 1.]),
///     line([1., 0., 0.], [1., 0., 1.]),
/// ];
/// let mut op = CoonsBicubic::new(boundary, cross);
/// op.twist = TwistChoice::Gregory;
/// op.at.u = Params::Given(vec![0.25]);
/// op.at.v = Params::Given(vec![0.5]);
/// let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.25, 0.5, 0.125]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug)]
pub struct CoonsBicubic<T: Scalar> {
    /// `[c1, c2, d1, d2]`: `x(u,0)`, `x(u,1)` in `u`, `x(0,v)`, `x(1,v)` in `v`.
    pub boundary: [CurveArg<T>; 4],
    /// `[c1v, c2v, d1u, d2u]`: `x_v(u,0)`, `x_v(u,1)` in `u`, `x_u(0,v)`, `x_u(1,v)` in `v`.
    pub cross: [CurveArg<T>; 4],
    /// The corner twists.
    pub twist: TwistChoice<T>,
    /// Where: `u`, `v` (samples of `[0, 1]`), `--list` layout.
    pub at: SurfaceParams<T>,
    /// `hc`, `hd`, `hcd` as steps.
    pub steps: bool,
    /// A picture: the surface with `c1`, `c2` in red and `d1`, `d2` in green.
    pub drawing: bool,
    /// The surface sampled for a mesh.
    pub mesh: bool,
}

impl<T: Scalar> CoonsBicubic<T> {
    /// The patch of four boundary curves and their cross-boundary derivatives, with zero
    /// twists, at the default parameters.
    pub fn new(boundary: [CurveArg<T>; 4], cross: [CurveArg<T>; 4]) -> Self {
        CoonsBicubic {
            boundary,
            cross,
            twist: TwistChoice::Zero,
            at: SurfaceParams::default(),
            steps: false,
            drawing: false,
            mesh: false,
        }
    }
}

/// The patch of realised curves.
type Patch<'a, T> = BicubicCoonsPatch<Realised<'a, T>, Realised<'a, T>, T>;

impl<T: Scalar> Operation<T> for CoonsBicubic<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let [us, vs, pus, pvs] = self.grids(cx)?;
        let single = self.at.single();
        let pictures = self.drawing || self.mesh;
        let at_u = needed(&[&us, &pus]);
        let at_v = needed(&[&vs, &pvs]);
        let ats = [at_u.as_slice(), &at_u, &at_v, &at_v];
        let boundary = parts(BOUNDARY_ROLES, &self.boundary, ats);
        let cross = parts(CROSS_ROLES, &self.cross, ats);
        // All eight curves are estimated together, before any is evaluated.
        check_curves_work(cx, &[boundary.clone(), cross.clone()].concat())?;
        let curves = realise_all(&boundary, true)?;
        let gregory = self.twist == TwistChoice::Gregory;
        let [dv0, dv1, du0, du1] = realise_all(&cross, gregory)?;
        let realised = [
            &curves[0], &curves[1], &curves[2], &curves[3], &dv0, &dv1, &du0, &du1,
        ];
        let pairs: Vec<(&Realised<'_, T>, &[T])> = realised
            .into_iter()
            .zip(ats.into_iter().chain(ats))
            .collect();
        let d = curves[0].dim();
        let per_point =
            bicubic_point_cost(curve_costs(&pairs), d, max_bits(&at_u), max_bits(&at_v));
        let points = evaluated_points((&us, &vs), pictures.then_some((&pus, &pvs)));
        cx.check_cost(Role::Grid, per_point.times(points), T::EXACT)?;
        let patch = self.patch(curves, CrossDerivatives { du0, du1, dv0, dv1 })?;
        let mut report = Report::new();
        report.push("u", Value::row(&us));
        report.push("v", Value::row(&vs));
        push_terms(
            &mut report,
            ["hc", "hd", "hcd"],
            (self.steps, self.at.list, single),
            (&us, &vs),
            patch.dim(),
            cx,
            |u, v| {
                let p = patch.eval_parts(u, v);
                [p.hc, p.hd, p.hcd, p.x]
            },
        )?;
        let pictures = Pictures {
            at: (&us, &vs, single),
            grid: (&pus, &pvs),
            drawing: self.drawing,
            mesh: self.mesh,
        };
        answer(report, &patch, pictures, |grid| {
            let (c1, c2, d1, d2) = patch.boundary().curves();
            boundary_picture("bicubic Coons patch", grid, [c1, c2, d1, d2], (&pus, &pvs))
        })
    }
}

impl<T: Scalar> CoonsBicubic<T> {
    /// `u` and `v` (samples of `[0, 1]`), and the pictures' grid.
    fn grids(&self, cx: &mut Context) -> Result<[Vec<T>; 4]> {
        let unit = (&T::zero(), &T::one());
        let (us, vs) = self
            .at
            .resolve((unit, unit), "the patch is extrapolated there", cx)?;
        let (pus, pvs) = if self.drawing || self.mesh {
            picture_grid((&us, &vs), self.at.single(), (unit, unit))?
        } else {
            (Vec::new(), Vec::new())
        };
        Ok([us, vs, pus, pvs])
    }

    /// The patch: the boundary checked at the corners, the cross-boundary derivatives against
    /// the boundary's tangents there, the twists.
    fn patch<'a>(
        &self,
        [c1, c2, d1, d2]: [Realised<'a, T>; 4],
        cross: CrossDerivatives<Realised<'a, T>>,
    ) -> Result<Patch<'a, T>> {
        let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default())
            .map_err(|e| OpError::library(Role::Boundary, e, BOUNDARY_FORM))?;
        let twist = match &self.twist {
            TwistChoice::Zero => Twist::Zero,
            TwistChoice::Gregory => Twist::Gregory,
            TwistChoice::Given(m) => {
                if m.ncols() != 4 || m.nrows() != boundary.dim() {
                    return Err(OpError::new(
                        Role::Twists,
                        Kind::Shape,
                        format!(
                            "a {}×{} matrix for points of dimension {}",
                            m.nrows(),
                            m.ncols(),
                            boundary.dim()
                        ),
                        TWISTS_FORM,
                    ));
                }
                Twist::Given(std::array::from_fn(|k| m.column(k).into_owned()))
            }
        };
        BicubicCoonsPatch::new(boundary, cross, twist).map_err(|e| match e {
            cagd::Error::NonFinite {
                what: "given twists",
                ..
            } => OpError::library(Role::Twists, e, TWISTS_FORM),
            _ => OpError::library(Role::Cross, e, CROSS_FORM),
        })
    }
}

/// Each curve with its role and the parameters it is evaluated at.
fn parts<'a, T: Scalar>(
    roles: [Role; 4],
    curves: &'a [CurveArg<T>; 4],
    ats: [&'a [T]; 4],
) -> Vec<(Role, &'a CurveArg<T>, &'a [T])> {
    roles
        .into_iter()
        .zip(curves.iter())
        .zip(ats)
        .map(|((r, c), at)| (r, c, at))
        .collect()
}
