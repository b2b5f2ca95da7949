//! Interpolating cubic splines (the lecture notes, "Kubické spline křivky").
//!
//! Through points `x_0, …, x_{m−1}` at parameters `t_0 < … < t_{m−1}` (the lecture notes: every
//! segment over `⟨0, 1⟩`, i.e. `t_k = k`) the spline is a Hermite cubic on each segment
//! whose tangents `x'_k` make the second derivative continuous at every joint:
//!
//! ```text
//! h_k x'_{k−1} + 2(h_{k−1} + h_k) x'_k + h_{k−1} x'_{k+1} = 3(h_k δ_{k−1} + h_{k−1} δ_k),
//! h_k = t_{k+1} − t_k,  δ_k = (x_{k+1} − x_k)/h_k,
//! ```
//!
//! which for unit steps is the lecture notes' `x'_{k−1} + 4x'_k + x'_{k+1} = 3(x_{k+1} − x_{k−1})`
//! (the notes print the right-hand side as `3(x'_1 − x_0)`, a typo for `3(x_2 − x_0)`). The end
//! conditions ([`EndCondition`]) close the system:
//! - **clamped** (case a): `x'_0`, `x'_{m−1}` given — a tridiagonal system;
//! - **natural** (case b): `x''(t_0) = x''(t_{m−1}) = 0`, i.e. `2x'_0 + x'_1 = 3δ_0` and
//!   `x'_{m−2} + 2x'_{m−1} = 3δ_{m−2}` (the notes' matrix is right, but the last entry of
//!   their right-hand side, `3(x_{m−1} − x_{m−3})`, must be `3(x_{m−1} − x_{m−2})`);
//! - **closed** (case c): a further segment from `x_{m−1}` back to `x_0` and the joint
//!   equation at every point, indices cyclic — a cyclic tridiagonal system (the first entry of
//!   the notes' right-hand side, `3(x_1 − x_0)`, must be `3(x_1 − x_{m−1})`).
//!
//! The solves ([`solve_tridiagonal`], [`solve_cyclic_tridiagonal`]) are generic, so the spline
//! is exact in rationals. The lecture notes' worked example (points (0,0), (2,1), (4,4), (6,0), end
//! tangents (1,1), (−1,1)) gives x-tangents 1, 31/15, 41/15, −1 and y-tangents 1, 48/15,
//! −27/15, 1: the notes print the third y-tangent as +27/15, but
//! `y'_1 + 4y'_2 = 3(0 − 1) − 1 = −4` with `4y'_1 + y'_2 = 12 − 1 = 11` gives
//! `y'_2 = −27/15`.

use nalgebra::{DMatrix, DVector};

use crate::cost::Cost;
use crate::error::{check_finite, check_overflow, Error, Result};
use crate::hermite::HermiteCubic;
use crate::param::Curve;
use crate::scalar::Scalar;

/// How the spline is closed at its ends (the lecture notes cases a, b, c).
#[derive(Debug, Clone, PartialEq)]
pub enum EndCondition<T: Scalar = f64> {
    /// Given end tangents `x'(t_0) = start`, `x'(t_{m−1}) = end`.
    Clamped {
        /// Tangent at the first point.
        start: DVector<T>,
        /// Tangent at the last point.
        end: DVector<T>,
    },
    /// Zero second derivative at both ends.
    Natural,
    /// A closed curve: one more segment from the last point back to the first, `C²` there too.
    Closed,
}

/// How the parameters `t_k` of the points of an interpolating spline are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parametrization {
    /// `t_k = k`: every segment over `[0, 1]` of its own, as the lecture notes.
    Uniform,
    /// Steps `t_{k+1} − t_k = |x_{k+1} − x_k|` (chord length).
    Chord,
    /// Steps `t_{k+1} − t_k = √|x_{k+1} − x_k|` (centripetal).
    Centripetal,
}

impl Parametrization {
    /// The parameters of the columns of `points` from `t_0 = 0`: one per point, and for a
    /// `closed` spline one more, the parameter of the return to `x_0`. Chord-length and
    /// centripetal steps are square roots: computed in doubles (so not exact in rationals).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for two consecutive points that coincide (a zero step).
    ///
    /// ```
    /// use cagd::spline::Parametrization;
    /// use nalgebra::DMatrix;
    /// let x = DMatrix::from_column_slice(2, 3, &[0.0, 0.0, 3.0, 4.0, 3.0, 0.0]);
    /// assert_eq!(Parametrization::Chord.params(&x, false)?, vec![0.0, 5.0, 9.0]);
    /// assert_eq!(Parametrization::Uniform.params(&x, true)?, vec![0.0, 1.0, 2.0, 3.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn params<T: Scalar>(self, points: &DMatrix<T>, closed: bool) -> Result<Vec<T>> {
        let m = points.ncols();
        let count = m + usize::from(closed);
        if self == Parametrization::Uniform || m == 0 {
            return Ok((0..count).map(T::from_usize).collect());
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
            let step = match self {
                Parametrization::Centripetal => dist.sqrt(),
                _ => dist,
            };
            if step == 0.0 {
                return Err(Error::InvalidArgument {
                    what: "spline parameters",
                    message: format!(
                        "points {} and {} coincide, a step of zero; consecutive points must differ",
                        k,
                        k % m + 1
                    ),
                });
            }
            let next = t[k - 1].to_f64() + step;
            t.push(T::from_f64(next).unwrap_or_else(T::zero));
        }
        Ok(t)
    }
}

