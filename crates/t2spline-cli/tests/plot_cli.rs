//! `t2spline plot` and `t2spline report` run as the built binary.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;
use predicates::str::contains;

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json")
}

fn t2spline() -> Command {
    Command::cargo_bin("t2spline").unwrap()
}

/// `t2spline SUB EXAMPLE -o DIR`, to add options to.
fn on_example(sub: &str, dir: &Path) -> Command {
    let mut c = t2spline();
    c.args([
        sub,
        example().to_str().unwrap(),
        "-o",
        dir.to_str().unwrap(),
    ]);
    c
}

const NAMES: [&str; 11] = [
    "number",
    "stage1-fuzzy",
    "stage2-alpha-cut",
    "stage3-type-reduced",
    "stage4-defuzzified",
    "alpha-sweep",
    "distance-alpha",
    "reductions",
    "measures",
    "membership",
    "section",
];

#[test]
fn plot_writes_every_figure_in_both_formats_by_default() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    t2spline()
        .args([
            "plot",
            example().to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .assert()
        .success()
        .stdout(contains("stage4-defuzzified.png"));
    for name in NAMES {
        for ext in ["svg", "png"] {
            let p = out.join(format!("{name}.{ext}"));
            assert!(
                std::fs::metadata(&p).unwrap().len() > 1000,
                "{}",
                p.display()
            );
        }
    }
    assert_eq!(
        std::fs::read_dir(&out).unwrap().count(),
        2 * NAMES.len(),
        "no stray files"
    );
}

#[test]
fn plot_svg_only_and_a_chosen_number() {
    let dir = tempfile::tempdir().unwrap();
    t2spline()
        .args([
            "plot",
            example().to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
        ])
        .args([
            "--format", "svg", "--point", "3", "--axis", "y", "--alpha", "0.3",
        ])
        .assert()
        .success();
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), NAMES.len());
    let number = std::fs::read_to_string(dir.path().join("number.svg")).unwrap();
    assert!(
        number.contains("coordinate y of control point 3"),
        "{number}"
    );
    assert!(number.contains("α = 0.3"));
}

#[test]
fn aspect_auto_fits_each_axis_and_notes_it() {
    let dir = tempfile::tempdir().unwrap();
    for aspect in ["equal", "auto"] {
        let out = dir.path().join(aspect);
        on_example("plot", &out)
            .args(["--format", "svg", "--aspect", aspect])
            .assert()
            .success();
        let stage1 = std::fs::read_to_string(out.join("stage1-fuzzy.svg")).unwrap();
        assert_eq!(
            stage1.contains("Axes not to scale"),
            aspect == "auto",
            "{aspect}"
        );
    }
    on_example("plot", dir.path())
        .args(["--aspect", "wide"])
        .assert()
        .code(2)
        .stderr(contains("--aspect"));
}

#[test]
fn report_accepts_the_figure_options() {
    let dir = tempfile::tempdir().unwrap();
    on_example("report", dir.path())
        .args(["--point", "3", "--axis", "y", "--aspect", "auto"])
        .assert()
        .success();
    let html = std::fs::read_to_string(dir.path().join("report.html")).unwrap();
    assert!(html.contains("coordinate y of control point 3"));
    assert!(html.contains("Axes not to scale"));
    on_example("report", dir.path())
        .args(["--point", "9"])
        .assert()
        .code(2)
        .stderr(contains("--point: point 9 does not exist"));
}

#[test]
fn plot_errors_name_the_option_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    t2spline()
        .args([
            "plot",
            example().to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--point",
            "4",
        ])
        .assert()
        .code(2)
        .stderr("t2spline: --point: point 4 does not exist: the job has 4 points, 0 to 3\n");
    t2spline()
        .args([
            "plot",
            example().to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--axis",
            "z",
        ])
        .assert()
        .code(2)
        .stderr("t2spline: --axis: coordinate z does not exist in a 2-D job\n");
    t2spline()
        .args([
            "plot",
            example().to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--alpha",
            "1.5",
        ])
        .assert()
        .code(2)
        .stderr(contains("--alpha"));
    assert!(!out.exists(), "nothing written on error");
}

#[test]
fn report_is_one_self_contained_file() {
    let dir = tempfile::tempdir().unwrap();
    t2spline()
        .args([
            "report",
            example().to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
        ])
        .assert()
        .success()
        .stdout(contains("report.html"));
    let html = std::fs::read_to_string(dir.path().join("report.html")).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    // Nothing is loaded from elsewhere: no links, no script or image sources,
    // and the only URL is the SVG namespace.
    for forbidden in ["<link", "src=", "@import", "url(http", "href=\"http"] {
        assert!(!html.contains(forbidden), "found {forbidden}");
    }
    let urls = html.matches("http://").count();
    let namespaces = html.matches("http://www.w3.org/2000/svg").count();
    assert_eq!(urls, namespaces, "only the SVG namespace is a URL");
    assert!(
        html.contains("&quot;order&quot;: 3"),
        "the job itself is shown"
    );
    assert!(html.len() < 4_000_000, "report size {}", html.len());
}

