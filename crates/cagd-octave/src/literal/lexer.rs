//! Tokens of Octave's expression syntax, with the context Octave's own lexer keeps.
//!
//! Inside `[...]` Octave's syntax depends on white space: `[1 -2]` has two elements, `[1 - 2]`
//! one; `[a' b']` transposes while `[a 'b']` starts a string. The lexer therefore records for
//! every token whether white space preceded it and whether it stands directly inside brackets,
//! and decides between the transpose operator and a string quote itself.

use super::{LiteralError, Position};

/// One token.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Tok {
    /// A decimal number exactly as written (`d`/`D` exponents normalised to `e`).
    Num(String),
    /// A name: variable, function or keyword.
    Ident(String),
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    DotStar,
    DotSlash,
    DotCaret,
    /// `'` used as the (complex conjugate) transpose.
    Quote,
    /// `.'`
    DotQuote,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Comma,
    Semi,
    Newline,
    Colon,
    Assign,
    Eof,
    /// An operator or character the language does not support (kept for a good message).
    Other(String),
}

impl Tok {
    /// How the token reads in an error message.
    pub(crate) fn describe(&self) -> String {
        match self {
            Tok::Num(s) => format!("the number `{s}`"),
            Tok::Ident(s) => format!("`{s}`"),
            Tok::Plus => "`+`".into(),
            Tok::Minus => "`-`".into(),
            Tok::Star => "`*`".into(),
            Tok::Slash => "`/`".into(),
            Tok::Caret => "`^`".into(),
            Tok::DotStar => "`.*`".into(),
            Tok::DotSlash => "`./`".into(),
            Tok::DotCaret => "`.^`".into(),
            Tok::Quote => "`'`".into(),
            Tok::DotQuote => "`.'`".into(),
            Tok::LParen => "`(`".into(),
            Tok::RParen => "`)`".into(),
            Tok::LBracket => "`[`".into(),
            Tok::RBracket => "`]`".into(),
            Tok::Comma => "`,`".into(),
            Tok::Semi => "`;`".into(),
            Tok::Newline => "end of line".into(),
            Tok::Colon => "`:`".into(),
            Tok::Assign => "`=`".into(),
            Tok::Eof => "end of input".into(),
            Tok::Other(s) => format!("`{s}`"),
        }
    }

    /// Whether the token can end an operand (so that a following `'` is a transpose).
    fn ends_value(&self) -> bool {
        matches!(
            self,
            Tok::Num(_) | Tok::Ident(_) | Tok::RParen | Tok::RBracket | Tok::Quote | Tok::DotQuote
        )
    }
}

/// A token with its position and white-space context.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Token {
    pub tok: Tok,
    pub at: Position,
    /// White space (or a line continuation) directly before the token.
    pub space_before: bool,
    /// The innermost open delimiter is `[`, where white space separates elements.
    pub in_matrix: bool,
    /// Offset of the token's first character, in characters from the start of the input.
    pub offset: usize,
}

/// Longest number literal accepted (digits, point and exponent), so that exact arithmetic on a
/// pasted number stays cheap.
const MAX_NUMBER_LEN: usize = 400;
/// Largest decimal exponent magnitude accepted in a number literal.
const MAX_EXPONENT: i64 = 10_000;

