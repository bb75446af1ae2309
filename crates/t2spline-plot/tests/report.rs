//! Reports of larger jobs: within the size budget, with a coarser grid of
//! stops as the job grows, and still every figure and download.

use t2spline::Alpha;
use t2spline_plot::{render_report, FigureOptions, Stops};

#[allow(dead_code)]
#[path = "../examples/many_points.rs"]
mod many_points;

/// The number of stops of a report (the slider's `max` + 1).
fn stops_in(html: &str) -> usize {
    let at = html
        .find("id=\"alpha\" min=\"0\" max=\"")
        .expect("a slider")
        + 24;
    let end = html[at..].find('"').unwrap() + at;
    html[at..end].parse::<usize>().unwrap() + 1
}

#[test]
fn a_report_of_200_points_stays_under_5_mb_with_every_part() {
    let text = many_points::job(200, 2, 1).to_string();
    let job = t2spline_io::parse_job(&text, "generated").unwrap();
    let start = Alpha::try_new(0.8).unwrap();
    let html = render_report(&job, &text, start, &FigureOptions::default()).unwrap();
    assert!(html.len() < 5_000_000, "{} bytes", html.len());
    // Coarser than 0.01, finer than 0.25: at least 0, 0.1, …, 1 and both heights.
    let n = stops_in(&html);
    assert!((13..101).contains(&n), "{n} stops");
    let grid = [100, 50, 20, 10, 4].map(|k| Stops::new(&job, start, k).alphas.len());
    assert!(grid.contains(&n), "{n} stops is one of the grids {grid:?}");
    for id in [
        "number",
        "stage1",
        "stage2",
        "stage3",
        "stage4",
        "distance",
        "sweep",
        "reductions",
        "membership",
        "section",
        "job",
    ] {
        assert!(html.contains(&format!("<section id=\"{id}\">")), "{id}");
    }
    // Every figure, the membership map and the section included; no
    // measures (more than MEASURES_MAX_POINTS control points).
    assert_eq!(html.matches("data-svg=").count(), 10);
    assert!(!html.contains("<section id=\"measures\">"));
    assert!(!html.contains("href=\"#measures\""));
    assert_eq!(html.matches("data-file=\"stage").count(), 4);
    // Tables list the first 12 points and say where the others are.
    assert!(html.contains("the other 188 are in the downloads"));
}

#[test]
fn a_report_of_a_40_by_40_net_sampled_finely_stays_under_5_mb() {
    let text = many_points::net(40, 101).to_string();
    let job = t2spline_io::parse_job(&text, "net").unwrap();
    let start = Alpha::try_new(0.5).unwrap();
    let html = render_report(&job, &text, start, &FigureOptions::default()).unwrap();
    assert!(html.len() < 5_000_000, "{} bytes", html.len());
    // The net is a terrain: its width map and shoreline are drawn anew at
    // every stop and take their share of the budget beside the finely
    // sampled stages, so the stops are 0, 0.25, …, 1 and the height 0.6 at
    // least (0.1 apart without them).
    let n = stops_in(&html);
    assert!(n >= 6, "{n} stops");
    assert!(html.contains("id=\"envelope-width\"") || html.contains("envelope-width"));
    let grid = [100, 50, 20, 10, 4].map(|k| Stops::new(&job, start, k).alphas.len());
    assert!(grid.contains(&n), "{n} stops is one of the grids {grid:?}");
    assert!(
        html.contains("one row and column in 4 of the net drawn"),
        "the net is thinned and says so"
    );
    assert_eq!(html.matches("data-file=\"stage").count(), 4);
}

#[test]
fn the_report_of_the_example_shows_its_fuzzy_length_and_area_beside_the_distance() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/paper-alg-1-1.json"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let job = t2spline_io::parse_job(&text, "example").unwrap();
    let start = Alpha::try_new(0.5).unwrap();
    let html = render_report(&job, &text, start, &FigureOptions::default()).unwrap();
    let distance = html.find("<section id=\"distance\">").expect("distance");
    let measures = html.find("<section id=\"measures\">").expect("measures");
    let next = html[distance + 1..].find("<section id=").unwrap() + distance + 1;
    assert_eq!(next, measures, "the measures follow the distance");
    assert!(html.contains("href=\"#measures\""), "in the contents");
    let section = &html[measures..];
    let section = &section[..section[1..]
        .find("<section id=")
        .unwrap_or(section.len() - 1)
        + 1];
    for text in ["arc length", "area under the curve", "t2spline measure"] {
        assert!(section.contains(text), "{text}");
    }
    assert_eq!(html.matches("data-svg=").count(), 11);
}
