//! Atomic output files: a file either appears complete or not at all, and a failed command
//! leaves every file as it was.
//!
//! Every file is first written to a temporary file `.cagd-XXXXXX.tmp` beside its destination
//! and then renamed over it (a rename within one folder is atomic on POSIX systems). The
//! destination follows the shell's `>` (see [`crate::outputs`]): a symbolic link is followed
//! and its target replaced (the link stays), a read-only or irregular file is refused, and the
//! new file keeps the permissions (and, where allowed, the owner) of the file it replaces.
//! [`PendingWrites`] extends this to all the outputs of a command, standard output included:
//! every file is staged, then standard output is written, and only when all of that succeeded
//! is any file renamed into place — so a result that cannot be printed (`> /dev/full`, a
//! closed standard output) replaces no file. A temporary file is removed on any error and,
//! in the `cagd` program, on SIGINT, SIGTERM and SIGHUP ([`crate::temporaries`]).

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::outputs::{destination, directory_of, refusal, OUTPUT_FORM};
use crate::temporaries::{Renaming, Temporary};
use crate::{CliError, ErrorKind};

/// Writes `bytes` into a temporary file beside `target`, with the permissions and owner of
/// the file it replaces (a new file gets 0666 less the umask, as `>` gives it).
fn stage(target: &Path, bytes: &[u8]) -> std::io::Result<Temporary> {
    let existing = std::fs::metadata(target).ok();
    let mut tmp = Temporary::new_in(directory_of(target), ".cagd-", |p| {
        let mut options = std::fs::OpenOptions::new();
        options.write(true).create_new(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::mode(&mut options, 0o666);
        options.open(p)
    })?;
    if let Some(meta) = &existing {
        tmp.file().set_permissions(meta.permissions())?;
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            // Only root may give a file away; anyone else's file stays theirs or fails here.
            let _ = std::os::unix::fs::fchown(tmp.file(), Some(meta.uid()), Some(meta.gid()));
        }
    }
    tmp.file().write_all(bytes)?;
    tmp.file().sync_all()?;
    Ok(tmp)
}

/// Writes `bytes` to `path` atomically (temporary file beside the destination, then rename),
/// following a symbolic link as `>` does.
///
/// ```
/// let dir = tempfile::tempdir().unwrap();
/// let path = dir.path().join("out.txt");
/// cagd_cli::write_atomic(&path, b"hello\n").unwrap();
/// assert_eq!(std::fs::read(&path).unwrap(), b"hello\n");
/// // A missing directory is an error and leaves nothing behind.
/// assert!(cagd_cli::write_atomic(&dir.path().join("no/such/dir/x"), b"x").is_err());
/// ```
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let target = destination(path)?;
    let tmp = stage(&target, bytes)?;
    Renaming::start()?.persist(tmp, &target)
}

/// Files to be written together: nothing is written until [`PendingWrites::commit`], which
/// stages every file before renaming any.
#[derive(Debug, Default)]
pub struct PendingWrites {
    dirs: Vec<(String, PathBuf)>,
    files: Vec<(String, PathBuf, Vec<u8>)>,
}

impl PendingWrites {
    /// No files yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a file; `argument` names the option it came from, for error messages. The path
    /// `-` is standard output, written after the files are staged and before they are renamed.
    pub fn add(&mut self, argument: impl Into<String>, path: impl Into<PathBuf>, bytes: Vec<u8>) {
        self.files.push((argument.into(), path.into(), bytes));
    }

    /// Adds a folder to create (with its parents) before the files are staged.
    pub fn create_dir(&mut self, argument: impl Into<String>, path: impl Into<PathBuf>) {
        self.dirs.push((argument.into(), path.into()));
    }

    /// Refuses, before any work, a folder that cannot be created: the same error as when the
    /// files are committed ([`PendingWrites::commit_with`]). The folders it had to create are
    /// removed again, so that nothing is left when the command fails later. In WebAssembly
    /// (the page, whose files stay in memory; no file system) there is nothing to check.
    ///
    /// ```
    /// use cagd_cli::PendingWrites;
    /// let e = PendingWrites::check_dir("--out /proc/x", std::path::Path::new("/proc/x/y")).unwrap_err();
    /// assert!(e.to_string().starts_with("--out /proc/x: "), "{e}");
    /// let dir = tempfile::tempdir().unwrap();
    /// PendingWrites::check_dir("--out", &dir.path().join("a/b")).unwrap();
    /// assert!(!dir.path().join("a").exists());
    /// ```
    pub fn check_dir(argument: &str, dir: &Path) -> Result<(), CliError> {
        if cfg!(target_arch = "wasm32") {
            return Ok(());
        }
        let probe = PendingWrites {
            dirs: vec![(argument.to_string(), dir.to_path_buf())],
            files: Vec::new(),
        };
        for created in probe.create_dirs()?.iter().rev() {
            let _ = std::fs::remove_dir(created);
        }
        Ok(())
    }

