//! The binary under hostile input and failure: one test per kind of
//! error and exit code, the message format `t2spline: FILE:LINE:COLUMN: PLACE:
//! RULE`, limits checked before reading, outputs that are complete or
//! untouched, `-o -`, closed pipes and full disks.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde_json::{json, Value};

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_t2spline"))
}

/// Runs `t2spline args…` with `stdin`, and returns (exit code, stdout, stderr).
fn run_with(args: &[&str], stdin: &[u8]) -> (i32, String, String) {
    let mut child = bin()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // The program may stop reading early (a limit): a closed pipe is fine.
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

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn number(c: f64) -> Value {
    json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]})
}

fn job() -> Value {
    json!({"order": 2, "alpha": 0.5, "lower_height": 0.5, "samples": 5,
           "points": [{"x": number(0.0), "y": number(0.0)}, {"x": number(1.0), "y": number(2.0)},
                      {"x": number(2.0), "y": number(1.0)}]})
}

/// Whether every line is `t2spline: {file}:LINE:COLUMN: PLACE: RULE`.
fn all_located(stderr: &str, file: &str) -> bool {
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    !stderr.is_empty()
        && stderr.lines().all(|l| {
            let Some(rest) = l.strip_prefix(&format!("t2spline: {file}:")) else {
                return false;
            };
            match rest.splitn(3, ':').collect::<Vec<_>>()[..] {
                [line, column, rule] => digits(line) && digits(column) && rule.starts_with(' '),
                _ => false,
            }
        })
}

// ---------------------------------------------------------------------------
// One test per exit code
// ---------------------------------------------------------------------------

#[test]
fn exit_0_on_success() {
    let (code, stdout, stderr) = run(&["run", s(&example())]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    assert!(stdout.starts_with('{'));
}

#[test]
fn exit_2_for_an_invalid_job_with_every_line_located() {
    let dir = tempfile::tempdir().unwrap();
    let mut v = job();
    v["alhpa"] = json!(1);
    v["points"][1]["y"]["upper"][0] = json!(1e151);
    v["weights"] = json!([1, 0, 1]);
    let path = write(
        dir.path(),
        "bad job.json",
        &serde_json::to_string_pretty(&v).unwrap(),
    );
    for sub in ["run", "validate"] {
        let (code, stdout, stderr) = run(&[sub, s(&path)]);
        assert_eq!(code, 2, "{stderr}");
        assert_eq!(stdout, "");
        assert_eq!(stderr.lines().count(), 3, "{stderr}");
        assert!(all_located(&stderr, s(&path)), "{stderr}");
        assert!(stderr.contains(": points[1].y: upper.left = 1e151 is outside [-1e150, 1e150]"));
    }
}

#[test]
fn exit_2_for_usage_and_option_errors() {
    // clap's own usage errors.
    let (code, _, stderr) = run(&["run", s(&example()), "--no-such-flag"]);
    assert_eq!(code, 2, "{stderr}");
    let (code, _, stderr) = run(&["run", s(&example()), "--samples", "lots"]);
    assert_eq!(code, 2, "{stderr}");
    // Values clap accepts that break a rule.
    for (args, message) in [
        (
            ["--alpha", "1.5"],
            "t2spline: --alpha: alpha = 1.5 is outside [0, 1]\n",
        ),
        (
            ["--samples", "18446744073709551615"],
            "t2spline: --samples: samples = 18446744073709551615 is more than the limit 1000000\n",
        ),
    ] {
        let job = example();
        let mut all = vec!["run", s(&job)];
        all.extend(args);
        let (code, stdout, stderr) = run(&all);
        assert_eq!((code, stdout.as_str(), stderr.as_str()), (2, "", message));
    }
}

#[test]
fn exit_2_for_a_file_past_the_size_limit_without_reading_it() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.json");
    // Sparse: 65 MiB of size, no data; reading it would take a while.
    std::fs::File::create(&path)
        .unwrap()
        .set_len(65 << 20)
        .unwrap();
    let (code, stdout, stderr) = run(&["validate", s(&path)]);
    assert_eq!(code, 2, "{stderr}");
    assert_eq!(stdout, "");
    assert_eq!(
        stderr,
        format!(
            "t2spline: {}: the file has 68157440 bytes, more than the limit of 64 MiB (67108864 bytes)\n",
            path.display()
        )
    );
}

#[test]
fn exit_2_for_standard_input_past_the_size_limit() {
    let endless = vec![b' '; (64 << 20) + 1024];
    let (code, stdout, stderr) = run_with(&["validate", "-"], &endless);
    assert_eq!((code, stdout.as_str()), (2, ""), "{stderr}");
    assert_eq!(
        stderr,
        "t2spline: <stdin>: the input is larger than the limit of 64 MiB (67108864 bytes)\n"
    );
}

