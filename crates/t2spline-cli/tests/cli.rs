//! The `t2spline` binary, run for real: stdout, stderr and exit code of `run`
//! and `validate` on good and bad inputs, output files, CSV folders, standard
//! input and a reader that closes the pipe early.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::Stdio;

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::{json, Value};
use t2spline::job::Overrides;

/// The worked example of docs/jobs.md (alpha 0.8 above h = 0.6, 101 samples).
fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn t2spline() -> Command {
    Command::cargo_bin("t2spline").expect("the binary is built for the tests")
}

/// Runs `t2spline args…` and returns (exit code, stdout, stderr).
fn run(args: &[&str]) -> (i32, String, String) {
    let out = t2spline().args(args).output().unwrap();
    (
        out.status.code().expect("exited, not killed"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn path_str(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 temporary path")
}

/// A valid fuzzy number around `c` without its own height.
fn number(c: f64) -> Value {
    json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]})
}

/// A valid job of order 2 with three 2-D points and no alpha.
fn job_without_alpha() -> Value {
    json!({
        "order": 2,
        "lower_height": 0.5,
        "samples": 5,
        "points": [
            {"x": number(0.0), "y": number(0.0)},
            {"x": number(1.0), "y": number(2.0)},
            {"x": number(2.0), "y": number(1.0)}
        ]
    })
}

/// A job file with exactly three distinct problems: an unknown key, a broken
/// order at `points[1].y`, and a zero weight.
fn job_with_three_problems() -> Value {
    let mut v = job_without_alpha();
    v["alhpa"] = json!(0.5);
    v["points"][1]["y"]["lower"] = json!([2.125, 2.25]);
    v["weights"] = json!([1, 0, 1]);
    v
}

/// Writes `contents` to `dir/name` and returns the path.
fn write_file(dir: &Path, name: &str, contents: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, contents).unwrap();
    p
}

fn parse_json(stdout: &str) -> Value {
    serde_json::from_str(stdout).unwrap_or_else(|e| panic!("stdout is not JSON: {e}\n{stdout}"))
}

/// The value at a dotted path, e.g. `curves.layers.upper_left`.
fn get<'v>(v: &'v Value, path: &str) -> &'v Value {
    path.split('.').fold(v, |v, k| {
        v.get(k)
            .unwrap_or_else(|| panic!("no key {path} (at {k}) in the result"))
    })
}

/// The result of the library on the same job, as JSON values: what `run`
/// must print.
fn library_result(job_file: &Path, alpha: Option<f64>, samples: Option<u64>) -> Value {
    let job = t2spline_io::read_job(job_file).unwrap();
    let overrides = Overrides {
        alpha,
        samples: samples.map(|n| vec![n]),
        ..Overrides::default()
    };
    let result = job.run(&job.settings(&overrides).unwrap()).unwrap();
    serde_json::to_value(&result).unwrap()
}

/// Asserts that the directory holds no files at all.
#[track_caller]
fn assert_empty_dir(dir: &Path, except: &[&Path]) {
    let left: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| !except.contains(&p.as_path()))
        .collect();
    assert!(left.is_empty(), "files left behind: {left:?}");
}

// ---------------------------------------------------------------------------
// run: the good path
// ---------------------------------------------------------------------------

#[test]
fn run_prints_every_key_of_spec_8() {
    let (code, stdout, stderr) = run(&["run", path_str(&example())]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stderr, "");
    let v = parse_json(&stdout);
    assert_eq!(get(&v, "alpha"), &json!(0.8));
    for key in [
        "control_points.crisp",
        "control_points.type_reduced_left",
        "control_points.type_reduced_right",
        "control_points.defuzzified",
        "curves.params",
        "curves.crisp",
        "curves.defuzzified",
        "curves.layers.upper_left",
        "curves.layers.primary_left",
        "curves.layers.lower_left",
        "curves.layers.lower_right",
        "curves.layers.primary_right",
        "curves.layers.upper_right",
    ] {
        let list = get(&v, key)
            .as_array()
            .unwrap_or_else(|| panic!("{key} is a list"));
        // Each a list of points, a point a list of two coordinates.
        assert!(
            list.iter().all(|p| p.is_number()
                || p.as_array()
                    .is_some_and(|p| p.len() == 2 && p.iter().all(Value::is_number))),
            "{key}: {list:?}"
        );
    }
    for key in ["error.max", "error.rms"] {
        assert!(get(&v, key).as_f64().is_some_and(|e| e >= 0.0), "{key}");
    }
    assert_eq!(get(&v, "control_points.crisp").as_array().unwrap().len(), 4);

    let params: Vec<f64> = serde_json::from_value(get(&v, "curves.params").clone()).unwrap();
    assert_eq!(params.len(), 101);
    assert_eq!(params[0], 0.0);
    assert_eq!(params[100], 1.0, "the last parameter is exactly the end");
    assert!(params.windows(2).all(|w| w[0] < w[1]));
    for key in [
        "curves.crisp",
        "curves.defuzzified",
        "curves.layers.upper_right",
    ] {
        assert_eq!(get(&v, key).as_array().unwrap().len(), 101, "{key}");
    }
    assert!(stdout.ends_with("}\n"));
}

