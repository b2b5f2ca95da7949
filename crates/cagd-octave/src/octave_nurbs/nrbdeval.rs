//! octave-nurbs' `nrbdeval`: points and derivatives of NURBS curves, surfaces and volumes
//! from the structures of `nrbderiv`, by the quotient rule on homogeneous values.

use super::error::{NurbsError, Result};
use super::interrupt::Interrupt;
use super::nd::Nd;
use super::nrb::{Kind, NrbParts};
use super::nrbeval::{NrbEval, Tt};

/// A derivative argument of `nrbdeval`: a structure (a curve's), or a cell of structures
/// with its size (`dnurbs{i}`, `dnurbs2{i, j}`, …).
#[derive(Debug, Clone)]
pub enum Ders<'a> {
    /// A structure.
    One(NrbParts<'a>),
    /// A cell: its size and items in storage order.
    Cell {
        /// `size (cell)`.
        dims: Vec<usize>,
        /// The structures (`None` for an item that is not one: an error when used).
        items: Vec<Option<NrbParts<'a>>>,
    },
}

impl<'a> Ders<'a> {
    /// The structure of a curve (`dnurbs` itself).
    fn one(&self) -> Result<&NrbParts<'a>> {
        match self {
            Ders::One(n) => Ok(n),
            Ders::Cell { .. } => Err(NurbsError::refused(
                "dnurbs",
                "a cell for a curve (octave-nurbs: \"NURBS representation is not structure!\")",
            )),
        }
    }

    /// `cell{s_1, …, s_r}` (1-based subscripts, Octave's indexing of the cell's size).
    fn at(&self, subs: &[usize]) -> Result<&NrbParts<'a>> {
        let Ders::Cell { dims, items } = self else {
            return Err(NurbsError::refused(
                "dnurbs",
                "a structure where octave-nurbs indexes a cell ('{' undefined for a struct)",
            ));
        };
        let mut index = 0;
        let mut stride = 1;
        for (k, &s) in subs.iter().enumerate() {
            let extent = if k + 1 == subs.len() {
                dims[k.min(dims.len())..]
                    .iter()
                    .product::<usize>()
                    .max(usize::from(k >= dims.len()))
            } else {
                dims.get(k).copied().unwrap_or(1)
            };
            if s > extent {
                return Err(NurbsError::Index {
                    what: "dnurbs (a cell)",
                    index: s as i64,
                    bound: extent,
                });
            }
            index += (s - 1) * stride;
            stride *= extent;
        }
        items[index].as_ref().ok_or_else(|| {
            NurbsError::refused(
                "dnurbs",
                "an item of the cell is not a NURBS structure (octave-nurbs: \"NURBS representation is not structure!\")",
            )
        })
    }
}

/// An output of `nrbdeval` beyond the first two.
#[derive(Debug, Clone, PartialEq)]
pub enum Slot {
    /// Not asked for.
    NotAsked,
    /// Asked for but its structures were not given: octave-nurbs warns and returns `[]`
    /// (surfaces and volumes; `warning` is its text).
    Empty {
        /// octave-nurbs' warning.
        warning: &'static str,
    },
    /// The values: for a surface or volume the entries of the cell in storage order (`D^r`
    /// of them); for a curve one array.
    Values(Vec<Nd>),
}

/// The results of [`nrbdeval`].
#[derive(Debug, Clone, PartialEq)]
pub struct NrbDeval {
    /// `pnt`: the points.
    pub pnt: Nd,
    /// `jac`: one array per direction (a curve: one).
    pub jac: Vec<Nd>,
    /// `hess`.
    pub hess: Slot,
    /// `third_der`.
    pub third: Slot,
    /// `fourth_der`.
    pub fourth: Slot,
}

/// The parameters of `nrbdeval` and the interrupt its evaluations ask.
#[derive(Debug, Clone, Copy)]
struct At<'a> {
    tt: &'a Tt<'a>,
    interrupt: Interrupt<'a>,
}

/// Homogeneous values `(c, w(ones (3, 1), :…))` of a structure at `tt`.
fn values(n: &NrbParts<'_>, tt: &At<'_>, colons: usize) -> Result<(Nd, Nd)> {
    let e = NrbEval::new(n, tt.tt, true)?;
    let mut p = vec![0.0; e.p_dims().iter().product()];
    let mut w = vec![0.0; e.points()];
    e.eval_into(&mut p, Some(&mut w), tt.interrupt)?;
    Ok((Nd::new(e.p_dims(), p), Nd::new(e.w_dims(), w).rows3(colons)))
}

