//! `cagd serve`: the web page's files on localhost — their types, compression, tags and
//! caching — a clear error when the page is not built, and a server that hostile clients
//! cannot take down or stall.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

struct Server {
    child: Child,
    address: String,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Server {
    /// Whether the process still runs.
    fn is_up(&mut self) -> bool {
        self.child.try_wait().unwrap().is_none()
    }
}

fn start(dir: &Path) -> Server {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(["serve", "--port", "0", "--dir"])
        .arg(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let address = line
        .split("http://")
        .nth(1)
        .and_then(|rest| rest.split('/').next())
        .unwrap_or_else(|| panic!("no address in {line:?}"))
        .to_string();
    assert!(address.starts_with("127.0.0.1:"), "{line}");
    Server { child, address }
}

/// An answer: the status line, the headers (names in lower case) and the body.
struct Answer {
    status: String,
    headers: Vec<(String, String)>,
    body: Vec<u8>,
}

impl Answer {
    fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }
}

/// One request with extra header lines; the connection closes after the answer, which must
/// come within `wait`.
fn ask(address: &str, method: &str, path: &str, extra: &str, wait: Duration) -> Answer {
    let mut stream = TcpStream::connect(address).unwrap();
    stream.set_read_timeout(Some(wait)).unwrap();
    write!(
        stream,
        "{method} {path} HTTP/1.1\r\nHost: {address}\r\n{extra}Connection: close\r\n\r\n"
    )
    .unwrap();
    let mut raw = Vec::new();
    stream
        .read_to_end(&mut raw)
        .unwrap_or_else(|e| panic!("{method} {path}: no whole answer within {wait:?}: {e}"));
    let split = raw
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .expect("a head");
    let head = String::from_utf8(raw[..split].to_vec()).unwrap();
    let mut lines = head.lines();
    let status = lines.next().unwrap().to_string();
    let headers = lines
        .filter_map(|l| l.split_once(':'))
        .map(|(n, v)| (n.trim().to_ascii_lowercase(), v.trim().to_string()))
        .collect();
    Answer {
        status,
        headers,
        body: raw[split + 4..].to_vec(),
    }
}

fn get(address: &str, method: &str, path: &str) -> Answer {
    ask(address, method, path, "", Duration::from_secs(10))
}

/// A page folder: index.html, a WebAssembly file, a hashed module, a large script.
fn page() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("page");
    std::fs::create_dir_all(page.join("pkg")).unwrap();
    std::fs::write(
        page.join("index.html"),
        "<!doctype html><title>cagd</title>",
    )
    .unwrap();
    std::fs::write(page.join("pkg/cagd_web_bg.wasm"), b"\0asm\x01\0\0\0").unwrap();
    let script = "export const x = [0, 1, 2, 3];\n".repeat(4000);
    std::fs::write(page.join("app.js"), &script).unwrap();
    std::fs::write(page.join("app.0123abcd.js"), &script).unwrap();
    std::fs::write(dir.path().join("secret.txt"), "outside").unwrap();
    dir
}

#[test]
fn serves_the_page_files_with_their_types_and_nothing_else() {
    let dir = page();
    let server = start(&dir.path().join("page"));

    let answer = get(&server.address, "GET", "/");
    assert!(answer.status.contains("200"), "{}", answer.status);
    assert_eq!(
        answer.header("content-type"),
        Some("text/html; charset=utf-8")
    );
    assert_eq!(answer.body, b"<!doctype html><title>cagd</title>");
    let answer = get(&server.address, "GET", "/pkg/cagd_web_bg.wasm");
    assert!(answer.status.contains("200"));
    assert_eq!(answer.header("content-type"), Some("application/wasm"));
    let answer = get(&server.address, "GET", "/app.js");
    assert_eq!(
        answer.header("content-type"),
        Some("text/javascript; charset=utf-8")
    );
    let answer = get(&server.address, "HEAD", "/index.html");
    assert!(answer.status.contains("200"));
    assert!(answer.body.is_empty(), "HEAD has no body");
    assert_eq!(answer.header("content-length"), Some("34"));
    for path in [
        "/../secret.txt",
        "/pkg/../../secret.txt",
        "/%2e%2e/secret.txt",
        "/missing.js",
    ] {
        let answer = get(&server.address, "GET", path);
        assert!(answer.status.contains("404"), "{path}: {}", answer.status);
    }
    let answer = get(&server.address, "POST", "/");
    assert!(answer.status.contains("405"));
    assert_eq!(answer.header("allow"), Some("GET, HEAD"));
}

