//! [`ParamExpr::derivative`]: the derivative of an expression in one of its parameters, by
//! differentiating its tree, element by element (the rules are in its documentation).
//!
//! **Size.** A value or derivative larger than [`SHARED_NODES`] nodes is bound once in the
//! prelude, under a name no user can type (`#1`, `#2`, …), and read by name wherever a rule
//! needs it again: the derivative of `u*u*…*u` is linear in its length, not quadratic, and
//! no deeper than the expression, so evaluating it cannot overflow the stack.

use std::collections::{BTreeMap, BTreeSet};

use cagd::scalar::rational_from_decimal;

use super::eval::{is_builtin_name, walk};
use super::parser::{chain, BinOp, Node, Row};
use super::{Expr, Function, LiteralError, ParamExpr, Position};

/// The largest value or derivative (in nodes) written out wherever it is needed; a larger one
/// is bound to a name of its own in the prelude.
const SHARED_NODES: usize = 16;

/// Functions whose value is locally constant (shapes and constant fills): derivative zero.
const LOCALLY_CONSTANT: [&str; 5] = ["zeros", "ones", "numel", "length", "size"];

impl ParamExpr {
    /// The derivative in `param`: a [`ParamExpr`] whose value, evaluated with the same
    /// [`Env`](super::Env) and parameter bindings, is the element-wise derivative
    /// `d/dparam` of this expression's value, of the same shape.
    ///
    /// The rules, with `a`, `b` subexpressions, `da`, `db` their derivatives and `c` an
    /// expression that does not vary with `param`:
    ///
    /// | expression | derivative |
    /// |---|---|
    /// | a number, a constant `c` | `0`, `0 .* c + 0` (the shape of `c`, never −0) |
    /// | the parameter | `1` |
    /// | a name the prelude computes from the parameter | its derivative, bound in the prelude |
    /// | `-a`, `a'`, `[a b; …]` | `-da`, `da'`, `[da db; …]` |
    /// | `a + b`, `a - b` | `da + db`, `da - db` |
    /// | `a * b`, `a .* b` | `da * b + a * db` (the same operator) |
    /// | `a / b`, `a ./ b` | `da / b - a / b .* db / b` |
    /// | `a ^ n`, `a .^ n` (a literal integer `n`) | `n .* a ^ (n−1) .* da`, literally (`n = 0, 1, 2` give `0`, `da`, `2 .* a .* da`) |
    /// | `a ^ c` (other `c` that does not vary) | `c .* a ^ (c - 1) .* da` |
    /// | `a ^ b` (`b` varies) | `a ^ b .* (db .* log(a) + b .* da ./ a)` |
    /// | `sin(a)`, `cos(a)`, `tan(a)` | `cos(a) .* da`, `-(sin(a) .* da)`, `(1 + tan(a) .^ 2) .* da` |
    /// | `sqrt(a)`, `exp(a)`, `log(a)`, `abs(a)` | `da ./ (2 .* sqrt(a))`, `exp(a) .* da`, `da ./ a`, `a ./ abs(a) .* da` |
    /// | `linspace(a, b, n)` | `linspace(da, db, n)` |
    /// | `zeros`, `ones`, `numel`, `length`, `size` | `0` (they are locally constant) |
    /// | `x(i, j)`, `x` computed from the parameter | `dx(i, j)` |
    ///
    /// In exact arithmetic the derivative is rational wherever the expression is, with two
    /// exceptions: `a ^ b` with a varying `b` brings in `log(a)`, and `a ^ n` with an exponent
    /// that is not a literal computes `a ^ (n - 1)`, a division by zero at `a = 0` if `n = 0`. A literal power never divides by zero where
    /// the expression itself does not: `d/du u^2` is `2 .* u .* 1`, exact at `u = 0`.
    ///
    /// A name of the prelude (another curve of a data script) that depends on `param` gets its
    /// own derivative in the prelude, evaluated just before it. Names bound in the environment
    /// are constants; a variable of the environment named like a function (`sin`) is taken to
    /// be that function. Where this expression cannot be evaluated, the derivative may still
    /// be (it need not report the same error).
    ///
    /// The source text becomes `d/du (<source>)`.
    ///
    /// # Errors
    /// [`LiteralError::Unsupported`], naming the construct and its position, for what varies
    /// with `param` but has no derivative here: a range whose bounds vary, an index that
    /// varies, a function other than those above, `linspace` with a varying number of points
    /// (in a curve of the prelude: where its derivative is needed, not where only its size is).
    ///
    /// ```
    /// use cagd_octave::literal::{Env, ParamExpr};
    /// use num_rational::BigRational;
    ///
    /// let c1 = ParamExpr::parse("[u; 0; u-u^2]").unwrap();
    /// let dc1 = c1.derivative("u").unwrap();
    /// assert_eq!(dc1.source(), "d/du ([u; 0; u-u^2])");
    /// // At u = 1/3 the tangent is (1, 0, 1 − 2/3), exactly.
    /// let r = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    /// let t = dc1.eval_at(&Env::new(), &[("u", r(1, 3))]).unwrap();
    /// assert_eq!(t.as_slice(), &[r(1, 1), r(0, 1), r(1, 3)]);
    ///
    /// let err = ParamExpr::parse("[u; u:2]").unwrap().derivative("u").unwrap_err();
    /// assert_eq!(
    ///     err.to_string(),
    ///     "column 5: not supported: the derivative in `u` of a range whose start, increment or limit depends on `u`"
    /// );
    /// ```
    pub fn derivative(&self, param: &str) -> Result<ParamExpr, LiteralError> {
        let mut d = Deriver::new(param, &self.prelude);
        for (name, e) in &self.prelude {
            let meaning = match d.diff_node(e).map(|p| p.d) {
                // Refused only where the derivative is needed: `numel(c)` needs none.
                Err(err) => Meaning::Refused(err),
                Ok(None) => Meaning::Fixed,
                Ok(Some(de)) => {
                    let dname = d.fresh(&format!("d{name}/d{param}"));
                    d.out.push((dname.clone(), de));
                    Meaning::Varying(dname)
                }
            };
            d.out.push((name.clone(), e.clone()));
            d.names.insert(name.clone(), meaning);
        }
        let part = d.diff_node(&self.expr)?;
        let expr = part.d.unwrap_or_else(|| zero_like(&part.value));
        Ok(ParamExpr {
            prelude: live_entries(d.out, &expr),
            expr,
            source: format!("d/d{param} ({})", self.source),
        })
    }
}

