//! The distance between the crisp and the defuzzified curve (`error.max` and
//! `error.rms`, sampled) against alpha, with both one-sided limits at every
//! lower height h, where the solution jumps (docs/method.md §3).

use t2spline::job::Job;
use t2spline::Alpha;

use crate::chart::paint::{Marker, Shape, Stroke, BLACK, BLUE, GREY, INK};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel};
use crate::chart::ticks::short;
use crate::data::{self, just_above};

/// The alphas at which the distance is computed: 0, 0.01, …, 1, and at
/// every lower height h in (0, 1) both h and the next float above it.
#[must_use]
pub fn distance_alphas(heights: &[f64]) -> Vec<f64> {
    let mut v: Vec<f64> = (0..=100).map(|i| f64::from(i) / 100.0).collect();
    v.extend(heights.iter().copied());
    v.extend(heights.iter().filter_map(|&h| just_above(h)));
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

fn max_stroke() -> Stroke {
    Stroke::solid(BLACK, 1.8)
}

fn rms_stroke() -> Stroke {
    Stroke::dashed(BLUE, 1.8, "6 3")
}

/// The graph of one quantity: a line per stretch between jumps (so that no
/// line bridges a jump), closed markers at the values at each h, open ones
/// at the limits from above.
fn series(
    p: &mut Panel,
    key: &str,
    alphas: &[f64],
    values: &[f64],
    heights: &[f64],
    stroke: &Stroke,
) {
    let piece = |a: f64| heights.iter().filter(|&&h| h < a).count();
    let mut pieces: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut last = usize::MAX;
    for (&a, &v) in alphas.iter().zip(values) {
        if piece(a) != last {
            pieces.push(Vec::new());
            last = piece(a);
        }
        if let Some(line) = pieces.last_mut() {
            line.push([a, v]);
        }
    }
    // One polyline, the stretches separated by gaps.
    let mut points = Vec::new();
    for line in pieces {
        if !points.is_empty() {
            points.push([f64::NAN, f64::NAN]);
        }
        points.extend(line);
    }
    p.push(
        format!("{key}-curve"),
        Mark::Line {
            points,
            stroke: stroke.clone(),
        },
    );
    let at = |x: f64| {
        alphas
            .iter()
            .position(|&a| a == x)
            .map(|k| [alphas[k], values[k]])
    };
    let closed: Vec<_> = heights.iter().filter_map(|&h| at(h)).collect();
    // The limit from above is drawn at h itself.
    let open: Vec<_> = heights
        .iter()
        .filter_map(|&h| just_above(h).and_then(at).map(|[_, v]| [h, v]))
        .collect();
    p.push(
        format!("{key}-at-h"),
        Mark::Markers {
            points: closed,
            marker: Marker::filled(Shape::Circle, 6.0, stroke.color),
        },
    );
    p.push(
        format!("{key}-above-h"),
        Mark::Markers {
            points: open,
            marker: Marker::open(Shape::Circle, 6.0, stroke.color),
        },
    );
}

/// The `distance-alpha` figure: the largest and the rms distance against
/// alpha (sampled by [`data::sampled_distances`] at [`distance_alphas`]),
/// with the lower heights and the figure's own alpha marked; always the
/// paper's type reduction (the one that uses alpha; docs/method.md §9).
///
/// # Errors
/// [`crate::Error::Core`] if sampling fails (never for a validated job).
pub fn distance_figure(job: &Job, alpha: f64) -> Result<Figure, crate::error::Error> {
    let heights = job.model.heights();
    let alphas = distance_alphas(&heights);
    let levels = alphas
        .iter()
        .map(|&a| Alpha::try_new(a))
        .collect::<Result<Vec<_>, _>>()?;
    let samples = data::figure_samples(&job.model);
    let d = data::sampled_distances(&job.model, &levels, samples)?;
    let (what, over) = match data::surface_grid(&job.model) {
        Some([su, sv]) => (
            "surfaces",
            format!("‖D(u, v) − C(u, v)‖ over the {su} × {sv} grid of uniform (u, v)"),
        ),
        None => ("curves", format!("‖D(t) − C(t)‖ over {samples} uniform t")),
    };
    let inner: Vec<f64> = heights.iter().copied().filter(|&h| h < 1.0).collect();
    let mut p = Panel::graph("α", &format!("distance between the {what}"));
    let top = d.iter().map(|x| x[0]).fold(0.0, f64::max);
    p.x_range = Some([-0.02, 1.02]);
    p.y_range = Some([0.0, if top > 0.0 { 1.12 * top } else { 1.0 }]);
    for &h in &inner {
        p.push(
            format!("h-{}", short(h, 6)),
            Mark::VRule {
                x: h,
                stroke: Stroke::dashed(GREY, 1.0, "2 3"),
                label: format!("h = {}", short(h, 4)),
            },
        );
    }
    p.push("alpha", alpha_rule(alpha));
    series(
        &mut p,
        "max",
        &alphas,
        &d.iter().map(|x| x[0]).collect::<Vec<_>>(),
        &inner,
        &max_stroke(),
    );
    series(
        &mut p,
        "rms",
        &alphas,
        &d.iter().map(|x| x[1]).collect::<Vec<_>>(),
        &inner,
        &rms_stroke(),
    );
    let mut legend = vec![
        LegendEntry::line("max distance", max_stroke()),
        LegendEntry::line("rms distance", rms_stroke()),
    ];
    if !inner.is_empty() {
        legend.push(LegendEntry::marker(
            "value at α = h",
            Marker::filled(Shape::Circle, 6.0, BLACK),
        ));
        legend.push(LegendEntry::marker(
            "limit from above h",
            Marker::open(Shape::Circle, 6.0, BLACK),
        ));
    }
    Ok(Figure {
        notes: vec![format!(
            "Max and rms of {over} (t2spline run computes error.max and error.rms exactly)."
        )],
        ..Figure::new(
            "distance-alpha",
            format!(
                "Distance between the crisp and the defuzzified {} as α varies",
                &what[..what.len() - 1]
            ),
            "the paper's type reduction at α = 0, 0.01, …, 1 and both sides of every h, where it jumps",
            vec![p],
            legend,
        )
    })
}

/// The vertical line at the figure's alpha.
#[must_use]
pub fn alpha_rule(alpha: f64) -> Mark {
    Mark::VRule {
        x: alpha,
        stroke: Stroke::solid(INK, 0.9),
        label: format!("α = {}", short(alpha, 4)),
    }
}
