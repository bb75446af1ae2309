//! The `section` figure: the fuzzy value of y at a station `x = x0` of a
//! plane curve (docs/method.md §10), drawn as the `number` figure draws one
//! fuzzy number. The upper, primary and lower membership of `y` are the
//! grades of the points `(x0, y)` (the core's `memberships`), the cut at α
//! the section's intervals there (the core's `sections`: several where the
//! curve passes the station more than once), and the y samples include every
//! interval end at 21 levels, so the lines pass through those ends.

use t2spline::job::Job;
use t2spline::set::SectionLevel;
use t2spline::{Alpha, Layer, Membership};

use super::scene::CurveScene;
use crate::chart::paint::{Stroke, GREY, INK};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel, Xy};
use crate::chart::ticks::short;
use crate::error::Error;
use crate::figures::style::{layer_marker, layer_stroke, upper_band};
use crate::set_view;

/// Levels at which the section is cut for the y samples: 0, 0.05, …, 1.
const LEVELS: u32 = 20;

/// Uniform y samples across the section, besides the interval ends.
const SAMPLES: usize = 61;

/// The station drawn when none is given: x of the crisp curve at the middle
/// of its samples (the middle of the domain).
#[must_use]
pub fn default_station(scene: &CurveScene<'_>) -> f64 {
    let x = scene.r.samples.crisp.coord(0);
    x.get(x.len() / 2).copied().unwrap_or(0.0)
}

/// The functions as the number figure draws them: (key, membership, layer
/// whose style it takes, legend name).
const FUNCTIONS: [(&str, Membership, Layer, &str); 3] = [
    ("umf", Membership::Upper, Layer::UpperLeft, "upper"),
    (
        "primary",
        Membership::Primary,
        Layer::PrimaryLeft,
        "primary",
    ),
    ("lmf", Membership::Lower, Layer::LowerLeft, "lower"),
];

/// The levels of the samples, the figure's alpha and every height, as
/// alphas, ascending.
fn levels(alpha: f64, heights: &[f64]) -> Result<Vec<Alpha>, Error> {
    let mut v: Vec<f64> = (0..=LEVELS)
        .map(|k| f64::from(k) / f64::from(LEVELS))
        .collect();
    v.push(alpha);
    v.extend(heights);
    v.sort_by(f64::total_cmp);
    v.dedup();
    Ok(v.into_iter()
        .map(Alpha::try_new)
        .collect::<Result<_, _>>()?)
}

/// The y samples: [`SAMPLES`] across `[lo, hi]` and every interval end.
fn samples(cuts: &[SectionLevel], [lo, hi]: [f64; 2]) -> Vec<f64> {
    let mut ys: Vec<f64> = (0..SAMPLES)
        .map(|k| lo + (hi - lo) * k as f64 / (SAMPLES - 1) as f64)
        .collect();
    for c in cuts {
        for (_, m, _, _) in FUNCTIONS {
            ys.extend(c.get(m).unwrap_or_default().iter().flatten());
        }
    }
    ys.sort_by(f64::total_cmp);
    ys.dedup();
    ys
}

