//! Coons patches: surfaces that fill four boundary curves (thesis chapter 4, notes §2.1).
//!
//! The four boundary curves are named as in the thesis: `c1(u) = x(u, 0)`, `c2(u) = x(u, 1)`,
//! `d1(v) = x(0, v)`, `d2(v) = x(1, v)`, all over `[0, 1]`. A curve given on another domain
//! `[a, b]` is reparametrised affinely onto `[0, 1]`, `s ↦ c(a + (b − a)s)` (see
//! [`crate::param`]: a boundary `BSplineCurve::uniform_cubic(…)` on `[0, 4]` is used whole), and
//! one whose domain is not a finite interval is refused with [`Error::UnusableDomain`]. The
//! curves must meet at the four corners (the *compatibility condition* of thesis §4.4):
//!
//! ```text
//!   v ↑        c2
//!   1 P3 ────────────── P4        P1 = x(0,0) = c1(0) = d1(0)
//!     │                 │         P2 = x(1,0) = c1(1) = d2(0)
//!  d1 │                 │ d2      P3 = x(0,1) = c2(0) = d1(1)
//!     │                 │         P4 = x(1,1) = c2(1) = d2(1)
//!   0 P1 ────────────── P2 → u
//!     0        c1       1
//! ```
//!
//! The corner names `P1..P4` are those of the thesis code (`krpaCoons`, `vrednostCoons`): its
//! bilinear term `rcd = (1-u)(1-v)P1 + u(1-v)P2 + (1-u)v P3 + uv P4` is eq. (4.3),
//! `[1-u, u] [x(0,0) x(0,1); x(1,0) x(1,1)] [1-v; v]`, written out, so `P2 = x(1,0)` and
//! `P3 = x(0,1)`.
//!
//! Constructions, one per file:
//! - [`CoonsPatch`] (`bilinear.rs`): the bilinearly blended patch `x = r_c + r_d − r_cd`
//!   (Izrek 4.2); of Bézier curves exactly as one Bézier patch, of B-spline curves as one
//!   B-spline surface ([`coons_bspline_net`], `bspline_form.rs`);
//! - [`GeneralizedCoonsPatch`] (`generalized.rs`): user blending functions `f1, f2, g1, g2`,
//!   including the partially bicubic blend `H0³ = B0³ + B1³`, `H3³ = B2³ + B3³` (§4.2);
//! - [`BicubicCoonsPatch`] (`bicubic.rs`): the bicubically blended (Hermite) patch of §4.3 with
//!   the twist choices of [`Twist`], including Gregory's square (`gregory.rs`, §4.4);
//! - [`discrete_coons`] (`discrete.rs`): the discrete Coons patch, interior control points of a
//!   Bézier net from its boundary (end of §4.1, notes (6));
//! - [`Mask`] and [`solve_mask`] (`mask.rs`): the same net from the 3×3 mask of notes (7)–(9),
//!   and its generalisations.
//!
//! All of it is generic over the [`Scalar`]: in `BigRational` the thesis's Primer 4.3 comes out
//! exactly.

use nalgebra::DVector;

use crate::error::{Error, Result};
use crate::param::{usable_domain, Curve, OnUnitInterval};
use crate::scalar::Scalar;

mod bicubic;
mod bilinear;
mod bspline_form;
mod discrete;
mod generalized;
mod gregory;
mod mask;

pub use crate::tolerance::{Corner, CornerGap, Tolerance};
pub use bicubic::{
    bicubic_point_cost, BicubicCoonsPatch, BicubicCoonsPoint, CrossDerivatives, SurfacePartials,
    Twist,
};
pub use bilinear::{coons_point_cost, CoonsPatch};
pub use bspline_form::coons_bspline_net;
pub use discrete::{
    discrete_coons, discrete_coons_cost, discrete_coons_parts, discrete_coons_parts_cost,
};
pub use generalized::{BlendingPair, GeneralizedCoonsPatch, BLEND_TOLERANCE};
pub use gregory::GregoryTwist;
pub use mask::{solve_mask, Mask};

