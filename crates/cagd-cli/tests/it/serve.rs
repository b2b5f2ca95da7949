//! `cagd serve`: the web page's files on localhost, and a clear error when the page is not
//! built.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};

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

fn start(dir: &std::path::Path) -> Server {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(["serve", "--port", "0", "--dir"])
        .arg(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
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

/// One request: (status line, headers and body as text).
fn get(address: &str, method: &str, path: &str) -> (String, String) {
    let mut stream = TcpStream::connect(address).unwrap();
    write!(
        stream,
        "{method} {path} HTTP/1.1\r\nHost: {address}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut answer = String::new();
    stream.read_to_string(&mut answer).unwrap();
    let status = answer.lines().next().unwrap_or_default().to_string();
    (status, answer)
}

#[test]
fn serves_the_page_files_with_their_types_and_nothing_else() {
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("page");
    std::fs::create_dir_all(page.join("pkg")).unwrap();
    std::fs::write(
        page.join("index.html"),
        "<!doctype html><title>cagd</title>",
    )
    .unwrap();
    std::fs::write(page.join("pkg/cagd_web_bg.wasm"), b"\0asm\x01\0\0\0").unwrap();
    std::fs::write(dir.path().join("secret.txt"), "outside").unwrap();
    let server = start(&page);

    let (status, answer) = get(&server.address, "GET", "/");
    assert!(status.contains("200"), "{answer}");
    assert!(answer.contains("Content-Type: text/html; charset=utf-8"));
    assert!(answer.ends_with("<!doctype html><title>cagd</title>"));
    let (status, answer) = get(&server.address, "GET", "/pkg/cagd_web_bg.wasm");
    assert!(status.contains("200"));
    assert!(
        answer.contains("Content-Type: application/wasm"),
        "{answer}"
    );
    let (status, answer) = get(&server.address, "HEAD", "/index.html");
    assert!(status.contains("200"));
    assert!(!answer.contains("<title>"), "HEAD has no body");
    for path in ["/../secret.txt", "/pkg/../../secret.txt", "/missing.js"] {
        let (status, _) = get(&server.address, "GET", path);
        assert!(status.contains("404"), "{path}: {status}");
    }
    let (status, _) = get(&server.address, "POST", "/");
    assert!(status.contains("405"));
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
