//! `bspline-surface`: a tensor-product B-spline surface (the CAD notes §1.2–1.3, the lecture
//! notes "B-spline plocha"),
//!
//! `S(u, v) = Σ_i Σ_j P_{i,j} N_{i,p}(u) N_{j,q}(v)` over `[u_(p+1), u_(nu+1)] × [v_(q+1), v_(nv+1)]`
//! (`nu × nv` control points, knots numbered from 1),
//!
//! with the knots and the basis values in each direction as steps. The degrees and the knots
//! of each direction follow the one convention of [`crate::knots`]; the surface is not
//! defined outside its domain.

use cagd::bspline::{basis_all, BSplineSurface as Surface};
use cagd::cost::{max_bits, Cost};
use cagd::grid::PointGrid;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::surface::{evaluated_points, grid_f64, picture_grid, push_surface, SurfaceParams};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::knots::{self, Degree, DOMAIN_FORM};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of a control net.
pub const NET_FORM: &str =
    "a control net of (m+1) × (n+1) points, at least p + 1 along u and q + 1 along v";

/// A B-spline surface.
///
/// ```
/// use cagd_ops::ops::BSplineSurface;
/// use cagd_ops::knots::Degree;
/// use cagd_ops::{Context, Operation, Params};
/// use cagd::grid::PointGrid;
/// // The bilinear patch of z = 0, 1, 1, 3: S(½, ½) = 5/4.
/// let net = PointGrid::from_vec((2, 2, 1), vec![0.0, 1.0, 1.0, 3.0]).unwrap();
/// let mut op = BSplineSurface::new(net);
/// op.degrees = [Degree::Degree(1); 2];
/// op.at.u = Params::Given(vec![0.5]);
/// op.at.v = Params::Given(vec![0.5]);
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[1.25]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface<T> {
    /// The control net `(nu, nv, d)`: `net[[i, j, k]]` is coordinate `k` of `P_{i,j}`, `i`
    /// along `u`.
    pub net: PointGrid<T>,
    /// The degrees along `u` and `v` (or orders).
    pub degrees: [Degree; 2],
    /// The knots along `u` (`nu + p + 1`) and `v`, or clamped uniform on `[0, 1]`.
    pub knots: [Option<Vec<T>>; 2],
    /// Where: `u`, `v` (samples cover the domain; outside it an error), `list` layout.
    pub at: SurfaceParams<T>,
    /// The knots (`knots_u`, `knots_v`) and the basis values (`basis_u`, `basis_v`).
    pub steps: bool,
    /// A picture: the surface and its control net.
    pub drawing: bool,
    /// The surface sampled for a mesh.
    pub mesh: bool,
}

impl<T: Scalar> BSplineSurface<T> {
    /// The clamped bicubic surface of `net` at the default parameters.
    pub fn new(net: PointGrid<T>) -> Self {
        BSplineSurface {
            net,
            degrees: [Degree::Default; 2],
            knots: [None, None],
            at: SurfaceParams::default(),
            steps: false,
            drawing: false,
            mesh: false,
        }
    }

    /// The degrees and the knots of both directions, checked.
    pub(crate) fn knots(&self, cx: &Context) -> Result<DegreesAndKnots<T>> {
        let (nu, nv, _) = self.net.dim();
        let (p, q) = (self.degrees[0].resolve(cx)?, self.degrees[1].resolve(cx)?);
        let ku = knots::knots_or_clamped(self.knots[0].as_deref(), p, nu, knots::SURFACE_U)?;
        let kv = knots::knots_or_clamped(self.knots[1].as_deref(), q, nv, knots::SURFACE_V)?;
        Ok(((p, q), [ku, kv]))
    }

    /// The net as one `nu × nv` matrix per coordinate.
    pub(crate) fn coordinates(&self) -> Vec<DMatrix<T>> {
        let (nu, nv, d) = self.net.dim();
        (0..d)
            .map(|k| DMatrix::from_fn(nu, nv, |i, j| self.net[[i, j, k]].clone()))
            .collect()
    }
}

impl<T: Scalar> BSplineSurface<T> {
    /// The surface: the degrees resolved, the knots of both directions checked (or clamped),
    /// the net built (a front end that keeps the surface builds it here).
    ///
    /// # Errors
    /// The rules of [`crate::knots`]; the library's errors about the net.
    pub fn surface(&self, cx: &Context) -> Result<Surface<T>> {
        let ((p, q), [ku, kv]) = self.knots(cx)?;
        Surface::new(p, q, ku, kv, self.coordinates()).map_err(lib(Role::Net, NET_FORM))
    }
}

impl<T: Scalar> Operation<T> for BSplineSurface<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let surface = self.surface(cx)?;
        let (ku, kv) = surface.knots();
        let evaluated = Evaluated {
            surface: &surface,
            cost: &|bu, bv| surface.point_cost(bu, bv),
            degrees: surface.degrees(),
            knots: [ku.as_slice(), kv.as_slice()],
            title: "B-spline surface",
        };
        answer(self, evaluated, grid_f64(&self.net), cx)
    }
}

