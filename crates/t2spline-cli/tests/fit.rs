//! `t2spline fit`: the built binary on the shipped example and on bad input.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::{json, Value};

/// The shipped example (relative to this crate).
fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fit-measurements.json")
}

fn t2spline() -> Command {
    Command::cargo_bin("t2spline").unwrap()
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn fits_the_example_into_a_job_that_runs() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    t2spline()
        .arg("fit")
        .arg(example())
        .arg("-o")
        .arg(&job)
        .assert()
        .code(0)
        .stdout("")
        .stderr(predicate::str::contains(
            "13 data points, degree 3, chord parameters: interpolation, 13 control points",
        ))
        // The README quotes these numbers.
        .stderr(predicate::str::contains(
            "each layer fitted on its own would break the order of the seven values at 35 place(s)",
        ))
        .stderr(predicate::str::contains(
            "upper_left      1.606e-1  points[8].y   spread  1.606e-1  points[8].y",
        ))
        .stderr(
            predicate::str::is_match(
                r"crisp +[0-9.]+e-1[0-9] +points\[\d+\]\.[xy] +\(interpolated\)",
            )
            .unwrap(),
        );
    let v = read_json(&job);
    assert_eq!(v["degree"], json!(3));
    assert_eq!(v["points"].as_array().unwrap().len(), 13);
    // The data file (made by `t2spline fuzzify`) leaves samples to the default.
    assert_eq!(v["samples"], Value::Null);
    t2spline()
        .args(["validate"])
        .arg(&job)
        .assert()
        .code(0)
        .stdout(predicate::str::contains(
            "ok: 2-D curve, 13 control points, order 4, alpha 0.5, 101 samples",
        ));
    t2spline().arg("run").arg(&job).assert().code(0);
}

#[test]
fn writes_to_standard_output_and_reads_standard_input() {
    let text = std::fs::read_to_string(example()).unwrap();
    let out = t2spline()
        .args(["fit", "-", "--quiet", "--parametrization", "centripetal"])
        .write_stdin(text)
        .assert()
        .code(0)
        .stderr("")
        .get_output()
        .stdout
        .clone();
    let v: Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["knots"].as_array().unwrap().len(), 17);
}

#[test]
fn least_squares_with_fewer_control_points() {
    let out = t2spline()
        .arg("fit")
        .arg(example())
        .args(["--control-points", "7", "-q"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let v: Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["points"].as_array().unwrap().len(), 7);
    assert_eq!(v["knots"].as_array().unwrap().len(), 11);
}

#[test]
fn independent_fit_of_the_example_is_refused_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    std::fs::write(&job, "old").unwrap();
    t2spline()
        .arg("fit")
        .arg(example())
        .args(["--fuzzy-fit", "independent", "-o"])
        .arg(&job)
        .assert()
        .code(2)
        .stdout("")
        .stderr(predicate::str::contains("fitting every layer on its own breaks the order of the seven values at"))
        .stderr(predicate::str::is_match(
            r"t2spline: .*fit-measurements.json: control point \d+, [xy]: the order [a-z.]+ <= [a-z.]+ is broken: ",
        ).unwrap())
        .stderr(predicate::str::contains("no job written"));
    assert_eq!(std::fs::read_to_string(&job).unwrap(), "old");
}

/// Data near the limit of coordinates (1e150) whose interpolant swings
/// beyond it: the fit names the control value and the limit, in both modes,
/// never broken orders (there are none) nor `--fuzzy-fit valid` (given).
#[test]
fn a_fitted_control_value_beyond_the_limit_is_named() {
    let n = |c: f64| {
        json!({"crisp": c, "upper": [c - 1e148, c + 1e148], "primary": [c - 5e147, c + 5e147],
               "lower": [c - 1e147, c + 1e147]})
    };
    let ys = [0.0, 9e149, -9e149, 9e149, 0.0];
    let points: Vec<Value> = ys
        .iter()
        .enumerate()
        .map(|(i, &y)| json!({"x": n(i as f64 * 1e149), "y": n(y)}))
        .collect();
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("big.json");
    let text = json!({"degree": 3, "lower_height": 0.5, "points": points}).to_string();
    std::fs::write(&data, text).unwrap();
    for mode in ["valid", "independent"] {
        let out = t2spline()
            .arg("fit")
            .arg(&data)
            .args(["--fuzzy-fit", mode])
            .assert()
            .code(2)
            .stdout("")
            .get_output()
            .clone();
        let stderr = String::from_utf8(out.stderr).unwrap();
        let lines: Vec<&str> = stderr.lines().collect();
        assert_eq!(lines.len(), 1, "{mode}: {stderr}");
        assert!(
            predicate::str::is_match(
                r"^t2spline: .*big\.json: control point 1, y, layer crisp: the fitted value [0-9.]+e150 is beyond the limit of coordinates, \[-1e150, 1e150\]; "
            )
            .unwrap()
            .eval(lines[0]),
            "{mode}: {stderr}"
        );
        assert!(
            !stderr.contains("breaks the order") && !stderr.contains("--fuzzy-fit"),
            "{mode}: {stderr}"
        );
    }
}

