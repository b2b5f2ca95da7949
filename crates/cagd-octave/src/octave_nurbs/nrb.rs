//! The octave-nurbs NURBS structure (`nrbmak`): the fields as octave-nurbs' functions read
//! them ([`NrbParts`]), and the structure they build ([`Nrb`], [`nrbmak`]).

use std::borrow::Cow;

use nalgebra::DMatrix;

use cagd::bspline::BSplineCurve;
use cagd::nurbs::NurbsCurve;

use super::basis::truncate;
use super::error::{NurbsError, Result};

/// The `knots` field: a vector (a curve), or a cell of vectors.
#[derive(Debug, Clone, PartialEq)]
pub enum Knots<'a> {
    /// One knot vector (read in Octave's storage order).
    Vector(&'a [f64]),
    /// A cell: `size (knots, 2)` (octave-nurbs tells surfaces from volumes by it) and the
    /// items in storage order.
    Cell {
        /// `size (knots, 2)`.
        cols: usize,
        /// The knot vectors.
        items: Vec<&'a [f64]>,
    },
}

/// The fields of an octave-nurbs NURBS structure as the caller holds them (borrowed, not
/// checked): `form` has been checked to be `"B-NURBS"`.
///
/// Layout (octave-nurbs' own): `coefs` is `4 × n1 × n2 × n3` in homogeneous coordinates
/// `(w·x, w·y, w·z, w)` (a curve `4 × n1`), `knots` one vector per direction, `order` the
/// degrees plus one, `number` the `n`s. Which field each function reads follows octave-nurbs:
/// `nrbeval` reshapes surfaces and volumes by `number` but hands a curve's `coefs` to `bspeval`
/// as they are, `nrbdegelev` takes the sizes of `coefs`, and so on.
#[derive(Debug, Clone, PartialEq)]
pub struct NrbParts<'a> {
    /// `coefs`, column-major.
    pub coefs: &'a [f64],
    /// `size (coefs)`.
    pub coef_dims: &'a [usize],
    /// `knots`.
    pub knots: Knots<'a>,
    /// `order`, as given.
    pub order: Cow<'a, [f64]>,
    /// `number`, as given.
    pub number: Cow<'a, [f64]>,
}

/// What a structure represents, as octave-nurbs' functions decide it: by whether `knots` is a
/// cell and then by `size (knots, 2)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// `knots` is not a cell.
    Curve,
    /// A cell with 2 columns.
    Surface,
    /// A cell with 3 columns.
    Volume,
    /// A cell with another number of columns (octave-nurbs' functions then fail).
    Other(usize),
}

impl<'a> NrbParts<'a> {
    /// Curve, surface or volume.
    pub fn kind(&self) -> Kind {
        match &self.knots {
            Knots::Vector(_) => Kind::Curve,
            Knots::Cell { cols: 2, .. } => Kind::Surface,
            Knots::Cell { cols: 3, .. } => Kind::Volume,
            Knots::Cell { cols, .. } => Kind::Other(*cols),
        }
    }

    /// `knots{k}` (0-based `k`), or the vector of a curve for `k = 0`.
    ///
    /// # Errors
    /// [`NurbsError::Index`] when there is no such item.
    pub fn knots(&self, k: usize) -> Result<&'a [f64]> {
        match &self.knots {
            Knots::Vector(v) if k == 0 => Ok(v),
            Knots::Cell { items, .. } if k < items.len() => Ok(items[k]),
            other => Err(NurbsError::Index {
                what: "knots",
                index: k as i64 + 1,
                bound: match other {
                    Knots::Vector(_) => 1,
                    Knots::Cell { items, .. } => items.len(),
                },
            }),
        }
    }

    /// `order(k) − 1`, the degree as octave-nurbs hands it to its compiled functions.
    ///
    /// # Errors
    /// [`NurbsError::Index`] when `order` has no entry `k`.
    pub fn degree(&self, k: usize) -> Result<f64> {
        self.order.get(k).map(|o| o - 1.0).ok_or(NurbsError::Index {
            what: "order",
            index: k as i64 + 1,
            bound: self.order.len(),
        })
    }

    /// `number(k)` as a count.
    ///
    /// # Errors
    /// [`NurbsError::Index`] when `number` has no entry `k`; [`NurbsError::Refused`] when it
    /// is not a non-negative integer (Octave's `reshape` refuses it).
    pub fn number(&self, k: usize) -> Result<usize> {
        let x = *self.number.get(k).ok_or(NurbsError::Index {
            what: "number",
            index: k as i64 + 1,
            bound: self.number.len(),
        })?;
        if x < 0.0 || x.fract() != 0.0 || x.is_nan() || x > 1e15 {
            return Err(NurbsError::refused(
                "number",
                format!("{x} is not a count (octave-nurbs reshapes coefs by it)"),
            ));
        }
        Ok(x as usize)
    }

    /// `number(1:dirs)`, checked against the number of coefficients as `reshape (coefs,
    /// 4*…)` checks them.
    ///
    /// # Errors
    /// As [`number`](Self::number); [`NurbsError::Refused`] when `4·prod(number)` differs from
    /// `numel (coefs)`.
    pub fn numbers(&self, dirs: usize) -> Result<Vec<usize>> {
        let n: Vec<usize> = (0..dirs).map(|k| self.number(k)).collect::<Result<_>>()?;
        let total = n.iter().try_fold(4usize, |a, &b| a.checked_mul(b));
        if total != Some(self.coefs.len()) {
            return Err(NurbsError::refused(
                "coefs",
                format!(
                    "{} coefficients cannot be reshaped to 4 × {} (the structure's number)",
                    self.coefs.len(),
                    n.iter()
                        .map(usize::to_string)
                        .collect::<Vec<_>>()
                        .join(" × ")
                ),
            ));
        }
        Ok(n)
    }

    /// `size (coefs, 1)` and the number of columns of `coefs` read as a matrix.
    pub fn coef_matrix(&self) -> (usize, usize) {
        let rows = self.coef_dims.first().copied().unwrap_or(0);
        (rows, self.coef_dims.iter().skip(1).product())
    }

    /// A curve as the core's B-spline curve of its homogeneous coefficients (`4 × n`,
    /// `(w·x, w·y, w·z, w)`): any weights, including zero and negative ones (the reusable
    /// reading for Rust callers; octave-nurbs' own evaluation rules are in
    /// [`NrbEval`](super::NrbEval)).
    ///
    /// # Errors
    /// [`NurbsError::Refused`] unless this is a curve with 4 coefficient rows and an integer
    /// order; the core's errors for its knots and coefficients (finite, `n + p + 1` knots,
    /// non-decreasing, a domain of positive length).
    pub fn to_homogeneous_curve(&self) -> Result<BSplineCurve> {
        let Knots::Vector(knots) = &self.knots else {
            return Err(NurbsError::refused("knots", "a cell: not a curve"));
        };
        let (rows, cols) = self.coef_matrix();
        if rows != 4 {
            return Err(NurbsError::refused(
                "coefs",
                format!("{rows} rows; a NURBS has 4 (w·x, w·y, w·z, w)"),
            ));
        }
        let d = self.degree(0)?;
        if d.fract() != 0.0 || d < 0.0 || self.order.len() != 1 {
            return Err(NurbsError::refused("order", "not one positive integer"));
        }
        let control = DMatrix::from_column_slice(4, cols, self.coefs);
        Ok(BSplineCurve::new(
            truncate(d) as usize,
            knots.to_vec(),
            control,
        )?)
    }

    /// A curve as the core's NURBS curve (`NurbsCurve::from_homogeneous`): weights must be
    /// positive there.
    ///
    /// # Errors
    /// As [`to_homogeneous_curve`](Self::to_homogeneous_curve); the core's
    /// `NonPositiveWeight`.
    pub fn to_nurbs_curve(&self) -> Result<NurbsCurve> {
        Ok(NurbsCurve::from_homogeneous(self.to_homogeneous_curve()?)?)
    }
}