/// The cost of [`CubicSpline::interpolate`] through `points` points in `d` coordinates: the
/// (cyclic, when [`EndCondition::Closed`]) tridiagonal solve, about 10 operations per point and
/// coordinate, twice when closed. In exact arithmetic the solve's pivots are continuants growing
/// by about 4 bits per point, so the numbers reach `4 points + 2 data_bits` bits, `data_bits`
/// the size of the points and end tangents (found by fuzzing: 2 223 points took 2 s, 1 000
/// points of random digits 6 s, each number of the result near 3 800 bits).
///
/// ```
/// use cagd::spline::{interpolation_cost, EndCondition};
/// use cagd::cost::Cost;
/// assert_eq!(interpolation_cost::<f64>(5, 2, &EndCondition::Natural, 3), Cost::new(100, 26));
/// assert_eq!(interpolation_cost::<f64>(5, 2, &EndCondition::Closed, 3).ops(), 200);
/// ```
pub fn interpolation_cost<T: Scalar>(
    points: usize,
    d: usize,
    end: &EndCondition<T>,
    data_bits: u128,
) -> Cost {
    let solves = if matches!(end, EndCondition::Closed) {
        2
    } else {
        1
    };
    let (n, d) = (points as u128, d as u128);
    Cost::new(
        (10 * solves * n).saturating_mul(d),
        solved_bits(points, data_bits),
    )
}

/// The cost of one point of an interpolating spline through `points` points in `d`
/// coordinates, at a parameter of `param_bits` bits: a cubic segment, about 12 operations per
/// coordinate, on the solve's numbers ([`interpolation_cost`]) grown by three powers of the
/// parameter.
///
/// ```
/// use cagd::cost::Cost;
/// assert_eq!(cagd::spline::sample_cost(5, 2, 3, 4), Cost::new(24, 26 + 12));
/// ```
pub fn sample_cost(points: usize, d: usize, data_bits: u128, param_bits: u128) -> Cost {
    Cost::new(
        12 * d as u128,
        solved_bits(points, data_bits).saturating_add(param_bits.saturating_mul(3)),
    )
}

/// The size of the tangents a spline solve produces (see [`interpolation_cost`]).
fn solved_bits(points: usize, data_bits: u128) -> u128 {
    (4 * points as u128).saturating_add(data_bits.saturating_mul(2))
}

