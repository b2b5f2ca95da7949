//! The `cagd` command line: run [`cagd_cli::run`], print, write the files.
//!
//! Every input error is one line `cagd: error: <argument>: <problem>; expected <form>` on
//! standard error with exit code 2; exit code 1 is reserved for internal faults (a panic hook
//! prints one line, never a backtrace). Output files are written atomically, and only after
//! every result has been computed, so a failing command leaves no file behind.

use std::io::Write;

use cagd_cli::{CliError, Outcome};

fn main() {
    std::panic::set_hook(Box::new(|info| {
        let payload = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unexpected fault".to_string());
        let place = info
            .location()
            .map(|l| format!(" ({}:{})", l.file(), l.line()))
            .unwrap_or_default();
        let message = payload.split_whitespace().collect::<Vec<_>>().join(" ");
        let _ = writeln!(
            std::io::stderr(),
            "cagd: internal error: {message}{place}; this is a bug in cagd"
        );
        std::process::exit(1);
    }));
    // The command runs on a thread whose stack holds the deepest nesting the limits allow
    // (cagd_cli::limits::MAX_DEPTH_CAP levels of the recursive parsers and readers).
    let command = std::thread::Builder::new()
        .name("cagd".into())
        .stack_size(cagd_cli::limits::COMMAND_STACK_BYTES)
        .spawn(|| {
            let args: Vec<_> = std::env::args_os().collect();
            let result = match cagd_cli::serve_request(args.iter().cloned()) {
                Some(serve) => cagd_cli::serve::serve(&serve),
                None => cagd_cli::run(args).and_then(finish),
            };
            match result {
                Ok(()) => 0,
                Err(e) => {
                    let _ = writeln!(std::io::stderr(), "cagd: error: {e}");
                    e.exit_code()
                }
            }
        });
    let code = match command.map(|c| c.join()) {
        Ok(Ok(code)) => code,
        // A panic has already been reported (and exited) by the hook.
        Ok(Err(_)) => 1,
        Err(e) => {
            let _ = writeln!(
                std::io::stderr(),
                "cagd: internal error: cannot start the command thread: {e}"
            );
            1
        }
    };
    std::process::exit(code);
}

/// Prints warnings, writes the files, then prints the result.
fn finish(outcome: Outcome) -> Result<(), CliError> {
    let mut stderr = std::io::stderr().lock();
    for (argument, w) in &outcome.warnings {
        let _ = writeln!(stderr, "cagd: warning: {argument}: {w}");
    }
    drop(stderr);
    outcome.files.commit()?;
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(outcome.stdout.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(CliError::io(
            "standard output",
            &e,
            "a writable standard output",
        )),
        _ => Ok(()),
    }
}
