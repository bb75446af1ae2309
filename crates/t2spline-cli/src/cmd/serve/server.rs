//! The server of `t2spline serve`: one self-contained page (`page.html` with
//! `page.css` and `page.js` inlined, nothing fetched from elsewhere) and a
//! small JSON API (`api.rs`), on 127.0.0.1 only, every request checked first
//! (`security.rs`). Requests are answered one at a time, in order; every
//! computation goes through the I/O and core crates as the other commands'.

use std::io::Cursor;

use tiny_http::{Header, Request, Response, StatusCode};

use super::answer::{Answer, Served};
use super::{api, security};

/// A listening server.
pub struct Server {
    http: tiny_http::Server,
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
        let http = tiny_http::Server::http(("127.0.0.1", port))
            .map_err(|e| anyhow::anyhow!("--port: cannot listen on 127.0.0.1:{port}: {e}"))?;
        let port = http
            .server_addr()
            .to_ip()
            .map_or(port, |address| address.port());
        Ok(Server {
            http,
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

    /// Answers requests until the process ends (Ctrl-C, `signals.rs`).
    pub fn run(self) {
        for request in self.http.incoming_requests() {
            self.answer(request);
        }
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
        let is_page = answer.media.starts_with("text/html");
        let mut response = Response::new(
            StatusCode(answer.status),
            Vec::new(),
            Cursor::new(answer.body),
            None,
            None,
        )
        .with_header(header("Content-Type", answer.media))
        .with_header(header("Cache-Control", "no-store"))
        .with_header(header("X-Content-Type-Options", "nosniff"))
        .with_header(header("Referrer-Policy", "no-referrer"))
        .with_header(header("X-Frame-Options", "DENY"));
        if is_page {
            response = response.with_header(header(
                "Content-Security-Policy",
                "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; \
                 connect-src 'self'; img-src 'self' data: blob:; frame-ancestors 'none'",
            ));
        }
        // The browser may have gone; nothing to do then.
        let _ = request.respond(response);
    }

    /// The answer to a checked request.
    fn route(&self, request: &mut Request) -> Answer {
        let url = request.url().to_owned();
        let path = url.split_once('?').map_or(url.as_str(), |(p, _)| p);
        let method = request.method().as_str().to_owned();
        match (method.as_str(), path) {
            ("GET", "/") => Answer::new(
                200,
                "text/html; charset=utf-8",
                self.page.clone().into_bytes(),
            ),
            ("GET", "/api/job") => api::job(&self.job),
            ("POST", "/api/run") => api::with_body(request, &self.job, api::run),
            ("POST", "/api/canonical") => api::with_body(request, &self.job, api::canonical),
            ("POST", "/api/region") => {
                let tolerance = security::query(&url, "tolerance").map(str::to_owned);
                api::with_body(request, &self.job, |text, job| {
                    api::region(text, job, tolerance.as_deref())
                })
            }
            ("POST", "/api/membership") => api::with_body(request, &self.job, api::membership),
            ("POST", "/api/save") => api::with_body(request, &self.job, api::save),
            (_, "/" | "/api/job" | "/api/run" | "/api/canonical" | "/api/region")
            | (_, "/api/membership" | "/api/save") => Answer::problem(405, "method not allowed"),
            _ => Answer::problem(404, "not found"),
        }
    }
}

fn header(name: &str, value: &str) -> Header {
    // Both are ASCII constants here.
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("an ASCII header")
}