/// Solves the tridiagonal system `sub[k] y_{k−1} + diag[k] y_k + sup[k] y_{k+1} = rhs[k]`
/// (`sub[0]` and `sup[n−1]` unused) by elimination without pivoting (Thomas' algorithm) —
/// right for the diagonally dominant spline systems. Each `rhs[k]` is a vector (one unknown
/// point per row). Generic: exact in rationals.
///
/// # Errors
/// [`Error::ShapeMismatch`] for lengths that differ, [`Error::NonFinite`] for a NaN or
/// infinite entry, [`Error::Singular`] for a zero pivot, [`Error::Overflow`] for a solution
/// whose double overflows (a nearly singular system).
///
/// ```
/// use cagd::spline::solve_tridiagonal;
/// use nalgebra::DVector;
/// // [4 1; 1 4] y = [5; 5]  →  y = [1; 1]
/// let y = solve_tridiagonal(&[0.0, 1.0], &[4.0, 4.0], &[1.0, 0.0],
///     &[DVector::from_element(1, 5.0), DVector::from_element(1, 5.0)])?;
/// assert_eq!((y[0][0], y[1][0]), (1.0, 1.0));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn solve_tridiagonal<T: Scalar>(
    sub: &[T],
    diag: &[T],
    sup: &[T],
    rhs: &[DVector<T>],
) -> Result<Vec<DVector<T>>> {
    let n = diag.len();
    if sub.len() != n || sup.len() != n || rhs.len() != n {
        return Err(Error::ShapeMismatch {
            what: "tridiagonal system",
            expected: format!("{n} entries in every band and right-hand side"),
            found: format!(
                "{}, {}, {}, {}",
                sub.len(),
                diag.len(),
                sup.len(),
                rhs.len()
            ),
        });
    }
    if let Some(k) = rhs.iter().position(|r| r.len() != rhs[0].len()) {
        return Err(Error::ShapeMismatch {
            what: "tridiagonal system",
            expected: format!("right-hand sides of {} entries each", rhs[0].len()),
            found: format!("{} entries in row {k}", rhs[k].len()),
        });
    }
    check_finite("tridiagonal system", sub.iter().chain(diag).chain(sup))?;
    check_finite(
        "tridiagonal right-hand sides",
        rhs.iter().flat_map(|r| r.iter()),
    )?;
    let mut c = vec![T::zero(); n];
    let mut d: Vec<DVector<T>> = Vec::with_capacity(n);
    for k in 0..n {
        let (pivot, prev) = if k == 0 {
            (diag[0].clone(), None)
        } else {
            (
                diag[k].clone() - sub[k].clone() * c[k - 1].clone(),
                Some(&d[k - 1]),
            )
        };
        if pivot.is_zero() {
            return Err(Error::Singular {
                what: "tridiagonal system",
                reason: format!("zero pivot in row {k}"),
            });
        }
        c[k] = sup[k].clone() / pivot.clone();
        let row = DVector::from_fn(rhs[k].len(), |r, _| {
            let v = match prev {
                Some(p) => rhs[k][r].clone() - sub[k].clone() * p[r].clone(),
                None => rhs[k][r].clone(),
            };
            v / pivot.clone()
        });
        d.push(row);
    }
    for k in (0..n.saturating_sub(1)).rev() {
        let next = d[k + 1].clone();
        d[k] = DVector::from_fn(next.len(), |r, _| {
            d[k][r].clone() - c[k].clone() * next[r].clone()
        });
    }
    check_overflow("tridiagonal solution", d.iter().flat_map(|r| r.iter()))?;
    Ok(d)
}

/// Solves the cyclic tridiagonal system: as [`solve_tridiagonal`] plus the corner entries
/// `sub[0]` (row 0, column n−1) and `sup[n−1]` (row n−1, column 0), by the Sherman–Morrison
/// formula (two tridiagonal solves). Needs `n ≥ 3`.
///
/// # Errors
/// As [`solve_tridiagonal`]; [`Error::TooFewPoints`] for `n < 3`; [`Error::Singular`] for a
/// zero first diagonal entry or a zero Sherman–Morrison denominator.
pub fn solve_cyclic_tridiagonal<T: Scalar>(
    sub: &[T],
    diag: &[T],
    sup: &[T],
    rhs: &[DVector<T>],
) -> Result<Vec<DVector<T>>> {
    let n = diag.len();
    if n < 3 {
        return Err(Error::TooFewPoints {
            what: "cyclic tridiagonal system",
            min: 3,
            found: n,
        });
    }
    if sub.len() != n || sup.len() != n {
        return Err(Error::ShapeMismatch {
            what: "cyclic tridiagonal system",
            expected: format!("{n} entries in every band"),
            found: format!("{}, {}, {}", sub.len(), diag.len(), sup.len()),
        });
    }
    check_finite(
        "cyclic tridiagonal system",
        sub.iter().chain(diag).chain(sup),
    )?;
    let (alpha, beta) = (sub[0].clone(), sup[n - 1].clone());
    let gamma = -diag[0].clone();
    if gamma.is_zero() {
        return Err(Error::Singular {
            what: "cyclic tridiagonal system",
            reason: "the first diagonal entry is zero".into(),
        });
    }
    let mut b = diag.to_vec();
    b[0] = diag[0].clone() - gamma.clone();
    b[n - 1] = diag[n - 1].clone() - alpha.clone() * beta.clone() / gamma.clone();
    let x = solve_tridiagonal(sub, &b, sup, rhs)?;
    let mut u = vec![DVector::from_element(1, T::zero()); n];
    u[0] = DVector::from_element(1, gamma.clone());
    u[n - 1] = DVector::from_element(1, beta.clone());
    let z = solve_tridiagonal(sub, &b, sup, &u)?;
    // v = (1, 0, …, 0, alpha/gamma)
    let ratio = alpha / gamma;
    let denom = T::one() + z[0][0].clone() + ratio.clone() * z[n - 1][0].clone();
    if denom.is_zero() {
        return Err(Error::Singular {
            what: "cyclic tridiagonal system",
            reason: "Sherman–Morrison denominator is zero".into(),
        });
    }
    let dim = rhs[0].len();
    let fact: Vec<T> = (0..dim)
        .map(|r| (x[0][r].clone() + ratio.clone() * x[n - 1][r].clone()) / denom.clone())
        .collect();
    let solution: Vec<DVector<T>> = x
        .iter()
        .zip(&z)
        .map(|(xk, zk)| {
            DVector::from_fn(dim, |r, _| xk[r].clone() - fact[r].clone() * zk[0].clone())
        })
        .collect();
    check_overflow(
        "cyclic tridiagonal solution",
        solution.iter().flat_map(|r| r.iter()),
    )?;
    Ok(solution)
}

