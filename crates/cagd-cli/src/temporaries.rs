//! The temporary files of outputs being written, never left behind: each is registered while
//! it exists, and [`remove_on_signals`] (called by the `cagd` program at start) removes every
//! registered one when SIGINT, SIGTERM or SIGHUP arrives, then ends the process by that signal.
//!
//! The renames that put staged files into place form one step that a signal does not cut in
//! two: while they are under way, the signal waits for them (renames take microseconds).

use std::path::{Path, PathBuf};
use std::sync::{Condvar, Mutex, MutexGuard};

use tempfile::NamedTempFile;

/// The registered temporary files, and whether the process is ending.
struct Registry {
    paths: Vec<PathBuf>,
    ending: bool,
    renaming: usize,
}

static REGISTRY: Mutex<Registry> = Mutex::new(Registry {
    paths: Vec::new(),
    ending: false,
    renaming: 0,
});
static RENAMED: Condvar = Condvar::new();

fn registry() -> MutexGuard<'static, Registry> {
    // The registry holds plain paths; a panic elsewhere cannot leave it half-updated.
    REGISTRY.lock().unwrap_or_else(|e| e.into_inner())
}

fn ending() -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::Interrupted,
        "the program is being stopped",
    )
}

/// A temporary file named `.cagd-…` in a folder, removed when dropped (or by a signal).
#[derive(Debug)]
pub(crate) struct Temporary {
    file: Option<NamedTempFile>,
    path: PathBuf,
}

impl Temporary {
    /// A new temporary file in `dir`, named `{prefix}XXXXXX.tmp`, made by `create` (which must
    /// create the file at the path it is given, failing if it exists).
    pub fn new_in(
        dir: &Path,
        prefix: &str,
        create: impl Fn(&Path) -> std::io::Result<std::fs::File>,
    ) -> std::io::Result<Temporary> {
        let file = tempfile::Builder::new()
            .prefix(prefix)
            .suffix(".tmp")
            .make_in(dir, |path| {
                // Registered in the same step as created: a signal sees both or neither.
                let mut registry = registry();
                if registry.ending {
                    return Err(ending());
                }
                let file = create(path)?;
                registry.paths.push(path.to_path_buf());
                Ok(file)
            })?;
        let path = file.path().to_path_buf();
        Ok(Temporary {
            file: Some(file),
            path,
        })
    }

    /// The open file.
    pub fn file(&mut self) -> &mut std::fs::File {
        self.file
            .as_mut()
            .map(NamedTempFile::as_file_mut)
            .expect("a temporary is open until it is persisted or dropped")
    }

    /// Where the temporary file is.
    #[cfg(test)]
    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        // Removed first, then forgotten: a signal in between finds nothing to remove.
        drop(self.file.take());
        let mut registry = registry();
        if let Some(k) = registry.paths.iter().position(|p| *p == self.path) {
            registry.paths.swap_remove(k);
        }
    }
}

/// The step of renames: while it is held, a signal waits before it removes the temporaries.
pub(crate) struct Renaming(());

impl Renaming {
    /// Starts the renames, unless the process is being stopped.
    pub fn start() -> std::io::Result<Renaming> {
        let mut registry = registry();
        if registry.ending {
            return Err(ending());
        }
        registry.renaming += 1;
        Ok(Renaming(()))
    }

    /// Renames the temporary onto `target` (replacing it).
    pub fn persist(&mut self, mut temporary: Temporary, target: &Path) -> std::io::Result<()> {
        let file = temporary
            .file
            .take()
            .expect("a temporary is persisted once");
        match file.persist(target) {
            Ok(_) => Ok(()),
            Err(e) => {
                temporary.file = Some(e.file);
                Err(e.error)
            }
        }
    }
}

impl Drop for Renaming {
    fn drop(&mut self) {
        registry().renaming -= 1;
        RENAMED.notify_all();
    }
}

/// Removes every registered temporary file and refuses new ones; waits for renames under way.
/// Returns how many files were removed.
pub fn remove_all() -> usize {
    let mut registry = registry();
    registry.ending = true;
    while registry.renaming > 0 {
        registry = RENAMED.wait(registry).unwrap_or_else(|e| e.into_inner());
    }
    let paths = std::mem::take(&mut registry.paths);
    paths
        .iter()
        .filter(|p| std::fs::remove_file(p).is_ok())
        .count()
}

/// Installs the handler of SIGINT, SIGTERM and SIGHUP: remove the temporaries ([`remove_all`]),
/// then end the process by the same signal (so that a shell sees the interruption).
///
/// # Errors
/// When the handler or its thread cannot be set up.
#[cfg(unix)]
pub fn remove_on_signals() -> std::io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])?;
    std::thread::Builder::new()
        .name("cagd-signals".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                remove_all();
                let _ = signal_hook::low_level::emulate_default_handler(signal);
                std::process::exit(128 + signal);
            }
        })?;
    Ok(())
}

/// Without Unix signals there is nothing to install.
#[cfg(not(unix))]
pub fn remove_on_signals() -> std::io::Result<()> {
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registered_temporaries_are_removed_and_forgotten() {
        let dir = tempfile::tempdir().unwrap();
        let create = |p: &Path| std::fs::File::create_new(p);
        let kept = Temporary::new_in(dir.path(), ".cagd-", create).unwrap();
        let dropped = Temporary::new_in(dir.path(), ".cagd-", create).unwrap();
        let dropped_path = dropped.path().to_path_buf();
        drop(dropped);
        assert!(!dropped_path.exists());
        assert!(registry().paths.iter().all(|p| *p != dropped_path));
        let persisted = Temporary::new_in(dir.path(), ".cagd-", create).unwrap();
        let persisted_path = persisted.path().to_path_buf();
        Renaming::start()
            .unwrap()
            .persist(persisted, &dir.path().join("out.txt"))
            .unwrap();
        assert!(dir.path().join("out.txt").exists());
        assert!(registry().paths.iter().all(|p| *p != persisted_path));
        assert!(registry().paths.contains(&kept.path().to_path_buf()));
    }
}
