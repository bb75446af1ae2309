//! The page of `t2spline serve` in a real browser: Debian's headless
//! Chromium driven through ChromeDriver (WebDriver over HTTP on loopback),
//! as the report's browser test drives it.
//!
//! Synthesised mouse drags move a crisp point (its whole number) and an
//! interval's foot (which stops at its neighbour); the slider, the type
//! reduction, undo, inserting and deleting points, a 3-D point's z field and
//! saving; after each, every number shown must be that of `t2spline run` of
//! the job the page would download, and the download must be that job. A
//! surface opens in the view-only mode. The page loads nothing from
//! elsewhere and logs no errors.
//!
//! Without `chromium` and `chromedriver` the test says it was skipped and
//! passes, unless `T2SPLINE_REQUIRE_BROWSER=1` (set by CI), when it fails.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::{json, Value};

use webdriver::{browser, Driver, Killed, Page};

mod webdriver;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `t2spline serve ARGS…` in `dir`, and the address it printed first.
fn serve(args: &[&str], dir: &Path) -> (Killed, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .arg("serve")
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    assert!(line.starts_with("http://127.0.0.1:"), "{line}");
    (Killed(child), line.trim_end().to_owned())
}

/// `t2spline run` of a job's text: its standard output.
fn run(text: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    std::fs::write(&job, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .arg("run")
        .arg(&job)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

const READ: &str = r#"
const s = window.t2splineServe;
const n = id => { const e = document.getElementById(id); return [e.dataset.value || null, e.textContent]; };
return { idle: s.idle() && document.body.dataset.state !== "loading", job: s.jobText(), result: s.result(), problems: s.problems(), state: document.body.dataset.state,
         max: n("m-max"), at: n("m-max-at"), rms: n("m-rms"), regime: JSON.parse(document.getElementById("m-regime").dataset.value || "null"),
         regimeText: document.getElementById("m-regime").textContent,
         alpha: document.getElementById("alpha-value").textContent,
         resources: performance.getEntriesByType("resource").map(e => e.name) };
"#;

/// Where an element is, in the viewport: its centre.
const CENTRE: &str = r#"
const r = document.getElementById(arguments[0]).getBoundingClientRect();
return [Math.round(r.left + r.width / 2), Math.round(r.top + r.height / 2)];
"#;

impl Page<'_> {
    /// Waits until the page has shown the result of its current job, and
    /// reads it (in the same script: nothing can start in between).
    fn settle(&self) -> Value {
        let deadline = Instant::now() + Duration::from_secs(60);
        while Instant::now() < deadline {
            if self.exec("return !!window.t2splineServe;", json!([])) == json!(true) {
                let p = self.exec(READ, json!([]));
                if p["idle"] == json!(true) {
                    return p;
                }
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        panic!("the page did not settle");
    }

    /// A synthesised mouse drag from the centre of element `id` by (dx, dy)
    /// pixels, in several moves.
    fn drag(&self, id: &str, dx: i64, dy: i64) {
        let c = self.exec(CENTRE, json!([id]));
        let (x, y) = (c[0].as_i64().unwrap(), c[1].as_i64().unwrap());
        let mut actions = vec![
            json!({"type": "pointerMove", "duration": 0, "x": x, "y": y, "origin": "viewport"}),
            json!({"type": "pointerDown", "button": 0}),
        ];
        for k in 1..=8 {
            actions.push(json!({"type": "pointerMove", "duration": 30,
                "x": x + dx * k / 8, "y": y + dy * k / 8, "origin": "viewport"}));
        }
        actions.push(json!({"type": "pointerUp", "button": 0}));
        self.driver.post(
            &format!("/session/{}/actions", self.id),
            &json!({"actions": [{"type": "pointer", "id": "mouse",
                "parameters": {"pointerType": "mouse"}, "actions": actions}]}),
        );
    }

    fn click(&self, id: &str) {
        self.exec(
            "document.getElementById(arguments[0]).click();",
            json!([id]),
        );
    }

    /// Sets a field or the slider and fires its event.
    fn set(&self, id: &str, value: &str, event: &str) {
        self.exec(
            "const e = document.getElementById(arguments[0]); e.value = arguments[1]; e.dispatchEvent(new Event(arguments[2], {bubbles: true})); if (arguments[2] === 'input') e.dispatchEvent(new Event('change', {bubbles: true}));",
            json!([id, value, event]),
        );
    }
}

/// Every number shown is `t2spline run`'s of the job the page holds, and
/// the page's result is run's bytes.
fn check_numbers(p: &Value, what: &str) -> Value {
    assert_eq!(p["state"], json!("ok"), "{what}: {:?}", p["problems"]);
    let stdout = run(p["job"].as_str().unwrap());
    assert!(
        p["result"].as_str() == Some(stdout.as_str()),
        "{what}: the page's result is run's"
    );
    let result: Value = serde_json::from_str(&stdout).unwrap();
    for (shown, key) in [("max", "max"), ("at", "max_at"), ("rms", "rms")] {
        let exact: Value = serde_json::from_str(p[shown][0].as_str().unwrap()).unwrap();
        assert!(
            same_numbers(&exact, &result["error"][key]),
            "{what}: {key}: {exact} vs {}",
            result["error"][key]
        );
        let text = p[shown][1].as_str().unwrap();
        if let Some(x) = result["error"][key].as_f64() {
            let t: f64 = text.parse().unwrap();
            assert!(
                (t - x).abs() <= 5e-4 * x.abs().max(1e-300),
                "{what}: {key} shows {text} for {x}"
            );
        }
    }
    assert_eq!(p["regime"], result["regime"], "{what}: regime");
    if let Some(regime) = result["regime"].as_str() {
        assert_eq!(p["regimeText"], json!(regime), "{what}");
    }
    result
}

/// The same numbers (JavaScript writes 0.0 as 0), or arrays of them.
fn same_numbers(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Array(a), Value::Array(b)) => {
            a.len() == b.len() && a.iter().zip(b).all(|(a, b)| same_numbers(a, b))
        }
        _ => a.as_f64().is_some() && a.as_f64() == b.as_f64(),
    }
}

fn job_of(p: &Value) -> Value {
    serde_json::from_str(p["job"].as_str().unwrap()).unwrap()
}

fn seven(n: &Value) -> Vec<f64> {
    let v = |k: &str, i: usize| n[k][i].as_f64().unwrap();
    vec![
        v("upper", 0),
        v("primary", 0),
        v("lower", 0),
        n["crisp"].as_f64().unwrap(),
        v("lower", 1),
        v("primary", 1),
        v("upper", 1),
    ]
}

fn ordered(job: &Value) -> bool {
    job["points"].as_array().unwrap().iter().all(|p| {
        p.as_object()
            .unwrap()
            .values()
            .all(|n| seven(n).windows(2).all(|w| w[0] <= w[1]))
    })
}

fn session(driver: &Driver, chromium: &Path, profile: &Path, url: &str) -> String {
    let id = driver.session(chromium, profile, "1300,1000");
    driver.post(&format!("/session/{id}/url"), &json!({ "url": url }));
    id
}

fn no_errors(page: &Page<'_>) {
    let logs = page.driver.post(
        &format!("/session/{}/se/log", page.id),
        &json!({"type": "browser"}),
    );
    let errors: Vec<&Value> = logs
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["level"] == json!("SEVERE") || e["level"] == json!("WARNING"))
        // The job made bad on purpose (an order of 9) is answered 422.
        .filter(|e| {
            !(e["source"] == json!("network")
                && e["message"]
                    .as_str()
                    .is_some_and(|m| m.contains("status of 422")))
        })
        .collect();
    assert!(errors.is_empty(), "console errors: {errors:?}");
}

