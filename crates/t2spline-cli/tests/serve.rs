//! `t2spline serve` as a user and an attacker meet it: the address printed
//! first, the API's answers against the commands' (`run`, `region`,
//! `membership`, the CLI's messages for every hostile job of the fuzzing
//! corpus), and each rule of its security: loopback only, the token, the
//! `Host` header, cross-origin requests, the size of bodies, no file touched
//! but the job saved over on request (and not over another's change), and
//! Ctrl-C; and hostile clients: lying lengths, stalled heads and bodies, 200
//! at once.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Duration;

use serde_json::Value;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_t2spline"))
}

/// A running `t2spline serve`; killed on drop.
struct Serve {
    child: Child,
    port: u16,
    token: String,
    first_line: String,
}

impl Drop for Serve {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Serve {
    /// `t2spline serve ARGS…` in `dir`, once it has printed its address.
    fn start(args: &[&str], dir: &Path) -> Serve {
        let mut child = bin()
            .arg("serve")
            .args(args)
            .current_dir(dir)
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("the binary runs");
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let first_line = line.trim_end().to_owned();
        let rest = first_line
            .strip_prefix("http://127.0.0.1:")
            .unwrap_or_else(|| panic!("first line {first_line:?}"));
        let (port, token) = rest.split_once("/?token=").expect("a token");
        Serve {
            port: port.parse().unwrap(),
            token: token.to_owned(),
            first_line,
            child,
        }
    }

    fn host(&self) -> String {
        format!("127.0.0.1:{}", self.port)
    }

    /// A request with the right host and token (as the header).
    fn call(&self, method: &str, path: &str, body: &[u8]) -> (u16, Vec<u8>) {
        let token = format!("X-T2spline-Token: {}", self.token);
        self.raw(
            method,
            path,
            &[&format!("Host: {}", self.host()), &token],
            body,
        )
    }

    fn post(&self, path: &str, body: &[u8]) -> (u16, String) {
        let (status, body) = self.call("POST", path, body);
        (status, String::from_utf8(body).unwrap())
    }

