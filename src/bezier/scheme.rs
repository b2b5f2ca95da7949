//! The de Casteljau schemes: every intermediate point of one evaluation, level by level.
//!
//! For a curve this is the triangle of thesis §2.1 (Primer 2.4 prints one); for a patch it is
//! the sequence of shrinking nets of the tensor algorithm of §3.2.

use std::fmt;

use nalgebra::{DMatrix, DVector};

use super::bilinear::BilinearWeights;
use super::format_point;
use crate::scalar::Scalar;

/// One de Casteljau step `b_i^r = s · b_i^{r−1} + t · b_{i+1}^{r−1}` on all columns, with
/// `(s, t) = (1 − t, t)` on `[0, 1]`, in exactly that operation order.
pub(crate) fn curve_step<T: Scalar>(prev: &DMatrix<T>, s: &T, t: &T) -> DMatrix<T> {
    let cols = prev.ncols() - 1;
    DMatrix::from_fn(prev.nrows(), cols, |c, i| {
        s.clone() * prev[(c, i)].clone() + t.clone() * prev[(c, i + 1)].clone()
    })
}

/// The full de Casteljau scheme of a Bézier curve at one parameter (thesis §2.1, eq. (2.1)):
///
/// ```text
/// b_i^0 = b_i,   b_i^r = (1 − t) b_i^{r−1} + t b_{i+1}^{r−1},   i = 0, …, n − r,  r = 1, …, n.
/// ```
///
/// Level `r` is a `d × (n + 1 − r)` matrix whose column `i` is `b_i^r`; level 0 is the control
/// polygon and level `n` holds the single point `b_0^n(t)` on the curve. On an interval
/// `[a, b]` the weights are `(b − u)/(b − a)` and `(u − a)/(b − a)` (thesis §2.3.2).
///
/// Its [`Display`](fmt::Display) prints the triangle as the thesis does: row `k` lists
/// `b_k^0, b_{k−1}^1, …, b_0^k`, so column `r` is level `r`. A precision given to the formatter
/// applies to every coordinate.
///
/// ```
/// use cagd::bezier::BezierCurve;
/// use nalgebra::DMatrix;
/// let curve = BezierCurve::new(DMatrix::from_column_slice(
///     3,
///     4,
///     &[0.0, 0.0, 0.0, 0.0, 2.0, 2.0, 8.0, 2.0, 0.0, 4.0, 0.0, 0.0],
/// ))?;
/// let scheme = curve.scheme(0.5);
/// assert_eq!(scheme.point(2, 1).unwrap().as_slice(), &[5.0, 1.5, 0.5]);
/// assert_eq!(scheme.point_on_curve().as_slice(), &[3.5, 1.5, 0.75]);
/// println!("{scheme}");
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct DeCasteljauScheme<T: Scalar = f64> {
    parameter: T,
    levels: Vec<DMatrix<T>>,
}

impl<T: Scalar> DeCasteljauScheme<T> {
    /// Runs the scheme on `control` (at least one column) with weights `(s, t)`.
    pub(crate) fn compute(control: &DMatrix<T>, s: &T, t: &T, parameter: T) -> Self {
        let n = control.ncols() - 1;
        let mut levels = Vec::with_capacity(n + 1);
        levels.push(control.clone());
        for r in 1..=n {
            let next = curve_step(&levels[r - 1], s, t);
            levels.push(next);
        }
        DeCasteljauScheme { parameter, levels }
    }

    /// The parameter the scheme was computed at.
    pub fn parameter(&self) -> &T {
        &self.parameter
    }

    /// The degree `n` of the curve (the scheme has `n + 1` levels).
    pub fn degree(&self) -> usize {
        self.levels.len() - 1
    }

    /// The dimension `d` of the points.
    pub fn dim(&self) -> usize {
        self.levels[0].nrows()
    }

    /// All levels: `levels()[r]` is the `d × (n + 1 − r)` matrix of the points `b_i^r`.
    pub fn levels(&self) -> &[DMatrix<T>] {
        &self.levels
    }

    /// Level `r` (`None` if `r > n`).
    pub fn level(&self, r: usize) -> Option<&DMatrix<T>> {
        self.levels.get(r)
    }

