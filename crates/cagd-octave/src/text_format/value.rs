//! The value model: what one variable of an Octave text file holds, and a file's variables.

use ndarray::{Array2, ArrayD, IxDyn};

use super::{Result, TextFormatError};

/// How a character matrix was quoted in Octave: `'…'` (`sq_string`) or `"…"` (`string`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Quote {
    /// Single-quoted, `# type: sq_string` (Octave's default for `'text'`).
    #[default]
    Single,
    /// Double-quoted, `# type: string`.
    Double,
}

/// A character matrix: `rows.len()` rows, all of the same length in bytes (Octave stores UTF-8
/// text as bytes, so `'é'` is a 1×2 char array). `''` is a matrix with no rows.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct CharMatrix {
    /// The rows, top to bottom.
    pub rows: Vec<String>,
    /// How Octave quotes it.
    pub quote: Quote,
}

impl CharMatrix {
    /// A one-row, single-quoted string.
    pub fn new(text: impl Into<String>) -> Self {
        CharMatrix {
            rows: vec![text.into()],
            quote: Quote::Single,
        }
    }
}

/// One Octave value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A real double, `# type: scalar`.
    Scalar(f64),
    /// A real double array of two or more dimensions, `# type: matrix`, indexed as in Octave
    /// (`a[[i, j]]` is `A(i+1, j+1)`). The writer writes a 0-d array as 1×1 and a 1-d array as
    /// a row vector.
    Matrix(ArrayD<f64>),
    /// A range such as `1:3`, `# type: double_range`, kept as Octave stores it. See
    /// [`Value::to_array`] for its elements.
    Range {
        /// First element.
        base: f64,
        /// Upper (or, for a negative increment, lower) limit.
        limit: f64,
        /// Step.
        increment: f64,
    },
    /// A logical scalar, `# type: bool`.
    Bool(bool),
    /// A logical array, `# type: bool matrix`.
    BoolMatrix(ArrayD<bool>),
    /// A character matrix, `# type: sq_string` or `string`.
    Str(CharMatrix),
    /// A scalar struct, `# type: scalar struct`: fields in order.
    Struct(Vec<(String, Value)>),
    /// A cell array, `# type: cell`, indexed as in Octave.
    Cell(ArrayD<Value>),
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Scalar(x)
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Self {
        Value::Bool(b)
    }
}

impl From<&str> for Value {
    fn from(s: &str) -> Self {
        Value::Str(CharMatrix::new(s))
    }
}

impl From<Array2<f64>> for Value {
    fn from(a: Array2<f64>) -> Self {
        Value::Matrix(a.into_dyn())
    }
}

impl From<ArrayD<f64>> for Value {
    fn from(a: ArrayD<f64>) -> Self {
        Value::Matrix(a)
    }
}

impl Value {
    /// A short description of the type, as in error messages (`matrix 3x4`, `scalar`, …).
    pub fn describe(&self) -> String {
        fn dims(shape: &[usize]) -> String {
            shape
                .iter()
                .map(|d| d.to_string())
                .collect::<Vec<_>>()
                .join("x")
        }
        match self {
            Value::Scalar(_) => "scalar".into(),
            Value::Matrix(a) => format!("matrix {}", dims(a.shape())),
            Value::Range { .. } => "range".into(),
            Value::Bool(_) => "bool".into(),
            Value::BoolMatrix(a) => format!("bool matrix {}", dims(a.shape())),
            Value::Str(s) => format!("string with {} row(s)", s.rows.len()),
            Value::Struct(f) => format!("scalar struct with {} field(s)", f.len()),
            Value::Cell(c) => format!("cell {}", dims(c.shape())),
        }
    }

    /// The numbers of a numeric value as an N-d array (at least 2-D, like Octave): a scalar is
    /// 1×1, logical values are 1 and 0 (as in Octave arithmetic), a range is expanded to a row.
    /// `None` for other types.
    ///
    /// A range `base:increment:limit` has `floor((limit-base)/increment) + 1` elements
    /// `base + i*increment` (with a relative allowance of a few ULPs in the count, so that
    /// `0:0.1:1` has 11 elements); the last element is clipped to `limit`. This is exact for
    /// integer ranges; for fractional ranges Octave's own elements may differ in the last bit.
    /// Ranges of more elements than the default [`cagd::limits::Limits::max_elements`]
    /// (4 000 000) give `None` ([`to_array_with`](Self::to_array_with) takes other limits).
    pub fn to_array(&self) -> Option<ArrayD<f64>> {
        self.to_array_with(&cagd::limits::Limits::default())
    }

    /// [`to_array`](Self::to_array), expanding ranges of at most `limits.max_elements`
    /// elements.
    pub fn to_array_with(&self, limits: &cagd::limits::Limits) -> Option<ArrayD<f64>> {
        match self {
            Value::Scalar(x) => Some(ArrayD::from_elem(IxDyn(&[1, 1]), *x)),
            // Logical values are numbers in Octave (`true + 1` is 2): 1 and 0.
            Value::Bool(b) => Some(ArrayD::from_elem(IxDyn(&[1, 1]), f64::from(u8::from(*b)))),
            Value::BoolMatrix(a) => {
                let a = a.mapv(|b| f64::from(u8::from(b)));
                Some(match a.ndim() {
                    0 => a.into_shape_with_order(IxDyn(&[1, 1])).ok()?,
                    1 => {
                        let n = a.len();
                        a.into_shape_with_order(IxDyn(&[1, n])).ok()?
                    }
                    _ => a,
                })
            }
            Value::Matrix(a) => Some(match a.ndim() {
                0 => a.clone().into_shape_with_order(IxDyn(&[1, 1])).ok()?,
                1 => a.clone().into_shape_with_order(IxDyn(&[1, a.len()])).ok()?,
                _ => a.clone(),
            }),
            Value::Range {
                base,
                limit,
                increment,
            } => {
                let n = range_count(*base, *limit, *increment, limits.max_elements)?;
                let row: Vec<f64> = (0..n)
                    .map(|i| {
                        let x = base + i as f64 * increment;
                        if (*increment > 0.0 && x > *limit) || (*increment < 0.0 && x < *limit) {
                            *limit
                        } else {
                            x
                        }
                    })
                    .collect();
                ArrayD::from_shape_vec(IxDyn(&[1, n]), row).ok()
            }
            _ => None,
        }
    }

