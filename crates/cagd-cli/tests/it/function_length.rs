//! No function of the command line or of the operation layer is over 60 lines (the style
//! guide's rule for the front ends and `cagd-ops`): every `fn` with a body in
//! `crates/cagd-cli/src` and `crates/cagd-ops/src`, counted from the line of its `fn` to the
//! line of its closing brace (as the style guide's `fnlen.py` counts), test code left out (a
//! `#[cfg(test)]` module, inline or in a file of its own, and a `#[cfg(test)]` function).
//! Comments, string and character literals are blanked first, so a brace inside them does not
//! count.

use std::path::{Path, PathBuf};

/// The most lines a function may take.
const LIMIT: usize = 60;

/// The source folders the rule holds for, relative to the workspace root.
const SOURCES: [&str; 2] = ["crates/cagd-cli/src", "crates/cagd-ops/src"];

/// `source` with comments, string literals (plain, raw and byte) and character literals
/// replaced by spaces, line breaks kept, so that positions and line numbers stay.
fn code_only(source: &str) -> String {
    let s: Vec<char> = source.chars().collect();
    let mut out: Vec<char> = Vec::with_capacity(s.len());
    let blank = |out: &mut Vec<char>, part: &[char]| {
        out.extend(part.iter().map(|&c| if c == '\n' { '\n' } else { ' ' }));
    };
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut i = 0;
    while i < s.len() {
        let at = |k: usize| s.get(i + k).copied().unwrap_or('\0');
        let after_ident = i > 0 && ident(s[i - 1]);
        let end = if at(0) == '/' && at(1) == '/' {
            (i..s.len()).find(|&j| s[j] == '\n').unwrap_or(s.len())
        } else if at(0) == '/' && at(1) == '*' {
            block_comment_end(&s, i)
        } else if !after_ident && (at(0) == 'r' || (at(0) == 'b' && at(1) == 'r')) {
            raw_string_end(&s, i).unwrap_or(i)
        } else if at(0) == '"' || (!after_ident && at(0) == 'b' && at(1) == '"') {
            string_end(&s, i + usize::from(at(0) == 'b'))
        } else if at(0) == '\'' {
            char_literal_end(&s, i).unwrap_or(i)
        } else {
            i
        };
        if end > i {
            blank(&mut out, &s[i..end]);
            i = end;
        } else {
            out.push(s[i]);
            i += 1;
        }
    }
    out.into_iter().collect()
}

/// The end of the (nested) block comment starting at `i`.
fn block_comment_end(s: &[char], i: usize) -> usize {
    let (mut depth, mut j) = (0, i);
    while j < s.len() {
        if s[j] == '/' && s.get(j + 1) == Some(&'*') {
            depth += 1;
            j += 2;
        } else if s[j] == '*' && s.get(j + 1) == Some(&'/') {
            depth -= 1;
            j += 2;
            if depth == 0 {
                return j;
            }
        } else {
            j += 1;
        }
    }
    s.len()
}

/// The end of the raw string (`r"…"`, `r#"…"#`, `br"…"`) starting at `i`, if one does.
fn raw_string_end(s: &[char], i: usize) -> Option<usize> {
    let mut j = i + if s[i] == 'b' { 2 } else { 1 };
    let hashes = s[j..].iter().take_while(|&&c| c == '#').count();
    j += hashes;
    if s.get(j) != Some(&'"') {
        return None;
    }
    let close: Vec<char> = std::iter::once('"')
        .chain(std::iter::repeat_n('#', hashes))
        .collect();
    (j + 1..s.len())
        .find(|&k| s[k..].starts_with(&close))
        .map(|k| k + close.len())
        .or(Some(s.len()))
}

/// The end of the string whose opening quote is at `i`.
fn string_end(s: &[char], i: usize) -> usize {
    let mut j = i + 1;
    while j < s.len() && s[j] != '"' {
        j += if s[j] == '\\' { 2 } else { 1 };
    }
    (j + 1).min(s.len())
}

/// The end of the character literal at `i` (`'a'`, `'\n'`, `'\u{1b}'`), if it is one and not
/// a lifetime.
fn char_literal_end(s: &[char], i: usize) -> Option<usize> {
    match (s.get(i + 1), s.get(i + 2)) {
        (Some('\\'), _) => (i + 2..s.len().min(i + 12))
            .find(|&k| s[k] == '\'')
            .map(|k| k + 1),
        (Some(c), Some('\'')) if *c != '\'' => Some(i + 3),
        _ => None,
    }
}

/// The position of the brace closing the one at `open`.
fn matching_brace(code: &[u8], open: usize) -> usize {
    let mut depth = 0usize;
    for (k, &c) in code.iter().enumerate().skip(open) {
        match c {
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return k;
                }
            }
            _ => {}
        }
    }
    code.len()
}

/// The byte ranges of test code in `code` (already [`code_only`]), and the names of the
/// child modules declared `#[cfg(test)] mod name;` (test files of their own).
fn test_code(code: &str) -> (Vec<(usize, usize)>, Vec<String>) {
    let bytes = code.as_bytes();
    let (mut ranges, mut files) = (Vec::new(), Vec::new());
    for (at, _) in code.match_indices("#[cfg(test)]") {
        let mut rest = &code[at + "#[cfg(test)]".len()..];
        // Other attributes between.
        while let Some(r) = rest.trim_start().strip_prefix("#[") {
            rest = &r[r.find(']').map_or(r.len(), |k| k + 1)..];
        }
        let item = rest.trim_start();
        let item = item.strip_prefix("pub(crate) ").unwrap_or(item);
        let item = item.strip_prefix("pub ").unwrap_or(item);
        let start = code.len() - item.len();
        if let Some(m) = item.strip_prefix("mod ") {
            let name: String = m
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let after = m[name.len()..].trim_start();
            if after.starts_with(';') {
                files.push(name);
            } else if after.starts_with('{') {
                let open = code.len() - after.len();
                ranges.push((at, matching_brace(bytes, open)));
            }
        } else if item.starts_with("fn ") {
            if let Some(open) = code[start..].find('{').map(|k| start + k) {
                ranges.push((at, matching_brace(bytes, open)));
            }
        }
    }
    (ranges, files)
}