    /// A request with exactly these header lines (plus `Content-Length` and
    /// `Connection: close`).
    fn raw(&self, method: &str, path: &str, headers: &[&str], body: &[u8]) -> (u16, Vec<u8>) {
        let mut stream = TcpStream::connect(("127.0.0.1", self.port)).unwrap();
        let mut head = format!("{method} {path} HTTP/1.1\r\n");
        for h in headers {
            head.push_str(h);
            head.push_str("\r\n");
        }
        head.push_str(&format!(
            "Content-Length: {}\r\nConnection: close\r\n\r\n",
            body.len()
        ));
        stream.write_all(head.as_bytes()).unwrap();
        stream.write_all(body).unwrap();
        response(stream)
    }
}

/// Status and body of an HTTP/1.1 response read to its end.
fn response(mut stream: TcpStream) -> (u16, Vec<u8>) {
    let mut bytes = Vec::new();
    stream.read_to_end(&mut bytes).unwrap();
    let split = bytes
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .expect("a head");
    let head = String::from_utf8_lossy(&bytes[..split]).into_owned();
    let status = head[9..12].parse().unwrap();
    let mut body = bytes[split + 4..].to_vec();
    if head
        .to_ascii_lowercase()
        .contains("transfer-encoding: chunked")
    {
        body = unchunk(&body);
    }
    (status, body)
}

fn unchunk(mut bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    loop {
        let end = bytes.windows(2).position(|w| w == b"\r\n").unwrap();
        let size =
            usize::from_str_radix(std::str::from_utf8(&bytes[..end]).unwrap().trim(), 16).unwrap();
        if size == 0 {
            return out;
        }
        out.extend_from_slice(&bytes[end + 2..end + 2 + size]);
        bytes = &bytes[end + 4 + size..];
    }
}

/// `t2spline ARGS…` in `dir`: exit code, standard output and error.
fn cli(args: &[&str], dir: &Path) -> (i32, String, String) {
    let out = bin().args(args).current_dir(dir).output().unwrap();
    (
        out.status.code().expect("exited"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The problems of a 422 answer.
fn problems(body: &str) -> Vec<String> {
    let v: Value = serde_json::from_str(body).unwrap_or_else(|e| panic!("{e}: {body}"));
    v["problems"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap().to_owned())
        .collect()
}

/// The CLI's lines of error, without `t2spline: `.
fn cli_lines(stderr: &str) -> Vec<String> {
    stderr
        .lines()
        .filter(|l| !l.starts_with("t2spline run: note"))
        .map(|l| l.strip_prefix("t2spline: ").unwrap_or(l).to_owned())
        .collect()
}

#[test]
fn the_first_line_is_the_address_with_a_fresh_token_on_loopback_only() {
    let dir = tempfile::tempdir().unwrap();
    let a = Serve::start(&[], dir.path());
    let b = Serve::start(&[], dir.path());
    assert_eq!(
        a.first_line,
        format!("http://127.0.0.1:{}/?token={}", a.port, a.token)
    );
    assert_eq!(a.token.len(), 32);
    assert!(a.token.bytes().all(|c| c.is_ascii_hexdigit()));
    assert_ne!(a.token, b.token, "a token per run");
    // The socket listens on 127.0.0.1 alone: its line in /proc/net/tcp
    // (state 0A, listening) has the local address 0100007F.
    let tcp = std::fs::read_to_string("/proc/net/tcp").unwrap();
    let listening: Vec<&str> = tcp
        .lines()
        .filter(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            f.len() > 3 && f[3] == "0A" && f[1].ends_with(&format!(":{:04X}", a.port))
        })
        .collect();
    assert_eq!(listening.len(), 1, "{listening:?}");
    assert!(
        listening[0]
            .split_whitespace()
            .nth(1)
            .unwrap()
            .starts_with("0100007F:"),
        "{}",
        listening[0]
    );
    let tcp6 = std::fs::read_to_string("/proc/net/tcp6").unwrap_or_default();
    assert!(!tcp6.contains(&format!(":{:04X} ", a.port)), "not on IPv6");
    // The page: self-contained, nothing fetched from elsewhere.
    let (status, page) = a.raw(
        "GET",
        &format!("/?token={}", a.token),
        &[&format!("Host: {}", a.host())],
        b"",
    );
    assert_eq!(status, 200);
    let page = String::from_utf8(page).unwrap();
    assert!(page.starts_with("<!DOCTYPE html>"), "{}", &page[..40]);
    assert!(!page.contains("/*PAGE_JS*/") && page.contains("/api/run"));
    // Only the SVG namespace's name is an address; nothing is loaded.
    // (and an empty icon, so that the browser asks for no `/favicon.ico`).
    let without_namespace = page
        .replace("http://www.w3.org/2000/svg", "")
        .replace(r#"<link rel="icon" href="data:,">"#, "");
    for outside in ["http://", "https://", "src=", "<link", "@import", "url("] {
        assert!(
            !without_namespace.contains(outside),
            "the page refers to {outside}"
        );
    }
}

#[test]
fn requests_without_the_token_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let s = Serve::start(&[], dir.path());
    let host = format!("Host: {}", s.host());
    let job = std::fs::read(root().join("examples/paper-alg-1-1.json")).unwrap();
    for (method, path) in [
        ("GET", "/"),
        ("GET", "/api/job"),
        ("POST", "/api/run"),
        ("POST", "/api/save"),
        ("GET", "/nowhere"),
    ] {
        let body: &[u8] = if method == "POST" { &job } else { b"" };
        let (status, answer) = s.raw(method, path, &[&host], body);
        assert_eq!(status, 403, "{method} {path}");
        assert!(String::from_utf8(answer).unwrap().contains("token"));
        let wrong = format!("{path}?token={}", "0".repeat(32));
        assert_eq!(s.raw(method, &wrong, &[&host], body).0, 403, "wrong token");
        let almost = format!("X-T2spline-Token: {}", &s.token[..31]);
        assert_eq!(
            s.raw(method, path, &[&host, &almost], body).0,
            403,
            "a prefix"
        );
    }
    // With it, as the query or the header.
    let with_query = format!("/api/job?token={}", s.token);
    assert_eq!(s.raw("GET", &with_query, &[&host], b"").0, 200);
    assert_eq!(s.call("GET", "/api/job", b"").0, 200);
    assert_eq!(s.call("GET", "/nowhere", b"").0, 404);
}

#[test]
fn a_host_header_other_than_loopback_and_port_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let s = Serve::start(&[], dir.path());
    let token = format!("X-T2spline-Token: {}", s.token);
    let other_port = format!("Host: 127.0.0.1:{}", s.port.wrapping_add(1));
    for host in [
        "Host: attacker.example",
        &format!("Host: attacker.example:{}", s.port),
        &other_port,
        "Host: 127.0.0.1",
        &format!("Host: 127.0.0.1.attacker.example:{}", s.port),
    ] {
        let (status, body) = s.raw("GET", "/api/job", &[host, &token], b"");
        assert_eq!(status, 403, "{host}");
        assert!(String::from_utf8(body).unwrap().contains("Host"));
    }
    assert_eq!(s.raw("GET", "/api/job", &[&token], b"").0, 403, "no Host");
    let localhost = format!("Host: localhost:{}", s.port);
    assert_eq!(s.raw("GET", "/api/job", &[&localhost, &token], b"").0, 200);
}

#[test]
fn a_cross_origin_post_is_refused_and_changes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    let text = std::fs::read_to_string(root().join("examples/paper-alg-1-1.json")).unwrap();
    std::fs::write(&job, &text).unwrap();
    let s = Serve::start(&["job.json"], dir.path());
    let host = format!("Host: {}", s.host());
    let token = format!("X-T2spline-Token: {}", s.token);
    let changed = text.replace("\"alpha\": 0.8", "\"alpha\": 0.3");
    for origin in [
        "Origin: http://attacker.example",
        "Origin: null",
        &format!("Origin: http://attacker.example:{}", s.port),
        &format!("Origin: https://127.0.0.1:{}", s.port),
    ] {
        let (status, _) = s.raw(
            "POST",
            "/api/save",
            &[&host, &token, origin],
            changed.as_bytes(),
        );
        assert_eq!(status, 403, "{origin}");
        assert_eq!(
            s.raw(
                "POST",
                "/api/run",
                &[&host, &token, origin],
                text.as_bytes()
            )
            .0,
            403
        );
    }
    let (status, _) = s.raw(
        "POST",
        "/api/save",
        &[&host, &token, "Sec-Fetch-Site: cross-site"],
        changed.as_bytes(),
    );
    assert_eq!(status, 403, "Sec-Fetch-Site");
    assert_eq!(std::fs::read_to_string(&job).unwrap(), text, "not saved");
    // The page's own origin may.
    let own = format!("Origin: http://{}", s.host());
    assert_eq!(
        s.raw("POST", "/api/run", &[&host, &token, &own], text.as_bytes())
            .0,
        200
    );
}

#[test]
fn run_answers_the_bytes_of_t2spline_run() {
    let dir = tempfile::tempdir().unwrap();
    for job in [
        "examples/paper-alg-1-1.json",
        "fixtures/spiral-3d.json",
        "examples/fuzzy-cylinder.json",
    ] {
        let path = root().join(job);
        let s = Serve::start(&[path.to_str().unwrap()], dir.path());
        let (code, expected, _) = cli(&["run", path.to_str().unwrap()], dir.path());
        assert_eq!(code, 0);
        let text = std::fs::read(&path).unwrap();
        let (status, body) = s.post("/api/run", &text);
        assert_eq!(status, 200, "{job}: {body}");
        assert!(body == expected, "{job}: the bytes of run");
        // The job as read at start, and its canonical form that runs the same.
        let (status, start) = s.call("GET", "/api/job", b"");
        assert_eq!(status, 200);
        let start: Value = serde_json::from_slice(&start).unwrap();
        assert_eq!(start["text"].as_str().unwrap().as_bytes(), text);
        assert_eq!(start["saveable"], Value::Bool(true));
        let (status, canonical) = s.post("/api/canonical", &text);
        assert_eq!(status, 200);
        let (status, again) = s.post("/api/run", canonical.as_bytes());
        assert_eq!(status, 200);
        let a: Value = serde_json::from_str(&again).unwrap();
        let b: Value = serde_json::from_str(&expected).unwrap();
        assert_eq!(a["error"], b["error"], "{job}: canonical runs the same");
        assert_eq!(a["curves"], b["curves"], "{job}");
    }
}

#[test]
fn region_and_membership_answer_the_commands_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let job = root().join("examples/paper-alg-1-1.json");
    let points = root().join("examples/query-points.csv");
    let s = Serve::start(&[], dir.path());
    let text = std::fs::read_to_string(&job).unwrap();
    for alpha in ["0.8", "0.3"] {
        let at = text.replace("\"alpha\": 0.8", &format!("\"alpha\": {alpha}"));
        let (status, body) = s.post("/api/region", at.as_bytes());
        assert_eq!(status, 200, "{body}");
        let (code, expected, _) = cli(
            &["region", job.to_str().unwrap(), "--alpha", alpha],
            dir.path(),
        );
        assert_eq!(code, 0);
        assert!(body == expected, "alpha {alpha}: region's bytes");
    }
    let request =
        serde_json::json!({"job": text, "points": std::fs::read_to_string(&points).unwrap()});
    let (status, body) = s.post("/api/membership", request.to_string().as_bytes());
    assert_eq!(status, 200, "{body}");
    let (_, expected, _) = cli(
        &[
            "membership",
            job.to_str().unwrap(),
            points.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert_eq!(body, expected);
    let (status, body) = s.post("/api/membership", b"{\"job\": 1}");
    assert_eq!(status, 422, "{body}");
    // A surface has no regions: the command's message.
    let surface = std::fs::read(root().join("examples/fuzzy-cylinder.json")).unwrap();
    let (status, body) = s.post("/api/region", &surface);
    assert_eq!(status, 422);
    assert!(
        problems(&body)[0].starts_with("JOB: regions are drawn for curves"),
        "{body}"
    );
}

#[test]
fn the_hostile_job_corpus_gets_the_clis_messages_and_never_a_crash() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(
        root().join("examples/paper-alg-1-1.json"),
        dir.path().join("job.json"),
    )
    .unwrap();
    let s = Serve::start(&["job.json"], dir.path());
    let corpus = tempfile::tempdir().unwrap();
    let mut files: Vec<PathBuf> = ["fuzz/seeds/job", "fuzz/regressions/job"]
        .iter()
        .flat_map(|d| std::fs::read_dir(root().join(d)).unwrap())
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    assert!(files.len() >= 12, "{files:?}");
    let mut refused = 0;
    for file in &files {
        let bytes = std::fs::read(file).unwrap();
        // The CLI on the same bytes under the same name.
        std::fs::write(corpus.path().join("job.json"), &bytes).unwrap();
        let (code, stdout, stderr) = cli(&["run", "job.json"], corpus.path());
        let (status, body) = s.post("/api/run", &bytes);
        match code {
            0 => {
                assert_eq!(status, 200, "{file:?}: {body}");
                assert!(body == stdout, "{file:?}: run's bytes");
            }
            2 => {
                refused += 1;
                assert_eq!(status, 422, "{file:?}: {body}");
                assert_eq!(problems(&body), cli_lines(&stderr), "{file:?}");
            }
            other => panic!("{file:?}: run exits {other}: {stderr}"),
        }
        for endpoint in [
            "/api/region",
            "/api/canonical",
            "/api/save",
            "/api/membership",
        ] {
            let (status, body) = s.post(endpoint, &bytes);
            assert!(
                matches!(status, 200 | 422),
                "{file:?} {endpoint}: {status} {body}"
            );
            if status == 422 {
                assert!(!problems(&body).is_empty());
            }
        }
    }
    assert!(refused >= 3, "the corpus holds bad jobs: {refused}");
    // Still serving.
    assert_eq!(s.call("GET", "/api/job", b"").0, 200);
}

#[test]
fn bodies_are_limited_as_job_files_are() {
    let dir = tempfile::tempdir().unwrap();
    let s = Serve::start(&[], dir.path());
    let limit: u64 = 64 << 20;
    // A declared length past the limit: refused before the body is sent.
    let mut stream = TcpStream::connect(("127.0.0.1", s.port)).unwrap();
    write!(
        stream,
        "POST /api/run HTTP/1.1\r\nHost: {}\r\nX-T2spline-Token: {}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        s.host(),
        s.token,
        limit + 1
    )
    .unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(20)))
        .unwrap();
    let (status, body) = response(stream);
    assert_eq!(status, 413);
    assert!(String::from_utf8(body).unwrap().contains("64 MiB"));
    // An undeclared one (chunked) is refused unread: only a declared length
    // can be checked before the body is read.
    let mut stream = TcpStream::connect(("127.0.0.1", s.port)).unwrap();
    write!(
        stream,
        "POST /api/run HTTP/1.1\r\nHost: {}\r\nX-T2spline-Token: {}\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n5\r\nhello\r\n",
        s.host(),
        s.token
    )
    .unwrap();
    let (status, body) = response(stream);
    assert_eq!(status, 411);
    assert!(String::from_utf8(body).unwrap().contains("Content-Length"));
    // One of the limit's size is read, and answered as `run` answers it.
    let (status, body) = s.post("/api/run", &vec![b' '; limit as usize]);
    assert_eq!(status, 422);
    let mut child = bin()
        .args(["run", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(&vec![b' '; limit as usize]).unwrap();
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let expected: Vec<String> = cli_lines(&String::from_utf8(out.stderr).unwrap())
        .iter()
        .map(|l| l.replace("<stdin>", "paper-alg-1-1.json"))
        .collect();
    assert_eq!(problems(&body), expected);
}

#[test]
fn only_the_named_job_is_written_and_only_when_asked() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    let text = std::fs::read_to_string(root().join("examples/paper-alg-1-1.json")).unwrap();
    std::fs::write(&job, &text).unwrap();
    let s = Serve::start(&["job.json"], dir.path());
    let listing = || {
        let mut names: Vec<String> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    };
    let job_file = text.as_bytes();
    assert_eq!(s.post("/api/run", job_file).0, 200);
    assert_eq!(s.post("/api/region", job_file).0, 200);
    assert_eq!(
        std::fs::read_to_string(&job).unwrap(),
        text,
        "running saves nothing"
    );
    assert_eq!(listing(), ["job.json"]);
    // A bad job is not saved.
    let (status, body) = s.post("/api/save", b"{\"order\": 3}");
    assert_eq!(status, 422, "{body}");
    assert_eq!(std::fs::read_to_string(&job).unwrap(), text);
    // A good one replaces the file whole, and nothing else appears.
    let changed = text.replace("\"alpha\": 0.8", "\"alpha\": 0.3");
    let (status, body) = s.post("/api/save", changed.as_bytes());
    assert_eq!(status, 200, "{body}");
    assert_eq!(std::fs::read_to_string(&job).unwrap(), changed);
    assert_eq!(listing(), ["job.json"]);
    // The example was named by nobody: nothing to save over.
    let other = tempfile::tempdir().unwrap();
    let e = Serve::start(&[], other.path());
    let (status, body) = e.post("/api/save", changed.as_bytes());
    assert_eq!(status, 409, "{body}");
    assert_eq!(std::fs::read_dir(other.path()).unwrap().count(), 0);
}

