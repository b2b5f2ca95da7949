//! Reader for thesis-style Octave data scripts (`--script file.m`).
//!
//! The thesis gives its input data as small Octave scripts (appendices C and D):
//!
//! ```text
//! u = linspace(0,1,N);
//! c1x = u;
//! c1z = zeros(1,N);
//! for i = 1:N
//!     c1z(i) = u(i)-(u(i))^2;
//! end;
//! c1 = [c1x;c1y;c1z];
//! P1 = [0;0;0];
//! ```
//!
//! [`run`] executes such a script and returns the variables it binds. Supported: assignments
//! `name = expr` (one per line, or several separated by `;` or `,`), indexed assignments
//! `x(i) = expr` and `x(i,j) = expr` of scalars (growing the array as Octave does),
//! `for var = expr ... end` loops (`endfor` too; nested), `%` and `#` comments, `...`
//! continuations, and every expression of [`crate::literal`] (`linspace`, `zeros`,
//! `ones`, ranges, element-wise arithmetic, concatenation, indexing). A bare expression is
//! assigned to `ans`.
//!
//! **Curves in a free parameter.** A right-hand side that reads one of the parameters `u`,
//! `v`, `t` while it is not bound — appendix C's `c1 = [u;0;u-u^2];` for `vrednostCoons` —
//! is kept as a [`ParamExpr`] (a curve or surface in that parameter), evaluated per sample
//! when a command asks for it; later definitions may combine such curves (`g_u = [c0 c1
//! c2]`). Reassigning a variable that such a curve reads is an error (the curve would
//! otherwise silently change).
//!
//! **Deliberate differences from Octave**, each documented where it happens:
//! - `u^2` (and `*`, `/`) on a sampled vector `u` is evaluated element-wise with a
//!   [`Warning`]: in Octave it is an error ("for x^y, only square matrix arguments are
//!   permitted"), but it is what the thesis's appendix D means;
//! - a constant 1×1 row in a column of sampled rows (`[u; 0; u-u^2]` with `u` a 1×N vector) is
//!   repeated along the row, with a warning (Octave: "vertical dimensions mismatch");
//! - chained assignment `g1 = g2 = g12 = 0` (written in the thesis's `krpaGordon`) is not valid
//!   Octave and is rejected with [`LiteralError::ChainedAssignment`];
//! - function definitions, `if`, `while`, strings and commands (`clear all`, `hold on`) are
//!   not supported in data scripts.
//!
//! ```
//! use cagd_octave::literal::Env;
//! use cagd_octave::script::run;
//!
//! let s = run::<f64>("N = 3; u = linspace(0,1,N); z = zeros(1,N);\nfor i = 1:N\n  z(i) = u(i)-(u(i))^2;\nend", Env::new()).unwrap();
//! assert_eq!(s.value("z").unwrap().as_slice(), &[0.0, 0.25, 0.0]);
//! ```

use std::collections::{BTreeMap, BTreeSet};

use nalgebra::DMatrix;

use crate::literal::lexer::{lex, Tok, Token};
use crate::literal::parser::{Parser, KEYWORDS};
use crate::literal::{
    Env, Expr, LiteralError, LiteralScalar, ParamExpr, Position, Warning, PARAMETERS,
};

/// A statement of a data script.
#[derive(Debug, Clone)]
enum Stmt {
    Assign {
        name: String,
        at: Position,
        index: Option<Vec<Expr>>,
        value: Expr,
        source: String,
    },
    For {
        var: String,
        range: Expr,
        body: Vec<Stmt>,
    },
}

