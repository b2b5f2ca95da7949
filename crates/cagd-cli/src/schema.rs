//! The command line described as data: every subcommand with its arguments, their help,
//! defaults and choices, read from the same clap definitions that parse the arguments. The
//! web page builds its forms from it, so every subcommand has a form and a new subcommand
//! needs no page code. Beside clap's English it hands over the Slovenian and Czech words of
//! [`crate::lang::forms`]: the summary of each subcommand, the label and hint of each argument.

use serde_json::{json, Value};

use crate::lang::{forms, Lang};

/// Every subcommand (in the order of `cagd --help`) as JSON:
///
/// ```json
/// [{"name": "decasteljau", "about": "…", "help": "…(after_help)…",
///   "i18n": {"sl": "…summary…", "cs": "…"},
///   "args": [{"id": "control", "positional": true, "value_name": "CONTROL", "help": "…",
///             "i18n": {"sl": {"label": "…", "hint": "…"}, "cs": {"label": "…", "hint": "…"}},
///             "required": true, "takes_value": true, "repeated": false,
///             "default": null, "choices": []}, …]}, …]
/// ```
///
/// Options of the limits (global, `--max-…`) are left out; `--help` and `--version` too.
///
/// ```
/// let schema = cagd_cli::schema::schema();
/// let decasteljau = schema.as_array().unwrap().iter().find(|c| c["name"] == "decasteljau").unwrap();
/// let t = decasteljau["args"].as_array().unwrap().iter().find(|a| a["long"] == "t").unwrap();
/// assert_eq!(t["value_name"], "VALUES");
/// assert_eq!(t["i18n"]["sl"]["label"], "Parametri krivulje");
/// assert_eq!(t["i18n"]["cs"]["label"], "Parametry křivky");
/// let format = decasteljau["args"].as_array().unwrap().iter().find(|a| a["long"] == "format").unwrap();
/// assert_eq!(format["default"], "text");
/// assert!(format["choices"].as_array().unwrap().iter().any(|c| c == "json"));
/// assert!(decasteljau["i18n"]["sl"].as_str().unwrap().starts_with("Točke Bézierove krivulje"));
/// ```
pub fn schema() -> Value {
    let command = crate::app::command();
    Value::Array(
        command
            .get_subcommands()
            .map(|sub| {
                let name = sub.get_name();
                json!({
                    "name": name,
                    "about": sub.get_about().map(|s| s.to_string()),
                    "help": sub.get_after_help().map(|s| s.to_string()),
                    "i18n": translations(|lang| forms::summary(name, lang).map(Value::from)),
                    "args": form_arguments(sub).map(|a| argument(name, a)).collect::<Vec<_>>(),
                })
            })
            .collect(),
    )
}

/// The arguments of subcommand `sub` its form shows: all but the limits' (global) options,
/// `--help` and `--version`.
pub(crate) fn form_arguments(sub: &clap::Command) -> impl Iterator<Item = &clap::Arg> {
    sub.get_arguments()
        .filter(|a| !a.is_global_set() && !is_builtin(a))
}

/// `{"sl": …, "cs": …}` of the words `of` gives in each language other than English.
fn translations(of: impl Fn(Lang) -> Option<Value>) -> Value {
    Lang::ALL
        .into_iter()
        .filter(|&lang| lang != Lang::En)
        .filter_map(|lang| of(lang).map(|v| (lang.code().to_string(), v)))
        .collect::<serde_json::Map<_, _>>()
        .into()
}

fn is_builtin(a: &clap::Arg) -> bool {
    matches!(a.get_id().as_str(), "help" | "version")
}

fn argument(command: &str, a: &clap::Arg) -> Value {
    let takes_value = a.get_num_args().is_none_or(|n| n.takes_values())
        && !matches!(
            a.get_action(),
            clap::ArgAction::SetTrue | clap::ArgAction::SetFalse | clap::ArgAction::Count
        );
    let choices: Vec<String> = a
        .get_possible_values()
        .iter()
        .filter(|v| !v.is_hide_set())
        .map(|v| v.get_name().to_string())
        .collect();
    let default = a
        .get_default_values()
        .first()
        .map(|v| v.to_string_lossy().into_owned());
    let id = a.get_id().as_str();
    json!({
        "id": id,
        "long": a.get_long(),
        "short": a.get_short().map(String::from),
        "positional": a.is_positional(),
        "value_name": a.get_value_names().and_then(|v| v.first()).map(|s| s.to_string()),
        "help": a.get_help().map(|s| s.to_string()),
        "i18n": translations(|lang| forms::argument(command, id, lang)
            .map(|h| json!({ "label": h.label, "hint": h.hint }))),
        "required": a.is_required_set(),
        "takes_value": takes_value && !(choices.is_empty() && is_flag(a)),
        "repeated": matches!(a.get_action(), clap::ArgAction::Append),
        "default": default,
        "choices": if is_flag(a) { Vec::new() } else { choices },
    })
}

fn is_flag(a: &clap::Arg) -> bool {
    matches!(
        a.get_action(),
        clap::ArgAction::SetTrue | clap::ArgAction::SetFalse | clap::ArgAction::Count
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    /// The page's forms get both languages for every subcommand and argument, from the one
    /// table: a subcommand or argument without its translations fails here.
    #[test]
    fn every_form_field_of_the_schema_has_slovenian_and_czech_words() {
        let blank = |v: &Value| v.as_str().is_none_or(|s| s.trim().is_empty());
        let mut missing = Vec::new();
        for c in schema().as_array().unwrap() {
            for lang in ["sl", "cs"] {
                if blank(&c["i18n"][lang]) {
                    missing.push(format!("{} ({lang})", c["name"]));
                }
                for a in c["args"].as_array().unwrap() {
                    for part in ["label", "hint"] {
                        if blank(&a["i18n"][lang][part]) {
                            missing.push(format!("{} {} {part} ({lang})", c["name"], a["id"]));
                        }
                    }
                }
            }
        }
        assert!(missing.is_empty(), "no translation: {missing:?}");
        assert_eq!(
            forms::SUMMARIES.len(),
            crate::subcommands().len(),
            "a summary of no subcommand"
        );
    }

    /// One entry translates one English text: an entry for several subcommands may only stand
    /// for arguments whose help is the same, and every entry is used by each subcommand it
    /// names.
    #[test]
    fn each_entry_of_the_table_translates_one_english_help_and_is_used() {
        let command = crate::app::command();
        let mut all = Vec::new();
        for sub in command.get_subcommands() {
            for a in form_arguments(sub) {
                let help = a.get_help().map(|s| s.to_string()).unwrap_or_default();
                all.push((sub.get_name().to_string(), a.get_id().to_string(), help));
            }
        }
        let mut english: BTreeMap<usize, &str> = BTreeMap::new();
        for (command, id, help) in &all {
            let Some(e) = forms::entry(command, id) else {
                continue;
            };
            let i = forms::ARGUMENTS
                .iter()
                .position(|a| std::ptr::eq(a, e))
                .unwrap();
            if let Some(before) = english.insert(i, help) {
                assert_eq!(before, help, "one entry for two texts: {command} {id}");
            }
        }
        for (i, a) in forms::ARGUMENTS.iter().enumerate() {
            assert!(
                english.contains_key(&i),
                "unused entry: {:?} {}",
                a.commands,
                a.id
            );
            for command in a.commands {
                assert!(
                    all.iter().any(|(c, id, _)| c == command && id == a.id),
                    "{command} has no argument {}",
                    a.id
                );
            }
        }
    }
}
