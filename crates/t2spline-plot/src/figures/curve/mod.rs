//! The figures of a curve job: the four stages of Algorithm 1.1, the distance
//! along the curve for several alphas, the distance against alpha, and the
//! type reductions compared.
//!
//! Each builder reads a [`RunOutput`] (or asks [`crate::data`] for more) and
//! is written with the series helpers below, one per thing drawn, so that a
//! figure's function lists what it shows.

mod density;
mod distance;
mod largest;
mod membership;
mod reductions;
mod section;
mod stage1;
mod stage2;
mod stage3;
mod stage4;
mod sweep;
mod zoom;

pub use density::Density;
pub use distance::{alpha_rule, distance_figure};
pub use largest::largest_distance;
pub use membership::membership_figure;
pub use reductions::reductions_figure;
pub use section::section_figure;
pub use stage1::stage1_figure;
pub use stage2::stage2_figure;
pub use stage3::stage3_figure;
pub use stage4::{stage4_figure, Zoom};
pub use sweep::sweep_figure;

use t2spline::job::{Points, RunOutput};

use t2spline::set::Region;
use t2spline::Membership;

use super::style::{
    crisp_marker, crisp_stroke, lower_band, polygon_stroke, reduction_label, upper_band,
};
use super::Aspect;
use crate::chart::paint::Fill;
use crate::chart::paint::{Marker, Stroke};
use crate::chart::scene::{LegendEntry, Mark, Panel, Priority, Xy};
use crate::chart::ticks::short;
use crate::set_view::Regions;

const AXIS_NAMES: [&str; 3] = ["x", "y", "z"];

/// Jobs of up to this many control points name every one of them.
const FEW_POINTS: usize = 12;

/// A pair of coordinates drawn in one panel: `(x, y)` in 2-D, each of the
/// three pairs in 3-D.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Projection {
    /// The coordinates on the horizontal and the vertical axis.
    pub axes: (usize, usize),
    /// Whether the panel says which projection it shows (3-D).
    titled: bool,
}

impl Projection {
    /// The projection to `axes`, titled or not.
    #[must_use]
    pub fn new(axes: (usize, usize), titled: bool) -> Projection {
        Projection { axes, titled }
    }

    /// "x–z".
    #[must_use]
    pub fn name(&self) -> String {
        format!("{}–{}", AXIS_NAMES[self.axes.0], AXIS_NAMES[self.axes.1])
    }

    /// An empty panel for this projection.
    #[must_use]
    pub fn panel(&self, aspect: Aspect) -> Panel {
        let (i, j) = self.axes;
        let mut p = match aspect {
            Aspect::Equal => Panel::curves(AXIS_NAMES[i], AXIS_NAMES[j]),
            Aspect::Auto => Panel::graph(AXIS_NAMES[i], AXIS_NAMES[j]),
        };
        if self.titled {
            p.title = Some(format!("{} projection", self.name()));
        }
        p
    }
}

/// The projections drawn for points of `dimension` coordinates.
#[must_use]
pub fn projections(dimension: usize) -> Vec<Projection> {
    if dimension >= 3 {
        [(0, 1), (0, 2), (1, 2)]
            .into_iter()
            .map(|ij| Projection::new(ij, true))
            .collect()
    } else {
        vec![Projection::new((0, 1), false)]
    }
}

/// What the curve figures of one result share: the result, the lower heights,
/// the projections, the aspect and the detail that fits.
#[derive(Debug)]
pub struct CurveScene<'a> {
    /// The result drawn.
    pub r: &'a RunOutput,
    /// The distinct lower heights of the job, ascending.
    pub heights: &'a [f64],
    /// The projections drawn.
    pub projections: Vec<Projection>,
    /// Equal or free aspect.
    pub aspect: Aspect,
    /// The per-point detail that fits.
    pub density: Density,
}

