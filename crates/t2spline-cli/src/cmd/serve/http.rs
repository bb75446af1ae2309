//! HTTP/1.1 as `t2spline serve` needs it, with limits that a client on the
//! same computer cannot get past (the page's origin, `security.rs`, decides
//! who is answered; this module decides what a connection may cost).
//!
//! - Each connection is read on a thread of its own, at most
//!   [`MAX_CONNECTIONS`] at once (a connection past that is answered 503 at
//!   once), so a client that stalls blocks no other.
//! - The head (request line and headers, parsed by `httparse`) must arrive
//!   within [`HEAD_DEADLINE`] and be at most [`MAX_HEAD_BYTES`] long.
//! - A body is read only when asked for ([`Request::body`], after the
//!   request was checked), only with a `Content-Length` no larger than the
//!   caller's cap (a larger declared length is refused unread), and within
//!   [`BODY_DEADLINE`]: nothing is allocated from a length the client
//!   declares beyond what it has sent.
//! - One request per connection (`Connection: close`): every answer carries
//!   its `Content-Length` and the connection ends with it.

use std::io::{Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Connections served at once; one more is answered 503 and closed.
pub const MAX_CONNECTIONS: usize = 256;
/// The longest a head may be, request line and headers together.
pub const MAX_HEAD_BYTES: usize = 16 * 1024;
/// The most headers a request may carry.
const MAX_HEADERS: usize = 64;
/// The time a client has to send its head, from the connection's start.
pub const HEAD_DEADLINE: Duration = Duration::from_secs(5);
/// The time a client has to send a body, from the end of its head.
pub const BODY_DEADLINE: Duration = Duration::from_secs(10);
/// The time an answer has to be taken by the client.
const WRITE_TIMEOUT: Duration = Duration::from_secs(10);

/// A request whose head has been read; its body is still on the wire.
#[derive(Debug)]
pub struct Request {
    method: String,
    target: String,
    headers: Vec<(String, String)>,
    /// Bytes of the body that arrived with the head.
    early: Vec<u8>,
    stream: TcpStream,
}

/// Why a request could not be read: the status and message of the answer.
#[derive(Debug, PartialEq, Eq)]
pub struct Failure {
    pub status: u16,
    pub message: String,
}

impl Failure {
    fn new(status: u16, message: impl Into<String>) -> Failure {
        Failure {
            status,
            message: message.into(),
        }
    }
}

impl Request {
    /// The method, e.g. `GET`.
    pub fn method(&self) -> &str {
        &self.method
    }

    /// The request target: the path and the query.
    pub fn url(&self) -> &str {
        &self.target
    }

    /// The value of header `name` (case-insensitive), if present.
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(name))
            .map(|(_, v)| v.as_str())
    }

    /// Reads the body: exactly `Content-Length` bytes (no header: empty),
    /// refused unread when the length is over `cap`, not a number, or the
    /// body is chunked; a client that does not send it within
    /// [`BODY_DEADLINE`] is answered 408.
    ///
    /// # Errors
    /// The answer to give instead (411, 413, 400 or 408).
    pub fn body(&mut self, cap: u64, what: &str) -> Result<Vec<u8>, Failure> {
        if self.header("Transfer-Encoding").is_some() {
            return Err(Failure::new(
                411,
                "a chunked body is not accepted: send it with Content-Length",
            ));
        }
        let declared = match self.header("Content-Length") {
            None => return Ok(Vec::new()),
            Some(text) => text.trim().parse::<u64>().map_err(|_| {
                Failure::new(400, format!("Content-Length `{text}` is not a length"))
            })?,
        };
        if declared > cap {
            return Err(Failure::new(
                413,
                format!(
                    "{what}: the request body is larger than a job file may be ({} MiB)",
                    cap >> 20
                ),
            ));
        }
        // Within the cap, so it fits in memory.
        let length = usize::try_from(declared).unwrap_or(usize::MAX);
        let mut body = std::mem::take(&mut self.early);
        body.truncate(length);
        let deadline = Instant::now() + BODY_DEADLINE;
        let mut chunk = [0u8; 64 * 1024];
        while body.len() < length {
            let want = (length - body.len()).min(chunk.len());
            match read_before(&mut self.stream, &mut chunk[..want], deadline) {
                Ok(0) => {
                    return Err(Failure::new(
                        400,
                        "the body ended before its Content-Length",
                    ))
                }
                Ok(n) => body.extend_from_slice(&chunk[..n]),
                Err(_) => {
                    return Err(Failure::new(
                        408,
                        format!(
                            "the body did not arrive within {} s",
                            BODY_DEADLINE.as_secs()
                        ),
                    ))
                }
            }
        }
        Ok(body)
    }

    /// Writes the answer and ends the connection.
    pub fn respond(mut self, status: u16, headers: &[(&str, &str)], body: &[u8]) {
        write_answer(&mut self.stream, status, headers, body);
    }
}

/// One read that gives up at `deadline`.
fn read_before(
    stream: &mut TcpStream,
    buffer: &mut [u8],
    deadline: Instant,
) -> std::io::Result<usize> {
    let left = deadline.saturating_duration_since(Instant::now());
    if left.is_zero() {
        return Err(std::io::ErrorKind::TimedOut.into());
    }
    stream.set_read_timeout(Some(left))?;
    stream.read(buffer)
}

