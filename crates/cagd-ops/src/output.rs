//! What a request produces: named items in order ([`Report`]) — the answer `result`, the
//! parameters it was computed at, and the steps — and, when asked for, a picture
//! ([`crate::drawing::Drawing`]). Each front end lays the items out its own way (text,
//! Octave's `save -text`, JSON, Octave outputs by position, Python objects); the names, the
//! order and the layout of each value (points as columns, grids `nu × nv × d`) are the
//! operation's.

use cagd::grid::PointGrid;
use cagd::Scalar;
use nalgebra::{DMatrix, DVector};

/// The value of a report item.
#[derive(Debug, Clone, PartialEq)]
pub enum Value<T: Scalar> {
    /// A matrix (a scalar is 1×1).
    Matrix(DMatrix<T>),
    /// A grid of points, shape (nu, nv, d).
    Grid(PointGrid<T>),
    /// A line of text.
    Text(String),
    /// Named parts (the levels of a scheme, the pieces of a step): an object in JSON, a
    /// struct in Octave's format, `name.part` items in text and CSV.
    Record(Vec<Item<T>>),
    /// Data with a readable form: the text in readable output, the data elsewhere (a de
    /// Casteljau triangle for people, its levels for programs).
    Shown {
        /// What readable output prints.
        text: String,
        /// What the other formats write.
        data: Box<Value<T>>,
    },
}

impl<T: Scalar> Value<T> {
    /// A 1×k row of values.
    pub fn row(values: &[T]) -> Self {
        Value::Matrix(DMatrix::from_row_slice(1, values.len(), values))
    }

    /// A d×1 column point.
    pub fn column(p: &DVector<T>) -> Self {
        Value::Matrix(DMatrix::from_column_slice(p.len(), 1, p.as_slice()))
    }

    /// A 1×1 scalar.
    pub fn scalar(x: T) -> Self {
        Value::Matrix(DMatrix::from_element(1, 1, x))
    }

    /// Named values as a [`Value::Record`].
    pub fn record(parts: Vec<(&str, Value<T>)>) -> Self {
        Value::Record(
            parts
                .into_iter()
                .map(|(name, value)| Item {
                    name: name.to_string(),
                    value,
                })
                .collect(),
        )
    }
}

/// One named item of a report.
#[derive(Debug, Clone, PartialEq)]
pub struct Item<T: Scalar> {
    /// The name (`result`, `t`, a step's name).
    pub name: String,
    /// The value.
    pub value: Value<T>,
}

/// What a request answers: named items in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Report<T: Scalar> {
    /// The items, in order.
    pub items: Vec<Item<T>>,
}

impl<T: Scalar> Default for Report<T> {
    fn default() -> Self {
        Report { items: Vec::new() }
    }
}

impl<T: Scalar> Report<T> {
    /// An empty report.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends an item.
    pub fn push(&mut self, name: impl Into<String>, value: Value<T>) -> &mut Self {
        self.items.push(Item {
            name: name.into(),
            value,
        });
        self
    }

    /// The item named `name`.
    pub fn get(&self, name: &str) -> Option<&Value<T>> {
        self.items.iter().find(|i| i.name == name).map(|i| &i.value)
    }

    /// The matrix named `name`.
    pub fn matrix(&self, name: &str) -> Option<&DMatrix<T>> {
        match self.get(name)? {
            Value::Matrix(m) => Some(m),
            Value::Shown { data, .. } => match data.as_ref() {
                Value::Matrix(m) => Some(m),
                _ => None,
            },
            _ => None,
        }
    }

    /// The first number of the report that is not finite: the item's name, the flat index
    /// (column-major for matrices, row-major `(i, j, k)` for grids) and the value's double.
    /// Text items (steps) are searched for the words `inf` and `NaN` in any case. The item
    /// `result` is searched first (the answer is what a refusal names, whatever steps were
    /// asked for). Every request's report is checked with it before it is returned
    /// ([`crate::execute`]).
    ///
    /// ```
    /// use cagd_ops::{Report, Value};
    /// use nalgebra::dmatrix;
    /// let mut r = Report::<f64>::new();
    /// r.push("result", Value::Matrix(dmatrix![1.0, f64::INFINITY]));
    /// assert_eq!(r.first_non_finite(), Some(("result".to_string(), 1, f64::INFINITY)));
    /// ```
    pub fn first_non_finite(&self) -> Option<(String, usize, f64)> {
        let (result, rest): (Vec<_>, Vec<_>) =
            self.items.iter().partition(|item| item.name == "result");
        result
            .into_iter()
            .chain(rest)
            .find_map(|item| first_bad(&item.name, &item.value, &|x: &T| x.is_finite_value()))
    }

    /// The first number whose double is not finite: an exact value beyond ±1.8e308, which a
    /// front end that hands out doubles (Octave's format, the Octave package) must refuse
    /// rather than write as ±Inf. Same answer as [`first_non_finite`](Self::first_non_finite)
    /// for doubles.
    ///
    /// ```
    /// use cagd_ops::{Report, Value};
    /// use num_rational::BigRational;
    /// use num_traits::Pow;
    /// let huge = BigRational::from_integer(10.into()).pow(400i32);
    /// let mut r = Report::<BigRational>::new();
    /// r.push("result", Value::scalar(huge));
    /// assert_eq!(r.first_non_finite(), None);
    /// assert_eq!(r.first_beyond_doubles(), Some(("result".to_string(), 0, f64::INFINITY)));
    /// ```
    pub fn first_beyond_doubles(&self) -> Option<(String, usize, f64)> {
        self.items.iter().find_map(|item| {
            first_bad(&item.name, &item.value, &|x: &T| {
                x.is_finite_value() && x.to_f64().is_finite()
            })
        })
    }
}

/// The first value of `value` that is not `good`: named parts are searched as `name.part`.
fn first_bad<T: Scalar>(
    name: &str,
    value: &Value<T>,
    good: &dyn Fn(&T) -> bool,
) -> Option<(String, usize, f64)> {
    let found = match value {
        Value::Matrix(m) => m.iter().position(|x| !good(x)).map(|k| (k, m[k].to_f64())),
        Value::Grid(g) => g
            .iter()
            .position(|x| !good(x))
            .map(|k| (k, g.as_slice()[k].to_f64())),
        Value::Text(t) => t
            .split(|c: char| !c.is_ascii_alphanumeric())
            .position(|w| w.eq_ignore_ascii_case("inf") || w.eq_ignore_ascii_case("nan"))
            .map(|k| (k, f64::NAN)),
        Value::Record(items) => {
            return items
                .iter()
                .find_map(|i| first_bad(&format!("{name}.{}", i.name), &i.value, good));
        }
        Value::Shown { text, data } => {
            return first_bad(name, data, good)
                .or_else(|| first_bad(name, &Value::<T>::Text(text.clone()), good));
        }
    };
    found.map(|(k, x)| (name.to_string(), k, x))
}