/// An interpolating cubic spline: Hermite cubics between consecutive points with `C²` joints.
///
/// **Layout:** points `d × m`, one per column; parameters `t_0 < … < t_{m−1}` (and `t_m`, the
/// parameter at which a closed spline returns to `x_0`); tangents `d × m`.
///
/// ```
/// use cagd::spline::{CubicSpline, EndCondition};
/// use nalgebra::{DMatrix, DVector};
/// let x = DMatrix::from_column_slice(2, 4, &[0.0, 0.0, 2.0, 1.0, 4.0, 4.0, 6.0, 0.0]);
/// let end = EndCondition::Clamped {
///     start: DVector::from_vec(vec![1.0, 1.0]),
///     end: DVector::from_vec(vec![-1.0, 1.0]),
/// };
/// let s = CubicSpline::interpolate(x, end)?;
/// assert!((s.tangents()[(1, 2)] + 27.0 / 15.0).abs() < 1e-15);
/// assert_eq!(s.eval(1.0).as_slice(), &[2.0, 1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CubicSpline<T: Scalar = f64> {
    params: Vec<T>,
    points: DMatrix<T>,
    tangents: DMatrix<T>,
    closed: bool,
}

impl<T: Scalar> CubicSpline<T> {
    /// The spline through the columns of `points` at the parameters `0, 1, …` (the lecture notes:
    /// every segment over `⟨0, 1⟩`; a closed spline returns to `x_0` at `t = m`).
    ///
    /// # Errors
    /// As [`interpolate_with_params`](Self::interpolate_with_params).
    pub fn interpolate(points: DMatrix<T>, end: EndCondition<T>) -> Result<Self> {
        let m = points.ncols() + usize::from(matches!(end, EndCondition::Closed));
        let params = (0..m).map(T::from_usize).collect();
        Self::interpolate_with_params(points, params, end)
    }

