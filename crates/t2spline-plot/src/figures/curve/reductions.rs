//! The type reductions side by side (docs/method.md §9): the solution curve of every
//! reduction beside the crisp curve, and each one's distance to it along the
//! curve, with the distance's maximum and root mean square in the legend.

use t2spline::job::{Job, RunOutput};
use t2spline::{Alpha, TypeReduction};

use super::projection::project;
use super::scene::CurveScene;
use super::series::{crisp_curve, crisp_legend, crisp_points, line, polygon};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel, Xy};
use crate::chart::ticks::short;
use crate::data;
use crate::error::Error;
use crate::figures::aspect::Aspect;
use crate::figures::style::{reduction_label, reduction_marker, reduction_stroke};

/// `paper (α = 0.8)` or `centroid (Karnik–Mendel)`: a reduction with the
/// level it used, if any.
fn with_level(r: &RunOutput) -> String {
    if r.alpha_used {
        format!(
            "{} (α = {})",
            reduction_label(r.type_reduction),
            short(r.alpha, 4)
        )
    } else {
        reduction_label(r.type_reduction).to_owned()
    }
}

/// The `reductions` figure: the crisp curve and the solution curve of every
/// type reduction (the paper's at `alpha`; the others do not use alpha) in
/// each projection, and a panel of each solution's distance to the crisp
/// curve at equal t, its largest value marked. The legend gives each
/// reduction's distance, max and rms, as `t2spline run --type-reduction`
/// reports them.
///
/// # Errors
/// [`Error::Surface`] for a surface job; [`Error::Core`] if a run fails
/// (never for a validated curve job).
pub fn reductions_figure(job: &Job, alpha: Alpha, aspect: Aspect) -> Result<Figure, Error> {
    let results = TypeReduction::ALL
        .into_iter()
        .map(|m| data::compute_with(job, alpha, m))
        .collect::<Result<Vec<RunOutput>, Error>>()?;
    let heights = job.model.heights();
    // Every result has the same crisp curve and control points.
    let scene = CurveScene::new(&results[0], &heights, aspect);
    let (c, cp) = (&scene.r.samples, &scene.r.control_points);
    let mut panels = scene.panels(|p, ij| {
        polygon(p, &cp.crisp, ij);
        crisp_curve(p, &c.crisp, ij);
        for r in &results {
            line(
                p,
                format!("curve-{}", r.type_reduction.name()),
                Some(project(&r.samples.defuzzified, ij)),
                reduction_stroke(r.type_reduction),
            );
        }
        crisp_points(p, &cp.crisp, ij, &scene.density);
    });
    panels.push(distance_panel(&results));
    let mut legend = crisp_legend();
    legend.extend(results.iter().map(|r| {
        LegendEntry::line_marker(
            &format!(
                "{}: max {}, rms {}",
                with_level(r),
                short(r.error.max, 4),
                short(r.error.rms, 4)
            ),
            reduction_stroke(r.type_reduction),
            reduction_marker(r.type_reduction),
        )
    }));
    Ok(Figure {
        notes: scene.notes(None),
        ..Figure::new(
            "reductions",
            "Solution curve of every type reduction",
            format!(
                "defuzzified curves and their distance to the crisp curve at equal t; only the paper's reduction uses α (here {})",
                short(alpha.get(), 4)
            ),
            panels,
            legend,
        )
    })
}

/// `‖D(t) − C(t)‖` at the sample parameters for every reduction, the
/// largest distance (from the run, not the samples) marked at its `t`.
fn distance_panel(results: &[RunOutput]) -> Panel {
    let mut p = Panel::graph("t", "‖D(t) − C(t)‖");
    p.title = Some("distance to the crisp curve".into());
    let top = results.iter().map(|r| r.error.max).fold(0.0, f64::max);
    p.y_range = Some([0.0, if top > 0.0 { 1.08 * top } else { 1.0 }]);
    for r in results {
        let (c, d) = (&r.samples.crisp, &r.samples.defuzzified);
        let points: Vec<Xy> = r
            .samples
            .params
            .along()
            .iter()
            .enumerate()
            .map(|(k, &t)| [t, d.distance_at(c, k).unwrap_or(f64::NAN)])
            .collect();
        line(
            &mut p,
            format!("distance-{}", r.type_reduction.name()),
            Some(points),
            reduction_stroke(r.type_reduction),
        );
    }
    for r in results {
        p.push(
            format!("max-{}", r.type_reduction.name()),
            Mark::Markers {
                points: vec![[data::curve_spline(r).max_at, r.error.max]],
                marker: reduction_marker(r.type_reduction),
            },
        );
    }
    p
}