/// Every function of `source` over [`LIMIT`] lines outside test code: (name, line of its
/// `fn`, lines).
fn long_functions(source: &str) -> Vec<(String, usize, usize)> {
    let code = code_only(source);
    let bytes = code.as_bytes();
    let (tests, _) = test_code(&code);
    let line_of = |pos: usize| code[..pos].matches('\n').count() + 1;
    let mut long = Vec::new();
    for (at, _) in code.match_indices("fn ") {
        let word = at == 0 || !(bytes[at - 1].is_ascii_alphanumeric() || bytes[at - 1] == b'_');
        if !word || tests.iter().any(|&(a, b)| a <= at && at <= b) {
            continue;
        }
        let name: String = code[at + 3..]
            .trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if name.is_empty() {
            continue; // a `fn(…)` pointer type
        }
        // The body: the first `{` outside parentheses and brackets, unless a `;` ends the
        // declaration first (a trait's required method).
        let mut depth = 0i32;
        let mut open = None;
        for (k, &c) in bytes.iter().enumerate().skip(at) {
            match c {
                b'(' | b'[' => depth += 1,
                b')' | b']' => depth -= 1,
                b';' if depth == 0 => break,
                b'{' if depth == 0 => {
                    open = Some(k);
                    break;
                }
                _ => {}
            }
        }
        let Some(open) = open else { continue };
        let lines = line_of(matching_brace(bytes, open)) - line_of(at) + 1;
        if lines > LIMIT {
            long.push((name, line_of(at), lines));
        }
    }
    long
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The files of `files` that a `#[cfg(test)] mod name;` declares: `name.rs` or `name/mod.rs`
/// beside the declaring file (in its folder for `mod.rs`, `lib.rs` and `main.rs`).
fn test_files(files: &[PathBuf]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for file in files {
        let source = std::fs::read_to_string(file).unwrap();
        let (_, names) = test_code(&code_only(&source));
        let stem = file.file_stem().unwrap().to_string_lossy();
        let dir = if matches!(stem.as_ref(), "mod" | "lib" | "main") {
            file.parent().unwrap().to_path_buf()
        } else {
            file.with_extension("")
        };
        for name in names {
            out.push(dir.join(format!("{name}.rs")));
            out.push(dir.join(&name).join("mod.rs"));
        }
    }
    out
}

#[test]
fn no_function_of_the_command_line_or_the_operation_layer_is_over_60_lines() {
    let root = Path::new(cagd_test_support::WORKSPACE);
    let mut files = Vec::new();
    for dir in SOURCES {
        rust_files(&root.join(dir), &mut files);
    }
    let tests = test_files(&files);
    let mut long = Vec::new();
    let mut counted = 0;
    for file in files.iter().filter(|f| !tests.contains(f)) {
        let source = std::fs::read_to_string(file).unwrap();
        counted += 1;
        for (name, line, lines) in long_functions(&source) {
            let at = file.strip_prefix(root).unwrap().display();
            long.push(format!("{at}:{line} {name}: {lines} lines"));
        }
    }
    assert!(counted > 100, "only {counted} files read");
    assert!(long.is_empty(), "over {LIMIT} lines:\n{}", long.join("\n"));
}

#[test]
fn the_length_check_finds_a_planted_long_function_and_only_it() {
    let body = |n: usize| "    let x = 1;\n".repeat(n);
    // 61 lines from `fn` to `}`: 59 of body.
    let planted = format!(
        "/// Docs are not counted.\n#[inline]\npub fn long() {{\n{}}}\n\nfn short() {{\n{}}}\n",
        body(59),
        body(58)
    );
    assert_eq!(long_functions(&planted), vec![("long".to_string(), 3, 61)]);
    // Braces in strings, characters and comments do not end a function early; a lifetime is
    // not a character.
    let tricky = format!(
        "fn tricky<'a>(s: &'a str) -> char {{\n    let _ = \"}}\"; // }}\n    /* }} */\n    let _ = r#\"}}\"#;\n{}    '}}'\n}}\n",
        body(55)
    );
    assert_eq!(long_functions(&tricky), vec![("tricky".to_string(), 1, 61)]);
    // Test code is left out: an inline test module and a test-only function.
    let test_module = format!(
        "#[cfg(test)]\nmod tests {{\n    fn helper() {{\n{}    }}\n}}\n",
        body(70)
    );
    assert!(long_functions(&test_module).is_empty());
    let test_fn = format!("#[cfg(test)]\npub fn only_in_tests() {{\n{}}}\n", body(70));
    assert!(long_functions(&test_fn).is_empty());
    // A declaration without a body is no function to count.
    assert!(long_functions("trait T {\n    fn f(&self);\n}\n").is_empty());
    // A test module in a file of its own is found from its declaration.
    let (_, files) = test_code(&code_only("#[cfg(test)]\nmod tests;\n"));
    assert_eq!(files, ["tests"]);
}
