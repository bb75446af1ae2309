//! `t2spline fuzzify`, `t2spline fit READINGS.csv` and `t2spline export`: the
//! built binary on the shipped example and on bad input (one line with the
//! place and the rule, the README's exit codes, no partial output).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn t2spline() -> Command {
    let mut c = Command::cargo_bin("t2spline").unwrap();
    c.current_dir(root()).env("SOURCE_DATE_EPOCH", "0");
    c
}

const PAPER: &str = "examples/paper-alg-1-1.json";

#[test]
fn fuzzify_rebuilds_the_shipped_example() {
    let out = t2spline()
        .args([
            "fuzzify",
            "examples/beach-readings.csv",
            "--tolerance",
            "0.02",
            "--alpha",
            "0.5",
        ])
        .assert()
        .code(0)
        .stderr("")
        .get_output()
        .stdout
        .clone();
    let shipped = std::fs::read_to_string(root().join("examples/fit-measurements.json")).unwrap();
    assert_eq!(String::from_utf8(out).unwrap(), shipped);
}

#[test]
fn fit_reads_readings_directly_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.json"), dir.path().join("b.json"));
    t2spline()
        .args(["fit", "examples/beach-readings.csv", "--tolerance", "0.02", "-o"])
        .arg(&a)
        .assert()
        .code(0)
        .stderr(predicate::str::contains(
            "t2spline fit: examples/beach-readings.csv: a readings file (CSV), fuzzified first as `t2spline fuzzify` does",
        ));
    t2spline()
        .args(["fit", "examples/fit-measurements.json", "-q", "-o"])
        .arg(&b)
        .assert()
        .code(0);
    let read =
        |p: &Path| -> Value { serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap() };
    let (a, b) = (read(&a), read(&b));
    for key in ["degree", "weights", "knots", "points", "description"] {
        assert_eq!(a[key], b[key], "{key}");
    }
}

#[test]
fn readings_options_are_only_for_readings() {
    t2spline()
        .args(["fit", "examples/fit-measurements.json", "--tolerance", "0.1"])
        .assert()
        .code(2)
        .stderr(
            "t2spline: --tolerance: only for a readings file (CSV); examples/fit-measurements.json is a data file, whose numbers and degree are its own\n",
        );
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn bad_readings_are_one_line_each_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let bad = write(
        dir.path(),
        "bad.csv",
        "station,x,y\nA,0,1\nA,0.5,abc\nB,1,1\nB,2\nA,3,3\n",
    );
    let out = write(dir.path(), "data.json", "old");
    let stderr = format!(
        "t2spline: {0}:3:7: y (column 3): `abc` is not a number\n\
         t2spline: {0}:5:4: missing column(s) y: every row needs 3 values (station,x,y)\n\
         t2spline: {0}:4:1: station `B`: 1 reading(s); percentiles need at least 2\n",
        bad.display()
    );
    t2spline()
        .arg("fuzzify")
        .arg(&bad)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(2)
        .stdout("")
        .stderr(stderr);
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "old");
    // fit of the same file says the same.
    t2spline()
        .arg("fit")
        .arg(&bad)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "3:7: y (column 3): `abc` is not a number",
        ));
}

#[test]
fn options_of_fuzzify_are_checked() {
    let dir = tempfile::tempdir().unwrap();
    let two = write(
        dir.path(),
        "two.csv",
        "station,x,y\nA,0,0\nA,1,1\nB,2,2\nB,3,3\n",
    );
    let cases: [(&[&str], &str); 5] = [
        (
            &["--tolerance", "-1"],
            "t2spline: --tolerance: tolerance = -1 is outside [0, 1e150]\n",
        ),
        (
            &["--lower-height", "0"],
            "t2spline: --lower-height: lower_height = 0 is outside (0, 1]\n",
        ),
        (
            &["--degree", "0"],
            "t2spline: --degree: a fit needs degree 1 to 31 (order 2 to 32)\n",
        ),
        (
            &["--alpha", "2"],
            "t2spline: --alpha: alpha = 2 is outside [0, 1]\n",
        ),
        (&["--order", "4"], ""),
    ];
    for (args, stderr) in cases {
        let assert = t2spline()
            .arg("fuzzify")
            .arg(&two)
            .args(args)
            .assert()
            .code(2);
        if stderr.is_empty() {
            assert.stderr(predicate::str::ends_with(
                "2 stations, but a curve of degree 3 needs at least 4; give a lower degree\n",
            ));
        } else {
            assert.stderr(stderr);
        }
    }
    t2spline()
        .arg("fuzzify")
        .arg(&two)
        .args(["--degree", "1"])
        .assert()
        .code(0);
}

#[test]
fn unreadable_and_oversized_readings() {
    let dir = tempfile::tempdir().unwrap();
    t2spline()
        .arg("fuzzify")
        .arg(dir.path().join("missing.csv"))
        .assert()
        .code(3)
        .stderr(predicate::str::contains(
            "missing.csv: cannot read: No such file or directory",
        ));
    let big = dir.path().join("big.csv");
    std::fs::File::create(&big)
        .unwrap()
        .set_len((64 << 20) + 1)
        .unwrap();
    t2spline()
        .arg("fuzzify")
        .arg(&big)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("more than the limit of 64 MiB"));
}

