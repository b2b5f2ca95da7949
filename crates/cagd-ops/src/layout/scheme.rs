//! The de Casteljau schemes as report values: the triangle of the thesis for people (numbers
//! as readable text prints them), the levels for programs (JSON, Octave's format, CSV).

use cagd::bezier::{DeCasteljauScheme, PatchScheme};
use cagd::grid::PointGrid;
use cagd::Scalar;

use crate::{number_text_digits, Item, Value};

/// Which points of a curve scheme to mark: the subdivision's two control polygons.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Marks {
    /// No marks (`decasteljau --steps`).
    None,
    /// `L` before `b_0^r` (the diagonal: the left part's control points) and `R` before
    /// `b_{n−r}^r` (the last row: the right part's), `LR` on the point on the curve.
    Subdivision,
}

/// A curve scheme: the triangle (row `k` lists `b_k^0, b_{k−1}^1, …, b_0^k`, so column `r` is
/// level `r`, as thesis Primer 2.4 prints it) and the levels `r0 … rn` (`d × (n+1−r)`).
pub fn curve_scheme<T: Scalar>(
    scheme: &DeCasteljauScheme<T>,
    digits: usize,
    marks: Marks,
) -> Value<T> {
    let text = triangle(scheme, &cells(scheme, digits, marks), digits, marks);
    let levels = scheme
        .levels()
        .iter()
        .enumerate()
        .map(|(r, m)| Item {
            name: format!("r{r}"),
            value: Value::Matrix(m.clone()),
        })
        .collect();
    Value::Shown {
        text,
        data: Box::new(Value::Record(levels)),
    }
}

/// The points of the scheme as text, level by level (`cells[r][i]` is `b_i^r`), each with its
/// mark.
fn cells<T: Scalar>(
    scheme: &DeCasteljauScheme<T>,
    digits: usize,
    marks: Marks,
) -> Vec<Vec<String>> {
    let n = scheme.degree();
    let point = |r: usize, i: usize| {
        let level = &scheme.levels()[r];
        let coords: Vec<String> = level
            .column(i)
            .iter()
            .map(|x| number_text_digits(x, digits))
            .collect();
        let tag = match marks {
            Marks::None => "",
            Marks::Subdivision => match (i == 0, i + r == n) {
                (true, true) => "LR",
                (true, false) => "L",
                (false, true) => "R",
                (false, false) => "",
            },
        };
        format!("{tag}({})", coords.join(", "))
    };
    (0..=n)
        .map(|r| (0..=n - r).map(|i| point(r, i)).collect())
        .collect()
}

/// The triangle of the scheme's `cells`: row `k` lists `b_k^0, b_{k−1}^1, …, b_0^k`, each
/// column as wide as its widest cell, under a title and the column heads `r = …`.
fn triangle<T: Scalar>(
    scheme: &DeCasteljauScheme<T>,
    cells: &[Vec<String>],
    digits: usize,
    marks: Marks,
) -> String {
    let n = scheme.degree();
    let widths: Vec<usize> = (0..=n)
        .map(|r| {
            cells[r]
                .iter()
                .map(|s| s.chars().count())
                .chain([format!("r = {r}").chars().count()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut text = format!(
        "de Casteljau scheme, degree {n}, t = {}\n",
        number_text_digits(scheme.parameter(), digits)
    );
    if marks == Marks::Subdivision {
        text.push_str(
            "L: control points of the part before t (the diagonal b_0^r), R: of the part after t (the last row b_(n-r)^r)\n",
        );
    }
    let header: Vec<String> = (0..=n)
        .map(|r| format!("{:<w$}", format!("r = {r}"), w = widths[r]))
        .collect();
    text.push_str(header.join("   ").trim_end());
    text.push('\n');
    for k in 0..=n {
        let row: Vec<String> = (0..=k)
            .map(|r| format!("{:<w$}", cells[r][k - r], w = widths[r]))
            .collect();
        text.push_str(row.join("   ").trim_end());
        text.push('\n');
    }
    text
}

/// A patch scheme: its own text (thesis §3.2) and its nets, `level_0 …` as grids.
pub fn patch_scheme<T: Scalar>(scheme: &PatchScheme<T>) -> Value<T> {
    let mut levels = Vec::with_capacity(scheme.level_count());
    for k in 0..scheme.level_count() {
        let (Some(coords), Some((m, n))) = (scheme.level(k), scheme.level_shape(k)) else {
            continue;
        };
        let d = coords.len();
        let grid = PointGrid::from_shape_fn((m, n, d), |(i, j, c)| coords[c][(i, j)].clone());
        levels.push(Item {
            name: format!("level_{k}"),
            value: Value::Grid(grid),
        });
    }
    Value::Shown {
        text: scheme.to_string(),
        data: Box::new(Value::Record(levels)),
    }
}
