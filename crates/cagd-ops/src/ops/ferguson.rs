//! `ferguson`: the Hermite bicubic (Ferguson) patch of the lecture notes ("Hermitova plocha"):
//!
//! `x(u, v) = f(u)ᵀ G f(v)`, `f` the cubic Hermite basis, `G` (one `4 × 4` per coordinate)
//! holding the corner points, the tangents `x_u`, `x_v` and the twists `x_uv`
//! ([`cagd::surfaces::FergusonPatch`]). The corner data are given as `d × 4` matrices, or the
//! points and tangents are those of four boundary curves (any curves: their ends and end
//! tangents, [`FergusonPatch::from_boundary`]).

use cagd::coons::CoonsBoundary;
use cagd::cost::max_bits;
use cagd::surfaces::{ferguson_point_cost, FergusonPatch};
use cagd::{Scalar, Surface, Tolerance};
use nalgebra::{DMatrix, DVector};

use super::coons::{boundary_line, realise_all, BOUNDARY_FORM, BOUNDARY_ROLES};
use super::patch::{answer, push_result, Pictures};
use super::surface::{evaluated_points, picture_grid, SurfaceParams};
use super::to_f64;
use crate::curves::{check_curves_work, CurveArg};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of a matrix of corner vectors.
pub const CORNERS_FORM: &str =
    "a d×4 matrix: the vectors at the corners (0,0), (1,0), (0,1), (1,1) as columns";

/// Where the corner points and tangents come from.
#[derive(Debug)]
pub enum FergusonData<T: Scalar> {
    /// Given: `d × 4` matrices of points, `u`-tangents and `v`-tangents, columns the corners
    /// `(u, v) = (0,0), (1,0), (0,1), (1,1)`.
    Corners {
        /// `x(i, j)`.
        points: DMatrix<T>,
        /// `∂x/∂u` at the corners.
        du: DMatrix<T>,
        /// `∂x/∂v` at the corners.
        dv: DMatrix<T>,
    },
    /// Four boundary curves `[c1, c2, d1, d2]` = `x(u,0)`, `x(u,1)`, `x(0,v)`, `x(1,v)`, whose
    /// ends and end tangents (each curve's domain mapped onto `[0, 1]`) are the corner data.
    Boundary(Box<[CurveArg<T>; 4]>),
}

/// The Hermite bicubic (Ferguson) patch.
///
/// ```
/// use cagd_ops::{execute, ops::{Ferguson, FergusonData}, Context, Params};
/// use nalgebra::DMatrix;
/// // z = u·v: corner points, u-tangents (1, 0, v), v-tangents (0, 1, u), twists 1.
/// let m = |v: [f64; 12]| DMatrix::from_column_slice(3, 4, &v);
/// let mut op = Ferguson::new(FergusonData::Corners {
///     points: m([0., 0., 0., 1., 0., 0., 0., 1., 0., 1., 1., 1.]),
///     du: m([1., 0., 0., 1., 0., 0., 1., 0., 1., 1., 0., 1.]),
///     dv: m([0., 1., 0., 0., 1., 1., 0., 1., 0., 0., 1., 1.]),
/// });
/// op.twists = Some(m([0., 0., 1., 0., 0., 1., 0., 0., 1., 0., 0., 1.]));
/// op.at.u = Params::Given(vec![0.5]);
/// op.at.v = Params::Given(vec![0.25]);
/// let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[0.5, 0.25, 0.125]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug)]
pub struct Ferguson<T: Scalar> {
    /// The corner points and tangents, or the boundary curves they come from.
    pub data: FergusonData<T>,
    /// The twists `∂²x/∂u∂v` at the corners (`d × 4`; default zero, the notes' F-patch).
    pub twists: Option<DMatrix<T>>,
    /// Where: `u`, `v` (samples of `[0, 1]`), `--list` layout.
    pub at: SurfaceParams<T>,
    /// The geometry matrices `G_1 … G_d` as steps.
    pub steps: bool,
    /// A picture: the surface and its corners (and the boundary curves, if given).
    pub drawing: bool,
    /// The surface sampled for a mesh.
    pub mesh: bool,
}