fn surface_example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../../examples/{name}"))
}

#[test]
fn plot_and_report_draw_both_surface_examples() {
    for name in ["fuzzy-terrain.json", "fuzzy-cylinder.json"] {
        let dir = tempfile::tempdir().unwrap();
        let job = surface_example(name);
        t2spline()
            .args(["plot", job.to_str().unwrap(), "-o"])
            .arg(dir.path().join("figs"))
            .args(["--view", "30,45", "--point", "5", "--axis", "z"])
            .assert()
            .success()
            .stdout(contains("stage4-defuzzified.png"));
        for stem in &NAMES[..5] {
            for ext in ["svg", "png"] {
                let p = dir.path().join("figs").join(format!("{stem}.{ext}"));
                assert!(
                    std::fs::metadata(&p).unwrap().len() > 1000,
                    "{}",
                    p.display()
                );
            }
        }
        let png = std::fs::read(dir.path().join("figs/stage1-fuzzy.png")).unwrap();
        assert_eq!(
            &png[37..41],
            b"pHYs",
            "{name}: 300 dpi like the curve figures"
        );
        let svg = std::fs::read_to_string(dir.path().join("figs/stage1-fuzzy.svg")).unwrap();
        assert!(
            svg.contains("azimuth 30°, elevation 45°"),
            "{name}: the view is stated"
        );
        assert!(!dir.path().join("figs/alpha-sweep.svg").exists());
        assert!(dir.path().join("figs/distance-alpha.svg").exists());
        t2spline()
            .args(["report", job.to_str().unwrap(), "-o"])
            .arg(dir.path().join("report"))
            .args(["--view", "-30,20"])
            .assert()
            .success();
        let html = std::fs::read_to_string(dir.path().join("report/report.html")).unwrap();
        assert!(
            html.contains("id=\"m-max-at-v\""),
            "{name}: max_at is (u, v)"
        );
        assert!(html.contains("azimuth −30°, elevation 20°"), "{name}");
        assert!(html.len() < 5_000_000, "{name}: report size {}", html.len());
    }
}

#[test]
fn a_bad_view_is_an_error_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let job = surface_example("fuzzy-terrain.json");
    for (sub, view, why) in [
        ("plot", "30", "expected AZIMUTH,ELEVATION"),
        ("plot", "30,100", "[-90, 90]"),
        ("report", "east,10", "is not a number"),
    ] {
        t2spline()
            .args([sub, job.to_str().unwrap(), "-o"])
            .arg(dir.path().join("out"))
            .arg(format!("--view={view}"))
            .assert()
            .code(2)
            .stderr(contains("--view").and(contains(why)));
    }
    assert!(!dir.path().join("out").exists(), "nothing written on error");
}

#[test]
fn point_names_a_net_point_by_row_and_column() {
    let dir = tempfile::tempdir().unwrap();
    // The terrain's net is 6 × 5: (2, 1) is point 2·5 + 1 = 11.
    let job = surface_example("fuzzy-terrain.json");
    let number = |point: &str| {
        let out = dir.path().join(format!("figs-{point}"));
        t2spline()
            .args(["plot", job.to_str().unwrap(), "-o"])
            .arg(&out)
            .args(["--format", "svg", "--point", point, "--axis", "z"])
            .assert()
            .success();
        std::fs::read_to_string(out.join("number.svg")).unwrap()
    };
    let by_net = number("2,1");
    assert!(
        by_net.contains("coordinate z of control point (2, 1)"),
        "the title names (i, j)"
    );
    assert_eq!(by_net, number("11"), "I,J and the row-major I agree");
    let report = dir.path().join("report");
    t2spline()
        .args(["report", job.to_str().unwrap(), "-o"])
        .arg(&report)
        .args(["--point", "5,4"])
        .assert()
        .success();
    let html = std::fs::read_to_string(report.join("report.html")).unwrap();
    assert!(html.contains("coordinate x of control point (5, 4)"));
    assert!(html.contains("--point I,J"));
}

#[test]
fn bad_net_points_are_errors_of_the_option() {
    let dir = tempfile::tempdir().unwrap();
    let terrain = surface_example("fuzzy-terrain.json");
    let run = |job: &Path, point: &str| {
        t2spline()
            .args(["plot", job.to_str().unwrap(), "-o"])
            .arg(dir.path().join("figs"))
            .args(["--point", point])
            .assert()
            .code(2)
    };
    run(&terrain, "6,0").stderr(
        "t2spline: --point: 6,0 lies outside the 6 × 5 control net (I from 0 to 5, J from 0 to 4)\n",
    );
    run(&terrain, "0,5").stderr(contains("--point: 0,5 lies outside"));
    run(&terrain, "30").stderr(contains(
        "--point: point 30 does not exist: the job has 30 points, 0 to 29",
    ));
    run(&example(), "1,2").stderr(contains(
        "--point: 1,2 names a point of a surface's net, but this job is a curve",
    ));
    run(&terrain, "1,x").stderr(contains("--point"));
    assert!(!dir.path().join("figs").exists(), "nothing written");
}