    /// The spline through the columns of `points` at the strictly increasing `params` (one per
    /// point; for [`EndCondition::Closed`] one more, the parameter of the return to `x_0`).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 points (3 when closed);
    /// [`Error::ShapeMismatch`] for a wrong number of parameters, points with no coordinates
    /// or end tangents of another dimension; [`Error::NonFinite`];
    /// [`Error::InvalidArgument`] for parameters that do not increase; [`Error::Overflow`] for
    /// parameters whose range or gaps no double can divide by (5·10⁻³²⁴ apart), or tangents
    /// whose doubles overflow (points near ±1.7·10³⁰⁸).
    pub fn interpolate_with_params(
        points: DMatrix<T>,
        params: Vec<T>,
        end: EndCondition<T>,
    ) -> Result<Self> {
        let what = "interpolating spline";
        let closed = matches!(end, EndCondition::Closed);
        let m = points.ncols();
        let min = if closed { 3 } else { 2 };
        if m < min {
            return Err(Error::TooFewPoints {
                what,
                min,
                found: m,
            });
        }
        let d = points.nrows();
        if d == 0 {
            return Err(Error::ShapeMismatch {
                what,
                expected: "at least one coordinate row".into(),
                found: "0 rows".into(),
            });
        }
        let np = m + usize::from(closed);
        if params.len() != np {
            return Err(Error::ShapeMismatch {
                what: "spline parameters",
                expected: format!("{np} values"),
                found: format!("{}", params.len()),
            });
        }
        check_finite("spline points", points.iter())?;
        check_finite("spline parameters", params.iter())?;
        if let Some(k) = params.windows(2).position(|w| w[0] >= w[1]) {
            return Err(Error::InvalidArgument {
                what: "spline parameters",
                message: format!("expected strictly increasing values, but value {k} ({}) is not below value {} ({})", params[k], k + 1, params[k + 1]),
            });
        }
        crate::error::check_spacing("spline parameters", &params)?;
        if let EndCondition::Clamped { start, end } = &end {
            if start.len() != d || end.len() != d {
                return Err(Error::ShapeMismatch {
                    what: "spline end tangents",
                    expected: format!("{d} coordinates (as the points)"),
                    found: format!("{} and {}", start.len(), end.len()),
                });
            }
            check_finite("spline end tangents", start.iter().chain(end.iter()))?;
        }
        let x = |k: usize| points.column(k % m).into_owned();
        let segs = if closed { m } else { m - 1 };
        let h: Vec<T> = (0..segs)
            .map(|k| params[k + 1].clone() - params[k].clone())
            .collect();
        let delta: Vec<DVector<T>> = (0..segs)
            .map(|k| {
                let (a, b) = (x(k), x(k + 1));
                DVector::from_fn(d, |r, _| (b[r].clone() - a[r].clone()) / h[k].clone())
            })
            .collect();
        let three = T::from_usize(3);
        let two = T::from_usize(2);
        // Interior joint k (previous segment k−1, next segment k).
        let joint = |hp: &T, hn: &T, dp: &DVector<T>, dn: &DVector<T>| {
            let rhs = DVector::from_fn(d, |r, _| {
                three.clone() * (hn.clone() * dp[r].clone() + hp.clone() * dn[r].clone())
            });
            (
                hn.clone(),
                two.clone() * (hp.clone() + hn.clone()),
                hp.clone(),
                rhs,
            )
        };
        let mut sub = Vec::with_capacity(m);
        let mut diag = Vec::with_capacity(m);
        let mut sup = Vec::with_capacity(m);
        let mut rhs = Vec::with_capacity(m);
        for k in 0..m {
            let (a, b, c, r) = if closed {
                let p = (k + m - 1) % m;
                joint(&h[p], &h[k], &delta[p], &delta[k])
            } else if k == 0 || k == m - 1 {
                match &end {
                    EndCondition::Clamped { start, end } => {
                        let t = if k == 0 { start } else { end };
                        (T::zero(), T::one(), T::zero(), t.clone())
                    }
                    EndCondition::Natural => {
                        let s = if k == 0 { &delta[0] } else { &delta[m - 2] };
                        let r = DVector::from_fn(d, |q, _| three.clone() * s[q].clone());
                        if k == 0 {
                            (T::zero(), two.clone(), T::one(), r)
                        } else {
                            (T::one(), two.clone(), T::zero(), r)
                        }
                    }
                    EndCondition::Closed => unreachable!("handled above"),
                }
            } else {
                joint(&h[k - 1], &h[k], &delta[k - 1], &delta[k])
            };
            sub.push(a);
            diag.push(b);
            sup.push(c);
            rhs.push(r);
        }
        // Finite points whose differences overflow: the spline's own error, not the solve's.
        crate::error::check_overflow(
            "spline tangent equations",
            rhs.iter()
                .flat_map(|r| r.iter())
                .chain(&diag)
                .chain(&sub)
                .chain(&sup),
        )?;
        let t = if closed {
            solve_cyclic_tridiagonal(&sub, &diag, &sup, &rhs)?
        } else {
            solve_tridiagonal(&sub, &diag, &sup, &rhs)?
        };
        let tangents = DMatrix::from_fn(d, m, |r, c| t[c][r].clone());
        check_overflow("spline tangents", tangents.iter())?;
        Ok(CubicSpline {
            params,
            points,
            tangents,
            closed,
        })
    }

    /// The parameters (`m`, or `m + 1` for a closed spline).
    pub fn params(&self) -> &[T] {
        &self.params
    }

    /// The interpolated points (`d × m`).
    pub fn points(&self) -> &DMatrix<T> {
        &self.points
    }

    /// The tangents `x'_k` at the points (`d × m`), with respect to the parameter `t`.
    pub fn tangents(&self) -> &DMatrix<T> {
        &self.tangents
    }

    /// Whether the spline is closed.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The dimension `d`.
    pub fn dim(&self) -> usize {
        self.points.nrows()
    }

    /// `t` moved into `[t_0, t_last)` by whole periods `t_last − t_0` for a closed spline,
    /// which is periodic; `t` itself for an open one.
    ///
    /// ```
    /// use cagd::spline::{CubicSpline, EndCondition};
    /// use nalgebra::DMatrix;
    /// let x = DMatrix::from_column_slice(1, 3, &[0.0, 1.0, 0.0]);
    /// let s = CubicSpline::interpolate(x, EndCondition::Closed)?;
    /// assert_eq!((s.wrap(&7.5), s.wrap(&-0.5)), (1.5, 2.5));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn wrap(&self, t: &T) -> T {
        if !self.closed {
            return t.clone();
        }
        let (a, b) = (&self.params[0], &self.params[self.params.len() - 1]);
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

