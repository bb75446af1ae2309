//! Axes: data ranges fitted to what the panels draw (padded, equal aspect
//! where asked) and nice ticks.

use crate::chart::font::text_width;
use crate::chart::geometry::Rect;
use crate::chart::paint::font_size;
use crate::chart::panel_layout::{AxisLayout, PanelLayout};
use crate::chart::scene::{Figure, Mark, Panel, Xy};
use crate::chart::ticks::{decimals_for, nice_ticks};

/// Data bounds of a panel's items: `[x0, x1, y0, y1]`.
pub(super) fn bounds(panel: &Panel) -> Option<[f64; 4]> {
    let mut b = [
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    let mut add = |p: Xy| {
        if p[0].is_finite() && p[1].is_finite() {
            b = [
                b[0].min(p[0]),
                b[1].max(p[0]),
                b[2].min(p[1]),
                b[3].max(p[1]),
            ];
        }
    };
    for item in &panel.items {
        match &item.mark {
            Mark::Line { points, .. }
            | Mark::Area { points, .. }
            | Mark::Markers { points, .. } => {
                points.iter().copied().for_each(&mut add);
            }
            Mark::Segments { segments, .. } => {
                segments.iter().flatten().copied().for_each(&mut add)
            }
            Mark::Region { rings, .. } => rings.iter().flatten().copied().for_each(&mut add),
            Mark::Tiles { tiles } => tiles
                .iter()
                .flat_map(|(_, t)| t.iter().flatten())
                .copied()
                .for_each(&mut add),
            Mark::Label { anchor, .. } | Mark::Text { at: anchor, .. } => add(*anchor),
            Mark::Mesh { facets } => {
                for f in facets {
                    f.points.iter().copied().for_each(&mut add);
                    f.lines.iter().flatten().copied().for_each(&mut add);
                }
            }
            Mark::HRule { .. } | Mark::VRule { .. } | Mark::Empty => {}
        }
    }
    (b[0] <= b[1]).then_some(b)
}

/// `[lo, hi]` padded by 5 % on each side (a degenerate range gets a unit width).
fn padded(lo: f64, hi: f64) -> [f64; 2] {
    let span = hi - lo;
    let pad = if span > 1e-12 * (lo.abs() + hi.abs()).max(1e-300) {
        0.05 * span
    } else {
        0.5 * lo.abs().max(1.0)
    };
    [lo - pad, hi + pad]
}

pub(super) fn axis(range: [f64; 2], pixels: f64, spacing: f64) -> AxisLayout {
    let target = ((pixels / spacing).round() as usize).max(3);
    let (ticks, step) = nice_ticks(range[0], range[1], target);
    AxisLayout {
        range,
        ticks,
        decimals: decimals_for(step),
    }
}

/// The data ranges of panel `i` of each figure: fixed ranges as given, others
/// fitted to the data of all figures together.
pub(super) fn data_ranges(figures: &[&Figure], i: usize) -> Vec<([f64; 2], [f64; 2])> {
    let mut b = [
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    for f in figures {
        if let Some(c) = f.panels.get(i).and_then(bounds) {
            b = [
                b[0].min(c[0]),
                b[1].max(c[1]),
                b[2].min(c[2]),
                b[3].max(c[3]),
            ];
        }
    }
    if b[0] > b[1] {
        b = [0.0, 1.0, 0.0, 1.0];
    }
    figures
        .iter()
        .map(|f| {
            let p = &f.panels[i];
            (
                p.x_range.unwrap_or_else(|| padded(b[0], b[1])),
                p.y_range.unwrap_or_else(|| padded(b[2], b[3])),
            )
        })
        .collect()
}

/// Expands the shorter range so that one unit has the same length on both axes.
pub(super) fn equalise(x: [f64; 2], y: [f64; 2], w: f64, h: f64) -> ([f64; 2], [f64; 2]) {
    let scale = (w / (x[1] - x[0])).min(h / (y[1] - y[0]));
    let grow = |r: [f64; 2], len: f64| {
        let c = 0.5 * (r[0] + r[1]);
        let half = 0.5 * len / scale;
        [c - half, c + half]
    };
    (grow(x, w), grow(y, h))
}

/// Width of the widest tick label of an axis.
pub(super) fn label_width(a: &AxisLayout) -> f64 {
    a.labels()
        .iter()
        .map(|l| text_width(l, font_size::TICK))
        .fold(0.0, f64::max)
}

/// The panel in box `plot` showing ranges `x` and `y`, equalised when the
/// panel asks for equal aspect.
pub(super) fn placed(p: &Panel, plot: Rect, x: [f64; 2], y: [f64; 2]) -> PanelLayout {
    let (x, y) = if p.equal_aspect {
        equalise(x, y, plot.w, plot.h)
    } else {
        (x, y)
    };
    PanelLayout {
        plot,
        x: axis(x, plot.w, 80.0),
        y: axis(y, plot.h, 55.0),
    }
}

/// `pl` with a fixed-range panel's own ranges (a zoom), in the same box.
#[must_use]
pub fn with_ranges(pl: &PanelLayout, p: &Panel) -> PanelLayout {
    match (p.x_range, p.y_range) {
        (Some(x), Some(y)) => placed(p, pl.plot, x, y),
        _ => pl.clone(),
    }
}
