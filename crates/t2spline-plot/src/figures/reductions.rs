//! The type reductions side by side (SPEC §10): the solution curve of every
//! reduction beside the crisp curve, and each one's distance to it along the
//! curve, with the distance's maximum and root mean square in the legend.

use t2spline::job::{Job, RunOutput};
use t2spline::pipeline::euclidean_norm;
use t2spline::{Alpha, TypeReduction};

use super::style::{crisp_marker, crisp_stroke, polygon_stroke};
use super::{curve_panels, project};
use crate::scene::{Figure, LegendEntry, Mark, Panel, Xy};
use crate::style::{Marker, Shape, Stroke, BLUE, ORANGE, PURPLE, SKY};
use crate::ticks::short;
use crate::{data, Error};

/// A reduction's name in legends and subtitles.
#[must_use]
pub fn reduction_label(method: TypeReduction) -> &'static str {
    match method {
        TypeReduction::Paper => "paper",
        TypeReduction::Centroid => "centroid (Karnik–Mendel)",
        TypeReduction::NieTan => "Nie–Tan",
        TypeReduction::AlphaPlanes => "alpha-planes",
    }
}

/// How a reduction's solution curve is drawn: a colour and a dash pattern
/// each, so that the four stay apart in grey print too. The paper's is the
/// purple of the type-reduced curves (stage 3); the others avoid the colours
/// of the membership functions (blue, green, vermillion) where they are
/// drawn beside them (the `number` figure).
#[must_use]
pub fn reduction_stroke(method: TypeReduction) -> Stroke {
    match method {
        TypeReduction::Paper => Stroke::dashed(PURPLE, 1.8, "7 3"),
        TypeReduction::Centroid => Stroke::solid(SKY, 1.8),
        TypeReduction::NieTan => Stroke::dashed(BLUE, 1.8, "2 2"),
        TypeReduction::AlphaPlanes => Stroke::dashed(ORANGE, 1.8, "9 3 2 3"),
    }
}

/// The marker of a reduction's defuzzified value or largest distance.
#[must_use]
pub fn reduction_marker(method: TypeReduction) -> Marker {
    match method {
        TypeReduction::Paper => Marker::filled(Shape::Diamond, 8.0, PURPLE),
        TypeReduction::Centroid => Marker::filled(Shape::Square, 6.5, SKY),
        TypeReduction::NieTan => Marker::filled(Shape::Triangle, 7.5, BLUE),
        TypeReduction::AlphaPlanes => Marker::filled(Shape::Circle, 6.5, ORANGE),
    }
}

/// `paper (α = 0.8)` or `centroid (Karnik–Mendel)`: a reduction with the
/// level it used, if any.
#[must_use]
pub fn reduction_with_level(method: TypeReduction, alpha: f64) -> String {
    if method.uses_alpha() {
        format!("{} (α = {})", reduction_label(method), short(alpha, 4))
    } else {
        reduction_label(method).to_owned()
    }
}

/// The `reductions` figure: the crisp curve and the solution curve of every
/// type reduction (the paper's at `alpha`; the others do not use alpha) in
/// each projection, and a panel of each solution's distance to the crisp
/// curve at equal t, its largest value marked. The legend gives each
/// reduction's distance, max and rms, as `t2spline run --type-reduction`
/// reports them.
///
/// # Errors
/// [`Error::Surface`] for a surface job; [`Error::Core`] if a run fails
/// (never for a validated curve job).
pub fn reductions_figure(job: &Job, alpha: Alpha) -> Result<Figure, Error> {
    let results = TypeReduction::ALL
        .into_iter()
        .map(|m| Ok((m, data::compute_with(job, alpha, m)?)))
        .collect::<Result<Vec<(TypeReduction, RunOutput)>, Error>>()?;
    let first = &results[0].1;
    let mut panels: Vec<Panel> = curve_panels(first.dimension)
        .into_iter()
        .map(|(mut p, ij)| {
            p.push(
                "polygon",
                Mark::Line {
                    points: project(&first.control_points.crisp, ij),
                    stroke: polygon_stroke(),
                },
            );
            p.push(
                "curve-crisp",
                Mark::Line {
                    points: project(&first.samples.crisp, ij),
                    stroke: crisp_stroke(),
                },
            );
            for (m, r) in &results {
                p.push(
                    format!("curve-{}", m.name()),
                    Mark::Line {
                        points: project(&r.samples.defuzzified, ij),
                        stroke: reduction_stroke(*m),
                    },
                );
            }
            p.push(
                "points-crisp",
                Mark::Markers {
                    points: project(&first.control_points.crisp, ij),
                    marker: crisp_marker(),
                },
            );
            p
        })
        .collect();
    panels.push(distance_panel(&results));
    let mut legend = vec![LegendEntry::line_marker(
        "crisp curve, control points and polygon",
        crisp_stroke(),
        crisp_marker(),
    )];
    legend.extend(results.iter().map(|(m, r)| {
        LegendEntry::line_marker(
            &format!(
                "{}: max {}, rms {}",
                reduction_with_level(*m, r.alpha),
                short(r.error.max, 4),
                short(r.error.rms, 4)
            ),
            reduction_stroke(*m),
            reduction_marker(*m),
        )
    }));
    Ok(Figure {
        name: "reductions",
        title: "Solution curve of every type reduction".into(),
        subtitle: format!(
            "defuzzified curves and their distance to the crisp curve at equal t; only the paper's reduction uses α (here {})",
            short(alpha.get(), 4)
        ),
        panels,
        legend,
        colorbar: None,
    })
}

/// `|D(t) − C(t)|` at the sample parameters for every reduction, the
/// largest distance (from the run, not the samples) marked at its `t`.
fn distance_panel(results: &[(TypeReduction, RunOutput)]) -> Panel {
    let mut p = Panel {
        title: Some("distance to the crisp curve".into()),
        x_label: "t".into(),
        y_label: "|D(t) − C(t)|".into(),
        equal_aspect: false,
        x_range: None,
        y_range: None,
        items: Vec::new(),
    };
    for (m, r) in results {
        let (c, d) = (&r.samples.crisp, &r.samples.defuzzified);
        let params = r.samples.params.along();
        let points: Vec<Xy> = params
            .iter()
            .enumerate()
            .map(|(k, &t)| {
                let difference: Vec<f64> = (0..r.dimension)
                    .map(|axis| d.coord(axis)[k] - c.coord(axis)[k])
                    .collect();
                [t, euclidean_norm(&difference)]
            })
            .collect();
        p.push(
            format!("distance-{}", m.name()),
            Mark::Line {
                points,
                stroke: reduction_stroke(*m),
            },
        );
    }
    for (m, r) in results {
        p.push(
            format!("max-{}", m.name()),
            Mark::Markers {
                points: vec![[data::max_at(r), r.error.max]],
                marker: reduction_marker(*m),
            },
        );
    }
    p
}
