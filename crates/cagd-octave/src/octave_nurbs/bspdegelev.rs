//! octave-nurbs' `bspdegelev`: degree elevation (Piegl & Tiller A5.9, its `.m` file).

use cagd::bernstein::binomial_f64;

use super::error::{NurbsError, Result};
use super::oct::{integer, OctMat, OctVec};

/// octave-nurbs' `[ic, ik] = bspdegelev (d, c, k, t)`: the control points `ic` and knots `ik`
/// of the B-spline of degree `d` (control points `c`, `rows × cols`, knots `k`) raised to
/// degree `d + t`, by Piegl & Tiller A5.9 (Bézier pieces by knot insertion, each raised, the
/// knots removed again) in the operation order of octave-nurbs' `.m` file, including its
/// integer `bet = floor ((ub − ik(kind)) / den)` of the C code it was written from; binomial
/// coefficients are exact (octave-nurbs rounds `exp (gammaln …)`, the same integers for the
/// degrees in use). Every distinct knot gains multiplicity `t`. Returns `ic` (column-major),
/// its number of columns, and `ik`.
///
/// The core's [`BSplineCurve::elevate`](cagd::BSplineCurve::elevate) gives the same curve
/// (the representation is unique) for clamped knot vectors.
///
/// # Errors
/// Where `bspdegelev` fails: every index its code would take outside its arrays — a knot
/// vector not clamped at its end, too few knots or control points, no coordinate
/// ([`NurbsError::Index`], [`NurbsError::Refused`]); a negative or non-integer `d` or `t`.
///
/// ```
/// use cagd_octave::octave_nurbs::bspdegelev;
/// // The straight line 0 → 1 raised to degree 2: points 0, 0.5, 1 on knots [0 0 0 1 1 1].
/// let (ic, cols, ik) = bspdegelev(1.0, 1, 2, &[0.0, 1.0], &[0.0, 0.0, 1.0, 1.0], 1.0)?;
/// assert_eq!((ic, cols), (vec![0.0, 0.5, 1.0], 3));
/// assert_eq!(ik, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
/// # Ok::<(), cagd_octave::octave_nurbs::NurbsError>(())
/// ```
pub fn bspdegelev(
    d: f64,
    rows: usize,
    cols: usize,
    c: &[f64],
    k: &[f64],
    t: f64,
) -> Result<(Vec<f64>, usize, Vec<f64>)> {
    let (d, t) = (integer("d", d)?, integer("t", t)?);
    if d < 0 || t < 0 {
        return Err(NurbsError::refused(
            "t",
            format!("degree {d} raised {t} times (both must be ≥ 0)"),
        ));
    }
    if rows == 0 {
        return Err(NurbsError::refused(
            "c",
            "no coordinate rows: octave-nurbs' bspdegelev leaves ic undefined",
        ));
    }
    let mut e = Elevation::new(d, t, rows, cols, c, k)?;
    e.run()?;
    let cols = e.ic.cols();
    Ok((e.ic.into_data(), cols, e.ik.into_data()))
}

/// The state of A5.9 (octave-nurbs' variable names).
struct Elevation {
    d: i64,
    t: i64,
    mc: i64,
    ph: i64,
    c: OctMat,
    k: OctVec,
    bezalfs: OctMat,
    bpts: OctMat,
    ebpts: OctMat,
    nextbpts: OctMat,
    alfs: OctVec,
    ic: OctMat,
    ik: OctVec,
}

impl Elevation {
    fn new(d: i64, t: i64, rows: usize, cols: usize, c: &[f64], k: &[f64]) -> Result<Self> {
        let mc = rows as i64;
        let ph = d + t;
        let mut bezalfs = OctMat::zeros("bezalfs", d + 1, d + t + 1);
        let ph2 = ph / 2;
        bezalfs.set(1, 1, 1.0)?;
        bezalfs.set(d + 1, ph + 1, 1.0)?;
        for i in 1..=ph2 {
            let inv = 1.0 / bincoeff(ph, i);
            for j in (i - t).max(0)..=d.min(i) {
                bezalfs.set(j + 1, i + 1, inv * bincoeff(d, j) * bincoeff(t, i - j))?;
            }
        }
        for i in ph2 + 1..ph {
            for j in (i - t).max(0)..=d.min(i) {
                let x = bezalfs.get(d - j + 1, ph - i + 1)?;
                bezalfs.set(j + 1, i + 1, x)?;
            }
        }
        Ok(Elevation {
            d,
            t,
            mc,
            ph,
            c: OctMat::from_data("c", rows, cols, c),
            k: OctVec::from_data("k", k),
            bezalfs,
            bpts: OctMat::zeros("bpts", mc, d + 1),
            ebpts: OctMat::zeros("ebpts", mc, d + t + 1),
            nextbpts: OctMat::zeros("Nextbpts", mc, d + 1),
            alfs: OctVec::zeros("alfs", d),
            ic: OctMat::zeros("ic", 0, 0),
            ik: OctVec::zeros("ik", 0),
        })
    }

