//! The `cagd` command line: run [`cagd_cli::run`], print, write the files.
//!
//! Every input error is one line `cagd: error: <argument>: <problem>; expected <form>` on
//! standard error with exit code 2; exit code 1 is reserved for internal faults (a panic hook
//! prints one line, never a backtrace). Output files are written atomically, and only after
//! every result has been computed and standard output written, so a failing command replaces
//! no file; their temporary files are removed on SIGINT, SIGTERM and SIGHUP.

use std::io::Write;

use cagd_cli::{escape_text, CliError, Outcome};

use cagd_cli::faults::COMMAND_THREAD;

fn main() {
    cagd_cli::faults::report_faults();
    if let Err(e) = cagd_cli::temporaries::remove_on_signals() {
        let _ = writeln!(
            std::io::stderr(),
            "cagd: warning: signals: cannot watch for Ctrl-C ({}); an interrupted write may leave a .cagd-*.tmp file",
            escape_text(&e.to_string())
        );
    }
    // The command runs on a thread whose stack holds the deepest nesting the limits allow
    // (cagd_cli::limits::MAX_DEPTH_CAP levels of the recursive parsers and readers).
    let command = std::thread::Builder::new()
        .name(COMMAND_THREAD.into())
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
        // A panic has already been reported by the hook.
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

/// Prints warnings, then writes standard output and the files together (see
/// [`cagd_cli::PendingWrites::commit_with`]).
fn finish(outcome: Outcome) -> Result<(), CliError> {
    let mut stderr = std::io::stderr().lock();
    for (argument, w) in &outcome.warnings {
        let _ = writeln!(
            stderr,
            "cagd: warning: {}: {}",
            escape_text(argument),
            escape_text(&w.to_string())
        );
    }
    drop(stderr);
    outcome
        .files
        .commit_with(outcome.stdout.as_bytes(), stdout::Stdout::at_start())
}

/// Standard output as the program was given it.
mod stdout {
    use std::io::Write;

    /// Standard output, or a closed one whose every write fails.
    pub enum Stdout {
        Open(std::io::Stdout),
        Closed,
    }

    impl Stdout {
        /// Standard output as it was when the program started.
        pub fn at_start() -> Stdout {
            if closed_at_start() {
                Stdout::Closed
            } else {
                Stdout::Open(std::io::stdout())
            }
        }
    }

    impl Write for Stdout {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            match self {
                Stdout::Open(s) => s.write(buf),
                Stdout::Closed if buf.is_empty() => Ok(0),
                Stdout::Closed => Err(std::io::Error::other(
                    "it is closed (the program was started with >&-)",
                )),
            }
        }

        fn flush(&mut self) -> std::io::Result<()> {
            match self {
                Stdout::Open(s) => s.flush(),
                Stdout::Closed => Ok(()),
            }
        }
    }

    /// Whether descriptor 1 was closed when the program started (`cagd … >&-`). The Rust
    /// runtime reopens a closed standard descriptor on /dev/null before `main`, after which
    /// every write would vanish without an error; [`RECORD`] looks before it does.
    #[cfg(target_os = "linux")]
    fn closed_at_start() -> bool {
        CLOSED.load(std::sync::atomic::Ordering::Relaxed)
    }

    #[cfg(not(target_os = "linux"))]
    fn closed_at_start() -> bool {
        false
    }

    #[cfg(target_os = "linux")]
    static CLOSED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

    /// `/proc/self/fd/1` is missing exactly when descriptor 1 is closed (with /proc mounted).
    #[cfg(target_os = "linux")]
    extern "C" fn record() {
        let missing = std::fs::symlink_metadata("/proc/self/fd/1").is_err();
        let proc_mounted = std::fs::symlink_metadata("/proc/self/fd").is_ok();
        CLOSED.store(
            missing && proc_mounted,
            std::sync::atomic::Ordering::Relaxed,
        );
    }

    /// Runs [`record`] before `main`, as the C runtime runs every entry of `.init_array`
    /// (std itself reads the program's arguments this way). The attribute is `unsafe` only in
    /// that it places the entry where the loader calls it; the function is safe Rust.
    #[cfg(target_os = "linux")]
    #[used]
    #[unsafe(link_section = ".init_array")]
    static RECORD: extern "C" fn() = record;
}
