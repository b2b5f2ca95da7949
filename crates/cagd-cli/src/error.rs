//! The one error type of the command line, and how each error reads and exits.

use cagd_octave::literal::LiteralError;

/// What kind of thing went wrong, with the typed error underneath where there is one.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A literal, expression or data script did not parse or evaluate.
    Literal(Box<LiteralError>),
    /// A file could not be read or written (the I/O error kind).
    Io(std::io::ErrorKind),
    /// A numeric text file is malformed (ragged rows, a token that is not a number).
    Data,
    /// Inputs of the wrong shape or size for the command (e.g. `--n 1` for a grid).
    Shape,
    /// A construction of the library refused its input.
    Library(Box<cagd::Error>),
    /// A construction refused its input (a check of the operation layer, [`cagd_ops`]).
    Operation(cagd_ops::Kind),
    /// Command-line usage: an unknown option, a missing or conflicting argument.
    Usage,
    /// A valid request this build cannot serve yet.
    Unsupported,
    /// A picture could not be drawn.
    Plot,
    /// A fault of the program itself (exit code 1).
    Internal,
}

/// A command-line error: which argument, what was wrong, and the form that was expected.
///
/// It reads as one line, `<argument>: <problem>; expected <form>`, which the binary prints as
/// `cagd: error: …` on standard error before exiting with [`CliError::exit_code`] (2 for
/// every input error, 1 for internal faults).
///
/// ```
/// use cagd_cli::{CliError, ErrorKind};
/// let e = CliError::new("--n", "N = 1 is too small", "an integer N ≥ 2", ErrorKind::Shape);
/// assert_eq!(e.to_string(), "--n: N = 1 is too small; expected an integer N ≥ 2");
/// assert_eq!(e.exit_code(), 2);
/// ```
///
/// Whatever its fields hold, it prints with every control character escaped
/// ([`escape_text`]), so a message is always one line that cannot drive the terminal.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "{}: {}; expected {}",
    escape_text(argument),
    escape_text(problem),
    escape_text(expected)
)]
pub struct CliError {
    /// The argument (option name, positional name, or file) the error is about.
    pub argument: String,
    /// What was wrong.
    pub problem: String,
    /// The form that would have been accepted.
    pub expected: String,
    /// The kind, with the underlying typed error.
    pub kind: ErrorKind,
}

impl CliError {
    /// An error about `argument`.
    pub fn new(
        argument: impl Into<String>,
        problem: impl Into<String>,
        expected: impl Into<String>,
        kind: ErrorKind,
    ) -> Self {
        CliError {
            argument: one_line(&argument.into()),
            problem: one_line(&problem.into()),
            expected: one_line(&expected.into()),
            kind,
        }
    }

    /// A literal or script error about `argument`.
    pub fn literal(argument: impl Into<String>, error: LiteralError, expected: &str) -> Self {
        Self::new(
            argument,
            error.to_string(),
            expected,
            ErrorKind::Literal(Box::new(error)),
        )
    }

    /// An I/O error about `argument` (usually a file name).
    ///
    /// A file argument is named `NAME PATH` (`CONTROL data.txt`); when such a path is missing
    /// because it is a folder, the error says so (kind [`std::io::ErrorKind::IsADirectory`]).
    pub fn io(argument: impl Into<String>, error: &std::io::Error, expected: &str) -> Self {
        use std::io::ErrorKind as K;
        let argument = argument.into();
        let (problem, kind) = if error.kind() == K::NotFound && names_a_folder(&argument) {
            (FOLDER.to_string(), K::IsADirectory)
        } else {
            io_problem(error)
        };
        Self::new(argument, problem, expected, ErrorKind::Io(kind))
    }

    /// An error about the file `path` given to `argument` (`-o`, `--plot`, …): named
    /// `ARGUMENT PATH`, the path escaped ([`escape_path`]).
    pub fn file(
        argument: &str,
        path: &std::path::Path,
        problem: impl Into<String>,
        expected: impl Into<String>,
        kind: ErrorKind,
    ) -> Self {
        Self::new(
            format!("{argument} {}", escape_path(path)),
            problem,
            expected,
            kind,
        )
    }

    /// A library error about `argument`. A limit the library names ([`cagd::Error::TooLarge`])
    /// is named by its flag and environment variable.
    pub fn library(argument: impl Into<String>, error: cagd::Error, expected: &str) -> Self {
        let problem = match &error {
            cagd::Error::TooLarge {
                what,
                requested,
                limit,
                which,
            } => format!(
                "{what}: {requested} exceeds the limit of {limit} (raise it with {} or {})",
                crate::limits::flag(*which),
                crate::limits::variable(*which)
            ),
            other => other.to_string(),
        };
        Self::new(
            argument,
            problem,
            expected,
            ErrorKind::Library(Box::new(error)),
        )
    }

    /// The process exit code: 1 for [`ErrorKind::Internal`], 2 for everything else.
    pub fn exit_code(&self) -> i32 {
        match self.kind {
            ErrorKind::Internal => 1,
            _ => 2,
        }
    }

