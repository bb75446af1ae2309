//! The HTML report in a real browser: Debian's headless Chromium driven through
//! ChromeDriver (WebDriver over HTTP on loopback).
//!
//! The page must load with no console errors and no network requests; moving
//! the slider or typing an alpha must change the figures; every number shown
//! must be `t2spline run --alpha A`'s, rounded where shown and exact in its
//! `data-value`; selecting another type reduction must show the numbers and
//! downloads of `t2spline run --type-reduction NAME`, with the slider at
//! rest; every download must be the bytes `run` writes (JSON, CSV) or the
//! figure (SVG, PNG at 300 dpi); the page must not scroll sideways at 800
//! pixels, headings must show below the sticky bar after jumping to them,
//! and the page must print.
//!
//! Without `chromium` and `chromedriver` the test says it was skipped and
//! passes, unless `T2SPLINE_REQUIRE_BROWSER=1` (set by CI), when it fails.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use assert_cmd::cargo::CommandCargoExt;
use serde_json::{json, Value};

use webdriver::{browser, Driver, Page};

mod webdriver;

/// The value at a cell key in a result file (see the report's tables).
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

/// `t2spline run JOB ARGS…` (standard output) and the CSV files of
/// `--csv`, as the binary writes them.
fn run_files(job: &Path, args: &[&str]) -> (String, Vec<(String, String)>) {
    let dir = tempfile::tempdir().unwrap();
    let out = Command::cargo_bin("t2spline")
        .unwrap()
        .args(["run", job.to_str().unwrap()])
        .args(args)
        .arg("--csv")
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut csv: Vec<(String, String)> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            (
                e.file_name().to_string_lossy().into_owned(),
                std::fs::read_to_string(e.path()).unwrap(),
            )
        })
        .collect();
    csv.sort();
    (String::from_utf8(out.stdout).unwrap(), csv)
}

const READ_PAGE: &str = r#"
const cells = Array.from(document.querySelectorAll("td[data-key]")).map(td => [td.dataset.key, td.dataset.value, td.textContent]);
const bar = ["m-max", "m-max-at", "m-max-at-v", "m-rms"].filter(id => document.getElementById(id)).map(id => { const e = document.getElementById(id); return [id, e.dataset.value, e.textContent]; });
return { alpha: document.getElementById("alpha-value").dataset.value, shown: document.getElementById("alpha-value").textContent,
         reduction: document.getElementById("reduction").value, disabled: document.getElementById("alpha").disabled,
         field: document.getElementById("alpha-field").value, slider: Number(document.getElementById("alpha").value),
         cells: cells, bar: bar, max: Number(document.getElementById("alpha").max),
         s4: Array.from(document.querySelectorAll("[id^=s4-]")).map(e => e.innerHTML).join(""),
         note: document.getElementById("alpha-note").textContent,
         resources: performance.getEntriesByType("resource").length };
"#;

const SELECT_REDUCTION: &str = r#"
const s = document.getElementById("reduction");
s.value = arguments[0];
s.dispatchEvent(new Event("change", { bubbles: true }));
return s.value;
"#;

const MOVE_SLIDER: &str = r#"
const s = document.getElementById("alpha");
s.value = String(arguments[0]);
s.dispatchEvent(new Event("input", { bubbles: true }));
return s.value;
"#;

const TYPE_ALPHA: &str = r#"
const f = document.getElementById("alpha-field");
f.value = arguments[0];
f.dispatchEvent(new Event("change", { bubbles: true }));
return f.value;
"#;

const DOWNLOADS: &str = r#"
const r = window.t2splineReport;
const files = Array.from(document.querySelectorAll("button.dl[data-file]")).map(b => b.dataset.file);
return { files: files.map(f => [f, r.fileText(f)]),
         svgs: Array.from(document.querySelectorAll("button.dl[data-svg]")).map(b => [b.dataset.svg, r.svgText(b.dataset.svg)]),
         pngs: Array.from(document.querySelectorAll("button.dl[data-png]")).map(b => b.dataset.png) };
