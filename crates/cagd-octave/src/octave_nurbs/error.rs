//! The one error type of the octave-nurbs layer.

/// Why an octave-nurbs function, called as octave-nurbs 1.4.3 would be, gives no result.
///
/// Each variant is a call that octave-nurbs refuses too ([`Refused`](Self::Refused),
/// [`OutsideKnots`](Self::OutsideKnots), [`Index`](Self::Index)), or one for which octave-nurbs
/// has no defined result because it reads outside its own arrays
/// ([`Undefined`](Self::Undefined)), or an error of the core.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NurbsError {
    /// octave-nurbs raises an error for these arguments; `message` says which (its own words
    /// where it has them).
    #[error("{what}: {message}")]
    Refused {
        /// The argument or quantity at fault.
        what: &'static str,
        /// What is wrong, and octave-nurbs' message.
        message: String,
    },
    /// A parameter outside the knot range `[U(1), U(end)]`, which octave-nurbs refuses
    /// ("Value … is outside the knot span").
    #[error("{what}: {value} is outside the knots [{min}, {max}] (octave-nurbs: \"outside the knot span\")")]
    OutsideKnots {
        /// The argument.
        what: &'static str,
        /// The parameter.
        value: f64,
        /// `U(1)`.
        min: f64,
        /// `U(end)`.
        max: f64,
    },
    /// octave-nurbs' own code indexes outside an array here, which Octave refuses
    /// ("index (i): out of bound n").
    #[error("{what}: index {index} is out of bound {bound} (octave-nurbs fails the same way)")]
    Index {
        /// The array octave-nurbs indexes.
        what: &'static str,
        /// The 1-based index.
        index: i64,
        /// The array's length.
        bound: usize,
    },
    /// octave-nurbs' compiled code would read outside its arrays for these arguments: its
    /// result is whatever memory lies there, so there is no answer to reproduce.
    #[error("{what}: {message} (octave-nurbs reads outside its arrays here: no defined result)")]
    Undefined {
        /// The argument at fault.
        what: &'static str,
        /// Which read would leave the arrays.
        message: String,
    },
    /// The caller asked to stop (Octave's Ctrl-C) between two chunks of the work
    /// ([`Interrupt`](super::Interrupt)).
    #[error("interrupted")]
    Interrupted,
    /// An error of the core library.
    #[error(transparent)]
    Core(#[from] cagd::Error),
}

/// The result type of the octave-nurbs layer.
pub type Result<T, E = NurbsError> = std::result::Result<T, E>;

impl NurbsError {
    /// [`NurbsError::Refused`].
    pub fn refused(what: &'static str, message: impl Into<String>) -> Self {
        NurbsError::Refused {
            what,
            message: message.into(),
        }
    }

    /// [`NurbsError::Undefined`].
    pub fn undefined(what: &'static str, message: impl Into<String>) -> Self {
        NurbsError::Undefined {
            what,
            message: message.into(),
        }
    }
}
