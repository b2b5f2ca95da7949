//! What the two worked-example commands (`cagd thesis`, `cagd course`) share: exact numbers,
//! headings and reports as text, the pictures and meshes they stage, appendix C's picture.

use std::fmt::Write as _;
use std::path::Path;

use cagd::grid::PointGrid;
use cagd::Curve;
use cagd_octave::literal::LiteralScalar;
use nalgebra::DMatrix;
use num_rational::BigRational;

use super::common::{add_mesh, add_plot, sample, to_f64};
use crate::plot::{Colour, Figure};
use crate::{render, CliError, ErrorKind, Format, PendingWrites, Report};

/// The exact numbers of the examples.
pub(super) type Q = BigRational;

/// The fraction `num/den`.
pub(super) fn q(num: i64, den: i64) -> Q {
    Q::new(num.into(), den.into())
}

/// A report as the command line prints it.
pub(super) fn text<T: LiteralScalar>(report: &Report<T>) -> String {
    render(report, Format::Text).unwrap_or_default()
}

/// A title underlined with `=`.
pub(super) fn heading(out: &mut String, title: &str) {
    let _ = writeln!(out, "{title}\n{}\n", "=".repeat(title.chars().count()));
}

/// The pictures and meshes of a worked-examples command, staged until everything is computed.
pub(super) struct Files<'a> {
    /// The folder they go to.
    pub(super) dir: &'a Path,
    /// The files staged.
    pub(super) pending: PendingWrites,
    /// Their names, in order.
    pub(super) written: Vec<String>,
}

impl Files<'_> {
    /// The picture `name` in every picture format.
    pub(super) fn picture(&mut self, name: &str, figure: &Figure) -> Result<(), CliError> {
        for ext in crate::plot::PICTURE_EXTENSIONS {
            let file = format!("{name}.{ext}");
            add_plot(&mut self.pending, "--out", &self.dir.join(&file), figure)?;
            self.written.push(file);
        }
        Ok(())
    }

    /// The surface `name` in every mesh format.
    pub(super) fn meshes(&mut self, name: &str, grid: &PointGrid<f64>) -> Result<(), CliError> {
        for ext in ["stl", "obj", "ply"] {
            let file = format!("{name}.{ext}");
            add_mesh(&mut self.pending, "--out", &self.dir.join(&file), grid)?;
            self.written.push(file);
        }
        Ok(())
    }
}

/// The polyline a picture draws of a curve (its points at parameters by `eval`, in doubles)
/// over `[a, b]`: from `first` uniform samples, as many more as keep its chords a few pixels
/// long and close to the curve ([`cagd_ops::picture`]).
pub(super) fn dense_line<T: LiteralScalar>(
    (a, b): (&T, &T),
    first: usize,
    eval: impl Fn(&[T]) -> DMatrix<f64>,
) -> Result<DMatrix<f64>, CliError> {
    cagd_ops::picture::picture_line((a, b), first, false, |ts| Ok(eval(ts)), |_| true).map_err(
        |e| {
            CliError::new(
                "picture",
                e.to_string(),
                "a valid built-in example",
                ErrorKind::Internal,
            )
        },
    )
}

/// The polyline a picture draws of `curve` over `[a, b]` ([`dense_line`]).
pub(super) fn curve_line<T: LiteralScalar, C: Curve<T>>(
    curve: &C,
    (a, b): (&T, &T),
    first: usize,
) -> Result<DMatrix<f64>, CliError> {
    dense_line((a, b), first, |ts| to_f64(&sample(curve, ts)))
}

/// The picture of appendix C: the surface, c1 and c2 in red, d1 and d2 in green. Each curve
/// is drawn as the patch uses it: its domain `[a, b]` mapped onto the grid's `[0, 1]`.
pub(super) fn coons_figure<T: LiteralScalar, C: Curve<T>>(
    title: &str,
    grid: PointGrid<f64>,
    [c1, c2, d1, d2]: [&C; 4],
    us: &[T],
    vs: &[T],
) -> Figure {
    let along = |c: &C, ts: &[T]| {
        let (a, b) = c.domain();
        let own: Vec<T> = ts
            .iter()
            .map(|s| a.clone() + (b.clone() - a.clone()) * s.clone())
            .collect();
        to_f64(&sample(c, &own))
    };
    Figure::new(title)
        .surface(grid, "x(u,v)")
        .boundary(along(c1, us), Colour::Red, "c1, c2")
        .boundary(along(c2, us), Colour::Red, "")
        .boundary(along(d1, vs), Colour::Green, "d1, d2")
        .boundary(along(d2, vs), Colour::Green, "")
}
