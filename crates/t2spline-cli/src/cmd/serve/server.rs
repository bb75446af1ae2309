//! The server of `t2spline serve`: one self-contained page (`page.html` with
//! `page.css` and `page.js` inlined, nothing fetched from elsewhere) and a
//! small JSON API (`api.rs`), on 127.0.0.1 only, every request checked first
//! (`security.rs`). Each connection is served on a thread of its own with
//! the limits of `http.rs`; every
//! computation goes through the I/O and core crates as the other commands'.

use std::net::TcpListener;
use std::sync::Arc;

use super::answer::{Answer, Served};
use super::http::{self, Request};
use super::{api, security};

/// The headers of every answer.
const HEADERS: &[(&str, &str)] = &[
    ("Cache-Control", "no-store"),
    ("X-Content-Type-Options", "nosniff"),
    ("Referrer-Policy", "no-referrer"),
    ("X-Frame-Options", "DENY"),
];

/// The page's policy: nothing fetched from elsewhere.
const PAGE_POLICY: &str =
    "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; \
     connect-src 'self'; img-src 'self' data: blob:; frame-ancestors 'none'";

/// A listening server.
pub struct Server {
    listener: TcpListener,
    port: u16,
    token: String,
    job: Served,
    page: String,
}

impl std::fmt::Debug for Server {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Server").field("port", &self.port).finish()
    }
}

/// The page, its style sheet and script inlined.
fn page() -> String {
    include_str!("page.html")
        .replace("/*PAGE_CSS*/", include_str!("page.css"))
        .replace("/*PAGE_JS*/", include_str!("page.js"))
}

impl Server {
    /// Listens on `127.0.0.1:port` (0: a free port) with a fresh token.
    ///
    /// # Errors
    /// The port cannot be bound; no random bytes for the token.
    pub fn start(job: Served, port: u16) -> anyhow::Result<Server> {
        let token = security::new_token()?;
        let listener = TcpListener::bind(("127.0.0.1", port))
            .map_err(|e| anyhow::anyhow!("--port: cannot listen on 127.0.0.1:{port}: {e}"))?;
        let port = listener.local_addr().map_or(port, |address| address.port());
        Ok(Server {
            listener,
            port,
            token,
            job,
            page: page(),
        })
    }

    /// The page's address, with the token.
    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/?token={}", self.port, self.token)
    }

    /// Answers requests until the process ends (Ctrl-C, `signals.rs`), each
    /// connection on a thread of its own (`http.rs`).
    pub fn run(self) {
        let listener = self.listener.try_clone();
        let Ok(listener) = listener else { return };
        let server = Arc::new(self);
        http::serve(
            &listener,
            move |request| server.answer(request),
            JSON_HEADERS,
        );
    }

    /// Checks and answers one request; a panic (a bug) is answered 500 and
    /// the server goes on.
    fn answer(&self, mut request: Request) {
        let answer = match security::check(&request, self.port, &self.token) {
            Err(refusal) => Answer::problem(403, refusal.message()),
            Ok(()) => {
                let call = std::panic::AssertUnwindSafe(|| self.route(&mut request));
                std::panic::catch_unwind(call)
                    .unwrap_or_else(|_| Answer::problem(500, "internal error (a bug)"))
            }
        };
        let mut headers = vec![("Content-Type", answer.media)];
        headers.extend_from_slice(HEADERS);
        if answer.media.starts_with("text/html") {
            headers.push(("Content-Security-Policy", PAGE_POLICY));
        }
        request.respond(answer.status, &headers, &answer.body);
    }

    /// The answer to a checked request.
    fn route(&self, request: &mut Request) -> Answer {
        let url = request.url().to_owned();
        let path = url.split_once('?').map_or(url.as_str(), |(p, _)| p);
        let method = request.method().to_owned();
        let overwrite = security::query(&url, "overwrite") == Some("1");
        match (method.as_str(), path) {
            ("GET", "/") => Answer::new(
                200,
                "text/html; charset=utf-8",
                self.page.clone().into_bytes(),
            ),
            ("GET", "/api/job") => {
                api::job(&self.job, security::query(&url, "reload") == Some("1"))
            }
            ("POST", "/api/run") => api::with_body(request, &self.job, api::run),
            ("POST", "/api/canonical") => api::with_body(request, &self.job, api::canonical),
            ("POST", "/api/region") => {
                let tolerance = security::query(&url, "tolerance").map(str::to_owned);
                api::with_body(request, &self.job, |text, job| {
                    api::region(text, job, tolerance.as_deref())
                })
            }
            ("POST", "/api/membership") => api::with_body(request, &self.job, api::membership),
            ("POST", "/api/save") => api::with_body(request, &self.job, |text, job| {
                api::save(text, job, overwrite)
            }),
            (_, "/" | "/api/job" | "/api/run" | "/api/canonical" | "/api/region")
            | (_, "/api/membership" | "/api/save") => Answer::problem(405, "method not allowed"),
            _ => Answer::problem(404, "not found"),
        }
    }
}

/// The headers of the answers `http.rs` gives by itself (busy, too slow).
const JSON_HEADERS: &[(&str, &str)] = &[
    ("Content-Type", "application/json"),
    ("Cache-Control", "no-store"),
    ("X-Content-Type-Options", "nosniff"),
];
