//! Where an output file lands, as the shell's `>` would put it, and whether it may be written:
//! a symbolic link is followed to its target (the link stays, the target gets the content),
//! a dangling link creates its target, a loop of links is refused; an existing target must be
//! a regular file that may be written.

use std::io;
use std::path::{Path, PathBuf};

use crate::ErrorKind;

/// The longest chain of symbolic links followed (Linux's own limit).
pub const MAX_LINKS: usize = 40;

/// The directory a file is written into (`.` for a bare file name).
pub fn directory_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// The file that writing `path` replaces or creates: `path` itself, or the end of its chain
/// of symbolic links (which need not exist yet).
///
/// # Errors
/// A loop of links, or a chain longer than [`MAX_LINKS`]; a link that cannot be read.
///
/// ```
/// # #[cfg(unix)] {
/// use cagd_cli::outputs::destination;
/// let dir = tempfile::tempdir().unwrap();
/// let link = dir.path().join("link.txt");
/// std::os::unix::fs::symlink("target.txt", &link).unwrap();
/// assert_eq!(destination(&link).unwrap(), dir.path().join("target.txt"));
/// std::os::unix::fs::symlink("b", dir.path().join("a")).unwrap();
/// std::os::unix::fs::symlink("a", dir.path().join("b")).unwrap();
/// assert!(destination(&dir.path().join("a")).is_err());
/// # }
/// ```
pub fn destination(path: &Path) -> io::Result<PathBuf> {
    let mut current = path.to_path_buf();
    for _ in 0..=MAX_LINKS {
        match std::fs::symlink_metadata(&current) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let link = std::fs::read_link(&current)?;
                current = match current.parent() {
                    Some(dir) if !link.is_absolute() && !dir.as_os_str().is_empty() => {
                        dir.join(link)
                    }
                    _ => link,
                };
            }
            Ok(_) => return Ok(current),
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::NotFound | io::ErrorKind::NotADirectory
                ) =>
            {
                return Ok(current);
            }
            Err(e) => return Err(e),
        }
    }
    Err(io::Error::other(format!(
        "is a loop of symbolic links (or a chain of more than {MAX_LINKS})"
    )))
}

/// Why `path` (an output, not `-`) cannot be written, with the kind of the refusal: a loop of
/// links; an existing target that is not a regular file, is read-only, or cannot be opened
/// for writing; a target whose folder does not exist. Without a file system (the browser)
/// there is nothing to refuse.
pub fn refusal(path: &Path) -> Option<(String, ErrorKind)> {
    let unsupported = |e: &io::Error| e.kind() == io::ErrorKind::Unsupported;
    let target = match destination(path) {
        Ok(t) => t,
        Err(e) if unsupported(&e) => return None,
        Err(e) => return Some((e.to_string(), ErrorKind::Io(e.kind()))),
    };
    let link = if target == path {
        String::new()
    } else {
        format!(" (the link's target {})", crate::escape_path(&target))
    };
    let meta = match std::fs::metadata(&target) {
        Ok(meta) => meta,
        Err(e)
            if matches!(
                e.kind(),
                io::ErrorKind::NotFound | io::ErrorKind::NotADirectory
            ) =>
        {
            return folder_refusal(&target, &link);
        }
        Err(e) if unsupported(&e) => return None,
        Err(e) => return Some(cannot_write(&e, &link)),
    };
    if let Some(kind) = not_regular(&target) {
        return Some((
            format!("exists and is {kind}, not a regular file{link}; it is not replaced"),
            ErrorKind::Io(io::ErrorKind::AlreadyExists),
        ));
    }
    if meta.permissions().readonly() {
        return Some((
            format!("is read-only{}{link}; it is not replaced", mode_text(&meta)),
            ErrorKind::Io(io::ErrorKind::PermissionDenied),
        ));
    }
    // What `>` checks: that the file may be opened for writing (its owner, its ACL, a
    // read-only mount, the immutable attribute). Opening changes nothing.
    match std::fs::OpenOptions::new().write(true).open(&target) {
        Ok(_) => None,
        Err(e) => Some(cannot_write(&e, &link)),
    }
}

