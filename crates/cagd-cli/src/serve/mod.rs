//! `cagd serve`: the web page (built by `bash web/build.sh` into `web/dist/`) on localhost.
//!
//! A static file server bound to 127.0.0.1 only: `GET` and `HEAD` of the page's files, with
//! the content type by extension (`application/wasm` for the WebAssembly, which browsers need
//! to compile it while it downloads; `text/javascript` for the ES modules). Nothing outside
//! the folder is served: a path with a `..` segment, a backslash, a `%` or a NUL is refused,
//! and a file reached through a link must still lie inside the folder. The page itself
//! computes everything in the browser; the server only hands out files, so `web/dist/` may as
//! well be copied to any static host.
//!
//! **No client can take it down.** It is hyper's HTTP/1 server on a tokio runtime of
//! [`WORKER_THREADS`] threads: every connection is its own task, at most [`MAX_CONNECTIONS`]
//! at once (further clients wait in the listening queue of [`ACCEPT_QUEUE`]), so a client that pipelines
//! requests and never reads its answers, or reads a large file slowly, holds one task and
//! nobody else. A connection that makes no progress for [`STALL_TIMEOUT`] in either direction,
//! takes longer than [`HEADER_TIMEOUT`] to send a request head, or has been open for
//! [`MAX_CONNECTION_TIME`], is closed. An error on one
//! connection (a reset, a malformed request) ends that connection only, and a fault inside a
//! request handler ends that task only (the panic hook of the program exits only for its
//! command thread).
//!
//! **Caching and compression**:
//! - every answer carries a strong `ETag` (a hash of the bytes sent); a request whose
//!   `If-None-Match` names it gets `304 Not Modified` without a body;
//! - text, JavaScript, CSS, JSON, SVG and WebAssembly go out compressed when the client
//!   accepts it: brotli (`br`) from a precompressed `FILE.br` beside the file, gzip from a
//!   `FILE.gz` beside it or compressed here once and kept in memory (either sibling is used
//!   only while it is at least as new as the file); `Vary: Accept-Encoding` tells caches;
//! - a file whose name carries a content hash — a dot-separated part of 8 to 64 hexadecimal
//!   digits that is neither the first nor the last part, as in `cagd_web_bg.3f9a1c2e.wasm` or
//!   `app.0123456789abcdef.js` ([`is_hashed_name`]) — is sent with
//!   `Cache-Control: public, max-age=31536000, immutable`: a new build gives it a new name.
//!   Every other file is sent with `Cache-Control: no-cache`, so the browser asks again each
//!   time and gets a `304` while the file is unchanged.
//!
//! Files up to [`MAX_CACHED_FILE_BYTES`] are read once and kept in memory (re-read when their
//! size or modification time changes); larger ones are streamed from disk uncompressed.

use std::path::{Path, PathBuf};

use clap::Args;

use crate::{CliError, ErrorKind};

mod budget;
mod cache;
mod files;
mod http;
mod negotiate;

pub use budget::{
    ACCEPT_QUEUE, FILE_THREADS, HEADER_TIMEOUT, MAX_CACHED_FILE_BYTES, MAX_CONNECTIONS,
    MAX_CONNECTION_TIME, STALL_TIMEOUT, WORKER_THREADS,
};
pub use files::{content_type, is_hashed_name, resolve};

/// Serve the web page (every construction, in the browser) on localhost.
#[derive(Debug, Clone, Args)]
#[command(after_help = "\
Serves the page built by `bash web/build.sh` (web/dist/) on http://127.0.0.1:P/ until stopped
with Ctrl-C; the page computes in the browser, the server only hands out its files. A link
such as http://127.0.0.1:8000/#cmd=cagd%20bernstein%20--degree%203%20--t%200.5 opens the page
with that command run.

Files go out gzip-compressed when the browser accepts it (or as a precompressed FILE.br or
FILE.gz beside them), with an ETag; a name with a content hash (a dot-separated part of 8 to
64 hexadecimal digits, as in cagd_web_bg.3f9a1c2e.wasm) is cached as immutable.

Examples:
  cagd serve
  cagd serve --port 8080 --dir web/dist")]
pub struct ServeCommand {
    /// The port on 127.0.0.1 (0 picks a free one; the address is printed).
    #[arg(long, value_name = "P", default_value_t = 8000)]
    pub port: u16,
    /// The folder of the built page (default: web/dist under the current folder, else under a
    /// folder above the cagd program, as in a checkout of the repository).
    #[arg(long, value_name = "DIR", value_parser = crate::args::path_value)]
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
            format!("--dir {}", crate::escape_path(dir)),
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

/// Serves the page until the process is stopped. Prints the address on standard output first.
///
/// # Errors
/// A [`CliError`] if the page is not built ([`page_dir`]), the port cannot be bound or the
/// threads cannot be started.
pub fn serve(cmd: &ServeCommand) -> Result<(), CliError> {
    use std::io::Write;

    let root = page_dir(cmd.dir.as_deref())?;
    let page = cache::Page::new(&root).map_err(|e| {
        CliError::io(
            format!("--dir {}", crate::escape_path(&root)),
            &e,
            BUILD_HINT,
        )
    })?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(WORKER_THREADS)
        .max_blocking_threads(FILE_THREADS)
        .thread_name("cagd-serve")
        .enable_all()
        .build()
        .map_err(|e| CliError::io("serve", &e, "a system that can start threads"))?;
    let listener = runtime.block_on(async { listen(cmd.port) }).map_err(|e| {
        CliError::new(
            format!("--port {}", cmd.port),
            format!("cannot listen on 127.0.0.1:{}: {e}", cmd.port),
            "a free port, such as --port 8001 (or --port 0 for any free one)",
            ErrorKind::Io(e.kind()),
        )
    })?;
    let address = listener
        .local_addr()
        .map(|a| a.to_string())
        .unwrap_or_else(|_| format!("127.0.0.1:{}", cmd.port));
    let mut stdout = std::io::stdout().lock();
    let _ = writeln!(
        stdout,
        "cagd: serving {} at http://{address}/ (Ctrl-C to stop)",
        crate::escape_path(&root)
    );
    let _ = stdout.flush();
    drop(stdout);
    runtime.block_on(http::accept_loop(listener, std::sync::Arc::new(page)));
    Ok(())
}

/// Listens on 127.0.0.1:`port` (0: any free port) with a queue of [`ACCEPT_QUEUE`]
/// connections (in the tokio runtime that will serve them).
fn listen(port: u16) -> std::io::Result<tokio::net::TcpListener> {
    let socket = tokio::net::TcpSocket::new_v4()?;
    // As the standard library and tokio do: the port again at once after a restart.
    socket.set_reuseaddr(true)?;
    socket.bind(std::net::SocketAddr::from(([127, 0, 0, 1], port)))?;
    socket.listen(ACCEPT_QUEUE)
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
