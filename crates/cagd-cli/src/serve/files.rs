//! Which file a request names, its content type, and how long a browser may keep it.

use std::path::{Path, PathBuf};

/// `Cache-Control` of a file whose name carries a content hash ([`is_hashed_name`]).
pub(super) const IMMUTABLE: &str = "public, max-age=31536000, immutable";
/// `Cache-Control` of every other file: the browser revalidates it (and gets a 304).
pub(super) const REVALIDATE: &str = "no-cache";

/// The content type of a file of the page, by extension.
pub fn content_type(path: &Path) -> &'static str {
    match extension(path).as_deref() {
        Some("html") => "text/html; charset=utf-8",
        Some("js" | "mjs") => "text/javascript; charset=utf-8",
        Some("css") => "text/css; charset=utf-8",
        Some("wasm") => "application/wasm",
        Some("svg") => "image/svg+xml",
        Some("png") => "image/png",
        Some("json" | "map" | "webmanifest") => "application/json",
        Some("txt" | "md" | "m") => "text/plain; charset=utf-8",
        Some("ico") => "image/x-icon",
        _ => "application/octet-stream",
    }
}

fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// Whether a file of this type gains from compression (images in PNG are compressed already).
pub(super) fn compressible(path: &Path) -> bool {
    matches!(
        extension(path).as_deref(),
        Some("html" | "js" | "mjs" | "css" | "wasm" | "svg" | "json" | "map" | "txt" | "md" | "m")
    )
}

/// Whether the file name carries a content hash, so that its contents never change under that
/// name: one of its dot-separated parts, neither the first nor the last, is 8 to 64
/// hexadecimal digits (`cagd_web_bg.3f9a1c2e.wasm`, `app.0123456789abcdef.js`; not
/// `index.html`, `cagd_web_bg.wasm` or `deadbeef.js`).
///
/// ```
/// use cagd_cli::serve::is_hashed_name;
/// assert!(is_hashed_name("cagd_web_bg.3f9a1c2e.wasm"));
/// assert!(is_hashed_name("app.0123456789ABCDEF.min.js"));
/// assert!(!is_hashed_name("cagd_web_bg.wasm"));
/// assert!(!is_hashed_name("deadbeef.js"));
/// assert!(!is_hashed_name("app.1234567.js"));
/// ```
pub fn is_hashed_name(name: &str) -> bool {
    let parts: Vec<&str> = name.split('.').collect();
    parts.len() >= 3
        && parts[1..parts.len() - 1]
            .iter()
            .any(|p| (8..=64).contains(&p.len()) && p.bytes().all(|b| b.is_ascii_hexdigit()))
}

/// The file under `root` that the request path `url` names (`/` and folders mean their
/// `index.html`), or `None` if it is outside the folder, malformed or missing.
pub fn resolve(root: &Path, url: &str) -> Option<PathBuf> {
    let real_root = root.canonicalize().ok()?;
    resolve_in(&real_root, url)
}

/// [`resolve`] under a root that is already canonical.
pub(super) fn resolve_in(real_root: &Path, url: &str) -> Option<PathBuf> {
    let path = url.split(['?', '#']).next().unwrap_or("");
    if !path.starts_with('/') || path.contains(['\\', '\0', '%']) {
        return None;
    }
    let mut file = real_root.to_path_buf();
    for segment in path.split('/').filter(|s| !s.is_empty()) {
        if segment == "." || segment == ".." {
            return None;
        }
        file.push(segment);
    }
    if file.is_dir() {
        file.push("index.html");
    }
    let real = file.canonicalize().ok()?;
    (real.starts_with(real_root) && real.is_file()).then_some(real)
}

/// The `Cache-Control` of the file at `path` ([`IMMUTABLE`] for hashed names).
pub(super) fn cache_control(path: &Path) -> &'static str {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
    if is_hashed_name(name) {
        IMMUTABLE
    } else {
        REVALIDATE
    }
}
