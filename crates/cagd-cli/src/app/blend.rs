//! `coons --blend`: the Coons patch with other blending functions (thesis (4.4)): the linear
//! pair of the bilinear patch, the cubic Hermite pair `H0³, H3³` of the partially bicubic patch
//! (§4.2), or a pair of the user's.

use cagd::coons::{BlendingPair, CoonsBoundary, CoonsPatch, CoonsPoint, GeneralizedCoonsPatch};
use cagd::limits::Limits;
use cagd::{Curve, Surface};
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr};
use nalgebra::DVector;

use crate::CliError;

/// The form of `--blend`.
pub const BLEND_FORM: &str = "linear, hermite, or f1 as an expression in t such as \"1-3*t^2+2*t^3\" (f2 = 1 − f1), or the pair \"[f1; f2]\"";

/// A Coons patch with the linear (bilinear) or another blending pair.
pub enum BlendedCoons<C, T: LiteralScalar> {
    /// `x = r_c + r_d − r_cd` with `(1 − t, t)`: thesis Izrek 4.2.
    Bilinear(CoonsPatch<C, T>),
    /// The same with the pairs `f` in `u` and `g` in `v`.
    Blended(GeneralizedCoonsPatch<C, T>),
}

impl<C: Curve<T>, T: LiteralScalar> BlendedCoons<C, T> {
    /// The point with its parts `r_c`, `r_d`, `r_cd`.
    pub fn parts(&self, u: T, v: T) -> CoonsPoint<T> {
        match self {
            BlendedCoons::Bilinear(p) => p.eval_parts(u, v),
            BlendedCoons::Blended(p) => p.eval_parts(u, v),
        }
    }
}

impl<C: Curve<T>, T: LiteralScalar> Surface<T> for BlendedCoons<C, T> {
    fn domain(&self) -> ((T, T), (T, T)) {
        match self {
            BlendedCoons::Bilinear(p) => p.domain(),
            BlendedCoons::Blended(p) => p.domain(),
        }
    }

    fn dim(&self) -> usize {
        match self {
            BlendedCoons::Bilinear(p) => p.dim(),
            BlendedCoons::Blended(p) => p.dim(),
        }
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        match self {
            BlendedCoons::Bilinear(p) => p.eval(u, v),
            BlendedCoons::Blended(p) => p.eval(u, v),
        }
    }

    fn eval_grid(&self, us: &[T], vs: &[T]) -> cagd::grid::PointGrid<T> {
        match self {
            BlendedCoons::Bilinear(p) => p.eval_grid(us, vs),
            BlendedCoons::Blended(p) => p.eval_grid(us, vs),
        }
    }
}

/// The blending pair of `--blend` (`None`: linear, the bilinear patch), with user functions
/// evaluated in advance at `at` and at the check points `k/32` of
/// [`GeneralizedCoonsPatch::new`] (the patch only evaluates them there).
pub fn blending_pair<T: LiteralScalar>(
    limits: &Limits,
    text: Option<&str>,
    at: &[T],
) -> Result<Option<BlendingPair<T>>, CliError> {
    let text = match text.map(str::trim) {
        None | Some("linear") => return Ok(None),
        Some("hermite") => return Ok(Some(BlendingPair::hermite_cubic())),
        Some(t) => t,
    };
    let expr = ParamExpr::parse_with(text, limits)
        .map_err(|e| CliError::literal("--blend", e, BLEND_FORM))?;
    let env = Env::<T>::with_limits(*limits);
    let params = expr.parameters(&env);
    let name = match params.as_slice() {
        [] => "t",
        [p] => *p,
        _ => {
            return Err(super::common::shape(
                "--blend",
                format!("`{text}` uses the parameters {}", params.join(" and ")),
                BLEND_FORM,
            ))
        }
    };
    let mut points: Vec<T> = at.to_vec();
    points.extend((0..=32).map(|k| T::from_ratio(k, 32)));
    points.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    points.dedup();
    super::work::check_expression_work(
        limits,
        &[super::work::Sampling {
            argument: "--blend",
            expr: &expr,
            params: vec![(name, &points)],
        }],
        &env,
    )?;
    let mut table: Vec<(T, T, T)> = Vec::with_capacity(points.len());
    for t in points {
        let m = expr
            .eval_at(&env, &[(name, t.clone())])
            .map_err(|e| CliError::literal("--blend", e, BLEND_FORM))?;
        let (f1, f2) = match m.as_slice() {
            [f1] => (f1.clone(), T::one() - f1.clone()),
            [f1, f2] => (f1.clone(), f2.clone()),
            _ => {
                return Err(super::common::shape(
                    "--blend",
                    format!("a {}×{} value", m.nrows(), m.ncols()),
                    BLEND_FORM,
                ))
            }
        };
        table.push((t, f1, f2));
    }
    let table = std::sync::Arc::new(table);
    let lookup = |table: &[(T, T, T)], t: &T, second: bool| -> T {
        match table
            .binary_search_by(|(x, _, _)| x.partial_cmp(t).unwrap_or(std::cmp::Ordering::Equal))
        {
            Ok(k) if second => table[k].2.clone(),
            Ok(k) => table[k].1.clone(),
            // Every parameter the patch asks for was tabulated.
            Err(_) => T::zero(),
        }
    };
    let (t1, t2) = (table.clone(), table);
    Ok(Some(BlendingPair::new(
        "--blend",
        move |t: T| lookup(&t1, &t, false),
        move |t: T| lookup(&t2, &t, true),
    )))
}

/// The patch of four curves (with the script's corners, if given) and `pair` in both
/// directions.
pub fn coons_patch<C: Curve<T> + Clone, T: LiteralScalar>(
    [c1, c2, d1, d2]: [C; 4],
    corners: Option<[DVector<T>; 4]>,
    pair: Option<BlendingPair<T>>,
) -> Result<BlendedCoons<C, T>, cagd::Error> {
    let tolerance = cagd::Tolerance::default();
    match pair {
        None => match corners {
            Some(c) => CoonsPatch::with_corners(c1, c2, d1, d2, c, tolerance),
            None => CoonsPatch::new(c1, c2, d1, d2),
        }
        .map(BlendedCoons::Bilinear),
        Some(f) => {
            let boundary = match corners {
                Some(c) => CoonsBoundary::with_corners(c1, c2, d1, d2, c, tolerance)?,
                None => CoonsBoundary::new(c1, c2, d1, d2, tolerance)?,
            };
            GeneralizedCoonsPatch::from_boundary(
                boundary,
                f.clone(),
                f,
                cagd::coons::BLEND_TOLERANCE,
            )
            .map(BlendedCoons::Blended)
        }
    }
}
