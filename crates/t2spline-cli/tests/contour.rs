//! `t2spline contour` (docs/method.md §13): the fuzzy shoreline of the
//! shipped seabed as GeoJSON on standard output and in a file, the section
//! `--at` of a point inside and outside a band against its polygons, and the
//! options' errors (exit 2, one line naming the option and the rule, no
//! output file).

use std::path::{Path, PathBuf};

mod common;
use common::{run, s};

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
}

#[test]
fn the_shoreline_is_a_feature_collection_of_bands_and_the_crisp_line() {
    let job = example("salish-sea-seabed.json");
    let (code, out, err) = run(&["contour", s(&job), "--z", "0", "--levels", "2"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let features = v["features"].as_array().expect("features");
    let names: Vec<(f64, &str)> = features
        .iter()
        .filter_map(|f| {
            Some((
                f["properties"]["alpha"].as_f64()?,
                f["properties"]["membership"].as_str()?,
            ))
        })
        .collect();
    // The lower function's cut ends at its height 0.5: left out at level 1.
    assert_eq!(
        names,
        vec![
            (0.0, "upper"),
            (0.0, "primary"),
            (0.0, "lower"),
            (1.0, "upper"),
            (1.0, "primary")
        ]
    );
    let last = features.last().expect("the crisp contour");
    assert_eq!(last["properties"]["crisp"], true);
    assert_eq!(last["geometry"]["type"], "MultiLineString");
    assert!(!last["geometry"]["coordinates"]
        .as_array()
        .expect("lines")
        .is_empty());
    for f in &features[..features.len() - 1] {
        for polygon in f["geometry"]["coordinates"].as_array().expect("polygons") {
            for ring in polygon.as_array().expect("rings") {
                let r = ring.as_array().expect("positions");
                assert!(r.len() >= 4 && r.first() == r.last(), "ring not closed");
            }
        }
    }
    // The band at level 1 (the crisp surface alone) is narrower than at 0.
    let area = |k: usize| features[k]["properties"]["area"].as_f64().expect("area");
    assert!(area(3) < area(0), "{} vs {}", area(3), area(0));
}

#[test]
fn a_file_is_the_same_as_standard_output() {
    let job = example("salish-sea-seabed.json");
    let dir = tempfile::tempdir().expect("a folder");
    let path = dir.path().join("shore.geojson");
    let (code, out, err) = run(&[
        "contour",
        s(&job),
        "--z",
        "-20",
        "--alpha",
        "0.3",
        "--grid",
        "40,50",
    ]);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = run(&[
        "contour",
        s(&job),
        "--z",
        "-20",
        "--alpha",
        "0.3",
        "--grid",
        "40,50",
        "-o",
        s(&path),
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read_to_string(&path).expect("written"), out);
}

#[test]
fn bad_options_are_named_and_nothing_is_written() {
    let job = example("salish-sea-seabed.json");
    let curve = example("paper-alg-1-1.json");
    let dir = tempfile::tempdir().expect("a folder");
    let path = dir.path().join("out.geojson");
    let out = s(&path);
    for (args, start) in [
        (
            vec!["contour", s(&job), "--z", "inf", "-o", out],
            "t2spline: --z: inf is not a finite number",
        ),
        (
            vec!["contour", s(&job), "--z", "0", "--alpha", "-0.1", "-o", out],
            "t2spline: --alpha: alpha = -0.1 is outside [0, 1]",
        ),
        (
            vec!["contour", s(&job), "--z", "0", "--levels", "1", "-o", out],
            "t2spline: --levels: 1 is outside 2 ..= 1001",
        ),
        (
            vec!["contour", s(&job), "--z", "0", "--grid", "3", "-o", out],
            "t2spline: --grid: `3` is not two positive whole numbers NX,NY",
        ),
        (
            vec![
                "contour",
                s(&job),
                "--z",
                "0",
                "--extent",
                "0,0,0,1",
                "-o",
                out,
            ],
            "t2spline: --extent: X0 = 0 is not less than X1 = 0",
        ),
        (
            vec!["contour", s(&job), "--z", "0", "-o", "shore.tif"],
            "t2spline: --output: `shore.tif` does not end in .geojson or .json",
        ),
        (
            vec!["contour", s(&curve), "--z", "0", "-o", out],
            // The job's file named, as every message about a job.
            Box::leak(
                format!("t2spline: {}: contours are traced on surfaces", s(&curve))
                    .into_boxed_str(),
            ),
        ),
    ] {
        let (code, _, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.starts_with(start), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(!path.exists(), "{args:?} wrote a file");
    }
}