    /// The linear system for the tangents, as the lecture notes write it: the matrix `A`
    /// (`m × m`) and the right-hand sides `R` (`d × m`, column `k` the right side of equation
    /// `k`), with `A · tangentsᵀ = Rᵀ`. Interior equation `k`:
    /// `h_k x'_{k−1} + 2(h_{k−1} + h_k) x'_k + h_{k−1} x'_{k+1} = 3(h_k δ_{k−1} + h_{k−1} δ_k)`
    /// (unit steps: `x'_{k−1} + 4x'_k + x'_{k+1} = 3(x_{k+1} − x_{k−1})`); clamped ends
    /// `x'_0 = s`, natural ends `2x'_0 + x'_1 = 3δ_0` and `x'_{m−2} + 2x'_{m−1} = 3δ_{m−2}`;
    /// closed: the interior equation at every point, cyclically. `end` is the condition the
    /// spline was made with.
    ///
    /// ```
    /// use cagd::spline::{CubicSpline, EndCondition};
    /// use nalgebra::DMatrix;
    /// let x = DMatrix::from_column_slice(1, 3, &[0.0, 1.0, 0.0]);
    /// let s = CubicSpline::interpolate(x, EndCondition::Natural)?;
    /// let (a, r) = s.system(&EndCondition::Natural);
    /// assert_eq!(a, DMatrix::from_row_slice(3, 3, &[2.0, 1.0, 0.0, 1.0, 4.0, 1.0, 0.0, 1.0, 2.0]));
    /// assert_eq!(r.as_slice(), &[3.0, 0.0, -3.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn system(&self, end: &EndCondition<T>) -> (DMatrix<T>, DMatrix<T>) {
        let (pts, t) = (&self.points, &self.params);
        let (d, m) = (pts.nrows(), pts.ncols());
        let segs = self.segment_count();
        let h: Vec<T> = (0..segs).map(|k| t[k + 1].clone() - t[k].clone()).collect();
        let delta = |k: usize, r: usize| {
            (pts[(r, (k + 1) % m)].clone() - pts[(r, k)].clone()) / h[k].clone()
        };
        let (two, three) = (T::from_usize(2), T::from_usize(3));
        let mut a = DMatrix::from_element(m, m, T::zero());
        let mut rhs = DMatrix::from_element(d, m, T::zero());
        for k in 0..m {
            if self.closed || (k > 0 && k + 1 < m) {
                let p = (k + m - 1) % m;
                let (hp, hn) = (h[p].clone(), h[k].clone());
                a[(k, p)] = a[(k, p)].clone() + hn.clone();
                a[(k, k)] = two.clone() * (hp.clone() + hn.clone());
                a[(k, (k + 1) % m)] = a[(k, (k + 1) % m)].clone() + hp.clone();
                for r in 0..d {
                    rhs[(r, k)] =
                        three.clone() * (hn.clone() * delta(p, r) + hp.clone() * delta(k, r));
                }
            } else if let EndCondition::Clamped { start, end } = end {
                a[(k, k)] = T::one();
                let v = if k == 0 { start } else { end };
                for r in 0..d {
                    rhs[(r, k)] = v[r].clone();
                }
            } else {
                let (j, seg) = if k == 0 { (1, 0) } else { (m - 2, m - 2) };
                a[(k, k)] = two.clone();
                a[(k, j)] = T::one();
                for r in 0..d {
                    rhs[(r, k)] = three.clone() * delta(seg, r);
                }
            }
        }
        (a, rhs)
    }

    /// Number of segments (`m − 1`, or `m` when closed).
    pub fn segment_count(&self) -> usize {
        self.params.len() - 1
    }

    /// Segment `k` as a Ferguson cubic over its local parameter `u ∈ [0, 1]`,
    /// `u = (t − t_k)/h_k`: its tangents are `h_k x'_k`, `h_k x'_{k+1}`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for `k ≥ segment_count()`; [`Error::Overflow`] for a scaled
    /// tangent whose double overflows.
    pub fn segment(&self, k: usize) -> Result<HermiteCubic<T>> {
        if k >= self.segment_count() {
            return Err(Error::InvalidArgument {
                what: "spline segment",
                message: format!(
                    "index {k}, but the spline has {} segments",
                    self.segment_count()
                ),
            });
        }
        let m = self.points.ncols();
        let j = (k + 1) % m;
        let h = self.params[k + 1].clone() - self.params[k].clone();
        let g = DMatrix::from_fn(self.dim(), 4, |r, c| match c {
            0 => self.points[(r, k)].clone(),
            1 => self.points[(r, j)].clone(),
            2 => h.clone() * self.tangents[(r, k)].clone(),
            _ => h.clone() * self.tangents[(r, j)].clone(),
        });
        check_overflow("spline segment tangents", g.iter())?;
        HermiteCubic::from_geometry(g)
    }

    /// The segment holding `t` (clamped to the ends) and the local parameter offset `t − t_k`.
    fn locate(&self, t: &T) -> (usize, T) {
        let last = self.segment_count() - 1;
        let above = self.params.partition_point(|p| p <= t);
        let k = above.saturating_sub(1).min(last);
        (k, t.clone() - self.params[k].clone())
    }

    /// The value, first and second derivative at `t` (with respect to `t`), from the local
    /// polynomial `y_k + s(x'_k + s(c_2 + s c_3))`, `s = t − t_k` (the piecewise-polynomial
    /// form Octave's `ppval` evaluates). Outside `[t_0, t_last]` the end segments continue.
    pub fn eval_with_derivatives(&self, t: T) -> [DVector<T>; 3] {
        let (k, s) = self.locate(&t);
        let m = self.points.ncols();
        let j = (k + 1) % m;
        let h = self.params[k + 1].clone() - self.params[k].clone();
        let (two, three) = (T::from_usize(2), T::from_usize(3));
        let d = self.dim();
        let mut out = [
            DVector::from_element(d, T::zero()),
            DVector::from_element(d, T::zero()),
            DVector::from_element(d, T::zero()),
        ];
        #[allow(clippy::needless_range_loop)] // r indexes three outputs and two matrices
        for r in 0..d {
            let y = self.points[(r, k)].clone();
            let (m0, m1) = (self.tangents[(r, k)].clone(), self.tangents[(r, j)].clone());
            let delta = (self.points[(r, j)].clone() - y.clone()) / h.clone();
            let c2 =
                (three.clone() * delta.clone() - two.clone() * m0.clone() - m1.clone()) / h.clone();
            let c3 = (m0.clone() + m1 - two.clone() * delta) / (h.clone() * h.clone());
            out[0][r] =
                y + s.clone() * (m0.clone() + s.clone() * (c2.clone() + s.clone() * c3.clone()));
            out[1][r] = m0
                + s.clone() * (two.clone() * c2.clone() + three.clone() * s.clone() * c3.clone());
            out[2][r] = two.clone() * c2 + T::from_usize(6) * s.clone() * c3;
        }
        out
    }

    /// The point at `t`.
    pub fn eval(&self, t: T) -> DVector<T> {
        let [v, _, _] = self.eval_with_derivatives(t);
        v
    }

    /// The points at `ts`, one per column (`d × ts.len()`), by
    /// [`eval_many_into`](Self::eval_many_into) (the values of [`eval`](Self::eval), bit for
    /// bit).
    pub fn eval_many(&self, ts: &[T]) -> DMatrix<T> {
        let mut out = DMatrix::from_element(self.dim(), ts.len(), T::zero());
        // Infallible: a non-finite point (far outside, or a NaN parameter) stays in place.
        let _ = self.fill_many(ts, out.as_mut_slice());
        out
    }

    /// The points at all parameters `ts` written into `out`, one after the other:
    /// `out[k·d + c]` is coordinate `c` of `x(ts[k])` (`ts.len() × d` row-major, the storage
    /// of [`eval_many`](Self::eval_many)'s `d × ts.len()` matrix; see [`crate::grid`]). As
    /// [`eval`](Self::eval), any finite parameter is accepted: outside `[t_0, t_last]` the end
    /// segments continue.
    ///
    /// The coefficients `y_k, x'_k, c_2, c_3` of every segment's local polynomial are computed
    /// once per call (`4·d` numbers per segment, by the formulas of
    /// [`eval_with_derivatives`](Self::eval_with_derivatives)); each parameter then finds its
    /// segment — the previous parameter's segment or the next one first (`O(1)` for sorted
    /// parameters), otherwise a binary search, no allocation — and the point is
    /// `y_k + s(x'_k + s(c_2 + s c_3))`, `s = t − t_k`: the operations of `eval`, so the same
    /// values bit for bit. Long batches are split over all cores.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `out.len() == ts.len() · d`; [`Error::NonFinite`] for
    /// a NaN or infinite parameter; [`Error::Overflow`] for a point whose double overflows
    /// (far outside; the buffer is written all the same).
    ///
    /// ```
    /// use cagd::spline::{CubicSpline, EndCondition};
    /// use nalgebra::DMatrix;
    /// let x = DMatrix::from_column_slice(1, 3, &[0.0, 1.0, 0.0]);
    /// let s = CubicSpline::interpolate(x, EndCondition::Natural)?;
    /// let mut out = [0.0; 3];
    /// s.eval_many_into(&[0.0, 1.0, 2.0], &mut out)?;
    /// assert_eq!(out, [0.0, 1.0, 0.0]);
    /// assert!(s.eval_many_into(&[0.5], &mut out).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        let len = crate::grid::grid_len("spline points", &[ts.len(), self.dim()])?;
        crate::grid::check_len("spline point buffer", len, out)?;
        crate::error::check_finite_slice("spline parameters", ts)?;
        self.fill_many(ts, out)
    }

    /// [`eval_many_into`](Self::eval_many_into) after the length check.
    fn fill_many(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        /// Points per block (one segment hint per block).
        const BLOCK: usize = 256;
        let d = self.dim();
        let segs = self.segment_count();
        let m = self.points.ncols();
        let (two, three) = (T::from_usize(2), T::from_usize(3));
        // coef[(k·d + r)·4 ..] = (y, x', c_2, c_3) of coordinate r on segment k.
        let mut coef = Vec::with_capacity(segs * d * 4);
        for k in 0..segs {
            let j = (k + 1) % m;
            let h = self.params[k + 1].clone() - self.params[k].clone();
            for r in 0..d {
                let y = self.points[(r, k)].clone();
                let (m0, m1) = (self.tangents[(r, k)].clone(), self.tangents[(r, j)].clone());
                let delta = (self.points[(r, j)].clone() - y.clone()) / h.clone();
                let c2 = (three.clone() * delta.clone() - two.clone() * m0.clone() - m1.clone())
                    / h.clone();
                let c3 = (m0.clone() + m1 - two.clone() * delta) / (h.clone() * h.clone());
                coef.extend([y, m0, c2, c3]);
            }
        }
        let params = &self.params;
        let last = segs - 1;
        let work = ts.len().saturating_mul(6 * d + 8);
        crate::grid::for_each_row(
            "spline points",
            out,
            BLOCK * d,
            work,
            || 0usize,
            |hint, block, chunk| {
                for (t, x) in ts[block * BLOCK..].iter().zip(chunk.chunks_exact_mut(d)) {
                    let k = segment_of(params, last, t, hint);
                    let s = t.clone() - params[k].clone();
                    for (o, c) in x.iter_mut().zip(coef[k * d * 4..].chunks_exact(4)) {
                        *o = c[0].clone()
                            + s.clone()
                                * (c[1].clone()
                                    + s.clone() * (c[2].clone() + s.clone() * c[3].clone()));
                    }
                }
            },
        )
    }
}