    fn run(&mut self) -> Result<()> {
        let (d, t, ph, mc) = (self.d, self.t, self.ph, self.mc);
        let n = self.c.cols() as i64 - 1;
        let m = n + d + 1;
        let mut kind = ph + 1;
        let mut r: i64 = -1;
        let mut a = d;
        let mut b = d + 1;
        let mut cind: i64 = 1;
        let mut ua = self.k.get(1)?;
        for ii in 0..mc {
            let x = self.c.get(ii + 1, 1)?;
            self.ic.set(ii + 1, 1, x)?;
        }
        for i in 0..=ph {
            self.ik.set(i + 1, ua)?;
        }
        for i in 0..=d {
            for ii in 0..mc {
                let x = self.c.get(ii + 1, i + 1)?;
                self.bpts.set(ii + 1, i + 1, x)?;
            }
        }
        while b < m {
            let i0 = b;
            while b < m && self.k.get(b + 1)? == self.k.get(b + 2)? {
                b += 1;
            }
            let mul = b - i0 + 1;
            let ub = self.k.get(b + 1)?;
            let oldr = r;
            r = d - mul;
            let lbz = if oldr > 0 { (oldr + 2) / 2 } else { 1 };
            let rbz = if r > 0 { ph - (r + 1) / 2 } else { ph };
            if r > 0 {
                self.insert_knot(a, mul, r, ua, ub)?;
            }
            self.elevate_bezier(lbz)?;
            if oldr > 1 {
                self.remove_knot(kind, oldr, lbz, cind, ua, ub)?;
            }
            if a != d {
                for _ in 0..ph - oldr {
                    self.ik.set(kind + 1, ua)?;
                    kind += 1;
                }
            }
            for j in lbz..=rbz {
                for ii in 0..mc {
                    let x = self.ebpts.get(ii + 1, j + 1)?;
                    self.ic.set(ii + 1, cind + 1, x)?;
                }
                cind += 1;
            }
            if b < m {
                for j in 0..r {
                    for ii in 0..mc {
                        let x = self.nextbpts.get(ii + 1, j + 1)?;
                        self.bpts.set(ii + 1, j + 1, x)?;
                    }
                }
                for j in r..=d {
                    for ii in 0..mc {
                        let x = self.c.get(ii + 1, b - d + j + 1)?;
                        self.bpts.set(ii + 1, j + 1, x)?;
                    }
                }
                a = b;
                b += 1;
                ua = ub;
            } else {
                for i in 0..=ph {
                    self.ik.set(kind + i + 1, ub)?;
                }
            }
        }
        let _ = t;
        Ok(())
    }

    /// Inserts the knot `ub` `r` times into the Bézier points `bpts` of the segment
    /// `[ua, ub]`, keeping the points of the next segment in `Nextbpts`.
    fn insert_knot(&mut self, a: i64, mul: i64, r: i64, ua: f64, ub: f64) -> Result<()> {
        let (d, mc) = (self.d, self.mc);
        let numer = ub - ua;
        for q in (mul + 1..=d).rev() {
            let x = numer / (self.k.get(a + q + 1)? - ua);
            self.alfs.set(q - mul, x)?;
        }
        for j in 1..=r {
            let save = r - j;
            let s = mul + j;
            for q in (s..=d).rev() {
                for ii in 0..mc {
                    let al = self.alfs.get(q - s + 1)?;
                    let tmp1 = al * self.bpts.get(ii + 1, q + 1)?;
                    let tmp2 = (1.0 - al) * self.bpts.get(ii + 1, q)?;
                    self.bpts.set(ii + 1, q + 1, tmp1 + tmp2)?;
                }
            }
            for ii in 0..mc {
                let x = self.bpts.get(ii + 1, d + 1)?;
                self.nextbpts.set(ii + 1, save + 1, x)?;
            }
        }
        Ok(())
    }