#[test]
fn the_editor_in_headless_chromium_matches_t2spline_run() {
    let Some((chromium, chromedriver)) = browser("serve_browser") else {
        return;
    };
    let driver = Driver::start(&chromedriver);
    let dir = tempfile::tempdir().unwrap();
    let profile = tempfile::tempdir().unwrap();
    let (_server, url) = serve(&[], dir.path());
    let origin = url.split("/?").next().unwrap().to_owned();
    let page = Page {
        driver: &driver,
        id: session(&driver, &chromium, profile.path(), &url),
    };

    // The shipped example, as `run` computes it.
    let first = page.settle();
    check_numbers(&first, "start");
    assert_eq!(first["regime"], json!("alpha > h"));
    let start_job = job_of(&first);
    assert_eq!(start_job["alpha"], json!(0.8));

    // A drag of a crisp point moves its whole number: all seven values of x
    // (and of y) by one step, right and up as the mouse.
    page.drag("h-1-crisp", 60, -40);
    let p = page.settle();
    let moved = job_of(&p);
    let before = &start_job["points"][1];
    let after = &moved["points"][1];
    for (c, sign) in [("x", 1.0), ("y", 1.0)] {
        let (a, b) = (seven(&before[c]), seven(&after[c]));
        let d = b[3] - a[3];
        assert!(d * sign > 0.0, "{c} moved the way of the mouse: {d}");
        for k in 0..7 {
            assert!(
                (b[k] - a[k] - d).abs() < 1e-3,
                "{c}: value {k} moved by {} not {d}",
                b[k] - a[k]
            );
        }
    }
    assert_eq!(moved["points"][0], start_job["points"][0], "one point only");
    assert!(ordered(&moved));
    check_numbers(&p, "crisp drag");

    // A foot dragged past its neighbour stops there: point 2's upper right
    // foot of x, dragged far left, meets its primary right foot.
    page.drag("h-2-x-upper-right", -300, 0);
    let p = page.settle();
    let footed = job_of(&p);
    let x = seven(&footed["points"][2]["x"]);
    assert_eq!(x[6], x[5], "stopped at the primary foot: {x:?}");
    assert_eq!(
        x[..6],
        seven(&moved["points"][2]["x"])[..6],
        "only that foot moved"
    );
    assert!(ordered(&footed));
    check_numbers(&p, "foot drag");
    // And one dragged a little stays between its neighbours.
    page.drag("h-0-y-lower-left", 0, 8);
    let p = page.settle();
    let y = seven(&job_of(&p)["points"][0]["y"]);
    assert_ne!(y[2], seven(&footed["points"][0]["y"])[2], "the foot moved");
    assert!(ordered(&job_of(&p)));
    check_numbers(&p, "small foot drag");
    let before_slider = p["job"].clone();

    // The slider: alpha 0.3, below h, the other regime.
    page.set("alpha", "0.3", "input");
    let p = page.settle();
    assert_eq!(job_of(&p)["alpha"], json!(0.3));
    let r = check_numbers(&p, "alpha 0.3");
    assert_eq!(r["regime"], json!("alpha <= h"));
    assert!(p["alpha"].as_str().unwrap().starts_with("0.3"));

    // Undo brings back the job before the slider, and its numbers; redo
    // the slider's.
    page.click("undo");
    let p = page.settle();
    assert_eq!(p["job"], before_slider, "undo");
    check_numbers(&p, "undo");
    page.click("redo");
    let p = page.settle();
    assert_eq!(job_of(&p)["alpha"], json!(0.3), "redo");
    page.click("undo");
    let p = page.settle();
    assert_eq!(p["job"], before_slider);
    // Undo again takes back the small foot drag.
    page.click("undo");
    let p = page.settle();
    assert_eq!(job_of(&p), footed, "undo of a drag");

    // The type reduction.
    page.set("reduction", "centroid", "change");
    let p = page.settle();
    let r = check_numbers(&p, "centroid");
    assert_eq!(r["type_reduction"], json!("centroid"));
    assert!(p["alpha"].as_str().unwrap().contains("not used"));
    page.set("reduction", "paper", "change");

    // Fields: a weight, the order, a lower height; inserting and deleting.
    page.set("weight", "2.5", "change");
    let p = page.settle();
    assert_eq!(
        job_of(&p)["weights"][0],
        json!(2.5),
        "point 0, dragged last, is selected"
    );
    check_numbers(&p, "weight");
    page.click("insert");
    let p = page.settle();
    assert_eq!(job_of(&p)["points"].as_array().unwrap().len(), 5);
    assert!(ordered(&job_of(&p)));
    check_numbers(&p, "inserted");
    page.set("order", "4", "change");
    let p = page.settle();
    assert_eq!(check_numbers(&p, "order 4")["order"], json!(4));
    page.set("lower-height", "0.9", "change");
    let p = page.settle();
    let r = check_numbers(&p, "lower height 0.9");
    assert_eq!(r["regime"], json!("alpha <= h"), "0.8 is now below h");
    page.click("delete");
    let p = page.settle();
    assert_eq!(job_of(&p)["points"].as_array().unwrap().len(), 4);
    check_numbers(&p, "deleted");
    // An order above the number of points: the CLI's message, shown.
    page.set("order", "9", "change");
    let p = page.settle();
    assert_eq!(p["state"], json!("problems"));
    let problem = p["problems"][0].as_str().unwrap().to_owned();
    assert!(problem.starts_with("paper-alg-1-1.json:"), "{problem}");
    page.click("undo");
    let p = page.settle();
    check_numbers(&p, "undone");

    // The membership map: `t2spline membership`'s grades of its grid.
    page.click("show-map");
    let p = page.settle();
    let map = page.exec("return window.t2splineServe.map();", json!([]));
    let files = tempfile::tempdir().unwrap();
    std::fs::write(files.path().join("job.json"), p["job"].as_str().unwrap()).unwrap();
    std::fs::write(
        files.path().join("grid.csv"),
        map["points"].as_str().unwrap(),
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args(["membership", "job.json", "grid.csv"])
        .current_dir(files.path())
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(
        map["grades"].as_str().unwrap().as_bytes(),
        out.stdout,
        "the map's grades"
    );
    let cells = page.exec(
        "return document.querySelectorAll('#membership-map rect').length;",
        json!([]),
    );
    assert!(cells.as_u64().unwrap() > 100, "cells drawn: {cells}");

    // Download: the job shown, which `run` accepts with the numbers shown.
    page.click("download");
    let d = page.exec("return window.t2splineServe.lastDownload();", json!([]));
    assert_eq!(d["text"], p["job"], "the download is the job");
    assert_eq!(d["name"], json!("paper-alg-1-1.json"));
    check_numbers(&p, "download");

    // Opening a job file: the fuzzy circle, run as `run` runs it.
    let input = page.driver.post(
        &format!("/session/{}/element", page.id),
        &json!({"using": "css selector", "value": "#open"}),
    );
    let element = input["element-6066-11e4-a52e-4f735466cecf"]
        .as_str()
        .unwrap_or_else(|| panic!("the file field: {input}"));
    page.driver.post(
        &format!("/session/{}/element/{element}/value", page.id),
        &json!({"text": root().join("fixtures/circle.json").canonicalize().unwrap().to_str().unwrap()}),
    );
    let deadline = Instant::now() + Duration::from_secs(30);
    let p = loop {
        let p = page.settle();
        if job_of(&p)["points"].as_array().unwrap().len() == 9 {
            break p;
        }
        assert!(Instant::now() < deadline, "the circle opens");
        std::thread::sleep(Duration::from_millis(100));
    };
    check_numbers(&p, "opened circle");
    let name = page.exec(
        "return document.getElementById('job-name').textContent;",
        json!([]),
    );
    assert_eq!(name, json!("circle.json"));

    // Nothing was fetched from elsewhere.
    for r in p["resources"].as_array().unwrap() {
        assert!(
            r.as_str().unwrap().starts_with(&format!("{origin}/api/")),
            "{r}"
        );
    }
    no_errors(&page);
    let _ = ureq::delete(&format!("{}/session/{}", driver.base, page.id)).call();
}

#[test]
fn a_space_curve_is_edited_in_x_y_and_z_and_saved_and_a_surface_viewed() {
    let Some((chromium, chromedriver)) = browser("serve_browser") else {
        return;
    };
    let driver = Driver::start(&chromedriver);
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("spiral.json");
    std::fs::copy(root().join("fixtures/spiral-3d.json"), &job).unwrap();
    let profile = tempfile::tempdir().unwrap();
    let (_server, url) = serve(&["spiral.json"], dir.path());
    let page = Page {
        driver: &driver,
        id: session(&driver, &chromium, profile.path(), &url),
    };
    let p = page.settle();
    check_numbers(&p, "spiral");
    let start = job_of(&p);
    // z of point 0 in its field: the crisp value within its lower foot.
    let z = seven(&start["points"][0]["z"]);
    let new = (z[2] + z[3]) / 2.0;
    page.set("z-3", &new.to_string(), "change");
    let p = page.settle();
    assert_eq!(job_of(&p)["points"][0]["z"]["crisp"], json!(new));
    check_numbers(&p, "z field");
    page.drag("h-3-crisp", -30, 30);
    let p = page.settle();
    let after = job_of(&p);
    assert_ne!(after["points"][3]["x"], start["points"][3]["x"]);
    assert_eq!(after["points"][3]["z"], start["points"][3]["z"], "z stays");
    check_numbers(&p, "3-D drag");
    // Saving over the job file named on the command line.
    page.click("save");
    let deadline = Instant::now() + Duration::from_secs(20);
    while std::fs::read_to_string(&job).unwrap() != p["job"].as_str().unwrap() {
        assert!(Instant::now() < deadline, "saved");
        std::thread::sleep(Duration::from_millis(50));
    }
    no_errors(&page);
    let _ = ureq::delete(&format!("{}/session/{}", driver.base, page.id)).call();

    // A surface: view-only, with the slider.
    let (_surface, url) = serve(
        &[root()
            .join("examples/fuzzy-cylinder.json")
            .to_str()
            .unwrap()],
        dir.path(),
    );
    let profile = tempfile::tempdir().unwrap();
    let page = Page {
        driver: &driver,
        id: session(&driver, &chromium, profile.path(), &url),
    };
    let p = page.settle();
    check_numbers(&p, "cylinder");
    let hidden = page.exec(
        "return [document.getElementById('point-fields').hidden, document.querySelectorAll('#surface-crisp polyline').length];",
        json!([]),
    );
    assert_eq!(hidden[0], json!(true), "no editing of surfaces");
    assert!(hidden[1].as_u64().unwrap() > 10, "a wireframe: {hidden}");
    page.set("alpha", "0.9", "input");
    let p = page.settle();
    assert_eq!(job_of(&p)["alpha"], json!(0.9));
    check_numbers(&p, "cylinder at 0.9");
    no_errors(&page);
    let _ = ureq::delete(&format!("{}/session/{}", driver.base, page.id)).call();
}