"#;

const FILES_ENABLED: &str = r#"
const b = document.querySelector("button.dl[data-file]");
return { enabled: !b.disabled, text: window.t2splineReport.fileText(b.dataset.file) };
"#;

const PNG: &str = r#"
const done = arguments[arguments.length - 1];
window.t2splineReport.pngBytes(arguments[0]).then(b => {
  let s = ""; for (let i = 0; i < b.length; i++) s += String.fromCharCode(b[i]);
  done(btoa(s));
}, e => done("error: " + e));
"#;

const LAYOUT: &str = r#"
const bar = document.getElementById("controls").getBoundingClientRect().bottom;
const out = { scroll: document.documentElement.scrollWidth, width: window.innerWidth, headings: [] };
for (const a of document.querySelectorAll(".toc a")) {
  a.click();
  const h = document.querySelector(a.getAttribute("href") + " h2");
  const r = h.getBoundingClientRect();
  out.headings.push([a.getAttribute("href"), r.top, r.bottom, document.getElementById("controls").getBoundingClientRect().bottom, window.innerHeight]);
}
return out;
"#;

/// `text` is `exact` rounded: the same number to four significant digits.
fn is_rounding(text: &str, exact: &str) -> bool {
    if exact == "null" {
        return text == "null";
    }
    match (text.parse::<f64>(), exact.parse::<f64>()) {
        (Ok(t), Ok(e)) => (t - e).abs() <= 5e-4 * e.abs().max(1e-300) && text.len() <= 10,
        _ => false,
    }
}

impl Page<'_> {
    fn wait_ready(&self) {
        let deadline = Instant::now() + Duration::from_secs(60);
        while Instant::now() < deadline {
            if self.exec("return document.body.dataset.ready === '1';", json!([])) == json!(true) {
                return;
            }
            std::thread::sleep(Duration::from_millis(100));
        }
        panic!("the report's data did not unpack");
    }

    /// Every number on the page is run's at the shown alpha, or with the
    /// selected type reduction when it does not use alpha; returns run's
    /// standard output and CSV files.
    fn check_numbers(&self, job: &Path, page: &Value) -> (String, Vec<(String, String)>) {
        let alpha = page["alpha"].as_str().unwrap().to_owned();
        let reduction = page["reduction"].as_str().unwrap().to_owned();
        let paper = reduction == "paper";
        let args = if paper {
            ["--alpha", alpha.as_str()]
        } else {
            ["--type-reduction", reduction.as_str()]
        };
        let (stdout, csv) = run_files(job, &args);
        let result: Value = serde_json::from_str(&stdout).unwrap();
        assert_eq!(result["type_reduction"], json!(reduction));
        if paper {
            assert_eq!(result["alpha"].to_string(), alpha, "alpha shown");
            assert!(is_rounding(page["shown"].as_str().unwrap(), &alpha));
        } else {
            assert_eq!(result["alpha_used"], json!(false), "{reduction}");
            assert_eq!(page["shown"], json!("not used"), "{reduction}");
        }
        let what = if paper { alpha } else { reduction };
        let cells = page["cells"].as_array().unwrap();
        assert!(cells.len() > 20, "tables have cells: {}", cells.len());
        for cell in cells.iter().chain(page["bar"].as_array().unwrap()) {
            let (key, exact, text) = (
                cell[0].as_str().unwrap(),
                cell[1].as_str().unwrap(),
                cell[2].as_str().unwrap(),
            );
            // A surface's max_at is (u, v).
            let surface = result["error"]["max_at"].is_array();
            let key = match key {
                "m-max" => "error.max",
                "m-max-at" if surface => "error.max_at.0",
                "m-max-at-v" => "error.max_at.1",
                "m-max-at" => "error.max_at",
                "m-rms" => "error.rms",
                k => k,
            };
            let expected = lookup(&result, key);
            assert!(
                !expected.is_null() || exact == "null",
                "{key} missing in the result"
            );
            assert_eq!(exact, expected.to_string(), "{what}: {key}");
            assert!(
                is_rounding(text, exact),
                "{what}: {key} shows {text} for {exact}"
            );
        }
        (stdout, csv)
    }

    /// The result and CSV files offered for download are `expected`'s
    /// bytes (run's standard output and CSV files).
    fn check_files(&self, expected: &(String, Vec<(String, String)>), what: &str) {
        let (stdout, csv) = expected;
        let d = self.exec(DOWNLOADS, json!([]));
        let files = d["files"].as_array().unwrap();
        assert_eq!(files.len(), 5, "the result and four CSV files: {files:?}");
        for f in files {
            let (name, text) = (f[0].as_str().unwrap(), f[1].as_str().unwrap());
            let expected = if name == "result.json" {
                stdout.as_str()
            } else {
                csv.iter()
                    .find(|(n, _)| n == name)
                    .map(|(_, t)| t.as_str())
                    .unwrap_or_else(|| panic!("run writes no {name}"))
            };
            assert!(
                text == expected,
                "{what}: {name} differs from run's ({} vs {} bytes)",
                text.len(),
                expected.len()
            );
        }
    }
}

