//! The four stages of Algorithm 1.1 as figures (paper Figs. 5.1–5.4).

use t2spline::job::Points;
use t2spline::job::{Job, RunOutput};
use t2spline::Layer;

use super::style::{
    crisp_marker, crisp_stroke, layer_marker, layer_stroke, lower_band, polygon_stroke,
    reduced_band, reduced_stroke, solution_marker, solution_stroke, upper_band,
};
use super::{alpha_phrase, band, curve_panels, point_name, project, reduction_phrase};
use crate::scene::{Figure, LegendEntry, Mark, Panel};
use crate::style::{Marker, Shape, Stroke, BLACK, BLUE, GREEN, GREY, PURPLE, VERMILLION};
use crate::ticks::short;
use crate::{data, Error};

/// The layers of one function, for legends: (left, right, name).
const FUNCTIONS: [(Layer, Layer, &str); 3] = [
    (Layer::UpperLeft, Layer::UpperRight, "upper"),
    (Layer::PrimaryLeft, Layer::PrimaryRight, "primary"),
    (Layer::LowerLeft, Layer::LowerRight, "lower"),
];

fn figure(
    name: &'static str,
    title: &str,
    subtitle: String,
    panels: Vec<Panel>,
    legend: Vec<LegendEntry>,
) -> Figure {
    Figure {
        name,
        title: title.to_owned(),
        subtitle,
        panels,
        legend,
        colorbar: None,
    }
}

fn name_labels(p: &mut Panel, points: &Points, ij: (usize, usize), text: impl Fn(usize) -> String) {
    for (k, xy) in project(points, ij).into_iter().enumerate() {
        p.push(
            format!("name-{k}"),
            Mark::Label {
                anchor: xy,
                text: text(k),
            },
        );
    }
}

