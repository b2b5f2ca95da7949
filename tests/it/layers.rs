//! The module graph of each crate has no cycle.
//!
//! Every `.rs` file is a module (`a/mod.rs` is `a`). A module depends on another when its code
//! names it: a `use` path or an expression path (a call, a type, a macro's expansion written
//! out) starting with `crate::`, `super::`, `self::` or a child module's name — so a parent
//! calling `child::f()` depends on its child, and a child reaching its parent through
//! `crate::parent::g` or `super::g` depends on the parent. A path is resolved to the deepest module that exists, and through the
//! re-exports of a parent (`pub use child::Item` in `a/mod.rs` sends `a::Item` to `a/child`), so
//! that a parent re-exporting its children is not counted as depending on them. Comments and
//! string literals are ignored; `mod` declarations are not dependencies. The code of an inline
//! module (`mod tests { use super::*; }`) counts as its file's, its `super::` meaning the file. The test fails with
//! every cycle found (Tarjan's strongly connected components) and the edges inside it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

type Module = Vec<String>;

/// The crates whose module graphs must be acyclic, relative to the workspace root.
const CRATES: [&str; 8] = [
    "src",
    "crates/cagd-ops/src",
    "crates/cagd-octave/src",
    "crates/cagd-cli/src",
    "crates/cagd-octave-pkg/src",
    "crates/cagd-octave-ffi/src",
    "crates/cagd-web/src",
    "python/src",
];

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

fn module_of(root: &Path, file: &Path) -> Module {
    let rel = file.strip_prefix(root).unwrap().with_extension("");
    let mut parts: Module = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    if parts.len() == 1 && (parts[0] == "lib" || parts[0] == "main") {
        parts.clear();
    }
    parts
}

/// The source without comments and with every string and char literal emptied.
fn code_only(source: &str) -> String {
    let mut out = String::with_capacity(source.len());
    let mut chars = source.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '/' if chars.peek() == Some(&'/') => {
                for c in chars.by_ref() {
                    if c == '\n' {
                        out.push('\n');
                        break;
                    }
                }
            }
            '"' => {
                let mut escaped = false;
                for c in chars.by_ref() {
                    if escaped {
                        escaped = false;
                    } else if c == '\\' {
                        escaped = true;
                    } else if c == '"' {
                        break;
                    }
                }
                out.push_str("\"\"");
            }
            _ => out.push(c),
        }
    }
    out
}

/// `code` with the paths inside each inline module (`mod name { … }`) rewritten as seen from
/// the file: one leading `super::` of a path there names the file's module, so it becomes
/// `self::` (and `super::super::` becomes `super::`).
fn inline_modules_flattened(code: &str) -> String {
    let bytes = code.as_bytes();
    let mut out = String::with_capacity(code.len());
    let mut i = 0;
    while let Some(at) = code[i..].find("mod ").map(|k| i + k) {
        let starts_word = at == 0 || !is_ident(bytes[at - 1] as char);
        let rest = &code[at + 4..];
        let name_len = rest.find(|c: char| !is_ident(c)).unwrap_or(rest.len());
        let after = rest[name_len..].trim_start();
        if !starts_word || name_len == 0 || !after.starts_with('{') {
            out.push_str(&code[i..at + 4]);
            i = at + 4;
            continue;
        }
        let open = code.len() - after.len();
        let mut depth = 0usize;
        let mut close = code.len();
        for (k, c) in code[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        close = open + k;
                        break;
                    }
                }
                _ => {}
            }
        }
        out.push_str(&code[i..open]);
        out.push_str(&one_super_less(&code[open..close]));
        i = close;
    }
    out.push_str(&code[i..]);
    out
}