#[test]
fn files_go_out_compressed_tagged_and_cached_by_their_names() {
    let dir = page();
    let root = dir.path().join("page");
    let script = std::fs::read(root.join("app.js")).unwrap();
    // A precompressed brotli form beside the page is sent as it is to clients that take it.
    std::fs::write(root.join("app.js.br"), b"pretend brotli").unwrap();
    let server = start(&root);
    let a = &server.address;
    let wait = Duration::from_secs(10);

    let plain = get(a, "GET", "/app.js");
    assert_eq!(plain.body, script);
    assert_eq!(plain.header("content-encoding"), None);
    assert_eq!(plain.header("cache-control"), Some("no-cache"));
    assert_eq!(plain.header("vary"), Some("Accept-Encoding"));
    let tag = plain.header("etag").expect("an ETag").to_string();

    let gz = ask(
        a,
        "GET",
        "/app.js",
        "Accept-Encoding: gzip, deflate\r\n",
        wait,
    );
    assert_eq!(gz.header("content-encoding"), Some("gzip"));
    assert!(gz.body.len() * 20 < script.len(), "{} bytes", gz.body.len());
    let mut unpacked = Vec::new();
    flate2::read::GzDecoder::new(&gz.body[..])
        .read_to_end(&mut unpacked)
        .unwrap();
    assert_eq!(unpacked, script);
    let gz_tag = gz.header("etag").unwrap().to_string();
    assert_ne!(gz_tag, tag, "each coding has its own tag");

    let br = ask(a, "GET", "/app.js", "Accept-Encoding: gzip, br\r\n", wait);
    assert_eq!(br.header("content-encoding"), Some("br"));
    assert_eq!(br.body, b"pretend brotli");

    // Revalidation: the same tag gets 304 without a body; another tag gets the file.
    let again = ask(
        a,
        "GET",
        "/app.js",
        &format!("If-None-Match: {tag}\r\n"),
        wait,
    );
    assert!(again.status.contains("304"), "{}", again.status);
    assert!(again.body.is_empty());
    assert_eq!(again.header("etag"), Some(tag.as_str()));
    let again = ask(
        a,
        "GET",
        "/app.js",
        &format!("Accept-Encoding: gzip\r\nIf-None-Match: \"old\", {gz_tag}\r\n"),
        wait,
    );
    assert!(again.status.contains("304"), "{}", again.status);
    let changed = ask(a, "GET", "/app.js", "If-None-Match: \"old\"\r\n", wait);
    assert!(changed.status.contains("200"));

    // A hashed name never changes: the browser keeps it without asking.
    let hashed = get(a, "GET", "/app.0123abcd.js");
    assert_eq!(
        hashed.header("cache-control"),
        Some("public, max-age=31536000, immutable")
    );
    // Images are not compressed again.
    std::fs::write(root.join("p.png"), vec![7u8; 5000]).unwrap();
    let png = ask(a, "GET", "/p.png", "Accept-Encoding: gzip\r\n", wait);
    assert_eq!(png.header("content-encoding"), None);
    assert_eq!(png.body.len(), 5000);
}

