//! The files a command will write, checked before any work, with the rules of the shell's `>`:
//! - a symbolic link is followed: the link stays and its target gets the content (a dangling
//!   link creates its target; a loop of links is refused) — [`destination`];
//! - an existing target must be a regular file that may be written: a FIFO, a device or a
//!   folder is never replaced by a regular file, and a read-only file (mode 0444, or one that
//!   cannot be opened for writing) is refused, not replaced — [`refusal`];
//! - the folder of a new file must exist;
//! - an output that is also an input (the same file by any path, link or hard link; `FILE`
//!   of `FILE:NAME`; standard input redirected from it) is refused;
//! - no two outputs may share a file, and standard output carries one thing.
//!
//! Where atomic replacement differs from `>` (which writes into the existing file): the new
//! file is written beside the old one and renamed over it, so its folder must be writable,
//! and another hard link to the old file keeps the old contents. A file without any write
//! permission bit is refused even for root, whom `>` would let through.
//!
//! [`check`] runs them for every subcommand from its parsed arguments ([`crate::run`] calls it
//! before any work); the files are written by [`crate::PendingWrites::commit`], which applies
//! the same rules again at the moment of writing.

use std::path::{Path, PathBuf};

use clap::ArgMatches;

use crate::{CliError, ErrorKind};

mod inputs;
mod target;

pub use target::{destination, directory_of, file_id, not_regular, refusal, FileId, MAX_LINKS};

/// The output options of every subcommand: (argument id, how the error names it).
const OUTPUTS: [(&str, &str); 3] = [("output", "-o"), ("plot", "--plot"), ("mesh", "--mesh")];

/// The form of an output argument, for error messages.
pub const OUTPUT_FORM: &str =
    "a new or writable regular file in an existing folder, or - for standard output";

/// Checks the output targets of the subcommand in `matches`.
///
/// # Errors
/// A [`CliError`] naming the option and its path when its target may not be written
/// ([`refusal`]), when it is also an input, or when two outputs (or an output and the printed
/// result) would go to the same place.
pub fn check(matches: &ArgMatches) -> Result<(), CliError> {
    let Some((_, sub)) = matches.subcommand() else {
        return Ok(());
    };
    let mut seen: Vec<(&str, PathBuf, String)> = Vec::new();
    let mut result_to_stdout = true;
    for (id, flag) in OUTPUTS {
        let Ok(Some(path)) = sub.try_get_one::<PathBuf>(id) else {
            continue;
        };
        let shown = format!("{flag} {}", crate::escape_path(path));
        let place = if path.as_os_str() == "-" {
            PathBuf::from("-")
        } else {
            check_file(sub, flag, path)?;
            same_file_key(&destination(path).unwrap_or_else(|_| path.clone()))
        };
        if id == "output" {
            result_to_stdout = place.as_os_str() == "-";
        }
        if let Some((other, _, _)) = seen.iter().find(|(_, p, _)| *p == place) {
            return Err(CliError::new(
                shown,
                format!("{other} writes to the same place"),
                "a different path for each output",
                ErrorKind::Usage,
            ));
        }
        seen.push((flag, place, shown));
    }
    if result_to_stdout {
        if let Some((flag, _, shown)) = seen
            .iter()
            .find(|(f, p, _)| *f != "-o" && p.as_os_str() == "-")
        {
            return Err(CliError::new(
                shown.as_str(),
                format!("standard output already carries the result, so {flag} - cannot use it"),
                "-o FILE for the result when a picture or mesh goes to standard output",
                ErrorKind::Usage,
            ));
        }
    }
    Ok(())
}

/// The rules for one output file: writable, and not an input of `sub`.
fn check_file(sub: &ArgMatches, flag: &str, path: &Path) -> Result<(), CliError> {
    if let Some((problem, kind)) = refusal(path) {
        return Err(CliError::file(flag, path, problem, OUTPUT_FORM, kind));
    }
    let Some(id) = file_id(path) else {
        return Ok(());
    };
    match inputs::input_naming(sub, &id) {
        Some(input) => Err(CliError::file(
            flag,
            path,
            format!(
                "is also an input (`{}`); writing it would destroy the input, so it is not replaced",
                crate::escape_text(&input)
            ),
            "an output file that is not one of the inputs (write elsewhere, then rename)",
            ErrorKind::Usage,
        )),
        None => Ok(()),
    }
}

/// A key under which two spellings of one file compare equal: the canonical folder and the
/// file name (the file itself may not exist yet).
fn same_file_key(path: &Path) -> PathBuf {
    if let Ok(p) = std::fs::canonicalize(path) {
        return p;
    }
    let dir = directory_of(path);
    let dir = std::fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf());
    match path.file_name() {
        Some(name) => dir.join(name),
        None => path.to_path_buf(),
    }
}