#[test]
fn bad_options_are_named() {
    t2spline()
        .arg("fit")
        .arg(example())
        .args(["--control-points", "3"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "t2spline: --control-points: 3 is outside [4, 13]",
        ));
    t2spline()
        .arg("fit")
        .arg(example())
        .args(["--parametrization", "chordal"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("invalid value 'chordal'"));
}

fn write_data(dir: &Path, v: &Value) -> PathBuf {
    let path = dir.join("data.json");
    std::fs::write(&path, v.to_string()).unwrap();
    path
}

#[test]
fn bad_data_files_name_file_place_and_rule() {
    let dir = tempfile::tempdir().unwrap();
    let n = |c: f64| json!({"crisp": c, "upper": [c - 0.3, c + 0.3], "primary": [c - 0.2, c + 0.2], "lower": [c - 0.1, c + 0.1]});
    let good: Vec<Value> = (0..5)
        .map(|k| json!({"x": n(f64::from(k)), "y": n(f64::from(k * k))}))
        .collect();

    let mut v = json!({"degree": 2, "lower_height": 0.5, "knots": [0, 1], "points": good.clone()});
    let path = write_data(dir.path(), &v);
    t2spline()
        .arg("fit")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicate::str::starts_with(format!(
            "t2spline: {}:1:",
            path.display()
        )))
        .stderr(predicate::str::contains(
            ": knots: not allowed in a data file",
        ));

    v = json!({"degree": 2, "lower_height": 0.5, "points": good.clone()});
    v["points"][1]["y"]["primary"] = json!([0.5, 1.05]);
    let path = write_data(dir.path(), &v);
    // Both lines at the key `"y"` of points[1] (line 1: the file is compact).
    let text = std::fs::read_to_string(&path).unwrap();
    let y = text.match_indices("\"y\"").nth(1).unwrap().0 + 1;
    t2spline()
        .arg("fit")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(format!(
            "t2spline: {0}:1:{y}: points[1].y: the order upper.left <= primary.left is broken: 0.7 > 0.5\n\
             t2spline: {0}:1:{y}: points[1].y: the order lower.right <= primary.right is broken: 1.1 > 1.05\n",
            path.display()
        ));

    v = json!({"degree": 2, "lower_height": 0.5, "points": good.clone()});
    v["points"][3] = v["points"][2].clone();
    let path = write_data(dir.path(), &v);
    t2spline()
        .arg("fit")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "points[2] and points[3]: consecutive data points",
        ));
    // Uniform parameters accept the repeat (a curve may pass a point twice).
    t2spline()
        .arg("fit")
        .arg(&path)
        .args(["--parametrization", "uniform", "-q"])
        .assert()
        .code(0);

    t2spline()
        .arg("fit")
        .arg(dir.path().join("missing.json"))
        .assert()
        .code(3)
        .stderr(predicate::str::contains("missing.json: cannot read"));
}

#[test]
fn independent_fit_is_written_when_it_is_valid() {
    // Equal spreads everywhere: every layer is the crisp curve moved by a
    // constant, and fitting each on its own keeps the order.
    let dir = tempfile::tempdir().unwrap();
    let n = |c: f64| json!({"crisp": c, "upper": [c - 0.3, c + 0.4], "primary": [c - 0.2, c + 0.2], "lower": [c - 0.1, c + 0.05]});
    let points: Vec<Value> = (0..6)
        .map(|k| json!({"x": n(f64::from(k)), "y": n(f64::from(k * k % 7))}))
        .collect();
    let path = write_data(
        dir.path(),
        &json!({"order": 3, "lower_height": 0.8, "points": points}),
    );
    t2spline()
        .arg("fit")
        .arg(&path)
        .args(["--fuzzy-fit", "independent", "-o"])
        .arg(dir.path().join("job.json"))
        .assert()
        .code(0)
        .stderr(predicate::str::contains(
            "each layer fitted on its own gives valid fuzzy control points",
        ));
    let v = read_json(&dir.path().join("job.json"));
    assert_eq!(v["order"], json!(3));
    assert_eq!(v["lower_height"], json!(0.8));
}

/// A data file takes a job's keys but `weights` and `knots`: its
/// `type_reduction` is carried into the job written, and an unknown key is
/// offered only keys a data file accepts.
#[test]
fn a_data_file_carries_its_type_reduction_into_the_job() {
    let dir = tempfile::tempdir().unwrap();
    let mut v = read_json(&example());
    v["type_reduction"] = json!("centroid");
    let path = write_data(dir.path(), &v);
    let job = dir.path().join("job.json");
    t2spline()
        .arg("fit")
        .arg(&path)
        .arg("-o")
        .arg(&job)
        .arg("-q")
        .assert()
        .code(0);
    assert_eq!(read_json(&job)["type_reduction"], json!("centroid"));
    t2spline()
        .arg("validate")
        .arg(&job)
        .assert()
        .code(0)
        .stdout(predicate::str::contains(
            "alpha 0.5 (unused: type reduction centroid does not use alpha)",
        ));
    v["colour"] = json!("red");
    let path = write_data(dir.path(), &v);
    t2spline()
        .arg("fit")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "colour: unknown key (known keys: description, order, degree, alpha, type_reduction, lower_height, samples, points)",
        ));
}

