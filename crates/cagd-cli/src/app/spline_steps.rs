//! The parts of `spline` beyond the tangents: the parameters of the points (`--params`), the
//! linear system of the lecture notes and each segment's Hermite and Bézier data (`--steps`),
//! and the periodic evaluation of a closed spline.

use cagd::CubicSpline;
use cagd_octave::literal::LiteralScalar;
use clap::ValueEnum;
use nalgebra::{DMatrix, DVector};

use crate::{load_params, CliError, Item, Value};

use super::common::{shape, usage};

/// How the parameters of the points are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ParamChoice {
    /// t_k = k: every segment over [0, 1], as the lecture notes.
    Uniform,
    /// Steps equal to the distances between the points (chord length).
    Chord,
    /// Steps equal to the square roots of the distances (centripetal).
    Centripetal,
}

/// The parameters of the points: `--params` as a choice or a list (`count` values: one per
/// point, one more for a closed spline).
pub fn parameters<T: LiteralScalar>(
    limits: &cagd::Limits,
    given: Option<&str>,
    points: &DMatrix<T>,
    closed: bool,
) -> Result<Vec<T>, CliError> {
    let m = points.ncols();
    let count = m + usize::from(closed);
    let choice = match given {
        None => ParamChoice::Uniform,
        Some(text) => match ParamChoice::from_str(text.trim(), true) {
            Ok(c) => c,
            Err(_) => {
                let list: Vec<T> = load_params(limits, "--params", text)?;
                if list.len() != count {
                    return Err(shape(
                        "--params",
                        format!("{} value(s) for {m} point(s)", list.len()),
                        &format!(
                            "uniform, chord, centripetal, or {count} increasing values (one per point{})",
                            if closed { " and one for the return to the first" } else { "" }
                        ),
                    ));
                }
                return Ok(list);
            }
        },
    };
    if choice == ParamChoice::Uniform {
        return Ok((0..count).map(T::from_usize).collect());
    }
    if T::EXACT {
        return Err(usage(
            "--params",
            &format!(
                "{} parameters are sums of square roots, not rational",
                if choice == ParamChoice::Chord {
                    "chord-length"
                } else {
                    "centripetal"
                }
            ),
            "--params uniform or a list of values with --exact, or leave out --exact",
        ));
    }
    let mut t = vec![T::zero()];
    for k in 1..count {
        let (a, b) = (points.column(k - 1), points.column(k % m));
        let dist = a
            .iter()
            .zip(b.iter())
            .map(|(x, y)| (x.to_f64() - y.to_f64()).powi(2))
            .sum::<f64>()
            .sqrt();
        let step = if choice == ParamChoice::Chord {
            dist
        } else {
            dist.sqrt()
        };
        if step == 0.0 {
            return Err(shape(
                "POINTS",
                format!("points {} and {} coincide", k, k % m + 1),
                "distinct consecutive points for chord-length or centripetal parameters",
            ));
        }
        let next = t[k - 1].to_f64() + step;
        t.push(T::from_f64(next).unwrap_or_else(T::zero));
    }
    Ok(t)
}

