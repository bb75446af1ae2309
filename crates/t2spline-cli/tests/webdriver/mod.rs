//! The browser tests' harness: headless Chromium driven through ChromeDriver
//! (the W3C WebDriver protocol over loopback), shared by the report's and the
//! editor's tests. Without the browser a test is skipped with a message,
//! unless `T2SPLINE_REQUIRE_BROWSER=1`, when it fails.

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::{json, Value};

/// Chromium's flags for a window `size` (`"1300,1000"`): headless, and no
/// traffic of its own.
pub fn flags(size: &str) -> Vec<String> {
    [
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .chain([format!("--window-size={size}")])
    .collect()
}

fn find(names: &[&str]) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    names.iter().find_map(|n| {
        std::env::split_paths(&path)
            .map(|d| d.join(n))
            .find(|p| p.is_file())
    })
}

/// Chromium and ChromeDriver, or `None` after saying why the test `test` is
/// skipped.
pub fn browser(test: &str) -> Option<(PathBuf, PathBuf)> {
    match (
        find(&["chromium", "chromium-browser"]),
        find(&["chromedriver"]),
    ) {
        (Some(c), Some(d)) => Some((c, d)),
        _ => {
            let msg = "chromium and chromedriver are not installed (Debian packages `chromium` and `chromium-driver`)";
            assert!(
                std::env::var("T2SPLINE_REQUIRE_BROWSER").as_deref() != Ok("1"),
                "T2SPLINE_REQUIRE_BROWSER=1 but {msg}"
            );
            eprintln!("SKIPPED {test}: {msg}");
            None
        }
    }
}

/// A child process killed on drop.
pub struct Killed(pub Child);

impl Drop for Killed {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// ChromeDriver on a free loopback port; killed on drop.
pub struct Driver {
    _child: Killed,
    /// `http://127.0.0.1:PORT`.
    pub base: String,
}

impl Driver {
    /// Starts the ChromeDriver at `path` and waits until it is ready.
    pub fn start(path: &Path) -> Driver {
        let port = TcpListener::bind("127.0.0.1:0")
            .unwrap()
            .local_addr()
            .unwrap()
            .port();
        let child = Command::new(path)
            .arg(format!("--port={port}"))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("chromedriver starts");
        let driver = Driver {
            _child: Killed(child),
            base: format!("http://127.0.0.1:{port}"),
        };
        let deadline = Instant::now() + Duration::from_secs(30);
        while Instant::now() < deadline {
            if let Ok(r) = ureq::get(&format!("{}/status", driver.base)).call() {
                let v: Value = r.into_json().unwrap();
                if v["value"]["ready"] == json!(true) {
                    return driver;
                }
            }
            std::thread::sleep(Duration::from_millis(100));
        }
        panic!("chromedriver did not become ready");
    }

    /// POSTs `body` to the driver's `path`; its `value`.
    pub fn post(&self, path: &str, body: &Value) -> Value {
        let url = format!("{}{path}", self.base);
        match ureq::post(&url).send_json(body.clone()) {
            Ok(r) => r.into_json::<Value>().unwrap()["value"].take(),
            Err(ureq::Error::Status(code, r)) => {
                panic!("{url}: {code}: {}", r.into_string().unwrap_or_default())
            }
            Err(e) => panic!("{url}: {e}"),
        }
    }
}

impl Driver {
    /// A new browser session of Chromium at `chromium`, its window `size`
    /// (`"1300,1000"`), its profile in the folder `profile`, the browser's
    /// console kept; the session's id.
    pub fn session(&self, chromium: &Path, profile: &Path, size: &str) -> String {
        let mut args = flags(size);
        args.push(format!("--user-data-dir={}", profile.display()));
        let s = self.post(
            "/session",
            &json!({"capabilities": {"alwaysMatch": {
                "browserName": "chrome",
                "goog:chromeOptions": {"binary": chromium, "args": args},
                "goog:loggingPrefs": {"browser": "ALL"},
                "timeouts": {"script": 60000}
            }}}),
        );
        s["sessionId"].as_str().expect("a session").to_owned()
    }
}

/// A page of a session: scripts run in it.
pub struct Page<'a> {
    /// The driver of its session.
    pub driver: &'a Driver,
    /// The session's id.
    pub id: String,
}

impl Page<'_> {
    /// Runs `script` with `args`; its return value.
    pub fn exec(&self, script: &str, args: Value) -> Value {
        self.driver.post(
            &format!("/session/{}/execute/sync", self.id),
            &json!({"script": script, "args": args}),
        )
    }

    /// Runs `script` with `args`, which calls its last argument when done;
    /// the value it gives.
    #[allow(dead_code)] // the editor's test needs only `exec`
    pub fn exec_async(&self, script: &str, args: Value) -> Value {
        self.driver.post(
            &format!("/session/{}/execute/async", self.id),
            &json!({"script": script, "args": args}),
        )
    }
}