/// The value of a Coons patch at one parameter pair with its three parts
/// (what the thesis function `vrednostCoons` computes): `x = r_c + r_d − r_cd`.
#[derive(Debug, Clone, PartialEq)]
pub struct CoonsPoint<T: Scalar = f64> {
    /// The surface point `x(u, v)`.
    pub x: DVector<T>,
    /// The ruled surface between `c1` and `c2`: `r_c = g1(v) c1(u) + g2(v) c2(u)` (4.1).
    pub rc: DVector<T>,
    /// The ruled surface between `d1` and `d2`: `r_d = f1(u) d1(v) + f2(u) d2(v)` (4.2).
    pub rd: DVector<T>,
    /// The blend of the corners: `r_cd = f1 g1 P1 + f2 g1 P2 + f1 g2 P3 + f2 g2 P4` (4.3).
    pub rcd: DVector<T>,
}

/// Four boundary curves checked for compatibility, with the four corner points `P1..P4`.
///
/// Each curve is used reparametrised onto `[0, 1]` ([`CoonsBoundary::unit_curves`]; a curve
/// on `[a, b]` enters as `s ↦ c(a + (b − a)s)`, one on `[0, 1]` unchanged). The corner points
/// are taken from `c1` and `c2` (`P1 = c1(0)`, `P2 = c1(1)`, `P3 = c2(0)`, `P4 = c2(1)` of
/// the reparametrised curves, i.e. the ends of their domains, as octave-nurbs `nrbcoons` does)
/// unless given explicitly with [`CoonsBoundary::with_corners`] (as the thesis code passes
/// `P1..P4`).
#[derive(Debug, Clone)]
pub struct CoonsBoundary<C, T: Scalar = f64> {
    c1: C,
    c2: C,
    d1: C,
    d2: C,
    /// The domains of `c1, c2, d1, d2`, each a finite interval `a < b`.
    domains: [(T, T); 4],
    corners: [DVector<T>; 4],
    tolerance: Tolerance,
}