/// Stage 1 (paper Fig. 5.1): the fuzzy control points — the crisp point with
/// bars for its upper, primary and lower interval in each coordinate — the
/// control polygon, the seven layer curves, and the bands between the upper
/// layers (light) and between the lower layers (darker).
#[must_use]
pub fn stage1_figure(r: &RunOutput) -> Figure {
    let (c, cp) = (&r.samples, &r.control_points);
    let layer_curve = |l: Layer| c.layers.get(l).unwrap_or(&c.crisp);
    let layer_points = |l: Layer| cp.layers.get(l).unwrap_or(&cp.crisp);
    let panels = curve_panels(r.dimension)
        .into_iter()
        .map(|(mut p, ij)| {
            p.push(
                "band-upper",
                Mark::Area {
                    points: band(&c.layers.upper_left, &c.layers.upper_right, ij),
                    fill: upper_band(),
                },
            );
            p.push(
                "band-lower",
                Mark::Area {
                    points: band(&c.layers.lower_left, &c.layers.lower_right, ij),
                    fill: lower_band(),
                },
            );
            p.push(
                "polygon",
                Mark::Line {
                    points: project(&cp.crisp, ij),
                    stroke: polygon_stroke(),
                },
            );
            for ((left, right, name), (color, width)) in
                FUNCTIONS
                    .iter()
                    .zip([(BLUE, 1.2), (GREEN, 2.6), (VERMILLION, 4.4)])
            {
                let (lo, hi, mid) = (layer_points(*left), layer_points(*right), &cp.crisp);
                let (i, j) = ij;
                let (lo, hi, mid) = (
                    [lo.coord(i), lo.coord(j)],
                    [hi.coord(i), hi.coord(j)],
                    [mid.coord(i), mid.coord(j)],
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
            for l in Layer::ALL {
                p.push(
                    format!("curve-{}", l.name()),
                    Mark::Line {
                        points: project(layer_curve(l), ij),
                        stroke: layer_stroke(l),
                    },
                );
            }
            p.push(
                "points-crisp",
                Mark::Markers {
                    points: project(&cp.crisp, ij),
                    marker: crisp_marker(),
                },
            );
            name_labels(&mut p, &cp.crisp, ij, point_name);
            p
        })
        .collect();
    let mut legend = vec![
        LegendEntry::line_marker(
            "crisp curve and control points",
            crisp_stroke(),
            crisp_marker(),
        ),
        LegendEntry::line("control polygon", polygon_stroke()),
    ];
    for (l, _, name) in FUNCTIONS {
        legend.push(LegendEntry::line(
            &format!("{name} layers (left, right)"),
            layer_stroke(l),
        ));
    }
    legend.push(LegendEntry::area("between the upper layers", upper_band()));
    legend.push(LegendEntry::area("between the lower layers", lower_band()));
    figure(
        "stage1-fuzzy",
        "Stage 1: normal type-2 fuzzy rational B-spline curve",
        format!(
            "order {}, weights ({}); bars: upper ⊃ primary ⊃ lower interval of each coordinate",
            r.spline.orders()[0],
            r.spline
                .weights()
                .iter()
                .map(|w| short(*w, 4))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        panels,
        legend,
    )
}

/// Stage 2 (paper Fig. 5.2): the alpha-cut control points and their curves.
/// Lower layers are drawn only where every number has a lower cut.
#[must_use]
pub fn stage2_figure(r: &RunOutput, heights: &[f64]) -> Figure {
    let (c, cp) = (&r.samples, &r.control_points);
    let curve = |l: Layer| -> Option<&Points> {
        match c.alpha_cut.get(l) {
            None => Some(&c.crisp),
            Some(v) => v.as_ref(),
        }
    };
    let panels = curve_panels(r.dimension)
        .into_iter()
        .map(|(mut p, ij)| {
            let area = |a: Layer, b: Layer, fill| match (curve(a), curve(b)) {
                (Some(x), Some(y)) => Mark::Area {
                    points: band(x, y, ij),
                    fill,
                },
                _ => Mark::Empty,
            };
            p.push(
                "band-upper",
                area(Layer::UpperLeft, Layer::UpperRight, upper_band()),
            );
            p.push(
                "band-lower",
                area(Layer::LowerLeft, Layer::LowerRight, lower_band()),
            );
            p.push(
                "polygon",
                Mark::Line {
                    points: project(&cp.crisp, ij),
                    stroke: polygon_stroke(),
                },
            );
            for l in Layer::ALL {
                let mark = curve(l).map_or(Mark::Empty, |pts| Mark::Line {
                    points: project(pts, ij),
                    stroke: layer_stroke(l),
                });
                p.push(format!("curve-{}", l.name()), mark);
            }
            for l in Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp) {
                // A cut point exists when every coordinate has its lower cut.
                let (i, j) = ij;
                let pts: Vec<_> = cp
                    .alpha_cut
                    .get(l)
                    .map(|cut| {
                        cut.coord(i)
                            .iter()
                            .zip(cut.coord(j))
                            .filter_map(|(x, y)| Some([(*x)?, (*y)?]))
                            .collect()
                    })
                    .unwrap_or_default();
                let mark = if pts.is_empty() {
                    Mark::Empty
                } else {
                    Mark::Markers {
                        points: pts,
                        marker: layer_marker(l),
                    }
                };
                p.push(format!("points-{}", l.name()), mark);
            }
            p.push(
                "points-crisp",
                Mark::Markers {
                    points: project(&cp.crisp, ij),
                    marker: crisp_marker(),
                },
            );
            name_labels(&mut p, &cp.crisp, ij, point_name);
            p
        })
        .collect();
    let mut legend = vec![
        LegendEntry::line_marker(
            "crisp curve and control points",
            crisp_stroke(),
            crisp_marker(),
        ),
        LegendEntry::line("control polygon", polygon_stroke()),
    ];
    for (l, _, name) in FUNCTIONS {
        let label = if name == "lower" {
            "lower cuts (only for α ≤ h)".to_owned()
        } else {
            format!("{name} cuts (left, right)")
        };
        legend.push(LegendEntry::line_marker(
            &label,
            layer_stroke(l),
            layer_marker(l),
        ));
    }
    figure(
        "stage2-alpha-cut",
        "Stage 2: alpha-cut of the fuzzy control points (α-NT2FRBsC)",
        alpha_phrase(r, heights),
        panels,
        legend,
    )
}

/// Stage 3 (paper Fig. 5.3): the type-reduced control points — each a type-1
/// triangle (left, crisp, right) labelled with its weight — and the curves
/// through the left and the right values.
#[must_use]
pub fn stage3_figure(r: &RunOutput, heights: &[f64]) -> Figure {
    let (c, cp) = (&r.samples, &r.control_points);
    let left_marker = Marker::filled(Shape::Triangle, 7.5, PURPLE);
    let right_marker = Marker::filled(Shape::Diamond, 8.0, PURPLE);
    let spread = Stroke::solid(GREY, 1.0);
    let panels = curve_panels(r.dimension)
        .into_iter()
        .map(|(mut p, ij)| {
            p.push(
                "band",
                Mark::Area {
                    points: band(&c.type_reduced.left, &c.type_reduced.right, ij),
                    fill: reduced_band(),
                },
            );
            p.push(
                "polygon",
                Mark::Line {
                    points: project(&cp.crisp, ij),
                    stroke: polygon_stroke(),
                },
            );
            let (l, m, rr) = (
                project(&cp.type_reduced_left, ij),
                project(&cp.crisp, ij),
                project(&cp.type_reduced_right, ij),
            );
            let segments = (0..m.len())
                .flat_map(|k| [[l[k], m[k]], [m[k], rr[k]]])
                .collect();
            p.push(
                "spreads",
                Mark::Segments {
                    segments,
                    stroke: spread.clone(),
                },
            );
            p.push(
                "curve-left",
                Mark::Line {
                    points: project(&c.type_reduced.left, ij),
                    stroke: reduced_stroke(),
                },
            );
            p.push(
                "curve-right",
                Mark::Line {
                    points: project(&c.type_reduced.right, ij),
                    stroke: reduced_stroke(),
                },
            );
            p.push(
                "curve-crisp",
                Mark::Line {
                    points: project(&c.crisp, ij),
                    stroke: crisp_stroke(),
                },
            );
            p.push(
                "points-left",
                Mark::Markers {
                    points: l,
                    marker: left_marker.clone(),
                },
            );
            p.push(
                "points-right",
                Mark::Markers {
                    points: rr,
                    marker: right_marker.clone(),
                },
            );
            p.push(
                "points-crisp",
                Mark::Markers {
                    points: m,
                    marker: crisp_marker(),
                },
            );
            name_labels(&mut p, &cp.crisp, ij, |k| {
                format!("{}, w = {}", point_name(k), short(r.spline.weights()[k], 4))
            });
            p
        })
        .collect();
    let legend = vec![
        LegendEntry::line_marker(
            "crisp curve and control points",
            crisp_stroke(),
            crisp_marker(),
        ),
        LegendEntry::line_marker(
            "type-reduced left curve and points",
            reduced_stroke(),
            left_marker,
        ),
        LegendEntry::line_marker(
            "type-reduced right curve and points",
            reduced_stroke(),
            right_marker,
        ),
        LegendEntry::line("type-1 control point: left–crisp–right", spread),
        LegendEntry::area("between left and right curves", reduced_band()),
    ];
    figure(
        "stage3-type-reduced",
        "Stage 3: type reduction (TR-α-NT2FRBsC)",
        alpha_phrase(r, heights),
        panels,
        legend,
    )
}

/// Stage 4 (paper Fig. 5.4): the crisp curve and the defuzzified solution
/// curve with their control points, and the largest distance between them
/// marked and annotated. With `detail`, a 2-D figure gets a second panel
/// magnifying the neighbourhood of that distance.
///
/// # Errors
/// Only if the library cannot evaluate a curve at the result's `max_at`, which
/// lies in the domain by construction.
pub fn stage4_figure(job: &Job, r: &RunOutput, detail: bool) -> Result<Figure, Error> {
    let (c, cp, e) = (&r.samples, &r.control_points, &r.error);
    let alpha = t2spline::Alpha::try_new(r.alpha)?;
    let (at_crisp, at_solution) =
        data::curves_at(&job.model, alpha, r.type_reduction, data::max_at(r))?;
    let distance_stroke = Stroke::solid(BLACK, 1.4);
    let end_marker = Marker::open(Shape::Circle, 4.0, BLACK);
    let text = format!(
        "max distance {} at t = {}",
        short(e.max, 4),
        short(data::max_at(r), 4)
    );
    let mut panels: Vec<Panel> = curve_panels(r.dimension)
        .into_iter()
        .map(|(mut p, ij)| {
            let ends = vec![
                [at_crisp[ij.0], at_crisp[ij.1]],
                [at_solution[ij.0], at_solution[ij.1]],
            ];
            p.push(
                "polygon",
                Mark::Line {
                    points: project(&cp.crisp, ij),
                    stroke: polygon_stroke(),
                },
            );
            p.push(
                "curve-crisp",
                Mark::Line {
                    points: project(&c.crisp, ij),
                    stroke: crisp_stroke(),
                },
            );
            p.push(
                "curve-defuzzified",
                Mark::Line {
                    points: project(&c.defuzzified, ij),
                    stroke: solution_stroke(),
                },
            );
            p.push(
                "points-crisp",
                Mark::Markers {
                    points: project(&cp.crisp, ij),
                    marker: crisp_marker(),
                },
            );
            p.push(
                "points-defuzzified",
                Mark::Markers {
                    points: project(&cp.defuzzified, ij),
                    marker: solution_marker(),
                },
            );
            p.push(
                "distance",
                Mark::Segments {
                    segments: vec![[ends[0], ends[1]]],
                    stroke: distance_stroke.clone(),
                },
            );
            p.push(
                "distance-ends",
                Mark::Markers {
                    points: ends.clone(),
                    marker: end_marker.clone(),
                },
            );
            let mid = [
                0.5 * (ends[0][0] + ends[1][0]),
                0.5 * (ends[0][1] + ends[1][1]),
            ];
            // One annotation is enough; 3-D jobs repeat the mark, not the text.
            let label = if ij == (0, 1) {
                Mark::Label {
                    anchor: mid,
                    text: text.clone(),
                }
            } else {
                Mark::Empty
            };
            p.push("distance-text", label);
            p
        })
        .collect();
    if detail && r.dimension == 2 && e.max > 0.0 {
        panels.push(detail_panel(
            r,
            [&at_crisp, &at_solution],
            &distance_stroke,
            &end_marker,
        ));
    }
    let legend = vec![
        LegendEntry::line_marker(
            "crisp curve and control points",
            crisp_stroke(),
            crisp_marker(),
        ),
        LegendEntry::line_marker(
            "defuzzified curve and control points",
            solution_stroke(),
            solution_marker(),
        ),
        LegendEntry::line("control polygon", polygon_stroke()),
        LegendEntry::line_marker("largest distance at equal t", distance_stroke, end_marker),
    ];
    Ok(figure(
        "stage4-defuzzified",
        "Stage 4: crisp type-2 solution curve (D-TR-α-NT2FRBsC)",
        format!(
            "{}: max distance {} at t = {}, rms distance {}",
            reduction_phrase(r),
            short(e.max, 4),
            short(data::max_at(r), 4),
            short(e.rms, 4)
        ),
        panels,
        legend,
    ))
}

/// A square window around the largest distance, a few times its size.
fn detail_panel(r: &RunOutput, ends: [&[f64]; 2], stroke: &Stroke, marker: &Marker) -> Panel {
    let (c, cp) = (&r.samples, &r.control_points);
    let mid = [
        0.5 * (ends[0][0] + ends[1][0]),
        0.5 * (ends[0][1] + ends[1][1]),
    ];
    let span = c
        .crisp
        .coord(0)
        .iter()
        .fold([f64::INFINITY, f64::NEG_INFINITY], |b, &x| {
            [b[0].min(x), b[1].max(x)]
        });
    let half = (4.0 * r.error.max).max(0.01 * (span[1] - span[0]));
    let mut p = Panel::curves("x", "y");
    p.title = Some(format!("detail around t = {}", short(data::max_at(r), 4)));
    p.x_range = Some([mid[0] - half, mid[0] + half]);
    p.y_range = Some([mid[1] - half, mid[1] + half]);
    let ij = (0, 1);
    p.push(
        "curve-crisp",
        Mark::Line {
            points: project(&c.crisp, ij),
            stroke: crisp_stroke(),
        },
    );
    p.push(
        "curve-defuzzified",
        Mark::Line {
            points: project(&c.defuzzified, ij),
            stroke: solution_stroke(),
        },
    );
    p.push(
        "points-crisp",
        Mark::Markers {
            points: project(&cp.crisp, ij),
            marker: crisp_marker(),
        },
    );
    p.push(
        "points-defuzzified",
        Mark::Markers {
            points: project(&cp.defuzzified, ij),
            marker: solution_marker(),
        },
    );
    let ends = [[ends[0][0], ends[0][1]], [ends[1][0], ends[1][1]]];
    p.push(
        "distance",
        Mark::Segments {
            segments: vec![ends],
            stroke: stroke.clone(),
        },
    );
    p.push(
        "distance-ends",
        Mark::Markers {
            points: ends.to_vec(),
            marker: marker.clone(),
        },
    );
    p.push(
        "distance-text",
        Mark::Label {
            anchor: mid,
            text: short(r.error.max, 4),
        },
    );
    p
}
