//! The basis functions as octave-nurbs' compiled `basisfun` and `basisfunder` compute them.

use cagd::bspline::{basis_cost, basis_functions_into};
use cagd::cost::Cost;

use super::error::{NurbsError, Result};
use super::interrupt::Interrupt;

/// The degree or span of octave-nurbs' C++ code from an Octave number: truncated toward zero,
/// as its `int_value` and `int (...)` conversions do (NaN reads as 0).
pub fn truncate(x: f64) -> i64 {
    if x.is_nan() {
        0
    } else {
        x.trunc().clamp(i64::MIN as f64, i64::MAX as f64) as i64
    }
}

/// Whether the span `s` of degree `p` has the knots `U(s+1−p) … U(s+p)` (0-based) that the
/// triangular scheme reads.
pub fn span_has_knots(s: i64, p: usize, nk: usize) -> bool {
    p == 0 || (s + 1 >= p as i64 && s.saturating_add(p as i64) < nk as i64)
}

/// octave-nurbs' `B = basisfun (iv, uv, p, U)`: row `k` of `B` (`numel (uv) × (p+1)`,
/// column-major into `out`) holds the `p + 1` basis functions of span `iv(k)` at `uv(k)` by the
/// triangular scheme of Piegl & Tiller A2.2 in octave-nurbs' operation order (the core's
/// [`basis_functions_into`]), bit for bit. As there, a span is truncated toward zero and taken
/// as given — a span that does not hold `uv(k)` gives the polynomial pieces of that span at
/// `uv(k)`, an empty span NaN or ±Inf — and `uv(k)` is not checked against the knots. Spans
/// after the first `numel (uv)` are not used.
///
/// One span for several parameters (`numel (iv) = 1`) is used for all of them. The
/// parameters are taken in chunks ([`basisfun_cost`] each), `interrupt` asked before each.
///
/// # Errors
/// [`NurbsError::Undefined`] where octave-nurbs reads outside its arrays: a span without the
/// knots `U(s+1−p) … U(s+p)`, fewer spans than parameters (other than one span), a NaN span;
/// [`NurbsError::Refused`] for a negative degree; [`NurbsError::Interrupted`].
///
/// ```
/// use cagd_octave::octave_nurbs::{basisfun_into, Interrupt};
/// let knots = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
/// let mut b = [0.0; 3];
/// let never = Interrupt::never();
/// basisfun_into(&[2.0], &[0.25], 2, &knots, (&mut b, never))?;
/// assert_eq!(b, [0.25, 0.625, 0.125]);
/// // A wrong span is taken as given (octave-nurbs: basisfun (1, 0.5, 2, U) = [Inf NaN Inf]).
/// basisfun_into(&[1.0], &[0.5], 2, &knots, (&mut b, never))?;
/// assert!(b[0].is_infinite() && b[1].is_nan() && b[2].is_infinite());
/// # Ok::<(), cagd_octave::octave_nurbs::NurbsError>(())
/// ```
pub fn basisfun_into(
    iv: &[f64],
    uv: &[f64],
    p: usize,
    knots: &[f64],
    (out, interrupt): (&mut [f64], Interrupt<'_>),
) -> Result<()> {
    let n = uv.len();
    if iv.len() < n && iv.len() != 1 {
        return Err(NurbsError::undefined(
            "iv",
            format!("{} spans for {} parameters", iv.len(), n),
        ));
    }
    for &x in iv.iter().take(n.max(1)) {
        let s = truncate(x);
        if x.is_nan() && p > 0 || !span_has_knots(s, p, knots.len()) {
            return Err(NurbsError::undefined(
                "iv",
                format!(
                    "span {x} of degree {p} needs the knots U({}) … U({}) of {} (1-based)",
                    s + 2 - p as i64,
                    s + 1 + p as i64,
                    knots.len()
                ),
            ));
        }
    }
    // Scratch on the stack for the usual degrees (a call for one point allocates nothing).
    let mut small = [0.0; 3 * SMALL];
    let mut large = Vec::new();
    let nb: &mut [f64] = if p < SMALL {
        &mut small[..3 * (p + 1)]
    } else {
        large.resize(3 * (p + 1), 0.0);
        &mut large
    };
    let (nv, rest) = nb.split_at_mut(p + 1);
    let (left, right) = rest.split_at_mut(p + 1);
    let mut poll = interrupt.poll(n, || basisfun_cost(p).weigh(false));
    for (k, &u) in uv.iter().enumerate() {
        poll.at(k)?;
        let s = truncate(if iv.len() == 1 { iv[0] } else { iv[k] });
        if p == 0 {
            nv[0] = 1.0;
        } else {
            basis_functions_into(p, knots, s as usize, &u, nv, left, right);
        }
        for (j, b) in nv.iter().enumerate() {
            out[k + n * j] = *b;
        }
    }
    Ok(())
}

/// Degrees below this use scratch on the stack.
const SMALL: usize = 16;

/// The cost of `basisfun` at one parameter: the core's estimate of the `p + 1` basis
/// functions by the triangular scheme ([`basis_cost`]).
pub fn basisfun_cost(p: usize) -> Cost {
    basis_cost(p, 0, 0)
}

/// The cost of `basisfunder` at one parameter: A2.3 is the triangular scheme of the basis
/// ([`basis_cost`]) and, for each of the `nd` orders, the differences of the `pl + 1`
/// functions over rows of up to `pl + 1` entries: about the scheme again per order, so
/// `nd + 1` schemes (and their scaling, one more).
pub fn basisfunder_cost(pl: usize, nd: usize) -> Cost {
    basis_cost(pl, 0, 0).times(nd as u128 + 2)
}

/// octave-nurbs' `ders = basisfunder (ii, pl, uu, U, nd)`: for each span `ii(k)` and
/// parameter `uu(k)`, the basis functions of degree `pl` and their derivatives up to order
/// `nd` by Piegl & Tiller A2.3 in octave-nurbs' operation order: `ders(k, r+1, j+1)` is the
/// `r`-th derivative of `N_{s−pl+j}` (`numel (uu) × (nd+1) × (pl+1)`, column-major into
/// `out`). Orders above `pl` are zero. Spans are truncated toward zero and taken as given.
/// The parameters are taken in chunks ([`basisfunder_cost`] each), `interrupt` asked before
/// each.
///
/// # Errors
/// [`NurbsError::Refused`] unless there are as many spans as parameters (octave-nurbs prints
/// its usage); [`NurbsError::Undefined`] for a span without its knots or a NaN span;
/// [`NurbsError::Interrupted`].
pub fn basisfunder_into(
    (ii, pl): (&[f64], usize),
    uu: &[f64],
    knots: &[f64],
    nd: usize,
    (out, interrupt): (&mut [f64], Interrupt<'_>),
) -> Result<()> {
    if ii.len() != uu.len() {
        return Err(NurbsError::refused(
            "ii",
            format!(
                "{} spans for {} parameters (octave-nurbs: \"Invalid call to basisfunder\")",
                ii.len(),
                uu.len()
            ),
        ));
    }
    let n = uu.len();
    let mut work = DersWork::new(pl, nd);
    let mut poll = interrupt.poll(n, || basisfunder_cost(pl, nd).weigh(false));
    for (k, (&x, &u)) in ii.iter().zip(uu).enumerate() {
        poll.at(k)?;
        let s = truncate(x);
        if x.is_nan() && pl > 0 || !span_has_knots(s, pl, knots.len()) {
            return Err(NurbsError::undefined(
                "ii",
                format!("span {x} of degree {pl} needs knots outside U"),
            ));
        }
        work.ders(s.max(0) as usize, u, knots);
        for r in 0..=nd {
            for j in 0..=pl {
                out[k + n * (r + (nd + 1) * j)] = work.ders[r * (pl + 1) + j];
            }
        }
    }
    Ok(())
}

/// The work arrays of A2.3 (row-major `(pl+1) × (pl+1)` `ndu`, `2 × (pl+1)` `a`,
/// `(nd+1) × (pl+1)` `ders`), in one allocation.
struct DersWork {
    pl: usize,
    nd: usize,
    ndu: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
    a: Vec<f64>,
    ders: Vec<f64>,
}

impl DersWork {
    fn new(pl: usize, nd: usize) -> Self {
        let w = pl + 1;
        DersWork {
            pl,
            nd,
            ndu: vec![0.0; w * w],
            left: vec![0.0; w],
            right: vec![0.0; w],
            a: vec![0.0; 2 * w],
            ders: vec![0.0; (nd + 1) * w],
        }
    }

    /// A2.3 at span `i`, parameter `u`: the basis values (`ndu`, with the knot differences
    /// below the diagonal), then the derivatives by the differences of the `a` rows, then the
    /// factors `pl!/(pl−k)!` — the operations of octave-nurbs' `basisfunder`.
    fn ders(&mut self, i: usize, u: f64, knots: &[f64]) {
        let (pl, nd) = (self.pl, self.nd);
        let w = pl + 1;
        let ndu = |r: usize, c: usize| r * w + c;
        self.ndu.fill(0.0);
        self.ders.fill(0.0);
        self.ndu[0] = 1.0;
        for j in 1..=pl {
            self.left[j] = u - knots[i + 1 - j];
            self.right[j] = knots[i + j] - u;
            let mut saved = 0.0;
            for r in 0..j {
                self.ndu[ndu(j, r)] = self.right[r + 1] + self.left[j - r];
                let temp = self.ndu[ndu(r, j - 1)] / self.ndu[ndu(j, r)];
                self.ndu[ndu(r, j)] = saved + self.right[r + 1] * temp;
                saved = self.left[j - r] * temp;
            }
            self.ndu[ndu(j, j)] = saved;
        }
        for j in 0..=pl {
            self.ders[j] = self.ndu[ndu(j, pl)];
        }
        let a = |row: usize, c: usize| row * w + c;
        for r in 0..=pl {
            let (mut s1, mut s2) = (0, 1);
            self.a[0] = 1.0;
            for k in 1..=nd {
                let mut d = 0.0;
                let rk = r as i64 - k as i64;
                let pk = pl as i64 - k as i64;
                if r >= k {
                    let (pk1, rk) = ((pk + 1) as usize, rk as usize);
                    self.a[a(s2, 0)] = self.a[a(s1, 0)] / self.ndu[ndu(pk1, rk)];
                    d = self.a[a(s2, 0)] * self.ndu[ndu(rk, pk as usize)];
                }
                let j1 = if rk >= -1 { 1 } else { -rk };
                let j2 = if r as i64 - 1 <= pk {
                    k as i64 - 1
                } else {
                    pl as i64 - r as i64
                };
                for j in j1..=j2 {
                    let (j, pk1) = (j as usize, (pk + 1) as usize);
                    let col = (rk + j as i64) as usize;
                    self.a[a(s2, j)] =
                        (self.a[a(s1, j)] - self.a[a(s1, j - 1)]) / self.ndu[ndu(pk1, col)];
                    d += self.a[a(s2, j)] * self.ndu[ndu(col, pk as usize)];
                }
                if r as i64 <= pk {
                    let pk1 = (pk + 1) as usize;
                    self.a[a(s2, k)] = -self.a[a(s1, k - 1)] / self.ndu[ndu(pk1, r)];
                    d += self.a[a(s2, k)] * self.ndu[ndu(r, pk as usize)];
                }
                self.ders[k * w + r] = d;
                std::mem::swap(&mut s1, &mut s2);
            }
        }
        let mut factor = pl as i64;
        for k in 1..=nd {
            for j in 0..=pl {
                self.ders[k * w + j] *= factor as f64;
            }
            factor *= pl as i64 - k as i64;
        }
    }
}

/// The values `N_{i,p}(u)` of the existing basis functions `i = max(0, s−p) … min(s, nc−1)`
/// by the Cox–de Boor recursion on the whole knot vector (a term with a zero denominator is
/// zero), for a parameter on span `s` of the knots: what a B-spline is at `u` below `U(p+1)`
/// of a knot vector that is not clamped at its start, where octave-nurbs' `bspeval` reads
/// before its arrays. Returns the first index and the values.
pub fn existing_basis(p: usize, nc: usize, knots: &[f64], s: usize, u: f64) -> (usize, Vec<f64>) {
    let first = s.saturating_sub(p);
    let last = s.min(nc.saturating_sub(1));
    // N_{i,0} for i = first … s + p (enough for the recursion up to degree p).
    let top = (s + p).min(knots.len().saturating_sub(2));
    let mut n: Vec<f64> = (first..=top)
        .map(|i| f64::from(u8::from(knots[i] <= u && u < knots[i + 1])))
        .collect();
    for k in 1..=p {
        for (idx, i) in (first..=top).enumerate() {
            if i + k + 1 >= knots.len() {
                n[idx] = 0.0;
                continue;
            }
            let d1 = knots[i + k] - knots[i];
            let d2 = knots[i + k + 1] - knots[i + 1];
            let a = if d1 == 0.0 {
                0.0
            } else {
                (u - knots[i]) / d1 * n[idx]
            };
            let next = n.get(idx + 1).copied().unwrap_or(0.0);
            let b = if d2 == 0.0 {
                0.0
            } else {
                (knots[i + k + 1] - u) / d2 * next
            };
            n[idx] = a + b;
        }
    }
    let count = last + 1 - first;
    n.truncate(count);
    (first, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn basisfun_as_octave_nurbs() {
        // octave-nurbs 1.4.3: basisfun (2.7, 0.3, 2, U) = [0.16 0.66 0.18] (span truncated),
        // basisfun (2, 1.5, 2, U) = [4 -7.5 4.5] (no range check), basisfun (3, 0.3, 2, U) =
        // [0.98 -0.14 0.16] (another span's pieces), basisfun (4, 0.3, 2, U) = [Inf -Inf Inf].
        let k = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
        let mut b = [0.0; 3];
        basisfun_into(&[2.7], &[0.3], 2, &k, (&mut b, Interrupt::never())).unwrap();
        assert!((b[0] - 0.16).abs() < 1e-15 && (b[1] - 0.66).abs() < 1e-15);
        basisfun_into(&[2.0], &[1.5], 2, &k, (&mut b, Interrupt::never())).unwrap();
        assert_eq!(b, [4.0, -7.5, 4.5]);
        basisfun_into(&[3.0], &[0.3], 2, &k, (&mut b, Interrupt::never())).unwrap();
        assert!((b[0] - 0.98).abs() < 1e-15 && (b[1] + 0.14).abs() < 1e-15);
        basisfun_into(&[4.0], &[0.3], 2, &k, (&mut b, Interrupt::never())).unwrap();
        assert!(b[0] == f64::INFINITY && b[1] == f64::NEG_INFINITY && b[2] == f64::INFINITY);
        // Spans without their knots: undefined in octave-nurbs.
        assert!(basisfun_into(&[5.0], &[0.3], 2, &k, (&mut b, Interrupt::never())).is_err());
        assert!(basisfun_into(&[0.0], &[0.3], 2, &k, (&mut b, Interrupt::never())).is_err());
        // p = 0: the one function is 1 whatever the span.
        let mut one = [0.0];
        basisfun_into(&[-3.0], &[0.3], 0, &k, (&mut one, Interrupt::never())).unwrap();
        assert_eq!(one, [1.0]);
    }

    #[test]
    fn basisfunder_as_octave_nurbs() {
        // octave-nurbs 1.4.3: basisfunder (2, 2, 0.3, U, 1) = cat (3, [0.16 -1.6], [0.66 0.4],
        // [0.18 1.2]); with nd = 5 the orders above 2 are zero.
        let k = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
        let mut d = [0.0; 6];
        basisfunder_into((&[2.0], 2), &[0.3], &k, 1, (&mut d, Interrupt::never())).unwrap();
        let want = [0.16, -1.6, 0.66, 0.4, 0.18, 1.2];
        for (a, b) in d.iter().zip(want) {
            assert!((a - b).abs() < 1e-14, "{d:?}");
        }
        let mut d5 = [1.0; 18];
        basisfunder_into((&[2.0], 2), &[0.3], &k, 5, (&mut d5, Interrupt::never())).unwrap();
        assert_eq!(d5[3..6], [0.0; 3]);
        assert!(basisfunder_into(
            (&[2.0, 2.0], 2),
            &[0.3],
            &k,
            1,
            (&mut d, Interrupt::never())
        )
        .is_err());
    }

    #[test]
    fn existing_basis_below_an_unclamped_start() {
        // Uniform knots 0..6, degree 2, 4 points: on [0, 1) only N_0 = u²/2 exists.
        let k = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        let (first, n) = existing_basis(2, 4, &k, 0, 0.5);
        assert_eq!((first, n), (0, vec![0.125]));
        // On [1, 2): N_0 = (−2u² + 6u − 3)/2, N_1 = (u − 1)²/2.
        let (first, n) = existing_basis(2, 4, &k, 1, 1.5);
        assert_eq!(first, 0);
        assert_eq!(n, vec![0.75, 0.125]);
    }
}