#[test]
fn a_save_over_a_file_changed_on_disk_is_refused_unless_asked() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    let text = std::fs::read_to_string(root().join("examples/paper-alg-1-1.json")).unwrap();
    std::fs::write(&job, &text).unwrap();
    let s = Serve::start(&["job.json"], dir.path());
    let page = text.replace("\"alpha\": 0.8", "\"alpha\": 0.3");
    // Someone else edits the file after the server read it.
    let theirs = text.replace("\"alpha\": 0.8", "\"alpha\": 0.6");
    std::fs::write(&job, &theirs).unwrap();
    let (status, body) = s.post("/api/save", page.as_bytes());
    assert_eq!(status, 409, "{body}");
    let answer: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(answer["changed"], true);
    assert_eq!(
        problems(&body),
        ["job.json: the file changed on disk since it was read; reload it, or save again to overwrite it"]
    );
    assert_eq!(
        std::fs::read_to_string(&job).unwrap(),
        theirs,
        "their change is kept"
    );
    // Reloading gives their text, and a save after it is no longer refused.
    let (status, body) = s.call("GET", "/api/job?reload=1", b"");
    assert_eq!(status, 200);
    let reloaded: Value = serde_json::from_slice(&body).unwrap();
    assert_eq!(reloaded["text"], theirs.as_str());
    let (status, body) = s.post("/api/save", page.as_bytes());
    assert_eq!(status, 200, "{body}");
    assert_eq!(std::fs::read_to_string(&job).unwrap(), page);
    // Changed again: `overwrite=1` writes over it, as the page offers.
    std::fs::write(&job, &theirs).unwrap();
    assert_eq!(s.post("/api/save", page.as_bytes()).0, 409);
    let (status, body) = s.post("/api/save?overwrite=1", page.as_bytes());
    assert_eq!(status, 200, "{body}");
    assert_eq!(std::fs::read_to_string(&job).unwrap(), page);
    // A file deleted since is a change too.
    std::fs::remove_file(&job).unwrap();
    assert_eq!(s.post("/api/save", page.as_bytes()).0, 409);
}

