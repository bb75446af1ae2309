//! Placing texts on the data: each label tries positions around its anchor,
//! nearest first, and takes the first that covers no curve, marker, area, legend
//! or earlier label; far positions get a leader line.

use crate::font::{cap_height, line_height, text_width};
use crate::geometry::{Obstacles, Px, Rect};
use crate::layout::PanelLayout;
use crate::scene::{Mark, Panel};
use crate::style::font_size;

/// A placed text: its box, where its baseline starts, and an optional leader
/// line from the anchor to the box.
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// The text's box.
    pub rect: Rect,
    /// Start of the baseline.
    pub baseline: Px,
    /// A thin line from the anchor towards the box.
    pub leader: Option<[Px; 2]>,
}

/// The box of `text` with its top-left corner at `(x, y)`.
fn text_box(text: &str, x: f64, y: f64) -> Rect {
    Rect {
        x,
        y,
        w: text_width(text, font_size::LABEL) + 2.0,
        h: line_height(font_size::LABEL),
    }
}

fn placed(rect: Rect, leader: Option<[Px; 2]>) -> Placed {
    let inner = line_height(font_size::LABEL);
    Placed {
        baseline: [
            rect.x + 1.0,
            rect.y + 0.5 * (inner + cap_height(font_size::LABEL)),
        ],
        rect,
        leader,
    }
}

/// Places the labels of `panel` (its `Label` items and the texts of its
/// `HRule`s), avoiding `obstacles`; one entry per item, `None` for other items.
///
/// `forbidden` boxes (the legend) are never covered; other obstacles are
/// avoided where possible.
#[must_use]
pub fn place(
    panel: &Panel,
    pl: &PanelLayout,
    obstacles: &Obstacles,
    forbidden: &[Rect],
) -> Vec<Option<Placed>> {
    let mut taken = obstacles.clone();
    let plot = pl.plot.grow(-1.0);
    let mut out = Vec::with_capacity(panel.items.len());
    for item in &panel.items {
        let candidates: Vec<(Rect, Option<[Px; 2]>)> = match &item.mark {
            Mark::HRule { y, label, .. } if !label.is_empty() => {
                let py = pl.to_px([0.0, *y])[1];
                let b = text_box(label, 0.0, 0.0);
                let (left, right) = (plot.x + 4.0, plot.right() - 4.0 - b.w);
                let (above, below) = (py - 2.0 - b.h, py + 2.0);
                [(right, above), (right, below), (left, above), (left, below)]
                    .into_iter()
                    .map(|(x, y)| (Rect { x, y, ..b }, None))
                    .collect()
            }
            Mark::Label { anchor, text } => around(pl.to_px(*anchor), text),
            _ => {
                out.push(None);
                continue;
            }
        };
        let inside: Vec<_> = candidates
            .into_iter()
            .filter(|(r, _)| plot.contains_rect(r) && !forbidden.iter().any(|f| f.overlaps(r)))
            .collect();
        let best = inside
            .iter()
            .find(|(r, _)| taken.hits(r) == 0)
            .or_else(|| inside.iter().min_by_key(|(r, _)| taken.hits(r)))
            .cloned();
        out.push(best.map(|(rect, leader)| {
            taken.rects.push(rect.grow(1.0));
            placed(rect, leader)
        }));
    }
    out
}

/// Candidate boxes around `anchor`, nearest first, with leaders for far ones.
fn around(anchor: Px, text: &str) -> Vec<(Rect, Option<[Px; 2]>)> {
    let b = text_box(text, 0.0, 0.0);
    let dirs: [(f64, f64); 8] = [
        (1.0, -1.0),
        (-1.0, -1.0),
        (1.0, 1.0),
        (-1.0, 1.0),
        (1.0, 0.0),
        (-1.0, 0.0),
        (0.0, -1.0),
        (0.0, 1.0),
    ];
    let mut out = Vec::new();
    for r in [5.0, 12.0, 24.0, 40.0, 60.0] {
        for (dx, dy) in dirs {
            let norm = (dx * dx + dy * dy).sqrt();
            let (ux, uy) = (dx / norm, dy / norm);
            let cx = anchor[0] + ux * r + dx * 0.5 * b.w;
            let cy = anchor[1] + uy * r + dy * 0.5 * b.h;
            let rect = Rect {
                x: cx - 0.5 * b.w,
                y: cy - 0.5 * b.h,
                ..b
            };
            let leader = (r > 10.0).then(|| {
                let end = rect.nearest(anchor);
                let (lx, ly) = (end[0] - anchor[0], end[1] - anchor[1]);
                let len = (lx * lx + ly * ly).sqrt().max(1e-9);
                [
                    [anchor[0] + lx / len * 3.0, anchor[1] + ly / len * 3.0],
                    end,
                ]
            });
            out.push((rect, leader));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layout::AxisLayout;
    use crate::style::{Stroke, BLACK};

    fn layout() -> PanelLayout {
        let axis = |r| AxisLayout {
            range: r,
            ticks: vec![],
            decimals: 0,
        };
        PanelLayout {
            plot: Rect {
                x: 0.0,
                y: 0.0,
                w: 200.0,
                h: 200.0,
            },
            x: axis([0.0, 10.0]),
            y: axis([0.0, 10.0]),
        }
    }

    #[test]
    fn labels_avoid_curves_and_each_other() {
        let mut p = crate::scene::Panel::curves("x", "y");
        p.push(
            "c",
            Mark::Line {
                points: vec![[0.0, 5.0], [10.0, 5.0]],
                stroke: Stroke::solid(BLACK, 1.0),
            },
        );
        for k in 0..3 {
            p.push(
                format!("l{k}"),
                Mark::Label {
                    anchor: [5.0, 5.0],
                    text: "label".into(),
                },
            );
        }
        let pl = layout();
        let o = crate::layout::panel_obstacles(&p, &pl);
        let placed: Vec<Placed> = place(&p, &pl, &o, &[]).into_iter().flatten().collect();
        assert_eq!(placed.len(), 3);
        for (i, a) in placed.iter().enumerate() {
            assert_eq!(o.hits(&a.rect), 0, "label {i} covers the curve");
            for b in &placed[i + 1..] {
                assert!(!a.rect.overlaps(&b.rect), "{a:?} {b:?}");
            }
        }
    }
}
