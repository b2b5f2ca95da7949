//! octave-nurbs' compiled `bspeval`, which `nrbeval` calls along each direction.

use cagd::bspline::{basis_functions_into, curve_point_cost};
use cagd::cost::Cost;

use super::basis::{existing_basis, truncate};
use super::error::{NurbsError, Result};
use super::interrupt::Interrupt;
use super::span::{check_in_knots, eval_span, is_sorted};

/// A B-spline as octave-nurbs' univariate functions take it: the degree `d`, the control
/// points `c` (`rows × cols`, one per column, column-major) and the knots `k` (read as a
/// vector in Octave's storage order).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bsp<'a> {
    /// The degree `d`.
    pub degree: usize,
    /// Rows of `c` (the dimension of the points).
    pub rows: usize,
    /// Columns of `c` (the number of control points).
    pub cols: usize,
    /// `c`, column-major (`rows × cols`; [`along_axis`] reads its own array instead).
    pub coefs: &'a [f64],
    /// `k`.
    pub knots: &'a [f64],
    sorted: bool,
}

impl<'a> Bsp<'a> {
    /// The B-spline `bspeval (d, c, k, u)` evaluates: `d` truncated toward zero, as
    /// octave-nurbs' `int_value` does.
    ///
    /// # Errors
    /// [`NurbsError::Refused`] unless `d + columns (c) = numel (k) − 1` (octave-nurbs:
    /// "inconsistent bspline data") or for a negative degree (octave-nurbs reads before its
    /// arrays).
    pub fn new(
        d: f64,
        rows: usize,
        cols: usize,
        coefs: &'a [f64],
        knots: &'a [f64],
    ) -> Result<Self> {
        let d = truncate(d);
        if d < 0 {
            return Err(NurbsError::undefined("d", format!("degree {d}")));
        }
        if d as i128 + cols as i128 != knots.len() as i128 - 1 {
            return Err(NurbsError::refused(
                "k",
                format!(
                    "degree {d} and {cols} control points need {} knots, not {} (octave-nurbs: \"inconsistent bspline data, d + columns(c) != numel(k) - 1\")",
                    d as i128 + cols as i128 + 1,
                    knots.len()
                ),
            ));
        }
        Ok(Bsp {
            degree: d as usize,
            rows,
            cols,
            coefs,
            knots,
            sorted: is_sorted(knots),
        })
    }

    /// The cost of one point, `bspeval`'s work at one parameter: the core's estimate of a
    /// B-spline curve's point ([`curve_point_cost`]) of this degree in `rows` coordinates.
    pub fn point_cost(&self) -> Cost {
        curve_point_cost(self.degree, self.rows, 0, 0, 0)
    }

    /// The span and the `d + 1` basis values at `u` (into `n`, with scratch `left`, `right`),
    /// as `bspeval` computes them: the range check, its span search, A2.2. Returns the index
    /// of the first control point the values belong to. Below `U(d+1)` of a knot vector not
    /// clamped at its start, where `bspeval` reads before its arrays, the values of the
    /// basis functions that exist (see [`existing_basis`]), padded with zeros in front.
    ///
    /// # Errors
    /// [`NurbsError::OutsideKnots`] outside `[U(1), U(end)]`.
    pub fn basis(
        &self,
        u: f64,
        n: &mut [f64],
        left: &mut [f64],
        right: &mut [f64],
    ) -> Result<usize> {
        check_in_knots("u", u, self.knots)?;
        let d = self.degree;
        let s = eval_span(self.cols, self.knots, u, self.sorted);
        if s >= d || u.is_nan() {
            let s = s.max(d);
            if u.is_nan() {
                n[..=d].fill(f64::NAN);
            } else {
                basis_functions_into(d, self.knots, s, &u, n, left, right);
            }
            return Ok(s - d);
        }
        let (first, values) = existing_basis(d, self.cols, self.knots, s, u);
        // Place N_first … in the window that starts at index 0.
        n[..=d].fill(0.0);
        n[first..first + values.len()].copy_from_slice(&values);
        Ok(0)
    }
}

/// Scratch buffers for [`Bsp::basis`], on the stack for degrees below 16 (a call for one point
/// allocates nothing).
#[derive(Debug, Clone)]
pub struct BasisWork {
    d: usize,
    small: [f64; 3 * SMALL],
    large: Vec<f64>,
}