/// A variable bound by a script.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Binding<'a, T: LiteralScalar> {
    /// A value.
    Value(&'a DMatrix<T>),
    /// An expression in free parameters (a curve in `u`, `v` or `t`).
    Function(&'a ParamExpr),
}

/// A parameter expression defined by the script, with what it reads.
#[derive(Debug, Clone)]
struct Definition {
    name: String,
    line: usize,
    expr: ParamExpr,
    /// Value variables it reads (directly or through other definitions).
    reads: BTreeSet<String>,
    /// Indices (into `Script::definitions`) of the definitions it needs, in order.
    needs: BTreeSet<usize>,
}

/// The result of running a data script: its variables, in the order first assigned.
#[derive(Debug, Clone)]
pub struct Script<T: LiteralScalar = f64> {
    env: Env<T>,
    definitions: Vec<Definition>,
    /// Name → index of its current definition.
    functions: BTreeMap<String, usize>,
    order: Vec<String>,
    /// The names of `order`, for constant-time lookup (a script of 10⁵ assignments must not
    /// search a list of 10⁵ names at each).
    named: BTreeSet<String>,
    iterations: usize,
    /// Elements of all values assigned so far, and the work of every evaluation (see
    /// [`WORK_PER_ELEMENT_LIMIT`]).
    work: u128,
}

/// A script may assign at most this many times [`Limits::max_elements`] elements in total
/// (10⁸ by default), so that a loop that rebuilds a large matrix at every iteration
/// (`x = [x i]` a million times) stops with an error instead of running for hours. The work
/// of every evaluation counts too (element operations; an exact operation on operands of `a`
/// and `b` words `32 (a + b)²`, as within one evaluation): a loop of a million iterations,
/// each cheap, cannot add up to minutes either (found by fuzzing: 740 000 iterations of exact
/// element arithmetic inside nested loops took 20 s).
///
/// [`Limits::max_elements`]: cagd::limits::Limits::max_elements
pub const WORK_PER_ELEMENT_LIMIT: u128 = 25;

/// Runs a data script. `env` holds variables bound before the script starts (the command line
/// binds `N` from `--n`, so appendix C's script, which uses `N` without setting it, runs) and
/// the [`cagd::limits::Limits`] in force.
///
/// Errors carry the line and column of the offending text.
pub fn run<T: LiteralScalar>(source: &str, env: Env<T>) -> Result<Script<T>, LiteralError> {
    let limits = *env.limits();
    if source.len() > limits.max_expression_bytes {
        return Err(LiteralError::TooLong {
            length: source.len(),
            limit: limits.max_expression_bytes,
        });
    }
    let tokens = lex(source, true)?;
    let chars: Vec<char> = source.chars().collect();
    let mut reader = Reader {
        p: Parser::new(&tokens, limits.max_depth),
        chars: &chars,
        loop_depth: 0,
    };
    let program = reader.statements(false)?;
    let order: Vec<String> = env.names().map(str::to_string).collect();
    let mut script = Script {
        named: order.iter().cloned().collect(),
        order,
        env,
        definitions: Vec::new(),
        functions: BTreeMap::new(),
        iterations: 0,
        work: 0,
    };
    script.execute(&program)?;
    Ok(script)
}

impl<T: LiteralScalar> Script<T> {
    /// The variable `name`, if the script (or the initial environment) bound it.
    pub fn get(&self, name: &str) -> Option<Binding<'_, T>> {
        if let Some(&k) = self.functions.get(name) {
            return Some(Binding::Function(&self.definitions[k].expr));
        }
        self.env.get(name).map(Binding::Value)
    }

    /// The value of `name`, if it is bound to a value.
    pub fn value(&self, name: &str) -> Option<&DMatrix<T>> {
        self.env.get(name)
    }

    /// The parameter expression `name`, if it is bound to one.
    pub fn function(&self, name: &str) -> Option<&ParamExpr> {
        self.functions.get(name).map(|&k| &self.definitions[k].expr)
    }

    /// All bound names, in the order first assigned (initial variables first).
    pub fn names(&self) -> Vec<&str> {
        self.order
            .iter()
            .map(String::as_str)
            .filter(|n| self.get(n).is_some())
            .collect()
    }

    /// The value variables.
    pub fn env(&self) -> &Env<T> {
        &self.env
    }

    /// The value variables, by value.
    pub fn into_env(self) -> Env<T> {
        self.env
    }

    /// The warnings collected while running (see the module documentation).
    pub fn warnings(&self) -> Vec<Warning> {
        self.env.warnings().cloned().collect()
    }

    /// Parses `text` (an expression typed on the command line) in the context of the script:
    /// names of the script's parameter expressions may be used in it (`--c1 c1`,
    /// `--c1 "2*c1"`).
    ///
    /// ```
    /// use cagd_octave::literal::Env;
    /// let s = cagd_octave::script::run::<f64>("c1 = [u;0;u-u^2];", Env::new()).unwrap();
    /// let c = s.resolve("c1").unwrap();
    /// let p = c.sample_curve(&mut s.env().clone(), "u", &[0.5]).unwrap();
    /// assert_eq!(p.as_slice(), &[0.5, 0.0, 0.25]);
    /// ```
    pub fn resolve(&self, text: &str) -> Result<ParamExpr, LiteralError> {
        let expr = Expr::parse_with(text, self.env.limits())?;
        let mut needs = BTreeSet::new();
        for name in expr.name_uses().keys() {
            if self.env.get(name).is_none() {
                if let Some(&k) = self.functions.get(name) {
                    needs.extend(self.definitions[k].needs.iter().copied());
                    needs.insert(k);
                }
            }
        }
        Ok(ParamExpr {
            prelude: self.prelude(&needs),
            expr,
            source: text.to_string(),
        })
    }

    fn prelude(&self, needs: &BTreeSet<usize>) -> Vec<(String, Expr)> {
        needs
            .iter()
            .map(|&k| {
                let d = &self.definitions[k];
                (d.name.clone(), d.expr.expr.clone())
            })
            .collect()
    }

    fn note_name(&mut self, name: &str) {
        if !self.named.contains(name) {
            self.named.insert(name.to_string());
            self.order.push(name.to_string());
        }
    }

    /// Counts `elements` assigned against the script's work limit.
    fn charge(&mut self, elements: usize, at: Position) -> Result<(), LiteralError> {
        self.charge_work(elements as u128 + 1, at)
    }

    /// Counts `work` (elements assigned, or an evaluation's work) against the script's limit.
    fn charge_work(&mut self, work: u128, at: Position) -> Result<(), LiteralError> {
        self.work = self.work.saturating_add(work);
        let limit = self.env.limits().max_elements;
        if self.work > WORK_PER_ELEMENT_LIMIT * limit as u128 {
            return Err(LiteralError::TooLarge {
                at,
                what:
                    "the work of the script (values assigned and element operations), all together,"
                        .into(),
                count: self.work,
                limit: limit.saturating_mul(WORK_PER_ELEMENT_LIMIT as usize),
            });
        }
        Ok(())
    }

    /// Refuses to change `name` if a parameter expression reads it.
    fn check_not_read(&self, name: &str, at: Position) -> Result<(), LiteralError> {
        for (fname, &k) in &self.functions {
            let d = &self.definitions[k];
            if d.reads.contains(name) {
                return Err(LiteralError::Unsupported {
                    at,
                    what: format!(
                        "changing `{name}`, which the curve `{fname}` (line {}) reads; assign the new value to a new name",
                        d.line
                    ),
                });
            }
        }
        Ok(())
    }

    fn execute(&mut self, program: &[Stmt]) -> Result<(), LiteralError> {
        for stmt in program {
            match stmt {
                Stmt::Assign {
                    name,
                    at,
                    index: None,
                    value,
                    source,
                } => self.assign(name, *at, value, source)?,
                Stmt::Assign {
                    name,
                    at,
                    index: Some(index),
                    value,
                    ..
                } => self.assign_element(name, *at, index, value)?,
                Stmt::For { var, range, body } => {
                    let values = self.value_of(range)?;
                    // The loop's steps are counted before the first one: a loop that would
                    // pass the limit is refused before it runs, not after a million steps.
                    let limit = self.env.limits().max_iterations;
                    let after = self.iterations.saturating_add(values.ncols());
                    if after > limit {
                        return Err(LiteralError::TooLarge {
                            at: range.position(),
                            what: "the loops of the script".into(),
                            count: after as u128,
                            limit,
                        });
                    }
                    self.iterations = after;
                    for j in 0..values.ncols() {
                        self.check_not_read(var, range.position())?;
                        self.functions.remove(var);
                        self.env.bind(var, values.columns(j, 1).into_owned());
                        self.note_name(var);
                        self.execute(body)?;
                    }
                }
            }
        }
        Ok(())
    }

    /// Evaluates an expression that must not depend on free parameters.
    fn value_of(&mut self, e: &Expr) -> Result<DMatrix<T>, LiteralError> {
        for (name, at) in e.name_uses() {
            if self.env.get(&name).is_none() && self.functions.contains_key(&name) {
                return Err(LiteralError::Unsupported {
                    at,
                    what: format!(
                        "using the curve `{name}` (an expression in a free parameter) where a value is needed"
                    ),
                });
            }
        }
        let value = e.eval(&mut self.env)?;
        self.charge_work(self.env.meter.work(), e.position())?;
        Ok(value)
    }

    fn assign(
        &mut self,
        name: &str,
        at: Position,
        value: &Expr,
        source: &str,
    ) -> Result<(), LiteralError> {
        self.check_not_read(name, at)?;
        let mut reads = BTreeSet::new();
        let mut needs = BTreeSet::new();
        let mut free = false;
        for (n, pos) in value.name_uses() {
            if self.env.get(&n).is_some() {
                reads.insert(n);
            } else if let Some(&k) = self.functions.get(&n) {
                needs.extend(self.definitions[k].needs.iter().copied());
                needs.insert(k);
                reads.extend(self.definitions[k].reads.iter().cloned());
            } else if PARAMETERS.contains(&n.as_str()) {
                free = true;
            } else if !crate::literal::eval::is_builtin_name(&n) {
                return Err(crate::literal::eval::unknown_name_error(value, &n, pos));
            }
        }
        self.note_name(name);
        if !free && needs.is_empty() {
            let v = value.eval(&mut self.env)?;
            self.charge(v.len(), at)?;
            self.functions.remove(name);
            self.env.bind(name, v);
            return Ok(());
        }
        let expr = ParamExpr {
            prelude: self.prelude(&needs),
            expr: value.clone(),
            source: source.to_string(),
        };
        self.env.unbind(name);
        self.definitions.push(Definition {
            name: name.to_string(),
            line: at.line,
            expr,
            reads,
            needs,
        });
        self.functions
            .insert(name.to_string(), self.definitions.len() - 1);
        Ok(())
    }

    fn assign_element(
        &mut self,
        name: &str,
        at: Position,
        index: &[Expr],
        value: &Expr,
    ) -> Result<(), LiteralError> {
        self.check_not_read(name, at)?;
        if self.functions.contains_key(name) {
            return Err(LiteralError::Unsupported {
                at,
                what: format!("assigning an element of the curve `{name}`"),
            });
        }
        let mut positions = Vec::with_capacity(index.len());
        for e in index {
            let m = self.value_of(e)?;
            let k = if m.len() == 1 {
                m[(0, 0)].to_count()
            } else {
                None
            };
            match k {
                Some(k) if k >= 1 => positions.push(k),
                _ => {
                    return Err(LiteralError::Shape {
                        at: e.position(),
                        message:
                            "an indexed assignment needs one positive integer index per dimension"
                                .into(),
                    })
                }
            }
        }
        let rhs = self.value_of(value)?;
        if rhs.len() != 1 {
            return Err(LiteralError::Shape {
                at: value.position(),
                message: format!(
                    "expected a scalar on the right of `{name}(...) =`, got a {}×{} matrix",
                    rhs.nrows(),
                    rhs.ncols()
                ),
            });
        }
        let x = rhs[(0, 0)].clone();
        let max = self.env.limits().max_elements;
        let (r, c) = self.env.get(name).map_or((0, 0), |m| m.shape());
        let (target, new_shape) = match positions.as_slice() {
            [k] => {
                let k = *k;
                if k <= r * c {
                    (((k - 1) % r.max(1), (k - 1) / r.max(1)), (r, c))
                } else if r <= 1 {
                    ((0, k - 1), (1, k))
                } else if c == 1 {
                    ((k - 1, 0), (k, 1))
                } else {
                    return Err(LiteralError::Shape {
                        at,
                        message: format!(
                            "index ({k}) out of bound; `{name}` is {r}×{c} and a matrix cannot grow by a linear index"
                        ),
                    });
                }
            }
            [i, j] => ((i - 1, j - 1), (r.max(*i), c.max(*j))),
            _ => {
                return Err(LiteralError::Unsupported {
                    at,
                    what: "indexed assignment with more than two indices".into(),
                })
            }
        };
        if new_shape != (r, c) {
            let count = new_shape.0 as u128 * new_shape.1 as u128;
            if count > max as u128 {
                return Err(LiteralError::TooLarge {
                    at,
                    what: format!("`{name}`"),
                    count,
                    limit: max,
                });
            }
        }
        // Taken out of the environment, not cloned: `x(i) = ...` in a loop costs O(1) per
        // assignment, not a copy of `x` (which made filling a vector quadratic).
        let mut m = self
            .env
            .unbind(name)
            .unwrap_or_else(|| DMatrix::from_vec(0, 0, Vec::new()));
        if new_shape != (r, c) {
            let len = new_shape.0 * new_shape.1;
            let vector_growth = (r <= 1 && new_shape.0 == 1) || (c == 1 && new_shape.1 == 1);
            // What growing costs: a vector grows at the end of its storage (the new elements,
            // amortized O(1) each); a matrix gaining a row is copied whole. Both are charged
            // against the script's budget before the copy, so `x(i,i) = i` for i = 1:2000
            // (Σ i² ≈ 2.7·10⁹ elements copied, 19 s) stops once its copies exceed the budget.
            let copied = if vector_growth || m.is_empty() {
                (len - r * c) as u128
            } else {
                len as u128
            };
            self.charge_work(copied, at)?;
            let too_large = || LiteralError::TooLarge {
                at,
                what: format!("`{name}` (more memory than can be reserved)"),
                count: len as u128,
                limit: max,
            };
            m = if vector_growth || m.is_empty() {
                // Column-major storage of a vector grows at its end, in place (amortized).
                let mut data: Vec<T> = m.data.into();
                data.try_reserve(len - data.len())
                    .map_err(|_| too_large())?;
                data.resize(len, T::zero());
                DMatrix::from_vec(new_shape.0, new_shape.1, data)
            } else {
                let mut data: Vec<T> = Vec::new();
                data.try_reserve_exact(len).map_err(|_| too_large())?;
                for j in 0..new_shape.1 {
                    for i in 0..new_shape.0 {
                        data.push(if i < r && j < c {
                            m[(i, j)].clone()
                        } else {
                            T::zero()
                        });
                    }
                }
                DMatrix::from_vec(new_shape.0, new_shape.1, data)
            };
        }
        m[target] = x;
        self.env.bind(name, m);
        self.charge(1, at)?;
        self.note_name(name);
        Ok(())
    }
}