/// The `section` figure of a plane curve job at the station `x0` (the
/// [default](default_station) when `None`), cut at the result's alpha.
///
/// # Errors
/// [`Error::Planar`] for a space curve or a surface; [`Error::Core`] if
/// `x0` is not finite.
pub fn section_figure(job: &Job, scene: &CurveScene<'_>, x0: Option<f64>) -> Result<Figure, Error> {
    let curve = set_view::planar(&job.model)?;
    let x0 = x0.unwrap_or_else(|| default_station(scene));
    let alpha = scene.r.alpha;
    let heights = job.model.heights();
    let lv = levels(alpha, &heights)?;
    let (cuts, _) = set_view::section(curve, x0, &lv, &[])?;
    let station = short(x0, 4);
    let mut panel = Panel::graph(&format!("y at x = {station}"), "membership grade");
    panel.y_range = Some([-0.07, 1.12]);
    let reach = cuts
        .first()
        .and_then(|c| c.upper.as_deref())
        .and_then(|iv| Some([iv.first()?[0], iv.last()?[1]]));
    let mut notes = Vec::new();
    match reach {
        Some([lo, hi]) => {
            let pad = 0.08 * (hi - lo).max(1e-9 * (lo.abs() + hi.abs()).max(1e-300));
            let ys = samples(&cuts, [lo - pad, hi + pad]);
            let (_, grades) = set_view::section(curve, x0, &[], &ys)?;
            draw(&mut panel, &grades);
        }
        None => {
            notes.push(format!(
                "The curve's region does not reach the station x = {station} at any level."
            ));
            for key in ["fou", "umf", "primary", "lmf"] {
                panel.push(key, Mark::Empty);
            }
        }
    }
    if let [h] = heights.as_slice() {
        panel.push(
            "h",
            Mark::HRule {
                y: *h,
                stroke: Stroke::dashed(GREY, 1.0, "2 3"),
                label: format!("h = {}", short(*h, 4)),
            },
        );
    }
    let at = cuts.iter().find(|c| c.alpha == alpha);
    let lower_cut = cut(&mut panel, at, alpha);
    let several = cuts
        .iter()
        .any(|c| c.upper.as_ref().is_some_and(|iv| iv.len() > 1));
    let subtitle = if several {
        format!(
            "the grades of the points (x = {station}, y); the curve passes the station more than once: several intervals at some levels"
        )
    } else {
        format!("the grades of the points (x = {station}, y), and their cut at α")
    };
    Ok(Figure {
        notes,
        ..Figure::new(
            "section",
            format!("Section at x = {station}: the fuzzy value of y"),
            subtitle,
            vec![panel],
            legend(lower_cut, alpha),
        )
    })
}

/// The footprint between the upper and lower grades, and the three
/// membership functions of y.
fn draw(p: &mut Panel, grades: &[[f64; 4]]) {
    let mut fou: Vec<Xy> = grades.iter().map(|g| [g[0], g[1]]).collect();
    fou.extend(grades.iter().rev().map(|g| [g[0], g[3]]));
    p.push(
        "fou",
        Mark::Area {
            points: fou,
            fill: upper_band(),
        },
    );
    for (k, (key, _, layer, _)) in FUNCTIONS.iter().enumerate() {
        p.push(
            *key,
            Mark::Line {
                points: grades.iter().map(|g| [g[0], g[k + 1]]).collect(),
                stroke: layer_stroke(*layer),
            },
        );
    }
}

/// The level α and the ends of each function's intervals on it; whether
/// the lower function has a cut there.
fn cut(p: &mut Panel, at: Option<&SectionLevel>, alpha: f64) -> bool {
    p.push(
        "alpha",
        Mark::HRule {
            y: alpha,
            stroke: Stroke::solid(INK, 0.9),
            label: format!("α = {}", short(alpha, 4)),
        },
    );
    let mut lower = false;
    for (key, m, layer, _) in FUNCTIONS {
        let ends: Vec<Xy> = at
            .and_then(|c| c.get(m))
            .unwrap_or_default()
            .iter()
            .flat_map(|iv| [[iv[0], alpha], [iv[1], alpha]])
            .collect();
        lower |= m == Membership::Lower && !ends.is_empty();
        p.push(
            format!("cut-{key}"),
            if ends.is_empty() {
                Mark::Empty
            } else {
                Mark::Markers {
                    points: ends,
                    marker: layer_marker(layer),
                }
            },
        );
    }
    lower
}

/// The legend: the three functions with their cut ends (the lower's only
/// where it is cut), the footprint.
fn legend(lower_cut: bool, alpha: f64) -> Vec<LegendEntry> {
    let mut v = Vec::new();
    for (_, m, layer, name) in FUNCTIONS {
        let label = format!("{name} membership of y");
        v.push(if m != Membership::Lower || lower_cut {
            LegendEntry::line_marker(
                &format!("{label}, its section at α = {}", short(alpha, 4)),
                layer_stroke(layer),
                layer_marker(layer),
            )
        } else {
            LegendEntry::line(&label, layer_stroke(layer))
        });
    }
    v.push(LegendEntry::area("footprint of uncertainty", upper_band()));
    v
}