impl<'a> CurveScene<'a> {
    /// The scene of result `r` of a job with lower heights `heights`.
    #[must_use]
    pub fn new(r: &'a RunOutput, heights: &'a [f64], aspect: Aspect) -> CurveScene<'a> {
        let projections = projections(r.dimension);
        let density = Density::of(&r.control_points.crisp, &projections, aspect);
        CurveScene {
            r,
            heights,
            projections,
            aspect,
            density,
        }
    }

    /// The axes of the projections, in the order of the panels.
    #[must_use]
    pub fn axes(&self) -> Vec<(usize, usize)> {
        self.projections.iter().map(|p| p.axes).collect()
    }

    /// One panel per projection, each filled by `fill`.
    pub fn panels(&self, mut fill: impl FnMut(&mut Panel, (usize, usize))) -> Vec<Panel> {
        self.projections
            .iter()
            .map(|pr| {
                let mut p = pr.panel(self.aspect);
                fill(&mut p, pr.axes);
                p
            })
            .collect()
    }

    /// The notes of a figure: what the density left out (`left_out` says
    /// what, when the derived markers are; `None` for a figure that draws
    /// none), and whether the axes are to scale.
    #[must_use]
    pub fn notes(&self, left_out: Option<&str>) -> Vec<String> {
        let left_out = left_out.filter(|_| !self.density.markers);
        let mut notes: Vec<String> = self.density.note(left_out).into_iter().collect();
        if self.aspect == Aspect::Auto {
            notes.push("Axes not to scale: each is fitted to the data.".to_owned());
        }
        notes
    }
}

/// The legend entries of the crisp curve with its control points, and of the
/// control polygon.
#[must_use]
pub fn crisp_legend() -> Vec<LegendEntry> {
    vec![
        LegendEntry::line_marker(
            "crisp curve and control points",
            crisp_stroke(),
            crisp_marker(),
        ),
        LegendEntry::line("control polygon", polygon_stroke()),
    ]
}

/// Points projected to the coordinates `(i, j)`.
#[must_use]
pub fn project(points: &Points, (i, j): (usize, usize)) -> Vec<Xy> {
    points
        .coord(i)
        .iter()
        .zip(points.coord(j))
        .map(|(&x, &y)| [x, y])
        .collect()
}

/// The area between two curves: one forwards, the other backwards (the
/// type-reduced curves' band; not a region of the curve).
#[must_use]
pub fn band(a: &Points, b: &Points, ij: (usize, usize)) -> Vec<Xy> {
    let mut poly = project(a, ij);
    poly.extend(project(b, ij).into_iter().rev());
    poly
}

/// The upper and the lower function's regions at the level of `regions`,
/// in the panel of projection `k`, as the core's polygons (holes included)
/// filled by the even–odd rule; nothing where a function has no cut.
pub fn regions(p: &mut Panel, regions: &Regions, k: usize) {
    for (key, m, fill) in [
        ("region-upper", Membership::Upper, upper_band()),
        ("region-lower", Membership::Lower, lower_band()),
    ] {
        p.push(
            key,
            regions
                .get(m, k)
                .map_or(Mark::Empty, |r| region_mark(r, fill)),
        );
    }
}

/// A region of the core as one mark: the rings of all its polygons.
#[must_use]
pub fn region_mark(region: &Region, fill: Fill) -> Mark {
    let rings = region
        .polygons()
        .iter()
        .flat_map(|g| std::iter::once(&g.exterior).chain(&g.holes))
        .cloned()
        .collect();
    Mark::Region { rings, fill }
}

/// The legend entries of the shaded regions that `regions` holds in some
/// panel, at level `alpha_text` ("α = 0").
#[must_use]
pub fn regions_legend(regions: &Regions, alpha_text: &str) -> Vec<LegendEntry> {
    let mut legend = Vec::new();
    for (m, name, fill) in [
        (Membership::Upper, "upper", upper_band()),
        (Membership::Lower, "lower", lower_band()),
    ] {
        if (0..regions.upper.len()).any(|k| regions.get(m, k).is_some()) {
            legend.push(LegendEntry::area(
                &format!("{name} region at {alpha_text}"),
                fill,
            ));
        }
    }
    legend
}

/// `P₀`, `P₁₂`: a control point's name with a subscript index.
#[must_use]
pub fn point_name(i: usize) -> String {
    const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    let digits: String = i
        .to_string()
        .chars()
        .map(|c| c.to_digit(10).map_or(c, |d| SUB[d as usize]))
        .collect();
    format!("P{digits}")
}

/// "α = 0.8 > h = 0.6" and what it means, for subtitles of result `r`; for
/// a type reduction other than the paper's, that it does not use α (docs/method.md §9).
#[must_use]
pub fn alpha_phrase(r: &RunOutput, heights: &[f64]) -> String {
    let a = short(r.alpha, 4);
    let Some(regime) = r.regime.filter(|_| r.alpha_used) else {
        return format!(
            "{} does not use α: cut shown at α = {a}, the whole footprint",
            reduction_label(r.type_reduction)
        );
    };
    match heights {
        [h] if r.alpha <= *h => format!(
            "α = {a} ≤ h = {}: all three functions are cut",
            short(*h, 4)
        ),
        [h] => format!(
            "α = {a} > h = {}: the lower function has no cut",
            short(*h, 4)
        ),
        _ => format!(
            "α = {a}, heights h from {} to {} ({regime})",
            short(heights.first().copied().unwrap_or(1.0), 4),
            short(heights.last().copied().unwrap_or(1.0), 4),
        ),
    }
}