    /// The point `b_i^r` (`None` unless `r ≤ n` and `i ≤ n − r`).
    pub fn point(&self, r: usize, i: usize) -> Option<DVector<T>> {
        let level = self.levels.get(r)?;
        (i < level.ncols()).then(|| level.column(i).into_owned())
    }

    /// The last point `b_0^n`, the point on the curve.
    pub fn point_on_curve(&self) -> DVector<T> {
        self.levels[self.degree()].column(0).into_owned()
    }

    /// The control polygon `b_0^0, b_0^1, …, b_0^n` of the part of the curve before the
    /// parameter (the upper edge of the triangle), as a `d × (n + 1)` matrix.
    pub fn left_control(&self) -> DMatrix<T> {
        let columns: Vec<DVector<T>> = self
            .levels
            .iter()
            .map(|level| level.column(0).into_owned())
            .collect();
        DMatrix::from_columns(&columns)
    }

    /// The control polygon `b_0^n, b_1^{n−1}, …, b_n^0` of the part of the curve after the
    /// parameter (the lower edge of the triangle), as a `d × (n + 1)` matrix.
    pub fn right_control(&self) -> DMatrix<T> {
        let n = self.degree();
        let columns: Vec<DVector<T>> = (0..=n)
            .map(|j| self.levels[n - j].column(j).into_owned())
            .collect();
        DMatrix::from_columns(&columns)
    }
}

impl<T: Scalar> fmt::Display for DeCasteljauScheme<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.degree();
        let precision = f.precision();
        // cells[r][i] = text of b_i^r
        let cells: Vec<Vec<String>> = self
            .levels
            .iter()
            .map(|level| {
                level
                    .column_iter()
                    .map(|c| format_point(c.iter(), precision))
                    .collect()
            })
            .collect();
        let widths: Vec<usize> = (0..=n)
            .map(|r| {
                let head = format!("r = {r}").chars().count();
                cells[r]
                    .iter()
                    .map(|s| s.chars().count())
                    .max()
                    .unwrap_or(0)
                    .max(head)
            })
            .collect();
        writeln!(f, "de Casteljau scheme, degree {n}, t = {}", self.parameter)?;
        let header: Vec<String> = (0..=n)
            .map(|r| format!("{:<w$}", format!("r = {r}"), w = widths[r]))
            .collect();
        writeln!(f, "{}", header.join("   ").trim_end())?;
        for k in 0..=n {
            // Row k: b_k^0, b_{k−1}^1, …, b_0^k.
            let row: Vec<String> = (0..=k)
                .map(|r| format!("{:<w$}", cells[r][k - r], w = widths[r]))
                .collect();
            writeln!(f, "{}", row.join("   ").trim_end())?;
        }
        Ok(())
    }
}

/// The kind of one step of the tensor de Casteljau algorithm for patches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PatchStep {
    /// A bilinear step in both directions:
    /// `b_{i,j} ← (1−u)(1−v) b_{i,j} + u(1−v) b_{i+1,j} + (1−u)v b_{i,j+1} + uv b_{i+1,j+1}`;
    /// both degrees drop by one.
    Bilinear,
    /// A linear step in `u` only, `b_{i,j} ← (1−u) b_{i,j} + u b_{i+1,j}` (taken once the `v`
    /// degree is used up); the `u` degree drops by one.
    LinearU,
    /// A linear step in `v` only, `b_{i,j} ← (1−v) b_{i,j} + v b_{i,j+1}` (taken once the `u`
    /// degree is used up); the `v` degree drops by one.
    LinearV,
}

/// One patch step on every coordinate matrix.
pub(crate) fn patch_step<T: Scalar>(
    net: &[DMatrix<T>],
    step: PatchStep,
    u: &T,
    v: &T,
) -> Vec<DMatrix<T>> {
    match step {
        PatchStep::Bilinear => {
            let w = BilinearWeights::new(u, v);
            net.iter()
                .map(|x| {
                    DMatrix::from_fn(x.nrows() - 1, x.ncols() - 1, |i, j| {
                        w.combine(
                            &x[(i, j)],
                            &x[(i + 1, j)],
                            &x[(i, j + 1)],
                            &x[(i + 1, j + 1)],
                        )
                    })
                })
                .collect()
        }
        PatchStep::LinearU => {
            let s = T::one() - u.clone();
            net.iter()
                .map(|x| {
                    DMatrix::from_fn(x.nrows() - 1, x.ncols(), |i, j| {
                        s.clone() * x[(i, j)].clone() + u.clone() * x[(i + 1, j)].clone()
                    })
                })
                .collect()
        }
        PatchStep::LinearV => {
            let s = T::one() - v.clone();
            net.iter()
                .map(|x| {
                    DMatrix::from_fn(x.nrows(), x.ncols() - 1, |i, j| {
                        s.clone() * x[(i, j)].clone() + v.clone() * x[(i, j + 1)].clone()
                    })
                })
                .collect()
        }
    }
}

