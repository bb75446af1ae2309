//! The HTML report in a real browser: Debian's headless Chromium driven through
//! ChromeDriver (WebDriver over HTTP on loopback).
//!
//! The page must load with no console errors and no network requests; moving
//! the slider must change the figures, and every number shown must be the text
//! `t2spline run --alpha A` prints for the alpha shown; selecting another type
//! reduction must show what `t2spline run --type-reduction NAME` prints.
//!
//! Without `chromium` and `chromedriver` the test says it was skipped and
//! passes, unless `T2SPLINE_REQUIRE_BROWSER=1` (set by CI), when it fails.

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use assert_cmd::cargo::CommandCargoExt;
use serde_json::{json, Value};

const FLAGS: [&str; 9] = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--window-size=1300,1600",
];

fn find(names: &[&str]) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    names.iter().find_map(|n| {
        std::env::split_paths(&path)
            .map(|d| d.join(n))
            .find(|p| p.is_file())
    })
}

/// Chromium and ChromeDriver, or `None` after saying why the test is skipped.
fn browser() -> Option<(PathBuf, PathBuf)> {
    let found = (
        find(&["chromium", "chromium-browser"]),
        find(&["chromedriver"]),
    );
    match found {
        (Some(c), Some(d)) => Some((c, d)),
        _ => {
            let msg = "chromium and chromedriver are not installed (Debian packages `chromium` and `chromium-driver`)";
            assert!(
                std::env::var("T2SPLINE_REQUIRE_BROWSER").as_deref() != Ok("1"),
                "T2SPLINE_REQUIRE_BROWSER=1 but {msg}"
            );
            eprintln!("SKIPPED report_browser: {msg}");
            None
        }
    }
}

/// ChromeDriver on a free loopback port; killed on drop.
struct Driver {
    child: Child,
    base: String,
}