/// Degrees below this use the buffer on the stack.
const SMALL: usize = 16;

impl BasisWork {
    /// Buffers for degree `d`.
    pub fn new(d: usize) -> Self {
        BasisWork {
            d,
            small: [0.0; 3 * SMALL],
            large: if d < SMALL {
                Vec::new()
            } else {
                vec![0.0; 3 * (d + 1)]
            },
        }
    }

    fn buffers(&mut self) -> (&mut [f64], &mut [f64], &mut [f64]) {
        let w = self.d + 1;
        let all: &mut [f64] = if self.d < SMALL {
            &mut self.small[..3 * w]
        } else {
            &mut self.large
        };
        let (n, rest) = all.split_at_mut(w);
        let (l, r) = rest.split_at_mut(w);
        (n, l, r)
    }

    /// The basis values of the last [`at`](Self::at).
    pub fn values(&self) -> &[f64] {
        let w = self.d + 1;
        if self.d < SMALL {
            &self.small[..w]
        } else {
            &self.large[..w]
        }
    }

    /// [`Bsp::basis`] into these buffers.
    ///
    /// # Errors
    /// As [`Bsp::basis`].
    pub fn at(&mut self, b: &Bsp<'_>, u: f64) -> Result<usize> {
        let (n, l, r) = self.buffers();
        b.basis(u, n, l, r)
    }
}

/// octave-nurbs' `p = bspeval (d, c, k, u)`: the B-spline at every `u` (any array, read in
/// Octave's storage order), into `out` (`rows × numel (u)`, column-major): each coordinate the
/// sum `Σ_{i=0}^{d} N_i c(:, s−d+i)` from zero, `i` ascending, with `bspeval`'s span and
/// basis — its values bit for bit. NaN gives NaN; a parameter past the last knot of the
/// domain (inside the knots) continues the last span, an empty last span gives NaN, as there.
///
/// The parameters are taken in chunks, `interrupt` asked before each.
///
/// # Errors
/// [`NurbsError::OutsideKnots`] for a parameter outside `[U(1), U(end)]`;
/// [`NurbsError::Interrupted`].
///
/// ```
/// use cagd_octave::octave_nurbs::{bspeval_into, Bsp, Interrupt};
/// // The quadratic on knots [0 0 0 .4 .4 .4 1 1]: octave-nurbs gives NaN from 0.4 on,
/// // where its span [0.4, 0.4] is empty.
/// let c = [0.0, 1.0, 3.0, 4.0, 5.0];
/// let k = [0.0, 0.0, 0.0, 0.4, 0.4, 0.4, 1.0, 1.0];
/// let b = Bsp::new(2.0, 1, 5, &c, &k)?;
/// let mut out = [0.0; 3];
/// bspeval_into(&b, &[0.2, 0.4, 0.7], &mut out, Interrupt::never())?;
/// assert_eq!(out[0], 1.25);
/// assert!(out[1].is_nan() && out[2].is_nan());
/// # Ok::<(), cagd_octave::octave_nurbs::NurbsError>(())
/// ```
pub fn bspeval_into(
    b: &Bsp<'_>,
    u: &[f64],
    out: &mut [f64],
    interrupt: Interrupt<'_>,
) -> Result<()> {
    let mut work = BasisWork::new(b.degree);
    let mut poll = interrupt.poll(u.len(), || b.point_cost().weigh(false));
    for (col, &x) in u.iter().enumerate() {
        poll.at(col)?;
        let first = work.at(b, x)?;
        combine(
            b,
            first,
            work.values(),
            &mut out[col * b.rows..(col + 1) * b.rows],
        );
    }
    Ok(())
}

/// `out[r] = Σ_i n[i] · c(r, first + i)`, from zero, `i` ascending (`bspeval`'s sum); terms
/// past the last control point (only with fewer control points than `d + 1`) are left out.
pub fn combine(b: &Bsp<'_>, first: usize, n: &[f64], out: &mut [f64]) {
    let terms = n.len().min(b.cols.saturating_sub(first));
    for (r, o) in out.iter_mut().enumerate() {
        let mut acc = 0.0;
        for (i, w) in n[..terms].iter().enumerate() {
            acc += w * b.coefs[r + b.rows * (first + i)];
        }
        *o = acc;
    }
}

