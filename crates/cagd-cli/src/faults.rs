//! Faults of the program itself (a panic, which is a bug): reported as one line on standard
//! error, never a backtrace. Only a fault on the command thread ([`COMMAND_THREAD`]) ends the
//! program, with exit code 1; a fault on any other thread ends that thread alone, and its
//! owner decides — the page server drops that one connection, a parallel evaluation passes the
//! fault on to the command that waits for it.

use std::io::Write;

use crate::escape_text;

/// The name of the thread that runs the command (the `cagd` program names it so).
pub const COMMAND_THREAD: &str = "cagd";

/// Installs the report of faults described in the module documentation.
///
/// ```
/// cagd_cli::faults::report_faults();
/// // A fault on a worker thread ends that thread, not the program.
/// let worker = std::thread::Builder::new()
///     .name("cagd-serve".into())
///     .spawn(|| -> () { panic!("a fault in one connection") })
///     .unwrap();
/// assert!(worker.join().is_err());
/// println!("still running");
/// ```
pub fn report_faults() {
    std::panic::set_hook(Box::new(|info| {
        let _ = writeln!(std::io::stderr(), "{}", fault_line(info));
        if std::thread::current().name() == Some(COMMAND_THREAD) {
            std::process::exit(1);
        }
    }));
}

/// The one line that reports a fault: `cagd: internal error: <message> (<file>:<line>); this
/// is a bug in cagd`, the message on one line and escaped ([`escape_text`]). The web page
/// reports its faults with it too.
pub fn fault_line(info: &std::panic::PanicHookInfo<'_>) -> String {
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
    format!(
        "cagd: internal error: {}{place}; this is a bug in cagd",
        escape_text(&message)
    )
}