/// Sends `head` (and no more) on a new connection.
fn send_head(s: &Serve, head: &str) -> TcpStream {
    let mut stream = TcpStream::connect(("127.0.0.1", s.port)).unwrap();
    stream.write_all(head.as_bytes()).unwrap();
    stream
}

/// Whether `stream` has been answered (or closed) yet, without waiting.
fn answered(stream: &TcpStream) -> bool {
    stream.set_nonblocking(true).unwrap();
    let mut byte = [0u8; 1];
    let seen =
        !matches!(stream.peek(&mut byte), Err(e) if e.kind() == std::io::ErrorKind::WouldBlock);
    stream.set_nonblocking(false).unwrap();
    seen
}

#[test]
fn a_lying_content_length_is_refused_unread_and_the_server_lives() {
    let dir = tempfile::tempdir().unwrap();
    let s = Serve::start(&[], dir.path());
    let host = s.host();
    // Without the token: 403, nothing read or allocated from the length.
    for length in ["1000000000000000", "18446744073709551615"] {
        let head =
            format!("POST /api/run HTTP/1.1\r\nHost: {host}\r\nContent-Length: {length}\r\n\r\n");
        assert_eq!(response(send_head(&s, &head)).0, 403);
    }
    // With it: past the cap 413; not a number 400.
    let token = &s.token;
    for (length, status) in [("1000000000000000", 413), ("1e15", 400), ("-1", 400)] {
        let head = format!(
            "POST /api/run HTTP/1.1\r\nHost: {host}\r\nX-T2spline-Token: {token}\r\nContent-Length: {length}\r\n\r\n"
        );
        assert_eq!(
            response(send_head(&s, &head)).0,
            status,
            "Content-Length: {length}"
        );
    }
    // A head without end, past its limit: 431.
    let long = format!(
        "GET / HTTP/1.1\r\nHost: {host}\r\nX-Padding: {}\r\n",
        "a".repeat(20_000)
    );
    let mut stream = TcpStream::connect(("127.0.0.1", s.port)).unwrap();
    let _ = stream.write_all(long.as_bytes());
    assert_eq!(response(stream).0, 431);
    let (status, _) = s.call("GET", "/api/job", b"");
    assert_eq!(status, 200, "the server still answers");
}