/// A file larger than the memory cache is streamed whole.
#[test]
fn large_files_are_streamed() {
    let dir = page();
    let root = dir.path().join("page");
    let len = (cagd_cli::serve::MAX_CACHED_FILE_BYTES + 12345) as usize;
    let data: Vec<u8> = (0..len).map(|k| (k % 251) as u8).collect();
    std::fs::write(root.join("big.bin"), &data).unwrap();
    let server = start(&root);
    let answer = get(&server.address, "GET", "/big.bin");
    assert!(answer.status.contains("200"));
    assert_eq!(
        answer.header("content-length"),
        Some(len.to_string().as_str())
    );
    assert!(answer.body == data, "the streamed file differs");
}

/// What took the server down or stalled it before: clients that reset their connections
/// right after sending a request (2,000 of them), a client that pipelines requests for a large
/// file and never reads, and one that sends half a request head. Other clients are answered
/// within a second throughout, and the server is still up at the end.
#[test]
fn hostile_clients_cannot_take_the_server_down_or_stall_it() {
    let dir = page();
    let root = dir.path().join("page");
    std::fs::write(root.join("large.bin"), vec![1u8; 16 << 20]).unwrap();
    let mut server = start(&root);
    let a = server.address.clone();
    let second = Duration::from_secs(1);

    for k in 0..2000 {
        let stream = TcpStream::connect(&a).unwrap_or_else(|e| panic!("connection {k}: {e}"));
        let mut stream = socket2::Socket::from(stream);
        let path = if k % 2 == 0 { "/" } else { "/large.bin" };
        let _ = stream.write_all(format!("GET {path} HTTP/1.1\r\nHost: x\r\n\r\n").as_bytes());
        // SO_LINGER 0: closing sends a reset instead of the orderly end.
        stream.set_linger(Some(Duration::ZERO)).unwrap();
        drop(stream);
    }
    let answer = ask(&a, "GET", "/", "", Duration::from_secs(5));
    assert!(answer.status.contains("200"), "{}", answer.status);
    assert!(server.is_up(), "the server died after the resets");

    // Pipelined requests for 16 MB each, never read: the server's writes to it block.
    let mut greedy = TcpStream::connect(&a).unwrap();
    for _ in 0..20 {
        write!(greedy, "GET /large.bin HTTP/1.1\r\nHost: x\r\n\r\n").unwrap();
    }
    // Half a request head, never finished.
    let mut slow = TcpStream::connect(&a).unwrap();
    write!(slow, "GET / HTTP/1.1\r\nHost: x\r\nX-Slow: ").unwrap();
    std::thread::sleep(Duration::from_millis(300));
    for path in ["/", "/app.js", "/pkg/cagd_web_bg.wasm"] {
        let started = Instant::now();
        let answer = ask(&a, "GET", path, "", second);
        assert!(answer.status.contains("200"), "{path}: {}", answer.status);
        assert!(
            started.elapsed() < second,
            "{path}: {:?}",
            started.elapsed()
        );
    }
    // Many clients at once are all answered.
    let clients: Vec<_> = (0..64)
        .map(|_| {
            let a = a.clone();
            std::thread::spawn(move || ask(&a, "GET", "/app.js", "", Duration::from_secs(10)))
        })
        .collect();
    for c in clients {
        assert!(c.join().unwrap().status.contains("200"));
    }
    drop((greedy, slow));
    let answer = ask(&a, "GET", "/index.html", "", second);
    assert!(answer.status.contains("200"));
    assert!(server.is_up(), "the server is no longer running");
}

#[test]
fn an_unbuilt_page_is_a_one_line_error_naming_the_build_script() {
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(["serve", "--dir"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("cagd: error: --dir "), "{stderr}");
    assert!(stderr.contains("bash web/build.sh"), "{stderr}");
    // In-process (the library, the web page), serve is refused with the same one-line form.
    let e = cagd_cli::run(["cagd", "serve"]).unwrap_err();
    assert!(e
        .to_string()
        .starts_with("serve: serving the page is done by the cagd program"));
    assert!(cagd_cli::serve_request(["cagd", "serve", "--port", "0"]).is_some());
    assert!(cagd_cli::serve_request(["cagd", "bernstein", "--degree", "1"]).is_none());
}