#[test]
fn run_prints_exactly_what_the_library_computes() {
    let (code, stdout, stderr) = run(&["run", path_str(&example())]);
    assert_eq!(code, 0, "{stderr}");
    let printed = parse_json(&stdout);
    let computed = library_result(&example(), None, None);
    assert_eq!(
        printed["control_points"]["defuzzified"],
        computed["control_points"]["defuzzified"]
    );
    assert_eq!(printed["error"], computed["error"]);
    // Everything, bit for bit.
    assert_eq!(printed, computed);
}

#[test]
fn alpha_and_samples_on_the_command_line_override_the_file() {
    let (code, stdout, stderr) = run(&[
        "run",
        path_str(&example()),
        "--alpha",
        "0.3",
        "--samples",
        "11",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stderr, "");
    let v = parse_json(&stdout);
    assert_eq!(get(&v, "alpha"), &json!(0.3));
    assert_eq!(
        get(&v, "regime"),
        &json!("alpha <= h"),
        "0.3 is below h = 0.6"
    );
    let params = get(&v, "curves.params").as_array().unwrap();
    assert_eq!(params.len(), 11);
    assert_eq!(params[10], json!(1.0));
    assert_eq!(v, library_result(&example(), Some(0.3), Some(11)));
}

#[test]
fn output_file_gets_the_result_and_stdout_stays_empty() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let (code, stdout, stderr) = run(&["run", path_str(&example()), "-o", path_str(&out)]);
    assert_eq!((code, stdout.as_str(), stderr.as_str()), (0, "", ""));
    let written = std::fs::read_to_string(&out).unwrap();
    let (_, printed, _) = run(&["run", path_str(&example())]);
    assert_eq!(written, printed, "file and stdout hold the same text");
    assert_empty_dir(dir.path(), &[&out]);

    // An existing file is replaced.
    std::fs::write(&out, "old").unwrap();
    t2spline()
        .args([
            "run",
            path_str(&example()),
            "--output",
            path_str(&out),
            "--samples",
            "3",
        ])
        .assert()
        .success()
        .stdout("")
        .stderr("");
    let v = parse_json(&std::fs::read_to_string(&out).unwrap());
    assert_eq!(get(&v, "curves.params"), &json!([0.0, 0.5, 1.0]));
}

#[test]
fn output_dash_is_standard_output() {
    let (code, stdout, stderr) = run(&["run", path_str(&example()), "-o", "-"]);
    assert_eq!(code, 0, "{stderr}");
    let (_, plain, _) = run(&["run", path_str(&example())]);
    assert_eq!(stdout, plain);
}

#[test]
fn csv_folder_is_created_with_the_four_files() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("new/csv");
    let out = dir.path().join("out.json");
    t2spline()
        .args([
            "run",
            path_str(&example()),
            "--csv",
            path_str(&csv),
            "-o",
            path_str(&out),
        ])
        .assert()
        .success()
        .stdout("")
        .stderr("");
    let mut names: Vec<String> = std::fs::read_dir(&csv)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "stage1-layers.csv",
            "stage2-alpha-cut.csv",
            "stage3-type-reduced.csv",
            "stage4-defuzzified.csv"
        ]
    );
    // The same text the library renders; 101 rows and a header.
    let job = t2spline_io::read_job(&example()).unwrap();
    let result = job
        .run(&job.settings(&Overrides::default()).unwrap())
        .unwrap();
    for (name, text) in t2spline_io::render_csv(&result) {
        let written = std::fs::read_to_string(csv.join(name)).unwrap();
        assert_eq!(written, text, "{name}");
        assert_eq!(written.lines().count(), 102, "{name}");
    }
    assert!(out.exists());
}

