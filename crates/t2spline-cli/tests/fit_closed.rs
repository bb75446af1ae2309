//! `t2spline fit --closed`: readings around a circle become a closed job
//! that `run` and `measure` take as closed, with the enclosed area of the
//! circle; a repeated last point is the first; bad input is one line each,
//! exit 2, and no file.

use std::f64::consts::{PI, TAU};
use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::{json, Value};

fn t2spline() -> Command {
    Command::cargo_bin("t2spline").unwrap()
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

const RADIUS: f64 = 10.0;
const STATIONS: usize = 16;

/// Readings of 16 stations on a circle of radius 10 about (3, −2): five
/// readings each, the station plus offsets symmetric about it, so that the
/// median (the crisp value) is the station itself, exactly.
fn circle_readings(dir: &Path) -> PathBuf {
    let mut csv = String::from("station,x,y\n");
    for k in 0..STATIONS {
        let a = TAU * k as f64 / STATIONS as f64;
        let (x, y) = (3.0 + RADIUS * a.cos(), -2.0 + RADIUS * a.sin());
        for (dx, dy) in [
            (0.0, 0.0),
            (-0.08, 0.05),
            (0.08, -0.05),
            (-0.03, -0.1),
            (0.03, 0.1),
        ] {
            csv.push_str(&format!("S{k:02},{},{}\n", x + dx, y + dy));
        }
    }
    let path = dir.join("circle.csv");
    std::fs::write(&path, csv).unwrap();
    path
}

fn area_at_alpha_1(job: &Path) -> (Value, f64) {
    let out = t2spline()
        .arg("measure")
        .arg(job)
        .args(["--levels", "3"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let m: Value = serde_json::from_slice(&out).unwrap();
    let crisp = m["area"]["upper"]
        .as_array()
        .unwrap()
        .iter()
        .find(|l| l["alpha"] == json!(1.0))
        .map(|l| (l["min"].as_f64().unwrap() + l["max"].as_f64().unwrap()) / 2.0)
        .unwrap();
    (m, crisp)
}

#[test]
fn readings_around_a_circle_give_a_closed_job_enclosing_pi_r_squared() {
    let dir = tempfile::tempdir().unwrap();
    let readings = circle_readings(dir.path());
    let job = dir.path().join("job.json");
    t2spline()
        .arg("fit")
        .arg(&readings)
        .args(["--closed", "--alpha", "0.5", "--tolerance", "0.02", "-o"])
        .arg(&job)
        .assert()
        .code(0)
        .stderr(predicate::str::contains(
            "a closed loop of 16 data points, degree 3, chord parameters with the closing chord: periodic interpolation, periodic knots, 16 control points and the first 3 again at the end",
        ));
    let j = read_json(&job);
    assert_eq!(j["closed"], json!(true));
    let points = j["points"].as_array().unwrap();
    assert_eq!(points.len(), STATIONS + 3);
    assert_eq!(
        &points[STATIONS..],
        &points[..3],
        "the first 3 points repeat"
    );
    let knots: Vec<f64> = j["knots"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    // Unclamped, the domain [0, 1], evenly spaced stations: uniform knots.
    assert_eq!((knots[3], knots[STATIONS + 3]), (0.0, 1.0));
    for w in knots.windows(2) {
        assert!((w[1] - w[0] - 1.0 / 16.0).abs() < 1e-12, "{knots:?}");
    }
    t2spline().arg("run").arg(&job).assert().code(0);
    // The other commands take it as the closed curve it is.
    let out = |name: &str| dir.path().join(name);
    for args in [
        vec!["validate".into(), job.clone()],
        vec![
            "region".into(),
            job.clone(),
            "-o".into(),
            out("region.geojson"),
        ],
        vec!["export".into(), job.clone(), "-o".into(), out("pond.dxf")],
        vec!["plot".into(), job.clone(), "-o".into(), out("figures")],
    ] {
        t2spline().args(&args).assert().code(0);
    }
    let (m, crisp) = area_at_alpha_1(&job);
    assert_eq!(m["area"]["kind"], "enclosed", "{m}");
    // The crisp curve interpolates 16 exact points of the circle (the medians
    // of symmetric readings). A cubic spline interpolant is within
    // (5/384)·h⁴·max|C⁗| of the curve (Hall and Meyer 1976), h the chord:
    // for a circle, a radial error of at most (5/384)·(h/r)⁴·r ≈ 3.1e-4·r
    // with h/r ≈ 2π/16, so the area is within twice that, 6.2e-4, of πr².
    // It came out 6.9e-5 below (measured). The polygon through the same
    // points misses by 2.6 %, an open curve by more.
    let want = PI * RADIUS * RADIUS;
    assert!(
        ((crisp - want) / want).abs() < 6.2e-4,
        "crisp area {crisp}, πr² {want}"
    );
    // The fuzzy areas hold the crisp one, and widen as alpha falls.
    for f in ["upper", "primary"] {
        let levels = m["area"][f].as_array().unwrap();
        for l in levels {
            let (lo, hi) = (l["min"].as_f64().unwrap(), l["max"].as_f64().unwrap());
            assert!(lo <= crisp + 1e-6 && crisp - 1e-6 <= hi, "{f}: {l}");
        }
        let width = |l: &Value| l["max"].as_f64().unwrap() - l["min"].as_f64().unwrap();
        assert!(width(&levels[0]) > width(&levels[levels.len() - 1]), "{f}");
    }
}

/// A data file with its last point repeating the first gives the job of the
/// same data without it, and the report says so; least squares with fewer
/// control points is closed too.
#[test]
fn a_repeated_last_point_is_the_first_and_least_squares_closes() {
    let dir = tempfile::tempdir().unwrap();
    let n = |c: f64| json!({"crisp": c, "upper": [c - 0.3, c + 0.3], "primary": [c - 0.2, c + 0.2], "lower": [c - 0.1, c + 0.1]});
    let loop_points: Vec<Value> = (0..10)
        .map(|k| {
            let a = TAU * f64::from(k) / 10.0;
            let r = 4.0 + f64::from(k % 3);
            json!({"x": n(r * a.cos()), "y": n(r * a.sin())})
        })
        .collect();
    let mut repeated = loop_points.clone();
    repeated.push(loop_points[0].clone());
    let write = |name: &str, points: &[Value]| {
        let path = dir.path().join(name);
        let v = json!({"degree": 3, "lower_height": 0.5, "alpha": 0.5, "points": points});
        std::fs::write(&path, v.to_string()).unwrap();
        path
    };
    let (once, twice) = (
        write("once.json", &loop_points),
        write("twice.json", &repeated),
    );
    let fitted = |data: &Path, extra: &[&str]| {
        let out = t2spline()
            .arg("fit")
            .arg(data)
            .arg("--closed")
            .args(extra)
            .assert()
            .code(0)
            .get_output()
            .clone();
        (
            serde_json::from_slice::<Value>(&out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
        )
    };
    let (a, _) = fitted(&once, &[]);
    let (b, report) = fitted(&twice, &[]);
    assert_eq!(a, b);
    assert!(
        report.contains(
            "a closed loop of 10 data points (the last repeats the first and is taken as it)"
        ),
        "{report}"
    );
    // As many control points as distinct points: interpolation.
    let (full, report) = fitted(&twice, &["--control-points", "10"]);
    assert_eq!(full, a);
    assert!(report.contains("periodic interpolation"), "{report}");
    let (ls, report) = fitted(&twice, &["--control-points", "6"]);
    assert!(report.contains("periodic least squares"), "{report}");
    assert_eq!(ls["points"].as_array().unwrap().len(), 6 + 3);
    assert_eq!(ls["closed"], json!(true));
    let job = dir.path().join("ls.json");
    std::fs::write(&job, ls.to_string()).unwrap();
    t2spline().arg("run").arg(&job).assert().code(0);
    let (m, _) = area_at_alpha_1(&job);
    assert_eq!(m["area"]["kind"], "enclosed", "{m}");
}

#[test]
fn bad_closed_fits_are_one_line_each_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("job.json");
    let n = |c: f64| json!({"crisp": c, "upper": [c - 0.3, c + 0.3], "primary": [c - 0.2, c + 0.2], "lower": [c - 0.1, c + 0.1]});
    let p = |x: f64, y: f64| json!({"x": n(x), "y": n(y)});
    let cases: Vec<(Value, Vec<&str>, &str)> = vec![
        (
            json!({"degree": 3, "lower_height": 0.5, "points": [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 0.0)]}),
            vec![],
            "points: a closed curve of degree 3 needs at least 4 distinct data points around its loop, got 3 (the last point repeats the first and counts once)",
        ),
        (
            json!({"degree": 2, "lower_height": 0.5, "points": [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(0.0, 0.0)]}),
            vec!["--control-points", "5"],
            "--control-points: 5 is outside [3, 4]: at least degree + 1, at most the 4 distinct data points around the loop of",
        ),
        (
            json!({"degree": [1, 1], "lower_height": 0.5, "points": [
                [{"x": n(0.0), "y": n(0.0), "z": n(0.0)}, {"x": n(0.0), "y": n(1.0), "z": n(0.0)}],
                [{"x": n(1.0), "y": n(0.0), "z": n(0.0)}, {"x": n(1.0), "y": n(1.0), "z": n(1.0)}]
            ]}),
            vec![],
            "--closed: only for the data points of a curve, taken as a loop;",
        ),
    ];
    for (data, extra, message) in cases {
        let path = dir.path().join("data.json");
        std::fs::write(&path, data.to_string()).unwrap();
        let assert = t2spline()
            .arg("fit")
            .arg(&path)
            .arg("--closed")
            .args(&extra)
            .arg("-o")
            .arg(&out)
            .assert()
            .code(2)
            .stderr(predicate::str::contains(message));
        let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(!out.exists(), "{message}");
    }
}

/// The example of docs/fitting.md ("Closed curves"): the pond's readings,
/// and the areas the page quotes.
#[test]
fn the_pond_of_the_docs_encloses_the_areas_quoted() {
    let readings =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/fit-example/pond-readings.csv");
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("pond.json");
    t2spline()
        .arg("fit")
        .arg(&readings)
        .args([
            "--closed",
            "--tolerance",
            "0.05",
            "--alpha",
            "0.5",
            "-q",
            "-o",
        ])
        .arg(&job)
        .assert()
        .code(0);
    let out = t2spline()
        .arg("measure")
        .arg(&job)
        .args(["--alpha", "0.5"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let m: Value = serde_json::from_slice(&out).unwrap();
    let bounds = |f: &str| {
        let l = &m["area"][f][0];
        [l["min"].as_f64().unwrap(), l["max"].as_f64().unwrap()]
    };
    let quoted = [
        ("lower", [1255.96, 1255.96], 0.005),
        ("primary", [1247.8, 1264.0], 0.05),
        ("upper", [1240.2, 1272.1], 0.05),
    ];
    for (f, want, tol) in quoted {
        let got = bounds(f);
        assert!(
            (got[0] - want[0]).abs() <= tol && (got[1] - want[1]).abs() <= tol,
            "{f}: {got:?}, the docs say {want:?}"
        );
    }
}