#[test]
fn a_stalled_client_blocks_no_other_and_is_timed_out() {
    let dir = tempfile::tempdir().unwrap();
    let s = Serve::start(&[], dir.path());
    let host = s.host();
    let token = &s.token;
    // One says nothing, one stops in its head, one stops in its body.
    let silent = TcpStream::connect(("127.0.0.1", s.port)).unwrap();
    let half_head = send_head(&s, &format!("POST /api/run HTTP/1.1\r\nHost: {host}\r\n"));
    let half_body = send_head(
        &s,
        &format!("POST /api/run HTTP/1.1\r\nHost: {host}\r\nX-T2spline-Token: {token}\r\nContent-Length: 1000\r\n\r\n{{\"order\""),
    );
    // Meanwhile others are answered, while the stalled are not.
    let example = std::fs::read(root().join("examples/paper-alg-1-1.json")).unwrap();
    for _ in 0..3 {
        assert_eq!(s.call("GET", "/api/job", b"").0, 200);
        assert_eq!(s.call("POST", "/api/run", &example).0, 200);
    }
    assert!(
        !answered(&half_body),
        "a stalled body is still being waited for"
    );
    // Within seconds the stalled are let go: the body with 408, the head
    // with 408, the silent one closed.
    for stream in [&half_body, &half_head, &silent] {
        stream
            .set_read_timeout(Some(Duration::from_secs(60)))
            .unwrap();
    }
    let (status, body) = response(half_body);
    assert_eq!(status, 408);
    assert!(String::from_utf8(body)
        .unwrap()
        .contains("did not arrive within"));
    assert_eq!(response(half_head).0, 408);
    let mut rest = Vec::new();
    let mut silent = silent;
    silent.read_to_end(&mut rest).unwrap();
    assert!(
        rest.is_empty(),
        "a silent connection is closed without an answer"
    );
}