/// Reads a request's head from `stream`.
///
/// # Errors
/// The answer to give instead: 408 (too slow), 431 (too long), 400 (not
/// HTTP/1.x); a connection closed before its head is `None`.
fn read_head(mut stream: TcpStream) -> Result<Request, (TcpStream, Option<Failure>)> {
    let deadline = Instant::now() + HEAD_DEADLINE;
    let mut buffer = Vec::with_capacity(1024);
    let mut chunk = [0u8; 4096];
    loop {
        let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
        let mut parsed = httparse::Request::new(&mut headers);
        match parsed.parse(&buffer) {
            Ok(httparse::Status::Complete(end)) => {
                let request = Request {
                    method: parsed.method.unwrap_or_default().to_owned(),
                    target: parsed.path.unwrap_or_default().to_owned(),
                    headers: parsed
                        .headers
                        .iter()
                        .map(|h| {
                            (
                                h.name.to_owned(),
                                String::from_utf8_lossy(h.value).into_owned(),
                            )
                        })
                        .collect(),
                    early: buffer[end..].to_vec(),
                    stream,
                };
                return Ok(request);
            }
            Ok(httparse::Status::Partial) => {}
            Err(httparse::Error::TooManyHeaders) => {
                let failure = Failure::new(431, format!("more than {MAX_HEADERS} headers"));
                return Err((stream, Some(failure)));
            }
            Err(e) => {
                return Err((
                    stream,
                    Some(Failure::new(400, format!("not an HTTP/1.1 request: {e}"))),
                ))
            }
        }
        if buffer.len() >= MAX_HEAD_BYTES {
            let failure = Failure::new(
                431,
                format!("the head is longer than {} KiB", MAX_HEAD_BYTES >> 10),
            );
            return Err((stream, Some(failure)));
        }
        let want = (MAX_HEAD_BYTES - buffer.len()).min(chunk.len());
        match read_before(&mut stream, &mut chunk[..want], deadline) {
            Ok(0) => return Err((stream, None)),
            Ok(n) => buffer.extend_from_slice(&chunk[..n]),
            Err(_) if buffer.is_empty() => return Err((stream, None)),
            Err(_) => {
                let failure = Failure::new(
                    408,
                    format!(
                        "the head did not arrive within {} s",
                        HEAD_DEADLINE.as_secs()
                    ),
                );
                return Err((stream, Some(failure)));
            }
        }
    }
}

/// The reason phrase of the statuses the server gives.
fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        409 => "Conflict",
        411 => "Length Required",
        413 => "Content Too Large",
        422 => "Unprocessable Content",
        431 => "Request Header Fields Too Large",
        500 => "Internal Server Error",
        503 => "Service Unavailable",
        _ => "",
    }
}

/// Writes a whole answer, then closes the connection gently: what the
/// client still sends (a body not read) is taken for a moment and dropped,
/// so that the answer is not lost to a reset.
fn write_answer(stream: &mut TcpStream, status: u16, headers: &[(&str, &str)], body: &[u8]) {
    let mut head = format!("HTTP/1.1 {status} {}\r\n", reason(status));
    for (name, value) in headers {
        head.push_str(&format!("{name}: {value}\r\n"));
    }
    head.push_str(&format!(
        "Content-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    ));
    let _ = stream.set_write_timeout(Some(WRITE_TIMEOUT));
    // The client may have gone; nothing to do then.
    if stream.write_all(head.as_bytes()).is_err() || stream.write_all(body).is_err() {
        return;
    }
    let _ = stream.flush();
    let _ = stream.shutdown(Shutdown::Write);
    let deadline = Instant::now() + Duration::from_millis(500);
    let mut sink = [0u8; 16 * 1024];
    let mut taken = 0usize;
    while taken < (1 << 20) {
        match read_before(stream, &mut sink, deadline) {
            Ok(0) | Err(_) => break,
            Ok(n) => taken += n,
        }
    }
}

/// Counts the connections being served; one is given back when its guard
/// drops.
#[derive(Debug, Clone, Default)]
struct Gauge(Arc<AtomicUsize>);

#[derive(Debug)]
struct Held(Arc<AtomicUsize>);

impl Drop for Held {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

impl Gauge {
    fn take(&self) -> Option<Held> {
        let before = self.0.fetch_add(1, Ordering::SeqCst);
        let held = Held(Arc::clone(&self.0));
        (before < MAX_CONNECTIONS).then_some(held)
    }
}

/// Accepts connections on `listener` until the process ends, and calls
/// `answer` on a thread of its own for each request whose head was read.
/// `headers` go with every answer this module gives by itself (503, 408, …).
pub fn serve<F>(listener: &TcpListener, answer: F, headers: &'static [(&'static str, &'static str)])
where
    F: Fn(Request) + Send + Sync + 'static,
{
    let answer = Arc::new(answer);
    let gauge = Gauge::default();
    let problem = |message: &str| {
        serde_json::json!({ "problems": [message] })
            .to_string()
            .into_bytes()
    };
    for stream in listener.incoming() {
        let Ok(mut stream) = stream else { continue };
        let Some(held) = gauge.take() else {
            let body = problem("busy: too many connections at once; try again");
            write_answer(&mut stream, 503, headers, &body);
            continue;
        };
        let answer = Arc::clone(&answer);
        let spawned = std::thread::Builder::new()
            .name("serve-connection".to_owned())
            .spawn(move || {
                let _held = held;
                match read_head(stream) {
                    Ok(request) => answer(request),
                    Err((mut stream, Some(failure))) => {
                        write_answer(
                            &mut stream,
                            failure.status,
                            headers,
                            &problem(&failure.message),
                        );
                    }
                    Err((_, None)) => {}
                }
            });
        // No thread to be had: the connection is dropped; the next may fare better.
        drop(spawned);
    }
}
