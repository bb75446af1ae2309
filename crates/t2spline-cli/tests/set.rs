//! `membership`, `region` and `section` (the fuzzy curve as a set,
//! docs/method.md §10): exit codes, messages naming the place and the rule,
//! and no output file when the input is bad.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn terrain() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-terrain.json")
}

/// Runs `t2spline args…` with `stdin`; (exit code, stdout, stderr).
fn run_with(args: &[&str], stdin: &[u8]) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let _ = child.stdin.take().expect("piped").write_all(stdin);
    let out = child.wait_with_output().expect("it ends");
    (
        out.status.code().expect("exited, not killed"),
        String::from_utf8(out.stdout).expect("UTF-8"),
        String::from_utf8(out.stderr).expect("UTF-8"),
    )
}

fn run(args: &[&str]) -> (i32, String, String) {
    run_with(args, b"")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

/// `args` followed by `-o OUT` must exit 2 with a message holding `words`,
/// and leave no OUT.
fn refused(args: &[&str], words: &str) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let mut all = args.to_vec();
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
fn membership_grades_the_crisp_end_points_and_a_far_point() {
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("p.csv");
    std::fs::write(&points, "x,y\n6,1\n100,100\n1,1\n").unwrap();
    let (code, stdout, stderr) = run(&["membership", s(&example()), s(&points)]);
    assert_eq!(code, 0, "{stderr}");
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines[0], "x,y,upper,primary,lower");
    assert_eq!(lines[2], "100,100,0,0,0");
    for line in [lines[1], lines[3]] {
        let g: Vec<f64> = line.split(',').map(|v| v.parse().unwrap()).collect();
        assert!(
            (g[2] - 1.0).abs() < 1e-9 && (g[3] - 1.0).abs() < 1e-9,
            "{line}"
        );
        assert!((g[4] - 0.6).abs() < 1e-9, "{line}");
    }
    assert!(lines[1].starts_with("6,1,") && lines[3].starts_with("1,1,"));
}

#[test]
fn a_bad_points_file_names_file_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("p.csv");
    std::fs::write(&points, "x,y\n1,2\n3,two\n4\n5,NaN\n").unwrap();
    let p = s(&points);
    refused(
        &["membership", s(&example()), p],
        &format!("t2spline: {p}:3:3: y (column 2): `two` is not a number\n"),
    );
    refused(
        &["membership", s(&example()), p],
        &format!("{p}:4:2: y (column 2) is missing; every row has x,y\n"),
    );
    refused(
        &["membership", s(&example()), p],
        &format!("{p}:5:3: y (column 2): `NaN` is not a number\n"),
    );
    std::fs::write(&points, "a,b\n1,2\n").unwrap();
    refused(
        &["membership", s(&example()), p],
        &format!("{p}:1:1: the header must be x,y or x,y,z, not `a,b`"),
    );
    std::fs::write(&points, "x,y,z\n1,2,3\n").unwrap();
    refused(
        &["membership", s(&example()), p],
        "the job is a plane curve, so the header must be x,y",
    );
}

#[test]
fn option_values_that_break_a_rule() {
    let job = example();
    let job = s(&job);
    refused(&["region", job, "--alpha", "1.5"], "--alpha: ");
    refused(&["region", job, "--alpha", "nan"], "--alpha: ");
    for t in ["0", "-1", "nan", "inf"] {
        refused(
            &["region", job, "--alpha", "0.5", "--tolerance", t],
            "--tolerance: ",
        );
        refused(
            &["section", job, "--x", "3", "--tolerance", t],
            "--tolerance: ",
        );
    }
    // The finest tolerance allowed, rounded up so that the number shown is allowed.
    refused(
        &["region", job, "--alpha", "0.5", "--tolerance", "1e-13"],
        "t2spline: --tolerance: tolerance = 1e-13 must be a positive number of at least 6.5e-7\n",
    );
    let (code, _, stderr) = run(&["region", job, "--alpha", "0.5", "--tolerance", "6.5e-7"]);
    assert_eq!(code, 0, "{stderr}");
    refused(
        &["section", job, "--x", "3", "--levels", "1"],
        "--levels: 1 is outside 2 ..= 1001",
    );
    refused(
        &["section", job, "--x", "nan"],
        "t2spline: --x: NaN is not a finite number",
    );
    refused(
        &["section", job, "--at", "3,2"],
        "--x: the job is a plane curve",
    );
    refused(
        &["section", s(&terrain()), "--x", "3"],
        "--at: the job is a surface",
    );
    refused(
        &["section", s(&terrain()), "--at", "3;2"],
        "--at: `3;2` is not two finite numbers X0,Y0",
    );
    refused(
        &["region", s(&terrain()), "--alpha", "0.5"],
        &format!("{}: regions are drawn for curves", s(&terrain())),
    );
}