/// What a name read by the expression stands for.
#[derive(Debug, Clone)]
enum Meaning {
    /// The parameter itself.
    Param,
    /// A prelude value that varies, with the name its derivative is bound to.
    Varying(String),
    /// A prelude value that does not vary.
    Fixed,
    /// A prelude value without a derivative, and why.
    Refused(LiteralError),
}

/// A subexpression differentiated: an expression of its value (small, or a name bound in
/// the prelude), its derivative (`None`: identically zero, of the value's shape), and whether
/// it reads a variable (which decides whether a 1×1 row of a matrix literal is repeated
/// along a longer row).
struct Part {
    value: Expr,
    d: Option<Expr>,
    reads: bool,
}

/// The state of one differentiation: the meaning of names, and the prelude being written.
struct Deriver<'p> {
    param: &'p str,
    names: BTreeMap<String, Meaning>,
    taken: BTreeSet<String>,
    out: Vec<(String, Expr)>,
    next: usize,
}

/// One step of [`Deriver::fold`]: from the prefix `A`, its derivative, `op` and its position,
/// and the next operand, the derivative of `A op f`.
type Step<'p> =
    fn(&mut Deriver<'p>, &mut Prefix, Option<Expr>, BinOp, Position, Part) -> Option<Expr>;

/// A left-associative chain being built: `base op₁ x₁ op₂ x₂ …`, kept flat.
struct Prefix {
    base: Expr,
    tail: Vec<(BinOp, Position, Expr)>,
}

impl Prefix {
    fn expr(&self) -> Expr {
        chain(self.base.clone(), self.tail.clone())
    }
}

impl<'p> Deriver<'p> {
    fn new(param: &'p str, prelude: &[(String, Expr)]) -> Self {
        Deriver {
            param,
            names: BTreeMap::from([(param.to_string(), Meaning::Param)]),
            taken: prelude.iter().map(|(n, _)| n.clone()).collect(),
            out: Vec::new(),
            next: 0,
        }
    }

    /// `stem`, or `stem#2`, `stem#3`, … if taken: never a name the lexer reads.
    fn fresh(&mut self, stem: &str) -> String {
        let mut name = stem.to_string();
        let mut k = 1;
        while self.taken.contains(&name) {
            k += 1;
            name = format!("{stem}#{k}");
        }
        self.taken.insert(name.clone());
        name
    }

    /// `e` itself if small, else a new prelude name bound to it.
    fn share(&mut self, e: Expr) -> Expr {
        if at_most_nodes(&e, SHARED_NODES) {
            return e;
        }
        let name = loop {
            self.next += 1;
            let candidate = format!("#{}", self.next);
            if !self.taken.contains(&candidate) {
                break candidate;
            }
        };
        self.taken.insert(name.clone());
        let at = e.at;
        self.out.push((name.clone(), e));
        Expr {
            node: Node::Var(name),
            at,
        }
    }

    /// The value of the chain so far, shared (a long chain is bound once and continued from
    /// its name).
    fn prefix_value(&mut self, prefix: &mut Prefix) -> Expr {
        let e = prefix.expr();
        if at_most_nodes(&e, SHARED_NODES) {
            return e;
        }
        let v = self.share(e);
        *prefix = Prefix {
            base: v.clone(),
            tail: Vec::new(),
        };
        v
    }

    fn unsupported(&self, at: Position, what: impl FnOnce(&str) -> String) -> LiteralError {
        LiteralError::Unsupported {
            at,
            what: format!("the derivative in `{}` of {}", self.param, what(self.param)),
        }
    }

    /// Whether `e` reads a variable: a name of the prelude, or any name but a builtin.
    fn reads_names(&self, e: &Expr) -> bool {
        let mut reads = false;
        walk(e, &mut |x| {
            if let Node::Var(n) | Node::Call { name: n, .. } = &x.node {
                reads |= self.names.contains_key(n) || !is_builtin_name(n);
            }
        });
        reads
    }

    /// [`Deriver::diff_node`] with its value and derivative shared.
    fn diff(&mut self, e: &Expr) -> Result<Part, LiteralError> {
        let part = self.diff_node(e)?;
        let value = self.share(part.value);
        let d = part.d.map(|d| self.share(d));
        Ok(Part {
            value,
            d,
            reads: part.reads,
        })
    }

    fn diff_node(&mut self, e: &Expr) -> Result<Part, LiteralError> {
        let at = e.at;
        Ok(match &e.node {
            Node::Number { .. } | Node::Colon => Part {
                value: e.clone(),
                d: None,
                reads: false,
            },
            Node::Var(name) => self.variable(e, name)?,
            Node::Call { name, args } => self.call(e, name, args)?,
            Node::Neg(x) => self.diff(x)?.map(|x| Node::Neg(Box::new(x)), at),
            Node::Transpose(x) => self.diff(x)?.map(|x| Node::Transpose(Box::new(x)), at),
            Node::Chain { first, rest } => match rest.first().map(|r| r.0) {
                None => self.diff_node(first)?,
                Some(BinOp::Add | BinOp::Sub) => self.sum(first, rest)?,
                Some(BinOp::Pow | BinOp::ElPow) => self.fold(first, rest, Self::power_step)?,
                Some(_) => self.fold(first, rest, Self::product_step)?,
            },
            Node::Range {
                base,
                increment,
                limit,
            } => self.range(at, base, increment.as_deref(), limit)?,
            Node::Matrix(rows) => self.matrix(at, rows)?,
        })
    }

    fn variable(&self, e: &Expr, name: &str) -> Result<Part, LiteralError> {
        let (d, reads) = match self.names.get(name) {
            Some(Meaning::Refused(err)) => return Err(err.clone()),
            Some(Meaning::Param) => (Some(number(1, e.at)), true),
            Some(Meaning::Varying(dname)) => (Some(var(dname, e.at)), true),
            Some(Meaning::Fixed) => (None, true),
            None => (None, !is_builtin_name(name)),
        };
        Ok(Part {
            value: e.clone(),
            d,
            reads,
        })
    }

    fn range(
        &mut self,
        at: Position,
        base: &Expr,
        increment: Option<&Expr>,
        limit: &Expr,
    ) -> Result<Part, LiteralError> {
        let b = self.diff(base)?;
        let s = increment.map(|s| self.diff(s)).transpose()?;
        let l = self.diff(limit)?;
        let varies = b.d.is_some() || l.d.is_some() || s.as_ref().is_some_and(|s| s.d.is_some());
        if varies {
            return Err(self.unsupported(at, |p| {
                format!("a range whose start, increment or limit depends on `{p}`")
            }));
        }
        let reads = b.reads || l.reads || s.as_ref().is_some_and(|s| s.reads);
        let node = Node::Range {
            base: Box::new(b.value),
            increment: s.map(|s| Box::new(s.value)),
            limit: Box::new(l.value),
        };
        Ok(Part {
            value: Expr { node, at },
            d: None,
            reads,
        })
    }

    /// `[…]`: each element differentiated. An element that reads no variable is kept as
    /// written, so that a constant 1×1 row is still repeated along a longer row.
    fn matrix(&mut self, at: Position, rows: &[Row]) -> Result<Part, LiteralError> {
        let mut values = Vec::with_capacity(rows.len());
        let mut derivatives = Vec::with_capacity(rows.len());
        let (mut varies, mut reads) = (false, false);
        for row in rows {
            let (mut vs, mut ds) = (Vec::new(), Vec::new());
            for x in &row.elements {
                let p = self.diff(x)?;
                let value = if p.reads { p.value } else { x.clone() };
                varies |= p.d.is_some();
                reads |= p.reads;
                ds.push(p.d.unwrap_or_else(|| zero_like(&value)));
                vs.push(value);
            }
            values.push(Row {
                at: row.at,
                elements: vs,
            });
            derivatives.push(Row {
                at: row.at,
                elements: ds,
            });
        }
        Ok(Part {
            value: Expr {
                node: Node::Matrix(values),
                at,
            },
            d: varies.then_some(Expr {
                node: Node::Matrix(derivatives),
                at,
            }),
            reads,
        })
    }

    /// `t₀ ± t₁ ± …`: the derivatives of the terms, with the same signs. A constant term
    /// stays as a zero of its shape (it may broadcast the sum), unless it is a number.
    fn sum(
        &mut self,
        first: &Expr,
        rest: &[(BinOp, Position, Expr)],
    ) -> Result<Part, LiteralError> {
        let p0 = self.diff(first)?;
        let mut reads = p0.reads;
        let mut terms = vec![(BinOp::Add, first.at, p0.d, p0.value.clone())];
        let mut tail = Vec::with_capacity(rest.len());
        for (op, at, x) in rest {
            let p = self.diff(x)?;
            reads |= p.reads;
            terms.push((*op, *at, p.d, p.value.clone()));
            tail.push((*op, *at, p.value));
        }
        let value = chain(p0.value, tail);
        if terms.iter().all(|t| t.2.is_none()) {
            return Ok(Part {
                value,
                d: None,
                reads,
            });
        }
        let signed = terms
            .into_iter()
            .filter_map(|(op, at, d, v)| match d {
                Some(d) => Some((op, at, d)),
                None if matches!(v.node, Node::Number { .. }) => None,
                None => Some((op, at, zero_like(&v))),
            })
            .collect();
        Ok(Part {
            value,
            d: Some(signed_sum(signed)),
            reads,
        })
    }

    /// A chain of one precedence level above the sum, `f₀ op₁ f₁ op₂ …`, left to right: with
    /// `A` the value so far, `d(A op f)` by `step` (which continues the prefix with `op f`).
    fn fold(
        &mut self,
        first: &Expr,
        rest: &[(BinOp, Position, Expr)],
        step: Step<'p>,
    ) -> Result<Part, LiteralError> {
        let p0 = self.diff(first)?;
        let (mut reads, mut d) = (p0.reads, p0.d);
        let mut prefix = Prefix {
            base: p0.value,
            tail: Vec::new(),
        };
        for (op, at, x) in rest {
            let f = self.diff(x)?;
            reads |= f.reads;
            d = if d.is_none() && f.d.is_none() {
                prefix.tail.push((*op, *at, f.value));
                None
            } else {
                step(self, &mut prefix, d, *op, *at, f).map(|d| self.share(d))
            };
        }
        Ok(Part {
            value: prefix.expr(),
            d,
            reads,
        })
    }

    /// `d(A op f)` for `op` one of `* .* / ./`: the product or quotient rule.
    fn product_step(
        &mut self,
        prefix: &mut Prefix,
        da: Option<Expr>,
        op: BinOp,
        at: Position,
        f: Part,
    ) -> Option<Expr> {
        let a = self.prefix_value(prefix);
        prefix.tail.push((op, at, f.value.clone()));
        Some(product_rule(a, da, op, at, &f.value, f.d))
    }

    /// `d(A ^ b)` (and `.^`): a power rule for a constant exponent, else through `log`.
    fn power_step(
        &mut self,
        prefix: &mut Prefix,
        da: Option<Expr>,
        op: BinOp,
        at: Position,
        b: Part,
    ) -> Option<Expr> {
        let a = self.prefix_value(prefix);
        prefix.tail.push((op, at, b.value.clone()));
        match (da, b.d) {
            (Some(da), None) => constant_power_rule(a, da, op, at, &b.value),
            (da, Some(db)) => {
                let v = self.prefix_value(prefix);
                Some(varying_power_rule(v, a, da, db, at, &b.value))
            }
            (None, None) => None,
        }
    }

    fn call(&mut self, e: &Expr, name: &str, args: &[Expr]) -> Result<Part, LiteralError> {
        if let Some(meaning) = self.names.get(name).cloned() {
            return self.index(e.at, name, args, meaning);
        }
        if let Some(f) = Function::from_name(name) {
            if let [x] = args {
                return self.function(e.at, f, x);
            }
        }
        if LOCALLY_CONSTANT.contains(&name) {
            // No derivative of the arguments is needed (nor refused).
            return Ok(Part {
                value: e.clone(),
                d: None,
                reads: self.reads_names(e),
            });
        }
        let parts = args
            .iter()
            .map(|a| self.diff(a))
            .collect::<Result<Vec<_>, _>>()?;
        let reads = !is_builtin_name(name) || parts.iter().any(|p| p.reads);
        let varies = parts.iter().any(|p| p.d.is_some());
        // A function called with the wrong number of arguments: its value reports it.
        let wrong_arity = Function::from_name(name).is_some() && args.len() != 1;
        if name == "linspace" && varies {
            return self.linspace(e.at, parts);
        }
        if varies && !wrong_arity {
            return Err(self.unsupported(e.at, |p| {
                format!("`{name}(…)` with an argument that depends on `{p}`: only sin, cos, tan, sqrt, exp, log, abs, linspace and the indexing of a curve of the script by a constant index have derivatives")
            }));
        }
        let values = parts.into_iter().map(|p| p.value).collect();
        Ok(Part {
            value: call_expr(name, values, e.at),
            d: None,
            reads,
        })
    }

    /// `x(i, j)` of the parameter or a prelude name: the same elements of its derivative.
    fn index(
        &mut self,
        at: Position,
        name: &str,
        args: &[Expr],
        meaning: Meaning,
    ) -> Result<Part, LiteralError> {
        let mut values = Vec::with_capacity(args.len());
        for a in args {
            let p = self.diff(a)?;
            if p.d.is_some() {
                return Err(self.unsupported(a.at, |p| {
                    format!("`{name}(…)` indexed by an index that depends on `{p}`")
                }));
            }
            values.push(p.value);
        }
        let value = call_expr(name, values.clone(), at);
        let d = match meaning {
            // `u(1)` is `u`: ones of the shape the indexing gives.
            Meaning::Param => Some(bin(
                zero_times(value.clone()),
                BinOp::Add,
                at,
                number(1, at),
            )),
            Meaning::Varying(dname) => Some(call_expr(&dname, values, at)),
            Meaning::Fixed => None,
            Meaning::Refused(err) => return Err(err),
        };
        Ok(Part {
            value,
            d,
            reads: true,
        })
    }

    /// The chain rule for the element-wise functions, reusing the value `f(a)` where the
    /// derivative contains it.
    fn function(&mut self, at: Position, f: Function, x: &Expr) -> Result<Part, LiteralError> {
        use BinOp::{Add, ElDiv, ElMul, ElPow};
        let p = self.diff(x)?;
        let a = p.value;
        let value = call_expr(f.name(), vec![a.clone()], at);
        let Some(da) = p.d else {
            return Ok(Part {
                value,
                d: None,
                reads: p.reads,
            });
        };
        let v = self.share(value);
        let d = match f {
            Function::Sin => chain(call_expr("cos", vec![a], at), vec![(ElMul, at, da)]),
            Function::Cos => neg(bin(call_expr("sin", vec![a], at), ElMul, at, da)),
            Function::Tan => {
                let square = bin(v.clone(), ElPow, at, number(2, at));
                bin(bin(number(1, at), Add, at, square), ElMul, at, da)
            }
            Function::Sqrt => bin(da, ElDiv, at, bin(number(2, at), ElMul, at, v.clone())),
            Function::Exp => bin(v.clone(), ElMul, at, da),
            Function::Log => bin(da, ElDiv, at, a),
            Function::Abs => chain(a, vec![(ElDiv, at, v.clone()), (ElMul, at, da)]),
        };
        Ok(Part {
            value: v,
            d: Some(d),
            reads: p.reads,
        })
    }

    /// `linspace(a, b, n)` is linear in `a` and `b`: its derivative is `linspace(da, db, n)`.
    fn linspace(&mut self, at: Position, parts: Vec<Part>) -> Result<Part, LiteralError> {
        let [a, b, n]: [Part; 3] = match parts.try_into() {
            Ok(parts) => parts,
            // A wrong number of arguments: the value reports it when evaluated.
            Err(parts) => {
                let values = parts.into_iter().map(|p| p.value).collect();
                return Ok(Part {
                    value: call_expr("linspace", values, at),
                    d: None,
                    reads: true,
                });
            }
        };
        if n.d.is_some() {
            return Err(self.unsupported(at, |p| {
                format!("`linspace(a, b, n)` whose number of points n depends on `{p}`")
            }));
        }
        let da = a.d.unwrap_or_else(|| zero_like(&a.value));
        let db = b.d.unwrap_or_else(|| zero_like(&b.value));
        Ok(Part {
            d: Some(call_expr("linspace", vec![da, db, n.value.clone()], at)),
            value: call_expr("linspace", vec![a.value, b.value, n.value], at),
            reads: true,
        })
    }
}

impl Part {
    /// The part of a unary operation `node(x)`.
    fn map(self, node: impl Fn(Expr) -> Node, at: Position) -> Part {
        Part {
            value: Expr {
                node: node(self.value),
                at,
            },
            d: self.d.map(|d| Expr { node: node(d), at }),
            reads: self.reads,
        }
    }
}

/// `d(A op f)` for `op` one of `* .* / ./`, from `A`, its derivative `dA`, `f` and `df`.
fn product_rule(
    a: Expr,
    da: Option<Expr>,
    op: BinOp,
    at: Position,
    f: &Expr,
    df: Option<Expr>,
) -> Expr {
    let mut terms = Vec::with_capacity(2);
    if let Some(da) = da {
        terms.push((BinOp::Add, at, bin(da, op, at, f.clone())));
    }
    if let Some(df) = df {
        terms.push(match op {
            BinOp::Mul | BinOp::ElMul => (BinOp::Add, at, bin(a, op, at, df)),
            // d(A / f) = dA / f − A / f .* df / f
            _ => {
                let rest = vec![
                    (op, at, f.clone()),
                    (BinOp::ElMul, at, df),
                    (op, at, f.clone()),
                ];
                (BinOp::Sub, at, chain(a, rest))
            }
        });
    }
    signed_sum(terms)
}

/// `d(a op c)` for a power `op` whose exponent `c` does not vary; `None` for `c = 0`.
fn constant_power_rule(a: Expr, da: Expr, op: BinOp, at: Position, c: &Expr) -> Option<Expr> {
    let times = |factors: Vec<Expr>| {
        let mut factors = factors.into_iter();
        let first = factors.next().expect("a product has factors");
        chain(first, factors.map(|f| (BinOp::ElMul, at, f)).collect())
    };
    Some(match literal_integer(c) {
        Some(0) => return None,
        Some(1) => da,
        Some(2) => times(vec![number(2, at), a, da]),
        Some(n) => times(vec![number(n, at), bin(a, op, at, number(n - 1, at)), da]),
        None => {
            let lowered = bin(c.clone(), BinOp::Sub, at, number(1, at));
            times(vec![c.clone(), bin(a, op, at, lowered), da])
        }
    })
}

/// `d(a ^ b) = a ^ b .* (db .* log(a) + b .* da ./ a)`, with `v` the value `a ^ b`.
fn varying_power_rule(
    v: Expr,
    a: Expr,
    da: Option<Expr>,
    db: Expr,
    at: Position,
    b: &Expr,
) -> Expr {
    let log_a = call_expr("log", vec![a.clone()], at);
    let mut terms = vec![(BinOp::Add, at, bin(db, BinOp::ElMul, at, log_a))];
    if let Some(da) = da {
        let rest = vec![(BinOp::ElMul, at, da), (BinOp::ElDiv, at, a)];
        terms.push((BinOp::Add, at, chain(b.clone(), rest)));
    }
    bin(v, BinOp::ElMul, at, signed_sum(terms))
}

/// The integer a literal exponent (`2`, `-1`, `3.0`) stands for, exactly; `None` for any
/// other exponent (`0.5`, `n`, `3.0000000000000001`, beyond 2⁵³).
fn literal_integer(e: &Expr) -> Option<i64> {
    match &e.node {
        Node::Number { text, value } => {
            let exact = value.fract() == 0.0 && value.abs() < 9.0e15;
            (exact && rational_from_decimal(text)?.is_integer()).then_some(*value as i64)
        }
        Node::Neg(x) => literal_integer(x).map(|n| -n),
        _ => None,
    }
}

/// Whether `e` has at most `limit` nodes (without counting a large tree to its end).
fn at_most_nodes(e: &Expr, limit: usize) -> bool {
    fn count(e: &Expr, budget: &mut usize) -> bool {
        if *budget == 0 {
            return false;
        }
        *budget -= 1;
        match &e.node {
            Node::Number { .. } | Node::Var(_) | Node::Colon => true,
            Node::Call { args, .. } => args.iter().all(|a| count(a, budget)),
            Node::Neg(x) | Node::Transpose(x) => count(x, budget),
            Node::Chain { first, rest } => {
                count(first, budget) && rest.iter().all(|(_, _, x)| count(x, budget))
            }
            Node::Range {
                base,
                increment,
                limit,
            } => {
                count(base, budget)
                    && increment.as_deref().is_none_or(|s| count(s, budget))
                    && count(limit, budget)
            }
            Node::Matrix(rows) => rows
                .iter()
                .all(|r| r.elements.iter().all(|x| count(x, budget))),
        }
    }
    let mut budget = limit;
    count(e, &mut budget)
}

/// The prelude entries the expression needs, in order: an entry is kept if a later kept entry
/// or the expression reads its name before another entry binds it again.
fn live_entries(entries: Vec<(String, Expr)>, expr: &Expr) -> Vec<(String, Expr)> {
    let mut live = BTreeSet::new();
    names_read(expr, &mut live);
    let mut kept = Vec::new();
    for (name, e) in entries.into_iter().rev() {
        if live.remove(&name) {
            names_read(&e, &mut live);
            kept.push((name, e));
        }
    }
    kept.reverse();
    kept
}

/// Every name the expression reads, builtin names included (a prelude may bind `size`).
fn names_read(e: &Expr, out: &mut BTreeSet<String>) {
    walk(e, &mut |x| {
        if let Node::Var(n) | Node::Call { name: n, .. } = &x.node {
            out.insert(n.clone());
        }
    });
}

/// `t₀ ± t₁ ± …` from signed terms (the first one's sign as a unary minus); at least one term.
fn signed_sum(terms: Vec<(BinOp, Position, Expr)>) -> Expr {
    let mut terms = terms.into_iter();
    let (op, _, first) = terms.next().expect("a sum has terms");
    let first = if op == BinOp::Sub { neg(first) } else { first };
    chain(first, terms.collect())
}

/// A zero of the shape of `v`: `0` for a number, else `0 .* v + 0` (`+ 0` so that a
/// negative constant does not give −0 in `f64`).
fn zero_like(v: &Expr) -> Expr {
    if matches!(v.node, Node::Number { .. }) {
        return number(0, v.at);
    }
    bin(zero_times(v.clone()), BinOp::Add, v.at, number(0, v.at))
}

/// `0 .* v`.
fn zero_times(v: Expr) -> Expr {
    let at = v.at;
    bin(number(0, at), BinOp::ElMul, at, v)
}

fn bin(a: Expr, op: BinOp, at: Position, b: Expr) -> Expr {
    chain(a, vec![(op, at, b)])
}

fn neg(x: Expr) -> Expr {
    let at = x.at;
    Expr {
        node: Node::Neg(Box::new(x)),
        at,
    }
}

/// The integer `n` as a literal (a negative one as `-m`).
fn number(n: i64, at: Position) -> Expr {
    let literal = Expr {
        node: Node::Number {
            text: n.unsigned_abs().to_string(),
            value: n.unsigned_abs() as f64,
        },
        at,
    };
    if n < 0 {
        neg(literal)
    } else {
        literal
    }
}

fn var(name: &str, at: Position) -> Expr {
    Expr {
        node: Node::Var(name.to_string()),
        at,
    }
}

fn call_expr(name: &str, args: Vec<Expr>, at: Position) -> Expr {
    Expr {
        node: Node::Call {
            name: name.to_string(),
            args,
        },
        at,
    }
}

#[cfg(test)]
mod tests;
