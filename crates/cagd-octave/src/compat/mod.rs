//! The thesis functions under their own names, with the thesis array layouts.
//!
//! Each function here is the Rust twin of one function of the thesis appendices A–D (I. Čavdek,
//! *Bézierove in Gordon-Coons krpe*, Koper 2014), as **fixed** in `octave_ref/fixed/`: the same
//! name (in snake case), the same arguments in the same order, the same array layouts, and the
//! same numbers (within 4 ULPs or `1e-14` relative to the scale of the array; most agree bit for
//! bit). Every twin is a thin layer: it checks and converts the Octave-shaped `ndarray` arrays
//! to the native types, calls the native API, and converts the result back. None of them holds a
//! second implementation of the mathematics.
//!
//! Every twin is generic over the scalar ([`LiteralScalar`]): in `f64` it gives the numbers of the
//! fixed Octave code; in exact `BigRational` the same construction without rounding, the samples
//! `t = linspace(0,1,N)` then exactly `k/(N−1)` ([`samples`]; the Python package's
//! `cagd.octave` calls the twins this way on `Fraction`s).
//!
//! | thesis (Octave) | twin | native function it wraps |
//! |---|---|---|
//! | `deCasteljau(kontrolneT, N)` (A, Alg. 1) | [`de_casteljau`] | [`BezierCurve::eval_many`](cagd::bezier::BezierCurve::eval_many) |
//! | `ploskevB(kontrolneT, N)` (B, Alg. 2) | [`ploskev_b`] | [`BezierPatch::eval`](cagd::bezier::BezierPatch::eval) on the grid |
//! | `bilinearna(B, u, v, N)` (B, Alg. 3) | [`bilinearna`] | [`BezierPatch::eval`](cagd::bezier::BezierPatch::eval) |
//! | `tenzor(B)` (B, Alg. 4) | [`tenzor`] (inverse: [`untenzor`]) | a layout conversion |
//! | `krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)` (C, Alg. 5) | [`krpa_coons`] | [`CoonsPatch`](cagd::coons::CoonsPatch) on [`SampledCurve`](cagd::param::SampledCurve)s |
//! | `vrednostCoons(u,v,c1,c2,d1,d2,P1,P2,P3,P4)` (C, Alg. 6) | [`vrednost_coons`] | [`CoonsPatch::eval_parts`](cagd::coons::CoonsPatch::eval_parts) |
//! | `krpaGordon(g_u,g_v,g_uv,x,N)` (D, Alg. 7) | [`krpa_gordon`] | [`GordonSurface`](cagd::gordon::GordonSurface) on the sampled curves of [`PackedNetwork`] |
//! | `Lagrange(x, m, u)` (D, Alg. 8) | [`lagrange`] | [`basis_product`](cagd::lagrange::basis_product) |
//! | `linspace(a, b, N)` (Octave built-in) | [`linspace`] | [`cagd::linspace::linspace`] |
//!
//! # Layouts
//! - **Control points as columns**: a curve of degree `n` in dimension `d` is a `d × (n+1)`
//!   matrix, column `i` = `b_i`, row 1 = x (as the plotting code of the thesis reads them).
//! - **Sampled curves**: `d × N`, column `k` = the point at `t(k)`, `t = linspace(0,1,N)`.
//! - **Packed nets and packed grids**: `(m+1) × 3(n+1)`, row `i+1` holds the points
//!   `b_{i,0}, …, b_{i,n}` one after the other as x y z triples:
//!   `B(i+1, 3j+1:3j+3) = b_{i,j}`. [`tenzor`] turns this into the `(m+1) × (n+1) × 3` array
//!   `A(i+1, j+1, :) = b_{i,j}`; [`untenzor`] back.
//! - **Patch grids**: `N × N × 3`, `P(i, j, :)` = the point at `(u, v) = (t(i), t(j))`; the
//!   Coons and Gordon results also come packed as `N × 3N` (`R` in the thesis code).
//! - **Gordon networks** (appendix D): `g_u = [c_0 c_1 … c_n]` (`3 × (n+1)N`, the curves
//!   `g(u, v_j)` sampled at `t`), `g_v = [d_0 d_1 … d_m]` (`3 × (m+1)N`, the curves
//!   `g(u_i, v)`), `g_uv` packed `(m+1) × 3(n+1)` with `g_uv(i+1, 3j+1:3j+3) = g(u_i, v_j)`.
//!   [`PackedNetwork`] is the one place that unpacks it (here and for `cagd gordon --script`).
//!
//! Indices in these docs are Octave's (from 1) where they name Octave expressions and the
//! thesis's (from 0) where they name control points; ndarray indices are from 0.
//!
//! # Errors
//! Every twin returns [`cagd::Error`]: a wrong shape is an [`Error::ShapeMismatch`] naming the
//! argument (`"krpa_coons: c2"`), a NaN or infinite input an [`Error::NonFinite`] with the
//! column-major (Octave) index of the first offending value; the native constructors add their
//! own checks (for example a Coons boundary whose corners do not meet is an
//! [`Error::CornerMismatch`]). Where Octave would stop with an error the twin returns one; where
//! the fixed Octave code returns an empty array (`N = 0`) so does the twin.
//!
//! # Moving data to and from Octave
//! The twins read and write Octave's own text format through [`super::text_format`]
//! (`save -text` in Octave, `load` to read back); names, shapes and every bit of every double
//! survive both ways. `docs/PORTING.md` has the whole recipe.
//!
//! ```
//! use cagd_octave::compat::de_casteljau;
//! use cagd_octave::{read_text, write_text, Workspace};
//! // What Octave writes for `P = [0 0 8 4; 0 2 2 0; 0 2 0 0]; save -text primer.txt P`:
//! let saved = "# name: P\n# type: matrix\n# rows: 3\n# columns: 4\n 0 0 8 4\n 0 2 2 0\n 0 2 0 0\n";
//! let p = read_text(saved)?.matrix("P")?;
//! let t = de_casteljau(p.view(), 3)?;
//! let mut out = Workspace::new();
//! out.insert("T", t);
//! let text = write_text(&out)?; // `load` in Octave defines T, 3 x 3
//! assert_eq!(read_text(&text)?.matrix("T")?.column(1).to_vec(), vec![3.5, 1.5, 0.75]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! The bugs of the printed originals, with what GNU Octave 7 does with each, are catalogued in
//! `octave_ref/BUGS.md`; the porting table (thesis function → Rust → command line) is
//! `docs/PORTING.md`.

