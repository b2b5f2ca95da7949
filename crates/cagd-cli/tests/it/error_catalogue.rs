//! Every error variant has a section with a triggering doc test in docs/ERRORS.md (the
//! catalogue is included in the crate docs, so `cargo test --doc` runs its examples).

use std::path::Path;

fn read(path: &str) -> String {
    std::fs::read_to_string(Path::new(cagd_test_support::WORKSPACE).join(path)).unwrap()
}

/// The variant names of `enum name` in `source` (lines `    Name {`, `    Name(`, `    Name,`
/// at the first indentation level of the enum body).
fn variants(source: &str, name: &str) -> Vec<String> {
    let start = source
        .find(&format!("pub enum {name} {{"))
        .unwrap_or_else(|| panic!("enum {name} not found"));
    let body = &source[start..];
    let end = body.find("\n}\n").unwrap();
    body[..end]
        .lines()
        .skip(1)
        .filter(|l| l.starts_with("    ") && !l.starts_with("     "))
        .map(str::trim)
        .filter(|l| l.chars().next().is_some_and(char::is_uppercase))
        .map(|l| {
            l.split(|c: char| !c.is_alphanumeric() && c != '_')
                .next()
                .unwrap()
                .to_string()
        })
        .collect()
}

/// The part of the catalogue under the heading that starts with `## {heading}`.
fn section<'a>(catalogue: &'a str, heading: &str) -> &'a str {
    let start = catalogue
        .find(&format!("\n## {heading}"))
        .unwrap_or_else(|| panic!("no section {heading}"));
    let rest = &catalogue[start + 1..];
    let end = rest[3..].find("\n## ").map_or(rest.len(), |e| e + 3);
    &rest[..end]
}

/// The example of `### \`variant\`` inside `section`: the text up to the next `###`.
fn example<'a>(section: &'a str, variant: &str) -> Option<&'a str> {
    let start = section.find(&format!("### `{variant}`\n"))?;
    let rest = &section[start + 4..];
    Some(&rest[..rest.find("\n### ").unwrap_or(rest.len())])
}

#[test]
fn every_variant_has_a_triggering_example() {
    let catalogue = read("docs/ERRORS.md");
    let enums = [
        ("src/error.rs", "Error", "`cagd::Error`", "Error::"),
        (
            "crates/cagd-octave/src/text_format/mod.rs",
            "TextFormatError",
            "`TextFormatError`",
            "TextFormatError::",
        ),
        (
            "crates/cagd-octave/src/literal/error.rs",
            "LiteralError",
            "`LiteralError`",
            "LiteralError::",
        ),
        (
            "crates/cagd-cli/src/error.rs",
            "ErrorKind",
            "`ErrorKind`",
            "ErrorKind::",
        ),
        (
            "crates/cagd-ops/src/error.rs",
            "Kind",
            "`cagd_ops::Kind`",
            "Kind::",
        ),
    ];
    let mut total = 0;
    for (file, name, heading, prefix) in enums {
        let found = variants(&read(file), name);
        assert!(found.len() >= 9, "{name}: only {found:?}");
        let part = section(&catalogue, heading);
        for v in &found {
            let text = example(part, v).unwrap_or_else(|| panic!("{name}::{v} has no section"));
            assert!(text.contains("\n```\n"), "{name}::{v}: no code block");
            assert!(
                text.contains(&format!("{prefix}{v}")),
                "{name}::{v}: the example does not name the variant"
            );
            total += 1;
        }
    }
    // The five enums as they stand; a new variant must come with its example.
    assert!(total >= 23 + 13 + 15 + 9 + 15, "variants counted: {total}");
}
