//! What the surface constructions share: the grid they are evaluated on (or a single point),
//! the layout of a surface result, the pictures' grid.

use cagd::grid::PointGrid;
use cagd::Scalar;
use nalgebra::{DMatrix, DVector};

use crate::error::Result;
use crate::{Context, Params, Report, Role, Value};

/// The parameters of a surface request.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceParams<T> {
    /// The `u` values (samples cover the domain in `u`).
    pub u: Params<T>,
    /// The `v` values.
    pub v: Params<T>,
    /// One row `u v x y z` per grid point instead of the `nu × nv × d` grid.
    pub list: bool,
}

impl<T> Default for SurfaceParams<T> {
    /// The default samples in both directions, as a grid.
    fn default() -> Self {
        SurfaceParams {
            u: Params::Default,
            v: Params::Default,
            list: false,
        }
    }
}

impl<T: Scalar> SurfaceParams<T> {
    /// Whether one `u` and one `v` are given: the result is then a point (a `d × 1` column).
    pub fn single(&self) -> bool {
        matches!((&self.u, &self.v), (Params::Given(u), Params::Given(v)) if u.len() == 1 && v.len() == 1)
    }

    /// The `u` and `v` values on the domain `[a, b] × [c, d]`, checked against the grid limit;
    /// `consequence` says what happens outside the domain.
    pub fn resolve(
        &self,
        ((a, b), (c, d)): ((&T, &T), (&T, &T)),
        consequence: &str,
        cx: &mut Context,
    ) -> Result<(Vec<T>, Vec<T>)> {
        let us = self.u.resolve(Role::U, (a, b), consequence, cx)?;
        let vs = self.v.resolve(Role::V, (c, d), consequence, cx)?;
        cx.check_grid(Role::Grid, us.len(), vs.len())?;
        Ok((us, vs))
    }
}

/// The grid of a surface's picture or mesh: the result's, or 21 × 21 samples of the domain
/// when the result is a single point.
pub fn picture_grid<T: Scalar>(
    (us, vs): (&[T], &[T]),
    single: bool,
    ((a, b), (c, d)): ((&T, &T), (&T, &T)),
) -> Result<(Vec<T>, Vec<T>)> {
    if !single {
        return Ok((us.to_vec(), vs.to_vec()));
    }
    let lin = |x: &T, y: &T| {
        cagd::linspace::linspace_in(x, y, 21).map_err(crate::error::lib(Role::U, "a grid"))
    };
    Ok((lin(a, b)?, lin(c, d)?))
}

/// The number of points evaluated: the result's, and the picture's if any.
pub fn evaluated_points<T>((us, vs): (&[T], &[T]), picture: Option<(&[T], &[T])>) -> u128 {
    let n = |a: &[T], b: &[T]| a.len() as u128 * b.len() as u128;
    n(us, vs) + picture.map_or(0, |(a, b)| n(a, b))
}

/// Pushes a surface result: the grid `us × vs × d` (`result(i,j,:)` at `(us[i], vs[j])`), or
/// with `list` a matrix with one row `u v x y z` per grid point, `u` varying slowest.
pub fn push_surface<T: Scalar>(
    report: &mut Report<T>,
    name: &str,
    (us, vs): (&[T], &[T]),
    grid: PointGrid<T>,
    list: bool,
) {
    if !list {
        report.push(name, Value::Grid(grid));
        return;
    }
    let (nu, nv, d) = grid.dim();
    let rows = DMatrix::from_fn(nu * nv, d + 2, |k, c| {
        let (i, j) = (k / nv, k % nv);
        match c {
            0 => us[i].clone(),
            1 => vs[j].clone(),
            _ => grid[[i, j, c - 2]].clone(),
        }
    });
    report.push(name, Value::Matrix(rows));
}

/// The result of a surface that is a sum of terms (Coons: x = rc + rd − rcd; Gordon:
/// g = g1 + g2 − g12), `terms(u, v)` giving the three terms and the sum: at a single point the
/// d×1 columns, else the grids `us × vs × d`; the three terms too, under `names`, with steps.
#[allow(clippy::too_many_arguments)]
pub fn push_terms<T: Scalar>(
    report: &mut Report<T>,
    names: [&str; 3],
    (steps, list, single): (bool, bool, bool),
    (us, vs): (&[T], &[T]),
    d: usize,
    cx: &Context,
    terms: impl Fn(T, T) -> [DVector<T>; 4],
) -> Result<()> {
    if single && !list {
        let [a, b, c, x] = terms(us[0].clone(), vs[0].clone());
        if steps {
            for (name, term) in names.into_iter().zip([a, b, c]) {
                report.push(name, Value::column(&term));
            }
        }
        report.push("result", Value::column(&x));
        return Ok(());
    }
    let shape = (us.len(), vs.len(), d);
    let mut grids: [PointGrid<T>; 4] =
        std::array::from_fn(|_| PointGrid::from_elem(shape, T::zero()));
    for (i, u) in us.iter().enumerate() {
        cx.check_interrupt()?;
        for (j, v) in vs.iter().enumerate() {
            for (grid, term) in grids.iter_mut().zip(terms(u.clone(), v.clone())) {
                for k in 0..d {
                    grid[[i, j, k]] = term[k].clone();
                }
            }
        }
    }
    let [a, b, c, x] = grids;
    if steps {
        for (name, grid) in names.into_iter().zip([a, b, c]) {
            push_surface(report, name, (us, vs), grid, list);
        }
    }
    push_surface(report, "result", (us, vs), x, list);
    Ok(())
}

/// A grid in doubles, for pictures and meshes.
pub fn grid_f64<T: Scalar>(g: &PointGrid<T>) -> PointGrid<f64> {
    g.map(|x| x.to_f64())
}
