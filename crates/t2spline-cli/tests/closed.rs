//! A closed curve built the usual periodic way (`fixtures/periodic-circle.json`:
//! uniform unclamped knots, the first p points repeated, `"closed": true`)
//! goes through every command that takes a curve; its area is enclosed and
//! positive; `"closed": true` on a curve that does not close is refused,
//! naming its ends.

use std::path::{Path, PathBuf};

mod common;
use common::{run, s};

fn circle() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/periodic-circle.json")
}

#[test]
fn the_periodic_circle_goes_through_every_command() {
    let dir = tempfile::tempdir().unwrap();
    let job = circle();
    let job = s(&job);
    let out = |name: &str| s(&dir.path().join(name)).to_owned();
    std::fs::write(dir.path().join("points.csv"), "x,y\n0,4.5\n0,0\n").unwrap();
    let commands: Vec<Vec<String>> = [
        vec!["validate", job],
        vec!["run", job, "-o", &out("run.json")],
        vec!["region", job, "-o", &out("region.geojson")],
        vec!["section", job, "--x", "0"],
        vec!["membership", job, &out("points.csv")],
        vec!["plot", job, "-o", &out("figures")],
        vec!["export", job, "-o", &out("circle.dxf")],
        vec!["export", job, "-o", &out("circle.step")],
        vec!["export", job, "-o", &out("circle.igs")],
        vec!["export", job, "-o", &out("circle.obj")],
        vec!["report", job, "-o", &out("report")],
    ]
    .into_iter()
    .map(|c| c.into_iter().map(str::to_owned).collect())
    .collect();
    for c in &commands {
        let args: Vec<&str> = c.iter().map(String::as_str).collect();
        let (code, _, stderr) = run(&args);
        assert_eq!(code, 0, "{args:?}: {stderr}");
    }
    let (code, stdout, stderr) = run(&["measure", job, "--levels", "3"]);
    assert_eq!(code, 0, "{stderr}");
    let m: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(m["area"]["kind"], "enclosed", "{stdout}");
    for level in m["area"]["upper"].as_array().unwrap() {
        let (lo, hi) = (
            level["min"].as_f64().unwrap(),
            level["max"].as_f64().unwrap(),
        );
        // The crisp circle of 8 control points encloses about 63.9.
        assert!(
            lo > 40.0 && lo <= 63.9 && (63.8..90.0).contains(&hi),
            "{level}"
        );
    }
}

#[test]
fn closed_on_a_curve_that_does_not_close_is_refused_with_its_ends() {
    let dir = tempfile::tempdir().unwrap();
    let mut job: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(circle()).unwrap()).unwrap();
    // The last point moved: the wrap no longer matches.
    job["points"][10]["x"]["crisp"] = serde_json::json!(0.5);
    for f in ["upper", "primary", "lower"] {
        job["points"][10]["x"][f] = serde_json::json!([0.5, 0.5]);
    }
    let path = dir.path().join("open.json");
    std::fs::write(&path, job.to_string()).unwrap();
    let (code, _, stderr) = run(&["validate", s(&path)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("closed: the curve does not close: it starts at (")
            && stderr.contains("its last p points repeat its first p"),
        "{stderr}"
    );
}