/// `block` with the first `super` of each path replaced by `self` (`super::super` by `super`).
fn one_super_less(block: &str) -> String {
    let mut out = String::with_capacity(block.len());
    let mut rest = block;
    while let Some(k) = rest.find("super::") {
        let before = &rest[..k];
        let word_start = !before.ends_with(|c: char| is_ident(c)) && !before.ends_with("::");
        out.push_str(before);
        if word_start && rest[k + 7..].starts_with("super::") {
            out.push_str("super::");
            rest = &rest[k + 14..];
        } else if word_start {
            out.push_str("self::");
            rest = &rest[k + 7..];
        } else {
            out.push_str("super::");
            rest = &rest[k + 7..];
        }
    }
    out.push_str(rest);
    out
}

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The paths of a `use` tree such as `super::{a::{B, C}, d}` (aliases dropped).
fn expand_use(prefix: &[String], tree: &str, out: &mut Vec<Vec<String>>) {
    let tree = tree.trim();
    if tree.is_empty() {
        return;
    }
    if let Some(inner) = tree.strip_prefix('{').and_then(|t| t.strip_suffix('}')) {
        let mut depth = 0;
        let mut start = 0;
        for (i, c) in inner.char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    expand_use(prefix, &inner[start..i], out);
                    start = i + 1;
                }
                _ => {}
            }
        }
        expand_use(prefix, &inner[start..], out);
        return;
    }
    if let Some(i) = tree.find("::{") {
        let mut p = prefix.to_vec();
        p.extend(tree[..i].split("::").map(|s| s.trim().to_string()));
        expand_use(&p, &tree[i + 2..], out);
        return;
    }
    let tree = tree.split(" as ").next().unwrap().trim();
    let mut p = prefix.to_vec();
    p.extend(tree.split("::").map(|s| s.trim().to_string()));
    out.push(p);
}

/// `(is pub, use tree)` of every `use` declaration, and the code with them removed.
fn uses(code: &str) -> (Vec<(bool, String)>, String) {
    let mut found = Vec::new();
    let mut rest = String::new();
    let mut i = 0;
    let bytes = code.as_bytes();
    while i < code.len() {
        let at_word = i == 0 || !is_ident(bytes[i - 1] as char);
        if at_word && code[i..].starts_with("use ") {
            let end = i + code[i..].find(';').unwrap();
            let before = rest.trim_end();
            let public = before.ends_with("pub") || before.ends_with(')');
            found.push((public, code[i + 4..end].to_string()));
            i = end + 1;
        } else {
            let c = code[i..].chars().next().unwrap();
            rest.push(c);
            i += c.len_utf8();
        }
    }
    (found, rest)
}

/// Expression paths of two or more segments: those starting with `crate::`, `super::` or
/// `self::`, and those starting with any other name, which [`absolute`] keeps when the name is
/// a child module (`bezier::decasteljau(…)` in the parent of `bezier`).
fn expression_paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let chars: Vec<char> = code.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if is_ident_start(chars[i]) && (i == 0 || !is_ident(chars[i - 1])) {
            let mut j = i;
            let mut segments = Vec::new();
            loop {
                let start = j;
                while j < chars.len() && is_ident(chars[j]) {
                    j += 1;
                }
                segments.push(chars[start..j].iter().collect::<String>());
                if j + 2 < chars.len()
                    && chars[j] == ':'
                    && chars[j + 1] == ':'
                    && is_ident_start(chars[j + 2])
                {
                    j += 2;
                } else {
                    break;
                }
            }
            if segments.len() > 1 {
                out.push(segments);
            }
            i = j.max(i + 1);
        } else {
            i += 1;
        }
    }
    out
}

struct Graph {
    modules: BTreeSet<Module>,
    reexports: BTreeMap<(Module, String), Module>,
}

impl Graph {
    fn resolve(&self, segments: &[String]) -> Option<Module> {
        let k = (0..=segments.len())
            .rev()
            .find(|&k| self.modules.contains(&segments[..k]))?;
        let mut module = segments[..k].to_vec();
        let mut k = k;
        while let Some(child) = segments
            .get(k)
            .and_then(|item| self.reexports.get(&(module.clone(), item.clone())))
        {
            module = child.clone();
            k += 1;
        }
        Some(module)
    }
}

