//! The context of one command: its limits, the files it may read besides the file system, and
//! what it noticed while reading its input — a value passed down every call, never global.

use std::cell::{RefCell, RefMut};

use cagd::limits::Limits;

use crate::noticed::Noticed;

/// The context a command runs in ([`crate::run`] makes one per command; the input readers such
/// as [`crate::load_matrix`] take one).
///
/// ```
/// // A numeric text file given in memory, read as a file of that name.
/// let files = vec![("net.txt".to_string(), "0 1 2\n0 2 0\n".to_string())];
/// let cx = cagd_cli::Cx::new(cagd::Limits::default()).with_files(files);
/// let b = cagd_cli::load_matrix::<f64>(&cx, "CONTROL", "net.txt", None).unwrap();
/// assert_eq!(b.shape(), (2, 3));
/// ```
#[derive(Debug)]
pub struct Cx {
    /// The resource limits (`--max-…`, `CAGD_MAX_…`, defaults).
    pub limits: Limits,
    /// Files given in memory (name, contents), read before the file system: the page, which
    /// has none, passes a data script typed into it as `--script data.m`.
    files: Vec<(String, String)>,
    /// What the command noticed while reading its input (its warnings, how its points were
    /// read), behind a cell so that the readers take the context by shared reference.
    noticed: RefCell<Noticed>,
}

impl Cx {
    /// A context with `limits`, no files in memory, nothing noticed.
    pub fn new(limits: Limits) -> Self {
        Cx {
            limits,
            files: Vec::new(),
            noticed: RefCell::new(Noticed::default()),
        }
    }

    /// The same context with `files` (name, contents) readable as input files of that name.
    pub fn with_files(self, files: Vec<(String, String)>) -> Self {
        Cx { files, ..self }
    }

    /// The same context, noting whether the command stated the orientation of its points
    /// (`--rows` or `--columns`), which silences the orientation note
    /// ([`crate::slips::point_matrix`]).
    pub fn stating_orientation(self, stated: bool) -> Self {
        self.noticed.borrow_mut().stated = stated;
        self
    }

    /// The contents of the in-memory file `name`, if one was given.
    pub(crate) fn file(&self, name: &str) -> Option<&str> {
        self.files
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, text)| text.as_str())
    }

    /// What the command noticed so far, to add to.
    pub(crate) fn noticed(&self) -> RefMut<'_, Noticed> {
        self.noticed.borrow_mut()
    }
}
