//! The octave-nurbs twins: `cagd_<name>` takes exactly what octave-nurbs 1.4.3's `<name>`
//! takes and returns what it returns (sizes, classes, NaN where it gives NaN, errors where it
//! errors). The functions themselves — octave-nurbs' conventions and quirks — are the Octave
//! layer's [`cagd_octave::octave_nurbs`]; this module only translates Octave's values:
//!
//! - [`read`]: an octave-nurbs NURBS structure ([`read::nrb_parts`], reusable: the structure
//!   from `nrbmak`, `nrbcirc`, `nrbcoons`, … as the core's curves), parameters, and the
//!   classes octave-nurbs takes for each argument (`single`, integer, `logical` and sparse
//!   arrays arrive as [`Value::Numeric`](crate::Value::Numeric));
//! - [`eval`]: `cagd_nrbeval`, `cagd_bspeval`;
//! - [`basis`]: `cagd_findspan`, `cagd_basisfun`, `cagd_basisfunder`;
//! - [`deriv`]: `cagd_bspderiv`, `cagd_nrbderiv`, `cagd_nrbdeval`;
//! - [`refine`]: `cagd_bspkntins`, `cagd_bspdegelev`, `cagd_nrbkntins`, `cagd_nrbdegelev`,
//!   `cagd_nrbcoons`.

pub mod basis;
pub mod deriv;
pub mod eval;
pub mod read;
pub mod refine;

pub use basis::{basisfun, basisfunder, findspan};
pub use deriv::{bspderiv, nrbderiv, nrbdeval};
pub use eval::{bspeval, nrbeval};
pub use refine::{bspdegelev, bspkntins, nrbcoons, nrbdegelev, nrbkntins};

use cagd_octave::octave_nurbs::NurbsError;

use crate::error::{Kind, PkgError};

impl From<NurbsError> for PkgError {
    /// The octave-nurbs layer's text: a parameter outside the knots is `cagd:domain`, an index
    /// octave-nurbs' own code would fail on `cagd:shape`, anything else it refuses (or reads
    /// outside its arrays for) `cagd:value`; core errors as usual.
    fn from(error: NurbsError) -> Self {
        match error {
            NurbsError::Core(e) => e.into(),
            NurbsError::OutsideKnots { .. } => PkgError::new(Kind::Domain, error.to_string()),
            NurbsError::Index { .. } => PkgError::new(Kind::Shape, error.to_string()),
            NurbsError::Refused { .. } | NurbsError::Undefined { .. } => {
                PkgError::new(Kind::Value, error.to_string())
            }
            NurbsError::Interrupted => PkgError::new(Kind::Interrupted, error.to_string()),
        }
    }
}