/// The segment `k ≤ last` of `t` that [`CubicSpline`]'s `locate` finds (the largest `k` with
/// `params[k] ≤ t`, at least 0 and at most `last`): the segment `hint` of the previous
/// parameter or the next one if it holds `t`, else a binary search; `hint` is updated.
#[inline]
fn segment_of<T: Scalar>(params: &[T], last: usize, t: &T, hint: &mut usize) -> usize {
    let holds =
        |k: usize| k <= last && (k == 0 || params[k] <= *t) && (k == last || *t < params[k + 1]);
    let k = if holds(*hint) {
        *hint
    } else if holds(*hint + 1) {
        *hint + 1
    } else {
        params
            .partition_point(|p| p <= t)
            .saturating_sub(1)
            .min(last)
    };
    *hint = k;
    k
}

impl<T: Scalar> Curve<T> for CubicSpline<T> {
    fn dim(&self) -> usize {
        CubicSpline::dim(self)
    }
    /// `[t_0, t_last]` (the end segments continue outside it).
    fn domain(&self) -> (T, T) {
        let last = self.params.len() - 1;
        (self.params[0].clone(), self.params[last].clone())
    }
    fn eval(&self, t: T) -> DVector<T> {
        CubicSpline::eval(self, t)
    }

    fn try_eval(&self, t: T) -> Result<DVector<T>> {
        crate::checked::try_eval_curve(self, "spline point", t)
    }