/// `α = 0.8` for a result of the paper's type reduction, else the
/// reduction's name.
#[must_use]
pub fn reduction_phrase(r: &RunOutput) -> String {
    if r.alpha_used {
        format!("α = {}", short(r.alpha, 4))
    } else {
        reduction_label(r.type_reduction).to_owned()
    }
}

/// The weights for a subtitle: all of them when few, else their range.
#[must_use]
pub fn weights_phrase(weights: &[f64]) -> String {
    let (lo, hi) = weights
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &w| {
            (a.min(w), b.max(w))
        });
    if lo == hi {
        format!("all weights {}", short(lo, 4))
    } else if weights.len() <= 8 {
        let list: Vec<String> = weights.iter().map(|w| short(*w, 4)).collect();
        format!("weights ({})", list.join(", "))
    } else {
        format!(
            "{} weights from {} to {}",
            weights.len(),
            short(lo, 4),
            short(hi, 4)
        )
    }
}

/// A line, or nothing when `points` is `None` (a series absent at this alpha).
pub fn line(p: &mut Panel, key: impl Into<String>, points: Option<Vec<Xy>>, stroke: Stroke) {
    p.push(
        key,
        points.map_or(Mark::Empty, |points| Mark::Line { points, stroke }),
    );
}

/// Markers, or nothing when not `shown` or there are none.
pub fn markers(
    p: &mut Panel,
    key: impl Into<String>,
    points: Vec<Xy>,
    marker: Marker,
    shown: bool,
) {
    let mark = if shown && !points.is_empty() {
        Mark::Markers { points, marker }
    } else {
        Mark::Empty
    };
    p.push(key, mark);
}

/// The crisp control polygon.
pub fn polygon(p: &mut Panel, crisp_points: &Points, ij: (usize, usize)) {
    line(
        p,
        "polygon",
        Some(project(crisp_points, ij)),
        polygon_stroke(),
    );
}

/// The crisp curve.
pub fn crisp_curve(p: &mut Panel, curve: &Points, ij: (usize, usize)) {
    line(p, "curve-crisp", Some(project(curve, ij)), crisp_stroke());
}

/// The crisp control points, smaller when they crowd.
pub fn crisp_points(p: &mut Panel, points: &Points, ij: (usize, usize), density: &Density) {
    let mut marker = crisp_marker();
    if !density.markers {
        marker.size = 3.5;
    }
    markers(
        p,
        "points-crisp",
        project(points, ij),
        marker,
        density.crisp_markers,
    );
}

/// Names of the control points that the density allows, shown where there
/// is room; `text(k)` is the name of point `k`.
pub fn names(
    p: &mut Panel,
    points: &Points,
    ij: (usize, usize),
    density: &Density,
    text: impl Fn(usize) -> String,
) {
    // Thinned names go in the first projection only: in the others a curve
    // folded over itself would mix them up.
    if density.name_stride > 1 && ij != (0, 1) {
        return;
    }
    // A job of a few points is read by its names (the paper's P₀ … P₃): each
    // is shown, where it covers least; beyond, names only where there is room.
    let priority = if density.count <= FEW_POINTS {
        Priority::Always
    } else {
        Priority::IfRoom
    };
    for (k, xy) in project(points, ij).into_iter().enumerate() {
        if density.named(k) {
            p.push(
                format!("name-{k}"),
                Mark::Label {
                    anchor: xy,
                    text: text(k),
                    priority,
                },
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_names_use_subscripts() {
        assert_eq!(point_name(0), "P₀");
        assert_eq!(point_name(12), "P₁₂");
    }

    #[test]
    fn many_weights_are_summarised() {
        assert_eq!(
            weights_phrase(&[1.0, 1.0, 3.0, 1.0]),
            "weights (1, 1, 3, 1)"
        );
        assert_eq!(weights_phrase(&[1.0; 200]), "all weights 1");
        let w: Vec<f64> = (0..200).map(|i| 0.5 + f64::from(i) / 100.0).collect();
        assert_eq!(weights_phrase(&w), "200 weights from 0.5 to 2.49");
    }
}