/// Splits `text` into tokens. `multiline` selects how positions are reported (see
/// [`Position`]).
pub(crate) fn lex(text: &str, multiline: bool) -> Result<Vec<Token>, LiteralError> {
    let chars: Vec<char> = text.chars().collect();
    let mut tokens: Vec<Token> = Vec::new();
    let mut stack: Vec<char> = Vec::new();
    let mut i = 0;
    let mut line = 1;
    let mut line_start = 0;
    let mut space = false;
    let pos = |i: usize, line: usize, line_start: usize| Position {
        line: if multiline { line } else { 0 },
        column: i - line_start + 1,
    };
    while i < chars.len() {
        let c = chars[i];
        let at = pos(i, line, line_start);
        let in_matrix = stack.last() == Some(&'[');
        let offset = i;
        let prev_ends_value = tokens.last().is_some_and(|t| t.tok.ends_value());
        let push = |tok: Tok, tokens: &mut Vec<Token>, space: &mut bool| {
            tokens.push(Token {
                tok,
                at,
                space_before: *space,
                in_matrix,
                offset,
            });
            *space = false;
        };
        match c {
            ' ' | '\t' | '\r' => {
                space = true;
                i += 1;
            }
            '\n' => {
                push(Tok::Newline, &mut tokens, &mut space);
                space = true;
                i += 1;
                line += 1;
                line_start = i;
            }
            '%' | '#' => {
                if let Some(end) = block_comment_end(&chars, i, line_start) {
                    // `%{` … `%}` (or `#{` … `#}`) on lines of their own: a block comment,
                    // possibly nested, as in Octave. Its lines count; its text does not.
                    let Some((end, lines)) = end else {
                        return Err(LiteralError::Syntax {
                            at,
                            expected:
                                "`%}` (or `#}`) on a line of its own to close the block comment"
                                    .into(),
                            found: "end of input".into(),
                        });
                    };
                    i = end;
                    line += lines;
                    line_start = i - (chars[..i].iter().rev().take_while(|&&c| c != '\n').count());
                    space = true;
                    continue;
                }
                // A comment runs to the end of the line; the newline itself stays a token.
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
                space = true;
            }
            '.' if chars.get(i + 1) == Some(&'.') && chars.get(i + 2) == Some(&'.') => {
                // Continuation: the rest of the line and its newline are white space.
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
                if i < chars.len() {
                    i += 1;
                    line += 1;
                    line_start = i;
                }
                space = true;
            }
            '0'..='9' => {
                let (tok, next) = lex_number(&chars, i, at)?;
                push(tok, &mut tokens, &mut space);
                i = next;
            }
            '.' if chars.get(i + 1).is_some_and(|d| d.is_ascii_digit()) => {
                let (tok, next) = lex_number(&chars, i, at)?;
                push(tok, &mut tokens, &mut space);
                i = next;
            }
            'a'..='z' | 'A'..='Z' | '_' => {
                let start = i;
                while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                let name: String = chars[start..i].iter().collect();
                push(Tok::Ident(name), &mut tokens, &mut space);
            }
            '\'' => {
                if prev_ends_value && !(space && in_matrix) {
                    push(Tok::Quote, &mut tokens, &mut space);
                    i += 1;
                } else {
                    return Err(LiteralError::Unsupported {
                        at,
                        what: "character strings".into(),
                    });
                }
            }
            '"' => {
                return Err(LiteralError::Unsupported {
                    at,
                    what: "character strings".into(),
                })
            }
            '.' => {
                let next = chars.get(i + 1).copied();
                let tok = match next {
                    Some('*') => Tok::DotStar,
                    Some('/') => Tok::DotSlash,
                    Some('^') => Tok::DotCaret,
                    Some('\'') => Tok::DotQuote,
                    Some('\\') => Tok::Other(".\\".into()),
                    _ => Tok::Other(".".into()),
                };
                push(tok, &mut tokens, &mut space);
                i += if next.is_some_and(|n| "*/^'\\".contains(n)) {
                    2
                } else {
                    1
                };
            }
            _ => {
                let next = chars.get(i + 1).copied();
                let two: String = [Some(c), next].iter().flatten().collect();
                let (tok, len) = match c {
                    '+' | '-' if next == Some('=') => (Tok::Other(two), 2),
                    '+' => (Tok::Plus, 1),
                    '-' => (Tok::Minus, 1),
                    '*' if next == Some('*') => (Tok::Caret, 2),
                    '*' | '/' | '^' if next == Some('=') => (Tok::Other(two), 2),
                    '*' => (Tok::Star, 1),
                    '/' => (Tok::Slash, 1),
                    '^' => (Tok::Caret, 1),
                    '(' => (Tok::LParen, 1),
                    ')' => (Tok::RParen, 1),
                    '[' => (Tok::LBracket, 1),
                    ']' => (Tok::RBracket, 1),
                    ',' => (Tok::Comma, 1),
                    ';' => (Tok::Semi, 1),
                    ':' => (Tok::Colon, 1),
                    '=' if next == Some('=') => (Tok::Other(two), 2),
                    '=' => (Tok::Assign, 1),
                    '<' | '>' | '~' | '!' if next == Some('=') => (Tok::Other(two), 2),
                    '&' | '|' if next == Some(c) => (Tok::Other(two), 2),
                    other => (Tok::Other(other.to_string()), 1),
                };
                match tok {
                    Tok::LParen => stack.push('('),
                    Tok::LBracket => stack.push('['),
                    Tok::RParen | Tok::RBracket => {
                        stack.pop();
                    }
                    Tok::Other(ref s) if s == "{" => stack.push('{'),
                    Tok::Other(ref s) if s == "}" => {
                        stack.pop();
                    }
                    _ => {}
                }
                push(tok, &mut tokens, &mut space);
                i += len;
            }
        }
    }
    let at = pos(i, line, line_start);
    tokens.push(Token {
        tok: Tok::Eof,
        at,
        space_before: space,
        in_matrix: false,
        offset: i,
    });
    Ok(tokens)
}