#[test]
fn export_writes_every_format() {
    let dir = tempfile::tempdir().unwrap();
    for (file, start) in [
        ("c.dxf", "  0\nSECTION\n  2\nHEADER\n"),
        ("c.step", "ISO-10303-21;\n"),
        ("c.igs", "t2spline: a run's curves or surfaces"),
        ("c.obj", "# t2spline"),
    ] {
        let path = dir.path().join(file);
        t2spline()
            .args(["export", PAPER, "-o"])
            .arg(&path)
            .assert()
            .code(0)
            .stdout("")
            .stderr("");
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.starts_with(start), "{file}: {}", &text[..40]);
    }
    // The same run, the same file (SOURCE_DATE_EPOCH fixes the time stamp).
    let other = tempfile::tempdir().unwrap();
    let again = other.path().join("c.step");
    t2spline()
        .args(["export", PAPER, "-o"])
        .arg(&again)
        .assert()
        .code(0);
    let (a, b) = (
        std::fs::read(dir.path().join("c.step")).unwrap(),
        std::fs::read(&again).unwrap(),
    );
    assert!(a == b, "two exports of one job differ");
    assert!(String::from_utf8(a)
        .unwrap()
        .contains("'1970-01-01T00:00:00'"));
    // Standard output, with the format named.
    t2spline()
        .args([
            "export", PAPER, "-o", "-", "--format", "obj", "--alpha", "0.2",
        ])
        .assert()
        .code(0)
        .stdout(predicate::str::contains("g defuzzified\n"));
}

#[test]
fn export_failures_name_their_place_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no/such/folder/c.step");
    t2spline()
        .args(["export", PAPER, "-o"])
        .arg(&missing)
        .assert()
        .code(4)
        .stderr(predicate::str::contains(
            "c.step: cannot write: No such file or directory",
        ));
    let old = write(dir.path(), "old.dxf", "old");
    t2spline()
        .args(["export", PAPER, "--alpha", "2", "-o"])
        .arg(&old)
        .assert()
        .code(2)
        .stderr("t2spline: --alpha: alpha = 2 is outside [0, 1]\n");
    assert_eq!(std::fs::read_to_string(&old).unwrap(), "old");
    t2spline()
        .args(["export", PAPER, "-o"])
        .arg(dir.path().join("c.pdf"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "--format: missing: the extension of",
        ));
    let flat = write(
        dir.path(),
        "flat.json",
        r#"{"degree": 0, "alpha": 0.5, "lower_height": 0.5, "points": [
            {"x": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]},
             "y": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}}]}"#,
    );
    t2spline()
        .arg("export")
        .arg(&flat)
        .arg("-o")
        .arg(&old)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("the curves have degree 0 (piecewise constant: a set of points), which DXF cannot hold; export needs degree 1 or more"));
    assert_eq!(std::fs::read_to_string(&old).unwrap(), "old");
}

#[test]
fn readings_on_standard_input_are_told_by_their_content() {
    let text = "\u{feff}station;x;y\r\nA;0;0\r\nA;0,5;1\r\nB;2;1\r\nB;3;2\r\n";
    let out = t2spline()
        .args(["fuzzify", "-", "--degree", "1"])
        .write_stdin(text)
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let data: Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(data["points"][0]["x"]["crisp"], serde_json::json!(0.25));
    t2spline()
        .args(["fit", "-", "--degree", "1", "-o", "-"])
        .write_stdin(text)
        .assert()
        .code(0)
        .stderr(predicate::str::contains(
            "<stdin>: a readings file (CSV), fuzzified first",
        ))
        .stdout(predicate::str::contains("\"knots\""));
}

#[test]
fn export_names_are_matched_without_case_and_a_contradicting_format_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let upper = dir.path().join("C.STEP");
    t2spline()
        .args(["export", PAPER, "-o"])
        .arg(&upper)
        .assert()
        .code(0);
    assert!(std::fs::read_to_string(&upper)
        .unwrap()
        .starts_with("ISO-10303-21;\n"));
    // The same format named twice is no contradiction.
    t2spline()
        .args(["export", PAPER, "--format", "step", "-o"])
        .arg(dir.path().join("d.Stp"))
        .assert()
        .code(0);
    let step = dir.path().join("e.step");
    t2spline()
        .args(["export", PAPER, "--format", "dxf", "-o"])
        .arg(&step)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "--format: dxf contradicts the name",
        ))
        .stderr(predicate::str::contains("whose extension says step"));
    assert!(!step.exists());
}

/// The unit a CAD file records: `--units`, else the job's `units`, else
/// millimetres; a unit not in the list is refused by name.
#[test]
fn export_records_the_unit_of_the_option_else_the_job() {
    let dir = tempfile::tempdir().unwrap();
    let example = root().join("examples/paper-alg-1-1.json");
    let mut job: Value = serde_json::from_str(&std::fs::read_to_string(&example).unwrap()).unwrap();
    job["units"] = Value::from("m");
    let in_metres = dir.path().join("metres.json");
    std::fs::write(&in_metres, job.to_string()).unwrap();
    let insunits = |job: &Path, extra: &[&str]| {
        let out = dir.path().join("out.dxf");
        t2spline()
            .arg("export")
            .arg(job)
            .arg("-o")
            .arg(&out)
            .args(extra)
            .assert()
            .success();
        let text = std::fs::read_to_string(&out).unwrap();
        let at = text.find("$INSUNITS\n 70\n").expect("the header variable");
        text[at + 14..].lines().next().unwrap().to_owned()
    };
    assert_eq!(insunits(&example, &[]), "4");
    assert_eq!(insunits(&in_metres, &[]), "6");
    assert_eq!(insunits(&in_metres, &["--units", "in"]), "1");
    t2spline()
        .arg("export")
        .arg(&example)
        .args([
            "-o",
            dir.path().join("x.dxf").to_str().unwrap(),
            "--units",
            "yd",
        ])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--units").and(predicate::str::contains("yd")));
}