#[test]
fn the_output_may_not_overwrite_an_input() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("job.json");
    let text = std::fs::read_to_string(example()).unwrap();
    std::fs::write(&job, &text).unwrap();
    let points = dir.path().join("p.csv");
    std::fs::write(&points, "x,y\n1,1\n").unwrap();
    for args in [
        vec!["region", s(&job), "--alpha", "0.5", "-o", s(&job)],
        vec!["section", s(&job), "--x", "3", "-o", s(&job)],
        vec!["membership", s(&job), s(&points), "-o", s(&job)],
        vec!["membership", s(&job), s(&points), "-o", s(&points)],
    ] {
        let (code, _, stderr) = run(&args);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert!(stderr.contains("--output"), "{stderr}");
    }
    assert_eq!(std::fs::read_to_string(&job).unwrap(), text);
    assert_eq!(std::fs::read_to_string(&points).unwrap(), "x,y\n1,1\n");
}

#[test]
fn missing_inputs_exit_3() {
    let (code, _, stderr) = run(&["region", "no/such/job.json", "--alpha", "0.5"]);
    assert_eq!(code, 3, "{stderr}");
    let (code, _, stderr) = run(&["membership", s(&example()), "no/such/points.csv"]);
    assert_eq!(code, 3, "{stderr}");
    assert!(stderr.contains("no/such/points.csv"), "{stderr}");
}

#[test]
fn a_level_above_h_has_no_lower_region() {
    let (code, stdout, stderr) = run(&["region", s(&example()), "--alpha", "0.7"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("\"membership\": \"upper\""));
    assert!(stdout.contains("\"membership\": \"primary\""));
    assert!(!stdout.contains("\"membership\": \"lower\""), "{stdout}");
}

#[test]
fn points_from_standard_input_and_not_both_inputs() {
    let (code, stdout, stderr) =
        run_with(&["membership", s(&example()), "-"], b"x,y\n1,1\n10,10\n");
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        stdout,
        "x,y,upper,primary,lower\n1,1,1,1,0.6\n10,10,0,0,0\n"
    );
    let (code, _, stderr) = run_with(&["membership", s(&example()), "-"], b"x,y\n1,two\n");
    assert_eq!(code, 2, "{stderr}");
    assert_eq!(
        stderr,
        "t2spline: <stdin>:2:3: y (column 2): `two` is not a number\n"
    );
    let job = std::fs::read(example()).unwrap();
    let (code, _, stderr) = run_with(&["membership", "-", "-"], &job);
    assert_eq!(code, 2, "{stderr}");
    assert_eq!(
        stderr,
        "t2spline: POINTS: standard input (`-`) can hold the job or the points, not both\n"
    );
}

#[test]
fn a_terrain_with_crisp_positions_grades_its_crisp_surface() {
    // (250, 200) is the crisp surface at (u, v) = (0.5, 0.5), height 111.745625.
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("p.csv");
    std::fs::write(&points, "x,y,z\n250,200,111.745625\n250,200,120\n").unwrap();
    let (code, stdout, stderr) = run(&["membership", s(&terrain()), s(&points)]);
    assert_eq!(code, 0, "{stderr}");
    let lines: Vec<&str> = stdout.lines().collect();
    let g: Vec<f64> = lines[1].split(',').map(|v| v.parse().unwrap()).collect();
    assert!((g[3] - 1.0).abs() < 1e-9, "{stdout}");
    assert!((g[4] - 1.0).abs() < 1e-9, "{stdout}");
    assert!((g[5] - 0.6).abs() < 1e-9, "{stdout}");
    assert_eq!(lines[2], "250,200,120,0,0,0");
}