/// The linear system for the tangents, as the lecture notes write it: the matrix `A` (m×m)
/// and the right-hand sides `R` (d×m, column k is the right side of equation k), with
/// `A · tangentsᵀ = Rᵀ`. Interior equation k:
/// `h_k x'_{k−1} + 2(h_{k−1} + h_k) x'_k + h_{k−1} x'_{k+1} = 3(h_k δ_{k−1} + h_{k−1} δ_k)`
/// (unit steps: `x'_{k−1} + 4x'_k + x'_{k+1} = 3(x_{k+1} − x_{k−1})`); clamped ends
/// `x'_0 = s`, natural ends `2x'_0 + x'_1 = 3δ_0` and `x'_{m−2} + 2x'_{m−1} = 3δ_{m−2}`;
/// closed: the interior equation at every point, cyclically.
pub fn system<T: LiteralScalar>(
    s: &CubicSpline<T>,
    clamped: Option<(&DVector<T>, &DVector<T>)>,
) -> (DMatrix<T>, DMatrix<T>) {
    let (pts, t) = (s.points(), s.params());
    let (d, m) = (pts.nrows(), pts.ncols());
    let closed = s.is_closed();
    let segs = s.segment_count();
    let h: Vec<T> = (0..segs).map(|k| t[k + 1].clone() - t[k].clone()).collect();
    let delta =
        |k: usize, r: usize| (pts[(r, (k + 1) % m)].clone() - pts[(r, k)].clone()) / h[k].clone();
    let (two, three) = (T::from_usize(2), T::from_usize(3));
    let mut a = DMatrix::from_element(m, m, T::zero());
    let mut rhs = DMatrix::from_element(d, m, T::zero());
    for k in 0..m {
        let interior = closed || (k > 0 && k + 1 < m);
        if interior {
            let p = (k + m - 1) % m;
            let (hp, hn) = (h[p].clone(), h[k].clone());
            a[(k, p)] = a[(k, p)].clone() + hn.clone();
            a[(k, k)] = two.clone() * (hp.clone() + hn.clone());
            a[(k, (k + 1) % m)] = a[(k, (k + 1) % m)].clone() + hp.clone();
            for r in 0..d {
                rhs[(r, k)] = three.clone() * (hn.clone() * delta(p, r) + hp.clone() * delta(k, r));
            }
            continue;
        }
        match clamped {
            Some((start, end)) => {
                a[(k, k)] = T::one();
                let v = if k == 0 { start } else { end };
                for r in 0..d {
                    rhs[(r, k)] = v[r].clone();
                }
            }
            None => {
                let (j, seg) = if k == 0 { (1, 0) } else { (m - 2, m - 2) };
                a[(k, k)] = two.clone();
                a[(k, j)] = T::one();
                for r in 0..d {
                    rhs[(r, k)] = three.clone() * delta(seg, r);
                }
            }
        }
    }
    (a, rhs)
}

/// Each segment's Hermite data `[x_k, x_{k+1}, h_k x'_k, h_k x'_{k+1}]` (over its own
/// parameter `u ∈ [0, 1]`) and the Bézier control points of the same cubic, as records
/// `segment_1`, `segment_2`, ….
pub fn segments<T: LiteralScalar>(s: &CubicSpline<T>) -> Result<Vec<Item<T>>, CliError> {
    let mut out = Vec::with_capacity(s.segment_count());
    for k in 0..s.segment_count() {
        let h = s
            .segment(k)
            .map_err(super::common::lib("POINTS", "a spline"))?;
        out.push(Item {
            name: format!("segment_{}", k + 1),
            value: Value::Record(vec![
                Item {
                    name: "hermite".into(),
                    value: Value::Matrix(h.geometry().clone()),
                },
                Item {
                    name: "bezier".into(),
                    value: Value::Matrix(
                        h.to_bezier()
                            .map_err(|e| {
                                CliError::library(
                                    "POINTS",
                                    e,
                                    "points whose segments' Bézier points stay within ±1.8e308",
                                )
                            })?
                            .control()
                            .clone(),
                    ),
                },
            ]),
        });
    }
    Ok(out)
}

/// `t` moved into `[t_0, t_m)` by whole periods `t_m − t_0`: a closed spline is periodic.
pub fn periodic<T: LiteralScalar>(t: &T, params: &[T]) -> T {
    let (a, b) = (&params[0], &params[params.len() - 1]);
    let period = b.clone() - a.clone();
    let x = (t.clone() - a.clone()) / period.clone();
    if !x.to_f64().is_finite() {
        return t.clone();
    }
    // floor(x), exactly: from the double's floor, corrected by at most a step each way.
    let mut k = T::from_f64(x.to_f64().floor()).unwrap_or_else(T::zero);
    while k > x {
        k = k - T::one();
    }
    while k.clone() + T::one() <= x {
        k = k + T::one();
    }
    t.clone() - k * period
}
