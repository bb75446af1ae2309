//! Stage 1 (paper Fig. 5.1): the fuzzy control points and the seven layer
//! curves.

use t2spline::job::{Points, RunOutput};
use t2spline::Layer;

use super::phrases::{point_name, weights_phrase};
use super::projection::project;
use super::scene::CurveScene;
use super::series::{crisp_legend, crisp_points, names, polygon, regions, regions_legend};
use crate::chart::paint::{Stroke, BLUE, GREEN, VERMILLION};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel};
use crate::figures::style::{layer_stroke, FUNCTIONS};
use crate::set_view::Regions;

/// Stage 1 (paper Fig. 5.1): the fuzzy control points — the crisp point with
/// bars for its upper, primary and lower interval in each coordinate — the
/// control polygon, the seven layer curves, and the regions the curve can
/// occupy at level 0 (`zero`, from the core's set view, docs/method.md §10):
/// the upper function's (light) and the lower's (darker). A layer curve is
/// not a boundary of the region: at each t the curve can be anywhere in the
/// box whose corners lie on the layer curves.
#[must_use]
pub fn stage1_figure(scene: &CurveScene<'_>, zero: &Regions) -> Figure {
    let r = scene.r;
    let (c, cp) = (&r.samples, &r.control_points);
    let d = &scene.density;
    let mut k = 0;
    let panels = scene.panels(|p, ij| {
        regions(p, zero, k);
        k += 1;
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
    legend.extend(regions_legend(zero, "α = 0"));
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
