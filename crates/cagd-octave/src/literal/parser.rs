//! Recursive-descent parser for Octave expressions, with Octave's precedence:
//! transpose and power (left-associative, `2^-1` allowed) bind tightest, then unary minus,
//! then `* / .* ./`, then `+ -`, then the range colon.
//!
//! Chains of one precedence level are kept flat (`1+2+…+n` is one node), so the depth of the
//! tree — and of every recursion over it — is bounded by the nesting of parentheses, brackets
//! and unary operators, which the parser limits.

use super::lexer::{Tok, Token};
use super::{LiteralError, Position};

/// A binary operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    ElMul,
    ElDiv,
    ElPow,
}

impl BinOp {
    pub(crate) fn symbol(self) -> &'static str {
        match self {
            BinOp::Add => "+",
            BinOp::Sub => "-",
            BinOp::Mul => "*",
            BinOp::Div => "/",
            BinOp::Pow => "^",
            BinOp::ElMul => ".*",
            BinOp::ElDiv => "./",
            BinOp::ElPow => ".^",
        }
    }
}

/// One row of a matrix literal: its elements, concatenated horizontally.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Row {
    pub at: Position,
    pub elements: Vec<Expr>,
}

/// The shape of an expression node.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Node {
    /// A number literal: its text (for exact evaluation) and its nearest double.
    Number { text: String, value: f64 },
    /// A name.
    Var(String),
    /// `:` standing alone as an index (`c(:, i)`).
    Colon,
    /// `name(args)`: indexing if `name` is a variable, else a function call.
    Call { name: String, args: Vec<Expr> },
    /// Unary minus.
    Neg(Box<Expr>),
    /// Left-associative chain of operators of one precedence level.
    Chain {
        first: Box<Expr>,
        rest: Vec<(BinOp, Position, Expr)>,
    },
    /// `'` or `.'` (the same for real numbers).
    Transpose(Box<Expr>),
    /// `base:limit` or `base:increment:limit`.
    Range {
        base: Box<Expr>,
        increment: Option<Box<Expr>>,
        limit: Box<Expr>,
    },
    /// `[...]`: rows concatenated vertically.
    Matrix(Vec<Row>),
}

/// Names that are statements, never values.
pub(crate) const KEYWORDS: &[&str] = &[
    "for",
    "end",
    "endfor",
    "while",
    "endwhile",
    "if",
    "elseif",
    "else",
    "endif",
    "function",
    "endfunction",
    "return",
    "break",
    "continue",
    "switch",
    "case",
    "otherwise",
    "endswitch",
    "do",
    "until",
    "try",
    "catch",
    "end_try_catch",
    "unwind_protect",
    "global",
    "persistent",
];

/// A parser over a token slice that always ends with [`Tok::Eof`].
pub(crate) struct Parser<'t> {
    toks: &'t [Token],
    pos: usize,
    depth: usize,
    max_depth: usize,
}

impl<'t> Parser<'t> {
    pub(crate) fn new(toks: &'t [Token], max_depth: usize) -> Self {
        debug_assert!(toks.last().is_some_and(|t| t.tok == Tok::Eof));
        Parser {
            toks,
            pos: 0,
            depth: 0,
            max_depth,
        }
    }

    pub(crate) fn peek(&self) -> &Token {
        &self.toks[self.pos.min(self.toks.len() - 1)]
    }

    pub(crate) fn peek_at(&self, k: usize) -> &Token {
        &self.toks[(self.pos + k).min(self.toks.len() - 1)]
    }

    pub(crate) fn bump(&mut self) -> Token {
        let t = self.peek().clone();
        if self.pos < self.toks.len() - 1 {
            self.pos += 1;
        }
        t
    }

    /// Index of the current token (for look-ahead by the script reader).
    pub(crate) fn position(&self) -> usize {
        self.pos
    }

    pub(crate) fn token(&self, index: usize) -> &Token {
        &self.toks[index.min(self.toks.len() - 1)]
    }

    /// The error "expected `expected`, found <the current token>".
    pub(crate) fn unexpected(&self, expected: &str) -> LiteralError {
        let t = self.peek();
        if let Tok::Other(op) = &t.tok {
            if [
                "==", "~=", "!=", "<", "<=", ">", ">=", "&", "&&", "|", "||", "!", "~",
            ]
            .contains(&op.as_str())
            {
                return LiteralError::Unsupported {
                    at: t.at,
                    what: format!("the comparison or logical operator `{op}`"),
                };
            }
            if ["\\", ".\\"].contains(&op.as_str()) {
                return LiteralError::Unsupported {
                    at: t.at,
                    what: format!("left division `{op}`"),
                };
            }
            if op == "{" || op == "}" {
                return LiteralError::Unsupported {
                    at: t.at,
                    what: "cell arrays `{...}`".into(),
                };
            }
        }
        LiteralError::Syntax {
            at: t.at,
            expected: expected.into(),
            found: t.tok.describe(),
        }
    }