/// A curve end: `(curve name, curve index 0..4 in c1 c2 d1 d2, parameter 0|1)`.
type CurveEnd = (&'static str, usize, usize);

/// The eight curve ends, grouped by corner.
const CURVE_ENDS: [(Corner, [CurveEnd; 2]); 4] = [
    (Corner::U0V0, [("c1(0)", 0, 0), ("d1(0)", 2, 0)]),
    (Corner::U1V0, [("c1(1)", 0, 1), ("d2(0)", 3, 0)]),
    (Corner::U0V1, [("c2(0)", 1, 0), ("d1(1)", 2, 1)]),
    (Corner::U1V1, [("c2(1)", 1, 1), ("d2(1)", 3, 1)]),
];

impl<T: Scalar, C: Curve<T>> CoonsBoundary<C, T> {
    /// Checks that the curves `c1 = x(·,0)`, `c2 = x(·,1)`, `d1 = x(0,·)`, `d2 = x(1,·)` share
    /// one dimension, have domains that can be reparametrised onto `[0, 1]`, and meet at the
    /// corners (the ends of their domains) within `tolerance`.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for curves of different dimensions,
    /// [`Error::UnusableDomain`] for a curve whose domain is not a finite interval `a < b`
    /// (naming the curve), [`Error::NonFinite`] for a non-finite corner, [`Error::CornerMismatch`] listing every
    /// corner where the two curves disagree, [`Error::InvalidArgument`] for a negative or
    /// non-finite tolerance.
    ///
    /// ```
    /// use cagd::coons::{CoonsBoundary, Corner, Tolerance};
    /// use cagd::{Curve, Error, FnCurve};
    /// use nalgebra::dvector;
    /// // Closures are of different types: box them to pass them as one curve type.
    /// let c1: Box<dyn Curve> = Box::new(FnCurve::new(2, |u: f64| dvector![u, 0.0]));
    /// let c2: Box<dyn Curve> = Box::new(FnCurve::new(2, |u: f64| dvector![u, 1.0]));
    /// let d1: Box<dyn Curve> = Box::new(FnCurve::new(2, |v: f64| dvector![0.0, v]));
    /// let d2: Box<dyn Curve> = Box::new(FnCurve::new(2, |v: f64| dvector![1.0, v + 0.5])); // off at both ends
    /// match CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default()) {
    ///     Err(Error::CornerMismatch { gaps, .. }) => {
    ///         assert_eq!(gaps.len(), 2);
    ///         assert_eq!((gaps[0].corner, gaps[0].first, gaps[0].second), (Corner::U1V0, "c1(1)", "d2(0)"));
    ///         assert_eq!(gaps[0].gap, 0.5);
    ///         assert_eq!(gaps[1].corner, Corner::U1V1);
    ///     }
    ///     _ => panic!("expected a corner mismatch"),
    /// }
    /// ```
    pub fn new(c1: C, c2: C, d1: C, d2: C, tolerance: Tolerance) -> Result<Self> {
        let (domains, ends) = Self::ends(&c1, &c2, &d1, &d2)?;
        crate::error::check_tolerance(&tolerance)?;
        let mut gaps = Vec::new();
        for (corner, [(na, ia, ea), (nb, ib, eb)]) in CURVE_ENDS {
            let (p, q) = (&ends[ia][ea], &ends[ib][eb]);
            push_gap(&mut gaps, &tolerance, corner, na, nb, p, q);
        }
        if !gaps.is_empty() {
            return Err(Error::CornerMismatch { gaps, tolerance });
        }
        let corners = [
            ends[0][0].clone(),
            ends[0][1].clone(),
            ends[1][0].clone(),
            ends[1][1].clone(),
        ];
        Ok(CoonsBoundary {
            c1,
            c2,
            d1,
            d2,
            domains,
            corners,
            tolerance,
        })
    }

    /// Like [`CoonsBoundary::new`], but with the corner points `P1..P4 = x(0,0), x(1,0),
    /// x(0,1), x(1,1)` given, as the thesis code passes them; each must agree with both curve
    /// ends that meet there.
    ///
    /// # Errors
    /// As [`CoonsBoundary::new`]; a corner of the wrong dimension is an
    /// [`Error::ShapeMismatch`].
    pub fn with_corners(
        c1: C,
        c2: C,
        d1: C,
        d2: C,
        corners: [DVector<T>; 4],
        tolerance: Tolerance,
    ) -> Result<Self> {
        let (domains, ends) = Self::ends(&c1, &c2, &d1, &d2)?;
        crate::error::check_tolerance(&tolerance)?;
        let dim = c1.dim();
        for p in &corners {
            if p.len() != dim {
                return Err(Error::ShapeMismatch {
                    what: "Coons corner points P1..P4",
                    expected: format!("points of dimension {dim}"),
                    found: format!("a point of dimension {}", p.len()),
                });
            }
            crate::error::check_finite("Coons corner points P1..P4", p.iter())?;
        }
        const NAMES: [&str; 4] = ["P1", "P2", "P3", "P4"];
        let mut gaps = Vec::new();
        for (corner, pair) in CURVE_ENDS {
            let k = corner.index();
            for (name, i, e) in pair {
                push_gap(
                    &mut gaps,
                    &tolerance,
                    corner,
                    NAMES[k],
                    name,
                    &corners[k],
                    &ends[i][e],
                );
            }
        }
        if !gaps.is_empty() {
            return Err(Error::CornerMismatch { gaps, tolerance });
        }
        Ok(CoonsBoundary {
            c1,
            c2,
            d1,
            d2,
            domains,
            corners,
            tolerance,
        })
    }

    /// The domains of the four curves and their values at the ends of them (the
    /// reparametrised curves at 0 and 1), after checking dimensions, domains and finiteness.
    #[allow(clippy::type_complexity)]
    fn ends(c1: &C, c2: &C, d1: &C, d2: &C) -> Result<([(T, T); 4], [[DVector<T>; 2]; 4])> {
        let dim = c1.dim();
        const NAMES: [&str; 4] = ["c1", "c2", "d1", "d2"];
        let curves = [c1, c2, d1, d2];
        for (k, c) in curves.iter().enumerate() {
            if c.dim() != dim {
                return Err(Error::ShapeMismatch {
                    what: "Coons boundary curves",
                    expected: format!("curves of one dimension ({dim}, the dimension of c1)"),
                    found: format!("{} of dimension {}", NAMES[k], c.dim()),
                });
            }
        }
        let domains = [
            usable_domain("Coons boundary curve c1", c1)?,
            usable_domain("Coons boundary curve c2", c2)?,
            usable_domain("Coons boundary curve d1", d1)?,
            usable_domain("Coons boundary curve d2", d2)?,
        ];
        let ends = [0, 1, 2, 3].map(|k| {
            let (a, b) = domains[k].clone();
            [curves[k].eval(a), curves[k].eval(b)]
        });
        for (k, pair) in ends.iter().enumerate() {
            for p in pair {
                if p.len() != dim {
                    return Err(Error::ShapeMismatch {
                        what: "Coons boundary curves",
                        expected: format!("points of dimension {dim}"),
                        found: format!("{} returned a point of dimension {}", NAMES[k], p.len()),
                    });
                }
                crate::error::check_finite("Coons boundary curve end", p.iter())?;
            }
        }
        Ok((domains, ends))
    }
}

impl<T: Scalar, C> CoonsBoundary<C, T> {
    /// The curves `(c1, c2, d1, d2)`, each in its own parameter.
    pub fn curves(&self) -> (&C, &C, &C, &C) {
        (&self.c1, &self.c2, &self.d1, &self.d2)
    }

    /// The curves `[c1, c2, d1, d2]` as the patch uses them: reparametrised onto `[0, 1]`
    /// (unchanged for a curve on `[0, 1]`).
    pub fn unit_curves(&self) -> [OnUnitInterval<&C, T>; 4] {
        let curves = [&self.c1, &self.c2, &self.d1, &self.d2];
        [0, 1, 2, 3].map(|k| OnUnitInterval::from_checked(curves[k], self.domains[k].clone()))
    }

    /// The corner points `[P1, P2, P3, P4] = [x(0,0), x(1,0), x(0,1), x(1,1)]`.
    pub fn corners(&self) -> &[DVector<T>; 4] {
        &self.corners
    }

    /// The tolerance the corners were checked against.
    pub fn tolerance(&self) -> Tolerance {
        self.tolerance
    }
}

impl<T: Scalar, C: Curve<T>> CoonsBoundary<C, T> {
    /// The dimension of the points.
    pub fn dim(&self) -> usize {
        self.c1.dim()
    }

    /// `x = r_c + r_d − r_cd` with blending weights `f = (f1(u), f2(u))`, `g = (g1(v), g2(v))`,
    /// in the term order of the thesis code (`vrednostCoons`), so that `f64` results agree with
    /// Octave bit for bit.
    pub(crate) fn blend(&self, u: &T, v: &T, f: &(T, T), g: &(T, T)) -> CoonsPoint<T> {
        let [c1, c2, d1, d2] = self.unit_curves();
        let values = [
            c1.eval(u.clone()),
            c2.eval(u.clone()),
            d1.eval(v.clone()),
            d2.eval(v.clone()),
        ];
        self.blend_values(values, f, g)
    }

    /// The point `x(u, v)` for `(u, v)` in `[0, 1]²` as [`blend`](Self::blend) computes it
    /// (bit for bit), with each boundary curve evaluated by its own `try_eval` — its work
    /// bounded, its point checked — and the result checked: the `try_eval` of the Coons
    /// patches.
    ///
    /// # Errors
    /// [`Error::NonFinite`], [`Error::ParameterOutOfRange`] for a parameter outside
    /// `[0, 1]`; a curve's own error (named after it: `"Coons boundary curve c1"`, …) for a
    /// point of another dimension, a non-finite point or too much work;
    /// [`Error::Overflow`] for a blended point whose double overflows.
    pub(crate) fn try_blend(&self, u: &T, v: &T, f: &(T, T), g: &(T, T)) -> Result<DVector<T>> {
        let unit = (T::zero(), T::one());
        crate::param::check_parameter("Coons patch parameter u", u, &unit)?;
        crate::param::check_parameter("Coons patch parameter v", v, &unit)?;
        let [c1, c2, d1, d2] = self.unit_curves();
        let names = [
            "Coons boundary curve c1",
            "Coons boundary curve c2",
            "Coons boundary curve d1",
            "Coons boundary curve d2",
        ];
        let mut values: [DVector<T>; 4] = Default::default();
        for (k, (curve, t)) in [(&c1, u), (&c2, u), (&d1, v), (&d2, v)]
            .into_iter()
            .enumerate()
        {
            values[k] = curve
                .try_eval(t.clone())
                .map_err(|e| crate::checked::named(names[k], e))?;
        }
        let x = self.blend_values(values, f, g).x;
        crate::checked::point("Coons patch point", self.dim(), x)
    }

    /// `x = r_c + r_d − r_cd` from the curves' values `[c1(u), c2(u), d1(v), d2(v)]`.
    fn blend_values(&self, values: [DVector<T>; 4], f: &(T, T), g: &(T, T)) -> CoonsPoint<T> {
        let [c1, c2, d1, d2] = values;
        let w = corner_weights(f, g);
        let dim = self.dim();
        let mut point = CoonsPoint {
            x: DVector::from_element(dim, T::zero()),
            rc: DVector::from_element(dim, T::zero()),
            rd: DVector::from_element(dim, T::zero()),
            rcd: DVector::from_element(dim, T::zero()),
        };
        for k in 0..dim {
            let (rc, rd, rcd, x) =
                blend_coordinate(f, g, &w, [&c1[k], &c2[k], &d1[k], &d2[k]], &self.corners, k);
            point.rc[k] = rc;
            point.rd[k] = rd;
            point.rcd[k] = rcd;
            point.x[k] = x;
        }
        point
    }

    /// The blend on the grid `us × vs` (shape `(us.len(), vs.len(), d)`), evaluating `c1`, `c2`
    /// once per `u` and `d1`, `d2` once per `v`.
    pub(crate) fn blend_grid(
        &self,
        us: &[T],
        vs: &[T],
        f: &[(T, T)],
        g: &[(T, T)],
    ) -> crate::grid::PointGrid<T> {
        let dim = self.dim();
        let [c1, c2, d1, d2] = self.unit_curves();
        let c1: Vec<_> = us.iter().map(|u| c1.eval(u.clone())).collect();
        let c2: Vec<_> = us.iter().map(|u| c2.eval(u.clone())).collect();
        let d1: Vec<_> = vs.iter().map(|v| d1.eval(v.clone())).collect();
        let d2: Vec<_> = vs.iter().map(|v| d2.eval(v.clone())).collect();
        let mut grid = crate::grid::PointGrid::from_elem((us.len(), vs.len(), dim), T::zero());
        for i in 0..us.len() {
            for j in 0..vs.len() {
                let w = corner_weights(&f[i], &g[j]);
                for k in 0..dim {
                    let (_, _, _, x) = blend_coordinate(
                        &f[i],
                        &g[j],
                        &w,
                        [&c1[i][k], &c2[i][k], &d1[j][k], &d2[j][k]],
                        &self.corners,
                        k,
                    );
                    grid[[i, j, k]] = x;
                }
            }
        }
        grid
    }
}

/// The weights `[f1 g1, f2 g1, f1 g2, f2 g2]` of `P1..P4` (each product formed first, as
/// Octave evaluates `(1-u)*(1-v)*P1` from the left).
fn corner_weights<T: Scalar>(f: &(T, T), g: &(T, T)) -> [T; 4] {
    [
        f.0.clone() * g.0.clone(),
        f.1.clone() * g.0.clone(),
        f.0.clone() * g.1.clone(),
        f.1.clone() * g.1.clone(),
    ]
}

/// One coordinate of `(r_c, r_d, r_cd, x)`, term order as in the thesis code:
/// `rc = g1 c1 + g2 c2`, `rd = f1 d1 + f2 d2`, `rcd = ((w1 P1 + w2 P2) + w3 P3) + w4 P4`,
/// `x = (rc + rd) − rcd`.
fn blend_coordinate<T: Scalar>(
    f: &(T, T),
    g: &(T, T),
    w: &[T; 4],
    curves: [&T; 4],
    corners: &[DVector<T>; 4],
    k: usize,
) -> (T, T, T, T) {
    let [c1, c2, d1, d2] = curves;
    let rc = g.0.clone() * c1.clone() + g.1.clone() * c2.clone();
    let rd = f.0.clone() * d1.clone() + f.1.clone() * d2.clone();
    let rcd = w[0].clone() * corners[0][k].clone()
        + w[1].clone() * corners[1][k].clone()
        + w[2].clone() * corners[2][k].clone()
        + w[3].clone() * corners[3][k].clone();
    let x = rc.clone() + rd.clone() - rcd.clone();
    (rc, rd, rcd, x)
}

/// Records a [`CornerGap`] when `p` and `q` are further apart than `tolerance` allows.
pub(crate) fn push_gap<T: Scalar>(
    gaps: &mut Vec<CornerGap>,
    tolerance: &Tolerance,
    corner: Corner,
    first: &'static str,
    second: &'static str,
    p: &DVector<T>,
    q: &DVector<T>,
) {
    let (gap, allowed) = tolerance.gap(p, q);
    if gap > allowed {
        gaps.push(CornerGap {
            corner,
            first,
            second,
            gap: gap.to_f64(),
            allowed: allowed.to_f64(),
        });
    }
}
