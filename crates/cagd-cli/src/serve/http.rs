//! The connections: accepted without end, each served as its own task by hyper, with a bound
//! on how many at once and on how long one may stall.

use std::convert::Infallible;
use std::io;
use std::pin::Pin;
use std::sync::Arc;
use std::task::{ready, Context, Poll};
use std::time::Duration;

use http_body_util::{combinators::BoxBody, BodyExt, Full};
use hyper::body::{Body, Bytes, Frame, Incoming, SizeHint};
use hyper::header::{self, HeaderValue};
use hyper::{Method, Request, Response, StatusCode};
use hyper_util::rt::{TokioIo, TokioTimer};
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::Semaphore;
use tokio::time::{Instant, Sleep};

use super::budget::{HEADER_TIMEOUT, MAX_CONNECTIONS, MAX_CONNECTION_TIME, STALL_TIMEOUT};
use super::cache::{self, Found, Large, Page, Variant};
use super::files;
use super::negotiate::{self, Accepts};

type Answer = Response<BoxBody<Bytes, io::Error>>;

/// Accepts connections until the process ends. A failed accept (a client gone before it was
/// accepted, no file descriptor left) is waited out, never the end of the server.
pub(super) async fn accept_loop(listener: TcpListener, page: Arc<Page>) {
    let slots = Arc::new(Semaphore::new(MAX_CONNECTIONS));
    loop {
        let Ok(slot) = slots.clone().acquire_owned().await else {
            return;
        };
        let stream = match listener.accept().await {
            Ok((stream, _)) => stream,
            Err(_) => {
                tokio::time::sleep(Duration::from_millis(20)).await;
                continue;
            }
        };
        let page = page.clone();
        tokio::spawn(async move {
            connection(stream, page).await;
            drop(slot);
        });
    }
}

/// Serves one connection until it closes, fails or stalls; its errors end it alone.
async fn connection(stream: TcpStream, page: Arc<Page>) {
    let _ = stream.set_nodelay(true);
    let io = TokioIo::new(Patient::new(stream, STALL_TIMEOUT));
    let service = hyper::service::service_fn(move |request| {
        let page = page.clone();
        async move { Ok::<_, Infallible>(respond(page, request).await) }
    });
    let serving = hyper::server::conn::http1::Builder::new()
        .timer(TokioTimer::new())
        .header_read_timeout(HEADER_TIMEOUT)
        .serve_connection(io, service);
    let _ = tokio::time::timeout(MAX_CONNECTION_TIME, serving).await;
}

/// What a request gets: a file from memory, in the form chosen for the client, or a file
/// streamed from disk.
enum Sendable {
    Memory {
        variant: Variant,
        file: Arc<cache::Cached>,
    },
    Stream(Large),
}

impl Sendable {
    fn tag(&self) -> &str {
        match self {
            Sendable::Memory { variant, .. } => &variant.tag,
            Sendable::Stream(l) => &l.tag,
        }
    }
}

/// The answer to one request.
async fn respond(page: Arc<Page>, request: Request<Incoming>) -> Answer {
    if !matches!(*request.method(), Method::GET | Method::HEAD) {
        let mut answer = text(StatusCode::METHOD_NOT_ALLOWED, "only GET and HEAD\n");
        answer
            .headers_mut()
            .insert(header::ALLOW, HeaderValue::from_static("GET, HEAD"));
        return answer;
    }
    let header_text = |name| {
        request
            .headers()
            .get(name)
            .and_then(|v: &HeaderValue| v.to_str().ok())
            .map(str::to_string)
    };
    let accepts = Accepts::parse(header_text(header::ACCEPT_ENCODING).as_deref());
    let if_none_match = header_text(header::IF_NONE_MATCH);
    let url = request.uri().path().to_string();
    // Reading and compressing a file blocks: it runs on the runtime's file threads.
    let sendable = match tokio::task::spawn_blocking(move || lookup(&page, &url, accepts)).await {
        Ok(Some(s)) => s,
        Ok(None) => return text(StatusCode::NOT_FOUND, "not found\n"),
        Err(_) => return text(StatusCode::INTERNAL_SERVER_ERROR, "cannot read\n"),
    };
    if if_none_match.is_some_and(|h| negotiate::none_match(&h, sendable.tag())) {
        return with_headers(StatusCode::NOT_MODIFIED, empty(), &sendable);
    }
    let body = match &sendable {
        Sendable::Memory { variant, .. } => full(variant.bytes.clone()),
        Sendable::Stream(l) => match tokio::fs::File::open(&l.path).await {
            Ok(file) => FileBody::new(file, l.len).boxed(),
            Err(_) => return text(StatusCode::NOT_FOUND, "not found\n"),
        },
    };
    with_headers(StatusCode::OK, body, &sendable)
}

/// The file that `url` names, in the form for a client that accepts `accepts` (blocking).
fn lookup(page: &Page, url: &str, accepts: Accepts) -> Option<Sendable> {
    match page.find(url).ok()?? {
        Found::Cached(file) => Some(Sendable::Memory {
            variant: file.variant(accepts),
            file,
        }),
        Found::Large(large) => Some(Sendable::Stream(large)),
    }
}