#[test]
fn exit_2_for_text_that_is_not_utf8() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("latin1.json");
    std::fs::write(&path, b"{\n  \"description\": \"caf\xe9\"\n}").unwrap();
    let (code, _, stderr) = run(&["validate", s(&path)]);
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        format!(
            "t2spline: {}:2:22: not UTF-8 text (byte 0xe9); save the file as UTF-8\n",
            path.display()
        )
    );
}

#[test]
fn exit_3_when_the_job_cannot_be_read() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nope.json");
    let (code, stdout, stderr) = run(&["run", s(&missing)]);
    assert_eq!((code, stdout.as_str()), (3, ""));
    assert!(
        stderr.starts_with(&format!("t2spline: {}: cannot read: ", missing.display())),
        "{stderr}"
    );
    // A folder is not a job either.
    let (code, _, stderr) = run(&["validate", s(dir.path())]);
    assert_eq!(code, 3, "{stderr}");
    assert!(stderr.contains("cannot read"), "{stderr}");
}

#[test]
fn exit_4_when_an_output_cannot_be_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("missing/out.json");
    let (code, stdout, stderr) = run(&["run", s(&example()), "-o", s(&out)]);
    assert_eq!((code, stdout.as_str()), (4, ""));
    assert!(
        stderr.starts_with(&format!("t2spline: {}: cannot write: ", out.display())),
        "{stderr}"
    );
    // The CSV folder cannot be made: a file is in its way.
    let blocker = write(dir.path(), "csv", "not a folder");
    let (code, _, stderr) = run(&["run", s(&example()), "--csv", s(&blocker.join("sub"))]);
    assert_eq!(code, 4, "{stderr}");
}

#[cfg(target_os = "linux")]
#[test]
fn exit_4_when_standard_output_is_full() {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .expect("/dev/full exists on Linux");
    let out = bin()
        .args(["run", s(&example())])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(4));
    assert_eq!(
        String::from_utf8(out.stderr).unwrap(),
        "t2spline: <stdout>: cannot write: No space left on device (os error 28)\n"
    );
}

