//! `t2spline envelope` (docs/method.md §12): the table on standard output
//! against `section --at` at cell centres, the three file formats, and the
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

/// The rows of the CSV table: `(x, y, alpha, membership, lower, upper)`.
fn table(csv: &str) -> Vec<(f64, f64, f64, String, f64, f64)> {
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("x,y,alpha,membership,lower,upper"));
    lines
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let n = |k: usize| f[k].parse::<f64>().expect("a number");
            (n(0), n(1), n(2), f[3].to_owned(), n(4), n(5))
        })
        .collect()
}

#[test]
fn the_table_matches_sections_at_cell_centres() {
    let job = example("fuzzy-terrain.json");
    let (code, out, err) = run(&["envelope", s(&job), "--grid", "3,2", "--levels", "3"]);
    assert_eq!(code, 0, "{err}");
    let rows = table(&out);
    // 6 cells, 3 levels, upper and primary at every level, lower up to its
    // height (below 1).
    assert!(rows.len() >= 6 * 3 * 2 + 6, "{} rows", rows.len());
    for r in &rows {
        assert!(r.4 <= r.5, "{r:?}");
    }
    // Section at the first cell centre, every level.
    let (x, y) = (rows[0].0, rows[0].1);
    let at = format!("{x},{y}");
    let (code, json, err) = run(&["section", s(&job), "--at", &at, "--levels", "3"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let levels = v["levels"].as_array().expect("levels");
    for r in rows.iter().filter(|r| r.0 == x && r.1 == y) {
        let level = levels
            .iter()
            .find(|l| l["alpha"].as_f64() == Some(r.2))
            .expect("the level");
        let intervals = level[r.3.as_str()].as_array().expect("intervals");
        let lo = intervals[0][0].as_f64().expect("a number");
        let hi = intervals[intervals.len() - 1][1]
            .as_f64()
            .expect("a number");
        // Sections are refined to about 1e-9 of the region's height.
        assert!(
            (lo - r.4).abs() < 1e-6 && (hi - r.5).abs() < 1e-6,
            "{r:?} vs [{lo}, {hi}]"
        );
    }
}

#[test]
fn files_of_each_format() {
    let dir = tempfile::tempdir().expect("a folder");
    let job = example("salish-sea-seabed.json");
    for (name, magic) in [
        ("e.tif", &b"II*\0"[..]),
        ("e.parquet", b"PAR1"),
        ("e.csv", b"x,y,"),
    ] {
        let out = dir.path().join(name);
        let mut args = vec![
            "envelope",
            s(&job),
            "--grid",
            "8,6",
            "--alpha",
            "0.5",
            "-o",
            s(&out),
        ];
        if name.ends_with(".tif") {
            args.extend(["--crs", "EPSG:3857"]);
        }
        let (code, stdout, err) = run(&args);
        assert_eq!((code, stdout.as_str()), (0, ""), "{name}: {err}");
        let bytes = std::fs::read(&out).expect("written");
        assert_eq!(&bytes[..magic.len()], magic, "{name}");
    }
    // A level-1 GeoTIFF: upper, primary (lower above its height 0.5) × 2.
    let csv = std::fs::read_to_string(dir.path().join("e.csv")).expect("written");
    assert_eq!(
        table(&csv).len(),
        8 * 6 * 3,
        "every cell has data, three functions at 0.5"
    );
}

#[test]
fn an_extent_beyond_the_surface_is_nodata() {
    let job = example("fuzzy-terrain.json");
    let (code, out, err) = run(&[
        "envelope",
        s(&job),
        "--grid",
        "2,2",
        "--alpha",
        "0",
        "--extent",
        "1e6,1e6,2e6,2e6",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "x,y,alpha,membership,lower,upper\n");
}

#[test]
fn option_values_that_break_a_rule() {
    let job = example("fuzzy-terrain.json");
    let curve = example("paper-alg-1-1.json");
    let cases: &[(&[&str], &str)] = &[
        (&["--grid", "0,3"], "--grid: `0,3` is not two positive whole numbers NX,NY"),
        (&["--grid", "3"], "--grid: `3` is not two positive whole numbers"),
        (&["--grid", "10000,10000"], "--grid: 10000 x 10000 cells at 11 level(s) are 6600000000 values (cells x levels x 6), more than the limit of 100000000"),
        (&["--grid", "3,3", "--levels", "1"], "--levels: 1 is outside 2 ..= 1001"),
        (&["--grid", "3,3", "--alpha", "1.5"], "--alpha: 1.5 is outside [0, 1]"),
        (&["--grid", "3,3", "--extent", "0,0,1"], "--extent: `0,0,1` is not four finite numbers X0,Y0,X1,Y1"),
        (&["--grid", "3,3", "--extent", "1,0,0,1"], "--extent: X0 = 1 is not less than X1 = 0"),
        (&["--grid", "3,3", "--crs", "WGS84"], "--crs: `WGS84` is not EPSG:CODE"),
    ];
    let dir = tempfile::tempdir().expect("a folder");
    let out = dir.path().join("out.tif");
    for (extra, words) in cases {
        let mut args = vec!["envelope", s(&job)];
        args.extend_from_slice(extra);
        args.extend(["-o", s(&out)]);
        let (code, stdout, err) = run(&args);
        assert_eq!((code, stdout.as_str()), (2, ""), "{extra:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with("t2spline: "), "{err}");
        assert!(err.contains(words), "{extra:?}: {err}");
        assert!(!out.exists(), "{extra:?} wrote its output");
    }
    let csv = dir.path().join("out.csv");
    let (code, _, err) = run(&[
        "envelope",
        s(&job),
        "--grid",
        "3,3",
        "--crs",
        "EPSG:4326",
        "-o",
        s(&csv),
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--crs: is recorded in a GeoTIFF only"),
        "{err}"
    );
    let txt = dir.path().join("out.txt");
    let (code, _, err) = run(&["envelope", s(&job), "--grid", "3,3", "-o", s(&txt)]);
    assert_eq!(code, 2);
    assert!(
        err.contains("does not end in .tif, .tiff, .csv or .parquet"),
        "{err}"
    );
    let (code, _, err) = run(&["envelope", s(&curve), "--grid", "3,3", "-o", s(&out)]);
    assert_eq!(code, 2);
    assert!(
        err.contains(&format!("{}: envelopes are taken of surfaces", s(&curve))),
        "{err}"
    );
    assert!(!out.exists() && !csv.exists() && !txt.exists());
    let (code, _, err) = run(&[
        "envelope",
        s(&job),
        "--grid",
        "3,3",
        "--levels",
        "3",
        "--alpha",
        "0.5",
    ]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn the_seabed_agrees_with_its_section_at_negative_coordinates() {
    let job = example("salish-sea-seabed.json");
    let extent = "-13900000,6150000,-13890000,6160000";
    let (code, out, err) = run(&[
        "envelope",
        s(&job),
        "--grid",
        "1,1",
        "--alpha",
        "0",
        "--extent",
        extent,
    ]);
    assert_eq!(code, 0, "{err}");
    let rows = table(&out);
    let (code, json, err) = run(&[
        "section",
        s(&job),
        "--at",
        "-13895000,6155000",
        "--levels",
        "2",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let level = &v["levels"][0];
    for r in &rows {
        let intervals = level[r.3.as_str()].as_array().expect("intervals");
        let lo = intervals[0][0].as_f64().expect("a number");
        let hi = intervals[intervals.len() - 1][1]
            .as_f64()
            .expect("a number");
        // Metres of depth; sections to about 1e-9 of the region's height.
        assert!(
            (lo - r.4).abs() < 1e-5 && (hi - r.5).abs() < 1e-5,
            "{r:?} vs [{lo}, {hi}]"
        );
    }
}