/// An answer with the headers of the file: its type, tag, caching and coding.
fn with_headers(
    status: StatusCode,
    body: BoxBody<Bytes, io::Error>,
    sendable: &Sendable,
) -> Answer {
    let (content_type, cache_control, varies, encoding) = match sendable {
        Sendable::Memory { variant, file } => (
            file.content_type(),
            file.cache_control(),
            file.varies(),
            variant.encoding,
        ),
        Sendable::Stream(l) => (
            files::content_type(&l.path),
            files::cache_control(&l.path),
            false,
            None,
        ),
    };
    let mut answer = Response::new(body);
    *answer.status_mut() = status;
    let headers = answer.headers_mut();
    let mut set = |name, value: &str| {
        if let Ok(v) = HeaderValue::from_str(value) {
            headers.insert(name, v);
        }
    };
    set(header::CONTENT_TYPE, content_type);
    set(header::CACHE_CONTROL, cache_control);
    set(header::ETAG, sendable.tag());
    set(header::X_CONTENT_TYPE_OPTIONS, "nosniff");
    if varies {
        set(header::VARY, "Accept-Encoding");
    }
    if let Some(coding) = encoding {
        set(header::CONTENT_ENCODING, coding);
    }
    answer
}

fn full(bytes: Bytes) -> BoxBody<Bytes, io::Error> {
    Full::new(bytes).map_err(|never| match never {}).boxed()
}

fn empty() -> BoxBody<Bytes, io::Error> {
    full(Bytes::new())
}

/// A short plain-text answer.
fn text(status: StatusCode, body: &'static str) -> Answer {
    let mut answer = Response::new(full(Bytes::from_static(body.as_bytes())));
    *answer.status_mut() = status;
    answer.headers_mut().insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("text/plain; charset=utf-8"),
    );
    answer
}

/// A file streamed from disk in pieces of 64 KiB.
struct FileBody {
    file: tokio::fs::File,
    remaining: u64,
    buffer: Box<[u8]>,
}

impl FileBody {
    fn new(file: tokio::fs::File, len: u64) -> FileBody {
        FileBody {
            file,
            remaining: len,
            buffer: vec![0; 64 << 10].into_boxed_slice(),
        }
    }
}

impl Body for FileBody {
    type Data = Bytes;
    type Error = io::Error;

    fn poll_frame(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, io::Error>>> {
        let this = self.get_mut();
        if this.remaining == 0 {
            return Poll::Ready(None);
        }
        let want = this
            .buffer
            .len()
            .min(usize::try_from(this.remaining).unwrap_or(usize::MAX));
        let mut buf = ReadBuf::new(&mut this.buffer[..want]);
        ready!(Pin::new(&mut this.file).poll_read(cx, &mut buf))?;
        let n = buf.filled().len();
        if n == 0 {
            // The file shrank while it was sent: end the connection rather than send less
            // than the Content-Length promised.
            return Poll::Ready(Some(Err(io::ErrorKind::UnexpectedEof.into())));
        }
        this.remaining -= n as u64;
        Poll::Ready(Some(Ok(Frame::data(Bytes::copy_from_slice(buf.filled())))))
    }

    fn is_end_stream(&self) -> bool {
        self.remaining == 0
    }

    fn size_hint(&self) -> SizeHint {
        SizeHint::with_exact(self.remaining)
    }
}

/// A connection that fails with `TimedOut` once it has made no progress — no byte read or
/// written — for `limit` while a read or a write waits: a client that stopped reading its
/// answers (its window full) or went silent.
struct Patient<S> {
    inner: S,
    limit: Duration,
    deadline: Pin<Box<Sleep>>,
}

impl<S> Patient<S> {
    fn new(inner: S, limit: Duration) -> Patient<S> {
        Patient {
            inner,
            limit,
            deadline: Box::pin(tokio::time::sleep(limit)),
        }
    }

    /// Moves the deadline on after progress.
    fn progressed(&mut self) {
        let next = Instant::now() + self.limit;
        self.deadline.as_mut().reset(next);
    }

    /// Called while an operation waits: `TimedOut` once the deadline has passed.
    fn waiting<T>(&mut self, cx: &mut Context<'_>) -> Poll<io::Result<T>> {
        match self.deadline.as_mut().poll(cx) {
            Poll::Ready(()) => Poll::Ready(Err(io::ErrorKind::TimedOut.into())),
            Poll::Pending => Poll::Pending,
        }
    }

    fn after<T>(
        &mut self,
        cx: &mut Context<'_>,
        poll: Poll<io::Result<T>>,
        moved: bool,
    ) -> Poll<io::Result<T>> {
        match poll {
            Poll::Pending => self.waiting(cx),
            Poll::Ready(result) => {
                if moved {
                    self.progressed();
                }
                Poll::Ready(result)
            }
        }
    }
}

impl<S: AsyncRead + Unpin> AsyncRead for Patient<S> {
    fn poll_read(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        let before = buf.filled().len();
        let poll = Pin::new(&mut this.inner).poll_read(cx, buf);
        let moved = buf.filled().len() > before;
        this.after(cx, poll, moved)
    }
}

impl<S: AsyncWrite + Unpin> AsyncWrite for Patient<S> {
    fn poll_write(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &[u8],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        let poll = Pin::new(&mut this.inner).poll_write(cx, buf);
        let moved = matches!(poll, Poll::Ready(Ok(n)) if n > 0);
        this.after(cx, poll, moved)
    }

    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        let poll = Pin::new(&mut this.inner).poll_write_vectored(cx, bufs);
        let moved = matches!(poll, Poll::Ready(Ok(n)) if n > 0);
        this.after(cx, poll, moved)
    }

    fn is_write_vectored(&self) -> bool {
        self.inner.is_write_vectored()
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        let poll = Pin::new(&mut this.inner).poll_flush(cx);
        this.after(cx, poll, false)
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        let poll = Pin::new(&mut this.inner).poll_shutdown(cx);
        this.after(cx, poll, false)
    }
}
