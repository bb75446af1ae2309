//! One fuzzy number (paper Figs. 3.1 and 4.1–4.4): its three membership
//! functions, the footprint of uncertainty, the height h, the cut at alpha and
//! the type-reduced triangle with its centroid; and the other reductions of
//! SPEC §10 (`number_reductions.rs`).

use t2spline::job::Job;
use t2spline::{Alpha, Axis, TypeReduction};

use super::style::{layer_marker, layer_stroke, upper_band};
use super::{number_reductions, NumberChoice};
use crate::scene::{Figure, LegendEntry, Mark, Panel};
use crate::style::{Marker, Shape, Stroke, GREY, INK, PURPLE};
use crate::ticks::short;
use crate::{data, Error};
use t2spline::Layer;

/// The `number` figure for one coordinate of one control point at `alpha`.
///
/// # Errors
/// [`Error::NoSuchPoint`] or [`Error::NoSuchAxis`] if the job has no such
/// point or coordinate.
pub fn number_figure(job: &Job, alpha: Alpha, choice: NumberChoice) -> Result<Figure, Error> {
    let x = data::number(&job.model, choice.point, choice.axis)?;
    let cut = x.alpha_cut(alpha);
    let tfn = cut.type_reduce();
    let d = tfn.defuzzify();
    let (a, h, c) = (alpha.get(), x.height().get(), x.crisp());
    let (u, p, l) = (x.upper(), x.primary(), x.lower());
    let triangle = |lo: f64, top: f64, hi: f64| vec![[lo, 0.0], [c, top], [hi, 0.0]];
    let name = Axis::name(choice.axis);
    let mut panel = Panel {
        title: None,
        x_label: name.to_owned(),
        y_label: "membership grade".into(),
        equal_aspect: false,
        x_range: None,
        y_range: Some([-0.07, 1.12]),
        items: Vec::new(),
    };
    panel.push(
        "fou",
        Mark::Area {
            points: vec![
                [u.left(), 0.0],
                [c, 1.0],
                [u.right(), 0.0],
                [l.right(), 0.0],
                [c, h],
                [l.left(), 0.0],
            ],
            fill: upper_band(),
        },
    );
    panel.push(
        "h",
        Mark::HRule {
            y: h,
            stroke: Stroke::dashed(GREY, 1.0, "2 3"),
            label: format!("h = {}", short(h, 4)),
        },
    );
    panel.push(
        "alpha",
        Mark::HRule {
            y: a,
            stroke: Stroke::solid(INK, 0.9),
            label: format!("α = {}", short(a, 4)),
        },
    );
    panel.push(
        "umf",
        Mark::Line {
            points: triangle(u.left(), 1.0, u.right()),
            stroke: layer_stroke(Layer::UpperLeft),
        },
    );
    panel.push(
        "primary",
        Mark::Line {
            points: triangle(p.left(), 1.0, p.right()),
            stroke: layer_stroke(Layer::PrimaryLeft),
        },
    );
    panel.push(
        "lmf",
        Mark::Line {
            points: triangle(l.left(), h, l.right()),
            stroke: layer_stroke(Layer::LowerLeft),
        },
    );
    let tfn_stroke = Stroke::solid(PURPLE, 2.0);
    panel.push(
        "tfn",
        Mark::Line {
            points: triangle(tfn.left(), 1.0, tfn.right()),
            stroke: tfn_stroke.clone(),
        },
    );
    let ends = |iv: t2spline::Interval| vec![[iv.left(), a], [iv.right(), a]];
    panel.push(
        "cut-upper",
        Mark::Markers {
            points: ends(cut.upper()),
            marker: layer_marker(Layer::UpperLeft),
        },
    );
    panel.push(
        "cut-primary",
        Mark::Markers {
            points: ends(cut.primary()),
            marker: layer_marker(Layer::PrimaryLeft),
        },
    );
    panel.push(
        "cut-lower",
        cut.lower().map_or(Mark::Empty, |iv| Mark::Markers {
            points: ends(iv),
            marker: layer_marker(Layer::LowerLeft),
        }),
    );
    // The centroid on the axis, with a drop line from the triangle.
    let top = if d <= c {
        if c > tfn.left() {
            (d - tfn.left()) / (c - tfn.left())
        } else {
            1.0
        }
    } else if tfn.right() > c {
        (tfn.right() - d) / (tfn.right() - c)
    } else {
        1.0
    };
    panel.push(
        "defuzzified-line",
        Mark::Segments {
            segments: vec![[[d, 0.0], [d, top]]],
            stroke: Stroke::dashed(PURPLE, 1.0, "3 2"),
        },
    );
    let d_marker = Marker::filled(Shape::Diamond, 8.0, PURPLE);
    panel.push(
        "defuzzified",
        Mark::Markers {
            points: vec![[d, 0.0]],
            marker: d_marker.clone(),
        },
    );
    panel.push(
        "defuzzified-text",
        Mark::Label {
            anchor: [d, 0.0],
            text: format!("defuzzified {}", short(d, 4)),
        },
    );
    panel.push(
        "crisp-text",
        Mark::Label {
            anchor: [c, 1.0],
            text: format!("crisp {}", short(c, 4)),
        },
    );
    let mut legend = vec![
        LegendEntry::line_marker(
            "UMF (upper) and its cut ends",
            layer_stroke(Layer::UpperLeft),
            layer_marker(Layer::UpperLeft),
        ),
        LegendEntry::line_marker(
            "primary MF and its cut ends",
            layer_stroke(Layer::PrimaryLeft),
            layer_marker(Layer::PrimaryLeft),
        ),
        LegendEntry::line_marker(
            "LMF (lower, height h), cut ends",
            layer_stroke(Layer::LowerLeft),
            layer_marker(Layer::LowerLeft),
        ),
        LegendEntry::area("footprint of uncertainty", upper_band()),
        LegendEntry::line("type-reduced triangle", tfn_stroke),
        LegendEntry::marker(&format!("paper: defuzzified {}", short(d, 4)), d_marker),
    ];
    legend.extend(number_reductions::add_reductions(&mut panel, &x));
    let regime = if a <= h {
        "α ≤ h: three cut ends averaged"
    } else {
        "α > h: no lower cut, two ends averaged"
    };
    Ok(Figure {
        name: "number",
        title: format!(
            "Fuzzy number: coordinate {name} of control point {}",
            choice.point
        ),
        subtitle: match job.type_reduction {
            TypeReduction::Paper => format!(
                "{regime}; type-reduced ({}, {}, {}), defuzzified {}",
                short(tfn.left(), 4),
                short(c, 4),
                short(tfn.right(), 4),
                short(d, 4)
            ),
            method => number_reductions::reduction_subtitle(&x, method),
        },
        panels: vec![panel],
        legend,
        colorbar: None,
    })
}