fn absolute(from: &Module, path: &[String], modules: &BTreeSet<Module>) -> Option<Vec<String>> {
    match path[0].as_str() {
        "crate" => Some(path[1..].to_vec()),
        "super" => {
            let ups = path.iter().take_while(|s| *s == "super").count();
            let base = from.len().checked_sub(ups)?;
            let mut p = from[..base].to_vec();
            p.extend_from_slice(&path[ups..]);
            Some(p)
        }
        "self" => {
            let mut p = from.clone();
            p.extend_from_slice(&path[1..]);
            Some(p)
        }
        first => {
            let mut child = from.clone();
            child.push(first.to_string());
            modules.contains(&child).then(|| {
                let mut p = from.clone();
                p.extend_from_slice(path);
                p
            })
        }
    }
}

fn cycles(root: &Path) -> Vec<String> {
    let mut files = Vec::new();
    rust_files(root, &mut files);
    let sources: BTreeMap<Module, String> = files
        .iter()
        .map(|f| {
            (
                module_of(root, f),
                inline_modules_flattened(&code_only(&std::fs::read_to_string(f).unwrap())),
            )
        })
        .collect();
    let modules: BTreeSet<Module> = sources.keys().cloned().collect();
    let mut reexports = BTreeMap::new();
    for (module, code) in &sources {
        for (public, tree) in uses(code).0 {
            let mut paths = Vec::new();
            expand_use(&[], &tree, &mut paths);
            for p in paths.into_iter().filter(|p| public && p.len() == 2) {
                let mut child = module.clone();
                child.push(p[0].clone());
                if modules.contains(&child) {
                    reexports.insert((module.clone(), p[1].clone()), child);
                }
            }
        }
    }
    let graph = Graph { modules, reexports };
    let mut edges: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for (module, code) in &sources {
        let (declared, rest) = uses(code);
        let mut paths = Vec::new();
        for (public, tree) in declared {
            let mut expanded = Vec::new();
            expand_use(&[], &tree, &mut expanded);
            for p in expanded {
                let own_child = {
                    let mut c = module.clone();
                    c.push(p[0].clone());
                    graph.modules.contains(&c)
                };
                // A re-export of an own child is the parent's interface, not a dependency.
                if !(public && (own_child || p[0] == "self")) {
                    paths.push(p);
                }
            }
        }
        paths.extend(expression_paths(&rest));
        for p in paths {
            let Some(abs) = absolute(module, &p, &graph.modules) else {
                continue;
            };
            if let Some(target) = graph.resolve(&abs) {
                if &target != module {
                    edges.entry(module.clone()).or_default().insert(target);
                }
            }
        }
    }
    strongly_connected(&graph.modules, &edges)
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|component| {
            let set: BTreeSet<&Module> = component.iter().collect();
            let mut lines: Vec<String> = component
                .iter()
                .flat_map(|a| {
                    edges
                        .get(a)
                        .into_iter()
                        .flatten()
                        .filter(|b| set.contains(b))
                        .map(move |b| format!("  {} -> {}\n", a.join("/"), b.join("/")))
                })
                .collect();
            lines.sort();
            lines.concat()
        })
        .collect()
}