#[test]
fn csv_alone_still_prints_the_json() {
    let dir = tempfile::tempdir().unwrap();
    let (code, stdout, stderr) = run(&[
        "run",
        path_str(&example()),
        "--csv",
        path_str(dir.path()),
        "--samples",
        "2",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        get(&parse_json(&stdout), "curves.params"),
        &json!([0.0, 1.0])
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 4);
}

#[test]
fn the_job_can_come_from_standard_input() {
    let text = std::fs::read_to_string(example()).unwrap();
    let (_, from_file, _) = run(&["run", path_str(&example())]);
    t2spline()
        .args(["run", "-"])
        .write_stdin(text.clone())
        .assert()
        .success()
        .stdout(from_file)
        .stderr("");
    t2spline()
        .args(["validate", "-"])
        .write_stdin(text)
        .assert()
        .success()
        .stdout(predicate::str::contains("ok"))
        .stderr("");
}

// ---------------------------------------------------------------------------
// run: options and alpha
// ---------------------------------------------------------------------------

#[test]
fn alpha_missing_everywhere_is_an_error_naming_alpha() {
    let dir = tempfile::tempdir().unwrap();
    let job = write_file(dir.path(), "job.json", &job_without_alpha().to_string());
    let (code, stdout, stderr) = run(&["run", path_str(&job)]);
    assert_eq!(code, 2);
    assert_eq!(stdout, "");
    assert_eq!(
        stderr,
        format!(
            // A missing key is placed at the object that lacks it.
            "t2spline: {}:1:1: alpha: missing: give it in the job file or with --alpha\n",
            job.display()
        )
    );
    // Given on the command line it runs.
    let (code, stdout, stderr) = run(&["run", path_str(&job), "--alpha", "0"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(get(&parse_json(&stdout), "alpha"), &json!(0.0));
    // From standard input the message names `<stdin>`, like every other.
    t2spline()
        .args(["run", "-"])
        .write_stdin(job_without_alpha().to_string())
        .assert()
        .code(2)
        .stdout("")
        .stderr("t2spline: <stdin>:1:1: alpha: missing: give it in the job file or with --alpha\n");
}

#[test]
fn bad_options_are_errors_naming_the_option() {
    let ex = example();
    let ex = path_str(&ex);
    let cases: [(&[&str], &str); 6] = [
        (
            &["--alpha", "1.5"],
            "t2spline: --alpha: alpha = 1.5 is outside [0, 1]\n",
        ),
        (
            &["--alpha", "-0.5"],
            "t2spline: --alpha: alpha = -0.5 is outside [0, 1]\n",
        ),
        (
            &["--alpha", "NaN"],
            "t2spline: --alpha: alpha = NaN is outside [0, 1]\n",
        ),
        (
            &["--samples", "1"],
            "t2spline: --samples: samples = 1: at least 2 are needed (both ends of the domain)\n",
        ),
        (
            &["--samples", "0"],
            "t2spline: --samples: samples = 0: at least 2 are needed (both ends of the domain)\n",
        ),
        (
            &["--samples", "1000001"],
            "t2spline: --samples: samples = 1000001 is more than the limit 1000000\n",
        ),
    ];
    for (options, message) in cases {
        let mut args = vec!["run", ex];
        args.extend_from_slice(options);
        let (code, stdout, stderr) = run(&args);
        assert_eq!(
            (code, stdout.as_str(), stderr.as_str()),
            (2, "", message),
            "{options:?}"
        );
    }
    // Values clap cannot parse are usage errors: exit 2, naming the option.
    for options in [
        ["--alpha", "high"],
        ["--samples", "2.5"],
        ["--samples", "-3"],
    ] {
        let mut args = vec!["run", ex];
        args.extend_from_slice(&options);
        let (code, stdout, stderr) = run(&args);
        assert_eq!(code, 2, "{options:?}: {stderr}");
        assert_eq!(stdout, "");
        assert!(!stderr.is_empty());
    }
}

#[test]
fn a_failed_run_leaves_an_existing_output_untouched_and_creates_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let old: &[u8] = b"{\"previous\": \"result\"}\n\x00\xff binary tail";
    std::fs::write(&out, old).unwrap();
    let csv = dir.path().join("csv");
    let bad = write_file(
        dir.path(),
        "bad.json",
        &job_with_three_problems().to_string(),
    );
    let no_alpha = write_file(
        dir.path(),
        "no-alpha.json",
        &job_without_alpha().to_string(),
    );
    let ex = example();
    let runs: [Vec<&str>; 4] = [
        vec!["run", path_str(&bad)],
        vec!["run", path_str(&no_alpha)],
        vec!["run", path_str(&ex), "--alpha", "2"],
        vec!["run", path_str(&ex), "--samples", "1"],
    ];
    for mut args in runs {
        args.extend(["-o", path_str(&out), "--csv", path_str(&csv)]);
        let (code, stdout, stderr) = run(&args);
        assert_eq!(code, 2, "{args:?}");
        assert_eq!(stdout, "", "{args:?}");
        assert!(stderr.starts_with("t2spline: "), "{stderr}");
        assert_eq!(
            std::fs::read(&out).unwrap(),
            old,
            "{args:?}: output changed"
        );
        assert!(!csv.exists(), "{args:?}: CSV folder created");
        assert_empty_dir(dir.path(), &[&out, &bad, &no_alpha]);
    }
    // And without an existing file, none is created.
    std::fs::remove_file(&out).unwrap();
    let (code, _, _) = run(&["run", path_str(&bad), "-o", path_str(&out)]);
    assert_eq!(code, 2);
    assert!(!out.exists());
}

// ---------------------------------------------------------------------------
// Bad job files
// ---------------------------------------------------------------------------

#[test]
fn bad_job_files_give_one_line_per_problem_naming_file_and_place() {
    let dir = tempfile::tempdir().unwrap();
    let cases: Vec<(&str, String, Vec<&str>)> = vec![
        (
            "syntax.json",
            "{\n  \"order\": 2,\n  \"alpha\": 0.5,}\n".to_owned(),
            vec!["3:16: JSON syntax error: trailing comma"],
        ),
        ("array.json", "[]".to_owned(), vec!["job: expected the job (a JSON object), got an array"]),
        (
            "three.json",
            job_with_three_problems().to_string(),
            vec![
                "alhpa: unknown key (did you mean `alpha`?)",
                "points[1].y: the order lower.left <= crisp is broken: 2.125 > 2",
                "weights[1] = 0 must be finite and greater than 0",
            ],
        ),
        (
            "order.json",
            {
                let mut v = job_without_alpha();
                v["order"] = json!(2.5);
                v.to_string()
            },
            vec!["order: expected a whole number >= 0, got 2.5"],
        ),
        (
            "mixed.json",
            {
                let mut v = job_without_alpha();
                v["points"][2]["z"] = number(1.0);
                v["points"][0]["x"]["lower_height"] = json!(0);
                v.to_string()
            },
            vec![
                "points[0].x: lower_height = 0 is outside (0, 1]",
                "points[2]: has coordinates [x, y, z] but points[0] has [x, y]: every point needs the same coordinates",
            ],
        ),
    ];
    for (name, text, rules) in cases {
        let job = write_file(dir.path(), name, &text);
        let prefix = format!("t2spline: {}: ", job.display());
        let expected: String = rules
            .iter()
            .map(|r| {
                // Syntax errors put line and column right after the file name.
                if r.starts_with(|c: char| c.is_ascii_digit()) {
                    format!("t2spline: {}:{r}\n", job.display())
                } else {
                    format!("{prefix}{r}\n")
                }
            })
            .collect();
        for sub in ["run", "validate"] {
            let (code, stdout, stderr) = run(&[sub, path_str(&job)]);
            assert_eq!(code, 2, "{sub} {name}");
            assert_eq!(stdout, "", "{sub} {name}");
            // Every line has the line and column after the file name; the
            // positions themselves are checked in `errors.rs`.
            let file = format!("t2spline: {}:", job.display());
            assert!(
                stderr.lines().all(|l| without_position(l, &file) != l),
                "{sub} {name}: {stderr}"
            );
            let strip = |text: &str| -> String {
                text.lines()
                    .map(|l| without_position(l, &file) + "\n")
                    .collect()
            };
            assert_eq!(strip(&stderr), strip(&expected), "{sub} {name}");
        }
    }
}

/// `{file}12:5: rest` → `{file} rest`; other lines unchanged.
fn without_position(line: &str, file: &str) -> String {
    let number = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let Some(rest) = line.strip_prefix(file) else {
        return line.to_owned();
    };
    match rest.splitn(3, ':').collect::<Vec<_>>()[..] {
        [l, c, rest] if number(l) && number(c) => format!("{file}{rest}"),
        _ => line.to_owned(),
    }
}

#[test]
fn validate_a_good_file_says_ok() {
    t2spline()
        .args(["validate", path_str(&example())])
        .assert()
        .success()
        .stdout(predicate::str::contains("ok").and(predicate::str::ends_with("\n")))
        .stdout(predicate::str::contains(
            "2-D curve, 4 control points, order 3, alpha 0.8, 101 samples",
        ))
        .stderr("");
    let dir = tempfile::tempdir().unwrap();
    let job = write_file(dir.path(), "j.json", &job_without_alpha().to_string());
    t2spline()
        .args(["validate", path_str(&job)])
        .assert()
        .success()
        .stdout(format!(
            "{}: ok: 2-D curve, 3 control points, order 2, alpha not set, 5 samples\n",
            job.display()
        ));
}

#[test]
fn validate_lists_exactly_the_three_problems() {
    let dir = tempfile::tempdir().unwrap();
    let job = write_file(
        dir.path(),
        "bad.json",
        &job_with_three_problems().to_string(),
    );
    let (code, stdout, stderr) = run(&["validate", path_str(&job)]);
    assert_eq!(code, 2);
    assert_eq!(stdout, "");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 3, "{stderr}");
    let file = format!("t2spline: {}:", job.display());
    let prefix = format!("t2spline: {}: ", job.display());
    assert!(
        lines
            .iter()
            .all(|l| without_position(l, &file).starts_with(&prefix)),
        "{stderr}"
    );
    assert!(lines[0].contains("alhpa") && lines[0].contains("`alpha`"));
    assert!(lines[1].contains("points[1].y") && lines[1].contains("lower.left <= crisp"));
    assert!(lines[2].contains("weights[1]"));
}

#[test]
fn a_missing_file_is_an_error_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nope.json");
    for sub in ["run", "validate"] {
        let (code, stdout, stderr) = run(&[sub, path_str(&missing)]);
        assert_eq!(code, 3, "exit code 3: the job cannot be read");
        assert_eq!(stdout, "");
        let lines: Vec<&str> = stderr.lines().collect();
        assert_eq!(lines.len(), 1, "{stderr}");
        assert!(
            lines[0].starts_with(&format!("t2spline: {}: cannot read: ", missing.display())),
            "{stderr}"
        );
        // The operating system's reason follows, once.
        let reason = std::fs::read(&missing).unwrap_err().to_string();
        assert!(
            lines[0].ends_with(&format!(": cannot read: {reason}")),
            "{stderr}"
        );
        assert_eq!(lines[0].matches(&reason).count(), 1, "{stderr}");
    }
}

