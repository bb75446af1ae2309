//! Stage 1 (paper Fig. 5.1): the fuzzy control points and the seven layer
//! curves.

use t2spline::job::{Points, RunOutput};
use t2spline::Layer;

use super::{
    band, crisp_legend, crisp_points, names, point_name, polygon, project, weights_phrase,
    CurveScene,
};
use crate::figures::style::{layer_stroke, lower_band, upper_band, FUNCTIONS};
use crate::scene::{Figure, LegendEntry, Mark, Panel};
use crate::style::{Stroke, BLUE, GREEN, VERMILLION};

/// Stage 1 (paper Fig. 5.1): the fuzzy control points — the crisp point with
/// bars for its upper, primary and lower interval in each coordinate — the
/// control polygon, the seven layer curves, and the bands between the upper
/// layers (light) and between the lower layers (darker).
#[must_use]
pub fn stage1_figure(scene: &CurveScene<'_>) -> Figure {
    let r = scene.r;
    let (c, cp) = (&r.samples, &r.control_points);
    let d = &scene.density;
    let panels = scene.panels(|p, ij| {
        bands(p, r, ij);
        polygon(p, &cp.crisp, ij);
        if d.markers {
            bars(p, r, ij);
        }
        for l in Layer::ALL {
            p.push(
                format!("curve-{}", l.name()),
                Mark::Line {
                    points: project(c.layer(l), ij),
                    stroke: layer_stroke(l),
                },
            );
        }
        crisp_points(p, &cp.crisp, ij, d);
        names(p, &cp.crisp, ij, d, point_name);
    });
    let mut legend = crisp_legend();
    for (l, _, name) in FUNCTIONS {
        legend.push(LegendEntry::line(
            &format!("{name} layers (left, right)"),
            layer_stroke(l),
        ));
    }
    legend.push(LegendEntry::area("between the upper layers", upper_band()));
    legend.push(LegendEntry::area("between the lower layers", lower_band()));
    let bars_phrase = if d.markers {
        "; bars: upper ⊃ primary ⊃ lower interval of each coordinate"
    } else {
        ""
    };
    Figure {
        notes: scene.notes(Some("no interval bars")),
        ..Figure::new(
            "stage1-fuzzy",
            "Stage 1: normal type-2 fuzzy rational B-spline curve",
            format!(
                "order {}, {}{bars_phrase}",
                crate::data::curve_spline(r).order,
                weights_phrase(crate::data::curve_spline(r).weights)
            ),
            panels,
            legend,
        )
    }
}

/// The bands between the upper and between the lower layer curves.
fn bands(p: &mut Panel, r: &RunOutput, ij: (usize, usize)) {
    let l = &r.samples.layers;
    p.push(
        "band-upper",
        Mark::Area {
            points: band(&l.upper_left, &l.upper_right, ij),
            fill: upper_band(),
        },
    );
    p.push(
        "band-lower",
        Mark::Area {
            points: band(&l.lower_left, &l.lower_right, ij),
            fill: lower_band(),
        },
    );
}

/// Through each crisp control point, a bar per function and coordinate from
/// its left to its right end (thinner for wider intervals, so all show).
fn bars(p: &mut Panel, r: &RunOutput, (i, j): (usize, usize)) {
    let cp = &r.control_points;
    let layer = |l: Layer| cp.layers.get(l).unwrap_or(&cp.crisp);
    for ((left, right, name), (color, width)) in
        FUNCTIONS
            .iter()
            .zip([(BLUE, 1.2), (GREEN, 2.6), (VERMILLION, 4.4)])
    {
        let coords = |pts: &Points| [pts.coord(i).to_vec(), pts.coord(j).to_vec()];
        let (lo, hi, mid) = (
            coords(layer(*left)),
            coords(layer(*right)),
            coords(&cp.crisp),
        );
        let segments = (0..mid[0].len())
            .flat_map(|k| {
                [
                    [[lo[0][k], mid[1][k]], [hi[0][k], mid[1][k]]],
                    [[mid[0][k], lo[1][k]], [mid[0][k], hi[1][k]]],
                ]
            })
            .collect();
        p.push(
            format!("bars-{name}"),
            Mark::Segments {
                segments,
                stroke: Stroke::solid(color, width),
            },
        );
    }
}
