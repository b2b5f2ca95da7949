//! What the page builds itself from, read from the program's own definitions: every
//! subcommand's arguments (the forms) and the labels of the steps in the page's languages.

use wasm_bindgen::prelude::wasm_bindgen;

/// Every subcommand of the command line with its arguments, their help, defaults and choices
/// ([`cagd_cli::schema::schema`], from the clap definitions that parse them), as JSON text:
/// the page generates each subcommand's form from it, so a new subcommand needs no page code.
///
/// ```
/// let schema: serde_json::Value = serde_json::from_str(&cagd_web::schema()).unwrap();
/// let names: Vec<&str> = schema.as_array().unwrap().iter().map(|c| c["name"].as_str().unwrap()).collect();
/// assert_eq!(names, cagd_cli::subcommands());
/// ```
#[wasm_bindgen]
pub fn schema() -> String {
    cagd_cli::schema::schema().to_string()
}

/// The labels of the steps in English, Slovenian and Czech ([`cagd_cli::lang`], the table the
/// command line's `--lang` uses), as JSON text: `{"labels": {name: {en, sl, cs}}, "phrases":
/// [{en, sl, cs}]}`.
///
/// ```
/// let tables: serde_json::Value = serde_json::from_str(&cagd_web::step_tables()).unwrap();
/// assert_eq!(tables["labels"]["rcd"]["sl"], "r_cd: bilinearna interpolacija štirih oglišč");
/// ```
#[wasm_bindgen]
pub fn step_tables() -> String {
    cagd_cli::lang::tables_json().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_subcommand_has_arguments_the_page_can_build_a_form_from() {
        let schema: serde_json::Value = serde_json::from_str(&schema()).unwrap();
        for c in schema.as_array().unwrap() {
            for a in c["args"].as_array().unwrap() {
                assert!(a["id"].is_string(), "{c}");
                assert!(
                    a["positional"].as_bool().unwrap() || a["long"].is_string(),
                    "{}: {a}",
                    c["name"]
                );
            }
        }
    }
}
