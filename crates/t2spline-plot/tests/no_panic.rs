//! The figures and the report never panic on valid but extreme jobs: every
//! point at one place, spreads of zero, coordinates near the input range's
//! end, knots of full multiplicity inside, alpha at 0, at h and at 1, a number
//! asked for that the job lacks; and the layout of no figure at all. Each
//! call runs under `catch_unwind` and must return, with a value or an error.

#[path = "../../t2spline/tests/no_panic/returns.rs"]
mod returns;

use proptest::prelude::*;
use returns::returns;
use t2spline::job::Job;
use t2spline::{Alpha, Axis};
use t2spline_plot::{
    all_figures, fit_layout, render_files, render_report, render_svg, Aspect, Figure,
    FigureOptions, Format, NumberChoice,
};

/// A job file of `points` (crisp values and one spread per point), degree,
/// a knot vector with an interior knot of full multiplicity if `jump`.
fn job_text(points: &[(f64, f64, f64)], dim: usize, degree: usize, jump: bool, h: f64) -> String {
    let number = |c: f64, s: f64| {
        format!(
            r#"{{"crisp": {c:e}, "upper": [{:e}, {:e}], "primary": [{:e}, {:e}], "lower": [{:e}, {:e}]}}"#,
            c - 3.0 * s,
            c + 3.0 * s,
            c - 2.0 * s,
            c + 2.0 * s,
            c - s,
            c + s
        )
    };
    let pts: Vec<String> = points
        .iter()
        .map(|&(x, y, s)| {
            let coords = [("x", x), ("y", y), ("z", x - y)];
            let body: Vec<String> = coords[..dim]
                .iter()
                .map(|(k, c)| format!(r#""{k}": {}"#, number(*c, s)))
                .collect();
            format!("{{{}}}", body.join(", "))
        })
        .collect();
    let n = points.len();
    let knots = if jump && n >= 2 * (degree + 1) {
        // Clamped ends and the middle knot repeated degree + 1 times.
        let interior = n - degree - 1;
        let mut k = vec![0.0; degree + 1];
        k.extend((0..interior).map(|i| {
            if i < degree + 1 {
                0.5
            } else {
                0.5 + i as f64 / (2.0 * interior as f64)
            }
        }));
        k.extend(vec![1.0; degree + 1]);
        k.sort_by(f64::total_cmp);
        let k: Vec<String> = k.iter().map(|v| format!("{v:?}")).collect();
        format!(r#""knots": [{}], "#, k.join(", "))
    } else {
        String::new()
    };
    format!(
        r#"{{"degree": {degree}, "lower_height": {h:?}, {knots}"points": [{}]}}"#,
        pts.join(", ")
    )
}

/// Coordinates: ordinary, repeated, or near the input range's end.
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        1 => Just(0.0),
        1 => prop::sample::select(vec![1e140, -1e140, 1e-300, 5e-324, 1e15]),
    ]
}

fn spread() -> impl Strategy<Value = f64> {
    prop_oneof![2 => 0.0..1.0f64, 1 => Just(0.0), 1 => prop::sample::select(vec![1e-300, 1e130])]
}

/// Every figure of `job` at `alpha`, as SVG files and rendered one by one.
fn figures_and_report(job: &Job, alpha: f64, number: NumberChoice, aspect: Aspect, report: bool) {
    let alpha = Alpha::try_new(alpha).unwrap();
    let options = FigureOptions {
        number,
        aspect,
        ..FigureOptions::default()
    };
    if let Ok(figures) = returns("all_figures", || all_figures(job, alpha, &options)) {
        for fig in &figures {
            returns("render_svg", || render_svg(fig));
        }
        returns("render_files", || render_files(&figures, Format::Svg)).ok();
    }
    if report {
        returns("render_report", || {
            render_report(job, "{}", alpha, &options)
        })
        .ok();
    }
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(8, 16))]

    #[test]
    fn extreme_valid_jobs_never_panic(
        points in prop::collection::vec((coordinate(), coordinate(), spread()), 1..7),
        dim in 2..=3usize,
        degree in 1..4usize,
        jump in any::<bool>(),
        h in prop::sample::select(vec![0.1, 0.5, 1.0]),
        alpha in prop::sample::select(vec![0.0, 0.1, 0.5, 1.0]),
        point in prop::sample::select(vec![0, 1, 99]),
        axis in prop::sample::select(vec![Axis::X, Axis::Y, Axis::Z]),
        auto in any::<bool>(),
        same in any::<bool>(),
    ) {
        let mut points = points;
        if same {
            let first = points[0];
            points.iter_mut().for_each(|p| *p = first);
        }
        let text = job_text(&points, dim, degree, jump, h);
        let Ok(job) = t2spline_io::parse_job(&text, "extreme.json") else { return Ok(()) };
        let aspect = if auto { Aspect::Auto } else { Aspect::Equal };
        let number = NumberChoice { point, axis };
        // The report lays out every stop: a few of the cases suffice.
        figures_and_report(&job, alpha, number, aspect, point == 0 && degree == 1);
        figures_and_report(&job, h, number, aspect, false);
    }
}

/// Laying out no figure, or a figure without panels, gives a page.
#[test]
fn the_layout_of_nothing_is_a_page() {
    returns("fit_layout of no figure", || fit_layout(&[]));
    let empty = Figure::new("empty", "", "", Vec::new(), Vec::new());
    returns("fit_layout of a figure without panels", || {
        fit_layout(&[&empty])
    });
    returns("render_svg of a figure without panels", || {
        render_svg(&empty)
    });
    returns("render_files of no figure", || {
        render_files(&[], Format::Svg)
    })
    .unwrap();
}
