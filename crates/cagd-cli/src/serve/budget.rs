//! What the page server allows one client and all of them: threads, connections, time.

use std::time::Duration;

/// The threads that serve connections (each connection is a task on one of them).
pub const WORKER_THREADS: usize = 2;
/// The threads that read files from disk and compress them, at most.
pub const FILE_THREADS: usize = 4;
/// The most connections served at once; further clients wait in the listening queue.
pub const MAX_CONNECTIONS: usize = 256;
/// The listening queue: connections the system has completed and the server not yet taken.
/// The standard library's and tokio's 128 overflowed under a burst of clients while all
/// [`MAX_CONNECTIONS`] were busy, and a client whose connection found the queue full was
/// dropped and tried again only a second later; the system caps it (`somaxconn`).
pub const ACCEPT_QUEUE: u32 = 4096;
/// A connection that makes no progress (no byte read or written) for this long is closed: a
/// client that stopped reading its answers, or an idle kept-alive connection.
pub const STALL_TIMEOUT: Duration = Duration::from_secs(15);
/// The longest a client may take to send the head of a request (a slow-loris client).
pub const HEADER_TIMEOUT: Duration = Duration::from_secs(10);
/// The longest one connection is served, however busy (a client trickling bytes forever).
pub const MAX_CONNECTION_TIME: Duration = Duration::from_secs(600);
/// Files up to this size are kept in memory (and compressed there); larger ones are streamed.
pub const MAX_CACHED_FILE_BYTES: u64 = 32 << 20;