/// An octave-nurbs NURBS structure as `nrbmak (coefs, knots)` builds it (owned): `form =
/// "B-NURBS"`, `dim = 4`, and the fields below.
#[derive(Debug, Clone, PartialEq)]
pub struct Nrb {
    /// `number`: the control points per direction.
    pub number: Vec<usize>,
    /// `coefs`, column-major, of size [`coef_dims`](Self::coef_dims).
    pub coefs: Vec<f64>,
    /// `size (coefs)`: `4 × number` (a curve `4 × n`).
    pub coef_dims: Vec<usize>,
    /// `knots`, sorted, one vector per direction.
    pub knots: Vec<Vec<f64>>,
    /// `order`: `numel (knots{k}) − number(k)`.
    pub order: Vec<usize>,
}

impl Nrb {
    /// The structure as [`NrbParts`], to hand it to another octave-nurbs function (a curve's
    /// `knots` a vector, otherwise a cell).
    pub fn parts(&self) -> NrbParts<'_> {
        let knots = if self.knots.len() == 1 {
            Knots::Vector(&self.knots[0])
        } else {
            Knots::Cell {
                cols: self.knots.len(),
                items: self.knots.iter().map(Vec::as_slice).collect(),
            }
        };
        NrbParts {
            coefs: &self.coefs,
            coef_dims: &self.coef_dims,
            knots,
            order: Cow::Owned(self.order.iter().map(|&o| o as f64).collect()),
            number: Cow::Owned(self.number.iter().map(|&n| n as f64).collect()),
        }
    }
}

/// octave-nurbs' `nrbmak (coefs, knots)` for 4-row homogeneous coefficients of size `dims`
/// (`4 × n1 (× n2 (× n3))`, trailing ones filled in) and one knot vector per direction: the
/// knots sorted, `order(k) = numel (knots{k}) − n_k`.
///
/// # Errors
/// As `nrbmak`: [`NurbsError::Refused`] for an order below 1 ("The knot sequence is too
/// short") or fewer control points than the order ("Not enough control points").
pub fn nrbmak(coefs: Vec<f64>, dims: &[usize], knots: Vec<Vec<f64>>) -> Result<Nrb> {
    let dirs = knots.len();
    let number: Vec<usize> = (0..dirs)
        .map(|k| dims.get(1 + k).copied().unwrap_or(1))
        .collect();
    let mut order = Vec::with_capacity(dirs);
    let mut sorted = Vec::with_capacity(dirs);
    for (k, mut kv) in knots.into_iter().enumerate() {
        let o = kv.len() as i64 - number[k] as i64;
        if o < 1 {
            return Err(NurbsError::refused(
                "knots",
                "the knot sequence is too short, as it gives order < 1 (octave-nurbs' nrbmak)",
            ));
        }
        if (number[k] as i64) < o {
            return Err(NurbsError::refused(
                "coefs",
                "not enough control points, or too long knot sequence (octave-nurbs' nrbmak)",
            ));
        }
        kv.sort_by(f64::total_cmp);
        order.push(o as usize);
        sorted.push(kv);
    }
    let mut coef_dims = vec![4];
    coef_dims.extend_from_slice(&number);
    if coef_dims.len() < 2 {
        coef_dims.push(1);
    }
    Ok(Nrb {
        number,
        coefs,
        coef_dims,
        knots: sorted,
        order,
    })
}