#[test]
fn exit_0_when_the_reader_closes_the_pipe() {
    // A large result, of which the reader takes 10 bytes and goes.
    let mut child = bin()
        .args(["run", s(&example()), "--samples", "200000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 10];
    std::io::Read::read_exact(child.stdout.as_mut().unwrap(), &mut first).unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(&first, b"{\n  \"descr");
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8(out.stderr).unwrap(), "");
}

#[test]
fn derivatives_beyond_the_range_of_a_float_are_an_option_error() {
    // A span of 1e-140 and coordinates near 1e148: the third derivative is
    // about 1e148/(1e-140)³, far past 1.8e308.
    let dir = tempfile::tempdir().unwrap();
    let mut v = job();
    v["order"] = json!(3);
    v["knots"] = json!([0, 0, 0, 1e-140, 1, 1]);
    v["points"][1]["x"] = json!({"crisp": 1e148, "upper": [1e148, 1e148], "primary": [1e148, 1e148], "lower": [1e148, 1e148]});
    let path = write(dir.path(), "steep.json", &v.to_string());
    let (code, stdout, stderr) = run(&["run", s(&path), "--derivatives", "3"]);
    assert_eq!((code, stdout.as_str()), (2, ""), "{stderr}");
    assert!(
        stderr.starts_with("t2spline: --derivatives: curves.derivatives.crisp["),
        "{stderr}"
    );
    assert!(
        stderr.contains("is beyond the range of a 64-bit float"),
        "{stderr}"
    );
    // Without derivatives the same job runs, and every number is finite.
    let (code, stdout, stderr) = run(&["run", s(&path)]);
    assert_eq!(code, 0, "{stderr}");
    assert!(!stdout.contains("NaN") && !stdout.contains("inf"));
}

// ---------------------------------------------------------------------------
// Outputs: complete or untouched
// ---------------------------------------------------------------------------

#[test]
fn a_failed_run_leaves_existing_outputs_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let out = write(dir.path(), "out.json", "previous result");
    let csv = dir.path().join("csv");
    std::fs::create_dir(&csv).unwrap();
    let old_csv = write(&csv, "stage1-layers.csv", "previous csv");
    // 1. The job is invalid: nothing is touched.
    let bad = write(dir.path(), "bad.json", "{\"order\": 2}");
    let (code, _, _) = run(&["run", s(&bad), "-o", s(&out), "--csv", s(&csv)]);
    assert_eq!(code, 2);
    // 2. The JSON output cannot be written (its name is a folder): the CSV
    //    files, written first to temporary files, are not renamed either.
    //    (A folder beside the CSV folder: one holding it would be refused,
    //    exit 2, as an output inside another's.)
    let folder = dir.path().join("folder.json");
    std::fs::create_dir(&folder).unwrap();
    let (code, _, stderr) = run(&["run", s(&example()), "-o", s(&folder), "--csv", s(&csv)]);
    assert_eq!(code, 4, "{stderr}");
    let (code, _, stderr) = run(&["run", s(&example()), "-o", s(dir.path()), "--csv", s(&csv)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("lies inside"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "previous result");
    assert_eq!(std::fs::read_to_string(&old_csv).unwrap(), "previous csv");
    // No temporary file is left behind anywhere.
    for d in [dir.path(), csv.as_path(), folder.as_path()] {
        for entry in std::fs::read_dir(d).unwrap() {
            let name = entry.unwrap().file_name();
            assert!(
                !name.to_string_lossy().starts_with(".t2spline-"),
                "{name:?}"
            );
        }
    }
    // 3. A good run replaces both, completely.
    let (code, _, stderr) = run(&["run", s(&example()), "-o", s(&out), "--csv", s(&csv)]);
    assert_eq!(code, 0, "{stderr}");
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(v["order"], json!(3));
    assert_eq!(
        std::fs::read_to_string(&old_csv).unwrap().lines().count(),
        102
    );
}

#[test]
fn dash_o_dash_is_standard_output() {
    let (code, to_stdout, _) = run(&["run", s(&example())]);
    assert_eq!(code, 0);
    let (code, dash, stderr) = run(&["run", s(&example()), "-o", "-"]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    assert_eq!(dash, to_stdout);
    // A file named "-" in a folder is still reachable as ./-.
    let dir = tempfile::tempdir().unwrap();
    let dashed = dir.path().join("-");
    let (code, stdout, _) = run(&["run", s(&example()), "-o", s(&dashed)]);
    assert_eq!((code, stdout.as_str()), (0, ""));
    assert_eq!(std::fs::read_to_string(dashed).unwrap(), to_stdout);
}

#[test]
fn a_missing_alpha_is_placed_at_the_top_level_object() {
    let mut v = job();
    v.as_object_mut().unwrap().remove("alpha");
    let text = format!("\n\n  {v}");
    let (code, _, stderr) = run_with(&["run", "-"], text.as_bytes());
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        "t2spline: <stdin>:3:3: alpha: missing: give it in the job file or with --alpha\n"
    );
}

#[test]
fn hostile_file_names_are_printed_escaped() {
    let dir = tempfile::tempdir().unwrap();
    // A name that would set the terminal's title and clear the screen.
    let name = dir.path().join("\u{1b}]0;pwned\u{7}\u{1b}[2J.json");
    let (code, _, stderr) = run(&["run", s(&name)]);
    assert_eq!(code, 3, "{stderr}");
    assert!(
        stderr.contains("\\u001b]0;pwned\\u0007\\u001b[2J.json: cannot read"),
        "{stderr}"
    );
    assert!(
        !stderr.contains('\u{1b}') && !stderr.contains('\u{7}'),
        "{stderr:?}"
    );
    // The same name for a file that exists but is invalid.
    std::fs::write(&name, "{\"order\": 2}").unwrap();
    let (code, _, stderr) = run(&["validate", s(&name)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(!stderr.contains('\u{1b}'), "{stderr:?}");
    assert!(stderr.contains("\\u001b]0;pwned"), "{stderr}");
}

#[test]
fn a_csv_file_given_for_a_job_is_named_as_csv() {
    let dir = tempfile::tempdir().unwrap();
    let csv = write(
        dir.path(),
        "readings.csv",
        "station,x,y\n1,0.5,2.0\n1,0.6,2.1\n",
    );
    let (code, _, stderr) = run(&["run", s(&csv)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("readings.csv:1:1: JSON syntax error"),
        "{stderr}"
    );
    assert!(stderr.contains("this looks like CSV"), "{stderr}");
    assert!(stderr.contains("t2spline fuzzify READINGS.csv"), "{stderr}");
    // A JSON file with a plain syntax error gets no such hint.
    let broken = write(dir.path(), "broken.json", "{\"order\": 2,, }");
    let (_, _, stderr) = run(&["run", s(&broken)]);
    assert!(!stderr.contains("CSV"), "{stderr}");
}