/// octave-nurbs' `[pnt, jac, hess, third_der, fourth_der] = nrbdeval (nurbs, dnurbs,
/// dnurbs2, dnurbs3, dnurbs4, tt)` with `nout` outputs: the cartesian points `c/w` and their
/// derivatives by the quotient rule on the homogeneous values of the derivative structures of
/// [`nrbderiv`](super::nrbderiv), in octave-nurbs' formulas and sizes (its `w(ones (3, 1),
/// :)` included — for a curve at a column of parameters it divides every point by the first
/// weight, as there). `higher` holds the structures given after `dnurbs`.
///
/// # Errors
/// Where `nrbdeval` fails: an output whose structures were not given for a curve (octave-nurbs
/// leaves it undefined), cells where structures are expected and the reverse, sizes its
/// formulas cannot combine, and the errors of [`NrbEval`] (each structure evaluated with
/// `interrupt` asked between chunks).
pub fn nrbdeval<'a>(
    nurbs: &NrbParts<'_>,
    (dnurbs, higher): (&Ders<'_>, &[Ders<'_>]),
    tt: &'a Tt<'a>,
    nout: usize,
    interrupt: Interrupt<'a>,
) -> Result<NrbDeval> {
    let tt = &At { tt, interrupt };
    match nurbs.kind() {
        Kind::Curve => curve(nurbs, dnurbs, higher, tt, nout),
        Kind::Surface => surface(nurbs, dnurbs, higher, tt, nout),
        Kind::Volume => volume(nurbs, dnurbs, higher, tt, nout),
        Kind::Other(cols) => Err(NurbsError::refused(
            "nurbs",
            format!("a cell of {cols} knot vectors: octave-nurbs' nrbdeval leaves its outputs undefined"),
        )),
    }
}

/// `(cij - (2*ci.*ti + cp.*tii)./temp + 2*cp.*ti.^2./temp.^2)./temp`.
fn hess_diag(cij: &Nd, ci: &Nd, ti: &Nd, tii: &Nd, cp: &Nd, temp: &Nd) -> Result<Nd> {
    let inner = ci.scale(2.0).mul(ti)?.add(&cp.mul(tii)?)?.div(temp)?;
    let last = cp.scale(2.0).mul(&ti.sq())?.div(&temp.sq())?;
    cij.sub(&inner)?.add(&last)?.div(temp)
}

/// `(cij - (ci.*tj + cj.*ti + cp.*tij)./temp + 2*cp.*ti.*tj./temp.^2)./temp`.
#[allow(clippy::too_many_arguments)]
fn hess_mixed(
    cij: &Nd,
    ci: &Nd,
    cj: &Nd,
    ti: &Nd,
    tj: &Nd,
    tij: &Nd,
    cp: &Nd,
    temp: &Nd,
) -> Result<Nd> {
    let inner = ci
        .mul(tj)?
        .add(&cj.mul(ti)?)?
        .add(&cp.mul(tij)?)?
        .div(temp)?;
    let last = cp.scale(2.0).mul(ti)?.mul(tj)?.div(&temp.sq())?;
    cij.sub(&inner)?.add(&last)?.div(temp)
}

/// `(c - Σ_k a_k * x_k .* y_k) ./ temp`, the terms subtracted left to right (`a_k * x_k`
/// first, as Octave evaluates `a*x.*y`; `a_k = 1` is left out).
fn subtract_terms(c: &Nd, terms: &[(f64, &Nd, &Nd)], temp: &Nd) -> Result<Nd> {
    let mut acc = c.clone();
    for &(a, x, y) in terms {
        let t = if a == 1.0 {
            x.mul(y)?
        } else {
            x.scale(a).mul(y)?
        };
        acc = acc.sub(&t)?;
    }
    acc.div(temp)
}

