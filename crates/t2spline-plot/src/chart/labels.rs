//! Placing texts on the data. Each label tries a bounded set of positions
//! around its anchor, nearest first, and takes the first that covers nothing
//! drawn; far positions get a leader line.
//!
//! A position is free when its box covers nothing drawn and its leader cuts
//! through nothing; failing that, a box on a filled area alone will do (a
//! text with a white halo reads well on a pale band). Labels of
//! [`Priority::Always`] (annotations) are placed first; when no position is
//! free they take the one covering the fewest things, but never another text
//! or the legend. Labels of [`Priority::IfRoom`] (point names) are placed
//! only where free and near their anchor, and are left out otherwise, so that
//! a dense figure shows fewer names rather than a heap of them.
//!
//! Every label tests at most 64 boxes (8 distances × 8 directions) against
//! the indexed [`Obstacles`], so placing `n` labels costs `O(n)` bounded
//! queries.

use crate::chart::font::{cap_height, line_height, text_width};
use crate::chart::geometry::{Px, Rect};
use crate::chart::obstacles::Obstacles;
use crate::chart::paint::font_size;
use crate::chart::panel_layout::PanelLayout;
use crate::chart::scene::{Mark, Panel, Priority};

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

/// Distances from the anchor tried, in pixels; a label of
/// [`Priority::IfRoom`] tries only those up to [`NEAR`].
const RADII: [f64; 8] = [5.0, 12.0, 24.0, 40.0, 60.0, 90.0, 130.0, 180.0];
/// Directions tried at each distance, nearest-looking first.
const DIRECTIONS: [(f64, f64); 8] = [
    (1.0, -1.0),
    (-1.0, -1.0),
    (1.0, 1.0),
    (-1.0, 1.0),
    (1.0, 0.0),
    (-1.0, 0.0),
    (0.0, -1.0),
    (0.0, 1.0),
];

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

/// The candidate boxes of a text item, or `None` for other items.
/// A candidate box and its leader line, if any.
type Candidate = (Rect, Option<[Px; 2]>);

fn candidates(mark: &Mark, pl: &PanelLayout) -> Option<(Vec<Candidate>, Priority)> {
    let plot = pl.plot.grow(-1.0);
    match mark {
        Mark::HRule { y, label, .. } if !label.is_empty() => {
            let py = pl.to_px([0.0, *y])[1];
            let b = text_box(label, 0.0, 0.0);
            let (left, right) = (plot.x + 4.0, plot.right() - 4.0 - b.w);
            let (above, below) = (py - 2.0 - b.h, py + 2.0);
            let c = [(right, above), (right, below), (left, above), (left, below)]
                .into_iter()
                .map(|(x, y)| (Rect { x, y, ..b }, None))
                .collect();
            Some((c, Priority::Always))
        }
        Mark::VRule { x, label, .. } if !label.is_empty() => {
            let px = pl.to_px([*x, 0.0])[0];
            let b = text_box(label, 0.0, 0.0);
            let (top, bottom) = (plot.y + 3.0, plot.bottom() - 3.0 - b.h);
            let (right, left) = (px + 3.0, px - 3.0 - b.w);
            let c = [(right, top), (left, top), (right, bottom), (left, bottom)]
                .into_iter()
                .map(|(x, y)| (Rect { x, y, ..b }, None))
                .collect();
            Some((c, Priority::Always))
        }
        Mark::Label {
            anchor,
            text,
            priority,
        } => {
            let radii = match priority {
                Priority::Always => &RADII[..],
                Priority::IfRoom => &RADII[..4],
            };
            Some((around(pl.to_px(*anchor), text, radii), *priority))
        }
        _ => None,
    }
}

