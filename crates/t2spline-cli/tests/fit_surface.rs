//! `t2spline fit` of a net: readings of a net and data files of a net give
//! surface jobs that run, draw and export; the counts of `--control-points`
//! are checked per direction; the shipped seabed (docs/terrain.md) runs.

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

/// Readings of a net of `rows × columns` stations, three readings each, in
/// an order that interleaves the stations (as a time-ordered log does): a
/// smooth hill with readings that scatter in z only.
fn net_readings(rows: usize, columns: usize) -> String {
    let mut text = String::from("row,col,x,y,z\n");
    for round in 0..3 {
        for i in 0..rows {
            for j in 0..columns {
                let (x, y) = (10.0 * i as f64, 8.0 * j as f64);
                let z = 5.0 - 0.01 * (x - 20.0).powi(2) - 0.02 * (y - 16.0).powi(2);
                let scatter = [0.0, -0.3, 0.45][round] * (1.0 + 0.1 * (i + j) as f64);
                text.push_str(&format!("{i},{j},{x},{y},{}\n", z + scatter));
            }
        }
    }
    text
}

#[test]
fn readings_of_a_net_fit_into_a_surface_job_that_runs_draws_and_exports() {
    let dir = tempfile::tempdir().unwrap();
    let readings = dir.path().join("net.csv");
    std::fs::write(&readings, net_readings(6, 5)).unwrap();
    let job = dir.path().join("job.json");
    t2spline()
        .args(["fit", "--degree", "3,2", "--alpha", "0.5", "-o"])
        .arg(&job)
        .arg(&readings)
        .assert()
        .code(0)
        .stderr(predicate::str::contains(
            "a net of 6 × 5 data points, degree 3 × 2, chord parameters averaged over rows and columns: interpolation, 6 × 5 control points",
        ))
        .stderr(predicate::str::is_match(r"crisp +[0-9.]+e-1[0-9] +points\[\d+\]\[\d+\]\.[xyz] +\(interpolated\)").unwrap());
    let v = read_json(&job);
    assert_eq!(v["degree"], json!([3, 2]));
    assert_eq!(v["points"].as_array().unwrap().len(), 6);
    assert_eq!(v["points"][0].as_array().unwrap().len(), 5);
    t2spline()
        .arg("validate")
        .arg(&job)
        .assert()
        .code(0)
        .stdout(predicate::str::contains(
            "3-D surface, 6 × 5 control points, orders 4 × 3, alpha 0.5",
        ));
    t2spline()
        .arg("run")
        .arg(&job)
        .arg("-o")
        .arg(dir.path().join("result.json"))
        .assert()
        .code(0);
    let figures = dir.path().join("figures");
    t2spline()
        .arg("plot")
        .arg(&job)
        .arg("-o")
        .arg(&figures)
        .assert()
        .code(0);
    assert!(figures.join("stage1-fuzzy.svg").exists());
    t2spline()
        .args(["export", "--format", "step", "-o"])
        .arg(dir.path().join("net.step"))
        .arg(&job)
        .assert()
        .code(0);
    assert!(std::fs::read_to_string(dir.path().join("net.step"))
        .unwrap()
        .contains("B_SPLINE_SURFACE"));
}

#[test]
fn a_data_file_of_a_net_fits_by_least_squares_with_a_pair_of_counts() {
    let dir = tempfile::tempdir().unwrap();
    let readings = dir.path().join("net.csv");
    std::fs::write(&readings, net_readings(9, 7)).unwrap();
    let data = dir.path().join("data.json");
    t2spline()
        .arg("fuzzify")
        .arg(&readings)
        .args(["--degree", "2", "-o"])
        .arg(&data)
        .assert()
        .code(0);
    let job = dir.path().join("job.json");
    t2spline()
        .arg("fit")
        .arg(&data)
        .args([
            "--control-points",
            "5,4",
            "--parametrization",
            "uniform",
            "-q",
            "-o",
        ])
        .arg(&job)
        .assert()
        .code(0)
        .stderr("");
    let v = read_json(&job);
    assert_eq!(v["degree"], json!([2, 2]));
    assert_eq!(v["knots"]["u"].as_array().unwrap().len(), 5 + 3);
    assert_eq!(v["knots"]["v"].as_array().unwrap().len(), 4 + 3);
    // One count for a net: the same in both directions.
    t2spline()
        .arg("fit")
        .arg(&data)
        .args(["--control-points", "4", "-q"])
        .assert()
        .code(0);
}

#[test]
fn control_point_counts_are_checked_per_direction_and_named() {
    let dir = tempfile::tempdir().unwrap();
    let readings = dir.path().join("net.csv");
    std::fs::write(&readings, net_readings(6, 5)).unwrap();
    let job = dir.path().join("job.json");
    t2spline()
        .arg("fit")
        .arg(&readings)
        .args(["--control-points", "5,7", "-o"])
        .arg(&job)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "--control-points: 7 in v is outside [4, 5]",
        ));
    t2spline()
        .arg("fit")
        .arg(&readings)
        .args(["--control-points", "5,x"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "--control-points: `5,x` is not a count M or a pair M,N",
        ));
    assert!(!job.exists(), "nothing is written on an error");
    // A pair is for nets only.
    let example =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fit-measurements.json");
    t2spline()
        .arg("fit")
        .arg(example)
        .args(["--control-points", "5,5"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "a pair M,N is for a net of data points",
        ));
}

/// The seabed fitted to real topography and bathymetry (docs/terrain.md).
fn seabed() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/salish-sea-seabed.json")
}

#[test]
fn the_shipped_seabed_runs() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("result.json");
    t2spline()
        .arg("run")
        .arg(seabed())
        .arg("-o")
        .arg(&out)
        .assert()
        .code(0);
    let v = read_json(&out);
    assert_eq!(v["degree"], json!([3, 3]));
    assert_eq!(v["alpha"], json!(0.5));
    let max = v["error"]["max"].as_f64().unwrap();
    assert!(max > 0.0 && max.is_finite(), "{max}");
}