use nalgebra::{DMatrix, DVector};
use ndarray::{Array2, ArrayView, ArrayView2, Dimension};

use cagd::error::{Error, Result};
use cagd::Scalar;

use crate::literal::LiteralScalar;

mod bilinearna;
mod de_casteljau;
mod krpa_coons;
mod krpa_gordon;
mod lagrange;
mod linspace;
mod packed_network;
mod ploskev_b;
mod tenzor;
mod vrednost_coons;

pub use bilinearna::bilinearna;
pub use de_casteljau::de_casteljau;
pub use krpa_coons::{krpa_coons, SampledPatch};
pub use krpa_gordon::{krpa_gordon, krpa_gordon_surface};
pub use lagrange::lagrange;
pub use linspace::linspace;
pub use packed_network::PackedNetwork;
pub use ploskev_b::ploskev_b;
pub use tenzor::{tenzor, untenzor};
pub use vrednost_coons::{vrednost_coons, VrednostCoons};

/// `"3×4"`: a shape in words, as Octave's `size` would print it.
pub(crate) fn shape_str(shape: &[usize]) -> String {
    let parts: Vec<String> = shape.iter().map(usize::to_string).collect();
    parts.join("×")
}

/// Rejects NaN and infinities, reporting the column-major (Octave) index of the first one.
pub(crate) fn check_finite_array<T: Scalar, D: Dimension>(
    what: &'static str,
    a: &ArrayView<'_, T, D>,
) -> Result<()> {
    // The reversed view iterated in row-major order visits the original in column-major order.
    cagd::error::check_finite(what, a.view().reversed_axes().iter())
}

/// The matrix with the same entries (both are `rows × cols`).
pub(crate) fn to_dmatrix<T: Scalar>(a: &ArrayView2<'_, T>) -> DMatrix<T> {
    DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[[i, j]].clone())
}

/// The array with the same entries.
pub(crate) fn from_dmatrix<T: Scalar>(m: &DMatrix<T>) -> Array2<T> {
    Array2::from_shape_fn((m.nrows(), m.ncols()), |(i, j)| m[(i, j)].clone())
}

