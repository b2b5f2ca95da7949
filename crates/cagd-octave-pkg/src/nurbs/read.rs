//! Reading octave-nurbs' arguments: its NURBS structure, parameters and the classes it takes.
//!
//! octave-nurbs converts most numeric arguments to double itself: `single`, integer and
//! `logical` arrays and sparse matrices arrive here as [`Value::Numeric`] with their values
//! as doubles. Each reader takes the classes octave-nurbs takes for that argument and refuses
//! the others by name (`cagd:class`), as octave-nurbs refuses them.

use std::borrow::Cow;

use cagd_octave::octave_nurbs::{Ders, Knots, NrbParts, Params, Tt};

use crate::error::{Kind, PkgError, Result};
use crate::value::{Real, Value};

/// Which classes an argument takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Classes {
    /// Any real numeric or logical array: double, single, integers, logical, sparse
    /// (octave-nurbs reads it with `array_value`, or computes with it in a `.m` file).
    Numeric,
    /// Real floating-point arrays: double or single, full or sparse (octave-nurbs' compiled
    /// functions test `is_real_matrix`, which integer and logical arrays fail).
    Float,
}

/// `v` as a real array of the classes `classes` (values as doubles).
///
/// # Errors
/// [`Kind::Class`] for any other class, naming it.
pub fn real<'a>(v: &Value<'a>, what: &str, classes: Classes) -> Result<Real<'a>> {
    match v {
        Value::Real(r) => Ok(*r),
        Value::Numeric { class, real }
            if classes == Classes::Numeric || *class == "single" || *class == "sparse double" =>
        {
            Ok(*real)
        }
        other => Err(PkgError::arg(
            Kind::Class,
            what,
            format!("{} is not accepted", other.class()),
            match classes {
                Classes::Numeric => "a real numeric array (as octave-nurbs takes it)",
                Classes::Float => "a real double or single array (as octave-nurbs takes it)",
            },
        )),
    }
}

/// `v` as one number of the classes `classes` (octave-nurbs' degrees and counts).
///
/// # Errors
/// As [`real`]; [`Kind::Shape`] unless it has exactly one element.
pub fn scalar(v: &Value<'_>, what: &str, classes: Classes) -> Result<f64> {
    let r = real(v, what, classes)?;
    if r.len() != 1 {
        return Err(PkgError::arg(
            Kind::Shape,
            what,
            format!("size {}", r.size_str()),
            "a scalar (octave-nurbs: \"degree should be a scalar\")",
        ));
    }
    Ok(r.data[0])
}

/// `v` as parameters of any size: any real numeric or logical array.
///
/// # Errors
/// As [`real`].
pub fn params<'a>(v: &Value<'a>, what: &str) -> Result<Params<'a>> {
    let r = real(v, what, Classes::Numeric)?;
    Ok(Params {
        dims: r.dims,
        data: r.data,
    })
}

/// `tt` of `nrbeval`: an array, or a cell of arrays (a grid).
///
/// # Errors
/// As [`params`], for the array or any item of the cell.
pub fn tt<'a>(v: &Value<'a>) -> Result<Tt<'a>> {
    match v {
        Value::Cell { items, .. } => Ok(Tt::Cell(
            items
                .iter()
                .map(|item| params(item, "tt{k}"))
                .collect::<Result<_>>()?,
        )),
        other => Ok(Tt::Array(params(other, "tt")?)),
    }
}

/// The form of a NURBS structure, for messages.
pub const NURBS_FORM: &str =
    "a NURBS structure from nrbmak (fields form, coefs, knots, order, number)";

/// Field `name` of a structure, or the error naming it.
fn field<'v, 'a>(s: &'v Value<'a>, name: &str) -> Result<&'v Value<'a>> {
    s.field(name).ok_or_else(|| {
        PkgError::arg(
            Kind::Struct,
            "NURBS",
            format!("the structure has no field '{name}'"),
            NURBS_FORM,
        )
    })
}

