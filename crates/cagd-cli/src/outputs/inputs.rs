//! An output that is also an input is refused before any work (`cagd decasteljau pts.txt -o
//! pts.txt` would read the points and then replace them): every text argument of the
//! subcommand that names an existing file — as typed, as the `FILE` of `FILE:NAME`, or `-`
//! for standard input — is compared with the output by identity, so another spelling of the
//! path, a symbolic link or a hard link to the same file is caught as well.

use std::path::Path;

use clap::parser::ValueSource;
use clap::ArgMatches;

use super::target::{file_id, FileId};

/// The text arguments of `sub` (as typed) that name the file `output`, if any: the first one.
pub fn input_naming(sub: &ArgMatches, output: &FileId) -> Option<String> {
    for id in sub.ids() {
        let id = id.as_str();
        // Inputs are text arguments typed by the user; outputs, folders, numbers, switches
        // and choices are other types, and defaults are never files.
        if sub.value_source(id) == Some(ValueSource::DefaultValue) {
            continue;
        }
        let Ok(Some(values)) = sub.try_get_many::<String>(id) else {
            continue;
        };
        for value in values {
            if candidates(value.trim()).any(|c| c.as_ref() == Some(output)) {
                return Some(value.clone());
            }
        }
    }
    None
}

/// The files an argument may be read from: standard input for `-`, else the text as a path
/// and each part of it before a `:` (the `FILE` of `FILE:NAME`).
fn candidates(text: &str) -> impl Iterator<Item = Option<FileId>> + '_ {
    let whole = if text == "-" {
        file_id(Path::new("/dev/stdin"))
    } else {
        file_id(Path::new(text))
    };
    let prefixes = text
        .match_indices(':')
        .map(move |(k, _)| file_id(Path::new(&text[..k])));
    std::iter::once(whole).chain(prefixes)
}