/// The thesis's sample parameters `t = linspace(0,1,N)`: in doubles Octave's own points (bit
/// for bit, [`cagd::linspace::linspace`]), in exact arithmetic `t(k+1) = k/(N−1)` exactly
/// (`[1]` for `N = 1`, as Octave).
pub fn samples<T: LiteralScalar>(n: usize) -> Vec<T> {
    if T::EXACT {
        let last = n.saturating_sub(1).max(1) as i64;
        let first = if n == 1 { 1 } else { 0 };
        (0..n as i64)
            .map(|k| T::from_ratio(k + first, last))
            .collect()
    } else {
        cagd::linspace::linspace(0.0, 1.0, n)
            .into_iter()
            .map(|x| T::from_f64(x).unwrap_or_else(T::zero))
            .collect()
    }
}

/// A `d × 1` column (of dimension `dim` when given) as a vector.
pub(crate) fn column_vector<T: Scalar>(
    what: &'static str,
    a: &ArrayView2<'_, T>,
    dim: Option<usize>,
) -> Result<DVector<T>> {
    let ok = a.ncols() == 1 && a.nrows() >= 1 && dim.is_none_or(|d| a.nrows() == d);
    if !ok {
        return Err(Error::ShapeMismatch {
            what,
            expected: match dim {
                Some(d) => format!("a {d}×1 column"),
                None => "a d×1 column (d ≥ 1)".into(),
            },
            found: shape_str(a.shape()),
        });
    }
    check_finite_array(what, a)?;
    Ok(DVector::from_iterator(a.nrows(), a.iter().cloned()))
}

/// Checks that `a` is `rows × cols` (either may be left free with `None`).
pub(crate) fn check_shape<T>(
    what: &'static str,
    a: &ArrayView2<'_, T>,
    rows: Option<usize>,
    cols: Option<usize>,
) -> Result<()> {
    let ok = rows.is_none_or(|r| a.nrows() == r) && cols.is_none_or(|c| a.ncols() == c);
    if ok {
        return Ok(());
    }
    let side = |x: Option<usize>, name: &str| x.map_or_else(|| name.to_string(), |x| x.to_string());
    Err(Error::ShapeMismatch {
        what,
        expected: format!("{}×{}", side(rows, "any"), side(cols, "any")),
        found: shape_str(a.shape()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::array;

    #[test]
    fn non_finite_index_is_column_major() {
        let a = array![[0.0, 1.0], [2.0, f64::NAN]];
        match check_finite_array("a", &a.view()) {
            Err(Error::NonFinite { index, .. }) => assert_eq!(index, 3),
            other => panic!("expected NonFinite, got {other:?}"),
        }
        let b = array![[0.0, f64::INFINITY], [2.0, 3.0]];
        match check_finite_array("b", &b.view()) {
            Err(Error::NonFinite { index, .. }) => assert_eq!(index, 2),
            other => panic!("expected NonFinite, got {other:?}"),
        }
    }

    #[test]
    fn exact_samples_are_k_over_n_minus_1() {
        use num_rational::BigRational;
        let r = |a: i64, b: i64| BigRational::new(a.into(), b.into());
        assert_eq!(
            samples::<BigRational>(4),
            vec![r(0, 1), r(1, 3), r(2, 3), r(1, 1)]
        );
        assert_eq!(samples::<BigRational>(1), vec![r(1, 1)]);
        assert!(samples::<BigRational>(0).is_empty());
        assert_eq!(samples::<f64>(11), cagd::linspace::linspace(0.0, 1.0, 11));
    }

    #[test]
    fn exact_twin_gives_primer_2_4() {
        use num_rational::BigRational;
        let r = |a: i64, b: i64| BigRational::new(a.into(), b.into());
        let p = Array2::from_shape_fn((3, 4), |(i, j)| {
            r([[0, 0, 8, 4], [0, 2, 2, 0], [0, 2, 0, 0]][i][j], 1)
        });
        let t = de_casteljau(p.view(), 3).unwrap();
        assert_eq!(t.column(1).to_vec(), vec![r(7, 2), r(3, 2), r(3, 4)]);
    }

    #[test]
    fn shapes_in_words() {
        assert_eq!(shape_str(&[3, 4]), "3×4");
        let a = Array2::<f64>::zeros((2, 5));
        let e = check_shape("x", &a.view(), Some(3), None).unwrap_err();
        assert_eq!(
            e,
            Error::ShapeMismatch {
                what: "x",
                expected: "3×any".into(),
                found: "2×5".into()
            }
        );
        assert!(column_vector("p", &a.view(), None).is_err());
        let p = array![[1.0], [2.0], [3.0]];
        assert_eq!(
            column_vector("p", &p.view(), Some(3)).unwrap().as_slice(),
            &[1.0, 2.0, 3.0]
        );
        assert!(column_vector("p", &p.view(), Some(2)).is_err());
    }
}