impl Drop for Driver {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Driver {
    fn start(path: &Path) -> Driver {
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
            child,
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

    fn post(&self, path: &str, body: &Value) -> Value {
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

/// The value at a cell key in a result file (see `report::tables`).
fn lookup<'a>(result: &'a Value, key: &str) -> &'a Value {
    let mut v = if key.starts_with("error.") {
        result
    } else {
        &result["control_points"]
    };
    for part in key.split('.') {
        v = match part.parse::<usize>() {
            Ok(i) => &v[i],
            Err(_) => &v[part],
        };
    }
    v
}

fn run_json(job: &Path, alpha: &str) -> Value {
    run_json_with(job, &["--alpha", alpha])
}

/// `t2spline run JOB --samples 2 ARGS…` as JSON.
fn run_json_with(job: &Path, args: &[&str]) -> Value {
    let out = Command::cargo_bin("t2spline")
        .unwrap()
        .args(["run", job.to_str().unwrap(), "--samples", "2"])
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

const READ_PAGE: &str = r#"
const cells = Array.from(document.querySelectorAll("td[data-key]")).map(td => [td.dataset.key, td.textContent]);
const part = id => { const e = document.getElementById(id); return e ? e.innerHTML : null; };
return { alpha: document.getElementById("alpha-value").textContent, cells: cells,
         max: Number(document.getElementById("alpha").max),
         s4: part("s4-0") === null ? null : Array.from(document.querySelectorAll("[id^=s4-]")).map(e => e.innerHTML).join(""),
         resources: performance.getEntriesByType("resource").length };
"#;

const SELECT_REDUCTION: &str = r#"
const s = document.getElementById("reduction");
s.value = arguments[0];
s.dispatchEvent(new Event("change", { bubbles: true }));
return document.getElementById("alpha").disabled;
"#;

/// Every cell of the page's tables equals the result's value at its key.
fn check_cells(page: &Value, result: &Value, what: &str) {
    let cells = page["cells"].as_array().unwrap();
    assert!(cells.len() > 20, "tables have cells: {}", cells.len());
    for cell in cells {
        let (key, text) = (cell[0].as_str().unwrap(), cell[1].as_str().unwrap());
        let expected = lookup(result, key);
        assert!(
            !expected.is_null() || text == "null",
            "{key} missing in the result"
        );
        assert_eq!(text, expected.to_string(), "{what}: {key}");
    }
}

const MOVE_SLIDER: &str = r#"
const s = document.getElementById("alpha");
s.value = String(arguments[0]);
s.dispatchEvent(new Event("input", { bubbles: true }));
return s.value;
"#;

fn check_report(chromium: &Path, driver: &Driver, job: &Path, stops_to_check: &[usize]) {
    let dir = tempfile::tempdir().unwrap();
    let status = Command::cargo_bin("t2spline")
        .unwrap()
        .args([
            "report",
            job.to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
        ])
        .stdout(Stdio::null())
        .status()
        .unwrap();
    assert!(status.success());
    let html = dir.path().join("report.html");
    let profile = tempfile::tempdir().unwrap();
    let mut args: Vec<String> = FLAGS.iter().map(|s| (*s).to_owned()).collect();
    args.push(format!("--user-data-dir={}", profile.path().display()));
    let session = driver.post(
        "/session",
        &json!({"capabilities": {"alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": {"binary": chromium, "args": args},
            "goog:loggingPrefs": {"browser": "ALL"}
        }}}),
    );
    let id = session["sessionId"].as_str().expect("a session").to_owned();
    let s = |p: &str| format!("/session/{id}{p}");
    driver.post(
        &s("/url"),
        &json!({"url": format!("file://{}", html.display())}),
    );
    let exec = |script: &str, args: Value| {
        driver.post(
            &s("/execute/sync"),
            &json!({"script": script, "args": args}),
        )
    };

    let first = exec(READ_PAGE, json!([]));
    assert_eq!(
        first["resources"],
        json!(0),
        "the page loaded external resources"
    );
    let max = first["max"].as_u64().unwrap() as usize;
    let mut seen_s4 = Vec::new();
    let mut stops: Vec<usize> = stops_to_check.iter().map(|&k| k.min(max)).collect();
    stops.push(max);
    for k in stops {
        exec(MOVE_SLIDER, json!([k]));
        let page = exec(READ_PAGE, json!([]));
        let alpha = page["alpha"].as_str().unwrap().to_owned();
        let result = run_json(job, &alpha);
        assert_eq!(
            result["alpha"].to_string(),
            alpha,
            "alpha shown at stop {k}"
        );
        check_cells(&page, &result, &format!("alpha {alpha}"));
        seen_s4.push(page["s4"].as_str().unwrap_or_default().to_owned());
    }
    seen_s4.dedup();
    assert!(
        seen_s4.len() > 2,
        "the stage 4 figure changes with the slider"
    );
    // Every other type reduction: its own frame, the slider at rest, and
    // every number that of `run --type-reduction NAME`.
    let paper_page = exec(READ_PAGE, json!([]));
    for name in ["centroid", "nie-tan", "alpha-planes"] {
        assert_eq!(
            exec(SELECT_REDUCTION, json!([name])),
            json!(true),
            "{name}: slider at rest"
        );
        let page = exec(READ_PAGE, json!([]));
        assert_eq!(page["alpha"], json!("not used"), "{name}");
        let result = run_json_with(job, &["--type-reduction", name]);
        check_cells(&page, &result, name);
        assert_ne!(page["s4"], paper_page["s4"], "{name}: stage 4 changes");
    }
    assert_eq!(exec(SELECT_REDUCTION, json!(["paper"])), json!(false));
    let back = exec(READ_PAGE, json!([]));
    assert_eq!(
        back["cells"], paper_page["cells"],
        "back to the paper at the same stop"
    );

    let logs = driver.post(&s("/se/log"), &json!({"type": "browser"}));
    let errors: Vec<&Value> = logs
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["level"] == json!("SEVERE") || e["level"] == json!("WARNING"))
        .collect();
    assert!(errors.is_empty(), "console errors: {errors:?}");
    let _ = ureq::delete(&format!("{}{}", driver.base, s(""))).call();
}

#[test]
fn report_in_headless_chromium_matches_t2spline_run() {
    let Some((chromium, chromedriver)) = browser() else {
        return;
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let driver = Driver::start(&chromedriver);
    // The paper's example: stop 60 is alpha = h = 0.6, 61 is just above.
    check_report(
        &chromium,
        &driver,
        &root.join("examples/paper-alg-1-1.json"),
        &[0, 37, 60, 61, 80],
    );
    // A 3-D job with mixed heights (0.4 on z, 0.7 elsewhere).
    check_report(
        &chromium,
        &driver,
        &root.join("fixtures/spiral-3d.json"),
        &[0, 40, 41, 55, 71, 72],
    );
}