#[test]
fn an_unwritable_output_is_an_error_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("no/such/folder/out.json");
    let (code, stdout, stderr) = run(&["run", path_str(&example()), "-o", path_str(&out)]);
    assert_eq!(code, 4, "exit code 4: an output cannot be written");
    assert_eq!(stdout, "");
    assert!(
        stderr.starts_with(&format!("t2spline: {}: cannot write: ", out.display())),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert_eq!(
        stderr.matches("(os error").count(),
        1,
        "the reason once: {stderr}"
    );
}

#[test]
fn usage_errors_exit_2() {
    for args in [
        &[][..],
        &["run"][..],
        &["frobnicate"][..],
        &["run", "a", "b"][..],
    ] {
        let (code, stdout, _) = run(args);
        assert_eq!(code, 2, "{args:?}");
        assert_eq!(stdout, "", "{args:?}");
    }
    t2spline().arg("--help").assert().success();
    t2spline()
        .arg("--version")
        .assert()
        .success()
        .stdout(predicate::str::starts_with("t2spline "));
}

// ---------------------------------------------------------------------------
// A reader that goes away
// ---------------------------------------------------------------------------

fn closed_pipe(read_first: usize) {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args(["run", path_str(&example()), "--samples", "100000"])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    if read_first > 0 {
        let mut buf = vec![0u8; read_first];
        stdout.read_exact(&mut buf).unwrap();
        assert_eq!(buf[0], b'{');
    }
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(stderr, "", "a closed pipe is not an error");
    assert_eq!(out.status.code(), Some(0), "{stderr}");
}