    fn enter(&mut self, at: Position) -> Result<(), LiteralError> {
        self.depth += 1;
        if self.depth > self.max_depth {
            return Err(LiteralError::TooDeep {
                at,
                limit: self.max_depth,
            });
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// A full expression (range level).
    pub(crate) fn expr(&mut self) -> Result<Expr, LiteralError> {
        let at = self.peek().at;
        self.enter(at)?;
        let result = self.range();
        self.leave();
        result
    }

    fn range(&mut self) -> Result<Expr, LiteralError> {
        let base = self.additive()?;
        if self.peek().tok != Tok::Colon {
            return Ok(base);
        }
        let at = base.at;
        self.bump();
        let second = self.additive()?;
        let node = if self.peek().tok == Tok::Colon {
            self.bump();
            let limit = self.additive()?;
            Node::Range {
                base: Box::new(base),
                increment: Some(Box::new(second)),
                limit: Box::new(limit),
            }
        } else {
            Node::Range {
                base: Box::new(base),
                increment: None,
                limit: Box::new(second),
            }
        };
        if self.peek().tok == Tok::Colon {
            return Err(self.unexpected("at most two `:` in a range `base:increment:limit`"));
        }
        Ok(Expr { node, at })
    }

    /// Inside brackets, `a -b` (space before the sign, none after) starts a new element.
    fn sign_starts_element(&self) -> bool {
        let t = self.peek();
        t.in_matrix && t.space_before && !self.peek_at(1).space_before
    }

    fn additive(&mut self) -> Result<Expr, LiteralError> {
        let first = self.multiplicative()?;
        let mut rest = Vec::new();
        loop {
            let op = match self.peek().tok {
                Tok::Plus => BinOp::Add,
                Tok::Minus => BinOp::Sub,
                _ => break,
            };
            if self.sign_starts_element() {
                break;
            }
            let at = self.bump().at;
            rest.push((op, at, self.multiplicative()?));
        }
        Ok(chain(first, rest))
    }

    fn multiplicative(&mut self) -> Result<Expr, LiteralError> {
        let first = self.unary()?;
        let mut rest = Vec::new();
        loop {
            let op = match self.peek().tok {
                Tok::Star => BinOp::Mul,
                Tok::Slash => BinOp::Div,
                Tok::DotStar => BinOp::ElMul,
                Tok::DotSlash => BinOp::ElDiv,
                _ => break,
            };
            let at = self.bump().at;
            rest.push((op, at, self.unary()?));
        }
        Ok(chain(first, rest))
    }

    fn unary(&mut self) -> Result<Expr, LiteralError> {
        let t = self.peek().clone();
        match t.tok {
            Tok::Minus | Tok::Plus => {
                self.bump();
                self.enter(t.at)?;
                let operand = self.unary();
                self.leave();
                let operand = operand?;
                Ok(if t.tok == Tok::Minus {
                    Expr {
                        node: Node::Neg(Box::new(operand)),
                        at: t.at,
                    }
                } else {
                    operand
                })
            }
            _ => self.power(),
        }
    }

    fn power(&mut self) -> Result<Expr, LiteralError> {
        let first = self.postfix()?;
        let mut rest = Vec::new();
        loop {
            let op = match self.peek().tok {
                Tok::Caret => BinOp::Pow,
                Tok::DotCaret => BinOp::ElPow,
                _ => break,
            };
            let at = self.bump().at;
            rest.push((op, at, self.power_operand()?));
        }
        Ok(chain(first, rest))
    }

    /// The right operand of `^`: Octave accepts a sign there (`2^-1`).
    fn power_operand(&mut self) -> Result<Expr, LiteralError> {
        let t = self.peek().clone();
        match t.tok {
            Tok::Minus | Tok::Plus => {
                self.bump();
                self.enter(t.at)?;
                let operand = self.power_operand();
                self.leave();
                let operand = operand?;
                Ok(if t.tok == Tok::Minus {
                    Expr {
                        node: Node::Neg(Box::new(operand)),
                        at: t.at,
                    }
                } else {
                    operand
                })
            }
            _ => self.postfix(),
        }
    }

    /// A primary followed by any number of transposes (`'` or `.'`, the same on real
    /// matrices). Two transposes cancel, so a run of them becomes at most one node: a long run
    /// (found by fuzzing: `.5555` and 1 300 quotes overflowed the stack when evaluated) never
    /// makes a deep tree.
    fn postfix(&mut self) -> Result<Expr, LiteralError> {
        let e = self.primary()?;
        let mut last = None;
        let mut odd = false;
        while matches!(self.peek().tok, Tok::Quote | Tok::DotQuote) {
            last = Some(self.bump().at);
            odd = !odd;
        }
        Ok(match last {
            Some(at) if odd => Expr {
                node: Node::Transpose(Box::new(e)),
                at,
            },
            _ => e,
        })
    }

    fn primary(&mut self) -> Result<Expr, LiteralError> {
        let t = self.peek().clone();
        match &t.tok {
            Tok::Num(text) => {
                self.bump();
                // The lexer only produces decimal digits, so parsing cannot fail; an overflow
                // gives infinity, rejected when the number is evaluated.
                let value = text.parse::<f64>().unwrap_or(f64::INFINITY);
                Ok(Expr {
                    node: Node::Number {
                        text: text.clone(),
                        value,
                    },
                    at: t.at,
                })
            }
            Tok::Ident(name) => {
                if KEYWORDS.contains(&name.as_str()) {
                    return Err(self.unexpected("a number, a name, `(` or `["));
                }
                self.bump();
                let next = self.peek();
                let call = next.tok == Tok::LParen && !(next.in_matrix && next.space_before);
                if call {
                    let args = self.arguments()?;
                    Ok(Expr {
                        node: Node::Call {
                            name: name.clone(),
                            args,
                        },
                        at: t.at,
                    })
                } else {
                    Ok(Expr {
                        node: Node::Var(name.clone()),
                        at: t.at,
                    })
                }
            }
            Tok::LParen => {
                self.bump();
                let inner = self.expr()?;
                if self.peek().tok != Tok::RParen {
                    return Err(self.unexpected("`)`"));
                }
                self.bump();
                Ok(inner)
            }
            Tok::LBracket => self.matrix(),
            _ => Err(self.unexpected("a number, a name, `(` or `[`")),
        }
    }

    /// `( arg, arg, ... )` after a name; a lone `:` is an index meaning "all".
    fn arguments(&mut self) -> Result<Vec<Expr>, LiteralError> {
        self.bump(); // `(`
        let mut args = Vec::new();
        if self.peek().tok == Tok::RParen {
            self.bump();
            return Ok(args);
        }
        loop {
            let t = self.peek().clone();
            let lone_colon =
                t.tok == Tok::Colon && matches!(self.peek_at(1).tok, Tok::Comma | Tok::RParen);
            if lone_colon {
                self.bump();
                args.push(Expr {
                    node: Node::Colon,
                    at: t.at,
                });
            } else {
                args.push(self.expr()?);
            }
            match self.peek().tok {
                Tok::Comma => {
                    self.bump();
                }
                Tok::RParen => {
                    self.bump();
                    return Ok(args);
                }
                _ => return Err(self.unexpected("`,` or `)`")),
            }
        }
    }

    /// `[ ... ]`: elements separated by commas or white space, rows by `;` or new lines.
    fn matrix(&mut self) -> Result<Expr, LiteralError> {
        let open = self.bump(); // `[`
        let mut rows: Vec<Row> = Vec::new();
        let mut row = Row {
            at: self.peek().at,
            elements: Vec::new(),
        };
        let mut after_comma = false;
        loop {
            let t = self.peek().clone();
            match t.tok {
                Tok::RBracket => {
                    self.bump();
                    break;
                }
                Tok::Semi | Tok::Newline => {
                    self.bump();
                    if !row.elements.is_empty() {
                        rows.push(row);
                    }
                    row = Row {
                        at: self.peek().at,
                        elements: Vec::new(),
                    };
                    after_comma = false;
                }
                Tok::Comma => {
                    if row.elements.is_empty() || after_comma {
                        return Err(self.unexpected("an element before `,`"));
                    }
                    self.bump();
                    after_comma = true;
                }
                Tok::Eof => {
                    return Err(LiteralError::Syntax {
                        at: t.at,
                        expected: format!("`]` to close the `[` opened at {}", open.at.describe()),
                        found: t.tok.describe(),
                    })
                }
                _ => {
                    if !row.elements.is_empty() && !after_comma && !t.space_before {
                        return Err(self.unexpected("`,`, `;`, white space or `]`"));
                    }
                    if row.elements.is_empty() {
                        row.at = t.at;
                    }
                    row.elements.push(self.expr()?);
                    after_comma = false;
                }
            }
        }
        if !row.elements.is_empty() {
            rows.push(row);
        }
        Ok(Expr {
            node: Node::Matrix(rows),
            at: open.at,
        })
    }
}

/// `first op₁ x₁ op₂ x₂ …` as one flat chain (just `first` without operators).
pub(crate) fn chain(first: Expr, rest: Vec<(BinOp, Position, Expr)>) -> Expr {
    if rest.is_empty() {
        return first;
    }
    let at = first.at;
    Expr {
        node: Node::Chain {
            first: Box::new(first),
            rest,
        },
        at,
    }
}

/// A parsed expression: a matrix literal, a range, or an expression in bound variables.
///
/// ```
/// use cagd_octave::literal::{Env, Expr};
///
/// let e = Expr::parse("[g00 g10; g01 g11]").unwrap();
/// let mut env = Env::<f64>::new();
/// for (name, x) in [("g00", 0.0), ("g10", 1.0), ("g01", 2.0), ("g11", 3.0)] {
///     env.bind_scalar(name, x);
/// }
/// let m = e.eval(&mut env).unwrap();
/// assert_eq!(m.shape(), (2, 2));
/// assert_eq!(m[(1, 0)], 2.0);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    pub(crate) node: Node,
    pub(crate) at: Position,
}
