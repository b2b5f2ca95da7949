//! [`ParamExpr`]: an expression in free parameters, sampled as a curve or a surface.

use std::collections::BTreeSet;

use nalgebra::DMatrix;

use cagd::grid::PointGrid;
use cagd::limits::Limits;

use super::{eval, Env, Expr, LiteralError, LiteralScalar};

/// The parameter names an expression may leave free: `u`, `v` and `t`.
pub const PARAMETERS: [&str; 3] = ["u", "v", "t"];

/// An expression in free parameters (`u`, `v`, `t`) evaluated once per sample — how the
/// thesis writes curves: `c1 = [u; 0; u-u^2]`, `d1 = [0.5; v; 0.25+v]`.
///
/// Each evaluation binds the parameter to one scalar sample, so `u^2` is the square of that
/// sample. The value at a sample must be a scalar, a row or a column vector (the point); the
/// samples of a curve become the columns of a d × k matrix, like `T` in the thesis function
/// `deCasteljau`. Sampling evaluates in a copy of the environment and adds only its warnings
/// to it.
///
/// A `ParamExpr` may read other bound variables (from `--script` files: see
/// [`crate::script`]) and may depend on other parameter expressions of a script,
/// which are evaluated first at every sample (its *prelude*).
#[derive(Debug, Clone, PartialEq)]
pub struct ParamExpr {
    pub(crate) prelude: Vec<(String, Expr)>,
    pub(crate) expr: Expr,
    pub(crate) source: String,
}

impl ParamExpr {
    /// Parses an expression (with the default [`Limits`]).
    pub fn parse(text: &str) -> Result<ParamExpr, LiteralError> {
        Self::parse_with(text, &Limits::default())
    }

    /// Parses an expression within the given limits.
    pub fn parse_with(text: &str, limits: &Limits) -> Result<ParamExpr, LiteralError> {
        Ok(ParamExpr {
            prelude: Vec::new(),
            expr: Expr::parse_with(text, limits)?,
            source: text.to_string(),
        })
    }

    /// The source text.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The size of one evaluation: the nodes of the expression and of its prelude
    /// ([`Expr::node_count`]). Sampling at `k` parameter values costs about `k` times this.
    ///
    /// ```
    /// use cagd_octave::literal::ParamExpr;
    /// assert_eq!(ParamExpr::parse("[u; 0; u-u^2]").unwrap().node_count(), 8);
    /// ```
    pub fn node_count(&self) -> usize {
        self.prelude
            .iter()
            .map(|(_, e)| e.node_count())
            .fold(self.expr.node_count(), usize::saturating_add)
    }

    /// The work of one evaluation estimated before any is done: an operation per node
    /// ([`node_count`](Self::node_count)) on numbers of `param_bits` bits, the size of the
    /// parameters bound. What [`eval_metered`](Self::eval_metered) measures may be more (powers
    /// and products grow the numbers in exact arithmetic).
    ///
    /// ```
    /// use cagd_octave::literal::ParamExpr;
    /// let e = ParamExpr::parse("[u; 0; u-u^2]").unwrap();
    /// assert_eq!(e.point_cost(53), cagd::cost::Cost::new(8, 53));
    /// ```
    pub fn point_cost(&self, param_bits: u128) -> cagd::cost::Cost {
        cagd::cost::Cost::new(self.node_count() as u128, param_bits)
    }