/// One patch step in place on the leading `rows × cols` block of every coordinate matrix (the
/// arithmetic of [`patch_step`], bit for bit); returns the new active shape. Entries are
/// overwritten in increasing `(i, j)`, so every read of `(i + 1, j)` or `(i, j + 1)` still sees
/// the previous level.
pub(crate) fn patch_step_in_place<T: Scalar>(
    net: &mut [DMatrix<T>],
    (rows, cols): (usize, usize),
    step: PatchStep,
    u: &T,
    v: &T,
) -> (usize, usize) {
    match step {
        PatchStep::Bilinear => {
            let w = BilinearWeights::new(u, v);
            for x in net.iter_mut() {
                for i in 0..rows - 1 {
                    for j in 0..cols - 1 {
                        x[(i, j)] = w.combine(
                            &x[(i, j)],
                            &x[(i + 1, j)],
                            &x[(i, j + 1)],
                            &x[(i + 1, j + 1)],
                        );
                    }
                }
            }
            (rows - 1, cols - 1)
        }
        PatchStep::LinearU => {
            let s = T::one() - u.clone();
            for x in net.iter_mut() {
                for i in 0..rows - 1 {
                    for j in 0..cols {
                        x[(i, j)] =
                            s.clone() * x[(i, j)].clone() + u.clone() * x[(i + 1, j)].clone();
                    }
                }
            }
            (rows - 1, cols)
        }
        PatchStep::LinearV => {
            let s = T::one() - v.clone();
            for x in net.iter_mut() {
                for i in 0..rows {
                    for j in 0..cols - 1 {
                        x[(i, j)] =
                            s.clone() * x[(i, j)].clone() + v.clone() * x[(i, j + 1)].clone();
                    }
                }
            }
            (rows, cols - 1)
        }
    }
}

/// The steps of the tensor de Casteljau algorithm for degree `(m, n)`: `min(m, n)` bilinear
/// steps, then `|m − n|` linear steps in the direction whose degree remains.
pub(crate) fn patch_steps(m: usize, n: usize) -> impl Iterator<Item = PatchStep> {
    let both = m.min(n);
    let rest = if m > n {
        PatchStep::LinearU
    } else {
        PatchStep::LinearV
    };
    std::iter::repeat_n(PatchStep::Bilinear, both).chain(std::iter::repeat_n(rest, m.max(n) - both))
}

/// The full tensor de Casteljau scheme of a Bézier patch at `(u, v)` (thesis §3.2, fixed for
/// `m ≠ n`).
///
/// Level 0 is the control net; each further level comes from the previous one by a
/// [`PatchStep`]: `min(m, n)` bilinear steps `b_{i,j}^{k,k}` (thesis §3.2), then linear steps in
/// the direction whose degree remains, until one point — the point on the patch — is left. A
/// level is stored like the patch itself, one matrix per coordinate, entry `(i, j)` belonging
/// to the point with indices `i` (along `u`) and `j` (along `v`).
///
/// Its [`Display`](fmt::Display) prints every level as a grid of points, one row per `i`.
///
/// ```
/// use cagd::bezier::{BezierPatch, PatchStep};
/// // Degree (2, 1): one bilinear step, then one linear step in u.
/// let patch = BezierPatch::from_net(&[
///     vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
///     vec![[1.0, 0.0, 1.0], [1.0, 1.0, 1.0]],
///     vec![[2.0, 0.0, 0.0], [2.0, 1.0, 0.0]],
/// ])?;
/// let scheme = patch.scheme(0.5, 0.5);
/// assert_eq!(scheme.steps(), &[PatchStep::Bilinear, PatchStep::LinearU]);
/// assert_eq!(scheme.level_shape(1), Some((2, 1)));
/// assert_eq!(scheme.point_on_surface().as_slice(), &[1.0, 0.5, 0.5]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PatchScheme<T: Scalar = f64> {
    u: T,
    v: T,
    levels: Vec<Vec<DMatrix<T>>>,
    steps: Vec<PatchStep>,
}