/// `--tolerance -0` is 0, and the description says so.
#[test]
fn a_negative_zero_tolerance_is_described_as_zero() {
    let readings = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/beach-readings.csv");
    let out = t2spline()
        .arg("fuzzify")
        .arg(&readings)
        .args(["--tolerance", "-0"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let v: Value = serde_json::from_slice(&out).unwrap();
    let description = v["description"].as_str().unwrap();
    assert!(description.contains("with T = 0 "), "{description}");
    assert!(!description.contains("-0"), "{description}");
}

/// `fit` of a readings file takes `--alpha` as `fuzzify` does: the job it
/// writes carries it and runs, and equals the fit of `fuzzify`'s data file;
/// without it the job has no alpha and `run` asks for one; a bad alpha is
/// named; on a data file `--alpha` replaces the file's.
#[test]
fn a_fit_of_readings_takes_alpha_and_its_job_runs() {
    let readings = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/beach-readings.csv");
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    t2spline()
        .arg("fit")
        .arg(&readings)
        .args(["--alpha", "0.4", "--tolerance", "0.05", "-q", "-o"])
        .arg(&job)
        .assert()
        .code(0);
    assert_eq!(read_json(&job)["alpha"], json!(0.4));
    let run = t2spline()
        .arg("run")
        .arg(&job)
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let result: Value = serde_json::from_slice(&run).unwrap();
    assert_eq!(result["alpha"], json!(0.4));
    // The same job as fuzzify's data file fitted.
    let data = dir.path().join("data.json");
    t2spline()
        .arg("fuzzify")
        .arg(&readings)
        .args(["--alpha", "0.4", "--tolerance", "0.05", "-o"])
        .arg(&data)
        .assert()
        .code(0);
    let again = dir.path().join("again.json");
    t2spline()
        .arg("fit")
        .arg(&data)
        .args(["-q", "-o"])
        .arg(&again)
        .assert()
        .code(0);
    assert_eq!(std::fs::read(&job).unwrap(), std::fs::read(&again).unwrap());
    // Without --alpha: no alpha in the job, and `run` says how to give one.
    let bare = dir.path().join("bare.json");
    t2spline()
        .arg("fit")
        .arg(&readings)
        .args(["-q", "-o"])
        .arg(&bare)
        .assert()
        .code(0);
    assert_eq!(read_json(&bare).get("alpha"), None);
    t2spline()
        .arg("run")
        .arg(&bare)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--alpha"));
    t2spline()
        .arg("run")
        .arg(&bare)
        .args(["--alpha", "0.4"])
        .assert()
        .code(0);
    // Out of range: named, nothing written.
    let bad = dir.path().join("bad.json");
    t2spline()
        .arg("fit")
        .arg(&readings)
        .args(["--alpha", "1.5", "-o"])
        .arg(&bad)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--alpha"));
    assert!(!bad.exists());
    // On a data file, --alpha replaces the file's alpha.
    let over = dir.path().join("over.json");
    t2spline()
        .arg("fit")
        .arg(&data)
        .args(["--alpha", "0.9", "-q", "-o"])
        .arg(&over)
        .assert()
        .code(0);
    assert_eq!(read_json(&over)["alpha"], json!(0.9));
}

#[test]
fn a_closed_or_gone_standard_error_does_not_stop_the_fit() {
    // The report goes to standard error; `fit … 2>&1 | head` closes it early
    // and `2>&-` closes it from the start. The fit is written either way.
    let dir = tempfile::tempdir().unwrap();
    for closed_at_start in [false, true] {
        let out = dir.path().join(format!("fit-{closed_at_start}.json"));
        let status = if closed_at_start {
            // A shell's `2>&-`: descriptor 2 closed in the command.
            std::process::Command::new("sh")
                .arg("-c")
                .arg(r#"exec "$0" fit "$1" -o "$2" 2>&-"#)
                .arg(env!("CARGO_BIN_EXE_t2spline"))
                .arg(example())
                .arg(&out)
                .status()
                .unwrap()
        } else {
            let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_t2spline"))
                .arg("fit")
                .arg(example())
                .arg("-o")
                .arg(&out)
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap();
            // The reader goes away before the report is written.
            drop(child.stderr.take());
            child.wait().unwrap()
        };
        assert!(
            status.success(),
            "closed at start: {closed_at_start}: {status:?}"
        );
        let job = read_json(&out);
        assert!(job["points"].as_array().is_some_and(|p| !p.is_empty()));
    }
}