impl<T: Scalar> Ferguson<T> {
    /// The patch of `data` with zero twists at the default parameters.
    pub fn new(data: FergusonData<T>) -> Self {
        Ferguson {
            data,
            twists: None,
            at: SurfaceParams::default(),
            steps: false,
            drawing: false,
            mesh: false,
        }
    }
}

/// Corner data `[i][j]` for the corner `(u, v) = (i, j)`.
type Corners<T> = [[DVector<T>; 2]; 2];

impl<T: Scalar> Operation<T> for Ferguson<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let (patch, curves) = self.patch(cx)?;
        let unit = (&T::zero(), &T::one());
        let (us, vs) = self
            .at
            .resolve((unit, unit), "the patch is extrapolated there", cx)?;
        let single = self.at.single();
        let pictures = self.drawing || self.mesh;
        let (pus, pvs) = if pictures {
            picture_grid((&us, &vs), single, (unit, unit))?
        } else {
            (Vec::new(), Vec::new())
        };
        let data_bits = patch
            .geometry()
            .iter()
            .map(|g| max_bits(g.iter()))
            .max()
            .unwrap_or(0);
        let (u_bits, v_bits) = (
            max_bits(us.iter().chain(&pus)),
            max_bits(vs.iter().chain(&pvs)),
        );
        let per_point = ferguson_point_cost(patch.dim(), u_bits, v_bits, data_bits);
        let points = evaluated_points((&us, &vs), pictures.then_some((&pus, &pvs)));
        cx.check_cost(Role::Grid, per_point.times(points), T::EXACT)?;
        let mut report = Report::new();
        if self.steps {
            for (k, g) in patch.geometry().iter().enumerate() {
                report.push(format!("G_{}", k + 1), Value::Matrix(g.clone()));
            }
        }
        report.push("u", Value::row(&us));
        report.push("v", Value::row(&vs));
        push_result(
            &mut report,
            (&patch, per_point),
            (&us, &vs),
            (single, self.at.list),
            cx,
        )?;
        let pictures = Pictures {
            at: (&us, &vs, single),
            grid: (&pus, &pvs),
            drawing: self.drawing,
            mesh: self.mesh,
        };
        answer(report, &patch, pictures, |grid| {
            Ok(picture(&patch, grid, curves))
        })
    }
}

impl<T: Scalar> Ferguson<T> {
    /// The patch, and the boundary curves sampled for a picture (`[c1, c2]` at the picture's
    /// `u`, `[d1, d2]` at its `v`) if they were given.
    #[allow(clippy::type_complexity)]
    fn patch(&self, cx: &mut Context) -> Result<(FergusonPatch<T>, Option<[DMatrix<f64>; 4]>)> {
        match &self.data {
            FergusonData::Corners { points, du, dv } => {
                let points = corners(Role::Points, points, None)?;
                let d = points[0][0].len();
                let du = corners(Role::Du, du, Some(d))?;
                let dv = corners(Role::Dv, dv, Some(d))?;
                let twists = self.twists(d)?;
                let patch = FergusonPatch::new(&points, &du, &dv, &twists)
                    .map_err(lib(Role::Points, CORNERS_FORM))?;
                Ok((patch, None))
            }
            FergusonData::Boundary(boundary) => self.of_boundary(cx, boundary),
        }
    }

