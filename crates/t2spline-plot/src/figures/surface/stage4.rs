//! Stage 4 of a surface job: the crisp surface coloured by its distance to
//! the defuzzified one, and the largest distance.

use t2spline::job::{Job, Parameter};
use t2spline::Alpha;

use super::bins::Bins;
use super::mesh::Paint;
use super::points::distances;
use super::scene::SurfaceScene;
use crate::chart::paint::{Marker, Shape, BLACK};
use crate::chart::scene::{Figure, LegendEntry, Mark, Priority, Xy};
use crate::chart::ticks::short;
use crate::data;
use crate::error::Error;
use crate::figures::curve::{largest_distance, reduction_phrase};
use crate::figures::style::{
    distance_marker, distance_stroke, polygon_stroke, solution_marker, solution_stroke,
};

/// Stage 4: the crisp surface coloured by `‖D(u, v) − C(u, v)‖` (the
/// distance to the defuzzified surface at equal parameters, lightly shaded),
/// the defuzzified surface's boundary and control points, and the largest
/// distance `error.max` at `error.max_at` marked by the segment between the
/// two surfaces there; beside it, the distance as a map over `(u, v)` with
/// `max_at` marked. One colour bar serves both.
///
/// # Errors
/// Only if the library cannot evaluate a surface at the result's `max_at`,
/// which lies in the domain by construction.
pub fn stage4_figure(job: &Job, scene: &SurfaceScene<'_>) -> Result<Figure, Error> {
    let r = scene.r;
    let (s, cp, e) = (&r.samples, &r.control_points, &r.error);
    let uv = match e.max_at {
        Parameter::Uv(uv) => uv,
        Parameter::T(t) => [t, f64::NAN],
    };
    let [crisp_end, solution_end] =
        data::surfaces_at(&job.model, Alpha::try_new(r.alpha)?, r.type_reduction, uv)?;
    let d = distances(&s.defuzzified, &s.crisp);
    let bins = Bins {
        max: e.max.max(Bins::of(&d).max),
    };
    let colour = |v: f64| bins.colour(v);
    let mut facets = scene.crisp_faces(Paint::Values(&d, &colour));
    facets.extend(scene.outline(&s.defuzzified, &solution_stroke()));
    let at = format!("(u, v) = ({}, {})", short(uv[0], 4), short(uv[1], 4));
    let ends: [Xy; 2] = [crisp_end, solution_end].map(|p| {
        scene.camera.project(std::array::from_fn(|k| {
            p.get(k).copied().unwrap_or(f64::NAN)
        }))
    });
    let text = format!("max distance {} at {at}", short(e.max, 4));
    let view = scene.view_panel(facets, |p| {
        p.push(
            "net-defuzzified",
            Mark::Segments {
                segments: scene.net_segments(&cp.defuzzified),
                stroke: polygon_stroke(),
            },
        );
        let mut marker = solution_marker();
        if !scene.bars_shown() {
            marker.size = 3.5;
        }
        p.push(
            "points-defuzzified",
            Mark::Markers {
                points: scene.projected(&cp.defuzzified),
                marker,
            },
        );
        largest_distance(p, ends, Some(text.clone()));
    });
    let mut map = scene.map_panel("distance over (u, v)", &d, &bins);
    map.push(
        "max-at",
        Mark::Markers {
            points: vec![uv],
            marker: max_marker(),
        },
    );
    map.push(
        "max-at-text",
        Mark::Label {
            anchor: uv,
            text: format!("max at {at}"),
            priority: Priority::Always,
        },
    );
    let legend = vec![
        LegendEntry::area(
            "crisp surface, coloured by its distance to the defuzzified one",
            crate::chart::paint::Fill {
                color: bins.colour(0.5 * bins.max),
                opacity: 1.0,
            },
        ),
        LegendEntry::line_marker(
            "defuzzified surface (boundary), control net and points",
            solution_stroke(),
            solution_marker(),
        ),
        LegendEntry::line_marker(
            "largest distance at equal (u, v)",
            distance_stroke(),
            distance_marker(),
        ),
        LegendEntry::marker("where the distance is largest", max_marker()),
    ];
    Ok(Figure {
        colorbar: Some(bins.colorbar("‖D − C‖", vec![(e.max, "max".to_owned())])),
        notes: scene.notes(),
        ..Figure::new(
            "stage4-defuzzified",
            "Stage 4: crisp type-2 solution surface",
            format!(
                "{}: max distance {} at {at}, rms distance {}",
                reduction_phrase(r),
                short(e.max, 4),
                short(e.rms, 4)
            ),
            vec![view, map],
            legend,
        )
    })
}

/// The marker of `max_at` on the map.
fn max_marker() -> Marker {
    Marker::filled(Shape::Cross, 11.0, BLACK)
}
