//! The `measures` figure draws the core's numbers: each membership
//! function's line runs through the ends of the core's cuts of the fuzzy
//! arc length and area (docs/method.md §11), and the crisp mark is the crisp
//! curve's value.

use std::path::Path;

use t2spline::job::{Job, Model};
use t2spline::measure::{Level, MeasureOptions, Measures};
use t2spline::Alpha;
use t2spline_plot::{all_figures, FigureOptions, Mark, Panel};

fn read(job: &str) -> Job {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    t2spline_io::read_job(&root.join(job)).unwrap()
}

/// The levels 0, 0.05, …, 1 and the job's heights.
fn levels(job: &Job) -> Vec<Alpha> {
    let mut a: Vec<f64> = (0..=20).map(|k| f64::from(k) / 20.0).collect();
    a.extend(job.model.heights());
    a.sort_by(f64::total_cmp);
    a.dedup();
    a.into_iter().map(|a| Alpha::try_new(a).unwrap()).collect()
}

fn options(job: &Job) -> MeasureOptions {
    MeasureOptions::new(levels(job), Vec::new(), 1)
        .unwrap()
        .closed(job.closed)
}

fn line<'a>(p: &'a Panel, key: &str) -> &'a [[f64; 2]] {
    p.items
        .iter()
        .find_map(|it| match (&it.mark, it.key == key) {
            (Mark::Line { points, .. }, true) => Some(points.as_slice()),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no line {key}"))
}

fn crisp_mark(p: &Panel) -> f64 {
    p.items
        .iter()
        .find_map(|it| match (&it.mark, it.key == "crisp") {
            (Mark::Markers { points, .. }, true) => Some(points[0][0]),
            _ => None,
        })
        .unwrap()
}

/// The drawn line of one function is the least ends up the levels and the
/// largest ends down, exactly the core's numbers.
fn assert_traces(p: &Panel, key: &str, cuts: &[Level]) {
    let drawn = line(p, key);
    assert_eq!(drawn.len(), 2 * cuts.len(), "{key}");
    for (k, c) in cuts.iter().enumerate() {
        assert_eq!(drawn[k], [c.min, c.alpha], "{key} left end at {}", c.alpha);
        assert_eq!(
            drawn[drawn.len() - 1 - k],
            [c.max, c.alpha],
            "{key} right end at {}",
            c.alpha
        );
    }
}

fn measures_figure(job: &Job) -> t2spline_plot::Figure {
    all_figures(job, Alpha::try_new(0.5).unwrap(), &FigureOptions::default())
        .unwrap()
        .into_iter()
        .find(|f| f.name == "measures")
        .expect("a measures figure")
}

fn check(p: &Panel, cuts: &t2spline::measure::PerMembership<Vec<Level>>, crisp: f64) {
    assert_traces(p, "umf", &cuts.upper);
    assert_traces(p, "primary", &cuts.primary);
    assert_traces(p, "lmf", &cuts.lower);
    assert!((crisp_mark(p) - crisp).abs() <= 1e-9 * crisp.abs().max(1.0));
    // The crisp value lies in every cut of the upper and primary functions
    // (the crisp control points are in every box).
    for c in cuts.upper.iter().chain(&cuts.primary) {
        assert!(c.bracket().holds(crisp, 1e-9), "{c:?} {crisp}");
    }
    // The lower function ends at its height, below 1.
    let top = cuts.lower.last().unwrap().alpha;
    assert!(top < 1.0 && top > 0.0);
}

#[test]
fn the_plane_curve_figure_draws_the_cores_length_and_area() {
    let job = read("examples/paper-alg-1-1.json");
    let Model::Planar(c) = &job.model else {
        panic!("a plane curve")
    };
    let m: Measures = c.measure(&options(&job)).unwrap();
    let fig = measures_figure(&job);
    assert_eq!(fig.panels.len(), 2);
    check(&fig.panels[0], &m.length, c.crisp_curve().arc_length());
    let area = m.area.unwrap();
    let cuts = t2spline::measure::PerMembership {
        upper: area.upper,
        primary: area.primary,
        lower: area.lower,
    };
    let one = cuts.upper.last().unwrap();
    assert_eq!(one.alpha, 1.0);
    check(&fig.panels[1], &cuts, 0.5 * (one.min + one.max));
}

#[test]
fn the_space_curve_figure_draws_the_cores_length_only() {
    let job = read("fixtures/spiral-3d.json");
    let Model::Spatial(c) = &job.model else {
        panic!("a space curve")
    };
    let m = c.measure(&options(&job)).unwrap();
    let fig = measures_figure(&job);
    assert_eq!(fig.panels.len(), 1);
    check(&fig.panels[0], &m.length, c.crisp_curve().arc_length());
}