fn strongly_connected(
    nodes: &BTreeSet<Module>,
    edges: &BTreeMap<Module, BTreeSet<Module>>,
) -> Vec<Vec<Module>> {
    struct State<'a> {
        edges: &'a BTreeMap<Module, BTreeSet<Module>>,
        index: BTreeMap<Module, usize>,
        low: BTreeMap<Module, usize>,
        stack: Vec<Module>,
        on_stack: BTreeSet<Module>,
        out: Vec<Vec<Module>>,
    }
    fn visit(s: &mut State<'_>, v: &Module) {
        let i = s.index.len();
        s.index.insert(v.clone(), i);
        s.low.insert(v.clone(), i);
        s.stack.push(v.clone());
        s.on_stack.insert(v.clone());
        for w in s.edges.get(v).cloned().into_iter().flatten() {
            if !s.index.contains_key(&w) {
                visit(s, &w);
                let lw = s.low[&w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if s.on_stack.contains(&w) {
                let iw = s.index[&w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on_stack.remove(&w);
                let done = &w == v;
                component.push(w);
                if done {
                    break;
                }
            }
            s.out.push(component);
        }
    }
    let mut s = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in nodes {
        if !s.index.contains_key(v) {
            visit(&mut s, v);
        }
    }
    s.out
}

#[test]
fn no_module_depends_on_itself_through_others() {
    let mut report = String::new();
    for dir in CRATES {
        for cycle in cycles(&Path::new(cagd_test_support::WORKSPACE).join(dir)) {
            report.push_str(&format!("cycle in {dir}:\n{cycle}"));
        }
    }
    assert!(report.is_empty(), "{report}");
}

#[test]
fn the_checker_finds_a_cycle() {
    let dir = cagd_test_support::TempDir::new("layers");
    let root = dir.path();
    std::fs::create_dir_all(root.join("a")).unwrap();
    std::fs::write(root.join("lib.rs"), "pub mod a;\npub mod b;\n").unwrap();
    // A parent re-exporting its child is not a dependency ...
    std::fs::write(root.join("a/mod.rs"), "mod x;\npub use x::X;\n").unwrap();
    // ... but a child naming a sibling module through the parent is.
    std::fs::write(
        root.join("a/x.rs"),
        "// crate::b::Y in a comment does not count\npub struct X(crate::b::Y);\n",
    )
    .unwrap();
    std::fs::write(root.join("b.rs"), "use crate::a::X;\npub struct Y;\n").unwrap();
    let found = cycles(root);
    assert_eq!(found, ["  a/x -> b\n  b -> a/x\n"], "{found:?}");
    std::fs::write(root.join("b.rs"), "pub struct Y;\n").unwrap();
    assert!(cycles(root).is_empty());
}

#[test]
fn the_checker_finds_a_parent_child_cycle() {
    let dir = cagd_test_support::TempDir::new("layers-parent");
    let root = dir.path();
    std::fs::create_dir_all(root.join("app")).unwrap();
    std::fs::write(root.join("lib.rs"), "pub mod app;\n").unwrap();
    // The parent calls into its child by the child's name (no `use`, no `crate::`) ...
    std::fs::write(
        root.join("app/mod.rs"),
        "mod bezier;\npub fn run() { bezier::decasteljau() }\npub fn prepare() {}\n",
    )
    .unwrap();
    // ... and the child reaches back up, through `crate::` or through `super::`.
    for back in ["crate::app::prepare()", "super::prepare()"] {
        std::fs::write(
            root.join("app/bezier.rs"),
            format!("pub fn decasteljau() {{ {back} }}\n"),
        )
        .unwrap();
        let found = cycles(root);
        assert_eq!(
            found,
            ["  app -> app/bezier\n  app/bezier -> app\n"],
            "{back}: {found:?}"
        );
    }
    // A child that takes what it needs from a sibling, not from the parent, is fine.
    std::fs::write(root.join("app/cx.rs"), "pub fn prepare() {}\n").unwrap();
    std::fs::write(
        root.join("app/mod.rs"),
        "mod bezier;\nmod cx;\npub fn run() { bezier::decasteljau() }\n",
    )
    .unwrap();
    std::fs::write(
        root.join("app/bezier.rs"),
        "pub fn decasteljau() { super::cx::prepare() }\n",
    )
    .unwrap();
    assert!(cycles(root).is_empty(), "{:?}", cycles(root));
    // A test module inside the child, taking the child's items with `super::*`, is the child.
    std::fs::write(
        root.join("app/bezier.rs"),
        "pub fn decasteljau() { super::cx::prepare() }\n\
         #[cfg(test)]\nmod tests {\n    use super::*;\n    fn t() { decasteljau() }\n}\n",
    )
    .unwrap();
    assert!(cycles(root).is_empty(), "{:?}", cycles(root));
    // ... but `super::super::prepare()` there is the parent again.
    std::fs::write(
        root.join("app/bezier.rs"),
        "pub fn decasteljau() {}\nmod tests {\n    fn t() { super::super::prepare() }\n}\n",
    )
    .unwrap();
    std::fs::write(
        root.join("app/mod.rs"),
        "mod bezier;\npub fn run() { bezier::decasteljau() }\npub fn prepare() {}\n",
    )
    .unwrap();
    assert_eq!(cycles(root), ["  app -> app/bezier\n  app/bezier -> app\n"]);
}
