//! Bicubic patches in matrix form.

use nalgebra::{DMatrix, DVector};

use crate::conversion::CubicForm;
use crate::error::{check_finite, Error, Result};
use crate::param::Surface;
use crate::scalar::Scalar;

/// A bicubic patch in the matrix form of the lecture notes (and the matrix-form notes §2.2):
/// `x(u, v) = Σ_a Σ_b f_a(u) f_b(v) X[a, b]` with `f = M [1, u, u², u³]ᵀ` ([`CubicForm::basis`]), one `4 × 4`
/// geometry matrix `X` per coordinate, `a` along `u`, `b` along `v`.
///
/// The lecture notes write it `x(u, v) = vᵀ Mᵀ X M u` with the rows of its `X` running along `v`;
/// that is the same number as `uᵀ Mᵀ X M v` with `X` transposed, which is the layout here (the
/// one of [`BezierPatch`](crate::BezierPatch): `i` along `u`). With
/// [`CubicForm::Bezier`] it is the bicubic Bézier patch, with [`CubicForm::BSpline`] one span
/// of the uniform bicubic B-spline surface (the notes' "Coons B-spline surface", whose matrix
/// `M_S` must be `M_C`, not the `M_B` they print), with [`CubicForm::Hermite`] the Ferguson
/// patch of [`FergusonPatch`](super::FergusonPatch).
///
/// ```
/// use cagd::conversion::CubicForm;
/// use cagd::surfaces::CubicMatrixPatch;
/// use cagd::Surface;
/// use nalgebra::DMatrix;
/// // z = u·v as a Bézier patch: control values i·j/9.
/// let z = DMatrix::from_fn(4, 4, |i, j| (i * j) as f64 / 9.0);
/// let p = CubicMatrixPatch::new(CubicForm::Bezier, vec![z])?;
/// assert!((p.eval(0.5, 0.25)[0] - 0.125).abs() < 1e-15);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CubicMatrixPatch<T: Scalar = f64> {
    form: CubicForm,
    coords: Vec<DMatrix<T>>,
}

impl<T: Scalar> CubicMatrixPatch<T> {
    /// The patch of `form` with one `4 × 4` geometry matrix per coordinate.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for no coordinates or a matrix that is not `4 × 4`,
    /// [`Error::NonFinite`].
    pub fn new(form: CubicForm, coords: Vec<DMatrix<T>>) -> Result<Self> {
        if coords.is_empty() || coords.iter().any(|c| c.shape() != (4, 4)) {
            return Err(Error::ShapeMismatch {
                what: "bicubic matrix patch",
                expected: "one 4 × 4 matrix per coordinate (at least one)".into(),
                found: format!("{:?}", coords.iter().map(|c| c.shape()).collect::<Vec<_>>()),
            });
        }
        for c in &coords {
            check_finite("bicubic matrix patch", c.iter())?;
        }
        Ok(CubicMatrixPatch { form, coords })
    }

    /// The form.
    pub fn form(&self) -> CubicForm {
        self.form
    }

    /// The geometry matrices (`a` along `u`).
    pub fn coordinates(&self) -> &[DMatrix<T>] {
        &self.coords
    }
}

impl<T: Scalar> Surface<T> for CubicMatrixPatch<T> {
    fn dim(&self) -> usize {
        self.coords.len()
    }

    /// `[0, 1]²` (the bicubic continues outside it).
    fn domain(&self) -> ((T, T), (T, T)) {
        ((T::zero(), T::one()), (T::zero(), T::one()))
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        let fu = self.form.basis(&u);
        let fv = self.form.basis(&v);
        DVector::from_fn(self.coords.len(), |k, _| {
            let x = &self.coords[k];
            (0..4).fold(T::zero(), |acc, a| {
                let row = (0..4).fold(T::zero(), |s, b| s + fv[b].clone() * x[(a, b)].clone());
                acc + fu[a].clone() * row
            })
        })
    }

    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        crate::checked::try_eval_surface(self, "matrix patch point", u, v)
    }

    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        crate::checked::eval_grid_into(self, "matrix patch grid", us, vs, out)
    }
}
