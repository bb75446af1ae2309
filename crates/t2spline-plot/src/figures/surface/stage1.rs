//! Stage 1 of a surface job: the fuzzy control net and the seven layer
//! surfaces.

use t2spline::job::Points;
use t2spline::Layer;

use super::bins::Bins;
use super::crisp::crisp_legend;
use super::crisp::SURFACE;
use super::mesh::Paint;
use super::points::distances;
use super::scene::SurfaceScene;
use crate::chart::scene::{Figure, LegendEntry};
use crate::figures::curve::weights_phrase;
use crate::figures::style::{layer_stroke, upper_band, FUNCTIONS};

/// Stage 1: the shaded crisp surface, the two upper layer surfaces as
/// translucent envelopes, the boundaries of the primary and lower layer
/// surfaces, the fuzzy control net (crisp points with bars for the upper,
/// primary and lower interval of each coordinate); beside it, the spread
/// between the upper layers `‖S_ur(u, v) − S_ul(u, v)‖` as a map.
#[must_use]
pub fn stage1_figure(scene: &SurfaceScene<'_>) -> Figure {
    let r = scene.r;
    let (s, cp) = (&r.samples, &r.control_points);
    let mut facets = scene.crisp_faces(Paint::Shaded(SURFACE));
    facets.extend(scene.envelopes(
        [
            (s.layer(Layer::UpperLeft), layer_stroke(Layer::UpperLeft)),
            (s.layer(Layer::UpperRight), layer_stroke(Layer::UpperRight)),
        ],
        &upper_band(),
    ));
    for l in [
        Layer::PrimaryLeft,
        Layer::PrimaryRight,
        Layer::LowerLeft,
        Layer::LowerRight,
    ] {
        facets.extend(scene.outline(s.layer(l), &layer_stroke(l)));
    }
    let view = scene.view_panel(facets, |p| {
        scene.crisp_net(p);
        let ends = |l: Layer| {
            let pts: &Points = cp.layers.get(l).unwrap_or(&cp.crisp);
            (0..3)
                .map(|k| pts.coord(k).iter().map(|&v| Some(v)).collect())
                .collect()
        };
        scene.bars(p, ends);
    });
    let spread = distances(s.layer(Layer::UpperRight), s.layer(Layer::UpperLeft));
    let bins = Bins::of(&spread);
    let map = scene.map_panel(
        "spread between the upper layers over (u, v)",
        &spread,
        &bins,
    );
    let mut legend = crisp_legend();
    for (l, _, name) in FUNCTIONS {
        legend.push(LegendEntry::line(
            &format!("{name} layer surfaces (boundaries)"),
            layer_stroke(l),
        ));
    }
    legend.push(LegendEntry::area(
        "envelope of the upper layer surfaces",
        upper_band(),
    ));
    let bars = if scene.bars_shown() {
        "; bars: upper ⊃ primary ⊃ lower interval of each coordinate"
    } else {
        ""
    };
    let orders = r.spline.orders();
    Figure {
        colorbar: Some(bins.colorbar("spread", vec![])),
        notes: scene.notes(),
        ..Figure::new(
            "stage1-fuzzy",
            "Stage 1: normal type-2 fuzzy rational B-spline surface",
            format!(
                "{} × {} control points, orders {} × {}, {}{bars}",
                scene.net[0],
                scene.net[1],
                orders.first().copied().unwrap_or(0),
                orders.get(1).copied().unwrap_or(0),
                weights_phrase(&r.spline.weights()),
            ),
            vec![view, map],
            legend,
        )
    }
}