    /// The numbers of a numeric value as a 2-D matrix (see [`Value::to_array`]); `None` for
    /// other types and for arrays of more than two dimensions.
    pub fn to_matrix(&self) -> Option<Array2<f64>> {
        self.to_array()?.into_dimensionality().ok()
    }

    /// The value of a scalar (or of a 1×1 matrix).
    pub fn to_scalar(&self) -> Option<f64> {
        match self {
            Value::Scalar(x) => Some(*x),
            Value::Matrix(a) if a.len() == 1 => a.iter().next().copied(),
            _ => None,
        }
    }

    /// The text of a one-row string (`''` gives `""`).
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::Str(s) if s.rows.len() == 1 => Some(&s.rows[0]),
            Value::Str(s) if s.rows.is_empty() => Some(""),
            _ => None,
        }
    }

    /// A field of a scalar struct.
    pub fn field(&self, name: &str) -> Option<&Value> {
        match self {
            Value::Struct(fields) => fields.iter().find(|(n, _)| n == name).map(|(_, v)| v),
            _ => None,
        }
    }
}

/// The variables of one file, in order (as `save` wrote them and `load` returns them).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Workspace {
    vars: Vec<(String, Value)>,
}

impl Workspace {
    /// An empty list.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a variable, or replaces the value of one of the same name (keeping its position).
    pub fn insert(&mut self, name: impl Into<String>, value: impl Into<Value>) {
        let name = name.into();
        let value = value.into();
        match self.vars.iter_mut().find(|(n, _)| *n == name) {
            Some(slot) => slot.1 = value,
            None => self.vars.push((name, value)),
        }
    }

    /// The value of a variable.
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.vars.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }

    /// The variable names, in order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.vars.iter().map(|(n, _)| n.as_str())
    }

    /// The variables, in order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.vars.iter().map(|(n, v)| (n.as_str(), v))
    }

    /// The number of variables.
    pub fn len(&self) -> usize {
        self.vars.len()
    }

    /// Whether there are no variables.
    pub fn is_empty(&self) -> bool {
        self.vars.is_empty()
    }

    fn require(&self, name: &str) -> Result<&Value> {
        self.get(name)
            .ok_or_else(|| TextFormatError::MissingVariable { name: name.into() })
    }

    /// A numeric variable as an N-d array (see [`Value::to_array`]).
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`] if it is not
    /// numeric.
    pub fn array(&self, name: &str) -> Result<ArrayD<f64>> {
        let v = self.require(name)?;
        v.to_array().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a numeric array".into(),
            found: v.describe(),
        })
    }

    /// A numeric variable as a 2-D matrix (a scalar is 1×1).
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`] if it is not
    /// numeric or has more than two dimensions.
    pub fn matrix(&self, name: &str) -> Result<Array2<f64>> {
        let v = self.require(name)?;
        v.to_matrix().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a 2-D numeric matrix".into(),
            found: v.describe(),
        })
    }

    /// A numeric variable holding one number.
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`].
    pub fn scalar(&self, name: &str) -> Result<f64> {
        let v = self.require(name)?;
        v.to_scalar().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a scalar".into(),
            found: v.describe(),
        })
    }

    /// A one-row string variable.
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`].
    pub fn string(&self, name: &str) -> Result<&str> {
        let v = self.require(name)?;
        v.as_str().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a one-row string".into(),
            found: v.describe(),
        })
    }
}

impl FromIterator<(String, Value)> for Workspace {
    fn from_iter<I: IntoIterator<Item = (String, Value)>>(iter: I) -> Self {
        let mut ws = Workspace::new();
        for (n, v) in iter {
            ws.insert(n, v);
        }
        ws
    }
}

// ---------------------------------------------------------------------------------------------
// Reading

/// The number of elements of the range `base:increment:limit`.
pub(super) fn range_count(
    base: f64,
    limit: f64,
    increment: f64,
    max_elements: usize,
) -> Option<usize> {
    if increment == 0.0
        || !(base.is_finite() && limit.is_finite() && increment.is_finite())
        || (increment > 0.0 && limit < base)
        || (increment < 0.0 && limit > base)
    {
        return Some(0);
    }
    let q = (limit - base) / increment;
    // Allow a few ULPs, as Octave does, so that 0:0.1:1 has 11 elements and not 10.
    let n = (q + q.abs() * 4.0 * f64::EPSILON).floor();
    // A malformed file must not make the reader allocate without bound: a range is expanded
    // only up to the element limit (found by fuzzing: `1 16666666666 8` asked for 16 GB).
    if n >= max_elements as f64 {
        return None;
    }
    Some(n as usize + 1)
}
