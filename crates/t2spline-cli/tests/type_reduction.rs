//! `--type-reduction` and the job key `type_reduction` (docs/method.md §9) through the
//! built binary: the flag overrides the job, the result names the reduction,
//! an alpha the reduction does not use is noted on standard error; `plot`,
//! `report` and `export` take the flag too, surface jobs run with every
//! reduction, and a run of many jobs honours each job's key.

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

#[test]
fn surface_jobs_run_with_every_reduction() {
    let terrain = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-terrain.json");
    let path = terrain.to_str().unwrap();
    for method in TypeReduction::ALL {
        let (code, stdout, stderr) = t2spline(&[
            "run",
            path,
            "--samples",
            "4,5",
            "--type-reduction",
            method.name(),
        ]);
        assert_eq!(code, 0, "{method}: {stderr}");
        let v: Value = serde_json::from_str(&stdout).unwrap();
        assert_eq!(v["type_reduction"], json!(method.name()));
        assert_eq!(v["alpha_used"], json!(method.uses_alpha()));
        assert_eq!(v["regime"].is_null(), !method.uses_alpha(), "{method}");
        assert_eq!(v["surfaces"]["defuzzified"].as_array().unwrap().len(), 4);
        let overrides = Overrides {
            type_reduction: Some(method),
            samples: Some(vec![4, 5]),
            ..Overrides::default()
        };
        assert_eq!(v, library(&terrain, &overrides), "{method}");
        // The note names the surface job's alpha when it is not used.
        assert_eq!(
            stderr.contains("does not use alpha; the job's alpha"),
            !method.uses_alpha(),
            "{method}: {stderr}"
        );
    }
    // The key in a surface job file, with no alpha: the reduction's result.
    let dir = tempfile::tempdir().unwrap();
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(&terrain).unwrap()).unwrap();
    let o = v.as_object_mut().unwrap();
    o.remove("alpha");
    o.insert("type_reduction".into(), json!("alpha-planes"));
    let job = dir.path().join("terrain.json");
    std::fs::write(&job, v.to_string()).unwrap();
    let (code, stdout, stderr) = t2spline(&["run", job.to_str().unwrap(), "--samples", "3"]);
    assert_eq!((code, stderr.as_str()), (0, ""));
    let out: Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(out["type_reduction"], json!("alpha-planes"));
    let overrides = Overrides {
        samples: Some(vec![3]),
        ..Overrides::default()
    };
    assert_eq!(out, library(&job, &overrides));
}

/// The control points (x, y, z, w) of the group `name` of an OBJ file.
fn obj_points(text: &str, name: &str) -> Vec<Vec<f64>> {
    let start = text
        .find(&format!("g {name}\n"))
        .unwrap_or_else(|| panic!("no group {name}"));
    text[start..]
        .lines()
        .skip(1)
        .take_while(|l| l.starts_with("v "))
        .map(|l| l[2..].split(' ').map(|x| x.parse().unwrap()).collect())
        .collect()
}

#[test]
fn export_writes_the_chosen_reduction_s_curve() {
    let example = example();
    let path = example.to_str().unwrap();
    let mut seen = Vec::new();
    for method in TypeReduction::ALL {
        let (code, obj, stderr) = t2spline(&[
            "export",
            path,
            "-o",
            "-",
            "--format",
            "obj",
            "--type-reduction",
            method.name(),
        ]);
        assert_eq!(code, 0, "{method}: {stderr}");
        assert_eq!(
            stderr.starts_with("t2spline export: note: type reduction"),
            !method.uses_alpha(),
            "{stderr}"
        );
        let (_, run, _) = t2spline(&["run", path, "--type-reduction", method.name()]);
        let run: Value = serde_json::from_str(&run).unwrap();
        let weights = run["weights"].as_array().unwrap();
        let points = obj_points(&obj, "defuzzified");
        let want = run["control_points"]["defuzzified"].as_array().unwrap();
        assert_eq!(points.len(), want.len());
        // The run's control points and weights, exactly; z = 0 for a planar job.
        for ((p, w), weight) in points.iter().zip(want).zip(weights) {
            let w: Vec<f64> = w
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            assert_eq!(p, &[w[0], w[1], 0.0, weight.as_f64().unwrap()], "{method}");
        }
        // The crisp curve does not depend on the reduction.
        assert_eq!(
            obj_points(&obj, "crisp")[1],
            [2.0, 4.0, 0.0, 1.0],
            "{method}"
        );
        seen.push(points);
    }
    seen.dedup();
    assert_eq!(seen.len(), 4, "each reduction its own curve");
}

#[test]
fn a_run_of_many_jobs_honours_each_job_s_reduction() {
    let dir = tempfile::tempdir().unwrap();
    let jobs = dir.path().join("jobs");
    std::fs::create_dir(&jobs).unwrap();
    let text = std::fs::read_to_string(example()).unwrap();
    std::fs::write(jobs.join("a.json"), &text).unwrap();
    let mut v: Value = serde_json::from_str(&text).unwrap();
    v.as_object_mut()
        .unwrap()
        .insert("type_reduction".into(), json!("centroid"));
    std::fs::write(jobs.join("b.json"), v.to_string()).unwrap();
    let out = dir.path().join("out");
    let (code, _, stderr) = t2spline(&[
        "run",
        "--jobs",
        jobs.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--samples",
        "7",
    ]);
    assert_eq!(code, 0, "{stderr}");
    // Only the centroid job leaves its alpha unused.
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("t2spline run: ")
            && stderr.contains("b.json: note: type reduction centroid does not use alpha; the job's alpha 0.8 is ignored"),
        "{stderr}"
    );
    for (name, method) in [("a", "paper"), ("b", "centroid")] {
        let job = jobs.join(format!("{name}.json"));
        let (_, alone, _) = t2spline(&["run", job.to_str().unwrap(), "--samples", "7"]);
        let written = std::fs::read_to_string(out.join(format!("{name}.json"))).unwrap();
        assert_eq!(written, alone, "{name}");
        let v: Value = serde_json::from_str(&written).unwrap();
        assert_eq!(v["type_reduction"], json!(method));
    }
    let summary = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let lines: Vec<&str> = summary.lines().collect();
    assert_eq!(
        lines[0],
        "name,file,status,type_reduction,regime,alpha,h,error_max,error_max_at,error_max_at_v,error_rms,description,message"
    );
    assert!(
        lines[1].starts_with("a,") && lines[1].contains(",ok,paper,alpha > h,0.8,"),
        "{}",
        lines[1]
    );
    // No regime and no alpha for a reduction that does not use alpha.
    assert!(
        lines[2].starts_with("b,") && lines[2].contains(",ok,centroid,,,"),
        "{}",
        lines[2]
    );
    // The flag overrides every job's key.
    let again = dir.path().join("again");
    let (code, _, _) = t2spline(&[
        "run",
        "--jobs",
        jobs.to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
        "--type-reduction",
        "nie-tan",
    ]);
    assert_eq!(code, 0);
    for name in ["a", "b"] {
        let v: Value = serde_json::from_str(
            &std::fs::read_to_string(again.join(format!("{name}.json"))).unwrap(),
        )
        .unwrap();
        assert_eq!(v["type_reduction"], json!("nie-tan"), "{name}");
    }
}
