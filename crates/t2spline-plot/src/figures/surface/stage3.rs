//! Stage 3 of a surface job: the type-reduced left and right surfaces.

use super::bins::Bins;
use super::crisp::crisp_legend;
use super::crisp::SURFACE;
use super::mesh::Paint;
use super::points::distances;
use super::scene::SurfaceScene;
use crate::chart::scene::{Figure, LegendEntry, Mark};
use crate::figures::curve::alpha_phrase;
use crate::figures::style::{left_marker, left_stroke, reduced_band, right_marker, right_stroke};

/// Stage 3: the shaded crisp surface, the type-reduced left and right
/// surfaces as translucent envelopes with their control points; beside it,
/// their distance `‖S_r − S_l‖` as a map.
#[must_use]
pub fn stage3_figure(scene: &SurfaceScene<'_>) -> Figure {
    let r = scene.r;
    let (s, cp) = (&r.samples, &r.control_points);
    let mut facets = scene.crisp_faces(Paint::Shaded(SURFACE));
    facets.extend(scene.envelopes(
        [
            (&s.type_reduced.left, left_stroke()),
            (&s.type_reduced.right, right_stroke()),
        ],
        &reduced_band(),
    ));
    let view = scene.view_panel(facets, |p| {
        scene.crisp_net(p);
        for (key, pts, marker) in [
            ("points-left", &cp.type_reduced_left, left_marker()),
            ("points-right", &cp.type_reduced_right, right_marker()),
        ] {
            let mut marker = marker;
            if !scene.bars_shown() {
                marker.size = 3.5;
            }
            p.push(
                key,
                Mark::Markers {
                    points: scene.projected(pts),
                    marker,
                },
            );
        }
    });
    let width = distances(&s.type_reduced.right, &s.type_reduced.left);
    let bins = Bins::of(&width);
    let map = scene.map_panel("distance between right and left over (u, v)", &width, &bins);
    let mut legend = crisp_legend();
    legend.push(LegendEntry::line_marker(
        "type-reduced left surface and points",
        left_stroke(),
        left_marker(),
    ));
    legend.push(LegendEntry::line_marker(
        "type-reduced right surface and points",
        right_stroke(),
        right_marker(),
    ));
    legend.push(LegendEntry::area("between left and right", reduced_band()));
    Figure {
        colorbar: Some(bins.colorbar("‖R − L‖", vec![])),
        notes: scene.notes(),
        ..Figure::new(
            "stage3-type-reduced",
            "Stage 3: type-reduced surfaces",
            alpha_phrase(r, scene.heights),
            vec![view, map],
            legend,
        )
    }
}