/// `bspeval` along axis 1 of an array `a` of size `lead × cols × trail` (column-major): the
/// B-spline whose control points are the `cols` slices, at every `u`, into `out` of size
/// `lead × numel (u) × trail` — what `nrbeval` does to `reshape`d and `permute`d coefficients
/// along each direction, each sum in `bspeval`'s order, without the copies. `b.coefs` is not
/// read (pass the array as `a`).
///
/// # Errors
/// As [`bspeval_into`].
pub fn along_axis(
    b: &Bsp<'_>,
    (a, lead, trail): (&[f64], usize, usize),
    u: &[f64],
    out: &mut [f64],
    interrupt: Interrupt<'_>,
) -> Result<()> {
    let cols = b.cols;
    let nt = u.len();
    let mut work = BasisWork::new(b.degree);
    let mut poll = interrupt.poll(u.len(), || {
        curve_point_cost(b.degree, lead.saturating_mul(trail), 0, 0, 0).weigh(false)
    });
    for (j, &x) in u.iter().enumerate() {
        poll.at(j)?;
        let first = work.at(b, x)?;
        let n = work.values();
        let terms = n.len().min(cols.saturating_sub(first));
        for t in 0..trail {
            let src = &a[t * lead * cols..(t + 1) * lead * cols];
            let dst = &mut out[(t * nt + j) * lead..(t * nt + j + 1) * lead];
            for (r, o) in dst.iter_mut().enumerate() {
                let mut acc = 0.0;
                for (i, w) in n[..terms].iter().enumerate() {
                    acc += w * src[r + lead * (first + i)];
                }
                *o = acc;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bspeval_as_octave_nurbs() {
        // octave-nurbs 1.4.3: bspeval (2, [0 1 2 3], [0 0 0 .5 1 1 1], [0 .5 .7 1]) and
        // bspeval (0, [0 1 2 3], [0 1 2 3 4], [0 .5 1 1.5 3.5 4]) = [0 0 1 1 3 3].
        let c = [0.0, 1.0, 2.0, 3.0];
        let k = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
        let b = Bsp::new(2.0, 1, 4, &c, &k).unwrap();
        let mut out = [0.0; 4];
        bspeval_into(&b, &[0.0, 0.5, 0.7, 1.0], &mut out, Interrupt::never()).unwrap();
        assert_eq!(out[0], 0.0);
        assert_eq!(out[3], 3.0);
        assert!((out[2] - 1.98).abs() < 1e-15);
        let b0 = Bsp::new(0.0, 1, 4, &c, &[0.0, 1.0, 2.0, 3.0, 4.0]).unwrap();
        let mut out = [0.0; 6];
        bspeval_into(
            &b0,
            &[0.0, 0.5, 1.0, 1.5, 3.5, 4.0],
            &mut out,
            Interrupt::never(),
        )
        .unwrap();
        assert_eq!(out, [0.0, 0.0, 1.0, 1.0, 3.0, 3.0]);
        // d = 2.5 is 2; inconsistent data and parameters outside the knots are refused.
        assert!(Bsp::new(2.5, 1, 4, &c, &k).is_ok());
        assert!(Bsp::new(3.0, 1, 4, &c, &k).is_err());
        assert!(bspeval_into(&b, &[1.5], &mut out[..1], Interrupt::never()).is_err());
        bspeval_into(&b, &[f64::NAN], &mut out[..1], Interrupt::never()).unwrap();
        assert!(out[0].is_nan());
    }

    #[test]
    fn unclamped_start_gives_the_existing_functions() {
        // Degree 2, uniform knots 0..6, 4 points: below U(3) = 2 only N_0 (and N_1) exist.
        let c = [1.0, 10.0, 100.0, 1000.0];
        let k = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        let b = Bsp::new(2.0, 1, 4, &c, &k).unwrap();
        let mut out = [0.0; 3];
        bspeval_into(&b, &[0.5, 1.5, 2.5], &mut out, Interrupt::never()).unwrap();
        assert_eq!(out[0], 0.125);
        assert_eq!(out[1], 0.75 + 10.0 * 0.125);
        assert_eq!(out[2], 0.125 + 10.0 * 0.75 + 100.0 * 0.125);
    }
}
