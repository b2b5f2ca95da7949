//! The resource limits on the command line: each [`Limit`] of the library has a flag and an
//! environment variable; the flag wins over the variable, the variable over the default.

use cagd::limits::{Limit, Limits};

use crate::{CliError, ErrorKind};

/// The deepest nesting `--max-depth` (or `CAGD_MAX_DEPTH`) may allow: the parsers and readers
/// recurse once per level, and the `cagd` binary runs each command on a thread with a stack of
/// [`COMMAND_STACK_BYTES`], which holds this many levels even in an unoptimised build (about
/// 10–40 KB a level there, far less in a release build).
pub const MAX_DEPTH_CAP: u64 = 1000;

/// The stack of the thread the `cagd` binary runs a command on (reserved address space; only
/// what deep nesting actually uses is ever touched).
pub const COMMAND_STACK_BYTES: usize = 256 << 20;

/// Every limit with its environment variable and flag, in field order.
pub const SETTINGS: [(Limit, &str, &str); 10] = [
    (
        Limit::InputBytes,
        "CAGD_MAX_INPUT_BYTES",
        "--max-input-bytes",
    ),
    (
        Limit::ExpressionBytes,
        "CAGD_MAX_EXPRESSION_BYTES",
        "--max-expression-bytes",
    ),
    (Limit::Depth, "CAGD_MAX_DEPTH", "--max-depth"),
    (Limit::Elements, "CAGD_MAX_ELEMENTS", "--max-elements"),
    (Limit::Iterations, "CAGD_MAX_ITERATIONS", "--max-iterations"),
    (Limit::Samples, "CAGD_MAX_SAMPLES", "--max-samples"),
    (
        Limit::GridPoints,
        "CAGD_MAX_GRID_POINTS",
        "--max-grid-points",
    ),
    (Limit::Degree, "CAGD_MAX_DEGREE", "--max-degree"),
    (
        Limit::SystemEntries,
        "CAGD_MAX_SYSTEM_ENTRIES",
        "--max-system-entries",
    ),
    (Limit::Work, "CAGD_MAX_WORK", "--max-work"),
];

/// The flag that sets `limit`, e.g. `--max-grid-points`.
///
/// ```
/// use cagd::limits::Limit;
/// assert_eq!(cagd_cli::limits::flag(Limit::GridPoints), "--max-grid-points");
/// assert_eq!(cagd_cli::limits::variable(Limit::Work), "CAGD_MAX_WORK");
/// ```
pub fn flag(limit: Limit) -> &'static str {
    setting(limit).2
}

/// The environment variable that sets `limit`, e.g. `CAGD_MAX_GRID_POINTS`.
pub fn variable(limit: Limit) -> &'static str {
    setting(limit).1
}

fn setting(limit: Limit) -> (Limit, &'static str, &'static str) {
    *SETTINGS
        .iter()
        .find(|(l, _, _)| *l == limit)
        .expect("SETTINGS lists every limit")
}

/// The defaults, overridden by the environment variables of [`SETTINGS`] that are set.
///
/// # Errors
/// A [`CliError`] naming the variable if one is not a whole number.
pub fn from_env() -> Result<Limits, CliError> {
    let mut limits = Limits::default();
    for (limit, var, _) in SETTINGS {
        if let Ok(text) = std::env::var(var) {
            let value = parse_limit(var, &text)?;
            check_cap(var, limit, value)?;
            limits.set(limit, value);
        }
    }
    Ok(limits)
}

/// Refuses a depth above [`MAX_DEPTH_CAP`], naming `argument` (the flag or the variable).
pub(crate) fn check_cap(argument: &str, limit: Limit, value: u64) -> Result<(), CliError> {
    if limit == Limit::Depth && value > MAX_DEPTH_CAP {
        return Err(CliError::new(
            argument,
            format!(
                "{value} is deeper than the {MAX_DEPTH_CAP} levels of nesting the parsers' stack holds"
            ),
            format!("a depth of at most {MAX_DEPTH_CAP}"),
            ErrorKind::Usage,
        ));
    }
    Ok(())
}

fn parse_limit(var: &str, text: &str) -> Result<u64, CliError> {
    let clean: String = text.trim().chars().filter(|c| *c != '_').collect();
    clean.parse::<u64>().map_err(|_| {
        CliError::new(
            "limits",
            format!("{var}: `{text}` is not a whole number; expected a limit such as 10000000"),
            "whole numbers in the CAGD_MAX_… variables and --max-… flags",
            ErrorKind::Usage,
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_limit_has_one_flag_and_variable() {
        for limit in Limit::ALL {
            let field = limit.field();
            assert_eq!(flag(limit), format!("--{}", field.replace('_', "-")));
            assert_eq!(variable(limit), format!("CAGD_{}", field.to_uppercase()));
        }
        assert!(parse_limit("X", "1_000").is_ok_and(|v| v == 1000));
        assert!(parse_limit("X", "-1").is_err());
    }
}
