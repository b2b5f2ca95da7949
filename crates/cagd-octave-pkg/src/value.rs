//! Octave's values as the package's functions see them: the arguments of a call ([`Value`]) and
//! the place its results go ([`Sink`]).
//!
//! Arrays keep Octave's own storage: column-major, with Octave's size vector (at least two
//! entries). An argument borrows the Octave array it came from (no copy); a result is written
//! straight into the array Octave will return (no copy either): [`Sink::real`] hands out its
//! buffer.

use crate::error::{Kind, PkgError};

/// A real, full, double array: Octave's size and its elements in column-major order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Real<'a> {
    /// Octave's `size(x)`: at least two entries.
    pub dims: &'a [usize],
    /// `prod(dims)` elements, column-major.
    pub data: &'a [f64],
}

impl<'a> Real<'a> {
    /// The number of rows, `size(x, 1)`.
    pub fn rows(&self) -> usize {
        self.dims.first().copied().unwrap_or(0)
    }

    /// The number of columns of the array seen as a matrix, `prod(size(x)(2:end))`.
    pub fn cols(&self) -> usize {
        self.dims.iter().skip(1).product()
    }

    /// Whether the array has exactly two dimensions (trailing singletons dropped, as Octave
    /// does).
    pub fn is_matrix(&self) -> bool {
        self.dims.iter().skip(2).all(|&d| d == 1)
    }

    /// Whether the array is a row or a column (or a scalar).
    pub fn is_vector(&self) -> bool {
        self.is_matrix() && (self.rows() == 1 || self.cols() == 1)
    }

    /// `numel(x)`.
    pub fn len(&self) -> usize {
        self.data.len()
    }

    /// `isempty(x)`.
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// The size in words, as Octave prints it: `3×4`, `2×2×3`.
    pub fn size_str(&self) -> String {
        size_str(self.dims)
    }
}

/// `"3×4"`: a size vector in words.
pub fn size_str(dims: &[usize]) -> String {
    let parts: Vec<String> = dims.iter().map(usize::to_string).collect();
    parts.join("×")
}

/// One argument of a call, as Octave holds it.
#[derive(Debug, Clone, PartialEq)]
pub enum Value<'a> {
    /// A real, full, double array (`isa (x, "double") && isreal (x) && ! issparse (x)`); ranges
    /// and diagonal matrices arrive as full arrays.
    Real(Real<'a>),
    /// A char array: its size and its bytes, column-major.
    Char {
        /// Octave's size.
        dims: &'a [usize],
        /// The characters (Octave's bytes, UTF-8 for non-ASCII text).
        bytes: &'a [u8],
    },
    /// A cell array: its size and its items, column-major.
    Cell {
        /// Octave's size.
        dims: &'a [usize],
        /// `prod(dims)` items.
        items: Vec<Value<'a>>,
    },
    /// A real numeric or logical array of a class other than full double — `single`, an
    /// integer type, `logical`, a sparse matrix — with its values converted to double. Only
    /// the octave-nurbs twins read it (octave-nurbs takes these classes); every other function
    /// refuses it by its class, as [`Value::Other`].
    Numeric {
        /// The class as the package names it in messages (`single`, `int32`, `logical`,
        /// `sparse double`, …).
        class: &'a str,
        /// Octave's size and the values as doubles, column-major.
        real: Real<'a>,
    },
    /// A scalar struct (1 × 1): its fields in Octave's order.
    Struct {
        /// `(name, value)` pairs.
        fields: Vec<(&'a str, Value<'a>)>,
    },
    /// Anything else, refused by every function: its class as the package names it in
    /// messages (`int32`, `logical`, `single`, `complex double`, `sparse double`,
    /// `function_handle`, `struct array`, …).
    Other {
        /// The class.
        class: &'a str,
    },
}

