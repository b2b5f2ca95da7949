//! `cagd serve`: the web page (built by `bash web/build.sh` into `web/dist/`) on localhost.
//!
//! A static file server bound to 127.0.0.1 only: `GET` and `HEAD` of the page's files, with
//! the content type by extension (`application/wasm` for the WebAssembly, which browsers need
//! to compile it while it downloads). Nothing outside the folder is served: a path with a `..`
//! segment, a backslash or a NUL is refused, and a file reached through a link must still lie
//! inside the folder. The page itself computes everything in the browser; the server only
//! hands out files, so `web/dist/` may as well be copied to any static host.

use std::path::{Path, PathBuf};

use clap::Args;

use crate::{CliError, ErrorKind};

/// Serve the web page (every construction, in the browser) on localhost.
#[derive(Debug, Clone, Args)]
#[command(after_help = "\
Serves the page built by `bash web/build.sh` (web/dist/) on http://127.0.0.1:P/ until stopped
with Ctrl-C; the page computes in the browser, the server only hands out its files. A link
such as http://127.0.0.1:8000/#cmd=cagd%20bernstein%20--degree%203%20--t%200.5 opens the page
with that command run.

Examples:
  cagd serve
  cagd serve --port 8080 --dir web/dist")]
pub struct ServeCommand {
    /// The port on 127.0.0.1 (0 picks a free one; the address is printed).
    #[arg(long, value_name = "P", default_value_t = 8000)]
    pub port: u16,
    /// The folder of the built page (default: web/dist under the current folder, else under a
    /// folder above the cagd program, as in a checkout of the repository).
    #[arg(long, value_name = "DIR")]
    pub dir: Option<PathBuf>,
}

/// Where the built page is looked for when `--dir` is not given, relative to a base folder.
const DEFAULT_DIR: &str = "web/dist";

const BUILD_HINT: &str = "the page built first with `bash web/build.sh`, or --dir naming a folder that holds its index.html";

/// The folder to serve: `--dir`, or `web/dist` under the current folder or under a folder
/// above the program (`target/debug/cagd` in a checkout finds the checkout's `web/dist`).
///
/// # Errors
/// A one-line [`CliError`] telling to run `bash web/build.sh` when no `index.html` is found.
pub fn page_dir(dir: Option<&Path>) -> Result<PathBuf, CliError> {
    if let Some(dir) = dir {
        if dir.join("index.html").is_file() {
            return Ok(dir.to_path_buf());
        }
        return Err(CliError::new(
            format!("--dir {}", dir.display()),
            "no index.html in this folder (the page is not built there)",
            BUILD_HINT,
            ErrorKind::Usage,
        ));
    }
    let mut bases: Vec<PathBuf> = vec![PathBuf::from(".")];
    if let Ok(exe) = std::env::current_exe() {
        bases.extend(exe.ancestors().skip(1).map(Path::to_path_buf));
    }
    bases
        .iter()
        .map(|b| b.join(DEFAULT_DIR))
        .find(|d| d.join("index.html").is_file())
        .ok_or_else(|| {
            CliError::new(
                "serve",
                format!("no built page in {DEFAULT_DIR} (here or above the cagd program)"),
                BUILD_HINT,
                ErrorKind::Usage,
            )
        })
}

/// The content type of a file of the page, by extension.
pub fn content_type(path: &Path) -> &'static str {
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("html") => "text/html; charset=utf-8",
        Some("js" | "mjs") => "text/javascript; charset=utf-8",
        Some("css") => "text/css; charset=utf-8",
        Some("wasm") => "application/wasm",
        Some("svg") => "image/svg+xml",
        Some("png") => "image/png",
        Some("json" | "map") => "application/json",
        Some("txt" | "md" | "m") => "text/plain; charset=utf-8",
        Some("ico") => "image/x-icon",
        _ => "application/octet-stream",
    }
}

