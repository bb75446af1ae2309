//! Stage 3 (paper Fig. 5.3): the type-reduced control points and curves.

use t2spline::job::RunOutput;

use super::phrases::{alpha_phrase, point_name};
use super::projection::{band, project};
use super::scene::CurveScene;
use super::series::{crisp_curve, crisp_points, line, markers, names, polygon};
use crate::chart::paint::{Stroke, GREY};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel};
use crate::chart::ticks::short;
use crate::figures::style::{
    crisp_marker, crisp_stroke, left_marker, left_stroke, reduced_band, right_marker, right_stroke,
};

/// The thin line from a type-reduced left point through the crisp point to
/// the right point: one type-1 triangle.
fn spread_stroke() -> Stroke {
    Stroke::solid(GREY, 1.0)
}

/// Stage 3 (paper Fig. 5.3): the type-reduced control points — each a type-1
/// triangle (left, crisp, right) labelled with its weight — and the curves
/// through the left and the right values, each in its own colour and dash.
#[must_use]
pub fn stage3_figure(scene: &CurveScene<'_>) -> Figure {
    let r = scene.r;
    let (c, cp) = (&r.samples, &r.control_points);
    let d = &scene.density;
    let panels = scene.panels(|p, ij| {
        p.push(
            "band",
            Mark::Area {
                points: band(&c.type_reduced.left, &c.type_reduced.right, ij),
                fill: reduced_band(),
            },
        );
        polygon(p, &cp.crisp, ij);
        spreads(p, r, ij, d.markers);
        line(
            p,
            "curve-left",
            Some(project(&c.type_reduced.left, ij)),
            left_stroke(),
        );
        line(
            p,
            "curve-right",
            Some(project(&c.type_reduced.right, ij)),
            right_stroke(),
        );
        crisp_curve(p, &c.crisp, ij);
        markers(
            p,
            "points-left",
            project(&cp.type_reduced_left, ij),
            left_marker(),
            d.markers,
        );
        markers(
            p,
            "points-right",
            project(&cp.type_reduced_right, ij),
            right_marker(),
            d.markers,
        );
        crisp_points(p, &cp.crisp, ij, d);
        names(p, &cp.crisp, ij, d, |k| {
            format!(
                "{}, w = {}",
                point_name(k),
                short(
                    crate::data::curve_spline(r)
                        .weights
                        .get(k)
                        .copied()
                        .unwrap_or(f64::NAN),
                    4
                )
            )
        });
    });
    let with = |s: &str| {
        if d.markers {
            format!("{s} and points")
        } else {
            s.to_owned()
        }
    };
    let mut legend = vec![
        LegendEntry::line_marker(
            "crisp curve and control points",
            crisp_stroke(),
            crisp_marker(),
        ),
        LegendEntry::line_maybe_marker(
            &with("type-reduced left curve"),
            left_stroke(),
            d.markers.then(left_marker),
        ),
        LegendEntry::line_maybe_marker(
            &with("type-reduced right curve"),
            right_stroke(),
            d.markers.then(right_marker),
        ),
    ];
    if d.markers {
        legend.push(LegendEntry::line(
            "type-1 control point: left–crisp–right",
            spread_stroke(),
        ));
    }
    legend.push(LegendEntry::area(
        "between left and right curves",
        reduced_band(),
    ));
    Figure {
        notes: scene.notes(Some("type-reduced points not marked")),
        ..Figure::new(
            "stage3-type-reduced",
            "Stage 3: type reduction (TR-α-NT2FRBsC)",
            alpha_phrase(r, scene.heights),
            panels,
            legend,
        )
    }
}

/// Each control point's type-1 triangle as two segments, left–crisp–right.
fn spreads(p: &mut Panel, r: &RunOutput, ij: (usize, usize), shown: bool) {
    let cp = &r.control_points;
    let (l, m, rr) = (
        project(&cp.type_reduced_left, ij),
        project(&cp.crisp, ij),
        project(&cp.type_reduced_right, ij),
    );
    let mark = if shown {
        Mark::Segments {
            segments: (0..m.len())
                .flat_map(|k| [[l[k], m[k]], [m[k], rr[k]]])
                .collect(),
            stroke: spread_stroke(),
        }
    } else {
        Mark::Empty
    };
    p.push("spreads", mark);
}