impl<'a> Value<'a> {
    /// The class in words, for messages.
    pub fn class(&self) -> &str {
        match self {
            Value::Real(_) => "double",
            Value::Char { .. } => "char",
            Value::Cell { .. } => "cell",
            Value::Struct { .. } => "struct",
            Value::Numeric { class, .. } | Value::Other { class } => class,
        }
    }

    /// The text of a char row (or of any char array, column-major), `None` for other values.
    pub fn text(&self) -> Option<String> {
        match self {
            Value::Char { bytes, .. } => Some(String::from_utf8_lossy(bytes).into_owned()),
            _ => None,
        }
    }

    /// The field `name` of a struct.
    pub fn field(&self, name: &str) -> Option<&Value<'a>> {
        match self {
            Value::Struct { fields } => fields.iter().find(|(n, _)| *n == name).map(|(_, v)| v),
            _ => None,
        }
    }
}

/// Where a call's results go: output `index` (from 0) of the Octave function.
///
/// The package's oct-file implements it with Octave arrays; [`VecSink`] with vectors (tests).
/// Every output a call announces is set exactly once, in order.
pub trait Sink {
    /// A new real double array of size `dims` (column-major, zero-filled) as output `index`,
    /// returned for the caller to fill.
    ///
    /// # Errors
    /// [`Kind::Memory`] when the array cannot be allocated.
    fn real(&mut self, index: usize, dims: &[usize]) -> Result<&mut [f64], PkgError>;

    /// A cell array of size `dims` holding the char rows `items` (column-major) as output
    /// `index`.
    ///
    /// # Errors
    /// [`Kind::Memory`] when the array cannot be allocated.
    fn strings(&mut self, index: usize, dims: &[usize], items: &[String]) -> Result<(), PkgError>;
}

/// One result held by [`VecSink`].
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// A real array: size and column-major data.
    Real(Vec<usize>, Vec<f64>),
    /// A cell array of strings: size and column-major items.
    Strings(Vec<usize>, Vec<String>),
}

impl Output {
    /// The real array's data (panics on strings: for tests).
    pub fn data(&self) -> &[f64] {
        match self {
            Output::Real(_, d) => d,
            Output::Strings(..) => panic!("expected a real output, got strings"),
        }
    }

    /// The size.
    pub fn dims(&self) -> &[usize] {
        match self {
            Output::Real(d, _) | Output::Strings(d, _) => d,
        }
    }

    /// The strings (panics on a real array: for tests).
    pub fn items(&self) -> &[String] {
        match self {
            Output::Strings(_, s) => s,
            Output::Real(..) => panic!("expected strings, got a real output"),
        }
    }
}

/// A [`Sink`] into vectors: what the package's Rust tests call the functions with.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct VecSink {
    /// The outputs by index.
    pub outputs: Vec<Option<Output>>,
}

impl VecSink {
    /// Output `index`, which must have been set.
    pub fn get(&self, index: usize) -> &Output {
        self.outputs
            .get(index)
            .and_then(Option::as_ref)
            .unwrap_or_else(|| panic!("output {index} was not set"))
    }

    fn slot(&mut self, index: usize) -> &mut Option<Output> {
        if self.outputs.len() <= index {
            self.outputs.resize(index + 1, None);
        }
        &mut self.outputs[index]
    }
}

impl Sink for VecSink {
    fn real(&mut self, index: usize, dims: &[usize]) -> Result<&mut [f64], PkgError> {
        let n: usize = dims.iter().product();
        let slot = self.slot(index);
        *slot = Some(Output::Real(dims.to_vec(), vec![0.0; n]));
        match slot {
            Some(Output::Real(_, data)) => Ok(data),
            _ => Err(PkgError::new(Kind::Internal, "output slot lost")),
        }
    }

    fn strings(&mut self, index: usize, dims: &[usize], items: &[String]) -> Result<(), PkgError> {
        *self.slot(index) = Some(Output::Strings(dims.to_vec(), items.to_vec()));
        Ok(())
    }
}