/// The degrees `(p, q)` and the knots along `u` and `v`.
pub(crate) type DegreesAndKnots<T> = ((usize, usize), [Vec<T>; 2]);

/// A surface as the answer needs it: the surface, the cost of a point at parameters of so
/// many bits, its degrees and knots, the picture's title.
pub(crate) struct Evaluated<'a, T: Scalar> {
    /// The surface.
    pub surface: &'a dyn cagd::Surface<T>,
    /// The cost of one point.
    pub cost: &'a dyn Fn(u128, u128) -> Cost,
    /// The degrees `(p, q)`.
    pub degrees: (usize, usize),
    /// The knots along `u` and `v`.
    pub knots: [&'a [T]; 2],
    /// The picture's title.
    pub title: &'a str,
}

/// The answer of a B-spline or NURBS surface asked for by `args`: parameters in the domain,
/// the cost refused above the limit, the steps, the result, the picture (with the control
/// `net`) and the mesh.
pub(crate) fn answer<T: Scalar>(
    args: &BSplineSurface<T>,
    s: Evaluated<'_, T>,
    net: PointGrid<f64>,
    cx: &mut Context,
) -> Result<Answer<T>> {
    let ((a, b), (c, d)) = s.surface.domain();
    let what = ("B-spline surface", DOMAIN_FORM);
    let us = knots::params_within(&args.at.u, Role::U, (&a, &b), what, cx)?;
    let vs = knots::params_within(&args.at.v, Role::V, (&c, &d), what, cx)?;
    cx.check_grid(Role::Grid, us.len(), vs.len())?;
    let single = args.at.single();
    let pictures = args.drawing || args.mesh;
    let (pus, pvs) = if pictures {
        picture_grid((&us, &vs), single, ((&a, &b), (&c, &d)))?
    } else {
        (Vec::new(), Vec::new())
    };
    let bits = |x: &[T], y: &[T]| (max_bits(x), max_bits(y));
    let (bu, bv) = bits(&us, &vs);
    let (pbu, pbv) = bits(&pus, &pvs);
    let per = (s.cost)(bu.max(pbu), bv.max(pbv));
    let points = evaluated_points((&us, &vs), pictures.then_some((&pus, &pvs)));
    cx.check_cost(Role::Grid, per.times(points), T::EXACT)?;
    let grid = eval_grid(s.surface, &us, &vs)?;
    let report = report(args, &s, (&us, &vs), &grid)?;
    let mut answer = Answer {
        report,
        drawing: None,
        mesh: None,
    };
    if pictures {
        let g = grid_f64(&if single {
            eval_grid(s.surface, &pus, &pvs)?
        } else {
            grid
        });
        if args.drawing {
            let drawing = Drawing::new(s.title).surface(g.clone(), "surface").net(
                net,
                Colour::Red,
                "control net",
            );
            answer.drawing = Some(drawing);
        }
        if args.mesh {
            answer.mesh = Some(g);
        }
    }
    Ok(answer)
}

/// The knots and basis values with steps, `u`, `v` and the `result` on `grid`.
fn report<T: Scalar>(
    args: &BSplineSurface<T>,
    s: &Evaluated<'_, T>,
    (us, vs): (&[T], &[T]),
    grid: &PointGrid<T>,
) -> Result<Report<T>> {
    let mut report = Report::new();
    if args.steps {
        let ((p, q), [ku, kv], (nu, nv, _)) = (s.degrees, s.knots, args.net.dim());
        report.push("knots_u", Value::row(ku));
        report.push("knots_v", Value::row(kv));
        report.push("basis_u", basis(p, nu, ku, us)?);
        report.push("basis_v", basis(q, nv, kv, vs)?);
    }
    report.push("u", Value::row(us));
    report.push("v", Value::row(vs));
    if args.at.single() && !args.at.list {
        let dim = grid.dim().2;
        let point = DMatrix::from_fn(dim, 1, |k, _| grid[[0, 0, k]].clone());
        report.push("result", Value::Matrix(point));
    } else {
        push_surface(&mut report, "result", (us, vs), grid.clone(), args.at.list);
    }
    Ok(report)
}

/// The surface on the grid `us × vs` (parameters in the domain).
fn eval_grid<T: Scalar>(s: &dyn cagd::Surface<T>, us: &[T], vs: &[T]) -> Result<PointGrid<T>> {
    let shape = (us.len(), vs.len(), s.dim());
    let mut out = vec![T::zero(); shape.0 * shape.1 * shape.2];
    s.eval_grid_into(us, vs, &mut out)
        .map_err(lib(Role::Grid, DOMAIN_FORM))?;
    PointGrid::from_vec(shape, out).ok_or_else(|| {
        crate::OpError::new(
            Role::Grid,
            crate::Kind::Internal,
            "a grid of the wrong length",
            "a grid",
        )
    })
}

/// The `n` basis functions of degree `p` on `knots` at `at`: `k × n`, row = parameter.
fn basis<T: Scalar>(p: usize, n: usize, knots: &[T], at: &[T]) -> Result<Value<T>> {
    let rows = at.iter().map(|t| basis_all(p, n, knots, t));
    super::bspline::basis_matrix(rows, at.len(), n)
}