/// The file under `root` that the request path `url` names (`/` and folders mean their
/// `index.html`), or `None` if it is outside the folder, malformed or missing.
pub fn resolve(root: &Path, url: &str) -> Option<PathBuf> {
    let path = url.split(['?', '#']).next().unwrap_or("");
    if !path.starts_with('/') || path.contains(['\\', '\0', '%']) {
        return None;
    }
    let mut file = root.to_path_buf();
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
    let real_root = root.canonicalize().ok()?;
    (real.starts_with(&real_root) && real.is_file()).then_some(real)
}

/// Serves the page until the process is stopped. Prints the address on standard output first.
///
/// # Errors
/// A [`CliError`] if the page is not built ([`page_dir`]) or the port cannot be bound.
pub fn serve(cmd: &ServeCommand) -> Result<(), CliError> {
    use std::io::Write;

    let root = page_dir(cmd.dir.as_deref())?;
    let server = tiny_http::Server::http(("127.0.0.1", cmd.port)).map_err(|e| {
        CliError::new(
            format!("--port {}", cmd.port),
            format!("cannot listen on 127.0.0.1:{}: {e}", cmd.port),
            "a free port, such as --port 8001 (or --port 0 for any free one)",
            ErrorKind::Io(std::io::ErrorKind::AddrInUse),
        )
    })?;
    let address = server
        .server_addr()
        .to_ip()
        .map(|a| a.to_string())
        .unwrap_or_else(|| format!("127.0.0.1:{}", cmd.port));
    let mut stdout = std::io::stdout().lock();
    let _ = writeln!(
        stdout,
        "cagd: serving {} at http://{address}/ (Ctrl-C to stop)",
        root.display()
    );
    let _ = stdout.flush();
    drop(stdout);
    for request in server.incoming_requests() {
        respond(&root, request);
    }
    Ok(())
}

fn header(name: &str, value: &str) -> tiny_http::Header {
    tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes())
        .expect("header names and values are ASCII")
}

fn respond(root: &Path, request: tiny_http::Request) {
    use tiny_http::{Method, Response};

    if !matches!(request.method(), Method::Get | Method::Head) {
        let _ = request.respond(
            Response::from_string("only GET and HEAD\n")
                .with_status_code(405)
                .with_header(header("Allow", "GET, HEAD")),
        );
        return;
    }
    let Some(file) = resolve(root, request.url()) else {
        let _ = request.respond(
            Response::from_string("not found\n")
                .with_status_code(404)
                .with_header(header("Content-Type", "text/plain; charset=utf-8")),
        );
        return;
    };
    let answer = match std::fs::read(&file) {
        // tiny_http leaves the body out of the answer to a HEAD request.
        Ok(bytes) => Response::from_data(bytes)
            .with_header(header("Content-Type", content_type(&file)))
            .with_header(header("Cache-Control", "no-cache"))
            .with_header(header("X-Content-Type-Options", "nosniff")),
        Err(_) => Response::from_string("cannot read\n").with_status_code(500),
    };
    // A client that hangs up mid-answer is its own business.
    let _ = request.respond(answer);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_stay_inside_the_folder() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir(dir.path().join("js")).unwrap();
        std::fs::write(dir.path().join("index.html"), "<!doctype html>").unwrap();
        std::fs::write(dir.path().join("js/app.js"), "").unwrap();
        let root = dir.path();
        let index = root.join("index.html").canonicalize().unwrap();
        assert_eq!(resolve(root, "/"), Some(index.clone()));
        assert_eq!(resolve(root, "/index.html?x=1#cmd=a"), Some(index));
        assert!(resolve(root, "/js/app.js").is_some());
        for bad in [
            "/../etc/passwd",
            "/js/../../x",
            "/js\\app.js",
            "/%2e%2e/x",
            "",
            "/nope.js",
        ] {
            assert_eq!(resolve(root, bad), None, "{bad}");
        }
        assert_eq!(
            content_type(Path::new("a/cagd_web_bg.wasm")),
            "application/wasm"
        );
        assert!(page_dir(Some(&root.join("js"))).is_err());
        assert_eq!(page_dir(Some(root)).unwrap(), root);
    }
}
