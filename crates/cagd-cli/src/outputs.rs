//! The files a command will write, checked before any work: each target must be a new or
//! regular file (or `-`, standard output), and no two outputs may share a path. A FIFO, a
//! device or a folder is never replaced by a regular file.

use std::path::{Path, PathBuf};

use clap::ArgMatches;

use crate::{CliError, ErrorKind};

/// The output options of every subcommand: (argument id, how the error names it).
const OUTPUTS: [(&str, &str); 3] = [("output", "-o"), ("plot", "--plot"), ("mesh", "--mesh")];

/// The form of an output argument, for error messages.
const OUTPUT_FORM: &str = "a new or regular file in an existing folder, or - for standard output";

/// Checks the output targets of the subcommand in `matches`.
///
/// # Errors
/// A [`CliError`] naming the option when its target exists and is not a regular file, or when
/// two outputs (or an output and the printed result) would go to the same place.
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
        let shown = format!("{flag} {}", path.display());
        let place = if path.as_os_str() == "-" {
            PathBuf::from("-")
        } else {
            if let Some(kind) = not_regular(path) {
                return Err(CliError::new(
                    shown,
                    format!("exists and is {kind}, not a regular file; it is not replaced"),
                    OUTPUT_FORM,
                    ErrorKind::Io(std::io::ErrorKind::AlreadyExists),
                ));
            }
            same_file_key(path)
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

/// What `path` is when it exists and is not a regular file (following symbolic links).
pub fn not_regular(path: &Path) -> Option<&'static str> {
    let meta = std::fs::metadata(path).ok()?;
    let t = meta.file_type();
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("a folder");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return Some("a named pipe (FIFO)");
        }
        if t.is_char_device() || t.is_block_device() {
            return Some("a device");
        }
        if t.is_socket() {
            return Some("a socket");
        }
    }
    Some("not a regular file")
}

/// A key under which two spellings of one file compare equal: the canonical folder and the
/// file name (the file itself may not exist yet).
fn same_file_key(path: &Path) -> PathBuf {
    if let Ok(p) = std::fs::canonicalize(path) {
        return p;
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let dir = std::fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf());
    match path.file_name() {
        Some(name) => dir.join(name),
        None => path.to_path_buf(),
    }
}
