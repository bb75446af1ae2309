//! The series helpers of the curve figures, one per thing drawn, so that a
//! figure's function lists what it shows.

use t2spline::job::Points;
use t2spline::set::Region;
use t2spline::Membership;

use super::density::Density;
use super::projection::project;
use crate::chart::paint::{Fill, Marker, Stroke};
use crate::chart::scene::{LegendEntry, Mark, Panel, Priority, Xy};
use crate::figures::style::{crisp_marker, crisp_stroke, lower_band, polygon_stroke, upper_band};
use crate::set_view::Regions;

/// Jobs of up to this many control points name every one of them.
const FEW_POINTS: usize = 12;

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
