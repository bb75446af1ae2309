//! Stage 4 (paper Fig. 5.4): the crisp and the defuzzified curve, and the
//! largest distance between them.

use t2spline::job::Job;

use super::largest::{largest_distance, Ends};
use super::phrases::reduction_phrase;
use super::projection::project;
use super::scene::CurveScene;
use super::series::{crisp_curve, crisp_legend, crisp_points, line, markers, polygon};
use super::zoom::zoom_panel;
use crate::chart::scene::{Figure, LegendEntry};
use crate::chart::ticks::short;
use crate::data;
use crate::error::Error;
use crate::figures::style::{distance_marker, distance_stroke, solution_marker, solution_stroke};

/// Whether stage 4 gets a panel magnifying the largest distance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Zoom {
    /// A magnified panel when the curves are apart (`error.max > 0`).
    WhereApart,
    /// Always a magnified panel; where the curves coincide it says so (the
    /// report, whose figures keep one structure at every alpha).
    Always,
}

/// Stage 4 (paper Fig. 5.4): the crisp curve and the defuzzified solution
/// curve with their control points, and the largest distance between them
/// marked and annotated; `zoom` adds a panel magnifying it, with the curves
/// computed anew on the magnified stretch.
///
/// # Errors
/// Only if the library cannot evaluate a curve at the result's `max_at`, which
/// lies in the domain by construction.
pub fn stage4_figure(job: &Job, scene: &CurveScene<'_>, zoom: Zoom) -> Result<Figure, Error> {
    let r = scene.r;
    let (c, cp, e) = (&r.samples, &r.control_points, &r.error);
    let ends = Ends::of(job, r)?;
    let d = &scene.density;
    let first = scene.projections.first().map(|p| p.axes);
    let mut panels = scene.panels(|p, ij| {
        polygon(p, &cp.crisp, ij);
        crisp_curve(p, &c.crisp, ij);
        line(
            p,
            "curve-defuzzified",
            Some(project(&c.defuzzified, ij)),
            solution_stroke(),
        );
        crisp_points(p, &cp.crisp, ij, d);
        markers(
            p,
            "points-defuzzified",
            project(&cp.defuzzified, ij),
            solution_marker(),
            d.markers,
        );
        let text = (Some(ij) == first).then(|| {
            format!(
                "max distance {} at t = {}",
                short(e.max, 4),
                short(data::curve_spline(r).max_at, 4)
            )
        });
        largest_distance(p, ends.projected(ij), text);
    });
    let zoomed = match zoom {
        Zoom::WhereApart => e.max > 0.0,
        Zoom::Always => true,
    };
    if zoomed {
        panels.push(zoom_panel(job, r, &ends)?);
    }
    let mut legend = crisp_legend();
    legend.push(LegendEntry::line_maybe_marker(
        if d.markers {
            "defuzzified curve and control points"
        } else {
            "defuzzified curve"
        },
        solution_stroke(),
        d.markers.then(solution_marker),
    ));
    legend.push(LegendEntry::line_marker(
        "largest distance at equal t",
        distance_stroke(),
        distance_marker(),
    ));
    Ok(Figure {
        notes: scene.notes(Some("defuzzified points not marked")),
        ..Figure::new(
            "stage4-defuzzified",
            "Stage 4: crisp type-2 solution curve (D-TR-α-NT2FRBsC)",
            format!(
                "{}: max distance {} at t = {}, rms distance {}",
                reduction_phrase(r),
                short(e.max, 4),
                short(data::curve_spline(r).max_at, 4),
                short(e.rms, 4)
            ),
            panels,
            legend,
        )
    })
}
