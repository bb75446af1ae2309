//! Stage 4 (paper Fig. 5.4): the crisp and the defuzzified curve, and the
//! largest distance between them.

use t2spline::job::{Job, RunOutput};
use t2spline::Alpha;

use super::zoom::zoom_panel;
use super::{
    crisp_curve, crisp_legend, crisp_points, line, markers, polygon, project, reduction_phrase,
    CurveScene,
};
use crate::figures::style::{distance_marker, distance_stroke, solution_marker, solution_stroke};
use crate::scene::{Figure, LegendEntry, Mark, Panel, Priority, Xy};
use crate::ticks::short;
use crate::{data, Error};

/// Whether stage 4 gets a panel magnifying the largest distance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Zoom {
    /// A magnified panel when the curves are apart (`error.max > 0`).
    WhereApart,
    /// Always a magnified panel; where the curves coincide it says so (the
    /// report, whose figures keep one structure at every alpha).
    Always,
}

/// The two ends of the largest distance: the crisp and the defuzzified curve
/// at `max_at`, by the library.
pub(super) struct Ends {
    pub crisp: Vec<f64>,
    pub solution: Vec<f64>,
}

impl Ends {
    fn of(job: &Job, r: &RunOutput) -> Result<Ends, Error> {
        let (c, d) = data::curves_at(
            &job.model,
            Alpha::try_new(r.alpha)?,
            r.type_reduction,
            &[data::curve_spline(r).max_at],
        )?;
        Ok(Ends {
            crisp: c.point(0).unwrap_or_default(),
            solution: d.point(0).unwrap_or_default(),
        })
    }

    pub fn projected(&self, (i, j): (usize, usize)) -> [Xy; 2] {
        [
            [self.crisp[i], self.crisp[j]],
            [self.solution[i], self.solution[j]],
        ]
    }
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

/// The segment between the two ends of the largest distance, its end
/// markers, and (with `text`) its annotation, which is always placed.
pub fn largest_distance(p: &mut Panel, ends: [Xy; 2], text: Option<String>) {
    p.push(
        "distance",
        Mark::Segments {
            segments: vec![ends],
            stroke: distance_stroke(),
        },
    );
    p.push(
        "distance-ends",
        Mark::Markers {
            points: ends.to_vec(),
            marker: distance_marker(),
        },
    );
    let mid = [
        0.5 * (ends[0][0] + ends[1][0]),
        0.5 * (ends[0][1] + ends[1][1]),
    ];
    p.push(
        "distance-text",
        text.map_or(Mark::Empty, |text| Mark::Label {
            anchor: mid,
            text,
            priority: Priority::Always,
        }),
    );
}