    /// The patch of the boundary curves' corner data.
    #[allow(clippy::type_complexity)]
    fn of_boundary(
        &self,
        cx: &mut Context,
        boundary: &[CurveArg<T>; 4],
    ) -> Result<(FergusonPatch<T>, Option<[DMatrix<f64>; 4]>)> {
        // The curves' ends and end tangents; a picture draws them along 21 samples.
        let at = cagd::linspace::linspace_in(&T::zero(), &T::one(), 21)
            .map_err(lib(Role::Boundary, BOUNDARY_FORM))?;
        let ends = [T::zero(), T::one()];
        let wanted: &[T] = if self.drawing { &at } else { &ends };
        let parts: Vec<(Role, &CurveArg<T>, &[T])> = BOUNDARY_ROLES
            .into_iter()
            .zip(boundary.iter())
            .map(|(r, c)| (r, c, wanted))
            .collect();
        check_curves_work(cx, &parts)?;
        let [c1, c2, d1, d2] = realise_all(&parts, true)?;
        let checked = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default())
            .map_err(lib(Role::Boundary, BOUNDARY_FORM))?;
        let twists = self.twists(checked.dim())?;
        let patch = FergusonPatch::from_boundary(&checked, &twists)
            .map_err(lib(Role::Boundary, BOUNDARY_FORM))?;
        if !self.drawing {
            return Ok((patch, None));
        }
        let (c1, c2, d1, d2) = checked.curves();
        let lines = [
            boundary_line(c1, &at)?,
            boundary_line(c2, &at)?,
            boundary_line(d1, &at)?,
            boundary_line(d2, &at)?,
        ];
        Ok((patch, Some(lines)))
    }

    /// The twists (zero unless given) for points of dimension `d`.
    fn twists(&self, d: usize) -> Result<Corners<T>> {
        match &self.twists {
            Some(m) => corners(Role::Twists, m, Some(d)),
            None => Ok(std::array::from_fn(|_| {
                std::array::from_fn(|_| DVector::from_element(d, T::zero()))
            })),
        }
    }
}

/// A `d × 4` matrix of corner vectors as `[i][j]` for the corner `(u, v) = (i, j)`, of the
/// dimension `d` of the points if known.
fn corners<T: Scalar>(role: Role, m: &DMatrix<T>, d: Option<usize>) -> Result<Corners<T>> {
    if m.ncols() != 4 || m.nrows() == 0 {
        return Err(OpError::new(
            role,
            Kind::Shape,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            CORNERS_FORM,
        ));
    }
    if let Some(k) = m.iter().position(|x| !x.is_finite_value()) {
        return Err(OpError::new(
            role,
            Kind::NonFinite,
            format!("entry {} is not finite ({})", k + 1, m[k].to_f64()),
            CORNERS_FORM,
        ));
    }
    if let Some(d) = d.filter(|d| *d != m.nrows()) {
        return Err(OpError::new(
            role,
            Kind::Shape,
            format!(
                "vectors of dimension {}, the corner points have {d}",
                m.nrows()
            ),
            CORNERS_FORM,
        ));
    }
    let c = |k: usize| m.column(k).into_owned();
    Ok([[c(0), c(2)], [c(1), c(3)]])
}

/// The picture: the surface, the corners around the square (and the boundary curves).
fn picture<T: Scalar>(
    patch: &FergusonPatch<T>,
    grid: cagd::grid::PointGrid<f64>,
    curves: Option<[DMatrix<f64>; 4]>,
) -> Drawing {
    // Around the square: (0,0), (1,0), (1,1), (0,1).
    let (o, l) = (T::zero(), T::one());
    let ring =
        [(&o, &o), (&l, &o), (&l, &l), (&o, &l)].map(|(u, v)| patch.eval(u.clone(), v.clone()));
    let mut drawing = Drawing::new("Ferguson (Hermite bicubic) patch")
        .surface(grid, "x(u,v)")
        .control_polygon(to_f64(&DMatrix::from_columns(&ring)), "corners");
    if let Some([c1, c2, d1, d2]) = curves {
        drawing = drawing
            .boundary(c1, Colour::Red, "c1, c2")
            .boundary(c2, Colour::Red, "")
            .boundary(d1, Colour::Green, "d1, d2")
            .boundary(d2, Colour::Green, "");
    }
    drawing
}