    /// `ebpts(:, i+1) = Σ_j bezalfs(j+1, i+1) bpts(:, j+1)` for `i = lbz … ph`.
    fn elevate_bezier(&mut self, lbz: i64) -> Result<()> {
        let (d, t, ph, mc) = (self.d, self.t, self.ph, self.mc);
        for i in lbz..=ph {
            for ii in 0..mc {
                self.ebpts.set(ii + 1, i + 1, 0.0)?;
            }
            for j in (i - t).max(0)..=d.min(i) {
                for ii in 0..mc {
                    let tmp1 = self.ebpts.get(ii + 1, i + 1)?;
                    let tmp2 = self.bezalfs.get(j + 1, i + 1)? * self.bpts.get(ii + 1, j + 1)?;
                    self.ebpts.set(ii + 1, i + 1, tmp1 + tmp2)?;
                }
            }
        }
        Ok(())
    }

    /// Removes the knot `ua` `oldr − 1` times from `ic` and `ebpts`.
    fn remove_knot(
        &mut self,
        kind: i64,
        oldr: i64,
        lbz: i64,
        cind: i64,
        ua: f64,
        ub: f64,
    ) -> Result<()> {
        let (ph, mc) = (self.ph, self.mc);
        let den = ub - ua;
        let bet = ((ub - self.ik.get(kind)?) / den).floor();
        for tr in 1..oldr {
            // octave-nurbs' first and last: kind − 2 and kind, moving apart by one per step.
            let (mut i, mut j) = (kind - 1 - tr, kind + tr - 1);
            let mut kj = j - kind + 1;
            while j - i > tr {
                if i < cind {
                    let alf = (ub - self.ik.get(i + 1)?) / (ua - self.ik.get(i + 1)?);
                    for ii in 0..mc {
                        let tmp1 = alf * self.ic.get(ii + 1, i + 1)?;
                        let tmp2 = (1.0 - alf) * self.ic.get(ii + 1, i)?;
                        self.ic.set(ii + 1, i + 1, tmp1 + tmp2)?;
                    }
                }
                if j >= lbz {
                    let f = if j - tr <= kind - ph + oldr {
                        (ub - self.ik.get(j - tr + 1)?) / den
                    } else {
                        bet
                    };
                    for ii in 0..mc {
                        let tmp1 = f * self.ebpts.get(ii + 1, kj + 1)?;
                        let tmp2 = (1.0 - f) * self.ebpts.get(ii + 1, kj + 2)?;
                        self.ebpts.set(ii + 1, kj + 1, tmp1 + tmp2)?;
                    }
                }
                i += 1;
                j -= 1;
                kj -= 1;
            }
        }
        Ok(())
    }
}

/// The binomial coefficient `C(n, k)` (0 outside `0 ≤ k ≤ n`).
fn bincoeff(n: i64, k: i64) -> f64 {
    if n < 0 || k < 0 {
        return 0.0;
    }
    binomial_f64(n as usize, k as usize)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd::BSplineCurve;
    use nalgebra::DMatrix;

    #[test]
    fn agrees_with_the_core_on_clamped_knots() {
        let c = [0.0, 0.0, 1.0, 2.0, 3.0, -1.0, 4.0, 1.0, 5.0, 2.0, 6.0, 0.0];
        let k = [0.0, 0.0, 0.0, 0.3, 0.3, 0.6, 1.0, 1.0, 1.0];
        for t in 1..4 {
            let (ic, cols, ik) = bspdegelev(2.0, 2, 6, &c, &k, t as f64).unwrap();
            let core = BSplineCurve::new(2, k.to_vec(), DMatrix::from_column_slice(2, 6, &c))
                .unwrap()
                .elevate(t)
                .unwrap();
            assert_eq!(ik, core.knots().as_slice());
            assert_eq!(cols, core.control().ncols());
            for (a, b) in ic.iter().zip(core.control().iter()) {
                assert!((a - b).abs() < 1e-14, "t = {t}: {a} vs {b}");
            }
        }
    }

    #[test]
    fn unclamped_end_fails_as_octave_nurbs() {
        // octave-nurbs 1.4.3: bspdegelev (2, [0 1 3 4; 0 2 2 0], [0 0 0 1 2 3 3.5], 1) fails
        // with "c(_,5): out of bound 4".
        let c = [0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0];
        let k = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.5];
        assert!(matches!(
            bspdegelev(2.0, 2, 4, &c, &k, 1.0),
            Err(NurbsError::Index { .. })
        ));
    }
}