/// What a report shows: its number of figures, and the width in pixels of
/// stage 4's PNG (3 per unit of its SVG).
struct Expected {
    figures: usize,
    png_width: u32,
    files_everywhere: bool,
}

/// A plane curve's report: the eight figures of the method, the fuzzy
/// measures and the set view's two (`membership` and `section`).
const CURVE: Expected = Expected {
    figures: 11,
    png_width: 3000,
    files_everywhere: true,
};

/// A space curve's report: the eight figures of the method and the fuzzy
/// measures (the set view's figures are of plane curves).
const SPACE_CURVE: Expected = Expected {
    figures: 9,
    png_width: 3000,
    files_everywhere: true,
};

fn check_report(
    chromium: &Path,
    driver: &Driver,
    job: &Path,
    stops_to_check: &[usize],
    expected: &Expected,
) {
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
    let page = Page {
        driver,
        id: driver.session(chromium, profile.path(), "1300,1600"),
    };
    let s = |p: &str| format!("/session/{}{p}", page.id);
    driver.post(
        &s("/url"),
        &json!({"url": format!("file://{}", html.display())}),
    );
    page.wait_ready();

    let first = page.exec(READ_PAGE, json!([]));
    assert_eq!(
        first["resources"],
        json!(0),
        "the page loaded external resources"
    );
    let max = first["max"].as_u64().unwrap() as usize;

    // The slider: numbers and figures at each stop, at each h and just above.
    let mut seen_s4 = Vec::new();
    let mut stops: Vec<usize> = stops_to_check.iter().map(|&k| k.min(max)).collect();
    let at_h = page.exec("return Array.from(document.querySelectorAll('button[data-stop]')).map(b => Number(b.dataset.stop));", json!([]));
    for k in at_h.as_array().unwrap() {
        let k = k.as_u64().unwrap() as usize;
        stops.extend([k, (k + 1).min(max)]);
    }
    stops.push(max);
    for k in stops {
        page.exec(MOVE_SLIDER, json!([k]));
        let p = page.exec(READ_PAGE, json!([]));
        page.check_numbers(job, &p);
        assert_eq!(p["field"], p["alpha"], "the field follows the slider");
        seen_s4.push(p["s4"].as_str().unwrap_or_default().to_owned());
    }
    seen_s4.dedup();
    assert!(
        seen_s4.len() > 2,
        "the stage 4 figure changes with the slider"
    );
    // Every other type reduction: its own frame, the slider at rest, and
    // every number and download that of `run --type-reduction NAME`.
    let paper_page = page.exec(READ_PAGE, json!([]));
    for name in ["centroid", "nie-tan", "alpha-planes"] {
        assert_eq!(page.exec(SELECT_REDUCTION, json!([name])), json!(name));
        let p = page.exec(READ_PAGE, json!([]));
        assert_eq!(p["disabled"], json!(true), "{name}: slider at rest");
        assert_eq!(p["slider"], paper_page["slider"], "{name}: slider kept");
        let files = page.check_numbers(job, &p);
        if expected.files_everywhere {
            page.check_files(&files, name);
        } else {
            // A large surface carries the files of the paper's frames only.
            let enabled = page.exec(FILES_ENABLED, json!([]));
            assert_eq!(enabled["enabled"], json!(false), "{name}: no files");
            assert_eq!(enabled["text"], Value::Null, "{name}: no file text");
            let note = page.exec(READ_PAGE, json!([]))["note"].clone();
            assert!(
                note.as_str()
                    .unwrap()
                    .contains(&format!("t2spline run JOB --type-reduction {name}")),
                "{name}: {note}"
            );
        }
        assert_ne!(p["s4"], paper_page["s4"], "{name}: stage 4 changes");
    }
    page.exec(SELECT_REDUCTION, json!(["paper"]));
    let back = page.exec(READ_PAGE, json!([]));
    assert_eq!(back["disabled"], json!(false), "the slider works again");
    assert_eq!(
        back["cells"], paper_page["cells"],
        "back to the paper at the same stop"
    );
    assert_eq!(back["s4"], paper_page["s4"], "and its figures");

    // The number field drives the slider and the figures; an alpha between
    // stops shows the nearest and says so.
    page.exec(MOVE_SLIDER, json!([max]));
    let before = page.exec(READ_PAGE, json!([]))["s4"].clone();
    page.exec(TYPE_ALPHA, json!(["0.5"]));
    let p = page.exec(READ_PAGE, json!([]));
    assert_eq!(p["alpha"], json!("0.5"), "the field moves to alpha 0.5");
    assert_ne!(p["s4"], before, "the field changes the figures");
    page.check_numbers(job, &p);
    page.exec(TYPE_ALPHA, json!(["0.503"]));
    let p = page.exec(READ_PAGE, json!([]));
    assert_eq!(p["alpha"], json!("0.5"), "nearest stop");
    assert!(
        p["note"].as_str().unwrap().contains("No stop at α = 0.503"),
        "{}",
        p["note"]
    );

    // Which stops carry the result files (a large surface's only some): the
    // others disable their buttons and say how to get the files.
    let with_files: Vec<bool> = (0..=max)
        .map(|k| {
            page.exec(MOVE_SLIDER, json!([k]));
            let enabled = page.exec(FILES_ENABLED, json!([]));
            if enabled["enabled"] == json!(false) {
                assert_eq!(enabled["text"], Value::Null, "stop {k}: no file text");
                let note = page.exec(READ_PAGE, json!([]))["note"].clone();
                assert!(
                    note.as_str().unwrap().contains("t2spline run JOB --alpha"),
                    "stop {k}: {note}"
                );
            }
            enabled["enabled"] == json!(true)
        })
        .collect();
    assert!(with_files.iter().any(|&f| f), "some stop carries the files");
    assert_eq!(
        with_files.iter().all(|&f| f),
        expected.files_everywhere,
        "files at every stop: {with_files:?}"
    );

    // Downloads at the shown alpha: run's bytes, and the figures.
    let at = stops_to_check[1].min(max);
    let at = if with_files[at] {
        at
    } else {
        with_files.iter().position(|&f| f).unwrap()
    };
    page.exec(MOVE_SLIDER, json!([at]));
    let p = page.exec(READ_PAGE, json!([]));
    let alpha = p["alpha"].as_str().unwrap().to_owned();
    page.check_files(&run_files(job, &["--alpha", &alpha]), &alpha);
    let d = page.exec(DOWNLOADS, json!([]));
    let svgs = d["svgs"].as_array().unwrap();
    assert_eq!(svgs.len(), expected.figures, "an SVG per figure");
    for f in svgs {
        let text = f[1].as_str().unwrap();
        assert!(
            text.starts_with("<svg") && text.contains("</svg>"),
            "{}",
            f[0]
        );
    }
    assert_eq!(
        d["pngs"].as_array().unwrap().len(),
        expected.figures,
        "a PNG per figure"
    );
    let png = page.exec_async(PNG, json!(["stage4-defuzzified"]));
    let png = base64_decode(png.as_str().unwrap());
    assert_eq!(&png[1..4], b"PNG");
    let width = u32::from_be_bytes(png[16..20].try_into().unwrap());
    assert_eq!(width, expected.png_width, "3 pixels per unit of the figure");
    assert_eq!(&png[37..41], b"pHYs");
    assert_eq!(
        u32::from_be_bytes(png[41..45].try_into().unwrap()),
        11811,
        "300 dpi"
    );

    // 800 pixels wide: no sideways scrolling; every heading jumped to shows
    // below the sticky bar.
    driver.post(&s("/window/rect"), &json!({"width": 800, "height": 900}));
    let l = page.exec(LAYOUT, json!([]));
    assert!(
        l["scroll"].as_f64().unwrap() <= l["width"].as_f64().unwrap(),
        "sideways scroll at 800 px: {l}"
    );
    for h in l["headings"].as_array().unwrap() {
        let (top, bottom, bar, height) = (
            h[1].as_f64().unwrap(),
            h[2].as_f64().unwrap(),
            h[3].as_f64().unwrap(),
            h[4].as_f64().unwrap(),
        );
        assert!(
            top >= bar - 0.5 && bottom <= height,
            "{}: heading at {top}–{bottom}, bar ends at {bar}",
            h[0]
        );
    }

    // It prints (the print style sheet applies; headless Chromium makes a PDF).
    let pdf = driver.post(&s("/print"), &json!({}));
    let pdf = base64_decode(pdf.as_str().unwrap());
    assert!(
        pdf.starts_with(b"%PDF") && pdf.len() > 20_000,
        "{} bytes",
        pdf.len()
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

fn base64_decode(s: &str) -> Vec<u8> {
    const ALPHABET: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = Vec::new();
    let (mut acc, mut bits) = (0u32, 0);
    for c in s.bytes().filter(|&c| c != b'=') {
        let v = ALPHABET.iter().position(|&a| a == c).expect("base64") as u32;
        acc = (acc << 6) | v;
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
        }
    }
    out
}

#[test]
fn report_in_headless_chromium_matches_t2spline_run() {
    let Some((chromium, chromedriver)) = browser("report_browser") else {
        return;
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let driver = Driver::start(&chromedriver);
    // The paper's example (stops 0.01 apart; 60 is alpha = h = 0.6).
    check_report(
        &chromium,
        &driver,
        &root.join("examples/paper-alg-1-1.json"),
        &[0, 37, 80],
        &CURVE,
    );
    // A 3-D job with mixed heights (0.4 on z, 0.7 elsewhere).
    check_report(
        &chromium,
        &driver,
        &root.join("fixtures/spiral-3d.json"),
        &[0, 13],
        &SPACE_CURVE,
    );
}

#[test]
fn surface_report_in_headless_chromium_matches_t2spline_run() {
    let Some((chromium, chromedriver)) = browser("report_browser") else {
        return;
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let driver = Driver::start(&chromedriver);
    // Six figures (no sweep along t, no reductions figure); stage 4 is two
    // panels and a colour bar, 1096 units wide.
    let surface = Expected {
        figures: 6,
        png_width: 3288,
        files_everywhere: true,
    };
    check_report(
        &chromium,
        &driver,
        &root.join("examples/fuzzy-cylinder.json"),
        &[0, 7],
        &surface,
    );
    // The terrain's files (51 × 41 samples, 1 MB packed) are in the report at
    // the starting alpha only, so that its figures get stops 0.05 apart.
    check_report(
        &chromium,
        &driver,
        &root.join("examples/fuzzy-terrain.json"),
        &[0, 3],
        // And the three of a terrain: the width map, the shoreline and the
        // fuzzy measures.
        &Expected {
            figures: 9,
            files_everywhere: false,
            ..surface
        },
    );
}