#[test]
fn a_reader_that_closes_the_pipe_at_once_is_not_an_error() {
    closed_pipe(0);
}

#[test]
fn a_reader_that_closes_the_pipe_after_a_few_bytes_is_not_an_error() {
    closed_pipe(16);
}

#[test]
fn stdin_can_be_written_by_a_pipe_too() {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args(["validate", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(std::fs::read_to_string(example()).unwrap().as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(
        String::from_utf8(out.stdout).unwrap(),
        "<stdin>: ok: 2-D curve, 4 control points, order 3, alpha 0.8, 101 samples\n"
    );
}

#[test]
fn csv_and_output_are_written_all_or_nothing() {
    // The JSON output's folder is missing: the run fails and leaves neither the
    // CSV files nor the CSV folder it would have created.
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("csv/nested");
    let out = dir.path().join("missing/out.json");
    let (code, stdout, stderr) = run(&[
        "run",
        path_str(&example()),
        "--csv",
        path_str(&csv),
        "-o",
        path_str(&out),
    ]);
    assert_eq!(code, 4, "{stderr}");
    assert!(stdout.is_empty(), "{stdout}");
    assert!(stderr.contains("out.json: cannot write"), "{stderr}");
    assert!(
        !stderr.contains(".t2spline-"),
        "names a temporary file: {stderr}"
    );
    assert_empty_dir(dir.path(), &[]);
}

/// A negative number in any form is an option's value, never taken for a
/// flag: `-1e-3`, `-.5`, `-0`, `-5E0`, and lists that start with one.
#[test]
fn negative_numbers_in_any_form_are_values() {
    let curve = example();
    let curve = curve.to_str().unwrap();
    let terrain = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-terrain.json");
    let terrain = terrain.to_str().unwrap();
    let cases: [&[&str]; 7] = [
        &["section", curve, "--x", "-1e-3"],
        &["section", curve, "--x", "-.5"],
        &["region", curve, "--alpha", "-0"],
        &["measure", terrain, "--datum", "-5E0", "--no-area"],
        &["section", terrain, "--at", "-.5,1"],
        &[
            "envelope",
            terrain,
            "--grid",
            "3,3",
            "--extent",
            "-1e0,-1,2,2",
        ],
        &["run", curve, "--alpha", "-.5"],
    ];
    for args in cases {
        let out = t2spline().args(args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            !stderr.contains("unexpected argument"),
            "{args:?}: {stderr}"
        );
        if args.contains(&"-.5") && args[0] == "run" {
            // A value, and out of range: refused by name.
            assert_eq!(out.status.code(), Some(2), "{args:?}");
            assert!(stderr.contains("alpha"), "{args:?}: {stderr}");
        } else {
            assert!(out.status.success(), "{args:?}: {stderr}");
        }
    }
    let out = t2spline()
        .args(["region", curve, "--alpha", "-0"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("\"alpha\": 0.0") && !text.contains("-0.0"),
        "{text}"
    );
}

/// An output name whose extension (in any case) asks for another kind of
/// output than the command writes is refused naming both, and nothing is
/// written: `plot` and `report` write folders, `run -o` writes JSON.
#[test]
fn an_output_named_for_another_kind_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let job = example();
    let job = job.to_str().unwrap();
    let cases = [
        ("plot", "figures.SVG", "plot writes a folder of figures"),
        ("report", "report.Html", "report writes a folder"),
        ("run", "result.CSV", "run -o writes the result as JSON"),
    ];
    for (command, name, words) in cases {
        let out = dir.path().join(name);
        let result = t2spline()
            .args([command, job, "-o", out.to_str().unwrap()])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{command}: {stderr}");
        assert!(
            stderr.contains("--output") && stderr.contains(name) && stderr.contains(words),
            "{stderr}"
        );
        assert!(!out.exists(), "{command} wrote {name}");
    }
}