/// Lexes the number starting at `start`: digits, an optional fraction and an optional exponent.
fn lex_number(chars: &[char], start: usize, at: Position) -> Result<(Tok, usize), LiteralError> {
    let mut i = start;
    let digits = |i: &mut usize| {
        while *i < chars.len() && chars[*i].is_ascii_digit() {
            *i += 1;
        }
    };
    digits(&mut i);
    if i < chars.len() && chars[i] == '.' {
        // `1.*x`, `1./x`, `1.^x`, `1.'` and `1...` keep the dot for the operator after it.
        let after = chars.get(i + 1).copied();
        let dotted_operator = after.is_some_and(|a| "*/^'\\".contains(a))
            || (after == Some('.') && chars.get(i + 2) == Some(&'.'));
        if !dotted_operator {
            i += 1;
            digits(&mut i);
        }
    }
    let mut text: String = chars[start..i].iter().collect();
    if i < chars.len() && matches!(chars[i], 'e' | 'E' | 'd' | 'D') {
        let mut j = i + 1;
        if j < chars.len() && matches!(chars[j], '+' | '-') {
            j += 1;
        }
        let exp_start = j;
        while j < chars.len() && chars[j].is_ascii_digit() {
            j += 1;
        }
        if j == exp_start {
            return Err(LiteralError::Syntax {
                at,
                expected: "digits after the exponent mark of a number".into(),
                found: format!(
                    "`{}`",
                    chars[start..j.min(chars.len())].iter().collect::<String>()
                ),
            });
        }
        let exponent: String = chars[i + 1..j].iter().collect();
        let magnitude = exponent
            .trim_start_matches(['+', '-'])
            .parse::<i64>()
            .unwrap_or(i64::MAX);
        if magnitude > MAX_EXPONENT {
            return Err(LiteralError::NumberOutOfRange {
                at,
                text: chars[start..j].iter().collect(),
            });
        }
        text.push('e');
        text.push_str(&exponent);
        i = j;
    }
    if text.len() > MAX_NUMBER_LEN {
        return Err(LiteralError::NumberOutOfRange {
            at,
            text: format!("{}…", &text[..20]),
        });
    }
    if let Some(&c) = chars.get(i) {
        if matches!(c, 'i' | 'j' | 'I' | 'J')
            && !chars
                .get(i + 1)
                .is_some_and(|n| n.is_ascii_alphanumeric() || *n == '_')
        {
            return Err(LiteralError::Unsupported {
                at,
                what: "complex numbers".into(),
            });
        }
        if c.is_ascii_alphanumeric() || c == '_' {
            return Err(LiteralError::Syntax {
                at,
                expected: format!("an operator or separator after the number `{text}`"),
                found: format!("`{c}`"),
            });
        }
    }
    Ok((Tok::Num(text), i))
}