/// Reads an octave-nurbs NURBS structure — from `nrbmak`, `nrbcirc`, `nrbcoons`,
/// `nrbtestsrf`, … — as octave-nurbs' functions read it: `form` must be `"B-NURBS"`;
/// `coefs` (`4 × n1 × n2 × n3`, homogeneous `(w·x, w·y, w·z, w)`) and the knots double or
/// single; `order` and `number` any numeric class; `number` may be missing (curves do not
/// read it). Nothing else is checked here: each function checks what it reads, as
/// octave-nurbs does.
///
/// The result borrows Octave's arrays. For the core's types use
/// [`NrbParts::to_nurbs_curve`] (positive weights: a `cagd::NurbsCurve`, e.g. a boundary of a
/// Coons patch or a curve of a Gordon network given as `nrbmak (coefs, knots)`) or
/// [`NrbParts::to_homogeneous_curve`] (any weights: the B-spline curve of the homogeneous
/// coefficients).
///
/// # Errors
/// [`Kind::Struct`] for a value that is not a scalar structure, a missing field, or a `form`
/// other than `"B-NURBS"` (octave-nurbs: "NURBS representation is not structure!", "Not a
/// recognised NURBS representation"); [`Kind::Class`] for fields of classes octave-nurbs
/// refuses.
///
/// ```
/// use cagd_octave_pkg::nurbs::read::nrb_parts;
/// use cagd_octave_pkg::{Real, Value};
/// // nrbmak ([0 1 2; 0 1 0; 0 0 0; 1 1 1], [0 0 0 1 1 1]): a parabola arc.
/// let coefs = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0];
/// let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
/// let real = |dims: &'static [usize], data: &'static [f64]| Value::Real(Real { dims, data });
/// let s = Value::Struct { fields: vec![
///     ("form", Value::Char { dims: &[1, 7], bytes: b"B-NURBS" }),
///     ("coefs", real(&[4, 3], &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0])),
///     ("knots", real(&[1, 6], &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0])),
///     ("order", real(&[1, 1], &[3.0])),
/// ] };
/// let curve = nrb_parts(&s)?.to_nurbs_curve()?;
/// assert_eq!(curve.try_eval(0.5)?.as_slice(), &[1.0, 0.5, 0.0]);
/// # let _ = (coefs, knots);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn nrb_parts<'a>(v: &Value<'a>) -> Result<NrbParts<'a>> {
    if !matches!(v, Value::Struct { .. }) {
        return Err(PkgError::arg(
            Kind::Struct,
            "NURBS",
            format!(
                "{} is not a NURBS structure (octave-nurbs: \"NURBS representation is not structure!\")",
                v.class()
            ),
            NURBS_FORM,
        ));
    }
    let form = field(v, "form")?.text().unwrap_or_default();
    if form != "B-NURBS" {
        return Err(PkgError::arg(
            Kind::Struct,
            "NURBS.form",
            format!("'{form}' is not a recognised NURBS representation"),
            "'B-NURBS'",
        ));
    }
    let coefs = real(field(v, "coefs")?, "NURBS.coefs", Classes::Float)?;
    let knots = match field(v, "knots")? {
        Value::Cell { dims, items } => Knots::Cell {
            cols: dims.get(1).copied().unwrap_or(1),
            items: items
                .iter()
                .map(|k| real(k, "NURBS.knots{k}", Classes::Float).map(|r| r.data))
                .collect::<Result<_>>()?,
        },
        other => Knots::Vector(real(other, "NURBS.knots", Classes::Float)?.data),
    };
    let order = real(field(v, "order")?, "NURBS.order", Classes::Numeric)?.data;
    let number = match v.field("number") {
        Some(n) => real(n, "NURBS.number", Classes::Numeric)?.data,
        None => &[],
    };
    Ok(NrbParts {
        coefs: coefs.data,
        coef_dims: coefs.dims,
        knots,
        order: Cow::Borrowed(order),
        number: Cow::Borrowed(number),
    })
}

/// A derivative argument of `nrbdeval`: a structure, or a cell of structures (an item that
/// is not one fails only when `nrbdeval` uses it, as in octave-nurbs).
///
/// # Errors
/// As [`nrb_parts`] for a structure.
pub fn ders<'a>(v: &Value<'a>) -> Result<Ders<'a>> {
    match v {
        Value::Cell { dims, items } => Ok(Ders::Cell {
            dims: dims.to_vec(),
            items: items.iter().map(|i| nrb_parts(i).ok()).collect(),
        }),
        other => Ok(Ders::One(nrb_parts(other)?)),
    }
}
