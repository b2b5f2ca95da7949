//! The page's files in memory: each read once (again when it changes), tagged by a hash of
//! its bytes, and compressed once; files too large to keep are streamed instead.

use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::SystemTime;

use hyper::body::Bytes;

use super::budget::MAX_CACHED_FILE_BYTES;
use super::files::{cache_control, compressible, content_type, resolve_in};
use super::negotiate::Accepts;

/// The most bytes kept in memory for all cached files together; past it the cache starts over.
const MAX_CACHE_BYTES: usize = 256 << 20;

/// What changes when a file is rewritten: its size and modification time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Stamp {
    len: u64,
    modified: Option<SystemTime>,
}

impl Stamp {
    fn of(meta: &std::fs::Metadata) -> Stamp {
        Stamp {
            len: meta.len(),
            modified: meta.modified().ok(),
        }
    }
}

/// One file held in memory with its tag and its compressed forms.
#[derive(Debug)]
pub(super) struct Cached {
    stamp: Stamp,
    path: PathBuf,
    tag: String,
    identity: Bytes,
    gzip: OnceLock<Option<Bytes>>,
    brotli: Option<Bytes>,
}

/// One form of a file to send: its bytes, its content coding and its tag.
pub(super) struct Variant {
    pub bytes: Bytes,
    pub encoding: Option<&'static str>,
    pub tag: String,
}

impl Cached {
    fn load(path: &Path, stamp: Stamp) -> std::io::Result<Cached> {
        let identity = Bytes::from(std::fs::read(path)?);
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        identity.hash(&mut hasher);
        let tag = format!("\"{:x}-{:016x}\"", identity.len(), hasher.finish());
        let gzip = OnceLock::new();
        let mut brotli = None;
        if compressible(path) {
            if let Some(gz) = sibling(path, "gz", &stamp) {
                let _ = gzip.set(Some(gz));
            }
            brotli = sibling(path, "br", &stamp);
        }
        Ok(Cached {
            stamp,
            path: path.to_path_buf(),
            tag,
            identity,
            gzip,
            brotli,
        })
    }

    /// The form to send to a client that accepts `accepts`: brotli when precompressed, else
    /// gzip (compressed here once), else the file itself; a coding only when it is smaller.
    pub fn variant(&self, accepts: Accepts) -> Variant {
        let tagged = |bytes: &Bytes, coding: &'static str| Variant {
            bytes: bytes.clone(),
            encoding: Some(coding),
            tag: format!("{}-{coding}\"", self.tag.trim_end_matches('"')),
        };
        if let (true, Some(br)) = (accepts.brotli, &self.brotli) {
            return tagged(br, "br");
        }
        if accepts.gzip && compressible(&self.path) {
            if let Some(gz) = self.gzip.get_or_init(|| gzip(&self.identity)) {
                return tagged(gz, "gzip");
            }
        }
        Variant {
            bytes: self.identity.clone(),
            encoding: None,
            tag: self.tag.clone(),
        }
    }

    /// Whether other codings of this file exist (so caches must key on `Accept-Encoding`).
    pub fn varies(&self) -> bool {
        compressible(&self.path)
    }

    /// The `Cache-Control` of this file.
    pub fn cache_control(&self) -> &'static str {
        cache_control(&self.path)
    }

    /// The content type of this file.
    pub fn content_type(&self) -> &'static str {
        content_type(&self.path)
    }
}

/// A precompressed `FILE.EXT` beside the file, when it is at least as new as the file.
fn sibling(path: &Path, ext: &str, stamp: &Stamp) -> Option<Bytes> {
    let mut name = path.as_os_str().to_owned();
    name.push(".");
    name.push(ext);
    let sibling = PathBuf::from(name);
    let modified = std::fs::metadata(&sibling).ok()?.modified().ok()?;
    if stamp.modified.is_some_and(|m| modified < m) {
        return None;
    }
    std::fs::read(&sibling).ok().map(Bytes::from)
}

/// The gzip form of `bytes` (best compression), when it is smaller.
fn gzip(bytes: &[u8]) -> Option<Bytes> {
    let mut encoder = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    encoder.write_all(bytes).ok()?;
    let packed = encoder.finish().ok()?;
    (packed.len() < bytes.len()).then(|| Bytes::from(packed))
}