    /// The resource limit that refused the request, if a limit did (`--max-work`, …).
    ///
    /// ```
    /// use cagd::limits::Limit;
    /// let e = cagd_cli::run(["cagd", "bernstein", "--degree", "3", "--n", "101", "--max-work", "10"])
    ///     .unwrap_err();
    /// assert_eq!(e.limit(), Some(Limit::Work));
    /// let e = cagd_cli::run(["cagd", "bernstein", "--degree", "-1"]).unwrap_err();
    /// assert_eq!(e.limit(), None);
    /// ```
    pub fn limit(&self) -> Option<cagd::limits::Limit> {
        match &self.kind {
            ErrorKind::Library(e) => match **e {
                cagd::Error::TooLarge { which, .. } => Some(which),
                _ => None,
            },
            _ => None,
        }
    }
}

/// How an I/O error reads in a message, and its kind.
pub(crate) fn io_problem(error: &std::io::Error) -> (String, std::io::ErrorKind) {
    use std::io::ErrorKind as K;
    let problem = match error.kind() {
        K::NotFound => "no such file or directory",
        K::IsADirectory => FOLDER,
        K::PermissionDenied => "permission denied",
        K::StorageFull => "no space left on the device",
        K::ReadOnlyFilesystem => "the file system is read-only",
        K::NotADirectory => "a part of the path is not a folder",
        _ => return (error.to_string(), error.kind()),
    };
    (problem.to_string(), error.kind())
}

/// The problem of an input path that is a folder.
const FOLDER: &str = "is a folder, not a file";

/// Whether `argument`, of the form `NAME PATH` or `NAME PATH:VARIABLE`, names a folder.
fn names_a_folder(argument: &str) -> bool {
    let Some((_, path)) = argument.split_once(' ') else {
        return false;
    };
    let is_dir = |p: &str| std::fs::metadata(p).is_ok_and(|m| m.is_dir());
    is_dir(path) || path.rsplit_once(':').is_some_and(|(p, _)| is_dir(p))
}

/// Makes a message one line that is safe to print: the text escaped ([`escape_text`]), white
/// space at its ends trimmed, and a quotation longer than [`MAX_QUOTE_CHARS`] characters
/// shortened to its start and end around `…`, so that an error line stays one readable line
/// whatever the input.
fn one_line(s: &str) -> String {
    shorten_quotes(&escape_text(s.trim()))
}

/// The one way user-supplied text — a path, a value, a quotation of an input — appears in a
/// message or a warning: line breaks and tabs as `\n`, `\r`, `\t`, every other control
/// character (a terminal's escape sequences start with one) and the invisible Unicode format
/// characters that reorder or hide text (bidirectional overrides, zero-width spaces) as
/// `\u{…}`. Everything else, spaces and non-ASCII letters included, is kept. Escaping twice
/// changes nothing.
///
/// ```
/// use cagd_cli::escape_text;
/// assert_eq!(escape_text("no\x1b]0;T\x07dir/x"), "no\\u{1b}]0;T\\u{7}dir/x");
/// assert_eq!(escape_text("a\nb\tč"), "a\\nb\\tč");
/// assert_eq!(escape_text("x\u{202e}y"), "x\\u{202e}y");
/// assert_eq!(escape_text(&escape_text("a\nb")), escape_text("a\nb"));
/// ```
pub fn escape_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() || is_invisible_format(c) => {
                out.extend(c.escape_unicode());
            }
            c => out.push(c),
        }
    }
    out
}

/// Unicode format characters that change how the text around them shows: bidirectional
/// marks, embeddings, overrides and isolates, zero-width characters, the byte-order mark and
/// the interlinear annotation marks.
fn is_invisible_format(c: char) -> bool {
    matches!(c,
        '\u{061c}' | '\u{180e}' | '\u{200b}'..='\u{200f}' | '\u{2028}'..='\u{202e}'
        | '\u{2060}'..='\u{206f}' | '\u{feff}' | '\u{fff9}'..='\u{fffb}')
}

/// A path as it appears in a message: its text escaped as [`escape_text`] does, and each
/// byte that is not UTF-8 shown as `\x{ff}`.
///
/// ```
/// use std::path::Path;
/// assert_eq!(cagd_cli::escape_path(Path::new("out\n.txt")), "out\\n.txt");
/// ```
pub fn escape_path(path: &std::path::Path) -> String {
    let bytes = path.as_os_str().as_encoded_bytes();
    let mut out = String::new();
    for chunk in bytes.utf8_chunks() {
        out.push_str(&escape_text(chunk.valid()));
        for b in chunk.invalid() {
            out.push_str(&format!("\\x{{{b:02x}}}"));
        }
    }
    out
}

/// Longest input quotation (between backquotes) kept whole in a message.
pub const MAX_QUOTE_CHARS: usize = 60;