impl<T: Scalar> PatchScheme<T> {
    /// Runs the scheme on a validated net (one non-empty matrix per coordinate, all the same
    /// shape).
    pub(crate) fn compute(net: &[DMatrix<T>], u: T, v: T) -> Self {
        let (m, n) = (net[0].nrows() - 1, net[0].ncols() - 1);
        let steps: Vec<PatchStep> = patch_steps(m, n).collect();
        let mut levels = Vec::with_capacity(steps.len() + 1);
        levels.push(net.to_vec());
        for (k, &step) in steps.iter().enumerate() {
            let next = patch_step(&levels[k], step, &u, &v);
            levels.push(next);
        }
        PatchScheme {
            u,
            v,
            levels,
            steps,
        }
    }

    /// The parameters `(u, v)` the scheme was computed at.
    pub fn parameters(&self) -> (&T, &T) {
        (&self.u, &self.v)
    }

    /// The number of levels, `max(m, n) + 1` (level 0 is the control net).
    pub fn level_count(&self) -> usize {
        self.levels.len()
    }

    /// The steps taken: `steps()[k]` leads from level `k` to level `k + 1`.
    pub fn steps(&self) -> &[PatchStep] {
        &self.steps
    }

    /// Level `k`, one matrix per coordinate (`None` past the last level).
    pub fn level(&self, k: usize) -> Option<&[DMatrix<T>]> {
        self.levels.get(k).map(Vec::as_slice)
    }

    /// The shape `(rows along u, columns along v)` of level `k`.
    pub fn level_shape(&self, k: usize) -> Option<(usize, usize)> {
        self.levels.get(k).map(|l| l[0].shape())
    }

    /// The point with indices `(i, j)` of level `k`.
    pub fn point(&self, k: usize, i: usize, j: usize) -> Option<DVector<T>> {
        let level = self.levels.get(k)?;
        let (rows, cols) = level[0].shape();
        (i < rows && j < cols)
            .then(|| DVector::from_iterator(level.len(), level.iter().map(|x| x[(i, j)].clone())))
    }

    /// The single point of the last level: the point on the patch.
    pub fn point_on_surface(&self) -> DVector<T> {
        let last = &self.levels[self.levels.len() - 1];
        DVector::from_iterator(last.len(), last.iter().map(|x| x[(0, 0)].clone()))
    }
}

impl<T: Scalar> fmt::Display for PatchScheme<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let precision = f.precision();
        writeln!(
            f,
            "tensor de Casteljau scheme, u = {}, v = {}",
            self.u, self.v
        )?;
        for (k, level) in self.levels.iter().enumerate() {
            let (rows, cols) = level[0].shape();
            let how = match k.checked_sub(1).map(|s| self.steps[s]) {
                None => "control net".to_string(),
                Some(PatchStep::Bilinear) => "bilinear step".to_string(),
                Some(PatchStep::LinearU) => "linear step in u".to_string(),
                Some(PatchStep::LinearV) => "linear step in v".to_string(),
            };
            writeln!(f, "level {k} ({how}), {rows} × {cols}:")?;
            let cells: Vec<Vec<String>> = (0..rows)
                .map(|i| {
                    (0..cols)
                        .map(|j| format_point(level.iter().map(|x| &x[(i, j)]), precision))
                        .collect()
                })
                .collect();
            let widths: Vec<usize> = (0..cols)
                .map(|j| {
                    cells
                        .iter()
                        .map(|row| row[j].chars().count())
                        .max()
                        .unwrap_or(0)
                })
                .collect();
            for row in &cells {
                let line: Vec<String> = row
                    .iter()
                    .zip(&widths)
                    .map(|(s, &w)| format!("{s:<w$}"))
                    .collect();
                writeln!(f, "  {}", line.join("   ").trim_end())?;
            }
        }
        Ok(())
    }
}