/// Statement-level parser over the token stream.
struct Reader<'t> {
    p: Parser<'t>,
    chars: &'t [char],
    loop_depth: usize,
}

impl Reader<'_> {
    fn at_terminator(&self) -> bool {
        matches!(
            self.p.peek().tok,
            Tok::Semi | Tok::Comma | Tok::Newline | Tok::Eof
        )
    }

    fn skip_terminators(&mut self) {
        while matches!(self.p.peek().tok, Tok::Semi | Tok::Comma | Tok::Newline) {
            self.p.bump();
        }
    }

    /// Statements up to the end of input, or (in a loop body) up to `end`/`endfor`.
    fn statements(&mut self, in_loop: bool) -> Result<Vec<Stmt>, LiteralError> {
        let mut out = Vec::new();
        loop {
            self.skip_terminators();
            let t = self.p.peek().clone();
            match &t.tok {
                Tok::Eof => {
                    if in_loop {
                        return Err(LiteralError::Syntax {
                            at: t.at,
                            expected: "`end` to close the `for` loop".into(),
                            found: "end of input".into(),
                        });
                    }
                    return Ok(out);
                }
                Tok::Ident(k) if k == "end" || k == "endfor" => {
                    if !in_loop {
                        return Err(LiteralError::Syntax {
                            at: t.at,
                            expected: "a statement".into(),
                            found: format!("`{k}` without an open `for` loop"),
                        });
                    }
                    self.p.bump();
                    self.end_of_statement()?;
                    return Ok(out);
                }
                _ => out.push(self.statement()?),
            }
        }
    }

    fn end_of_statement(&mut self) -> Result<(), LiteralError> {
        if self.at_terminator() {
            return Ok(());
        }
        if self.p.peek().tok == Tok::Assign {
            return Err(LiteralError::ChainedAssignment {
                at: self.p.peek().at,
            });
        }
        Err(self.p.unexpected("`;`, `,` or the end of the line"))
    }

    fn statement(&mut self) -> Result<Stmt, LiteralError> {
        let t = self.p.peek().clone();
        let Tok::Ident(name) = &t.tok else {
            return self.expression_statement();
        };
        if name == "for" {
            return self.for_loop();
        }
        if KEYWORDS.contains(&name.as_str()) {
            return Err(LiteralError::Unsupported {
                at: t.at,
                what: format!(
                    "`{name}` (a data script may contain assignments and `for` loops only)"
                ),
            });
        }
        let next = self.p.peek_at(1).clone();
        match next.tok {
            Tok::Assign => {
                self.p.bump();
                self.p.bump();
                self.assignment(name.clone(), t.at, None)
            }
            Tok::LParen if self.indexed_assignment_ahead() => {
                self.p.bump();
                let index = self.index_list()?;
                if self.p.peek().tok != Tok::Assign {
                    return Err(self.p.unexpected("`=`"));
                }
                self.p.bump();
                self.assignment(name.clone(), t.at, Some(index))
            }
            Tok::Ident(_) | Tok::Num(_) if next.space_before => Err(LiteralError::Unsupported {
                at: t.at,
                what: format!("the command `{name} ...` (command syntax)"),
            }),
            _ => self.expression_statement(),
        }
    }

    /// Whether `name ( ... ) =` follows, looking past balanced parentheses.
    fn indexed_assignment_ahead(&self) -> bool {
        let mut depth = 0usize;
        let mut k = self.p.position() + 1;
        loop {
            let t = self.p.token(k);
            match t.tok {
                Tok::LParen | Tok::LBracket => depth += 1,
                Tok::RParen | Tok::RBracket => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return self.p.token(k + 1).tok == Tok::Assign;
                    }
                }
                Tok::Eof | Tok::Newline | Tok::Semi => return false,
                _ => {}
            }
            k += 1;
        }
    }

    /// `( expr, expr )` of an indexed assignment.
    fn index_list(&mut self) -> Result<Vec<Expr>, LiteralError> {
        self.p.bump(); // `(`
        let mut out = Vec::new();
        loop {
            if self.p.peek().tok == Tok::Colon {
                return Err(LiteralError::Unsupported {
                    at: self.p.peek().at,
                    what: "`:` in an indexed assignment".into(),
                });
            }
            out.push(self.p.expr()?);
            match self.p.peek().tok {
                Tok::Comma => {
                    self.p.bump();
                }
                Tok::RParen => {
                    self.p.bump();
                    return Ok(out);
                }
                _ => return Err(self.p.unexpected("`,` or `)`")),
            }
        }
    }

    fn text_between(&self, from: &Token, to: &Token) -> String {
        let (a, b) = (
            from.offset.min(self.chars.len()),
            to.offset.min(self.chars.len()),
        );
        self.chars[a..b.max(a)]
            .iter()
            .collect::<String>()
            .trim()
            .to_string()
    }

    fn assignment(
        &mut self,
        name: String,
        at: Position,
        index: Option<Vec<Expr>>,
    ) -> Result<Stmt, LiteralError> {
        let start = self.p.peek().clone();
        let value = self.p.expr()?;
        let end = self.p.peek().clone();
        self.end_of_statement()?;
        Ok(Stmt::Assign {
            name,
            at,
            index,
            value,
            source: self.text_between(&start, &end),
        })
    }

    fn expression_statement(&mut self) -> Result<Stmt, LiteralError> {
        let start = self.p.peek().clone();
        let value = self.p.expr()?;
        let end = self.p.peek().clone();
        self.end_of_statement()?;
        Ok(Stmt::Assign {
            name: "ans".into(),
            at: start.at,
            index: None,
            value,
            source: self.text_between(&start, &end),
        })
    }

    fn for_loop(&mut self) -> Result<Stmt, LiteralError> {
        let for_token = self.p.bump();
        self.loop_depth += 1;
        if self.loop_depth > 16 {
            return Err(LiteralError::TooDeep {
                at: for_token.at,
                limit: 16,
            });
        }
        let parenthesised = self.p.peek().tok == Tok::LParen;
        if parenthesised {
            self.p.bump();
        }
        let var = match self.p.peek().tok.clone() {
            Tok::Ident(v) if !KEYWORDS.contains(&v.as_str()) => {
                self.p.bump();
                v
            }
            _ => return Err(self.p.unexpected("the loop variable after `for`")),
        };
        if self.p.peek().tok != Tok::Assign {
            return Err(self.p.unexpected("`=` after the loop variable"));
        }
        self.p.bump();
        let range = self.p.expr()?;
        if parenthesised {
            if self.p.peek().tok != Tok::RParen {
                return Err(self.p.unexpected("`)`"));
            }
            self.p.bump();
        }
        self.end_of_statement()?;
        let body = self.statements(true)?;
        self.loop_depth -= 1;
        Ok(Stmt::For { var, range, body })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd::limits::Limits;

    #[test]
    fn growing_a_matrix_is_charged_for_its_copies() {
        // A budget of 25 × 10 000 element operations. `x(i,i) = i` copies the whole matrix at
        // every step (Σ i² elements): stopped near i = 90, where it once ran to the end (19 s
        // at i = 2000 in a release build).
        let limits = Limits {
            max_elements: 10_000,
            ..Limits::default()
        };
        let grow = "for i = 1:2000\n  x(i,i) = i;\nend\n";
        let err = run::<f64>(grow, Env::with_limits(limits)).unwrap_err();
        assert!(
            matches!(&err, LiteralError::TooLarge { what, .. } if what.contains("the work of the script")),
            "{err:?}"
        );
        // A vector grows at its end: one element per step, far within the same budget.
        let s = run::<f64>(
            "for i = 1:2000\n  x(i) = i;\nend\n",
            Env::with_limits(limits),
        )
        .unwrap();
        assert_eq!(s.value("x").unwrap().ncols(), 2000);
    }

    #[test]
    fn sizes_beyond_the_machine_are_refused_even_with_the_limits_lifted() {
        // Every limit at its largest: what would need terabytes is refused by the reservation
        // (try_reserve), never an abort ("memory allocation of 8000000000000 bytes failed").
        let lifted = Limits {
            max_elements: usize::MAX,
            max_iterations: usize::MAX,
            ..Limits::default()
        };
        for script in [
            "for i = 1:1e12\n  x = i;\nend\n",
            "x = zeros(1e6);\n",
            "x = linspace(0, 1, 1e12);\n",
            "x(1e6, 1e6) = 1;\n",
            "x = (1:1e6)' .* (1:1e6);\n",
        ] {
            let err = run::<f64>(script, Env::with_limits(lifted)).unwrap_err();
            assert!(
                matches!(err, LiteralError::TooLarge { .. }),
                "{script}: {err:?}"
            );
        }
    }

    #[test]
    fn chained_assignment_is_rejected() {
        let err = run::<f64>("g1 = g2 = g12 = 0;", Env::new()).unwrap_err();
        assert!(
            matches!(err, LiteralError::ChainedAssignment { at } if at.line == 1 && at.column == 9),
            "{err:?}"
        );
    }

    #[test]
    fn free_parameter_makes_a_curve() {
        let s = run::<f64>("c1 = [u;0;u-u^2];\nP1 = [0;0;0];", Env::new()).unwrap();
        assert!(matches!(s.get("c1"), Some(Binding::Function(_))));
        assert!(matches!(s.get("P1"), Some(Binding::Value(_))));
        assert_eq!(s.names(), vec!["c1", "P1"]);
        assert_eq!(s.function("c1").unwrap().source(), "[u;0;u-u^2]");
    }

    #[test]
    fn changing_what_a_curve_reads_is_an_error() {
        let err = run::<f64>("a = 1;\nc = [u; a];\na = 2;", Env::new()).unwrap_err();
        assert!(matches!(err, LiteralError::Unsupported { at, .. } if at.line == 3));
    }

    #[test]
    fn loops_have_an_iteration_limit() {
        let limits = cagd::limits::Limits {
            max_iterations: 100,
            ..Default::default()
        };
        let err = run::<f64>(
            "s = 0;\nfor i = 1:1000\n s = s + i;\nend",
            Env::with_limits(limits),
        )
        .unwrap_err();
        assert!(matches!(err, LiteralError::TooLarge { .. }));
    }
}
