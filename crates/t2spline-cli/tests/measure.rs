//! `measure` (quantities measured on a fuzzy curve, docs/method.md §11):
//! the file's shape on the shipped example, the output file written
//! atomically, exit codes and messages naming the flag and the rule, no
//! output file when the input is bad, and a surface refused.

use std::path::{Path, PathBuf};
use std::process::Command;

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn terrain() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-terrain.json")
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().expect("exited, not killed"),
        String::from_utf8(out.stdout).expect("UTF-8"),
        String::from_utf8(out.stderr).expect("UTF-8"),
    )
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

/// `args` followed by `-o OUT` must exit 2 with a message holding `words`,
/// and leave no OUT.
fn refused(args: &[&str], words: &str) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let mut all = vec!["measure"];
    all.extend(args);
    all.extend(["-o", s(&out)]);
    let (code, stdout, stderr) = run(&all);
    assert_eq!(code, 2, "{args:?}: {stderr}");
    assert_eq!(stdout, "");
    assert!(stderr.starts_with("t2spline: "), "{stderr}");
    assert!(stderr.contains(words), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!out.exists(), "{args:?} wrote its output");
}

#[test]
fn the_example_measured_into_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("m.json");
    let (code, stdout, stderr) =
        run(&["measure", s(&example()), "--at", "0.25,0.5", "-o", s(&out)]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stdout, "");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(v["levels"].as_array().unwrap().len(), 11);
    let upper = v["length"]["upper"].as_array().unwrap();
    assert_eq!(upper.len(), 11);
    // The level 0.5: lengths from 7.2953 to 10.6953.
    assert_eq!(upper[5]["alpha"], 0.5);
    let (lo, hi) = (
        upper[5]["min"].as_f64().unwrap(),
        upper[5]["max"].as_f64().unwrap(),
    );
    assert!(
        (lo - 7.2953).abs() < 5e-5 && (hi - 10.6953).abs() < 5e-5,
        "{lo} {hi}"
    );
    assert_eq!(upper[5]["exact"], true);
    // The lower function up to its height 0.6.
    assert_eq!(v["length"]["lower"].as_array().unwrap().len(), 7);
    assert_eq!(v["area"]["kind"], "under");
    let at = v["at"].as_array().unwrap();
    assert_eq!(at.len(), 2);
    assert_eq!(at[1]["t"], 0.5);
    let d = &at[1]["derivative"]["upper"][0];
    assert_eq!(d["min"].as_array().unwrap().len(), 2);
    assert!(at[1]["tangent_angle"]["upper"][0]["defined"]
        .as_bool()
        .unwrap());
    assert!(at[1]["curvature"]["primary"][10]["max"].as_f64().unwrap() > 0.0);
}

#[test]
fn bad_flags_name_the_flag_and_write_nothing() {
    let e = example();
    let job = s(&e);
    refused(
        &[job, "--at", "1.5"],
        "--at: at[0] = 1.5 is outside the domain [0, 1]",
    );
    refused(
        &[job, "--at", "0.5,x"],
        "--at: item 2 `x` is not a finite number",
    );
    refused(&[job, "--at", "nan"], "--at: item 1");
    refused(&[job, "--levels", "1"], "--levels: 1 is outside 2 ..= 1001");
    refused(&[job, "--levels", "5000"], "--levels");
    refused(&[job, "--order", "0"], "--order: 0 is outside 1 ..= 64");
}

#[test]
fn a_surface_is_refused() {
    let t = terrain();
    refused(&[s(&t)], "measures are taken of curves");
}

#[test]
fn a_bad_job_names_its_place() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("bad.json");
    std::fs::write(&job, "{\"order\": 2, \"alhpa\": 1, \"points\": []}").unwrap();
    let (code, _, stderr) = run(&["measure", s(&job)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("bad.json:1:"), "{stderr}");
}

#[test]
fn the_output_may_not_be_the_job() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    std::fs::copy(example(), &job).unwrap();
    let before = std::fs::read(&job).unwrap();
    let (code, _, stderr) = run(&["measure", s(&job), "-o", s(&job)]);
    assert_ne!(code, 0);
    assert!(stderr.contains("--output"), "{stderr}");
    assert_eq!(std::fs::read(&job).unwrap(), before);
}