fn curve(
    nurbs: &NrbParts<'_>,
    dnurbs: &Ders<'_>,
    higher: &[Ders<'_>],
    tt: &At<'_>,
    nout: usize,
) -> Result<NrbDeval> {
    let (cp, temp) = values(nurbs, tt, 1)?;
    let pnt = cp.div(&temp)?;
    let (cup, temp1) = values(dnurbs.one()?, tt, 1)?;
    let jac = cup.sub(&temp1.mul(&pnt)?)?.div(&temp)?;
    let undefined = |name: &'static str| {
        NurbsError::refused(
            name,
            "asked for without the derivative structure it needs (octave-nurbs leaves it undefined)",
        )
    };
    let (mut hess, mut third, mut fourth) = (Slot::NotAsked, Slot::NotAsked, Slot::NotAsked);
    if nout >= 3 {
        let d2 = higher.first().ok_or_else(|| undefined("hess"))?;
        let (cuup, temp2) = values(d2.one()?, tt, 1)?;
        let h = hess_diag(&cuup, &cup, &temp1, &temp2, &cp, &temp)?;
        if nout >= 4 {
            let d3 = higher.get(1).ok_or_else(|| undefined("third_der"))?;
            let (cuuup, temp3) = values(d3.one()?, tt, 1)?;
            let t3 = subtract_terms(
                &cuuup,
                &[(3.0, &jac, &temp2), (1.0, &cp, &temp3), (3.0, &h, &temp1)],
                &temp,
            )?;
            if nout >= 5 {
                let d4 = higher.get(2).ok_or_else(|| undefined("fourth_der"))?;
                let (cuuuup, temp4) = values(d4.one()?, tt, 1)?;
                let t4 = subtract_terms(
                    &cuuuup,
                    &[
                        (1.0, &cp, &temp4),
                        (4.0, &jac, &temp3),
                        (6.0, &h, &temp2),
                        (4.0, &t3, &temp1),
                    ],
                    &temp,
                )?;
                fourth = Slot::Values(vec![t4]);
            }
            third = Slot::Values(vec![t3]);
        }
        hess = Slot::Values(vec![h]);
    }
    Ok(NrbDeval {
        pnt,
        jac: vec![jac],
        hess,
        third,
        fourth,
    })
}

const NO_SECOND: &str = "nrbdeval: dnurbs2 missing. The second derivative is not computed";
const NO_THIRD: &str = "nrbdeval: dnurbs3 missing. The third derivative is not computed";
const NO_FOURTH: &str = "nrbdeval: dnurbs4 missing. The fourth derivative is not computed";
const NO_VOLUME: &str = "nrbdeval: 3rd and 4th order derivatives not implemented for volumes";

