//! `t2spline plot` and `t2spline report` of terrains: the envelope width,
//! the fuzzy shoreline and the fuzzy measures are written, parse as SVG,
//! and their numbers are those `t2spline envelope`, `contour` and
//! `measure` print; a surface that is not a terrain plots its stages and
//! says why the terrain figures are left out.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::str::contains;
use serde_json::Value;

fn t2spline() -> Command {
    Command::cargo_bin("t2spline").unwrap()
}

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../../examples/{name}"))
}

/// The texts of an SVG file, which must parse as XML, joined by spaces
/// (a wrapped note is one text again).
fn texts(path: &Path) -> String {
    let svg = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&svg).expect("the SVG parses");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect::<Vec<_>>()
        .join(" ")
}

/// The number after `prefix` in `text` (`−` read as a minus sign).
fn number_after(text: &str, prefix: &str) -> f64 {
    let at = text
        .find(prefix)
        .unwrap_or_else(|| panic!("{prefix:?} in {text:?}"))
        + prefix.len();
    let n: String = text[at..]
        .replace('−', "-")
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-'))
        .collect();
    n.parse()
        .unwrap_or_else(|_| panic!("a number after {prefix:?} in {text:?}"))
}

/// `shown` is `exact` to the four significant digits the figures print.
fn agrees(shown: f64, exact: f64, what: &str) {
    let unit = if exact == 0.0 {
        0.0
    } else {
        10f64.powf(exact.abs().log10().floor() - 3.0)
    };
    assert!(
        (shown - exact).abs() <= 0.5 * unit * (1.0 + 1e-9),
        "{what}: shown {shown}, exact {exact}"
    );
}

fn stdout(args: &[&str]) -> String {
    let out = t2spline().args(args).assert().success();
    String::from_utf8(out.get_output().stdout.clone()).unwrap()
}

#[test]
fn terrain_figures_agree_with_envelope_contour_and_measure() {
    for name in ["fuzzy-terrain.json", "salish-sea-seabed.json"] {
        let dir = tempfile::tempdir().unwrap();
        let job = example(name);
        let job = job.to_str().unwrap();
        let figs = dir.path().join("figs");
        t2spline()
            .args(["plot", job, "--format", "svg", "-o"])
            .arg(&figs)
            .assert()
            .success()
            .stdout(contains("envelope-width.svg"))
            .stdout(contains("shoreline.svg"))
            .stdout(contains("terrain-measures.svg"));
        // The width map: its colour bar's largest value is the envelope
        // table's largest width at the job's alpha (0.5), on the grid it names.
        let width = texts(&figs.join("envelope-width.svg"));
        for label in ["width (units of z)", "upper (UMF) width", "primary width"] {
            assert!(width.contains(label), "{name}: {label}");
        }
        let at = width.find("t2spline envelope --grid ").unwrap() + 25;
        let grid: String = width[at..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == ',')
            .collect();
        let table = stdout(&["envelope", job, "--grid", &grid, "--alpha", "0.5"]);
        let mut largest = 0.0_f64;
        for row in table.lines().skip(1) {
            let f: Vec<&str> = row.split(',').collect();
            if f[3] == "upper" {
                if let (Ok(lo), Ok(hi)) = (f[4].parse::<f64>(), f[5].parse::<f64>()) {
                    largest = largest.max(hi - lo);
                }
            }
        }
        agrees(number_after(&width, "max "), largest, name);
        // The shoreline: the band areas are those of `t2spline contour`.
        let shore = texts(&figs.join("shoreline.svg"));
        assert!(shore.contains("crisp surface's shoreline z = 0"), "{name}");
        let geojson: Value =
            serde_json::from_str(&stdout(&["contour", job, "--z", "0", "--alpha", "0.5"])).unwrap();
        for f in geojson["features"].as_array().unwrap() {
            let p = &f["properties"];
            // The crisp contour (a line, no membership) is not a band.
            let Some(m) = p["membership"].as_str() else {
                continue;
            };
            let area = p["area"].as_f64().unwrap();
            let areas = &shore[shore.find("Band areas").unwrap()..];
            agrees(number_after(areas, &format!("{m} ")), area, name);
        }
        // The measures: the crisp surface's values are those of `measure`
        // at level 1.
        let measures = texts(&figs.join("terrain-measures.svg"));
        let m: Value =
            serde_json::from_str(&stdout(&["measure", job, "--alpha", "1", "--no-area"])).unwrap();
        for (key, label) in [
            ("volume_below", "volume below z = 0 "),
            ("volume_above", "volume above z = 0 "),
            ("plan_area_below", "plan area below z = 0 "),
        ] {
            let crisp = m[key]["upper"][0]["min"].as_f64().unwrap();
            let subtitle = &measures[measures.find("crisp surface: ").unwrap()..];
            agrees(
                number_after(subtitle, label),
                crisp,
                &format!("{name} {key}"),
            );
            assert!(measures.contains(&format!("fuzzy {}", label.trim_end())));
        }
    }
}

#[test]
fn a_surface_that_is_not_a_terrain_plots_its_stages_and_says_why() {
    let dir = tempfile::tempdir().unwrap();
    let job = example("fuzzy-cylinder.json");
    t2spline()
        .args(["plot", job.to_str().unwrap(), "--format", "svg", "-o"])
        .arg(dir.path())
        .assert()
        .success()
        .stdout(contains("stage4-defuzzified.svg"))
        .stderr(contains(
            "the terrain figures (envelope-width, shoreline, terrain-measures) are left out",
        ));
    for stem in ["envelope-width", "shoreline", "terrain-measures"] {
        assert!(!dir.path().join(format!("{stem}.svg")).exists(), "{stem}");
    }
}

#[test]
fn the_report_of_a_terrain_shows_its_figures() {
    let dir = tempfile::tempdir().unwrap();
    let job = example("fuzzy-terrain.json");
    t2spline()
        .args(["report", job.to_str().unwrap(), "-o"])
        .arg(dir.path())
        .assert()
        .success();
    let html = std::fs::read_to_string(dir.path().join("report.html")).unwrap();
    for figure in ["envelope-width", "shoreline", "terrain-measures"] {
        assert!(
            html.contains(&format!("data-name=\"{figure}\"")),
            "{figure}"
        );
    }
    assert!(html.len() < 5_000_000, "report size {}", html.len());
}