#[test]
fn two_hundred_clients_at_once_are_each_answered() {
    let dir = tempfile::tempdir().unwrap();
    let s = Serve::start(&[], dir.path());
    let (port, host, token) = (s.port, s.host(), s.token.clone());
    let example = std::fs::read(root().join("examples/paper-alg-1-1.json")).unwrap();
    let expected_run = cli(&["run", "examples/paper-alg-1-1.json"], &root()).1;
    let clients: Vec<_> = (0..200)
        .map(|i| {
            let (host, token, example) = (host.clone(), token.clone(), example.clone());
            std::thread::spawn(move || {
                let mut stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
                let (head, body, status): (String, &[u8], u16) = match i % 4 {
                    0 => (format!("GET /api/job HTTP/1.1\r\nHost: {host}\r\nX-T2spline-Token: {token}\r\n\r\n"), b"", 200),
                    1 => (format!("GET /api/job HTTP/1.1\r\nHost: {host}\r\nX-T2spline-Token: {}\r\n\r\n", "0".repeat(32)), b"", 403),
                    2 => (format!("POST /api/run HTTP/1.1\r\nHost: {host}\r\nContent-Length: 999999999999\r\n\r\n"), b"", 403),
                    _ => (
                        format!("POST /api/run HTTP/1.1\r\nHost: {host}\r\nX-T2spline-Token: {token}\r\nContent-Length: {}\r\n\r\n", example.len()),
                        &example,
                        200,
                    ),
                };
                stream.write_all(head.as_bytes()).unwrap();
                stream.write_all(body).unwrap();
                stream.set_read_timeout(Some(Duration::from_secs(120))).unwrap();
                let (got, answer) = response(stream);
                assert_eq!(got, status, "client {i}");
                (i % 4 == 3).then(|| String::from_utf8(answer).unwrap())
            })
        })
        .collect();
    // A legitimate request is answered while they are.
    assert_eq!(s.call("GET", "/api/job", b"").0, 200);
    for client in clients {
        if let Some(run) = client.join().expect("every client answered as expected") {
            assert_eq!(run, expected_run);
        }
    }
}

#[test]
fn ctrl_c_stops_it() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let mut s = Serve::start(&[], dir.path());
    assert_eq!(s.call("GET", "/api/job", b"").0, 200);
    let sent = Command::new("kill")
        .args(["-INT", &s.child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let status = s.child.wait().unwrap();
    assert_eq!(status.signal(), Some(2), "{status:?}");
    assert!(
        TcpStream::connect(("127.0.0.1", s.port)).is_err(),
        "the port is closed"
    );
}