fn surface(
    nurbs: &NrbParts<'_>,
    dnurbs: &Ders<'_>,
    higher: &[Ders<'_>],
    tt: &At<'_>,
    nout: usize,
) -> Result<NrbDeval> {
    let (cp, temp) = values(nurbs, tt, 2)?;
    let pnt = cp.div(&temp)?;
    let (cup, tu) = values(dnurbs.at(&[1])?, tt, 2)?;
    let ju = cup.sub(&tu.mul(&pnt)?)?.div(&temp)?;
    let (cvp, tv) = values(dnurbs.at(&[2])?, tt, 2)?;
    let jv = cvp.sub(&tv.mul(&pnt)?)?.div(&temp)?;
    let (mut hess, mut third, mut fourth) = (Slot::NotAsked, Slot::NotAsked, Slot::NotAsked);
    let mut second = None;
    if nout >= 3 {
        match higher.first() {
            Some(d2) => {
                let (cuup, tuu) = values(d2.at(&[1, 1])?, tt, 2)?;
                let huu = hess_diag(&cuup, &cup, &tu, &tuu, &cp, &temp)?;
                let (cvvp, tvv) = values(d2.at(&[2, 2])?, tt, 2)?;
                let hvv = hess_diag(&cvvp, &cvp, &tv, &tvv, &cp, &temp)?;
                let (cuvp, tuv) = values(d2.at(&[1, 2])?, tt, 2)?;
                let huv = hess_mixed(&cuvp, &cup, &cvp, &tu, &tv, &tuv, &cp, &temp)?;
                hess = Slot::Values(vec![huu.clone(), huv.clone(), huv.clone(), hvv.clone()]);
                second = Some((huu, huv, hvv, tuu, tuv, tvv));
            }
            None => hess = Slot::Empty { warning: NO_SECOND },
        }
    }
    if nout >= 4 {
        match (higher.get(1), &second) {
            (Some(d3), Some((huu, huv, hvv, tuu, tuv, tvv))) => {
                let (cuuup, tuuu) = values(d3.at(&[1, 1, 1])?, tt, 2)?;
                let t111 = subtract_terms(
                    &cuuup,
                    &[(3.0, &ju, tuu), (1.0, &cp, &tuuu), (3.0, huu, &tu)],
                    &temp,
                )?;
                let (cvvvp, tvvv) = values(d3.at(&[2, 2, 2])?, tt, 2)?;
                let t222 = subtract_terms(
                    &cvvvp,
                    &[(3.0, &jv, tvv), (1.0, &cp, &tvvv), (3.0, hvv, &tv)],
                    &temp,
                )?;
                let (cuuvp, tuuv) = values(d3.at(&[1, 1, 2])?, tt, 2)?;
                let t112 = subtract_terms(
                    &cuuvp,
                    &[
                        (2.0, &ju, tuv),
                        (1.0, &jv, tuu),
                        (1.0, &cp, &tuuv),
                        (2.0, huv, &tu),
                        (1.0, huu, &tv),
                    ],
                    &temp,
                )?;
                let (cuvvp, tuvv) = values(d3.at(&[1, 2, 2])?, tt, 2)?;
                let t122 = subtract_terms(
                    &cuvvp,
                    &[
                        (2.0, &jv, tuv),
                        (1.0, &ju, tvv),
                        (1.0, &cp, &tuvv),
                        (2.0, huv, &tv),
                        (1.0, hvv, &tu),
                    ],
                    &temp,
                )?;
                // Storage order of the 2×2×2 cell: (1,1,1) (2,1,1) (1,2,1) (2,2,1) (1,1,2) …
                third = Slot::Values(vec![
                    t111.clone(),
                    t112.clone(),
                    t112.clone(),
                    t122.clone(),
                    t112.clone(),
                    t122.clone(),
                    t122.clone(),
                    t222.clone(),
                ]);
                if nout >= 5 {
                    fourth = match higher.get(2) {
                        Some(d4) => {
                            let f = Fourth {
                                cp: &cp,
                                temp: &temp,
                                ju: &ju,
                                jv: &jv,
                                huu,
                                huv,
                                hvv,
                                tuu,
                                tuv,
                                tvv,
                                tuuu: &tuuu,
                                tuuv: &tuuv,
                                tuvv: &tuvv,
                                tvvv: &tvvv,
                                t111: &t111,
                                t112: &t112,
                                t122: &t122,
                                t222: &t222,
                                tu: &tu,
                                tv: &tv,
                            };
                            Slot::Values(f.eval(d4, tt)?)
                        }
                        None => Slot::Empty { warning: NO_FOURTH },
                    };
                }
            }
            _ => {
                // Without dnurbs3 there is no dnurbs4 either (they are positional).
                third = Slot::Empty { warning: NO_THIRD };
                if nout >= 5 {
                    fourth = Slot::Empty { warning: NO_FOURTH };
                }
            }
        }
    }
    Ok(NrbDeval {
        pnt,
        jac: vec![ju, jv],
        hess,
        third,
        fourth,
    })
}

/// The quantities of the fourth derivatives of a surface.
struct Fourth<'x> {
    cp: &'x Nd,
    temp: &'x Nd,
    ju: &'x Nd,
    jv: &'x Nd,
    huu: &'x Nd,
    huv: &'x Nd,
    hvv: &'x Nd,
    tuu: &'x Nd,
    tuv: &'x Nd,
    tvv: &'x Nd,
    tuuu: &'x Nd,
    tuuv: &'x Nd,
    tuvv: &'x Nd,
    tvvv: &'x Nd,
    t111: &'x Nd,
    t112: &'x Nd,
    t122: &'x Nd,
    t222: &'x Nd,
    tu: &'x Nd,
    tv: &'x Nd,
}