/// The characters of line `line` of `chars` around `at`: whether the text from `line_start` to
/// `at` and after the two characters at `at` to the end of the line is white space only.
fn alone_on_line(chars: &[char], line_start: usize, at: usize, len: usize) -> bool {
    let blank = |c: &char| c.is_whitespace() && *c != '\n';
    chars[line_start..at].iter().all(blank)
        && chars[at + len..]
            .iter()
            .take_while(|&&c| c != '\n')
            .all(blank)
}

/// If a block comment opens at `at` (`%{` or `#{` alone on its line), where it ends: `Some(Some((i,
/// lines)))` with `i` the index of the newline after the closing `%}`/`#}` line (or the end of
/// the input) and `lines` the number of line breaks skipped; `Some(None)` if it never closes.
/// Block comments nest, as in Octave.
fn block_comment_end(
    chars: &[char],
    at: usize,
    line_start: usize,
) -> Option<Option<(usize, usize)>> {
    let opens = |i: usize, ls: usize| {
        matches!(chars.get(i), Some('%' | '#'))
            && chars.get(i + 1) == Some(&'{')
            && alone_on_line(chars, ls, i, 2)
    };
    let closes = |i: usize, ls: usize| {
        matches!(chars.get(i), Some('%' | '#'))
            && chars.get(i + 1) == Some(&'}')
            && alone_on_line(chars, ls, i, 2)
    };
    if !opens(at, line_start) {
        return None;
    }
    let mut depth = 0usize;
    let mut lines = 0usize;
    let mut ls = line_start;
    let mut i = at;
    loop {
        // `i` is at the first non-blank character of a line (or the opening mark).
        if opens(i, ls) {
            depth += 1;
        } else if closes(i, ls) {
            depth -= 1;
            if depth == 0 {
                let end = chars[i..]
                    .iter()
                    .position(|&c| c == '\n')
                    .map_or(chars.len(), |k| i + k);
                return Some(Some((end, lines)));
            }
        }
        match chars[i..].iter().position(|&c| c == '\n') {
            Some(k) => {
                i += k + 1;
                ls = i;
                lines += 1;
                while i < chars.len() && chars[i] != '\n' && chars[i].is_whitespace() {
                    i += 1;
                }
            }
            None => return Some(None),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(s: &str) -> Vec<Tok> {
        lex(s, false).unwrap().into_iter().map(|t| t.tok).collect()
    }

    #[test]
    fn numbers_and_dotted_operators() {
        assert_eq!(
            toks("1.*x"),
            vec![
                Tok::Num("1".into()),
                Tok::DotStar,
                Tok::Ident("x".into()),
                Tok::Eof
            ]
        );
        assert_eq!(
            toks(".5 5. 1e-3 2D2"),
            vec![
                Tok::Num(".5".into()),
                Tok::Num("5.".into()),
                Tok::Num("1e-3".into()),
                Tok::Num("2e2".into()),
                Tok::Eof
            ]
        );
    }

    #[test]
    fn quote_is_transpose_or_string() {
        assert_eq!(
            toks("[a' b']")[2],
            Tok::Quote,
            "directly after a value it transposes"
        );
        assert!(matches!(
            lex("[a 'b']", false),
            Err(LiteralError::Unsupported { .. })
        ));
        assert_eq!(
            toks("a '")[1],
            Tok::Quote,
            "outside brackets space is allowed"
        );
    }

    #[test]
    fn comments_and_continuations() {
        assert_eq!(
            toks("1 + ... comment\n 2 % rest"),
            vec![
                Tok::Num("1".into()),
                Tok::Plus,
                Tok::Num("2".into()),
                Tok::Eof
            ]
        );
    }
}