/// Places the labels of `panel` (its `Label` items and the texts of its
/// rules), avoiding `obstacles`; one entry per item, `None` for other items
/// and for labels left out.
///
/// `forbidden` boxes (the legend) are never covered, nor are earlier texts.
#[must_use]
pub fn place(
    panel: &Panel,
    pl: &PanelLayout,
    obstacles: &Obstacles,
    forbidden: &[Rect],
) -> Vec<Option<Placed>> {
    let mut taken = Obstacles::new(pl.plot);
    taken.extend(obstacles);
    let mut texts = Obstacles::new(pl.plot);
    for f in forbidden {
        texts.add_rect(*f);
    }
    for item in &panel.items {
        if let Mark::Text { at, text } = &item.mark {
            texts.add_rect(crate::chart::obstacles::text_rect(pl, *at, text));
        }
    }
    let plot = pl.plot.grow(-1.0);
    let mut out: Vec<Option<Placed>> = vec![None; panel.items.len()];
    for pass in [Priority::Always, Priority::IfRoom] {
        for (k, item) in panel.items.iter().enumerate() {
            let Some((boxes, priority)) = candidates(&item.mark, pl) else {
                continue;
            };
            if priority != pass {
                continue;
            }
            let inside: Vec<_> = boxes
                .into_iter()
                .filter(|(r, _)| plot.contains_rect(r) && !texts.overlaps_rect(r))
                .collect();
            // Free: the box covers nothing, and its leader cuts through
            // nothing either, past the anchor's own marker (at most 8 px).
            let clear = |leader: &Option<[Px; 2]>| {
                leader.is_none_or(|[a, b]| {
                    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                    let len = dx.hypot(dy).max(1e-9);
                    let start = [a[0] + dx / len * 5.0, a[1] + dy / len * 5.0];
                    len <= 5.0 || !taken.crosses(start, b)
                })
            };
            // Best on nothing at all, else on a filled area only.
            let free = inside
                .iter()
                .find(|(r, leader)| taken.is_free(r) && clear(leader))
                .or_else(|| {
                    inside
                        .iter()
                        .find(|(r, leader)| taken.is_clear(r) && clear(leader))
                });
            let best = match priority {
                Priority::IfRoom => free,
                Priority::Always => free.or_else(|| {
                    inside
                        .iter()
                        .min_by_key(|(r, l)| taken.hits(r) + usize::from(!clear(l)))
                }),
            };
            if let Some((rect, leader)) = best.cloned() {
                taken.add_rect(rect.grow(1.0));
                texts.add_rect(rect.grow(1.0));
                if let Some([a, b]) = leader {
                    taken.add_segment(a, b);
                }
                out[k] = Some(placed(rect, leader));
            }
        }
    }
    out
}

/// Candidate boxes around `anchor` at the given distances, nearest first,
/// with leaders for far ones.
fn around(anchor: Px, text: &str, radii: &[f64]) -> Vec<Candidate> {
    let b = text_box(text, 0.0, 0.0);
    let mut out = Vec::with_capacity(radii.len() * DIRECTIONS.len());
    for &r in radii {
        for (dx, dy) in DIRECTIONS {
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
    use crate::chart::paint::{Stroke, BLACK};
    use crate::chart::panel_layout::AxisLayout;

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

    fn label(p: &mut Panel, key: &str, anchor: [f64; 2], priority: Priority) {
        p.push(
            key,
            Mark::Label {
                anchor,
                text: "label".into(),
                priority,
            },
        );
    }

    #[test]
    fn labels_avoid_curves_and_each_other() {
        let mut p = Panel::curves("x", "y");
        p.push(
            "c",
            Mark::Line {
                points: vec![[0.0, 5.0], [10.0, 5.0]],
                stroke: Stroke::solid(BLACK, 1.0),
            },
        );
        for k in 0..3 {
            label(&mut p, &format!("l{k}"), [5.0, 5.0], Priority::Always);
        }
        let pl = layout();
        let o = crate::chart::obstacles::panel_obstacles(&p, &pl);
        let placed: Vec<Placed> = place(&p, &pl, &o, &[]).into_iter().flatten().collect();
        assert_eq!(placed.len(), 3);
        for (i, a) in placed.iter().enumerate() {
            assert_eq!(o.hits(&a.rect), 0, "label {i} covers the curve");
            for b in &placed[i + 1..] {
                assert!(!a.rect.overlaps(&b.rect), "{a:?} {b:?}");
            }
        }
    }

    #[test]
    fn names_without_room_are_left_out_and_annotations_never() {
        // Forty names on one point: only those with a free place near it stay.
        let mut p = Panel::curves("x", "y");
        for k in 0..40 {
            label(&mut p, &format!("n{k}"), [5.0, 5.0], Priority::IfRoom);
        }
        label(&mut p, "a", [5.0, 5.0], Priority::Always);
        let pl = layout();
        let o = crate::chart::obstacles::panel_obstacles(&p, &pl);
        let placed = place(&p, &pl, &o, &[]);
        let names = placed[..40].iter().flatten().count();
        assert!(names > 0 && names < 40, "{names} names placed");
        assert!(placed[40].is_some(), "the annotation is always placed");
        let boxes: Vec<Rect> = placed.iter().flatten().map(|p| p.rect).collect();
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                assert!(!a.overlaps(b), "texts overlap: {a:?} {b:?}");
            }
        }
    }
}
