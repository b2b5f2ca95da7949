//! Resource limits on the command line: defaults, environment variables, flags (the flag
//! wins), each refusal a one-line error with exit code 2 that names the setting.

use assert_cmd::Command;

fn cagd() -> Command {
    let mut c = Command::cargo_bin("cagd").unwrap();
    for (_, var, _) in cagd::limits::SETTINGS {
        c.env_remove(var);
    }
    c
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn environment_and_flags_set_the_limits() {
    let surface = ["surface", "[u; v; u.*v]", "--n", "4"];
    // Default: 16 points are fine.
    assert!(cagd().args(surface).output().unwrap().status.success());
    // The environment lowers the limit.
    let out = cagd()
        .env("CAGD_MAX_GRID_POINTS", "10")
        .args(surface)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let e = stderr(&out);
    assert_eq!(e.lines().count(), 1);
    assert!(
        e.contains("16 exceeds the limit of 10")
            && e.contains("--max-grid-points")
            && e.contains("CAGD_MAX_GRID_POINTS"),
        "{e}"
    );
    // The flag wins over the environment, before or after the subcommand.
    let out = cagd()
        .env("CAGD_MAX_GRID_POINTS", "10")
        .args(surface)
        .args(["--max-grid-points", "16"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    let out = cagd()
        .args(["--max-degree", "2", "decasteljau", "[0 1 2 3]"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("degree: 3 exceeds the limit of 2"));
    // A malformed variable is an error naming it.
    let out = cagd()
        .env("CAGD_MAX_DEPTH", "deep")
        .args(surface)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("CAGD_MAX_DEPTH"), "{}", stderr(&out));
}

#[test]
fn parser_limits_follow_the_settings() {
    let deep = format!("[u; {}u{}]", "(".repeat(10), ")".repeat(10));
    assert!(cagd()
        .args(["curve", &deep, "--n", "2"])
        .output()
        .unwrap()
        .status
        .success());
    let out = cagd()
        .args(["curve", &deep, "--n", "2", "--max-depth", "5"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("nested more than 5 levels"),
        "{}",
        stderr(&out)
    );
    let out = cagd()
        .env("CAGD_MAX_ELEMENTS", "100")
        .args(["decasteljau", "[0 1]", "--t", "0:0.001:1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("limit of 100"), "{}", stderr(&out));
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.txt");
    std::fs::write(&big, "0 1\n".repeat(1000)).unwrap();
    let out = cagd()
        .args([
            "decasteljau",
            big.to_str().unwrap(),
            "--max-input-bytes",
            "1000",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("larger than 1000 bytes"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_mask_system_is_refused_before_it_is_allocated() {
    let net = format!(
        "[{}]",
        (0..60)
            .map(|i| (0..60 * 3)
                .map(|j| ((i + j) % 7).to_string())
                .collect::<Vec<_>>()
                .join(" "))
            .collect::<Vec<_>>()
            .join("; ")
    );
    let out = cagd()
        .args([
            "discrete-coons",
            &net,
            "--mask=0,0.25",
            "--max-system-entries",
            "1000",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("--max-system-entries"),
        "{}",
        stderr(&out)
    );
}
