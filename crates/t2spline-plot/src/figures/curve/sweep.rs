//! The distance between the defuzzified and the crisp curve along the
//! curve, `‖D(t) − C(t)‖`, for several alphas: how far and where the
//! solution moves, and its jump at every lower height h. Each alpha has its
//! own lightness (viridis, dark to light as alpha grows, without its pale
//! yellow end) and its regime its own dash, so the lines stay apart in grey.

use t2spline::job::Job;
use t2spline::Alpha;

use crate::chart::paint::{viridis, Stroke};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel};
use crate::chart::ticks::short;
use crate::data::{self, figure_samples, just_above};

/// The most lower heights that get their two sides drawn.
const MAX_HEIGHTS: usize = 3;

/// The alphas of the sweep: 0, 0.25, 0.5, 0.75 (without those within 0.04
/// of a height), and each of the first heights h and the next float above
/// it; as `(alpha, label)`.
fn sweep_alphas(heights: &[f64]) -> Vec<(f64, String)> {
    let hs: Vec<f64> = heights
        .iter()
        .copied()
        .filter(|&h| h < 1.0)
        .take(MAX_HEIGHTS)
        .collect();
    let mut v: Vec<(f64, String)> = [0.0, 0.25, 0.5, 0.75]
        .into_iter()
        .filter(|a| hs.iter().all(|h| (a - h).abs() > 0.04))
        .map(|a| (a, format!("α = {}", short(a, 4))))
        .collect();
    for &h in &hs {
        v.push((h, format!("α = h = {}", short(h, 4))));
        if let Some(a) = just_above(h) {
            v.push((a, format!("α just above h = {}", short(h, 4))));
        }
    }
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    v
}

/// The line style of the `k`-th of `n` alphas, dashed above the lowest height
/// and dotted above the highest.
fn stroke(k: usize, n: usize, alpha: f64, heights: &[f64]) -> Stroke {
    let color = viridis(0.85 * k as f64 / (n.max(2) - 1) as f64);
    let below = heights.iter().filter(|&&h| h < alpha).count();
    match below {
        0 => Stroke::solid(color, 1.9),
        b if b == heights.len() => Stroke::dashed(color, 1.9, "7 3"),
        _ => Stroke::dashed(color, 1.9, "7 3 2 3"),
    }
}

/// The `alpha-sweep` figure: `‖D(t) − C(t)‖` against t for the alphas of
/// [`sweep_alphas`], from one sampling sweep of the library, always with
/// the paper's type reduction (the one that uses alpha; docs/method.md §9).
///
/// # Errors
/// [`crate::Error::Core`] if sampling fails (never for a validated job).
pub fn sweep_figure(job: &Job) -> Result<Figure, crate::error::Error> {
    let heights: Vec<f64> = job.model.heights();
    let chosen = sweep_alphas(&heights);
    let levels = chosen
        .iter()
        .map(|(a, _)| Alpha::try_new(*a))
        .collect::<Result<Vec<_>, _>>()?;
    let (params, along) = data::distance_along(&job.model, &levels, figure_samples(&job.model))?;
    let top = along.iter().flatten().copied().fold(0.0, f64::max);
    let mut p = Panel::graph("t", "‖D(t) − C(t)‖");
    p.y_range = Some([0.0, if top > 0.0 { 1.08 * top } else { 1.0 }]);
    let mut legend = Vec::new();
    for (k, ((a, label), d)) in chosen.iter().zip(&along).enumerate() {
        let s = stroke(k, chosen.len(), *a, &heights);
        p.push(
            format!("curve-{k}"),
            Mark::Line {
                points: params.iter().zip(d).map(|(&t, &v)| [t, v]).collect(),
                stroke: s.clone(),
            },
        );
        legend.push(LegendEntry::line(label, s));
    }
    Ok(Figure::new(
        "alpha-sweep",
        "Distance from the crisp curve along t, as α varies",
        "the paper's type reduction: ‖D(t) − C(t)‖ at equal t, dashed above h; at α = 1 the distance is 0",
        vec![p],
        legend,
    ))
}
