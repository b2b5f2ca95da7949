//! Atomic output files: a file either appears complete or not at all.
//!
//! Every file is first written to a temporary file in its target directory and then renamed
//! over the target (a rename within one directory is atomic on POSIX systems). A failure
//! before the rename removes the temporary file, so no partial output is ever left behind.
//! [`PendingWrites`] extends this to several files: all of them are staged before the first
//! rename, so an error while writing any of them leaves none.

use std::io::Write;
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;

/// The directory a file will be written into (`.` for a bare file name).
fn directory_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Writes `bytes` into a temporary file next to `path`, ready to be renamed onto it.
fn stage(path: &Path, bytes: &[u8]) -> std::io::Result<NamedTempFile> {
    let mut builder = tempfile::Builder::new();
    builder.prefix(".cagd-").suffix(".tmp");
    // Temporary files are private (0600); the output should get the permissions a plainly
    // created file would (0666 less the umask), or keep those of the file it replaces.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let permissions = std::fs::metadata(path)
            .map(|m| m.permissions())
            .unwrap_or_else(|_| std::fs::Permissions::from_mode(0o666));
        builder.permissions(permissions);
    }
    let mut tmp = builder.tempfile_in(directory_of(path))?;
    tmp.write_all(bytes)?;
    tmp.flush()?;
    tmp.as_file().sync_all()?;
    Ok(tmp)
}

/// Writes `bytes` to `path` atomically (temporary file in the same directory, then rename).
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
    let tmp = stage(path, bytes)?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
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
    /// `-` is standard output, written after the files.
    pub fn add(&mut self, argument: impl Into<String>, path: impl Into<PathBuf>, bytes: Vec<u8>) {
        self.files.push((argument.into(), path.into(), bytes));
    }

    /// Adds a folder to create (with its parents) before the files are staged.
    pub fn create_dir(&mut self, argument: impl Into<String>, path: impl Into<PathBuf>) {
        self.dirs.push((argument.into(), path.into()));
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

    /// Writes every file. On an error while staging, no file is written; the error names the
    /// argument and the path.
    pub fn commit(self) -> Result<(), super::CliError> {
        for (argument, dir) in &self.dirs {
            std::fs::create_dir_all(dir).map_err(|e| {
                super::CliError::io(
                    argument.as_str(),
                    &e,
                    "a folder that can be created and written",
                )
            })?;
        }
        let mut staged = Vec::with_capacity(self.files.len());
        let mut to_stdout = Vec::new();
        for (argument, path, bytes) in &self.files {
            if path.as_os_str() == "-" {
                to_stdout.push((argument, bytes));
                continue;
            }
            // A folder in the way would only fail at the rename, after other files were
            // renamed into place; a FIFO or a device must not become a regular file: refuse
            // both before anything is written.
            if let Some(kind) = crate::outputs::not_regular(path) {
                let e = std::io::Error::other(format!("is {kind}, not a regular file"));
                return Err(write_error(argument, path, &e));
            }
            let tmp = stage(path, bytes).map_err(|e| write_error(argument, path, &e))?;
            staged.push((argument, path, tmp));
        }
        // Renames can still fail (a race, a file system that refuses): undo the ones done, so
        // that the files are all written or none is.
        let mut done: Vec<(&PathBuf, Option<tempfile::TempPath>)> = Vec::new();
        for (argument, path, tmp) in staged {
            let backup = backup_of(path);
            if let Err(e) = tmp.persist(path) {
                roll_back(done);
                return Err(write_error(argument, path, &e.error));
            }
            done.push((path, backup));
        }
        for (argument, bytes) in to_stdout {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes)
                .and_then(|()| out.flush())
                .map_err(|e| write_error(argument, Path::new("-"), &e))?;
        }
        Ok(())
    }
}

/// A hard link to the file at `path` under a temporary name, if there is one, so that a
/// replaced file can be restored.
fn backup_of(path: &Path) -> Option<tempfile::TempPath> {
    if !path.is_file() {
        return None;
    }
    let name = tempfile::Builder::new()
        .prefix(".cagd-backup-")
        .suffix(".tmp")
        .make_in(directory_of(path), |p| std::fs::hard_link(path, p))
        .ok()?;
    Some(name.into_temp_path())
}

/// Restores the files replaced and removes the files created by the renames in `done`.
fn roll_back(done: Vec<(&PathBuf, Option<tempfile::TempPath>)>) {
    for (path, backup) in done.into_iter().rev() {
        match backup {
            Some(b) => {
                let _ = b.persist(path);
            }
            None => {
                let _ = std::fs::remove_file(path);
            }
        }
    }
}

fn write_error(argument: &str, path: &Path, e: &std::io::Error) -> super::CliError {
    let mut err = super::CliError::io(argument, e, "a writable path in an existing directory");
    err.problem = format!("cannot write {}: {}", path.display(), err.problem);
    err
}