impl Fourth<'_> {
    /// The 16 entries of the 2×2×2×2 cell in storage order.
    fn eval(&self, d4: &Ders<'_>, tt: &At<'_>) -> Result<Vec<Nd>> {
        let (cp, temp) = (self.cp, self.temp);
        let (c1111, t1111) = values(d4.at(&[1, 1, 1, 1])?, tt, 2)?;
        let f1111 = subtract_terms(
            &c1111,
            &[
                (1.0, cp, &t1111),
                (4.0, self.ju, self.tuuu),
                (6.0, self.huu, self.tuu),
                (4.0, self.t111, self.tu),
            ],
            temp,
        )?;
        let (c2222, t2222) = values(d4.at(&[2, 2, 2, 2])?, tt, 2)?;
        let f2222 = subtract_terms(
            &c2222,
            &[
                (1.0, cp, &t2222),
                (4.0, self.jv, self.tvvv),
                (6.0, self.hvv, self.tvv),
                (4.0, self.t222, self.tv),
            ],
            temp,
        )?;
        let (c1112, t1112) = values(d4.at(&[1, 1, 1, 2])?, tt, 2)?;
        let f1112 = subtract_terms(
            &c1112,
            &[
                (1.0, cp, &t1112),
                (3.0, self.ju, self.tuuv),
                (1.0, self.jv, self.tuuu),
                (3.0, self.huv, self.tuu),
                (3.0, self.huu, self.tuv),
                (1.0, self.t111, self.tv),
                (3.0, self.t112, self.tu),
            ],
            temp,
        )?;
        let (c1222, t1222) = values(d4.at(&[1, 2, 2, 2])?, tt, 2)?;
        let f1222 = subtract_terms(
            &c1222,
            &[
                (1.0, cp, &t1222),
                (3.0, self.jv, self.tuvv),
                (1.0, self.ju, self.tvvv),
                (3.0, self.huv, self.tvv),
                (3.0, self.hvv, self.tuv),
                (1.0, self.t222, self.tu),
                (3.0, self.t122, self.tv),
            ],
            temp,
        )?;
        let (c1122, t1122) = values(d4.at(&[1, 1, 2, 2])?, tt, 2)?;
        let f1122 = subtract_terms(
            &c1122,
            &[
                (1.0, cp, &t1122),
                (2.0, self.ju, self.tuvv),
                (2.0, self.jv, self.tuuv),
                (1.0, self.huu, self.tvv),
                (1.0, self.hvv, self.tuu),
                (4.0, self.huv, self.tuv),
                (2.0, self.t112, self.tv),
                (2.0, self.t122, self.tu),
            ],
            temp,
        )?;
        // Entry (i, j, k, l) by the number of 2s among its subscripts.
        Ok((0..16)
            .map(|idx: usize| match idx.count_ones() {
                0 => f1111.clone(),
                1 => f1112.clone(),
                2 => f1122.clone(),
                3 => f1222.clone(),
                _ => f2222.clone(),
            })
            .collect())
    }
}

fn volume(
    nurbs: &NrbParts<'_>,
    dnurbs: &Ders<'_>,
    higher: &[Ders<'_>],
    tt: &At<'_>,
    nout: usize,
) -> Result<NrbDeval> {
    let (cp, temp) = values(nurbs, tt, 3)?;
    let pnt = cp.div(&temp)?;
    let mut c = Vec::new();
    let mut t = Vec::new();
    let mut jac = Vec::new();
    for i in 1..=3 {
        let (ci, ti) = values(dnurbs.at(&[i])?, tt, 3)?;
        jac.push(ci.sub(&ti.mul(&pnt)?)?.div(&temp)?);
        c.push(ci);
        t.push(ti);
    }
    let (mut hess, mut third, mut fourth) = (Slot::NotAsked, Slot::NotAsked, Slot::NotAsked);
    if nout >= 3 {
        hess = match higher.first() {
            Some(d2) => {
                let mut h: Vec<Option<Nd>> = vec![None; 9];
                for (i, j) in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)] {
                    let (cij, tij) = values(d2.at(&[i + 1, j + 1])?, tt, 3)?;
                    let v = if i == j {
                        hess_diag(&cij, &c[i], &t[i], &tij, &cp, &temp)?
                    } else {
                        hess_mixed(&cij, &c[i], &c[j], &t[i], &t[j], &tij, &cp, &temp)?
                    };
                    h[i + 3 * j] = Some(v.clone());
                    h[j + 3 * i] = Some(v);
                }
                Slot::Values(h.into_iter().map(|v| v.expect("all nine set")).collect())
            }
            None => Slot::Empty { warning: NO_SECOND },
        };
        if nout > 3 {
            third = Slot::Empty { warning: NO_VOLUME };
            fourth = Slot::Empty { warning: NO_VOLUME };
        }
    }
    Ok(NrbDeval {
        pnt,
        jac,
        hess,
        third,
        fourth,
    })
}
