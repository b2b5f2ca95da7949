//! What a command notices while reading its input: its warnings, how each matrix of points
//! was read, the decimal commas it met ([`crate::slips`] decides; [`crate::Cx`] keeps them).

use cagd_octave::literal::Warning;

/// What one command noticed while reading its input (kept in its [`crate::Cx`]).
#[derive(Debug, Default)]
pub struct Noticed {
    /// The warnings, with their argument.
    pub(crate) warnings: Vec<(String, Warning)>,
    /// Whether the orientation of points was stated (`--rows` or `--columns`).
    pub(crate) stated: bool,
    /// How each matrix of points was read, by argument.
    pub(crate) readings: Vec<(String, Reading)>,
    /// The decimal-comma warnings, by argument.
    pub(crate) commas: Vec<(String, String)>,
}

/// How a matrix of points was read: `count` points in `dim`-D, one per column or (with
/// `--rows`) one per row, with the flag that flips the reading.
///
/// ```
/// let r = cagd_cli::slips::Reading { count: 3, dim: 2, rows: false };
/// assert_eq!(r.to_string(), "read as 3 points in 2-D, one per column; --rows if each row is a point");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Reading {
    /// The number of points.
    pub count: usize,
    /// Their dimension.
    pub dim: usize,
    /// Whether each row is a point (`--rows`).
    pub rows: bool,
}

impl std::fmt::Display for Reading {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (count, dim) = (self.count, self.dim);
        let points = if count == 1 { "point" } else { "points" };
        if self.rows {
            write!(
                f,
                "read as {count} {points} in {dim}-D, one per row (--rows); leave out --rows if each column is a point"
            )
        } else {
            write!(
                f,
                "read as {count} {points} in {dim}-D, one per column; --rows if each row is a point"
            )
        }
    }
}
