//! The `measures` figure: the fuzzy arc length and the fuzzy area of a curve
//! (docs/method.md §11) drawn as the `number` figure draws a fuzzy number —
//! the upper, primary and lower membership functions over the quantity,
//! the footprint between upper and lower, the least height h, and the crisp
//! curve's value marked. Each function is traced by its cuts' ends at the
//! levels of [`crate::measure_view`]; where a cut is a certified bracket
//! rather than exact, its outer bounds are drawn and a note gives the
//! bracket's width.

use t2spline::job::Job;
use t2spline::measure::{AreaKind, Level, PerMembership};
use t2spline::Layer;

use super::number::rules;
use super::style::{crisp_marker, layer_stroke, upper_band};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel, Priority, Xy};
use crate::chart::ticks::short;
use crate::error::Error;
use crate::measure_view::{fuzzy_measures, FuzzyMeasures, FuzzyQuantity};

/// The membership function traced by cuts: the least ends up the levels,
/// then the largest ends down (outer bounds where a cut is not exact).
#[must_use]
pub fn traced(levels: &[Level]) -> Vec<Xy> {
    let up = levels.iter().map(|l| [l.min, l.alpha]);
    let down = levels.iter().rev().map(|l| [l.max, l.alpha]);
    up.chain(down).collect()
}

/// The largest bracket gap of a quantity's cuts, `None` where all are exact.
fn widest_gap(q: &FuzzyQuantity) -> Option<f64> {
    widest_gap_of(&q.levels)
}

/// The largest bracket gap of cuts per function, `None` where all are exact.
#[must_use]
pub fn widest_gap_of(levels: &PerMembership<Vec<Level>>) -> Option<f64> {
    [&levels.upper, &levels.primary, &levels.lower]
        .into_iter()
        .flatten()
        .filter(|l| !l.exact)
        .map(|l| l.gap)
        .reduce(f64::max)
}

/// One panel: the footprint, the three functions, h and the crisp value.
fn panel(name: &str, q: &FuzzyQuantity) -> Panel {
    quantity_panel(name, &q.levels, q.crisp)
}

/// The panel of a fuzzy quantity `name` traced by its cuts `levels`: the
/// footprint, the three functions, h and the value `crisp` of the crisp
/// curve or surface.
#[must_use]
pub fn quantity_panel(name: &str, levels: &PerMembership<Vec<Level>>, crisp: f64) -> Panel {
    let mut p = Panel::graph(name, "membership grade");
    p.title = Some(format!("fuzzy {name}"));
    p.y_range = Some([-0.07, 1.12]);
    let (u, pr, l) = (
        traced(&levels.upper),
        traced(&levels.primary),
        traced(&levels.lower),
    );
    p.push(
        "fou",
        Mark::Area {
            points: u.iter().chain(l.iter().rev()).copied().collect(),
            fill: upper_band(),
        },
    );
    if let Some(top) = levels.lower.last() {
        rules(&mut p, top.alpha);
    }
    for (key, points, layer) in [
        ("umf", u, Layer::UpperLeft),
        ("primary", pr, Layer::PrimaryLeft),
        ("lmf", l, Layer::LowerLeft),
    ] {
        p.push(
            key,
            Mark::Line {
                points,
                stroke: layer_stroke(layer),
            },
        );
    }
    p.push(
        "crisp",
        Mark::Markers {
            points: vec![[crisp, 1.0]],
            marker: crisp_marker(),
        },
    );
    p.push(
        "crisp-text",
        Mark::Label {
            anchor: [crisp, 1.0],
            text: format!("crisp {}", short(crisp, 4)),
            priority: Priority::Always,
        },
    );
    p
}

/// The legend: the functions as the `number` figure names them, the
/// crisp curve's value.
fn legend() -> Vec<LegendEntry> {
    legend_of("crisp curve's value")
}

/// The legend of a figure of fuzzy quantities, the crisp value named `crisp`.
#[must_use]
pub fn legend_of(crisp: &str) -> Vec<LegendEntry> {
    vec![
        LegendEntry::line("UMF (upper)", layer_stroke(Layer::UpperLeft)),
        LegendEntry::line("primary MF", layer_stroke(Layer::PrimaryLeft)),
        LegendEntry::line(
            "LMF (lower, up to height h)",
            layer_stroke(Layer::LowerLeft),
        ),
        LegendEntry::area("footprint of uncertainty", upper_band()),
        LegendEntry::marker(crisp, crisp_marker()),
    ]
}

/// The `measures` figure of a curve job: the fuzzy arc length, and for a
/// plane curve the fuzzy area beside it.
///
/// # Errors
/// [`Error::Surface`] for a surface job.
pub fn measures_figure(job: &Job) -> Result<Figure, Error> {
    let m = fuzzy_measures(&job.model, job.closed)?;
    let levels = m.length.levels.upper.len();
    Ok(measures_figure_of(
        &m,
        &format!(
            "Each function is traced by its cuts at {levels} levels (0, 0.05, …, 1 and every h), joined by straight lines; docs/method.md §11."
        ),
    ))
}

/// The `measures` figure of the fuzzy measures `m`; `levels_note`, the last
/// note, says at which levels the functions are traced.
#[must_use]
pub fn measures_figure_of(m: &FuzzyMeasures, levels_note: &str) -> Figure {
    let mut panels = vec![panel("arc length", &m.length)];
    let mut notes = Vec::new();
    let mut quantities = vec![("arc length", &m.length)];
    if let Some((kind, area)) = &m.area {
        let name = match kind {
            AreaKind::Under => "area under the curve",
            AreaKind::Enclosed => "enclosed area",
        };
        panels.push(panel(name, area));
        quantities.push((name, area));
    }
    for (name, q) in quantities {
        if let Some(gap) = widest_gap(q) {
            notes.push(format!(
                "{name}: some cuts are certified brackets, not exact; their outer bounds are drawn, at most {} outside the values attained (bracket width).",
                short(gap, 3)
            ));
        }
    }
    notes.push(levels_note.to_owned());
    let subtitle = match &m.area {
        Some((_, a)) => format!(
            "crisp arc length {}, crisp area {}",
            short(m.length.crisp, 4),
            short(a.crisp, 4)
        ),
        None => format!("crisp arc length {}", short(m.length.crisp, 4)),
    };
    let mut fig = Figure::new(
        "measures",
        "Fuzzy measures: arc length and area of the fuzzy curve",
        subtitle,
        panels,
        legend(),
    );
    fig.notes = notes;
    fig
}