/// A file too large to keep in memory: streamed as it is.
#[derive(Debug)]
pub(super) struct Large {
    pub path: PathBuf,
    pub len: u64,
    pub tag: String,
}

/// What a request path names.
pub(super) enum Found {
    Cached(Arc<Cached>),
    Large(Large),
}

/// The served folder with the files read so far.
#[derive(Debug)]
pub(super) struct Page {
    real_root: PathBuf,
    cache: Mutex<(HashMap<PathBuf, Arc<Cached>>, usize)>,
}

impl Page {
    /// The folder `root` (which must exist).
    pub fn new(root: &Path) -> std::io::Result<Page> {
        Ok(Page {
            real_root: root.canonicalize()?,
            cache: Mutex::new((HashMap::new(), 0)),
        })
    }

    /// The file that the request path `url` names, read (or found in memory), or `None`.
    /// Blocking: call it off the connection threads.
    pub fn find(&self, url: &str) -> std::io::Result<Option<Found>> {
        let Some(file) = resolve_in(&self.real_root, url) else {
            return Ok(None);
        };
        let meta = std::fs::metadata(&file)?;
        let stamp = Stamp::of(&meta);
        if stamp.len > MAX_CACHED_FILE_BYTES {
            let nanos = stamp
                .modified
                .and_then(|m| m.duration_since(SystemTime::UNIX_EPOCH).ok())
                .map_or(0, |d| d.as_nanos());
            let tag = format!("\"{:x}-t{nanos:x}\"", stamp.len);
            let len = stamp.len;
            return Ok(Some(Found::Large(Large {
                path: file,
                len,
                tag,
            })));
        }
        if let Some(hit) = self.lock().0.get(&file).filter(|c| c.stamp == stamp) {
            return Ok(Some(Found::Cached(hit.clone())));
        }
        let loaded = Arc::new(Cached::load(&file, stamp)?);
        let mut cache = self.lock();
        let size = loaded.identity.len();
        if cache.1 + size > MAX_CACHE_BYTES {
            *cache = (HashMap::new(), 0);
        }
        cache.1 += size;
        cache.0.insert(file, loaded.clone());
        Ok(Some(Found::Cached(loaded)))
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, (HashMap<PathBuf, Arc<Cached>>, usize)> {
        // A panic while the cache was held cannot leave it inconsistent (entries are whole).
        self.cache.lock().unwrap_or_else(|e| e.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::serve::files::{IMMUTABLE, REVALIDATE};

    #[test]
    fn files_are_cached_tagged_and_compressed_once() {
        let dir = tempfile::tempdir().unwrap();
        let text = "let x = 1;\n".repeat(1000);
        std::fs::write(dir.path().join("app.js"), &text).unwrap();
        std::fs::write(dir.path().join("cagd.0123abcd.wasm"), &text).unwrap();
        let page = Page::new(dir.path()).unwrap();
        let Some(Found::Cached(js)) = page.find("/app.js").unwrap() else {
            panic!("app.js not found")
        };
        let plain = js.variant(Accepts::default());
        assert_eq!(plain.bytes.len(), text.len());
        assert!(plain.encoding.is_none());
        let gz = js.variant(Accepts::parse(Some("gzip")));
        assert_eq!(gz.encoding, Some("gzip"));
        assert!(gz.bytes.len() < text.len() / 10, "{}", gz.bytes.len());
        assert_ne!(gz.tag, plain.tag);
        let mut back = String::new();
        std::io::Read::read_to_string(&mut flate2::read::GzDecoder::new(&gz.bytes[..]), &mut back)
            .unwrap();
        assert_eq!(back, text);
        // The same file again is the same entry; a rewritten one is read anew.
        let Some(Found::Cached(again)) = page.find("/app.js").unwrap() else {
            panic!()
        };
        assert!(Arc::ptr_eq(&js, &again));
        std::fs::write(dir.path().join("app.js"), "changed").unwrap();
        let Some(Found::Cached(changed)) = page.find("/app.js").unwrap() else {
            panic!()
        };
        assert_ne!(changed.variant(Accepts::default()).tag, plain.tag);
        assert_eq!(js.cache_control(), REVALIDATE);
        let Some(Found::Cached(wasm)) = page.find("/cagd.0123abcd.wasm").unwrap() else {
            panic!()
        };
        assert_eq!(wasm.cache_control(), IMMUTABLE);
        assert!(page.find("/missing.js").unwrap().is_none());
    }
}