/// Why a new file `target` cannot be created: its folder is missing or is not a folder.
fn folder_refusal(target: &Path, link: &str) -> Option<(String, ErrorKind)> {
    let dir = directory_of(target);
    let shown = crate::escape_path(dir);
    match std::fs::metadata(dir) {
        Ok(meta) if meta.is_dir() => None,
        Ok(_) => Some((
            format!("{shown} is not a folder{link}"),
            ErrorKind::Io(io::ErrorKind::NotADirectory),
        )),
        Err(e) if e.kind() == io::ErrorKind::Unsupported => None,
        Err(e)
            if matches!(
                e.kind(),
                io::ErrorKind::NotFound | io::ErrorKind::NotADirectory
            ) =>
        {
            Some((
                format!("the folder {shown} does not exist{link}"),
                ErrorKind::Io(io::ErrorKind::NotFound),
            ))
        }
        Err(e) => Some(cannot_write(&e, link)),
    }
}

fn cannot_write(e: &io::Error, link: &str) -> (String, ErrorKind) {
    let (problem, kind) = crate::error::io_problem(e);
    (
        format!("cannot be written{link}: {problem}"),
        ErrorKind::Io(kind),
    )
}

/// ` (mode 0444)` on Unix.
fn mode_text(meta: &std::fs::Metadata) -> String {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        format!(" (mode {:04o})", meta.permissions().mode() & 0o7777)
    }
    #[cfg(not(unix))]
    {
        let _ = meta;
        String::new()
    }
}

/// What `path` is when it exists and is not a regular file (following symbolic links).
pub fn not_regular(path: &Path) -> Option<&'static str> {
    let meta = std::fs::metadata(path).ok()?;
    let t = meta.file_type();
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("a folder");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return Some("a named pipe (FIFO)");
        }
        if t.is_char_device() || t.is_block_device() {
            return Some("a device");
        }
        if t.is_socket() {
            return Some("a socket");
        }
    }
    Some("not a regular file")
}

/// The identity of an existing file, through any links: two paths with one identity are one
/// file (another spelling, a link, a hard link).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileId {
    /// Device and inode.
    #[cfg(unix)]
    dev_ino: (u64, u64),
    /// The canonical path, where there are no inodes.
    #[cfg(not(unix))]
    canonical: PathBuf,
}

/// The identity of the file at `path`, if it exists.
pub fn file_id(path: &Path) -> Option<FileId> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let meta = std::fs::metadata(path).ok()?;
        Some(FileId {
            dev_ino: (meta.dev(), meta.ino()),
        })
    }
    #[cfg(not(unix))]
    {
        Some(FileId {
            canonical: std::fs::canonicalize(path).ok()?,
        })
    }
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn links_are_followed_and_refusals_named() {
        let dir = tempfile::tempdir().unwrap();
        let p = |name: &str| dir.path().join(name);
        std::fs::write(p("file.txt"), "x").unwrap();
        std::os::unix::fs::symlink("file.txt", p("link.txt")).unwrap();
        std::os::unix::fs::symlink("link.txt", p("link2.txt")).unwrap();
        std::os::unix::fs::symlink("missing.txt", p("dangling.txt")).unwrap();
        std::os::unix::fs::symlink("nowhere/x.txt", p("astray.txt")).unwrap();
        std::os::unix::fs::symlink("self.txt", p("self.txt")).unwrap();
        assert_eq!(destination(&p("link2.txt")).unwrap(), p("file.txt"));
        assert_eq!(destination(&p("dangling.txt")).unwrap(), p("missing.txt"));
        assert_eq!(refusal(&p("link2.txt")), None);
        assert_eq!(refusal(&p("dangling.txt")), None);
        let (problem, _) = refusal(&p("self.txt")).unwrap();
        assert!(problem.contains("loop of symbolic links"), "{problem}");
        let (problem, kind) = refusal(&p("astray.txt")).unwrap();
        assert!(
            problem.contains("does not exist (the link's target"),
            "{problem}"
        );
        assert_eq!(kind, ErrorKind::Io(io::ErrorKind::NotFound));
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(p("file.txt"), std::fs::Permissions::from_mode(0o444)).unwrap();
        let (problem, kind) = refusal(&p("link.txt")).unwrap();
        assert!(
            problem.starts_with("is read-only (mode 0444) (the link's target"),
            "{problem}"
        );
        assert_eq!(kind, ErrorKind::Io(io::ErrorKind::PermissionDenied));
        assert_eq!(file_id(&p("link2.txt")), file_id(&p("file.txt")));
    }
}