    /// Whether no file was added.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// The paths of the files to be written, in the order added.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().map(|(_, p, _)| p.as_path())
    }

    /// The contents staged for `path`, if a file was added there.
    pub fn contents(&self, path: &Path) -> Option<&[u8]> {
        self.files
            .iter()
            .find(|(_, p, _)| p == path)
            .map(|(_, _, b)| b.as_slice())
    }

    /// Writes every file (and the `-` ones to this process's standard output).
    ///
    /// # Errors
    /// As [`PendingWrites::commit_with`].
    pub fn commit(self) -> Result<(), CliError> {
        self.commit_with(&[], std::io::stdout())
    }

    /// Writes every file, and `text` after the `-` files to `stdout`: all files are staged,
    /// then standard output is written and flushed, then the files are renamed into place.
    /// A broken pipe on standard output (a reader that stopped early, as `head` does) is not
    /// an error.
    ///
    /// # Errors
    /// A [`CliError`] naming the argument and the path when a file may not or cannot be
    /// written, or `standard output` when it cannot be written (closed, full): then no file
    /// was replaced, no temporary file is left, and a folder created for the files is removed
    /// again if it stayed empty.
    pub fn commit_with(self, text: &[u8], stdout: impl Write) -> Result<(), CliError> {
        let created = self.create_dirs()?;
        let result = self.write_all(text, stdout);
        if result.is_err() {
            for dir in created.iter().rev() {
                let _ = std::fs::remove_dir(dir);
            }
        }
        result
    }

    /// Creates the folders; returns the ones that did not exist, outermost first.
    fn create_dirs(&self) -> Result<Vec<PathBuf>, CliError> {
        let mut created = Vec::new();
        for (argument, dir) in &self.dirs {
            let missing: Vec<PathBuf> = dir
                .ancestors()
                .filter(|a| !a.as_os_str().is_empty() && !a.exists())
                .map(Path::to_path_buf)
                .collect();
            std::fs::create_dir_all(dir).map_err(|e| {
                CliError::io(
                    argument.as_str(),
                    &e,
                    "a folder that can be created and written",
                )
            })?;
            created.extend(missing.into_iter().rev());
        }
        Ok(created)
    }

    fn write_all(&self, text: &[u8], mut stdout: impl Write) -> Result<(), CliError> {
        let mut staged = Vec::with_capacity(self.files.len());
        let mut to_stdout = Vec::new();
        for (argument, path, bytes) in &self.files {
            if path.as_os_str() == "-" {
                to_stdout.push((argument.as_str(), bytes.as_slice()));
                continue;
            }
            // Checked again now: the file system may have changed since the arguments were.
            if let Some((problem, kind)) = refusal(path) {
                return Err(CliError::file(argument, path, problem, OUTPUT_FORM, kind));
            }
            let target = destination(path).map_err(|e| write_error(argument, path, &e))?;
            let tmp = stage(&target, bytes).map_err(|e| write_error(argument, path, &e))?;
            staged.push((argument, path, target, tmp));
        }
        to_stdout.push(("standard output", text));
        for (argument, bytes) in to_stdout {
            match stdout.write_all(bytes).and_then(|()| stdout.flush()) {
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => break,
                Err(e) => return Err(stdout_error(argument, &e)),
                Ok(()) => {}
            }
        }
        let mut renaming = Renaming::start()
            .map_err(|e| CliError::io("cagd", &e, "the command to run to its end"))?;
        // Renames can still fail (a race, a file system that refuses): undo the ones done, so
        // that the files are all written or none is.
        let mut done: Vec<(PathBuf, Option<Temporary>)> = Vec::new();
        for (argument, path, target, tmp) in staged {
            let backup = backup_of(&target);
            if let Err(e) = renaming.persist(tmp, &target) {
                roll_back(&mut renaming, done);
                return Err(write_error(argument, path, &e));
            }
            done.push((target, backup));
        }
        Ok(())
    }
}

/// A hard link to the file at `target` under a temporary name, if there is one, so that a
/// replaced file can be restored.
fn backup_of(target: &Path) -> Option<Temporary> {
    if !target.is_file() {
        return None;
    }
    Temporary::new_in(directory_of(target), ".cagd-backup-", |p| {
        std::fs::hard_link(target, p)?;
        std::fs::File::open(p)
    })
    .ok()
}

/// Restores the files replaced and removes the files created by the renames in `done`.
fn roll_back(renaming: &mut Renaming, done: Vec<(PathBuf, Option<Temporary>)>) {
    for (target, backup) in done.into_iter().rev() {
        match backup {
            Some(b) => {
                let _ = renaming.persist(b, &target);
            }
            None => {
                let _ = std::fs::remove_file(&target);
            }
        }
    }
}

fn write_error(argument: &str, path: &Path, e: &std::io::Error) -> CliError {
    let (problem, kind) = crate::error::io_problem(e);
    CliError::file(
        argument,
        path,
        format!("cannot write: {problem}"),
        "a writable path in an existing directory",
        ErrorKind::Io(kind),
    )
}

/// A failed write to standard output: no file is replaced.
fn stdout_error(argument: &str, e: &std::io::Error) -> CliError {
    let (problem, kind) = crate::error::io_problem(e);
    let argument = if argument == "standard output" {
        argument.to_string()
    } else {
        format!("{argument} - (standard output)")
    };
    CliError::new(
        argument,
        format!("cannot write: {problem}; no output file was replaced"),
        "a standard output that can be written (not closed, not full), or -o FILE",
        ErrorKind::Io(kind),
    )
}
