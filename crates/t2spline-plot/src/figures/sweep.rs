//! The defuzzified curve for alpha = 0, 0.1, …, 1, coloured by alpha.

use t2spline::job::Job;
use t2spline::{Alpha, TypeReduction};

use super::style::{crisp_marker, polygon_stroke};
use super::{curve_panels, project};
use crate::data;
use crate::scene::{ColorBar, Figure, LegendEntry, Mark};
use crate::style::{viridis, Stroke};
use crate::ticks::short;

/// The alphas of the sweep: 0, 0.1, …, 1.
#[must_use]
pub fn sweep_alphas() -> Vec<f64> {
    (0..=10).map(|i| f64::from(i) / 10.0).collect()
}

/// The `alpha-sweep` figure: one defuzzified curve of the paper's type
/// reduction (the one that uses alpha) per alpha of `sweep_alphas`, coloured by alpha (viridis) with a colour bar marking the
/// lower heights, where the solution jumps.
///
/// # Errors
/// [`crate::Error::Core`] if a run fails (never for a validated job).
pub fn sweep_figure(job: &Job) -> Result<crate::scene::Figure, crate::Error> {
    let alphas = sweep_alphas();
    let results = alphas
        .iter()
        // Values in [0, 1] are valid alphas.
        .filter_map(|&a| Alpha::try_new(a).ok())
        // Only the paper's reduction varies with alpha.
        .map(|a| data::compute_with(job, a, TypeReduction::Paper))
        .collect::<Result<Vec<_>, _>>()?;
    let Some(first) = results.first() else {
        return Err(crate::Error::Core(t2spline::Error::MissingAlpha));
    };
    let panels = curve_panels(first.dimension)
        .into_iter()
        .map(|(mut p, ij)| {
            p.push(
                "polygon",
                Mark::Line {
                    points: project(&first.control_points.crisp, ij),
                    stroke: polygon_stroke(),
                },
            );
            for (a, r) in alphas.iter().zip(&results) {
                p.push(
                    format!("curve-{}", short(*a, 2)),
                    Mark::Line {
                        points: project(&r.samples.defuzzified, ij),
                        stroke: Stroke::solid(viridis(*a), 1.5),
                    },
                );
            }
            p.push(
                "points-crisp",
                Mark::Markers {
                    points: project(&first.control_points.crisp, ij),
                    marker: crisp_marker(),
                },
            );
            p
        })
        .collect();
    let heights = job.model.heights();
    Ok(Figure {
        name: "alpha-sweep",
        title: "Defuzzified curve as alpha varies".into(),
        subtitle: format!(
            "the paper's reduction at α = 0, 0.1, …, 1 (α = 1 gives the crisp curve); the solution jumps at α = h ({})",
            heights
                .iter()
                .map(|h| short(*h, 4))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        panels,
        legend: vec![
            LegendEntry::line(
                "defuzzified curve (colour: α)",
                Stroke::solid(viridis(0.5), 1.5),
            ),
            LegendEntry::line_marker(
                "crisp control points and polygon",
                polygon_stroke(),
                crisp_marker(),
            ),
        ],
        colorbar: Some(ColorBar {
            label: "α".into(),
            stops: alphas.iter().map(|&a| (a, viridis(a))).collect(),
            marks: heights.iter().map(|&h| (h, "h".to_owned())).collect(),
        }),
    })
}
