//! An alpha a few ulps above a number's lower height (the paper's jump at
//! `alpha = h`, docs/method.md §3) through the built binary: the result file
//! says so in a `note` naming the height, for one job and for each job of a
//! run of many; at the height, above it, or with a reduction that does not
//! use alpha, the result has no `note`.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

/// `numpy.linspace(0, 1, 21)[12]`: one ulp above the example's height 0.6.
const SWEEP: &str = "0.6000000000000001";

/// Runs `t2spline args…`, which must succeed, and returns (stdout, stderr).
fn t2spline(args: &[&str]) -> (String, String) {
    let out = Command::cargo_bin("t2spline")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert!(out.status.success(), "{args:?}: {out:?}");
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn the_result_names_the_height_only_next_to_it() {
    let job = example();
    let job = job.to_str().unwrap();
    let (stdout, stderr) = t2spline(&["run", job, "--alpha", SWEEP, "--samples", "5"]);
    let v: Value = serde_json::from_str(&stdout).unwrap();
    let note = v["note"].as_str().expect("a note");
    assert!(
        note.starts_with("alpha 0.6000000000000001 lies 1 ulp above the lower height 0.6 "),
        "{note}"
    );
    // The same words as the line on standard error.
    assert_eq!(stderr, format!("t2spline run: note: {note}\n"));
    // After `regime`, before `control_points`.
    let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
    let at = keys.iter().position(|k| *k == "note").unwrap();
    assert_eq!(
        (keys[at - 1].as_str(), keys[at + 1].as_str()),
        ("regime", "control_points")
    );
    for args in [
        vec!["--alpha", "0.6"],
        vec!["--alpha", "0.61"],
        vec!["--alpha", SWEEP, "--type-reduction", "centroid"],
    ] {
        let mut all = vec!["run", job, "--samples", "5"];
        all.extend(&args);
        let (stdout, _) = t2spline(&all);
        let v: Value = serde_json::from_str(&stdout).unwrap();
        assert!(v.get("note").is_none(), "{args:?}: {}", v["note"]);
    }
}

#[test]
fn each_job_of_many_carries_its_own_note() {
    let dir = tempfile::tempdir().unwrap();
    let mut job: Value =
        serde_json::from_str(&std::fs::read_to_string(example()).unwrap()).unwrap();
    let jobs = dir.path().join("jobs");
    std::fs::create_dir(&jobs).unwrap();
    for (name, alpha) in [("a", 0.6), ("b", 0.600_000_000_000_000_1)] {
        job["alpha"] = alpha.into();
        std::fs::write(jobs.join(format!("{name}.json")), job.to_string()).unwrap();
    }
    let out = dir.path().join("out");
    t2spline(&[
        "run",
        "--jobs",
        jobs.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    let read = |name: &str| -> Value {
        serde_json::from_str(&std::fs::read_to_string(out.join(name)).unwrap()).unwrap()
    };
    assert!(read("a.json").get("note").is_none());
    assert!(read("b.json")["note"]
        .as_str()
        .unwrap()
        .contains("above the lower height 0.6 "));
}