    /// [`sample_cost`] on the spline's own points and tangents.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        let data = crate::cost::max_bits(self.points.iter().chain(self.tangents.iter()));
        crate::cost::Cost::new(
            12 * self.dim() as u128,
            data.saturating_add(param_bits.saturating_mul(3)),
        )
    }
    /// [`CubicSpline::eval_many_into`]: segment coefficients once, no allocation per point.
    fn eval_many_into(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        CubicSpline::eval_many_into(self, ts, out)
    }
}

impl<T: Scalar> crate::param::CurveDeriv<T> for CubicSpline<T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        let [_, d, _] = self.eval_with_derivatives(t);
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spline_costs_grow_with_the_points_and_saturate() {
        let natural = interpolation_cost::<f64>(1000, 3, &EndCondition::Natural, 0);
        assert_eq!(natural, Cost::new(30_000, 4000));
        let clamped = EndCondition::<f64>::Clamped {
            start: DVector::zeros(3),
            end: DVector::zeros(3),
        };
        assert_eq!(interpolation_cost(1000, 3, &clamped, 0), natural);
        assert_eq!(sample_cost(1000, 3, 0, 10), Cost::new(36, 4030));
        assert_eq!(sample_cost(1, 1, u128::MAX, 1).bits(), u128::MAX);
    }
}
