//! Stage 2 of a surface job: the alpha-cut net and surfaces.

use t2spline::Layer;

use super::bins::Bins;
use super::crisp::crisp_legend;
use super::crisp::SURFACE;
use super::mesh::Paint;
use super::points::distances;
use super::scene::SurfaceScene;
use crate::chart::scene::{Figure, LegendEntry};
use crate::figures::curve::alpha_phrase;
use crate::figures::style::{layer_stroke, upper_band, FUNCTIONS};

/// Stage 2: the shaded crisp surface, the upper cut surfaces as translucent
/// envelopes, the boundaries of the primary and (where every number has one)
/// lower cut surfaces, bars for the cut intervals of every control point;
/// beside it, the width of the upper cut `‖S_ur,α − S_ul,α‖` as a map.
#[must_use]
pub fn stage2_figure(scene: &SurfaceScene<'_>) -> Figure {
    let r = scene.r;
    let (s, cp) = (&r.samples, &r.control_points);
    let cut = |l: Layer| s.alpha_cut.get(l).and_then(Option::as_ref);
    let mut facets = scene.crisp_faces(Paint::Shaded(SURFACE));
    if let (Some(ul), Some(ur)) = (cut(Layer::UpperLeft), cut(Layer::UpperRight)) {
        facets.extend(scene.envelopes(
            [
                (ul, layer_stroke(Layer::UpperLeft)),
                (ur, layer_stroke(Layer::UpperRight)),
            ],
            &upper_band(),
        ));
    }
    for l in [
        Layer::PrimaryLeft,
        Layer::PrimaryRight,
        Layer::LowerLeft,
        Layer::LowerRight,
    ] {
        if let Some(c) = cut(l) {
            facets.extend(scene.outline(c, &layer_stroke(l)));
        }
    }
    let view = scene.view_panel(facets, |p| {
        scene.crisp_net(p);
        scene.bars(p, |l| {
            cp.alpha_cut
                .get(l)
                .map(|pts| (0..3).map(|k| pts.coord(k).to_vec()).collect())
                .unwrap_or_default()
        });
    });
    let width = match (cut(Layer::UpperLeft), cut(Layer::UpperRight)) {
        (Some(ul), Some(ur)) => distances(ur, ul),
        _ => vec![0.0; s.crisp.len()],
    };
    let bins = Bins::of(&width);
    let map = scene.map_panel("width of the upper cut over (u, v)", &width, &bins);
    let mut legend = crisp_legend();
    for (l, _, name) in FUNCTIONS {
        legend.push(LegendEntry::line(
            &format!("{name} cut surfaces (boundaries)"),
            layer_stroke(l),
        ));
    }
    legend.push(LegendEntry::area(
        "envelope of the upper cut surfaces",
        upper_band(),
    ));
    Figure {
        colorbar: Some(bins.colorbar("width", vec![])),
        notes: scene.notes(),
        ..Figure::new(
            "stage2-alpha-cut",
            "Stage 2: α-cut of the control net",
            format!(
                "{}; lower cut surfaces drawn where every number has a lower cut",
                alpha_phrase(r, scene.heights)
            ),
            vec![view, map],
            legend,
        )
    }
}