/// Shortens every backquoted quotation longer than [`MAX_QUOTE_CHARS`], and the whole text if
/// it is longer than ten times that.
fn shorten_quotes(s: &str) -> String {
    let shorten = |q: &str| -> String {
        let chars: Vec<char> = q.chars().collect();
        if chars.len() <= MAX_QUOTE_CHARS {
            return q.to_string();
        }
        let head: String = chars[..MAX_QUOTE_CHARS / 2].iter().collect();
        let tail: String = chars[chars.len() - MAX_QUOTE_CHARS / 4..].iter().collect();
        format!("{head}…{tail} ({} characters)", chars.len())
    };
    let parts: Vec<&str> = s.split('`').collect();
    let mut out = String::with_capacity(s.len().min(4 * MAX_QUOTE_CHARS));
    for (k, part) in parts.iter().enumerate() {
        if k > 0 {
            out.push('`');
        }
        // Odd parts lie between backquotes (an unmatched last quote leaves an odd part open).
        if k % 2 == 1 {
            out.push_str(&shorten(part));
        } else {
            out.push_str(part);
        }
    }
    let limit = 10 * MAX_QUOTE_CHARS;
    if out.chars().count() > limit {
        out = shorten(&out);
    }
    out
}

impl CliError {
    /// A mesh export error about `argument` (usually `--mesh FILE`).
    pub fn mesh(argument: impl Into<String>, error: &crate::mesh::MeshError) -> Self {
        use crate::mesh::MeshError as M;
        let (problem, expected, kind) = match error {
            M::UnknownExtension { .. } => (
                "unknown mesh format".to_string(),
                "a file name ending in .stl, .obj or .ply".to_string(),
                ErrorKind::Usage,
            ),
            M::Shape { nu, nv, dim } => (
                format!("the surface grid has shape ({nu}, {nv}, {dim})"),
                "a grid of 3-D points, at least 2 × 2 (e.g. --n 2 or more)".to_string(),
                ErrorKind::Shape,
            ),
            M::NonFinite { index } => (
                format!("grid value {index} is not finite"),
                "finite coordinates".to_string(),
                ErrorKind::Shape,
            ),
            M::OutOfRange { index, value } => (
                format!(
                    "grid value {index} is {value:e}, beyond the single precision of binary STL"
                ),
                "coordinates within ±3.4e38 for .stl (or write .obj or .ply, which keep doubles)"
                    .to_string(),
                ErrorKind::Shape,
            ),
            M::TooLarge { points, limit } => (
                format!("the grid has {points} points"),
                format!("at most {limit} grid points"),
                ErrorKind::Shape,
            ),
            M::Io { message, .. } => (
                message.clone(),
                "a writable path in an existing directory".to_string(),
                ErrorKind::Io(std::io::ErrorKind::Other),
            ),
        };
        Self::new(argument, problem, expected, kind)
    }

    /// A picture error about `argument` (usually `--plot FILE`).
    pub fn plot(argument: impl Into<String>, error: &crate::plot::PlotError) -> Self {
        use crate::plot::PlotError as P;
        let (problem, expected, kind) = match error {
            P::UnknownExtension { .. } => (
                "unknown picture format".to_string(),
                "a file name ending in .svg or .png".to_string(),
                ErrorKind::Usage,
            ),
            P::Empty => (
                "nothing to draw".to_string(),
                "a result with points".to_string(),
                ErrorKind::Plot,
            ),
            P::Shape { label, message } => (
                format!("`{label}`: {message}"),
                "curves and surfaces of 2-D or 3-D points".to_string(),
                ErrorKind::Plot,
            ),
            P::NonFinite { label, index } => (
                format!("`{label}`: coordinate {index} is not finite"),
                "finite coordinates".to_string(),
                ErrorKind::Plot,
            ),
            P::OutOfRange {
                label,
                index,
                value,
            } => (
                format!("`{label}`: coordinate {index} is {value:e}, too large to draw"),
                format!(
                    "coordinates within ±{:e} (scale the data down to draw it)",
                    crate::plot::MAX_COORDINATE
                ),
                ErrorKind::Plot,
            ),
            P::Size { width, height } => (
                format!("picture size {width}×{height}"),
                "100 to 10000 pixels per side".to_string(),
                ErrorKind::Plot,
            ),
            P::Io { message, .. } => (
                message.clone(),
                "a writable path in an existing directory".to_string(),
                ErrorKind::Io(std::io::ErrorKind::Other),
            ),
            _ => (
                error.to_string(),
                "a picture the drawing library can render".to_string(),
                ErrorKind::Internal,
            ),
        };
        Self::new(argument, problem, expected, kind)
    }
}

/// A library error about `argument`.
pub(crate) fn lib<'a>(
    argument: &'a str,
    expected: &'a str,
) -> impl Fn(cagd::Error) -> CliError + 'a {
    move |e| CliError::library(argument, e, expected)
}

/// A usage error: a required argument is missing or arguments do not fit together.
pub(crate) fn usage(argument: &str, problem: &str, expected: &str) -> CliError {
    CliError::new(argument, problem, expected, ErrorKind::Usage)
}

/// A shape error.
pub(crate) fn shape(argument: &str, problem: String, expected: &str) -> CliError {
    CliError::new(argument, problem, expected, ErrorKind::Shape)
}
