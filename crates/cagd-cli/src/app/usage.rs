//! What a command line meant when clap refuses it: the option as typed, and the option or
//! subcommand most like it.

use std::ffi::OsString;

use clap::CommandFactory;

/// An unknown option: (the option as typed, the problem, what is expected), with the option
/// meant; `clap_arg` is what clap names, `clap_suggestion` its suggestion.
pub(super) fn unknown_argument(
    args: &[OsString],
    clap_arg: String,
    clap_suggestion: Option<String>,
) -> (String, String, String) {
    let arg = match unknown_option(args) {
        Some(typed) if !clap_arg.starts_with('-') || typed.starts_with(&clap_arg) => typed,
        _ => clap_arg,
    };
    let expected = suggested_option(args, &arg)
        .or(clap_suggestion)
        .map(|s| format!("{s} perhaps, or an option listed by --help"))
        .unwrap_or_else(|| "an option listed by --help".into());
    (arg, "unknown option".into(), expected)
}

/// An unknown subcommand `typed`: (it, the problem, the closest and all `subcommands`).
pub(super) fn unknown_subcommand(typed: String, subcommands: &str) -> (String, String, String) {
    let suggestion = suggested_subcommand(&typed)
        .map(|s| format!("{s} perhaps, or "))
        .unwrap_or_default();
    let expected = format!("{suggestion}one of {subcommands}");
    (typed, "unknown subcommand".into(), expected)
}

/// The first option of `args` (`--name` or `--name=value`) that the subcommand does not
/// have, as typed (clap names the value after it when the subcommand takes an optional
/// positional: `integrate --bernstien 3` is about `--bernstien`, not `3`).
fn unknown_option(args: &[OsString]) -> Option<String> {
    let words: Vec<String> = args
        .iter()
        .skip(1)
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    let command = super::Cli::command();
    let sub = words
        .iter()
        .find(|w| !w.starts_with('-'))
        .and_then(|name| command.find_subcommand(name))?;
    let known = |name: &str| {
        sub.get_arguments().chain(command.get_arguments()).any(|a| {
            a.get_long() == Some(name) || a.get_all_aliases().is_some_and(|v| v.contains(&name))
        }) || name == "help"
    };
    words
        .iter()
        .filter_map(|w| w.strip_prefix("--"))
        .map(|w| w.split('=').next().unwrap_or(w))
        .find(|name| !name.is_empty() && !known(name))
        .map(|name| format!("--{name}"))
}

/// The option meant by `typed` in the subcommand of `args`: `--u` and `--v` for a curve's
/// `--t` on a surface, else the option of the subcommand closest in spelling.
fn suggested_option(args: &[OsString], typed: &str) -> Option<String> {
    let command = super::Cli::command();
    let sub = args
        .iter()
        .skip(1)
        .map(|a| a.to_string_lossy().into_owned())
        .find(|w| !w.starts_with('-'))
        .and_then(|name| command.find_subcommand(&name).cloned())?;
    let longs: Vec<String> = sub
        .get_arguments()
        .filter_map(|a| a.get_long().map(str::to_string))
        .collect();
    let has = |name: &str| longs.iter().any(|l| l == name);
    let name = typed.trim_start_matches('-');
    if name == "t" && has("u") && has("v") {
        return Some("--u and --v (a surface has two parameters)".into());
    }
    if has(&format!("u{name}")) && has(&format!("v{name}")) {
        return Some(format!(
            "--u{name} and --v{name} (one per direction of the surface)"
        ));
    }
    closest(name, longs.iter().map(String::as_str)).map(|l| format!("--{l}"))
}

/// The subcommand closest in spelling to `typed`, if any is close.
fn suggested_subcommand(typed: &str) -> Option<String> {
    let command = super::Cli::command();
    closest(typed, command.get_subcommands().map(|s| s.get_name())).map(str::to_string)
}

/// The one of `names` most like `typed` (Jaro–Winkler similarity at least 0.8).
fn closest<'a>(typed: &str, names: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    names
        .map(|n| (strsim::jaro_winkler(typed, n), n))
        .filter(|(score, _)| *score >= 0.8)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, n)| n)
}
