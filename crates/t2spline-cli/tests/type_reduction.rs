//! `--type-reduction` and the job key `type_reduction` (SPEC §10) through the
//! built binary: the flag overrides the job, the result names the reduction,
//! an alpha the reduction does not use is noted on standard error, and
//! `plot` and `report` take the flag too.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::{json, Value};
use t2spline::job::Overrides;
use t2spline::TypeReduction;

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

/// Runs `t2spline args…` and returns (exit code, stdout, stderr).
fn t2spline(args: &[&str]) -> (i32, String, String) {
    let out = Command::cargo_bin("t2spline")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().expect("exited, not killed"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The example job file with `edit` applied, written into `dir`.
fn example_with(dir: &Path, edit: impl FnOnce(&mut serde_json::Map<String, Value>)) -> PathBuf {
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(example()).unwrap()).unwrap();
    edit(v.as_object_mut().unwrap());
    let path = dir.join("job.json");
    std::fs::write(&path, v.to_string()).unwrap();
    path
}

/// What the library computes for the job file at `path` with these overrides.
fn library(path: &Path, overrides: &Overrides) -> Value {
    let job = t2spline_io::read_job(path).unwrap();
    serde_json::to_value(job.run(&job.settings(overrides).unwrap()).unwrap()).unwrap()
}

#[test]
fn the_flag_overrides_the_job_and_the_result_names_the_reduction() {
    let dir = tempfile::tempdir().unwrap();
    let job = example_with(dir.path(), |o| {
        o.insert("type_reduction".into(), json!("nie-tan"));
        o.remove("alpha");
    });
    let path = job.to_str().unwrap();
    // The job's own reduction.
    let (code, stdout, stderr) = t2spline(&["run", path, "--samples", "5"]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    let v: Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["type_reduction"], json!("nie-tan"));
    assert_eq!(
        (&v["alpha"], &v["alpha_used"], &v["regime"]),
        (&json!(0.0), &json!(false), &Value::Null)
    );
    // Every reduction by the flag: exactly the library's run.
    for method in TypeReduction::ALL {
        let (code, stdout, stderr) = t2spline(&[
            "run",
            path,
            "--samples",
            "5",
            "--alpha",
            "0.3",
            "--type-reduction",
            method.name(),
        ]);
        assert_eq!(code, 0, "{stderr}");
        let v: Value = serde_json::from_str(&stdout).unwrap();
        assert_eq!(v["type_reduction"], json!(method.name()));
        assert_eq!(v["alpha_used"], json!(method.uses_alpha()));
        let overrides = Overrides {
            alpha: Some(0.3),
            type_reduction: Some(method),
            samples: Some(vec![5]),
            ..Overrides::default()
        };
        assert_eq!(v, library(&job, &overrides), "{method}");
    }
}

#[test]
fn an_alpha_the_reduction_does_not_use_is_noted_on_stderr() {
    let example = example();
    let path = example.to_str().unwrap();
    // The job file's alpha 0.8 with the centroid.
    let (code, stdout, stderr) = t2spline(&["run", path, "--type-reduction", "centroid"]);
    assert_eq!(code, 0);
    assert_eq!(
        stderr,
        "t2spline run: note: type reduction centroid does not use alpha; the job's alpha 0.8 is ignored (stage 2 is cut at alpha = 0, the whole footprint)\n"
    );
    let v: Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(
        (&v["alpha"], &v["alpha_used"]),
        (&json!(0.0), &json!(false))
    );
    // --alpha names itself.
    let (_, _, stderr) = t2spline(&[
        "run",
        path,
        "--alpha",
        "0.3",
        "--type-reduction",
        "alpha-planes",
    ]);
    assert!(stderr.starts_with("t2spline run: note: type reduction alpha-planes does not use alpha; --alpha 0.3 is ignored"), "{stderr}");
    assert_eq!(stderr.lines().count(), 1);
    // The paper's reduction uses alpha: no note.
    let (code, _, stderr) = t2spline(&["run", path, "--type-reduction", "paper"]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    // No alpha anywhere: nothing to note, and nothing missing.
    let dir = tempfile::tempdir().unwrap();
    let job = example_with(dir.path(), |o| {
        o.remove("alpha");
    });
    let (code, _, stderr) =
        t2spline(&["run", job.to_str().unwrap(), "--type-reduction", "nie-tan"]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    // An alpha out of range is still an error.
    let (code, _, stderr) = t2spline(&["run", path, "--alpha", "2", "--type-reduction", "nie-tan"]);
    assert_eq!(code, 2);
    assert_eq!(stderr, "t2spline: --alpha: alpha = 2 is outside [0, 1]\n");
}

#[test]
fn an_unknown_name_is_a_usage_error_with_a_suggestion() {
    let (code, stdout, stderr) = t2spline(&[
        "run",
        example().to_str().unwrap(),
        "--type-reduction",
        "nietan",
    ]);
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert!(
        stderr.contains("invalid value 'nietan' for '--type-reduction <NAME>'"),
        "{stderr}"
    );
    assert!(
        stderr.contains("[possible values: paper, centroid, nie-tan, alpha-planes]"),
        "{stderr}"
    );
    assert!(
        stderr.contains("a similar value exists: 'nie-tan'"),
        "{stderr}"
    );
    // In a job file: the validator's line, column and suggestion.
    let dir = tempfile::tempdir().unwrap();
    let job = example_with(dir.path(), |o| {
        o.insert("type_reduction".into(), json!("alpha-plane"));
    });
    let (code, _, stderr) = t2spline(&["validate", job.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains(
            ": type_reduction: unknown type reduction `alpha-plane` (did you mean `alpha-planes`?)"
        ),
        "{stderr}"
    );
}

#[test]
fn plot_and_report_take_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let figures = dir.path().join("figures");
    let (code, _, stderr) = t2spline(&[
        "plot",
        example().to_str().unwrap(),
        "-o",
        figures.to_str().unwrap(),
        "--format",
        "svg",
        "--type-reduction",
        "centroid",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.starts_with("t2spline plot: note: type reduction centroid does not use alpha; the job's alpha 0.8 is used only by the paper's reduction"), "{stderr}");
    let stage4 = std::fs::read_to_string(figures.join("stage4-defuzzified.svg")).unwrap();
    assert!(
        stage4.contains("centroid (Karnik–Mendel): max distance"),
        "stage 4 is the centroid's"
    );
    let reductions = std::fs::read_to_string(figures.join("reductions.svg")).unwrap();
    assert!(
        reductions.contains("paper (α = 0.8): max"),
        "the paper's curve keeps the job's alpha"
    );
    let report = dir.path().join("report");
    let (code, _, stderr) = t2spline(&[
        "report",
        example().to_str().unwrap(),
        "-o",
        report.to_str().unwrap(),
        "--type-reduction",
        "alpha-planes",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("only sets where the alpha slider of the paper's reduction starts"),
        "{stderr}"
    );
    let html = std::fs::read_to_string(report.join("report.html")).unwrap();
    assert!(html.contains("<option value=\"alpha-planes\" selected>"));
}
