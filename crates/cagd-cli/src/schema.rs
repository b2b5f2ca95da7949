//! The command line described as data: every subcommand with its arguments, their help,
//! defaults and choices, read from the same clap definitions that parse the arguments. The
//! web page builds its forms from it, so every subcommand has a form and a new subcommand
//! needs no page code.

use serde_json::{json, Value};

/// Every subcommand (in the order of `cagd --help`) as JSON:
///
/// ```json
/// [{"name": "decasteljau", "about": "…", "help": "…(after_help)…",
///   "args": [{"id": "control", "positional": true, "value_name": "CONTROL", "help": "…",
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
/// let format = decasteljau["args"].as_array().unwrap().iter().find(|a| a["long"] == "format").unwrap();
/// assert_eq!(format["default"], "text");
/// assert!(format["choices"].as_array().unwrap().iter().any(|c| c == "json"));
/// ```
pub fn schema() -> Value {
    let command = crate::app::command();
    Value::Array(
        command
            .get_subcommands()
            .map(|sub| {
                json!({
                    "name": sub.get_name(),
                    "about": sub.get_about().map(|s| s.to_string()),
                    "help": sub.get_after_help().map(|s| s.to_string()),
                    "args": sub
                        .get_arguments()
                        .filter(|a| !a.is_global_set() && !is_builtin(a))
                        .map(argument)
                        .collect::<Vec<_>>(),
                })
            })
            .collect(),
    )
}

fn is_builtin(a: &clap::Arg) -> bool {
    matches!(a.get_id().as_str(), "help" | "version")
}

fn argument(a: &clap::Arg) -> Value {
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
    json!({
        "id": a.get_id().as_str(),
        "long": a.get_long(),
        "short": a.get_short().map(String::from),
        "positional": a.is_positional(),
        "value_name": a.get_value_names().and_then(|v| v.first()).map(|s| s.to_string()),
        "help": a.get_help().map(|s| s.to_string()),
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