#[test]
fn a_curve_with_crisp_stations_grades_its_crisp_curve() {
    // The example with every x crisp: (2.05, 2.875) is its crisp curve at t = 1/6.
    let dir = tempfile::tempdir().unwrap();
    let mut job: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(example()).unwrap()).unwrap();
    for p in job["points"].as_array_mut().unwrap() {
        let c = p["x"]["crisp"].clone();
        p["x"] =
            serde_json::json!({"crisp": c, "upper": [c, c], "primary": [c, c], "lower": [c, c]});
    }
    let path = dir.path().join("job.json");
    std::fs::write(&path, job.to_string()).unwrap();
    let points = dir.path().join("p.csv");
    std::fs::write(&points, "x,y\n2.05,2.875\n3.5,4.8\n").unwrap();
    let (code, stdout, stderr) = run(&["membership", s(&path), s(&points)]);
    assert_eq!(code, 0, "{stderr}");
    let lines: Vec<&str> = stdout.lines().collect();
    let g: Vec<f64> = lines[1].split(',').map(|v| v.parse().unwrap()).collect();
    assert!(
        (g[2] - 1.0).abs() < 1e-9 && (g[3] - 1.0).abs() < 1e-9,
        "{stdout}"
    );
    assert!((g[4] - 0.6).abs() < 1e-9, "{stdout}");
    assert_eq!(lines[2], "3.5,4.8,0,0,0");
}

/// The `alpha` of every feature or level of a JSON output.
fn alphas(json: &str) -> Vec<f64> {
    let v: serde_json::Value = serde_json::from_str(json).expect("JSON");
    let items = v
        .get("features")
        .or_else(|| v.get("levels"))
        .and_then(serde_json::Value::as_array)
        .unwrap_or_else(|| panic!("no features or levels: {json}"));
    let mut out: Vec<f64> = items
        .iter()
        .filter_map(|f| f.pointer("/properties/alpha").or_else(|| f.get("alpha")))
        .filter_map(serde_json::Value::as_f64)
        .collect();
    out.dedup();
    out
}

#[test]
fn the_levels_are_alpha_or_levels_or_the_job_s_alpha() {
    let shipped = example();
    let job = s(&shipped); // alpha 0.8
    let ok = |args: &[&str]| {
        let (code, stdout, stderr) = run(args);
        assert_eq!(code, 0, "{args:?}: {stderr}");
        stdout
    };
    // Neither flag: the job's alpha, as `run` uses it.
    assert_eq!(alphas(&ok(&["region", job])), [0.8]);
    assert_eq!(ok(&["region", job]), ok(&["region", job, "--alpha", "0.8"]));
    assert_eq!(alphas(&ok(&["section", job, "--x", "3"])), [0.8]);
    // --alpha A: that level; --levels N: N levels from 0 to 1.
    assert_eq!(alphas(&ok(&["region", job, "--alpha", "0.25"])), [0.25]);
    assert_eq!(
        alphas(&ok(&["region", job, "--levels", "3"])),
        [0.0, 0.5, 1.0]
    );
    assert_eq!(
        alphas(&ok(&["section", job, "--x", "3", "--alpha", "0.5"])),
        [0.5]
    );
    assert_eq!(
        alphas(&ok(&["section", job, "--x", "3", "--levels", "5"])),
        [0.0, 0.25, 0.5, 0.75, 1.0]
    );
    // A job without alpha: `section` takes 11 levels, `region` asks.
    let dir = tempfile::tempdir().unwrap();
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(example()).unwrap()).unwrap();
    v.as_object_mut().unwrap().remove("alpha");
    let bare = dir.path().join("bare.json");
    std::fs::write(&bare, v.to_string()).unwrap();
    assert_eq!(alphas(&ok(&["section", s(&bare), "--x", "3"])).len(), 11);
    refused(
        &["region", s(&bare)],
        "--alpha: the job has no alpha: give the level with --alpha A, or --levels N",
    );
    refused(
        &["region", job, "--alpha", "1.5"],
        "--alpha: alpha = 1.5 is outside [0, 1]",
    );
    refused(
        &["section", job, "--x", "3", "--alpha", "-0.5"],
        "--alpha: alpha = -0.5 is outside [0, 1]",
    );
    let (code, _, stderr) = run(&["region", job, "--alpha", "0.5", "--levels", "3"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("cannot be used with"), "{stderr}");
}