    /// The parameters (`u`, `v`, `t`) used but not bound in `env`, sorted.
    pub fn parameters<T: LiteralScalar>(&self, env: &Env<T>) -> Vec<&'static str> {
        let mut bound: BTreeSet<&str> = env.names().collect();
        let mut used = BTreeSet::new();
        for (name, e) in &self.prelude {
            for n in e.free_names() {
                if !bound.contains(n.as_str()) {
                    used.insert(n);
                }
            }
            bound.insert(name.as_str());
        }
        for n in self.expr.free_names() {
            if !bound.contains(n.as_str()) {
                used.insert(n);
            }
        }
        PARAMETERS
            .iter()
            .copied()
            .filter(|p| used.contains(*p))
            .collect()
    }

    /// Checks that every name is bound in `env`, is one of `params`, or is computed by the
    /// prelude — so that an unknown name is reported once, before sampling.
    pub fn check<T: LiteralScalar>(
        &self,
        env: &Env<T>,
        params: &[&str],
    ) -> Result<(), LiteralError> {
        let mut known: BTreeSet<String> = env.names().map(str::to_string).collect();
        known.extend(params.iter().map(|p| p.to_string()));
        let check = |e: &Expr, known: &BTreeSet<String>| -> Result<(), LiteralError> {
            for (name, at) in e.name_uses() {
                if !known.contains(&name) && !eval::is_builtin_name(&name) {
                    return Err(eval::unknown_name_error(e, &name, at));
                }
            }
            Ok(())
        };
        for (name, e) in &self.prelude {
            check(e, &known)?;
            known.insert(name.clone());
        }
        check(&self.expr, &known)
    }

    /// The value with the parameters bound as given (e.g. `[("u", 0.5)]`).
    pub fn eval_at<T: LiteralScalar>(
        &self,
        env: &Env<T>,
        bindings: &[(&str, T)],
    ) -> Result<DMatrix<T>, LiteralError> {
        let mut local = env.clone();
        self.eval_in(&mut local, bindings)
    }

    /// The value with the parameters bound as given, and the work its evaluation did: element
    /// results and matrix-product terms, an exact operation on numbers of `a` and `b` words
    /// counting `32 (a + b)²` (the measure of an evaluation's own limit). The command line
    /// evaluates an expression once at its largest parameter this way to estimate what
    /// sampling it will cost before it starts.
    ///
    /// ```
    /// use cagd_octave::literal::{Env, ParamExpr};
    /// use num_rational::BigRational;
    /// let e = ParamExpr::parse("[u; u^2]").unwrap();
    /// let (_, cheap) = e.eval_metered(&Env::<f64>::new(), &[("u", 0.5)]).unwrap();
    /// let half = BigRational::new(1.into(), 2.into());
    /// let (p, exact) = e.eval_metered(&Env::<BigRational>::new(), &[("u", half)]).unwrap();
    /// assert_eq!(p[(1, 0)], BigRational::new(1.into(), 4.into()));
    /// assert!(cheap < exact);
    /// ```
    ///
    /// # Errors
    /// As [`ParamExpr::eval_at`].
    pub fn eval_metered<T: LiteralScalar>(
        &self,
        env: &Env<T>,
        bindings: &[(&str, T)],
    ) -> Result<(DMatrix<T>, u128), LiteralError> {
        let mut local = env.clone();
        for (name, value) in bindings {
            local.bind_scalar(name, value.clone());
        }
        let mut work: u128 = 0;
        for (name, e) in &self.prelude {
            let value = e.eval(&mut local)?;
            work = work.saturating_add(local.meter.work());
            local.bind(name, value);
        }
        let value = self.expr.eval(&mut local)?;
        Ok((value, work.saturating_add(local.meter.work())))
    }

    fn eval_in<T: LiteralScalar>(
        &self,
        local: &mut Env<T>,
        bindings: &[(&str, T)],
    ) -> Result<DMatrix<T>, LiteralError> {
        for (name, value) in bindings {
            local.bind_scalar(name, value.clone());
        }
        for (name, e) in &self.prelude {
            let value = e.eval(local)?;
            local.bind(name, value);
        }
        self.expr.eval(local)
    }

    /// Samples a curve in parameter `param` at `values`: a d × k matrix whose column `j` is
    /// the point at `values[j]`. Each sample must evaluate to a vector of the same length d.
    ///
    /// ```
    /// use cagd_octave::literal::{Env, ParamExpr};
    /// let d1 = ParamExpr::parse("[0.5; v; 0.25+v]").unwrap();
    /// let pts = d1.sample_curve(&mut Env::<f64>::new(), "v", &[0.0, 1.0]).unwrap();
    /// assert_eq!(pts.column(1).as_slice(), &[0.5, 1.0, 1.25]);
    /// ```
    pub fn sample_curve<T: LiteralScalar>(
        &self,
        env: &mut Env<T>,
        param: &str,
        values: &[T],
    ) -> Result<DMatrix<T>, LiteralError> {
        self.check(env, &[param])?;
        let mut local = env.clone();
        let mut columns: Vec<T> = Vec::new();
        let mut dim = None;
        for t in values {
            let p = self.eval_in(&mut local, &[(param, t.clone())])?;
            let d = self.point_dim(&p, dim)?;
            dim = Some(d);
            columns.extend(p.iter().cloned());
        }
        env.warnings.append(&mut local.warnings);
        Ok(DMatrix::from_vec(dim.unwrap_or(0), values.len(), columns))
    }

    /// Samples a surface in `u` and `v` on the grid `us × vs`: a [`PointGrid`] of shape
    /// `(us.len(), vs.len(), d)` with `grid[[i, j, k]]` coordinate `k` of the point at
    /// `(us[i], vs[j])` (the layout of `P(i,j,:)` in the thesis function `ploskevB`).
    pub fn sample_surface<T: LiteralScalar>(
        &self,
        env: &mut Env<T>,
        us: &[T],
        vs: &[T],
    ) -> Result<PointGrid<T>, LiteralError> {
        self.check(env, &["u", "v"])?;
        let total = us.len().saturating_mul(vs.len());
        if total > env.limits.max_elements {
            return Err(LiteralError::TooLarge {
                at: self.expr.at,
                what: "the sample grid".into(),
                count: total as u128,
                limit: env.limits.max_elements,
            });
        }
        let mut local = env.clone();
        let mut points: Vec<DMatrix<T>> = Vec::with_capacity(total);
        let mut dim = None;
        for u in us {
            for v in vs {
                let p = self.eval_in(&mut local, &[("u", u.clone()), ("v", v.clone())])?;
                dim = Some(self.point_dim(&p, dim)?);
                points.push(p);
            }
        }
        let d = dim.unwrap_or(0);
        env.warnings.append(&mut local.warnings);
        Ok(PointGrid::from_shape_fn(
            (us.len(), vs.len(), d),
            |(i, j, k)| points[i * vs.len() + j][k].clone(),
        ))
    }

    fn point_dim<T: LiteralScalar>(
        &self,
        p: &DMatrix<T>,
        previous: Option<usize>,
    ) -> Result<usize, LiteralError> {
        if p.nrows() > 1 && p.ncols() > 1 {
            return Err(LiteralError::Shape {
                at: self.expr.at,
                message: format!(
                    "a curve point must be a vector, but the expression gives a {}×{} matrix",
                    p.nrows(),
                    p.ncols()
                ),
            });
        }
        let d = p.len();
        match previous {
            Some(prev) if prev != d => Err(LiteralError::Shape {
                at: self.expr.at,
                message: format!(
                    "points of different dimensions at different samples ({prev} and {d})"
                ),
            }),
            _ => Ok(d),
        }
    }
}
